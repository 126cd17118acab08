// TYPE4 springs (/SPRING with /PROP/SPRING): the kernel against its force law, the engine against the
// closed-form oscillator, the starter's reading and checks. Expected values come from formulas.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "kernel_test_util.hpp"
#include "solver/conditions/functions.hpp"
#include "solver/elements/element_groups.hpp"
#include "solver/engine/explicit_engine.hpp"
#include "test_util.hpp"

namespace {

using radx::test::Line;
using radx::test::rel;

constexpr std::size_t G = radx::solver::kGroupSize;

// One spring between nodes 0 and 1 of `ns`, initial length from x0.
radx::solver::SpringGroup one_spring(const radx::solver::NodeState& ns,
                                     const radx::model::SpringProperty& p) {
  radx::solver::SpringGroup g;
  g.allocate(1);
  g.props = p;
  g.conn[0] = 0;
  g.conn[G] = 1;
  g.element[0] = 0;
  g.l0[0] = std::hypot(ns.x0[1] - ns.x0[0], ns.y0[1] - ns.y0[0], ns.z0[1] - ns.z0[0]);
  return g;
}

radx::model::Function curve(std::vector<double> x, std::vector<double> y) {
  radx::model::Function f;
  f.id = 1;
  f.x = std::move(x);
  f.y = std::move(y);
  return f;
}

// Starter deck of the oscillator: node 1 clamped, node 2 with the added mass m_add and the initial velocity
// v0 along X, spring 1 of /PROP/SPRING/1 between them along X (length 100 mm). Units Mg mm s.
std::string oscillator_deck(double M, double K, double C, double m_add, double v0,
                            const std::string& extra = "", int fct1 = 0) {
  std::string s = radx::test::begin_block(2019);
  s += "/NODE\n" + Line().put(1, 1, 10).put(0.0, 11, 30).put(0.0, 31, 50).put(0.0, 51, 70).str() + "\n" +
       Line().put(2, 1, 10).put(100.0, 11, 30).put(0.0, 31, 50).put(0.0, 51, 70).str() + "\n";
  s += "/PART/1\nspring\n" + Line().put(1, 1, 10).put(0, 11, 20).str() + "\n";
  s += "/SPRING/1\n" + Line().put(1, 1, 10).put(1, 11, 20).put(2, 21, 30).str() + "\n";
  s += "/PROP/SPRING/1\nspring\n" + Line().put(M, 1, 20).str() + "\n" +
       Line().put(K, 1, 20).put(C, 21, 40).str() + "\n" + Line().put(fct1, 1, 10).put(0, 11, 20).str() +
       "\n" + Line().put(0.0, 1, 20).str() + "\n";
  s += "/GRNOD/NODE/1\nclamped\n" + Line().put(1, 1, 10).str() + "\n";
  s += "/BCS/1\nclamped\n" + Line().put("111 111", 4, 10).put(0, 11, 20).put(1, 21, 30).str() + "\n";
  s += "/GRNOD/NODE/2\nmass\n" + Line().put(2, 1, 10).str() + "\n";
  s += "/ADMAS/0/1\nmass\n" + Line().put(m_add, 1, 20).put(2, 21, 30).str() + "\n";
  s += "/INIVEL/TRA/1\nstart\n" +
       Line().put(v0, 1, 20).put(0.0, 21, 40).put(0.0, 41, 60).put(2, 61, 70).str() + "\n";
  s += extra;
  s += "/END\n";
  return s;
}

struct Trace {
  std::vector<double> t, u;  // time and displacement of node 2 along X, every cycle
  double dt = 0;             // the first step
  radx::solver::StepControl control;
  radx::solver::EnergyBalance last;
};

Trace run(const radx::model::Model& m, double t_stop) {
  radx::model::RunControls rc;
  rc.t_stop = t_stop;
  radx::solver::ExplicitEngine engine(m, rc, radx::solver::EngineOptions{1, 1});
  Trace tr;
  engine.run([&](const radx::solver::CycleReport& r) {
    tr.t.push_back(r.time);
    tr.u.push_back(engine.nodes().x[1] - 100.0);
    if (tr.dt == 0) {
      tr.dt = r.dt;
      tr.control = r.control;
    }
    if (r.full) tr.last = r.energy;
    return true;
  });
  return tr;
}

// Times where u crosses 0 upwards (linear interpolation between cycles).
std::vector<double> upward_zeros(const Trace& tr) {
  std::vector<double> z;
  for (std::size_t k = 1; k < tr.u.size(); ++k)
    if (tr.u[k - 1] < 0 && tr.u[k] >= 0)
      z.push_back(tr.t[k - 1] + (tr.t[k] - tr.t[k - 1]) * (-tr.u[k - 1]) / (tr.u[k] - tr.u[k - 1]));
  return z;
}

// The local maxima of u.
std::vector<double> peaks(const Trace& tr) {
  std::vector<double> p;
  for (std::size_t k = 1; k + 1 < tr.u.size(); ++k)
    if (tr.u[k] > tr.u[k - 1] && tr.u[k] >= tr.u[k + 1] && tr.u[k] > 0) p.push_back(tr.u[k]);
  return p;
}

}  // namespace

