// LAW27 (/MAT/PLAS_BRIT, solver/materials/law27_plas_brit.cpp) at a single shell integration point and
// through the shell section, against values computed here from the formulas at the top of that file. Units:
// MPa, mm, s (aluminium-like). "Round-off" is 1e-12 relative: a few thousand ulps of the quantities involved,
// far below any modelling effect tested here.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "solver/elements/element_groups.hpp"
#include "solver/elements/shell/shell_section.hpp"
#include "solver/materials/material_point.hpp"
#include "test_util.hpp"

using radx::model::Material;
using radx::model::MaterialLaw;
using namespace radx::solver;

namespace {

constexpr double kRound = 1e-12;

using radx::test::close;

// E 71000, nu 0.33, a 290, b 562.3, n 0.63, SIG_max0 425 (the LOI27 QA aluminium), crack off unless set.
Material brit(double eps_t = 0, double eps_m = 0, double d_max = 0, double eps_f = 0) {
  Material m;
  m.law = MaterialLaw::PlasBrit;
  m.rho = 2.8e-9;
  m.young = 71000.0;
  m.poisson = 0.33;
  m.a = 290.0;
  m.b = 562.3;
  m.n = 0.63;
  m.sig_max0 = 425.0;
  m.brit.eps_t1 = eps_t;
  m.brit.eps_m1 = eps_m;
  m.brit.d_max1 = d_max;
  m.brit.eps_f1 = eps_f;
  return m;
}

// One point: its stress, plastic strain and crack state (kBritVars rows, stride 1).
struct Point {
  double sig[5] = {0, 0, 0, 0, 0};
  double eps_p = 0;
  double st[kBritVars] = {0, 0, 0, 1, 0, 0, 0};
  ShellPointResult step(const MaterialParams& p, const double de[5], int iplas = 0, double rate = 0,
                        double dt1 = 1e-6) {
    return detail::law27_shell_point(p, iplas, rate, dt1, 1.0, de, p.shear * 5.0 / 6.0, sig, eps_p, st, 1);
  }
};

double vm_plane(const double* s) {
  return std::sqrt(s[0] * s[0] + s[1] * s[1] - s[0] * s[1] + 3.0 * s[2] * s[2]);
}

// Components xx yy xy (tensor shear) of a plane tensor in a frame turned by theta, and yz zx.
void rotate(double theta, const double in[5], double out[5]) {
  const double c = std::cos(theta), s = std::sin(theta);
  out[0] = c * c * in[0] + s * s * in[1] + 2 * c * s * in[2];
  out[1] = s * s * in[0] + c * c * in[1] - 2 * c * s * in[2];
  out[2] = c * s * (in[1] - in[0]) + (c * c - s * s) * in[2];
  out[3] = c * in[3] - s * in[4];
  out[4] = s * in[3] + c * in[4];
}

}  // namespace

TEST_CASE(
    "law 27 uniaxial stress: sigma = min(a + b eps_p^n, SIG_max0) of the step's start, sigma/E + eps_p "
    "= eps",
    "[material][law27]") {
  // de = (d, -nu d): elastic sigma_yy stays 0 (A12 d - nu A11 d = 0) and the radial return scales it, so the
  // path is uniaxial stress in x. Radial return (Iplas 0): sigma_new = sigma_y(eps_p old) and d_eps_p =
  // (svm - sigma_y)/E, hence sigma/E + eps_p = sum of d exactly. Strain to 0.2: the cap 425 holds from
  // eps_p = (135 / 562.3)^(1 / 0.63) = 0.104 on.
  const MaterialParams p = make_material_params(brit());
  Point pt;
  const double d = 1e-4;
  double eps = 0;
  bool yielded = false, capped = false;
  for (int k = 0; k < 2000; ++k) {
    const double de[5] = {d, -p.nu * d, 0, 0, 0};
    const double ep_old = pt.eps_p;
    const double sx_old = pt.sig[0];
    pt.step(p, de);
    eps += d;
    const double flow = std::min(p.jc.a + p.jc.b * std::pow(ep_old, p.jc.n), p.jc.sig_max0);
    if (pt.eps_p > ep_old) {
      yielded = true;
      capped = capped || flow == p.jc.sig_max0;
      REQUIRE(close(pt.sig[0], flow, kRound));  // on the yield surface of the step's start
    } else {
      REQUIRE(close(pt.sig[0], sx_old + p.young * d, kRound, 1e-9));  // elastic: E d
    }
    REQUIRE(std::abs(pt.sig[1]) <= 1e-9);
    REQUIRE(close(pt.sig[0] / p.young + pt.eps_p, eps, kRound));
  }
  CHECK(yielded);
  CHECK(capped);
  // First yield at eps = a/E: the elastic stretch ends within one step of it.
  CHECK(pt.eps_p == Approx(eps - p.jc.sig_max0 / p.young).epsilon(kRound));
}

