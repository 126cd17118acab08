// Loads and kinematic conditions (solver/conditions/kinematics.hpp) on hand-built models and node states,
// driven by a minimal central-difference loop written here: forces -> a = f/m -> conditions -> v += dt12 a,
// x += dt2 v, with dt1 = 0 at cycle 0 (docs/theory/elements.md section 0). Each check states what its
// tolerance means; "round-off" tolerances are 1e-12 relative unless a scale is given.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "solver/conditions/kinematics.hpp"

namespace m = radx::model;
namespace sv = radx::solver;

namespace {

using V3 = std::array<double, 3>;

m::Model nodes_model(const std::vector<V3>& pts) {
  m::Model md;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    md.nodes.id.push_back(static_cast<std::int64_t>(i + 1));
    md.nodes.x.push_back(pts[i][0]);
    md.nodes.y.push_back(pts[i][1]);
    md.nodes.z.push_back(pts[i][2]);
  }
  return md;
}

std::int32_t add_group(m::Model& md, std::vector<std::int32_t> nodes) {
  m::NodeGroup g;
  g.id = static_cast<std::int64_t>(md.node_groups.size() + 1);
  g.nodes = std::move(nodes);
  md.node_groups.push_back(g);
  return static_cast<std::int32_t>(md.node_groups.size() - 1);
}

std::int32_t add_function(m::Model& md, std::vector<double> x, std::vector<double> y) {
  m::Function f;
  f.id = static_cast<std::int64_t>(md.functions.size() + 1);
  f.x = std::move(x);
  f.y = std::move(y);
  md.functions.push_back(f);
  return static_cast<std::int32_t>(md.functions.size() - 1);
}

sv::NodeState state_of(const m::Model& md, const std::vector<double>& mass) {
  sv::NodeState s;
  s.resize(md.nodes.size());
  for (std::size_t i = 0; i < s.n; ++i) {
    s.x[i] = s.x0[i] = md.nodes.x[i];
    s.y[i] = s.y0[i] = md.nodes.y[i];
    s.z[i] = s.z0[i] = md.nodes.z[i];
    s.mass[i] = mass[i];
  }
  return s;
}

void zero_forces(sv::NodeState& s) {
  for (auto* v : {&s.fx, &s.fy, &s.fz, &s.mx, &s.my, &s.mz, &s.fx_ext, &s.fy_ext, &s.fz_ext})
    std::fill(v->begin(), v->end(), 0.0);
}

void accelerations(sv::NodeState& s) {
  for (std::size_t n = 0; n < s.n; ++n) {
    const double im = s.mass[n] > 0 ? 1.0 / s.mass[n] : 0.0;
    const double ii = s.inertia[n] > 0 ? 1.0 / s.inertia[n] : 0.0;
    s.ax[n] = s.fx[n] * im;
    s.ay[n] = s.fy[n] * im;
    s.az[n] = s.fz[n] * im;
    s.awx[n] = s.mx[n] * ii;
    s.awy[n] = s.my[n] * ii;
    s.awz[n] = s.mz[n] * ii;
  }
}

void update(sv::NodeState& s, double dt1, double dt2) {
  const double dt12 = 0.5 * (dt1 + dt2);
  for (std::size_t n = 0; n < s.n; ++n) {
    s.vx[n] += dt12 * s.ax[n];
    s.vy[n] += dt12 * s.ay[n];
    s.vz[n] += dt12 * s.az[n];
    s.wx[n] += dt12 * s.awx[n];
    s.wy[n] += dt12 * s.awy[n];
    s.wz[n] += dt12 * s.awz[n];
    s.x[n] += dt2 * s.vx[n];
    s.y[n] += dt2 * s.vy[n];
    s.z[n] += dt2 * s.vz[n];
  }
}

// Kinetic energy at print time (docs/theory/elements.md 8): v^{n-1/2} + dt1/2 a^n.
double kinetic_energy(const sv::NodeState& s, double dt1) {
  double e = 0;
  const double h = 0.5 * dt1;
  for (std::size_t n = 0; n < s.n; ++n) {
    const double vx = s.vx[n] + h * s.ax[n], vy = s.vy[n] + h * s.ay[n], vz = s.vz[n] + h * s.az[n];
    const double wx = s.wx[n] + h * s.awx[n], wy = s.wy[n] + h * s.awy[n], wz = s.wz[n] + h * s.awz[n];
    e += 0.5 * s.mass[n] * (vx * vx + vy * vy + vz * vz) + 0.5 * s.inertia[n] * (wx * wx + wy * wy + wz * wz);
  }
  return e;
}

// A varying step (+-30 %), to show that the exact results do not rely on a constant dt.
double step(int k) {
  return 1e-3 * (1.0 + 0.3 * std::sin(0.7 * k));
}

bool close(double a, double b, double tol_rel, double scale = 0) {
  return std::abs(a - b) <= tol_rel * std::max({std::abs(a), std::abs(b), scale});
}

}  // namespace

// (a) ------------------------------------------------------------------------------------------------------
TEST_CASE("function evaluation: interpolation, linear extrapolation, single point, scales", "[loads]") {
  m::Function f;
  f.x = {0.0, 1.0, 3.0};
  f.y = {0.0, 2.0, 3.0};
  // Exact in binary floating point for these values: compared with ==.
  CHECK(sv::function_value(f, 0.5) == 1.0);
  CHECK(sv::function_value(f, 2.0) == 2.5);
  CHECK(sv::function_value(f, 1.0) == 2.0);
  CHECK(sv::function_value(f, 3.0) == 3.0);
  CHECK(sv::function_value(f, -1.0) == -2.0);  // first segment, slope 2
  CHECK(sv::function_value(f, 5.0) == 4.0);    // last segment, slope 1/2
  m::Function one;
  one.x = {2.0};
  one.y = {7.0};
  CHECK(sv::function_value(one, -10.0) == 7.0);
  CHECK(sv::function_value(one, 10.0) == 7.0);
  CHECK(sv::function_value(m::Function{}, 1.0) == 0.0);
  // Fscale_y f(t / Ascale_x): t = 4, Ascale 2 -> f(2) = 2.5, times 3.
  CHECK(sv::scaled_function_value(f, 4.0, 2.0, 3.0) == 7.5);
  CHECK(sv::scaled_function_value(f, -0.5, 0.5, -1.0) == 2.0);  // f(-1) = -2, times -1
}

// (b) ------------------------------------------------------------------------------------------------------
TEST_CASE("gravity on a free node: exact parabola and work equal to the kinetic energy gained", "[loads]") {
  auto md = nodes_model({{0.1, -0.2, 0.3}});
  m::Gravity g;
  g.id = 1;
  g.dir = 2;
  g.fscale_y = -9.81;  // constant: no function
  md.gravities.push_back(g);
  const double mass = 2.0;
  auto s = state_of(md, {mass});
  const V3 v0 = {1.0, 2.0, 3.0};
  s.vx[0] = v0[0];
  s.vy[0] = v0[1];
  s.vz[0] = v0[2];
  const sv::SkewFrames frames(md);
  sv::ExternalLoads loads(md, frames);
  const double ke0 = kinetic_energy(s, 0.0);

  double t = 0, dt1 = 0, work = 0;
  const int n_steps = 200;
  for (int k = 0;; ++k) {
    zero_forces(s);
    work += loads.apply(s, t, dt1);
    CHECK(s.fz_ext[0] == mass * -9.81);
    accelerations(s);
    if (k == n_steps) break;
    const double dt2 = step(k);
    update(s, dt1, dt2);
    t += dt2;
    dt1 = dt2;
  }
  // Central differences integrate a constant acceleration exactly (v^{n+1/2} is the exact mid-step
  // velocity for any steps): the only error is round-off, 1e-12 of the displacement scale.
  const double scale = std::abs(v0[2]) * t + 9.81 * t * t;
  CHECK(close(s.x[0], 0.1 + v0[0] * t, 1e-12, scale));
  CHECK(close(s.y[0], -0.2 + v0[1] * t, 1e-12, scale));
  CHECK(close(s.z[0], 0.3 + v0[2] * t - 0.5 * 9.81 * t * t, 1e-12, scale));
  // The gravity work sum 1/2 (g_old + g_new) m v^{n-1/2} dt1 = m g (z_N - z_0) equals the change of the
  // print-time kinetic energy exactly (constant g): round-off relative to the KE scale.
  const double ke = kinetic_energy(s, dt1);
  CHECK(close(work, ke - ke0, 1e-12, ke0));
  CHECK(work < 0);  // the node rises: gravity takes energy out
}

TEST_CASE("gravity skips rigid-body secondary nodes and scales with a function", "[loads]") {
  auto md = nodes_model({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}});
  m::Gravity g;
  g.id = 1;
  g.dir = 0;
  g.function = add_function(md, {0.0, 1.0}, {0.0, 1.0});  // ramp f(x) = x
  g.ascale_x = 2.0;
  g.fscale_y = 4.0;
  g.group = add_group(md, {0, 1});
  md.gravities.push_back(g);
  auto s = state_of(md, {1.0, 3.0, 5.0});
  s.vx = {2.0, 7.0, 7.0};
  const std::vector<std::uint8_t> rigid_secondary = {0, 1, 0};
  const sv::SkewFrames frames(md);
  sv::ExternalLoads loads(md, frames, rigid_secondary);
  zero_forces(s);
  const double w = loads.apply(s, 1.0, 0.5);  // g(1) = 4 f(1/2) = 2, g(1 - 0.5) = 4 f(1/4) = 1
  CHECK(s.fx[0] == 2.0);
  CHECK(s.fx[1] == 0.0);  // rigid-body secondary: carried by its main node
  CHECK(s.fx[2] == 0.0);  // not in the group
  // 1/2 (g_old + g_new) m v dt1 on node 0 only: exact binary fractions.
  CHECK(w == 0.5 * (1.0 + 2.0) * 1.0 * 2.0 * 0.5);
}

