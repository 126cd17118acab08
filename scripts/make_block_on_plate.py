#!/usr/bin/env python3
"""Write the block-on-plate decks in Radioss block format (fixed columns).

The decks are committed as text; this script is how they were made, so that every field sits at its
exact columns (docs/theory/deck-format.md). Edit the script and regenerate rather than editing the decks by hand.

    python3 scripts/make_block_on_plate.py                  # both variants, into decks/
    python3 scripts/make_block_on_plate.py --variant lagdt  # only the /INTER/LAGDT/TYPE7 variant
    python3 scripts/make_block_on_plate.py --variant ctclaw # only the /CTCLAW variant
    python3 scripts/make_block_on_plate.py --variant sets   # only the /SET/GENERAL variant
    python3 scripts/make_block_on_plate.py --variant set_operations  # the set-operations test deck
    python3 scripts/make_block_on_plate.py --variant showcase  # the embedded default deck
    python3 scripts/make_block_on_plate.py --out /tmp/x     # somewhere else
    python3 scripts/make_block_on_plate.py --v0 50 --stfac 30 --block-layers 2 --out /tmp/x
                                                            # stiff, fast contact (the LAGDT tests)

Variants:
  penalty  decks/block_on_plate/BLOCK_ON_PLATE_0000.rad and _0001.rad (two /INTER/TYPE7)
  lagdt    decks/block_on_plate_lagdt/BLOCK_ON_PLATE_LAGDT_0000.rad and _0001.rad
           (two /INTER/LAGDT/TYPE7, /DT/INTER/CST 0.9 1e-6 in the engine deck: pairs switch at impact)
  ctclaw   decks/block_on_plate_ctclaw/BLOCK_ON_PLATE_CTCLAW_0000.rad and _0001.rad (the two /INTER/TYPE7
           with /CTCLAW laws: exponential pressure with arctangent friction on the block's nodes, the
           automatic bilinear law with exact Coulomb friction on the plate's nodes)
  sets     decks/block_on_plate_sets/BLOCK_ON_PLATE_SETS_0000.rad and _0001.rad: the penalty deck with its node
           groups and surfaces given as sets (/SET/COLLECT and /SET/GENERAL: the same members, so the same
           results to the bit)
  showcase decks/block_impact/BLOCK_IMPACT_0000.rad and _0001.rad, the deck the executables embed and run by
           default: what a crash engineer would choose for the same impact (QEPH shells, Ishell 24; HEPH bricks,
           Isolid 24; a 5 mm plate mesh) with both interfaces /INTER/LAGDT/TYPE7 and /DT/INTER/CST, so that tens
           of pairs switch to Lagrange multipliers at impact and slide with friction after the switch
  set_operations  decks/verification/set_operations/BLOCK_ON_PLATE_SET_OPS_0000.rad and _0001.rad: the sets
           variant with the block and the plate built by set operations (a union of two sets intersected
           with a third; everything less the block), which hold the same members again

Model (units Mg, mm, s): a 100 x 100 x 1 mm steel plate of 10 x 10 shells (Johnson-Cook), clamped on its
four edges, and a 20 mm aluminium cube of 4 x 4 x 4 bricks 1 mm above its centre, moving down at 10 m/s.
Plain python3, standard library only.
"""
import argparse
import os
import sys

import radx_cards as rc  # the card layouts and their writer

VERSION = 2026


# ---------------------------------------------------------------------------------------------------
# Model geometry

PLATE_N = 10          # elements per side
PLATE_L = 100.0       # mm
PLATE_T = 1.0         # mm
BLOCK_N = 4           # elements per side (2 x 2 x 2 put a quarter of the impact energy into hourglass)
BLOCK_L = 20.0        # mm
BLOCK_Z0 = 1.5        # mm, bottom face of the block (plate mid-plane at z = 0)
NODE0_BLOCK = 1001
ELEM0_BLOCK = 1001
V0 = -10000.0         # mm/s, initial velocity of the block along Z
GRAVITY = -9810.0     # mm/s^2 along Z
# Options of the test variants (main()): brick layers of the block (same pitch), Stfac of both interfaces,
# a free plate without gravity (no external force: momentum is conserved), the /DT/INTER/CST card.
BLOCK_NZ = BLOCK_N
STFAC = 1.0
FREE = False
INTER_DT = True
TSTOP = 0.002


