"""The interface's Tstart and Tstop (docs/theory/type7-lagdt.md 4.7): TYPE7 acts only for Tstart <= t < Tstop.

usage: /usr/bin/python3 check_contact_tstart_tstop.py --radx RADX
           --decks decks/verification/tstart_tstop/TSTART_AFTER_IMPACT_0000.rad
                   decks/verification/tstart_tstop/TSTOP_BEFORE_IMPACT_0000.rad
                   decks/verification/tstart_tstop/TSTOP_DURING_CONTACT_0000.rad
                   decks/verification/tstart_tstop/SENSOR_ON_AFTER_IMPACT_0000.rad
                   decks/verification/tstart_tstop/SENSOR_OFF_DURING_CONTACT_0000.rad --out DIR

A deck may instead name a /SENSOR/TIME in the interface's sens_ID: the window is then the sensor's [Tdelay, Tstop)
(within the interface's own), and the same expectations hold.

Each deck is node_on_segment's model: a stiff cube (mass M) moving at v0 along -Z, its N lower-face nodes the
secondary nodes of one fixed, flat main segment; its lower face starts outside the gap g and would enter it at
t_in. The window [Tstart, Tstop) is read from the deck and decides what is expected:

  Tstart > t_in    (the cube enters the gap freely): before Tstart no force and the cube keeps -v0 while it
                   penetrates the gap; from the first cycle at t >= Tstart the force is on, and the cube is the
                   one-degree-of-freedom body of check_contact_common.rigid_impact starting at the penetration
                   p_a of that cycle with v_n = -v0 (Inacti 0: no action at Tstart);
  Tstop <= t_in    no force at any time: the cube keeps -v0 and passes through the plate;
  Tstop inside the contact: the force is on before Tstop and off from Tstop; the cube then keeps the speed
                   it had, which is rigid_state's speed (same model) when the last force acted, and passes
                   through the plate.

What is compared and the tolerances (what they mean):
  * "no force": the interface's FNX, FNY, FNZ in the time history (every cycle) are exactly 0: a pair outside
    the window must not be computed at all; the contact energies (CE_ELAST, CE_DAMP, CE_FRIC) are exactly 0
    before Tstart and do not change from the first row at t >= Tstop on (the second half of the last force's
    trapezoidal work is booked in that cycle);
  * "keeps -v0": the cube's ZMOM / MASS equals -v0 to 1e-9 (round-off only; one cycle of the smallest contact
    force changes it by more than 1e-4);
  * "force on": FNZ > 0 at the first row at t >= Tstart, at the last row before Tstop;
  * largest penetration and rebound speed after Tstart within 1 % of the one-DOF values (as in
    check_contact_node_on_segment: 1 % is far above the sampling error and below what any term of the law
    changes); the speed after Tstop within 1 % of the one-DOF speed at t_eff = (t_last + t_off) / 2, the
    middle of the last step with a force (leapfrog velocities live at half steps, so this removes the half-cycle
    ambiguity, about 1 % of the speed here, leaving an O(dt^2) error);
  * "passes through": the lower face ends below the plate (penetration above g);
  * energy error within 1 % (docs/theory/verification.md C): in TSTART_AFTER_IMPACT the energy given to the cube at
    Tstart shows as negative elastic contact energy, so the balance closes.
"""
import os

import numpy as np

import check_contact_common as cc


