// LAW70 (/MAT/FOAM_TAB, solver/materials/law70_foam_tab.cpp) at one point and in the one-point brick, against
// closed forms. With nu = 0 the law's Hooke matrix is diagonal (A11 = E, A12 = 0), so a uniaxial strain
// eps_xx = -e gives a uniaxial stress whose norm is the curve's value: sigma_xx = -Y(e) (compression
// negative). The curves' slopes stay below E0 = 20, so on loading the elastic trial is always above the curve
// and the stress is the curve itself (sigeps70.F takes min(curve, trial)). "Round-off" is 1e-12 of the
// curve's scale.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "kernel_test_util.hpp"
#include "solver/elements/element_groups.hpp"
#include "solver/materials/material_point.hpp"

using radx::model::Function;
using radx::model::Material;
using radx::model::MaterialLaw;
using namespace radx::solver;

namespace {

constexpr double kRound = 1e-12;

// Loading curve L (slopes 10, 0.5, 6) and unloading curve U (slopes 0.6, 7/3).
double load_curve(double e) {
  if (e <= 0.1) return 10.0 * e;
  if (e <= 0.5) return 1.0 + 0.5 * (e - 0.1);
  return 1.2 + 6.0 * (e - 0.5);
}
double unload_curve(double e) {
  if (e <= 0.5) return 0.6 * e;
  return 0.3 + 7.0 / 3.0 * (e - 0.5);
}

struct Foam {
  std::vector<Function> functions;
  Material mat;
  MaterialParams p;
};

// Law 70 with nu = 0, E0 = e0 (20), Emax = 100, eps_max = 0.8; loading curves = `load_scales` times L at the
// `load_rates`, the unloading curve U when `with_unload`.
Foam foam(int iflag, bool with_unload, std::vector<double> load_rates = {0.0},
          std::vector<double> load_scales = {1.0}, double shape = 1, double hys = 1, double e0 = 20.0) {
  Foam f;
  Function l, u;
  l.id = 1;
  l.x = {0.0, 0.1, 0.5, 0.8};
  l.y = {0.0, 1.0, 1.2, 3.0};
  u.id = 2;
  u.x = {0.0, 0.5, 0.8};
  u.y = {0.0, 0.3, 1.0};
  f.functions = {l, u};
  auto& m = f.mat;
  m.law = MaterialLaw::FoamTab;
  m.rho = 1e-8;
  m.young = e0;
  m.poisson = 0.0;
  auto& t = m.foam;
  t.e_max = 100.0;
  t.eps_max = 0.8;
  t.iflag = iflag;
  t.shape = shape;
  t.hys = hys;
  for (std::size_t i = 0; i < load_rates.size(); ++i) {
    t.load_function_id.push_back(1);
    t.load_function.push_back(0);
    t.load_scale.push_back(load_scales[i]);
    t.load_rate.push_back(load_rates[i]);
  }
  if (with_unload) {
    t.unload_function_id = {2};
    t.unload_function = {0 + 1};
    t.unload_scale = {1.0};
    t.unload_rate = {0.0};
  }
  std::vector<TabCurve> curves;
  f.p = make_material_params(m, f.functions, curves);
  return f;
}

// One point driven in uniaxial strain eps_xx = -e along `path` (e >= 0) at strain rate `rate`. Returns
// sigma_xx at each step; `work` receives the stress work per unit volume, sum of the mean stress times the
// strain increment (positive when the point absorbs energy).
std::vector<double> drive(const MaterialParams& p, const std::vector<double>& path, double rate,
                          double* work = nullptr) {
  double st[kFoamVars], sig[6] = {0, 0, 0, 0, 0, 0};
  foam_initial_state(p, st);
  std::vector<double> out;
  double w = 0, e_prev = 0;
  for (double e : path) {
    const double eps[6] = {-e, 0, 0, 0, 0, 0};
    const double de[6] = {-(e - e_prev), 0, 0, 0, 0, 0};
    const double s_old = sig[0];
    foam_point(p, eps, de, rate, 1.0, sig, st);
    w += 0.5 * (s_old + sig[0]) * (-(e - e_prev));
    out.push_back(sig[0]);
    CHECK(std::abs(sig[1]) <= kRound);
    CHECK(std::abs(sig[2]) <= kRound);
    e_prev = e;
  }
  if (work) *work = w;
  return out;
}

std::vector<double> ramp(double a, double b, int n) {
  std::vector<double> v;
  for (int k = 1; k <= n; ++k) v.push_back(a + (b - a) * k / n);
  return v;
}

}  // namespace