TEST_CASE("concentrated load: full value on each node, moments, work with dt2", "[loads]") {
  auto md = nodes_model({{0, 0, 0}, {1, 0, 0}});
  const auto fn = add_function(md, {0.0, 1.0}, {0.0, 1.0});
  m::ConcentratedLoad c;
  c.id = 1;
  c.function = fn;
  c.dir = 1;
  c.fscale_y = 10.0;
  c.group = add_group(md, {0, 1});
  md.concentrated_loads.push_back(c);
  c.id = 2;
  c.dir = 5;  // ZZ moment
  md.concentrated_loads.push_back(c);
  auto s = state_of(md, {1.0, 1.0});
  s.vy = {2.0, 3.0};
  s.wz = {0.5, 0.0};
  const sv::SkewFrames frames(md);
  sv::ExternalLoads loads(md, frames);
  zero_forces(s);
  const double w = loads.apply(s, 0.5, 0.1);  // F(0.5) = 5, F(0.4) = 4
  CHECK(w == 0.0);                            // no gravity or pressure
  CHECK(s.fy[0] == 5.0);
  CHECK(s.fy[1] == 5.0);
  CHECK(s.fy_ext[1] == 5.0);
  CHECK(s.mz[0] == 5.0);
  CHECK(s.mz[1] == 5.0);
  CHECK(s.fx[0] == 0.0);
  // 1/2 (4 + 5) (2 + 3) dt2 for the force, 1/2 (4 + 5) (0.5 + 0) dt2 for the moment.
  CHECK(close(loads.concentrated_load_work(0.2), 0.5 * 9.0 * 5.0 * 0.2 + 0.5 * 9.0 * 0.5 * 0.2, 1e-14));
}

TEST_CASE("pressure load: p A n split over the segment's nodes, right-hand normal, Idel", "[loads]") {
  // Quad 1-2-3-4 counter-clockwise seen from +z (normal +z), area 2 x 1; triangle 2-5-3 (area 1/2).
  auto md = nodes_model({{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}, {3, 0, 0}});
  m::Surface surf;
  surf.id = 1;
  surf.segments = {{0, 1, 2, 3}, {1, 4, 2, 2}};
  surf.owner_type = {m::SegmentOwner::Shell4, m::SegmentOwner::Shell3};
  surf.owner = {0, 0};
  md.surfaces.push_back(surf);
  m::PressureLoad p;
  p.id = 1;
  p.surface = 0;
  p.function = add_function(md, {0.0}, {3.0});  // constant 3
  md.pressure_loads.push_back(p);
  auto s = state_of(md, {1, 1, 1, 1, 1});
  s.vz = {1, 1, 1, 1, 1};
  const sv::SkewFrames frames(md);
  sv::ExternalLoads loads(md, frames);
  zero_forces(s);
  const double w = loads.apply(s, 0.0, 0.5);
  // Quad: p A / 4 = 3 * 2 / 4 = 1.5 per node; triangle: p A / 3 = 3 * 0.5 / 3 = 0.5 per node.
  CHECK(s.fz[0] == 1.5);
  CHECK(s.fz[3] == 1.5);
  CHECK(s.fz[1] == 2.0);
  CHECK(s.fz[2] == 2.0);
  CHECK(s.fz[4] == 0.5);
  CHECK(s.fx[1] == 0.0);
  CHECK(close(w, 0.5 * (4 * 1.5 + 3 * 0.5), 1e-14));  // dt1 sum F.v
  // Deleting the quad's shell removes its load (Idel = 1), the triangle's stays.
  loads.remove_element(m::SegmentOwner::Shell4, 0);
  zero_forces(s);
  (void)loads.apply(s, 0.0, 0.5);
  CHECK(s.fz[0] == 0.0);
  CHECK(s.fz[1] == 0.5);
  CHECK(s.fz[4] == 0.5);
}

// (c) ------------------------------------------------------------------------------------------------------
TEST_CASE("BCS keeps the fixed translations and rotations at zero velocity", "[loads]") {
  auto md = nodes_model({{0, 0, 0}});
  m::BoundaryCondition b;
  b.id = 1;
  b.fixed = {1, 0, 0, 0, 1, 0};  // Tx and Ry
  b.group = add_group(md, {0});
  md.bcs.push_back(b);
  m::Gravity g;
  g.id = 1;
  g.dir = 0;  // pushes along the fixed X
  g.fscale_y = 5.0;
  md.gravities.push_back(g);
  g.dir = 1;  // and along the free Y
  md.gravities.push_back(g);
  auto s = state_of(md, {2.0});
  s.inertia[0] = 1.0;
  s.vx[0] = 3.0;
  s.vz[0] = 1.0;
  s.wy[0] = 4.0;
  s.wz[0] = 2.0;
  const sv::SkewFrames frames(md);
  sv::BoundaryConditions bcs(md, frames);
  sv::ExternalLoads loads(md, frames);
  bcs.set_fixed_bits(s);
  CHECK(s.fixed[0] == (1u | 16u));
  bcs.apply(s);
  double t = 0, dt1 = 0;
  for (int k = 0; k < 50; ++k) {
    zero_forces(s);
    (void)loads.apply(s, t, dt1);
    s.my[0] = 7.0;  // a moment on the fixed rotation
    accelerations(s);
    bcs.apply(s);
    const double dt2 = step(k);
    update(s, dt1, dt2);
    t += dt2;
    dt1 = dt2;
  }
  // Fixed dofs: exactly zero velocity, no displacement.
  CHECK(s.vx[0] == 0.0);
  CHECK(s.x[0] == 0.0);
  CHECK(s.wy[0] == 0.0);
  // Free dofs move: v_y^{N-1/2} = g (t_N - dt/2) (exact for a constant acceleration: round-off), v_z and
  // w_z unchanged.
  CHECK(close(s.vy[0], 5.0 * (t - 0.5 * dt1), 1e-12));
  CHECK(s.vz[0] == 1.0);
  CHECK(s.wz[0] == 2.0);
}

// (d) ------------------------------------------------------------------------------------------------------
TEST_CASE("IMPVEL ramp: velocity follows the function at the half steps, work = kinetic energy change",
          "[loads]") {
  auto md = nodes_model({{0, 0, 0}});
  m::ImposedVelocity iv;
  iv.id = 1;
  iv.function = add_function(md, {0.0, 1.0}, {0.0, 1.0});  // f(x) = x, extrapolated beyond 1
  iv.dir = 1;
  iv.ascale_x = 0.01;
  iv.fscale_y = 2.0;  // v_imp(t) = 2 t / 0.01 = 200 t
  iv.group = add_group(md, {0});
  md.imposed_velocities.push_back(iv);
  const double mass = 3.0;

  for (const bool with_gravity : {false, true}) {
    DYNAMIC_SECTION("gravity along the imposed direction: " << with_gravity) {
      auto mdl = md;
      const double g = with_gravity ? -9.81 : 0.0;
      if (with_gravity) {
        m::Gravity gr;
        gr.id = 1;
        gr.dir = 1;
        gr.fscale_y = g;
        mdl.gravities.push_back(gr);
      }
      auto s = state_of(mdl, {mass});
      s.vx[0] = 0.7;  // free direction
      s.vy[0] = 0.3;  // not the imposed value: the first cycle corrects it
      const double vy0 = s.vy[0];
      const sv::SkewFrames frames(mdl);
      sv::ImposedVelocities impvel(mdl, frames);
      sv::ExternalLoads loads(mdl, frames);
      double t = 0, dt1 = 0, w_imp = 0, reaction_term = 0;
      const int n_steps = 150;
      for (int k = 0; k < n_steps; ++k) {
        zero_forces(s);
        (void)loads.apply(s, t, dt1);
        accelerations(s);
        const double dt2 = step(k);
        const double dt12 = 0.5 * (dt1 + dt2);
        const double v_before = s.vy[0];
        w_imp += impvel.apply(s, t, dt1, dt2);
        update(s, dt1, dt2);
        // v^{n+1/2} = v_imp(t_n + dt2/2): exact up to round-off of the velocity scale.
        CHECK(close(s.vy[0], 200.0 * (t + 0.5 * dt2), 1e-12, 1.0));
        // Work of the free acceleration (here gravity) part of the reaction: m g dt12 vbar.
        reaction_term += mass * g * dt12 * 0.5 * (v_before + s.vy[0]);
        t += dt2;
        dt1 = dt2;
      }
      CHECK(s.vx[0] == 0.7);
      // Booked work + the pending half of the last cycle = sum dt12 m (a_imp - a_free) vbar
      //   = 1/2 m (v_N^2 - v_0^2) - sum m a_free dt12 vbar: exact up to round-off.
      const double dke = 0.5 * mass * (s.vy[0] * s.vy[0] - vy0 * vy0);
      CHECK(close(w_imp + impvel.pending_work(), dke - reaction_term, 1e-12, dke));
    }
  }
}

TEST_CASE("IMPDISP: the node is at X0 + u(t) at every step end, under a force and with a varying step",
          "[loads]") {
  // u(t) = 0.5 sin(t / 0.02) (a function sampled finely, linear between samples) along Y on a node pulled by
  // gravity along Y; the node starts 0.01 off (initial position X0 is the deck's, the offset is not).
  auto md = nodes_model({{1.0, 2.0, 3.0}});
  std::vector<double> xs, ys;
  for (int k = 0; k <= 400; ++k) {
    xs.push_back(k * 0.0025);
    ys.push_back(std::sin(xs.back()));
  }
  m::ImposedVelocity iv;
  iv.id = 1;
  iv.displacement = true;
  iv.function = add_function(md, xs, ys);
  iv.dir = 1;
  iv.ascale_x = 0.02;
  iv.fscale_y = 0.5;
  iv.group = add_group(md, {0});
  md.imposed_velocities.push_back(iv);
  m::Gravity gr;
  gr.id = 1;
  gr.dir = 1;
  gr.fscale_y = -9.81;
  md.gravities.push_back(gr);
  const auto& f = md.functions[0];
  auto u = [&](double t) {  // the function as the engine interpolates it, scaled
    const double x = t / 0.02;
    std::size_t k = 0;
    while (k + 2 < f.x.size() && f.x[k + 1] < x) ++k;
    return 0.5 * (f.y[k] + (f.y[k + 1] - f.y[k]) * (x - f.x[k]) / (f.x[k + 1] - f.x[k]));
  };
  auto s = state_of(md, {2.0});
  s.y[0] += 0.01;
  const sv::SkewFrames frames(md);
  sv::ImposedVelocities impvel(md, frames);
  sv::ExternalLoads loads(md, frames);
  double t = 0, dt1 = 0;
  for (int k = 0; k < 150; ++k) {
    zero_forces(s);
    (void)loads.apply(s, t, dt1);
    accelerations(s);
    const double dt2 = step(k);
    (void)impvel.apply(s, t, dt1, dt2);
    update(s, dt1, dt2);
    t += dt2;
    dt1 = dt2;
    // Exact up to round-off of the coordinate (3 m): the force and the initial offset do not show.
    CHECK(close(s.y[0] - 2.0, u(t), 1e-12, 3.0));
    CHECK(s.x[0] == 1.0);
    CHECK(s.z[0] == 3.0);
  }
}

