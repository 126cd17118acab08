#!/usr/bin/env python3
"""Sweeps the fields of a starter deck through extreme values and compares what radx and OpenRadioss accept.

For every number of every data line (bulk node and element lines and /FUNCT points left out), the deck is
written again with that one field blank, 0, -1 and at its largest value (1e30, or 999999999 for an integer),
then read by radx's starter and by OpenRadioss's starter (only the starters run). Each variant is classed:

  same        both accept, or both refuse
  stricter    OpenRadioss accepts, radx refuses: a deck Radioss reads that radx stops (to fix or to document)
  laxer       radx accepts, OpenRadioss refuses (radx may run a deck that Radioss stops)

The report lists the stricter and laxer variants with the keyword, line, field columns, value and the first
error radx gives. This is a development tool, not a test: it needs an OpenRadioss build (a folder
holding exec/starter_linux64_gf and hm_cfg_files: --openradioss DIR or OPENRADIOSS_ROOT) and takes about a second
per variant.

Usage: scripts/sweep_fields.py DECK_0000.rad [--radx build/apps/radx-starter] [--openradioss DIR]
       [--keywords /PROP/SHELL,/MAT/LAW2] [--values blank,0,-1,max] [--out REPORT.md] [--work DIR]
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile

# Keywords whose data lines are bulk geometry or curve points: their fields are ids and coordinates.
BULK = ("/NODE", "/SHELL", "/SH3N", "/BRICK", "/TETRA4", "/SPRING", "/TRUSS", "/BEAM", "/FUNCT", "/BRIC20",
        "/GRNOD/NODE", "/GRSHEL/SHEL", "/GRBRIC/BRIC", "/SURF/SEG", "/TITLE", "/BEGIN")
NUMBER = re.compile(r"[-+]?(\d+\.?\d*|\.\d+)([eEdD][-+]?\d+)?$")


def fields_of(line):
    """(start, end, text) of each number on the line, end exclusive, 0-based; the field spans the 10- or
    20-column slot that ends where the number ends (right-aligned Radioss fields)."""
    out = []
    for m in re.finditer(r"\S+", line):
        tok = m.group(0)
        if not NUMBER.match(tok):
            continue
        end = m.end()
        if end % 10 != 0:  # not right-aligned on the grid: free format or a name, leave it
            continue
        width = 10 if m.start() >= end - 10 else 20
        if m.start() < end - width:
            continue
        out.append((end - width, end, tok))
    return out


def blocks(lines):
    """(keyword, index of the keyword line, indices of its data lines) for each keyword block."""
    out, cur = [], None
    for i, l in enumerate(lines):
        if l.startswith("/"):
            if cur:
                out.append(cur)
            cur = (l.split()[0].rstrip(), i, [])
        elif cur and not l.startswith("#") and l.strip():
            cur[2].append(i)
    if cur:
        out.append(cur)
    return out


def is_bulk(kw):
    root = "/".join(kw.split("/")[:3]) if kw.count("/") >= 2 else kw
    return any(kw.startswith(b) and (len(kw) == len(b) or kw[len(b)] == "/") for b in BULK) or root in BULK


def variants(lines, keywords, values):
    for kw, k_line, data in blocks(lines):
        if is_bulk(kw) or (keywords and not any(kw.startswith(k) for k in keywords)):
            continue
        # the first data line of a keyword with a title is its title: numbers there are part of a name
        for n, i in enumerate(data):
            for (a, b, tok) in fields_of(lines[i]):
                integer = re.fullmatch(r"[-+]?\d+", tok) is not None
                for v in values:
                    text = {"blank": "", "0": "0" if integer else "0.0", "-1": "-1" if integer else "-1.0",
                            "max": "999999999" if integer else "1e30"}[v]
                    if text == tok:
                        continue
                    new = lines[i][:a] + text.rjust(b - a) + lines[i][b:]
                    yield kw, k_line, i, (a, b), tok, v, new


def run_radx(radx, deck, work):
    r = subprocess.run([radx, "-i", deck, "--out", work], capture_output=True, text=True, errors="replace", cwd=work)
    err = next((l for l in r.stderr.splitlines() + r.stdout.splitlines() if ": error: " in l), "")
    return r.returncode == 0, err


def run_openradioss(root, deck, work):
    env = dict(os.environ, RAD_CFG_PATH=os.path.join(root, "hm_cfg_files"),
               LD_LIBRARY_PATH=os.path.join(root, "exec"), OMP_NUM_THREADS="1", OMP_STACKSIZE="400m",
               KMP_STACKSIZE="400m")
    try:
        r = subprocess.run([os.path.join(root, "exec", "starter_linux64_gf"), "-i", os.path.basename(deck),
                            "-np", "1", "-nt", "1"], capture_output=True, text=True, errors="replace", cwd=work, env=env,
                           timeout=120)
    except subprocess.TimeoutExpired:
        return False, "timeout"
    log = r.stdout
    ok = r.returncode == 0 and "ERROR TERMINATION" not in log and (
        "NORMAL TERMINATION" in log or "TERMINATION WITH WARNING" in log)
    return ok, ""


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("deck")
    ap.add_argument("--radx", default=os.path.join(os.path.dirname(__file__), "..", "build", "apps",
                                                     "radx-starter"))
    ap.add_argument("--openradioss", default=os.environ.get("OPENRADIOSS_ROOT",
                                                             "/tmp/openradioss-ref/OpenRadioss"))
    ap.add_argument("--keywords", default="")
    ap.add_argument("--values", default="blank,0,-1,max")
    ap.add_argument("--out", default="")
    ap.add_argument("--work", default="")
    a = ap.parse_args(argv)
    radx = os.path.abspath(a.radx)
    src = os.path.abspath(a.deck)
    lines = open(src, encoding="latin-1").read().split("\n")
    keywords = [k for k in a.keywords.split(",") if k]
    values = a.values.split(",")
    work = a.work or tempfile.mkdtemp(prefix="sweep-")
    os.makedirs(work, exist_ok=True)
    name = os.path.basename(src)
    # the deck's includes and engine deck beside it
    for f in os.listdir(os.path.dirname(src)):
        if f != name and os.path.isfile(os.path.join(os.path.dirname(src), f)):
            shutil.copy(os.path.join(os.path.dirname(src), f), work)
    deck = os.path.join(work, name)
    open(deck, "w", encoding="latin-1").write("\n".join(lines))
    base_r, err = run_radx(radx, deck, work)
    base_o, _ = run_openradioss(a.openradioss, deck, work)
    if not (base_r and base_o):
        print("the unchanged deck must pass both starters (radx %s %s, OpenRadioss %s)" %
              (base_r, err, base_o), file=sys.stderr)
        return 2
    counts = {"same": 0, "stricter": 0, "laxer": 0}
    found = []
    for kw, k_line, i, (a0, b0), tok, v, new in variants(lines, keywords, values):
        changed = list(lines)
        changed[i] = new
        open(deck, "w", encoding="latin-1").write("\n".join(changed))
        r_ok, r_err = run_radx(radx, deck, work)
        o_ok, _ = run_openradioss(a.openradioss, deck, work)
        kind = "same" if r_ok == o_ok else ("stricter" if o_ok else "laxer")
        counts[kind] += 1
        if kind != "same":
            found.append((kind, kw, lines[k_line].strip(), i + 1, a0 + 1, b0, tok, v, r_err))
            print("%-8s %s line %d cols %d-%d: %s -> %s  %s" % (kind, lines[k_line].strip(), i + 1, a0 + 1, b0,
                                                               tok, v, r_err[:160]), flush=True)
    open(deck, "w", encoding="latin-1").write("\n".join(lines))
    summary = "%s: %d variants, same %d, stricter %d, laxer %d" % (name, sum(counts.values()), counts["same"],
                                                                   counts["stricter"], counts["laxer"])
    print(summary)
    if a.out:
        with open(a.out, "w") as f:
            f.write("# Field sweep of %s\n\n%s\n\n| kind | keyword | line | columns | was | now | radx |\n"
                    "|---|---|---|---|---|---|---|\n" % (name, summary))
            for kind, kw, kl, ln, c0, c1, tok, v, e in found:
                f.write("| %s | %s | %d | %d-%d | %s | %s | %s |\n" % (kind, kl, ln, c0, c1, tok, v,
                                                                    e.replace("|", "/")[:200]))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
