// Type-3 beams (/BEAM with /PROP/BEAM): the kernel against its section laws and the equilibrium of its nodal
// forces, a cantilever against Euler-Bernoulli's static deflection and first frequency, and the starter's
// checks. Expected values come from formulas with the deck's own parameters.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>
#include <vector>

#include "kernel_test_util.hpp"
#include "solver/elements/element_groups.hpp"
#include "solver/engine/explicit_engine.hpp"
#include "solver/materials/failure.hpp"
#include "solver/materials/material_params.hpp"
#include "test_util.hpp"

namespace {

using radx::test::Line;
using radx::test::rel;

constexpr std::size_t G = radx::solver::kGroupSize;

// Steel in Mg mm s and a 10 x 10 mm square section: A, I = a^4 / 12, the torsion constant 0.1406 a^4.
constexpr double kE = 210000.0, kRho = 7.85e-9, kNu = 0.3;
constexpr double kA = 100.0, kI = 10000.0 / 12.0, kJ = 1406.0;

radx::solver::MaterialParams steel(double a = 0) {
  radx::model::Material m;
  m.law = a > 0 ? radx::model::MaterialLaw::JohnsonCook : radx::model::MaterialLaw::Elastic;
  m.rho = kRho;
  m.young = kE;
  m.poisson = kNu;
  m.a = a;
  m.n = 1;
  return radx::solver::make_material_params(m);
}

// One beam from node 0 to node 1 along X, y axis along global Y, no damping.
radx::solver::BeamGroup one_beam(double l) {
  radx::solver::BeamGroup g;
  g.allocate(1);
  g.conn[0] = 0;
  g.conn[G] = 1;
  g.element[0] = 0;
  g.l0[0] = l;
  g.ey[G] = 1.0;
  g.section = {kA, kI, kI, kJ, 0.0, 0.0, false};
  return g;
}

// The cantilever: n beams along X over L, node 1 clamped, the tip loaded by P along Z from t = 0.
std::string cantilever_deck(int n, double L, double P) {
  std::string s = radx::test::begin_block(2024);
  s += "/NODE\n";
  for (int k = 0; k <= n; ++k)
    s += Line().put(k + 1, 1, 10).put(k * L / n, 11, 30).put(0.0, 31, 50).put(0.0, 51, 70).str() + "\n";
  s += "/BEAM/1\n";
  for (int k = 0; k < n; ++k)
    s += Line().put(k + 1, 1, 10).put(k + 1, 11, 20).put(k + 2, 21, 30).str() + "\n";
  s += "/PART/1\ncantilever\n" + Line().put(1, 1, 10).put(1, 11, 20).str() + "\n";
  s += "/PROP/BEAM/1\nsquare 10 mm\n" + Line().put(0, 11, 20).str() + "\n" + Line().put(0.0, 1, 20).str() +
       "\n" + Line().put(kA, 1, 20).put(kI, 21, 40).put(kI, 41, 60).put(kJ, 61, 80).str() + "\n" +
       Line().put("000 000", 4, 10).put(0, 11, 20).str() + "\n";
  s += "/MAT/LAW1/1\nsteel\n" + Line().put(kRho, 1, 20).str() + "\n" +
       Line().put(kE, 1, 20).put(kNu, 21, 40).str() + "\n";
  s += "/GRNOD/NODE/1\nclamped\n" + Line().put(1, 1, 10).str() + "\n";
  s += "/BCS/1\nclamped\n" + Line().put("111 111", 4, 10).put(0, 11, 20).put(1, 21, 30).str() + "\n";
  s += "/GRNOD/NODE/2\ntip\n" + Line().put(n + 1, 1, 10).str() + "\n";
  s += "/FUNCT/1\nconstant\n" + Line().put(0.0, 1, 20).put(1.0, 21, 40).str() + "\n" +
       Line().put(10.0, 1, 20).put(1.0, 21, 40).str() + "\n";
  s += "/CLOAD/1\ntip load\n" +
       Line()
           .put(1, 1, 10)
           .put("Z", 11, 20)
           .put(0, 21, 30)
           .put(0, 31, 40)
           .put(2, 41, 50)
           .put(0.0, 61, 80)
           .put(P, 81, 100)
           .str() +
       "\n";
  s += "/END\n";
  return s;
}

std::string errors_of(const std::string& text) {
  radx::test::TempDir dir;
  radx::Diagnostics diags;
  const auto deck = radx::read_starter_deck(dir.write("m_0000.rad", text), diags);
  (void)radx::build_model(deck, diags);
  std::string all;
  for (const auto& d : diags.items())
    if (d.severity == radx::Severity::Error) all += radx::Diagnostics::format(d) + "\n";
  return all;
}

}  // namespace