TEST_CASE("spring kernel: linear force K dx along the line, equal and opposite, and its step", "[spring]") {
  auto ns = radx::test::make_nodes({{0, 0, 0}, {30, 40, 0}});  // L0 = 50
  radx::model::SpringProperty p;
  p.mass = 2.0;
  p.x.stiffness = 8.0;
  auto g = one_spring(ns, p);
  // Stretch by 5 along the line: x2 = (33, 44, 0), dx = 5, N = K dx = 40 in tension, pulling node 1
  // towards 2.
  ns.x[1] = 33;
  ns.y[1] = 44;
  radx::solver::spring_type4_forces(g, ns, radx::solver::CycleInfo{1e-3, 1e-3, 0});
  CHECK(rel(g.force[0], 40.0) < 1e-12);
  CHECK(rel(g.dx[0], 5.0) < 1e-12);
  CHECK(rel(g.nodal_force[0 * G], 40.0 * 0.6) < 1e-12);
  CHECK(rel(g.nodal_force[1 * G], 40.0 * 0.8) < 1e-12);
  CHECK(rel(g.nodal_force[3 * G], -40.0 * 0.6) < 1e-12);
  CHECK(rel(g.nodal_force[4 * G], -40.0 * 0.8) < 1e-12);
  // Undamped step sqrt(M/K) (r1len3.F); the trapezoid work (0 + 40)/2 * 5 = 100 = K dx^2 / 2.
  CHECK(rel(g.dt[0], std::sqrt(2.0 / 8.0)) < 1e-12);
  CHECK(rel(g.e_int[0], 100.0) < 1e-12);
  // With damping C: dt = M / (sqrt(C^2 + M K) + C), below sqrt(M/K).
  g.props.x.damping = 3.0;
  radx::solver::spring_type4_forces(g, ns, radx::solver::CycleInfo{1e-3, 1e-3, 0});
  CHECK(rel(g.dt[0], 2.0 / (std::sqrt(9.0 + 16.0) + 3.0)) < 1e-12);
}

TEST_CASE("spring kernel: a rigid rotation of the spring gives no force (objectivity)", "[spring]") {
  auto ns = radx::test::make_nodes({{1, 2, 3}, {11, 2, 3}});  // L0 = 10 along X
  radx::model::SpringProperty p;
  p.mass = 1.0;
  p.x.stiffness = 100.0;
  p.x.damping = 5.0;
  auto g = one_spring(ns, p);
  // Turn n2 about n1 in steps up to 90 degrees about Z then tilt about X: the length stays 10, so the
  // elongation, its rate and the force stay 0 to round-off (force scale K L0 = 1000).
  for (int k = 1; k <= 18; ++k) {
    const double a = k * std::numbers::pi / 36.0;
    ns.x[1] = 1 + 10 * std::cos(a);
    ns.y[1] = 2 + 10 * std::sin(a) * std::cos(a / 2);
    ns.z[1] = 3 + 10 * std::sin(a) * std::sin(a / 2);
    radx::solver::spring_type4_forces(g, ns, radx::solver::CycleInfo{1e-3, 1e-3, 0});
    CHECK(std::abs(g.force[0]) < 1e-9);
    for (std::size_t d = 0; d < 6; ++d) CHECK(std::abs(g.nodal_force[d * G]) < 1e-9);
  }
}

