// TYPE13 beam-type springs (/SPRING with /PROP/SPR_BEAM): the kernel against the Euler-Bernoulli beam's end
// forces and moments, objectivity under a rigid rotation of 90 degrees, the initial frame, the engine against
// the closed-form axial and torsional oscillators, the starter's reading and refusals. Expected values come
// from formulas.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "kernel_test_util.hpp"
#include "solver/elements/element_groups.hpp"
#include "solver/engine/explicit_engine.hpp"
#include "test_util.hpp"

namespace {

using radx::test::Line;
using radx::test::rel;

constexpr std::size_t G = radx::solver::kGroupSize;

// A TYPE13 group of one spring between nodes 0 and 1, its initial Y axis from global Y (or X).
radx::solver::SpringGroup one_spring(const radx::solver::NodeState& ns,
                                     const radx::model::SpringProperty& p) {
  radx::solver::SpringGroup g;
  g.props = p;
  g.allocate(1);
  g.conn[0] = 0;
  g.conn[G] = 1;
  g.element[0] = 0;
  const radx::model::Vec3 l{ns.x0[1] - ns.x0[0], ns.y0[1] - ns.y0[0], ns.z0[1] - ns.z0[0]};
  g.l0[0] = radx::model::norm(l);
  const auto y = radx::solver::spring_type13_initial_y(l, {}, {1, 0, 0, 0, 1, 0, 0, 0, 1});
  for (std::size_t d = 0; d < 3; ++d) g.ey[d * G] = y[d];
  return g;
}

radx::model::SpringProperty linear_type13(double mass, double inertia, const std::array<double, 6>& k) {
  radx::model::SpringProperty p;
  p.type = 13;
  p.mass = mass;
  p.inertia = inertia;
  for (int d = 0; d < 6; ++d) p.law(d).stiffness = k[static_cast<std::size_t>(d)];
  return p;
}

// /PROP/SPR_BEAM/<id> (or its alias) with mass M, inertia I, Ileng, Ifail2 and the six stiffnesses.
std::string spr_beam(double M, double I, const std::array<double, 6>& k, int id = 1, int ileng = 0,
                     int ifail2 = 0, const std::string& path = "/PROP/SPR_BEAM") {
  std::string s = path + "/" + std::to_string(id) + "\nbeam spring\n" +
                  Line().put(M, 1, 20).put(I, 21, 40).put(ileng, 81, 90).put(ifail2, 91, 100).str() + "\n";
  for (std::size_t d = 0; d < 6; ++d) {
    s += Line().put(k[d], 1, 20).str() + "\n";
    s += Line().put(0, 1, 10).str() + "\n";
    s += Line().put(0.0, 1, 20).str() + "\n";
  }
  for (int c = 0; c < 7; ++c) s += Line().put(0.0, 1, 20).str() + "\n";
  return s;
}

// Node 1 clamped at the origin, node 2 at (100, 0, 0) with the added mass m_add, node 3 at (100, 100, 0),
// spring 1 of part 1 between nodes 1 and 2; `extra` adds cards. Units Mg mm s.
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

// The mean period of the upward zero crossings of `value` (read after every cycle) until t_stop; e_total
// and e_init the internal plus kinetic energy at the last and first full report.
template <class Fn>
double measured_period(const radx::model::Model& m, double t_stop, Fn value, double& e_total,
                       double& e_init) {
  radx::model::RunControls rc;
  rc.t_stop = t_stop;
  radx::solver::ExplicitEngine engine(m, rc, radx::solver::EngineOptions{1, 1});
  std::vector<double> t, u;
  engine.run([&](const radx::solver::CycleReport& r) {
    t.push_back(r.time);
    u.push_back(value(engine));
    if (r.full) {
      const double e = r.energy.internal + r.energy.kinetic_t + r.energy.kinetic_r;
      if (e_init == 0) e_init = e;
      e_total = e;
    }
    return true;
  });
  std::vector<double> z;
  for (std::size_t k = 1; k < u.size(); ++k)
    if (u[k - 1] < 0 && u[k] >= 0)
      z.push_back(t[k - 1] + (t[k] - t[k - 1]) * (-u[k - 1]) / (u[k] - u[k - 1]));
  REQUIRE(z.size() >= 3);
  return (z.back() - z.front()) / static_cast<double>(z.size() - 1);
}

// Turns the spring (node 1 at the origin, node 2 at (1.5, 0, 0), K as below) rigidly by 90 degrees about the
// axis a through node 1 in `steps` cycles; positions are the exact rotated ones, v^{n-1/2} the chords' rates,
// w the rate on both nodes. Returns the largest nodal force or moment met, and the distance of the frame's
// final Y axis from the initial one (global Y) turned by 90 degrees.
std::pair<double, double> rigid_quarter_turn(const std::array<double, 3>& axis, int steps) {
  const double len = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
  const double a[3] = {axis[0] / len, axis[1] / len, axis[2] / len};
  const double x0[3] = {1.5, 0.0, 0.0};
  auto rotate = [&](const double* x, double ang) {  // Rodrigues: x turned by ang about a
    const double c = std::cos(ang), s = std::sin(ang), ad = a[0] * x[0] + a[1] * x[1] + a[2] * x[2];
    const double cr[3] = {a[1] * x[2] - a[2] * x[1], a[2] * x[0] - a[0] * x[2], a[0] * x[1] - a[1] * x[0]};
    std::array<double, 3> r{};
    for (std::size_t q = 0; q < 3; ++q) r[q] = x[q] * c + cr[q] * s + a[q] * ad * (1 - c);
    return r;
  };
  auto ns = radx::test::make_nodes({{0, 0, 0}, {x0[0], x0[1], x0[2]}});
  auto g = one_spring(ns, linear_type13(1.0, 1.0, {1e3, 2e3, 3e3, 40, 50, 60}));
  const double omega = 1.0, dt1 = (std::numbers::pi / 2) / (omega * steps);
  double n_max = 0;
  for (int s = 1; s <= steps; ++s) {
    const auto x = rotate(x0, omega * dt1 * s), xp = rotate(x0, omega * dt1 * (s - 1));
    ns.x[1] = x[0];
    ns.y[1] = x[1];
    ns.z[1] = x[2];
    ns.vx[1] = (x[0] - xp[0]) / dt1;
    ns.vy[1] = (x[1] - xp[1]) / dt1;
    ns.vz[1] = (x[2] - xp[2]) / dt1;
    ns.wx[0] = ns.wx[1] = omega * a[0];
    ns.wy[0] = ns.wy[1] = omega * a[1];
    ns.wz[0] = ns.wz[1] = omega * a[2];
    radx::solver::spring_type13_forces(g, ns, radx::solver::CycleInfo{dt1, dt1, dt1});
    for (std::size_t d = 0; d < 12; ++d) n_max = std::max(n_max, std::abs(g.nodal_force[d * G]));
  }
  const double y0[3] = {0, 1, 0};
  const auto y = rotate(y0, std::numbers::pi / 2);
  double err = 0;
  for (std::size_t q = 0; q < 3; ++q) err = std::max(err, std::abs(g.ey[q * G] - y[q]));
  return {n_max, err};
}

}  // namespace

