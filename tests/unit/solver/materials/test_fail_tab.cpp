// /FAIL/TAB (solver/materials/fail_tab.cpp) and the damage stage it shares with /FAIL/JOHNSON
// (solver/materials/failure_damage.cpp): the failure strain from the triaxiality tables, the rate
// interpolation, the temperature and element-size factors, the damage integral with the exponent n and Dcrit,
// what a failed point does, the shell section's deletion by Ifail_sh and P_thickfail, and the starter's
// reading of the keyword. Expected values are computed here from the formulas at the top of those files.
// Units: MPa, mm, s.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "solver/elements/element_groups.hpp"
#include "solver/elements/shell/shell_section.hpp"
#include "solver/engine/explicit_engine.hpp"
#include "solver/materials/material_point.hpp"
#include "test_util.hpp"

using radx::model::Function;
using radx::model::Material;
using radx::model::MaterialLaw;
using namespace radx::solver;

namespace {

constexpr double kRound = 1e-12;  // relative round-off of a few operations

using radx::test::close;

Function curve(std::vector<double> x, std::vector<double> y) {
  Function f;
  f.x = std::move(x);
  f.y = std::move(y);
  return f;
}

// Functions: 0 the hardening curve of the law-36 material, 1 eps_f(triaxiality) = 0.3 - 0.2 eta (points at
// -0.5 and 0.5), 2 a constant eps_f = 0.02, 3 the size factor f(L / Lref) = L / Lref (points 0 and 10).
const std::vector<Function> kFns = {
    curve({0.0, 0.05, 0.1, 0.3, 1.0}, {200.0, 260.0, 300.0, 350.0, 400.0}),
    curve({-0.5, 0.5}, {0.4, 0.2}),
    curve({-1.0, 1.0}, {0.02, 0.02}),
    curve({0.0, 10.0}, {0.0, 10.0}),
};

// A law-36 material (curve 0) with a /FAIL/TAB whose rows are (function, scale, rate).
Material tab_material(const std::vector<std::array<double, 3>>& rows) {
  Material m;
  m.law = MaterialLaw::PlasTab;
  m.rho = 7.85e-9;
  m.young = 210000.0;
  m.poisson = 0.3;
  m.tab.function_id = {1};
  m.tab.function = {0};
  m.tab.scale = {1.0};
  m.tab.rate = {0.0};
  auto& f = m.fail_tab;
  f.on = true;
  for (const auto& r : rows) {
    f.function_id.push_back(static_cast<std::int64_t>(r[0]) + 1);
    f.function.push_back(static_cast<std::int32_t>(r[0]));
    f.scale.push_back(r[1]);
    f.rate.push_back(r[2]);
  }
  return m;
}

}  // namespace

