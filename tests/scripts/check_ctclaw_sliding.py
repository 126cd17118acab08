"""A block sliding under gravity with each /CTCLAW friction law (docs/theory/contact-laws.md 3, 5 and 6) against the
closed forms; the same on an /INTER/LAGDT/TYPE7 with every pair switched to a Lagrange-multiplier row.

usage: /usr/bin/python3 check_ctclaw_sliding.py --radx RADX
           --decks decks/verification/ctclaw_sliding/*_0000.rad decks/verification/ctclaw_lagdt/*_0000.rad
           --out DIR

A stiff cube (mass M) rests under gravity g on one fixed main segment through its N lower-face secondary nodes
(the law's normal part holds the weight: each pair carries M g / N) and starts sliding at v0 (the deck's
/INIVEL/TRA, along +X or +Y). The /CTCLAW friction law gives each pair a force per area f(s, p) opposing the
slip s, p = (M g / N) / A_s the pair's pressure (A_s by the starter's rule, check_ctclaw_common.tributary_areas);
all pairs slip at the cube's speed v, so dv/dt = -a(v) = -sum f(v, p) A_s / M:
  * s1, s11 (exact Coulomb): a = mu g: the cube stops at v0 / (mu g) and sticks;
  * s12: f = min(ct v, mu p); s14: f = p min(ct v, mu): a = mu g above the threshold speed, viscous below it;
  * s13: f = mu p (2/pi) atan(ct v): a = mu g (2/pi) atan(ct v) at every speed;
  * a steep law (the _STEEP decks: its threshold speed v*, mu p / ct, mu / ct, or for s13 the speed 63.7 / ct
    where it reaches 99 % of mu p, below 1e-6 v0) is exact Coulomb for the check: a = mu g, then at rest;
  * s1..s4 keep only the slip along the segment's first tangent t1 = x2 - x1: sliding along t1 they act as above;
    sliding across it (the _S1_Y deck) they give no friction and the cube keeps v0; sliding at an angle to it
    (the _S4_45 deck) they act as above on the velocity's part along t1, v1 (from v1(0) = v0 cos angle, the slip
    speed being |v1|), and the part across it, v2, keeps its value.
The friction's moment about the centre of mass (height h above the pairs) tilts the cube forward: the front
pairs carry more, N_i = M g / N + F h x_i / sum x_j^2 (x_i the pair's arm along the motion, equal linear springs);
this changes nothing for the laws linear in the pressure (s1, s11, s13, s14) but delays s12's viscous branch
(min(ct v, mu p_i) of the rear pairs switches first). The expected speed history is the ODE M dv/dt = -F(v) with
that F (RK4, steps of a tenth of its fastest time scale M / (slope at v = 0 * sum A_s), at most 1e-4 s; exact
Coulomb and steep laws: v0 - mu g t, then at rest); M, g, v0, the law string, the geometry and the first tangent
are read from the deck.
On LAGDT (every pair a multiplier row at every cycle, /DT/INTER/CST with Tmin far above the pairs' steps) the
multiplier is the normal force: the same closed form. The runs use one thread (the checks are about the laws;
thread determinism is contact.threads').

Tolerances (what they mean):
  * deceleration while sliding (least squares on the rows with 0.9 v0 >= v >= max(0.1 v0, 2 v*), v* the
    regularised laws' threshold speed: mu p / ct for s12, mu / ct for s14) within 3 % of mu g for the Coulomb-like
    laws (s1, s11, s12, s14 and the steep ones): the normal forces wobble by about 0.5 % as the cube settles and
    tilts on its pairs (block_sliding's tolerance);
  * the step is the cube's own, not a friction dashpot's: the run's mean step t_end / cycles is at least 0.9 of
    its first step (the listing's cycle 0) (the steep laws' dashpot m_s / (ct A_s), 3e-13 s, would make it 1e-7 of the cube's step);
  * the times at which the speed falls below 0.9, 0.5 and 0.1 v0 within 3 % (plus one time-history row) of the
    ODE's: the same 3 % on the mean deceleration up to there, and for s13 the check of its arctangent shape (its
    deceleration at 0.1 v0 is 0.54 mu g, at 0.9 v0 0.94 mu g: a Coulomb law would miss by 20 %), for the decks
    whose threshold speed is 0.3 v0 that of the viscous branch (a Coulomb law would reach 0.1 v0 ~25 % earlier);
  * the last speed within 1 % of v0 of the ODE's (exact Coulomb: at rest, its sticking spring oscillating at
    ~0.3 % of v0; s13 and the _LOW_CT decks: still creeping at 3 to 4 % of v0, where a Coulomb law is at rest);
  * sliding across a one-directional law's tangent: the speed changes by less than 0.1 % of v0 over the run (a
    friction of 0.1 % of Coulomb's would change it by 0.13 %) and the friction energy stays below 1e-6 of the
    kinetic energy; sliding at an angle to it: the same 0.1 % of v0 on the part across it, v2, and the checks
    above on the part along it, v1, with v1(0) in place of v0;
  * the cube stays in contact: its lower-face node in the time history stays between the plate and the gap
    surface at every row;
  * the frictional contact energy equals the kinetic energy lost within 2 % of the initial kinetic energy, and
    the run's energy error is within 1 % (docs/theory/verification.md C);
  * LAGDT: every pair switched at every cycle (the summary's count of switched pair-cycles).
"""
import math
import os

