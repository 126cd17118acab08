"""A SIGKILL at any write of a time-history flush: P_th.h5 then reads, with plain h5py and
with `radx th`, as exactly the rows of a completed flush, or is refused with a message saying it was being
written when the run was killed and how to recover. Never rows of zeros, never groups of different lengths.

usage: /usr/bin/python3 check_th_kill_sweep.py --radx R --radx-starter S --radx-engine E
                                                --deck FREE_FALL_0000.rad --out DIR

The free-fall deck with a row every cycle (/TFILE 0) and an end time far away. strace kills the engine
(SIGKILL, delivered by the kernel as the call enters) at the N-th pwrite64 to FREE_FALL_th.h5 itself: the
first flush writes FREE_FALL_th.h5.part and renames it, so the N-th pwrite is one of the in-place flushes.
A calibration run counts the pwrites of the first two in-place flushes; N sweeps every one of them (about
180 runs, two at a time, under a minute).
Checks at each N:
  * h5py either opens the file, and then every group has the same number of rows r >= 1, the times are
    r consecutive cycles from 0 (a row never written reads as a time of 0: it would break the sequence),
    and every value is finite; or h5py refuses it with HDF5's "open for write" (the 1.10 format's flag);
  * `radx th` agrees: it lists r rows; or, for a refused file, it lists the rows of the completed flushes
    with a warning saying the run was killed while the file was being written and naming --recover;
  * a refused file, once `radx th FILE --recover` has rewritten it as the warning says, reads with h5py as
    the rows radx th listed, under the same checks: never zeros.
"""
import argparse
import concurrent.futures
import math
import os
import re
import shutil
import subprocess
import sys

import h5py

from results_common import check, finish, write_engine_deck

DT = 0.01 / 1381  # the free fall's stable time step, constant (rigid motion)


def h5py_rows(path):
    """(rows, None) when h5py reads a consistent history, (None, message) otherwise."""
    try:
        with h5py.File(path, "r") as h:
            groups = {g: h[g][()] for g in h.attrs["groups"]}
    except Exception as e:  # noqa: BLE001 - any failure to read is one of the outcomes
        return None, "%s: %s" % (type(e).__name__, e)
    n = {len(v) for v in groups.values()}
    if len(n) != 1:
        return None, "INCONSISTENT: groups have row counts %s" % sorted(n)
    r = n.pop()
    t = groups["global"][:, 0]
    # A row never written reads as zeros: its time breaks the steps of about DT from 0.
    bad = [i for i in range(1, r) if not 0.5 * DT < t[i] - t[i - 1] < 2 * DT]
    if r < 1 or t[0] != 0 or bad:
        return None, "INCONSISTENT: %d rows, times %s" % (r, [(i, t[i]) for i in bad[:3]] or t[:1])
    if not all(math.isfinite(x) for v in groups.values() for x in v.flat):
        return None, "INCONSISTENT: a value is not finite"
    return r, None


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--radx", required=True)
    ap.add_argument("--radx-starter", required=True)
    ap.add_argument("--radx-engine", required=True)
    ap.add_argument("--deck", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    if shutil.which("strace") is None:
        sys.exit("strace is needed (Debian package strace)")
    shutil.rmtree(a.out, ignore_errors=True)
    base = os.path.basename(a.deck).replace("_0000.rad", "")
    env = dict(os.environ, OMP_NUM_THREADS="1")

    def folder(name):
        out = os.path.abspath(os.path.join(a.out, name))
        os.makedirs(out)
        s = subprocess.run([a.radx_starter, a.deck, "--out", out], capture_output=True, text=True)
        if s.returncode != 0:
            sys.exit("starter failed:\n" + s.stdout[-2000:] + s.stderr[-2000:])
        src = a.deck.replace("_0000.rad", "_0001.rad")
        return out, write_engine_deck(src, os.path.join(out, os.path.basename(src)), t_stop=1e30, th_dt=0.0,
                                      anim_dt=1e30)

    def engine(out, deck, inject):
        th = os.path.join(out, base + "_th.h5")
        cmd = ["strace", "-f", "-qq", "-P", th, "-e", "trace=pwrite64,fsync", "-e", inject,
               a.radx_engine, deck, "--out", out, "--no-plot"]
        try:
            return subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=120)
        except subprocess.TimeoutExpired:
            return None

    # Calibration: each in-place flush ends with an fsync of the file (the first flush's is of the .part).
    # Killed at the second: the pwrites before it are those of the first two in-place flushes.
    out, deck = folder("calibration")
    cal = engine(out, deck, "inject=fsync:signal=SIGKILL:when=2")
    check(cal is not None, "the calibration run did not reach a second in-place flush in 120 s")
    lines = cal.stderr.splitlines() if cal else []
    first = next((i for i, l in enumerate(lines) if "fsync(" in l), len(lines))
    n1 = len([l for l in lines[:first] if "pwrite64(" in l])
    n2 = len([l for l in lines if "pwrite64(" in l])
    check(0 < n1 < n2, "calibration: %d pwrites in the first flush, %d in two" % (n1, n2))
    sweep = list(range(1, n2 + 1))
    print("the first two in-place flushes make %d and %d pwrites; %d kills" % (n1, n2 - n1, len(sweep)))

    outcomes = {"rows": 0, "refused": 0}

    def one(out, deck, n):
        th = os.path.join(out, base + "_th.h5")
        r = engine(out, deck, "inject=pwrite64:signal=SIGKILL:when=%d" % n)
        if r is None:
            check(False, "N=%d: the engine was not killed within 120 s" % n)
            return
        rows, why = h5py_rows(th)
        t = subprocess.run([a.radx, "th", th], capture_output=True, text=True)
        listed = re.findall(r"rows:\s+(\d+)", t.stdout)
        if rows is not None:
            outcomes["rows"] += 1
            check(t.returncode == 0 and listed and all(int(x) == rows for x in listed),
                  "N=%d: h5py reads %d rows, radx th (exit %d) lists %s: %s"
                  % (n, rows, t.returncode, listed, t.stderr[-500:]))
            return
        outcomes["refused"] += 1
        check("open for write" in why, "N=%d: h5py reads no consistent history: %s" % (n, why))
        check(t.returncode == 0 and "killed" in t.stderr and "--recover" in t.stderr and listed
              and len(set(listed)) == 1,
              "N=%d: radx th (exit %d, rows %s) does not read the file and say it was killed while written: %s"
              % (n, t.returncode, listed, t.stderr[-500:]))
        c = subprocess.run([a.radx, "th", th, "--recover"], capture_output=True, text=True)
        check(c.returncode == 0, "N=%d: radx th --recover failed: %s" % (n, c.stderr[-500:]))
        rows, why = h5py_rows(th)
        check(rows is not None and listed and rows == int(listed[0]),
              "N=%d: after radx th --recover h5py reads %s rows (%s), radx th listed %s" % (n, rows, why, listed))

    # Two at a time, each in its own folder.
    workers = [folder("worker_%d" % k) for k in range(2)]

    def run_part(k):
        for n in sweep[k::2]:
            one(workers[k][0], workers[k][1], n)

    with concurrent.futures.ThreadPoolExecutor(2) as pool:
        list(pool.map(run_part, range(2)))
    writes = sweep
    print("kills at %d pwrites: %d left a readable history, %d a refused one"
          % (len(writes), outcomes["rows"], outcomes["refused"]))
    finish("a SIGKILL at any write of a time-history flush leaves the rows of a completed flush or a refusal")


if __name__ == "__main__":
    main()
