#!/usr/bin/env python3
"""Write the block-on-plate decks in Radioss block format (fixed columns).

The decks are committed as text; this script is how they were made, so that every field sits at its
exact columns (deck-format.md). Edit the script and regenerate rather than editing the decks by hand.

    python3 scripts/make_block_on_plate.py                  # both variants, into decks/
    python3 scripts/make_block_on_plate.py --variant lagdt  # only the /INTER/LAGDT/TYPE7 variant
    python3 scripts/make_block_on_plate.py --variant ctclaw # only the /CTCLAW variant
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

Model (units Mg, mm, s): a 100 x 100 x 1 mm steel plate of 10 x 10 shells (Johnson-Cook), clamped on its
four edges, and a 20 mm aluminium cube of 4 x 4 x 4 bricks 1 mm above its centre, moving down at 10 m/s.
Plain python3, standard library only.
"""
import argparse
import os
import sys

from radx_deck_format import I, R, S, RULER, bcs_code, blank, ibc_code, line, names, write  # fixed-column cells

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


RUN_NAMES = {"penalty": "BLOCK_ON_PLATE", "lagdt": "BLOCK_ON_PLATE_LAGDT", "ctclaw": "BLOCK_ON_PLATE_CTCLAW"}
# The /CTCLAW variant's laws (contact-laws.md; Mg, mm, s: pressures in MPa, Kc in MPa/mm, CtLin in MPa s/mm):
# on the block's nodes, an exponential pressure of 0.01 MPa at the gap's surface working at 200 MPa (lambda =
# Kc_auto / pe), stiffening to at most 1e5 MPa/mm, with arctangent friction mu 0.1 reaching half of mu p at a
# slip of 1 m/s (atan(CtLin s) = pi/4 at CtLin s = 1; a stiffer CtLin is a stiffer dashpot and a smaller step);
# on the plate's nodes the automatic bilinear law (the interface's stiffness K / A_s) with exact Coulomb
# friction mu 0.2.
CTCLAW_LAWS = {1: "n2s13{pz0.01,pe200,KcMax1e5,Mu0.1,CtLin1e-3}", 2: "n1s11{Kc-1,Mu0.2}"}


