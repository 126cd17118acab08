// The /CTCLAW law family (contact/ctclaw_laws.hpp) against docs/theory/contact-laws.md sections 2 and 3: each
// normal law's pressure and stiffness against its formula written out again here at several overclosures, at
// the KcMax knee and at both ends of a table, the stiffness against a centred finite difference of the
// pressure, the monotone cubic table's properties, and each friction law's force against its formula at
// several slip speeds and pressures, its direction and the one-directional variants.
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "contact/ctclaw_laws.hpp"

namespace c = radx::contact;
using Catch::Detail::Approx;
using radx::model::FrictionLaw;
using radx::model::NormalLaw;

namespace {

using Vec = std::array<double, 3>;

double norm(const Vec& v) {
  return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

double dot(const Vec& a, const Vec& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// dP/du by a centred difference with step h.
double centred_difference(const c::PairLaw& law, double u, double h) {
  return (c::normal_pressure(law, u + h).p - c::normal_pressure(law, u - h).p) / (2 * h);
}

c::PairLaw exponential_law(double pz, double lambda, double kc_max) {
  c::PairLaw law;
  law.normal = NormalLaw::Exponential;
  law.pz = pz;
  law.lambda = lambda;
  law.kc_max = kc_max;
  law.u_knee = c::exponential_knee(pz, lambda, kc_max);
  return law;
}

}  // namespace

TEST_CASE("linear law: P = Kc u for u > 0, its stiffness Kc, nothing when open", "[ctclaw]") {
  c::PairLaw law;
  law.normal = NormalLaw::Linear;
  law.kc = 3.5e12;
  for (const double u : {1e-9, 2e-6, 4e-4, 0.1}) {
    INFO("u " << u);
    CHECK(c::normal_pressure(law, u).p == Approx(3.5e12 * u).epsilon(1e-14));
    CHECK(c::normal_pressure(law, u).kc == 3.5e12);
    CHECK(centred_difference(law, u, u * 1e-4) == Approx(3.5e12).epsilon(1e-8));
  }
  for (const double u : {0.0, -1e-9, -0.3}) {
    CHECK(c::normal_pressure(law, u).p == 0);
    CHECK(c::normal_pressure(law, u).kc == 0);
  }
  CHECK(c::contact_onset(law) == 0);
}

TEST_CASE("Kc = -1 takes the interface's stiffness over the node's area, pe gives lambda = Kc_auto / pe",
          "[ctclaw]") {
  radx::model::Model m;
  radx::model::ContactLaw law;
  law.normal = NormalLaw::Linear;
  law.kc = -1;
  const double K = 2.0e5, area = 4e-4;  // N/m over 4 cm^2
  CHECK(c::resolve_pair_law(law, m, K, area).kc == Approx(K / area).epsilon(1e-15));
  law.normal = NormalLaw::Exponential;
  law.pz = 1e5;
  law.pe = 2e6;
  law.kc_max = 1e13;
  const auto r = c::resolve_pair_law(law, m, K, area);
  CHECK(r.lambda == Approx(K / area / 2e6).epsilon(1e-15));
  // The knee is where lambda pz exp(lambda u) reaches KcMax.
  CHECK(r.lambda * 1e5 * std::exp(r.lambda * r.u_knee) == Approx(1e13).epsilon(1e-12));
  law.lambda = 7e3;  // lambda given: pe is not used
  CHECK(c::resolve_pair_law(law, m, K, area).lambda == 7e3);
  // Without kappa the sticking stiffness is the interface's, K / A_s.
  law.friction = FrictionLaw::Coulomb;
  CHECK(c::resolve_pair_law(law, m, K, area).kappa == Approx(K / area).epsilon(1e-15));
  law.kappa = 9e9;
  CHECK(c::resolve_pair_law(law, m, K, area).kappa == 9e9);
}

TEST_CASE("exponential law: pz exp(lambda u) on both sides of the gap, linear past the KcMax knee",
          "[ctclaw]") {
  const double pz = 1e5, lambda = 2e3, kc_max = 1e12;
  const auto law = exponential_law(pz, lambda, kc_max);
  // The knee written out: lambda pz exp(lambda u) = KcMax.
  const double u_knee = std::log(kc_max / (lambda * pz)) / lambda;
  REQUIRE(law.u_knee == Approx(u_knee).epsilon(1e-14));
  for (const double u : {-0.01, -1e-3, 0.0, 1e-4, 2e-3, 0.5 * u_knee, 0.999 * u_knee}) {
    INFO("u " << u);
    const auto pr = c::normal_pressure(law, u);
    CHECK(pr.p == Approx(pz * std::exp(lambda * u)).epsilon(1e-13));
    CHECK(pr.kc == Approx(lambda * pz * std::exp(lambda * u)).epsilon(1e-13));
    CHECK(centred_difference(law, u, 1e-7) == Approx(pr.kc).epsilon(1e-6));
  }
  // At the knee: the pressure is continuous (KcMax / lambda from both sides), the stiffness reaches KcMax.
  const double p_knee = kc_max / lambda;
  CHECK(c::normal_pressure(law, u_knee * (1 - 1e-12)).p == Approx(p_knee).epsilon(1e-9));
  CHECK(c::normal_pressure(law, u_knee * (1 + 1e-12)).p == Approx(p_knee).epsilon(1e-9));
  CHECK(c::normal_pressure(law, u_knee * (1 - 1e-12)).kc == Approx(kc_max).epsilon(1e-9));
  for (const double du : {1e-6, 1e-3, 0.2}) {
    INFO("past the knee by " << du);
    const auto pr = c::normal_pressure(law, u_knee + du);
    CHECK(pr.p == Approx(p_knee + kc_max * du).epsilon(1e-12));
    CHECK(pr.kc == kc_max);
    CHECK(centred_difference(law, u_knee + du, 1e-8) == Approx(kc_max).epsilon(1e-5));
  }
  // The cut-off: P below 1e-12 pz is no contact, at u = ln(1e-12) / lambda.
  const double u_cut = std::log(1e-12) / lambda;
  CHECK(c::contact_onset(law) == Approx(u_cut).epsilon(1e-14));
  CHECK(c::normal_pressure(law, u_cut * 1.001).p == 0);
  CHECK(c::normal_pressure(law, u_cut * 0.999).p > 0);
  // Without KcMax the law never bends.
  const auto free_law = exponential_law(pz, lambda, 0);
  CHECK(c::normal_pressure(free_law, 0.01).p == Approx(pz * std::exp(20.0)).epsilon(1e-13));
}

TEST_CASE("tabulated law, linear: the bracketing segment, its slope, both ends extrapolated", "[ctclaw]") {
  // Gap (m) to pressure (Pa): stiffening as the gap closes, zero pressure beyond 1 mm of gap.
  const std::vector<double> g = {-2e-3, -1e-3, 0.0, 1e-3};
  const std::vector<double> P = {9e6, 3e6, 5e5, 0.0};
  c::PairLaw law;
  law.normal = NormalLaw::Tabulated;
  law.gap = g;
  law.pressure = P;
  struct Point {
    double u, p, kc;
  };
  // u = -gap; slopes written out per segment.
  const double k01 = (9e6 - 3e6) / 1e-3, k12 = (3e6 - 5e5) / 1e-3, k23 = 5e5 / 1e-3;
  const std::vector<Point> expected = {
      {1.5e-3, 3e6 + 0.5e-3 * k01, k01},  // inside the first segment
      {5e-4, 5e5 + 0.5e-3 * k12, k12},    // inside the middle one
      {0.0, 5e5, k12},                    // on a point: the segment on the larger gap's side... or the other
      {-2.5e-4, 5e5 - 2.5e-4 * k23, k23},
      {3e-3, 9e6 + 1e-3 * k01, k01},  // beyond the closed end: along the first segment
      {2e-3, 9e6, k01},               // the first point itself
      {-1e-3, 0.0, 0.0},              // the last point: zero pressure is no contact
      {-1.5e-3, 0.0, 0.0},            // beyond the open end: extrapolation clamped at no tension
  };
  for (const auto& e : expected) {
    INFO("u " << e.u);
    const auto pr = c::normal_pressure(law, e.u);
    CHECK(pr.p == Approx(e.p).epsilon(1e-12).margin(1e-6));
    if (e.u != 0.0) CHECK(pr.kc == Approx(e.kc).epsilon(1e-12));
  }
  // On a table point the stiffness is one of its two segments' slopes.
  const double k0 = c::normal_pressure(law, 0.0).kc;
  CHECK((k0 == Approx(k12) || k0 == Approx(k23)));
  // Stiffness against a centred difference inside each segment.
  for (const double u : {1.7e-3, 1.2e-3, 6e-4, 2e-4, -3e-4, -8e-4, 2.5e-3}) {
    INFO("u " << u);
    CHECK(centred_difference(law, u, 1e-8) == Approx(c::normal_pressure(law, u).kc).epsilon(1e-6));
  }
  CHECK(c::contact_onset(law) == Approx(-1e-3).epsilon(1e-14));
  // A table whose last pressure is positive: the last segment's extrapolation reaches 0 at the onset.
  const std::vector<double> P2 = {9e6, 3e6, 5e5, 2e5};
  law.pressure = P2;
  const double slope = (2e5 - 5e5) / 1e-3;
  CHECK(c::contact_onset(law) == Approx(-(1e-3 - 2e5 / slope)).epsilon(1e-12));
  CHECK(c::normal_pressure(law, -1.5e-3).p == Approx(2e5 + slope * 0.5e-3).epsilon(1e-12));
}

TEST_CASE("tabulated law, cubic: through the points, monotone, C1 into the linear ends", "[ctclaw]") {
  const std::vector<double> g = {-3e-3, -1e-3, -5e-4, 0.0, 2e-3};
  const std::vector<double> P = {4e7, 6e6, 5.5e6, 1e6, 0.0};  // a near-flat stretch tempts overshoot
  c::PairLaw law;
  law.normal = NormalLaw::Tabulated;
  law.gap = g;
  law.pressure = P;
  law.cubic = true;
  for (std::size_t k = 0; k + 1 < g.size(); ++k) {
    INFO("point " << k);
    CHECK(c::normal_pressure(law, -g[k]).p == Approx(P[k]).epsilon(1e-12));
  }
  // Monotone: the pressure never rises as the gap opens, so the stiffness is never negative.
  double previous = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= 5000; ++i) {
    const double gap = -3.5e-3 + i * (6e-3 / 5000);
    const auto pr = c::normal_pressure(law, -gap);
    INFO("gap " << gap);
    CHECK(pr.p <= previous * (1 + 1e-14));
    CHECK(pr.kc >= 0);
    previous = pr.p;
  }
  // The stiffness is the derivative of the cubic, and is continuous where the cubic meets the extrapolation.
  for (const double u : {2.5e-3, 1.7e-3, 7e-4, 3e-4, -1e-3, -1.9e-3}) {
    INFO("u " << u);
    CHECK(centred_difference(law, u, 1e-9) == Approx(c::normal_pressure(law, u).kc).epsilon(1e-5));
  }
  const double k_in = c::normal_pressure(law, 3e-3 * (1 - 1e-9)).kc;
  const double k_out = c::normal_pressure(law, 3e-3 * (1 + 1e-9)).kc;
  CHECK(k_in == Approx(k_out).epsilon(1e-6));
  // A straight table stays straight.
  const std::vector<double> Pl = {7e6, 5e6, 4.5e6, 4e6, 2e6};
  law.pressure = Pl;
  for (const double u : {2e-3, 7e-4, 2e-4, -1e-3})
    CHECK(c::normal_pressure(law, u).p == Approx(4e6 - 1e9 * (-u)).epsilon(1e-12));
}

TEST_CASE("a two-point table equal to the linear law gives the linear law", "[ctclaw]") {
  const double kc = 2e11;
  const std::vector<double> g = {-1e-3, 0.0};
  const std::vector<double> P = {kc * 1e-3, 0.0};
  c::PairLaw table, linear;
  table.normal = NormalLaw::Tabulated;
  table.gap = g;
  table.pressure = P;
  linear.normal = NormalLaw::Linear;
  linear.kc = kc;
  for (const bool cubic : {false, true}) {
    table.cubic = cubic;
    for (const double u : {-1e-4, 0.0, 1e-7, 3e-4, 1e-3, 5e-3}) {
      INFO("cubic " << cubic << " u " << u);
      // Round-off of the Hermite basis on the table's pressure scale kc 1e-3.
      CHECK(c::normal_pressure(table, u).p ==
            Approx(c::normal_pressure(linear, u).p).epsilon(1e-12).margin(1e-12 * kc * 1e-3));
      if (u > 0) CHECK(c::normal_pressure(table, u).kc == Approx(kc).epsilon(1e-12));
    }
  }
}

TEST_CASE("power law: the sum of kp_m u^m and its derivative", "[ctclaw]") {
  const std::vector<double> m = {1.0, 2.0, 3.5};
  const std::vector<double> k = {1e9, 1e15, 4e18};
  c::PairLaw law;
  law.normal = NormalLaw::Power;
  law.power_m = m;
  law.power_k = k;
  for (const double u : {1e-6, 1e-4, 2e-3}) {
    INFO("u " << u);
    const double p = 1e9 * u + 1e15 * u * u + 4e18 * std::pow(u, 3.5);
    const double kc = 1e9 + 2e15 * u + 3.5 * 4e18 * std::pow(u, 2.5);
    CHECK(c::normal_pressure(law, u).p == Approx(p).epsilon(1e-13));
    CHECK(c::normal_pressure(law, u).kc == Approx(kc).epsilon(1e-13));
    CHECK(centred_difference(law, u, u * 1e-5) == Approx(kc).epsilon(1e-7));
  }
  CHECK(c::normal_pressure(law, 0.0).p == 0);
  CHECK(c::normal_pressure(law, -1e-3).p == 0);
}

TEST_CASE("friction laws: the force of each law against its formula, opposite to the slip", "[ctclaw]") {
  const double mu = 0.3, ct = 40.0, area = 2e-4;
  const Vec n = {0, 0, 1}, t1 = {1, 0, 0};
  for (const auto kind : {FrictionLaw::Linear, FrictionLaw::Arctangent, FrictionLaw::ScaledLinear}) {
    c::PairLaw law;
    law.friction = kind;
    law.bidirectional = true;
    law.mu = mu;
    law.ct = ct;
    for (const double p : {1e3, 2e5, 7e6}) {
      for (const double s : {1e-6, 1e-3, 0.02, 0.5, 30.0}) {
        // Slip along a slanted direction of the tangent plane.
        const Vec w = {0.6 * s, -0.8 * s, 0};
        double expected = 0;
        switch (kind) {
          case FrictionLaw::Linear: expected = std::min(ct * s, mu * p); break;
          case FrictionLaw::Arctangent: expected = mu * p * 2 / std::numbers::pi * std::atan(ct * s); break;
          default: expected = p * std::min(ct * s, mu); break;
        }
        INFO("law " << static_cast<int>(kind) << " p " << p << " s " << s);
        const auto f = c::law_friction_force(law, c::LawFrictionInput{w, n, t1, {}, p, area, 1e-6});
        CHECK(norm(f) == Approx(expected * area).epsilon(1e-13));
        CHECK(dot(f, w) == Approx(-norm(f) * s).epsilon(1e-12));  // opposite to the slip
        CHECK(f[2] == 0);
      }
    }
  }
  // The linear law's threshold depends on the pressure, the scaled one's does not.
  c::PairLaw lin;
  lin.friction = FrictionLaw::Linear;
  lin.mu = mu;
  lin.ct = ct;
  c::PairLaw scaled = lin;
  scaled.friction = FrictionLaw::ScaledLinear;
  for (const double p : {1e3, 1e6}) {
    CHECK(c::friction_traction(lin, 0.999 * mu * p / ct, p) < mu * p);
    CHECK(c::friction_traction(lin, 1.001 * mu * p / ct, p) == Approx(mu * p).epsilon(1e-15));
    CHECK(c::friction_traction(scaled, 0.999 * mu / ct, p) < mu * p);
    CHECK(c::friction_traction(scaled, 1.001 * mu / ct, p) == Approx(mu * p).epsilon(1e-15));
  }
}

TEST_CASE("regularised laws: the force never exceeds what stops the slip within the step", "[ctclaw]") {
  // A pair of the sliding-block verification deck: pressure p on A_s, secondary mass m_s on a fixed segment
  // (mobility 1 / m_s), the cube's step dt; a steep linear law (CtLin 1e15 Pa s/m = 1e6 MPa s/mm), whose
  // dashpot C = ct A_s would need dt <= m_s / C = 3e-13 s if explicit.
  const double mu = 0.3, p = 8829.0, area = 0.0025, m_s = 0.75, dt = 1e-5;
  const double coulomb = mu * p * area;  // 6.6 N
  const Vec n = {0, 0, 1}, t1 = {1, 0, 0};
  for (const auto kind : {FrictionLaw::Linear, FrictionLaw::Arctangent, FrictionLaw::ScaledLinear}) {
    c::PairLaw law;
    law.friction = kind;
    law.bidirectional = true;
    law.mu = mu;
    law.ct = 1e15;
    INFO("law " << static_cast<int>(kind));
    // Sliding: m_s s / dt (37500 N) is far above the traction: the law's own force, mu p A_s.
    auto f = c::law_friction_force(law, c::LawFrictionInput{{0.5, 0, 0}, n, t1, {}, p, area, dt, 1 / m_s});
    CHECK(norm(f) == Approx(coulomb).epsilon(1e-12));
    // Almost at rest: the force is what stops the slip in one step, m_s s / dt, not mu p A_s.
    const double s = 1e-6;
    f = c::law_friction_force(law, c::LawFrictionInput{{s, 0, 0}, n, t1, {}, p, area, dt, 1 / m_s});
    CHECK(norm(f) == Approx(m_s * s / dt).epsilon(1e-14));
    CHECK(s + dt * f[0] / m_s == Approx(0).margin(1e-15 * s));
    // A block of mass m_s integrated with central differences from 0.5 m/s: it decelerates at mu p A_s / m_s
    // (mu g) and comes to rest at 0.5 m_s / (mu p A_s) without the speed changing sign (the explicit
    // dashpot, C dt / m_s = 3e7, would flip it every step).
    double v = 0.5, t = 0;
    bool reversed = false;
    double t_rest = -1;
    for (int k = 0; k < 100000 && t_rest < 0; ++k) {
      f = c::law_friction_force(law, c::LawFrictionInput{{v, 0, 0}, n, t1, {}, p, area, dt, 1 / m_s});
      v += dt * f[0] / m_s;
      t += dt;
      reversed = reversed || v < 0;
      if (v <= 1e-12) t_rest = t;
    }
    CHECK_FALSE(reversed);
    // The stop time of exact Coulomb, within one step (and, for the arctangent, the time it takes to lose
    // the last m_s v* of momentum, v* = 1 / ct of no consequence here).
    CHECK(t_rest == Approx(0.5 * m_s / coulomb).margin(1.001 * dt));
    // Without the bound the same step overshoots: the slip reverses in the first step once slow.
    v = 1e-6;
    f = c::law_friction_force(law, c::LawFrictionInput{{v, 0, 0}, n, t1, {}, p, area, dt, 0.0});
    CHECK(v + dt * f[0] / m_s < -0.5 * v);
  }
  // A law the step resolves (C dt / m_s = 1e-6 here) keeps its force to the bit.
  c::PairLaw soft;
  soft.friction = FrictionLaw::Linear;
  soft.bidirectional = true;
  soft.mu = mu;
  soft.ct = 40.0;
  for (const double s : {1e-9, 1e-3, 0.5}) {
    const auto bounded =
        c::law_friction_force(soft, c::LawFrictionInput{{s, 0, 0}, n, t1, {}, p, area, dt, 1 / m_s});
    const auto free =
        c::law_friction_force(soft, c::LawFrictionInput{{s, 0, 0}, n, t1, {}, p, area, dt, 0.0});
    CHECK(bounded[0] == free[0]);
  }
}

TEST_CASE("exact Coulomb: a sticking spring kappa A_s capped at mu p A_s", "[ctclaw]") {
  c::PairLaw law;
  law.friction = FrictionLaw::Coulomb;
  law.bidirectional = true;
  law.mu = 0.2;
  law.kappa = 5e12;  // Pa/m
  const double p = 1e6, area = 1e-4, dt = 1e-7;
  const double cap = 0.2 * p * area;  // 20 N
  const Vec n = {0, 0, 1}, t1 = {1, 0, 0};
  // A small slip: the spring's increment -kappa A w dt, on top of the previous force.
  const Vec w_small = {1e-4, 2e-4, 0};
  const Vec f_old = {-1.0, 0.5, 0};
  auto f = c::law_friction_force(law, c::LawFrictionInput{w_small, n, t1, f_old, p, area, dt});
  for (std::size_t d = 0; d < 3; ++d)
    CHECK(f[d] == Approx(f_old[d] - 5e12 * area * w_small[d] * dt).margin(1e-12));
  REQUIRE(norm(f) < cap);
  // A fast slip: the trial force exceeds mu p A_s and is scaled back along itself.
  const Vec w_fast = {3.0, -4.0, 0};
  f = c::law_friction_force(law, c::LawFrictionInput{w_fast, n, t1, {}, p, area, dt});
  CHECK(norm(f) == Approx(cap).epsilon(1e-14));
  CHECK(dot(f, w_fast) == Approx(-cap * 5.0).epsilon(1e-12));
  // No pressure, no friction.
  f = c::law_friction_force(law, c::LawFrictionInput{w_fast, n, t1, f_old, 0.0, area, dt});
  CHECK(norm(f) == 0);
}

TEST_CASE("one-directional laws ignore the slip along the second tangent", "[ctclaw]") {
  const Vec n = {0, 0, 1}, t1 = {0, 1, 0};
  for (const auto kind :
       {FrictionLaw::Coulomb, FrictionLaw::Linear, FrictionLaw::Arctangent, FrictionLaw::ScaledLinear}) {
    c::PairLaw law;
    law.friction = kind;
    law.mu = 0.4;
    law.ct = 10.0;
    law.kappa = 1e11;
    const double p = 5e5, area = 1e-4, dt = 1e-6;
    INFO("law " << static_cast<int>(kind));
    // Slip along the second tangent only: nothing.
    auto f = c::law_friction_force(law, c::LawFrictionInput{{2.0, 0, 0}, n, t1, {}, p, area, dt});
    CHECK(norm(f) == 0);
    // Mixed slip: the force is along t1 and equals the two-directional law's for the t1 slip alone.
    f = c::law_friction_force(law, c::LawFrictionInput{{2.0, -0.05, 0}, n, t1, {}, p, area, dt});
    c::PairLaw both = law;
    both.bidirectional = true;
    const auto f1 = c::law_friction_force(both, c::LawFrictionInput{{0, -0.05, 0}, n, t1, {}, p, area, dt});
    CHECK(f[0] == 0);
    CHECK(f[1] == Approx(f1[1]).epsilon(1e-14));
    CHECK(f[1] > 0);  // opposite to the t1 slip
  }
}
