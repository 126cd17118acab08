// TYPE8 general springs (/SPRING with /PROP/SPR_GENE): the kernel against its six force laws in a skewed
// frame, the hysteresis loop of the shared law by hand, the failure criteria, the engine against the
// closed-form translational and torsional oscillators, the starter's reading and refusals. Expected values
// come from formulas.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "kernel_test_util.hpp"
#include "solver/elements/element_groups.hpp"
#include "solver/engine/explicit_engine.hpp"
#include "test_util.hpp"

namespace {

using radx::test::Line;
using radx::test::rel;

constexpr std::size_t G = radx::solver::kGroupSize;

// A TYPE8 group of one spring between nodes 0 and 1, frame rows `frame`.
radx::solver::SpringGroup one_spring(const radx::solver::NodeState& ns, const radx::model::SpringProperty& p,
                                     const std::array<double, 9>& frame = {1, 0, 0, 0, 1, 0, 0, 0, 1}) {
  radx::solver::SpringGroup g;
  g.props = p;
  g.allocate(1);
  g.frame = frame;
  g.conn[0] = 0;
  g.conn[G] = 1;
  g.element[0] = 0;
  const double x21[3] = {ns.x0[1] - ns.x0[0], ns.y0[1] - ns.y0[0], ns.z0[1] - ns.z0[0]};
  for (std::size_t d = 0; d < 3; ++d)
    g.x0[d * G] = x21[0] * frame[3 * d] + x21[1] * frame[3 * d + 1] + x21[2] * frame[3 * d + 2];
  return g;
}

radx::model::SpringProperty linear_type8(double mass, double inertia, const std::array<double, 6>& k) {
  radx::model::SpringProperty p;
  p.type = 8;
  p.mass = mass;
  p.inertia = inertia;
  for (int d = 0; d < 6; ++d) p.law(d).stiffness = k[static_cast<std::size_t>(d)];
  return p;
}

// /PROP/SPR_GENE/1 with mass M, inertia I, skew, Ifail and the six stiffnesses; `h` the cards of one degree
// of freedom may be replaced through `dof_card2` (the card with fct_ID1 and H), given per dof ("" keeps it
// 0).
std::string spr_gene(double M, double I, const std::array<double, 6>& k, int skew = 0, int ifail = 0,
                     int iequil = 0, const std::array<std::string, 6>& dof_card2 = {}) {
  std::string s =
      "/PROP/SPR_GENE/1\ngeneral spring\n" +
      Line().put(M, 1, 20).put(I, 21, 40).put(skew, 41, 50).put(ifail, 71, 80).put(iequil, 91, 100).str() +
      "\n";
  for (std::size_t d = 0; d < 6; ++d) {
    s += Line().put(k[d], 1, 20).str() + "\n";
    s += (dof_card2[d].empty() ? Line().put(0, 1, 10).str() : dof_card2[d]) + "\n";
    s += Line().put(0.0, 1, 20).str() + "\n";
  }
  s += Line().put(0, 1, 10).str() + "\n";
  return s;
}

// Node 1 clamped at the origin, node 2 at (100, 0, 0) with the added mass m_add, node 3 at (100, 100, 0),
// spring 1 of part 1 between nodes 1 and 2; `extra` adds cards (initial velocities, more parts). Units Mg mm
// s.
std::string deck_of(const std::string& prop, double m_add, const std::string& extra) {
  std::string s = radx::test::begin_block(2019);
  s += "/NODE\n" + Line().put(1, 1, 10).put(0.0, 11, 30).put(0.0, 31, 50).put(0.0, 51, 70).str() + "\n" +
       Line().put(2, 1, 10).put(100.0, 11, 30).put(0.0, 31, 50).put(0.0, 51, 70).str() + "\n" +
       Line().put(3, 1, 10).put(100.0, 11, 30).put(100.0, 31, 50).put(0.0, 51, 70).str() + "\n";
  s += "/PART/1\nspring\n" + Line().put(1, 1, 10).put(0, 11, 20).str() + "\n";
  s += "/SPRING/1\n" + Line().put(1, 1, 10).put(1, 11, 20).put(2, 21, 30).str() + "\n";
  s += prop;
  s += "/GRNOD/NODE/1\nclamped\n" + Line().put(1, 1, 10).str() + "\n";
  s += "/BCS/1\nclamped\n" + Line().put("111 111", 4, 10).put(0, 11, 20).put(1, 21, 30).str() + "\n";
  s += "/GRNOD/NODE/2\nmass\n" + Line().put(2, 1, 10).str() + "\n";
  s += "/ADMAS/0/1\nmass\n" + Line().put(m_add, 1, 20).put(2, 21, 30).str() + "\n";
  s += extra;
  s += "/END\n";
  return s;
}

// Upward zero crossings of the samples u(t) (linear interpolation between cycles).
std::vector<double> upward_zeros(const std::vector<double>& t, const std::vector<double>& u) {
  std::vector<double> z;
  for (std::size_t k = 1; k < u.size(); ++k)
    if (u[k - 1] < 0 && u[k] >= 0)
      z.push_back(t[k - 1] + (t[k] - t[k - 1]) * (-u[k - 1]) / (u[k] - u[k - 1]));
  return z;
}

// The mean period of the upward zero crossings of `value` (read after every cycle) until t_stop.
template <class Fn>
double measured_period(const radx::model::Model& m, double t_stop, Fn value, double* e_total = nullptr,
                       double* e_init = nullptr) {
  radx::model::RunControls rc;
  rc.t_stop = t_stop;
  radx::solver::ExplicitEngine engine(m, rc, radx::solver::EngineOptions{1, 1});
  std::vector<double> t, u;
  engine.run([&](const radx::solver::CycleReport& r) {
    t.push_back(r.time);
    u.push_back(value(engine));
    if (r.full && e_total) {
      const double e = r.energy.internal + r.energy.kinetic_t + r.energy.kinetic_r;
      if (e_init && *e_init == 0) *e_init = e;
      *e_total = e;
    }
    return true;
  });
  const auto z = upward_zeros(t, u);
  REQUIRE(z.size() >= 3);
  return (z.back() - z.front()) / static_cast<double>(z.size() - 1);
}

}  // namespace