TEST_CASE("beam kernel: a stretch gives N = E A eps, a bend M = E I kappa, and the forces balance",
          "[beam]") {
  const double l = 100.0, dt = 1e-4;
  const auto mat = steel();
  auto ns = radx::test::make_nodes({{0, 0, 0}, {l, 0, 0}});
  auto g = one_beam(l);
  // Node 2 moves along X at u: exx = u / l (the mid-step terms vanish for a motion along the line).
  const double u = 10.0;
  ns.vx[1] = u;
  radx::solver::beam_type3_forces(g, ns, mat, radx::solver::CycleInfo{dt, dt, 0});
  const double n = kE * kA * u / l * dt;
  CHECK(rel(g.resultant[0], n) < 1e-12);
  CHECK(rel(g.nodal_force[0 * G], n) < 1e-12);   // node 1 pulled towards node 2
  CHECK(rel(g.nodal_force[6 * G], -n) < 1e-12);  // node 2 back
  CHECK(rel(g.e_int[0], 0.5 * n * u / l * dt * l) < 1e-12);
  // A relative rotation rate about Z at node 2 (w): kzz = w / l, Mz = E Izz kzz dt; the shear of the
  // rotation's mean (exy -= (rz1 + rz2) / 2) gives Qy, and the moments balance the shear couple.
  auto ns2 = radx::test::make_nodes({{0, 0, 0}, {l, 0, 0}});
  auto b = one_beam(l);
  const double w = 0.01;
  ns2.wz[1] = w;
  radx::solver::beam_type3_forces(b, ns2, mat, radx::solver::CycleInfo{dt, dt, 0});
  CHECK(rel(b.resultant[5 * G], kE * kI * w / l * dt) < 1e-9);
  double f[3] = {0, 0, 0}, m[3] = {0, 0, 0};
  const double x[2][3] = {{0, 0, 0}, {l, 0, 0}};
  for (int q = 0; q < 2; ++q)
    for (int d = 0; d < 3; ++d) {
      f[d] += b.nodal_force[static_cast<std::size_t>(6 * q + d) * G];
      m[d] += b.nodal_force[static_cast<std::size_t>(6 * q + 3 + d) * G];
    }
  // Moments about the origin: the nodal moments plus x2 x f2.
  const double f2[3] = {b.nodal_force[6 * G], b.nodal_force[7 * G], b.nodal_force[8 * G]};
  m[2] += x[1][0] * f2[1] - x[1][1] * f2[0];
  m[1] += x[1][2] * f2[0] - x[1][0] * f2[2];
  const double scale = std::abs(b.resultant[5 * G]) + std::abs(b.resultant[1 * G]) * l;
  for (int d = 0; d < 3; ++d) {
    CHECK(std::abs(f[d]) <= 1e-12 * scale);
    CHECK(std::abs(m[d]) <= 1e-12 * scale);
  }
  // The step: k l / c / sqrt(F) with no damping (k = 1), F = max(1, l / (A l^2 / 12 I + 6 E / 5 G)).
  const double fsh = std::max(1.0, l / (kA * l * l / (12 * kI) + 1.2 * kE / mat.shear));
  CHECK(rel(b.dt[0], l / std::sqrt(kE / kRho) / std::sqrt(fsh)) < 1e-12);
}

TEST_CASE("beam kernel: a rigid rotation of the beam gives no resultants (objectivity)", "[beam]") {
  const double l = 100.0, dt = 1e-5, w = 50.0;  // 0.05 rad per step about Z, nodes and element together
  const auto mat = steel();
  auto ns = radx::test::make_nodes({{0, 0, 0}, {l, 0, 0}});
  auto g = one_beam(l);
  // Rigid rotation about Z through node 1 at rate w: v2 = w e_z x (l, 0, 0) = (0, w l, 0), both nodes' w = w.
  ns.vy[1] = w * l;
  ns.wz[0] = ns.wz[1] = w;
  radx::solver::beam_type3_forces(g, ns, mat, radx::solver::CycleInfo{dt, dt, 0});
  const double ref = kE * kA * 1e-6;  // the force of a strain of 1e-6
  for (std::size_t k = 0; k < 3; ++k) CHECK(std::abs(g.resultant[k * G]) < ref);
  for (std::size_t k = 3; k < 6; ++k) CHECK(std::abs(g.resultant[k * G]) < ref * l);
}