TEST_CASE("law 27 yield consistency (Iplas 1 biaxial) and elastic unloading", "[material][law27]") {
  // Iplas 1: three Newton steps of LAW2's projection, with the hardening slope of the step's start, put the
  // stress on sigma_y(eps_p new) = a + b eps_p^n (no cap). At first yield the slope n b eps_p^(n-1) of n =
  // 0.63 is unbounded and the first two plastic steps miss by up to 0.6 %; once eps_p > 3e-4 the slope
  // changes little over a step and the residual is below 1e-5 of sigma_y (measured 4e-6 falling to 8e-8).
  Material m = brit();
  m.sig_max0 = 0;  // no cap
  const MaterialParams p = make_material_params(m);
  Point pt;
  for (int k = 0; k < 200; ++k) {
    const double de[5] = {1e-4, 0.5e-4, 0.6e-4, 0, 0};
    const double ep_old = pt.eps_p;
    pt.step(p, de, 1);
    if (ep_old > 3e-4) {
      const double sy = p.jc.a + p.jc.b * std::pow(pt.eps_p, p.jc.n);
      REQUIRE(close(vm_plane(pt.sig), sy, 1e-5));
    }
  }
  REQUIRE(pt.eps_p > 0.005);
  // Unloading: the increment of the stress is the plane-stress elasticity, eps_p unchanged.
  const double before[3] = {pt.sig[0], pt.sig[1], pt.sig[2]};
  const double ep = pt.eps_p;
  const double de[5] = {-2e-4, -1e-4, -1.2e-4, 0, 0};  // the loading path reversed
  pt.step(p, de, 1);
  CHECK(pt.eps_p == ep);
  CHECK(close(pt.sig[0], before[0] + p.a11 * de[0] + p.a12 * de[1], kRound));
  CHECK(close(pt.sig[1], before[1] + p.a12 * de[0] + p.a11 * de[1], kRound));
  CHECK(close(pt.sig[2], before[2] + p.shear * de[2], kRound));
}

TEST_CASE("law 27 crack in uniaxial tension: opening damage, damaged stiffness and deletion by the formulas",
          "[material][law27]") {
  // Elastic-brittle (a = 0 -> 1e20, no cap). EPS_t1 0.01, EPS_m1 0.02, d_max1 0.9, EPS_f1 0.0301 (not a
  // multiple of the step, so that the summed strain is not compared with it at round-off). Uniaxial stress in
  // x (de = (d, -nu d)) until the crack opens: at the first step with eps_xx >= 0.01 the crack takes
  // direction (1, 0) (no shear: the principal direction is x) and d0 = (eps - 0.01)/0.01; its stiffness acts
  // from the next step on. From then de = (d, 0): with the crack open there is no Poisson coupling, sigma_yy
  // stays 0, and the elastic strain e = sigma/((1 - d) E) grows by d each step:
  //   sigma_m = (1 - d_m) E (sigma_t / ((1 - d0) E) + m d),  d_m = min(max(d0, m d / 0.01), 0.9).
  Material m = brit(0.01, 0.02, 0.9, 0.0301);
  m.a = 0;
  m.sig_max0 = 0;
  const MaterialParams p = make_material_params(m);
  Point pt;
  const double d = 3e-4;
  double eps = 0;
  int k = 0;
  for (; k < 1000 && pt.st[kBritDamage] == 0.0; ++k) {
    const double de[5] = {d, -p.nu * d, 0, 0, 0};
    pt.step(p, de);
    eps += d;
  }
  REQUIRE(pt.st[kBritDamage] > 0.0);
  CHECK(eps >= 0.01);
  CHECK(eps - d < 0.01);
  const double d0 = (eps - 0.01) / 0.01;
  CHECK(close(pt.st[kBritDamage], d0, 1e-9));
  CHECK(pt.st[kBritCos] == 1.0);
  CHECK(pt.st[kBritSin] == 0.0);
  CHECK(close(pt.sig[0], p.young * eps, kRound));  // the opening step itself is undamaged
  const double sigma_t = pt.sig[0];
  bool deleted = false;
  for (int mstep = 1; mstep <= 100 && !deleted; ++mstep) {
    const double de[5] = {d, 0, 0, 0, 0};
    const ShellPointResult r = pt.step(p, de);
    eps += d;
    const double dm = std::min(std::max(d0, mstep * d / 0.01), 0.9);
    REQUIRE(close(pt.st[kBritDamage], dm, 1e-9));
    REQUIRE(close(pt.sig[0], (1.0 - dm) * p.young * (sigma_t / ((1.0 - d0) * p.young) + mstep * d), 1e-9));
    REQUIRE(std::abs(pt.sig[1]) <= 1e-9);
    // EPS_f1: deleted in the step the principal strain (here eps_xx) first passes 0.0301.
    deleted = r.fails;
    REQUIRE(deleted == (eps > 0.0301));
  }
  CHECK(deleted);
  // Compression closes the crack (D1 = 1 for s1 < 0, so k = 1): from a compressive stress the update is the
  // intact plane-stress elasticity s += A de, whatever the damage.
  pt.sig[0] = -10.0;
  pt.sig[1] = 0.0;
  const double de[5] = {-1e-4, 0, 0, 0, 0};
  pt.step(p, de);
  CHECK(close(pt.sig[0], -10.0 + p.a11 * de[0], kRound));
  CHECK(close(pt.sig[1], p.a12 * de[0], kRound));
}