TEST_CASE("spring kernel: a spring by function follows the function, scaled and amplified", "[spring]") {
  // f(x) = 0 at 0, 100 at 1, 150 at 3 (then extrapolated with the last slope 25); Ascale = 2 stretches the
  // abscissa: N = f(x / 2).
  const auto f = curve({0.0, 1.0, 3.0}, {0.0, 100.0, 150.0});
  auto ns = radx::test::make_nodes({{0, 0, 0}, {10, 0, 0}});
  radx::model::SpringProperty p;
  p.mass = 1.0;
  p.x.stiffness = 100.0;
  p.x.ascale = 2.0;
  auto g = one_spring(ns, p);
  g.curves[0].load = &f;
  const double dt = 1e-3;
  for (const double x : {0.5, 1.0, 2.0, 4.0, 6.0, 8.0, 3.0, -1.0}) {
    ns.x[1] = 10 + x;
    radx::solver::spring_type4_forces(g, ns, radx::solver::CycleInfo{dt, dt, 0});
    // The velocity |dx|/dt is large here, but B = 0: the amplification stays A = 1.
    CHECK(rel(g.force[0], radx::solver::function_value(f, x / 2.0)) < 1e-12);
  }
  // The dynamic amplification A + B ln(max(1, |v|/D)): from x = 2 to 2.5 in dt, v = 500, D = 50:
  // N = (A + B ln 10) f(1.25).
  g.props.x.a = 1.5;
  g.props.x.b = 0.2;
  g.props.x.d = 50.0;
  ns.x[1] = 12.0;
  radx::solver::spring_type4_forces(g, ns, radx::solver::CycleInfo{dt, dt, 0});
  ns.x[1] = 12.5;
  radx::solver::spring_type4_forces(g, ns, radx::solver::CycleInfo{dt, dt, 0});
  const double v = 0.5 / dt;
  CHECK(rel(g.force[0], (1.5 + 0.2 * std::log(v / 50.0)) * radx::solver::function_value(f, 1.25)) < 1e-9);
  // Slow enough (|v| < D): no amplification beyond A.
  ns.x[1] = 12.52;
  radx::solver::spring_type4_forces(g, ns, radx::solver::CycleInfo{dt, dt, 0});
  CHECK(rel(g.force[0], 1.5 * radx::solver::function_value(f, 1.26)) < 1e-9);
}