def plate_node_id(i, j):
    return 1 + i + (PLATE_N + 1) * j


def block_node_id(i, j, k):
    return NODE0_BLOCK + i + (BLOCK_N + 1) * j + (BLOCK_N + 1) ** 2 * k


def coord(i, n, length):
    # exact for the decimal sizes used here: (2 i - n) * length / (2 n)
    return (2 * i - n) * length / (2 * n)


def plate_nodes():
    out = []
    for j in range(PLATE_N + 1):
        for i in range(PLATE_N + 1):
            out.append((plate_node_id(i, j), coord(i, PLATE_N, PLATE_L), coord(j, PLATE_N, PLATE_L), 0.0))
    return out


def block_nodes():
    h = BLOCK_L / BLOCK_N
    out = []
    for k in range(BLOCK_NZ + 1):
        for j in range(BLOCK_N + 1):
            for i in range(BLOCK_N + 1):
                out.append((block_node_id(i, j, k), coord(i, BLOCK_N, BLOCK_L), coord(j, BLOCK_N, BLOCK_L),
                            BLOCK_Z0 + k * h))
    return out


def shells():
    out = []
    for j in range(PLATE_N):
        for i in range(PLATE_N):
            eid = 1 + i + PLATE_N * j
            n1 = plate_node_id(i, j)
            out.append((eid, n1, plate_node_id(i + 1, j), plate_node_id(i + 1, j + 1), plate_node_id(i, j + 1)))
    return out


def bricks():
    out = []
    for k in range(BLOCK_NZ):
        for j in range(BLOCK_N):
            for i in range(BLOCK_N):
                eid = ELEM0_BLOCK + i + BLOCK_N * j + BLOCK_N * BLOCK_N * k
                bottom = [block_node_id(i, j, k), block_node_id(i + 1, j, k), block_node_id(i + 1, j + 1, k),
                          block_node_id(i, j + 1, k)]
                top = [block_node_id(i, j, k + 1), block_node_id(i + 1, j, k + 1),
                       block_node_id(i + 1, j + 1, k + 1), block_node_id(i, j + 1, k + 1)]
                out.append((eid, *bottom, *top))
    return out


def edge_nodes():
    ids = []
    for j in range(PLATE_N + 1):
        for i in range(PLATE_N + 1):
            if i in (0, PLATE_N) or j in (0, PLATE_N):
                ids.append(plate_node_id(i, j))
    return ids


def centre_node():
    return plate_node_id(PLATE_N // 2, PLATE_N // 2)


def block_bottom_centre_node():
    return block_node_id(BLOCK_N // 2, BLOCK_N // 2, 0)


def check_geometry(nodes, shell_list, brick_list):
    """Positive areas (normals along +Z) and positive brick volumes (8-point hexahedron formula)."""
    xyz = {n[0]: n[1:] for n in nodes}

    def sub(a, b):
        return (a[0] - b[0], a[1] - b[1], a[2] - b[2])

    def cross(a, b):
        return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])

    def dot(a, b):
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]

    for e in shell_list:
        p = [xyz[n] for n in e[1:5]]
        nz = cross(sub(p[2], p[0]), sub(p[3], p[1]))[2]
        assert nz > 0, f"shell {e[0]} normal not along +Z"
    for e in brick_list:
        p = [xyz[n] for n in e[1:9]]
        # volume from the Jacobian at the centre (exact for parallelepipeds)
        d_xi = [sum(s * p[k][c] for s, k in zip((-1, 1, 1, -1, -1, 1, 1, -1), range(8))) / 4 for c in range(3)]
        d_eta = [sum(s * p[k][c] for s, k in zip((-1, -1, 1, 1, -1, -1, 1, 1), range(8))) / 4 for c in range(3)]
        d_zeta = [sum(s * p[k][c] for s, k in zip((-1, -1, -1, -1, 1, 1, 1, 1), range(8))) / 4 for c in range(3)]
        vol = dot(cross(d_xi, d_eta), d_zeta)
        assert vol > 0, f"brick {e[0]} has non-positive volume"