import numpy as np

import check_contact_common as cc
import check_ctclaw_common as ctc


def friction_traction(law, s, p):
    """|F_t| / A_s (Pa) of a friction law at slip speed s and pressure p (docs/theory/contact-laws.md 3)."""
    kind = law["friction"] % 10
    prm = law["params"]
    mu = prm.get("mu", 0.0)
    ct = prm.get("ctlin", 0.0)
    if kind == 1:
        return mu * p
    if kind == 2:
        return min(ct * s, mu * p)
    if kind == 3:
        return mu * p * (2 / math.pi) * math.atan(ct * s)
    if kind == 4:
        return p * min(ct * s, mu)
    return 0.0


def friction_force(law, v, weight, arms, height, areas):
    """The total friction force F of pairs at arms x_i (m, along the sliding direction from the centre of mass,
    sum x_i = 0) under a rigid body of weight W whose centre of mass is `height` above them, sliding at v: the
    friction's moment F h tilts the body forward, and equal linear springs share it as N_i = W / n + F h x_i /
    sum x_j^2; F = sum traction(v, N_i / A_i) A_i, solved by fixed-point iteration (a contraction: dF/dF is at
    most mu h max|x| / sum x^2 ~ mu / 2 here). Only a law that is not linear in the pressure (s12's min(ct s,
    mu p)) depends on the tilt."""
    n, sx2 = len(arms), sum(x * x for x in arms)
    f = 0.0
    for _ in range(200):
        f_new = sum(friction_traction(law, v, max(0.0, weight / n + f * height * x / sx2) / a) * a
                    for x, a in zip(arms, areas))
        if abs(f_new - f) <= 1e-14 * weight:
            return f_new
        f = f_new
    return f


def threshold_speed(law, p):
    """The slip speed above which a regularised law is Coulomb's mu p (s13: 99 % of it) at pressure p; 0 for
    exact Coulomb."""
    kind, prm = law["friction"] % 10, law["params"]
    mu, ct = prm.get("mu", 0.0), prm.get("ctlin", 0.0)
    return {1: 0.0, 2: mu * p / ct if ct else 0.0, 3: math.tan(0.99 * math.pi / 2) / ct if ct else 0.0,
            4: mu / ct if ct else 0.0}[kind]


def is_steep(law, p, v0):
    """A regularised law so steep that it is exact Coulomb for the check: threshold speed below 1e-6 v0."""
    return law["friction"] % 10 != 1 and threshold_speed(law, p) < 1e-6 * v0


def expected_speed(law, M, g_acc, arms, height, areas, v0, t_end):
    """(times, speeds) of M dv/dt = -F(v) (friction_force) from v0: RK4 with steps of a tenth of the ODE's
    fastest time scale M / (slope at v = 0 * sum A_s), at most 1e-4 s; exact Coulomb or a steep law: v0 - mu g t,
    then 0."""
    kind, prm = law["friction"] % 10, law["params"]
    mu, ct = prm.get("mu", 0.0), prm.get("ctlin", 0.0)
    if kind == 1 or is_steep(law, M * g_acc / sum(areas), v0):
        ts = np.linspace(0.0, t_end, 20001)
        return ts, np.maximum(0.0, v0 - mu * g_acc * ts)
    p_mean = M * g_acc / sum(areas)
    slope = {2: ct, 3: mu * p_mean * (2 / math.pi) * ct, 4: p_mean * ct}[kind]
    h = min(1e-4, 0.1 * M / (slope * sum(areas)))
    # Only s12 depends on the tilt (friction_force); the laws linear in the pressure see the mean pressure.
    tilted = kind == 2

    def acc(v):
        if v <= 0:
            return 0.0
        if not tilted:
            return sum(friction_traction(law, v, p_mean) * a for a in areas) / M
        return friction_force(law, v, M * g_acc, arms, height, areas) / M

    n = int(math.ceil(t_end / h))
    h = t_end / n
    ts, vs = [0.0], [v0]
    v = v0
    for k in range(n):
        k1 = -acc(v)
        k2 = -acc(v + 0.5 * h * k1)
        k3 = -acc(v + 0.5 * h * k2)
        k4 = -acc(v + h * k3)
        v = max(0.0, v + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4))
        ts.append((k + 1) * h)
        vs.append(v)
    return np.array(ts), np.array(vs)