TEST_CASE(
    "IMPDISP/FGEO: each node runs the straight line to its final position, at X0 + (XF - X0) f(t Ascale)",
    "[loads]") {
  // Node 0 from (1, 2, 3) to (4, 6, 3): D = 5 along u = (0.6, 0.8, 0); f the ramp 0 -> 1 over x in [0, 1]
  // with Ascale = 2, so it arrives at t = 0.5 (Radioss evaluates f at t * Ascale) and stays. Node 1's final
  // position is its own: it is held. Gravity pulls both along -Z, across the lines: the acceleration across
  // the line is removed, so neither leaves it. Varying step.
  auto md = nodes_model({{1.0, 2.0, 3.0}, {0.5, 0.5, 0.5}});
  m::ImposedFinalGeometry g;
  g.id = 10;
  g.function = add_function(md, {0.0, 1.0, 10.0}, {0.0, 1.0, 1.0});
  g.ascale_x = 2.0;
  g.nodes = {0, 1};
  g.targets = {{4.0, 6.0, 3.0}, {0.5, 0.5, 0.5}};
  md.imposed_final_geometries.push_back(g);
  m::Gravity gr;
  gr.id = 1;
  gr.dir = 2;
  gr.fscale_y = -9.81;
  md.gravities.push_back(gr);
  auto s = state_of(md, {2.0, 1.0});
  const sv::SkewFrames frames(md);
  sv::ImposedVelocities impvel(md, frames);
  sv::ExternalLoads loads(md, frames);
  double t = 0, dt1 = 0;
  for (int k = 0; k < 700; ++k) {
    zero_forces(s);
    (void)loads.apply(s, t, dt1);
    accelerations(s);
    const double dt2 = step(k);
    (void)impvel.apply(s, t, dt1, dt2);
    update(s, dt1, dt2);
    t += dt2;
    dt1 = dt2;
    const double f = std::min(2.0 * t, 1.0);
    // Exact up to round-off of the coordinates (a few units).
    CHECK(close(s.x[0], 1.0 + 3.0 * f, 1e-12, 6.0));
    CHECK(close(s.y[0], 2.0 + 4.0 * f, 1e-12, 6.0));
    CHECK(s.z[0] == 3.0);
    CHECK(s.x[1] == 0.5);
    CHECK(s.y[1] == 0.5);
    CHECK(s.z[1] == 0.5);
  }
  CHECK(t > 0.6);  // past the arrival: the node rests at its final position
  CHECK(close(s.x[0], 4.0, 1e-12, 6.0));
  CHECK(close(s.y[0], 6.0, 1e-12, 6.0));
}

TEST_CASE("IMPVEL only acts between Tstart and Tstop", "[loads]") {
  auto md = nodes_model({{0, 0, 0}});
  m::ImposedVelocity iv;
  iv.id = 1;
  iv.function = add_function(md, {0.0}, {5.0});
  iv.dir = 0;
  iv.t_start = 0.01;
  iv.t_stop = 0.02;
  iv.group = add_group(md, {0});
  md.imposed_velocities.push_back(iv);
  auto s = state_of(md, {1.0});
  const sv::SkewFrames frames(md);
  sv::ImposedVelocities impvel(md, frames);
  double t = 0, dt1 = 0;
  const double dt = 1e-3;
  for (int k = 0; k < 40; ++k) {
    zero_forces(s);
    accelerations(s);
    (void)impvel.apply(s, t, dt1, dt);
    update(s, dt1, dt);
    if (t < 0.01 - 1e-12) CHECK(s.vx[0] == 0.0);
    if (t > 0.0105 && t < 0.0195) CHECK(close(s.vx[0], 5.0, 1e-12));
    t += dt;
    dt1 = dt;
  }
  CHECK(close(s.vx[0], 5.0, 1e-12));  // kept after Tstop (free node, no force)
}

TEST_CASE("INIVEL/TRA: at t = 0, and at Tstart", "[loads]") {
  auto md = nodes_model({{0, 0, 0}, {1, 0, 0}});
  m::InitialVelocity a, b;
  a.id = 1;
  a.v = {1.0, 2.0, 3.0};
  a.group = add_group(md, {0});
  b.id = 2;
  b.v = {0.0, 0.0, -4.0};
  b.t_start = 0.5;
  b.group = add_group(md, {1});
  md.initial_velocities = {a, b};
  auto s = state_of(md, {2.0, 1.0});
  const sv::SkewFrames frames(md);
  sv::InitialVelocities iv(md, frames);
  CHECK(iv.apply(s, 0.0) == 0.5 * 2.0 * 14.0);
  CHECK(s.vz[0] == 3.0);
  CHECK(s.vz[1] == 0.0);
  CHECK(iv.pending());
  CHECK(iv.apply(s, 0.4) == 0.0);
  CHECK(iv.apply(s, 0.5) == 0.5 * 16.0);
  CHECK(s.vz[1] == -4.0);
  CHECK(!iv.pending());
}

// (e) ------------------------------------------------------------------------------------------------------
namespace {

m::RigidWall floor_wall(int slide, double mu, std::vector<std::int32_t> secondary) {
  m::RigidWall w;
  w.id = 1;
  w.slide = slide;
  w.friction = mu;
  w.m = {0, 0, 0};
  w.m1 = {0, 0, 1};
  w.normal = {0, 0, 1};
  w.secondary = std::move(secondary);
  return w;
}

}  // namespace

TEST_CASE("fixed rigid wall, slide 0: plastic impact, work -1/2 m v0^2, tangential velocity kept",
          "[loads]") {
  // The predicted position x + dt2 v* is 1e-9 above the plane at cycle 9 and below it at cycle 10: the
  // contact test (x* - x_w).n > 0 is checked to that margin.
  auto md = nodes_model({{0, 0, 0.01 + 1e-9}});
  md.rigid_walls.push_back(floor_wall(0, 0.0, {0}));
  const double mass = 2.0, v0 = 1.0, vt = 0.3;
  auto s = state_of(md, {mass});
  s.vx[0] = vt;
  s.vz[0] = -v0;
  sv::RigidWalls walls(md);
  walls.initialize(s);
  // Constant step: the impact work -1/2 dt1 m u^2 / dt12 is exactly -1/2 m u^2 when dt1 = dt2.
  const double dt = 1e-3;
  double t = 0, dt1 = 0, work = 0;
  int impact_cycle = -1;
  for (int k = 0; k < 30; ++k) {
    zero_forces(s);
    accelerations(s);
    const double vz_before = s.vz[0];
    work += walls.apply(s, dt1, dt);
    if (vz_before != s.vz[0]) {
      CHECK(impact_cycle == -1);  // one impact
      impact_cycle = k;
      // Force of the node on the wall: m u / dt12 along n, u = -v0.
      CHECK(close(walls.outputs()[0].normal_force[2], -mass * v0 / dt, 1e-12));
      CHECK(walls.outputs()[0].contacts == 1);
    }
    update(s, dt1, dt);
    t += dt;
    dt1 = dt;
  }
  CHECK(impact_cycle == 10);
  CHECK(s.vz[0] == 0.0);  // perfectly plastic: the normal velocity is the wall's
  CHECK(s.vx[0] == vt);   // sliding: tangential velocity untouched
  CHECK(s.z[0] > 0.0);    // stopped before the plane, never pushed back
  CHECK(close(work, -0.5 * mass * v0 * v0, 1e-12));
  CHECK(close(walls.outputs()[0].normal_impulse[2], -mass * v0, 1e-12));
}

TEST_CASE("fixed rigid wall, slide 2: Coulomb deceleration mu g of a node pressed by gravity", "[loads]") {
  auto md = nodes_model({{0, 0, 0}});
  const double mu = 0.3, gz = 9.81, mass = 1.5, v0 = 2.0;
  md.rigid_walls.push_back(floor_wall(2, mu, {0}));
  m::Gravity g;
  g.id = 1;
  g.dir = 2;
  g.fscale_y = -gz;
  md.gravities.push_back(g);
  auto s = state_of(md, {mass});
  s.vx[0] = v0;
  sv::RigidWalls walls(md);
  const sv::SkewFrames frames(md);
  sv::ExternalLoads loads(md, frames);
  const double ke0 = kinetic_energy(s, 0.0);
  double t = 0, dt1 = 0, work = 0, sum_dt2 = 0;
  const int n_steps = 300;
  for (int k = 0;; ++k) {
    zero_forces(s);
    work += loads.apply(s, t, dt1);
    accelerations(s);
    if (k == n_steps) break;
    const double dt2 = step(k);
    work += walls.apply(s, dt1, dt2);
    update(s, dt1, dt2);
    // Each cycle removes exactly mu g dt12 of tangential velocity while sliding, so
    // v^{n+1/2} = v0 - mu g t^{n+1/2}: the scheme is exact for this constant deceleration and the check is
    // at round-off (1e-12 of v0). The node stays on the plane (z and v_z exactly 0).
    CHECK(close(s.vx[0], v0 - mu * gz * (t + 0.5 * dt2), 1e-12, v0));
    CHECK(s.z[0] == 0.0);
    CHECK(s.vz[0] == 0.0);
    sum_dt2 += dt2 * dt2;
    t += dt2;
    dt1 = dt2;
  }
  // Friction work -sum (v^{n-1/2} . Ft) against the print-time KE change: the work uses v^{n-1/2} instead
  // of the cycle's mean velocity, a first-order difference bounded by m (mu g)^2 sum dt^2 (each cycle
  // differs by at most m (mu g dt)^2).
  const double ke = kinetic_energy(s, dt1);
  CHECK(std::abs(work - (ke - ke0)) <= mass * mu * gz * mu * gz * sum_dt2);
  CHECK(work < 0);

  // Long after the stop time v0/(mu g) = 0.68 the node sticks: exactly at rest.
  for (int k = n_steps; k < 1200; ++k) {
    zero_forces(s);
    (void)loads.apply(s, t, dt1);
    accelerations(s);
    const double dt2 = step(k);
    (void)walls.apply(s, dt1, dt2);
    update(s, dt1, dt2);
    t += dt2;
    dt1 = dt2;
  }
  CHECK(t > v0 / (mu * gz));
  CHECK(s.vx[0] == 0.0);
  CHECK(s.vz[0] == 0.0);
}

TEST_CASE("fixed rigid wall, slide 0: a node resting under gravity stays on the plane", "[loads]") {
  auto md = nodes_model({{0, 0, 0}});
  md.rigid_walls.push_back(floor_wall(0, 0.0, {0}));
  m::Gravity g;
  g.id = 1;
  g.dir = 2;
  g.fscale_y = -9.81;
  md.gravities.push_back(g);
  const double mass = 4.0;
  auto s = state_of(md, {mass});
  s.vx[0] = 1.0;
  sv::RigidWalls walls(md);
  const sv::SkewFrames frames(md);
  sv::ExternalLoads loads(md, frames);
  double t = 0, dt1 = 0, work = 0;
  for (int k = 0; k < 100; ++k) {
    zero_forces(s);
    work += loads.apply(s, t, dt1);
    accelerations(s);
    const double dt2 = step(k);
    work += walls.apply(s, dt1, dt2);
    // The wall carries the weight: force on the wall m a.n = -m g along n (round-off).
    CHECK(close(walls.outputs()[0].normal_force[2], -mass * 9.81, 1e-12));
    update(s, dt1, dt2);
    t += dt2;
    dt1 = dt2;
  }
  // The normal acceleration is removed: exactly on the plane, no work; frictionless sliding.
  CHECK(s.z[0] == 0.0);
  CHECK(s.vz[0] == 0.0);
  CHECK(s.vx[0] == 1.0);
  CHECK(work == 0.0);
}

