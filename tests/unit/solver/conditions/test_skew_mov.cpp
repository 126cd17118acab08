// /SKEW/MOV: the frame carried by three nodes (parser/building/build_skews.cpp, model::node_skew_axes,
// solver/conditions/skew_frames.cpp) and every use of a skew reading the frame of the cycle (boundary
// conditions, imposed velocities, initial velocities, loads, accelerometers, the /TH/NODE values). Expected
// values from the frame's definition (Dir axis along N1 -> N2, N3 in the plane of the Dir axis and the next
// one) and from rotating the frame's nodes by a known angle.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "solver/conditions/boundary_conditions.hpp"
#include "solver/conditions/external_loads.hpp"
#include "solver/conditions/skew_frames.hpp"
#include "solver/engine/explicit_engine.hpp"
#include "solver/model/geometry.hpp"
#include "solver/outputs/accelerometer.hpp"
#include "solver/outputs/time_history_values.hpp"
#include "test_util.hpp"

using radx::test::Line;
namespace m = radx::model;
namespace sv = radx::solver;

namespace {

using V3 = m::Vec3;

bool close(double a, double b, double tol) {
  return std::abs(a - b) <= tol;
}

V3 row(const std::array<double, 9>& r, int k) {
  const auto o = 3 * static_cast<std::size_t>(k);
  return {r[o], r[o + 1], r[o + 2]};
}

void check_frame(const std::array<double, 9>& got, const V3& x, const V3& y, const V3& z, double tol) {
  for (std::size_t d = 0; d < 3; ++d) {
    CHECK(close(got[d], x[d], tol));
    CHECK(close(got[3 + d], y[d], tol));
    CHECK(close(got[6 + d], z[d], tol));
  }
}

// Rotation by `angle` about the unit axis u (Rodrigues).
V3 rotate(const V3& p, const V3& u, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  const V3 uxp = m::cross(u, p);
  const double up = m::dot(u, p);
  return {p[0] * c + uxp[0] * s + u[0] * up * (1 - c), p[1] * c + uxp[1] * s + u[1] * up * (1 - c),
          p[2] * c + uxp[2] * s + u[2] * up * (1 - c)};
}

std::string node_line(int id, double x, double y, double z) {
  return Line().put(id, 1, 10).put(x, 11, 30).put(y, 31, 50).put(z, 51, 70).str() + "\n";
}

std::string skew_mov(int id, int n1, int n2, int n3, const char* dir) {
  return "/SKEW/MOV/" + std::to_string(id) + "\nmoving " + std::to_string(id) + "\n" +
         Line().put(n1, 1, 10).put(n2, 11, 20).put(n3, 21, 30).put(dir, 31, 40).str() + "\n";
}

}  // namespace

