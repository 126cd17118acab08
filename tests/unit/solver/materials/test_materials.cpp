// LAW1 (elastic) and LAW2 (Johnson-Cook) at a single integration point (solver/materials/material_point.hpp),
// against values computed here from the formulas of docs/theory/elements.md 1.4, 1.8, 3.3 and 6.
// Units are consistent but arbitrary (steel-like: MPa, mm, s). Each check says what its tolerance means;
// "round-off" tolerances are a few hundred ulps of the largest quantity in the formula.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "solver/materials/material_point.hpp"
#include "test_util.hpp"

using radx::model::Material;
using radx::model::MaterialLaw;
using radx::solver::jc_flow_stress;
using radx::solver::jc_rate_factor;
using radx::solver::make_material_params;
using radx::solver::MaterialParams;
using radx::solver::shell_point_update;
using radx::solver::solid_point_update;

namespace {

constexpr double kRound = 1e-12;  // relative round-off tolerance for closed-form results

Material steel(MaterialLaw law) {
  Material m;
  m.law = law;
  m.rho = 7.85e-9;
  m.young = 210000.0;
  m.poisson = 0.3;
  m.a = 200.0;
  m.b = 500.0;
  m.n = 0.4;
  m.c = 0.02;
  m.eps_dot_0 = 0.01;
  return m;
}

using radx::test::close;

// Flow stress written out from 6.2 (T = 1, no cap).
double jc_expected(const MaterialParams& p, double eps_p, double rate) {
  const double r = rate > p.jc.eps_dot0 ? 1.0 + p.jc.c * std::log(rate / p.jc.eps_dot0) : 1.0;
  return (p.jc.a + p.jc.b * std::pow(eps_p, p.jc.n)) * r;
}

double vm_plane(const double* s) {
  return std::sqrt(s[0] * s[0] + s[1] * s[1] - s[0] * s[1] + 3.0 * s[2] * s[2]);
}

double vm_solid(const double* s) {
  const double m = (s[0] + s[1] + s[2]) / 3.0;
  const double d0 = s[0] - m, d1 = s[1] - m, d2 = s[2] - m;
  return std::sqrt(1.5 * (d0 * d0 + d1 * d1 + d2 * d2) + 3.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
}

// Plane-stress elastic trial of 1.4.
std::array<double, 5> shell_trial(const MaterialParams& p, const double sig[5], const double de[5],
                                  double gs) {
  return {sig[0] + p.a11 * de[0] + p.a12 * de[1], sig[1] + p.a12 * de[0] + p.a11 * de[1],
          sig[2] + p.shear * de[2], sig[3] + gs * de[3], sig[4] + gs * de[4]};
}

// Iplas = 1 projection of 6.3, written out again. One evaluation at dp gives r, P, Q and the next iterate
// phi(dp) = max(0, dp - f/df).
struct Projection {
  double dp = 0, r = 0, pp = 1, qq = 1, next = 0;
};
Projection evaluate(const MaterialParams& p, const double t[3], double eps_p, double rate, double dp) {
  const double s1 = t[0] + t[1], s2 = t[0] - t[1];
  const double a = 0.25 * s1 * s1, b = 0.75 * s2 * s2 + 3.0 * t[2] * t[2];
  const double rr = rate > p.jc.eps_dot0 ? 1.0 + p.jc.c * std::log(rate / p.jc.eps_dot0) : 1.0;
  const double h =
      p.jc.n * p.jc.b * rr * std::pow(eps_p + 1e-7, p.jc.n - 1.0);  // H at the old eps_p (m2cplr.F)
  Projection out;
  out.dp = dp;
  const double yi = jc_flow_stress(p, eps_p + dp, rate);
  out.r = 0.5 * p.young * dp / yi;
  out.pp = 1.0 / (1.0 + out.r / (1.0 - p.nu));
  out.qq = 1.0 / (1.0 + 3.0 * out.r / (1.0 + p.nu));
  const double f = a * out.pp * out.pp + b * out.qq * out.qq - yi * yi;
  const double df = -(a * std::pow(out.pp, 3) / (1.0 - p.nu) + 3.0 * b * std::pow(out.qq, 3) / (1.0 + p.nu)) *
                        (p.young - 2.0 * out.r * h) / yi -
                    2.0 * h * yi;
  out.next = std::max(0.0, dp - f / df);
  return out;
}
double newton_start(const MaterialParams& p, const double t[3], double eps_p, double rate) {
  const double rr = rate > p.jc.eps_dot0 ? 1.0 + p.jc.c * std::log(rate / p.jc.eps_dot0) : 1.0;
  const double h = p.jc.n * p.jc.b * rr * std::pow(eps_p + 1e-7, p.jc.n - 1.0);
  return (vm_plane(t) - jc_flow_stress(p, eps_p, rate)) / (3.0 * p.shear + h);
}
// `evals` evaluations from the start of 6.3; the last one is the one used.
Projection project(const MaterialParams& p, const double t[3], double eps_p, double rate, int evals) {
  Projection out;
  out.next = newton_start(p, t, eps_p, rate);
  for (int k = 0; k < evals; ++k) out = evaluate(p, t, eps_p, rate, out.next);
  return out;
}

// Yield residual g(dp) = svm(P(dp), Q(dp) applied to the trial) - sigma_y(eps_p + dp): its root is the exact
// plane-stress projection.
double projection_residual(const MaterialParams& p, const double t[3], double eps_p, double rate, double dp) {
  const double yi = jc_flow_stress(p, eps_p + dp, rate);
  const double r = 0.5 * p.young * dp / yi;
  const double pp = 1.0 / (1.0 + r / (1.0 - p.nu)), qq = 1.0 / (1.0 + 3.0 * r / (1.0 + p.nu));
  const double s1 = pp * (t[0] + t[1]), s2 = qq * (t[0] - t[1]);
  const double s[3] = {0.5 * (s1 + s2), 0.5 * (s1 - s2), qq * t[2]};
  return vm_plane(s) - yi;
}

using Mat3 = std::array<std::array<double, 3>, 3>;

Mat3 rotation(double ax, double ay, double az, double angle) {
  const double n = std::sqrt(ax * ax + ay * ay + az * az);
  ax /= n, ay /= n, az /= n;
  const double c = std::cos(angle), s = std::sin(angle), t = 1.0 - c;
  return {{{t * ax * ax + c, t * ax * ay - s * az, t * ax * az + s * ay},
           {t * ax * ay + s * az, t * ay * ay + c, t * ay * az - s * ax},
           {t * ax * az - s * ay, t * ay * az + s * ax, t * az * az + c}}};
}

// Voigt {xx yy zz xy yz zx} <-> tensor; `shear_factor` 0.5 for engineering strains, 1 for stresses.
Mat3 to_tensor(const double* v, double shear_factor) {
  const double xy = shear_factor * v[3], yz = shear_factor * v[4], zx = shear_factor * v[5];
  return {{{v[0], xy, zx}, {xy, v[1], yz}, {zx, yz, v[2]}}};
}
void from_tensor(const Mat3& t, double shear_factor, double* v) {
  v[0] = t[0][0], v[1] = t[1][1], v[2] = t[2][2];
  v[3] = t[0][1] / shear_factor, v[4] = t[1][2] / shear_factor, v[5] = t[2][0] / shear_factor;
}
Mat3 rotate(const Mat3& q, const Mat3& a) {  // q a q^T
  Mat3 out{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) out[i][j] += q[i][k] * a[k][l] * q[j][l];
  return out;
}

}  // namespace

TEST_CASE("material params: moduli, plane-stress coefficients, sound speeds and LAW2 defaults",
          "[material]") {
  Material m = steel(MaterialLaw::JohnsonCook);
  m.n = 0;
  m.c = 0;
  m.eps_dot_0 = 0;
  const MaterialParams p = make_material_params(m);
  const double e = m.young, nu = m.poisson;
  // Closed forms of 6.1 / 3.3 / 4.1; round-off only.
  CHECK(close(p.shear, e / (2 * (1 + nu)), kRound));
  CHECK(close(p.bulk, e / (3 * (1 - 2 * nu)), kRound));
  CHECK(close(p.a11, e / (1 - nu * nu), kRound));
  CHECK(close(p.a12, nu * e / (1 - nu * nu), kRound));
  CHECK(close(p.c_shell, std::sqrt(e / m.rho), kRound));
  CHECK(close(p.c_solid, std::sqrt((p.bulk + 4 * p.shear / 3) / m.rho), kRound));
  CHECK(p.rho0 == m.rho);
  // Reader defaults: n 0 -> 1, c = 0 -> rate0 = 1, ICC 0 -> 1, VP 0 -> 2, caps 0 -> 1e20.
  CHECK(p.jc.n == 1.0);
  CHECK(p.jc.eps_dot0 == 1.0);
  CHECK(p.jc.icc == 1);
  CHECK(p.jc.flag_vp == 2);
  CHECK(p.jc.sig_max0 == 1e20);
  CHECK(p.jc.eps_p_max == 1e20);
}

TEST_CASE("shell point, uniaxial stress path: sxx = E exx, syy = 0, dezz = -nu dexx", "[material]") {
  // deyy = -nu dexx makes syy = A12 dexx + A11 deyy = 0 exactly (in exact arithmetic): uniaxial stress,
  // so sxx = E exx and the thickness strain is -nu exx. Tolerance: round-off (1e-12 of sxx).
  for (const MaterialLaw law : {MaterialLaw::Elastic, MaterialLaw::JohnsonCook}) {
    const MaterialParams p = make_material_params(steel(law));
    const double gs = 5.0 / 6.0 * p.shear;
    const double dx = 1e-5;  // 10 steps: sxx = 21 < a = 200, elastic for LAW2 too
    const double de[5] = {dx, -p.nu * dx, 0.0, 2e-5, -1e-5};
    double sig[5] = {0, 0, 0, 0, 0};
    double eps_p = 0;
    for (int k = 0; k < 10; ++k) {
      const auto res = shell_point_update(p, 0, 1e3, 1.0, de, gs, sig, eps_p);
      CHECK(close(res.dezz, -p.nu * dx, kRound));
      CHECK(res.deps_p == 0.0);
    }
    CHECK(close(sig[0], p.young * 10 * dx, kRound));
    CHECK(std::abs(sig[1]) <= kRound * sig[0]);
    CHECK(sig[2] == 0.0);
    CHECK(close(sig[3], gs * 10 * 2e-5, kRound));  // transverse shear: GS gamma
    CHECK(close(sig[4], gs * 10 * -1e-5, kRound));
    CHECK(eps_p == 0.0);
  }
  SECTION("LAW1 never yields: a stress of 100 times the LAW2 yield stays elastic") {
    const MaterialParams p = make_material_params(steel(MaterialLaw::Elastic));
    const double dx = 1e-2;
    const double de[5] = {dx, -p.nu * dx, 0.0, 0.0, 0.0};
    double sig[5] = {0, 0, 0, 0, 0};
    double eps_p = 0;
    for (int k = 0; k < 10; ++k) shell_point_update(p, 0, 0.0, 1.0, de, 0.0, sig, eps_p);
    CHECK(close(sig[0], p.young * 10 * dx, kRound));
    CHECK(eps_p == 0.0);
  }
}

TEST_CASE("Johnson-Cook flow stress: (a + b eps^n)(1 + c ln(rate/rate0)), rates below rate0, caps",
          "[material]") {
  const MaterialParams p = make_material_params(steel(MaterialLaw::JohnsonCook));
  // Same formula evaluated twice: round-off (1e-13) for the stress; the slope n b R eps^(n-1) is computed as
  // n b R eps^n / eps in the code, still round-off (1e-12).
  for (const double eps : {0.0, 1e-4, 0.01, 0.1, 0.5, 2.0}) {
    for (const double rate : {0.0, 0.005, 0.01, 1.0, 100.0, 1e4}) {
      double slope = -1;
      const double sy = jc_flow_stress(p, eps, rate, &slope);
      CHECK(close(sy, jc_expected(p, eps, rate), 1e-13));
      const double r = rate > p.jc.eps_dot0 ? 1.0 + p.jc.c * std::log(rate / p.jc.eps_dot0) : 1.0;
      if (rate <= p.jc.eps_dot0) CHECK(sy == jc_flow_stress(p, eps, 0.0));  // R = 1 exactly below rate0
      // eps = 0 with n < 1: the slope is infinite; the kernels use 0 there (m2law.F).
      const double h = eps > 0 ? p.jc.n * p.jc.b * r * std::pow(eps, p.jc.n - 1) : 0.0;
      CHECK(close(slope, h, kRound));
    }
  }
  SECTION("n = 1: the slope is b R also at eps = 0") {
    Material m = steel(MaterialLaw::JohnsonCook);
    m.n = 1.0;
    const MaterialParams q = make_material_params(m);
    double slope = 0;
    CHECK(close(jc_flow_stress(q, 0.0, 10.0, &slope), q.jc.a * (1 + q.jc.c * std::log(10.0 / q.jc.eps_dot0)),
                1e-13));
    CHECK(close(slope, q.jc.b * (1 + q.jc.c * std::log(10.0 / q.jc.eps_dot0)), 1e-13));
  }
  SECTION("cap SIG_max0: times R with ICC = 1, bare with ICC = 2, slope 0 when capped") {
    Material m = steel(MaterialLaw::JohnsonCook);
    m.sig_max0 = 450.0;
    const double rate = 100.0;
    const double r = 1.0 + m.c * std::log(rate / m.eps_dot_0);
    m.icc = 1;
    const MaterialParams p1 = make_material_params(m);
    m.icc = 2;
    const MaterialParams p2 = make_material_params(m);
    double s1 = -1, s2 = -1;
    // eps = 0.5: a + b eps^n = 579 > 450: capped either way.
    CHECK(close(jc_flow_stress(p1, 0.5, rate, &s1), 450.0 * r, 1e-13));
    CHECK(close(jc_flow_stress(p2, 0.5, rate, &s2), 450.0, 1e-13));
    CHECK(s1 == 0.0);
    CHECK(s2 == 0.0);
    // eps = 0.1: (a + b eps^n) R = 472.5 lies between 450 and 450 R = 532.8: capped with ICC 2 only.
    REQUIRE(jc_expected(p1, 0.1, rate) > 450.0);
    REQUIRE(jc_expected(p1, 0.1, rate) < 450.0 * r);
    CHECK(close(jc_flow_stress(p1, 0.1, rate, &s1), jc_expected(p1, 0.1, rate), 1e-13));
    CHECK(s1 > 0.0);
    CHECK(close(jc_flow_stress(p2, 0.1, rate, &s2), 450.0, 1e-13));
    CHECK(s2 == 0.0);
    // Below rate0 the ICC 1 cap is 450 (R = 1).
    CHECK(close(jc_flow_stress(p1, 0.5, 0.001), 450.0, 1e-13));
  }
  SECTION("c = 0: no rate effect at any rate") {
    Material m = steel(MaterialLaw::JohnsonCook);
    m.c = 0;
    const MaterialParams q = make_material_params(m);
    CHECK(jc_flow_stress(q, 0.1, 1e6) == jc_flow_stress(q, 0.1, 0.0));
  }
}

TEST_CASE("shell radial return: returned svm = sigma_y(old eps_p), d_eps_p = (svm_trial - sigma_y)/E",
          "[material]") {
  const MaterialParams p = make_material_params(steel(MaterialLaw::JohnsonCook));
  const double gs = 5.0 / 6.0 * p.shear;
  const double rate = 50.0;
  const double eps0 = 0.05;
  const double sig0[5] = {100.0, 30.0, 20.0, 5.0, -3.0};
  const double de[5] = {2e-3, 5e-4, 1e-3, 1e-4, 2e-4};
  const auto t = shell_trial(p, sig0, de, gs);
  const double svm_t = vm_plane(t.data());
  const double sy = jc_expected(p, eps0, rate);  // old eps_p: explicit hardening (6.2)
  REQUIRE(vm_plane(sig0) < sy);
  REQUIRE(svm_t > 1.2 * sy);
  for (const double off : {1.0, 0.8}) {
    double sig[5];
    std::copy(sig0, sig0 + 5, sig);
    double eps_p = eps0;
    const auto res = shell_point_update(p, 0, rate, off, de, gs, sig, eps_p);
    // Round-off: the returned stress is the trial times sy/svm_trial, so its svm is sy to a few ulps
    // (tighter than the 1e-10 asked).
    CHECK(close(vm_plane(sig), sy, kRound));
    for (int i = 0; i < 3; ++i) CHECK(close(sig[i], t[i] * sy / svm_t, kRound));
    CHECK(close(sig[3], t[3], kRound));  // transverse shear stays elastic
    CHECK(close(sig[4], t[4], kRound));
    const double dp = off * (svm_t - sy) / p.young;  // divided by E (6.3), OFF-weighted
    CHECK(close(res.deps_p, dp, kRound));
    CHECK(close(eps_p, eps0 + dp, kRound));
    // Thickness strain (1.8) with the plastic in-plane trace dp (sxx + syy)/(2 sy) of the returned stress.
    const double ezz_p = dp * (sig[0] + sig[1]) / (2.0 * sy);
    const double dezz = (-p.nu * (de[0] + de[1]) - (1 - 2 * p.nu) * ezz_p) / (1 - p.nu);
    CHECK(close(res.dezz, dezz, kRound));
    // The new eps_p would give a visibly different flow stress: the old one is the one used.
    CHECK(std::abs(jc_expected(p, eps_p, rate) - sy) > 1e-5 * sy);
  }
}

TEST_CASE("shell Iplas = 1: three Newton evaluations land on the yield surface within their computed error",
          "[material]") {
  const MaterialParams p = make_material_params(steel(MaterialLaw::JohnsonCook));
  const double rate = 50.0;
  const double eps0 = 0.05;
  const double gs = 5.0 / 6.0 * p.shear;
  // Strong uniaxial-stress step: trial svm = 630, sigma_y = 411.
  const double dx = 3e-3;
  const double sig0[5] = {0, 0, 0, 0, 0};
  const double de[5] = {dx, -p.nu * dx, 4e-4, 0, 0};
  const auto t = shell_trial(p, sig0, de, gs);
  double sig[5] = {0, 0, 0, 0, 0};
  double eps_p = eps0;
  const auto res = shell_point_update(p, 1, rate, 1.0, de, gs, sig, eps_p);

  // (1) Exactly the 6.3 recipe: the result equals the third evaluation written out here (round-off), and
  // differs from the second and the fourth by far more than round-off.
  const Projection p2 = project(p, t.data(), eps0, rate, 2);
  const Projection p3 = project(p, t.data(), eps0, rate, 3);
  const Projection p4 = project(p, t.data(), eps0, rate, 4);
  CHECK(close(res.deps_p, p3.dp, kRound));
  CHECK(std::abs(p3.dp - p2.dp) > 1e-8 * p3.dp);
  CHECK(std::abs(p3.dp - p4.dp) > 1e-10 * p3.dp);
  CHECK(close(eps_p, eps0 + p3.dp, kRound));
  const double s1 = p3.pp * (t[0] + t[1]), s2 = p3.qq * (t[0] - t[1]);
  CHECK(close(sig[0], 0.5 * (s1 + s2), kRound));
  CHECK(close(sig[1], 0.5 * (s1 - s2), kRound, kRound * std::abs(sig[0])));
  CHECK(close(sig[2], p3.qq * t[2], kRound));
  const double dezz = (-p.nu * (de[0] + de[1]) - (1 - 2 * p.nu) * p3.r * s1 / p.young) / (1 - p.nu);
  CHECK(close(res.dezz, dezz, kRound));

  // (2) Distance to the yield surface. The exact projection dp* is the root of g (bisection to round-off).
  // The iteration dp <- phi(dp) = max(0, dp - f/df) contracts toward dp* (df uses H at the old eps_p, so it
  // is a quasi-Newton step). By the mean value theorem, with kappa(w) = max |phi'| over [dp* - w, dp* + w]:
  // e1 <= kappa(e0) e0 and e2 <= kappa(e1) e1, where e0 = |dp0 - dp*| and e2 bounds the error of the third
  // evaluation (two updates); then |g(dp_3)| <= max|g'| e2. kappa and g' come from central differences on 200
  // samples of each interval (10 % margin for sampling).
  double lo = 0, hi = 2 * p3.dp;
  REQUIRE(projection_residual(p, t.data(), eps0, rate, lo) > 0);
  REQUIRE(projection_residual(p, t.data(), eps0, rate, hi) < 0);
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (projection_residual(p, t.data(), eps0, rate, mid) > 0 ? lo : hi) = mid;
  }
  const double dp_star = 0.5 * (lo + hi);
  struct Slopes {
    double kappa = 0, g = 0;
  };
  auto slopes = [&](double w) {
    Slopes out;
    const int samples = 200;
    const double hstep = 1e-4 * w;
    for (int k = 0; k <= samples; ++k) {
      const double x = dp_star - w + 2 * w * k / samples;
      const double dphi = evaluate(p, t.data(), eps0, rate, x + hstep).next -
                          evaluate(p, t.data(), eps0, rate, x - hstep).next;
      const double dg = projection_residual(p, t.data(), eps0, rate, x + hstep) -
                        projection_residual(p, t.data(), eps0, rate, x - hstep);
      out.kappa = std::max(out.kappa, 1.1 * std::abs(dphi) / (2 * hstep));
      out.g = std::max(out.g, 1.1 * std::abs(dg) / (2 * hstep));
    }
    return out;
  };
  const double e0 = std::abs(newton_start(p, t.data(), eps0, rate) - dp_star);
  const Slopes k0 = slopes(e0);
  const double e1 = k0.kappa * e0;
  const Slopes k1 = slopes(e1);
  const double e2 = k1.kappa * e1;
  const double sy_new = jc_flow_stress(p, eps_p, rate);
  const double bound = slopes(e2).g * e2 + kRound * sy_new;
  const double residual = std::abs(vm_plane(sig) - sy_new);
  INFO("e0/dp* = " << e0 / dp_star << ", kappa " << k0.kappa << " then " << k1.kappa
                   << ", residual/sy = " << residual / sy_new << ", bound/sy = " << bound / sy_new);
  CHECK(std::abs(p3.dp - dp_star) <= e2);
  REQUIRE(k0.kappa < 1.0);
  CHECK(residual <= bound);
  CHECK(bound < 1e-3 * sy_new);  // the bound is a real statement, not a blanket tolerance

