"""A /CTCLAW law on an /INTER/LAGDT/TYPE7 acts until its pairs switch to Lagrange multipliers, and the
multipliers act after the switch (docs/theory/contact-laws.md 5: "the normal law applies until a pair switches; after
the switch the friction law acts with the multiplier as the normal force"; docs/theory/type7-lagdt.md 6).

usage: /usr/bin/python3 check_ctclaw_lagdt_switch.py --radx RADX
           --decks decks/verification/ctclaw_lagdt_switch/*_0000.rad --out DIR

Each deck: ctclaw_drop's stiff cube (mass M, its N lower-face nodes the secondary nodes, lumped mass m each,
tributary area A_s by the starter's rule, check_ctclaw_common.tributary_areas) moving at v0 along -Z (and, for
a deck with friction, sideways along +X) onto one fixed segment of an /INTER/LAGDT/TYPE7 whose normal law is a
stiffening /CTCLAW law, with /DT/INTER/CST Tscale Tmin in the engine deck. Everything (M, m, A_s, the gap, VISs,
the law string, v0, Tscale, Tmin) is read from the decks. The runs use one thread and print every cycle
(/PRINT/-1), so the listing's LAG-PAIRS column (pairs solved with multipliers in the cycle) is known at every
cycle; the time history has a row at every cycle (its interval is below the step).

The switch rule (contact/type7_engine.cpp: law_reach_stiffness, pair_spring_step, settle_switches): at cycle n
a pair in contact votes with k = A_s max(Kc(u), Kc(u + 2 w dt1)) -- the law's stiffness at its overclosure u and
two steps ahead at its approach speed w = (u^n - u^{n-1}) / dt1 (dt1 = t^n - t^{n-1}); also exact Coulomb's
sticking spring kappa A_s when stiffer -- over (sqrt(1 + xi^2) - xi)^2 for the VISs damping, and switches when
min(Tscale sqrt(2 m / k) (the segment is fixed), 0.5 (g - u) / w, Tscale m / c) < Tmin. The expected first
switch cycle is computed with that rule from the time history's overclosures (u = the gap minus the node's
height above the plate).

Checks and tolerances (what they mean):
  (a) the law acts before the switch:
    * the law has taken at least 10 % of the kinetic energy (sum A_s * integral of P du at the overclosures
      of the last cycle before the switch): the run shows both phases (a Tmin far above the pairs' steps
      switches them at the law's onset, a tiny one never);
    * on every cycle before the first switch where the law pushes (at least 1e-3 of its force at the switch),
      the interface's normal force (time history FN) is sum P(u_i) A_s within 1e-5 relative: the law, on the
      tributary areas, on the penalty path (the overclosures are read back from the time history's DZ, exact
      to ~1e-16 m; the VISs 1e-10 damping adds ~1e-10 relative);
    * the energy at the last cycle before the first switch: the cube's kinetic, internal and hourglass energy
      (time history of its part) plus the law's work sum A_s * integral of P du (from the law's onset to each
      node's overclosure, check_ctclaw_common.NormalLaw.work) equals M v0^2 / 2 within 0.1 % of it: the cube
      has decelerated as the law predicts. Central differences do the law's work as a trapezoid over each step
      (the engine's energy balance books the same), which exceeds the integral of the convex exponential by
      ~(lambda w dt)^2 / 12 ~ 1e-3 of it near the switch (lambda w dt ~ 0.12): ~0.04 % of the energy here; a
      law or an area off by 1 % misses by ~0.4 %. Also printed: the rigid-body speed sqrt(v0^2 - 2 W / M)
      against the cube's ZMOM / MASS (0.2 % apart: the cube's elastic energy is not in it);
  (b) the pairs switch, and the multipliers hold them:
    * the first cycle with switched pairs (listing) is the one the rule predicts, and (frictionless decks,
      where the cube comes down level) all N pairs switch in it; the summary's switched_pairs_max is N;
    * frictionless decks: from the first switch until the cube moves up (ZMOM / MASS >= 0; at least 3 cycles)
      the mean overclosure stays within 0.1 % of its value at the switch: a multiplier row lets the node
      approach no further (velocity level, exact to round-off), while one cycle on the law's path at the speed
      of the switch moves it by w dt (~1.6 % here);
  (friction) decks with a friction part (exact Coulomb, sliding all along):
    * before the first switch, on the rows where the law pushes (1e-3 of its force at the switch and more),
      |FT| = mu |FN| within 0.1 % (the interface's summed forces of the time history): the sticking spring
      kappa A_s keeps up with the law's rising pressure (it lags by ~4e-6 here);
    * from the first switch on, |FT| <= mu |FN| (1 + 1e-6) + 1e-9 N at every cycle: the friction never exceeds
      Coulomb with the multipliers and the law's forces as the normal force (1e-9 N: on the law's tail, where
      the forces are ~1e-7 N, FN holds the VISs 1e-10 dashpot, ~1e-5 of it, which the friction does not see);
    * on the cycles where every pair is switched (at least one), the friction law acts with the multiplier as
      the normal force: |FT| / |FN| lies between 0.8 mu and mu, and reaches mu within 2 % on one of them. The
      rows hold the nodes where they switched (they keep their row while it pushes), so the multipliers of
      the first cycles carry the whole stop of the cube's normal motion and the friction takes most of its
      sideways speed in a step or two: a row whose sticking force m v_t / dt falls below mu lambda sticks and
      lowers the ratio, and the lower face spreads sideways (its nodes move at +-0.05 to 0.07 m/s along Y) so
      the four forces lean off -X, hence 0.8 and 2 %. Were the friction still bounded by the law's P A_s
      after the switch, the ratio would fall to ~0.1 (a third of mu);
  (c) the run's energy error (summary) within 1 % (docs/theory/verification.md C).
"""
import math
import os
import re