def starter_deck(variant):
    lagdt = variant == "lagdt"
    run = RUN_NAMES[variant]
    pn, bn = plate_nodes(), block_nodes()
    sh, br = shells(), bricks()
    check_geometry(pn + bn, sh, br)
    L = []
    a = L.append
    a("#RADIOSS STARTER")
    a("# radx default deck%s:" % {"penalty": "", "lagdt": ", LAGDT variant", "ctclaw": ", /CTCLAW variant"}[variant])
    a("# a steel plate (Johnson-Cook shells, clamped edges) hit by an aluminium block (elastic bricks)")
    a("# at 10 m/s. Units: Mg, mm, s (stress in MPa, force in N, energy in mJ).")
    a("# Generated by scripts/make_block_on_plate.py: edit the script and regenerate, not this file.")
    a(RULER)
    a("/BEGIN")
    a("#RUNNAME")
    a(run)
    a(names(("INVERS", 10)))
    a(line(I(VERSION)))
    a(names(("Input_mass", 20), ("Input_length", 20), ("Input_time", 20)))
    a(line(S("Mg", 20), S("mm", 20), S("s", 20)))
    a(names(("Work_mass", 20), ("Work_length", 20), ("Work_time", 20)))
    a(line(S("Mg", 20), S("mm", 20), S("s", 20)))
    a(RULER)
    a("/TITLE")
    a("Block on plate: 20 mm aluminium cube at 10 m/s onto a clamped 100 x 100 x 1 mm steel plate" +
      (" (LAGDT)" if lagdt else ""))
    a(RULER)
    a("#  Global defaults: all zero, so every 0 flag of the /PROP cards takes the hard-coded default")
    a("/DEF_SHELL")
    a(names(("Ishell", 10), ("Ismstr", 10), ("Ithick", 10), ("Iplas", 10), ("Istrain", 10), ("Ioffset", 10),
            ("", 10), ("Ish3n", 10), ("Idrill", 10), ("Ithin_dr", 10)))
    a(line(I(0), I(0), I(0), I(0), I(0), I(0), blank(10), I(0), I(0), I(0)))
    a("/DEF_SOLID")
    a(names(("Isolid", 10), ("Ismstr", 10), ("Icpre", 10), ("", 10), ("Itetra4", 10), ("Itetra10", 10),
            ("Imas", 10), ("Iframe", 10), ("Icontrol", 10)))
    a(line(I(0), I(0), I(0), blank(10), I(0), I(0), I(0), I(0), I(0)))
    a(RULER)
    a("#  Plate nodes 1..121 (11 x 11 grid, 10 mm pitch, mid-plane z = 0)")
    a("/NODE")
    a(names(("node_ID", 10), ("Xc", 20), ("Yc", 20), ("Zc", 20)))
    for n in pn:
        a(line(I(n[0]), R(n[1]), R(n[2]), R(n[3])))
    a("#  Block nodes %d..%d (%d x %d x %d grid, %g mm pitch, bottom face at z = %g)"
      % (NODE0_BLOCK, block_node_id(BLOCK_N, BLOCK_N, BLOCK_N), BLOCK_N + 1, BLOCK_N + 1, BLOCK_N + 1,
         BLOCK_L / BLOCK_N, BLOCK_Z0))
    a("/NODE")
    a(names(("node_ID", 10), ("Xc", 20), ("Yc", 20), ("Zc", 20)))
    for n in bn:
        a(line(I(n[0]), R(n[1]), R(n[2]), R(n[3])))
    a(RULER)
    a("#  Plate: 100 four-node shells of part 1 (normals along +Z)")
    a("/SHELL/1")
    a(names(("shell_ID", 10), ("node_ID1", 10), ("node_ID2", 10), ("node_ID3", 10), ("node_ID4", 10),
            ("", 10), ("PHI", 20), ("Thick", 20)))
    for e in sh:
        a(line(I(e[0]), I(e[1]), I(e[2]), I(e[3]), I(e[4])))
    a("#  Block: 8 bricks of part 2 (nodes 1-4 bottom face, 5-8 top face)")
    a("/BRICK/2")
    a(names(("brick_ID", 10), ("node_ID1", 10), ("node_ID2", 10), ("node_ID3", 10), ("node_ID4", 10),
            ("node_ID5", 10), ("node_ID6", 10), ("node_ID7", 10), ("node_ID8", 10)))
    for e in br:
        a(line(*[I(v) for v in e]))
    a(RULER)
    a("/PART/1")
    a("Plate")
    a(names(("prop_ID", 10), ("mat_ID", 10), ("subset_ID", 10), ("Thick", 20)))
    a(line(I(1), I(1), I(0), R(0.0)))
    a("/PART/2")
    a("Block")
    a(names(("prop_ID", 10), ("mat_ID", 10), ("subset_ID", 10), ("Thick", 20)))
    a(line(I(2), I(2), I(0), R(0.0)))
    a(RULER)
    a("#  Ishell Ismstr Ish3n Idrill = 0: from /DEF_SHELL (all 0), so Ishell 1, Ismstr 2, Ish3n 2, Idrill 0")
    a("/PROP/SHELL/1")
    a("Plate shell 1 mm with 5 integration points")
    a(names(("Ishell", 10), ("Ismstr", 10), ("Ish3n", 10), ("Idrill", 10), ("Ipinch", 10), ("", 10),
            ("P_Thick_Fail", 20)))
    a(line(I(0), I(0), I(0), I(0), I(0), blank(10), R(0.0)))
    a(names(("Hm", 20), ("Hf", 20), ("Hr", 20), ("Dm", 20), ("Dn", 20)))
    a(line(R(0.0), R(0.0), R(0.0), R(0.0), R(0.0)))
    a(names(("N", 10), ("", 10), ("Thick", 20), ("Ashear", 20), ("", 10), ("Ithick", 10), ("Iplas", 10),
            ("Ipos", 10)))
    a(line(I(5), blank(10), R(PLATE_T), R(0.0), blank(10), I(1), I(1), I(0)))
    a("#  Isolid Ismstr Icpre Iframe = 0: from /DEF_SOLID (all 0), so Isolid 1, Ismstr 4, Iframe 1")
    a("/PROP/SOLID/2")
    a("Block solid with one integration point")
    a(names(("Isolid", 10), ("Ismstr", 10), ("Iale", 10), ("Icpre", 10), ("Itetra10", 10), ("Inpts", 10),
            ("Itetra4", 10), ("Iframe", 10), ("dn", 20)))
    a(line(I(0), I(0), I(0), I(0), I(0), I(0), I(0), I(0), R(0.0)))
    a(names(("qa", 20), ("qb", 20), ("h", 20), ("LAMBDA_V", 20), ("MU_V", 20)))
    a(line(R(0.0), R(0.0), R(0.0), R(0.0), R(0.0)))
    a(names(("dtmin", 20), ("vdef_min", 20), ("vdef_max", 20), ("ASP_max", 20), ("COL_min", 20)))
    a(line(R(0.0), R(0.0), R(0.0), R(0.0), R(0.0)))
    a(RULER)
    a("/MAT/PLAS_JOHNS/1")
    a("Steel (Johnson-Cook)")
    a(names(("RHO_I", 20), ("RHO_ref", 20)))
    a(line(R(7.85e-9)))
    a(names(("E", 20), ("nu", 20), ("Iflag", 10), ("flagVP", 10), ("Pmin", 20)))
    a(line(R(210000.0), R(0.3), I(0), I(0), R(0.0)))
    a(names(("a", 20), ("b", 20), ("n", 20), ("EPS_p_max", 20), ("SIG_max0", 20)))
    a(line(R(250.0), R(450.0), R(0.3), R(0.0), R(0.0)))
    a(names(("c", 20), ("EPS_DOT_0", 20), ("ICC", 10), ("Fsmooth", 10), ("F_cut", 20), ("Chard", 20)))
    a(line(R(0.014), R(1.0), I(0), I(0), R(0.0), R(0.0)))
    a(names(("m", 20), ("T_melt", 20), ("rhoC_p", 20), ("T_r", 20), ("T_max", 20)))
    a(line(R(0.0), R(0.0), R(0.0), R(0.0), R(0.0)))
    a("/MAT/LAW1/2")
    a("Aluminium (elastic)")
    a(names(("RHO_I", 20), ("RHO_ref", 20)))
    a(line(R(2.7e-9)))
    a(names(("E", 20), ("nu", 20)))
    a(line(R(70000.0), R(0.33)))
    a(RULER)
    a("/GRNOD/NODE/1")
    a("Plate edge nodes (clamped)")
    a(names(*[("node_ID%d" % (k + 1) if k < 9 else "node_ID10", 10) for k in range(10)]))
    ids = edge_nodes()
    for k in range(0, len(ids), 10):
        a(line(*[I(v) for v in ids[k:k + 10]]))
    a("/GRNOD/PART/2")
    a("Block nodes")
    a(names(("part_ID1", 10)))
    a(line(I(2)))
    a("/GRNOD/PART/3")
    a("Plate nodes")
    a(names(("part_ID1", 10)))
    a(line(I(1)))
    a("/SURF/PART/1")
    a("Plate surface (shell segments with normals along +Z)")
    a(names(("part_ID1", 10)))
    a(line(I(1)))
    a("/SURF/PART/EXT/2")
    a("Block outer faces (outward)")
    a(names(("part_ID1", 10)))
    a(line(I(2)))
    a(RULER)
    if not FREE:
        a("/BCS/1")
        a("Clamped plate edges")
        a(names(("Tra rot", 10), ("skew_ID", 10), ("grnod_ID", 10)))
        a(line(bcs_code("111", "111"), I(0), I(1)))
    a("/INIVEL/TRA/1")
    a("Block initial velocity %g m/s downwards" % (-V0 / 1000.0))
    a(names(("Vx", 20), ("Vy", 20), ("Vz", 20), ("grnod_ID", 10), ("skew_ID", 10)))
    a(line(R(0.0), R(0.0), R(V0), I(2), I(0)))
    a(names(("Tstart", 20), ("sensor_ID", 10)))
    a(line(R(0.0), I(0)))
    if not FREE:
        a("/GRAV/1")
        a("Gravity 9.81 m/s^2 downwards on all nodes (constant: no function)")
        a(names(("funct_IDT", 10), ("DIR", 10), ("skew_ID", 10), ("sensor_ID", 10), ("grnod_ID", 10), ("", 10),
                ("Ascale_x", 20), ("Fscale_y", 20)))
        a(line(I(0), S("Z", 10), I(0), I(0), I(0), blank(10), R(0.0), R(GRAVITY)))
    a("/FUNCT/1")
    a("Unit ramp over 0.5 ms (not referenced by this deck)")
    a(names(("X", 20), ("Y", 20)))
    for x, y in ((0.0, 0.0), (0.0005, 1.0), (1.0, 1.0)):
        a(line(R(x), R(y)))
    a(RULER)
    a(interface(1, "Block nodes on plate surface", lagdt, grnod=2, surf=1, istf=4, inacti=6, fric=0.1,
                iform=1, viss=0.05))
    a(interface(2, "Plate nodes on block outer faces", lagdt, grnod=3, surf=2, istf=0, inacti=0, fric=0.2,
                iform=2, viss=0.0))
    if variant == "ctclaw":
        a("#  The interfaces' normal and friction laws replaced by the /CTCLAW family (contact-laws.md)")
        for iid, law in CTCLAW_LAWS.items():
            a("/CTCLAW/%d" % (10 + iid))
            a("Law of interface %d" % iid)
            a(names(("inter_ID", 10)))
            a(line(I(iid)))
            a(law)
    a(RULER)
    a("/TH/NODE/1")
    a("Plate centre and block bottom centre")
    a(names(("var_ID1", 10)))
    a("DEF")
    a(names(("node_ID", 10), ("skew_ID", 10)) + " node_name (columns 21-100)")
    a(line(I(centre_node()), I(0), " Plate centre"))
    a(line(I(block_bottom_centre_node()), I(0), " Block bottom centre"))
    a("/TH/PART/2")
    a("Plate and block")
    a(names(("var_ID1", 10)))
    a("DEF")
    a(names(("part_ID1", 10), ("part_ID2", 10)))
    a(line(I(1), I(2)))
    a("/TH/INTER/3")
    a("Both interfaces")
    a(names(("var_ID1", 10)))
    a("DEF")
    a(names(("inter_ID1", 10), ("inter_ID2", 10)))
    a(line(I(1), I(2)))
    a(RULER)
    a("/END")
    text = []
    for x in L:
        text.extend(x.split("\n") if "\n" in x else [x])
    return text