TEST_CASE("law 27 crack direction: the largest principal strain's, and the point objective under rotation",
          "[material][law27]") {
  // The same strain history in the element frame and in one turned by 0.7 rad: the stresses are the turned
  // ones and the damages equal (every law-27 formula is isotropic except its crack frame, which follows the
  // principal direction). Plasticity and the crack both act (a 290, EPS_t1 0.004). c = 0: the Fsmooth-0
  // rate measure max(|de1|, |de2|, |dg12|/2) is not objective (OpenRadioss m27plas.F), with c = 0 it is
  // unused.
  const MaterialParams p = make_material_params(brit(0.004, 0.02, 0.9, 0.5));
  const double theta = 0.7;
  Point a, b;
  for (int k = 0; k < 120; ++k) {
    const double ramp = k < 60 ? 1.0 : -0.5;  // load, then unload into compression along x
    const double de_t[5] = {1e-4 * ramp, 0.3e-4, 0.4e-4 * ramp, 1e-5, -2e-5};  // tensor shears
    double de_r[5];
    rotate(theta, de_t, de_r);
    const double ea[5] = {de_t[0], de_t[1], 2 * de_t[2], 2 * de_t[3], 2 * de_t[4]};
    const double eb[5] = {de_r[0], de_r[1], 2 * de_r[2], 2 * de_r[3], 2 * de_r[4]};
    a.step(p, ea);
    b.step(p, eb);
    double sa_r[5];
    rotate(theta, a.sig, sa_r);
    for (int c = 0; c < 5; ++c) REQUIRE(close(b.sig[c], sa_r[c], 1e-9, 1e-9 * vm_plane(a.sig)));
    REQUIRE(close(b.eps_p, a.eps_p, 1e-9, 1e-15));
    REQUIRE(close(b.st[kBritDamage], a.st[kBritDamage], 1e-9, 1e-15));
  }
  REQUIRE(a.eps_p > 0);
  REQUIRE(a.st[kBritDamage] > 0);
  // The crack normal is the principal direction of the total strain when it opened: (c, s) with
  // (exx - e1) c + exy s = 0. Checked on the final strain's frame only loosely: the normal is a unit vector.
  CHECK(close(a.st[kBritCos] * a.st[kBritCos] + a.st[kBritSin] * a.st[kBritSin], 1.0, kRound));
}

TEST_CASE("law 27 crack normal along a 45-degree principal strain", "[material][law27]") {
  // Pure shear strain gxy = 2 g (tensor g): principal strains +-g along (1, 1)/sqrt 2 and (1, -1)/sqrt 2. The
  // crack opens at g >= EPS_t1 along (1, 1)/sqrt 2.
  Material m = brit(0.002, 0.01, 0.9, 0.5);
  m.a = 0;
  m.sig_max0 = 0;
  const MaterialParams p = make_material_params(m);
  Point pt;
  for (int k = 0; k < 100 && pt.st[kBritDamage] == 0.0; ++k) {
    const double de[5] = {0, 0, 2e-4, 0, 0};
    pt.step(p, de);
  }
  REQUIRE(pt.st[kBritDamage] > 0);
  CHECK(close(pt.st[kBritCos], std::numbers::sqrt2 / 2, kRound));
  CHECK(close(pt.st[kBritSin], std::numbers::sqrt2 / 2, kRound));
}