TEST_CASE("fixed rigid wall, slide 1: tied on contact", "[loads]") {
  auto md = nodes_model({{0, 0, 0.0005}});
  md.rigid_walls.push_back(floor_wall(1, 0.0, {0}));
  auto s = state_of(md, {1.0});
  s.vx[0] = 5.0;
  s.vz[0] = -1.0;
  sv::RigidWalls walls(md);
  zero_forces(s);
  accelerations(s);
  (void)walls.apply(s, 1e-3, 1e-3);
  CHECK(s.vx[0] == 0.0);
  CHECK(s.vz[0] == 0.0);
  CHECK(close(walls.outputs()[0].tangential_force[0], 5.0 / 1e-3, 1e-12));
}

TEST_CASE("moving rigid wall: the node takes the wall's velocity, the wall slows by the lagged impulse",
          "[loads]") {
  // Node 0 carries the wall (normal +z, moving +z at 1); node 1 (mass 1) at rest above it.
  auto md = nodes_model({{0, 0, 0}, {0, 0, 0.0105}});
  auto w = floor_wall(0, 0.0, {1});
  w.node = 0;
  w.mass = 10.0;
  w.v0 = {0, 0, 1.0};
  md.rigid_walls.push_back(w);
  auto s = state_of(md, {0.0, 1.0});
  sv::RigidWalls walls(md);
  walls.initialize(s);
  CHECK(s.mass[0] == 10.0);
  CHECK(s.vz[0] == 1.0);
  const double dt = 1e-3;
  double dt1 = 0;
  for (int k = 0; k < 20; ++k) {
    zero_forces(s);
    accelerations(s);
    walls.apply_wall_node_forces(s);
    (void)walls.apply(s, dt1, dt);
    if (k == 10) {
      // Impact: the node's normal velocity becomes the wall's predicted velocity.
      CHECK(walls.outputs()[0].contacts == 1);
      CHECK(s.vz[1] == 1.0);
      CHECK(close(walls.outputs()[0].normal_force[2], -1.0 / dt, 1e-12));
    }
    update(s, dt1, dt);
    dt1 = dt;
  }
  // Next cycle the wall receives -1/dt12 with the contact mass added: dv = -1 / (10 + 1), then the node
  // (faster than the wall) separates. Round-off.
  CHECK(close(s.vz[0], 10.0 / 11.0, 1e-12));
  CHECK(close(s.vz[1], 1.0, 1e-12));
}

TEST_CASE("sphere and cylinder walls: the radial velocity is removed on contact, the tangential one kept",
          "[loads]") {
  // A free node (mass 1) heading for a fixed cylinder (axis Z through the origin, diameter 2) at velocity
  // (-1, 0, 0.5), or for a fixed sphere (centre 0, diameter 2) at (-1, 0, 0), from x = 1.1: it reaches r = 1
  // after 0.1 s and stops radially there (perfectly plastic), keeping vz (along the cylinder's axis), never
  // inside; the normal work is -1/2 m u^2 with u = 1 the radial approach speed (docs/theory/elements.md 7.1,
  // the law of the plane).
  for (const int shape : {1, 2}) {
    DYNAMIC_SECTION((shape == 1 ? "cylinder" : "sphere")) {
      auto md = nodes_model({{1.1, 0, 0}});
      m::RigidWall w;
      w.id = 1;
      w.shape = shape;
      w.diameter = 2.0;
      w.m = {0, 0, 0};
      w.m1 = {0, 0, 1};
      w.normal = {0, 0, 1};
      w.secondary = {0};
      md.rigid_walls.push_back(w);
      auto s = state_of(md, {1.0});
      const double vz0 = shape == 1 ? 0.5 : 0.0;
      s.vx[0] = -1.0;
      s.vz[0] = vz0;
      sv::RigidWalls walls(md);
      walls.initialize(s);
      const double dt = 1e-3;
      double dt1 = 0, work = 0, rmin = 10;
      for (int k = 0; k < 300; ++k) {
        zero_forces(s);
        accelerations(s);
        work += walls.apply(s, dt1, dt);
        update(s, dt1, dt);
        dt1 = dt;
        const double r = shape == 1 ? std::hypot(s.x[0], s.y[0]) : std::hypot(s.x[0], s.y[0], s.z[0]);
        rmin = std::min(rmin, r);
      }
      CHECK(std::abs(s.vx[0]) <= 1e-12);  // stopped radially
      CHECK(s.vy[0] == 0.0);
      CHECK(s.vz[0] == vz0);       // along the axis: tangential, kept
      CHECK(rmin >= 1.0 - 1e-12);  // never inside
      CHECK(close(work, -0.5, 1e-9));
    }
  }
}

TEST_CASE(
    "parallelogram wall: a node hitting inside stops, nodes beside it fly on, a node behind is put back",
    "[loads]") {
  // The fixed parallelogram of corner M = 0 and edges e1 = (2, 0, 0), e2 = (1, 1, 0) (the corners (0, 0),
  // (2, 0), (3, 1), (1, 1) of the plane z = 0; normal e1 x e2 along +Z). Node 0 comes down at (1.5, 0.5), the
  // point 0.5 e1 + 0.5 e2: inside, it hits at cycle 10 (its predicted position crosses z = 0 then, as for the
  // plane wall). Nodes 1 and 2 come down at (0.2, 0.5) and (3.2, 0.5): inside the parallelogram's bounding
  // box but outside it (a = -0.15 and 1.35 on e1), they fly on freely, z = z0 - v0 t. Node 3 starts 0.0004
  // behind the wall going down; at cycle 1 (dt1 > 0) it is within the tolerance 2 dt1 |v.n| and comes back
  // onto the plane in one step: it leaves with the normal velocity 0.0014 / dt.
  const double z0 = 0.01 + 1e-9, v0 = 1.0, vt = 0.3, dt = 1e-3;
  for (const int slide : {0, 1}) {
    DYNAMIC_SECTION("slide " << slide) {
      auto md = nodes_model({{1.5, 0.5, z0}, {0.2, 0.5, z0}, {3.2, 0.5, z0}, {1.5, 0.5, -0.0004}});
      m::RigidWall w;
      w.id = 1;
      w.shape = 3;
      w.slide = slide;
      w.m = {0, 0, 0};
      w.m1 = {2, 0, 0};
      w.m2 = {1, 1, 0};
      w.normal = {0, 0, 1};
      w.secondary = {0, 1, 2, 3};
      md.rigid_walls.push_back(w);
      const double mass = 2.0;
      auto s = state_of(md, {mass, 1.0, 1.0, 1.0});
      for (std::size_t n = 0; n < 3; ++n) {
        s.vx[n] = vt;
        s.vz[n] = -v0;
      }
      s.vz[3] = -v0;
      sv::RigidWalls walls(md);
      walls.initialize(s);
      double dt1 = 0, work = 0;
      int impact_cycle = -1;
      for (int k = 0; k < 30; ++k) {
        zero_forces(s);
        accelerations(s);
        const double vz_before = s.vz[0];
        work += walls.apply(s, dt1, dt);
        if (vz_before != s.vz[0]) {
          CHECK(impact_cycle == -1);  // one impact
          impact_cycle = k;
          // Force of the node on the wall: m u / dt12 along n, u = -v0.
          CHECK(close(walls.outputs()[0].normal_force[2], -mass * v0 / dt, 1e-12));
        }
        update(s, dt1, dt);
        dt1 = dt;
        if (k == 1) {
          // Node 3 put back on the plane (round-off of 0.0014) and leaving at 0.0014 / dt.
          CHECK(std::abs(s.z[3]) <= 1e-15);
          CHECK(close(s.vz[3], 0.0014 / dt, 1e-12));
        }
        for (const std::size_t n : {1, 2}) {  // free flight (round-off of the coordinate)
          CHECK(close(s.z[n], z0 - v0 * dt * (k + 1), 1e-12, 1.0));
          CHECK(close(s.x[n], md.nodes.x[n] + vt * dt * (k + 1), 1e-12, 4.0));
        }
      }
      CHECK(impact_cycle == 10);
      CHECK(s.vz[0] == 0.0);                      // perfectly plastic: the normal velocity is the wall's
      CHECK(s.vx[0] == (slide == 0 ? vt : 0.0));  // sliding keeps the tangential velocity, tied stops it
      CHECK(s.z[0] > 0.0);                        // stopped above the plane
      CHECK(s.z[1] < -0.01);                      // the others went through the plane z = 0
      CHECK(s.z[2] < -0.01);
      // Normal work -1/2 dt1/dt12 m u (u - v_p) of each contact (dt1 = dt2): node 0, u = -v0, v_p = 0;
      // node 3 at cycle 1, u = -v0, v_p = 1.4 v0. The tie books no tangential work (only a slip does).
      const double w3 = -0.5 * 1.0 * v0 * (v0 + 1.4 * v0);
      CHECK(close(work, -0.5 * mass * v0 * v0 + w3, 1e-9));
    }
  }
}

