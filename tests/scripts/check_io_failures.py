#!/usr/bin/env python3
"""Damaged files and failed writes: every radx reader refuses a damaged dataset, every writer fails cleanly.

Checksums. A run of --th-deck; every dataset with values of its model file, result mesh, a state and its
time history carries HDF5's Fletcher32 checksum. One byte flipped inside the stored values of the model
file's node coordinates makes radx-engine exit 1 naming the file, the dataset and the checksum; one flipped
in the time history's global group does the same for `radx th --csv` (exit 1) and `radx diff` (exit 2, its
code for an input it cannot read). Before the checksums both exited 0 with changed values.

Failed writes. Writes past a file size limit fail with EFBIG ("File too large"): RLIMIT_FSIZE with SIGXFSZ
ignored, which any process may set for itself, so this part runs everywhere. Where the test can mount a
tmpfs (root, and a container that allows it), a full disk ("No space left on device") too, at sizes that
make the run fail on the mesh, on the states and on the time history. Each failure must end with: exit 1
(not a signal: HDF5 1.10 crashed at exit after a failed close), the failing file and the system's reason
on standard error, no NORMAL TERMINATION anywhere, a summary (if one is written) with status "error",
and for the starter no model file nor .part left.
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

import h5py
import numpy as np

FAILURES = []


def check(cond, what):
    if not cond:
        FAILURES.append(what)
        print("FAIL: " + what)
    return cond


def run(cmd, cwd=None, fsize_kib=None):
    """Runs cmd; with fsize_kib, under that file size limit with SIGXFSZ ignored (writes then fail)."""
    if fsize_kib is not None:
        cmd = ["bash", "-c", f"trap '' XFSZ; ulimit -f {fsize_kib}; exec \"$@\"", "bash"] + cmd
    env = dict(os.environ, OMP_WAIT_POLICY="passive")
    return subprocess.run(cmd, cwd=cwd, env=env, capture_output=True, text=True, timeout=600)


def flip_value_byte(path, dataset):
    """Flips one bit of a byte inside the stored values of `dataset` (its first chunk, or its data)."""
    with h5py.File(path, "r") as f:
        ds = f[dataset]
        offset = ds.id.get_chunk_info(0).byte_offset if ds.chunks else ds.id.get_offset()
    with open(path, "r+b") as g:
        g.seek(offset + 25)
        b = g.read(1)
        g.seek(offset + 25)
        g.write(bytes([b[0] ^ 0x10]))


def unchecked_datasets(path):
    """Datasets with values of `path` that carry no Fletcher32 checksum (variable-length strings excepted:
    HDF5 filters do not take them)."""
    missing = []

    def visit(name, obj):
        if not isinstance(obj, h5py.Dataset) or obj.size == 0:
            return
        if h5py.check_string_dtype(obj.dtype) is not None and h5py.check_string_dtype(obj.dtype).length is None:
            return
        if not obj.fletcher32:
            missing.append(name)

    with h5py.File(path, "r") as f:
        f.visititems(visit)
    return missing


def check_checksums(a, th_deck, out):
    run_a = os.path.join(out, "checksum_a")
    r = run([a.radx, "run", th_deck, "--out", run_a, "--no-plot"])
    if not check(r.returncode == 0, f"radx run {th_deck} exit {r.returncode}: {r.stderr}"):
        return
    root = os.path.basename(th_deck)[: -len("_0000.rad")]
    files = {"model": f"{root}_0000.hdf", "mesh": f"{root}.mesh.hdf", "state": f"{root}_000001.hdf",
             "time history": f"{root}_th.h5"}
    for kind, name in files.items():
        missing = unchecked_datasets(os.path.join(run_a, name))
        check(not missing, f"{kind} {name}: {len(missing)} datasets without checksum, e.g. {missing[:5]}")
        print(f"{kind} {name}: every dataset with values checksummed")

    # The model file: radx-engine.
    run_b = os.path.join(out, "checksum_b")
    shutil.copytree(run_a, run_b)
    model = os.path.join(run_b, files["model"])
    flip_value_byte(model, "/VTKHDF/Points")
    engine_deck = th_deck.replace("_0000.rad", "_0001.rad")
    r = run([a.radx_engine, engine_deck, "--out", run_b, "--model", model, "--no-plot"])
    print("damaged model file:", r.stderr.strip())
    check(r.returncode == 1, f"radx-engine on a damaged model file: exit {r.returncode}, expected 1")
    # The coordinates are one dataset under two names (the mesh's and the model's): either may be named,
    # whichever the reader meets first (the content hash reads every dataset in link-name order).
    named = "dataset /radx/nodes/xyz" in r.stderr or "dataset /VTKHDF/Points" in r.stderr
    check(model in r.stderr and named and "checksum" in r.stderr,
          "radx-engine on a damaged model file does not name the file, the dataset and the checksum")

    # The time history: radx th and radx diff.
    th = os.path.join(run_b, files["time history"])
    shutil.copy(os.path.join(run_a, files["time history"]), th)
    flip_value_byte(th, "/global")
    r = run([a.radx, "th", th, "--csv"])
    print("damaged time history, radx th:", r.stderr.strip())
    check(r.returncode == 1 and r.stdout == "", f"radx th --csv on a damaged file: exit {r.returncode}, "
                                                f"{len(r.stdout)} bytes of CSV; expected exit 1 and none")
    check(th in r.stderr and "dataset /global" in r.stderr and "checksum" in r.stderr,
          "radx th on a damaged file does not name the file, the dataset and the checksum")
    shutil.copy(os.path.join(run_a, f"{root}_summary.json"), run_b)
    r = run([a.radx, "diff", run_a, run_b])
    print("damaged time history, radx diff:", r.stderr.strip())
    check(r.returncode == 2, f"radx diff with a damaged time history: exit {r.returncode}, expected 2")
    check("dataset /global" in r.stderr and "checksum" in r.stderr,
          "radx diff with a damaged time history does not name the dataset and the checksum")


def check_clean_failure(label, r, out_dir, root, expect_files, reason):
    """A run that failed to write: exit 1, the file and the reason said, no NORMAL TERMINATION."""
    print(f"--- {label}: exit {r.returncode}")
    print(r.stderr.strip()[-600:])
    ok = check(r.returncode == 1, f"{label}: exit {r.returncode}, expected 1 (negative or > 128: a signal)")
    said = [f for f in expect_files if f in r.stderr]
    ok &= check(said != [], f"{label}: standard error names none of {expect_files}")
    ok &= check(reason in r.stderr, f"{label}: standard error does not give the reason '{reason}'")
    listing = os.path.join(out_dir, f"{root}_0001.out")
    text = r.stdout + (open(listing, errors="replace").read() if os.path.exists(listing) else "")
    ok &= check("NORMAL TERMINATION" not in text, f"{label}: NORMAL TERMINATION printed")
    summary = os.path.join(out_dir, f"{root}_summary.json")
    if os.path.exists(summary):
        status = json.load(open(summary))["status"]
        ok &= check(status == "error", f"{label}: the summary says {status}, expected error")
    leftovers = [f for f in os.listdir(out_dir) if f.endswith(".part")]
    ok &= check(leftovers == [], f"{label}: .part files left: {leftovers}")
    return said


def engine_deck_printing_every_cycle(deck, folder):
    """The engine deck of `deck` with a listing line every cycle, two states and no /TFILE: a listing larger
    than any other file of the run."""
    text = open(deck.replace("_0000.rad", "_0001.rad")).read()
    text = re.sub(r"^/PRINT/-?\d+", "/PRINT/-1", text, flags=re.M)
    text = re.sub(r"^(/ANIM/DT\n#.*\n\s*\S+\s+)\S+", r"\g<1>1.0", text, flags=re.M)
    text = re.sub(r"^/TFILE\n#.*\n.*\n", "", text, flags=re.M)
    path = os.path.join(folder, os.path.basename(deck).replace("_0000.rad", "_0001.rad"))
    open(path, "w").write(text)
    return path


def check_file_size_limit(a, deck, out):
    root = os.path.basename(deck)[: -len("_0000.rad")]
    # The starter: the model file is larger than the limit.
    folder = os.path.join(out, "fsize_starter")
    os.makedirs(folder)
    r = run([a.radx_starter, deck, "--out", folder], fsize_kib=64)
    print(f"--- starter, model file beyond the limit: exit {r.returncode}\n{r.stderr.strip()}")
    check(r.returncode == 1, f"starter beyond the file size limit: exit {r.returncode}, expected 1")
    check(f"{root}_0000.hdf" in r.stderr and "File too large" in r.stderr,
          "starter: standard error does not name the model file and 'File too large'")
    left = [f for f in os.listdir(folder) if f.endswith(".hdf") or f.endswith(".part")]
    check(left == [], f"starter: model file or .part left behind: {left}")

    model_dir = os.path.join(out, "fsize_model")
    r = run([a.radx_starter, deck, "--out", model_dir])
    check(r.returncode == 0, f"starter: exit {r.returncode}")
    model = os.path.join(model_dir, f"{root}_0000.hdf")
    engine_deck = deck.replace("_0000.rad", "_0001.rad")
    # (limit KiB, engine deck, the files that may fail first): the mesh is written first; at 200 KiB the
    # mesh and the states fit and the time history (83 KiB, with the margins it reserves) does not; with a
    # listing line every cycle, at 300 KiB the listing is what outgrows the limit.
    cases = [(32, None, [f"{root}.mesh.hdf"]), (200, None, [f"{root}_th.h5"]),
             (300, "print", [f"{root}_0001.out"])]
    for kib, variant, expect in cases:
        folder = os.path.join(out, f"fsize_engine_{kib}")
        os.makedirs(folder)
        edeck = engine_deck_printing_every_cycle(deck, folder) if variant else engine_deck
        r = run([a.radx_engine, edeck, "--out", folder, "--model", model, "--no-plot"], fsize_kib=kib)
        check_clean_failure(f"engine, file size limit {kib} KiB", r, folder, root, expect, "File too large")


def mount_tmpfs(path, kib):
    os.makedirs(path, exist_ok=True)
    r = subprocess.run(["mount", "-t", "tmpfs", "-o", f"size={kib}k", "tmpfs", path], capture_output=True)
    return r.returncode == 0


def check_full_disk(a, deck, out):
    probe = os.path.join(out, "tmpfs_probe")
    if not mount_tmpfs(probe, 64):
        print("no tmpfs can be mounted here: the full-disk part is skipped (the file size limit covers the "
              "same paths)")
        return
    subprocess.run(["umount", probe])
    root = os.path.basename(deck)[: -len("_0000.rad")]
    model_dir = os.path.join(out, "full_model")
    r = run([a.radx_starter, deck, "--out", model_dir])
    model = os.path.join(model_dir, f"{root}_0000.hdf")
    engine_deck = deck.replace("_0000.rad", "_0001.rad")
    # The starter on a disk smaller than the model file.
    mnt = os.path.join(out, "full_starter")
    mount_tmpfs(mnt, 160)
    try:
        r = run([a.radx_starter, deck, "--out", mnt])
        print(f"--- starter, full disk: exit {r.returncode}\n{r.stderr.strip()}")
        check(r.returncode == 1, f"starter on a full disk: exit {r.returncode}, expected 1")
        check(f"{root}_0000.hdf" in r.stderr and "No space left on device" in r.stderr,
              "starter on a full disk: standard error does not name the model file and the reason")
        left = [f for f in os.listdir(mnt) if f.endswith(".hdf") or f.endswith(".part")]
        check(left == [], f"starter on a full disk: model file or .part left behind: {left}")
    finally:
        subprocess.run(["umount", mnt])
    # The engine on disks of several sizes: each run fails cleanly; together they fail on each kind of file.
    failed_on = set()
    kinds = {"mesh": re.compile(re.escape(root) + r"\.mesh\.hdf"),
             "state": re.compile(re.escape(root) + r"_\d{6}\.hdf"),
             "time history": re.compile(re.escape(root) + r"_th\.h5")}
    for kib in (96, 192, 320, 512, 768, 896):
        mnt = os.path.join(out, f"full_engine_{kib}")
        mount_tmpfs(mnt, kib)
        try:
            r = run([a.radx_engine, engine_deck, "--out", mnt, "--model", model, "--no-plot"])
            last = [l for l in r.stderr.splitlines() if "error termination" in l or "error:" in l]
            what = last[-1] if last else ""
            expect = [f"{root}.mesh.hdf", f"{root}_0", f"{root}_th.h5", f"{root}_summary.json"]
            check_clean_failure(f"engine, full disk of {kib} KiB", r, mnt, root, expect,
                                "No space left on device")
            failed_on |= {k for k, pattern in kinds.items() if pattern.search(what)}
        finally:
            subprocess.run(["umount", mnt])
    check(failed_on == set(kinds), f"the full-disk runs failed on {sorted(failed_on)}, expected every one of "
                                   f"{sorted(kinds)}")


def main():
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("--radx", required=True)
    p.add_argument("--radx-starter", required=True)
    p.add_argument("--radx-engine", required=True)
    p.add_argument("--deck", required=True, help="a deck whose run writes states, a time history and a listing")
    p.add_argument("--th-deck", required=True, help="a small deck with a time history")
    p.add_argument("--out", required=True)
    a = p.parse_args()
    shutil.rmtree(a.out, ignore_errors=True)
    os.makedirs(a.out)
    out = tempfile.mkdtemp(dir=a.out)
    check_checksums(a, a.th_deck, out)
    check_file_size_limit(a, a.deck, out)
    check_full_disk(a, a.deck, out)
    if FAILURES:
        print(f"{len(FAILURES)} failure(s)")
        return 1
    print("damaged files refused and failed writes ended cleanly")
    return 0


if __name__ == "__main__":
    sys.exit(main())
