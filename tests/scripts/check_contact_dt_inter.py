"""/DT/INTER/CST and /DT/INTER/DEL on a plain TYPE7 (docs/theory/type7-lagdt.md 4.4 and 6).

usage: /usr/bin/python3 check_contact_dt_inter.py --radx RADX
           --decks decks/verification/dt_inter/DT_INTER_CST_0000.rad
                   decks/verification/dt_inter/DT_INTER_DEL_0000.rad --out DIR

Each deck: a heavy stiff cube (mass M) and a light tile move at v0 along -Z towards fixed flat main segments,
their lower nodes the secondary nodes (Istf 1: pair stiffness K, Igap 0: gap g). The engine deck's
/DT/INTER/CST or /DT/INTER/DEL gives Tscale and Tmin. A secondary node is "light" when its contact step at first
contact, Tscale sqrt(2 m / K), is below Tmin: the tile's nodes; the cube's nodes are far above it. All values
are read from the decks. Expected:

  CST   each light node's mass is raised to m_new = 0.5 k_eff (Tmin / Tscale)^2 whenever its step would fall
        below Tmin (k_eff = K from the cycle before the pair closes, then K (g / (g - p))^2 raised by the damping
        ratio xi: k_t / (sqrt(1 + xi^2) - xi)^2); the mass only grows, so the added mass lies between the value
        at first contact, sum_light 0.5 K (Tmin / Tscale)^2 - m_light, and the same with the light nodes'
        largest penetration p_max (time history) and the largest xi. The heavy nodes get nothing. The run's step
        never falls below Tmin and equals it while the tile is in contact;
  DEL   the light nodes leave the interface (one listing warning each, naming node and interface), feel no
        force and pass through; the heavy ones stay. No mass is added.
  both  the cube is the one-degree-of-freedom body of check_contact_common.rigid_impact (its own nodes only).

Tolerances (what they mean):
  * time step: the time history's DT (every cycle) and the listing's TIME-STEP column (a line every cycle) never
    below Tmin (relative 1e-12, round-off), except the last step, cut short to land on the end time; CST: the
    smallest step equals Tmin to 1e-9 (the contact held it there);
  * CST added mass (summary `added_mass`) inside [first-contact value, p_max value] (both relative 1e-9); the
    interval is about 1 % wide here (the stiffness growth (g / (g - p_max))^2 and 2 xi), asserted below 2 % so
    that the check stays sharp: a missing Tscale (19 %), mass added instead of raised to m_new, or mass on the
    heavy nodes all fall outside. The same value in the time history (DMAS, the light part's MASS increase,
    relative 1e-9), the listing ("added mass" row and the last MASS ADDED, 6 printed digits: 1e-5), and the
    cube part's MASS unchanged (exactly);
  * DEL: the warnings name exactly the light nodes and the interface, once each; the tile keeps -v0 to 1e-9
    (one cycle of contact force at first penetration would change it by several per cent) and ends below the
    plate; no mass added (exactly 0);
  * cube: largest penetration and rebound speed within 1 % of the one-DOF values (as in
    check_contact_node_on_segment);
  * energy error within 1 % (docs/theory/verification.md C).
"""
import math
import os
import re

import numpy as np

import check_contact_common as cc