TEST_CASE(
    "moving rigid wall without mass: it follows its imposed motion, and its free directions the contact",
    "[loads]") {
  // Node 0 carries the wall (normal +z, no mass, no wall Mass), as in real decks that impose some of its
  // motion; node 1 (mass 1) 0.0105 above it, at rest.
  auto md = nodes_model({{0, 0, 0}, {0, 0, 0.0105}});
  auto w = floor_wall(0, 0.0, {1});
  w.node = 0;
  md.rigid_walls.push_back(w);
  SECTION("nothing imposed: it keeps its velocity until it touches, then moves with the node it pushes") {
    auto s = state_of(md, {0.0, 1.0});
    sv::RigidWalls walls(md);
    REQUIRE_NOTHROW(walls.initialize(s));
    s.vz[0] = 1.0;  // given VZ0
    const double dt = 1e-3;
    double dt1 = 0;
    int contact_cycles = 0;
    for (int k = 0; k < 20; ++k) {
      zero_forces(s);
      accelerations(s);
      walls.apply_wall_node_forces(s);
      (void)walls.apply(s, dt1, dt);
      contact_cycles += walls.outputs()[0].contacts;
      update(s, dt1, dt);
      dt1 = dt;
      CHECK(std::isfinite(s.vz[0]));
    }
    // Impact at 1 m/s on a node at rest: the node takes the wall's speed; the next cycle the wall, with no
    // inertia of its own, takes the node's reaction over the node's mass alone: it stops dead (1 - 1/1) and
    // the node goes on at 1 m/s.
    CHECK(contact_cycles >= 1);
    CHECK(close(s.vz[1], 1.0, 1e-12));
    CHECK(std::abs(s.vz[0]) <= 1e-12);
  }
  SECTION("/IMPVEL in X, Y and Z: it follows the imposed motion exactly") {
    const auto one = add_function(md, {0.0, 1.0}, {1.0, 1.0});
    const auto zero = add_function(md, {0.0, 1.0}, {0.0, 0.0});
    for (int dir = 0; dir < 3; ++dir) {
      m::ImposedVelocity iv;
      iv.id = dir + 1;
      iv.function = dir == 2 ? one : zero;
      iv.dir = dir;
      iv.group = add_group(md, {0});
      md.imposed_velocities.push_back(iv);
    }
    auto s = state_of(md, {0.0, 1.0});
    sv::RigidWalls walls(md);
    const sv::SkewFrames frames(md);
    sv::ImposedVelocities impvel(md, frames);
    walls.initialize(s);
    const double dt = 1e-3;
    double t = 0, dt1 = 0;
    for (int k = 0; k < 20; ++k) {
      zero_forces(s);
      accelerations(s);
      walls.apply_wall_node_forces(s);
      (void)impvel.apply(s, t, dt1, dt);
      (void)walls.apply(s, dt1, dt);
      update(s, dt1, dt);
      CHECK(s.vz[0] == 1.0);
      t += dt;
      dt1 = dt;
    }
    CHECK(s.vz[1] == 1.0);  // pushed along at the wall's speed: a wall of infinite mass
    CHECK(close(s.z[0], 20 * dt * 1.0, 1e-12));
  }
}

// (f) ------------------------------------------------------------------------------------------------------
namespace {

// Main node 0 (no mass, off-centre), secondaries 1..k.
m::Model rigid_model(const std::vector<V3>& secondary, V3 main_at, int icog = 1) {
  std::vector<V3> pts = {main_at};
  pts.insert(pts.end(), secondary.begin(), secondary.end());
  auto md = nodes_model(pts);
  m::RigidBody rb;
  rb.id = 1;
  rb.main_node = 0;
  rb.icog = icog;
  for (std::size_t i = 0; i < secondary.size(); ++i) rb.secondary.push_back(static_cast<std::int32_t>(i + 1));
  md.rigid_bodies.push_back(rb);
  return md;
}

// One cycle of the loop with the rigid-body calls in the engine's order; no other condition.
void rigid_cycle(sv::NodeState& s, sv::RigidBodies& rb, double dt1, double dt2) {
  accelerations(s);
  rb.gather_and_accelerate(s, 0.0, dt1);
  rb.secondary_kinematics(s, dt1, dt2);
}

double distance(const sv::NodeState& s, std::size_t a, std::size_t b) {
  return std::hypot(s.x[a] - s.x[b], s.y[a] - s.y[b], s.z[a] - s.z[b]);
}

// Global angular momentum of the body about its main node: R^T diag(I) R w.
V3 angular_momentum(const sv::RigidBodyInfo& b, const sv::NodeState& s, double dt1) {
  const auto n = static_cast<std::size_t>(b.main);
  const double h = 0.5 * dt1;
  const V3 w = {s.wx[n] + h * s.awx[n], s.wy[n] + h * s.awy[n], s.wz[n] + h * s.awz[n]};
  V3 l{};
  for (int i = 0; i < 3; ++i) {
    double wp = 0;
    for (int j = 0; j < 3; ++j)
      wp += b.axes[static_cast<std::size_t>(3 * i + j)] * w[static_cast<std::size_t>(j)];
    for (int j = 0; j < 3; ++j)
      l[static_cast<std::size_t>(j)] +=
          b.axes[static_cast<std::size_t>(3 * i + j)] * b.principal[static_cast<std::size_t>(i)] * wp;
  }
  return l;
}

}  // namespace

TEST_CASE("rigid body set-up: ICoG 1 moves the main node to the centre of mass, mass and inertia",
          "[loads]") {
  const std::vector<V3> sec = {{1, 0, 0}, {0, 2, 0}, {0, 0, 3}, {-1, -1, 1}};
  const std::vector<double> ms = {1.0, 2.0, 3.0, 4.0};
  auto md = rigid_model(sec, {5.0, 5.0, 5.0});
  auto s = state_of(md, {0.5, ms[0], ms[1], ms[2], ms[3]});
  s.inertia[1] = 0.25;  // a shell node's scalar inertia counts in the tensor
  sv::RigidBodies rb(md);
  rb.initialize(s);
  const auto& b = rb.bodies()[0];
  // Centre of mass of {main (0.5 at (5,5,5)), secondaries}; exact sums, compared at round-off.
  const double mt = 0.5 + 10.0;
  const V3 g = {(2.5 + 1.0 - 4.0) / mt, (2.5 + 4.0 - 4.0) / mt, (2.5 + 9.0 + 4.0) / mt};
  CHECK(close(s.x[0], g[0], 1e-14, 1.0));
  CHECK(close(s.y[0], g[1], 1e-14, 1.0));
  CHECK(close(s.z[0], g[2], 1e-14, 1.0));
  CHECK(s.x0[0] == s.x[0]);
  CHECK(close(b.mass, mt, 1e-15));
  CHECK(s.mass[0] == b.mass);
  CHECK(rb.secondary_flags() == std::vector<std::uint8_t>{0, 1, 1, 1, 1});
  // Tensor: sum over all point masses (the main node's 0.5 at its old place) about the centre, plus 0.25.
  std::vector<V3> pts = sec;
  pts.push_back({5, 5, 5});
  std::vector<double> mm = ms;
  mm.push_back(0.5);
  double ixx = 0.25, iyy = 0.25, izz = 0.25, ixy = 0, iyz = 0, ixz = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const double x = pts[i][0] - g[0], y = pts[i][1] - g[1], z = pts[i][2] - g[2];
    ixx += mm[i] * (y * y + z * z);
    iyy += mm[i] * (x * x + z * z);
    izz += mm[i] * (x * x + y * y);
    ixy -= mm[i] * x * y;
    iyz -= mm[i] * y * z;
    ixz -= mm[i] * x * z;
  }
  const double scale = ixx + iyy + izz;
  CHECK(close(b.tensor[0], ixx, 1e-13, scale));
  CHECK(close(b.tensor[1], iyy, 1e-13, scale));
  CHECK(close(b.tensor[2], izz, 1e-13, scale));
  CHECK(close(b.tensor[3], ixy, 1e-13, scale));
  CHECK(close(b.tensor[4], iyz, 1e-13, scale));
  CHECK(close(b.tensor[5], ixz, 1e-13, scale));
  // Principal values: same trace; the main node's scalar inertia is the smallest.
  CHECK(close(b.principal[0] + b.principal[1] + b.principal[2], scale, 1e-13));
  CHECK(s.inertia[0] == std::min({b.principal[0], b.principal[1], b.principal[2]}));

  SECTION("ICoG 3 keeps the main node; ICoG 4 ignores the secondary masses") {
    auto md3 = rigid_model(sec, {5.0, 5.0, 5.0}, 3);
    auto s3 = state_of(md3, {0.5, ms[0], ms[1], ms[2], ms[3]});
    sv::RigidBodies rb3(md3);
    rb3.initialize(s3);
    CHECK(s3.x[0] == 5.0);
    CHECK(close(rb3.bodies()[0].mass, mt, 1e-15));
    auto md4 = rigid_model(sec, {5.0, 5.0, 5.0}, 4);
    md4.rigid_bodies[0].inertia = {1.0, 2.0, 3.0, 0.0, 0.0, 0.0};
    auto s4 = state_of(md4, {0.5, ms[0], ms[1], ms[2], ms[3]});
    sv::RigidBodies rb4(md4);
    rb4.initialize(s4);
    CHECK(s4.x[0] == 5.0);
    CHECK(rb4.bodies()[0].mass == 0.5);
    CHECK(rb4.bodies()[0].tensor[0] == 1.0);
  }
}

TEST_CASE("rigid body Ispher: 2 lifts a vanishing principal inertia, 1 makes it spherical", "[loads]") {
  // Two unit masses at x = -1 and 1: principal inertias (0, 2, 2). Exact binary values.
  for (const int ispher : {1, 2}) {
    auto md = rigid_model({{-1, 0, 0}, {1, 0, 0}}, {0, 0, 0});
    md.rigid_bodies[0].ispher = ispher;
    auto s = state_of(md, {0, 1, 1});
    sv::RigidBodies rb(md);
    rb.initialize(s);
    auto p = rb.bodies()[0].principal;
    std::sort(p.begin(), p.end());
    if (ispher == 2) {
      CHECK(close(p[0], 0.2, 1e-12));  // 0 + 0.1 I_max
      CHECK(close(p[2], 2.0, 1e-12));
      CHECK(close(s.inertia[0], 0.2, 1e-12));
    } else {
      CHECK(close(p[0], 4.0 / 3.0, 1e-12));
      CHECK(close(p[2], 4.0 / 3.0, 1e-12));
    }
  }
}

