#!/usr/bin/env python3
"""Generate a large shell-plate benchmark deck pair in Radioss block format (fixed columns, format 2026).

    python3 bench/gen_shell_plate.py                    # N = 1000: 1,000,000 shells, 1,002,001 nodes
    python3 bench/gen_shell_plate.py --n 200 --out /tmp/bench
    python3 bench/gen_shell_plate.py --impact           # adds a 10 x 10 x 4 brick block and two TYPE7
    python3 bench/gen_shell_plate.py --n 200 --impact --contact lagdt     # the LAGDT variant (PLATE200I_LAGDT)
    python3 bench/gen_shell_plate.py --n 200 --impact --contact addmass   # TYPE7 + /DT/INTER/CST added mass

Writes PLATE<N>_0000.rad (starter) and PLATE<N>_0001.rad (engine) into --out (default: the current folder).
With --impact the root name is PLATE<N>I (PLATE<N>I_0000.rad ...), so both variants can sit side by side.

Model (units Mg, mm, s): a 1000 x 1000 mm steel plate, 1 mm thick, meshed with N x N four-node shells
(Johnson-Cook, 5 integration points), clamped on its four edges.
  * without --impact: every plate node starts at 1 m/s downwards (/INIVEL/TRA on /GRNOD/PART of the plate);
    the clamped edges hold it, so the whole plate vibrates and yields along the edges;
  * with --impact: the plate is at rest and an aluminium block of 10 x 10 x 4 bricks (100 x 100 x 40 mm,
    bricks of L/100 = 10 mm whatever N is) sits 1 mm above the plate centre (bottom face z = 1.5) and moves
    down at 10 m/s. Two TYPE7 interfaces as in decks/block_on_plate: block nodes on the plate surface
    (Istf 4, Inacti 6, Fric 0.1, Iform 1) and plate nodes on the block's outer faces (Istf 0, Fric 0.2,
    Iform 2).
  --contact lagdt writes both interfaces as /INTER/LAGDT/TYPE7 and adds /DT/INTER/CST 0.9 Tmin (--tmin) to the
  engine deck: pairs whose step would fall below Tmin switch to Lagrange multipliers; --contact addmass keeps
  the TYPE7 cards with the same /DT/INTER/CST, which adds mass instead. Root names PLATE<N>I_LAGDT and
  PLATE<N>I_ADDMASS.
Tstop is set so that about 1500 cycles run at the shell time step 0.9 h / sqrt(E/rho) (h = 1000/N mm);
contact can lower the step in the --impact variant. With Igap 0 the computed gaps are min(t, lmin/2) = 0.5 mm
for interface 1 when h = 1 mm (N = 1000) and l/10 = 1 mm for interface 2, so nothing penetrates at t = 0.

Plain python3, standard library only; a few seconds for N = 1000 (about 2 s here).
"""
import argparse
import math
import os
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scripts"))
from radx_deck_format import I, R, S, RULER, bcs_code, blank, ibc_code, line, names, write  # noqa: E402

L_PLATE = 1000.0       # mm
THICK = 1.0            # mm
E_STEEL, NU_STEEL, RHO_STEEL = 210000.0, 0.3, 7.85e-9
E_ALU, NU_ALU, RHO_ALU = 70000.0, 0.33, 2.7e-9
CYCLES = 1500
SIG = 12               # significant digits of a computed real whose shortest exact text is too long
BLOCK_NX, BLOCK_NZ = 10, 4
BLOCK_Z0 = 1.5


def sig3(x):
    """Round to 3 significant digits (for Tstop)."""
    e = math.floor(math.log10(abs(x)))
    return round(x, -e + 2)


def first_power_of_ten_above(n):
    p = 10
    while p <= n:
        p *= 10
    return p


