// /FAIL/BIQUAD (solver/materials/fail_biquad.cpp) through the damage stage it shares (failure_damage.cpp):
// the two parabolas through C1..C5 at their triaxialities, the plane-strain vertex form of S_Flag 2, the
// triaxiality of shell and solid stress states, the damage integral and the floor of a curve below zero, the
// starter's reading (M_Flag, S_Flag, P_thickfail, the size function), and the sample deck
// decks/fail_biquad_strip against its closed form. Expected values are the card's C1..C5 and the closed forms
// of docs/theory/failure-biquad.md. Units: MPa, mm, s.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "solver/elements/element_groups.hpp"
#include "solver/elements/shell/shell_section.hpp"
#include "solver/engine/explicit_engine.hpp"
#include "solver/materials/material_point.hpp"
#include "test_util.hpp"

using radx::model::Material;
using radx::model::MaterialLaw;
using namespace radx::solver;

namespace {

// Relative round-off of a few dozen operations on numbers of order 1: the fits are closed forms, so the curve
// meets C1..C5 to round-off, not to a fitting tolerance.
constexpr double kRound = 1e-12;
using radx::test::close;
const double kS = 1.0 / std::sqrt(3.0);  // plane strain

// A law-2 material with a /FAIL/BIQUAD of the given strains (all distinct, no symmetry to hide a swapped
// coefficient).
Material biquad_material(int s_flag, double c1 = 0.9, double c2 = 0.45, double c3 = 0.3, double c4 = 0.2,
                         double c5 = 0.35) {
  Material m;
  m.law = MaterialLaw::JohnsonCook;
  m.rho = 7.85e-9;
  m.young = 210000.0;
  m.poisson = 0.3;
  m.a = 300.0;
  m.b = 400.0;
  m.n = 0.3;
  m.eps_p_max = 1e30;
  m.sig_max0 = 1e30;
  auto& f = m.fail_bq;
  f.on = true;
  f.c1 = c1;
  f.c2 = c2;
  f.c3 = c3;
  f.c4 = c4;
  f.c5 = c5;
  f.s_flag = s_flag;
  return m;
}

}  // namespace

TEST_CASE("FAIL/BIQUAD curve: S_Flag 1 passes through C1..C5 at -1/3, 0, 1/3, 1/sqrt(3), 2/3",
          "[material][fail][biquad]") {
  const MaterialParams p = make_material_params(biquad_material(1));
  REQUIRE(p.fail.kind == FailKind::Biquad);
  CHECK(close(fail_biquad_curve(p.fail, -1.0 / 3.0), 0.9, kRound));
  CHECK(close(fail_biquad_curve(p.fail, 0.0), 0.45, kRound));
  CHECK(close(fail_biquad_curve(p.fail, 1.0 / 3.0), 0.3, kRound));
  CHECK(close(fail_biquad_curve(p.fail, kS), 0.2, kRound));
  CHECK(close(fail_biquad_curve(p.fail, 2.0 / 3.0), 0.35, kRound));
  // Both parabolas hold C3 at 1/3: the curve is continuous there (the second one taken just above).
  CHECK(close(fail_biquad_curve(p.fail, 1.0 / 3.0 + 1e-12), 0.3, 1e-9));
  // A quadratic through three points: the first one at -1/6 by Lagrange's form directly.
  const double x = -1.0 / 6.0;
  const double lagrange = 0.9 * (x - 0) * (x - 1.0 / 3) / ((-1.0 / 3) * (-2.0 / 3)) +
                          0.45 * (x + 1.0 / 3) * (x - 1.0 / 3) / ((1.0 / 3) * (-1.0 / 3)) +
                          0.3 * (x + 1.0 / 3) * (x - 0) / ((2.0 / 3) * (1.0 / 3));
  CHECK(close(fail_biquad_curve(p.fail, x), lagrange, kRound));
}

