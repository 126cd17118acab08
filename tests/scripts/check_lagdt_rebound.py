"""Switched LAGDT pairs release when the bodies separate: an elastic bar dropped on a fixed plate through an
/INTER/LAGDT/TYPE7 whose every pair is a Lagrange-multiplier row, against the closed form and against the same
bar stopped by a fixed rigid wall (decks/verification/lagdt_rebound, scripts/make_contact_decks.py).

usage: /usr/bin/python3 check_lagdt_rebound.py --radx RADX
           --deck decks/verification/lagdt_rebound/LAGDT_REBOUND_0000.rad
           --deck-wall decks/verification/lagdt_rebound/LAGDT_REBOUND_RWALL_0000.rad --out DIR

Closed form (1D elastic bar, nu = 0, on a rigid stop): contact force rho c A v0 for 2 L / c, c = sqrt(E / rho),
then the bar leaves at v0 with no stress; the rows must then release (a row that would pull is dropped by the
active set). Everything is read from the decks.

Tolerances (what they mean):
  * rebound speed (ZMOM / MASS of the bar at the end) within 2 % of the rigid-wall deck's: both are a one-step,
    perfectly plastic stop of the same lower face of the same discrete bar; the multipliers stop it on the
    gap's edge, the wall one step before crossing its plane, which shifts the impulse by at most one step of
    a contact of about 45 steps (2 %);
  * rebound speed between 0.9 v0 and v0: no energy is created (kinetic energy after <= before, so the mean
    speed <= v0, to 1e-6); the discrete bar keeps part of the energy as vibration and bulk-viscosity work,
    about 5 % of v0 with 20 elements;
  * contact duration (first to last time-history row with a force) within 5 % of 2 L / c: the rows come every
    step, 2 % of the contact each, at both ends;
  * the force plateau (median over the contact rows) within 3 % of rho c A v0: the bulk viscosity only acts in
    the front, and the wave carries the stress of the continuum behind it;
  * the multipliers never pull: FNZ (the interface's normal force on the bar) >= 0 on every row, and zero on
    every row after the separation, with no switched pair in the last listing lines;
  * no lower-face node inside the gap by more than 1e-3 of it (the rows stop the face on the gap's edge);
  * energy balance within 1 % (docs/theory/verification.md C), both decks.
"""
import argparse
import os
import sys

import numpy as np

import check_contact_common as cc


def lag_pairs_last(out, name):
    """LAG-PAIRS (the last column) of the last two cycle lines of the listing."""
    rows = []
    for ln in cc.read_listing(out, name).splitlines():
        f = ln.split()
        if len(f) >= 13 and f[0].isdigit() and any(x.endswith("%") for x in f):
            rows.append(int(f[-1]))
    return rows[-2:]


def rebound(radx, deck, out, checks):
    """Runs deck; returns (time, mean bar velocity along Z) and the summary."""
    m = cc.Model(deck)
    name = cc.run_radx(radx, deck, out)
    th = cc.read_th(out, name)
    t, vz = cc.part_velocity(th, m.brick_part(), "Z")
    s = cc.read_summary(out, name)
    cc.check_energy_error(checks, s)
    return m, th, t, vz, s, name


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--radx", required=True)
    ap.add_argument("--deck", required=True)
    ap.add_argument("--deck-wall", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()

    wall = cc.Checks("LAGDT_REBOUND_RWALL")
    _, _, _, vz_wall, _, _ = rebound(a.radx, a.deck_wall, os.path.join(a.out, "rwall"), wall)

    c = cc.Checks("LAGDT_REBOUND")
    m, th, t, vz, s, name = rebound(a.radx, a.deck, os.path.join(a.out, "lagdt"), c)
    (it,) = m.interfaces.values()
    assert it["lagdt"] and it["Istf"] == 1 and it["Igap"] == 0, "an /INTER/LAGDT/TYPE7 with Igap 0 (g = Gapmin)"
    gap = it["Gapmin"]
    _, M, vel = m.moving_body()
    v0 = -vel[2]
    pid = m.brick_part()
    mid = m.parts[pid][1]
    ((_, law1),) = [(i, d) for i, d in m.deck.of("/MAT/LAW1") if i == mid]
    rho, young = cc.real(law1[1], 1, 20), cc.real(law1[2], 1, 20)
    zs = [p[2] for p in m.nodes.values()]
    secondary = m.groups[it["grnd"]]
    z_plate = m.flat_z([n for _, ns, _ in m.shells.values() for n in ns], "the main plate")
    length = max(zs) - min(m.nodes[n][2] for n in secondary)
    wave = np.sqrt(young / rho)
    t_contact = 2 * length / wave
    print("bar: M = %g kg, L = %g m, c = %.6g m/s, v0 = %g m/s: contact %.6g s, force %.6g N, rebound at v0"
          % (M, length, wave, v0, t_contact, rho * wave * M / (rho * length) * v0))

    v_end, v_wall = vz[-1], vz_wall[-1]
    c.close(v_end, v_wall, 0.02, "rebound speed against the rigid-wall deck's (m/s)")
    c.check(0.9 * v0 <= v_end <= v0 * (1 + 1e-6),
            "rebound speed %.6g m/s within [0.9 v0, v0] = [%.6g, %.6g]" % (v_end, 0.9 * v0, v0))

    tf, fn = cc.contact_forces(th, 1)
    fz = fn[2]
    scale = rho * wave * (M / (rho * length)) * v0  # the closed-form force
    c.check(np.all(fz >= -1e-9 * scale), "the multipliers never pull: smallest FNZ %.4g N (closed-form force "
            "%.4g N)" % (fz.min(), scale))
    on = np.nonzero(fz > 1e-9 * scale)[0]
    c.check(len(on) > 2, "%d time-history rows with a contact force" % len(on))
    if len(on) > 2:
        duration = tf[on[-1]] - tf[on[0]]
        c.close(duration, t_contact, 0.05, "contact duration (s)")
        c.close(float(np.median(fz[on])), scale, 0.03, "force plateau, median over the contact rows (N)")
        after = np.arange(len(fz)) > on[-1]
        c.check(after.sum() > 10 and np.all(fz[after] == 0.0),
                "after the separation (%.4g s) the force is zero on all %d rows" % (tf[on[-1]], after.sum()))
    last = lag_pairs_last(os.path.join(a.out, "lagdt"), name)
    si = s["interfaces"][0]
    c.check(si["switched_pairs_max"] == len(secondary) and last == [0, 0],
            "all %d pairs switched during the contact (most in one cycle %d), none in the last listing lines %s"
            % (len(secondary), si["switched_pairs_max"], last))
    pen = cc.penetrations(m, th, secondary, gap, z_plate)
    c.check(pen.max() <= 1e-3 * gap, "the lower face stays on or outside the gap's edge: largest penetration "
            "%.3g m (allowed 1e-3 of the gap %g m)" % (pen.max(), gap))
    cc.finish([wall, c])


if __name__ == "__main__":
    sys.exit(main())
