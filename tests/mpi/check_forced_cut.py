"""A rigid body and a TYPE2 tie cut by the partition on purpose: radx-engine-mpi --partition FILE on 2 and 3
ranks against radx-engine, to the bit (docs/parallel.md); and bad group-rank files refused on every rank.

usage: /usr/bin/python3 check_forced_cut.py --radx-starter EXE --radx-engine EXE --radx-engine-mpi EXE
           --mpirun MPIRUN --out DIR [--errors]

The deck is generated (gen_cut_deck.py beside this file): a bar in three parts of one element group each,
the root tied by /INTER/TYPE2 to the tip, and one /RBODY over the tip's end nodes and the clamp's nodes.

  * For P = 2 and 3 a group-rank file puts the parts on ranks so that the tie's secondary nodes (the tip's)
    and main nodes (the root's) and the body's nodes (the tip's and the clamp's) have different owners. The
    cut is checked from `radx-engine --decompose P --partition FILE`: its table says 1 rigid body and every
    tied node cut, and its NAME_domain.hdf gives each cell the file's rank and the body's and the tie's
    nodes owners on more than one rank (the node owners are the engine's: solver/parallel/domain.hpp). A
    control file that keeps the body on one rank must make that check fail, so it can.
  * Then `mpirun -np P radx-engine-mpi --partition FILE --threads 1` runs the deck, says it takes the file's
    ranks, and every state and the time history are radx-engine's by h5diff without tolerance, the energy
    CSV the same text and the summaries equal apart from timings.
  * --errors: files for the wrong rank count (3 ranks on 2, 2 ranks on 3), with a group missing, with a rank
    out of range, and a file that is not there: mpirun exits 1, every rank exits 1 (each rank's code printed
    by a shell around it, in a second run), rank 0 alone says RX807 once with the file (and the line where there is one) and the summary
    line once, within 20 s, and the output folder, holding an earlier run's results, is left as it was.
    radx-engine (one rank) refuses a file naming rank 1 the same way.
Exit 0 on success, 1 with FAIL lines otherwise.
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

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import gen_cut_deck as gen  # noqa: E402  (the deck's node numbering: which nodes the body and the tie hold)
from run_np import MPI_FLAGS, check, failures, finish, timing_free  # noqa: E402

ROOT = gen.ROOT
# Part -> rank: the root, the tip and the clamp on different ranks where P allows (P = 2: root and clamp
# together, still apart from the tip).
PLANS = {2: {1: 0, 2: 1, 3: 0}, 3: {1: 0, 2: 1, 3: 2}}
CONTROL = {1: 0, 2: 1, 3: 1}  # the tip and the clamp together: the body is not cut
BODY_NODES = gen.TIP_BLOCK.face(gen.TIP_BLOCK.nx) + [n for n, *_ in gen.CLAMP_BLOCK.nodes()]
TIED_NODES = gen.TIP_BLOCK.face(0)
MAIN_NODES = gen.ROOT_BLOCK.face(gen.ROOT_BLOCK.nx)
REFUSAL = "error(s) in the group-rank file"


def run(cmd, timeout=600):
    return subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)


def mpirun(a, np_, *args):
    return [a.mpirun, *MPI_FLAGS, "-np", str(np_), *args]


def group_parts(domain_path):
    """Each flat group's part id, from a domain file's cells."""
    with h5py.File(domain_path, "r") as f:
        group = f["VTKHDF/CellData/group"][()]
        part = f["VTKHDF/CellData/part_id"][()]
    return {int(g): int(p) for g, p in zip(group, part) if g >= 0}


def write_ranks(path, parts, plan):
    with open(path, "w") as f:
        f.write("# GROUP RANK (check_forced_cut.py: part -> rank %s)\n" % plan)
        for g in sorted(parts):
            f.write("%d %d\n" % (g, plan[parts[g]]))


def decompose(a, folder, np_, ranks_file=None):
    cmd = [a.radx_engine, "--decompose", str(np_), os.path.join(a.deck_dir, ROOT + "_0001.rad"), "--out", folder]
    return run(cmd + (["--partition", ranks_file] if ranks_file else []))


def cut_seen(folder):
    """From a decomposition's domain file: (body nodes' owner ranks, tied nodes' owners, main nodes' owners)."""
    with h5py.File(os.path.join(folder, ROOT + "_domain.hdf"), "r") as f:
        owner = dict(zip(f["VTKHDF/PointData/node_id"][()].tolist(), f["VTKHDF/PointData/node_owner"][()].tolist()))
    return ({owner[n] for n in BODY_NODES}, {owner[n] for n in TIED_NODES}, {owner[n] for n in MAIN_NODES})


def is_cut(seen):
    body, tied, main = seen
    return len(body) > 1 and not (tied & main)


def check_cut(a, folder, np_, ranks_file, plan):
    r = decompose(a, folder, np_, ranks_file)
    check(r.returncode == 0, "np %d: --decompose --partition exit %d %s" % (np_, r.returncode, r.stderr[-300:]))
    check("rigid bodies cut: 1;" in r.stdout and "TYPE2 ties cut: %d" % len(TIED_NODES) in r.stdout,
          "np %d: the table says the body and all %d tied nodes are cut" % (np_, len(TIED_NODES)))
    with h5py.File(os.path.join(folder, ROOT + "_domain.hdf"), "r") as f:
        domain = f["VTKHDF/CellData/domain"][()]
        part = f["VTKHDF/CellData/part_id"][()]
    check(np.array_equal(domain, np.array([plan[int(p)] for p in part])), "np %d: every cell on its part's rank "
          "as the file says" % np_)
    seen = cut_seen(folder)
    check(is_cut(seen), "np %d: body node owners %s, tied node owners %s, main node owners %s" % (
        np_, sorted(seen[0]), sorted(seen[1]), sorted(seen[2])))


def compare_run(a, serial, np_, ranks_file):
    mpi = os.path.join(a.out, "np%d" % np_)
    os.makedirs(mpi)
    shutil.copy(os.path.join(serial, ROOT + "_0000.hdf"), mpi)
    r = run(mpirun(a, np_, a.radx_engine_mpi, os.path.join(a.deck_dir, ROOT + "_0001.rad"), "--partition",
                   ranks_file, "--out", mpi, "--threads", "1", "--no-plot"))
    check(r.returncode == 0, "np %d --partition: exit %d %s" % (np_, r.returncode, r.stderr[-500:]))
    check("the element groups go to the ranks %s gives (--partition)" % ranks_file in r.stdout,
          "np %d: the run says it takes the file's ranks" % np_)
    states = sorted(os.path.basename(p) for p in glob.glob(os.path.join(serial, ROOT + "*.hdf"))
                    if not p.endswith("_0000.hdf") and not p.endswith("_domain.hdf"))
    here = sorted(os.path.basename(p) for p in glob.glob(os.path.join(mpi, ROOT + "*.hdf"))
                  if not p.endswith("_0000.hdf"))
    check(here == states and len(states) >= 5, "np %d: the same %d state files" % (np_, len(states)))
    files = states + [ROOT + "_th.h5"]
    differ = [f for f in files if run([a.h5diff, "-q", os.path.join(serial, f), os.path.join(mpi, f)]).returncode != 0]
    check(not differ, "np %d: h5diff without tolerance on %d files%s" % (
        np_, len(files), "" if not differ else "; differ: " + ", ".join(differ)))
    csv = ROOT + "_energy.csv"
    check(filecmp.cmp(os.path.join(serial, csv), os.path.join(mpi, csv), shallow=False),
          "np %d: the energy CSV, the same text" % np_)
    s1 = timing_free(json.load(open(os.path.join(serial, ROOT + "_summary.json"))))
    s2 = timing_free(json.load(open(os.path.join(mpi, ROOT + "_summary.json"))))
    diff = sorted(k for k in set(s1) | set(s2) if s1.get(k) != s2.get(k))
    check(not diff and s1.get("status") == "normal" and s1.get("cycles", 0) >= 200,
          "np %d: summaries equal apart from timings (status %s, %s cycles)%s" % (
              np_, s1.get("status"), s1.get("cycles"), "" if not diff else "; differ in " + ", ".join(diff)))


def forced_cut(a, serial):
    for np_, plan in sorted(PLANS.items()):
        folder = os.path.join(a.out, "decompose%d" % np_)
        os.makedirs(folder)
        shutil.copy(os.path.join(serial, ROOT + "_0000.hdf"), folder)
        r = decompose(a, folder, np_)  # METIS's, for the group numbering only
        check(r.returncode == 0, "np %d: --decompose exit %d %s" % (np_, r.returncode, r.stderr[-300:]))
        parts = group_parts(os.path.join(folder, ROOT + "_domain.hdf"))
        check(sorted(set(parts.values())) == [1, 2, 3], "np %d: groups of parts %s" % (np_, sorted(set(parts.values()))))
        ranks_file = os.path.join(a.out, "cut_np%d.txt" % np_)
        write_ranks(ranks_file, parts, plan)
        if np_ == 2:
            control = os.path.join(a.out, "body_kept_np2.txt")
            write_ranks(control, parts, CONTROL)
            r = decompose(a, folder, np_, control)
            check(r.returncode == 0 and "rigid bodies cut: 0;" in r.stdout and not is_cut(cut_seen(folder)),
                  "np 2 control: the body kept on one rank is not seen as cut")
        check_cut(a, folder, np_, ranks_file, plan)
        compare_run(a, serial, np_, ranks_file)


def folder_state(folder):
    return {n: (os.stat(os.path.join(folder, n)).st_mtime_ns, os.path.getsize(os.path.join(folder, n)))
            for n in sorted(os.listdir(folder))}


def refused(a, serial, name, np_, ranks_file, codes, lines=()):
    """A run on np_ ranks with a bad file: every rank exits 1, rank 0 says it once, nothing is written."""
    folder = os.path.join(a.out, "refused_" + name)
    shutil.copytree(serial, folder)  # an earlier run's results, which a started run would remove
    before = folder_state(folder)
    deck = os.path.join(a.deck_dir, ROOT + "_0001.rad")
    args = [deck, "--partition", ranks_file, "--out", folder, "--threads", "1"]
    on_mpi = np_ > 0
    cmd = mpirun(a, np_, a.radx_engine_mpi, *args) if on_mpi else [a.radx_engine, *args]
    t0 = time.time()
    try:
        r = run(cmd, timeout=60)
    except subprocess.TimeoutExpired:
        check(False, "%s: the refusal hung (no end within 60 s)" % name)
        return
    seconds = time.time() - t0
    said = r.stdout + r.stderr
    if on_mpi:
        # Each rank's exit code, said by a shell around it that exits 0, so that mpirun lets every rank
        # finish (it kills the others when one exits non-zero).
        shell = '"$@"; echo "rank-exit ${OMPI_COMM_WORLD_RANK} $?"'
        try:
            w = run(mpirun(a, np_, "/bin/sh", "-c", shell, "sh", a.radx_engine_mpi, *args), timeout=60).stdout
        except subprocess.TimeoutExpired:
            w = "(no end within 60 s)"
        exits = sorted(line.split()[1:] for line in w.splitlines() if line.startswith("rank-exit "))
        check(exits == [[str(k), "1"] for k in range(np_)], "%s: every rank exits 1 (%s)" % (name, exits))
    check(r.returncode == 1, "%s: exit %d (want 1)" % (name, r.returncode))
    check(said.count("RX807") == codes and said.count(REFUSAL) == 1 and
          ("%s %s" % (REFUSAL, ranks_file)) in said,
          "%s: RX807 said %d time(s) (want %d) and the summary once, naming the file%s" % (
              name, said.count("RX807"), codes, "" if said.count("RX807") == codes else ": " + said[:600]))
    for line in lines:
        check("%s:%d: error: RX807" % (ranks_file, line) in said, "%s: the error names line %d" % (name, line))
    check(seconds < 20, "%s: ended in %.1f s (want < 20)" % (name, seconds))
    check(folder_state(folder) == before, "%s: the output folder is left as it was" % name)


def errors(a, serial):
    folder = os.path.join(a.out, "decompose_errors")
    os.makedirs(folder)
    shutil.copy(os.path.join(serial, ROOT + "_0000.hdf"), folder)
    check(decompose(a, folder, 3).returncode == 0, "--decompose 3 for the group numbering")
    parts = group_parts(os.path.join(folder, ROOT + "_domain.hdf"))
    group_of = {p: g for g, p in parts.items()}
    files = {}
    for name, plan in (("np2", PLANS[2]), ("np3", PLANS[3])):
        files[name] = os.path.join(a.out, "ranks_%s.txt" % name)
        write_ranks(files[name], parts, plan)
    # The header comment is line 1, group g on line g + 2.
    clamp_line = group_of[3] + 2
    files["missing"] = os.path.join(a.out, "ranks_missing.txt")
    with open(files["np2"]) as f:
        kept = [line for k, line in enumerate(f, 1) if k != clamp_line]
    with open(files["missing"], "w") as f:
        f.writelines(kept)
    files["range"] = os.path.join(a.out, "ranks_range.txt")
    with open(files["np2"]) as f:
        text = f.read().splitlines()
    text[clamp_line - 1] = "%d 7" % group_of[3]
    with open(files["range"], "w") as f:
        f.write("\n".join(text) + "\n")
    refused(a, serial, "3-rank file on 2 ranks", 2, files["np3"], 1, [clamp_line])
    refused(a, serial, "2-rank file on 3 ranks", 3, files["np2"], 1)
    refused(a, serial, "a group missing", 2, files["missing"], 1)
    refused(a, serial, "a rank out of range", 2, files["range"], 1, [clamp_line])
    refused(a, serial, "no such file", 2, os.path.join(a.out, "no_such_file.txt"), 1)
    refused(a, serial, "radx-engine, a 2-rank file", 0, files["np2"], 1, [group_of[2] + 2])


def main():
    ap = argparse.ArgumentParser()
    for opt in ("--radx-starter", "--radx-engine", "--radx-engine-mpi", "--mpirun", "--out"):
        ap.add_argument(opt, required=True)
    ap.add_argument("--h5diff", default="h5diff")
    ap.add_argument("--errors", action="store_true", help="check the refusals of bad group-rank files instead")
    a = ap.parse_args()
    shutil.rmtree(a.out, ignore_errors=True)
    a.deck_dir = os.path.join(a.out, "deck")
    r = run(["/usr/bin/python3", os.path.join(HERE, "gen_cut_deck.py"), "--out", a.deck_dir])
    check(r.returncode == 0, "the deck generated (%s)" % r.stderr.strip()[-300:])
    serial = os.path.join(a.out, "serial")
    r = run([a.radx_starter, os.path.join(a.deck_dir, ROOT + "_0000.rad"), "--out", serial])
    check(r.returncode == 0 and "0 warning(s)" in r.stdout, "starter exit 0 without warnings%s" % (
        "" if r.returncode == 0 and "0 warning(s)" in r.stdout else ": " + (r.stdout + r.stderr).strip()[-400:]))
    r = run([a.radx_engine, os.path.join(a.deck_dir, ROOT + "_0001.rad"), "--out", serial, "--threads", "1",
             "--no-plot"])
    check(r.returncode == 0, "radx-engine exit %d %s" % (r.returncode, r.stderr.strip()[-300:]))
    if not failures:
        (errors if a.errors else forced_cut)(a, serial)
    finish()


if __name__ == "__main__":
    main()