TEST_CASE("spring kernel: H = 7 follows the loading curve, unloads with K, then along the unloading curve",
          "[spring]") {
  // f1 = 100 x, f3 = 50 x (both through 0), K = 1000: the expected forces are worked out by hand in the
  // comments below from the rule of spring_type4.cpp.
  const auto f1 = curve({0.0, 10.0}, {0.0, 1000.0});
  const auto f3 = curve({0.0, 10.0}, {0.0, 500.0});
  auto ns = radx::test::make_nodes({{0, 0, 0}, {10, 0, 0}});
  radx::model::SpringProperty p;
  p.mass = 1.0;
  p.x.stiffness = 1000.0;
  p.x.hardening = 7;
  auto g = one_spring(ns, p);
  g.curves[0].load = &f1;
  g.curves[0].unload = &f3;
  auto at = [&](double x) {
    ns.x[1] = 10 + x;
    radx::solver::spring_type4_forces(g, ns, radx::solver::CycleInfo{1e-3, 1e-3, 0});
    return g.force[0];
  };
  for (int k = 1; k <= 10; ++k) CHECK(rel(at(k), 100.0 * k) < 1e-12);  // loading: capped by f1
  CHECK(rel(at(9.9), 900.0) < 1e-9);  // unloading elastically: 1000 - K 0.1, above f3 = 495
  CHECK(rel(at(9.5), 500.0) < 1e-9);  // 900 - K 0.4, above f3 = 475
  CHECK(rel(at(9.0), 450.0) < 1e-9);  // 500 - K 0.5 = 0 falls below f3 = 450: on the unloading curve
  CHECK(rel(at(8.0), 400.0) < 1e-9);  // along f3
  CHECK(rel(at(8.5), 850.0) < 1e-9);  // reloading: 400 + K 0.5 = 900, capped by f1 = 850
  // The work of the loop: loading to 10 along f1 stores 5000; the way back down to 8 and up to 8.5 is the
  // trapezoid sum of the forces above.
  const double w = 5000.0 + (-0.1) * (1000 + 900) / 2 + (-0.4) * (900 + 500) / 2 + (-0.5) * (500 + 450) / 2 +
                   (-1.0) * (450 + 400) / 2 + 0.5 * (400 + 850) / 2;
  CHECK(rel(g.e_int[0], w) < 1e-9);
}

TEST_CASE("spring kernel: Ileng 1 makes M, K and the elongation per unit length, and delta_max breaks it",
          "[spring]") {
  auto ns = radx::test::make_nodes({{0, 0, 0}, {0, 0, 20}});  // L0 = 20
  radx::model::SpringProperty p;
  p.mass = 0.5;
  p.x.stiffness = 400.0;
  p.ileng = 1;
  p.x.delta_max = 3.0;
  auto g = one_spring(ns, p);
  ns.z[1] = 22;  // strain 0.1: N = K 0.1 = 40
  radx::solver::spring_type4_forces(g, ns, radx::solver::CycleInfo{1e-3, 1e-3, 0});
  CHECK(rel(g.force[0], 40.0) < 1e-12);
  // m = M L0 = 10, k = K / L0 = 20: dt = sqrt(m/k).
  CHECK(rel(g.dt[0], std::sqrt(10.0 / 20.0)) < 1e-12);
  CHECK(g.off[0] == 1.0);
  // Elongation 3.5 > delta_max = 3: broken, but the force of this cycle (K 3.5 / 20 = 70) still acts on the
  // nodes and its work counts, as Radioss applies it before switching the element off.
  ns.z[1] = 23.5;
  radx::solver::spring_type4_forces(g, ns, radx::solver::CycleInfo{1e-3, 1e-3, 0});
  CHECK(g.off[0] == 0.0);
  CHECK(rel(g.force[0], 70.0) < 1e-12);
  CHECK(rel(g.nodal_force[2 * G], 70.0) < 1e-12);  // tension pulls node 1 towards node 2 (+z)
  // Work: the strain step 0.075 under the mean force (40 + 70) / 2, times L0 = 20.
  const double work = 0.5 * 0.1 * 40.0 * 20.0 + 0.075 * (40.0 + 70.0) / 2 * 20.0;
  CHECK(rel(g.e_int[0], work) < 1e-12);
  CHECK(std::isinf(g.dt[0]));  // it no longer limits the step
  // The next cycle (elongation 4, strain step 0.025) carries no force; the trapezoid books the half increment
  // of the last force, 0.025 x 70 / 2 x 20; after that the energy stays.
  ns.z[1] = 24.0;
  radx::solver::spring_type4_forces(g, ns, radx::solver::CycleInfo{1e-3, 1e-3, 0});
  CHECK(g.force[0] == 0.0);
  CHECK(g.nodal_force[2 * G] == 0.0);
  const double work_after = work + 0.025 * 70.0 / 2 * 20.0;
  CHECK(rel(g.e_int[0], work_after) < 1e-12);
  ns.z[1] = 25.0;
  radx::solver::spring_type4_forces(g, ns, radx::solver::CycleInfo{1e-3, 1e-3, 0});
  CHECK(rel(g.e_int[0], work_after) < 1e-12);
}

