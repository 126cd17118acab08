"""`radx-engine --decompose 3` on a sample deck, checked from its own files.

usage: check_decompose.py --starter EXE --engine EXE --deck NAME_0000.rad --out DIR

  * the starter writes the model; `radx-engine --decompose 3` exits 0 and prints a table per rank;
  * NAME_domain.hdf (read with h5py): `domain` in 0..2 on every cell, a group's cells on one rank, the cells
    per rank equal to the table's elements;
  * owned, ghost and shared nodes per rank, the neighbours and the total shared nodes recounted here from the
    mesh's connectivity (owner: the rank with the most element entries on the node, ties to the lowest rank),
    and the file's node_owner equal to that;
  * ParaView (pvpython, under xvfb-run -a when there is one) opens the file with its VTKHDF reader and sees the
    cell array `domain` with range [0, 2];
  * --partition with the written NAME_partition.txt edited (every group on rank 0 but the last two, on ranks
    1 and 2) gives that assignment; a damaged file is refused with RX807 and a line number, and so is one that
    leaves a rank without a group; P above the group count is refused with RX806; none leaves a file behind.
Exit 0 on success, 1 with FAIL lines otherwise.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
from collections import defaultdict

import h5py
import numpy as np

P = 3
failures = []


def check(ok, message):
    if not ok:
        failures.append(message)
        print("FAIL:", message)


def run(cmd):
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    return r.returncode, r.stdout, r.stderr


def parse_table(text):
    """rank -> dict of the table's columns; and the 'shared nodes:' total."""
    rows = {}
    for line in text.splitlines():
        f = line.split()
        if len(f) == 9 and f[0].isdigit():
            rows[int(f[0])] = dict(groups=int(f[1]), elements=int(f[2]), cost=int(f[3]), contact=int(f[4]),
                                   owned=int(f[5]), ghosts=int(f[6]), shared=int(f[7]),
                                   neighbours=[] if f[8] == "-" else [int(x) for x in f[8].split(",")])
    m = re.search(r"^shared nodes: (\d+)", text, re.M)
    return rows, int(m.group(1)) if m else None


def recount(conn, offsets, domain, nodes):
    """Per node, the entries of each rank; then owners, and per-rank owned, ghost, shared, neighbours."""
    entries = defaultdict(lambda: defaultdict(int))
    for c in range(len(offsets) - 1):
        for n in conn[offsets[c]:offsets[c + 1]]:
            entries[int(n)][int(domain[c])] += 1
    owner = np.full(nodes, -1, dtype=np.int64)
    owned, ghosts, shared = [0] * P, [0] * P, [0] * P
    neighbours = [set() for _ in range(P)]
    total_shared = 0
    for n, per_rank in entries.items():
        best = max(per_rank.values())
        owner[n] = min(r for r, c in per_rank.items() if c == best)
        owned[owner[n]] += 1
        if len(per_rank) > 1:
            total_shared += 1
            for r in per_rank:
                shared[r] += 1
                ghosts[r] += r != owner[n]
                neighbours[r] |= set(per_rank) - {r}
    return owner, owned, ghosts, shared, neighbours, total_shared