def starter(n, impact, root, lagdt=False):
    h = L_PLATE / n
    nn = n + 1
    out = []
    a = out.append
    a("#RADIOSS STARTER")
    a("# Benchmark deck written by bench/gen_shell_plate.py:")
    a("# %d x %d four-node shells (%d nodes)%s." % (n, n, nn * nn, " and a block of 400 bricks" if impact else ""))
    a("# Units: Mg, mm, s.")
    a(RULER)
    a("/BEGIN")
    a(root)
    a(names(("INVERS", 10)))
    a(I(2026))
    a(names(("Input_mass", 20), ("Input_length", 20), ("Input_time", 20)))
    a(line(S("Mg", 20), S("mm", 20), S("s", 20)))
    a(names(("Work_mass", 20), ("Work_length", 20), ("Work_time", 20)))
    a(line(S("Mg", 20), S("mm", 20), S("s", 20)))
    a(RULER)
    a("/TITLE")
    a("Clamped %g mm steel plate: %d x %d shells%s" % (L_PLATE, n, n, " hit by an aluminium block" if impact
                                                          else " with an initial velocity"))
    a(RULER)
    a("/NODE")
    a(names(("node_ID", 10), ("Xc", 20), ("Yc", 20), ("Zc", 20)))
    cs = [R((2 * i - n) * L_PLATE / (2 * n), sig=SIG) for i in range(nn)]
    z0 = R(0.0)
    # the plate nodes and shells are the bulk of the deck: "%10d" is I() without its checks, for speed
    nid = 1
    for j in range(nn):
        yz = cs[j] + z0
        a("\n".join("%10d%s%s" % (nid + i, cs[i], yz) for i in range(nn)))
        nid += nn
    block_node0 = first_power_of_ten_above(nn * nn)
    block_elem0 = first_power_of_ten_above(n * n)
    if impact:
        hb = L_PLATE / 100.0
        nb = BLOCK_NX + 1
        a("#  Block nodes: %d x %d x %d grid of %g mm pitch, bottom face at z = %g" % (nb, nb, BLOCK_NZ + 1, hb,
                                                                                     BLOCK_Z0))
        a("/NODE")
        a(names(("node_ID", 10), ("Xc", 20), ("Yc", 20), ("Zc", 20)))
        bc = [R((2 * i - BLOCK_NX) * hb / 2, sig=SIG) for i in range(nb)]
        for k in range(BLOCK_NZ + 1):
            zs = R(BLOCK_Z0 + k * hb, sig=SIG)
            for j in range(nb):
                for i in range(nb):
                    a(line(I(block_node0 + 1 + i + nb * j + nb * nb * k), bc[i], bc[j], zs))
    a(RULER)
    a("/SHELL/1")
    a(names(("shell_ID", 10), ("node_ID1", 10), ("node_ID2", 10), ("node_ID3", 10), ("node_ID4", 10),
            ("", 10), ("PHI", 20), ("Thick", 20)))
    eid = 1
    for j in range(n):
        base = 1 + nn * j
        a("\n".join("%10d%10d%10d%10d%10d" % (eid + i, base + i, base + i + 1, base + i + 1 + nn, base + i + nn)
                    for i in range(n)))
        eid += n
    if impact:
        nb = BLOCK_NX + 1
        a("/BRICK/2")
        a(names(("brick_ID", 10), ("node_ID1", 10), ("node_ID2", 10), ("node_ID3", 10), ("node_ID4", 10),
                ("node_ID5", 10), ("node_ID6", 10), ("node_ID7", 10), ("node_ID8", 10)))

        def bn(i, j, k):
            return block_node0 + 1 + i + nb * j + nb * nb * k

        for k in range(BLOCK_NZ):
            for j in range(BLOCK_NX):
                for i in range(BLOCK_NX):
                    e = block_elem0 + 1 + i + BLOCK_NX * j + BLOCK_NX * BLOCK_NX * k
                    ids = (bn(i, j, k), bn(i + 1, j, k), bn(i + 1, j + 1, k), bn(i, j + 1, k),
                           bn(i, j, k + 1), bn(i + 1, j, k + 1), bn(i + 1, j + 1, k + 1), bn(i, j + 1, k + 1))
                    a(line(I(e), *[I(x) for x in ids]))
    a(RULER)
    a("/PART/1")
    a("Plate")
    a(names(("prop_ID", 10), ("mat_ID", 10), ("subset_ID", 10), ("Thick", 20)))
    a(line(I(1), I(1), I(0), R(0.0)))
    if impact:
        a("/PART/2")
        a("Block")
        a(names(("prop_ID", 10), ("mat_ID", 10), ("subset_ID", 10), ("Thick", 20)))
        a(line(I(2), I(2), I(0), R(0.0)))
    a(RULER)
    a("/PROP/SHELL/1")
    a("Plate shell %g mm with 5 integration points" % THICK)
    a(names(("Ishell", 10), ("Ismstr", 10), ("Ish3n", 10), ("Idrill", 10), ("Ipinch", 10), ("", 10),
            ("P_Thick_Fail", 20)))
    a(line(I(1), I(2), I(2), I(0), I(0), blank(10), R(0.0)))
    a(names(("Hm", 20), ("Hf", 20), ("Hr", 20), ("Dm", 20), ("Dn", 20)))
    a(line(R(0.0), R(0.0), R(0.0), R(0.0), R(0.0)))
    a(names(("N", 10), ("", 10), ("Thick", 20), ("Ashear", 20), ("", 10), ("Ithick", 10), ("Iplas", 10),
            ("Ipos", 10)))
    a(line(I(5), blank(10), R(THICK), R(0.0), blank(10), I(1), I(1), I(0)))
    if impact:
        a("/PROP/SOLID/2")
        a("Block solid")
        a(names(("Isolid", 10), ("Ismstr", 10), ("Iale", 10), ("Icpre", 10), ("Itetra10", 10), ("Inpts", 10),
                ("Itetra4", 10), ("Iframe", 10), ("dn", 20)))
        a(line(I(1), I(4), I(0), I(0), I(0), I(0), I(0), I(1), R(0.0)))
        a(names(("qa", 20), ("qb", 20), ("h", 20), ("LAMBDA_V", 20), ("MU_V", 20)))
        a(line(R(0.0), R(0.0), R(0.0), R(0.0), R(0.0)))
        a(names(("dtmin", 20), ("vdef_min", 20), ("vdef_max", 20), ("ASP_max", 20), ("COL_min", 20)))
        a(line(R(0.0), R(0.0), R(0.0), R(0.0), R(0.0)))
    a(RULER)
    a("/MAT/PLAS_JOHNS/1")
    a("Steel (Johnson-Cook)")
    a(names(("RHO_I", 20), ("RHO_ref", 20)))
    a(line(R(RHO_STEEL)))
    a(names(("E", 20), ("nu", 20), ("Iflag", 10), ("flagVP", 10), ("Pmin", 20)))
    a(line(R(E_STEEL), R(NU_STEEL), I(0), I(0), R(0.0)))
    a(names(("a", 20), ("b", 20), ("n", 20), ("EPS_p_max", 20), ("SIG_max0", 20)))
    a(line(R(250.0), R(450.0), R(0.3), R(0.0), R(0.0)))
    a(names(("c", 20), ("EPS_DOT_0", 20), ("ICC", 10), ("Fsmooth", 10), ("F_cut", 20), ("Chard", 20)))
    a(line(R(0.014), R(1.0), I(0), I(0), R(0.0), R(0.0)))
    a(names(("m", 20), ("T_melt", 20), ("rhoC_p", 20), ("T_r", 20), ("T_max", 20)))
    a(line(R(0.0), R(0.0), R(0.0), R(0.0), R(0.0)))
    if impact:
        a("/MAT/LAW1/2")
        a("Aluminium (elastic)")
        a(names(("RHO_I", 20), ("RHO_ref", 20)))
        a(line(R(RHO_ALU)))
        a(names(("E", 20), ("nu", 20)))
        a(line(R(E_ALU), R(NU_ALU)))
    a(RULER)
    a("/GRNOD/NODE/1")
    a("Plate edge nodes (clamped)")
    a(names(*[("node_ID%d" % k, 10) for k in range(1, 11)]))
    edge = list(range(1, nn + 1))                                      # y = -L/2
    for j in range(1, nn - 1):
        edge += [1 + nn * j, nn + nn * j]                              # x = -L/2 and x = +L/2
    edge += list(range(1 + nn * (nn - 1), nn * nn + 1))                # y = +L/2
    a("\n".join(line(*[I(x) for x in edge[k:k + 10]]) for k in range(0, len(edge), 10)))
    a("/GRNOD/PART/2")
    a("Plate nodes")
    a(names(("part_ID1", 10)))
    a(I(1))
    if impact:
        a("/GRNOD/PART/3")
        a("Block nodes")
        a(names(("part_ID1", 10)))
        a(I(2))
        a("/SURF/PART/1")
        a("Plate surface")
        a(names(("part_ID1", 10)))
        a(I(1))
        a("/SURF/PART/EXT/2")
        a("Block outer faces")
        a(names(("part_ID1", 10)))
        a(I(2))
    a(RULER)
    a("/BCS/1")
    a("Clamped plate edges")
    a(names(("Tra rot", 10), ("skew_ID", 10), ("grnod_ID", 10)))
    a(line(bcs_code("111", "111"), I(0), I(1)))
    a("/INIVEL/TRA/1")
    a("Block at 10 m/s downwards" if impact else "Plate at 1 m/s downwards")
    a(names(("Vx", 20), ("Vy", 20), ("Vz", 20), ("grnod_ID", 10), ("skew_ID", 10)))
    a(line(R(0.0), R(0.0), R(-10000.0 if impact else -1000.0), I(3 if impact else 2), I(0)))
    if impact:
        a(RULER)
        for iid, title, grnod, surf, istf, inacti, fric, iform, viss in (
                (1, "Block nodes on plate surface", 3, 1, 4, 6, 0.1, 1, 0.05),
                (2, "Plate nodes on block outer faces", 2, 2, 0, 0, 0.2, 2, 0.0)):
            if lagdt:  # the LAGDT layout (deck-format.md): no Ithe, Icurv, Iadm, Fpenmax, ... fric_ID
                a("/INTER/LAGDT/TYPE7/%d" % iid)
                a(title)
                a(names(("grnd_IDs", 10), ("surf_IDm", 10), ("Istf", 10), ("", 10), ("Igap", 10), ("", 10),
                        ("Ibag", 10), ("Idel", 10)))
                a(line(I(grnod), I(surf), I(istf), blank(10), I(0), blank(10), I(0), I(0)))
                a(names(("Fscalegap", 20), ("Gapmax", 20)))
                a(line(R(0.0), R(0.0)))
                a(names(("Stmin", 20), ("Stmax", 20)))
                a(line(R(0.0), R("1E30" if istf >= 2 else 0.0)))
            else:
                a("/INTER/TYPE7/%d" % iid)
                a(title)
                a(names(("grnd_IDs", 10), ("surf_IDm", 10), ("Istf", 10), ("Ithe", 10), ("Igap", 10), ("", 10),
                        ("Ibag", 10), ("Idel", 10), ("Icurv", 10), ("Iadm", 10)))
                a(line(I(grnod), I(surf), I(istf), I(0), I(0), blank(10), I(0), I(0), I(0), I(0)))
                a(names(("Fscalegap", 20), ("Gap_max", 20), ("Fpenmax", 20), ("", 20), ("Itied", 10),
                        ("Ists", 10)))
                a(line(R(0.0), R(0.0), R(0.0), blank(20), I(0), I(0)))
                a(names(("Stmin", 20), ("Stmax", 20), ("%mesh_size", 20), ("dtmin", 20), ("Irem_gap", 10),
                        ("Irem_i2", 10)))
                a(line(R(0.0), R("1E30" if istf >= 2 else 0.0), R(0.0), R(0.0), I(0), I(0)))
            a(names(("Stfac", 20), ("Fric", 20), ("Gapmin", 20), ("Tstart", 20), ("Tstop", 20)))
            a(line(R(1.0), R(fric), R(0.0), R(0.0), R(0.0)))
            a(names(("IBC", 10), ("", 20), ("Inacti", 10), ("VISs", 20), ("VISf", 20), ("Bumult", 20)))
            a(line(ibc_code(0, 0, 0), blank(20), I(inacti), R(viss), R(1.0), R(0.0)))
            if lagdt:
                a(names(("Ifric", 10), ("Ifiltr", 10), ("Xfreq", 20), ("Iform", 10)))
                a(line(I(0), I(0), R(0.0), I(iform)))
            else:
                a(names(("Ifric", 10), ("Ifiltr", 10), ("Xfreq", 20), ("Iform", 10), ("sens_ID", 10),
                        ("fct_IDF", 10), ("AscaleF", 20), ("fric_ID", 10)))
                a(line(I(0), I(0), R(0.0), I(iform), I(0), I(0), R(0.0), I(0)))
    a(RULER)
    a("/TH/NODE/1")
    a("Plate centre")
    a(names(("var_ID1", 10)))
    a("DEF")
    a(names(("node_ID", 10), ("skew_ID", 10)) + " node_name (columns 21-100)")
    centre = 1 + (n // 2) + nn * (n // 2)
    a(line(I(centre), I(0), " Plate centre"))
    a("/TH/PART/2")
    a("Parts")
    a(names(("var_ID1", 10)))
    a("DEF")
    a(names(("part_ID1", 10), ("part_ID2", 10)) if impact else names(("part_ID1", 10)))
    a(line(I(1), I(2)) if impact else I(1))
    if impact:
        a("/TH/INTER/3")
        a("Both interfaces")
        a(names(("var_ID1", 10)))
        a("DEF")
        a(names(("inter_ID1", 10), ("inter_ID2", 10)))
        a(line(I(1), I(2)))
    a(RULER)
    a("/END")
    return out


def engine(n, root, inter_tmin=0.0):
    h = L_PLATE / n
    dt_shell = 0.9 * h / math.sqrt(E_STEEL / RHO_STEEL)
    tstop = sig3(CYCLES * dt_shell)
    out = ["#RADIOSS ENGINE",
           "# Tstop = %d cycles x shell time step 0.9 h / sqrt(E/rho) = %d x %.4g s" % (CYCLES, CYCLES, dt_shell),
           RULER,
           "/RUN/%s/1" % root,
           names(("Tstop", 20)), R(tstop, sig=SIG),
           "/TFILE", names(("dt_his", 20)), R(sig3(tstop / 100), sig=SIG),
           "/ANIM/DT", names(("Tstart", 20), ("dT", 20)), line(R(0.0), R(sig3(tstop / 2), sig=SIG)),
           "/ANIM/ELEM/VONM", "/ANIM/ELEM/EPSP", "/ANIM/VECT/VEL",
           "/DT", names(("Tscale", 20), ("Tmin", 20)), line(R(0.9), R(0.0)),
           *([] if not inter_tmin else
             ["#  /DT/INTER/CST: LAGDT pairs below Tmin switch to Lagrange multipliers; TYPE7 nodes get added mass",
              "/DT/INTER/CST", names(("Tscale", 20), ("Tmin", 20)), line(R(0.9), R(inter_tmin))]),
           "/PRINT/-100",
           "/STOP", names(("Emax", 20), ("Mmax", 20), ("Nmax", 20), ("NTH", 10), ("NANIM", 10)),
           line(R("1.0E+30"), R("1.0E+30"), R("1.0E+30"), I(1), I(1)),
           RULER,
           "/END"]
    return out, tstop


def main(argv):
    p = argparse.ArgumentParser(description="Write a large N x N shell plate benchmark deck (format 2026).")
    p.add_argument("--n", type=int, default=1000, help="elements per side (default 1000: one million shells)")
    p.add_argument("--out", default=".", help="output folder (default: current folder)")
    p.add_argument("--impact", action="store_true", help="add a 10 x 10 x 4 brick block and two TYPE7")
    p.add_argument("--contact", choices=("type7", "lagdt", "addmass"), default="type7",
                   help="with --impact: plain TYPE7 (default); lagdt: /INTER/LAGDT/TYPE7 with /DT/INTER/CST Tmin; "
                        "addmass: plain TYPE7 with /DT/INTER/CST Tmin (added mass)")
    p.add_argument("--tmin", type=float, default=8e-7,
                   help="Tmin of /DT/INTER/CST for --contact lagdt and addmass (default 8e-7 s: just below the "
                        "shell step of --n 200)")
    args = p.parse_args(argv)
    if args.n < 2:
        p.error("--n must be at least 2")
    if args.contact != "type7" and not args.impact:
        p.error("--contact needs --impact")
    root = "PLATE%d%s" % (args.n, "I" if args.impact else "")
    if args.contact != "type7":
        root += "_" + args.contact.upper()
    os.makedirs(args.out, exist_ok=True)
    t0 = time.time()
    s_path = os.path.join(args.out, root + "_0000.rad")
    e_path = os.path.join(args.out, root + "_0001.rad")
    write(s_path, starter(args.n, args.impact, root, lagdt=args.contact == "lagdt"))
    lines, tstop = engine(args.n, root, args.tmin if args.contact != "type7" else 0.0)
    write(e_path, lines)
    print("wrote %s and %s: %d shells, %d plate nodes%s, Tstop %g s (%.1f s)" %
          (s_path, e_path, args.n * args.n, (args.n + 1) ** 2,
           ", 400 bricks and 605 block nodes" if args.impact else "", tstop, time.time() - t0))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