TEST_CASE("FAIL/TAB failure strain: the triaxiality table, linear in the rate between rows and beyond them",
          "[material][fail][failtab]") {
  // Rows: f1 x 1 at rate 1, f1 x 2 at rate 11. f1(eta) = 0.3 - 0.2 eta. Between the rows the weight is
  // (rate - 1)/10; beyond them the end segment extrapolates (OpenRadioss's table does not clamp).
  Material m = tab_material({{1, 1.0, 1.0}, {1, 2.0, 11.0}});
  std::vector<TabCurve> curves;
  MaterialParams p = make_material_params(m, kFns, curves);
  REQUIRE(p.fail.kind == FailKind::Tab);
  REQUIRE(p.fail.n_rows == 2);
  REQUIRE(p.tab.n_curves == 1);  // the law-36 curve is kept in front of the rows
  auto expect = [](double eta, double rate) {
    const double f = 0.3 - 0.2 * eta;
    return f * (1.0 + (rate - 1.0) / 10.0);
  };
  for (const double eta : {-1.0, -1.0 / 3.0, 0.0, 1.0 / 3.0, 2.0 / 3.0})
    for (const double rate : {0.0, 1.0, 6.0, 11.0, 16.0})
      CHECK(close(fail_tab_strain(p.fail, eta * 300.0, 300.0, rate), expect(eta, rate), kRound));
  // One row: no rate effect (OpenRadioss builds two identical rows).
  Material m1 = tab_material({{1, 1.5, 5.0}});
  std::vector<TabCurve> c1;
  const MaterialParams p1 = make_material_params(m1, kFns, c1);
  for (const double rate : {0.0, 5.0, 1e3})
    CHECK(close(fail_tab_strain(p1.fail, 100.0, 300.0, rate), 1.5 * (0.3 - 0.2 / 3.0), kRound));
  // The constant temperature factor multiplies; the size factor is Fscale_el f(L / EI_ref).
  m1.fail_tab.temp_factor = 0.5;
  m1.fail_tab.size_function = 3;
  m1.fail_tab.size_scale = 2.0;
  m1.fail_tab.el_ref = 4.0;
  const MaterialParams p2 = make_material_params(m1, kFns, c1);
  CHECK(close(fail_tab_strain(p2.fail, 100.0, 300.0, 0.0), 0.5 * 1.5 * (0.3 - 0.2 / 3.0), kRound));
  CHECK(close(fail_size_factor(p2.fail, 2.0), 2.0 * 0.5, kRound));
  CHECK(close(fail_size_factor(p2.fail, 6.0), 2.0 * 1.5, kRound));
  CHECK(fail_size_factor(p1.fail, 6.0) == 1.0);  // no size function
  CHECK(close(fail_strain(p2.fail, 100.0, 300.0, 0.0, 3.0), 3.0 * 0.5 * 1.5 * (0.3 - 0.2 / 3.0), kRound));
}

TEST_CASE(
    "FAIL/TAB damage at constant triaxiality: D = (eps_p / eps_f)^n, the point fails at eps_f Dcrit^(1/n)",
    "[material][fail][failtab]") {
  // The damage stage alone, with a constant plastic increment h eps_f per step (proportional straining at a
  // constant triaxiality, eps_f constant). Closed form of dD = n D^(1 - 1/n) d_eps_p / eps_f from D = 0:
  // D = (eps_p / eps_f)^n. The update is explicit and its first step takes the factor 1 (D = 0), so
  // u = D^(1/2) (n = 2) follows u_1 = sqrt(h), u_k+1 = sqrt(u_k^2 + 2 u_k h): between
  // sqrt(h) + (x - h)(1 - sqrt(h)/2) and sqrt(h) + x - h with x = eps_p / eps_f (bounds derived from
  // u_k+1 - u_k in [h (1 - sqrt(h)/2), h]); the error is the first step's, O(sqrt(h)).
  Material m = tab_material({{1, 1.0, 0.0}});
  m.fail_tab.n = 2.0;
  m.fail_tab.dcrit = 0.64;  // fails at x = sqrt(0.64) = 0.8
  std::vector<TabCurve> curves;
  const MaterialParams p = make_material_params(m, kFns, curves);
  const double eps_f = 0.3;  // eta = 0
  for (const double h : {1e-4, 1e-6}) {
    double dmg = 0;
    int k = 0;
    bool failed = false;
    while (!failed && k < 10000000) {
      ++k;
      failed = fail_accumulate(p.fail, 0.0, 300.0, 0.0, 1.0, h * eps_f, dmg);
      const double x = k * h;
      if (!failed) {
        const double u = std::sqrt(dmg * 0.64);
        const double sh = std::sqrt(h);
        CHECK(u <= sh + x - h + 1e-12);
        CHECK(u >= sh + (x - h) * (1.0 - sh / 2.0) - 1e-12);
      }
    }
    REQUIRE(failed);
    CHECK(dmg == 1.0);
    // Fails once u passes 0.8: at x within [0.8 - sqrt(h), 0.8 + h] (upper bound of u, then one step).
    CHECK(k * h >= 0.8 - std::sqrt(h) - h);
    CHECK(k * h <= 0.8 + h);
  }
  // n = 1: D = eps_p / eps_f exactly (to round-off), fails in the step eps_p reaches Dcrit eps_f.
  Material m1 = tab_material({{1, 1.0, 0.0}});
  m1.fail_tab.dcrit = 0.5;
  std::vector<TabCurve> c1;
  const MaterialParams p1 = make_material_params(m1, kFns, c1);
  double dmg = 0;
  int k = 0;
  for (; k < 1000 && dmg < 1.0; ++k) {
    fail_accumulate(p1.fail, 0.0, 300.0, 0.0, 1.0, 1e-3, dmg);
    if (dmg < 1.0) CHECK(close(dmg * 0.5, (k + 1) * 1e-3 / eps_f, 1e-11));
  }
  CHECK(k == 150);  // 0.5 x 0.3 / 1e-3
}