TEST_CASE("TYPE8 kernel: six uncoupled linear springs in a skewed frame, forces, moments, work",
          "[spring8]") {
  auto ns = radx::test::make_nodes({{0, 0, 0}, {100, 0, 0}});
  // Frame: the global axes turned by 30 degrees about Z (rows are the axes).
  const double c = std::cos(std::numbers::pi / 6), s = std::sin(std::numbers::pi / 6);
  const std::array<double, 9> frame = {c, s, 0, -s, c, 0, 0, 0, 1};
  const std::array<double, 6> k = {10, 20, 30, 1, 2, 3};
  auto g = one_spring(ns, linear_type8(1.0, 0.5, k), frame);
  // Move node 2 by d and turn it at w for dt1 = 0.5 (node 1 fixed).
  const double d[3] = {1.0, 2.0, -3.0}, w[3] = {0.2, -0.4, 0.6}, dt1 = 0.5;
  ns.x[1] += d[0];
  ns.y[1] += d[1];
  ns.z[1] += d[2];
  ns.wx[1] = w[0];
  ns.wy[1] = w[1];
  ns.wz[1] = w[2];
  radx::solver::spring_type8_forces(g, ns, radx::solver::CycleInfo{dt1, dt1, dt1});
  double f[3] = {0, 0, 0}, mom[3] = {0, 0, 0}, work = 0;
  for (std::size_t j = 0; j < 3; ++j) {
    const double* e = &frame[3 * j];
    const double u = d[0] * e[0] + d[1] * e[1] + d[2] * e[2];
    const double r = dt1 * (w[0] * e[0] + w[1] * e[1] + w[2] * e[2]);
    CHECK(rel(g.dx[j * G], u) < 1e-12);
    CHECK(rel(g.dx[(3 + j) * G], r) < 1e-12);
    CHECK(rel(g.force[j * G], k[j] * u) < 1e-12);
    CHECK(rel(g.force[(3 + j) * G], k[3 + j] * r) < 1e-12);
    for (std::size_t q = 0; q < 3; ++q) {
      f[q] += k[j] * u * e[q];
      mom[q] += k[3 + j] * r * e[q];
    }
    work += 0.5 * (k[j] * u * u + k[3 + j] * r * r);  // first cycle from rest: the trapezoid is exact
  }
  for (std::size_t q = 0; q < 3; ++q) {
    CHECK(std::abs(g.nodal_force[q * G] - f[q]) < 1e-12 * 100);         // node 1: pulled towards node 2
    CHECK(std::abs(g.nodal_force[(3 + q) * G] - mom[q]) < 1e-12 * 10);  // node 1: the moment
    CHECK(g.nodal_force[(6 + q) * G] == -g.nodal_force[q * G]);         // node 2: equal and opposite
    CHECK(g.nodal_force[(9 + q) * G] == -g.nodal_force[(3 + q) * G]);
  }
  CHECK(rel(g.e_int[0], work) < 1e-12);
  // Step: min(sqrt(M / max K_t), sqrt(I / max K_r)) = min(sqrt(1/30), sqrt(0.5/3)).
  CHECK(rel(g.dt[0], std::min(std::sqrt(1.0 / 30.0), std::sqrt(0.5 / 3.0))) < 1e-12);
}