  // (3) The error shrinks with more evaluations (convergence of the recipe toward the exact projection).
  CHECK(std::abs(p4.dp - dp_star) < std::abs(p3.dp - dp_star));
  CHECK(std::abs(p3.dp - dp_star) < std::abs(p2.dp - dp_star));
}

TEST_CASE("shell Iplas = 1 agrees with radial return where plane stress makes the return radial",
          "[material]") {
  // Perfect plasticity (b = 0, H = 0): in pure shear and equal biaxial stress the plane-stress projection is
  // radial, and with H = 0 df is the exact derivative of f, so the recipe is a true Newton method.
  Material m = steel(MaterialLaw::JohnsonCook);
  m.b = 0;
  m.c = 0;
  const MaterialParams p = make_material_params(m);
  const double sy = p.jc.a;
  SECTION("pure shear") {
    const double de[5] = {0, 0, 4e-3, 0, 0};
    double sig[5] = {0, 0, 0, 0, 0};
    double eps_p = 0;
    const double svm_t = std::sqrt(3.0) * p.shear * 4e-3;
    const auto res = shell_point_update(p, 1, 0.0, 1.0, de, 0.0, sig, eps_p);
    CHECK(close(res.deps_p, (svm_t - sy) / (3 * p.shear), kRound));
    CHECK(close(sig[2], sy / std::sqrt(3.0), kRound));
    CHECK(std::abs(sig[0]) + std::abs(sig[1]) <= kRound * sy);
  }
  SECTION("equal biaxial") {
    // f(x) = A P(x)^2 - sy^2 with P = 1/(1 + c x), c = E/(2 sy (1 - nu)); the root P = sy/svm gives
    // dp* = 2(1 - nu)(svm - sy)/E. The start x0 = (svm - sy)/(3G) is below dp*; on [x0, dp*] Newton obeys
    // e_{k+1} <= M e_k^2 with M = max|f''|/(2 min|f'|) = 1.5 c (1 + c dp*)^3/(1 + c x0)^4, so the third
    // evaluation is within e2 = M^3 e0^4 of dp*, and the stress P svm within svm c e2 of sy.
    // A 20 % overstress (a large explicit step): e2/dp* comes out near 7e-4, the actual error near 3e-4.
    const double ex = 0.2 * sy / (p.a11 + p.a12) + sy / (p.a11 + p.a12);
    const double de[5] = {ex, ex, 0, 0, 0};
    double sig[5] = {0, 0, 0, 0, 0};
    double eps_p = 0;
    const double svm_t = (p.a11 + p.a12) * ex;
    const auto res = shell_point_update(p, 1, 0.0, 1.0, de, 0.0, sig, eps_p);
    const double dp_star = 2 * (1 - p.nu) * (svm_t - sy) / p.young;
    const double x0 = (svm_t - sy) / (3 * p.shear);
    const double c = p.young / (2 * sy * (1 - p.nu));
    const double m_newton = 1.5 * c * std::pow(1 + c * dp_star, 3) / std::pow(1 + c * x0, 4);
    const double e0 = dp_star - x0;
    const double e2 = std::pow(m_newton, 3) * std::pow(e0, 4);
    INFO("dp error " << (res.deps_p - dp_star) / dp_star << " bound " << e2 / dp_star << ", stress error "
                     << (sig[0] - sy) / sy);
    CHECK(std::abs(res.deps_p - dp_star) <= e2 + kRound * dp_star);
    CHECK(std::abs(sig[0] - sy) <= svm_t * c * e2 + kRound * sy);
    CHECK(e2 < 1e-3 * dp_star);
    CHECK(close(sig[1], sig[0], kRound));
  }
  SECTION("general state: Iplas 1 and radial return differ by O(step), halving with the step") {
    // Start on the yield surface (uniaxial sxx = sy), load by a mixed increment h de; the two returns differ
    // in direction by a term linear in the overstress, so the difference halves when h halves (within 10 %).
    std::vector<double> diff;
    for (const double h : {4e-5, 2e-5, 1e-5, 5e-6}) {
      const double de[5] = {h, 0.3 * h, 0.2 * h, 0, 0};
      double s_new[5] = {sy, 0, 0, 0, 0}, s_rad[5] = {sy, 0, 0, 0, 0};
      double e_new = 0, e_rad = 0;
      shell_point_update(p, 1, 0.0, 1.0, de, 0.0, s_new, e_new);
      shell_point_update(p, 0, 0.0, 1.0, de, 0.0, s_rad, e_rad);
      diff.push_back(std::hypot(s_new[0] - s_rad[0], s_new[1] - s_rad[1], s_new[2] - s_rad[2]) / sy);
    }
    for (std::size_t k = 1; k < diff.size(); ++k) {
      INFO("diff " << diff[k - 1] << " -> " << diff[k]);
      CHECK(diff[k - 1] / diff[k] > 1.8);
      CHECK(diff[k - 1] / diff[k] < 2.2);
    }
  }
  SECTION("OFF < 1: the projection is skipped, the trial stress is kept") {
    const double de[5] = {3e-3, 0, 0, 0, 0};
    double sig[5] = {0, 0, 0, 0, 0};
    double eps_p = 0;
    const auto res = shell_point_update(p, 1, 0.0, 0.8, de, 0.0, sig, eps_p);
    CHECK(res.deps_p == 0.0);
    CHECK(eps_p == 0.0);
    CHECK(close(sig[0], p.a11 * 3e-3, kRound));
  }
}