TEST_CASE("spring-mass oscillator: period 2 pi sqrt(m/K) and amplitude v0/omega", "[spring][engine]") {
  // m = the added mass plus the spring's half M/2 on node 2. omega dt ~ 0.03, so the central-difference
  // period error (omega dt)^2/24 ~ 4e-5 is far inside the 0.5 % the test allows.
  const double M = 1e-6, K = 1000.0, m_add = 1e-3, v0 = 100.0;
  const auto m = radx::test::model_of_deck(oscillator_deck(M, K, 0.0, m_add, v0));
  REQUIRE(m.springs.size() == 1);
  const double mass = m_add + 0.5 * M;
  CHECK(rel(m.node_mass[1], mass) < 1e-12);
  const double omega = std::sqrt(K / mass), period = 2 * std::numbers::pi / omega;
  const auto tr = run(m, 3.2 * period);
  // The spring controls the step: 0.9 sqrt(M / K).
  CHECK(tr.control.kind == radx::solver::StepControl::Kind::Spring);
  CHECK(tr.control.user_id == 1);
  CHECK(rel(tr.dt, 0.9 * std::sqrt(M / K)) < 1e-12);
  const auto z = upward_zeros(tr);
  REQUIRE(z.size() >= 3);
  const double measured = (z.back() - z.front()) / static_cast<double>(z.size() - 1);
  CHECK(rel(measured, period) < 0.005);
  const auto pk = peaks(tr);
  REQUIRE(!pk.empty());
  CHECK(rel(pk.front(), v0 / omega) < 0.005);
  // No damping: the spring's work and the kinetic energy add up to the initial kinetic energy (the
  // step's energy error, of order (omega dt)^2, well below 1e-3).
  const double e0 = 0.5 * mass * v0 * v0;
  CHECK(rel(tr.last.internal + tr.last.kinetic_t, e0) < 1e-3);
  CHECK(tr.last.spring == tr.last.internal);
}

TEST_CASE("damped spring-mass oscillator decays at the rate C/(2m) with frequency omega sqrt(1 - zeta^2)",
          "[spring][engine]") {
  const double M = 1e-6, K = 1000.0, m_add = 1e-3, v0 = 100.0;
  const double mass = m_add + 0.5 * M;
  const double zeta = 0.05, C = 2 * zeta * std::sqrt(K * mass);
  const auto m = radx::test::model_of_deck(oscillator_deck(M, K, C, m_add, v0));
  const double omega = std::sqrt(K / mass), omega_d = omega * std::sqrt(1 - zeta * zeta);
  const double period_d = 2 * std::numbers::pi / omega_d;
  const auto tr = run(m, 4.2 * period_d);
  const auto pk = peaks(tr);
  REQUIRE(pk.size() >= 4);
  // Successive peaks are one damped period apart: ln(A_k / A_{k+3}) / (3 T_d) = C / (2 m). The damping
  // force lags by half a step (v from the last increment): a relative error of order omega dt ~ 3 %
  // on the phase, 1e-4 on the decay rate; 1 % allows the peak sampling too.
  const double rate = std::log(pk[0] / pk[3]) / (3 * period_d);
  CHECK(rel(rate, C / (2 * mass)) < 0.01);
  const auto z = upward_zeros(tr);
  REQUIRE(z.size() >= 3);
  CHECK(rel((z.back() - z.front()) / static_cast<double>(z.size() - 1), period_d) < 0.005);
  // The damping work is in the spring energy: KE + IE stays the initial kinetic energy.
  CHECK(rel(tr.last.internal + tr.last.kinetic_t, 0.5 * mass * v0 * v0) < 2e-3);
}