def paraview_check(path):
    script = (
        "from paraview.simple import OpenDataFile\n"
        f"r = OpenDataFile({path!r})\n"
        "r.UpdatePipeline()\n"
        "a = r.CellData['domain']\n"
        "print('KIND', type(r).__name__)\n"
        "print('RANGE', *a.GetRange())\n")
    cmd = ["pvpython", "-c", script]
    if shutil.which("xvfb-run"):
        cmd = ["xvfb-run", "-a"] + cmd
    env = dict(os.environ, QT_QPA_PLATFORM="offscreen")
    for _ in range(3):  # xvfb-run -a: two tests may pick the same display; try again on another
        r = subprocess.run(cmd, capture_output=True, text=True, timeout=600, env=env)
        if "bad X server connection" not in r.stdout + r.stderr:
            break
    kind = re.search(r"^KIND (\S+)", r.stdout, re.M)
    rng = re.search(r"^RANGE (\S+) (\S+)", r.stdout, re.M)
    check(r.returncode == 0 and kind and rng, f"pvpython could not open {path}: {r.stdout[-2000:]} {r.stderr[-2000:]}")
    if kind and rng:
        check(kind.group(1) == "VTKHDFReader", f"ParaView picked {kind.group(1)}, expected its VTKHDF reader")
        check((float(rng.group(1)), float(rng.group(2))) == (0.0, float(P - 1)),
              f"ParaView's domain range {rng.group(1)}..{rng.group(2)}, expected 0..{P - 1}")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--starter", required=True)
    ap.add_argument("--engine", required=True)
    ap.add_argument("--deck", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    shutil.rmtree(a.out, ignore_errors=True)
    os.makedirs(a.out)
    root = os.path.basename(a.deck)[:-len("_0000.rad")]
    engine_deck = a.deck.replace("_0000.rad", "_0001.rad")
    code, out, err = run([a.starter, a.deck, "--out", a.out])
    if code != 0:
        print("FAIL: the starter failed:", out[-2000:], err[-2000:])
        return 1

    code, out, err = run([a.engine, "--decompose", str(P), engine_deck, "--out", a.out])
    print(out)
    check(code == 0, f"--decompose {P} exit {code}: {err[-2000:]}")
    rows, table_shared = parse_table(out)
    check(sorted(rows) == list(range(P)), f"table ranks {sorted(rows)}, expected 0..{P - 1}")
    check(not os.path.exists(os.path.join(a.out, root + "_0001.out")), "--decompose ran the engine (a listing)")
    domain_path = os.path.join(a.out, root + "_domain.hdf")
    with h5py.File(domain_path, "r") as f:
        v = f["VTKHDF"]
        domain = v["CellData/domain"][()]
        group = v["CellData/group"][()]
        node_owner = v["PointData/node_owner"][()]
        conn = v["Connectivity"][()]
        offsets = v["Offsets"][()]
        nodes = int(v["NumberOfPoints"][0])
    check(domain.dtype.kind == "i", f"domain is stored as {domain.dtype}, expected integers")
    check(domain.min() == 0 and domain.max() == P - 1 and set(np.unique(domain)) == set(range(P)),
          f"domain values {np.unique(domain)}, expected every rank 0..{P - 1} on every cell")
    for g in np.unique(group):
        check(len(np.unique(domain[group == g])) == 1, f"group {g} is split over ranks {np.unique(domain[group == g])}")
    for r in range(P):
        cells = int((domain == r).sum())
        check(rows.get(r, {}).get("elements") == cells, f"rank {r}: table {rows.get(r)} elements, file {cells} cells")
        check(rows.get(r, {}).get("groups") == len(np.unique(group[domain == r])), f"rank {r}: group count")
    owner, owned, ghosts, shared, neighbours, total_shared = recount(conn, offsets, domain, nodes)
    check(np.array_equal(owner, node_owner), "node_owner differs from the most-entries owners recounted here")
    check(table_shared == total_shared, f"shared nodes: table {table_shared}, recounted {total_shared}")
    check(total_shared > 0, "3 ranks on one connected mesh must share nodes")
    for r in range(P):
        t = rows.get(r, {})
        got = (t.get("owned"), t.get("ghosts"), t.get("shared"), t.get("neighbours"))
        want = (owned[r], ghosts[r], shared[r], sorted(neighbours[r]))
        check(got == want, f"rank {r}: table owned/ghost/shared/neighbours {got}, recounted {want}")
    paraview_check(domain_path)

    # --partition: the written group ranks, edited.
    ranks_path = os.path.join(a.out, root + "_partition.txt")
    lines = [l for l in open(ranks_path) if l.strip() and not l.startswith("#")]
    groups = len(lines)
    edited = os.path.join(a.out, "edited.txt")
    with open(edited, "w") as f:
        for g in range(groups):
            f.write(f"{g} {max(0, g - (groups - 3))}\n")
    code, out, err = run([a.engine, "--decompose", str(P), "--partition", edited, engine_deck, "--out", a.out])
    check(code == 0, f"--partition exit {code}: {err[-2000:]}")
    with h5py.File(domain_path, "r") as f:
        domain = f["VTKHDF/CellData/domain"][()]
        group = f["VTKHDF/CellData/group"][()]
    check(np.array_equal(domain, np.maximum(0, group - (groups - 3))), "--partition's ranks are not the file's")
    rows, _ = parse_table(out)
    check(rows.get(1, {}).get("groups") == 1, "rank 1 should have one group under the edited ranks")

    # Refusals leave nothing behind.
    os.remove(domain_path)
    os.remove(ranks_path)
    with open(edited, "w") as f:
        f.write("0 0\n0 1\nx y\n")
    code, out, err = run([a.engine, "--decompose", str(P), "--partition", edited, engine_deck, "--out", a.out])
    check(code == 1 and "RX807" in err and "edited.txt:2:" in err and "edited.txt:3:" in err,
          f"a damaged group-rank file: exit {code}, {err[-2000:]}")
    with open(edited, "w") as f:
        f.write("".join(f"{g} {2 if g == groups - 1 else 0}\n" for g in range(groups)))
    code, out, err = run([a.engine, "--decompose", str(P), "--partition", edited, engine_deck, "--out", a.out])
    check(code == 1 and "RX807" in err and "rank(s) 1 of the 3 ranks have no group" in err,
          f"a group-rank file leaving rank 1 idle: exit {code}, {err[-2000:]}")
    code, out, err = run([a.engine, "--decompose", str(groups + 1), engine_deck, "--out", a.out])
    check(code == 1 and "RX806" in err and f"give at most {groups} ranks" in err,
          f"--decompose {groups + 1} (more ranks than groups): exit {code}, {err[-2000:]}")
    check(not os.path.exists(domain_path) and not os.path.exists(ranks_path), "a refused decomposition wrote files")
    check(not any(n.endswith(".part") for n in os.listdir(a.out)), "a .part file was left behind")

    print("OK" if not failures else f"{len(failures)} failure(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