TEST_CASE("FAIL/BIQUAD curve: S_Flag 2 makes plane strain the minimum with two half-parabolas",
          "[material][fail][biquad]") {
  const MaterialParams p = make_material_params(biquad_material(2));
  // Below 1/3 the first parabola, as with S_Flag 1.
  CHECK(close(fail_biquad_curve(p.fail, -1.0 / 3.0), 0.9, kRound));
  CHECK(close(fail_biquad_curve(p.fail, 0.0), 0.45, kRound));
  CHECK(close(fail_biquad_curve(p.fail, 1.0 / 3.0), 0.3, kRound));
  // Above: C3 at 1/3 (from the right), the vertex C4 at 1/sqrt(3), C5 at 2/3.
  CHECK(close(fail_biquad_curve(p.fail, 1.0 / 3.0 + 1e-12), 0.3, 1e-9));
  CHECK(close(fail_biquad_curve(p.fail, kS), 0.2, kRound));
  CHECK(close(fail_biquad_curve(p.fail, 2.0 / 3.0), 0.35, kRound));
  // In between, the vertex form c4 + (c - c4) ((eta - s) / (x - s))^2.
  const double e1 = 0.45, e2 = 0.62;
  CHECK(close(fail_biquad_curve(p.fail, e1), 0.2 + 0.1 * std::pow((e1 - kS) / (1.0 / 3 - kS), 2), kRound));
  CHECK(close(fail_biquad_curve(p.fail, e2), 0.2 + 0.15 * std::pow((e2 - kS) / (2.0 / 3 - kS), 2), kRound));
  // Plane strain is the minimum of the upper branch.
  for (double eta = 0.34; eta < 0.666; eta += 0.01) CHECK(fail_biquad_curve(p.fail, eta) >= 0.2 - 1e-15);
}

TEST_CASE("FAIL/BIQUAD triaxiality of the stress: shells' plane stress and solids (kept in [-2/3, 2/3])",
          "[material][fail][biquad]") {
  const MaterialParams p = make_material_params(biquad_material(1));
  const auto shell = [](double sxx, double syy, double sxy) {
    const double svm = std::sqrt(sxx * sxx + syy * syy - sxx * syy + 3 * sxy * sxy);
    return std::array<double, 2>{(sxx + syy) / 3.0, svm};
  };
  auto e = [&](std::array<double, 2> s) { return fail_strain(p.fail, s[0], s[1], 0.0, 1.0); };
  CHECK(close(e(shell(250, 0, 0)), 0.3, kRound));     // uniaxial tension: C3
  CHECK(close(e(shell(-250, 0, 0)), 0.9, kRound));    // uniaxial compression: C1
  CHECK(close(e(shell(0, 0, 140)), 0.45, kRound));    // shear: C2
  CHECK(close(e(shell(250, 125, 0)), 0.2, kRound));   // plane strain, syy = sxx / 2: C4
  CHECK(close(e(shell(250, 250, 0)), 0.35, kRound));  // equibiaxial: C5
  // A solid under mostly hydrostatic tension (eta = 2) takes the curve at 2/3.
  CHECK(close(fail_strain(p.fail, 200.0, 100.0, 0.0, 1.0), 0.35, kRound));
  // The element-size factor multiplies eps_f.
  CHECK(close(fail_strain(p.fail, 250.0 / 3, 250.0, 0.0, 0.5), 0.15, kRound));
}

TEST_CASE("FAIL/BIQUAD damage: D = sum d_eps_p / eps_f, failure at D = 1, a curve below zero fails at once",
          "[material][fail][biquad]") {
  const MaterialParams p = make_material_params(biquad_material(2));
  // Uniaxial tension (eta = 1/3, eps_f = C3 = 0.3) in 0.001 steps: D reaches 1 at the 300th, or at the 301st
  // when the sum of 300 rounded 0.001 / 0.3 falls an ulp short of 1.
  double dmg = 0;
  int steps = 0;
  while (!fail_accumulate(p.fail, 100.0, 300.0, 0.0, 1.0, 0.001, dmg)) ++steps;
  CHECK((steps + 1 == 300 || steps + 1 == 301));
  CHECK(dmg == 1.0);
  // Half the path in shear (eps_f = C2 = 0.45), then tension: 0.225 / 0.45 + eps / 0.3 = 1 -> eps = 0.15.
  dmg = 0;
  fail_accumulate(p.fail, 0.0, 300.0, 0.0, 1.0, 0.225, dmg);
  CHECK(close(dmg, 0.5, kRound));
  fail_accumulate(p.fail, 100.0, 300.0, 0.0, 1.0, 0.149, dmg);
  CHECK(close(dmg, 0.5 + 0.149 / 0.3, kRound));
  CHECK(fail_accumulate(p.fail, 100.0, 300.0, 0.0, 1.0, 0.002, dmg));
  // C2 = -0.1: the curve is negative in shear; OpenRadioss floors eps_f at 1e-6, so 2e-6 of plastic strain
  // fails the point.
  const MaterialParams neg = make_material_params(biquad_material(2, 0.9, -0.1));
  dmg = 0;
  CHECK(close(fail_strain(neg.fail, 0.0, 300.0, 0.0, 1.0), 1e-6, kRound));
  CHECK(fail_accumulate(neg.fail, 0.0, 300.0, 0.0, 1.0, 2e-6, dmg));
}