TEST_CASE("law 27 through the shell section: every point cracks, EPS_f1 deletes the element at once",
          "[shell][law27]") {
  // Membrane stretch (1e-4 per cycle in x, -nu 1e-4 in y), three points. The section reports fail_now (OFF
  // 0 through next_off) in the cycle the strain first passes EPS_f1 = 0.01205, i.e. cycle 121.
  using namespace radx::solver::shell_detail;
  Material m = brit(0.01, 0.02, 0.9, 0.01205);
  m.a = 0;
  m.sig_max0 = 0;
  const MaterialParams p = make_material_params(m);
  ShellGroup g;
  g.allocate(1, 3);
  g.allocate_brit();
  const ThicknessRule rule = thickness_rule(3);
  SectionBlock<4> s{};
  s.dt1 = 1e-6;
  int cycle = 0;
  for (; cycle < 1000; ++cycle) {
    s.dem[0][0] = 1e-4;
    s.dem[1][0] = -p.nu * 1e-4;
    for (int c = 2; c < 5; ++c) s.dem[c][0] = 0;
    for (int c = 0; c < 3; ++c) s.dk[c][0] = 0;
    s.t[0] = s.area[0] = 1.0;
    s.rfac[0] = 1.0;
    s.rate[0] = 0.0;
    s.off[0] = 1.0;
    section_update_block(g, 0, 1, p, rule, p.shear * 5.0 / 6.0, s);
    if (next_off(failure_limit(p), 1.0, s.eps_p_max[0], s.fail_now[0]) != 1.0) break;
  }
  CHECK(cycle + 1 == 121);  // 121 x 1e-4 = 0.0121 > 0.01205 > 120 x 1e-4
  for (int q = 0; q < 3; ++q)
    CHECK(g.brit[(static_cast<std::size_t>(q) * kBritVars + kBritDamage) * kGroupSize] > 0.0);
}

TEST_CASE("law 27 reader: cards, defaults, and refusals", "[law27][parser]") {
  using radx::test::begin_block;
  using radx::test::Line;
  auto deck = [](double eps_t1, double eps_m1, double fcut) {
    std::string s = begin_block(2026, "Mg mm s");
    s += "/MAT/PLAS_BRIT/3\nglass\n" + Line().put(2.8e-9, 1, 20).str() + "\n" +
         Line().put(71000.0, 1, 20).put(0.33, 21, 40).str() + "\n" +
         Line().put(290.0, 1, 20).put(562.3, 21, 40).put(0.0, 41, 60).put(425.0, 81, 100).str() + "\n" +
         Line().put(0.0, 1, 20).put(0.0, 21, 40).put(0, 41, 50).put(0, 51, 60).put(fcut, 61, 80).str() +
         "\n" + Line().put(eps_t1, 1, 20).put(eps_m1, 21, 40).put(0.0, 41, 60).put(0.151, 61, 80).str() +
         "\n" + Line().put(0.0, 1, 20).str() + "\n/END\n";
    return s;
  };
  const auto m = radx::test::model_of_deck(deck(0.14, 0.15, 0.0));
  REQUIRE(m.materials.size() == 1);
  const auto& mat = m.materials[0];
  CHECK(mat.law == MaterialLaw::PlasBrit);
  CHECK(mat.a == 290.0);
  CHECK(mat.n == 1.0);              // 0 -> 1
  CHECK(mat.icc == 1);              // 0 -> 1
  CHECK(mat.eps_dot_0 == 1.0);      // c = 0
  CHECK(mat.brit.d_max1 == 0.999);  // 0 -> 0.999
  CHECK(mat.brit.eps_t1 == 0.14);
  CHECK(mat.brit.eps_f1 == 0.151);
  CHECK(mat.fsmooth == 0);
  CHECK(make_material_params(mat).brit.point_rate);
  // Fcut given: Fsmooth 1, the element's filtered rate.
  const auto f = radx::test::model_of_deck(deck(0.14, 0.15, 5000.0));
  CHECK(f.materials[0].fsmooth == 1);
  CHECK_FALSE(make_material_params(f.materials[0]).brit.point_rate);
  // The refusals (EPS_m1 <= EPS_t1, d_max1 >= 1, law 27 on bricks, N = 0) are the decks/invalid/plas_brit_*
  // cases (scripts/make_invalid_decks.py).
}
