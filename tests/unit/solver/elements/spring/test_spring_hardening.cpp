// The hardening flags H = 1, 2, 4, 5, 6, 8 of the scalar spring law (spring_law.hpp) shared by the TYPE4 and
// TYPE8 springs: each driven through a load-unload-reload cycle of imposed elongations at the law level and
// checked against the piecewise curve worked by hand from the equations at the top of spring_law.hpp; H 8
// through the TYPE4 kernel (it needs the length); the engine against the closed-form elasto-plastic
// oscillator for TYPE4 with H 1 and TYPE8 with H 6; the starter's acceptances and refusals.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "kernel_test_util.hpp"
#include "solver/elements/element_groups.hpp"
#include "solver/elements/spring/spring_law.hpp"
#include "solver/engine/explicit_engine.hpp"
#include "test_util.hpp"

namespace {

using radx::test::Line;
using radx::test::rel;

radx::model::Function curve(std::vector<double> x, std::vector<double> y) {
  radx::model::Function f;
  f.id = 1;
  f.x = std::move(x);
  f.y = std::move(y);
  return f;
}

// f1 of most cases: 100 x up to |x| = 1, then 100 + 10 (|x| - 1), odd.
radx::model::Function hardening_curve() {
  return curve({-11, -1, 0, 1, 11}, {-200, -100, 0, 100, 200});
}

radx::model::SpringLaw law(int h, double k) {
  radx::model::SpringLaw p;
  p.stiffness = k;
  p.hardening = h;
  return p;
}

// Drives the law through the elongations `path` (v = 0: no amplification, no damping) and checks each
// static force against `expect`. The forces are sums of a few products of exact decimals: 1e-12 relative
// (or 1e-9 absolute at a zero force) is rounding only.
void check_path(const radx::model::SpringLaw& p, const radx::solver::SpringLawCurves& c,
                const std::vector<double>& path, const std::vector<double>& expect,
                radx::solver::SpringLawState& s) {
  REQUIRE(path.size() == expect.size());
  double x_old = 0;
  for (std::size_t k = 0; k < path.size(); ++k) {
    const double n = radx::solver::spring_law_force(p, c, path[k], x_old, 0.0, 0.0, s);
    x_old = path[k];
    INFO("H " << p.hardening << ", step " << k << ": x = " << path[k] << ", N = " << n << ", expected "
              << expect[k]);
    if (expect[k] == 0)
      CHECK(std::abs(n) < 1e-9);
    else
      CHECK(rel(n, expect[k]) < 1e-12);
  }
}

}  // namespace

TEST_CASE("spring law H 1: yield on f1, elastic unloading with K, isotropic yield in compression",
          "[spring][hardening]") {
  const auto f1 = hardening_curve();
  const auto p = law(1, 100.0);
  radx::solver::SpringLawCurves c;
  c.load = &f1;
  radx::solver::SpringLawState s;
  // Loading 0 -> 3 follows f1: 100, 110, 120; the plastic elongation is then x_max - f_max / K = 1.8.
  // Unloading with K: x = 2 -> 20, x = 1.8 -> 0 (the residual elongation). Reloading with K to the largest
  // force: x = 3 -> 120; on to x = 4 along f1 -> 130 (p = 4 - 1.3 = 2.7). Reversing: elastic until the
  // compressive force reaches f1(p + |f| / K) = 117 + 0.1 |f|, i.e. |f| = 130 (the largest force reached:
  // isotropic), at x = 4 - 2.6 = 1.4; then along f1 of the equivalent elongation -(2.7 + 1.3 + 1.4) = -5.4
  // at x = 0: -144.
  check_path(p, c, {1, 2, 3}, {100, 110, 120}, s);
  CHECK(rel(s.plastic, 3.0 - 120.0 / 100.0) < 1e-12);
  double x_old = 3;
  const std::vector<double> path = {2, 1.8, 3, 4, 1.4, 0}, expect = {20, 0, 120, 130, -130, -144};
  for (std::size_t k = 0; k < path.size(); ++k) {
    const double n = radx::solver::spring_law_force(p, c, path[k], x_old, 0.0, 0.0, s);
    x_old = path[k];
    INFO("step " << k << ": x = " << path[k] << ", N = " << n);
    CHECK(std::abs(n - expect[k]) < 1e-9);
    if (k == 3) CHECK(rel(s.plastic, 4.0 - 130.0 / 100.0) < 1e-12);
  }
  // Plastic elongation grows in compression too: p = 2.7 + |-270 - (-144)| / K = 3.96, the equivalent
  // elongation 5.4 less 144 / K.
  CHECK(rel(s.plastic, 5.4 - 144.0 / 100.0) < 1e-12);
}