TEST_CASE("Law 70 uniaxial compression at one rate follows the loading curve", "[law70]") {
  const auto f = foam(0, true);
  const auto path = ramp(0.0, 0.75, 750);
  const auto s = drive(f.p, path, 0.0);
  for (std::size_t k = 0; k < path.size(); ++k) {
    INFO("e " << path[k]);
    CHECK(std::abs(s[k] + load_curve(path[k])) <= kRound * 3.0);
  }
}

TEST_CASE("Law 70 unloading follows the unloading curve and the loop dissipates the area between the curves",
          "[law70]") {
  // Load to e_m = 0.6, unload to 0. On the way back the stress drops elastically with the modulus E reached
  // (kept while the stress is between the curves) until it meets U, then follows U. The dissipated work is
  //   W = int_0^e_m (L - U) de - Delta^2 / (2 (E - U')),  Delta = L(e_m) - U(e_m), U' = 7/3 near e_m,
  // the second term the triangle cut off by the elastic drop. Tolerance: 1e-4 of the area, the trapezoid
  // error of 600 steps on the kinks of the curves (the drop itself ends inside one step: up to
  // E de^2 / 2 = 5e-5 of work per unit volume, 1e-4 of the area).
  const auto f = foam(0, true);
  const double em = 0.6;
  auto path = ramp(0.0, em, 600);
  const auto down = ramp(em, 0.0, 600);
  path.insert(path.end(), down.begin(), down.end());
  double st[kFoamVars], sig[6] = {0, 0, 0, 0, 0, 0};
  foam_initial_state(f.p, st);
  double w = 0, e_prev = 0, e_at_turn = 0;
  for (std::size_t k = 0; k < path.size(); ++k) {
    const double e = path[k];
    const double eps[6] = {-e, 0, 0, 0, 0, 0};
    const double de[6] = {-(e - e_prev), 0, 0, 0, 0, 0};
    const double s_old = sig[0];
    foam_point(f.p, eps, de, 0.0, 1.0, sig, st);
    w += 0.5 * (s_old + sig[0]) * (-(e - e_prev));
    if (k == 599) e_at_turn = st[kFoamE];
    // Below the end of the drop the stress is the unloading curve.
    if (k >= 600 && e < 0.55) {
      INFO("unloading, e " << e);
      CHECK(std::abs(sig[0] + unload_curve(e)) <= kRound * 3.0);
    }
    e_prev = e;
  }
  // Areas under L and U from 0 to 0.6 (trapezoids of the piecewise-linear curves).
  const double area_l = 0.5 * 0.1 * 1.0 + 0.5 * (1.0 + 1.2) * 0.4 + 0.5 * (1.2 + 1.8) * 0.1;
  const double area_u = 0.5 * 0.5 * 0.3 + 0.5 * (0.3 + 0.3 + 0.1 * 7.0 / 3.0) * 0.1;
  const double delta = load_curve(em) - unload_curve(em);
  const double expect = area_l - area_u - delta * delta / (2.0 * (e_at_turn - 7.0 / 3.0));
  INFO("dissipated " << w << " expected " << expect << " E at the turn " << e_at_turn);
  CHECK(e_at_turn >= 20.0);
  CHECK(e_at_turn <= 100.0);
  CHECK(std::abs(w - expect) <= 1e-4 * (area_l - area_u));
  CHECK(std::abs(sig[0]) <= kRound);  // back at zero strain, no stress
}

TEST_CASE("Law 70 interpolates the loading curves linearly in the strain rate", "[law70]") {
  // Curves L at rate 0 and 2 L at rate 10: at rate 2.5 the stress is 1.25 L, at 10 it is 2 L, at 15 (beyond
  // the last rate, extrapolated with the last interval) 2.5 L. E0 = 40 stays above every slope (25 at
  // most), so the loading follows the interpolated curve (the law takes min(curve, elastic trial)).
  const auto f = foam(0, true, {0.0, 10.0}, {1.0, 2.0}, 1, 1, 40.0);
  const auto path = ramp(0.0, 0.75, 300);
  for (const auto& [rate, factor] :
       std::vector<std::pair<double, double>>{{2.5, 1.25}, {10.0, 2.0}, {15.0, 2.5}}) {
    const auto s = drive(f.p, path, rate);
    for (std::size_t k = 0; k < path.size(); ++k) {
      INFO("rate " << rate << " e " << path[k]);
      CHECK(std::abs(s[k] + factor * load_curve(path[k])) <= kRound * 10.0);
    }
  }
}