def one_deck(radx, deck, out, checks):
    m = cc.Model(deck)
    (it,) = m.interfaces.values()
    iid = next(iter(m.interfaces))
    assert it["Istf"] == 1 and it["Igap"] == 0
    K, g, vis_s = it["Stfac"], it["Gapmin"], it["VISs"]
    cards = {a: cc.engine_card(deck, "/DT/INTER/" + a) for a in ("CST", "DEL")}
    ((action, (tscale, tmin)),) = [(a, c) for a, c in cards.items() if c is not None]
    secondary = m.groups[it["grnd"]]
    step0 = {n: tscale * math.sqrt(2 * m.masses[n] / K) for n in secondary}
    light = [n for n in secondary if step0[n] < tmin]
    heavy = [n for n in secondary if step0[n] >= tmin]
    assert light and heavy, "the deck needs nodes on both sides of Tmin"
    part_of = {}
    for pid, ns in m.bricks.values():
        part_of.update({n: pid for n in ns})
    for pid, ns, _ in m.shells.values():
        part_of.update({n: pid for n in ns})
    (light_part,) = {part_of[n] for n in light}
    (heavy_part,) = {part_of[n] for n in heavy}
    light_nodes = sorted(n for n, pid in part_of.items() if pid == light_part)
    assert sorted(light) == light_nodes, "every node of the light body is a light secondary node"
    m_light = sum(m.masses[n] for n in light)
    cube = sorted(n for n, pid in part_of.items() if pid == heavy_part)
    M = sum(m.masses[n] for n in cube)
    (vel, _), = m.inivel
    v0 = -vel[2]
    plate_nodes = sorted({n for n, pid in part_of.items() if pid not in (light_part, heavy_part)})
    z_plate = m.flat_z(plate_nodes, "the main plate")
    print("%s: /DT/INTER/%s Tscale %g Tmin %g; K = %g, g = %g, v0 = %g; light nodes %s (steps %.4g s), heavy nodes "
          "%s (steps %.4g s)" % (os.path.basename(deck), action, tscale, tmin, K, g, v0, light,
                                 max(step0[n] for n in light), heavy, min(step0[n] for n in heavy)))

    name = cc.run_radx(radx, deck, out)
    th = cc.read_th(out, name)
    s = cc.read_summary(out, name)
    text = cc.read_listing(out, name)
    t, dt = cc.th_column(th, "DT")
    t_end = t[-1]
    full = t + dt < t_end * (1 - 1e-12)
    checks.check(dt[full].min() >= tmin * (1 - 1e-12), "time history: the run's step never below Tmin (smallest "
                 "%.9g s over %d full steps)" % (dt[full].min(), full.sum()))
    rows = [r for r in cc.listing_rows(text) if r["time"] + r["dt"] < t_end * (1 - 1e-6)]
    checks.check(len(rows) > 0.9 * full.sum() and min(r["dt"] for r in rows) >= tmin * (1 - 1e-5),
                 "listing: TIME-STEP never below Tmin (smallest %.6g s over %d lines; 6 printed digits)"
                 % (min(r["dt"] for r in rows), len(rows)))

    pen_c = cc.penetrations(m, th, heavy, g, z_plate)
    p0 = g - (min(m.nodes[n][2] for n in heavy) - z_plate)
    exp = cc.rigid_impact(M, [m.masses[n] for n in heavy], K, g, vis_s, p0, -v0)
    checks.close(pen_c.mean(axis=0).max(), exp["p_max"], 0.01, "cube largest penetration (m)")
    checks.close(cc.part_velocity(th, heavy_part)[1][-1], exp["v_rebound"], 0.01, "cube rebound speed (m/s)")
    mass_c = cc.th_column(th, "%d:MASS" % heavy_part)[1]
    checks.check(np.all(mass_c == mass_c[0]), "no mass added to the cube (its part MASS %.9g to %.9g kg)"
                 % (mass_c.min(), mass_c.max()))
    pen_l = cc.penetrations(m, th, light, g, z_plate)

    if action == "CST":
        checks.check(abs(dt[full].min() - tmin) <= 1e-9 * tmin, "the contact held the step at Tmin: smallest step "
                     "%.12g s" % dt[full].min())
        m1 = 0.5 * K * (tmin / tscale) ** 2
        assert all(m1 > m.masses[n] for n in light)
        p_max = pen_l.max()
        stiff = (g / (g - p_max)) ** 2
        m2 = m1 * stiff * 1.1  # a bound on the mass while in contact, for the damping ratio below
        k_sec = K * g / (g - p_max)
        c_max = vis_s * math.sqrt(2 * k_sec * m2 / ((g - p_max) / g)) + 0.32 * m2 * v0 / (g - p_max)
        xi = c_max / (2 * math.sqrt(K * m1))
        shrink = math.sqrt(1 + xi * xi) - xi
        lower = len(light) * m1 - m_light
        upper = len(light) * m1 * stiff / shrink ** 2 - m_light
        assert (upper - lower) / lower < 0.02, "the bounds must stay within 2 %% (%.3g)" % ((upper - lower) / lower)
        added = s["added_mass"]
        checks.check(lower * (1 - 1e-9) <= added <= upper * (1 + 1e-9),
                     "added mass %.9g kg within [%.9g, %.9g] (first contact: %d x 0.5 K (Tmin/Tscale)^2 - m = "
                     "%d x %.6g - %.6g; largest: p_max %.4g m, (g/(g-p))^2 = %.5f, xi <= %.3g), at %.0f %% of the "
                     "interval" % (added, lower, upper, len(light), len(light), m1, m_light, p_max, stiff, xi,
                                   100 * (added - lower) / (upper - lower)))
        _, dmas = cc.th_column(th, "DMAS")
        mass_l = cc.th_column(th, "%d:MASS" % light_part)[1]
        checks.check(dmas[0] == 0 and abs(dmas[-1] - added) <= 1e-9 * added and
                     abs(mass_l[-1] - mass_l[0] - added) <= 1e-9 * added,
                     "time history: DMAS %.9g kg at the end (0 at the start), the tile's MASS grew by %.9g kg"
                     % (dmas[-1], mass_l[-1] - mass_l[0]))
        row = re.search(r"^\s*added mass\s+(\S+)", text, re.M)
        last = cc.listing_rows(text)[-1]["added_mass"]
        checks.check(row is not None and abs(float(row.group(1)) - added) <= 1e-5 * added and
                     abs(last - added) <= 1e-5 * added,
                     "listing: added mass row %s, last MASS ADDED %.6g (summary %.6g)"
                     % (row.group(1) if row else "missing", last, added))
    else:
        found = re.findall(r"WARNING \(cycle \d+\): interface (\d+): secondary node (\d+) left the interface", text)
        names = sorted((int(i), int(n)) for i, n in found)
        checks.check(names == sorted((iid, n) for n in light), "listing warnings name each light node once with "
                     "interface %d: %s" % (iid, ", ".join("%d:%d" % x for x in names) or "none"))
        _, vz = cc.part_velocity(th, light_part)
        dev = np.max(np.abs(vz + v0)) / v0
        checks.check(dev <= 1e-9, "the tile feels no contact force: speed -v0 to %.3g (allowed 1e-9)" % dev)
        checks.check(np.all(pen_l[:, -1] > g), "the tile passed through the plate (%.4g m below it)"
                     % (pen_l[:, -1].min() - g))
        checks.check(s["added_mass"] == 0, "no mass added (%g)" % s["added_mass"])
    cc.check_energy_error(checks, s)


if __name__ == "__main__":
    cc.main_per_deck(one_deck, self_test_first=True)