def interface(iid, title, lagdt, grnod, surf, istf, inacti, fric, iform, viss):
    """One TYPE7 (2026 layout) or LAGDT/TYPE7 block, as text with embedded newlines."""
    L = []
    a = L.append
    if lagdt:
        a("/INTER/LAGDT/TYPE7/%d" % iid)
        a(title)
        a(names(("grnd_IDs", 10), ("surf_IDm", 10), ("Istf", 10), ("", 10), ("Igap", 10), ("", 10),
                ("Ibag", 10), ("Idel", 10)))
        a(line(I(grnod), I(surf), I(istf), blank(10), I(0), blank(10), I(0), I(0)))
        a(names(("Fscalegap", 20), ("Gapmax", 20)))
        a(line(R(0.0), R(0.0)))
        a(names(("Stmin", 20), ("Stmax", 20)))
        a(line(R(0.0), R("1E30" if istf >= 2 else 0.0)))
        a(names(("Stfac", 20), ("Fric", 20), ("Gapmin", 20), ("Tstart", 20), ("Tstop", 20)))
        a(line(R(STFAC), R(fric), R(0.0), R(0.0), R(0.0)))
        a(names(("IBC", 10), ("", 20), ("Inacti", 10), ("VISs", 20), ("VISf", 20), ("Bumult", 20)))
        a(line(ibc_code(0, 0, 0), blank(20), I(inacti), R(viss), R(1.0), R(0.0)))
        a(names(("Ifric", 10), ("Ifiltr", 10), ("Xfreq", 20), ("Iform", 10)))
        a(line(I(0), I(0), R(0.0), I(iform)))
    else:
        a("/INTER/TYPE7/%d" % iid)
        a(title)
        a(names(("grnd_IDs", 10), ("surf_IDm", 10), ("Istf", 10), ("Ithe", 10), ("Igap", 10), ("", 10),
                ("Ibag", 10), ("Idel", 10), ("Icurv", 10), ("Iadm", 10)))
        a(line(I(grnod), I(surf), I(istf), I(0), I(0), blank(10), I(0), I(0), I(0), I(0)))
        a(names(("Fscalegap", 20), ("Gap_max", 20), ("Fpenmax", 20), ("", 20), ("Itied", 10), ("Ists", 10)))
        a(line(R(0.0), R(0.0), R(0.0), blank(20), I(0), I(0)))
        a(names(("Stmin", 20), ("Stmax", 20), ("%mesh_size", 20), ("dtmin", 20), ("Irem_gap", 10),
                ("Irem_i2", 10)))
        a(line(R(0.0), R("1E30" if istf >= 2 else 0.0), R(0.0), R(0.0), I(0), I(0)))
        a(names(("Stfac", 20), ("Fric", 20), ("Gapmin", 20), ("Tstart", 20), ("Tstop", 20)))
        a(line(R(STFAC), R(fric), R(0.0), R(0.0), R(0.0)))
        a(names(("IBC", 10), ("", 20), ("Inacti", 10), ("VISs", 20), ("VISf", 20), ("Bumult", 20)))
        a(line(ibc_code(0, 0, 0), blank(20), I(inacti), R(viss), R(1.0), R(0.0)))
        a(names(("Ifric", 10), ("Ifiltr", 10), ("Xfreq", 20), ("Iform", 10), ("sens_ID", 10), ("fct_IDF", 10),
                ("AscaleF", 20), ("fric_ID", 10)))
        a(line(I(0), I(0), R(0.0), I(iform), I(0), I(0), R(0.0), I(0)))
    return "\n".join(L)


