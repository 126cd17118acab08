"""A cube dropped on a plate with each /CTCLAW normal law (docs/theory/contact-laws.md 2 and 6) against the
closed forms.

usage: /usr/bin/python3 check_ctclaw_drop.py --radx RADX --decks decks/verification/ctclaw_drop/*_0000.rad
           --out DIR

Each deck: a stiff cube (mass M) moving at v0 along -Z towards one fixed, flat main segment of a TYPE7 whose
normal law is a /CTCLAW; its N lower-face nodes are the secondary nodes and reach the gap together, so the cube
is one degree of freedom on N pairs, each pushing with P(u) A_s (u the overclosure into the gap, A_s the node's
tributary area by the starter's rule, check_ctclaw_common.tributary_areas: a quarter of each patch of the
contact surface around the node, here the cube's lower face). Everything (M, the
nodal masses, K, the gap, VISs, v0, the law string and its /FUNCT, the geometry for A_s) is read from the deck.
The runs use one thread (the checks are about the laws; thread determinism is contact.threads').

Expected values:
  * VISs ~ 0 (below 1e-6): the law is elastic, so sum A_s * integral of P du from the law's onset (0, or the
    exponential law's cut-off ln(1e-12) / lambda) to u_max = M v0^2 / 2 (check_ctclaw_common.peak_overclosure),
    and the cube rebounds at v0; for the bilinear law, a spring of k = sum Kc A_s: contact time pi sqrt(M / k);
  * VISs > 0 (bilinear law only): each pair also damps with c_i = VISs sqrt(2 Kc A_s m_i) (m_i the secondary
    node's mass; contact/type7_engine.cpp), a Kelvin-Voigt contact: xi = sum c_i / (2 sqrt(k M)), contact time
    pi / (omega sqrt(1 - xi^2)), rebound v0 exp(-xi pi / sqrt(1 - xi^2)), u_max = (v0 / omega)
    exp(-xi / sqrt(1 - xi^2) atan(sqrt(1 - xi^2) / xi)) (check_ctclaw_common.damped_linear_impact).

Tolerances (what they mean):
  * largest overclosure (mean of the lower-face nodes, time history at every cycle) within 0.5 %: the cube is not
    rigid -- at the peak its elastic energy holds up to ~1.5 % of the kinetic energy for the stiffest law here
    (the exponential, whose peak stiffness is ~1/12 of the cube's axial E a), which lowers u_max by ~0.2 % (the
    steep law absorbs the difference within a small overclosure) and by ~0.05 % for the others; sampling the
    peak at every cycle adds ~1e-5. The laws' u_max differ by 4 % (linear and cubic table) to 12 % (KcMax);
  * rebound speed (ZMOM / MASS of the cube at the end, past the law's reach) within 0.2 % of the expected: the
    cube's elastic vibration and hourglass energy after the impact keep below 0.02 % of the energy, and the
    central-difference integration across the law's onset costs ~1e-4 of v0; with VISs 0.05 the damping removes
    5.4 % of the speed, so 0.2 % also catches a damping off by more than ~4 %;
  * contact time of the bilinear law (mean overclosure > 0, its two crossings interpolated between rows) within
    2 % of pi sqrt(M / k);
  * the lower-face nodes stay level at the peak (spread below 1 % of the gap): the rigid-body premise;
  * the starter listing's automatic stiffness density K / A_s (Kc = -1, pe) equals K over the A_s computed here
    (within its 6 printed digits): the checks' area is the starter's;
  * energy balance (docs/theory/verification.md C): the run's energy error within 1 %.
"""
import math
import os

import numpy as np

import check_contact_common as cc
import check_ctclaw_common as ctc


def crossing(t, y, k0, k1):
    """The time where y crosses 0 between rows k0 and k1, interpolated linearly."""
    return t[k0] + (t[k1] - t[k0]) * (0 - y[k0]) / (y[k1] - y[k0])