TEST_CASE(
    "/SKEW/MOV: the Dir axis along N1 -> N2, N3 in its plane with the next axis, ids shared with /SKEW/FIX",
    "[skew]") {
  // N1 (1, 1, 1), N2 = N1 + (2, 0, 0), N3 = N1 + (1, 3, 0): N1N2 along X, N1N3 in the XY plane.
  std::string s = radx::test::begin_block(2026, "Mg mm s") + "/NODE\n" + node_line(1, 1, 1, 1) +
                  node_line(2, 3, 1, 1) + node_line(3, 2, 4, 1);
  s += "/SKEW/FIX/5\nfixed\n" + Line().put(0.0, 1, 20).str() + "\n" + Line().put(1.0, 21, 40).str() + "\n" +
       Line().put(1.0, 41, 60).str() + "\n";
  s += skew_mov(6, 1, 2, 3, "X") + skew_mov(7, 1, 2, 3, "Y") + skew_mov(8, 1, 2, 3, "z") +
       skew_mov(9, 1, 2, 3, "");
  s += "/END\n";
  const auto md = radx::test::model_of_deck(s);
  REQUIRE(md.skews.size() == 5);
  CHECK(!md.skews[0].moving());
  const V3 X{1, 0, 0}, Y{0, 1, 0}, Z{0, 0, 1};
  // Dir X: x' = N1N2, z' = x' x N1N3 = Z, y' = z' x x' = Y.
  check_frame(md.skews[md.skew_index(6)].axes, X, Y, Z, 1e-15);
  // Dir Y: y' = N1N2 = X, x' = y' x N1N3 = Z, z' = x' x y' = Y.
  check_frame(md.skews[md.skew_index(7)].axes, Z, X, Y, 1e-15);
  // Dir Z (lower case accepted): z' = N1N2 = X, y' = z' x N1N3 = Z, x' = y' x z' = Y.
  check_frame(md.skews[md.skew_index(8)].axes, Y, Z, X, 1e-15);
  // Blank Dir: X.
  check_frame(md.skews[md.skew_index(9)].axes, X, Y, Z, 1e-15);
  const auto& k = md.skews[md.skew_index(7)];
  CHECK(k.moving());
  CHECK(k.n1 == 0);
  CHECK(k.n2 == 1);
  CHECK(k.n3 == 2);
  CHECK(k.dir == 1);
  CHECK(k.origin == std::array<double, 3>{1.0, 1.0, 1.0});
  CHECK(md.skews[md.skew_index(8)].dir == 2);
  CHECK(md.skews[md.skew_index(9)].dir == 0);

  // Before the 2019 layout the card has no Dir: the frame is Dir X.
  std::string old = radx::test::begin_block(2018, "Mg mm s") + "/NODE\n" + node_line(1, 1, 1, 1) +
                    node_line(2, 3, 1, 1) + node_line(3, 2, 4, 1) + skew_mov(6, 1, 2, 3, "") + "/END\n";
  const auto mo = radx::test::model_of_deck(old);
  REQUIRE(mo.skews.size() == 1);
  CHECK(mo.skews[0].dir == 0);
  check_frame(mo.skews[0].axes, X, Y, Z, 1e-15);
}

TEST_CASE("node_skew_axes: a right-handed orthonormal frame that turns with its nodes, and the fallbacks",
          "[skew]") {
  const V3 n1{0.3, -1.2, 2.0}, d2{1.5, 0.4, -0.2}, d3{-0.7, 2.0, 0.9};
  const V3 u = [] {
    const V3 a{1.0, 2.0, -0.5};
    return m::scale(a, 1.0 / m::norm(a));
  }();
  for (int dir = 0; dir < 3; ++dir) {
    const auto a = dir, b = (dir + 1) % 3, c = (dir + 2) % 3;
    const auto r0 = m::node_skew_axes(n1, m::add(n1, d2), m::add(n1, d3), dir);
    // Orthonormal and right-handed: x' x y' = z'.
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) CHECK(close(m::dot(row(r0, i), row(r0, j)), i == j ? 1.0 : 0.0, 1e-15));
    const V3 z = m::cross(row(r0, 0), row(r0, 1));
    for (std::size_t d = 0; d < 3; ++d) CHECK(close(z[d], r0[6 + d], 1e-15));
    // The Dir axis along N1N2; N1N3 in the plane of axes a and b, on the positive side of b.
    for (std::size_t d = 0; d < 3; ++d) CHECK(close(r0[3 * a + d], d2[d] / m::norm(d2), 1e-15));
    CHECK(close(m::dot(row(r0, c), d3), 0.0, 1e-14));
    CHECK(m::dot(row(r0, b), d3) > 0);
    // The frame of the nodes turned by 0.7 rad about u (and moved) is the first frame turned the same way.
    const V3 shift{5.0, -3.0, 1.0};
    const auto r1 = m::node_skew_axes(m::add(n1, shift), m::add(m::add(n1, shift), rotate(d2, u, 0.7)),
                                      m::add(m::add(n1, shift), rotate(d3, u, 0.7)), dir);
    for (int k = 0; k < 3; ++k) {
      const V3 want = rotate(row(r0, k), u, 0.7);
      for (std::size_t d = 0; d < 3; ++d)
        CHECK(close(r1[3 * static_cast<std::size_t>(k) + d], want[d], 1e-14));
    }
    // Positions the starter refuses, reached during a run: N2 on N1 (the global axis a), N3 on the line.
    for (const auto& r : {m::node_skew_axes(n1, n1, m::add(n1, d3), dir),
                          m::node_skew_axes(n1, m::add(n1, d2), m::add(n1, m::scale(d2, 2.0)), dir),
                          m::node_skew_axes(n1, m::add(n1, V3{0, 1, 0}), m::add(n1, V3{0, 2, 0}), dir)})
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) CHECK(close(m::dot(row(r, i), row(r, j)), i == j ? 1.0 : 0.0, 1e-15));
    const auto same = m::node_skew_axes(n1, n1, m::add(n1, d3), dir);
    CHECK(same[3 * static_cast<std::size_t>(a) + static_cast<std::size_t>(a)] == 1.0);
  }
}

