"""radx-engine-mpi on 1, 2 and 3 ranks against radx-engine, to the bit (docs/parallel.md).

usage: /usr/bin/python3 run_np.py --radx-starter EXE --radx-engine EXE --radx-engine-mpi EXE --mpirun MPIRUN
           --out DIR [--np 1,2,3] [--impact N --generator GEN_SHELL_PLATE_PY] [--refused DECK_0000.rad]...
           DECK_0000.rad...

  * Each deck (NAME_0000.rad, its engine deck NAME_0001.rad beside it) runs through the starter once, then
    through `radx-engine --threads 1` and `mpirun -np P radx-engine-mpi --threads 1` for each P, each in its
    own folder holding the same model file. Every state (NAME.mesh.hdf, NAME_%06d.hdf) and the time history
    NAME_th.h5 (where the deck asks for one) are compared by h5diff without tolerance (exit 0: no value
    differs in any bit); the energy CSV
    must be the same text; the summaries equal apart from timings (keys naming seconds or microseconds per
    element-cycle) and the thread and rank counts.
  * --impact N adds the impact benchmark's deck (bench/gen_shell_plate.py --n N --impact, 0.5 ms): an N x N
    shell plate and a brick block in many groups of 128 elements, so that many nodes are shared by groups of
    different ranks (the sample decks are mostly one group or two); and the same model without contact, its
    time history watching nodes over the plate and the moving block: no node is then kept whole on every
    rank, so this is where the owned-node passes, the ghost updates and the time-history cycles' partial
    gather on rank 0 show.
  * Each --refused deck uses a feature not yet run on more than one rank: at np 2 mpirun exits 1, rank 0
    alone names the feature ("cannot be split over 2 ranks yet"), and the folder holds nothing but the model.
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
REFUSAL = "cannot be split over 2 ranks yet"

failures = []


def check(ok, what):
    print(("ok:   " if ok else "FAIL: ") + what, flush=True)
    if not ok:
        failures.append(what)


def finish():
    """Ends the script: exit 1 with the count when a check failed."""
    if failures:
        print("%d check(s) failed" % len(failures))
        sys.exit(1)
    print("all checks passed")


def run(cmd):
    return subprocess.run(cmd, capture_output=True, text=True, timeout=600)


def timing_free(summary):
    """The summary without what depends on the wall clock."""
    if isinstance(summary, dict):
        return {k: timing_free(v) for k, v in summary.items() if not ("seconds" in k or "us_per" in k)}
    if isinstance(summary, list):
        return [timing_free(v) for v in summary]
    return summary


def watch_nodes(deck, n):
    """Replaces the deck's /TH/NODE node list by nodes spread over the plate (ids 1 .. (n + 1)^2, at rest
    without contact) and over the moving block (the deck's other nodes)."""
    with open(deck) as f:
        lines = f.read().split("\n")
    ids, in_nodes = [], False
    for line in lines:
        if line.startswith("/"):
            in_nodes = line.startswith("/NODE")
        elif in_nodes and line.split() and line.split()[0].isdigit():
            ids.append(int(line.split()[0]))
    side = n + 1
    step = max(1, n // 4)
    plate = {1 + i * side + j for i in range(0, side, step) for j in range(0, side, step)}
    block = [i for i in ids if i > side * side]
    watched = sorted(plate | set(block[:: max(1, len(block) // 12)]))
    start = lines.index("/TH/NODE/1")
    end = next(i for i in range(start + 1, len(lines)) if lines[i].startswith("/"))
    body = [l for l in lines[start:end] if l.startswith("#") or not l[:1].isdigit() and not l.startswith(" ")]
    lines[start:end] = body + ["%10d%10d" % (i, 0) for i in watched]
    with open(deck, "w") as f:
        f.write("\n".join(lines))


def names(deck):
    name = os.path.basename(deck)[: -len("_0000.rad")]
    return name, deck.replace("_0000.rad", "_0001.rad")


def compare(a, deck):
    name, engine_deck = names(deck)
    base = os.path.join(a.out, name)
    shutil.rmtree(base, ignore_errors=True)
    serial = os.path.join(base, "serial")
    r = run([a.radx_starter, deck, "--out", serial])
    check(r.returncode == 0, "%s: starter exit 0 (%s)" % (name, r.stderr.strip()[-300:]))
    t0 = time.time()
    r = run([a.radx_engine, engine_deck, "--out", serial, "--threads", "1", "--no-plot"])
    check(r.returncode == 0, "%s: radx-engine exit %d %s" % (name, r.returncode, r.stderr.strip()[-300:]))
    serial_seconds = time.time() - t0
    states = sorted(os.path.basename(p) for p in glob.glob(os.path.join(serial, name + "*.hdf"))
                    if not p.endswith("_0000.hdf"))
    s1 = timing_free(json.load(open(os.path.join(serial, name + "_summary.json"))))
    for np_ in a.np:
        mpi = os.path.join(base, "np%d" % np_)
        os.makedirs(mpi)
        shutil.copy(os.path.join(serial, name + "_0000.hdf"), mpi)
        t0 = time.time()
        r = run([a.mpirun, *MPI_FLAGS, "-np", str(np_), a.radx_engine_mpi, engine_deck, "--out", mpi,
                 "--threads", "1", "--no-plot"])
        seconds = time.time() - t0
        check(r.returncode == 0, "%s np %d: exit %d (%.1f s, serial %.1f s)%s" % (
            name, np_, r.returncode, seconds, serial_seconds, "" if r.returncode == 0 else ": " + r.stderr[-500:]))
        here = sorted(os.path.basename(p) for p in glob.glob(os.path.join(mpi, name + "*.hdf"))
                      if not p.endswith("_0000.hdf"))
        check(here == states and len(states) >= 2, "%s np %d: the same %d state files" % (name, np_, len(states)))
        th = [name + "_th.h5"] if os.path.exists(os.path.join(serial, name + "_th.h5")) else []
        check(os.path.exists(os.path.join(mpi, name + "_th.h5")) == bool(th),
              "%s np %d: a time history where one rank writes one" % (name, np_))
        files = states + th
        differ = [f for f in files
                  if run([a.h5diff, "-q", os.path.join(serial, f), os.path.join(mpi, f)]).returncode != 0]
        check(not differ, "%s np %d: h5diff without tolerance on %d files%s" % (
            name, np_, len(files), "" if not differ else "; differ: " + ", ".join(differ)))
        csv = name + "_energy.csv"
        check(filecmp.cmp(os.path.join(serial, csv), os.path.join(mpi, csv), shallow=False),
              "%s np %d: the energy CSV, the same text" % (name, np_))
        s2 = timing_free(json.load(open(os.path.join(mpi, name + "_summary.json"))))
        diff = sorted(k for k in set(s1) | set(s2) if s1.get(k) != s2.get(k))
        check(not diff and s1.get("status") == "normal", "%s np %d: summaries equal apart from timings "
              "(status %s, %s cycles)%s" % (name, np_, s1.get("status"), s1.get("cycles"),
                                            "" if not diff else "; differ in " + ", ".join(diff)))
        others = [p for p in os.listdir(mpi) if p.startswith("radx-rank-")]
        check(not others, "%s np %d: no scratch folder left in the output folder" % (name, np_))


def check_refused(a, deck):
    name, engine_deck = names(deck)
    folder = os.path.join(a.out, name + "_refused")
    shutil.rmtree(folder, ignore_errors=True)
    r = run([a.radx_starter, deck, "--out", folder])
    check(r.returncode == 0, "%s: starter exit 0" % name)
    before = sorted(os.listdir(folder))
    r = run([a.mpirun, *MPI_FLAGS, "-np", "2", a.radx_engine_mpi, engine_deck, "--out", folder, "--threads", "1"])
    said = (r.stdout + r.stderr).count(REFUSAL)
    check(r.returncode == 1, "%s np 2 refused: mpirun exit %d (want 1)" % (name, r.returncode))
    check(said == 1, "%s np 2: the refusal said once, by rank 0 (said %d times): %s" % (
        name, said, r.stderr.strip()[:400]))
    check(sorted(os.listdir(folder)) == before, "%s np 2: nothing written beside the model" % name)


def main():
    ap = argparse.ArgumentParser()
    for opt in ("--radx-starter", "--radx-engine", "--radx-engine-mpi", "--mpirun", "--out"):
        ap.add_argument(opt, required=True)
    ap.add_argument("--h5diff", default="h5diff")
    ap.add_argument("--np", default="1,2,3")
    ap.add_argument("--refused", action="append", default=[])
    ap.add_argument("--impact", type=int, default=0)
    ap.add_argument("--generator")
    ap.add_argument("decks", nargs="*")
    a = ap.parse_args()
    a.np = [int(p) for p in a.np.split(",")]
    if a.impact > 0:
        gen = os.path.join(a.out, "generated")
        shutil.rmtree(gen, ignore_errors=True)
        os.makedirs(gen)
        r = run(["/usr/bin/python3", a.generator, "--n", str(a.impact), "--impact", "--tstop", "0.0005", "--out", gen])
        check(r.returncode == 0, "the impact deck generated (%s)" % r.stderr.strip()[-300:])
        a.decks.append(os.path.join(gen, "PLATE%dI_0000.rad" % a.impact))
        # Without contact no node is kept whole on every rank: each rank integrates its own, and on the
        # time-history cycles rank 0 gathers only their motion and the watched nodes' whole state. The
        # time history watches nodes all over the plate and the block, so that other ranks own some.
        r = run(["/usr/bin/python3", a.generator, "--n", str(a.impact), "--impact", "--contact", "none",
                 "--th-records", "40", "--anim-states", "3", "--tstop", "0.0005", "--out", gen])
        check(r.returncode == 0, "the contact-free impact deck generated (%s)" % r.stderr.strip()[-300:])
        free = os.path.join(gen, "PLATE%dI_NOCONTACT_0000.rad" % a.impact)
        watch_nodes(free, a.impact)
        a.decks.append(free)
    for deck in a.decks:
        compare(a, deck)
    for deck in a.refused:
        check_refused(a, deck)
    finish()


if __name__ == "__main__":
    main()