# ---------------------------------------------------------------------------------------------------
# Starter deck


RUN_NAMES = {"penalty": "BLOCK_ON_PLATE", "lagdt": "BLOCK_ON_PLATE_LAGDT", "ctclaw": "BLOCK_ON_PLATE_CTCLAW",
             "sets": "BLOCK_ON_PLATE_SETS", "set_operations": "BLOCK_ON_PLATE_SET_OPS", "showcase": "BLOCK_IMPACT"}
# The variants whose interfaces are /INTER/LAGDT/TYPE7.
LAGDT_VARIANTS = ("lagdt", "showcase")
# Where each variant's folder goes, under --out (default decks/).
FOLDERS = {"set_operations": os.path.join("verification", "set_operations")}
# The /CTCLAW variant's laws (docs/theory/contact-laws.md; Mg, mm, s: pressures in MPa, Kc in MPa/mm, CtLin in MPa
# s/mm): on the block's nodes, an exponential pressure of 0.01 MPa at the gap's surface working at 200 MPa (lambda =
# Kc_auto / pe), stiffening to at most 1e5 MPa/mm, with arctangent friction mu 0.1 reaching half of mu p at a
# slip of 1 m/s (atan(CtLin s) = pi/4 at CtLin s = 1; a stiffer CtLin is a stiffer dashpot and a smaller step);
# on the plate's nodes the automatic bilinear law (the interface's stiffness K / A_s) with exact Coulomb
# friction mu 0.2.
CTCLAW_LAWS = {1: "n2s13{pz0.01,pe200,KcMax1e5,Mu0.1,CtLin1e-3}", 2: "n1s11{Kc-1,Mu0.2}"}