TEST_CASE("Law 70 Iflag 4 unloads the stress by the energy ratio (Shape, Hys)", "[law70]") {
  // Iflag 4 without unloading curve: on unloading sigma = -L(e) (1 - (1 - Hys)(1 - (W/W_max)^Shape)),
  // W(e) = int_0^e L (the static curve), W_max = W(e_m). W is integrated by the law with trapezoids of
  // 2000 steps: its relative error on the kinks of L is below 1e-6, the stress tolerance 1e-5 of L. The
  // law's first step takes the static curve's previous value as 1 (m70init.F starts it so), which adds
  // de_1 / 2 to W and W_max: part of the closed form.
  const double shape = 2.0, hys = 0.2, em = 0.7;
  const auto f = foam(4, false, {0.0}, {1.0}, shape, hys);
  auto path = ramp(0.0, em, 2000);
  const auto down = ramp(em, 0.0, 2000);
  path.insert(path.end(), down.begin(), down.end());
  auto integral = [](double e) {
    double w = 0;
    const double xs[4] = {0.0, 0.1, 0.5, 0.8};
    for (int i = 0; i < 3; ++i) {
      const double a = xs[i], b = std::min(e, xs[i + 1]);
      if (b <= a) break;
      w += 0.5 * (load_curve(a) + load_curve(b)) * (b - a);
    }
    return w;
  };
  const double w0 = 0.5 * em / 2000;  // the first step's extra (1 + L(0)) de_1 / 2 - L(0) de_1 / 2
  const double wmax = integral(em) + w0;
  const auto s = drive(f.p, path, 0.0);
  for (std::size_t k = 2000; k < path.size(); ++k) {
    const double e = path[k];
    const double r = 1.0 - (1.0 - hys) * (1.0 - std::pow((integral(e) + w0) / wmax, shape));
    INFO("e " << e);
    CHECK(std::abs(s[k] + load_curve(e) * r) <= 1e-5 * load_curve(em));
  }
}