import check_contact_common as cc
import check_ctclaw_common as ctc

# Exact Coulomb (s1, s11) in the law string's friction number.
COULOMB = (1, 11)


def stiffness(law, u):
    """Kc(u) = dP/du (Pa/m) of a check_ctclaw_common.NormalLaw: the closed forms of docs/theory/contact-laws.md 2 for
    the bilinear, exponential and power laws, the slope of the segment for a linear table (a central difference
    elsewhere)."""
    if law.kind == 1:
        return law.kc if u > 0 else 0.0
    if law.kind == 2:
        if u > law.u_knee:
            return law.kc_max
        return law.lam * law.pressure(u) if law.pressure(u) > 0 else 0.0
    if law.kind == 4:
        return sum(m * k * u ** (m - 1) for m, k in law.power) if u > 0 else 0.0
    h = 1e-9 * max(abs(u), 1e-6)
    return (law.pressure(u + h) - law.pressure(u - h)) / (2 * h)


def pair_step(law, area, mass, u, w, dt1, gap, tscale, viss, kappa_k):
    """The pair's step under the engine's switch rule (module docstring): (step, its spring stiffness)."""
    k_vote = area * max(stiffness(law, u), stiffness(law, u + 2 * max(w, 0.0) * dt1))
    k_vote = max(k_vote, kappa_k)
    kt = stiffness(law, u) * area
    c = viss * math.sqrt(2 * kt * mass)
    xi = c / (2 * math.sqrt(kt * mass)) if kt > 0 else 0.0
    keff = k_vote / (math.sqrt(1 + xi * xi) - xi) ** 2
    dt = tscale * math.sqrt(2 * mass / keff) if keff > 0 else math.inf
    if w > 0:
        dt = min(dt, 0.5 * (gap - u) / w)
    if c > 0:
        dt = min(dt, tscale * mass / c)
    return dt, keff


def switch_stiffness(mass, tscale, tmin):
    """k* = 2 m (Tscale / Tmin)^2: a pair whose (effective) stiffness exceeds it has a step below Tmin."""
    return 2 * mass * (tscale / tmin) ** 2