TEST_CASE("beam kernel: law 2 caps the equivalent stress of the resultants at the yield stress", "[beam]") {
  const double l = 100.0, dt = 1.0, a = 200.0;
  const auto mat = steel(a);
  auto ns = radx::test::make_nodes({{0, 0, 0}, {l, 0, 0}});
  auto g = one_beam(l);
  ns.vx[1] = 1.0;  // a strain increment of 0.01: far above a / E
  radx::solver::beam_type3_forces(g, ns, mat, radx::solver::CycleInfo{dt, dt, 0});
  CHECK(rel(g.resultant[0], a * kA) < 1e-12);  // pure tension: N = a A
  // Plastic strain: half the plastic work per unit length over sigma_y A (m2lawp.F); the work of the
  // increment (N_old + N_new) d eps = a A 0.01 less the elastic part (a A)^2 / (E A).
  const double work = a * kA * 0.01 - (a * kA) * (a * kA) / (kE * kA);
  CHECK(rel(g.eps_p[0], 0.5 * work / a / kA) < 1e-12);
}

// Pulls (dir 1) or pushes (dir -1) a law-2 beam at a constant strain increment until it starts to fade;
// returns its plastic strain when it did (0 if it never did in `cycles`), with its damage in `dmg`.
double eps_p_at_failure(const radx::solver::MaterialParams& mat, double dir, int cycles, double& dmg) {
  const double l = 100.0, dt = 1.0;
  auto ns = radx::test::make_nodes({{0, 0, 0}, {l, 0, 0}});
  auto g = one_beam(l);
  ns.vx[1] = 0.05 * dir;  // 5e-4 strain per cycle: the section yields after a few cycles
  for (int c = 0; c < cycles; ++c) {
    const double eps_p0 = g.eps_p[0];
    radx::solver::beam_type3_forces(g, ns, mat, radx::solver::CycleInfo{dt, dt, 0});
    ns.x[1] += ns.vx[1] * dt;
    if (g.off[0] < 1.0) {
      dmg = g.dmg[0];
      // the damage of this cycle's plastic increment took it past 1: the strain it failed at lies in it
      CHECK(eps_p0 < g.eps_p[0]);
      return g.eps_p[0];
    }
  }
  dmg = g.dmg[0];
  return 0.0;
}

TEST_CASE("beam kernel: /FAIL/BIQUAD and /FAIL/JOHNSON fail a yielding beam at eps_f of its triaxiality",
          "[beam][fail]") {
  // Pure tension or compression of the section: sigma_m / s = N / 3A / (|N| / A) = +-1/3, so the biquadratic
  // curve gives C3 in tension and C1 in compression, Johnson-Cook D1 + D2 exp(+-D3 / 3).
  auto mat = steel(200.0);
  const double c1 = 0.06, c3 = 0.03;
  radx::solver::fail_biquad_fit(c1, 0.04, c3, 0.02, 0.025, mat.fail);
  mat.fail.on = true;
  mat.fail.kind = radx::solver::FailKind::Biquad;
  // Once yielding on a flat curve the plastic strain grows by the strain increment, at most 5e-4 a cycle
  // (the length grows): the beam fails within one increment past eps_f.
  const double step = 5e-4;
  double dmg = 0;
  const double tension = eps_p_at_failure(mat, 1.0, 1000, dmg);
  CHECK(dmg == 1.0);
  CHECK(tension >= c3);
  CHECK(tension < c3 + step);
  const double compression = eps_p_at_failure(mat, -1.0, 1000, dmg);
  CHECK(compression >= c1);
  CHECK(compression < c1 + step);

  auto jc = steel(200.0);
  jc.fail.on = true;
  jc.fail.kind = radx::solver::FailKind::Johnson;
  jc.fail.d1 = 0.01;
  jc.fail.d2 = 0.05;
  jc.fail.d3 = -1.5;
  const double eps_f = 0.01 + 0.05 * std::exp(-1.5 / 3.0);
  const double jc_tension = eps_p_at_failure(jc, 1.0, 1000, dmg);
  CHECK(jc_tension >= eps_f);
  CHECK(jc_tension < eps_f + step);
  // Without a failure model the same beam does not fail (EPS_max is infinite).
  auto plain = steel(200.0);
  CHECK(eps_p_at_failure(plain, 1.0, 400, dmg) == 0.0);
}

