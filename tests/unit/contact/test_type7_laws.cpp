// TYPE7 pair laws (contact/type7_laws.hpp) against docs/theory/type7-lagdt.md 4.3 to 4.5: every function
// against its formula written out again here, the energy against a numerical integral of the force, the
// tangent stiffness against a finite difference of the force, the Renard law's continuity, the friction force
// direction and cap, the Iform 2 stick-then-slide history, the filters, and the energy equation of
// docs/theory/verification.md A.2 solved for its table.
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>
#include <vector>

#include "contact/type7_laws.hpp"

namespace c = radx::contact;
using Catch::Detail::Approx;

namespace {

struct Penalty {
  double K, g, p;
};

// Several stiffnesses, gaps (mm and m scales) and penetrations from tiny to close to the pole.
const std::vector<Penalty> kPenaltyPoints = {
    {1.0, 1.0, 0.3},       {105000.0, 0.5, 0.01}, {105000.0, 0.5, 0.25},
    {105000.0, 0.5, 0.49}, {1e5, 1e-3, 1e-7},     {1e5, 1e-3, 6.98e-4},
    {2.5e3, 2.0, 1.9},     {7.0, 0.1, 0.099},     {1e8, 1e-4, 3.33e-5},
};

double simpson(const auto& f, double a, double b, int n) {
  const double h = (b - a) / n;
  double s = f(a) + f(b);
  for (int k = 1; k < n; ++k) s += (k % 2 ? 4 : 2) * f(a + k * h);
  return s * h / 3;
}

double norm(const std::array<double, 3>& v) {
  return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

double dot(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

}  // namespace

TEST_CASE("penalty force, tangent stiffness and energy follow their formulas", "[type7-laws]") {
  for (const auto& [K, g, p] : kPenaltyPoints) {
    INFO("K " << K << " g " << g << " p " << p);
    const double x = p / g;
    CHECK(c::penalty_force(K, g, p) == Approx(K * p * g / (g - p)).epsilon(1e-14));
    CHECK(c::penalty_tangent_stiffness(K, g, p) == Approx(K * g * g / ((g - p) * (g - p))).epsilon(1e-14));
    // -x - ln(1 - x) written as the series x^2/2 + x^3/3 + ... (converges for x < 1; 4000 terms reach
    // round-off for x up to 0.99), so the test does not share the implementation's formula.
    double series = 0, term = x;
    for (int k = 2; k < 4000; ++k) {
      term *= x;
      series += term / k;
    }
    CHECK(c::penalty_energy(K, g, p) == Approx(K * g * g * series).epsilon(1e-12));
  }
}

TEST_CASE("penalty laws are 0 for an open pair and infinite at and past the pole", "[type7-laws]") {
  for (double p : {0.0, -1e-9, -0.5}) {
    CHECK(c::penalty_force(1e5, 1e-3, p) == 0.0);
    CHECK(c::penalty_tangent_stiffness(1e5, 1e-3, p) == 0.0);
    CHECK(c::penalty_energy(1e5, 1e-3, p) == 0.0);
    CHECK(c::damping_coefficient(0.05, 1e5, 1e-3, p, 0.1, -1.0) == 0.0);
  }
  constexpr double inf = std::numeric_limits<double>::infinity();
  for (double p : {1e-3, 1.5e-3}) {
    CHECK(c::penalty_force(1e5, 1e-3, p) == inf);
    CHECK(c::penalty_tangent_stiffness(1e5, 1e-3, p) == inf);
    CHECK(c::penalty_energy(1e5, 1e-3, p) == inf);
    CHECK(c::damping_coefficient(0.05, 1e5, 1e-3, p, 0.1, -1.0) == inf);
  }
  // Just below the pole everything is finite and large.
  const double p = 1e-3 * (1 - 1e-9);
  CHECK(std::isfinite(c::penalty_force(1e5, 1e-3, p)));
  CHECK(c::penalty_force(1e5, 1e-3, p) > 1e10);
  CHECK(std::isfinite(c::penalty_energy(1e5, 1e-3, p)));
}

TEST_CASE("penalty energy is the integral of the force and the stiffness its derivative", "[type7-laws]") {
  for (const auto& point : kPenaltyPoints) {
    const double K = point.K, g = point.g, p = point.p;  // named copies: lambdas below capture them
    if (p / g > 0.95) continue;  // Simpson needs many more points near the pole; covered below at 0.99
    INFO("K " << K << " g " << g << " p " << p);
    const auto force = [&](double s) { return c::penalty_force(K, g, s); };
    CHECK(c::penalty_energy(K, g, p) == Approx(simpson(force, 0.0, p, 20000)).epsilon(1e-9));
    // Central difference with a step of 1e-5 of the remaining gap: truncation ~1e-10, round-off ~1e-11.
    const double h = 1e-5 * std::min(p, g - p);
    const double fd = (force(p + h) - force(p - h)) / (2 * h);
    CHECK(c::penalty_tangent_stiffness(K, g, p) == Approx(fd).epsilon(1e-8));
  }
  const double K = 3.0, g = 2.0, p = 0.99 * g;
  const auto force = [&](double s) { return c::penalty_force(K, g, s); };
  CHECK(c::penalty_energy(K, g, p) == Approx(simpson(force, 0.0, p, 200000)).epsilon(1e-9));
  // Tiny penetration: the energy is K p^2 / 2 to first order and keeps its relative precision.
  const double tiny = 1e-9;
  CHECK(c::penalty_energy(1.0, 1.0, tiny) == Approx(0.5 * tiny * tiny * (1 + 2 * tiny / 3)).epsilon(1e-14));
}

TEST_CASE("energy equation of docs/theory/verification.md A.2 reproduces its table", "[type7-laws]") {
  // m v0^2 / (2 K g^2) = -x - ln(1 - x): with K = g = 1 the left side P equals the stored energy at
  // p = x, so x is found by bisection on penalty_energy (increasing in x). Columns: P, the table's x
  // (5 decimals), x to 15 digits (mpmath findroot at 30 digits, outside this project). The table's
  // 0.13484 is 0.1348348 rounded up: within one unit of its last decimal, not half a unit.
  struct Row {
    double P, x_table, x_exact;
  };
  const std::vector<Row> table = {{0.001, 0.04406, 0.0440571922590481}, {0.01, 0.13484, 0.134834751066835},
                                  {0.1, 0.38318, 0.383183168208295},    {0.5, 0.69829, 0.698290437315664},
                                  {1.0, 0.84141, 0.841405660436961},    {2.0, 0.94753, 0.947530902542285}};
  for (const auto& [P, x_table, x_exact] : table) {
    double lo = 0, hi = 1;
    for (int it = 0; it < 200 && hi - lo > 1e-16; ++it) {
      const double mid = 0.5 * (lo + hi);
      (c::penalty_energy(1.0, 1.0, mid) < P ? lo : hi) = mid;
    }
    INFO("P = " << P << " x = " << lo);
    CHECK(std::abs(lo - x_table) <= 1e-5);
    CHECK(lo == Approx(x_exact).epsilon(1e-13));
    // The same answer in other units: m = 0.1, v0 = 1, g = 1e-3 and K from P.
    const double m = 0.1, v0 = 1.0, g = 1e-3, K = m * v0 * v0 / (2 * P * g * g);
    CHECK(c::penalty_energy(K, g, lo * g) == Approx(0.5 * m * v0 * v0).epsilon(1e-12));
  }
}

TEST_CASE("VISs damping coefficient follows its formula", "[type7-laws]") {
  struct Point {
    double vis_s, K, g, p, m, v_n;
  };
  const std::vector<Point> points = {{0.05, 1e5, 1e-3, 4e-4, 0.1, -1.0}, {0.05, 1e5, 1e-3, 4e-4, 0.1, 1.0},
                                     {0.0, 1e5, 1e-3, 4e-4, 0.1, -1.0},  {1.0, 105000, 0.5, 0.2, 2e-7, -5e3},
                                     {1.0, 105000, 0.5, 0.2, 2e-7, 5e3}, {0.3, 10.0, 2.0, 1.99, 3.0, -0.5},
                                     {0.05, 1e5, 1e-3, 4e-4, 0.1, 0.0}};
  for (const auto& q : points) {
    INFO("VISs " << q.vis_s << " p " << q.p << " v_n " << q.v_n);
    const double k = q.K * q.g / (q.g - q.p);
    const double r = q.v_n < 0 ? (q.g - q.p) / q.g : 1.0;
    const double expected =
        q.vis_s * std::sqrt(2 * k * q.m / r) + 0.32 * q.m * std::max(0.0, -q.v_n) / (q.g - q.p);
    CHECK(c::damping_coefficient(q.vis_s, q.K, q.g, q.p, q.m, q.v_n) == Approx(expected).epsilon(1e-14));
  }
  // Separating, only the VISs term acts: with VISs = 0 there is no damping at all.
  CHECK(c::damping_coefficient(0.0, 1e5, 1e-3, 4e-4, 0.1, 2.0) == 0.0);
  // Approaching costs more damping than separating at the same speed.
  CHECK(c::damping_coefficient(0.05, 1e5, 1e-3, 4e-4, 0.1, -1.0) >
        c::damping_coefficient(0.05, 1e5, 1e-3, 4e-4, 0.1, 1.0));
}

TEST_CASE("friction coefficient of Ifric 0, 1 and 2 follows its formula", "[type7-laws]") {
  const std::array<double, 6> k = {0.01, -0.02, 0.003, 0.0004, 0.005, -0.06};
  for (double P : {0.0, 1.5, 40.0}) {
    for (double V : {0.0, 0.7, 12.0}) {
      INFO("P " << P << " V " << V);
      CHECK(c::friction_coefficient(0, 0.3, k, P, V) == 0.3);
      const double law1 = 0.3 + k[0] * P + k[1] * V + k[2] * P * V + k[3] * P * P + k[4] * V * V;
      CHECK(c::friction_coefficient(1, 0.3, k, P, V) == Approx(law1).epsilon(1e-14));
      const double law2 =
          k[0] * std::exp(k[1] * V) * P * P + k[2] * std::exp(k[3] * V) * P + k[4] * std::exp(k[5] * V);
      CHECK(c::friction_coefficient(2, 0.3, k, P, V) == Approx(law2).epsilon(1e-14));
    }
  }
}

TEST_CASE("Renard friction law: branches, continuity and slopes at C5 and C6", "[type7-laws]") {
  // mu_s 0.2, mu_d 0.15, mu_max 0.35, mu_min 0.1, V_cr1 0.5, V_cr2 2.
  const std::array<double, 6> k = {0.2, 0.15, 0.35, 0.1, 0.5, 2.0};
  const auto mu = [&](double V) { return c::friction_coefficient(3, 0.0, k, 0.0, V); };
  CHECK(mu(0.0) == Approx(0.2).epsilon(1e-15));  // static
  CHECK(mu(0.25) == Approx(0.2 + 0.15 * 0.5 * 1.5).epsilon(1e-14));
  CHECK(mu(1.25) == Approx(0.35 - 0.25 * 0.25 * 2.0).epsilon(1e-14));  // s = 0.5
  CHECK(mu(3.0) == Approx(0.15 - 1 / (1 / 0.05 + 1.0)).epsilon(1e-14));
  CHECK(mu(1e6) == Approx(0.15).epsilon(1e-9));  // dynamic limit
  for (double Vc : {k[4], k[5]}) {
    INFO("V = " << Vc);
    const double h = 1e-9;
    CHECK(mu(Vc - h) == Approx(mu(Vc + h)).margin(1e-12));
    // One-sided slopes on both sides are 0 (the law is C1): differences of order h^2 / h = h.
    CHECK(std::abs(mu(Vc) - mu(Vc - 1e-5)) / 1e-5 < 1e-4);
    CHECK(std::abs(mu(Vc + 1e-5) - mu(Vc)) / 1e-5 < 1e-4);
  }
  CHECK(mu(k[4]) == Approx(0.35).epsilon(1e-15));  // mu_max at V_cr1
  CHECK(mu(k[5]) == Approx(0.1).epsilon(1e-15));   // mu_min at V_cr2
  // mu_d == mu_min: constant mu_d beyond V_cr2 (the limit of the formula, no division by zero).
  const std::array<double, 6> flat = {0.2, 0.1, 0.35, 0.1, 0.5, 2.0};
  CHECK(c::friction_coefficient(3, 0.0, flat, 0.0, 5.0) == Approx(0.1).epsilon(1e-15));
}

TEST_CASE("friction filter factor alpha by Ifiltr, clamped to [0, 1]", "[type7-laws]") {
  const double dt = 1e-6;
  CHECK(c::friction_filter_alpha(0, 0.3, dt) == 1.0);
  CHECK(c::friction_filter_alpha(1, 0.3, dt) == Approx(0.3).epsilon(1e-15));
  CHECK(c::friction_filter_alpha(1, 1.7, dt) == 1.0);
  CHECK(c::friction_filter_alpha(1, -0.2, dt) == 0.0);
  CHECK(c::friction_filter_alpha(2, 0.1, dt) == Approx(2 * std::numbers::pi * 0.1).epsilon(1e-15));
  CHECK(c::friction_filter_alpha(2, 0.5, dt) == 1.0);
  CHECK(c::friction_filter_alpha(3, 1000.0, dt) == Approx(2 * std::numbers::pi * 1e-3).epsilon(1e-14));
  CHECK(c::friction_filter_alpha(3, 1e9, dt) == 1.0);
  CHECK(c::friction_filter_alpha(3, 0.0, dt) == 0.0);
}

TEST_CASE("Iform 1 friction force: opposite to v_t, min(C V, mu |F_n|)", "[type7-laws]") {
  c::FrictionInput in;
  in.iform = 1;
  in.mu = 0.3;
  in.K = 1e5;
  in.mass = 0.1;
  in.vis_f = 1.0;
  const double C = std::sqrt(2 * in.K * in.mass);  // 141.42 N s/m
  for (double fn : {10.0, -10.0}) {                // the sign of F_n does not matter, |F_n| caps
    in.normal_force = fn;
    // Fast: capped at mu |F_n| = 3 N.
    in.v_t = {0.3, -0.4, 0.0};  // V = 0.5, C V = 70.7 N
    auto f = c::tangential_force(in);
    CHECK(norm(f) == Approx(3.0).epsilon(1e-14));
    CHECK(dot(f, in.v_t) == Approx(-norm(f) * 0.5).epsilon(1e-14));  // exactly opposite to v_t
    // Slow: viscous, C V below the cap.
    in.v_t = {0.0, 6e-3, -8e-3};  // V = 0.01, C V = 1.414 N
    f = c::tangential_force(in);
    CHECK(norm(f) == Approx(C * 0.01).epsilon(1e-14));
    CHECK(dot(f, in.v_t) == Approx(-norm(f) * 0.01).epsilon(1e-14));
  }
  in.v_t = {0, 0, 0};
  CHECK(norm(c::tangential_force(in)) == 0.0);
  in.v_t = {1, 0, 0};
  in.vis_f = 0.5;  // VISF scales C
  in.normal_force = 1e6;
  CHECK(c::tangential_force(in)[0] == Approx(-0.5 * C).epsilon(1e-14));
  in.mu = 0;  // frictionless
  CHECK(norm(c::tangential_force(in)) == 0.0);
}

TEST_CASE("Iform 2 friction force: elastic build-up over steps, then sliding at mu |F_n|", "[type7-laws]") {
  c::FrictionInput in;
  in.iform = 2;
  in.mu = 0.2;
  in.normal_force = 50.0;  // cap 10 N
  in.K = 1e4;
  in.dt = 1e-5;
  in.v_t = {0.6, 0.8, 0.0};  // V = 1: each step adds K V dt = 0.1 N against v_t
  const std::array<double, 3> dir = {-0.6, -0.8, 0.0};
  std::array<double, 3> f{};
  for (int step = 1; step <= 150; ++step) {
    in.f_old = f;
    f = c::tangential_force(in);
    const double expected = std::min(10.0, 0.1 * step);
    INFO("step " << step);
    REQUIRE(norm(f) == Approx(expected).epsilon(1e-12));
    REQUIRE(dot(f, dir) == Approx(norm(f)).epsilon(1e-12));
  }
  // Reversing the motion first unloads the elastic force through zero before sliding the other way.
  in.v_t = {-0.6, -0.8, 0.0};
  for (int step = 1; step <= 250; ++step) {
    in.f_old = f;
    f = c::tangential_force(in);
  }
  CHECK(norm(f) == Approx(10.0).epsilon(1e-12));
  CHECK(dot(f, dir) == Approx(-10.0).epsilon(1e-12));
  // Stopped: the force is held (stick), not reset.
  in.v_t = {0, 0, 0};
  in.f_old = f;
  const auto held = c::tangential_force(in);
  CHECK(held[0] == Approx(f[0]).epsilon(1e-15));
  CHECK(held[1] == Approx(f[1]).epsilon(1e-15));
  // A smaller normal force scales a stored force back to the new cap, keeping its direction.
  in.normal_force = -5.0;  // cap 1 N
  const auto scaled = c::tangential_force(in);
  CHECK(norm(scaled) == Approx(1.0).epsilon(1e-14));
  CHECK(dot(scaled, f) == Approx(norm(f)).epsilon(1e-14));
}

TEST_CASE("friction filter blends the new force with the previous one", "[type7-laws]") {
  c::FrictionInput in;
  in.iform = 1;
  in.mu = 0.5;
  in.normal_force = 4.0;  // cap 2 N
  in.K = 1e5;
  in.mass = 0.1;
  in.v_t = {0, 2.0, 0};  // capped: unfiltered force (0, -2, 0)
  in.f_old = {0.4, 1.0, 0.0};
  in.alpha = c::friction_filter_alpha(1, 0.25, 1e-6);
  const auto f = c::tangential_force(in);
  CHECK(f[0] == Approx(0.75 * 0.4).epsilon(1e-14));
  CHECK(f[1] == Approx(0.25 * -2.0 + 0.75 * 1.0).epsilon(1e-14));
  CHECK(f[2] == 0.0);
  // Iform 1 ignores f_old without a filter.
  in.alpha = 1.0;
  const auto g = c::tangential_force(in);
  CHECK(g[0] == 0.0);
  CHECK(g[1] == Approx(-2.0).epsilon(1e-14));
  // Iform 2 with the filter: the trial uses f_old, then the blend.
  in.iform = 2;
  in.dt = 1e-6;
  in.alpha = 0.5;
  in.f_old = {0.0, -0.5, 0.0};  // trial = (0, -0.5 - 1e5 * 2 * 1e-6, 0) = (0, -0.7, 0), under the cap
  const auto h = c::tangential_force(in);
  CHECK(h[1] == Approx(0.5 * -0.7 + 0.5 * -0.5).epsilon(1e-14));
}
