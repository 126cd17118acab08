// LAW36 (/MAT/PLAS_TAB, solver/materials/law36_plas_tab.cpp) and /FAIL/JOHNSON
// (solver/materials/fail_johnson.cpp) at a single integration point and through the shell section and the
// brick kernel, against values computed here from the formulas at the top of those files. Units: MPa, mm, s
// (steel-like). Each tolerance says what it means; "round-off" is 1e-12 relative, a few thousand ulps of the
// quantities involved.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "solver/elements/element_groups.hpp"
#include "solver/elements/shell/shell_section.hpp"
#include "solver/materials/material_point.hpp"
#include "solver/model/geometry.hpp"
#include "test_util.hpp"

using radx::model::Function;
using radx::model::Material;
using radx::model::MaterialLaw;
using namespace radx::solver;

namespace {

constexpr double kRound = 1e-12;

using radx::test::close;

Function curve(std::vector<double> x, std::vector<double> y) {
  Function f;
  f.x = std::move(x);
  f.y = std::move(y);
  return f;
}

// A law-36 material on the functions 0 .. n-1 of `fns` with the given scales and rates.
Material plas_tab(const std::vector<double>& scales, const std::vector<double>& rates, int fsmooth = 0) {
  Material m;
  m.law = MaterialLaw::PlasTab;
  m.rho = 7.85e-9;
  m.young = 210000.0;
  m.poisson = 0.3;
  for (std::size_t i = 0; i < scales.size(); ++i) {
    m.tab.function_id.push_back(static_cast<std::int64_t>(i + 1));
    m.tab.function.push_back(static_cast<std::int32_t>(i));
    m.tab.scale.push_back(scales[i]);
    m.tab.rate.push_back(rates[i]);
  }
  m.tab.fsmooth = fsmooth;
  return m;
}

double vm_plane(const double* s) {
  return std::sqrt(s[0] * s[0] + s[1] * s[1] - s[0] * s[1] + 3.0 * s[2] * s[2]);
}

double vm_solid(const double* s) {
  const double m = (s[0] + s[1] + s[2]) / 3.0;
  const double d0 = s[0] - m, d1 = s[1] - m, d2 = s[2] - m;
  return std::sqrt(1.5 * (d0 * d0 + d1 * d1 + d2 * d2) + 3.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
}

// A piecewise-linear hardening curve with a kink at every point.
const Function kCurve = curve({0.0, 0.05, 0.1, 0.3, 1.0}, {200.0, 260.0, 300.0, 350.0, 400.0});

}  // namespace

TEST_CASE("law 36 flow stress: on a curve, between two rates (linear, logarithmic), below and above them",
          "[material][law36]") {
  // f1 = 200, 300, 350 and f2 = 250, 400, 450 at eps_p = 0, 0.1, 0.2; f2 scaled by 2; rates 10 and 100, so a
  // rate-0 copy of curve 1 comes first. At eps_p = 0.05: Y1 = 250 (H1 = 1000), Y2 = 2 x 325 = 650
  // (H2 = 2 x 1500). Every expected value below is exact up to round-off.
  const std::vector<Function> fns = {curve({0.0, 0.1, 0.2}, {200.0, 300.0, 350.0}),
                                     curve({0.0, 0.1, 0.2}, {250.0, 400.0, 450.0})};
  std::vector<TabCurve> curves;
  const MaterialParams lin = make_material_params(plas_tab({1.0, 2.0}, {10.0, 100.0}), fns, curves);
  REQUIRE(lin.tab.n_curves == 3);
  CHECK(lin.tab.curves[0].rate == 0.0);
  CHECK(lin.tab.curves[1].rate == 10.0);
  double h = 0;
  // Below the first rate the first curve holds (rate-0 copy): 250, H 1000.
  CHECK(close(tab_flow_stress(lin, 0.05, 5.0, &h), 250.0, kRound));
  CHECK(close(h, 1000.0, kRound));
  // Linear in the rate: w = (55 - 10)/(100 - 10) = 1/2: 250 + (650 - 250)/2 = 450, H = 1000 + (3000 -
  // 1000)/2.
  CHECK(close(tab_flow_stress(lin, 0.05, 55.0, &h), 450.0, kRound));
  CHECK(close(h, 2000.0, kRound));
  // Above the last rate the two last curves are extrapolated (w = 2 at rate 190): 250 + 2 x 400 = 1050.
  CHECK(close(tab_flow_stress(lin, 0.05, 190.0), 1050.0, kRound));
  // Beyond a curve's last point its last segment goes on: f1(0.3) = 350 + 500 x 0.1 = 400 at rate 10.
  CHECK(close(tab_flow_stress(lin, 0.3, 10.0), 400.0, kRound));
  // Fsmooth 2, in ln(rate): w = ln(rate/10)/ln(10) = 1/2 at rate sqrt(1000).
  std::vector<TabCurve> curves_log;
  const MaterialParams lg = make_material_params(plas_tab({1.0, 2.0}, {10.0, 100.0}, 2), fns, curves_log);
  CHECK(close(tab_flow_stress(lg, 0.05, std::sqrt(1000.0)), 450.0, kRound));
  // A single curve has no rate effect.
  std::vector<TabCurve> c1;
  const MaterialParams one = make_material_params(plas_tab({1.0}, {0.0}), fns, c1);
  CHECK(close(tab_flow_stress(one, 0.15, 1e6), 325.0, kRound));
  // The shells' rate term is the rate itself with several curves, 1 with one (no rate).
  CHECK(jc_rate_factor(lin, 55.0) == 55.0);
  CHECK(jc_rate_factor(one, 55.0) == 1.0);
  CHECK(shell_rate_threshold(lin) == -std::numeric_limits<double>::infinity());
  // Fast-path bound: the smallest scaled ordinate over eps_p >= 0, up to the highest rate.
  CHECK(lin.tab.bound);
  CHECK(lin.tab.lower == 200.0);
  CHECK(lin.tab.rate_max == 100.0);
}

TEST_CASE("law 36 with the Johnson-Cook curve tabulated equals LAW2 within the table's interpolation error",
          "[material][law36]") {
  // sigma_y = (a + b eps^n)(1 + c ln(rate/rate0)), a 200, b 500, n 0.4, c 0.02, rate0 1, sampled at
  // geometric eps_p from 1e-4 to 2 (plus 0) at rates 1 and 1000, Fsmooth 2: R is linear in ln(rate), so the
  // logarithmic rate interpolation is exact and only the eps_p sampling errs. For the concave f the chord on
  // [x0, x1] is below f by at most (x1 - x0)(f'(x0) - f'(x1))/4 (both tangents bound f): that, times R, is
  // the tolerance at each eps_p.
  Material jc;
  jc.law = MaterialLaw::JohnsonCook;
  jc.rho = 7.85e-9;
  jc.young = 210000.0;
  jc.poisson = 0.3;
  jc.a = 200.0;
  jc.b = 500.0;
  jc.n = 0.4;
  jc.c = 0.02;
  jc.eps_dot_0 = 1.0;
  const MaterialParams p2 = make_material_params(jc);
  std::vector<double> xs = {0.0};
  for (double x = 1e-4; x < 2.0; x *= 1.05) xs.push_back(x);
  auto f = [&](double e, double r) { return jc_flow_stress(p2, e, r); };
  std::vector<double> y1, y2;
  for (double x : xs) {
    y1.push_back(f(x, 1.0));
    y2.push_back(f(x, 1000.0));
  }
  const std::vector<Function> fns = {curve(xs, y1), curve(xs, y2)};
  std::vector<TabCurve> curves;
  const MaterialParams p36 = make_material_params(plas_tab({1.0, 1.0}, {1.0, 1000.0}, 2), fns, curves);
  auto slope = [&](double e) { return 0.4 * 500.0 * std::pow(e, -0.6); };
  double worst = 0;
  for (double e = 1e-3; e < 1.5; e *= 1.013) {
    const auto k = static_cast<std::size_t>(std::upper_bound(xs.begin(), xs.end(), e) - xs.begin());
    const double x0 = xs[k - 1], x1 = xs[k];
    for (double rate : {0.5, 1.0, 31.6, 1000.0}) {
      const double r = rate > 1.0 ? 1.0 + 0.02 * std::log(rate) : 1.0;
      const double tol = (x1 - x0) * (slope(x0) - slope(x1)) / 4.0 * r + kRound * f(e, rate);
      const double d = std::abs(tab_flow_stress(p36, e, rate) - f(e, rate));
      CHECK(d <= tol);
      worst = std::max(worst, d / f(e, rate));
    }
  }
  CHECK(worst < 2e-4);  // measured about 1e-4 (relative) with this 5 % spacing
}

TEST_CASE(
    "law 36 shell, uniaxial stress path: elastic E exx, then sxx on the table at the start-of-step eps_p",
    "[material][law36]") {
  // dexx = 1e-4, deyy = -nu dexx per step: the trial keeps syy = 0 and adds E dexx to sxx. Radial return
  // (Iplas 0): sxx goes back to sigma_y(eps_p of the start of the step) and d_eps_p = (svm_trial -
  // sigma_y)/(3G + H).
  const std::vector<Function> fns = {kCurve};
  std::vector<TabCurve> curves;
  const MaterialParams p = make_material_params(plas_tab({1.0}, {0.0}), fns, curves);
  const double de[5] = {1e-4, -0.3e-4, 0, 0, 0};
  double sig[5] = {0, 0, 0, 0, 0};
  double eps_p = 0;
  int plastic = 0;
  for (int k = 0; k < 2000; ++k) {
    const double e_old = eps_p, s_old = sig[0];
    double h = 0;
    const double sy = tab_flow_stress(p, e_old, 0.0, &h);
    const auto r = shell_point_update(p, 0, 0.0, 1.0, de, 0.0, sig, eps_p);
    CHECK(std::abs(sig[1]) <= kRound * 400.0);
    if (r.deps_p == 0) {
      CHECK(close(sig[0], s_old + p.young * 1e-4, kRound));
      continue;
    }
    ++plastic;
    const double trial = s_old + p.young * 1e-4;
    CHECK(close(sig[0], sy, kRound));
    CHECK(close(r.deps_p, (trial - sy) / (3.0 * p.shear + h), kRound));
  }
  CHECK(plastic > 1500);
  // At the end the stress is on the table at eps_p within one step's hardening (H d_eps_p, H <= 1200).
  CHECK(std::abs(sig[0] - tab_flow_stress(p, eps_p, 0.0)) <= 1200.0 * 1e-4);
}

TEST_CASE(
    "law 36 shell Iplas 1: three Newton evaluations land on sigma_y + H d_eps_p, error quartic in the step",
    "[material][law36]") {
  // From a biaxial state on the yield surface at eps_p = 0.07 (sigma_y 276, H 800), an explicit-size
  // increment of plane-stress projection (sigeps36c.F): the starting guess (svm - sigma_y)/(3G + H) is off by
  // a fraction proportional to the step, and the two Newton updates that are kept square that error twice, so
  // the residual |svm - (sigma_y + H d_eps_p)| goes as the step to the fourth power. Measured: 1.6e-3 MPa
  // (6e-6 of sigma_y) for strains of 1e-4, a 16th of it for half the step; checked below 1e-5 sigma_y and at
  // least 8 times smaller for the half step.
  const std::vector<Function> fns = {kCurve};
  std::vector<TabCurve> curves;
  const MaterialParams p = make_material_params(plas_tab({1.0}, {0.0}), fns, curves);
  double h = 0;
  const double sy = tab_flow_stress(p, 0.07, 0.0, &h);
  double base[5] = {200.0, 80.0, 40.0, 0, 0};
  const double k = sy / vm_plane(base);
  for (int c = 0; c < 3; ++c) base[c] *= k;
  auto residual = [&](double scale, double off, double& dp) {
    double sig[5] = {base[0], base[1], base[2], 0, 0};
    double eps_p = 0.07;
    const double de[5] = {2e-4 * scale, 1e-4 * scale, 1.5e-4 * scale, 0, 0};
    dp = shell_point_update(p, 1, 0.0, off, de, 1000.0, sig, eps_p).deps_p;
    return std::abs(vm_plane(sig) - (sy + h * dp));
  };
  double dp = 0, dp_half = 0;
  const double r1 = residual(1.0, 1.0, dp);
  const double r2 = residual(0.5, 1.0, dp_half);
  INFO("residuals " << r1 << " " << r2);
  REQUIRE(dp > 0);
  REQUIRE(dp_half > 0);
  CHECK(r1 <= 1e-5 * sy);
  CHECK(r2 * 8.0 <= r1);
  // Off < 1: no projection (the trial stays), as LAW2.
  double dp_off = 1;
  residual(1.0, 0.8, dp_off);
  CHECK(dp_off == 0);
}

TEST_CASE("law 36 solid: return to sigma_y(eps_p old), d_eps_p = (1 - R) svm/(3G + H), objective",
          "[material][law36]") {
  const std::vector<Function> fns = {kCurve};
  std::vector<TabCurve> curves;
  const MaterialParams p = make_material_params(plas_tab({1.0}, {0.0}), fns, curves);
  // Isochoric stretch (1, -1/2, -1/2) d: every plastic step returns svm to sigma_y of its start (round-off).
  const double d = 1e-4;
  const double de[6] = {d, -0.5 * d, -0.5 * d, 0, 0, 0};
  double sig[6] = {0, 0, 0, 0, 0, 0};
  double eps_p = 0;
  int plastic = 0;
  for (int k = 0; k < 3000; ++k) {
    double h = 0;
    const double sy = tab_flow_stress(p, eps_p, 0.0, &h);
    const double dp = solid_point_update(p, 0.0, de, 0.0, sig, eps_p);
    if (dp == 0) continue;
    ++plastic;
    CHECK(close(vm_solid(sig), sy, kRound));
  }
  CHECK(plastic > 2000);
  // One step checked against the formula: svm_trial from a known deviator.
  double s1[6] = {0, 0, 0, 0, 0, 0};
  double e1 = 0.2;
  const double big[6] = {5e-3, -2.5e-3, -2.5e-3, 0, 0, 0};
  double h = 0;
  const double sy = tab_flow_stress(p, 0.2, 0.0, &h);
  const double svm_trial = 3.0 * p.shear * 5e-3;  // sqrt(3 J2) of 2G (1, -1/2, -1/2) 5e-3
  const double dp = solid_point_update(p, 0.0, big, 0.0, s1, e1);
  CHECK(close(dp, (svm_trial - sy) / (3.0 * p.shear + h), kRound));
  // Objectivity: the same update in a rotated frame (90 degrees about z swaps x and y, shears change sign
  // pairs) gives the rotated stress (exact permutation, so round-off).
  double a[6] = {120.0, -30.0, 45.0, 60.0, 0.0, 0.0};
  double b[6] = {-30.0, 120.0, 45.0, -60.0, 0.0, 0.0};
  const double da[6] = {2e-3, -1e-3, 5e-4, 2.5e-3, 0, 0};
  const double db[6] = {-1e-3, 2e-3, 5e-4, -2.5e-3, 0, 0};
  double ea = 0.05, eb = 0.05;
  solid_point_update(p, 0.0, da, 1e-4, a, ea);
  solid_point_update(p, 0.0, db, 1e-4, b, eb);
  CHECK(close(ea, eb, kRound));
  CHECK(close(b[0], a[1], kRound, 1e-9));
  CHECK(close(b[1], a[0], kRound, 1e-9));
  CHECK(close(b[2], a[2], kRound, 1e-9));
  CHECK(close(b[3], -a[3], kRound, 1e-9));
}

TEST_CASE(
    "law 36 and LAW2 solids along a stretch: both on the same curve, law 36's steps smaller by a known ratio",
    "[material][law36]") {
  // The same curve a + b eps_p (JC n = 1; two table points reproduce it exactly) and the same radial return
  // d_eps_p = (svm_trial - sigma_y)/(3G + H). LAW2 puts the deviator at sigma_y + H d_eps_p (on the curve at
  // the new eps_p), law 36 at sigma_y of the start of the step (sigeps36.F), so its next trial starts H
  // d_eps_p lower. With an equivalent strain increment d per step the steady increments are
  //   LAW2: d_eps_p = 3G d / (3G + H),   law 36: d_eps_p = 3G d / (3G + 2H)
  // (law 36: (3G + H) dp = 3G d - H dp). Checked: each stress on the curve at its own eps_p (round-off) and
  // the ratio of the last increments (1e-9: the transient after the first plastic step has died out by then).
  Material jc;
  jc.law = MaterialLaw::JohnsonCook;
  jc.rho = 7.85e-9;
  jc.young = 210000.0;
  jc.poisson = 0.3;
  jc.a = 200.0;
  jc.b = 1000.0;
  jc.n = 1.0;
  const MaterialParams p2 = make_material_params(jc);
  const std::vector<Function> fns = {curve({0.0, 1.0}, {200.0, 1200.0})};
  std::vector<TabCurve> curves;
  const MaterialParams p36 = make_material_params(plas_tab({1.0}, {0.0}), fns, curves);
  const double d = 1e-4;
  const double de[6] = {d, -0.5 * d, -0.5 * d, 0, 0, 0};
  double s2[6] = {0, 0, 0, 0, 0, 0}, s36[6] = {0, 0, 0, 0, 0, 0};
  double e2 = 0, e36 = 0, dp2 = 0, dp36 = 0, e36_old = 0;
  for (int k = 0; k < 3000; ++k) {
    dp2 = solid_point_update(p2, 0.0, de, 0.0, s2, e2);
    e36_old = e36;
    dp36 = solid_point_update(p36, 0.0, de, 0.0, s36, e36);
  }
  CHECK(close(vm_solid(s2), 200.0 + 1000.0 * e2, kRound));
  CHECK(close(vm_solid(s36), 200.0 + 1000.0 * e36_old, kRound));
  const double g3 = 3.0 * p2.shear, h = 1000.0;
  CHECK(close(dp2, g3 * d / (g3 + h), 1e-9));
  CHECK(close(dp36, g3 * d / (g3 + 2.0 * h), 1e-9));
}

TEST_CASE("law 36 reader: curves, rates, defaults of Fcut and Fsmooth, and FAIL/JOHNSON attached",
          "[law36][parser]") {
  using radx::test::begin_block;
  using radx::test::Line;
  auto deck = [](const char* units, int n_curves) {
    std::string s = begin_block(2024, units);
    s += "/MAT/PLAS_TAB/3\nsteel\n" + Line().put(7.8e-9, 1, 20).str() + "\n" +
         Line().put(210000.0, 1, 20).put(0.3, 21, 40).put(0.5, 41, 60).str() + "\n" +
         Line().put(n_curves, 1, 10).put(2, 11, 20).str() + "\n" + Line().put(0, 1, 10).str() + "\n";
    Line ids, sc, rt;
    for (int i = 0; i < n_curves; ++i) {
      ids.put(10 + i, 10 * i + 1, 10 * i + 10);
      sc.put(i == 0 ? 0.0 : 2.0, 20 * i + 1, 20 * i + 20);
      rt.put(i == 0 ? 0.0 : 100.0 * i, 20 * i + 1, 20 * i + 20);
    }
    s += ids.str() + "\n" + sc.str() + "\n" + rt.str() + "\n";
    s += "/FAIL/JOHNSON/3\n" + Line().put(0.1, 1, 20).put(0.2, 21, 40).put(-1.5, 41, 60).str() + "\n" +
         Line().put(2, 21, 30).str() + "\n";
    for (int i = 0; i < n_curves; ++i)
      s += "/FUNCT/" + std::to_string(10 + i) + "\nc\n" + Line().put(0.0, 1, 20).put(200.0, 21, 40).str() +
           "\n" + Line().put(1.0, 1, 20).put(400.0, 21, 40).str() + "\n";
    s += "/END\n";
    return s;
  };
  const auto m = radx::test::model_of_deck(deck("Mg mm s", 2));
  REQUIRE(m.materials.size() == 1);
  const auto& mat = m.materials[0];
  CHECK(mat.law == MaterialLaw::PlasTab);
  REQUIRE(mat.tab.function.size() == 2);
  CHECK(mat.tab.function_id[1] == 11);
  CHECK(mat.tab.scale[0] == 1.0);  // 0 -> 1
  CHECK(mat.tab.scale[1] == 2.0);
  CHECK(mat.tab.rate[1] == 100.0);
  CHECK(mat.tab.fsmooth == 2);
  CHECK(mat.eps_p_max == 0.5);
  CHECK(mat.f_cut == 1e4);  // Fcut 0 with several curves: 10 kHz in 1/s
  CHECK(mat.fail_jc.on);
  CHECK(mat.fail_jc.ifail_sh == 2);
  CHECK(mat.fail_jc.ifail_so == 1);       // 0 -> 1
  CHECK(mat.fail_jc.eps_dot_0 == 1e-20);  // 0 -> 1e-20
  // 10 kHz in a millisecond deck is 10 per ms; one curve: no filter and no rate effect.
  CHECK(radx::test::model_of_deck(deck("Mg mm ms", 2)).materials[0].f_cut == 10.0);
  const auto one = radx::test::model_of_deck(deck("Mg mm s", 1));
  CHECK(one.materials[0].f_cut == 0.0);
  CHECK(one.materials[0].tab.fsmooth == 0);
}

TEST_CASE(
    "FAIL/JOHNSON on a shell point, uniaxial stress (triaxiality 1/3): D = eps_p / eps_f, fails at eps_f",
    "[material][fail]") {
  // eps_f = (D1 + D2 exp(D3/3))(1 + D4 ln(rate/rate0)) = (0.05 + 0.2 exp(-0.5))(1 + 0.01 ln 100) for the rate
  // 100 above rate0 = 1; constant along the path, so D = eps_p / eps_f to round-off until D reaches 1 in the
  // step where eps_p crosses eps_f; from then on the point carries no stress.
  const std::vector<Function> fns = {kCurve};
  for (const double rate : {100.0, 0.5}) {
    Material m = plas_tab({1.0}, {0.0});
    m.fail_jc.on = true;
    m.fail_jc.d1 = 0.05;
    m.fail_jc.d2 = 0.2;
    m.fail_jc.d3 = -1.5;
    m.fail_jc.d4 = 0.01;
    m.fail_jc.eps_dot_0 = 1.0;
    std::vector<TabCurve> curves;
    const MaterialParams p = make_material_params(m, fns, curves);
    const double eps_f = (0.05 + 0.2 * std::exp(-0.5)) * (1.0 + 0.01 * std::log(std::max(1.0, rate)));
    CHECK(close(fail_jc_strain(p.fail, 100.0, 300.0, rate), eps_f, kRound));
    const double de[5] = {1e-4, -0.3e-4, 0, 0, 0};
    double sig[5] = {0, 0, 0, 0, 0};
    double eps_p = 0, dmg = 0;
    int failed_at = -1;
    for (int k = 0; k < 5000 && failed_at < 0; ++k) {
      const double e_old = eps_p;
      shell_point_update_fail(p, 0, 1.0, rate, 1.0, 1.0, de, 0.0, sig, eps_p, dmg);
      if (dmg >= 1.0) {
        failed_at = k;
        CHECK(e_old < eps_f * (1 + 1e-9));
        CHECK(eps_p >= eps_f * (1 - 1e-9));
        for (double s : sig) CHECK(s == 0.0);
      } else {
        CHECK(close(dmg, eps_p / eps_f, 1e-11));  // a sum of up to 5000 terms: round-off of the sum
      }
    }
    CHECK(failed_at > 0);
    // A failed point stays without stress.
    shell_point_update_fail(p, 0, 1.0, rate, 1.0, 1.0, de, 0.0, sig, eps_p, dmg);
    for (double s : sig) CHECK(s == 0.0);
  }
}

TEST_CASE("FAIL/JOHNSON on a solid point: Ifail_so 1 deletes, 2 keeps the mean stress, 4 zeroes the stress",
          "[material][fail]") {
  // Isochoric stretch with mu = 0: tr(sigma) = 0, triaxiality 0, eps_f = D1 + D2 = 0.15 (no rate term).
  const std::vector<Function> fns = {kCurve};
  for (const int ifail : {1, 2, 4}) {
    Material m = plas_tab({1.0}, {0.0});
    m.fail_jc.on = true;
    m.fail_jc.d1 = 0.05;
    m.fail_jc.d2 = 0.1;
    m.fail_jc.d3 = -1.5;
    m.fail_jc.ifail_so = ifail;
    std::vector<TabCurve> curves;
    const MaterialParams p = make_material_params(m, fns, curves);
    const double d = 1e-4;
    const double de[6] = {d, -0.5 * d, -0.5 * d, 0, 0, 0};
    double sig[6] = {0, 0, 0, 0, 0, 0};
    double eps_p = 0, dmg = 0;
    bool fails = false;
    int k = 0;
    for (; k < 10000 && dmg < 1.0; ++k) {
      const double e_old = eps_p;
      const auto r = solid_point_update(p, 0.0, de, 0.0, sig, eps_p, dmg, 1.0);
      fails = r.element_fails;
      if (dmg < 1.0) {
        CHECK(close(dmg, eps_p / 0.15, 1e-11));
        CHECK_FALSE(fails);
      } else {
        CHECK(e_old < 0.15 * (1 + 1e-9));
        CHECK(eps_p >= 0.15 * (1 - 1e-9));
      }
    }
    REQUIRE(dmg == 1.0);
    CHECK(fails == (ifail == 1));
    if (ifail != 1) {
      // The point's strength is gone for good: one more step, with a volume change (p = -K mu), keeps no
      // deviator; 2 keeps the mean stress (-K mu), 4 keeps nothing.
      const auto r = solid_point_update(p, 0.0, de, -1e-4, sig, eps_p, dmg, 1.0);
      CHECK_FALSE(r.element_fails);
      const double mean = ifail == 2 ? p.bulk * 1e-4 : 0.0;
      for (int c = 0; c < 3; ++c) CHECK(close(sig[c], mean, kRound));
      for (int c = 3; c < 6; ++c) CHECK(sig[c] == 0.0);
    }
  }
}

TEST_CASE(
    "shell section with FAIL/JOHNSON: Ifail_sh 1 deletes at the first failed point, 2 only when all fail",
    "[shell][fail]") {
  // Three points through the thickness, pure bending: the surface points yield and fail, the middle point
  // (zeta = 0) sees no strain and never fails. Ifail_sh 1: fail_now as soon as a surface point has D = 1;
  // Ifail_sh 2: never (the failed weight 1/4 + 1/4 stays below P_thickfail 0.999999).
  using namespace radx::solver::shell_detail;
  const std::vector<Function> fns = {kCurve};
  for (const int ifail : {1, 2}) {
    Material m = plas_tab({1.0}, {0.0});
    m.fail_jc.on = true;
    m.fail_jc.d1 = 0.02;
    m.fail_jc.ifail_sh = ifail;
    std::vector<TabCurve> curves;
    const MaterialParams p = make_material_params(m, fns, curves);
    ShellGroup g;
    g.allocate(1, 3);
    const ThicknessRule rule = thickness_rule(3);
    SectionBlock<4> s{};
    bool deleted = false;
    int step = 0;
    for (; step < 400 && !deleted; ++step) {
      for (int c = 0; c < 5; ++c) s.dem[c][0] = 0;
      s.dk[0][0] = 2e-3;  // curvature increment: +-1e-3 strain at the surfaces of t = 1
      s.dk[1][0] = s.dk[2][0] = 0;
      s.t[0] = 1.0;
      s.area[0] = 1.0;
      s.rfac[0] = 1.0;
      s.rate[0] = 0.0;
      s.off[0] = 1.0;
      section_update_block(g, 0, 1, p, rule, p.shear * 5.0 / 6.0, s);
      deleted = next_off(failure_limit(p), 1.0, s.eps_p_max[0], s.fail_now[0]) == 0.0;
    }
    const double d_top = g.dmg[2 * kGroupSize], d_mid = g.dmg[1 * kGroupSize];
    CHECK(d_mid == 0.0);
    if (ifail == 1) {
      CHECK(deleted);
      CHECK(d_top == 1.0);
      // The surface points' plastic strain just passed eps_f = D1 (uniaxial-like, triaxiality 1/3 gives
      // eps_f = D1 since D2 = 0).
      CHECK(g.eps_p[2 * kGroupSize] >= 0.02 * (1 - 1e-9));
    } else {
      CHECK_FALSE(deleted);
      CHECK(d_top == 1.0);  // the surfaces failed long ago: their stress is zero
      for (int c = 0; c < 5; ++c) CHECK(g.sig[sig_index(2, c, 0)] == 0.0);
    }
  }
}

TEST_CASE("shell section with law 36 Eps_p_max: deleted at once in the cycle a point exceeds it",
          "[shell][law36]") {
  // Membrane stretch, three points with the same strain: in the cycle their eps_p passes 0.01 the section
  // says "delete now" (OFF 0 through next_off), not the 0.8 decay of LAW2.
  using namespace radx::solver::shell_detail;
  const std::vector<Function> fns = {kCurve};
  Material m = plas_tab({1.0}, {0.0});
  m.eps_p_max = 0.01;
  std::vector<TabCurve> curves;
  const MaterialParams p = make_material_params(m, fns, curves);
  ShellGroup g;
  g.allocate(1, 3);
  const ThicknessRule rule = thickness_rule(3);
  SectionBlock<4> s{};
  int step = 0;
  double e_before = 0;
  for (; step < 1000; ++step) {
    s.dem[0][0] = 1e-4;
    s.dem[1][0] = -0.3e-4;
    for (int c = 2; c < 5; ++c) s.dem[c][0] = 0;
    for (int c = 0; c < 3; ++c) s.dk[c][0] = 0;
    s.t[0] = s.area[0] = 1.0;
    s.rfac[0] = 1.0;
    s.rate[0] = 0.0;
    s.off[0] = 1.0;
    e_before = g.eps_p[0];
    section_update_block(g, 0, 1, p, rule, p.shear * 5.0 / 6.0, s);
    if (next_off(failure_limit(p), 1.0, s.eps_p_max[0], s.fail_now[0]) != 1.0) break;
  }
  REQUIRE(step < 1000);
  CHECK(next_off(failure_limit(p), 1.0, s.eps_p_max[0], s.fail_now[0]) == 0.0);
  CHECK(e_before <= 0.01);
  CHECK(s.eps_p_max[0] > 0.01);
}

TEST_CASE("brick with law 36 Eps_p_max: 0.8 when eps_p passes it, then 0.8 per cycle, deleted below 0.1",
          "[brick][law36]") {
  const std::vector<Function> fns = {kCurve};
  Material m = plas_tab({1.0}, {0.0});
  m.eps_p_max = 0.01;
  std::vector<TabCurve> curves;
  MaterialParams p = make_material_params(m, fns, curves);
  p.rho0 = 7.85e-9;
  p.c_solid = std::sqrt((p.bulk + 4.0 * p.shear / 3.0) / p.rho0);
  // A unit cube stretched along x at a constant velocity gradient (x faces move apart).
  const std::array<std::array<double, 3>, 8> pts = {
      {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}};
  NodeState ns;
  ns.resize(8);
  BrickGroup g;
  g.allocate(1);
  std::array<radx::model::Vec3, 8> xe;
  for (std::size_t k = 0; k < 8; ++k) {
    ns.x[k] = ns.x0[k] = pts[k][0];
    ns.y[k] = ns.y0[k] = pts[k][1];
    ns.z[k] = ns.z0[k] = pts[k][2];
    ns.vx[k] = 10.0 * pts[k][0];
    ns.vy[k] = -5.0 * pts[k][1];
    ns.vz[k] = -5.0 * pts[k][2];
    g.conn[k * kGroupSize] = static_cast<std::int32_t>(k);
    xe[k] = {pts[k][0], pts[k][1], pts[k][2]};
  }
  g.vol0[0] = g.vol[0] = radx::model::brick_volume(xe);
  g.rho[0] = p.rho0;
  CycleInfo cyc;
  cyc.dt1 = 1e-5;  // strain increment 1e-4 per cycle
  int trigger = -1, gone = -1;
  for (int n = 0; n < 400 && gone < 0; ++n) {
    const double e_old = g.eps_p[0], off_old = g.off[0];
    hex8_forces(g, ns, p, cyc);
    if (trigger < 0 && g.off[0] < 1.0) {
      trigger = n;
      CHECK(off_old == 1.0);
      CHECK(e_old <= 0.01);
      CHECK(g.eps_p[0] > 0.01);
      CHECK(g.off[0] == 0.8);
    }
    if (g.off[0] == 0.0) gone = n;
  }
  REQUIRE(trigger >= 0);
  // The cycle after the trigger starts at 0.8, the k-th at 0.8^k; 0.8^10 = 0.107 >= 0.1 > 0.8^11 = 0.086: the
  // 11th cycle after the trigger deletes it.
  CHECK(gone - trigger == 11);
}