TEST_CASE("FAIL/BIQUAD on a solid point: the brick starts its deletion when eps_p reaches eps_f(1/3)",
          "[material][fail][biquad]") {
  // Uniaxial stress: an isochoric strain path (d, -d/2, -d/2) gives the deviator diag(2/3, -1/3, -1/3) q, and
  // the volume change mu = -q / 3K (the deviatoric update does not depend on it, so a first pass gives q)
  // adds the mean stress q/3: sigma = diag(q, 0, 0), triaxiality exactly 1/3, eps_f = C3 = 0.3. The brick
  // fails on the step eps_p reaches 0.3.
  const MaterialParams p = make_material_params(biquad_material(2));
  double sig[6] = {0, 0, 0, 0, 0, 0};
  double eps_p = 0, dmg = 0, eps_before = 0;
  const double d = 2e-4;
  const double de[6] = {d, -0.5 * d, -0.5 * d, 0, 0, 0};
  bool failed = false;
  for (int k = 0; k < 4000 && !failed; ++k) {
    double trial[6];
    for (int c = 0; c < 6; ++c) trial[c] = sig[c];
    double e = eps_p;
    solid_point_update(p, 0.0, de, 0.0, trial, e);
    const double q = 1.5 * trial[0];
    eps_before = eps_p;
    failed = solid_point_update(p, 0.0, de, -q / (3.0 * p.bulk), sig, eps_p, dmg, 1.0).element_fails;
    CHECK(close(sig[1], 0.0, 0.0, 1e-9 * q));  // zero lateral stress, to round-off of q
  }
  REQUIRE(failed);
  CHECK(eps_before < 0.3 * (1 + 1e-12));
  CHECK(eps_p >= 0.3 * (1 - 1e-12));
}

TEST_CASE("FAIL/BIQUAD reader: M_Flag's multiples of C3, S_Flag defaults, P_thickfail, the size function",
          "[biquad][parser]") {
  using radx::test::begin_block;
  using radx::test::Line;
  auto deck = [](double c3, int m_flag, int s_flag, double inst, double pthk, const std::string& extra) {
    std::string s = begin_block(2026, "Mg mm s");
    s += "/MAT/PLAS_JOHNS/3\nsteel\n" + Line().put(7.8e-9, 1, 20).str() + "\n" +
         Line().put(210000.0, 1, 20).put(0.3, 21, 40).str() + "\n" +
         Line().put(300.0, 1, 20).put(400.0, 21, 40).put(0.3, 41, 60).str() + "\n" + Line().str() + "\n";
    s += "/FAIL/BIQUAD/3\n" + Line().put(0.0, 1, 20).put(0.0, 21, 40).put(c3, 41, 60).str() + "\n" +
         Line()
             .put(pthk, 1, 20)
             .put(m_flag, 21, 30)
             .put(s_flag, 31, 40)
             .put(inst, 41, 60)
             .put(extra.empty() ? 0 : 7, 71, 80)
             .str() +
         "\n";
    if (m_flag == 99)
      s += Line().put(2.0, 1, 20).put(1.5, 21, 40).put(0.5, 41, 60).put(1.2, 61, 80).str() + "\n";
    s += Line().str() + "\n" + extra + "/END\n";
    return s;
  };
  {
    // C3 blank with M_Flag 3 (UHSS): C3 = 0.12, C1 C2 C4 C5 = 5.2, 3.1, 0.8, 3.5 times it; S_Flag 3 with
    // Inst_start 0 runs as 2; P_thickfail 0 -> 1e-6.
    const auto m = radx::test::model_of_deck(deck(0.0, 3, 3, 0.0, 0.0, ""));
    const auto& f = m.materials[0].fail_bq;
    REQUIRE(f.on);
    CHECK(f.c3 == 0.12);
    CHECK(close(f.c1, 5.2 * 0.12, kRound));
    CHECK(close(f.c2, 3.1 * 0.12, kRound));
    CHECK(close(f.c4, 0.8 * 0.12, kRound));
    CHECK(close(f.c5, 3.5 * 0.12, kRound));
    CHECK(f.s_flag == 2);
    CHECK(f.p_thickfail == 1e-6);
    CHECK(f.size_function < 0);
    // Inst_start 0.05 below C4 = 0.096: S_Flag 3 runs, with its instability strain.
    const auto m3 = radx::test::model_of_deck(deck(0.0, 3, 3, 0.05, 0.0, ""));
    CHECK(m3.materials[0].fail_bq.s_flag == 3);
    CHECK(m3.materials[0].fail_bq.inst_start == 0.05);
  }
  {
    // M_Flag 99: the card's ratios R1 R2 R4 R5 of C3 = 0.4; S_Flag 0 -> 2; P_thickfail above 1 -> 1; the size
    // function /FUNCT/7 with EI_ref 0 -> 1.
    const std::string fn = "/FUNCT/7\nsize\n" + Line().put(0.0, 1, 20).put(1.0, 21, 40).str() + "\n" +
                           Line().put(10.0, 1, 20).put(0.5, 21, 40).str() + "\n";
    const auto m = radx::test::model_of_deck(deck(0.4, 99, 0, 0.0, 1.5, fn));
    const auto& f = m.materials[0].fail_bq;
    CHECK(close(f.c1, 0.8, kRound));
    CHECK(close(f.c2, 0.6, kRound));
    CHECK(close(f.c4, 0.2, kRound));
    CHECK(close(f.c5, 0.48, kRound));
    CHECK(f.s_flag == 2);
    CHECK(f.p_thickfail == 1.0);
    CHECK(f.size_function_id == 7);
    CHECK(f.size_function >= 0);
    CHECK(f.el_ref == 1.0);
  }
}