def starter_deck(variant):
    lagdt = variant in LAGDT_VARIANTS
    showcase = variant == "showcase"
    run = RUN_NAMES[variant]
    pn, bn = plate_nodes(), block_nodes()
    sh, br = shells(), bricks()
    check_geometry(pn + bn, sh, br)
    d = rc.Deck(fill=0)
    d.raw("#RADIOSS STARTER")
    what = {"penalty": "", "lagdt": ", LAGDT variant", "ctclaw": ", /CTCLAW variant",
            "sets": ", /SET/GENERAL variant (the same model as BLOCK_ON_PLATE)",
            "set_operations": ", set-operations variant (the same model as BLOCK_ON_PLATE)",
            "showcase": " (QEPH shells, HEPH bricks, LAGDT contact)"}[variant]
    d.comment("radx default deck%s:" % what,
              "a steel plate (Johnson-Cook shells, clamped edges) hit by an aluminium block (elastic bricks)",
              "at 10 m/s. Units: Mg, mm, s (stress in MPa, force in N, energy in mJ).",
              "Generated by scripts/make_block_on_plate.py: edit the script and regenerate, not this file.")
    d.ruler().begin(run, ("Mg", "mm", "s")).ruler()
    d.card("/TITLE", title="Block on plate: 20 mm aluminium cube at 10 m/s onto a clamped 100 x 100 x 1 mm steel plate"
           + (" (LAGDT)" if lagdt else ""))
    d.ruler()
    d.raw("#  Global defaults: all zero, so every 0 flag of the /PROP cards takes the hard-coded default")
    d.card("/DEF_SHELL").card("/DEF_SOLID")
    d.ruler()
    d.raw("#  Plate nodes 1..121 (11 x 11 grid, 10 mm pitch, mid-plane z = 0)")
    d.rows("/NODE", pn)
    d.raw("#  Block nodes %d..%d (%d x %d x %d grid, %g mm pitch, bottom face at z = %g)"
          % (NODE0_BLOCK, block_node_id(BLOCK_N, BLOCK_N, BLOCK_N), BLOCK_N + 1, BLOCK_N + 1, BLOCK_N + 1,
             BLOCK_L / BLOCK_N, BLOCK_Z0))
    d.rows("/NODE", bn)
    d.ruler()
    d.raw("#  Plate: 100 four-node shells of part 1 (normals along +Z)")
    d.rows("/SHELL", sh, 1)
    d.raw("#  Block: 8 bricks of part 2 (nodes 1-4 bottom face, 5-8 top face)")
    d.rows("/BRICK", br, 2)
    d.ruler()
    d.card("/PART", 1, "Plate", prop_ID=1, mat_ID=1)
    d.card("/PART", 2, "Block", prop_ID=2, mat_ID=2)
    d.ruler()
    if showcase:
        d.raw("#  QEPH (Ishell 24): one point in the plane with physical hourglass stiffness, where BT4's viscous",
              "#  hourglass would take a tenth and more of the impact energy on this coarse plate")
        d.card("/PROP/SHELL", 1, "Plate shell 1 mm QEPH with 5 integration points", Ishell=24, N=5, Thick=PLATE_T,
               Ithick=1, Iplas=1)
        d.raw("#  HEPH (Isolid 24): one point with physical hourglass stiffness, co-rotational")
        d.card("/PROP/SOLID", 2, "Block solid HEPH", Isolid=24)
    else:
        d.raw("#  Ishell Ismstr Ish3n Idrill = 0: from /DEF_SHELL (all 0), so Ishell 1, Ismstr 2, Ish3n 2, Idrill 0")
        d.card("/PROP/SHELL", 1, "Plate shell 1 mm with 5 integration points", N=5, Thick=PLATE_T, Ithick=1, Iplas=1)
        d.raw("#  Isolid Ismstr Icpre Iframe = 0: from /DEF_SOLID (all 0), so Isolid 1, Ismstr 4, Iframe 1")
        d.card("/PROP/SOLID", 2, "Block solid with one integration point")
    d.ruler()
    d.card("/MAT/PLAS_JOHNS", 1, "Steel (Johnson-Cook)", RHO_I=7.85e-9, RHO_ref=None, E=210000.0, nu=0.3,
           a=250.0, b=450.0, n=0.3, c=0.014, EPS_DOT_0=1.0)
    d.card("/MAT/LAW1", 2, "Aluminium (elastic)", RHO_I=2.7e-9, RHO_ref=None, E=70000.0, nu=0.33)
    d.ruler()
    plate_surface = 1
    if variant in ("sets", "set_operations"):
        plate_surface = 3
        set_cards(d, variant == "set_operations")
    else:
        d.card("/GRNOD/NODE", 1, "Plate edge nodes (clamped)", ids=edge_nodes())
        d.card("/GRNOD/PART", 2, "Block nodes", ids=[2])
        d.card("/GRNOD/PART", 3, "Plate nodes", ids=[1])
        d.card("/SURF/PART", 1, "Plate surface (shell segments with normals along +Z)", ids=[1])
        d.card("/SURF/PART/EXT", 2, "Block outer faces (outward)", ids=[2])
    d.ruler()
    if not FREE:
        d.card("/BCS", 1, "Clamped plate edges", Tra_rot=rc.bcs_code("111", "111"), grnod_ID=1)
    d.card("/INIVEL/TRA", 1, "Block initial velocity %g m/s downwards" % (-V0 / 1000.0), Vz=V0, grnod_ID=2)
    if not FREE:
        d.card("/GRAV", 1, "Gravity 9.81 m/s^2 downwards on all nodes (constant: no function)", DIR="Z",
               Fscale_y=GRAVITY)
    d.rows("/FUNCT", ((0.0, 0.0), (0.0005, 1.0), (1.0, 1.0)), 1, "Unit ramp over 0.5 ms (not referenced by this deck)")
    d.ruler()
    interface(d, 1, "Block nodes on plate surface", lagdt, grnod=2, surf=plate_surface, istf=4, inacti=6, fric=0.1,
              iform=1,
              viss=0.05)
    interface(d, 2, "Plate nodes on block outer faces", lagdt, grnod=3, surf=2, istf=0, inacti=0, fric=0.2, iform=2,
              viss=0.0)
    if variant == "ctclaw":
        d.raw("#  The interfaces' normal and friction laws replaced by /CTCLAW laws (docs/theory/contact-laws.md)")
        for iid, law in CTCLAW_LAWS.items():
            d.card("/CTCLAW", 10 + iid, "Law of interface %d" % iid, inter_ID=iid, law=law)
    d.ruler()
    d.card("/TH/NODE", 1, "Plate centre and block bottom centre", variables=["DEF"],
           rows=[(centre_node(), 0, "Plate centre"), (block_bottom_centre_node(), 0, "Block bottom centre")])
    d.card("/TH/PART", 2, "Plate and block", variables=["DEF"], ids=[1, 2])
    d.card("/TH/INTER", 3, "Both interfaces", variables=["DEF"], ids=[1, 2])
    d.ruler()
    d.raw("/END")
    return d.lines