TEST_CASE("rigid body: a force on a secondary node gives F/M and (r x F)/I, gravity counted once",
          "[loads]") {
  // Square of four unit masses, side 1, centred at the origin; main node at the centre (no mass).
  const std::vector<V3> sec = {{0.5, 0.5, 0}, {-0.5, 0.5, 0}, {-0.5, -0.5, 0}, {0.5, -0.5, 0}};
  auto md = rigid_model(sec, {0, 0, 0});
  auto s = state_of(md, {0, 1, 1, 1, 1});
  sv::RigidBodies rb(md);
  rb.initialize(s);
  // I = diag(1, 1, 2): Ixx = sum m y^2 = 1, Iyy = 1, Izz = sum m (x^2 + y^2) = 2.
  zero_forces(s);
  s.fz[1] = 3.0;
  accelerations(s);
  rb.gather_and_accelerate(s, 0.0, 0.0);
  // Round-off (the main node's 1e-20 mass is in M).
  CHECK(close(s.az[0], 3.0 / 4.0, 1e-14));
  CHECK(std::abs(s.ax[0]) < 1e-15);
  // r x F = (0.5, 0.5, 0) x (0, 0, 3) = (1.5, -1.5, 0); alpha = I^-1 (r x F) = (1.5, -1.5, 0).
  CHECK(close(s.awx[0], 1.5, 1e-13));
  CHECK(close(s.awy[0], -1.5, 1e-13));
  CHECK(std::abs(s.awz[0]) < 1e-13);
  CHECK(s.fz[0] == 3.0);  // gathered force kept on the main node for output
  // Secondary kinematics with dt1 = dt2 = dt: after the update every secondary spins with
  // omega^{n+1/2} = dt12 alpha, and v_s = v_N^{n+1/2} + c1 w x r + c2 dt w x (w x r) (round-off).
  const double dt = 1e-3;
  std::vector<V3> r0;
  for (std::size_t n = 0; n < s.n; ++n) r0.push_back({s.x[n] - s.x[0], s.y[n] - s.y[0], s.z[n] - s.z[0]});
  rb.secondary_kinematics(s, dt, dt);
  update(s, dt, dt);
  const V3 w = {1.5 * dt, -1.5 * dt, 0.0};
  const double phi = std::hypot(w[0], w[1]) * dt;
  const double c1 = std::sin(phi) / phi, c2 = (1 - std::cos(phi)) / (phi * phi);
  for (std::size_t n = 1; n <= 4; ++n) {
    CHECK(close(s.wx[n], w[0], 1e-12));
    CHECK(close(s.wy[n], w[1], 1e-12));
    const V3& r = r0[n];
    const V3 wr = {w[1] * r[2] - w[2] * r[1], w[2] * r[0] - w[0] * r[2], w[0] * r[1] - w[1] * r[0]};
    const V3 wwr = {w[1] * wr[2] - w[2] * wr[1], w[2] * wr[0] - w[0] * wr[2], w[0] * wr[1] - w[1] * wr[0]};
    CHECK(close(s.vx[n], s.vx[0] + c1 * wr[0] + c2 * dt * wwr[0], 1e-10, 1e-3));
    CHECK(close(s.vy[n], s.vy[0] + c1 * wr[1] + c2 * dt * wwr[1], 1e-10, 1e-3));
    CHECK(close(s.vz[n], s.vz[0] + c1 * wr[2] + c2 * dt * wwr[2], 1e-10, 1e-3));
  }
}

TEST_CASE("rigid body: angular acceleration with the full tensor and with fixed main-node rotations",
          "[loads]") {
  // Unit masses at (1,0,1), (-1,0,-1), (0,1,0), (0,-1,0): I = [[4,0,-2],[0,4,0],[-2,0,4]] about the
  // origin. A moment (1, 2, 3) on the main node, body at rest: alpha = I^-1 M = (10/12, 1/2, 14/12).
  // With Rx fixed by /BCS the (y, z) block is solved alone: (0, 1/2, 3/4); with Ry fixed, the coupled
  // (x, z) block: (10/12, 0, 14/12). Spinning at w = (0, 0, 1) with Rx fixed, the gyroscopic moment
  // -w x (I w) = (0, 2, 0) is added: (0, 1, 3/4). Round-off.
  const std::vector<V3> sec = {{1, 0, 1}, {-1, 0, -1}, {0, 1, 0}, {0, -1, 0}};
  struct Case {
    std::uint8_t fixed;
    double wz;
    V3 expected;
  };
  const std::vector<Case> cases = {{0, 0.0, {10.0 / 12.0, 0.5, 14.0 / 12.0}},
                                   {8, 0.0, {0.0, 0.5, 0.75}},
                                   {16, 0.0, {10.0 / 12.0, 0.0, 14.0 / 12.0}},
                                   {8, 1.0, {0.0, 1.0, 0.75}}};
  for (const auto& [fixed, wz, expected] : cases) {
    auto md = rigid_model(sec, {0, 0, 0});
    auto s = state_of(md, {0, 1, 1, 1, 1});
    sv::RigidBodies rb(md);
    rb.initialize(s);
    s.fixed[0] = fixed;
    s.wz[0] = wz;
    zero_forces(s);
    s.mx[0] = 1.0;
    s.my[0] = 2.0;
    s.mz[0] = 3.0;
    accelerations(s);
    rb.gather_and_accelerate(s, 0.0, 0.0);
    CHECK(close(s.awx[0], expected[0], 1e-13, 1.0));
    CHECK(close(s.awy[0], expected[1], 1e-13, 1.0));
    CHECK(close(s.awz[0], expected[2], 1e-13, 1.0));
  }
}

TEST_CASE("rigid body under gravity: the weight is counted once", "[loads]") {
  const std::vector<V3> sec = {{0.5, 0.5, 0}, {-0.5, 0.5, 0}, {-0.5, -0.5, 0}, {0.5, -0.5, 0}};
  auto md = rigid_model(sec, {0, 0, 0});
  m::Gravity g;
  g.id = 1;
  g.dir = 2;
  g.fscale_y = -9.81;
  md.gravities.push_back(g);
  auto s = state_of(md, {0, 1, 1, 1, 1});
  sv::RigidBodies rb(md);
  rb.initialize(s);
  // The secondaries are skipped and the main node carries M g, so a_N = g (round-off).
  const sv::SkewFrames frames(md);
  sv::ExternalLoads loads(md, frames, rb.secondary_flags());
  zero_forces(s);
  (void)loads.apply(s, 0.0, 0.0);
  CHECK(s.fz[1] == 0.0);
  accelerations(s);
  rb.gather_and_accelerate(s, 0.0, 0.0);
  CHECK(close(s.az[0], -9.81, 1e-14));
  rb.secondary_kinematics(s, 0.0, 1e-3);
  for (std::size_t n = 1; n <= 4; ++n) CHECK(close(s.az[n], -9.81, 1e-14));  // at rest: a_s = a_N
}

TEST_CASE("rigid body spinning about its normal: rigid, energy and angular momentum conserved", "[loads]") {
  const std::vector<V3> sec = {{0.5, 0.5, 0}, {-0.5, 0.5, 0}, {-0.5, -0.5, 0}, {0.5, -0.5, 0}};
  auto md = rigid_model(sec, {0.1, -0.05, 0.0});  // ICoG 1 moves it to the centre
  auto s = state_of(md, {0, 1, 1, 1, 1});
  const double w0 = 10.0;
  s.wz[0] = w0;
  sv::RigidBodies rb(md);
  rb.initialize(s);
  CHECK(close(s.vx[1], -w0 * 0.5, 1e-14));  // v_s = w x r
  std::vector<double> d0;
  for (std::size_t a = 1; a <= 4; ++a)
    for (std::size_t b = a + 1; b <= 4; ++b) d0.push_back(distance(s, a, b));
  const double izz = 2.0, ke_exact = 0.5 * izz * w0 * w0;
  const double dt = 1e-3, phi = w0 * dt;
  double dt1 = 0;
  const int n_steps = 2000;  // 20 rad, about three turns
  for (int k = 0; k < n_steps; ++k) {
    zero_forces(s);
    rigid_cycle(s, rb, dt1, dt);
    if (k > 0) {
      // Energy the engine prints: node sums + the rigid-body correction = 1/2 Izz w^2, and the rigid
      // body's own angular momentum Izz w: the spin axis is principal, so w stays constant and both hold
      // to round-off.
      sv::KineticSums c;
      rb.kinetic_correction(s, dt1, c);
      CHECK(c.mass.value() == -4.0);  // the secondaries' mass is already in the main node's
      CHECK(close(kinetic_energy(s, dt1) + c.translational.value() + c.rotational.value(), ke_exact, 1e-12));
      CHECK(close(rb.kinetic_energy(0, s, dt1), ke_exact, 1e-12));
      CHECK(close(angular_momentum(rb.bodies()[0], s, dt1)[2], izz * w0, 1e-12));
    }
    std::vector<V3> before;
    for (std::size_t n = 0; n < s.n; ++n) before.push_back({s.x[n], s.y[n], s.z[n]});
    update(s, dt1, dt);
    // Angular momentum carried by the nodes over the step, sum m r^n x (r^{n+1} - r^n)/dt: the exact
    // rotation by phi per step gives Izz w sin(phi)/phi at every step (round-off).
    double lz = 0;
    for (std::size_t n = 1; n <= 4; ++n) {
      const double rx = before[n][0] - before[0][0], ry = before[n][1] - before[0][1];
      const double dx = (s.x[n] - s.x[0]) - rx, dy = (s.y[n] - s.y[0]) - ry;
      lz += s.mass[n] * (rx * dy - ry * dx) / dt;
    }
    CHECK(close(lz, izz * w0 * std::sin(phi) / phi, 1e-12));
    dt1 = dt;
  }
  // Rigid: every distance kept to round-off after 2000 steps (1e-12 relative).
  std::size_t q = 0;
  for (std::size_t a = 1; a <= 4; ++a)
    for (std::size_t b = a + 1; b <= 4; ++b) CHECK(close(distance(s, a, b), d0[q++], 1e-12));
  // The main node stays at the centre (no force): round-off of the coordinate scale 1.
  CHECK(std::abs(s.x[0]) < 1e-14);
  CHECK(std::abs(s.y[0]) < 1e-14);
  // Turned by 20 rad: node 1 at angle pi/4 + 20.
  const double ang = std::atan2(s.y[1] - s.y[0], s.x[1] - s.x[0]);
  CHECK(std::abs(std::remainder(ang - (M_PI / 4 + n_steps * phi), 2 * M_PI)) < 1e-10);
}

namespace {

struct Drift {
  double momentum = 0, energy = 0, phi_max = 0, distance = 0;
};

// Torque-free tumbling body over the time t_end with the step dt: largest relative change of a component
// of the global angular momentum and of the kinetic energy, largest w dt, change of a distance.
Drift tumble(double dt, double t_end) {
  // Three distinct principal moments (1.54, 2.54, 3), spin mostly about the intermediate axis (unstable:
  // it tumbles), so the gyroscopic terms matter.
  const std::vector<V3> sec = {{1, 0, 0}, {-1, 0, 0}, {0, 0.5, 0}, {0, -0.5, 0}, {0, 0, 0.3}, {0, 0, -0.3}};
  auto md = rigid_model(sec, {0, 0, 0});
  auto s = state_of(md, {0, 1, 1, 2, 2, 3, 3});
  s.wx[0] = 1.0;
  s.wy[0] = 5.0;
  s.wz[0] = 0.2;
  sv::RigidBodies rb(md);
  rb.initialize(s);
  const auto& b = rb.bodies()[0];
  const V3 l0 = angular_momentum(b, s, 0.0);
  const double lnorm = std::hypot(l0[0], l0[1], l0[2]);
  const double ke0 = rb.kinetic_energy(0, s, 0.0);
  const double d0 = distance(s, 1, 3);
  Drift d;
  double dt1 = 0;
  const auto n_steps = static_cast<int>(std::lround(t_end / dt));
  for (int k = 0; k <= n_steps; ++k) {
    zero_forces(s);
    rigid_cycle(s, rb, dt1, dt);
    if (k > 0) {
      const V3 l = angular_momentum(b, s, dt1);
      for (std::size_t i = 0; i < 3; ++i) d.momentum = std::max(d.momentum, std::abs(l[i] - l0[i]) / lnorm);
      d.energy = std::max(d.energy, std::abs(rb.kinetic_energy(0, s, dt1) - ke0) / ke0);
    }
    d.phi_max = std::max(d.phi_max, std::hypot(s.wx[0], s.wy[0], s.wz[0]) * dt);
    update(s, dt1, dt);
    dt1 = dt;
  }
  d.distance = std::abs(distance(s, 1, 3) - d0) / d0;
  return d;
}

}  // namespace