TEST_CASE("FAIL/BIQUAD sample deck: the strip's shells and the bar's bricks fail at eps_p = C3 in tension",
          "[biquad][engine][deck]") {
  // decks/fail_biquad_strip: law 2 (300 + 1000 eps_p MPa, E 210000), C3 = 0.08, M_Flag 2; a shell strip and
  // a brick bar, each pulled at V = 1000 mm/s over L = 100 mm in uniaxial stress (triaxiality 1/3). Closed
  // form (the deck's README): the points fail at eps_p = C3, when the logarithmic strain C3 + (300 + 1000 C3)
  // / E is reached, at t_f = L (exp(C3 + sigma / E) - 1) / V.
  const std::string dir = std::string(RADX_SOURCE_DIR) + "/decks/fail_biquad_strip/";
  radx::Diagnostics diags;
  const auto deck = radx::read_starter_deck(dir + "FAIL_BIQUAD_STRIP_0000.rad", diags);
  const auto m = radx::build_model(deck, diags);
  REQUIRE_FALSE(diags.has_errors());
  const double c3 = 0.08, sigma = 300.0 + 1000.0 * c3;
  const double t_f = 100.0 * (std::exp(c3 + sigma / 210000.0) - 1.0) / 1000.0;
  radx::model::RunControls rc;
  rc.t_stop = 1.03 * t_f;
  ExplicitEngine engine(m, rc, EngineOptions{1, 1000});
  double t_shell = -1, t_brick = -1, eps_shell = 0, eps_brick = 0;
  engine.run([&](const CycleReport& r) {
    const auto& sh = engine.groups().shells;
    for (const auto& g : sh)
      for (int i = 0; i < g.count && t_shell < 0; ++i) {
        const auto e = static_cast<std::size_t>(i);
        if (g.off[e] == 1.0) continue;
        t_shell = r.time;
        for (int k = 0; k < g.gauss * g.props.n_points; ++k)
          eps_shell = std::max(eps_shell, g.eps_p[static_cast<std::size_t>(k) * kGroupSize + e]);
      }
    for (const auto& g : engine.groups().bricks)
      for (int i = 0; i < g.count && t_brick < 0; ++i) {
        const auto e = static_cast<std::size_t>(i);
        if (g.off[e] == 1.0) continue;
        t_brick = r.time;
        eps_brick = g.eps_p[e];
      }
    return true;
  });
  INFO("closed form t_f = " << t_f << " s; shells " << t_shell << " s at eps_p " << eps_shell << "; bricks "
                            << t_brick << " s at eps_p " << eps_brick);
  REQUIRE(t_shell > 0);
  REQUIRE(t_brick > 0);
  // The failed point's plastic strain is C3 to 1 %: the damage integral at a triaxiality within about 0.01
  // of 1/3 (the lateral inertia of the pulled strip and bar), plus one cycle's increment.
  CHECK(close(eps_shell, c3, 0.01));
  CHECK(close(eps_brick, c3, 0.01));
  // The failure time within 0.5 % of t_f: the strain rate along the pulled bar is uniform to that once the
  // first elastic waves have crossed it (the strain lags the pulled end by the wave transit, ~20 us).
  CHECK(close(t_shell, t_f, 0.005));
  CHECK(close(t_brick, t_f, 0.005));
}

