#!/usr/bin/env python3
"""Generate a brick-only benchmark deck pair in Radioss block format (fixed columns, format 2026).

    python3 bench/gen_brick_block.py --n 40 --isolid 24 --out /tmp/bench   # BRICKS40_24_0000.rad, _0001.rad

Model (units Mg, mm, s): a steel block of N x N x N/2 one-point bricks of 5 mm (Johnson-Cook, as the shell
plate of gen_shell_plate.py), Isolid 1 or 24 (--isolid), clamped on its bottom face; every other node starts
at 10 m/s along X, so the block shears and bends over the clamp and yields there. Tstop gives about 1000
cycles at the brick step 0.9 h / (1.05125 c). The element loop is the whole cost (no contact, no shells), so
the engine's "cost" line is the brick kernel's microseconds per element per cycle plus the nodal update.
Plain python3, standard library only.
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scripts"))
import radx_cards as rc  # noqa: E402  (the card layouts and their writer)

H = 5.0  # mm, brick edge
E, NU, RHO = 210000.0, 0.3, 7.85e-9
CYCLES = 1000
SIG = 12


def sig3(x):
    e = math.floor(math.log10(abs(x)))
    return round(x, -e + 2)


def starter(n, isolid, root):
    nz = max(1, n // 2)
    nb = n + 1

    def nid(i, j, k):
        return 1 + i + nb * j + nb * nb * k

    d = rc.Deck(fill=0)
    d.raw("#RADIOSS STARTER")
    d.comment("Benchmark deck written by bench/gen_brick_block.py: %d x %d x %d bricks, Isolid %d." % (n, n, nz, isolid),
              "Units: Mg, mm, s.")
    d.ruler().begin(root, ("Mg", "mm", "s")).ruler()
    d.card("/TITLE", title="Clamped steel block of %d x %d x %d bricks (Isolid %d) sheared at 10 m/s" % (n, n, nz, isolid))
    d.ruler()
    d.rows("/NODE", [(nid(i, j, k), i * H, j * H, k * H) for k in range(nz + 1) for j in range(nb) for i in range(nb)])
    d.rows("/BRICK", [(1 + i + n * j + n * n * k, nid(i, j, k), nid(i + 1, j, k), nid(i + 1, j + 1, k), nid(i, j + 1, k),
                       nid(i, j, k + 1), nid(i + 1, j, k + 1), nid(i + 1, j + 1, k + 1), nid(i, j + 1, k + 1))
                      for k in range(nz) for j in range(n) for i in range(n)], 1)
    d.ruler()
    d.card("/PART", 1, "Block", prop_ID=1, mat_ID=1)
    d.card("/PROP/SOLID", 1, "Block solid", Isolid=isolid, Ismstr=4, Iframe=1 if isolid != 24 else 2)
    d.card("/MAT/PLAS_JOHNS", 1, "Steel (Johnson-Cook)", RHO_I=RHO, RHO_ref=None, E=E, nu=NU,
           a=250.0, b=450.0, n=0.3, c=0.014, EPS_DOT_0=1.0)
    d.ruler()
    d.card("/GRNOD/NODE", 1, "Bottom nodes (clamped)", ids=[nid(i, j, 0) for j in range(nb) for i in range(nb)])
    d.card("/GRNOD/NODE", 2, "Moving nodes",
           ids=[nid(i, j, k) for k in range(1, nz + 1) for j in range(nb) for i in range(nb)])
    d.card("/BCS", 1, "Clamped bottom", Tra_rot=rc.bcs_code("111", "000"), grnod_ID=1)
    d.card("/INIVEL/TRA", 1, "Block at 10 m/s along X", Vx=10000.0, grnod_ID=2)
    d.ruler()
    d.raw("/END")
    return d.lines


def engine(root):
    c = math.sqrt(E * (1 - NU) / ((1 + NU) * (1 - 2 * NU)) / RHO)
    dt = 0.9 * H / (1.05125 * c)
    tstop = sig3(CYCLES * dt)
    e = rc.Deck(engine=True)
    e.raw("#RADIOSS ENGINE")
    e.comment("Tstop = %d cycles x brick step %.4g s" % (CYCLES, dt))
    e.ruler()
    e.card("/RUN", "%s/1" % root, Tstop=tstop, sig=SIG)
    e.card("/ANIM/DT", Tstart=0.0, dT=tstop, sig=SIG)
    e.card("/DT", Tscale=0.9, Tmin=0.0)
    e.raw("/PRINT/-100")
    e.ruler().raw("/END")
    return e.lines


def main(argv):
    p = argparse.ArgumentParser(description="Write a brick-only benchmark deck (format 2026).")
    p.add_argument("--n", type=int, default=40, help="bricks per side (N x N x N/2 bricks; default 40)")
    p.add_argument("--isolid", type=int, choices=(1, 2, 24), default=1, help="brick formulation (default 1)")
    p.add_argument("--out", default=".", help="output folder (default: current folder)")
    args = p.parse_args(argv)
    root = "BRICKS%d_%d" % (args.n, args.isolid)
    os.makedirs(args.out, exist_ok=True)
    rc.write(os.path.join(args.out, root + "_0000.rad"), starter(args.n, args.isolid, root))
    rc.write(os.path.join(args.out, root + "_0001.rad"), engine(root))
    print(root)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