TEST_CASE("shell point is isotropic in its plane (rotation about the normal commutes with the update)",
          "[material]") {
  // Rotating the input stress and strain increment by theta about z and updating gives the rotated result:
  // round-off (1e-12 of sigma_y), for both returns.
  const MaterialParams p = make_material_params(steel(MaterialLaw::JohnsonCook));
  const double gs = 5.0 / 6.0 * p.shear;
  const double th = 0.7, c = std::cos(th), s = std::sin(th);
  const Mat3 q = {{{c, -s, 0}, {s, c, 0}, {0, 0, 1}}};
  auto to_voigt3 = [](const double* v5, double f) {  // shell {xx yy xy yz zx} -> solid Voigt order
    return std::array<double, 6>{v5[0], v5[1], 0.0, v5[2] * f, v5[3] * f, v5[4] * f};
  };
  const double sig0[5] = {150.0, -40.0, 60.0, 8.0, -5.0};
  const double de[5] = {1.5e-3, -4e-4, 2e-3, 3e-4, -2e-4};
  for (const int iplas : {0, 1}) {
    double sa[5];
    std::copy(sig0, sig0 + 5, sa);
    double ea = 0.02;
    const auto ra = shell_point_update(p, iplas, 10.0, 1.0, de, gs, sa, ea);
    // Rotated inputs.
    const auto s6 = to_voigt3(sig0, 1.0), d6 = to_voigt3(de, 1.0);
    double sr6[6], dr6[6];
    from_tensor(rotate(q, to_tensor(s6.data(), 1.0)), 1.0, sr6);
    from_tensor(rotate(q, to_tensor(d6.data(), 0.5)), 0.5, dr6);
    double sb[5] = {sr6[0], sr6[1], sr6[3], sr6[4], sr6[5]};
    const double db[5] = {dr6[0], dr6[1], dr6[3], dr6[4], dr6[5]};
    double eb = 0.02;
    const auto rb = shell_point_update(p, iplas, 10.0, 1.0, db, gs, sb, eb);
    REQUIRE(ra.deps_p > 0);
    CHECK(close(rb.deps_p, ra.deps_p, kRound));
    CHECK(close(rb.dezz, ra.dezz, kRound));
    const auto sa6 = to_voigt3(sa, 1.0);
    double expect[6];
    from_tensor(rotate(q, to_tensor(sa6.data(), 1.0)), 1.0, expect);
    const double sb6[6] = {sb[0], sb[1], 0.0, sb[2], sb[3], sb[4]};
    for (int i = 0; i < 6; ++i) CHECK(std::abs(sb6[i] - expect[i]) <= kRound * 500.0);
  }
}