TEST_CASE("spring law H 2: tension and compression yield apart, slack between the plastic elongations",
          "[spring][hardening]") {
  const auto f1 = hardening_curve();
  const auto p = law(2, 100.0);
  radx::solver::SpringLawCurves c;
  c.load = &f1;
  radx::solver::SpringLawState s;
  // x = 1: min(K x, f1) = 100 (p_t = 0); x = 3: f1 = 120, p_t = 1.8; x = 2: K (2 - 1.8) = 20; x = 1: slack,
  // 0; x = -1: max(K x, f1) = -100 (p_c = 0); x = -2: f1 = -110, p_c = -0.9; x = -0.5: slack, 0; x = 2.5: K
  // (2.5 - 1.8) = 70 (tension's yield unchanged by compression's); x = 3.5: f1 = 125.
  check_path(p, c, {1, 3, 2, 1, -1, -2, -0.5, 2.5, 3.5}, {100, 120, 20, 0, -100, -110, 0, 70, 125}, s);
  CHECK(rel(s.plastic, 3.5 - 1.25) < 1e-12);
  CHECK(rel(s.plastic_c, -0.9) < 1e-12);
}

TEST_CASE("spring law H 4: kinematic hardening between f1 above and fct_ID3 below", "[spring][hardening]") {
  // Upper yield f1 = 50 + 10 x, lower f3 = -50 + 10 x: an elastic band 100 wide that moves with x.
  const auto f1 = curve({-10, 10}, {-50, 150});
  const auto f3 = curve({-10, 10}, {-150, 50});
  const auto p = law(4, 100.0);
  radx::solver::SpringLawCurves c;
  c.load = &f1;
  c.unload = &f3;
  radx::solver::SpringLawState s;
  // 0.25: K x = 25 inside the band; 1: 100 > f1 = 60; 3: f1 = 80; 2: 80 - 100 = -20 > f3 = -30; 1: -120 < f3
  // = -40; 2: -40 + 100 = 60 < f1 = 70; 3: 160 > f1 = 80.
  check_path(p, c, {0.25, 1, 3, 2, 1, 2, 3}, {25, 60, 80, -20, -40, 60, 80}, s);
}

TEST_CASE("spring law H 5: unloading on the power curve to the residual elongation, reloading on the chord",
          "[spring][hardening]") {
  const auto f1 = hardening_curve();
  const auto f3 = curve({-10, 10}, {-5, 5});  // residual elongation 0.5 x_max
  const auto p = law(5, 220.0);
  radx::solver::SpringLawCurves c;
  c.load = &f1;
  c.unload = &f3;
  radx::solver::SpringLawState s;
  // Loading to x_t = 2: F = f1(2) = 110. Residual r = min(f3(2), x_t - F / K) = min(1, 1.5) = 1, exponent
  // b = (x_t - r) K / F = 2, s = (x - r) / (x_t - r). Unloading follows F s^2: x = 1.5 -> 27.5, 1.2 -> 4.4;
  // x = 0.8 <= r -> 0. Reloading climbs with K (0 + 220 x 0.7 = 154) to the chord F s: 1.5 -> 55, 1.8 -> 88
  // (the trial 55 + 66 = 121 above it); x = 2.5 > x_t -> f1 = 115. Compression is the mirror: -1 -> -100,
  // -2 -> -110 (x_c = -2, r = 1, b = 2), -1.5 -> -27.5.
  check_path(p, c, {2, 1.5, 1.2, 0.8, 1.5, 1.8, 2.5, -1, -2, -1.5},
             {110, 27.5, 4.4, 0, 55, 88, 115, -100, -110, -27.5}, s);
  CHECK(s.plastic == 2.5);
  CHECK(s.plastic_c == -2.0);
}