def set_cards(d, operations=False):
    """The penalty deck's groups and surfaces as sets: the clamped edge nodes (two /SET/COLLECT of one id: the
    bottom and top rows generated, the side columns listed), and one /SET/GENERAL per part that is both its node
    group and its surface (a set gives each use the members it asks for: the nodes of the elements, or the
    shells and outer brick faces). With `operations`, the part sets are built by set operations instead."""
    n = PLATE_N + 1
    sides = sorted(plate_node_id(i, j) for j in range(1, n - 1) for i in (0, n - 1))
    rows_ = [("NODE_G", plate_node_id(0, 0), plate_node_id(n - 1, 0), 1,
              plate_node_id(0, n - 1), plate_node_id(n - 1, n - 1), 1)]
    columns = [("NODE" if k == 0 else "",) + tuple(sides[k:k + 9]) for k in range(0, len(sides), 9)]
    generated = set(range(plate_node_id(0, 0), plate_node_id(n - 1, 0) + 1)) | set(
        range(plate_node_id(0, n - 1), plate_node_id(n - 1, n - 1) + 1))
    assert generated | set(sides) == set(edge_nodes()), "the set is the penalty deck's /GRNOD/NODE/1"
    # Set 1 in two /SET/COLLECT blocks of one id: each adds to the one set.
    d.rows("/SET/COLLECT", rows_, 1, "Plate edge nodes (clamped): the bottom and top rows generated")
    d.rows("/SET/COLLECT", columns, 1, "Plate edge nodes (clamped): the side columns listed")
    if operations:
        # The same members by set operations: (block or plate) and block; everything less the block.
        d.rows("/SET/GENERAL", [("SET", 20, 21), ("SET_I", 22)], 2, "Block: sets 20 or 21 and set 22")
        d.rows("/SET/GENERAL", [("ALL",), ("PART_D", 2)], 3, "Plate: everything less the block")
        d.rows("/SET/GENERAL", [("PART", 2)], 20, "Block")
        d.rows("/SET/GENERAL", [("PART", 1)], 21, "Plate")
        d.rows("/SET/GENERAL", [("PART", 2)], 22, "Block again")
        return
    d.rows("/SET/GENERAL", [("PART", 2)], 2,
           "Block: its nodes (interface 1 and velocity) and outer faces (interface 2)")
    d.rows("/SET/GENERAL", [("PART", 1)], 3, "Plate: its nodes (interface 2) and shell segments (interface 1)")


def interface(d, iid, title, lagdt, grnod, surf, istf, inacti, fric, iform, viss):
    """One TYPE7 (2026 layout) or LAGDT/TYPE7 card of deck d."""
    d.card("/INTER/LAGDT/TYPE7" if lagdt else "/INTER/TYPE7", iid, title, grnd_IDs=grnod, surf_IDm=surf, Istf=istf,
           Stmax="1E30" if istf >= 2 else 0.0, Stfac=STFAC, Fric=fric, IBC=rc.ibc_code(0, 0, 0), Inacti=inacti,
           VISs=viss, VISf=1.0, Iform=iform)