TEST_CASE("spring by function in the engine: the time history force follows the curve", "[spring][engine]") {
  // A stiffening curve f(x) = 500 x + 50 x^3 sampled every 0.5 mm; node 2 pulled at 1000 mm/s by /IMPVEL:
  // the elongation is imposed, so N must be f(x) at each cycle, with no dynamics in between (B = 0).
  std::string fun = "/FUNCT/7\nstiffening\n";
  std::vector<double> fx, fy;
  for (int k = -2; k <= 12; ++k) {
    const double x = 0.5 * k;
    fx.push_back(x);
    fy.push_back(500 * x + 50 * x * x * x);
    fun += Line().put(x, 1, 20).put(fy.back(), 21, 40).str() + "\n";
  }
  fun += "/FUNCT/8\nconstant\n" + Line().put(0.0, 1, 20).put(1000.0, 21, 40).str() + "\n" +
         Line().put(100.0, 1, 20).put(1000.0, 21, 40).str() + "\n";
  fun += "/IMPVEL/1\npull\n" +
         Line().put(8, 1, 10).put("X", 20, 20).put(0, 21, 30).put(0, 31, 40).put(2, 41, 50).str() + "\n" +
         Line().put(0.0, 1, 20).put(1.0, 21, 40).str() + "\n";
  const auto m = radx::test::model_of_deck(oscillator_deck(1e-6, 6000.0, 0.0, 1e-3, 0.0, fun, 7));
  REQUIRE(m.properties[0].spring.x.f_load == 0);
  radx::model::RunControls rc;
  rc.t_stop = 5e-3;
  const radx::model::Function f = curve(fx, fy);
  radx::solver::ExplicitEngine engine(m, rc, radx::solver::EngineOptions{1, 1000});
  int checked = 0;
  double worst = 0;
  engine.run([&](const radx::solver::CycleReport&) {
    const auto& g = engine.groups().springs[0];
    const double x = g.dx[0];
    if (x > 0.1) {
      worst =
          std::max(worst, std::abs(g.force[0] - radx::solver::function_value(f, x)) / std::abs(g.force[0]));
      ++checked;
    }
    return true;
  });
  CHECK(checked > 100);
  CHECK(worst < 1e-9);  // the curve is read exactly: only round-off
}

TEST_CASE("spring starter: property defaults, the mass of the nodes, refusals by name", "[spring][starter]") {
  const auto m = radx::test::model_of_deck(oscillator_deck(2e-6, 1000.0, 0.5, 1e-3, 0.0));
  const auto& p = m.properties[0];
  CHECK(p.kind == radx::model::PropertyKind::Spring);
  CHECK(p.spring.x.a == 1.0);
  CHECK(p.spring.x.d == 1.0);
  CHECK(p.spring.x.fscale == 1.0);
  CHECK(p.spring.x.ascale == 1.0);
  CHECK(p.spring.x.delta_max >= 1e30);
  CHECK(p.spring.x.damping == 0.5);
  CHECK(m.node_mass[0] == 1e-6);  // M/2 on the clamped node

  auto errors_of = [](const std::string& text) {
    radx::test::TempDir dir;
    radx::Diagnostics diags;
    const auto deck = radx::read_starter_deck(dir.write("m_0000.rad", text), diags);
    (void)radx::build_model(deck, diags);
    std::string all;
    for (const auto& d : diags.items())
      if (d.severity == radx::Severity::Error) all += radx::Diagnostics::format(d) + "\n";
    return all;
  };
  // Non-positive mass.
  auto e = errors_of(oscillator_deck(0.0, 1000.0, 0.0, 1e-3, 0.0));
  CHECK(e.find("RX501") != std::string::npos);
  CHECK(e.find("spring mass M") != std::string::npos);
  // Negative stiffness.
  e = errors_of(oscillator_deck(1e-6, -5.0, 0.0, 1e-3, 0.0));
  CHECK(e.find("stiffness K = -5 is negative") != std::string::npos);
  // A missing function.
  e = errors_of(oscillator_deck(1e-6, 1000.0, 0.0, 1e-3, 0.0, "", 99));
  CHECK(e.find("fct_ID1 = 99: there is no /FUNCT/99") != std::string::npos);
  // H = 4 on a spring by function needs fct_ID3, its lower yield curve (RX502).
  const std::string fun = "/FUNCT/7\nforce\n" + Line().put(0.0, 1, 20).put(0.0, 21, 40).str() + "\n" +
                          Line().put(1.0, 1, 20).put(1000.0, 21, 40).str() + "\n";
  std::string h1 = oscillator_deck(1e-6, 1000.0, 0.0, 1e-3, 0.0, fun, 7);
  const std::string card3 = Line().put(7, 1, 10).put(0, 11, 20).str();
  const auto at = h1.find(card3 + "\n");
  REQUIRE(at != std::string::npos);
  h1.replace(at, card3.size(), Line().put(7, 1, 10).put(4, 11, 20).str());
  e = errors_of(h1);
  CHECK(e.find("RX502") != std::string::npos);
  CHECK(e.find("H = 4 needs the curve fct_ID3") != std::string::npos);
  CHECK(errors_of(h1.substr(0, at) + Line().put(7, 1, 10).put(7, 11, 20).put(7, 31, 40).str() +
                  h1.substr(at + card3.size())) == "");  // H = 7 with both curves runs
}