TEST_CASE("shell point with the rate factor given: shell_point_update_r(R) is shell_point_update(rate)",
          "[material]") {
  // The shell kernels take R = jc_rate_factor(rate) once per element: the update must be the same to the bit.
  Material capped = steel(MaterialLaw::JohnsonCook);
  capped.sig_max0 = 420.0;
  capped.icc = 2;
  const MaterialParams mats[] = {make_material_params(steel(MaterialLaw::JohnsonCook)),
                                 make_material_params(capped),
                                 make_material_params(steel(MaterialLaw::Elastic))};
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int plastic = 0;
  for (const MaterialParams& p : mats)
    for (const int iplas : {0, 1})
      for (const double off : {1.0, 0.8})
        for (const double rate : {0.0, 0.005, 0.01, 3.0, 2e3})
          for (int k = 0; k < 20; ++k) {
            const double gs = 5.0 / 6.0 * p.shear;
            const double sig0[5] = {300 * u(rng), 300 * u(rng), 150 * u(rng), 20 * u(rng), 20 * u(rng)};
            const double de[5] = {2e-3 * u(rng), 2e-3 * u(rng), 2e-3 * u(rng), 1e-3 * u(rng), 1e-3 * u(rng)};
            const double eps0 = k % 3 == 0 ? 0.0 : 0.05 * (1.0 + u(rng));
            double sa[5], sb[5];
            std::copy(sig0, sig0 + 5, sa);
            std::copy(sig0, sig0 + 5, sb);
            double ea = eps0, eb = eps0;
            const auto ra = shell_point_update(p, iplas, rate, off, de, gs, sa, ea);
            const auto rb =
                radx::solver::shell_point_update_r(p, iplas, jc_rate_factor(p, rate), off, de, gs, sb, eb);
            for (int c = 0; c < 5; ++c) CHECK(sa[c] == sb[c]);
            CHECK(ea == eb);
            CHECK(ra.deps_p == rb.deps_p);
            CHECK(ra.dezz == rb.dezz);
            CHECK(ra.w_plastic == rb.w_plastic);
            plastic += ra.deps_p > 0;
            // Plastic work per volume (6.5): 1/2 (svm_old + svm_new) d_eps_p.
            if (ra.deps_p > 0)
              CHECK(close(ra.w_plastic, 0.5 * (vm_plane(sig0) + vm_plane(sa)) * ra.deps_p, kRound));
            else
              CHECK(ra.w_plastic == 0.0);
          }
  CHECK(plastic > 50);  // both paths were exercised
  // R: exactly 1 at or below rate0 and for c = 0 (no logarithm); 1 + c ln(rate/rate0) above.
  const MaterialParams& p = mats[0];
  CHECK(jc_rate_factor(p, 0.0) == 1.0);
  CHECK(jc_rate_factor(p, p.jc.eps_dot0) == 1.0);
  CHECK(close(jc_rate_factor(p, 50.0), 1.0 + p.jc.c * std::log(50.0 / p.jc.eps_dot0), kRound));
  CHECK(jc_rate_factor(mats[2], 50.0) == 1.0);
  Material no_rate = steel(MaterialLaw::JohnsonCook);
  no_rate.c = 0;
  CHECK(jc_rate_factor(make_material_params(no_rate), 1e6) == 1.0);
}