TEST_CASE("Law 70 in the one-point brick is objective: a rigid rotation gives no stress", "[law70][hex8]") {
  // A unit cube driven homogeneously with exact mid-step velocities. (a) Turned rigidly by 0.9 rad about an
  // inclined axis, v = w x x: the strain V - I stays 0 and so does the stress (round-off). (b) Stretched to
  // x = U X (N steps), then turned rigidly (N steps): the stress turns with it, sigma = Q sigma(U) Q^T. In
  // Iframe 1 the rotation has D = 0 exactly and the Jaumann update does not lower the stress norm, so the
  // law keeps the loading curve's norm: round-off. In Iframe 2 the co-rotational increment's second-order
  // term (-dt/2 L'^T L', docs/theory/elements.md 3.6) lowers the elastic trial by up to E w^2 dt^2 / 2 a
  // step, at most E w^2 dt T / 2 over the rotation: that bound is the tolerance.
  const auto f = foam(0, true);
  const std::array<std::array<double, 3>, 8> X = {
      {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}};
  const double axis[3] = {0.48, 0.6, 0.64};  // unit
  const double theta = 0.9;
  const int n = 4000;
  const double dt = 1.0 / n;  // each phase lasts T = 1
  const double U[3][3] = {{0.8, 0.05, 0}, {0.05, 0.95, 0.02}, {0, 0.02, 0.9}};
  auto rot = [&](double a, double Q[3][3]) {  // Rodrigues
    const double c = std::cos(a), s = std::sin(a), k[3] = {axis[0], axis[1], axis[2]};
    const double K[3][3] = {{0, -k[2], k[1]}, {k[2], 0, -k[0]}, {-k[1], k[0], 0}};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        double kk = 0;
        for (int l = 0; l < 3; ++l) kk += K[i][l] * K[l][j];
        Q[i][j] = (i == j ? 1.0 : 0.0) + s * K[i][j] + (1 - c) * kk;
      }
  };
  auto run = [&](int iframe, bool stretch, double out[6], double out_u[6]) {
    std::vector<std::array<double, 3>> x0(X.begin(), X.end());
    auto nodes = radx::test::make_nodes(x0);
    BrickGroup g;
    g.allocate(1);
    g.iframe = iframe;
    g.qa = g.qb = 0.0;
    double xa[8][3];
    for (std::size_t k = 0; k < 8; ++k) {
      g.conn[k * kGroupSize] = static_cast<std::int32_t>(k);
      for (std::size_t d = 0; d < 3; ++d) xa[k][d] = X[k][d];
    }
    g.set_reference(0, xa);
    g.foam.assign(static_cast<std::size_t>(kFoamVars) * kGroupSize, 0.0);
    double st[kFoamVars];
    foam_initial_state(f.p, st);
    for (std::size_t v = 0; v < static_cast<std::size_t>(kFoamVars); ++v) g.foam[v * kGroupSize] = st[v];
    g.vol0[0] = g.vol[0] = 1.0;
    g.rho[0] = f.p.rho0;
    CycleInfo cyc;
    cyc.dt1 = dt;
    double A[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    if (stretch) {
      for (int k = 1; k <= n; ++k) {
        const double sk = double(k) / n;
        for (std::size_t q = 0; q < 8; ++q) {
          double y[3], v[3];
          for (int a = 0; a < 3; ++a) {
            y[a] = X[q][static_cast<std::size_t>(a)];
            v[a] = 0;
            for (int b = 0; b < 3; ++b) {
              const double du = U[a][b] - (a == b ? 1.0 : 0.0);
              y[a] += sk * du * X[q][static_cast<std::size_t>(b)];
              v[a] += du * X[q][static_cast<std::size_t>(b)];
            }
          }
          nodes.x[q] = y[0], nodes.y[q] = y[1], nodes.z[q] = y[2];
          nodes.vx[q] = v[0], nodes.vy[q] = v[1], nodes.vz[q] = v[2];
        }
        hex8_forces(g, nodes, f.p, cyc);
      }
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) A[a][b] = U[a][b];
      brick_global_stress(g, 0, out_u);
    }
    for (int k = 1; k <= n; ++k) {
      double Q[3][3];
      rot(theta * k / n, Q);
      for (std::size_t q = 0; q < 8; ++q) {
        double y[3] = {0, 0, 0};
        for (int a = 0; a < 3; ++a)
          for (int b = 0; b < 3; ++b)
            for (int c = 0; c < 3; ++c) y[a] += Q[a][b] * A[b][c] * X[q][static_cast<std::size_t>(c)];
        const double w[3] = {theta * axis[0], theta * axis[1], theta * axis[2]};  // v = w x x
        nodes.x[q] = y[0], nodes.y[q] = y[1], nodes.z[q] = y[2];
        nodes.vx[q] = w[1] * y[2] - w[2] * y[1];
        nodes.vy[q] = w[2] * y[0] - w[0] * y[2];
        nodes.vz[q] = w[0] * y[1] - w[1] * y[0];
      }
      hex8_forces(g, nodes, f.p, cyc);
    }
    brick_global_stress(g, 0, out);
  };
  double Q[3][3];
  rot(theta, Q);
  for (int iframe : {1, 2}) {
    INFO("Iframe " << iframe);
    double s_rot[6], s_u[6], s_qu[6], dummy[6];
    run(iframe, false, s_rot, dummy);
    for (double v : s_rot) CHECK(std::abs(v) <= kRound);
    run(iframe, true, s_qu, s_u);
    const double su[3][3] = {{s_u[0], s_u[3], s_u[5]}, {s_u[3], s_u[1], s_u[4]}, {s_u[5], s_u[4], s_u[2]}};
    double r[3][3] = {};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k)
          for (int l = 0; l < 3; ++l) r[i][j] += Q[i][k] * su[k][l] * Q[j][l];
    const double expect[6] = {r[0][0], r[1][1], r[2][2], r[0][1], r[1][2], r[2][0]};
    double scale = 0;
    for (double v : s_u) scale = std::max(scale, std::abs(v));
    CHECK(scale > 0.1);
    const double tol = iframe == 1 ? 1e-10 * scale : 100.0 * theta * theta * dt / 2.0;  // E_max = 100
    for (int m = 0; m < 6; ++m) {
      INFO("component " << m << " got " << s_qu[m] << " expected " << expect[m]);
      CHECK(std::abs(s_qu[m] - expect[m]) <= tol);
    }
  }
}