TEST_CASE("FAIL/BIQUAD S_Flag 3: the instability curve through Inst_start at plane strain, C3 and C5",
          "[material][fail][biquad]") {
  Material m = biquad_material(3);
  m.fail_bq.inst_start = 0.1;
  const MaterialParams p = make_material_params(m);
  REQUIRE(p.fail.bq_s_flag == 3);
  // Up to 1/3 no instability; above, the vertex Inst_start at 1/sqrt(3), C3 (0.3) at 1/3, C5 (0.35) at 2/3.
  CHECK(fail_biquad_instability_curve(p.fail, 0.0) == 0.0);
  CHECK(fail_biquad_instability_curve(p.fail, 1.0 / 3.0) == 0.0);
  CHECK(close(fail_biquad_instability_curve(p.fail, 1.0 / 3.0 + 1e-12), 0.3, 1e-9));
  CHECK(close(fail_biquad_instability_curve(p.fail, kS), 0.1, kRound));
  CHECK(close(fail_biquad_instability_curve(p.fail, 2.0 / 3.0), 0.35, kRound));
  const double e = 0.5;
  CHECK(close(fail_biquad_instability_curve(p.fail, e), 0.1 + 0.2 * std::pow((e - kS) / (1.0 / 3 - kS), 2),
              kRound));
  // The failure curve of S_Flag 3 is the one of S_Flag 2.
  const MaterialParams p2 = make_material_params(biquad_material(2));
  for (double eta : {-0.3, 0.1, 0.4, 0.55, 0.6, 0.65})
    CHECK(fail_biquad_curve(p.fail, eta) == fail_biquad_curve(p2.fail, eta));
  // The damage: 0.05 of plastic strain at plane strain is half the instability; none at eta = 1/3.
  double d = 0;
  fail_biquad_instability(p.fail, kS * 300.0, 300.0, 1.0, 0.05, d);
  CHECK(close(d, 0.5, 1e-9));
  d = 0;
  fail_biquad_instability(p.fail, 100.0, 300.0, 1.0, 0.05, d);
  CHECK(d == 0.0);
}

TEST_CASE("FAIL/BIQUAD S_Flag 3 on a shell section: deleted when every point has reached the instability",
          "[shell][fail][biquad]") {
  // Membrane plane strain (eps_yy = 0) with a little bending along x: the triaxiality rises from
  // (1 + nu) / (3 sqrt(1 - nu + nu^2)) at first yield (elastic syy = nu sxx) towards 1/sqrt(3), where the
  // instability curve has its minimum Inst_start = 0.1. The three points strain at different rates (the
  // bending), so they reach the instability one after the other: the element goes in the step the last one
  // (the lower surface) does, at an eps_p of that point between Inst_start and the instability strain at the
  // first yield's triaxiality, well before the failure strain (about C4 = 0.2). With S_Flag 2 the same path
  // does not delete it there.
  using namespace radx::solver::shell_detail;
  constexpr std::size_t G = kGroupSize;
  const double nu = 0.3;
  const double eta_y = (1 + nu) / (3 * std::sqrt(1 - nu + nu * nu));
  const double eps_i_max = 0.1 + 0.2 * std::pow((eta_y - kS) / (1.0 / 3 - kS), 2);
  for (const int s_flag : {3, 2}) {
    Material m = biquad_material(s_flag);
    m.fail_bq.inst_start = 0.1;
    const MaterialParams p = make_material_params(m);
    ShellGroup g;
    g.allocate(1, 3);
    const ThicknessRule rule = thickness_rule(3);
    SectionBlock<4> s{};
    bool deleted = false;
    double ep_low_before = 0, inst_low_before = 0, inst_top_before = 0;
    for (int step = 0; step < 2000 && !deleted; ++step) {
      ep_low_before = g.eps_p[0];
      inst_low_before = g.dmg_inst[0];
      inst_top_before = g.dmg_inst[2 * G];
      for (int k = 0; k < 5; ++k) s.dem[k][0] = 0;
      s.dem[0][0] = 2e-4;
      s.dk[0][0] = 2e-5;  // the surfaces at +-1e-5 of the membrane's 2e-4 per step
      s.dk[1][0] = s.dk[2][0] = 0;
      s.t[0] = 1.0;
      s.area[0] = 1.0;
      s.rfac[0] = 1.0;
      s.rate[0] = 0.0;
      s.off[0] = 1.0;
      section_update_block(g, 0, 1, p, rule, p.shear * 5.0 / 6.0, s);
      deleted = next_off(failure_limit(p), 1.0, s.eps_p_max[0], s.fail_now[0]) == 0.0 && g.eps_p[0] < 0.15;
    }
    INFO("S_Flag " << s_flag << ": lower point eps_p " << g.eps_p[0] << ", instability damage "
                   << g.dmg_inst[0]);
    if (s_flag == 3) {
      REQUIRE(deleted);
      for (int q = 0; q < 3; ++q) CHECK(g.dmg_inst[static_cast<std::size_t>(q) * G] == 1.0);
      CHECK(inst_top_before == 1.0);  // the upper surface got there first
      CHECK(inst_low_before < 1.0);   // the lower one in the deleting step
      CHECK(g.dmg[0] < 1.0);
      CHECK(ep_low_before < eps_i_max);
      CHECK(g.eps_p[0] >= 0.1 * (1 - 1e-9));
    } else {
      CHECK_FALSE(deleted);
      CHECK(g.dmg_inst[0] == 0.0);
    }
  }
}