TEST_CASE("TYPE8 kernel: the nodal stiffness carries the rotational step to the nodal time step",
          "[spring8]") {
  // A stiff rotation only (K_r = 1e4, I = 0.5, M = 1): the step is sqrt(I / K_r), and the nodal stiffness
  // M / dt^2 makes the nodal step sqrt(2 (M/2) / k) of each node equal to it (the /DT/NODA estimate).
  auto ns = radx::test::make_nodes({{0, 0, 0}, {100, 0, 0}});
  auto g = one_spring(ns, linear_type8(1.0, 0.5, {0, 0, 0, 1e4, 0, 0}));
  radx::solver::spring_type8_forces(g, ns, radx::solver::CycleInfo{0.1, 0.1, 0});
  const double dt_r = std::sqrt(0.5 / 1e4);
  CHECK(rel(g.dt[0], dt_r) < 1e-12);
  CHECK(rel(std::sqrt(2.0 * 0.5 / g.k_nodal[0]), dt_r) < 1e-12);
}

TEST_CASE("TYPE8 kernel: the elastic hysteresis (H 7) of a rotation, loop worked by hand", "[spring8]") {
  // Loading curve f1: 100 x up to x = 1, then 100 + 10 (x - 1); unloading curve f3: 20 x up to 1, then
  // 20 + 10 (x - 1) (both odd). K = 100 = A K / A, the elastic slope of the trial force.
  radx::model::Function f1, f3;
  f1.x = f3.x = {-11, -1, 0, 1, 11};
  f1.y = {-200, -100, 0, 100, 200};
  f3.y = {-120, -20, 0, 20, 120};
  auto ns = radx::test::make_nodes({{0, 0, 0}, {1, 0, 0}});
  auto p = linear_type8(1.0, 1.0, {0, 0, 0, 0, 100, 0});
  p.law(4).hardening = 7;
  auto g = one_spring(ns, p);
  g.curves[4].load = &f1;
  g.curves[4].unload = &f3;
  // The rotation about Y goes 0 -> 0.5 -> 2 -> 1.5 -> 0.5 -> 1 (node 2 turned at w for dt1 = 0.1 each).
  // By hand: 0.5: trial 50 <= f1 = 50 -> 50;  2: trial 200 > f1 = 110 -> 110;  1.5 (unloading): trial 60 >=
  // f3 = 25 -> 60;  0.5: trial -40 < f3 = 10 -> 10;  1 (loading again): trial 60 <= f1 = 100 -> 60.
  const double path[5] = {0.5, 2.0, 1.5, 0.5, 1.0}, expect[5] = {50, 110, 60, 10, 60};
  // Work, trapezoids of the same values: 12.5 + 120 - 42.5 - 35 + 17.5 = 72.5.
  double q_old = 0;
  for (int s = 0; s < 5; ++s) {
    ns.wy[1] = (path[s] - q_old) / 0.1;
    q_old = path[s];
    radx::solver::spring_type8_forces(g, ns, radx::solver::CycleInfo{0.1, 0.1, 0});
    INFO("step " << s);
    CHECK(rel(g.force[4 * G], expect[s]) < 1e-12);
    CHECK(rel(g.nodal_force[4 * G], expect[s]) < 1e-12);  // the moment about Y on node 1
  }
  CHECK(rel(g.e_int[0], 72.5) < 1e-12);
}

