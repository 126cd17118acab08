"""Initial penetrations treated by Inacti 0, 1, 2, 3, 5, 6 (docs/theory/type7-lagdt.md 4.6), one deck each.

usage: /usr/bin/python3 check_contact_initial_penetration.py --radx RADX
           --decks decks/verification/initial_penetration/INITIAL_PENETRATION_INACTI*_0000.rad --out DIR

Each deck: two stiff shell tiles (mass M, 9 nodes each) move at v along -Z towards their own fixed main segment;
tile A starts inside the gap (initial penetration P0), tile B outside it. Every tile is a rigid body on 9 equal
pairs, so its closest approach and rebound follow check_contact_common.rigid_impact (RK4 of the TYPE7 law with
its damping). Parameters (M, nodal masses, K, g, VISs, v, P0, Inacti) come from each deck. Expected:

  tile B, all decks   impact from outside the gap with gap g
  tile A, Inacti 0    penalty from the first cycle: impact starting at p = P0 with gap g
              1, 2    no force (its nodes, or its segment, lose their stiffness): constant velocity, ends below
                      the plate
              3       nodes moved to the gap surface before the run (first state at distance g), then an impact
                      starting at p = 0 with gap g
              5       pair gap g - P0: no elastic force at t = 0, impact starting at p = 0 with gap g - P0
              6       pair gap 0.95 (g - P0): free flight to it, then an impact with that gap

Tolerances (what they mean):
  * largest penetration into the (pair's) gap within 1 % of the one-DOF value, rebound speed (ZMOM / MASS of
    the tile) within 1 % where the gap stays fixed (B; A with Inacti 0 and 3): as in check_contact_node_on_segment,
    1 % is far above the sampling error (one cycle) and below what any term of the law changes;
  * Inacti 1 and 2: tile A's speed equals v to 1e-9 (no force at all, only round-off), and it ends below the
    plate;
  * Inacti 3: tile A's nodes at distance g in the first state within 1e-6 g;
  * Inacti 5 and 6: tile A never passes the plate and rebounds. (Its acceleration at t = 0 is not a test of
    the reduced gap: the pair is active from the first cycle, where the quadratic damping term of 4.3 already
    pushes with 0.32 m v^2 / gap per node; the largest penetration into the reduced gap is the test.)
  * energy error within 1 % (docs/theory/verification.md C).
"""
import os

import numpy as np

import check_contact_common as cc


def one_deck(radx, deck, out, checks):
    m = cc.Model(deck)
    (it,) = m.interfaces.values()
    assert it["Istf"] == 1 and it["Igap"] == 0
    K, g, vis_s, inacti = it["Stfac"], it["Gapmin"], it["VISs"], it["Inacti"]
    (vel, _), = m.inivel
    v = -vel[2]
    plate_part = next(pid for pid in m.parts
                      if all(m.nodes[n][2] == 0.0 for p, ns, _ in m.shells.values() if p == pid for n in ns))
    tiles = {}
    for pid in sorted(m.parts):
        if pid == plate_part:
            continue
        nodes = sorted({n for _, (p, ns, _) in m.shells.items() if p == pid for n in ns})
        z = m.nodes[nodes[0]][2]
        tiles[pid] = dict(nodes=nodes, masses=[m.masses[n] for n in nodes], M=sum(m.masses[n] for n in nodes), z=z)
    pa, pb = sorted(tiles, key=lambda pid: tiles[pid]["z"])  # A is the lower one (inside the gap)
    A, B = tiles[pa], tiles[pb]
    P0 = g - A["z"]
    assert 0 < P0 < g and B["z"] > g
    g0 = g - P0
    g6 = g0 - 0.05 * g0
    impact = lambda t, gap, p0: cc.rigid_impact(t["M"], t["masses"], K, gap, vis_s, p0, -v)  # noqa: E731
    expected_b = impact(B, g, g - B["z"])
    expected_a = {0: (g, impact(A, g, P0)), 3: (g, impact(A, g, 0.0)), 5: (g0, impact(A, g0, 0.0)),
                  6: (g6, impact(A, g6, -(g0 - g6)))}.get(inacti)
    print("%s: Inacti %d, M = %g, K = %g, g = %g, P0 = %g, v = %g" % (os.path.basename(deck), inacti, A["M"], K, g,
                                                                       P0, v))

    name = cc.run_radx(radx, deck, out)
    th = cc.read_th(out, name)
    res = cc.read_states(out, name)
    first = res["states"][0][1]
    index = {int(n): k for k, n in enumerate(res["node_id"])}

    def distance(tile):
        """Distance of the tile to the plate (mean over the tile's nodes in the time history) and its speed."""
        ids = [n for n in tile["nodes"] if cc.has_column(th, "%d:DZ" % n)]
        t, _ = cc.th_column(th, "%d:DZ" % ids[0])
        d = np.mean([first[index[n], 2] + cc.th_column(th, "%d:DZ" % n)[1] for n in ids], axis=0)
        pid = pa if tile is A else pb
        return t, d, cc.part_velocity(th, pid)[1]

    t, d_b, vz_b = distance(B)
    checks.close(g - d_b.min(), expected_b["p_max"], 0.01, "tile B largest penetration (mm)")
    checks.close(vz_b[-1], expected_b["v_rebound"], 0.01, "tile B rebound speed (mm/s)")
    t, d_a, vz_a = distance(A)
    if inacti in (1, 2):
        dev = np.max(np.abs(vz_a + v)) / v
        checks.check(dev <= 1e-9, "tile A untouched: speed -v to %.3g (allowed 1e-9)" % dev)
        checks.check(d_a[-1] < 0, "tile A ends below the plate (distance %.4g mm)" % d_a[-1])
    else:
        gap_a, exp = expected_a
        checks.close(gap_a - d_a.min(), exp["p_max"], 0.01, "tile A largest penetration into its gap %g (mm)" % gap_a)
        checks.check(d_a.min() > 0, "tile A never reaches the plate (closest %.4g mm)" % d_a.min())
        if inacti in (0, 3):
            checks.close(vz_a[-1], exp["v_rebound"], 0.01, "tile A rebound speed (mm/s)")
        else:
            checks.check(vz_a[-1] > 0, "tile A rebounds (final speed %.4g mm/s)" % vz_a[-1])
    if inacti == 3:
        za = np.array([first[index[n], 2] for n in A["nodes"]])
        checks.check(np.max(np.abs(za - g)) <= 1e-6 * g, "tile A moved to the gap surface before the run: "
                     "distance %.9g to %.9g mm (gap %g)" % (za.min(), za.max(), g))
    cc.check_energy_error(checks, cc.read_summary(out, name))


if __name__ == "__main__":
    cc.main_per_deck(one_deck)