TEST_CASE("FAIL/BIQUAD sample deck fail_biquad_neck: shells deleted by the instability in plane strain",
          "[biquad][engine][deck]") {
  // decks/fail_biquad_neck: a strip in plane strain (every node held along Y), law 2, C4 = 0.12 and
  // Inst_start = 0.06 (S_Flag 3). The shells go by the instability, not by their points' failure: at a
  // plastic strain between Inst_start and the instability strain at the first yield's triaxiality (the
  // README's closed form), every point's instability damage 1 and no point failed.
  const std::string dir = std::string(RADX_SOURCE_DIR) + "/decks/fail_biquad_neck/";
  radx::Diagnostics diags;
  const auto deck = radx::read_starter_deck(dir + "FAIL_BIQUAD_NECK_0000.rad", diags);
  const auto m0 = radx::build_model(deck, diags);
  REQUIRE_FALSE(diags.has_errors());
  const double nu = 0.3, inst = 0.06, c3 = 0.2;
  const double eta_y = (1 + nu) / (3 * std::sqrt(1 - nu + nu * nu));
  const double eps_i_y = inst + (c3 - inst) * std::pow((eta_y - kS) / (1.0 / 3 - kS), 2);
  for (const int ishell : {1, 12}) {
    auto m = m0;
    REQUIRE(m.properties.size() == 1);
    m.properties[0].shell.ishell = ishell;
    radx::model::RunControls rc;
    rc.t_stop = 8e-3;
    ExplicitEngine engine(m, rc, EngineOptions{1, 1000});
    double t_first = -1, eps_min = 1, eps_max = 0, dmg_max = 0;
    int deleted = 0;
    std::vector<double> seen(kGroupSize, 0.0);
    engine.run([&](const CycleReport& r) {
      for (const auto& g : engine.groups().shells)
        for (int i = 0; i < g.count; ++i) {
          const auto e = static_cast<std::size_t>(i);
          if (g.off[e] != 0.0 || seen[e] != 0.0) continue;
          seen[e] = 1.0;
          ++deleted;
          if (t_first < 0) t_first = r.time;
          for (int k = 0; k < g.gauss * g.props.n_points; ++k) {
            const std::size_t pk = static_cast<std::size_t>(k) * kGroupSize + e;
            CHECK(g.dmg_inst[pk] == 1.0);
            eps_min = std::min(eps_min, g.eps_p[pk]);
            eps_max = std::max(eps_max, g.eps_p[pk]);
            dmg_max = std::max(dmg_max, g.dmg[pk]);
          }
        }
      return true;
    });
    INFO("Ishell " << ishell << ": first deletion " << t_first << " s; " << deleted << " shells; eps_p "
                   << eps_min << " .. " << eps_max << "; damage up to " << dmg_max << "; eps_i(eta_y) "
                   << eps_i_y);
    REQUIRE(deleted > 0);
    CHECK(eps_min >= inst);
    CHECK(eps_max <= eps_i_y);
    CHECK(dmg_max < 1.0);
    if (ishell == 12) {
      REQUIRE(!engine.groups().shells.empty());
      CHECK(engine.groups().shells[0].gauss == 4);
    }
  }
}