TEST_CASE("beam cantilever: the tip swings about P L^3 / 3 E I with the first bending period",
          "[beam][engine]") {
  const int n = 10;
  const double L = 1000.0, P = 10.0;
  const auto m = radx::test::model_of_deck(cantilever_deck(n, L, P));
  REQUIRE(m.beams.size() == static_cast<std::size_t>(n));
  CHECK(rel(m.total_mass, kRho * kA * L) < 1e-12);
  const double omega = 1.875104 * 1.875104 * std::sqrt(kE * kI / (kRho * kA * L * L * L * L));
  const double period = 2 * std::numbers::pi / omega;
  const double shear = 0.5 * kE / (1 + kNu);
  const double delta = P * L * L * L / (3 * kE * kI) + P * L / (5.0 / 6.0 * shear * kA);
  radx::model::RunControls rc;
  rc.t_stop = 3.0 * period;
  radx::solver::ExplicitEngine engine(m, rc, radx::solver::EngineOptions{1, 1});
  std::vector<double> t, w;
  engine.run([&](const radx::solver::CycleReport& r) {
    t.push_back(r.time);
    w.push_back(engine.nodes().z[static_cast<std::size_t>(n)]);
    return true;
  });
  // Upward crossings of the static deflection: the period; the mean between the first and the last: delta.
  if (std::getenv("RADX_BEAM_TRACE"))
    for (std::size_t k = 0; k < w.size(); k += 500) std::printf("%g %g\n", t[k], w[k]);
  std::vector<double> up;
  for (std::size_t k = 1; k < w.size(); ++k)
    if (w[k - 1] < delta && w[k] >= delta) up.push_back(t[k]);
  INFO("tip z from " << *std::min_element(w.begin(), w.end()) << " to "
                     << *std::max_element(w.begin(), w.end()) << ", static deflection " << delta << ", "
                     << w.size() << " cycles");
  REQUIRE(up.size() >= 3);
  const double measured = (up.back() - up.front()) / static_cast<double>(up.size() - 1);
  INFO("period " << measured << " expected " << period);
  // Ten elements and the step load's higher modes: the period within 3 %.
  CHECK(rel(measured, period) < 0.03);
  double sum = 0, span = 0;
  for (std::size_t k = 1; k < w.size(); ++k)
    if (t[k] > up.front() && t[k] <= up.back()) sum += w[k] * (t[k] - t[k - 1]), span += t[k] - t[k - 1];
  INFO("mean tip deflection " << sum / span << " expected " << delta);
  // The mean over whole periods is the static deflection (2 % of L^3 / 3 E I: the deflection is 1.9 % of
  // L, so the geometric stiffening stays below that).
  CHECK(rel(sum / span, delta) < 0.03);
}

TEST_CASE("beam starter: what radx refuses by name", "[beam][starter]") {
  const std::string base = cantilever_deck(2, 100.0, 1.0);
  // Small strain.
  std::string small = base;
  const std::string ismstr = Line().put(0, 11, 20).str() + "\n" + Line().put(0.0, 1, 20).str();
  small.replace(small.find(ismstr), ismstr.size(),
                Line().put(1, 11, 20).str() + "\n" + Line().put(0.0, 1, 20).str());
  CHECK(errors_of(small).find("Ismstr = 1") != std::string::npos);
  // A law type-3 beams do not run.
  std::string tab = base;
  tab.replace(tab.find("/MAT/LAW1/1"), 11, "/MAT/VOID/1");
  CHECK(errors_of(tab).find("beams run law 1") != std::string::npos);
  // An orientation node on the axis.
  std::string axis = base;
  const std::string first = Line().put(1, 1, 10).put(1, 11, 20).put(2, 21, 30).str();
  axis.replace(axis.find(first), first.size(),
               Line().put(1, 1, 10).put(1, 11, 20).put(2, 21, 30).put(3, 31, 40).str());
  CHECK(errors_of(axis).find("lies on the beam's axis") != std::string::npos);
}
