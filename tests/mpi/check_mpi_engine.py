"""radx-engine-mpi against radx-engine, and what it refuses; the default executables stay free of MPI.

usage: /usr/bin/python3 check_mpi_engine.py --radx-starter EXE --radx-engine EXE --radx-engine-mpi EXE
           --mpirun MPIRUN --out DIR DECK_0000.rad...

  * np 1 is radx-engine: each deck (NAME_0000.rad, its engine deck NAME_0001.rad beside it) runs through the
    starter once, then through `radx-engine --threads 1` and `mpirun -np 1 radx-engine-mpi --threads 1` in two
    folders holding the same model file. Every state (NAME.mesh.hdf, NAME_%06d.hdf), and the time history
    NAME_th.h5 are compared by h5diff without tolerance (exit 0: no value differs in any bit); the energy CSV
    must be the same text; the summaries must be equal apart from timings (keys naming seconds or
    microseconds per element-cycle).
  * On 2 ranks, --version and a usage error are printed once (rank 0 alone speaks). Runs on 2 and 3 ranks,
    and the refusal of what they do not run yet, are tests/mpi/run_np.py's.
  * ldd: radx-engine, radx-starter and radx do not load libmpi; radx-engine-mpi does (so the check can fail).
"""
import argparse
import filecmp
import glob
import json
import os
import shutil
import subprocess
import sys
import time

MPI_FLAGS = ["--allow-run-as-root", "--oversubscribe", "--mca", "mpi_yield_when_idle", "1"]

failures = []


def check(ok, what):
    print(("ok:   " if ok else "FAIL: ") + what)
    if not ok:
        failures.append(what)


def run(cmd, **kw):
    return subprocess.run(cmd, capture_output=True, text=True, timeout=300, **kw)


def timing_free(summary):
    """The summary without what depends on the wall clock."""
    if isinstance(summary, dict):
        return {k: timing_free(v) for k, v in summary.items() if not ("seconds" in k or "us_per" in k)}
    if isinstance(summary, list):
        return [timing_free(v) for v in summary]
    return summary


def same_hdf5(a, b, h5diff):
    r = run([h5diff, "-q", a, b])
    return r.returncode == 0


def compare_np1(a, deck, out, h5diff):
    name = os.path.basename(deck)[: -len("_0000.rad")]
    engine_deck = deck.replace("_0000.rad", "_0001.rad")
    base = os.path.join(out, name)
    shutil.rmtree(base, ignore_errors=True)
    serial, mpi = os.path.join(base, "serial"), os.path.join(base, "mpi")
    r = run([a.radx_starter, deck, "--out", serial])
    check(r.returncode == 0, "%s: starter exit 0 (%s)" % (name, r.stderr.strip()[-300:]))
    os.makedirs(mpi)
    shutil.copy(os.path.join(serial, name + "_0000.hdf"), mpi)
    r1 = run([a.radx_engine, engine_deck, "--out", serial, "--threads", "1", "--no-plot"])
    r2 = run([a.mpirun, *MPI_FLAGS, "-np", "1", a.radx_engine_mpi, engine_deck, "--out", mpi, "--threads", "1",
              "--no-plot"])
    check(r1.returncode == 0 and r2.returncode == 0,
          "%s: radx-engine exit %d, radx-engine-mpi -np 1 exit %d%s" % (name, r1.returncode, r2.returncode,
                                                                       "" if r2.returncode == 0 else ": " + r2.stderr[-500:]))
    states = sorted(os.path.basename(p) for p in glob.glob(os.path.join(serial, name + "*.hdf"))
                    if not p.endswith("_0000.hdf"))
    states_mpi = sorted(os.path.basename(p) for p in glob.glob(os.path.join(mpi, name + "*.hdf"))
                        if not p.endswith("_0000.hdf"))
    check(states == states_mpi and len(states) >= 2,
          "%s: the same %d state files (mesh and states)" % (name, len(states)))
    files = states + [name + "_th.h5"]
    differ = [f for f in files if not same_hdf5(os.path.join(serial, f), os.path.join(mpi, f), a.h5diff)]
    check(not differ, "%s: h5diff without tolerance on %d files%s" % (name, len(files),
                                                                       "" if not differ else "; differ: " + ", ".join(differ)))
    csv = name + "_energy.csv"
    check(filecmp.cmp(os.path.join(serial, csv), os.path.join(mpi, csv), shallow=False),
          "%s: the energy CSV, the same text" % name)
    s1 = json.load(open(os.path.join(serial, name + "_summary.json")))
    s2 = json.load(open(os.path.join(mpi, name + "_summary.json")))
    t1, t2 = timing_free(s1), timing_free(s2)
    diff = sorted(k for k in set(t1) | set(t2) if t1.get(k) != t2.get(k))
    check(not diff and s1.get("status") == "normal",
          "%s: summaries equal apart from timings (status %s, %s cycles)%s"
          % (name, s1.get("status"), s1.get("cycles"), "" if not diff else "; differ in " + ", ".join(diff)))


