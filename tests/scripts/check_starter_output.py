#!/usr/bin/python3
"""Runs check_model_file.py on a starter's model file with the counts read independently from the deck.

usage: /usr/bin/python3 check_starter_output.py DECK.rad MODEL.hdf

The counts come from a plain reading of the deck text (records between /NODE, /SHELL, /SH3N, /BRICK,
/TETRA4 and the next keyword, comment lines skipped), not from radx, so a reader bug cannot hide itself. A
shell written with n4 = n3 (or n4 = 0) is a VTK triangle (5), other shells quads (9), bricks
hexahedra (12), tetrahedra tetras (10).
"""
import os
import subprocess
import sys


def count(deck):
    nodes = quads = tris = bricks = tetras = bricks20_lines = 0
    block = None
    for line in open(deck, encoding="ascii", errors="replace"):
        line = line.rstrip("\r\n")
        if line.startswith("#") or line.startswith("$"):
            continue
        if line.startswith("/"):
            key = line.split("/")[1].strip().upper()
            block = key if key in ("NODE", "SHELL", "SH3N", "BRICK", "TETRA4", "BRIC20") else None
            continue
        if block is None or not line.strip():
            continue
        if block == "NODE":
            nodes += 1
        elif block == "SHELL":
            n3, n4 = line[30:40].strip(), line[40:50].strip()
            if n4 in ("", "0") or n4 == n3:
                tris += 1
            else:
                quads += 1
        elif block == "SH3N":
            tris += 1
        elif block == "BRICK":
            bricks += 1
        elif block == "TETRA4":
            tetras += 1
        elif block == "BRIC20":  # three lines per element
            bricks20_lines += 1
    return nodes, quads, tris, bricks, tetras, bricks20_lines // 3


def main():
    if len(sys.argv) != 3:
        print(__doc__)
        return 2
    deck, model = sys.argv[1:]
    nodes, quads, tris, bricks, tetras, bricks20 = count(deck)
    types = ",".join(f"{t}:{n}" for t, n in ((9, quads), (5, tris), (12, bricks), (10, tetras), (25, bricks20))
                     if n)
    checker = os.path.join(os.path.dirname(os.path.abspath(__file__)), "check_model_file.py")
    cmd = [sys.executable, checker, model, "--nodes", str(nodes), "--cells",
           str(quads + tris + bricks + tetras + bricks20)]
    if types:
        cmd += ["--types", types]
    print("deck counts: nodes", nodes, "quads", quads, "triangles", tris, "bricks", bricks, "tetrahedra", tetras,
          "20-node bricks", bricks20)
    return subprocess.call(cmd)


if __name__ == "__main__":
    sys.exit(main())