TEST_CASE("spring with K = 0 and a force curve: the curve is the law, its steepest slope gives the step",
          "[spring][starter]") {
  // A curve through 0 with slopes 400 then 1000 (N/mm): the step stiffness is 1000, the step sqrt(M / 1000).
  const std::string fun = "/FUNCT/7\nforce\n" + Line().put(-1.0, 1, 20).put(-400.0, 21, 40).str() + "\n" +
                          Line().put(0.0, 1, 20).put(0.0, 21, 40).str() + "\n" +
                          Line().put(1.0, 1, 20).put(1000.0, 21, 40).str() + "\n";
  radx::test::TempDir dir;
  radx::Diagnostics diags;
  const auto deck = radx::read_starter_deck(
      dir.write("k0_0000.rad", oscillator_deck(1e-6, 0.0, 0.0, 1e-3, 0.0, fun, 7)), diags);
  const auto m = radx::build_model(deck, diags);
  std::string all;
  for (const auto& d : diags.items()) all += radx::Diagnostics::format(d) + "\n";
  INFO(all);
  REQUIRE_FALSE(diags.has_errors());
  CHECK(diags.contains(radx::Diag::DefaultApplied));
  CHECK(all.find("largest slope A df/dx = 1000") != std::string::npos);
  CHECK(m.properties[0].spring.x.stiffness == Approx(1000.0));
  // The engine's step on the oscillator: Tscale sqrt(M / k) with k = 1000, as OpenRadioss steps a straight
  // curve of that slope with K = 0 (not unbounded).
  const auto tr = run(m, 1e-4);
  CHECK(tr.dt == Approx(0.9 * std::sqrt(1e-6 / 1000.0)).epsilon(1e-6));
}

TEST_CASE("spring with K = 0, no damping and no curve: read with a warning, it carries its mass and no force",
          "[spring][starter]") {
  // Radioss runs such a spring (its QA deck IMPOSED/IMPDISP_FGEO carries a node's mass with one).
  radx::test::TempDir dir;
  radx::Diagnostics diags;
  const auto deck =
      radx::read_starter_deck(dir.write("m_0000.rad", oscillator_deck(2e-6, 0.0, 0.0, 1e-3, 100.0)), diags);
  const auto m = radx::build_model(deck, diags);
  REQUIRE_FALSE(diags.has_errors());
  std::string warnings;
  for (const auto& d : diags.items())
    if (d.severity == radx::Severity::Warning) warnings += radx::Diagnostics::format(d) + "\n";
  CHECK(warnings.find("carries no force, only its mass") != std::string::npos);
  // The free node flies at its initial velocity: no spring force acts on it (100 mm/s over 1 ms).
  const auto tr = run(m, 1e-3);
  REQUIRE_FALSE(tr.u.empty());
  CHECK(std::abs(tr.u.back() - 100.0 * tr.t.back()) < 1e-9);
}