namespace {

// Frame nodes 0 1 2 at (0,0,0), (1,0,0), (0,1,0): /SKEW/MOV 3 with Dir X starts on the global axes and
// turns about Z with its nodes. Node 3 is a free point of mass 2 at (5, 0, 0); node group 0 = {3}.
m::Model turning_model() {
  m::Model md;
  md.nodes.id = {1, 2, 3, 4};
  md.nodes.x = {0, 1, 0, 5};
  md.nodes.y = {0, 0, 1, 0};
  md.nodes.z = {0, 0, 0, 0};
  m::Skew k;
  k.id = 3;
  k.n1 = 0;
  k.n2 = 1;
  k.n3 = 2;
  md.skews.push_back(k);
  m::NodeGroup g;
  g.id = 1;
  g.nodes = {3};
  md.node_groups.push_back(g);
  m::Function f;
  f.id = 1;
  f.x = {0.0, 1.0};
  f.y = {1.0, 1.0};
  md.functions.push_back(f);
  return md;
}

sv::NodeState turning_state(const m::Model& md) {
  sv::NodeState s;
  s.resize(md.nodes.size());
  for (std::size_t n = 0; n < md.nodes.size(); ++n) {
    s.x[n] = s.x0[n] = md.nodes.x[n];
    s.y[n] = s.y0[n] = md.nodes.y[n];
    s.z[n] = s.z0[n] = md.nodes.z[n];
  }
  s.mass[3] = 2.0;
  return s;
}

// Turns the frame nodes to the angle theta about Z (about node 0).
void turn_frame(sv::NodeState& s, double theta) {
  s.x[1] = std::cos(theta);
  s.y[1] = std::sin(theta);
  s.x[2] = -std::sin(theta);
  s.y[2] = std::cos(theta);
}

void zero_forces(sv::NodeState& s) {
  for (auto* v :
       {&s.fx, &s.fy, &s.fz, &s.fx_ext, &s.fy_ext, &s.fz_ext, &s.mx, &s.my, &s.mz, &s.ax, &s.ay, &s.az})
    std::fill(v->begin(), v->end(), 0.0);
}

}  // namespace