TEST_CASE("TYPE8 kernel: failure, each direction alone (Ifail 0) or the sum of squares (Ifail 1)",
          "[spring8]") {
  for (int ifail : {0, 1}) {
    auto ns = radx::test::make_nodes({{0, 0, 0}, {10, 0, 0}});
    auto p = linear_type8(1.0, 0.0, {5, 5, 0, 0, 0, 0});
    p.ifail = ifail;
    p.x.delta_max = p.y.delta_max = 1.0;
    auto g = one_spring(ns, p);
    // u = (0.8, 0.8): each ratio 0.8 < 1, their squares sum to 1.28 >= 1.
    ns.x[1] += 0.8;
    ns.y[1] += 0.8;
    radx::solver::spring_type8_forces(g, ns, radx::solver::CycleInfo{0.1, 0.1, 0});
    INFO("Ifail " << ifail);
    CHECK(g.off[0] == (ifail == 0 ? 1.0 : 0.0));
    // K1 u1 = 5 x 0.8: the cycle that breaks the spring still applies its force (as Radioss)...
    CHECK(std::abs(g.nodal_force[0] - 4.0) < 1e-12);
    // ...and the next one applies none once broken.
    radx::solver::spring_type8_forces(g, ns, radx::solver::CycleInfo{0.1, 0.1, 0});
    CHECK(std::abs(g.nodal_force[0] - (ifail == 0 ? 4.0 : 0.0)) < 1e-12);
  }
}

TEST_CASE("TYPE8 in the engine: a translational oscillator at 2 pi sqrt(m / k)", "[spring8][engine]") {
  // The Y law acts on the transverse motion of node 2 (the frame is fixed: no geometric stiffness).
  const double M = 1e-6, K2 = 1000.0, m_add = 1e-3, v0 = 100.0;
  const std::string vel = "/GRNOD/NODE/3\nmoving\n" + Line().put(2, 1, 10).str() +
                          "\n/INIVEL/TRA/1\nstart\n" +
                          Line().put(0.0, 1, 20).put(v0, 21, 40).put(0.0, 41, 60).put(3, 61, 70).str() + "\n";
  const auto m = radx::test::model_of_deck(deck_of(spr_gene(M, 0.0, {0, K2, 0, 0, 0, 0}), m_add, vel));
  const double mass = m_add + 0.5 * M;
  const double period = 2 * std::numbers::pi * std::sqrt(mass / K2);
  double e = 0, e0 = 0;
  const double t = measured_period(
      m, 4.2 * period, [](const radx::solver::ExplicitEngine& en) { return en.nodes().vy[1]; }, &e, &e0);
  // Central differences lengthen the period by (omega dt)^2 / 24 ~ 1e-6 here: 0.5 % is the brief's margin.
  CHECK(rel(t, period) < 0.005);
  CHECK(rel(e, e0) < 1e-3);  // KE + spring energy conserved (no damping)
}