TEST_CASE("TYPE13 kernel: the end forces and moments of a bent spring are the Euler-Bernoulli beam's",
          "[spring13]") {
  // A spring of length L along X with K_y = 12 EI / L^3 and K_rz = EI / L. Node 2 moves by v along Y and
  // turns by phi about Z in one cycle of dt1 (node 1 clamped). The beam's end loads (stiffness matrix rows
  // of v2 and theta2), which the spring applies with the opposite sign on its nodes:
  //   node 1: F_y = 12 EI/L^3 v - 6 EI/L^2 phi,   M_z = 6 EI/L^2 v - 2 EI/L phi
  //   node 2: F_y = -(12 EI/L^3 v - 6 EI/L^2 phi), M_z = 6 EI/L^2 v - 4 EI/L phi
  const double L = 2.0, EI = 3.0, v = 1e-3, phi = 2e-3, dt1 = 0.01;
  auto ns = radx::test::make_nodes({{0, 0, 0}, {L, 0, 0}});
  auto g = one_spring(ns, linear_type13(1.0, 1.0, {100, 12 * EI / (L * L * L), 0, 0, 0, EI / L}));
  ns.y[1] += v;
  ns.vy[1] = v / dt1;
  ns.wz[1] = phi / dt1;
  radx::solver::spring_type13_forces(g, ns, radx::solver::CycleInfo{dt1, dt1, dt1});
  // The chord turns by v / L = 5e-4: the incremental measure (atan, mid-step frame) and the turned end frame
  // differ from the linear relation at second order, (v / L)^2 ~ 2.5e-7; 1e-5 is that margin.
  const double f1 = 12 * EI / (L * L * L) * v - 6 * EI / (L * L) * phi;
  const double m1 = 6 * EI / (L * L) * v - 2 * EI / L * phi;
  const double m2 = 6 * EI / (L * L) * v - 4 * EI / L * phi;
  CHECK(rel(g.nodal_force[1 * G], f1) < 1e-5);
  CHECK(rel(g.nodal_force[5 * G], m1) < 1e-5);
  CHECK(rel(g.nodal_force[7 * G], -f1) < 1e-5);
  CHECK(rel(g.nodal_force[11 * G], m2) < 1e-5);
  // The element is in equilibrium: forces sum to 0, and the moments about node 1 too (lever of node 2).
  const double fx2 = g.nodal_force[6 * G], fy2 = g.nodal_force[7 * G];
  CHECK(std::abs(g.nodal_force[0] + fx2) < 1e-12);
  CHECK(std::abs(g.nodal_force[5 * G] + g.nodal_force[11 * G] + (L * fy2 - v * fx2)) < 1e-9 * std::abs(m1));
  // The stored laws: shear u_y = v - L phi / 2 and bending r_z = phi, to the same second-order margin.
  CHECK(rel(g.dx[1 * G], v - L * phi / 2) < 1e-5);
  CHECK(rel(g.dx[5 * G], phi) < 1e-12);
  // Step: translations sqrt(M / K_x) = 0.1; rotations sqrt(I / (K_y L^2 + K_rz)) = sqrt(1 / 19.5).
  CHECK(rel(g.dt[0], std::min(0.1, std::sqrt(1.0 / (12 * EI / L + EI / L)))) < 1e-12);
}