def one_deck(radx, deck, out, checks):
    m = cc.Model(deck)
    ((iid, it),) = m.interfaces.items()
    assert it["Istf"] == 1 and it["Igap"] == 0 and it["Inacti"] == 0
    K, g, vis_s = it["Stfac"], it["Gapmin"], it["VISs"]
    t_start, t_stop = m.window(iid)  # Tstart and Tstop, or the window of the interface's sensor
    secondary = m.groups[it["grnd"]]
    _, M, vel = m.moving_body()
    masses = [m.masses[n] for n in secondary]
    v0 = -vel[2]
    plate_nodes = [n for _, ns, _ in m.shells.values() for n in ns]
    z_plate = m.flat_z(plate_nodes, "the main plate")
    z0 = np.array([m.nodes[n][2] for n in secondary])
    t_in = (z0.min() - z_plate - g) / v0
    print("%s: M = %g, %d pairs, K = %g, g = %g, v0 = %g; enters the gap at %.6g s; window [%g, %g)"
          % (os.path.basename(deck), M, len(secondary), K, g, v0, t_in, t_start, t_stop))

    name = cc.run_radx(radx, deck, out)
    th = cc.read_th(out, name)
    t, fn = cc.contact_forces(th, next(iter(m.interfaces)))
    fnz = fn[2]
    pen = cc.penetrations(m, th, secondary, g, z_plate).mean(axis=0)
    _, vz = cc.part_velocity(th, m.brick_part())
    s = cc.read_summary(out, name)
    window = (t >= t_start) & (t < t_stop)
    checks.check(np.all(fn[:, ~window] == 0), "no contact force outside [Tstart, Tstop): %d rows outside, largest "
                 "|FN| there %.3g N" % ((~window).sum(), np.abs(fn[:, ~window]).max(initial=0.0)))
    ce = np.array([cc.th_column(th, v)[1] for v in ("CE_ELAST", "CE_DAMP", "CE_FRIC")])
    before, k_off = t < t_start, int(np.argmax(t >= t_stop)) if np.any(t >= t_stop) else len(t)
    checks.check(np.all(ce[:, before] == 0) and np.all(ce[:, k_off:] == ce[:, -1:]),
                 "contact energies (time history CE_ELAST, CE_DAMP, CE_FRIC) 0 before Tstart and constant from "
                 "the first row at t >= Tstop (the work of the last force is booked in that cycle): %d and %d rows"
                 % (before.sum(), len(t) - k_off))

    if t_start > t_in:
        before = t < t_start
        dev = np.max(np.abs(vz[before] + v0)) / v0
        checks.check(dev <= 1e-9, "before Tstart the cube keeps -v0: largest relative deviation %.3g (allowed 1e-9)"
                     % dev)
        k_a = int(np.argmax(~before))
        checks.check(pen[k_a - 1] > 0, "the cube entered the gap before Tstart without force: penetration %.4g m at "
                     "t = %.6g s" % (pen[k_a - 1], t[k_a - 1]))
        checks.check(fnz[k_a] > 0, "the force is on from the first cycle at t >= Tstart (t = %.6g s): FNZ = %.4g N"
                     % (t[k_a], fnz[k_a]))
        exp = cc.rigid_impact(M, masses, K, g, vis_s, pen[k_a], -v0)
        print("  one-DOF from p_a = %.6g m at -%g m/s: p_max %.6g m, rebound %.6g m/s"
              % (pen[k_a], v0, exp["p_max"], exp["v_rebound"]))
        checks.close(pen.max(), exp["p_max"], 0.01, "largest penetration after Tstart (m)")
        checks.check(pen[-1] < 0, "the cube left the gap before the end")
        checks.close(vz[-1], exp["v_rebound"], 0.01, "rebound speed (m/s)")
    elif t_stop <= t_in:
        dev = np.max(np.abs(vz + v0)) / v0
        checks.check(dev <= 1e-9, "no contact at all: the cube keeps -v0 to %.3g (allowed 1e-9)" % dev)
        e = s["energy"]
        checks.check(e["contact_elastic"] == 0 and e["contact_damping"] == 0 and e["contact_friction"] == 0,
                     "contact energies 0: elastic %g, damping %g, friction %g" % (e["contact_elastic"],
                                                                                   e["contact_damping"],
                                                                                   e["contact_friction"]))
        checks.check(pen[-1] > g, "the cube passed through the plate: lower face %.4g m below it" % (pen[-1] - g))
    else:
        k_off = int(np.argmax(t >= t_stop))
        checks.check(t_start <= t_in < t_stop and k_off > 0, "Tstop falls inside the contact")
        checks.check(fnz[k_off - 1] > 0, "the force is on at the last row before Tstop (t = %.6g s): FNZ = %.4g N"
                     % (t[k_off - 1], fnz[k_off - 1]))
        after = vz[k_off:]
        dev = np.max(np.abs(after - after[-1])) / v0
        checks.check(dev <= 1e-9, "after Tstop the cube's speed no longer changes: spread %.3g of v0 (allowed 1e-9)"
                     % dev)
        checks.check(0 < -vz[-1] < v0, "the cube was slowed but still approaches at Tstop: %.6g m/s" % vz[-1])
        t_eff = 0.5 * (t[k_off - 1] + t[k_off])
        _, v_exp = cc.rigid_state(M, masses, K, g, vis_s, g - (z0.min() - z_plate), -v0, t_eff)
        checks.close(vz[-1], v_exp, 0.01, "speed after Tstop (m/s; one-DOF at t = %.6g s)" % t_eff)
        checks.check(pen[-1] > g, "the cube passed through the plate: lower face %.4g m below it" % (pen[-1] - g))
    cc.check_energy_error(checks, s, "; contact elastic %.4g, damping %.4g"
                          % (s["energy"]["contact_elastic"], s["energy"]["contact_damping"]))


if __name__ == "__main__":
    cc.main_per_deck(one_deck, self_test_first=True)