TEST_CASE("spring law H 6: f1 of the plastic travel, unloading on the slope of fct_ID3 at the force",
          "[spring][hardening]") {
  const auto f1 = hardening_curve();
  // Unloading curve: slope 200 below force 0, 40 from 0 to 20, 80 above 20.
  const auto f3 = curve({-1, 0, 0.5, 2}, {-200, 0, 20, 140});
  const auto p = law(6, 100.0);
  radx::solver::SpringLawCurves c;
  c.load = &f1;
  c.unload = &f3;
  radx::solver::SpringLawState s;
  // The yield force starts at 0: x = 1 -> f1(1) = 100, x = 3 -> f1(3) = 120 (travel 3, yield 120).
  // Unloading with the slope at the force: 120 -> 120 - 80 = 40 (x = 2), 40 -> 0 (x = 1.5, slope 80),
  // 0 -> -20 (x = 1, slope 40), -20 -> trial -220 (x = 0, slope 200) beyond -120: yield, f1(-(3 + 1)) =
  // -130 (travel 4). Reloading: -130 + 200 x 0.5 = -30 (x = 0.5); trial 270 (x = 2) beyond 130: f1(4 + 1.5)
  // = 145.
  check_path(p, c, {1, 3, 2, 1.5, 1, 0, 0.5, 2}, {100, 120, 40, 0, -20, -130, -30, 145}, s);
  CHECK(rel(s.travel, 5.5) < 1e-12);
  CHECK(rel(s.yield, 145.0) < 1e-12);
}

TEST_CASE("spring law H 8: f1 of the total length, through the TYPE4 kernel", "[spring][hardening]") {
  // The TYPE4 kernel with H 8: f1 of the current length over Ascale, whatever the elongation. (H 7 without
  // fct_ID3 runs as H 2: the starter test below.)
  const auto f1 = curve({0, 10}, {0, 1000});
  radx::model::SpringProperty prop;
  prop.mass = 1.0;
  prop.x = law(8, 100.0);
  prop.x.ascale = 2.0;
  auto ns = radx::test::make_nodes({{0, 0, 0}, {10, 0, 0}});
  radx::solver::SpringGroup g;
  g.allocate(1);
  g.props = prop;
  g.conn[0] = 0;
  g.conn[radx::solver::kGroupSize] = 1;
  g.l0[0] = 10.0;
  g.curves[0].load = &f1;
  ns.x[1] = 12.0;
  radx::solver::spring_type4_forces(g, ns, radx::solver::CycleInfo{0.1, 0.1, 0});
  CHECK(rel(g.force[0], 600.0) < 1e-12);  // f1(12 / 2)
  CHECK(rel(g.nodal_force[0], 600.0) < 1e-12);
}