TEST_CASE("TYPE13 kernel: a rigid rotation of 90 degrees gives no force", "[spring13]") {
  // About Z (normal to the spring): the chord's turn 2 atan(h v.Y / L) equals dt w exactly, so the shears
  // stay 0 to round-off: a force of 1e-9 K_z L (K_z = 3e3, L = 1.5) would be a nanometre per metre of shear.
  const auto [f_z, e_z] = rigid_quarter_turn({0, 0, 1}, 500);
  CHECK(f_z < 1e-9 * 3e3 * 1.5);
  CHECK(e_z < 1e-12);
  // About (1 1 1), which also spins the spring about its axis: the frame's spin is integrated by the
  // midpoint rule and the chord's turn about a slanted axis by its increments, both exact to O((w dt)^2) per
  // step. The spurious force stays below 1e-6 K L at 500 steps per quarter turn and falls by at least 3.5
  // (second order: 4) when the step is halved - it is the scheme's truncation, not a frame error.
  const auto [f_500, e_500] = rigid_quarter_turn({1, 1, 1}, 500);
  const auto [f_1000, e_1000] = rigid_quarter_turn({1, 1, 1}, 1000);
  CHECK(f_500 < 1e-6 * 3e3 * 1.5);
  CHECK(f_500 / f_1000 > 3.5);
  CHECK(e_500 < 1e-3);
  CHECK(e_500 / e_1000 > 1.8);
}