TEST_CASE("rigid body tumbling: Euler's equations keep the global angular momentum", "[loads]") {
  const double t_end = 2.0;  // several tumbling periods
  const double dt = 1e-4;
  const Drift a = tumble(dt, t_end), b = tumble(0.5 * dt, t_end);
  // The angular step w^{n+1/2} = w^{n-1/2} + dt alpha(w^{n-1/2}) is explicit and first order: each cycle
  // changes L and KE by O((w dt)^2) relative, so after N cycles the drift is bounded by N (w dt)^2
  // (5e-3 here). A wrong sign of a gyroscopic term turns L away from its direction by O(1) within one
  // tumbling period.
  const double n_steps = t_end / dt;
  CHECK(a.momentum <= n_steps * a.phi_max * a.phi_max);
  CHECK(a.energy <= n_steps * a.phi_max * a.phi_max);
  // And the drift is a discretisation error: halving the step halves it (first order, ratio 2 +- 20 %).
  CHECK(a.momentum / b.momentum == Approx(2.0).epsilon(0.2));
  CHECK(a.energy / b.energy == Approx(2.0).epsilon(0.2));
  // Rigid all along: round-off.
  CHECK(a.distance < 1e-12);
}

// (f) ------------------------------------------------------------------------------------------------------
// Sensors (solver/conditions/sensors.hpp): /SENSOR/TIME and what it drives. The loop below is the engine's
// order: loads at t_n with the sensor state of the previous check, the step, the sensors' check with it, the
// conditions, the update. With a constant step and activation times half a step before a cycle time, the
// central difference sums are the exact integrals (midpoint rule on linear functions): round-off tolerances.
namespace {

m::Sensor timer(std::int64_t id, double t_delay, double t_stop = m::kNever) {
  m::Sensor s;
  s.id = id;
  s.t_delay = t_delay;
  s.t_stop = t_stop;
  return s;
}

}  // namespace

TEST_CASE("sensor: on when t + dt reaches Tdelay (from Tdelay itself), off for good at Tstop", "[loads]") {
  m::Model md;
  md.sensors = {timer(7, 0.0), timer(8, 0.25, 0.5), timer(9, -1.0)};
  sv::Sensors sensors(md);
  const auto starts = sensors.starts();
  REQUIRE(starts.size() == 3);
  CHECK(starts[1] == m::kNever);
  sensors.update(0.0, 0.0);  // before cycle 0: Tdelay <= 0 is on from the start
  CHECK(starts[0] == 0.0);
  CHECK(starts[1] == m::kNever);
  CHECK(starts[2] == -1.0);
  CHECK(sensors.take_messages().size() == 2);
  sensors.update(0.1, 0.1);
  CHECK(starts[1] == m::kNever);
  sensors.update(0.2, 0.1);  // 0.2 + 0.1 >= 0.25: on, from 0.25 (not from the cycle's time)
  CHECK(starts[1] == 0.25);
  const auto on = sensors.take_messages();
  REQUIRE(on.size() == 1);
  CHECK(on[0] == "SENSOR (TIME) 8 ACTIVATED AT TIME 2.5000E-01");
  sensors.update(0.3, 0.1);
  CHECK(starts[1] == 0.25);
  sensors.update(0.4, 0.1);  // 0.5 >= Tstop: off
  CHECK(starts[1] == m::kNever);
  CHECK(sensors.take_messages() ==
        std::vector<std::string>{"SENSOR (TIME) 8 DEACTIVATED AT TIME 5.0000E-01"});
  sensors.update(10.0, 0.1);  // never on again
  CHECK(starts[1] == m::kNever);
  CHECK(sensors.take_messages().empty());
  CHECK(md.sensor_index(9) == 2);
  CHECK(md.sensor_index(0) == m::kNone);
  CHECK_THROWS_AS(md.sensor_index(10), std::out_of_range);
}

TEST_CASE("sensor: a /CLOAD and a /GRAV on free masses act from the activation, F read at t - Tdelay",
          "[loads]") {
  // Node 0: /CLOAD along Z, F(tau) = 6 tau (ramp), sensor 1 on from T1 = 0.0205 to Tstop = 0.0405.
  // Node 1: /GRAV along X, g = -9.81 constant, sensor 2 on from T2 = 0.0305 (never off).
  const double dt = 1e-3, T1 = 0.0205, T1_stop = 0.0405, T2 = 0.0305, g = -9.81, m0 = 2.0, m1 = 0.5;
  auto md = nodes_model({{0, 0, 0}, {1, 0, 0}});
  md.sensors = {timer(11, T1, T1_stop), timer(12, T2)};
  m::ConcentratedLoad c;
  c.id = 1;
  c.function = add_function(md, {0.0, 1.0}, {0.0, 1.0});
  c.dir = 2;
  c.fscale_y = 6.0;
  c.sensor = 11;
  c.group = add_group(md, {0});
  md.concentrated_loads.push_back(c);
  m::Gravity gr;
  gr.id = 1;
  gr.dir = 0;
  gr.fscale_y = g;
  gr.sensor = 12;
  gr.group = add_group(md, {1});
  md.gravities.push_back(gr);
  auto s = state_of(md, {m0, m1});
  sv::Sensors sensors(md);
  const sv::SkewFrames frames(md);
  sv::ExternalLoads loads(md, frames);
  sensors.update(0.0, 0.0);
  double t = 0, dt1 = 0;
  for (int k = 0; k < 60; ++k) {
    zero_forces(s);
    (void)loads.apply(s, t, dt1, sensors.starts());
    if (t < T1) CHECK(s.fz[0] == 0.0);  // nothing before the sensor
    if (t < T2) CHECK(s.fx[1] == 0.0);
    accelerations(s);
    sensors.update(t, dt);
    update(s, dt1, dt);
    const double mid = t + 0.5 * dt;  // v = v^{n+1/2}: the impulse up to t_n + dt/2
    // Momentum m v = integral of F(t' - T1) dt' from T1 to min(mid, Tstop) = 3 tau^2; 0 before.
    const double tau1 = std::clamp(mid, T1, T1_stop) - T1;
    // Round-off of the momentum scale (m g t ~ 0.2, 3 tau^2 ~ 1e-3): 1e-13 absolute.
    CHECK(close(m0 * s.vz[0], 3.0 * tau1 * tau1, 1e-13, 1.0));
    CHECK(close(m1 * s.vx[1], m1 * g * (std::max(mid, T2) - T2), 1e-13, 1.0));
    t += dt;
    dt1 = dt;
  }
  CHECK(s.vz[0] > 0);  // the load did act, and stopped: 3 (Tstop - T1)^2 / m0
  CHECK(close(s.vz[0], 3.0 * (T1_stop - T1) * (T1_stop - T1) / m0, 1e-12));
}