TEST_CASE("FAIL/TAB on a solid point: D = eps_p / eps_f of the table at the rate, Ifail_so 1, 2, 3",
          "[material][fail][failtab]") {
  // Isochoric stretch with mu = 0: tr(sigma) = 0, triaxiality 0; rows f1 x 1 at rate 1 and f1 x 2 at rate 11,
  // point rate 6: eps_f = 0.3 x 1.5 = 0.45; Dcrit 0.9: fails when eps_p reaches 0.405.
  for (const int ifail : {1, 2, 3}) {
    Material m = tab_material({{1, 1.0, 1.0}, {1, 2.0, 11.0}});
    m.fail_tab.dcrit = 0.9;
    m.fail_tab.ifail_so = ifail;
    std::vector<TabCurve> curves;
    const MaterialParams p = make_material_params(m, kFns, curves);
    const double d = 1e-3;
    const double de[6] = {d, -0.5 * d, -0.5 * d, 0.2 * d, 0, 0};
    double sig[6] = {0, 0, 0, 0, 0, 0};
    double eps_p = 0, dmg = 0;
    bool fails = false;
    for (int k = 0; k < 10000 && dmg < 1.0; ++k) {
      const double e_old = eps_p;
      const auto r = solid_point_update(p, 6.0, de, 0.0, sig, eps_p, dmg, 1.0);
      fails = r.element_fails;
      if (dmg < 1.0) {
        // eps_f at the stress's triaxiality, which is 0 up to the round-off of tr(sigma)
        CHECK(close(dmg, eps_p / 0.405, 1e-9));
        CHECK_FALSE(fails);
      } else {
        CHECK(e_old < 0.405 * (1 + 1e-9));
        CHECK(eps_p >= 0.405 * (1 - 1e-9));
      }
    }
    REQUIRE(dmg == 1.0);
    CHECK(fails == (ifail == 1));
    if (ifail != 1) {
      // One more step with a volume change (pressure -K mu): 2 sets the normal stresses to their mean and
      // keeps the shear (fail_tab_s.F), 3 keeps the stress as the material gives it.
      double ref[6];
      for (int c = 0; c < 6; ++c) ref[c] = sig[c];
      double ep_ref = eps_p;
      MaterialParams plain = p;
      plain.fail.on = false;
      solid_point_update(plain, 6.0, de, -1e-4, ref, ep_ref);
      const auto r = solid_point_update(p, 6.0, de, -1e-4, sig, eps_p, dmg, 1.0);
      CHECK_FALSE(r.element_fails);
      const double mean = (ref[0] + ref[1] + ref[2]) / 3.0;
      for (int c = 0; c < 3; ++c) CHECK(close(sig[c], ifail == 2 ? mean : ref[c], kRound, 1e-9));
      for (int c = 3; c < 6; ++c) CHECK(close(sig[c], ref[c], kRound, 1e-9));
      CHECK(std::abs(sig[3]) > 1.0);  // the shear is really there
    }
  }
}