TEST_CASE("shell_stays_elastic: the points it passes take no plastic step, the points well inside pass",
          "[material]") {
  // The batched shell loops trust shell_stays_elastic to skip the exact update: a point it passes must come
  // out of shell_point_update_r as its elastic trial (d_eps_p = 0, dezz = shell_dezz(.., 0)), to the bit.
  // Trial states are scaled to svm / min(a R, SIG_max0) in [0.5, 1.5], with eps_p = 0 (flow stress = bound)
  // or > 0 (flow stress above it).
  Material capped = steel(MaterialLaw::JohnsonCook);
  capped.sig_max0 = 260.0;
  Material softening = steel(MaterialLaw::JohnsonCook);
  softening.b = -100.0;  // the bound does not hold: never passed
  const MaterialParams mats[] = {make_material_params(steel(MaterialLaw::JohnsonCook)),
                                 make_material_params(capped), make_material_params(softening),
                                 make_material_params(steel(MaterialLaw::Elastic))};
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int passed = 0, inside = 0;
  for (int mi = 0; mi < 4; ++mi) {
    const MaterialParams& p = mats[mi];
    const radx::solver::ShellYieldBound yb = radx::solver::shell_yield_bound(p);
    for (const int iplas : {0, 1})
      for (const double off : {1.0, 0.8})
        for (const double rate : {0.0, 40.0})
          for (int k = 0; k < 200; ++k) {
            const double r = jc_rate_factor(p, rate);
            const double lb = std::min(p.jc.a * r, p.jc.sig_max0);
            const double gs = 5.0 / 6.0 * p.shear;
            const double de[5] = {1e-4 * u(rng), 1e-4 * u(rng), 1e-4 * u(rng), 1e-4 * u(rng), 1e-4 * u(rng)};
            const double eps0 = k % 2 == 0 ? 0.0 : 0.02 * (1.0 + u(rng));
            // A random direction, scaled so that the trial von Mises is `ratio` times the bound.
            double sig0[5] = {u(rng), u(rng), u(rng), 10 * u(rng), 10 * u(rng)};
            double t[5] = {sig0[0], sig0[1], sig0[2], sig0[3], sig0[4]};
            radx::solver::shell_trial(p, gs, de[0], de[1], de[2], de[3], de[4], t[0], t[1], t[2], t[3], t[4]);
            const double ratio = 1.0 + 0.5 * u(rng);
            const double scale = ratio * lb / std::max(vm_plane(t), 1e-300);
            for (int c = 0; c < 3; ++c) sig0[c] *= scale;
            std::copy(sig0, sig0 + 5, t);
            radx::solver::shell_trial(p, gs, de[0], de[1], de[2], de[3], de[4], t[0], t[1], t[2], t[3], t[4]);
            const bool pass =
                iplas == 1 ? radx::solver::shell_stays_elastic<true>(yb, r, off, eps0, t[0], t[1], t[2])
                           : radx::solver::shell_stays_elastic<false>(yb, r, off, eps0, t[0], t[1], t[2]);
            double sig[5];
            std::copy(sig0, sig0 + 5, sig);
            double eps_p = eps0;
            const auto res = radx::solver::shell_point_update_r(p, iplas, r, off, de, gs, sig, eps_p);
            if (pass) {
              ++passed;
              CHECK(res.deps_p == 0.0);
              CHECK(eps_p == eps0);
              for (int c = 0; c < 5; ++c) CHECK(sig[c] == t[c]);
              CHECK(res.dezz == radx::solver::shell_dezz(p, de[0], de[1], 0.0));
            }
            if (mi == 2 && !(iplas == 1 && off != 1.0)) CHECK_FALSE(pass);  // b < 0: no bound
            if (mi == 3) CHECK(pass);                                       // law 1 never yields
            if (mi < 2 && vm_plane(t) < 0.999 * lb) {
              ++inside;
              CHECK(pass);  // well inside the bound: the fast path is taken
            }
          }
  }
  CHECK(passed > 1000);
  CHECK(inside > 300);
}

