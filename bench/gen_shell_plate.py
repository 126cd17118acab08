#!/usr/bin/env python3
"""Generate a large shell-plate benchmark deck pair in Radioss block format (fixed columns, format 2026).

    python3 bench/gen_shell_plate.py                    # N = 1000: 1,000,000 shells, 1,002,001 nodes
    python3 bench/gen_shell_plate.py --n 200 --out /tmp/bench
    python3 bench/gen_shell_plate.py --impact           # adds a 10 x 10 x 4 brick block and two TYPE7
    python3 bench/gen_shell_plate.py --n 200 --impact --contact lagdt     # the LAGDT variant (PLATE200I_LAGDT)
    python3 bench/gen_shell_plate.py --n 200 --impact --contact addmass   # TYPE7 + /DT/INTER/CST added mass
    python3 bench/gen_shell_plate.py --n 400 --impact --block 40 --brick-size 5 --contact none
                                                         # contact-free (PLATE400I_NOCONTACT): 166,400 elements
    python3 bench/gen_shell_plate.py --n 200 --ishell 24                  # the plate in QEPH (PLATE200_QEPH)
    python3 bench/gen_shell_plate.py --n 200 --impact --isolid 24         # the block in HEPH bricks (PLATE200I_HEPH)

Writes PLATE<N>_0000.rad (starter) and PLATE<N>_0001.rad (engine) into --out (default: the current folder).
With --impact the root name is PLATE<N>I (PLATE<N>I_0000.rad ...), so both variants can sit side by side.
--ishell 12 or 24 writes the plate's /PROP/SHELL with that formulation (QBAT, QEPH) and appends _QBAT or
_QEPH to the root name; the default 1 is the Belytschko-Tsay shell.

Model (units Mg, mm, s): a 1000 x 1000 mm steel plate, 1 mm thick, meshed with N x N four-node shells
(Johnson-Cook, 5 integration points), clamped on its four edges.
  * without --impact: every plate node starts at 1 m/s downwards (/INIVEL/TRA on /GRNOD/PART of the plate);
    the clamped edges hold it, so the whole plate vibrates and yields along the edges;
  * with --impact: the plate is at rest and an aluminium block of 10 x 10 x 4 bricks (--block B: B x B x 4;
    10 mm bricks whatever N is, --brick-size H: H mm bricks) sits 1 mm (--gap G: G mm) above the plate
    centre (bottom face z = 1.5) and moves down at 10 m/s. Two TYPE7 interfaces as in decks/block_on_plate: block nodes on the plate surface
    (Istf 4, Inacti 6, Fric 0.1, Iform 1) and plate nodes on the block's outer faces (Istf 0, Fric 0.2,
    Iform 2).
  --contact lagdt writes both interfaces as /INTER/LAGDT/TYPE7 and adds /DT/INTER/CST 0.9 Tmin (--tmin) to the
  engine deck: pairs whose step would fall below Tmin switch to Lagrange multipliers; --contact addmass keeps
  the TYPE7 cards with the same /DT/INTER/CST, which adds mass instead. Root names PLATE<N>I_LAGDT and
  PLATE<N>I_ADDMASS. --contact none writes the same model without the interfaces (and their time history):
  the block's and the plate's elements all run, the block passes through the plate unhindered (root name
  PLATE<N>I_NOCONTACT; the MPI benchmark bench/mpi_scaling.sh, whose engine does not split contact).
--th-records K and --anim-states K set the time history's interval (/TFILE, Tstop / K, default 100) and the
states' (/ANIM/DT, Tstop / K, default 2); 0 leaves the card out (the engine then writes the time history and
the states at t = 0 and at the end only).
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
import radx_cards as rc  # noqa: E402  (the card layouts and their writer)

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


def starter(n, impact, root, lagdt=False, ishell=1, isolid=1, block_nx=BLOCK_NX, brick=L_PLATE / 100.0,
            block_z0=BLOCK_Z0, bumult=0.0, contact=True):
    nn = n + 1
    d = rc.Deck(fill=0)
    d.raw("#RADIOSS STARTER")
    d.comment("Benchmark deck written by bench/gen_shell_plate.py:",
              "%d x %d four-node shells (%d nodes)%s." % (
                  n, n, nn * nn, " and a block of %d bricks" % (block_nx * block_nx * BLOCK_NZ) if impact else ""),
              "Units: Mg, mm, s.")
    d.ruler().begin(root, ("Mg", "mm", "s")).ruler()
    d.card("/TITLE", title="Clamped %g mm steel plate: %d x %d shells%s" % (
        L_PLATE, n, n, " hit by an aluminium block" if impact else " with an initial velocity"))
    d.ruler()
    # the plate nodes and shells are the bulk of the deck: written here with "%10d" and the cells computed once
    # per coordinate, for speed (the card writer checks every cell)
    d.rows("/NODE", [])
    cs = [rc.R((2 * i - n) * L_PLATE / (2 * n), sig=SIG) for i in range(nn)]
    z0 = rc.R(0.0)
    for j in range(nn):
        yz = cs[j] + z0
        d.raw("\n".join("%10d%s%s" % (1 + nn * j + i, cs[i], yz) for i in range(nn)))
    block_node0 = first_power_of_ten_above(nn * nn)
    block_elem0 = first_power_of_ten_above(n * n)
    nb = block_nx + 1

    def bn(i, j, k):
        return block_node0 + 1 + i + nb * j + nb * nb * k

    if impact:
        hb = brick
        d.raw("#  Block nodes: %d x %d x %d grid of %g mm pitch, bottom face at z = %g" % (nb, nb, BLOCK_NZ + 1, hb,
                                                                                         block_z0))
        d.rows("/NODE", [(bn(i, j, k), (2 * i - block_nx) * hb / 2, (2 * j - block_nx) * hb / 2, block_z0 + k * hb)
                         for k in range(BLOCK_NZ + 1) for j in range(nb) for i in range(nb)], sig=SIG)
    d.ruler()
    d.rows("/SHELL", [], 1)
    for j in range(n):
        base = 1 + nn * j
        d.raw("\n".join("%10d%10d%10d%10d%10d" % (1 + n * j + i, base + i, base + i + 1, base + i + 1 + nn,
                                                   base + i + nn) for i in range(n)))
    if impact:
        d.rows("/BRICK", [(block_elem0 + 1 + i + block_nx * j + block_nx * block_nx * k,
                           bn(i, j, k), bn(i + 1, j, k), bn(i + 1, j + 1, k), bn(i, j + 1, k),
                           bn(i, j, k + 1), bn(i + 1, j, k + 1), bn(i + 1, j + 1, k + 1), bn(i, j + 1, k + 1))
                          for k in range(BLOCK_NZ) for j in range(block_nx) for i in range(block_nx)], 2)
    d.ruler()
    d.card("/PART", 1, "Plate", prop_ID=1, mat_ID=1)
    if impact:
        d.card("/PART", 2, "Block", prop_ID=2, mat_ID=2)
    d.ruler()
    d.card("/PROP/SHELL", 1, "Plate shell %g mm with 5 integration points" % THICK, Ishell=ishell, Ismstr=2, Ish3n=2,
           N=5, Thick=THICK, Ithick=1, Iplas=1)
    if impact:
        d.card("/PROP/SOLID", 2, "Block solid", Isolid=isolid, Ismstr=4, Iframe=2 if isolid == 24 else 1)
    d.ruler()
    d.card("/MAT/PLAS_JOHNS", 1, "Steel (Johnson-Cook)", RHO_I=RHO_STEEL, RHO_ref=None, E=E_STEEL, nu=NU_STEEL,
           a=250.0, b=450.0, n=0.3, c=0.014, EPS_DOT_0=1.0)
    if impact:
        d.card("/MAT/LAW1", 2, "Aluminium (elastic)", RHO_I=RHO_ALU, RHO_ref=None, E=E_ALU, nu=NU_ALU)
    d.ruler()
    edge = list(range(1, nn + 1))                                      # y = -L/2
    for j in range(1, nn - 1):
        edge += [1 + nn * j, nn + nn * j]                              # x = -L/2 and x = +L/2
    edge += list(range(1 + nn * (nn - 1), nn * nn + 1))                # y = +L/2
    d.card("/GRNOD/NODE", 1, "Plate edge nodes (clamped)", ids=edge)
    d.card("/GRNOD/PART", 2, "Plate nodes", ids=[1])
    if impact:
        d.card("/GRNOD/PART", 3, "Block nodes", ids=[2])
        d.card("/SURF/PART", 1, "Plate surface", ids=[1])
        d.card("/SURF/PART/EXT", 2, "Block outer faces", ids=[2])
    d.ruler()
    d.card("/BCS", 1, "Clamped plate edges", Tra_rot=rc.bcs_code("111", "111"), grnod_ID=1)
    d.card("/INIVEL/TRA", 1, "Block at 10 m/s downwards" if impact else "Plate at 1 m/s downwards",
           Vz=-10000.0 if impact else -1000.0, grnod_ID=3 if impact else 2)
    if impact and contact:
        d.ruler()
        for iid, title, grnod, surf, istf, inacti, fric, iform, viss in (
                (1, "Block nodes on plate surface", 3, 1, 4, 6, 0.1, 1, 0.05),
                (2, "Plate nodes on block outer faces", 2, 2, 0, 0, 0.2, 2, 0.0)):
            d.card("/INTER/LAGDT/TYPE7" if lagdt else "/INTER/TYPE7", iid, title, grnd_IDs=grnod, surf_IDm=surf,
                   Istf=istf, Stmax="1E30" if istf >= 2 else 0.0, Stfac=1.0, Fric=fric, IBC=rc.ibc_code(0, 0, 0),
                   Inacti=inacti, VISs=viss, VISf=1.0, Bumult=bumult, Iform=iform)
    d.ruler()
    d.card("/TH/NODE", 1, "Plate centre", variables=["DEF"], rows=[(1 + (n // 2) + nn * (n // 2), 0, "Plate centre")])
    d.card("/TH/PART", 2, "Parts", variables=["DEF"], ids=[1, 2] if impact else [1])
    if impact and contact:
        d.card("/TH/INTER", 3, "Both interfaces", variables=["DEF"], ids=[1, 2])
    d.ruler()
    d.raw("/END")
    return d.lines


def engine(n, root, inter_tmin=0.0, tstop=None, th_records=100, anim_states=2):
    h = L_PLATE / n
    dt_shell = 0.9 * h / math.sqrt(E_STEEL / RHO_STEEL)
    if tstop is None:
        tstop = sig3(CYCLES * dt_shell)
    e = rc.Deck(engine=True)
    e.raw("#RADIOSS ENGINE")
    e.comment("Tstop = %d cycles x shell time step 0.9 h / sqrt(E/rho) = %d x %.4g s" % (CYCLES, CYCLES, dt_shell))
    e.ruler()
    e.card("/RUN", "%s/1" % root, Tstop=tstop, sig=SIG)
    if th_records > 0:
        e.card("/TFILE", dt_his=sig3(tstop / th_records), sig=SIG)
    if anim_states > 0:
        e.card("/ANIM/DT", Tstart=0.0, dT=sig3(tstop / anim_states), sig=SIG)
        e.raw("/ANIM/ELEM/VONM", "/ANIM/ELEM/EPSP", "/ANIM/VECT/VEL")
    e.card("/DT", Tscale=0.9, Tmin=0.0)
    if inter_tmin:
        e.raw("#  /DT/INTER/CST: LAGDT pairs below Tmin switch to Lagrange multipliers; TYPE7 nodes get added mass")
        e.card("/DT/INTER/CST", Tscale=0.9, Tmin=inter_tmin)
    e.raw("/PRINT/-100")
    e.card("/STOP", Emax="1.0E+30", Mmax="1.0E+30", Nmax="1.0E+30", NTH=1, NANIM=1)
    e.ruler().raw("/END")
    return e.lines, tstop


def main(argv):
    p = argparse.ArgumentParser(description="Write a large N x N shell plate benchmark deck (format 2026).")
    p.add_argument("--n", type=int, default=1000, help="elements per side (default 1000: one million shells)")
    p.add_argument("--out", default=".", help="output folder (default: current folder)")
    p.add_argument("--impact", action="store_true", help="add a 10 x 10 x 4 brick block and two TYPE7")
    p.add_argument("--block", type=int, default=BLOCK_NX,
                   help="with --impact: bricks along each side of the block (default 10; 10 mm bricks, 4 deep)")
    p.add_argument("--brick-size", type=float, default=L_PLATE / 100.0,
                   help="with --impact: the block's brick edge in mm (default 10)")
    p.add_argument("--gap", type=float, default=BLOCK_Z0 - THICK / 2,
                   help="with --impact: initial distance in mm from the block's bottom face to the plate's top "
                        "surface (default 1); down to -0.5 (the mid-surface, which TYPE7 sees with its gap)")
    p.add_argument("--tstop", type=float, default=None,
                   help="end time in s (default: 1500 cycles of the plate's shell step)")
    p.add_argument("--th-records", type=int, default=100,
                   help="time history records over the run (/TFILE dt_his = Tstop / K; default 100; 0: no /TFILE)")
    p.add_argument("--anim-states", type=int, default=2,
                   help="animation states after t = 0 (/ANIM/DT dT = Tstop / K; default 2; 0: no /ANIM)")
    p.add_argument("--contact", choices=("type7", "lagdt", "addmass", "none"), default="type7",
                   help="with --impact: plain TYPE7 (default); lagdt: /INTER/LAGDT/TYPE7 with /DT/INTER/CST Tmin; "
                        "addmass: plain TYPE7 with /DT/INTER/CST Tmin (added mass); none: no interface (the "
                        "block passes through the plate; root name _NOCONTACT)")
    p.add_argument("--tmin", type=float, default=8e-7,
                   help="Tmin of /DT/INTER/CST for --contact lagdt and addmass (default 8e-7 s: just below the "
                        "shell step of --n 200)")
    p.add_argument("--ishell", type=int, choices=(1, 12, 24), default=1,
                   help="formulation of the plate's shells: 1 (default), 12 (QBAT) or 24 (QEPH)")
    p.add_argument("--isolid", type=int, choices=(1, 24), default=1,
                   help="with --impact: the block's brick formulation, 1 (default) or 24 (HEPH; root name _HEPH)")
    p.add_argument("--bumult", type=float, default=0.0,
                   help="with --impact: the interfaces' search margin factor Bumult (default 0: Radioss's default "
                        "by model size, 0.2, then 0.3 above 1.5 M nodes and 0.4 above 2.5 M)")
    args = p.parse_args(argv)
    if args.n < 2:
        p.error("--n must be at least 2")
    if args.brick_size <= 0 or args.gap <= -THICK / 2:
        p.error("--brick-size must be positive and --gap above %g (the plate's mid-surface)" % (-THICK / 2))
    if args.block * args.brick_size > L_PLATE:
        p.error("the block (--block x --brick-size) is wider than the %g mm plate" % L_PLATE)
    if args.contact != "type7" and not args.impact:
        p.error("--contact needs --impact")
    root = "PLATE%d%s" % (args.n, "I" if args.impact else "")
    if args.contact == "none":
        root += "_NOCONTACT"
    elif args.contact != "type7":
        root += "_" + args.contact.upper()
    if args.ishell != 1:
        root += {12: "_QBAT", 24: "_QEPH"}[args.ishell]
    if args.impact and args.isolid == 24:
        root += "_HEPH"
    os.makedirs(args.out, exist_ok=True)
    t0 = time.time()
    s_path = os.path.join(args.out, root + "_0000.rad")
    e_path = os.path.join(args.out, root + "_0001.rad")
    rc.write(s_path, starter(args.n, args.impact, root, lagdt=args.contact == "lagdt", ishell=args.ishell,
                             isolid=args.isolid, block_nx=args.block, brick=args.brick_size,
                             block_z0=THICK / 2 + args.gap, bumult=args.bumult, contact=args.contact != "none"))
    if args.th_records < 0 or args.anim_states < 0:
        p.error("--th-records and --anim-states must be 0 or more")
    lines, tstop = engine(args.n, root, args.tmin if args.contact in ("lagdt", "addmass") else 0.0, args.tstop,
                          args.th_records, args.anim_states)
    rc.write(e_path, lines)
    print("wrote %s and %s: %d shells, %d plate nodes%s, Tstop %g s (%.1f s)" %
          (s_path, e_path, args.n * args.n, (args.n + 1) ** 2,
           ", %d bricks and %d block nodes" % (args.block ** 2 * BLOCK_NZ, (args.block + 1) ** 2 * (BLOCK_NZ + 1))
           if args.impact else "", tstop, time.time() - t0))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
