#!/usr/bin/python3
"""User ids beyond 32 bits keep their value in the mesh ParaView opens.

usage: /usr/bin/python3 check_big_ids.py --radx-starter EXE --out DIR

A one-brick deck whose part id is 3e9, node ids 2^31 + 1 .. 2^31 + 8 and element id 2^32 + 7 goes through
the starter; the model file's /VTKHDF/CellData/part_id, element_id and PointData/node_id, read with h5py,
are 64-bit integers holding exactly those ids (integers: equality is exact).
"""
import argparse
import os
import subprocess
import sys

import h5py
import numpy as np

PART = 3_000_000_000
ELEMENT = 2**32 + 7
NODES = [2**31 + k for k in range(1, 9)]


def deck():
    c = [(0, 0, 0), (10, 0, 0), (10, 10, 0), (0, 10, 0), (0, 0, 10), (10, 0, 10), (10, 10, 10), (0, 10, 10)]
    lines = ["/BEGIN", "BIG_IDS", "      2026",
             "                  Mg                  mm                   s",
             "                  Mg                  mm                   s", "/NODE"]
    lines += ["%10d%20.1f%20.1f%20.1f" % (n, *x) for n, x in zip(NODES, c)]
    lines += ["/BRICK/%d" % PART, "%10d" % ELEMENT + "".join("%10d" % n for n in NODES)]
    lines += ["/PART/%d" % PART, "Part with a 3e9 id", "%10d%10d%10d" % (1, 1, 0)]
    lines += ["/PROP/SOLID/1", "solid", "%10d" % 0, "%20.1f" % 0.0, "%20.1f" % 0.0]
    lines += ["/MAT/ELAST/1", "steel", "%20.4g" % 7.85e-9, "%20.1f%20.1f" % (210000.0, 0.3), "/END"]
    return "\n".join(lines) + "\n"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--radx-starter", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    path = os.path.join(a.out, "BIG_IDS_0000.rad")
    with open(path, "w") as f:
        f.write(deck())
    r = subprocess.run([a.radx_starter, path, "--out", a.out], capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit("FAIL: the starter exited with %d\n%s%s" % (r.returncode, r.stdout, r.stderr))
    fails = []
    with h5py.File(os.path.join(a.out, "BIG_IDS_0000.hdf"), "r") as f:
        for name, want in (("CellData/part_id", [PART]), ("CellData/element_id", [ELEMENT]),
                           ("PointData/node_id", NODES)):
            d = f["VTKHDF/" + name]
            if d.dtype != np.int64:
                fails.append("%s is %s, expected int64" % (name, d.dtype))
            if d[()].tolist() != want:
                fails.append("%s holds %s, expected %s" % (name, d[()].tolist(), want))
    if fails:
        sys.exit("FAIL: " + "; ".join(fails))
    print("PASS: part id %d, element id %d and node ids %d..%d kept as int64" % (PART, ELEMENT, NODES[0],
                                                                                   NODES[-1]))


if __name__ == "__main__":
    main()
