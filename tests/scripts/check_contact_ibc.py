"""IBC (docs/theory/type7-lagdt.md 4.7): at its first impact a secondary node loses the fixed
translations IBCX/IBCY/IBCZ select.

usage: /usr/bin/python3 check_contact_ibc.py --radx RADX
           --decks decks/verification/ibc/IBC_Z0_0000.rad decks/verification/ibc/IBC_Z1_0000.rad --out DIR

Each deck: a light tile (mass m) lies at z = 0, its nodes the secondary nodes, fixed in Z by /BCS and pulled
down by gravity g_z applied to the tile only; a stiff cube (mass M, its outer faces the main surface) comes down
at v0 and meets the tile with its flat lower face (one segment). Everything is read from the deck; IBCZ decides
what is expected:

  IBCZ = 0   the tile never moves in Z; the cube is the one-degree-of-freedom body of
             check_contact_common.rigid_impact on the tile's pairs (secondary nodal masses in the damping);
  IBCZ = 1   the tile is held (against gravity) until the first cycle with a contact force, then nothing holds
             it in Z: the total Z momentum changes only by the tile's weight, and the tile is pushed away.

Tolerances (what they mean):
  * "never moves" / "held until the impact": DZ of every tile node exactly 0 (a /BCS-fixed translation is not
    integrated at all), at every row (IBCZ 0) or up to and including the first row with a contact force (its
    positions are those the force was computed with; IBCZ 1);
  * IBCZ 0: largest penetration and rebound speed within 1 % of the one-DOF values (as in
    check_contact_node_on_segment);
  * IBCZ 1: total ZMOM (time history, every cycle) equal to -M v0 before the impact (1e-9 relative) and to
    -M v0 - m g_z (t - t_impact) after it, within m g_z dt_max + 1e-9 M v0: the time-history velocity is the
    full-step one, so the weight's impulse is known to within one step; a /BCS still holding the tile would take
    the contact force's impulse instead, about 1e-3 M v0 per cycle of contact;
  * IBCZ 1: at the end every tile node has moved down by more than the gap, and the tile's mean speed (ZMOM /
    MASS of its part) is faster downwards than the cube's but not faster than after an elastic collision,
    2 M v0 / (M + m), plus g_z t_end;
  * energy error within 1 % (docs/theory/verification.md C).
"""
import os

import numpy as np

import check_contact_common as cc


def one_deck(radx, deck, out, checks):
    m = cc.Model(deck)
    (it,) = m.interfaces.values()
    assert it["Istf"] == 1 and it["Igap"] == 0
    K, g, vis_s = it["Stfac"], it["Gapmin"], it["VISs"]
    ibcz = it["IBC"][2]
    tile = m.groups[it["grnd"]]
    cube, M, vel = m.moving_body()
    v0 = -vel[2]
    mt = sum(m.masses[n] for n in tile)
    masses = [m.masses[n] for n in tile]
    (direction, grav_group, gz), = m.grav
    assert direction == "Z" and sorted(m.groups[grav_group]) == sorted(tile), "gravity acts on the tile only"
    z_tile = m.flat_z(tile, "the tile")
    face = [n for n in cube if m.nodes[n][2] == min(m.nodes[c][2] for c in cube)]
    z_face = m.nodes[face[0]][2]
    print("%s: IBC %s, M = %g, m = %g, %d pairs, K = %g, g = %g, v0 = %g, gravity %g on the tile"
          % (os.path.basename(deck), "".join(map(str, it["IBC"])), M, mt, len(tile), K, g, v0, gz))

    name = cc.run_radx(radx, deck, out)
    th = cc.read_th(out, name)
    iid = next(iter(m.interfaces))
    t, fnz = cc.th_column(th, "%d:FNZ" % iid)
    dz = np.array([cc.th_column(th, "%d:DZ" % n)[1] for n in tile])
    pen = g - (z_face + np.mean([cc.th_column(th, "%d:DZ" % n)[1] for n in face], axis=0) - z_tile - dz.mean(axis=0))
    hit = np.nonzero(fnz != 0)[0]
    checks.check(len(hit) > 0, "the cube reached the tile (a contact force at %d rows)" % len(hit))
    if not len(hit):
        return
    k_r = int(hit[0])
    tile_part = next(pid for pid in m.parts if any(s[0] == pid for s in m.shells.values()))
    vcube = cc.part_velocity(th, m.brick_part())[1]

    if ibcz == 0:
        checks.check(np.all(dz == 0), "the tile never moves in Z: largest |DZ| %.3g m (must be 0)" % np.abs(dz).max())
        exp = cc.rigid_impact(M, masses, K, g, vis_s, -(z_face - z_tile - g), -v0)
        checks.close(pen.max(), exp["p_max"], 0.01, "largest penetration (m)")
        checks.check(pen[-1] < 0, "the cube left the gap before the end")
        checks.close(vcube[-1], exp["v_rebound"], 0.01, "cube rebound speed (m/s)")
    else:
        held = dz[:, :k_r + 1]
        checks.check(np.all(held == 0), "the tile is held against gravity until the impact (t = %.6g s): largest "
                     "|DZ| %.3g m before it (must be 0)" % (t[k_r], np.abs(held).max()))
        checks.check(np.all(dz[:, -1] < -g), "released at the impact: every tile node moved down by more than the "
                     "gap (%.4g to %.4g m)" % (dz[:, -1].min(), dz[:, -1].max()))
        _, zmom = cc.th_column(th, "ZMOM")
        _, dt = cc.th_column(th, "DT")
        dev0 = np.max(np.abs(zmom[:k_r] + M * v0)) / (M * v0)
        checks.check(dev0 <= 1e-9, "total ZMOM = -M v0 before the impact (largest relative deviation %.3g)" % dev0)
        expected = -M * v0 + mt * gz * (t[k_r:] - t[k_r])
        dev = np.max(np.abs(zmom[k_r:] - expected))
        allowed = mt * abs(gz) * dt.max() + 1e-9 * M * v0
        checks.check(dev <= allowed, "no /BCS reaction after the impact: total ZMOM = -M v0 + m g_z (t - t_impact) "
                     "to %.3g (allowed %.3g = m g_z dt_max; a cycle of contact force is ~%.3g)"
                     % (dev, allowed, np.abs(fnz).max() * dt.max()))
        u = cc.part_velocity(th, tile_part)[1][-1]
        bound = 2 * M * v0 / (M + mt) + abs(gz) * t[-1]
        checks.check(u < vcube[-1] < 0 and -u <= bound, "the tile is pushed away: %.5g m/s, faster than the cube "
                     "(%.5g m/s), not faster than the elastic bound %.5g m/s" % (u, vcube[-1], -bound))
    cc.check_energy_error(checks, cc.read_summary(out, name))


if __name__ == "__main__":
    cc.main_per_deck(one_deck, self_test_first=True)