TEST_CASE("TYPE8 in the engine: a torsional oscillator at 2 pi sqrt(I / k_r)", "[spring8][engine]") {
  // Node 2 gets I_a / 2 from spring 1 and I_b / 2 from spring 2 (part 2, to the free node 3, no stiffness):
  // I = (I_a + I_b) / 2, large against I_a so that the step sqrt(I_a / K4) is far below the period.
  const double M = 1e-6, Ia = 2e-4, Ib = 2.0, K4 = 500.0, w0 = 3.0;
  std::string extra = "/PART/2\nfree\n" + Line().put(2, 1, 10).put(0, 11, 20).str() + "\n";
  extra += "/SPRING/2\n" + Line().put(2, 1, 10).put(2, 11, 20).put(3, 21, 30).str() + "\n";
  std::string p2 = spr_gene(M, Ib, {0, 0, 0, 0, 0, 0});
  p2.replace(p2.find("/PROP/SPR_GENE/1"), 16, "/PROP/SPR_GENE/2");
  extra += p2;
  extra += "/GRNOD/NODE/3\nturning\n" + Line().put(2, 1, 10).str() + "\n/INIVEL/ROT/1\nstart\n" +
           Line().put(w0, 1, 20).put(0.0, 21, 40).put(0.0, 41, 60).put(3, 61, 70).str() + "\n";
  const auto m = radx::test::model_of_deck(deck_of(spr_gene(M, Ia, {0, 0, 0, K4, 0, 0}), 0.0, extra));
  const double inertia = 0.5 * (Ia + Ib);
  const double period = 2 * std::numbers::pi * std::sqrt(inertia / K4);
  double e = 0, e0 = 0;
  const double t = measured_period(
      m, 4.2 * period, [](const radx::solver::ExplicitEngine& en) { return en.nodes().wx[1]; }, &e, &e0);
  CHECK(rel(t, period) < 0.005);
  CHECK(rel(e, e0) < 1e-3);  // rotational KE + spring energy conserved
}

TEST_CASE("TYPE8 starter: the six laws, the frame, refusals by name", "[spring8][starter]") {
  const auto m = radx::test::model_of_deck(deck_of(spr_gene(2e-6, 3e-6, {1, 2, 3, 4, 5, 6}), 1e-3, ""));
  const auto& s = m.properties[0].spring;
  CHECK(s.type == 8);
  CHECK(s.inertia == 3e-6);
  for (int d = 0; d < 6; ++d) CHECK(s.law(d).stiffness == d + 1.0);
  CHECK(s.skew == radx::model::kNone);
  CHECK(m.node_mass[0] == 1e-6);  // M / 2

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
  const std::string fun = "/FUNCT/7\nforce\n" + Line().put(0.0, 1, 20).put(0.0, 21, 40).str() + "\n" +
                          Line().put(1.0, 1, 20).put(1000.0, 21, 40).str() + "\n";
  // H 8 on the Y law is refused by name.
  std::array<std::string, 6> cards{};
  cards[1] = Line().put(7, 1, 10).put(8, 11, 20).put(7, 31, 40).str();
  auto e = errors_of(deck_of(spr_gene(1e-6, 0.0, {0, 1000, 0, 0, 0, 0}, 0, 0, 0, cards), 1e-3, fun));
  CHECK(e.find("RX510") != std::string::npos);
  CHECK(e.find("H2 = 8 (elastic, force of the total length)") != std::string::npos);
  // H 7 with both curves runs.
  cards[1] = Line().put(7, 1, 10).put(7, 11, 20).put(7, 31, 40).str();
  CHECK(errors_of(deck_of(spr_gene(1e-6, 0.0, {0, 1000, 0, 0, 0, 0}, 0, 0, 0, cards), 1e-3, fun)) == "");
  // A rotational stiffness without inertia.
  e = errors_of(deck_of(spr_gene(1e-6, 0.0, {0, 0, 0, 10, 0, 0}), 1e-3, ""));
  CHECK(e.find("spring inertia = 0 is not positive") != std::string::npos);
  // Iequil 1 (moment equilibrium) is not implemented.
  e = errors_of(deck_of(spr_gene(1e-6, 0.0, {1, 0, 0, 0, 0, 0}, 0, 0, 1), 1e-3, ""));
  CHECK(e.find("RX510") != std::string::npos);
  CHECK(e.find("Iequil") != std::string::npos);
  // A moving skew is read (its axes follow its nodes: the engine test below).
  const std::string mov =
      "/SKEW/MOV/5\nmoving\n" + Line().put(1, 1, 10).put(2, 11, 20).put(3, 21, 30).str() + "\n";
  CHECK(errors_of(deck_of(spr_gene(1e-6, 0.0, {1, 0, 0, 0, 0, 0}, 5), 1e-3, mov)) == "");
}