namespace {

// Node 1 clamped, node 2 at (100, 0, 0) with the added mass m_add and the initial velocity v0 along X;
// spring 1 between them with the property `prop`; the force curve /FUNCT/7 = `f1` and /FUNCT/8 = `f3`.
std::string oscillator(const std::string& prop, double m_add, double v0,
                       const std::vector<std::array<double, 2>>& f1,
                       const std::vector<std::array<double, 2>>& f3) {
  std::string s = radx::test::begin_block(2019);
  s += "/NODE\n" + Line().put(1, 1, 10).put(0.0, 11, 30).put(0.0, 31, 50).put(0.0, 51, 70).str() + "\n" +
       Line().put(2, 1, 10).put(100.0, 11, 30).put(0.0, 31, 50).put(0.0, 51, 70).str() + "\n";
  s += "/PART/1\nspring\n" + Line().put(1, 1, 10).put(0, 11, 20).str() + "\n";
  s += "/SPRING/1\n" + Line().put(1, 1, 10).put(1, 11, 20).put(2, 21, 30).str() + "\n";
  s += prop;
  auto funct = [](int id, const std::vector<std::array<double, 2>>& pts) {
    std::string t = "/FUNCT/" + std::to_string(id) + "\ncurve\n";
    for (const auto& q : pts) t += Line().put(q[0], 1, 20).put(q[1], 21, 40).str() + "\n";
    return t;
  };
  s += funct(7, f1) + funct(8, f3);
  s += "/GRNOD/NODE/1\nclamped\n" + Line().put(1, 1, 10).str() + "\n";
  s += "/BCS/1\nclamped\n" + Line().put("111 111", 4, 10).put(0, 11, 20).put(1, 21, 30).str() + "\n";
  s += "/GRNOD/NODE/2\nmass\n" + Line().put(2, 1, 10).str() + "\n";
  s += "/ADMAS/0/1\nmass\n" + Line().put(m_add, 1, 20).put(2, 21, 30).str() + "\n";
  s += "/INIVEL/TRA/1\nstart\n" +
       Line().put(v0, 1, 20).put(0.0, 21, 40).put(0.0, 41, 60).put(2, 61, 70).str() + "\n";
  s += "/END\n";
  return s;
}

std::string type4_prop(double M, double K, int h, int fct3) {
  return "/PROP/SPRING/1\nspring\n" + Line().put(M, 1, 20).str() + "\n" + Line().put(K, 1, 20).str() + "\n" +
         Line().put(7, 1, 10).put(h, 11, 20).put(fct3, 31, 40).str() + "\n" + Line().put(0.0, 1, 20).str() +
         "\n";
}

// /PROP/SPR_GENE/1: the X law K, fct_ID1 7, H `h`, fct_ID3 `fct3`; the other five free.
std::string type8_prop(double M, double K, int h, int fct3, int h2 = 0) {
  std::string s = "/PROP/SPR_GENE/1\ngeneral spring\n" + Line().put(M, 1, 20).put(0.0, 21, 40).str() + "\n";
  for (int d = 0; d < 6; ++d) {
    s += Line().put(d == 0 || (d == 1 && h2 != 0) ? K : 0.0, 1, 20).str() + "\n";
    if (d == 0)
      s += Line().put(7, 1, 10).put(h, 11, 20).put(fct3, 31, 40).str() + "\n";
    else if (d == 1 && h2 != 0)
      s += Line().put(7, 1, 10).put(h2, 11, 20).put(fct3, 31, 40).str() + "\n";
    else
      s += Line().put(0, 1, 10).str() + "\n";
    s += Line().put(0.0, 1, 20).str() + "\n";
  }
  s += Line().put(0, 1, 10).str() + "\n";
  return s;
}

// The elongation of the spring (node 2's X displacement) every cycle until t_stop.
std::vector<double> elongations(const radx::model::Model& m, double t_stop) {
  radx::model::RunControls rc;
  rc.t_stop = t_stop;
  radx::solver::ExplicitEngine engine(m, rc, radx::solver::EngineOptions{1, 1});
  std::vector<double> u;
  engine.run([&](const radx::solver::CycleReport&) {
    u.push_back(engine.nodes().x[1] - 100.0);
    return true;
  });
  return u;
}

}  // namespace

