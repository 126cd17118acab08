#!/usr/bin/env python3
"""Write the deck pair the forced-cut MPI test runs: a rigid body and a TYPE2 tie that a partition can cut.

    python3 tests/mpi/gen_cut_deck.py --out DIR      # writes DIR/CUT_0000.rad and DIR/CUT_0001.rad

Model (units Mg, mm, s), a 20 x 20 mm steel bar of bricks along x in three parts, one element group each:
  * part 1 "Root": 4 x 2 x 2 bricks of 10 mm, x in [0, 40], Johnson-Cook steel, clamped at x = 0;
  * part 2 "Tip": 6 x 3 x 3 bricks, x in [40, 80] (a finer mesh than the root's), elastic steel; its nodes at
    x = 40 are tied by /INTER/TYPE2 to the root's end faces at x = 40 (the tie's main surface): inside the
    faces and on their edges, not on the root's nodes;
  * part 3 "Clamp": 1 x 2 x 2 bricks, x in [82, 92], elastic steel, joined to the tip by one /RBODY whose
    secondary nodes are the tip's nodes at x = 80 and every clamp node: elements of two parts;
  * the body's main node (at its centre of mass, ICoG 1) starts at Vz = -5 m/s and spins at 200 rad/s about x,
    so the body pulls and twists the tip, and the tie carries it into the clamped root.
A partition that puts the parts on different ranks cuts the body (tip nodes on one rank, clamp nodes on
another) and the tie (secondary nodes on the tip's rank, main nodes on the root's). The end time gives about
250 cycles; states at four times and a time history of the nodes (a tied one among them), the body and
the parts (radx writes none of a TYPE2 interface).

Plain python3, standard library only.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
import radx_cards as rc  # noqa: E402  (the card layouts and their writer)

ROOT = "CUT"
SIG = 12
H = 20.0                     # bar section, mm
E, NU, RHO = 210000.0, 0.3, 7.85e-9
TSTOP = 2.5e-4               # s: about 250 cycles of the tip's brick step
MAIN_NODE = 9001


class Block:
    """A brick block on a regular grid: nodes first_node + i + (nx + 1) (j + (ny + 1) k)."""

    def __init__(self, first_node, first_brick, x0, x1, n_x, n_yz):
        self.first_node, self.first_brick = first_node, first_brick
        self.x0, self.x1, self.nx, self.n = x0, x1, n_x, n_yz

    def node(self, i, j, k):
        return self.first_node + i + (self.nx + 1) * (j + (self.n + 1) * k)

    def nodes(self):
        return [(self.node(i, j, k), self.x0 + (self.x1 - self.x0) * i / self.nx, -H / 2 + H * j / self.n,
                 -H / 2 + H * k / self.n)
                for k in range(self.n + 1) for j in range(self.n + 1) for i in range(self.nx + 1)]

    def bricks(self):
        b, rows = self.first_brick, []
        for k in range(self.n):
            for j in range(self.n):
                for i in range(self.nx):
                    n = self.node
                    rows.append((b, n(i, j, k), n(i + 1, j, k), n(i + 1, j + 1, k), n(i, j + 1, k),
                                 n(i, j, k + 1), n(i + 1, j, k + 1), n(i + 1, j + 1, k + 1), n(i, j + 1, k + 1)))
                    b += 1
        return rows

    def face(self, i):
        """The node ids of the grid plane x = x(i)."""
        return [self.node(i, j, k) for k in range(self.n + 1) for j in range(self.n + 1)]

    def end_segments(self):
        """The quadrilaterals of the plane x = x1, normal +x."""
        n, i = self.node, self.nx
        return [(n(i, j, k), n(i, j + 1, k), n(i, j + 1, k + 1), n(i, j, k + 1))
                for k in range(self.n) for j in range(self.n)]


ROOT_BLOCK = Block(1, 1, 0.0, 40.0, 4, 2)
TIP_BLOCK = Block(1001, 1001, 40.0, 80.0, 6, 3)
CLAMP_BLOCK = Block(2001, 2001, 82.0, 92.0, 1, 2)


def starter():
    d = rc.Deck(fill=0)
    d.raw("#RADIOSS STARTER")
    d.comment("Written by tests/mpi/gen_cut_deck.py: a rigid body over two parts and a TYPE2 tie between two",
              "parts, for radx-engine-mpi --partition runs that cut both on purpose. Units: Mg, mm, s.")
    d.ruler().begin(ROOT, ("Mg", "mm", "s")).ruler()
    d.card("/TITLE", title="Clamped bar: root tied to a finer tip (TYPE2), tip and clamp one rigid body")
    d.ruler()
    for b in (ROOT_BLOCK, TIP_BLOCK, CLAMP_BLOCK):
        d.rows("/NODE", b.nodes(), sig=SIG)
    d.rows("/NODE", [(MAIN_NODE, 87.0, 0.0, 0.0)])
    d.ruler()
    for part, b in ((1, ROOT_BLOCK), (2, TIP_BLOCK), (3, CLAMP_BLOCK)):
        d.rows("/BRICK", b.bricks(), part)
    d.ruler()
    d.card("/PART", 1, "Root", prop_ID=1, mat_ID=1)
    d.card("/PART", 2, "Tip", prop_ID=1, mat_ID=2)
    d.card("/PART", 3, "Clamp", prop_ID=1, mat_ID=2)
    d.card("/PROP/SOLID", 1, "HEPH bricks (physically stabilised hourglass)", Isolid=24, Ismstr=4, Iframe=2)
    d.card("/MAT/PLAS_JOHNS", 1, "Root steel (Johnson-Cook)", RHO_I=RHO, RHO_ref=None, E=E, nu=NU,
           a=250.0, b=450.0, n=0.3, c=0.0, EPS_DOT_0=1.0)
    d.card("/MAT/LAW1", 2, "Tip and clamp steel (elastic)", RHO_I=RHO, RHO_ref=None, E=E, nu=NU)
    d.ruler()
    d.card("/GRNOD/NODE", 1, "Root nodes at x = 0 (clamped)", ids=ROOT_BLOCK.face(0))
    d.card("/GRNOD/NODE", 2, "Tip nodes at x = 40 (tied)", ids=TIP_BLOCK.face(0))
    d.rows("/SURF/SEG", [(s + 1, *seg) for s, seg in enumerate(ROOT_BLOCK.end_segments())], 3,
           "Root end faces at x = 40")
    d.card("/GRNOD/NODE", 4, "Rigid body: tip nodes at x = 80 and every clamp node",
           ids=TIP_BLOCK.face(TIP_BLOCK.nx) + [n for n, *_ in CLAMP_BLOCK.nodes()])
    d.card("/GRNOD/NODE", 5, "Main node", ids=[MAIN_NODE])
    d.ruler()
    d.card("/BCS", 1, "Clamped root", Tra_rot=rc.bcs_code("111", "000"), grnod_ID=1)
    d.comment("Spotflag 0: the standard kinematic tie; Dsearch 0: automatic")
    d.card("/INTER/TYPE2", 1, "Tip tied to root", grnd_IDs=2, surf_IDm=3, Ignore=0, Spotflag=0, Level=0,
           Isearch=0, Idel2=0, Dsearch=0.0)
    d.comment("ICoG 1: the main node at the centre of mass; the inertia of the nodal masses")
    d.card("/RBODY", 1, "Tip end and clamp", node_ID=MAIN_NODE, sens_ID=0, skew_ID=0, Ispher=0, Mass=0.0,
           grnd_ID=4, Ikrem=0, ICoG=1, surf_ID=0, Jxx=0.0, Jyy=0.0, Jzz=0.0, Jxy=0.0, Jyz=0.0, Jxz=0.0,
           Ioptoff=0, Iexpams=0, Ifail=0)
    d.comment("The body moves as its main node: its secondary nodes get v_N + w_N x r at the start")
    d.card("/INIVEL/TRA", 1, "Body thrown down", Vx=0.0, Vy=0.0, Vz=-5000.0, grnod_ID=5, skew_ID=0, Tstart=0.0,
           sensor_ID=0)
    d.card("/INIVEL/ROT", 2, "Body spinning about x", Vx=200.0, Vy=0.0, Vz=0.0, grnod_ID=5, skew_ID=0,
           Tstart=0.0, sensor_ID=0)
    d.ruler()
    d.card("/TH/NODE", 1, "Main node, a tied node, a root node", variables=["DEF"],
           rows=[(MAIN_NODE, 0, "main node"), (TIP_BLOCK.node(0, 1, 1), 0, "tied tip node"),
                 (ROOT_BLOCK.node(2, 1, 1), 0, "root node at x = 20")])
    d.card("/TH/RBODY", 2, "Rigid body", variables=["DEF"], ids=[1])
    d.card("/TH/PART", 3, "Parts", variables=["DEF"], ids=[1, 2, 3])
    d.ruler()
    d.raw("/END")
    return d.lines


def engine():
    e = rc.Deck(engine=True)
    e.raw("#RADIOSS ENGINE")
    e.comment("About 250 cycles of the tip's brick step")
    e.ruler()
    e.card("/RUN", "%s/1" % ROOT, Tstop=TSTOP, sig=SIG)
    e.card("/TFILE", dt_his=TSTOP / 50, sig=SIG)
    e.card("/ANIM/DT", Tstart=0.0, dT=TSTOP / 4, sig=SIG)
    e.raw("/ANIM/ELEM/VONM", "/ANIM/ELEM/EPSP", "/ANIM/VECT/VEL", "/ANIM/VECT/DISP")
    e.card("/DT", Tscale=0.9, Tmin=0.0)
    e.raw("/PRINT/-50")
    e.ruler().raw("/END")
    return e.lines


def main(argv):
    p = argparse.ArgumentParser(description="Write CUT_0000.rad and CUT_0001.rad (see the module docstring).")
    p.add_argument("--out", default=".", help="output folder (default: the current folder)")
    args = p.parse_args(argv)
    os.makedirs(args.out, exist_ok=True)
    rc.write(os.path.join(args.out, ROOT + "_0000.rad"), starter())
    rc.write(os.path.join(args.out, ROOT + "_0001.rad"), engine())
    print("wrote %s_0000.rad and %s_0001.rad in %s" % (ROOT, ROOT, args.out))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