TEST_CASE("TYPE13 kernel: the cycle that passes delta_max still pulls, the next books its last work",
          "[spring13]") {
  auto ns = radx::test::make_nodes({{0, 0, 0}, {10, 0, 0}});
  auto p = linear_type13(1.0, 1.0, {200, 0, 0, 0, 0, 0});
  p.x.delta_max = 0.5;
  auto g = one_spring(ns, p);
  const radx::solver::CycleInfo cyc{0.1, 0.1, 0};
  ns.x[1] = 10.4;  // elongation 0.4 < 0.5: intact, N = K u = 80
  radx::solver::spring_type13_forces(g, ns, cyc);
  REQUIRE(g.off[0] == 1.0);
  ns.x[1] = 10.6;  // 0.6 > 0.5: broken this cycle, yet N = 120 acts on both nodes, as Radioss applies it
  radx::solver::spring_type13_forces(g, ns, cyc);
  CHECK(g.off[0] == 0.0);
  CHECK(rel(g.nodal_force[0], 120.0) < 1e-12);
  CHECK(rel(g.nodal_force[6 * G], -120.0) < 1e-12);
  // Trapezoid work 0.4 x 80 / 2 + 0.2 x (80 + 120) / 2: the breaking increment counts.
  CHECK(rel(g.e_int[0], 16.0 + 20.0) < 1e-12);
  CHECK(std::isinf(g.dt[0]));  // a broken spring no longer limits the step, from this cycle on
  // The next cycle (node to 10.7) the force is 0 and the trapezoid books the last force's half increment
  // 0.1 x 120 / 2 = 6: the work the nodes received from it over this step.
  ns.x[1] = 10.7;
  radx::solver::spring_type13_forces(g, ns, cyc);
  CHECK(g.nodal_force[0] == 0.0);
  CHECK(rel(g.e_int[0], 42.0) < 1e-12);
  ns.x[1] = 11.0;  // after that nothing changes: the broken spring keeps the energy it took
  radx::solver::spring_type13_forces(g, ns, cyc);
  CHECK(g.nodal_force[0] == 0.0);
  CHECK(rel(g.e_int[0], 42.0) < 1e-12);
}

TEST_CASE("TYPE13 initial frame: n3, else the skew's Y axis, else its X axis", "[spring13]") {
  const std::array<double, 9> global{1, 0, 0, 0, 1, 0, 0, 0, 1};
  using V = radx::model::Vec3;
  // n3 off the axis: Y is the part of x3 - x1 normal to the spring.
  auto y = radx::solver::spring_type13_initial_y(V{2, 0, 0}, V{1, 0, 3}, global);
  CHECK(std::abs(y[2] - 1) < 1e-15);
  // n3 on the axis: global Y.
  y = radx::solver::spring_type13_initial_y(V{2, 0, 0}, V{4, 0, 0}, global);
  CHECK(std::abs(y[1] - 1) < 1e-15);
  // A spring along Z without n3: global Y first, although global X would do as well.
  y = radx::solver::spring_type13_initial_y(V{0, 0, 2}, {}, global);
  CHECK(std::abs(y[1] - 1) < 1e-15);
  // A spring along Y without n3: global X.
  y = radx::solver::spring_type13_initial_y(V{0, 2, 0}, {}, global);
  CHECK(std::abs(y[0] - 1) < 1e-15);
}