TEST_CASE("jc_rate_factor_lower: a lower bound of R within 0.061 c, exactly 1 at or below rate0",
          "[material]") {
  // The BT4 kernel checks its points against min(a R_lo, SIG_max0) and takes the logarithm only for the
  // elements with a point that fails the check. R_lo must never exceed R (a yielding point would be taken as
  // elastic); the chord of ln over [1, 2] is below ln by at most ln(1/ln 2) - (1/ln 2 - 1) ln 2 = 0.0597.
  const MaterialParams p = make_material_params(steel(MaterialLaw::JohnsonCook));
  const double inv0 = 1.0 / p.jc.eps_dot0;
  auto lower = [&](double rate) { return radx::solver::jc_rate_factor_lower(p.jc.c, inv0, rate); };
  CHECK(lower(0.0) == 1.0);
  CHECK(lower(1e-310) == 1.0);  // subnormal
  CHECK(lower(0.5 * p.jc.eps_dot0) == 1.0);
  CHECK(lower(p.jc.eps_dot0) == 1.0);
  CHECK(lower(std::numeric_limits<double>::infinity()) > 1.0);
  int n = 0;
  double worst = 0;
  for (double lg = -6.0; lg <= 12.0; lg += 1.0 / 1024.0, ++n) {
    const double rate = std::pow(10.0, lg);
    const double r = jc_rate_factor(p, rate), lo = lower(rate);
    CHECK(lo <= r);
    CHECK(lo >= 1.0);
    worst = std::max(worst, (r - lo) / p.jc.c);
  }
  // Over every binade, the largest gap is reached (to the grid's resolution) and never exceeded.
  CHECK(n > 18000);
  CHECK(worst <= 0.0597 + 1e-8);
  CHECK(worst >= 0.059);

  // A point that passes shell_stays_elastic with R_lo takes no plastic step with the exact R (trials scaled
  // to 0.9 .. 1.1 times the exact bound a R).
  const radx::solver::ShellYieldBound yb = radx::solver::shell_yield_bound(p);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int passed = 0;
  for (int k = 0; k < 4000; ++k) {
    const double rate = std::pow(10.0, 6.0 * (1.0 + u(rng)));
    const double r = jc_rate_factor(p, rate), lo = lower(rate);
    double t[5] = {u(rng), u(rng), u(rng), 0.0, 0.0};
    const double scale = (1.0 + 0.1 * u(rng)) * p.jc.a * r / vm_plane(t);
    for (double& c : t) c *= scale;
    const double de[5] = {0, 0, 0, 0, 0};
    const int iplas = k % 2;
    const bool pass = iplas == 1
                          ? radx::solver::shell_stays_elastic<true>(yb, lo, 1.0, 0.0, t[0], t[1], t[2])
                          : radx::solver::shell_stays_elastic<false>(yb, lo, 1.0, 0.0, t[0], t[1], t[2]);
    double sig[5] = {t[0], t[1], t[2], t[3], t[4]};
    double eps_p = 0;
    const auto res = radx::solver::shell_point_update_r(p, iplas, r, 1.0, de, 0.0, sig, eps_p);
    if (pass) {
      ++passed;
      CHECK(res.deps_p == 0.0);
      for (int c = 0; c < 3; ++c) CHECK(sig[c] == t[c]);
    }
  }
  CHECK(passed > 1000);
}