TEST_CASE("FAIL/TAB: no softening before Dcrit (the stress is the material's until the point fails)",
          "[material][fail][failtab]") {
  // /FAIL/TAB has no fading exponent (OpenRadioss converts it to /FAIL/TAB1 with Fad_exp 0), so its D only
  // reaches Dcrit and the point fails: up to that step the shell point's stress is exactly the one of the
  // same material without the failure model; from it on, zero (Ifail_sh 1 and 2) or kept (Ifail_sh 3).
  for (const int ifail : {1, 3}) {
    Material m = tab_material({{2, 1.0, 0.0}});  // eps_f = 0.02
    m.fail_tab.ifail_sh = ifail;
    m.fail_tab.d = 0.5;  // the card's D: no effect
    std::vector<TabCurve> curves;
    const MaterialParams p = make_material_params(m, kFns, curves);
    MaterialParams plain = p;
    plain.fail.on = false;
    const double de[5] = {1e-4, -0.3e-4, 0.2e-4, 0, 0};
    double s1[5] = {0, 0, 0, 0, 0}, s2[5] = {0, 0, 0, 0, 0};
    double e1 = 0, e2 = 0, dmg = 0;
    bool seen_failure = false;
    for (int k = 0; k < 3000; ++k) {
      shell_point_update_fail(p, 0, 1.0, 0.0, 1.0, 1.0, de, 0.0, s1, e1, dmg);
      shell_point_update_r(plain, 0, 1.0, 1.0, de, 0.0, s2, e2);
      if (dmg < 1.0 || ifail == 3) {
        for (int c = 0; c < 5; ++c) CHECK(s1[c] == s2[c]);
      } else {
        for (int c = 0; c < 5; ++c) CHECK(s1[c] == 0.0);
        // the zero stress is put back into the next update: restart the reference from it
        for (int c = 0; c < 5; ++c) s2[c] = 0.0;
      }
      if (dmg >= 1.0 && !seen_failure) {
        seen_failure = true;
        CHECK(e1 >= 0.02 * (1 - 1e-9));
      }
    }
    CHECK(seen_failure);
  }
}

