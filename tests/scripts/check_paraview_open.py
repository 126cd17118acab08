"""Opens a starter model file in ParaView (pvpython) and checks it reads as the undeformed mesh.

usage: pvpython check_paraview_open.py DECK.rad MODEL.hdf

The expected node and cell counts come from a plain reading of the deck (check_starter_output.count),
the bounds from its /NODE coordinates. Exit 0 on success, 1 with FAIL lines otherwise.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_starter_output import count  # noqa: E402

from paraview.simple import OpenDataFile  # noqa: E402


def node_bounds(deck):
    lo, hi = [1e300] * 3, [-1e300] * 3
    block = None
    for line in open(deck, encoding="ascii", errors="replace"):
        line = line.rstrip("\r\n")
        if line.startswith(("#", "$")):
            continue
        if line.startswith("/"):
            block = line.split("/")[1].strip().upper()
            continue
        if block == "NODE" and line.strip():
            xyz = [float(line[a:b].replace("D", "E").replace("d", "e")) for a, b in ((10, 30), (30, 50), (50, 70))]
            lo = [min(p, q) for p, q in zip(lo, xyz)]
            hi = [max(p, q) for p, q in zip(hi, xyz)]
    return lo, hi


def main():
    deck, model = sys.argv[1:3]
    nodes, quads, tris, bricks, tetras, bricks20 = count(deck)
    cells = quads + tris + bricks + tetras + bricks20
    reader = OpenDataFile(model)
    reader.UpdatePipeline()
    info = reader.GetDataInformation()
    failures = []
    kind = type(reader).__name__
    if kind != "VTKHDFReader":
        failures.append(f"ParaView picked {kind}, expected its VTKHDF reader")
    if info.GetNumberOfPoints() != nodes:
        failures.append(f"points {info.GetNumberOfPoints()} != deck nodes {nodes}")
    if info.GetNumberOfCells() != cells:
        failures.append(f"cells {info.GetNumberOfCells()} != deck elements {cells}")
    for name in ("node_id",):
        if name not in reader.PointData.keys():
            failures.append(f"point array {name} missing")
    for name in ("part_id", "element_id"):
        if name not in reader.CellData.keys():
            failures.append(f"cell array {name} missing")
    lo, hi = node_bounds(deck)
    b = info.GetBounds()
    # Coordinates are stored as float64 from the same decimal text: equal to 1e-9 relative.
    span = max(h - l for l, h in zip(lo, hi)) or 1.0
    for k in range(3):
        if abs(b[2 * k] - lo[k]) > 1e-9 * span or abs(b[2 * k + 1] - hi[k]) > 1e-9 * span:
            failures.append(f"bounds {b} differ from the deck's node box {lo} {hi}")
            break
    print(f"{kind}: {info.GetNumberOfPoints()} points, {info.GetNumberOfCells()} cells, bounds {b}")
    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