def one_deck(radx, deck, out, checks):
    m = cc.Model(deck)
    (iid, it), = m.interfaces.items()
    assert it["Istf"] == 1 and it["Igap"] == 0, "the closed form needs Istf 1 (K = Stfac) and Igap 0 (g = Gapmin)"
    K, gap, vis_s = it["Stfac"], it["Gapmin"], it["VISs"]
    law_id, urn = ctc.ctclaws(m.deck)[iid]
    law = ctc.parse_urn(urn)
    curves = ctc.functs(m.deck)
    secondary = m.groups[it["grnd"]]
    areas = ctc.tributary_areas(m, secondary)
    _, M, vel = m.moving_body()
    v0 = -vel[2]
    z_plate = m.flat_z([n for pid, ns, _ in m.shells.values() for n in ns], "the main plate")
    pairs = [(ctc.NormalLaw(law, K, areas[n], curves), areas[n]) for n in secondary]
    onset = max(lw.onset() for lw, _ in pairs)
    z0 = min(m.nodes[n][2] for n in secondary)
    checks.check(gap - (z0 - z_plate) < onset, "the deck starts outside the law's reach (overclosure %.4g m below"
                 " the onset %.4g m)" % (gap - (z0 - z_plate), onset))
    undamped = vis_s < 1e-6
    ke = 0.5 * M * v0 * v0
    exp = dict(u_max=ctc.peak_overclosure(pairs, ke, gap), rebound=v0, t_contact=None)
    if law["normal"] == 1:
        ks = [lw.kc * a for lw, a in pairs]
        cs = [0.0 if undamped else vis_s * math.sqrt(2 * k * m.masses[n]) for k, n in zip(ks, secondary)]
        lin = ctc.damped_linear_impact(M, ks, cs, v0)
        exp = dict(u_max=lin["u_max"], rebound=lin["restitution"] * v0, t_contact=lin["t_contact"], xi=lin["xi"])
    else:
        assert undamped, "the closed forms with damping are for the bilinear law only"
    print("%s: /CTCLAW/%d %s, M = %g, %d pairs, A_s = %s, K = %g, gap = %g, VISs = %g, v0 = %g: expected u_max = "
          "%.6g, rebound %.6g%s" % (os.path.basename(deck), law_id, urn, M, len(secondary),
                                   ", ".join("%g" % areas[n] for n in secondary), K, gap, vis_s, v0, exp["u_max"],
                                   exp["rebound"], "" if exp["t_contact"] is None else
                                   ", contact time %.6g (xi %.4g)" % (exp["t_contact"], exp["xi"])))

    name = cc.run_radx(radx, deck, out, ("--threads", "1"))
    listing = open(os.path.join(out, name + "_0000.out"), encoding="utf-8", errors="replace").read()
    auto = law["params"].get("kc") == -1 or "pe" in law["params"]
    if auto:
        got = ctc.listing_automatic_stiffness(listing)
        want = (K / max(areas[n] for n in secondary), K / min(areas[n] for n in secondary))
        checks.check(got is not None and all(abs(a - b) <= 1e-5 * b for a, b in zip(got, want)),
                     "the listing's K / A_s %s = K / A_s %s of the starter's rule" % (got, want))
    th = cc.read_th(out, name)
    t, _ = cc.th_column(th, "%d:DZ" % secondary[0])
    pen = cc.penetrations(m, th, secondary, gap, z_plate)
    mean = pen.mean(axis=0)
    k_max = int(np.argmax(mean))
    checks.close(mean[k_max], exp["u_max"], 0.005, "largest overclosure (m)")
    checks.check(np.ptp(pen[:, k_max]) <= 0.01 * gap, "lower-face nodes level at the largest overclosure: spread "
                 "%.3g m (allowed 1 %% of the gap)" % np.ptp(pen[:, k_max]))
    checks.check(mean[-1] < onset, "the cube is past the law's reach at the end (overclosure %.4g m < %.4g m)"
                 % (mean[-1], onset))
    v_reb = cc.part_velocity(th, m.brick_part())[1][-1]
    checks.close(v_reb, exp["rebound"], 0.002, "rebound speed (m/s)")
    if exp["t_contact"] is not None:
        inside = np.nonzero(mean > 0)[0]
        ok = len(inside) > 0 and inside[0] > 0 and inside[-1] + 1 < len(t)
        checks.check(ok, "the cube entered the gap and left it during the run")
        if ok:
            t_in = crossing(t, mean, inside[0] - 1, inside[0])
            t_out = crossing(t, mean, inside[-1], inside[-1] + 1)
            checks.close(t_out - t_in, exp["t_contact"], 0.02, "contact time (s)")
    s = cc.read_summary(out, name)
    e = s["energy"]
    cc.check_energy_error(checks, s, "; contact elastic %.4g, damping %.4g J at the end; kinetic %.6g of %.6g J"
                          % (e["contact_elastic"], e["contact_damping"], e["kinetic"], ke))


if __name__ == "__main__":
    ctc.self_test()
    cc.main_per_deck(one_deck)