TEST_CASE("shell section with FAIL/TAB: Ifail_sh 1, 2, 3 with P_thickfail, and the element-size factor",
          "[shell][fail][failtab]") {
  // Three points through the thickness, pure bending: the surface points (weight 1/4 each) yield and fail
  // together at eps_p = eps_f = 0.02 x the element's size factor, the middle point never does.
  // Ifail_sh 1: deleted at the first failed point. Ifail_sh 2 and 3 delete when the failed weight (1/2)
  // reaches P_thickfail: 0.4 deletes, 0.6 does not; 2 zeroes a failed point's stress, 3 keeps it.
  using namespace radx::solver::shell_detail;
  struct Case {
    int ifail;
    double p_thick;
    double escale;
    bool deleted;
  };
  for (const Case c : {Case{1, 0.0, 1.0, true}, Case{2, 0.6, 1.0, false}, Case{3, 0.6, 1.0, false},
                       Case{3, 0.4, 1.0, true}, Case{1, 0.0, 0.5, true}}) {
    Material m = tab_material({{2, 1.0, 0.0}});
    m.fail_tab.ifail_sh = c.ifail;
    m.fail_tab.p_thickfail = c.p_thick;
    std::vector<TabCurve> curves;
    const MaterialParams p = make_material_params(m, kFns, curves);
    ShellGroup g;
    g.allocate(1, 3);
    g.fail_scale[0] = c.escale;
    const ThicknessRule rule = thickness_rule(3);
    SectionBlock<4> s{};
    bool deleted = false;
    double ep_before = 0;
    for (int step = 0; step < 400 && !deleted; ++step) {
      ep_before = g.eps_p[2 * kGroupSize];
      for (int k = 0; k < 5; ++k) s.dem[k][0] = 0;
      s.dk[0][0] = 2e-3;  // +-1e-3 strain at the surfaces of t = 1
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
    CHECK(d_top == 1.0);
    CHECK(deleted == c.deleted);
    if (c.deleted) {
      // deleted in the step the surface's eps_p passed 0.02 x escale
      CHECK(ep_before < 0.02 * c.escale * (1 + 1e-9));
      CHECK(g.eps_p[2 * kGroupSize] >= 0.02 * c.escale * (1 - 1e-9));
    } else {
      const double s_top = g.sig[sig_index(2, 0, 0)];
      if (c.ifail == 2) CHECK(s_top == 0.0);
      if (c.ifail == 3) CHECK(std::abs(s_top) > 100.0);  // a failed point keeps its (yield-level) stress
    }
  }
}

TEST_CASE("FAIL/TAB reader: the layouts of 100/120 and 110, defaults, functions, constant temperature",
          "[failtab][parser]") {
  using radx::test::begin_block;
  using radx::test::Line;
  auto deck = [](int version, double temp_y2) {
    std::string s = begin_block(version, "Mg mm s");
    s += "/MAT/PLAS_TAB/3\nsteel\n" + Line().put(7.8e-9, 1, 20).str() + "\n" +
         Line().put(210000.0, 1, 20).put(0.3, 21, 40).str() + "\n" + Line().put(1, 1, 10).str() + "\n" +
         Line().put(0, 1, 10).str() + "\n" + Line().put(23, 1, 10).str() + "\n" +
         Line().put(1.0, 1, 20).str() + "\n" + Line().put(0.0, 1, 20).str() + "\n";
    s += "/FAIL/TAB/3\n" +
         Line()
             .put(3, 1, 10)
             .put(0, 11, 20)
             .put(2, 21, 30)
             .put(0.4, version == 110 ? 61 : 41, version == 110 ? 80 : 60)
             .str() +
         "\n" + Line().put(0.0, 1, 20).put(1.0, 21, 40).put(2.0, 41, 60).str() + "\n" +
         Line().put(20, 1, 10).put(0.5, 11, 30).put(1e-5, 31, 50).str() + "\n" +
         Line().put(20, 1, 10).put(0.0, 11, 30).put(0.5, 31, 50).str() + "\n" +
         Line().put(21, 1, 10).put(0.0, 11, 30).put(0.0, 31, 50).str() + "\n" +
         Line().put(22, 1, 10).put(2.0, 11, 30).str() + "\n";
    for (int id : {20, 21, 22, 23}) {
      const double y2 = id == 22 ? temp_y2 : 1.0;
      s += "/FUNCT/" + std::to_string(id) + "\nf\n" +
           Line().put(0.0, 1, 20).put(id == 22 ? 1.5 : 1.0, 21, 40).str() + "\n" +
           Line().put(10.0, 1, 20).put(id == 22 ? y2 : 1.0, 21, 40).str() + "\n";
    }
    s += "/END\n";
    return s;
  };
  for (const int version : {100, 110, 2018}) {
    const auto m = radx::test::model_of_deck(deck(version, 1.5));
    REQUIRE(m.materials.size() == 1);
    const auto& f = m.materials[0].fail_tab;
    CHECK(f.on);
    CHECK(f.ifail_sh == 3);
    CHECK(f.ifail_so == 1);  // 0 -> 1
    CHECK(f.p_thickfail == 0.4);
    CHECK(f.dcrit == 1.0);  // 0 -> 1
    CHECK(f.d == 0.999);    // 1 -> 0.999 (not used)
    CHECK(f.n == 2.0);
    REQUIRE(f.function.size() == 2);
    CHECK(f.function_id[1] == 20);
    CHECK(f.scale[0] == 0.5);
    CHECK(f.scale[1] == 1.0);  // 0 -> 1
    CHECK(f.rate[1] == 0.5);
    CHECK(f.size_function >= 0);
    CHECK(f.size_scale == 1.0);                // 0 -> 1
    CHECK(f.el_ref == 1.0);                    // 0 -> 1
    CHECK(close(f.temp_factor, 3.0, kRound));  // FscaleT 2 x the constant 1.5
  }
}

TEST_CASE(
    "FAIL/TAB element-size factor: from each shell's length at t = 0 (docs/theory/elements.md 4.1, 4.2)",
    "[failtab][engine]") {
  // A 4 x 2 rectangle: L = max(A / longest diagonal, shortest side) = max(8 / sqrt(20), 2) = 2; a 6 x 1
  // strip: max(6 / sqrt(37), 1) = 1; a triangle (0,0) (4,0) (0,3): 2A / longest side = 12 / 5.
  // Size function f(x) = x (points 0 and 10), Fscale_el 0.5, EI_ref 4: factor 0.5 L / 4.
  using radx::test::Line;
  std::string s = radx::test::begin_block(2026, "Mg mm s") + "/NODE\n";
  const double xy[11][2] = {{0, 0},  {4, 0},  {4, 2},  {0, 2},  {10, 0}, {16, 0},
                            {16, 1}, {10, 1}, {20, 0}, {24, 0}, {20, 3}};
  for (int k = 0; k < 11; ++k)
    s += Line().put(k + 1, 1, 10).put(xy[k][0], 11, 30).put(xy[k][1], 31, 50).put(0.0, 51, 70).str() + "\n";
  s += "/SHELL/1\n" + Line().put(1, 1, 10).put(1, 11, 20).put(2, 21, 30).put(3, 31, 40).put(4, 41, 50).str() +
       "\n" + Line().put(2, 1, 10).put(5, 11, 20).put(6, 21, 30).put(7, 31, 40).put(8, 41, 50).str() + "\n";
  s += "/SH3N/1\n" + Line().put(3, 1, 10).put(9, 11, 20).put(10, 21, 30).put(11, 31, 40).str() + "\n";
  s += "/PART/1\nplate\n" + Line().put(1, 1, 10).put(1, 11, 20).str() + "\n";
  s += "/PROP/SHELL/1\nshell\n\n\n" + Line().put(3, 1, 10).put(1.0, 21, 40).str() + "\n";
  s += "/MAT/PLAS_TAB/1\nsteel\n" + Line().put(7.85e-9, 1, 20).str() + "\n" +
       Line().put(210000.0, 1, 20).put(0.3, 21, 40).str() + "\n" + Line().put(1, 1, 10).str() + "\n" +
       Line().put(0, 1, 10).str() + "\n" + Line().put(1, 1, 10).str() + "\n" + Line().put(1.0, 1, 20).str() +
       "\n" + Line().put(0.0, 1, 20).str() + "\n";
  s += "/FAIL/TAB/1\n" + Line().put(1, 1, 10).put(1, 11, 20).put(1, 21, 30).str() + "\n" + Line().str() +
       "\n" + Line().put(2, 1, 10).put(1.0, 11, 30).put(0.0, 31, 50).str() + "\n" +
       Line().put(3, 1, 10).put(0.5, 11, 30).put(4.0, 31, 50).str() + "\n" + Line().str() + "\n";
  s += "/FUNCT/1\nyield\n" + Line().put(0.0, 1, 20).put(200.0, 21, 40).str() + "\n" +
       Line().put(1.0, 1, 20).put(400.0, 21, 40).str() + "\n";
  s += "/FUNCT/2\neps_f\n" + Line().put(-1.0, 1, 20).put(0.3, 21, 40).str() + "\n" +
       Line().put(1.0, 1, 20).put(0.3, 21, 40).str() + "\n";
  s += "/FUNCT/3\nsize\n" + Line().put(0.0, 1, 20).put(0.0, 21, 40).str() + "\n" +
       Line().put(10.0, 1, 20).put(10.0, 21, 40).str() + "\n/END\n";
  const auto md = radx::test::model_of_deck(s);
  radx::model::RunControls rc;
  rc.t_stop = 1e-9;
  ExplicitEngine engine(md, rc, EngineOptions{1, 1});
  std::vector<double> quads, tris;
  for (const auto& g : engine.groups().shells)
    for (int i = 0; i < g.count; ++i)
      (g.triangle ? tris : quads).push_back(g.fail_scale[static_cast<std::size_t>(i)]);
  REQUIRE(quads.size() == 2);
  REQUIRE(tris.size() == 1);
  std::sort(quads.begin(), quads.end());
  CHECK(close(quads[0], 0.5 * 1.0 / 4.0, kRound));  // the 6 x 1 strip
  CHECK(close(quads[1], 0.5 * 2.0 / 4.0, kRound));  // the 4 x 2 rectangle
  CHECK(close(tris[0], 0.5 * 2.4 / 4.0, kRound));   // the 3-4-5 triangle
}