# ---------------------------------------------------------------------------------------------------
# Engine deck


def engine_deck(variant, lagdt_tmin=1e-6):
    lagdt = variant == "lagdt"
    run = RUN_NAMES[variant]
    L = []
    a = L.append
    a("#RADIOSS ENGINE")
    a("# Engine deck of %s_0000.rad." % run)
    a("# Engine data lines are free format; the values are aligned only to be easy to read.")
    a("# Generated by scripts/make_block_on_plate.py.")
    a(RULER)
    a("/RUN/%s/1" % run)
    a(names(("Tstop", 20)))
    a(line(R(TSTOP)))
    a(RULER)
    a("/TFILE")
    a(names(("dt_his", 20)))
    a(line(R(1e-5)))
    a("/ANIM/DT")
    a(names(("Tstart", 20), ("dT", 20)))
    a(line(R(0.0), R(0.0001)))
    a("/ANIM/ELEM/VONM")
    a("/ANIM/ELEM/EPSP")
    a("/ANIM/VECT/VEL")
    a("/ANIM/VECT/CONT")
    a(RULER)
    a("/DT")
    a(names(("Tscale", 20), ("Tmin", 20)))
    a(line(R(0.9), R(0.0)))
    if lagdt and INTER_DT:
        a("#  Contact pairs of the LAGDT interfaces whose time step would fall below Tmin switch to")
        a("#  Lagrange multipliers (type7-lagdt.md section 6; OpenRadioss itself needs /DT/INTER/LAG).")
        a("/DT/INTER/CST")
        a(names(("Tscale", 20), ("Tmin", 20)))
        a(line(R(0.9), R(lagdt_tmin)))
    a("/PRINT/-100")
    a("/STOP")
    a(names(("Emax", 20), ("Mmax", 20), ("Nmax", 20), ("NTH", 10), ("NANIM", 10)))
    a(line(R("1.0E+30"), R("1.0E+30"), R("1.0E+30"), I(1), I(1)))
    a(RULER)
    a("/END")
    return L


def main(argv):
    here = os.path.dirname(os.path.abspath(__file__))
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--variant", choices=("penalty", "lagdt", "ctclaw", "all"), default="all")
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
    variants = ("penalty", "lagdt", "ctclaw") if args.variant == "all" else (args.variant,)
    for v in variants:
        root = RUN_NAMES[v]
        folder = root.lower()
        d = os.path.normpath(os.path.join(args.out, folder))
        write(os.path.join(d, root + "_0000.rad"), starter_deck(v), report=True)
        write(os.path.join(d, root + "_0001.rad"), engine_deck(v, args.lagdt_tmin), report=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