TEST_CASE("TYPE13 in the engine: an axial oscillator at 2 pi sqrt(m / k)", "[spring13][engine]") {
  const double M = 1e-6, K1 = 1000.0, m_add = 1e-3, v0 = 100.0;
  const std::string vel = "/GRNOD/NODE/3\nmoving\n" + Line().put(2, 1, 10).str() +
                          "\n/INIVEL/TRA/1\nstart\n" +
                          Line().put(v0, 1, 20).put(0.0, 21, 40).put(0.0, 41, 60).put(3, 61, 70).str() + "\n";
  const auto m = radx::test::model_of_deck(deck_of(spr_beam(M, 0.0, {K1, 0, 0, 0, 0, 0}), m_add, vel));
  const double mass = m_add + 0.5 * M;
  const double period = 2 * std::numbers::pi * std::sqrt(mass / K1);
  double e = 0, e0 = 0;
  const double t = measured_period(
      m, 4.2 * period, [](const radx::solver::ExplicitEngine& en) { return en.nodes().vx[1]; }, e, e0);
  // Central differences lengthen the period by (omega dt)^2 / 24 ~ 1e-6 here: 0.5 % is the brief's margin.
  CHECK(rel(t, period) < 0.005);
  CHECK(rel(e, e0) < 1e-3);  // KE + spring energy conserved (no damping)
}

TEST_CASE("TYPE13 in the engine: a pretensioned spring that breaks keeps the work done up to its last cycle",
          "[spring13][engine]") {
  // The tension law is the curve f(u) = F0 + K u (a pretension F0 at u = 0), with delta_max = d_max. Node 2
  // (mass m) leaves at v0 along the spring: the spring decelerates it until u passes d_max, then breaks.
  // Energy: the spring's work W(u) = F0 u + K u^2 / 2 up to the elongation of the breaking cycle, which lies
  // between d_max and d_max + v0 dt (one step beyond), is what it keeps; the node keeps KE0 - W.
  const double F0 = 1000.0, K = 1000.0, d_max = 5.0, m_add = 1e-3, v0 = 6000.0, M = 1e-5;
  std::string prop = spr_beam(M, 0.0, {K, 0, 0, 0, 0, 0});
  // The tension law's second card (the first line that is a lone 0): fct_ID11 = 7, H = 0, delta_min -20,
  // delta_max d_max.
  const std::string card2 = "\n" + Line().put(0, 1, 10).str() + "\n";
  prop.replace(prop.find(card2), card2.size(),
               "\n" + Line().put(7, 1, 10).put(-20.0, 61, 80).put(d_max, 81, 100).str() + "\n");
  const std::string extra =
      "/FUNCT/7\npretension\n" + Line().put(-100.0, 1, 20).put(F0 - 100 * K, 21, 40).str() + "\n" +
      Line().put(100.0, 1, 20).put(F0 + 100 * K, 21, 40).str() + "\n" + "/GRNOD/NODE/3\nmoving\n" +
      Line().put(2, 1, 10).str() + "\n/INIVEL/TRA/1\nstart\n" +
      Line().put(v0, 1, 20).put(0.0, 21, 40).put(0.0, 41, 60).put(3, 61, 70).str() + "\n";
  const auto m = radx::test::model_of_deck(deck_of(prop, m_add, extra));
  radx::model::RunControls rc;
  rc.t_stop = 2e-3;
  radx::solver::ExplicitEngine engine(m, rc, radx::solver::EngineOptions{1, 1});
  double dt_max = 0, e0 = 0, ke = 0, ie = 0;
  engine.run([&](const radx::solver::CycleReport& r) {
    dt_max = std::max(dt_max, r.dt);
    if (r.full) {
      if (e0 == 0) e0 = r.energy.kinetic_t;
      ke = r.energy.kinetic_t;
      ie = r.energy.internal;
    }
    return true;
  });
  REQUIRE(engine.groups().springs.at(0).off[0] == 0.0);
  const double mass = m_add + 0.5 * M;
  const auto work = [&](double u) { return F0 * u + 0.5 * K * u * u; };
  CHECK(rel(e0, 0.5 * mass * v0 * v0) < 1e-12);
  // The trapezoid books each step's work to second order: 1e-3 of W is far above that error here.
  CHECK(ie >= work(d_max) * (1 - 1e-3));
  CHECK(ie <= work(d_max + v0 * dt_max) * (1 + 1e-3));
  CHECK(rel(ke + ie, e0) < 1e-3);  // nothing is lost when the spring lets go
}

