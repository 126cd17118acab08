"""Block sliding with Coulomb friction (docs/theory/verification.md A.6) against its closed form.

usage: /usr/bin/python3 check_contact_block_sliding.py --radx RADX
           --decks decks/verification/block_sliding/BLOCK_SLIDING_IFORM2_0000.rad
                   decks/verification/block_sliding/BLOCK_SLIDING_IFORM1_0000.rad
                   decks/verification/block_sliding/BLOCK_SLIDING_LAGDT_0000.rad --out DIR

A stiff cube (mass M) rests under gravity g on one fixed main segment through its lower-face secondary nodes and
starts sliding at v0 along +X; TYPE7 (or LAGDT/TYPE7 with every pair held switched to Lagrange multipliers,
whose friction is Coulomb bounded by mu lambda) with Fric = mu, Ifric 0. While it slides, the friction forces add up to
mu M g, so its mean velocity (XMOM / MASS of its part) falls as v0 - mu g t and it stops at v0 / (mu g) after
sliding v0^2 / (2 mu g). M, g, mu, v0, the gap and the start positions are read from each deck.

Tolerances (what they mean):
  * deceleration during the sliding phase (least squares on the rows with 0.9 v0 >= v >= 0.1 v0) within 3 % of
    mu g: the normal forces wobble by about 0.5 % as the cube settles and tilts on its pairs, and Iform 1's
    viscous branch only acts below about 1 % of v0;
  * the speed falls below 2 % of v0 at 0.98 v0 / (mu g) within 3 % (plus one time-history interval), and the
    distance slid by then is 0.9996 v0^2 / (2 mu g) within 3 %;
  * after 1.1 v0 / (mu g) the cube stays below 2 % of v0 (Iform 2 sticks elastically, Iform 1 decays);
  * the cube stays in contact: its lower-face nodes stay between the plate and the gap surface at every row;
  * the frictional contact energy equals the kinetic energy lost within 2 % of the initial kinetic energy, and the
    run's energy error is within 1 % (docs/theory/verification.md C).
"""
import os

import numpy as np

import check_contact_common as cc


def one_deck(radx, deck, out, checks):
    m = cc.Model(deck)
    (it,) = m.interfaces.values()
    mu, gap = it["Fric"], it["Gapmin"]
    assert it["Ifric"] == 0, "the closed form is for Coulomb friction (Ifric 0)"
    body, M, vel = m.moving_body()
    v0 = vel[0]
    (_, _, gz), = m.grav
    g_acc = abs(gz)
    a = mu * g_acc
    t_stop, dist = v0 / a, v0 * v0 / (2 * a)
    secondary = m.groups[it["grnd"]]
    z_plate = m.nodes[next(iter(m.shells.values()))[1][0]][2]
    print("%s: M = %g, mu = %g, g = %g, v0 = %g, Iform %d: a = %.6g, stop at %.6g s after %.6g m"
          % (os.path.basename(deck), M, mu, g_acc, v0, it["Iform"], a, t_stop, dist))

    name = cc.run_radx(radx, deck, out)
    th = cc.read_th(out, name)
    t, vx = cc.part_velocity(th, m.brick_part(), "X")
    sliding = (vx <= 0.9 * v0) & (vx >= 0.1 * v0)
    checks.check(sliding.sum() >= 10, "%d time-history rows in the sliding phase" % sliding.sum())
    slope = np.polyfit(t[sliding], vx[sliding], 1)[0]
    checks.close(-slope, a, 0.03, "deceleration while sliding (m/s2)")
    below = np.nonzero(vx < 0.02 * v0)[0]
    checks.check(len(below) > 0, "the cube stops before the end")
    if len(below):
        k = below[0]
        row_dt = t[k] - t[k - 1]
        t_expected = 0.98 * t_stop
        checks.check(abs(t[k] - t_expected) <= 0.03 * t_expected + row_dt,
                     "speed below 2 %% of v0 at %.6g s, expected %.6g s (allowed 3 %% + one row of %.3g s)"
                     % (t[k], t_expected, row_dt))
        moved = [cc.th_column(th, "%d:DX" % n)[1] for n in body if cc.has_column(th, "%d:DX" % n)]
        checks.check(len(moved) > 0, "a cube node in the time history")
        if moved:
            checks.close(moved[0][k], (1 - 0.02 ** 2) * dist, 0.03, "distance slid when stopping (m)")
    after = t > 1.1 * t_stop
    checks.check(after.any() and np.max(np.abs(vx[after])) < 0.02 * v0,
                 "at rest after 1.1 t_stop: largest speed %.3g m/s (allowed 2 %% of v0)"
                 % (np.max(np.abs(vx[after])) if after.any() else np.nan))
    for n in (n for n in secondary if cc.has_column(th, "%d:DZ" % n)):
        d = m.nodes[n][2] + cc.th_column(th, "%d:DZ" % n)[1] - z_plate
        checks.check(np.all(d > 0) and np.all(d < gap), "node %d stays in contact: distance to the plate from %.4g"
                     " to %.4g m (gap %g)" % (n, d.min(), d.max(), gap))
    s = cc.read_summary(out, name)
    e = s["energy"]
    ke0 = 0.5 * M * v0 * v0
    checks.check(abs(e["contact_friction"] - (ke0 - e["kinetic"])) <= 0.02 * ke0,
                 "frictional energy %.5g J = kinetic energy lost %.5g J (allowed 2 %% of %.4g J)"
                 % (e["contact_friction"], ke0 - e["kinetic"], ke0))
    if it["lagdt"]:
        # /INTER/LAGDT/TYPE7 with Tmin far above the pair steps: every lower-face pair is a multiplier row at
        # every cycle (cycle 0 included), so the friction checked above is the multipliers' Coulomb bound.
        cc.check_all_pairs_switched(checks, s, len(secondary))
    cc.check_energy_error(checks, s)


if __name__ == "__main__":
    cc.main_per_deck(one_deck)