TEST_CASE("sensor: a /PLOAD acts while its sensor is on, its function read from the activation", "[loads]") {
  // One triangle (area 1/2, normal +z): p(tau) = 4 tau, sensor on from 0.25 to 0.5: it acts at the cycles
  // 0.25 <= t < 0.5 (at 0.25 with p(0) = 0).
  auto md = nodes_model({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  m::Surface surf;
  surf.id = 1;
  surf.segments = {{0, 1, 2, 2}};
  md.surfaces.push_back(surf);
  md.sensors = {timer(6, 0.25, 0.5)};
  m::PressureLoad p;
  p.id = 1;
  p.surface = 0;
  p.function = add_function(md, {0.0, 1.0}, {0.0, 4.0});
  p.sensor = 6;
  md.pressure_loads.push_back(p);
  auto s = state_of(md, {1, 1, 1});
  sv::Sensors sensors(md);
  const sv::SkewFrames frames(md);
  sv::ExternalLoads loads(md, frames);
  sensors.update(0.0, 0.0);
  for (const auto& [t, expected] : std::vector<std::pair<double, double>>{
           {0.125, 0.0}, {0.25, 0.0}, {0.375, 4.0 * 0.125 * 0.5 / 3}, {0.5, 0.0}, {0.625, 0.0}}) {
    zero_forces(s);
    (void)loads.apply(s, t, 0.125, sensors.starts());
    INFO("t = " << t);
    CHECK(s.fz[0] == Approx(expected).epsilon(1e-14));  // p A / 3 on each node
    sensors.update(t, 0.125);
  }
}

TEST_CASE("sensor: /IMPVEL and /IMPDISP start at the activation, their functions from there", "[loads]") {
  // Node 0: /IMPVEL Y, v_imp(tau) = 3 tau, sensor on from T1; free before (it keeps 0.2).
  // Node 1: /IMPDISP Z, u(tau) = 2 tau, sensor on from T2; free at 0.5 before, then the function's
  //         increments from where it is: z = z(t_k0) + 2 (t - t_k0), k0 the first cycle with t >= T2.
  const double dt = 1e-3, T1 = 0.0105, T2 = 0.0155;
  auto md = nodes_model({{0, 0, 0}, {1, 0, 0}});
  md.sensors = {timer(1, T1), timer(2, T2)};
  const auto ramp = add_function(md, {0.0, 1.0}, {0.0, 1.0});
  m::ImposedVelocity iv;
  iv.id = 1;
  iv.function = ramp;
  iv.dir = 1;
  iv.fscale_y = 3.0;
  iv.sensor = 1;
  iv.group = add_group(md, {0});
  m::ImposedVelocity id = iv;
  id.id = 2;
  id.displacement = true;
  id.dir = 2;
  id.fscale_y = 2.0;
  id.sensor = 2;
  id.group = add_group(md, {1});
  md.imposed_velocities = {iv, id};
  auto s = state_of(md, {1.0, 1.0});
  s.vy[0] = 0.2;
  s.vz[1] = 0.5;
  sv::Sensors sensors(md);
  const sv::SkewFrames frames(md);
  sv::ImposedVelocities impvel(md, frames);
  sensors.update(0.0, 0.0);
  double t = 0, dt1 = 0, t_k0 = -1, z_k0 = 0;
  for (int k = 0; k < 40; ++k) {
    zero_forces(s);
    accelerations(s);
    sensors.update(t, dt);
    if (t >= T2 && t_k0 < 0) {
      t_k0 = t;
      z_k0 = s.z[1];
    }
    (void)impvel.apply(s, t, dt1, dt, sensors.starts());
    update(s, dt1, dt);
    if (t < T1)
      CHECK(s.vy[0] == 0.2);
    else
      CHECK(close(s.vy[0], 3.0 * (t + 0.5 * dt - T1), 1e-12, 1e-3));
    if (t < T2)
      CHECK(close(s.z[1], 0.5 * (t + dt), 1e-12, 1e-3));
    else
      CHECK(close(s.z[1], z_k0 + 2.0 * (t + dt - t_k0), 1e-12, 1e-3));
    t += dt;
    dt1 = dt;
  }
  CHECK(t_k0 > 0);
}

TEST_CASE("sensor: /INIVEL at the activation (Tstart 0), or at the earlier of Tstart and the activation",
          "[loads]") {
  auto md = nodes_model({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}});
  md.sensors = {timer(3, 0.3)};
  m::InitialVelocity a;
  a.id = 1;
  a.v = {0.0, 0.0, -4.0};
  a.sensor = 3;
  a.group = add_group(md, {0});
  m::InitialVelocity b = a;
  b.id = 2;
  b.t_start = 0.2;  // before the sensor: Tstart wins
  b.group = add_group(md, {1});
  m::InitialVelocity c = a;
  c.id = 3;
  c.t_start = 0.9;  // after it: the sensor wins
  c.group = add_group(md, {2});
  md.initial_velocities = {a, b, c};
  auto s = state_of(md, {1.0, 1.0, 1.0});
  sv::Sensors sensors(md);
  const sv::SkewFrames frames(md);
  sv::InitialVelocities inivel(md, frames);
  sensors.update(0.0, 0.0);
  CHECK(inivel.apply(s, 0.0, sensors.starts()) == 0.0);
  sensors.update(0.1, 0.1);
  CHECK(inivel.apply(s, 0.2, sensors.starts()) == 8.0);  // b
  CHECK(s.vz[1] == -4.0);
  CHECK(s.vz[0] == 0.0);
  sensors.update(0.2, 0.1);  // on from 0.3
  CHECK(inivel.apply(s, 0.29, sensors.starts()) == 0.0);
  CHECK(inivel.apply(s, 0.3, sensors.starts()) == 16.0);  // a and c
  CHECK(s.vz[0] == -4.0);
  CHECK(s.vz[2] == -4.0);
  CHECK(!inivel.pending());
}

TEST_CASE("sensor: a rigid body is formed from its secondaries and released 2 cycles after the sensor",
          "[loads]") {
  // Secondaries of masses 1, 1, 2 at (1,0,0), (-1,0,0), (0,1,0): centre (0, 0.5, 0), M = 4, I = diag(1, 2, 3)
  // about it. Nodes 1 and 2 move at +-1 along Y: momentum 0, angular momentum (0, 0, 2), so w = 2/3 about Z.
  auto md = rigid_model({{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}}, {5.0, 5.0, 5.0}, 3);
  md.sensors = {timer(4, 0.0105)};
  auto& rb_model = md.rigid_bodies[0];
  rb_model.sensor = 4;
  rb_model.mass = 100.0;                  // not used with a sensor, as the main node's own mass
  rb_model.inertia = {9, 9, 9, 0, 0, 0};  // nor the added inertia
  auto s = state_of(md, {7.0, 1.0, 1.0, 2.0});
  s.vy[1] = 1.0;
  s.vy[2] = -1.0;
  sv::Sensors sensors(md);
  sv::RigidBodies rb(md);
  sensors.update(0.0, 0.0);
  rb.initialize(s, sensors.starts());
  const auto& b = rb.bodies()[0];
  REQUIRE(b.active);
  CHECK(s.mass[0] == Approx(4.0).epsilon(1e-14));
  CHECK(s.x[0] == 0.0);
  CHECK(s.y[0] == Approx(0.5).epsilon(1e-14));
  CHECK(s.z[0] == 0.0);
  CHECK(s.wz[0] == Approx(2.0 / 3.0).epsilon(1e-14));
  CHECK(std::abs(s.vx[0]) + std::abs(s.vy[0]) + std::abs(s.vz[0]) < 1e-15);
  CHECK(s.vx[1] == Approx(1.0 / 3.0).epsilon(1e-14));  // w x r, r = (1, -0.5, 0)
  CHECK(s.vy[1] == Approx(2.0 / 3.0).epsilon(1e-14));

  const double dt = 1e-3;
  double t = 0, dt1 = 0;
  std::vector<std::string> messages;
  int released_at = -1;
  for (int k = 0; k < 20; ++k) {
    accelerations(s);
    sensors.update(t, dt);
    rb.gather_and_accelerate(s, t, dt1, sensors.starts());
    rb.secondary_kinematics(s, dt1, dt);
    for (auto& msg : rb.take_messages()) messages.push_back(std::to_string(k) + ": " + msg);
    if (!b.active && released_at < 0) released_at = k;
    update(s, dt1, dt);
    t += dt;
    dt1 = dt;
  }
  // Seen on at cycle 11 (the first t_n > 0.0105), released 2 cycles later.
  CHECK(messages == std::vector<std::string>{"11: RIGID BODY 1 WILL BE SET OFF WITHIN 2 CYCLES",
                                             "13: RIGID BODY 1 SET OFF"});
  CHECK(released_at == 13);
  CHECK(s.mass[0] == 0.0);
  CHECK(rb.secondary_flags() == std::vector<std::uint8_t>{0, 0, 0, 0});
  // Released: the secondaries fly on with the rigid velocities they had (no force acts), apart.
  const double v1x = s.vx[1];
  accelerations(s);
  rb.gather_and_accelerate(s, t, dt1, sensors.starts());
  rb.secondary_kinematics(s, dt1, dt);
  update(s, dt1, dt);
  CHECK(s.vx[1] == v1x);
}

TEST_CASE("sensor: a rigid body whose sensor is on at t = 0 is never formed", "[loads]") {
  auto md = rigid_model({{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}}, {5.0, 5.0, 5.0});
  md.sensors = {timer(4, 0.0)};
  md.rigid_bodies[0].sensor = 4;
  auto s = state_of(md, {7.0, 1.0, 1.0, 2.0});
  sv::Sensors sensors(md);
  sv::RigidBodies rb(md);
  sensors.update(0.0, 0.0);
  rb.initialize(s, sensors.starts());
  CHECK(!rb.bodies()[0].active);
  CHECK(s.mass[0] == 0.0);  // the main node of a body with a sensor has no mass of its own
  CHECK(s.mass[1] == 1.0);
  CHECK(s.x[0] == 5.0);
  CHECK(rb.secondary_flags() == std::vector<std::uint8_t>{0, 0, 0, 0});
  CHECK(rb.take_messages() == std::vector<std::string>{"RIGID BODY 1 SET OFF"});
}

TEST_CASE("sensor: /IMPDISP/FGEO under a sensor drives the node to its absolute place on the line",
          "[kinematics][sensor]") {
  // f = 1 from the start: the node must be at its final position one step after the sensor switches on
  // (Tdelay 10.5 ms, between cycles), as Radioss's fixfingeo.F imposes the place, not the increments of f
  // (which are 0 here and would leave the node where it is).
  auto md = nodes_model({{0.0, 0.0, 0.0}});
  md.sensors = {m::Sensor{}};
  md.sensors[0].id = 5;
  md.sensors[0].t_delay = 0.0105;
  m::ImposedFinalGeometry g;
  g.id = 10;
  g.function = add_function(md, {0.0, 10.0}, {1.0, 1.0});
  g.sensor = 5;
  g.nodes = {0};
  g.targets = {{1.0, 0.0, 0.0}};
  md.imposed_final_geometries.push_back(g);
  auto s = state_of(md, {1.0});
  sv::Sensors sensors(md);
  const sv::SkewFrames frames(md);
  sv::ImposedVelocities impvel(md, frames);
  sensors.update(0.0, 0.0);
  double t = 0, dt1 = 0;
  const double dt = 1e-3;
  for (int k = 0; k < 40; ++k) {
    zero_forces(s);
    accelerations(s);
    sensors.update(t, dt);
    (void)impvel.apply(s, t, dt1, dt, sensors.starts());
    update(s, dt1, dt);
    t += dt;
    dt1 = dt;
    if (t < 0.0105) CHECK(s.x[0] == 0.0);  // nothing before the sensor
  }
  // The place is imposed through the velocity of one step: exact to round-off.
  CHECK(s.x[0] == Approx(1.0).margin(1e-12));
  CHECK(s.y[0] == 0.0);
}

TEST_CASE("rigid body: its correction cancels the secondaries' terms of the exact node sums", "[loads]") {
  // The engine's node sums add 1/2 m |v|^2, m and m v for every node (kinematics_driver.cpp) and the body's
  // correction adds the same terms of its secondaries negated: in exact sums they cancel to the bit, so what
  // is left is the main node's terms alone, each rounded once (a plain running sum leaves round-off here).
  const std::vector<V3> sec = {{0.5, 0.5, 0}, {-0.5, 0.5, 0}, {-0.5, -0.5, 0}, {0.5, -0.5, 0}};
  auto md = rigid_model(sec, {0.1, -0.05, 0.0});
  auto s = state_of(md, {0, 1, 1, 1, 1});
  s.vx[0] = 0.3;
  s.vy[0] = -1.7;
  s.wz[0] = 10.0;
  sv::RigidBodies rb(md);
  rb.initialize(s);
  sv::KineticSums sums;
  for (std::size_t n = 0; n < s.n; ++n) {
    const double vx = s.vx[n], vy = s.vy[n], vz = s.vz[n];
    sums.translational.add(0.5 * s.mass[n] * (vx * vx + vy * vy + vz * vz));
    sums.mass.add(s.mass[n]);
    sums.momentum[0].add(s.mass[n] * vx);
    sums.momentum[1].add(s.mass[n] * vy);
  }
  rb.kinetic_correction(s, 0.0, sums);
  const double vx = s.vx[0], vy = s.vy[0], vz = s.vz[0];
  CHECK(sums.translational.value() == 0.5 * s.mass[0] * (vx * vx + vy * vy + vz * vz));
  CHECK(sums.mass.value() == s.mass[0]);
  CHECK(sums.momentum[0].value() == s.mass[0] * vx);
  CHECK(sums.momentum[1].value() == s.mass[0] * vy);
  CHECK(s.vy[1] != s.vy[0]);  // the secondaries spin with the body: their terms are not the main node's
}