TEST_CASE("elasto-plastic spring-mass oscillator in the engine: TYPE4 H 1 and TYPE8 H 6",
          "[spring][spring8][hardening][engine]") {
  // K = 1000 N/mm, f1 = K x up to x_y = 1 mm (F_y = 1000 N), then slope h = 10 N/mm; the mass m = 1e-3 Mg
  // (plus half the spring's 1e-6) starts at v0 = 2000 mm/s: KE0 = m v0^2 / 2 = 2000 N mm. Energy to the
  // first stop: KE0 = K x_y^2 / 2 + F_y d + h d^2 / 2 with d = x_max - x_y, so
  //   d = (-F_y + sqrt(F_y^2 + 2 h (KE0 - K x_y^2 / 2))) / h,  f_max = F_y + h d.
  // Both laws then unload with slope K (H 1: K; H 6: the slope of fct_ID3 = K) and swing elastically about
  // the residual elongation x_max - f_max / K down to x_max - 2 f_max / K, where the compressive force is
  // f_max: the isotropic yield of both (touched, not passed).
  const double K = 1000.0, h = 10.0, Fy = 1000.0, m = 1e-3, M = 1e-6, v0 = 2000.0;
  const double mass = m + 0.5 * M;
  const double ke0 = 0.5 * mass * v0 * v0;
  const double d = (-Fy + std::sqrt(Fy * Fy + 2 * h * (ke0 - 0.5 * K))) / h;
  const double x_max = 1.0 + d, f_max = Fy + h * d;
  const double x_min = x_max - 2 * f_max / K;
  const std::vector<std::array<double, 2>> f1 = {{-101, -2000}, {-1, -1000}, {0, 0}, {1, 1000}, {101, 2000}};
  const std::vector<std::array<double, 2>> f3 = {{-1, -1000}, {1, 1000}};
  const double period = 2 * 3.141592653589793 * std::sqrt(mass / K);
  for (int type : {4, 8}) {
    INFO("TYPE" << type);
    const std::string prop = type == 4 ? type4_prop(M, K, 1, 0) : type8_prop(M, K, 6, 8);
    const auto model = radx::test::model_of_deck(oscillator(prop, m, v0, f1, f3));
    const auto u = elongations(model, 2.5 * period);
    const double top = *std::max_element(u.begin(), u.end());
    // The swing after the first peak.
    const auto peak = std::max_element(u.begin(), u.end());
    const double bottom = *std::min_element(peak, u.end());
    // The step is sqrt(M / K) = 3e-5 s against a period of 6.3e-3 s: sampling and the central-difference
    // phase error move the extremes by well under 0.2 % of the 2 mm amplitude.
    CHECK(std::abs(top - x_max) < 2e-3 * x_max);
    CHECK(std::abs(bottom - x_min) < 4e-3);
    // The plastic part stays: the swing is centred on the residual elongation, not on 0.
    CHECK(std::abs(0.5 * (top + bottom) - (x_max - f_max / K)) < 4e-3);
  }
}

TEST_CASE("spring starter: the hardening flags and their curves", "[spring][spring8][hardening][starter]") {
  auto diags_of = [](const std::string& text, radx::Severity sev) {
    radx::test::TempDir dir;
    radx::Diagnostics diags;
    const auto deck = radx::read_starter_deck(dir.write("m_0000.rad", text), diags);
    (void)radx::build_model(deck, diags);
    std::string all;
    for (const auto& dg : diags.items())
      if (dg.severity == sev) all += radx::Diagnostics::format(dg) + "\n";
    return all;
  };
  const std::vector<std::array<double, 2>> f1 = {{0, 0}, {1, 1000}, {2, 1100}};
  const std::vector<std::array<double, 2>> f3 = {{0, 0}, {1, 1000}};
  // Each H runs on TYPE4 with its curves; 4, 5 and 6 refuse a missing fct_ID3 (RX502).
  for (int h : {1, 2, 4, 5, 6, 7, 8}) {
    INFO("H " << h);
    CHECK(diags_of(oscillator(type4_prop(1e-6, 1000, h, 8), 1e-3, 0, f1, f3), radx::Severity::Error) == "");
    const auto e = diags_of(oscillator(type4_prop(1e-6, 1000, h, 0), 1e-3, 0, f1, f3), radx::Severity::Error);
    if (h == 4 || h == 5 || h == 6) {
      CHECK(e.find("RX502") != std::string::npos);
      CHECK(e.find("needs the curve fct_ID3") != std::string::npos);
    } else {
      CHECK(e == "");
    }
  }
  // H 7 without fct_ID3 is H 2, with a warning (Radioss's message 1059).
  const auto m = radx::test::model_of_deck(oscillator(type4_prop(1e-6, 1000, 7, 0), 1e-3, 0, f1, f3));
  CHECK(m.properties[0].spring.x.hardening == 2);
  CHECK(diags_of(oscillator(type4_prop(1e-6, 1000, 7, 0), 1e-3, 0, f1, f3), radx::Severity::Warning)
            .find("is H = 2") != std::string::npos);
  // TYPE8: 1 to 7 run; 8 is refused by name (Radioss evaluates it at the initial offset).
  CHECK(diags_of(oscillator(type8_prop(1e-6, 1000, 6, 8, 1), 1e-3, 0, f1, f3), radx::Severity::Error) == "");
  const auto e =
      diags_of(oscillator(type8_prop(1e-6, 1000, 0, 8, 8), 1e-3, 0, f1, f3), radx::Severity::Error);
  CHECK(e.find("RX510") != std::string::npos);
  CHECK(e.find("H2 = 8 (elastic, force of the total length)") != std::string::npos);
}