TEST_CASE("solid point: pressure K mu, elastic shear G gamma, plastic return to sigma_y + d_eps_p H",
          "[material]") {
  for (const MaterialLaw law : {MaterialLaw::Elastic, MaterialLaw::JohnsonCook}) {
    const MaterialParams p = make_material_params(steel(law));
    SECTION(std::string("uniaxial strain compression, ") + (law == MaterialLaw::Elastic ? "LAW1" : "LAW2")) {
      // de = (-e, 0, 0): mu = 1/(1 - e) - 1 (volume V0(1 - e)); p = K mu total, deviator -4/3 G e, 2/3 G e.
      // Round-off (1e-12 of the stresses). e = 5e-4 keeps the deviator (svm = 2 G e = 81) elastic.
      const double e = 5e-4;
      const double de[6] = {-e, 0, 0, 0, 0, 0};
      const double mu = 1.0 / (1.0 - e) - 1.0;
      double sig[6] = {0, 0, 0, 0, 0, 0};
      double eps_p = 0;
      CHECK(solid_point_update(p, 0.0, de, mu, sig, eps_p) == 0.0);
      const double pressure = p.bulk * mu;
      CHECK(close(-(sig[0] + sig[1] + sig[2]) / 3.0, pressure, kRound));
      CHECK(close(sig[0], -4.0 / 3.0 * p.shear * e - pressure, kRound));
      CHECK(close(sig[1], 2.0 / 3.0 * p.shear * e - pressure, kRound));
      CHECK(close(sig[2], sig[1], kRound));
      CHECK(sig[3] == 0.0);
    }
    SECTION(std::string("simple shear, ") + (law == MaterialLaw::Elastic ? "LAW1" : "LAW2")) {
      // Engineering shear increment gamma: tau = G gamma, no normal stress (round-off).
      const double g = 1e-3;
      const double de[6] = {0, 0, 0, 0, g, 0};
      double sig[6] = {0, 0, 0, 0, 0, 0};
      double eps_p = 0;
      solid_point_update(p, 0.0, de, 0.0, sig, eps_p);
      CHECK(close(sig[4], p.shear * g, kRound));
      CHECK(std::abs(sig[0]) + std::abs(sig[1]) + std::abs(sig[2]) + std::abs(sig[3]) + std::abs(sig[5]) ==
            0.0);
    }
  }
  SECTION("LAW1 never yields") {
    const MaterialParams p = make_material_params(steel(MaterialLaw::Elastic));
    const double de[6] = {0, 0, 0, 0.1, 0, 0};
    double sig[6] = {0, 0, 0, 0, 0, 0};
    double eps_p = 0;
    CHECK(solid_point_update(p, 0.0, de, 0.0, sig, eps_p) == 0.0);
    CHECK(close(sig[3], p.shear * 0.1, kRound));
  }
  SECTION("LAW2 plastic return") {
    // Trial deviator from a general increment on a prestressed point at eps_p = 0.02, rate 10:
    // d_eps_p = (svm - sy)/(3G + H) and returned svm = sy + d_eps_p H with sy, H at the OLD eps_p (6.3).
    // Round-off (1e-12 of sy). The pressure is K mu whatever the deviator does.
    const MaterialParams p = make_material_params(steel(MaterialLaw::JohnsonCook));
    const double eps0 = 0.02, rate = 10.0, mu = 2e-3;
    const double sig0[6] = {50.0, -20.0, -100.0, 30.0, 10.0, -15.0};
    const double de[6] = {2e-3, -1e-3, 5e-4, 3e-3, -1e-3, 2e-3};
    const double ev3 = (de[0] + de[1] + de[2]) / 3.0, mean0 = (sig0[0] + sig0[1] + sig0[2]) / 3.0;
    double t[6];
    for (int i = 0; i < 3; ++i) t[i] = sig0[i] - mean0 + 2 * p.shear * (de[i] - ev3);
    for (int i = 3; i < 6; ++i) t[i] = sig0[i] + p.shear * de[i];
    const double svm_t = vm_solid(t);
    const double sy = jc_expected(p, eps0, rate);
    const double r = 1.0 + p.jc.c * std::log(rate / p.jc.eps_dot0);
    const double h = p.jc.n * p.jc.b * r * std::pow(eps0, p.jc.n - 1.0);
    REQUIRE(svm_t > 1.2 * sy);
    double sig[6];
    std::copy(sig0, sig0 + 6, sig);
    double eps_p = eps0;
    const double dp = solid_point_update(p, rate, de, mu, sig, eps_p);
    const double dp_expected = (svm_t - sy) / (3 * p.shear + h);
    const double sy_new = sy + dp_expected * h;
    CHECK(close(dp, dp_expected, kRound));
    CHECK(close(eps_p, eps0 + dp_expected, kRound));
    CHECK(close(vm_solid(sig), sy_new, kRound));
    CHECK(close(-(sig[0] + sig[1] + sig[2]) / 3.0, p.bulk * mu, kRound));
    for (int i = 3; i < 6; ++i) CHECK(close(sig[i], t[i] * sy_new / svm_t, kRound));  // radial
  }
  SECTION("LAW2 beyond EPS_p_max: the deviator is zero for ever, the pressure stays") {
    Material m = steel(MaterialLaw::JohnsonCook);
    m.eps_p_max = 0.05;
    const MaterialParams p = make_material_params(m);
    // Start just below EPS_p_max: the crossing step still returns to the yield surface.
    double sig[6] = {0, 0, 0, 0, 0, 0};
    double eps_p = 0.049;
    const double de[6] = {0, 0, 0, 0.01, 0, 0};
    double h = 0;
    const double sy = jc_flow_stress(p, 0.049, 0.0, &h);
    const double dp0 = solid_point_update(p, 0.0, de, 0.0, sig, eps_p);
    REQUIRE(eps_p > p.jc.eps_p_max);
    CHECK(close(vm_solid(sig), sy + dp0 * h, kRound));  // returned to the surface, not zeroed
    for (int k = 0; k < 5; ++k) {
      const double dek[6] = {1e-3 * k, -2e-3, 1e-3, 0.01, -0.02, 0.003};
      const double mu = 1e-3 * (k + 1);
      const double e_before = eps_p;
      const double dp = solid_point_update(p, 0.0, dek, mu, sig, eps_p);
      // Exactly zero deviator (scale factor 0), pressure K mu to round-off; eps_p keeps growing by svm/3G.
      CHECK(sig[3] == 0.0);
      CHECK(sig[4] == 0.0);
      CHECK(sig[5] == 0.0);
      CHECK(close(sig[0], -p.bulk * mu, kRound));
      CHECK(close(sig[1], -p.bulk * mu, kRound));
      CHECK(close(sig[2], -p.bulk * mu, kRound));
      CHECK(dp > 0);
      CHECK(eps_p == e_before + dp);
    }
  }
}