TEST_CASE("SkewFrames: a /SKEW/MOV follows its nodes at each update, a /SKEW/FIX stays", "[skew]") {
  auto md = turning_model();
  m::Skew fixed;
  fixed.id = 9;
  fixed.axes = {0, 1, 0, -1, 0, 0, 0, 0, 1};
  md.skews.push_back(fixed);
  auto s = turning_state(md);
  sv::SkewFrames frames(md);
  REQUIRE(frames.index(3) == 0);
  REQUIRE(frames.index(9) == 1);
  CHECK(frames.index(0) == m::kNone);
  CHECK_THROWS(frames.index(4));
  // Before any update: the starter's axes.
  check_frame(frames.axes(0), {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, 0.0);
  const double theta = 0.4;
  turn_frame(s, theta);
  const double c = std::cos(theta), sn = std::sin(theta);
  CHECK(frames.axis(0, 0)[0] == 1.0);  // nothing moves before update()
  frames.update(s);
  check_frame(frames.axes(0), {c, sn, 0}, {-sn, c, 0}, {0, 0, 1}, 1e-15);
  check_frame(frames.axes(1), {0, 1, 0}, {-1, 0, 0}, {0, 0, 1}, 0.0);
  check_frame(frames.axes(m::kNone), {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, 0.0);
  const auto on = frames.on_axes(0, {1.0, 2.0, 3.0});
  CHECK(close(on[0], c + 2 * sn, 1e-15));
  CHECK(close(on[1], -sn + 2 * c, 1e-15));
  CHECK(on[2] == 3.0);
}

TEST_CASE("conditions and loads in a /SKEW/MOV act along the axes of the cycle", "[skew]") {
  const double theta = 0.6, c = std::cos(theta), sn = std::sin(theta), dt = 1e-3;
  const V3 x1{c, sn, 0}, y1{-sn, c, 0};  // the frame after the turn
  auto md = turning_model();
  auto s = turning_state(md);
  sv::SkewFrames frames(md);
  auto along = [&](const V3& u) { return s.vx[3] * u[0] + s.vy[3] * u[1] + s.vz[3] * u[2]; };

  SECTION("/BCS holding y' and z': after the turn, only the velocity along the new x' is left") {
    m::BoundaryCondition bc;
    bc.id = 1;
    bc.fixed = {0, 1, 1, 0, 0, 0};
    bc.skew = 3;
    bc.group = 0;
    md.bcs.push_back(bc);
    sv::BoundaryConditions bcs(md, frames);
    s.vx[3] = 2.0;  // along x' at t = 0
    s.ax[3] = 1.0;
    s.ay[3] = 1.0;
    bcs.apply(s);
    CHECK(s.vx[3] == 2.0);
    CHECK(s.ay[3] == 0.0);
    turn_frame(s, theta);
    frames.update(s);
    bcs.apply(s);
    // v = (v.x1) x1 = 2 c x1, and a = (a.x1) x1 = c x1 (a was (1, 0, 0) after the first apply).
    CHECK(close(s.vx[3], 2 * c * c, 1e-15));
    CHECK(close(s.vy[3], 2 * c * sn, 1e-15));
    CHECK(close(along(y1), 0.0, 1e-15));
    CHECK(close(s.ax[3] * y1[0] + s.ay[3] * y1[1], 0.0, 1e-15));
    CHECK(close(s.ax[3] * x1[0] + s.ay[3] * x1[1], c, 1e-15));
  }
  SECTION("/IMPVEL along x': v.x' = V on the turned axis, the other components keep their free motion") {
    m::ImposedVelocity iv;
    iv.id = 1;
    iv.function = 0;
    iv.dir = 0;
    iv.skew = 3;
    iv.group = 0;
    iv.fscale_y = 3.0;
    md.imposed_velocities.push_back(iv);
    sv::ImposedVelocities impvel(md, frames);
    turn_frame(s, theta);
    frames.update(s);
    s.vz[3] = 0.25;
    (void)impvel.apply(s, 0.0, dt, dt);  // a constant step: dt12 = dt as the update below
    s.vx[3] += dt * s.ax[3];
    s.vy[3] += dt * s.ay[3];
    s.vz[3] += dt * s.az[3];
    CHECK(close(along(x1), 3.0, 1e-13));
    CHECK(close(along(y1), 0.0, 1e-13));
    CHECK(s.vz[3] == 0.25);
  }
  SECTION("/IMPDISP along x': the displacement measured on the turned axis reaches u(t + dt)") {
    m::ImposedVelocity iv;
    iv.id = 1;
    iv.function = 0;
    iv.dir = 0;
    iv.skew = 3;
    iv.group = 0;
    iv.fscale_y = 0.5;
    iv.displacement = true;
    md.imposed_velocities.push_back(iv);
    sv::ImposedVelocities impvel(md, frames);
    turn_frame(s, theta);
    frames.update(s);
    (void)impvel.apply(s, 0.0, dt, dt);
    s.vx[3] += dt * s.ax[3];
    s.vy[3] += dt * s.ay[3];
    s.x[3] += dt * s.vx[3];
    s.y[3] += dt * s.vy[3];
    CHECK(close((s.x[3] - s.x0[3]) * x1[0] + (s.y[3] - s.y0[3]) * x1[1], 0.5, 1e-12));
  }
  SECTION("/CLOAD along x' and /GRAV along y': F x' and m g y' of the turned frame") {
    m::ConcentratedLoad cl;
    cl.id = 1;
    cl.function = 0;
    cl.dir = 0;
    cl.skew = 3;
    cl.group = 0;
    cl.fscale_y = 4.0;
    md.concentrated_loads.push_back(cl);
    m::Gravity g;
    g.id = 1;
    g.dir = 1;
    g.skew = 3;
    g.group = 0;
    g.fscale_y = -9.0;
    md.gravities.push_back(g);
    sv::ExternalLoads loads(md, frames);
    turn_frame(s, theta);
    frames.update(s);
    zero_forces(s);
    (void)loads.apply(s, 0.0, dt);
    const double m2 = 2.0;
    CHECK(close(s.fx[3], 4.0 * c - 9.0 * m2 * -sn, 1e-13));
    CHECK(close(s.fy[3], 4.0 * sn - 9.0 * m2 * c, 1e-13));
    CHECK(s.fz[3] == 0.0);
    CHECK(close(s.fx_ext[3], s.fx[3], 0.0));
  }
  SECTION("/INIVEL in the skew takes the axes of the time it applies (Tstart after the turn)") {
    m::InitialVelocity iv;
    iv.id = 1;
    iv.v = {1.0, 2.0, 0.0};
    iv.skew = 3;
    iv.group = 0;
    iv.t_start = 0.5;
    md.initial_velocities.push_back(iv);
    sv::InitialVelocities inivel(md, frames);
    (void)inivel.apply(s, 0.0);
    CHECK(s.vx[3] == 0.0);
    turn_frame(s, theta);
    frames.update(s);
    (void)inivel.apply(s, 0.5);
    CHECK(close(s.vx[3], c - 2 * sn, 1e-15));
    CHECK(close(s.vy[3], sn + 2 * c, 1e-15));
  }
  SECTION("/ACCEL in the skew reads the acceleration on the turned axes") {
    m::Accelerometer a;
    a.id = 1;
    a.node = 3;
    a.skew = 3;
    md.accelerometers.push_back(a);
    sv::Accelerometers acc(md, frames);
    turn_frame(s, theta);
    frames.update(s);
    s.ax[3] = 1.0;
    acc.update(s, dt, dt);
    const auto& r = acc.readings()[0].acceleration;
    CHECK(close(r[0], c, 1e-15));
    CHECK(close(r[1], -sn, 1e-15));
    CHECK(r[2] == 0.0);
  }
}

TEST_CASE("a rigid body spinning at omega carries a /SKEW/MOV: /TH/NODE in the skew sees its axes at omega t",
          "[skew][engine]") {
  // Eight point masses at the corners of a 2 mm cube (nodes 1..8, no element, /DTIX sets the step) form
  // /RBODY 1 about main node 9 at the centre, spinning about Z at omega = 10 rad/s. /SKEW/MOV 1 rides on the
  // corners 1 (origin), 2 (X') and 4 (Y'). Node 20 is a point mass at rest at (5, 0, 0): in the skew its
  // position reads (5 cos wt, -5 sin wt, 0). Corner 2 reads a velocity (w h/2, w h/2, 0) in the skew at every
  // row (the body's rotation seen from the body), and (in the global axes) turns with the body.
  const double h = 2.0, w = 10.0, dt = 1e-4;
  std::string s = radx::test::begin_block(2026, "Mg mm s") + "/NODE\n";
  for (int k = 0; k < 8; ++k) {
    const double x = (k == 1 || k == 2 || k == 5 || k == 6) ? h : 0.0;
    const double y = (k == 2 || k == 3 || k == 6 || k == 7) ? h : 0.0;
    s += node_line(k + 1, x - h / 2, y - h / 2, k >= 4 ? h / 2 : -h / 2);
  }
  s += node_line(9, 0, 0, 0) + node_line(20, 5, 0, 0);
  s += "/GRNOD/NODE/1\ncorners\n" + Line().put(1, 1, 10).put(2, 11, 20).put(3, 21, 30).put(4, 31, 40).str() +
       "\n" + Line().put(5, 1, 10).put(6, 11, 20).put(7, 21, 30).put(8, 31, 40).str() + "\n";
  s += "/GRNOD/NODE/2\nmain\n" + Line().put(9, 1, 10).str() + "\n";
  s += "/GRNOD/NODE/3\nfree\n" + Line().put(20, 1, 10).str() + "\n";
  s += "/ADMAS/0/1\ncorner masses\n" + Line().put(1e-3, 1, 20).put(1, 21, 30).str() + "\n";
  s += "/ADMAS/0/2\nfree mass\n" + Line().put(1e-3, 1, 20).put(3, 21, 30).str() + "\n";
  s += "/RBODY/1\ncube\n" + Line().put(9, 1, 10).put(1, 61, 70).str() + "\n\n\n\n";
  s += "/INIVEL/ROT/1\nspin\n" + Line().put(0.0, 1, 20).put(0.0, 21, 40).put(w, 41, 60).put(2, 61, 70).str() +
       "\n";
  s += skew_mov(1, 1, 2, 4, "");
  s += "/TH/NODE/1\nin the skew\n" + Line().put("XYZ", 1, 10).put("V", 11, 20).str() + "\n" +
       Line().put(20, 1, 10).put(1, 11, 20).str() + "\n" + Line().put(2, 1, 10).put(1, 11, 20).str() + "\n" +
       Line().put(2, 1, 10).str() + "\n/END\n";
  const auto md = radx::test::model_of_deck(s);
  REQUIRE(md.time_histories.size() == 1);
  const auto& th = md.time_histories[0];
  REQUIRE(th.skews == std::vector<std::int64_t>{1, 1, 0});
  m::RunControls rc;
  rc.t_stop = 0.1;  // one rad
  rc.dt_initial = rc.dt_max = dt;
  sv::ExplicitEngine engine(md, rc, sv::EngineOptions{1, 1});
  sv::ThGroupSampler sampler(engine, th);
  std::vector<double> v(sampler.size());
  REQUIRE(v.size() == 3u * 6u);
  double worst_p = 0, worst_v = 0, worst_g = 0;
  int rows = 0;
  engine.run([&](const sv::CycleReport& r) {
    sampler.sample(engine, r, v);
    const double wt = w * r.time, cw = std::cos(wt), sw = std::sin(wt);
    worst_p = std::max({worst_p, std::abs(v[0] - 5 * cw), std::abs(v[1] + 5 * sw), std::abs(v[2])});
    // Corner 2 is at (h/2, -h/2, -h/2) from the centre in the body: v = w Z x r = w (h/2, h/2, 0) there.
    worst_v = std::max(
        {worst_v, std::abs(v[6 + 3] - w * h / 2), std::abs(v[6 + 4] - w * h / 2), std::abs(v[6 + 5])});
    // The same node on the global axes: that velocity turned by wt.
    worst_g = std::max(
        {worst_g, std::abs(v[12 + 3] - w * h / 2 * (cw - sw)), std::abs(v[12 + 4] - w * h / 2 * (sw + cw))});
    ++rows;
    return true;
  });
  CHECK(rows > 900);
  // The rigid body turns its corners by the exact rotation R(w dt) each cycle and the frame is rebuilt from
  // them: the angle is w t to round-off over 1000 cycles (1e-12 of the lengths).
  CHECK(worst_p <= 1e-11 * 5);
  // The full-step velocity v^{n-1/2} + dt/2 a of a point on a circle is the mean of two chord velocities:
  // |w x r| (1 - (w dt)^2 / 6) (1.7e-7 relative), along the tangent of t_n.
  CHECK(worst_v <= 2e-7 * w * h);
  CHECK(worst_g <= 2e-7 * w * h);
}