def listing_lag_pairs(text):
    """{cycle: (time, LAG-PAIRS)} of the engine listing's cycle lines (the LAG-PAIRS column is the last)."""
    out = {}
    header = False
    for ln in text.splitlines():
        if "LAG-PAIRS" in ln:
            header = True
            continue
        f = ln.split()
        if header and len(f) >= 12 and f[0].isdigit() and re.fullmatch(r"-?[0-9.]+%", f[5] if len(f) > 5 else ""):
            out[int(f[0])] = (float(f[1]), int(f[-1]))
    return out


def one_deck(radx, deck, out, checks):
    import numpy as np

    m = cc.Model(deck)
    (iid, it), = m.interfaces.items()
    assert it["lagdt"], "the case is about /INTER/LAGDT/TYPE7"
    assert it["Istf"] == 1 and it["Igap"] == 0, "K = Stfac (Istf 1) and g = Gapmin (Igap 0)"
    K, gap, vis_s = it["Stfac"], it["Gapmin"], it["VISs"]
    law_id, urn = ctc.ctclaws(m.deck)[iid]
    law = ctc.parse_urn(urn)
    secondary = m.groups[it["grnd"]]
    areas = ctc.tributary_areas(m, secondary)
    laws = {n: ctc.NormalLaw(law, K, areas[n], ctc.functs(m.deck)) for n in secondary}
    _, M, vel = m.moving_body()
    v0 = -vel[2]
    z_plate = m.flat_z([n for pid, ns, _ in m.shells.values() for n in ns], "the main plate")
    tscale, tmin = cc.engine_card(deck, "/DT/INTER/CST")
    fric = law["friction"]
    assert fric in (0,) + COULOMB, "the friction checks are written for exact Coulomb"
    mu = law["params"].get("mu", 0.0)
    kappa_k = {n: (law["params"]["kappa"] * areas[n] if "kappa" in law["params"] else K) if fric else 0.0
               for n in secondary}
    nb = len(secondary)
    n0 = secondary[0]
    k_star = switch_stiffness(m.masses[n0], tscale, tmin)
    print("%s: /CTCLAW/%d %s on LAGDT interface %d, M = %g kg, %d pairs (m = %s kg, A_s = %s m2), gap %g m, "
          "VISs %g, v0 = %g m/s%s; /DT/INTER/CST %g %g: a pair switches when its stiffness passes "
          "k* = 2 m (Tscale / Tmin)^2 = %.6g N/m" % (
              os.path.basename(deck), law_id, urn, iid, M, nb, ", ".join("%g" % m.masses[n] for n in secondary),
              ", ".join("%g" % areas[n] for n in secondary), gap, vis_s, v0,
              ", sideways %g m/s" % vel[0] if vel[0] else "", tscale, tmin, k_star))

    name = cc.run_radx(radx, deck, out, ("--threads", "1"))
    lag = listing_lag_pairs(cc.read_listing(out, name))
    th = cc.read_th(out, name)
    t, _ = cc.th_column(th, "%d:DZ" % n0)
    rows = len(t)
    ok_rows = (sorted(lag) == list(range(rows)) and
               all(abs(lag[k][0] - t[k]) <= 1e-5 * abs(t[k]) + 1e-12 for k in range(rows)))
    if not checks.check(ok_rows, "a listing line and a time-history row at every cycle (%d rows, %d lines)"
                        % (rows, len(lag))):
        return
    pairs_at = np.array([lag[k][1] for k in range(rows)])
    u = cc.penetrations(m, th, secondary, gap, z_plate)  # [node, row]
    umean = u.mean(axis=0)
    _, fnv = cc.contact_forces(th, iid)
    fn_abs = np.linalg.norm(fnv, axis=0)
    ftv = np.array([cc.th_column(th, "%d:FT%s_INST" % (iid, a))[1] for a in "XYZ"])  # the cycle's, as FN
    ft_abs = np.linalg.norm(ftv, axis=0)
    pid = m.brick_part()
    _, vz = cc.part_velocity(th, pid)

    # The rule's first switch cycle, from the overclosures of the time history.
    predicted, margin = None, []
    for k in range(1, rows):
        dt1 = t[k] - t[k - 1]
        steps = []
        for i, n in enumerate(secondary):
            lw = laws[n]
            if u[i, k] < lw.onset():
                continue
            w = (u[i, k] - u[i, k - 1]) / dt1
            steps.append(pair_step(lw, areas[n], m.masses[n], u[i, k], w, dt1, gap, tscale, vis_s, kappa_k[n])[0])
        if steps and min(steps) < tmin:
            predicted = k
            break
        if steps:
            margin = [(k, min(steps))]
    observed = next((k for k in range(rows) if pairs_at[k] > 0), None)
    if predicted is not None:
        k = predicted
        w = (umean[k] - umean[k - 1]) / (t[k] - t[k - 1])
        print("  the rule: first switch at cycle %d (t = %.6g s), overclosure %.6g m, approach speed %.5g m/s, "
              "pair step %.5g s < Tmin (the cycle before: %s)" % (
                  k, t[k], umean[k], w, min(pair_step(laws[n], areas[n], m.masses[n], u[i, k],
                                                      (u[i, k] - u[i, k - 1]) / (t[k] - t[k - 1]),
                                                      t[k] - t[k - 1], gap, tscale, vis_s, kappa_k[n])[0]
                                             for i, n in enumerate(secondary)),
                  ", ".join("step %.5g s at cycle %d" % (s, c) for c, s in margin) or "none"))
    checks.check(predicted is not None and observed == predicted,
                 "(b) first cycle with switched pairs: %s (listing LAG-PAIRS), the rule predicts %s"
                 % (observed, predicted))
    if observed is None or observed < 2:
        checks.check(False, "(a) the law acts for some cycles before the first switch")
        return
    s = cc.read_summary(out, name)
    (ires,) = [r for r in s["interfaces"] if r["id"] == iid]
    checks.check(ires["switched_pairs_max"] == nb, "(b) switched_pairs_max %d (summary) = the %d pairs"
                 % (ires["switched_pairs_max"], nb))

    # (a) before the switch: the law's share of the energy, its force, and the energy balance.
    k_last = observed - 1
    ke0 = 0.5 * M * (v0 * v0 + vel[0] ** 2 + vel[1] ** 2)
    ke0_n = 0.5 * M * v0 * v0
    w_law = sum(areas[n] * laws[n].work(u[i, k_last]) for i, n in enumerate(secondary))
    if not checks.check(w_law >= 0.1 * ke0_n, "(a) the law takes %.4g J (%.3g %%) of the normal kinetic energy "
                        "%.4g J before the switch (at least 10 %%)" % (w_law, 100 * w_law / ke0_n, ke0_n)):
        return
    f_law = np.array([sum(laws[n].pressure(u[i, k]) * areas[n] for i, n in enumerate(secondary))
                      for k in range(rows)])
    pushing = [k for k in range(observed) if f_law[k] >= 1e-3 * f_law[k_last]]
    err = max(abs(fn_abs[k] - f_law[k]) / f_law[k] for k in pushing)
    checks.check(err <= 1e-5, "(a) before the switch the interface's normal force is the law's sum P(u) A_s "
                 "(%d cycles, up to %.6g N): largest deviation %.3g (allowed 1e-5)" % (len(pushing), f_law[k_last],
                                                                                      err))
    if not fric:
        cube_e = sum(cc.th_column(th, "%d:%s" % (pid, c))[1][k_last] for c in ("KE", "IE", "HE"))
        checks.check(abs(cube_e + w_law - ke0) <= 1e-3 * ke0,
                     "(a) at cycle %d (the last on the law; overclosure %.6g m) the cube's kinetic + internal + "
                     "hourglass energy %.6g J + the law's work %.6g J = %.6g J, M v0^2 / 2 = %.6g J (off by %.3g %%, "
                     "allowed 0.1 %%)" % (k_last, umean[k_last], cube_e, w_law, cube_e + w_law, ke0,
                                          100 * (cube_e + w_law - ke0) / ke0))
        v_rigid = math.sqrt(max(0.0, v0 * v0 - 2 * w_law / M))
        print("  rigid-body speed from the law's work sqrt(v0^2 - 2 W / M) = %.6g m/s; the cube's ZMOM / MASS "
              "%.6g m/s (%.3g %%; the cube's elastic energy %.3g J)" % (
                  v_rigid, -vz[k_last], 100 * (-vz[k_last] - v_rigid) / v_rigid,
                  cc.th_column(th, "%d:IE" % pid)[1][k_last]))

        # (b) after the switch: the multipliers hold the overclosure while the cube moves down.
        checks.check(pairs_at[observed] == nb, "(b) all %d pairs switch at cycle %d (LAG-PAIRS %d)"
                     % (nb, observed, pairs_at[observed]))
        u1 = umean[observed]
        up = next((k for k in range(observed + 1, rows) if vz[k] >= 0), rows - 1)
        window = range(observed, up + 1)
        checks.check(len(window) >= 3, "(b) the cube still moves down for %d cycles after the switch (cycles %d to "
                     "%d)" % (len(window) - 1, observed, up))
        k_max = max(window, key=lambda k: umean[k])
        w1 = (umean[observed] - umean[observed - 1]) / (t[observed] - t[observed - 1])
        checks.check(umean[k_max] <= u1 * (1 + 1e-3),
                     "(b) overclosure after the switch, while the cube moves down: at most %.7g m (cycle %d) against"
                     " %.7g m at the switch (+%.3g %%, allowed 0.1 %%; one step on the law's path at the switch "
                     "speed: %.3g %%)" % (umean[k_max], k_max, u1, 100 * (umean[k_max] / u1 - 1),
                                         100 * w1 * (t[observed] - t[observed - 1]) / u1))
        print("  LAG-PAIRS from cycle %d to %d: %s; overclosure (m): %s" % (
            observed, up, " ".join(str(pairs_at[k]) for k in window),
            " ".join("%.6g" % umean[k] for k in window)))
    else:
        err = max(abs(ft_abs[k] - mu * fn_abs[k]) / (mu * fn_abs[k]) for k in pushing)
        checks.check(err <= 1e-3, "(friction) before the switch |FT| = mu |FN| (mu %g, %d cycles): largest "
                     "deviation %.3g (allowed 1e-3)" % (mu, len(pushing), err))
        after = range(observed, rows)
        k_over = max(after, key=lambda k: ft_abs[k] - mu * fn_abs[k] * (1 + 1e-6))
        checks.check(ft_abs[k_over] <= mu * fn_abs[k_over] * (1 + 1e-6) + 1e-9,
                     "(friction) from the switch on |FT| <= mu |FN| at every cycle (closest: cycle %d, |FT| %.6g N, "
                     "mu |FN| %.6g N)" % (k_over, ft_abs[k_over], mu * fn_abs[k_over]))
        full = [k for k in after if pairs_at[k] == nb and fn_abs[k] > 0]
        ratios = [ft_abs[k] / fn_abs[k] for k in full]
        checks.check(len(full) >= 1 and all(0.8 * mu <= r <= mu * (1 + 1e-6) for r in ratios) and
                     max(ratios) >= 0.98 * mu,
                     "(friction) on the cycles with every pair switched (%s) |FT| / |FN| = %s, mu = %g (allowed "
                     "0.8 mu to mu, mu within 2 %% on one); the cube's tangential deceleration |FT| / M = %s m/s2" % (
                         ", ".join(map(str, full)) or "none", ", ".join("%.5f" % r for r in ratios), mu,
                         ", ".join("%.5g" % (ft_abs[k] / M) for k in full)))
    e = s["energy"]
    cc.check_energy_error(checks, s, "; contact elastic %.4g, Lagrange %.4g, friction %.4g J at the end"
                          % (e["contact_elastic"], e.get("contact_lagrange", float("nan")), e["contact_friction"]))


if __name__ == "__main__":
    ctc.self_test()
    cc.main_per_deck(one_deck)