# ---------------------------------------------------------------------------------------------------
# Engine deck


def engine_deck(variant, lagdt_tmin=1e-6):
    lagdt = variant in LAGDT_VARIANTS
    run = RUN_NAMES[variant]
    e = rc.Deck(engine=True)
    e.raw("#RADIOSS ENGINE")
    e.comment("Engine deck of %s_0000.rad." % run,
              "Engine data lines are free format; the values are aligned only to be easy to read.",
              "Generated by scripts/make_block_on_plate.py.")
    e.ruler().card("/RUN", "%s/1" % run, Tstop=TSTOP).ruler()
    e.card("/TFILE", dt_his=1e-5)
    e.card("/ANIM/DT", Tstart=0.0, dT=0.0001)
    e.raw("/ANIM/ELEM/VONM", "/ANIM/ELEM/EPSP", "/ANIM/VECT/VEL", "/ANIM/VECT/CONT")
    e.ruler().card("/DT", Tscale=0.9, Tmin=0.0)
    if lagdt and INTER_DT:
        e.raw("#  Contact pairs of the LAGDT interfaces whose time step would fall below Tmin switch to Lagrange",
              "#  multipliers (docs/theory/type7-lagdt.md section 6; OpenRadioss itself needs /DT/INTER/LAG).")
        e.card("/DT/INTER/CST", Tscale=0.9, Tmin=lagdt_tmin)
    e.raw("/PRINT/-100")
    e.card("/STOP", Emax="1.0E+30", Mmax="1.0E+30", Nmax="1.0E+30", NTH=1, NANIM=1)
    e.ruler().raw("/END")
    return e.lines


def main(argv):
    here = os.path.dirname(os.path.abspath(__file__))
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--variant", choices=("penalty", "lagdt", "ctclaw", "sets", "set_operations", "showcase", "all"),
                   default="all")
    p.add_argument("--lagdt-tmin", type=float, default=1e-6,
                   help="Tmin of /DT/INTER/CST in the LAGDT engine deck (default 1e-6 s: the block's bottom pairs "
                        "switch at impact; 1e-7 s switches none)")
    p.add_argument("--out", default=os.path.join(here, "..", "decks"),
                   help="parent folder of block_on_plate/ and block_on_plate_lagdt/ (default: decks/)")
    p.add_argument("--v0", type=float, default=10.0, help="impact speed of the block, m/s (default 10)")
    p.add_argument("--stfac", type=float, default=1.0, help="Stfac of both interfaces (default 1)")
    p.add_argument("--block-layers", type=int, default=BLOCK_N, help="brick layers of the block (default 4)")
    p.add_argument("--free", action="store_true", help="no clamped edges and no gravity (no external force)")
    p.add_argument("--no-inter-dt", action="store_true", help="no /DT/INTER/CST in the LAGDT engine deck")
    p.add_argument("--tstop", type=float, default=0.002, help="end time, s (default 0.002)")
    args = p.parse_args(argv)
    global V0, STFAC, BLOCK_NZ, FREE, INTER_DT, TSTOP
    V0, STFAC, BLOCK_NZ, FREE = -1000.0 * args.v0, args.stfac, args.block_layers, args.free
    INTER_DT, TSTOP = not args.no_inter_dt, args.tstop
    variants = (("penalty", "lagdt", "ctclaw", "sets", "set_operations", "showcase") if args.variant == "all"
                else (args.variant,))
    for v in variants:
        root = RUN_NAMES[v]
        folder = FOLDERS.get(v, root.lower())
        d = os.path.normpath(os.path.join(args.out, folder))
        rc.write(os.path.join(d, root + "_0000.rad"), starter_deck(v), report=True)
        rc.write(os.path.join(d, root + "_0001.rad"), engine_deck(v, args.lagdt_tmin), report=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