TEST_CASE("TYPE13 in the engine: a torsional oscillator at 2 pi sqrt(I / k_r)", "[spring13][engine]") {
  // Node 2 gets I_a / 2 from spring 1 and I_b / 2 from spring 2 (part 2, to the free node 3, no stiffness):
  // I = (I_a + I_b) / 2, large against I_a so that the step sqrt(I_a / K4) is far below the period.
  const double M = 1e-6, Ia = 2e-4, Ib = 2.0, K4 = 500.0, w0 = 3.0;
  std::string extra = "/PART/2\nfree\n" + Line().put(2, 1, 10).put(0, 11, 20).str() + "\n";
  extra += "/SPRING/2\n" + Line().put(2, 1, 10).put(2, 11, 20).put(3, 21, 30).str() + "\n";
  extra += spr_beam(M, Ib, {0, 0, 0, 0, 0, 0}, 2);
  extra += "/GRNOD/NODE/3\nturning\n" + Line().put(2, 1, 10).str() + "\n/INIVEL/ROT/1\nstart\n" +
           Line().put(w0, 1, 20).put(0.0, 21, 40).put(0.0, 41, 60).put(3, 61, 70).str() + "\n";
  const auto m = radx::test::model_of_deck(deck_of(spr_beam(M, Ia, {0, 0, 0, K4, 0, 0}), 0.0, extra));
  const double inertia = 0.5 * (Ia + Ib);
  const double period = 2 * std::numbers::pi * std::sqrt(inertia / K4);
  double e = 0, e0 = 0;
  const double t = measured_period(
      m, 4.2 * period, [](const radx::solver::ExplicitEngine& en) { return en.nodes().wx[1]; }, e, e0);
  CHECK(rel(t, period) < 0.005);
  CHECK(rel(e, e0) < 1e-3);  // rotational KE + spring energy conserved
}

TEST_CASE("TYPE13 starter: the keyword and its alias, refusals by name", "[spring13][starter]") {
  for (const std::string path : {"/PROP/SPR_BEAM", "/PROP/TYPE13"}) {
    const auto m =
        radx::test::model_of_deck(deck_of(spr_beam(2e-6, 3e-6, {1, 2, 3, 4, 5, 6}, 1, 0, 0, path), 1e-3, ""));
    const auto& s = m.properties[0].spring;
    CHECK(s.type == 13);
    CHECK(s.inertia == 3e-6);
    for (int d = 0; d < 6; ++d) CHECK(s.law(d).stiffness == d + 1.0);
    CHECK(m.node_mass[0] == 1e-6);  // M / 2
  }
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
  // A shear stiffness turns the nodes (end moments): it needs the inertia.
  auto e = errors_of(deck_of(spr_beam(1e-6, 0.0, {0, 10, 0, 0, 0, 0}), 1e-3, ""));
  CHECK(e.find("spring inertia = 0 is not positive and a shear or rotation") != std::string::npos);
  // Ileng 1 and Ifail2 1 are not implemented.
  e = errors_of(deck_of(spr_beam(1e-6, 1e-6, {1, 0, 0, 0, 0, 0}, 1, 1, 0), 1e-3, ""));
  CHECK(e.find("RX510") != std::string::npos);
  CHECK(e.find("Ileng") != std::string::npos);
  e = errors_of(deck_of(spr_beam(1e-6, 1e-6, {1, 0, 0, 0, 0, 0}, 1, 0, 1), 1e-3, ""));
  CHECK(e.find("RX510") != std::string::npos);
  CHECK(e.find("Ifail2") != std::string::npos);
}