TEST_CASE("solid point: a volumetric increment never changes the deviator and never yields", "[material]") {
  // Deviator at 0.999 sigma_y; 50 volumetric increments (expansion and compression). The deviatoric trial
  // increment 2G(de - tr(de)/3) is zero up to the round-off of tr/3 (1e-12 of sigma_y); no plastic strain.
  const MaterialParams p = make_material_params(steel(MaterialLaw::JohnsonCook));
  const double eps0 = 0.03;
  const double sy = jc_expected(p, eps0, 0.0);
  double s0[6] = {2.0, -1.0, -1.0, 0.5, 0.0, 0.0};
  const double scale = 0.999 * sy / vm_solid(s0);
  for (double& v : s0) v *= scale;
  double sig[6];
  std::copy(s0, s0 + 6, sig);
  double eps_p = eps0;
  double mu = 0;
  for (int k = 0; k < 50; ++k) {
    const double e = (k % 2 == 0 ? 1.3e-3 : -0.7e-3);
    const double de[6] = {e, e, e, 0, 0, 0};
    mu += 3 * e;
    CHECK(solid_point_update(p, 1e3, de, mu, sig, eps_p) == 0.0);
    const double mean = (sig[0] + sig[1] + sig[2]) / 3.0;
    CHECK(close(-mean, p.bulk * mu, kRound, kRound * sy));
    for (int i = 0; i < 3; ++i) CHECK(std::abs(sig[i] - mean - s0[i]) <= kRound * sy);
    for (int i = 3; i < 6; ++i) CHECK(sig[i] == s0[i]);
  }
  CHECK(eps_p == eps0);
}

TEST_CASE("solid point is objective: rotating stress and strain increment commutes with the update",
          "[material]") {
  // Isotropic law: update(Q s Q^T, Q de Q^T) = Q update(s, de) Q^T, here through a plastic step.
  // Round-off (1e-12 of the stress scale 500).
  const MaterialParams p = make_material_params(steel(MaterialLaw::JohnsonCook));
  const Mat3 q = rotation(1.0, -2.0, 0.5, 1.1);
  const double sig0[6] = {120.0, -30.0, 45.0, 60.0, -25.0, 10.0};
  const double de[6] = {1e-3, -2e-3, 5e-4, 2.5e-3, 1e-3, -1.5e-3};
  const double mu = 1e-3;
  double sa[6];
  std::copy(sig0, sig0 + 6, sa);
  double ea = 0.01;
  const double dpa = solid_point_update(p, 5.0, de, mu, sa, ea);
  REQUIRE(dpa > 0);
  double sb[6], db[6];
  from_tensor(rotate(q, to_tensor(sig0, 1.0)), 1.0, sb);
  from_tensor(rotate(q, to_tensor(de, 0.5)), 0.5, db);
  double eb = 0.01;
  const double dpb = solid_point_update(p, 5.0, db, mu, sb, eb);
  CHECK(close(dpb, dpa, kRound));
  double expect[6];
  from_tensor(rotate(q, to_tensor(sa, 1.0)), 1.0, expect);
  for (int i = 0; i < 6; ++i) CHECK(std::abs(sb[i] - expect[i]) <= kRound * 500.0);
}

namespace {

struct PathResult {
  double work = 0, area = 0, bound = 0, eps_p = 0;
  int plastic_steps = 0;
  bool flow_stress_exact = true, between_bounds = true;
};

// Isochoric stretch (1, -1/2, -1/2) d per step to a total 0.3 in `steps` increments, at a constant rate.
PathResult stretch_path(const MaterialParams& p, int steps, double rate) {
  PathResult out;
  const double d = 0.3 / steps;
  const double de[6] = {d, -0.5 * d, -0.5 * d, 0, 0, 0};
  double sig[6] = {0, 0, 0, 0, 0, 0};
  double eps_p = 0;
  for (int k = 0; k < steps; ++k) {
    const double e_old = eps_p;
    double h = 0;
    const double sy_old = jc_flow_stress(p, e_old, rate, &h);
    const double dp = solid_point_update(p, rate, de, 0.0, sig, eps_p);
    if (dp == 0) continue;
    ++out.plastic_steps;
    const double svm = vm_solid(sig);
    const double sy_next = jc_flow_stress(p, eps_p, rate);
    // Flow stress followed: svm = sigma_y(eps_old) + dp H(eps_old) to round-off ...
    if (!close(svm, sy_old + dp * h, kRound)) out.flow_stress_exact = false;
    // ... which for the concave curve (n < 1) lies between sigma_y(eps_new) and its tangent (round-off); at
    // eps_old = 0 the slope is taken as 0 (infinite for n < 1), so the first plastic step returns to a R.
    if (e_old == 0) {
      if (!close(svm, sy_old, kRound)) out.between_bounds = false;
    } else if (svm < sy_next * (1 - kRound) || svm > sy_old + dp * h + kRound * svm) {
      out.between_bounds = false;
    }
    // Plastic work of 6.5 (solid: svm_new dp). Both it and the exact area over [e_old, e_new] lie in
    // [sigma(e_old) dp, max(svm, sigma(e_new)) dp] since sigma increases: their gap is below the width.
    out.work += svm * dp;
    out.bound += (std::max(svm, sy_next) - sy_old) * dp;
  }
  out.eps_p = eps_p;
  const double r = rate > p.jc.eps_dot0 ? 1.0 + p.jc.c * std::log(rate / p.jc.eps_dot0) : 1.0;
  out.area = r * (p.jc.a * eps_p + p.jc.b * std::pow(eps_p, p.jc.n + 1) / (p.jc.n + 1));
  return out;
}

}  // namespace

TEST_CASE("solid monotonic stretch follows the Johnson-Cook curve, plastic work = area under it",
          "[material]") {
  // docs/theory/verification.md case 14 at one point. The stretch path is deviatoric (lateral strains -1/2),
  // so svm = 3G e until yield. Tolerances: per step round-off (see stretch_path); for the work the computed
  // bound sum (max(svm, sigma(e_new)) - sigma(e_old)) dp, which is O(step) (about half of max dp times the
  // rise of the curve, plus the first-step term b dp^(n+1)).
  const MaterialParams p = make_material_params(steel(MaterialLaw::JohnsonCook));
  const PathResult r1 = stretch_path(p, 1500, 20.0);
  const PathResult r2 = stretch_path(p, 3000, 20.0);
  for (const PathResult* r : {&r1, &r2}) {
    INFO("eps_p " << r->eps_p << " work " << r->work << " area " << r->area << " bound " << r->bound);
    CHECK(r->plastic_steps > 1000);
    CHECK(r->flow_stress_exact);
    CHECK(r->between_bounds);
    CHECK(std::abs(r->work - r->area) <= r->bound);
    CHECK(r->bound < 2e-3 * r->area);
  }
  // First order in the step: halving the step halves the work error (within 15 %).
  const double ratio = std::abs(r1.work - r1.area) / std::abs(r2.work - r2.area);
  INFO("error ratio " << ratio);
  CHECK(ratio > 1.7);
  CHECK(ratio < 2.3);
}