TEST_CASE("TYPE8 spring in a /SKEW/MOV: its laws act along the skew's current axes", "[spring][engine]") {
  // Spring 1 from node 1 (origin) to node 2 at (0, 10, 0), both clamped, K = 1 along Y' and Z'. /SKEW/MOV/5:
  // X' from node 1 to node 4 (100, 0, 0), Y' towards node 3, which starts at (0, 100, 0) and flies at
  // (0, -100, 100): the skew turns about X while the spring's nodes stay put, so the spring is stretched in
  // the skew's frame. Units Mg mm s.
  const double K = 1.0;
  std::string d = radx::test::begin_block(2019);
  d += "/NODE\n" + Line().put(1, 1, 10).put(0.0, 11, 30).put(0.0, 31, 50).put(0.0, 51, 70).str() + "\n" +
       Line().put(2, 1, 10).put(0.0, 11, 30).put(10.0, 31, 50).put(0.0, 51, 70).str() + "\n" +
       Line().put(3, 1, 10).put(0.0, 11, 30).put(100.0, 31, 50).put(0.0, 51, 70).str() + "\n" +
       Line().put(4, 1, 10).put(100.0, 11, 30).put(0.0, 31, 50).put(0.0, 51, 70).str() + "\n";
  d += "/PART/1\nspring\n" + Line().put(1, 1, 10).put(0, 11, 20).str() + "\n";
  d += "/SPRING/1\n" + Line().put(1, 1, 10).put(1, 11, 20).put(2, 21, 30).str() + "\n";
  d += spr_gene(1e-6, 0.0, {0, K, K, 0, 0, 0}, 5);
  d += "/SKEW/MOV/5\nmoving\n" + Line().put(1, 1, 10).put(4, 11, 20).put(3, 21, 30).str() + "\n";
  d += "/GRNOD/NODE/1\nclamped\n" + Line().put(1, 1, 10).put(2, 11, 20).put(4, 21, 30).str() + "\n";
  d += "/BCS/1\nclamped\n" + Line().put("111 111", 4, 10).put(0, 11, 20).put(1, 21, 30).str() + "\n";
  d += "/GRNOD/NODE/3\nturning\n" + Line().put(3, 1, 10).str() + "\n";
  d += "/ADMAS/0/1\nmass\n" + Line().put(1e-3, 1, 20).put(3, 21, 30).str() + "\n";
  d += "/INIVEL/TRA/1\nturn\n" +
       Line().put(0.0, 1, 20).put(-100.0, 21, 40).put(100.0, 41, 60).put(3, 61, 70).str() + "\n/END\n";
  const auto m = radx::test::model_of_deck(d);
  radx::model::RunControls rc;
  rc.t_stop = 0.8;
  radx::solver::ExplicitEngine engine(m, rc, radx::solver::EngineOptions{1, 1});
  double worst = 0, last_turn = 0;
  engine.run([&](const radx::solver::CycleReport&) {
    // The skew's axes from node 3's position now (the positions the cycle's forces saw): Y' is node 3's
    // direction from node 1 less its X component, Z' = X' x Y'.
    const auto& s = engine.nodes();
    const double y = s.y[2], z = s.z[2], r = std::hypot(y, z);
    const double ey[3] = {0, y / r, z / r}, ez[3] = {0, -z / r, y / r};
    const double x21[3] = {0, 10, 0};
    const double uy = x21[1] * ey[1] + x21[2] * ey[2] - 10.0, uz = x21[1] * ez[1] + x21[2] * ez[2];
    const auto& g = engine.groups().springs.at(0);
    worst = std::max({worst, std::abs(g.force[1 * G] - K * uy), std::abs(g.force[2 * G] - K * uz)});
    last_turn = std::atan2(z, y);
    return true;
  });
  INFO("turned by " << last_turn << " rad");
  CHECK(last_turn > 1.0);  // the skew has turned by more than 57 degrees
  // The force follows K times the elongation in the current axes to round-off (10 N of elongation force).
  CHECK(worst < 1e-9);
}
