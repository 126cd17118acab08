#!/usr/bin/env python3
"""The CPU check of an executable (apps/cpu_check.cpp) must itself run on the x86-64 baseline.

It runs on the CPUs the rest of a -march=x86-64-v3 executable cannot, so its code, and the code of libgcc's
CPU model it calls, must hold no instruction beyond the baseline: no VEX or EVEX encoded instruction (their
mnemonics start with 'v', plus the BMI, F16C, LZCNT, MOVBE ones) and no ymm or zmm register. Disassembles
those functions in the executable with objdump and fails, naming the instruction, on the first such one.
Also checks that the check is registered in .preinit_array, so that it runs before every constructor.
"""
import argparse
import re
import subprocess
import sys

BEYOND_BASELINE = re.compile(r"^(v\w+|andn|bextr|blsi|blsmsk|blsr|bzhi|mulx|pdep|pext|rorx|sarx|shlx|shrx|"
                             r"lzcnt|tzcnt|movbe|popcnt|crc32|pcmpestri|pcmpestrm|pcmpistri|pcmpistrm)$")


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("exe")
    args = ap.parse_args()
    sections = subprocess.run(["objdump", "-h", args.exe], check=True, capture_output=True, text=True).stdout
    if ".preinit_array" not in sections:
        print(f"{args.exe}: no .preinit_array section: the CPU check is not linked in")
        return 1
    dis = subprocess.run(["objdump", "-d", "--no-show-raw-insn", "-C", args.exe], check=True,
                         capture_output=True, text=True).stdout
    wanted = ("radx_check_cpu", "__cpu_indicator_init", "get_available_features", "__get_cpuid")
    current = None
    checked = {}
    bad = []
    for line in dis.splitlines():
        head = re.match(r"^[0-9a-f]+ <(.+)>:$", line)
        if head:
            name = head.group(1)
            current = name if any(w in name for w in wanted) else None
            if current:
                checked[current] = 0
            continue
        if current is None:
            continue
        parts = line.split("\t")
        if len(parts) < 2:
            continue
        insn = parts[1].strip()
        mnemonic = insn.split()[0] if insn else ""
        checked[current] += 1
        if BEYOND_BASELINE.match(mnemonic) or re.search(r"%[yz]mm", insn):
            bad.append(f"{current}: {insn}")
    if not any("radx_check_cpu" in n for n in checked):
        print(f"{args.exe}: radx_check_cpu not found in the disassembly")
        return 1
    for name, count in checked.items():
        print(f"{name}: {count} instructions")
    if bad:
        print("instructions beyond the x86-64 baseline in the CPU check:")
        print("\n".join(bad))
        return 1
    print("the CPU check uses only x86-64 baseline instructions")
    return 0


if __name__ == "__main__":
    sys.exit(main())