TEST_CASE("Law 70 in the one-point brick: the internal energy of a crush is the area under the curve",
          "[law70][hex8]") {
  // A unit cube crushed along z to the height 1 - e_m (e_m = 0.6) with exact mid-step velocities, sides free
  // (nu = 0: no lateral stress, no lateral strain). The strain V - I is then -e with e = 1 - h, the Cauchy
  // stress -L(e) on the current area 1, so the work per unit initial volume is int_0^e_m L de. The kernel's
  // energy trapezoid on D taken at x^n is first order in the step: 1e-3 of the work allowed with 4000 steps.
  const auto f = foam(0, true);
  const std::array<std::array<double, 3>, 8> X = {
      {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}};
  std::vector<std::array<double, 3>> x0(X.begin(), X.end());
  auto nodes = radx::test::make_nodes(x0);
  BrickGroup g;
  g.allocate(1);
  g.qa = g.qb = 0.0;
  double xa[8][3];
  for (std::size_t k = 0; k < 8; ++k) {
    g.conn[k * kGroupSize] = static_cast<std::int32_t>(k);
    for (std::size_t d = 0; d < 3; ++d) xa[k][d] = X[k][d];
  }
  g.set_reference(0, xa);
  g.foam.assign(static_cast<std::size_t>(kFoamVars) * kGroupSize, 0.0);
  double st[kFoamVars];
  foam_initial_state(f.p, st);
  for (std::size_t v = 0; v < static_cast<std::size_t>(kFoamVars); ++v) g.foam[v * kGroupSize] = st[v];
  g.vol0[0] = g.vol[0] = 1.0;
  g.rho[0] = f.p.rho0;
  const int n = 4000;
  const double em = 0.6, dt = 1.0 / n;
  CycleInfo cyc;
  cyc.dt1 = dt;
  for (int k = 1; k <= n; ++k) {
    const double h = 1.0 - em * k / n;
    for (std::size_t q = 0; q < 8; ++q) {
      nodes.z[q] = X[q][2] * h;
      nodes.vz[q] = -em * X[q][2];
    }
    hex8_forces(g, nodes, f.p, cyc);
  }
  const double area = 0.5 * 0.1 * 1.0 + 0.5 * (1.0 + 1.2) * 0.4 + 0.5 * (1.2 + 1.8) * 0.1;
  INFO("internal energy " << g.e_int[0] << " area " << area);
  CHECK(std::abs(g.e_int[0] - area) <= 1e-3 * area);
  double s[6];
  brick_global_stress(g, 0, s);
  CHECK(std::abs(s[2] + load_curve(em)) <= 1e-9);
}

TEST_CASE("Law 70 tables of more than 100 points are thinned by least triangle area", "[law70]") {
  // y = x^2 at x = 0, 1, .., 100 (101 points): every interior triangle has the same area (twice it: 2), so
  // the first interior point goes. The same curve with y(50) on the chord of its neighbours (area 0):
  // that point goes. Either way 100 points remain, the others unchanged.
  std::vector<double> x, y;
  for (int k = 0; k <= 100; ++k) {
    x.push_back(k);
    y.push_back(double(k) * k);
  }
  auto table = [&](const std::vector<double>& ys) {
    radx::model::FoamCurveInput c{x.data(), ys.data(), x.size(), 1.0, 0.0};
    return radx::model::build_foam_table({c});
  };
  const auto t1 = table(y);
  REQUIRE(t1.x.size() == 100);
  CHECK(t1.x[0] == 0.0);
  CHECK(t1.x[1] == 2.0);
  CHECK(t1.x[99] == 100.0);
  auto y2 = y;
  y2[50] = 0.5 * (y[49] + y[51]);
  const auto t2 = table(y2);
  REQUIRE(t2.x.size() == 100);
  CHECK(std::find(t2.x.begin(), t2.x.end(), 50.0) == t2.x.end());
  CHECK(std::find(t2.x.begin(), t2.x.end(), 1.0) != t2.x.end());
  for (std::size_t k = 0; k < t2.x.size(); ++k) CHECK(t2.y[k] == t2.x[k] * t2.x[k]);
}