def first_below(t, v, level):
    k = np.nonzero(v < level)[0]
    return (t[k[0]], k[0]) if len(k) else (None, None)


def one_deck(radx, deck, out, checks):
    m = cc.Model(deck)
    (iid, it), = m.interfaces.items()
    law_id, urn = ctc.ctclaws(m.deck)[iid]
    law = ctc.parse_urn(urn)
    assert law["friction"] in (1, 2, 3, 4, 11, 12, 13, 14), "a friction law is needed: %s" % urn
    gap = it["Gapmin"]
    secondary = m.groups[it["grnd"]]
    areas = ctc.tributary_areas(m, secondary)
    body, M, vel = m.moving_body()
    v0 = math.sqrt(sum(c * c for c in vel))
    e = [c / v0 for c in vel]
    (_, _, gz), = m.grav
    g_acc = abs(gz)
    (seg_pid, seg, _), = m.shells.values()
    x1, x2 = m.nodes[seg[0]], m.nodes[seg[1]]
    t1 = [b - a for a, b in zip(x1, x2)]
    t1 = [c / math.sqrt(sum(q * q for q in t1)) for c in t1]
    along = abs(sum(a * b for a, b in zip(e, t1)))
    one_directional = law["friction"] < 10
    frictionless = one_directional and along < 1e-12
    # A one-directional law at an angle to its first tangent brakes the velocity's part along it (eb = +-t1, from
    # vb0); the part across it (along ef, vf0) keeps its value. Otherwise the whole velocity is braked (eb = e).
    oblique = one_directional and 1e-12 <= along <= 1 - 1e-12
    eb, vb0, ref = e, v0, "v0"
    if oblique:
        sign = 1.0 if sum(a * b for a, b in zip(e, t1)) > 0 else -1.0
        eb, vb0, ref = [sign * c for c in t1], v0 * along, "v1(0)"
        ef = [a - sign * along * b for a, b in zip(e, t1)]
        ef = [c / math.sqrt(sum(q * q for q in ef)) for c in ef]
        vf0 = v0 * math.sqrt(1 - along * along)
    weights = [M * g_acc / len(secondary)] * len(secondary)
    # The centre of mass (lumped masses), the pairs' arms along the sliding direction and its height above them.
    com = [sum(m.masses[n] * m.nodes[n][k] for n in body) / M for k in range(3)]
    arms = [sum((m.nodes[n][k] - com[k]) * eb[k] for k in range(3)) for n in secondary]
    height = com[2] - sum(m.nodes[n][2] for n in secondary) / len(secondary)
    a_s = [areas[n] for n in secondary]
    mu = law["params"]["mu"]
    steep = is_steep(law, weights[0] / a_s[0], v0)
    coulomb_like = law["friction"] % 10 in (1, 2, 4) or steep
    t_end = cc.engine_card(deck, "/RUN/" + os.path.basename(deck)[:-len("_0000.rad")] + "/1")[0]
    print("%s: /CTCLAW/%d %s on %s, M = %g, g = %g, v0 = %g along (%g, %g, %g), first tangent (%g, %g, %g), A_s = "
          "%s, pressure %.6g Pa%s" % (os.path.basename(deck), law_id, urn, "LAGDT/TYPE7" if it["lagdt"] else "TYPE7",
                                      M, g_acc, v0, *e, *t1, ", ".join("%g" % a for a in a_s), weights[0] / a_s[0],
                                      ": across the one-directional law, no friction" if frictionless else ""))
    if oblique:
        print("  at %.6g degrees to the first tangent: braked part v1(0) = %.6g m/s along (%g, %g, %g), free part "
              "v2 = %.6g m/s along (%g, %g, %g)" % (math.degrees(math.acos(along)), vb0, *eb, vf0, *ef))

    name = cc.run_radx(radx, deck, out, ("--threads", "1"))
    th = cc.read_th(out, name)
    pid = m.brick_part()
    t, mass = cc.th_column(th, "%d:MASS" % pid)
    v = sum(cc.th_column(th, "%d:%sMOM" % (pid, ax))[1] * c for ax, c in zip("XYZ", eb)) / mass
    s = cc.read_summary(out, name)
    en = s["energy"]
    ke0 = 0.5 * M * v0 * v0
    if frictionless:
        checks.check(np.max(np.abs(v - v0)) <= 1e-3 * v0, "across the first tangent the speed stays v0: largest "
                     "change %.3g m/s (allowed 0.1 %% of v0)" % np.max(np.abs(v - v0)))
        checks.check(abs(en["contact_friction"]) <= 1e-6 * ke0, "no friction energy: %.3g J (allowed 1e-6 of %.4g J)"
                     % (en["contact_friction"], ke0))
    else:
        if oblique:
            vf = sum(cc.th_column(th, "%d:%sMOM" % (pid, ax))[1] * c for ax, c in zip("XYZ", ef)) / mass
            checks.check(np.max(np.abs(vf - vf0)) <= 1e-3 * v0, "across the first tangent the part v2 stays %.6g m/s:"
                         " largest change %.3g m/s (allowed 0.1 %% of v0)" % (vf0, np.max(np.abs(vf - vf0))))
        te, ve = expected_speed(law, M, g_acc, arms, height, a_s, vb0, t_end)
        if coulomb_like:
            # Coulomb above the threshold speed of the regularised laws: mu p / ct (s12), mu / ct (s14).
            v_star = threshold_speed(law, weights[0] / a_s[0])
            sliding = (v <= 0.9 * vb0) & (v >= max(0.1 * vb0, 2 * v_star))
            if checks.check(sliding.sum() >= 10, "%d time-history rows in the sliding phase" % sliding.sum()):
                slope = np.polyfit(t[sliding], v[sliding], 1)[0]
                checks.close(-slope, mu * g_acc, 0.03, "deceleration while sliding (m/s2)")
        for level in (0.9, 0.5, 0.1):
            t_run, k = first_below(t, v, level * vb0)
            t_ode, _ = first_below(te, ve, level * vb0)
            checks.check(t_run is not None and t_ode is not None, "the speed falls below %g %s" % (level, ref))
            if t_run is not None and t_ode is not None:
                row = t[k] - t[k - 1]
                checks.check(abs(t_run - t_ode) <= 0.03 * t_ode + row, "speed below %g %s at %.6g s, expected %.6g s "
                             "(allowed 3 %% + one row of %.3g s)" % (level, ref, t_run, t_ode, row))
        checks.check(abs(v[-1] - ve[-1]) <= 0.01 * vb0, "last speed %.5g m/s, expected %.5g m/s (allowed 1 %% of %s)"
                     % (v[-1], ve[-1], ref))
        checks.check(abs(en["contact_friction"] - (ke0 - en["kinetic"])) <= 0.02 * ke0,
                     "frictional energy %.5g J = kinetic energy lost %.5g J (allowed 2 %% of %.4g J)"
                     % (en["contact_friction"], ke0 - en["kinetic"], ke0))
    dt0 = cc.listing_rows(cc.read_listing(out, name))[0]["dt"]
    checks.check(t_end / s["cycles"] >= 0.9 * dt0, "the step is the cube's own: mean step %.4g s over %d cycles, "
                 "first step %.4g s (the mean at least 0.9 of it)" % (t_end / s["cycles"], s["cycles"], dt0))
    z_plate = m.nodes[seg[0]][2]
    for n in (n for n in secondary if cc.has_column(th, "%d:DZ" % n)):
        d = m.nodes[n][2] + cc.th_column(th, "%d:DZ" % n)[1] - z_plate
        checks.check(np.all(d > 0) and np.all(d < gap), "node %d stays in contact: distance to the plate from %.4g"
                     " to %.4g m (gap %g)" % (n, d.min(), d.max(), gap))
    if it["lagdt"]:
        cc.check_all_pairs_switched(checks, s, len(secondary))
    cc.check_energy_error(checks, s)


if __name__ == "__main__":
    cc.main_per_deck(one_deck)