def check_rank0_speaks(a):
    # The other ranks parse the same options in silence: --version once, a usage error once and exit 2.
    r = run([a.mpirun, *MPI_FLAGS, "-np", "2", a.radx_engine_mpi, "--version"])
    check(r.returncode == 0 and r.stdout.count("radx-engine-mpi ") == 1,
          "np 2: --version printed once (exit %d): %s" % (r.returncode, r.stdout.strip()))
    r = run([a.mpirun, *MPI_FLAGS, "-np", "2", a.radx_engine_mpi, "--no-such-option"])
    check(r.returncode == 2 and r.stderr.count("unknown option --no-such-option") == 1,
          "np 2: a usage error said once, exit 2 (exit %d)" % r.returncode)


def check_one_rank_fails_alone(a, deck, out):
    # Rank 0 alone cannot claim the output folder (another process holds its lock); ranks 1 and 2 set up in
    # their scratch folders and go on to the engine's first collective. Before the abort on a rank's own
    # failure they waited there for good: the run must end on every rank within seconds, non-zero, with the
    # lock's message and what it does to the other ranks.
    name = os.path.basename(deck)[: -len("_0000.rad")]
    engine_deck = deck.replace("_0000.rad", "_0001.rad")
    serial = os.path.join(out, name, "serial")
    locked = os.path.join(out, name, "locked")
    shutil.rmtree(locked, ignore_errors=True)
    os.makedirs(locked)
    shutil.copy(os.path.join(serial, name + "_0000.hdf"), locked)
    holder = subprocess.Popen(["flock", os.path.join(locked, name + ".lock"), "sleep", "60"])
    try:
        time.sleep(0.5)
        t0 = time.monotonic()
        try:
            r = subprocess.run(["timeout", "30", a.mpirun, *MPI_FLAGS, "-np", "3", a.radx_engine_mpi, engine_deck,
                                "--out", locked, "--threads", "1", "--no-plot"],
                               capture_output=True, text=True, timeout=60)
            code, err = r.returncode, r.stderr
        except subprocess.TimeoutExpired:
            code, err = 124, ""
        seconds = time.monotonic() - t0
    finally:
        holder.kill()
        holder.wait()
    check(code not in (0, 124) and seconds < 20,
          "np 3, rank 0's folder locked: every rank ends (exit %d after %.1f s, limit 20 s)" % (code, seconds))
    check("is running " + name in err and "ends the run on every rank" in err,
          "np 3, rank 0's folder locked: the lock and the end of every rank are said: %s" % err.strip()[-400:])
    check(not glob.glob(os.path.join(locked, name + "*.hdf.series")),
          "np 3, rank 0's folder locked: no results written")


def libraries(exe):
    r = run(["ldd", exe])
    return r.stdout


def main():
    ap = argparse.ArgumentParser()
    for opt in ("--radx-starter", "--radx-engine", "--radx-engine-mpi", "--radx", "--mpirun", "--out"):
        ap.add_argument(opt, required=True)
    ap.add_argument("--h5diff", default="h5diff")
    ap.add_argument("decks", nargs="+")
    a = ap.parse_args()
    for deck in a.decks:
        compare_np1(a, deck, a.out, a.h5diff)
    check_rank0_speaks(a)
    check_one_rank_fails_alone(a, a.decks[0], a.out)
    for exe in (a.radx_engine, a.radx_starter, a.radx):
        check("libmpi" not in libraries(exe), "ldd %s: no libmpi" % os.path.basename(exe))
    check("libmpi" in libraries(a.radx_engine_mpi), "ldd radx-engine-mpi: libmpi (the ldd check can see MPI)")
    if failures:
        print("%d check(s) failed" % len(failures))
        sys.exit(1)
    print("all checks passed")


if __name__ == "__main__":
    main()
