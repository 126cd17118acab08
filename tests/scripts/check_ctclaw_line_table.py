"""A tabulated /CTCLAW law equal to the bilinear law gives the same run (docs/theory/contact-laws.md 2).

usage: /usr/bin/python3 check_ctclaw_line_table.py --radx RADX
           --deck-table decks/verification/ctclaw_line_table/CTCLAW_LINE_TABLE_0000.rad
           --deck-bilinear decks/verification/ctclaw_line_table/CTCLAW_LINE_BILINEAR_0000.rad --out DIR

The two decks are the same model (ctclaw_drop's cube dropped on one fixed segment, VISs damping on) but for the
interface's law: n3 with a /FUNCT of two points (gap -g0, Kc g0) and (gap 0, 0), and n1{Kc}. Read from the decks,
the table must be the bilinear law's line: its slope -dP/dgap equal to Kc (relative 1e-12), P = 0 at gap 0, and
the models otherwise equal (nodes, elements, interface cards). The tabulated law interpolates on that segment,
extrapolates along it beyond -g0 and clamps at 0 above gap 0: the same function P = Kc u for every u, and the
same stiffness Kc for the time step and the damping VISs sqrt(2 Kc A_s m) -- up to round-off, since the table
computes P_1 + slope (g - g_1) with slope = -P_1 / g_1 rounded, where the bilinear law computes Kc u.

Tolerances (what they mean): both runs have the same number of time-history rows (every cycle), at the same
times within 1e-9 of a step; every column of every group agrees within 1e-9 of its physical scale -- the gap for
displacements, v0 for velocities, M v0 for momenta, the peak normal force for contact forces, the initial kinetic
energy for energies, the largest step for the step, M for masses. The laws differ by a few ulps (~1e-16) per
evaluation; over the ~1000 cycles of this stable, damped run they stay below ~1e-11 of these scales (measured:
displacements 1e-13 of the gap, velocities 1e-11 of v0), so 1e-9 leaves a hundredfold margin and still catches
any difference of substance (a pressure, stiffness or damping off by 1e-9 of its value, a different step).
"""
import argparse
import os

import numpy as np

import check_contact_common as cc
import check_ctclaw_common as ctc


def scale_of(column, s):
    """The physical scale of a time-history column (name "ID:VAR" or "VAR") from the run's scales s."""
    var = column.split(":")[-1]
    if var in ("DX", "DY", "DZ"):
        return s["gap"]
    if var in ("VX", "VY", "VZ"):
        return s["v0"]
    if var in ("XMOM", "YMOM", "ZMOM"):
        return s["M"] * s["v0"]
    if var[:2] in ("FN", "FT"):
        return s["force"]
    if var in ("MASS", "DMAS", "ERODED"):
        return s["M"]
    if var == "DT":
        return s["dt"]
    if var == "DMAS_PCT":
        return 100.0
    return s["energy"]  # IE, KE, RKE, EXTW, SE, CE, HE, CE_*, PW, HEAT


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--radx", required=True)
    ap.add_argument("--deck-table", required=True)
    ap.add_argument("--deck-bilinear", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    checks = cc.Checks("line table")

    mt, mb = cc.Model(a.deck_table), cc.Model(a.deck_bilinear)
    (it_id, it), = mt.interfaces.items()
    (ib_id, ib), = mb.interfaces.items()
    law_t = ctc.parse_urn(ctc.ctclaws(mt.deck)[it_id][1])
    law_b = ctc.parse_urn(ctc.ctclaws(mb.deck)[ib_id][1])
    assert law_t["normal"] == 3 and law_b["normal"] == 1, "a tabulated deck and a bilinear deck"
    kc = law_b["params"]["kc"]
    x, y = ctc.functs(mt.deck)[int(law_t["params"]["curveid"])]
    checks.check(len(x) == 2 and y[1] == 0 and x[1] == 0 and x[0] < 0,
                 "the table is two points, the second (gap 0, P 0): %s" % list(zip(x, y)))
    slope = -(y[1] - y[0]) / (x[1] - x[0])
    checks.check(abs(slope - kc) <= 1e-12 * kc, "the table's slope %.17g = Kc %.17g" % (slope, kc))
    same = (mt.nodes == mb.nodes and mt.bricks == mb.bricks and mt.shells == mb.shells and it == ib and
            mt.inivel == mb.inivel and mt.masses == mb.masses and law_t["friction"] == law_b["friction"] == 0)
    checks.check(same, "the decks are the same model but for the law")

    _, M, vel = mb.moving_body()
    v0 = abs(vel[2])
    runs = []
    for deck in (a.deck_table, a.deck_bilinear):
        label = os.path.basename(deck)[:-len("_0000.rad")]
        out = os.path.join(a.out, label)
        name = cc.run_radx(a.radx, deck, out, ("--threads", "1"))
        runs.append((cc.read_th(out, name), cc.read_summary(out, name)))
    (tht, st), (thb, sb) = runs
    _, fnz = cc.th_column(thb, "%d:FNZ" % ib_id)
    _, dt = cc.th_column(thb, "DT")
    scales = dict(gap=it["Gapmin"], v0=v0, M=M, force=float(np.max(np.abs(fnz))), energy=0.5 * M * v0 * v0,
                  dt=float(np.max(dt)))
    print("Kc = %g, table (%g, %g) to (%g, %g); scales %s" % (kc, x[0], y[0], x[1], y[1], scales))
    checks.check(scales["force"] > 0, "the bilinear run has a contact force (peak %.5g N)" % scales["force"])
    checks.check(sorted(tht) == sorted(thb), "the same time-history groups")
    worst = []
    for group in sorted(set(tht) & set(thb)):
        rt, ct = tht[group]
        rb, cb_ = thb[group]
        if not checks.check(rt.shape == rb.shape and ct == cb_, "%s: the same rows and columns (%s and %s)"
                            % (group, rt.shape, rb.shape)):
            continue
        dt_max = np.max(np.abs(rt[:, 0] - rb[:, 0]))
        checks.check(dt_max <= 1e-9 * scales["dt"], "%s: row times equal within %.3g s (allowed 1e-9 of a step)"
                     % (group, dt_max))
        for col, k in ct.items():
            if k == 0:
                continue
            sc = scale_of(col, scales)
            d = float(np.max(np.abs(rt[:, k] - rb[:, k])))
            worst.append((d / sc, group, col, d, sc))
            if d > 1e-9 * sc:
                checks.check(False, "%s %s differs by %.3g (allowed 1e-9 of its scale %.4g)" % (group, col, d, sc))
    worst.sort(reverse=True)
    for r, group, col, d, sc in worst[:5]:
        print("     largest relative differences: %s %s: %.3g of its scale %.4g" % (group, col, r, sc))
    checks.check(len(worst) > 0 and worst[0][0] <= 1e-9, "every column within 1e-9 of its scale (%d columns, "
                 "largest %.3g)" % (len(worst), worst[0][0] if worst else float("nan")))
    for s in (st, sb):
        cc.check_energy_error(checks, s)
    cc.finish([checks])


if __name__ == "__main__":
    main()
