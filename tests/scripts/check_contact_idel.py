"""Idel (docs/theory/type7-lagdt.md 4.7): the segment of a deleted element stops acting with Idel = 1 or 2,
keeps acting with 0.

usage: /usr/bin/python3 check_contact_idel.py --radx RADX
           --decks decks/verification/idel/IDEL0_0000.rad decks/verification/idel/IDEL1_0000.rad
                   decks/verification/idel/IDEL2_0000.rad --out DIR

Each deck: the main surface is one Johnson-Cook shell with EPS_p_max failure, lying at z = 0 with all its nodes
fixed in Z; it is pulled in its plane until it fails and is deleted (docs/theory/elements.md 6.4), staying flat. A stiff
cube (mass M) then comes down at v0 on it, its lower-face nodes the secondary nodes. Everything is read from the
deck; Idel decides what is expected:

  Idel 0      the deleted element's segment keeps acting: a flat plane of Z-fixed nodes, so the cube is the
              one-degree-of-freedom body of check_contact_common.rigid_impact (as in node_on_segment);
  Idel 1, 2   the segment went with its element: the cube passes where the element was.

Tolerances (what they mean):
  * the element is deleted before the cube reaches the gap: the patch part's ERODED (time history) reaches the
    patch's mass rho t A (relative 1e-9: it is that mass, summed) at a time before the lower face enters the
    gap, so the contact only ever meets a deleted element;
  * Idel 0: largest penetration and rebound speed within 1 % of the one-DOF values (as in
    check_contact_node_on_segment);
  * Idel 1, 2: the interface's FNX, FNY, FNZ exactly 0 at every row, the cube keeps -v0 to 1e-9 (round-off; a
    single cycle of contact force would change it by more than 1e-4) and its lower face ends below z = 0;
  * energy error within 1 % (docs/theory/verification.md C).
"""
import os

import numpy as np

import check_contact_common as cc


def one_deck(radx, deck, out, checks):
    m = cc.Model(deck)
    (it,) = m.interfaces.values()
    assert it["Istf"] == 1 and it["Igap"] == 0
    K, g, vis_s, idel = it["Stfac"], it["Gapmin"], it["VISs"], it["Idel"]
    secondary = m.groups[it["grnd"]]
    _, M, vel = m.moving_body()
    masses = [m.masses[n] for n in secondary]
    v0 = -vel[2]
    (patch_part,) = {pid for pid, _, _ in m.shells.values()}
    patch_nodes = sorted({n for _, ns, _ in m.shells.values() for n in ns})
    patch_mass = sum(m.masses[n] for n in patch_nodes)
    z_plate = m.flat_z(patch_nodes, "the patch")
    z0 = np.array([m.nodes[n][2] for n in secondary])
    p_start = g - (z0.min() - z_plate)
    t_in = -p_start / v0
    print("%s: Idel %d, M = %g, %d pairs, K = %g, g = %g, v0 = %g; the cube enters the gap at %.6g s"
          % (os.path.basename(deck), idel, M, len(secondary), K, g, v0, t_in))

    name = cc.run_radx(radx, deck, out)
    th = cc.read_th(out, name)
    t, fn = cc.contact_forces(th, next(iter(m.interfaces)))
    pen = cc.penetrations(m, th, secondary, g, z_plate).mean(axis=0)
    _, eroded = cc.th_column(th, "%d:ERODED" % patch_part)
    gone = np.nonzero(np.abs(eroded - patch_mass) <= 1e-9 * patch_mass)[0]
    t_del = t[gone[0]] if len(gone) else np.inf
    checks.check(t_del < t_in, "the patch element is deleted (ERODED = its mass %.4g) at %.6g s, before the cube "
                 "enters the gap at %.6g s" % (patch_mass, t_del, t_in))
    _, vz = cc.part_velocity(th, m.brick_part())
    if idel == 0:
        exp = cc.rigid_impact(M, masses, K, g, vis_s, p_start, -v0)
        checks.check(np.any(fn[2] != 0), "the deleted element's segment pushes the cube")
        checks.close(pen.max(), exp["p_max"], 0.01, "largest penetration (mm)")
        checks.check(pen[-1] < 0, "the cube left the gap before the end")
        checks.close(vz[-1], exp["v_rebound"], 0.01, "rebound speed (mm/s)")
    else:
        checks.check(np.all(fn == 0), "no contact force at any row: largest |FN| %.3g N" % np.abs(fn).max())
        dev = np.max(np.abs(vz + v0)) / v0
        checks.check(dev <= 1e-9, "the cube keeps -v0 to %.3g (allowed 1e-9)" % dev)
        checks.check(pen[-1] > g, "the cube passed where the element was: lower face %.4g mm below it"
                     % (pen[-1] - g))
    cc.check_energy_error(checks, cc.read_summary(out, name))


if __name__ == "__main__":
    cc.main_per_deck(one_deck, self_test_first=True)
