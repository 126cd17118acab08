// Shell kernels (solver/elements/shell/shell_bt4.cpp, solver/elements/shell/shell_c0_tri3.cpp) on node states
// and groups built by hand, against values derived here from the formulas of docs/theory/elements.md
// (1.2-1.8, 2, 4.1, 4.2, 4.5, 6.4) and the closed-form cases of docs/theory/verification.md 13. Each check
// says what its tolerance means. "Round-off" is 1e-12 relative to the natural scale of the quantity (a few
// thousand ulps).
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <span>
#include <vector>

#include "kernel_test_util.hpp"
#include "solver/elements/element_groups.hpp"
#include "solver/engine/node_state.hpp"
#include "solver/materials/material_point.hpp"
#include "test_util.hpp"

using radx::model::Material;
using radx::model::MaterialLaw;
using radx::solver::CycleInfo;
using radx::solver::kGroupSize;
using radx::solver::make_material_params;
using radx::solver::MaterialParams;
using radx::solver::NodeState;
using radx::solver::ShellGroup;

namespace {

using radx::test::elastic;
using radx::test::make_nodes;

constexpr std::size_t G = kGroupSize;
using Vec3 = std::array<double, 3>;

// Elements given by 0-based node indices; triangles use the first three.
ShellGroup make_group(const std::vector<std::array<int, 4>>& conn, double t, int points,
                      bool triangle = false) {
  ShellGroup g;
  g.allocate(static_cast<int>(conn.size()), points);
  g.triangle = triangle;
  for (std::size_t e = 0; e < conn.size(); ++e) {
    for (std::size_t k = 0; k < 4; ++k) g.conn[k * G + e] = conn[e][k];
    g.t0[e] = g.thick[e] = t;
  }
  return g;
}

void run(ShellGroup& g, const NodeState& s, const MaterialParams& mat, double dt1) {
  CycleInfo cyc;
  cyc.dt1 = dt1;
  cyc.dt2 = dt1;
  if (g.triangle)
    radx::solver::shell_c0_tri3_forces(g, s, mat, cyc);
  else
    radx::solver::shell_bt4_forces(g, s, mat, cyc);
}

// Sum of the group's nodal_force per node: [node][fx fy fz mx my mz], as the engine assembles it.
std::vector<std::array<double, 6>> assemble(const ShellGroup& g, std::size_t nnodes) {
  std::vector<std::array<double, 6>> f(nnodes, std::array<double, 6>{});
  const int npe = g.triangle ? 3 : 4;
  for (int i = 0; i < g.count; ++i)
    for (int k = 0; k < npe; ++k) {
      const auto node =
          static_cast<std::size_t>(g.conn[static_cast<std::size_t>(k) * G + static_cast<std::size_t>(i)]);
      for (std::size_t d = 0; d < 6; ++d)
        f[node][d] += g.nodal_force[(static_cast<std::size_t>(k) * 6 + d) * G + static_cast<std::size_t>(i)];
    }
  return f;
}

double sig(const ShellGroup& g, int point, int comp, int e) {
  return g.sig[(static_cast<std::size_t>(point) * 5 + static_cast<std::size_t>(comp)) * G +
               static_cast<std::size_t>(e)];
}

// Resultant storage of N = 0 (shell_section.hpp): [8][G] FOR xx yy xy yz zx, MOM xx yy xy.
double resultant(const ShellGroup& g, int comp, int e) {
  return g.sig[static_cast<std::size_t>(comp) * G + static_cast<std::size_t>(e)];
}

// In-plane axis e1 of a flat quad in the xy plane, written again from docs/theory/elements.md 1.2 (the
// bisector of g1 and g2 rotated by -90 degrees), to bring the element's stresses to global axes.
std::array<double, 2> quad_e1(const NodeState& s, const std::array<int, 4>& c) {
  auto X = [&](int k) { return std::array<double, 2>{s.x[c[k]], s.y[c[k]]}; };
  const auto x1 = X(0), x2 = X(1), x3 = X(2), x4 = X(3);
  const double g1x = x2[0] - x1[0] + x3[0] - x4[0], g1y = x2[1] - x1[1] + x3[1] - x4[1];
  const double g2x = x3[0] - x2[0] + x4[0] - x1[0], g2y = x3[1] - x2[1] + x4[1] - x1[1];
  const double r = std::hypot(g1x, g1y) / std::hypot(g2x, g2y);
  const double ex = g1x + r * g2y, ey = g1y - r * g2x;  // g2 x e3 with e3 = +z
  const double n = std::hypot(ex, ey);
  return {ex / n, ey / n};
}

// Local (sxx, syy, sxy) in the frame whose first axis is (c, s) -> global (sxx, syy, sxy).
std::array<double, 3> to_global(double c, double s, double lxx, double lyy, double lxy) {
  return {c * c * lxx + s * s * lyy - 2 * c * s * lxy, s * s * lxx + c * c * lyy + 2 * c * s * lxy,
          c * s * (lxx - lyy) + (c * c - s * s) * lxy};
}

// The membrane patch of docs/theory/verification.md 13: 0.24 x 0.12
// plate, interior nodes 5..8 (0-based 4..7).
const std::vector<Vec3> kPatchNodes = {{0, 0, 0},       {0.24, 0, 0},    {0.24, 0.12, 0}, {0, 0.12, 0},
                                       {0.04, 0.02, 0}, {0.18, 0.03, 0}, {0.16, 0.08, 0}, {0.08, 0.08, 0}};
const std::vector<std::array<int, 4>> kPatchQuads = {
    {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}, {4, 5, 6, 7}};

// u = 1e-3 (x + y/2), v = 1e-3 (y + x/2) imposed in one step of dt: velocity u/dt.
void impose_patch_field(NodeState& s, double dt) {
  for (std::size_t k = 0; k < s.n; ++k) {
    s.vx[k] = 1e-3 * (s.x[k] + 0.5 * s.y[k]) / dt;
    s.vy[k] = 1e-3 * (s.y[k] + 0.5 * s.x[k]) / dt;
    s.vz[k] = 0;
  }
}

using radx::test::close;

// Rotation matrix about a unit axis by angle a (Rodrigues).
std::array<Vec3, 3> rotation(Vec3 n, double a) {
  const double l = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for (double& v : n) v /= l;
  const double c = std::cos(a), s = std::sin(a), C = 1 - c;
  return {{{c + n[0] * n[0] * C, n[0] * n[1] * C - n[2] * s, n[0] * n[2] * C + n[1] * s},
           {n[1] * n[0] * C + n[2] * s, c + n[1] * n[1] * C, n[1] * n[2] * C - n[0] * s},
           {n[2] * n[0] * C - n[1] * s, n[2] * n[1] * C + n[0] * s, c + n[2] * n[2] * C}}};
}

Vec3 apply(const std::array<Vec3, 3>& q, const Vec3& v) {
  return {q[0][0] * v[0] + q[0][1] * v[1] + q[0][2] * v[2], q[1][0] * v[0] + q[1][1] * v[1] + q[1][2] * v[2],
          q[2][0] * v[0] + q[2][1] * v[1] + q[2][2] * v[2]};
}

Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

double max_abs_force(const ShellGroup& g) {
  double m = 0;
  for (double v : g.nodal_force) m = std::max(m, std::abs(v));
  return m;
}

}  // namespace

TEST_CASE("BT4 membrane patch: constant strain exact on a distorted mesh", "[shell]") {
  // docs/theory/verification.md 13: E = 1e6, nu = 0.25, t = 0.001, sigma_x = sigma_y = 1333.33, tau = 400.
  // The linear field is imposed in one step (dt1 = dt) on X^n = initial geometry: the one-point rates of
  // a bilinear quad are exact for linear velocity fields and the second-order correction of 1.3 is zero
  // for in-plane motion, so the increments equal the imposed strain to round-off (1e-9 relative is 1e5
  // times round-off; any formulation error would be at least 1e-4).
  const double young = 1e6, nu = 0.25, t = 0.001, dt = 1e-4;
  const MaterialParams mat = elastic(young, nu, 1000.0);
  const double a11 = young / (1 - nu * nu);
  const double sx = a11 * (1e-3 + nu * 1e-3), tau = young / (2 * (1 + nu)) * 1e-3;
  REQUIRE(sx == Approx(1333.3333333).epsilon(1e-9));
  REQUIRE(tau == Approx(400.0).epsilon(1e-12));
  for (int points : {0, 3}) {
    INFO("through-thickness points " << points);
    NodeState s = make_nodes(kPatchNodes);
    impose_patch_field(s, dt);
    ShellGroup g = make_group(kPatchQuads, t, points);
    run(g, s, mat, dt);
    double e_int = 0;
    for (int e = 0; e < g.count; ++e) {
      const auto e1 = quad_e1(s, kPatchQuads[static_cast<std::size_t>(e)]);
      for (int p = 0; p < std::max(points, 1); ++p) {
        const double lxx = points == 0 ? resultant(g, 0, e) : sig(g, p, 0, e);
        const double lyy = points == 0 ? resultant(g, 1, e) : sig(g, p, 1, e);
        const double lxy = points == 0 ? resultant(g, 2, e) : sig(g, p, 2, e);
        const auto gs = to_global(e1[0], e1[1], lxx, lyy, lxy);
        CHECK(close(gs[0], sx, 1e-9));
        CHECK(close(gs[1], sx, 1e-9));
        CHECK(close(gs[2], tau, 1e-9));
      }
      // No hourglass content in a linear field (gamma is orthogonal to x and y): zero to round-off of
      // the internal energy.
      CHECK(std::abs(g.e_hg[static_cast<std::size_t>(e)]) <= 1e-12 * g.e_int[static_cast<std::size_t>(e)]);
      e_int += g.e_int[static_cast<std::size_t>(e)];
    }
    // Equivalent strain rate (1.3), no filter (Fcut = 0): sqrt(4/3 (exx^2 + eyy^2 + exx eyy + gxy^2/4))/dt;
    // thickness output (1.8, elastic plane stress): t (1 - nu/(1 - nu) (dexx + deyy)).
    const double rate = std::sqrt(4.0 / 3.0 * 3.25e-6) / dt;
    for (int e = 0; e < g.count; ++e) {
      CHECK(close(g.rate[static_cast<std::size_t>(e)], rate, 1e-9));
      CHECK(close(g.thick[static_cast<std::size_t>(e)], t * (1 - nu / (1 - nu) * 2e-3), 1e-12));
    }
    // 1.5 with FOR_old = 0: E = 1/2 sigma : eps V (engineering shear).
    const double volume = 0.24 * 0.12 * t;
    CHECK(close(e_int, 0.5 * (2 * sx * 1e-3 + tau * 1e-3) * volume, 1e-9));

    // Equilibrium: constant stress gives zero resultant at every interior node; the force scale is
    // sigma t L = 1333 * 0.001 * 0.12 = 0.16, round-off 1e-12 of it.
    const auto f = assemble(g, s.n);
    const double fscale = sx * t * 0.12;
    for (std::size_t node = 4; node < 8; ++node)
      for (std::size_t d = 0; d < 6; ++d) CHECK(std::abs(f[node][d]) <= 1e-12 * fscale);
    // Boundary: the internal force at a corner is t sigma . (half of each adjacent edge times its outward
    // normal); node 2 = (0.24, 0): right edge 0.12 long with n = (1, 0), bottom edge 0.24 with n = (0, -1).
    // nodal_force is the force added to the node, i.e. minus the internal force.
    const double fx_int = t * (sx * 0.06 - tau * 0.12), fy_int = t * (tau * 0.06 - sx * 0.12);
    CHECK(close(f[1][0], -fx_int, 1e-9));
    CHECK(close(f[1][1], -fy_int, 1e-9));
    double sum[3] = {0, 0, 0};
    for (const auto& fn : f)
      for (int d = 0; d < 3; ++d) sum[d] += fn[static_cast<std::size_t>(d)];
    for (double v : sum) CHECK(std::abs(v) <= 1e-12 * fscale);  // self-equilibrated
  }
}

TEST_CASE("Shell strain-rate filter of 6.1", "[shell]") {
  // alpha = min(1, 2 pi Fcut dt1): one step from rate 0 gives alpha times the element rate; a second step
  // with the same increments gives (1 - (1 - alpha)^2) times it.
  Material m;
  m.law = MaterialLaw::JohnsonCook;
  m.rho = 1000;
  m.young = 1e6;
  m.poisson = 0.25;
  m.a = 1e9;  // never yields
  m.c = 0.01;
  m.eps_dot_0 = 1;
  m.f_cut = 1000;
  const MaterialParams mat = make_material_params(m);
  const double dt = 1e-4, alpha = 2 * std::numbers::pi * 1000 * dt;
  NodeState s = make_nodes(kPatchNodes);
  impose_patch_field(s, dt);
  ShellGroup g = make_group(kPatchQuads, 0.001, 3);
  const double rate = std::sqrt(4.0 / 3.0 * 3.25e-6) / dt;
  run(g, s, mat, dt);
  for (int e = 0; e < g.count; ++e) CHECK(close(g.rate[static_cast<std::size_t>(e)], alpha * rate, 1e-9));
  run(g, s, mat, dt);
  for (int e = 0; e < g.count; ++e)
    CHECK(close(g.rate[static_cast<std::size_t>(e)], (1 - (1 - alpha) * (1 - alpha)) * rate, 1e-9));
}

TEST_CASE("BT4 rigid-body motions give no strain and no force", "[shell]") {
  // The distorted patch turned into a general plane in space. Translation and rotation about the normal
  // are exact rigid motions of the convected frame: every increment is zero to round-off. The reference
  // scale is the force a strain of |omega| dt would give, E t L |omega| dt.
  const double young = 210000, nu = 0.3, t = 1.0, dt = 1e-7;
  const MaterialParams mat = elastic(young, nu, 7.85e-9);
  const auto q = rotation({0.3, -0.7, 0.5}, 0.9);
  std::vector<Vec3> xyz;
  for (const auto& p : kPatchNodes) {
    auto r = apply(q, {p[0] * 100, p[1] * 100, 0});  // mm
    xyz.push_back({r[0] + 5, r[1] - 3, r[2] + 1});
  }
  const Vec3 normal = apply(q, {0, 0, 1});
  const Vec3 centre = {xyz[4][0], xyz[4][1], xyz[4][2]};
  const double omega = 50.0;  // rad/s: omega dt = 5e-6
  const double fscale = young * t * 24 * omega * dt;

  SECTION("translation") {
    NodeState s = make_nodes(xyz);
    for (std::size_t k = 0; k < s.n; ++k) s.vx[k] = 3.0, s.vy[k] = -2.0, s.vz[k] = 7.0;
    ShellGroup g = make_group(kPatchQuads, t, 3);
    run(g, s, mat, dt);
    CHECK(max_abs_force(g) <= 1e-12 * fscale);
    for (double v : g.sig) CHECK(std::abs(v) <= 1e-12 * young * omega * dt);
  }
  SECTION("rotation about the normal") {
    NodeState s = make_nodes(xyz);
    const Vec3 w = {omega * normal[0], omega * normal[1], omega * normal[2]};
    for (std::size_t k = 0; k < s.n; ++k) {
      const auto v = cross(w, {s.x[k] - centre[0], s.y[k] - centre[1], s.z[k] - centre[2]});
      s.vx[k] = v[0], s.vy[k] = v[1], s.vz[k] = v[2];
      s.wx[k] = w[0], s.wy[k] = w[1], s.wz[k] = w[2];
    }
    ShellGroup g = make_group(kPatchQuads, t, 3);
    run(g, s, mat, dt);
    CHECK(max_abs_force(g) <= 1e-12 * fscale);
    for (double v : g.sig) CHECK(std::abs(v) <= 1e-12 * young * omega * dt);
    for (int e = 0; e < g.count; ++e) CHECK(g.e_hg[static_cast<std::size_t>(e)] == Approx(0).margin(1e-30));
  }
  SECTION("rotation about an in-plane axis: only the second-order membrane term of 1.3") {
    // Square in the xy plane, omega = W (cos 30, sin 30, 0) in the plane: v = omega x r has only
    // vz = wx (y - 5) - wy (x - 5), nodal rotation omega. Transverse shear (dvz/dx + ry, dvz/dy - rx) and
    // curvatures are 0 exactly (uniform rotation); the membrane correction of 1.3 (rectangle) gives
    // dexx = -dt1^2 (dvz/dx)^2 = -(wy dt)^2, deyy = -(wx dt)^2, dgxy = 0.
    NodeState s = make_nodes({{0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {0, 10, 0}});
    const double wx = omega * std::cos(std::numbers::pi / 6), wy = omega * std::sin(std::numbers::pi / 6);
    for (std::size_t k = 0; k < s.n; ++k) {
      s.vz[k] = wx * (s.y[k] - 5) - wy * (s.x[k] - 5);
      s.wx[k] = wx, s.wy[k] = wy;
    }
    ShellGroup g = make_group({{0, 1, 2, 3}}, t, 0);
    run(g, s, mat, dt);
    const double dexx = -(wy * dt) * (wy * dt), deyy = -(wx * dt) * (wx * dt);
    const double a11 = young / (1 - nu * nu);
    CHECK(close(resultant(g, 0, 0), a11 * (dexx + nu * deyy), 1e-9));
    CHECK(close(resultant(g, 1, 0), a11 * (nu * dexx + deyy), 1e-9));
    for (int c : {2, 3, 4, 5, 6, 7}) CHECK(std::abs(resultant(g, c, 0)) <= 1e-12 * young * omega * dt);

    // On the distorted tilted patch the increments are purely of second order: halving dt divides every
    // stress by 4 (to round-off), i.e. no first-order (spurious) strain from a rigid rotation.
    const Vec3 axis = apply(q, {1, 0, 0});
    const Vec3 w = {omega * axis[0], omega * axis[1], omega * axis[2]};
    NodeState s2 = make_nodes(xyz);
    for (std::size_t k = 0; k < s2.n; ++k) {
      const auto v = cross(w, {s2.x[k] - centre[0], s2.y[k] - centre[1], s2.z[k] - centre[2]});
      s2.vx[k] = v[0], s2.vy[k] = v[1], s2.vz[k] = v[2];
      s2.wx[k] = w[0], s2.wy[k] = w[1], s2.wz[k] = w[2];
    }
    ShellGroup g1 = make_group(kPatchQuads, t, 0), g2 = make_group(kPatchQuads, t, 0);
    run(g1, s2, mat, dt);
    run(g2, s2, mat, 0.5 * dt);
    const double sscale = young * (omega * dt) * (omega * dt);
    for (int e = 0; e < g1.count; ++e)
      for (int c = 0; c < 8; ++c) {
        const double a = resultant(g1, c, e), b = resultant(g2, c, e);
        CHECK(std::abs(a) <= 10 * sscale);
        CHECK(std::abs(a - 4 * b) <= 1e-9 * sscale);
      }
  }
}

TEST_CASE("BT4 and C0 element time steps and nodal stiffness", "[shell]") {
  // docs/theory/elements.md 4.1, 4.2, 4.5; g.dt is the step before the /DT scale 0.9. Units mm, t, s, MPa.
  const double young = 210000, rho = 7.85e-9, t = 1.0;
  const MaterialParams mat = elastic(young, 0.3, rho);
  const double c = std::sqrt(young / rho);
  SECTION("10 mm square: L = side") {
    NodeState s = make_nodes({{0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {0, 10, 0}});
    ShellGroup g = make_group({{0, 1, 2, 3}}, t, 0);
    run(g, s, mat, 0.0);
    CHECK(close(g.dt[0], 10 / c, 1e-12));
    CHECK(close(0.9 * g.dt[0], 1.740e-6, 5e-4));  // the OpenRadioss run, printed to 4 digits
    // K = 0.81 * 1/2 * A t E / L^2 with A = 100, L = 10.
    CHECK(close(g.k_nodal[0], 0.81 * 0.5 * 100 * t * young / 100, 1e-12));
  }
  SECTION("membrane damping Dm scales the step by sqrt(1 + Dm^2) - Dm") {
    NodeState s = make_nodes({{0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {0, 10, 0}});
    ShellGroup g = make_group({{0, 1, 2, 3}}, t, 0);
    g.props.dm = 0.1;
    run(g, s, mat, 0.0);
    CHECK(close(g.dt[0], 10 / c * (std::sqrt(1.01) - 0.1), 1e-12));
  }
  SECTION("trapezoid: L = area / longest diagonal") {
    // Sides 10, 10.77, 2, 10.77, A = 60, diagonals sqrt(136) = 11.66: L^2 = 3600/136 > shortest side^2 = 4.
    NodeState s = make_nodes({{0, 0, 0}, {10, 0, 0}, {6, 10, 0}, {4, 10, 0}});
    ShellGroup g = make_group({{0, 1, 2, 3}}, t, 0);
    run(g, s, mat, 0.0);
    const double l = std::sqrt(3600.0 / 136.0);
    CHECK(close(l, 5.145, 1e-4));
    CHECK(close(g.dt[0], l / c, 1e-12));
    CHECK(close(0.9 * g.dt[0], 0.8953e-6, 1e-4));  // the OpenRadioss run
  }
  SECTION("triangle: L = 2A / longest side") {
    // (0,0), (10,0), (3,8): A = 40, longest side |(3,8)-(10,0)| = sqrt(113).
    NodeState s = make_nodes({{0, 0, 0}, {10, 0, 0}, {3, 8, 0}});
    ShellGroup g = make_group({{0, 1, 2, 2}}, t, 0, true);
    run(g, s, mat, 0.0);
    const double l = 80.0 / std::sqrt(113.0);
    CHECK(close(g.dt[0], l / c, 1e-12));
    CHECK(close(g.k_nodal[0], 0.81 * 0.81 * 40 * t * mat.a11 / (l * l), 1e-12));
  }
  SECTION("a deleted element gives no force and an infinite step") {
    NodeState s = make_nodes({{0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {0, 10, 0}});
    for (std::size_t k = 0; k < s.n; ++k) s.vx[k] = s.x[k];
    ShellGroup g = make_group({{0, 1, 2, 3}}, t, 0);
    g.off[0] = 0;
    run(g, s, mat, 1e-7);
    CHECK(std::isinf(g.dt[0]));
    CHECK(max_abs_force(g) == 0.0);
    CHECK(g.e_int[0] == 0.0);
  }
}

TEST_CASE("BT4 pure bending: M = D kappa", "[shell]") {
  // Square a = 10, rotations linear about the centre: ry = kx (x - a/2), rx = -ky (y - a/2), plus a twist
  // ry += kt/2 (y - a/2), rx -= kt/2 (x - a/2); vz = 0. Then kappa = (kx, ky, kt) exactly, transverse
  // shear is zero (sum of ry and rx over the nodes is zero) and no hourglass mode is excited. Moments per
  // unit length: Mxx = D (kx + nu ky), Myy = D (nu kx + ky), Mxy = D (1 - nu)/2 kt, D = E t^3/(12(1-nu^2)).
  // N = 0 integrates the resultant exactly; N = 5 uses the moment weights of 1.4, which are exact for a
  // stress linear through the thickness (elastic bending): the error is round-off, not the 12 % a plain
  // trapezoid on sigma z would make (sum w_i zeta_i^2 = 3/32 instead of 1/12).
  const double young = 210000, nu = 0.3, t = 1.0, a = 10.0, dt = 1e-6;
  const MaterialParams mat = elastic(young, nu, 7.85e-9);
  const double kx = 2e-4, ky = -1e-4, kt = 3e-4;  // curvature increments (1/mm) in one step
  const double d = young * t * t * t / (12 * (1 - nu * nu));
  const double mxx = d * (kx + nu * ky), myy = d * (nu * kx + ky), mxy = d * (1 - nu) / 2 * kt;
  NodeState s = make_nodes({{0, 0, 0}, {a, 0, 0}, {a, a, 0}, {0, a, 0}});
  for (std::size_t k = 0; k < s.n; ++k) {
    const double xc = s.x[k] - a / 2, yc = s.y[k] - a / 2;
    s.wy[k] = (kx * xc + 0.5 * kt * yc) / dt;
    s.wx[k] = (-ky * yc - 0.5 * kt * xc) / dt;
  }
  for (int points : {0, 5}) {
    INFO("through-thickness points " << points);
    ShellGroup g = make_group({{0, 1, 2, 3}}, t, points);
    run(g, s, mat, dt);
    double m[3];
    if (points == 0) {
      for (int c = 0; c < 3; ++c) m[c] = resultant(g, 5 + c, 0) * t * t;
    } else {
      const double wm[5] = {-5.0 / 96, -1.0 / 16, 0, 1.0 / 16, 5.0 / 96};
      for (int c = 0; c < 3; ++c) {
        m[c] = 0;
        for (int p = 0; p < 5; ++p) m[c] += wm[p] * sig(g, p, c, 0) * t * t;
      }
    }
    CHECK(close(m[0], mxx, 1e-12));
    CHECK(close(m[1], myy, 1e-12));
    CHECK(close(m[2], mxy, 1e-12));
    // Nodal moments (1.6): local e2 moment at node k = Mxx PXk + Mxy PYk; node 1 PX = -a/2, PY = -a/2.
    // nodal_force holds minus the internal moment; e1, e2 = x, y for this square.
    const double my1 = mxx * (-a / 2) + mxy * (-a / 2), mx1 = -(myy * (-a / 2) + mxy * (-a / 2));
    CHECK(close(g.nodal_force[4 * G], -my1, 1e-12));
    CHECK(close(g.nodal_force[3 * G], -mx1, 1e-12));
    CHECK(std::abs(g.nodal_force[0]) <= 1e-12 * d * kx);  // no membrane force
    CHECK(std::abs(g.e_hg[0]) <= 1e-12 * g.e_int[0]);     // plain h of the rotations: zero up to round-off
    // Element rate (1.3): sqrt(t^2/9 (kx^2 + ky^2 + kx ky + kt^2/4)) / dt.
    CHECK(close(g.rate[0], std::sqrt(t * t / 9 * (kx * kx + ky * ky + kx * ky + 0.25 * kt * kt)) / dt, 1e-9));
    // Bending energy 1/2 M . kappa A (from zero moments).
    CHECK(close(g.e_int[0], 0.5 * (mxx * kx + myy * ky + mxy * kt) * a * a, 1e-12));
  }
}

TEST_CASE("BT4 hourglass: energy only from the hourglass mode, none for a degenerate quad", "[shell]") {
  const double young = 210000, nu = 0.3, rho = 7.85e-9, t = 1.0, a = 10.0, dt = 1e-7;
  const MaterialParams mat = elastic(young, nu, rho);
  SECTION("in-plane mode on a free square") {
    // vx = delta h, h = (1, -1, 1, -1): no membrane strain (u13 = u24 = 0), gamma = h on a square.
    // One cycle: qx = 4 delta, Sx = Km qx, Hx = Sx + Cm |qx| qx, E_hg = dt1 Hx qx (1.7), Km = E Hm/8 t dt1,
    // Cm = 12.5 rho Hm t sqrt(A); nodal force (local = global here) Hx gamma_k.
    const double delta = 0.3;
    NodeState s = make_nodes({{0, 0, 0}, {a, 0, 0}, {a, a, 0}, {0, a, 0}});
    const double h[4] = {1, -1, 1, -1};
    for (std::size_t k = 0; k < 4; ++k) s.vx[k] = delta * h[k];
    ShellGroup g = make_group({{0, 1, 2, 3}}, t, 3);
    const double hm = g.props.hm;
    const double km = young * hm / 8 * t * dt, cm = 12.5 * rho * hm * t * a;
    double e_expected = 0, sx = 0, work = 0;
    for (int cycle = 0; cycle < 3; ++cycle) {
      run(g, s, mat, dt);
      const double qx = 4 * delta;
      sx += km * qx;
      const double hx = sx + cm * std::abs(qx) * qx;
      e_expected += dt * hx * qx;
      CHECK(close(g.nodal_force[0], -hx, 1e-12));
      CHECK(close(g.nodal_force[6 * G], hx, 1e-12));
      // The hourglass energy is the work of the new hourglass force over the step (rectangle rule).
      for (std::size_t k = 0; k < 4; ++k) work += -g.nodal_force[k * 6 * G] * s.vx[k] * dt;
    }
    CHECK(g.e_int[0] == 0.0);  // exactly: every increment is zero
    CHECK(close(g.e_hg[0], e_expected, 1e-12));
    CHECK(close(g.e_hg[0], work, 1e-12));
    CHECK(g.e_hg[0] > 0);
  }
  SECTION("out-of-plane and rotational modes") {
    // vz = delta h and rx = ry = rho_r h: qz = 4 delta, rxh = ryh = 4 rho_r.
    // Kf = E Hf SHF/(24(1+nu)) t^3 dt/(B1 + B2), B1 = B2 = a^2/2; Cf = 12.5 rho Hf sqrt(SHF/(3(1+nu))) t^2;
    // Cr = 0.90211 rho Hr t^2 A. E_hg = dt (Hz qz + 2 Mh rh), Mh = Cr |rh| rh.
    const double delta = 0.2, rr = 0.05;
    NodeState s = make_nodes({{0, 0, 0}, {a, 0, 0}, {a, a, 0}, {0, a, 0}});
    const double h[4] = {1, -1, 1, -1};
    for (std::size_t k = 0; k < 4; ++k) s.vz[k] = delta * h[k], s.wx[k] = rr * h[k], s.wy[k] = rr * h[k];
    ShellGroup g = make_group({{0, 1, 2, 3}}, t, 3);
    run(g, s, mat, dt);
    const double shf = 5.0 / 6.0, hf = 0.01, hr = 0.01;
    const double kf = young * hf * shf / (24 * (1 + nu)) * t * t * t * dt / (a * a);
    const double cf = 12.5 * rho * hf * std::sqrt(shf / (3 * (1 + nu))) * t * t;
    const double cr = 0.90211 * rho * hr * t * t * a * a;
    const double qz = 4 * delta, rh = 4 * rr;
    const double hz = kf * qz + cf * qz * qz, mh = cr * rh * rh;
    CHECK(close(g.e_hg[0], dt * (hz * qz + 2 * mh * rh), 1e-12));
    CHECK(close(g.nodal_force[2 * G], -hz, 1e-12));  // node 1 fz
    CHECK(close(g.nodal_force[3 * G], -mh, 1e-12));  // node 1 mx, h1 = +1
    CHECK(close(g.nodal_force[9 * G], mh, 1e-12));   // node 2 mx, h2 = -1
    CHECK(close(g.nodal_force[8 * G], hz, 1e-12));   // node 2 fz, gamma2 = -1
  }
  SECTION("degenerate quad (n3 = n4): no hourglass") {
    NodeState s = make_nodes({{0, 0, 0}, {a, 0, 0}, {0.3 * a, 0.8 * a, 0}});
    const double v[3][6] = {{0.3, -0.1, 0.2, 0.01, -0.02, 0.0},
                            {-0.2, 0.4, -0.3, 0.02, 0.03, 0.0},
                            {0.1, 0.2, 0.5, -0.04, 0.01, 0.0}};
    for (std::size_t k = 0; k < 3; ++k) {
      s.vx[k] = v[k][0], s.vy[k] = v[k][1], s.vz[k] = v[k][2];
      s.wx[k] = v[k][3], s.wy[k] = v[k][4];
    }
    ShellGroup g = make_group({{0, 1, 2, 2}}, t, 3);
    for (int cycle = 0; cycle < 3; ++cycle) run(g, s, mat, dt);
    CHECK(g.e_hg[0] == 0.0);
    for (double x : g.hg) CHECK(x == 0.0);
    CHECK(g.e_int[0] > 0);
  }
}

TEST_CASE("C0 triangle membrane patch: constant strain on every triangle", "[shell]") {
  // The quad patch of docs/theory/verification.md 13 cut into 10 triangles (diagonal 1-3 of each quad), same
  // field in one step. The Ish3n 2 correction of section 2 adds, in each triangle's own frame (e1 along
  // side 12), the second-order terms dexx = Hxx - Hyx^2/2, deyy = Hyy - Hxy^2/2, dgxy = Hxy + Hyx - (Hyx
  // Hyy + Hxy Hxx)/2 (H = displacement gradient in that frame; derived by hand from T11 = dt1/2 dvy/dx,
  // T22 = dt1/2 dvx/dy). Checks: (1) each triangle's local stress equals that closed form to 1e-9; (2)
  // rotated to global axes it equals 1333.33 / 400 to 5e-4 (the size of the second-order term, |H|/2); (3)
  // interior nodes are in equilibrium to 1e-3 of the force scale (the second-order terms differ between
  // triangles whose frames differ, by up to |H|/2 = 5e-4 relative to sigma).
  const double young = 1e6, nu = 0.25, t = 0.001, dt = 1e-4;
  const MaterialParams mat = elastic(young, nu, 1000.0);
  const double a11 = young / (1 - nu * nu), a12 = nu * a11, gm = young / (2 * (1 + nu));
  std::vector<std::array<int, 4>> tris;
  for (const auto& q : kPatchQuads) {
    tris.push_back({q[0], q[1], q[2], q[2]});
    tris.push_back({q[0], q[2], q[3], q[3]});
  }
  NodeState s = make_nodes(kPatchNodes);
  impose_patch_field(s, dt);
  ShellGroup g = make_group(tris, t, 3, true);
  run(g, s, mat, dt);
  const double hg[2][2] = {{1e-3, 0.5e-3}, {0.5e-3, 1e-3}};  // global H (du/dx, du/dy; dv/dx, dv/dy)
  for (int e = 0; e < g.count; ++e) {
    const auto& c = tris[static_cast<std::size_t>(e)];
    double ex = s.x[c[1]] - s.x[c[0]], ey = s.y[c[1]] - s.y[c[0]];
    const double n = std::hypot(ex, ey);
    ex /= n, ey /= n;
    // H in the local frame: R H R^T with rows e1 = (ex, ey), e2 = (-ey, ex).
    const double r[2][2] = {{ex, ey}, {-ey, ex}};
    double hl[2][2] = {{0, 0}, {0, 0}};
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j)
        for (int k = 0; k < 2; ++k)
          for (int l = 0; l < 2; ++l) hl[i][j] += r[i][k] * hg[k][l] * r[j][l];
    const double dxx = hl[0][0] - 0.5 * hl[1][0] * hl[1][0];
    const double dyy = hl[1][1] - 0.5 * hl[0][1] * hl[0][1];
    const double dxy = hl[0][1] + hl[1][0] - 0.5 * (hl[1][0] * hl[1][1] + hl[0][1] * hl[0][0]);
    for (int p = 0; p < 3; ++p) {
      CHECK(close(sig(g, p, 0, e), a11 * dxx + a12 * dyy, 1e-9, 1e-9 * 1333.3));
      CHECK(close(sig(g, p, 1, e), a12 * dxx + a11 * dyy, 1e-9, 1e-9 * 1333.3));
      CHECK(close(sig(g, p, 2, e), gm * dxy, 1e-9, 1e-9 * 1333.3));  // floor: the local shear can be ~0
      const auto gs = to_global(ex, ey, sig(g, p, 0, e), sig(g, p, 1, e), sig(g, p, 2, e));
      CHECK(close(gs[0], 1333.3333333, 5e-4));
      CHECK(close(gs[1], 1333.3333333, 5e-4));
      CHECK(close(gs[2], 400.0, 5e-4 * 1333.3333333 / 400.0));
    }
  }
  const auto f = assemble(g, s.n);
  const double fscale = 1333.33 * t * 0.12;
  for (std::size_t node = 4; node < 8; ++node)
    for (std::size_t d = 0; d < 6; ++d) CHECK(std::abs(f[node][d]) <= 1e-3 * fscale);

  SECTION("Ish3n 1: without T11 and T22 the increments are the first-order rates, exact to 1e-9") {
    // The field has vz = 0, so T1 = T2 = 0 too: dexx = Hxx, deyy = Hyy, dgxy = Hxy + Hyx in each frame.
    NodeState s1 = make_nodes(kPatchNodes);
    impose_patch_field(s1, dt);
    ShellGroup g1 = make_group(tris, t, 3, true);
    g1.props.ish3n = 1;
    run(g1, s1, mat, dt);
    for (int e = 0; e < g1.count; ++e) {
      const auto& c = tris[static_cast<std::size_t>(e)];
      double ex = s1.x[c[1]] - s1.x[c[0]], ey = s1.y[c[1]] - s1.y[c[0]];
      const double n = std::hypot(ex, ey);
      ex /= n, ey /= n;
      const double r[2][2] = {{ex, ey}, {-ey, ex}};
      double hl[2][2] = {{0, 0}, {0, 0}};
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j)
          for (int k = 0; k < 2; ++k)
            for (int l = 0; l < 2; ++l) hl[i][j] += r[i][k] * hg[k][l] * r[j][l];
      const double dxx = hl[0][0], dyy = hl[1][1], dxy = hl[0][1] + hl[1][0];
      CHECK(close(sig(g1, 0, 0, e), a11 * dxx + a12 * dyy, 1e-9, 1e-9 * 1333.3));
      CHECK(close(sig(g1, 0, 1, e), a12 * dxx + a11 * dyy, 1e-9, 1e-9 * 1333.3));
      CHECK(close(sig(g1, 0, 2, e), gm * dxy, 1e-9, 1e-9 * 1333.3));
    }
  }

  SECTION("small strain: the second-order terms vanish and the patch is exact to 1e-9") {
    // Same field scaled by 1e-6: the second-order terms are 1e-6 of the first-order ones.
    NodeState s2 = make_nodes(kPatchNodes);
    impose_patch_field(s2, dt / 1e-6);
    ShellGroup g2 = make_group(tris, t, 3, true);
    run(g2, s2, mat, dt);
    for (int e = 0; e < g2.count; ++e) {
      const auto& c = tris[static_cast<std::size_t>(e)];
      const double ex = s2.x[c[1]] - s2.x[c[0]], ey = s2.y[c[1]] - s2.y[c[0]], n = std::hypot(ex, ey);
      const auto gs = to_global(ex / n, ey / n, sig(g2, 0, 0, e), sig(g2, 0, 1, e), sig(g2, 0, 2, e));
      CHECK(close(gs[0], 1333.3333333e-6, 2e-6));
      CHECK(close(gs[1], 1333.3333333e-6, 2e-6));
      CHECK(close(gs[2], 400.0e-6, 2e-6 * 1333.3 / 400));
    }
    const auto f2 = assemble(g2, s2.n);
    for (std::size_t node = 4; node < 8; ++node)
      for (std::size_t d = 0; d < 6; ++d) CHECK(std::abs(f2[node][d]) <= 2e-6 * 1e-6 * fscale);
  }
}

TEST_CASE("C0 triangle rigid-body motion and bending", "[shell]") {
  const double young = 210000, nu = 0.3, t = 1.0, dt = 1e-7;
  const MaterialParams mat = elastic(young, nu, 7.85e-9);
  SECTION("translation and rotation about the normal of a tilted triangle: no force") {
    const auto q = rotation({1, 2, 3}, 0.7);
    std::vector<Vec3> xyz = {apply(q, {0, 0, 0}), apply(q, {12, 1, 0}), apply(q, {4, 9, 0})};
    const Vec3 normal = apply(q, {0, 0, 1});
    const double omega = 40;
    NodeState s = make_nodes(xyz);
    for (std::size_t k = 0; k < 3; ++k) {
      const auto v = cross({omega * normal[0], omega * normal[1], omega * normal[2]}, xyz[k]);
      s.vx[k] = v[0] + 2, s.vy[k] = v[1] - 1, s.vz[k] = v[2] + 4;
      s.wx[k] = omega * normal[0], s.wy[k] = omega * normal[1], s.wz[k] = omega * normal[2];
    }
    ShellGroup g = make_group({{0, 1, 2, 2}}, t, 3, true);
    run(g, s, mat, dt);
    // Translation is exact. The in-plane rotation (H = omega dt [[0, -1], [1, 0]] in any in-plane frame)
    // meets the Ish3n 2 terms: dexx = -Hyx^2/2 = deyy = -(omega dt)^2/2, dgxy = 0, a second-order
    // compression sigma = -E/(1 - nu) (omega dt)^2/2 in both directions (relative round-off 1e-6 of it:
    // the first-order terms cancel to ~1e-21 against 8e-12).
    const double de = -0.5 * (omega * dt) * (omega * dt);
    const double sig2 = young / (1 - nu) * de;
    for (int p = 0; p < 3; ++p) {
      CHECK(close(sig(g, p, 0, 0), sig2, 1e-6));
      CHECK(close(sig(g, p, 1, 0), sig2, 1e-6));
      for (int c : {2, 3, 4}) CHECK(std::abs(sig(g, p, c, 0)) <= 1e-6 * std::abs(sig2));
    }
    CHECK(max_abs_force(g) <= std::abs(sig2) * t * 12);
  }
  SECTION("uniform curvature: M = D kappa") {
    // Triangle (0,0), (10,0), (3,8); ry = kx x, rx = -ky y (linear): the curvature increments of section 2
    // are exactly (kx, ky, 0). The rotations also give a transverse shear (not zero on average), which
    // does not enter the moments.
    const double kx = 2e-4, ky = -1e-4;
    NodeState s = make_nodes({{0, 0, 0}, {10, 0, 0}, {3, 8, 0}});
    for (std::size_t k = 0; k < 3; ++k) s.wy[k] = kx * s.x[k] / dt, s.wx[k] = -ky * s.y[k] / dt;
    ShellGroup g = make_group({{0, 1, 2, 2}}, t, 0, true);
    run(g, s, mat, dt);
    const double d = young * t * t * t / (12 * (1 - nu * nu));
    CHECK(close(resultant(g, 5, 0) * t * t, d * (kx + nu * ky), 1e-12));
    CHECK(close(resultant(g, 6, 0) * t * t, d * (nu * kx + ky), 1e-12));
    CHECK(std::abs(resultant(g, 7, 0)) <= 1e-12 * d * kx);
  }
}

TEST_CASE("Shell energy: accumulated internal energy equals the work of the nodal forces", "[shell]") {
  // Work of the internal forces over step n (X^{n-1} -> X^n at velocity v^{n-1/2}), trapezoid rule:
  // W += 1/2 (f_int^{n-1} + f_int^n) . v^{n-1/2} dt1, f_int = -nodal_force, moments times the angular
  // velocities. 1.5 books 1/2 (FOR_old + FOR_new) . de A t with de = B(X^n) v dt1, so with a frozen
  // geometry and no velocity that enters a second-order term, both sums are the same numbers added in
  // another order: equal to round-off, whatever the material does (Johnson-Cook with yielding here).
  // Hourglass forces are switched off (Hm = Hf = Hr = 0): their energy is booked with the new force only
  // (rectangle rule, checked in the hourglass test) and would not match a trapezoid.
  Material jc;
  jc.law = MaterialLaw::JohnsonCook;
  jc.rho = 7.85e-9;
  jc.young = 210000;
  jc.poisson = 0.3;
  jc.a = 200;
  jc.b = 400;
  jc.n = 0.5;
  const MaterialParams mat_jc = make_material_params(jc);
  const MaterialParams mat_el = elastic(210000, 0.3, 7.85e-9);
  const double t = 1.0, dt = 1e-6;
  std::vector<Vec3> xyz;
  for (const auto& p : kPatchNodes) xyz.push_back({p[0] * 100, p[1] * 100, 0});

  // Velocity fields: which parts are switched on.
  struct Field {
    bool in_plane = true, out_of_plane = false;
  };
  auto velocity = [](NodeState& s, int cycle, Field f) {
    const double ph = 0.7 * cycle;
    for (std::size_t k = 0; k < s.n; ++k) {
      const double x = s.x0[k], y = s.y0[k];
      s.vx[k] = f.in_plane ? 5000 * std::sin(0.1 * x + 0.05 * y + ph) + 2000 * std::cos(0.3 * y) : 0.0;
      s.vy[k] = f.in_plane ? -4000 * std::cos(0.07 * x - 0.13 * y + ph) : 0.0;
      s.vz[k] = f.out_of_plane ? 3000 * std::sin(0.2 * x + 0.1 * y - ph) : 0.0;
      s.wx[k] = 4000 * std::cos(0.15 * x + ph);
      s.wy[k] = -3000 * std::sin(0.1 * y - 0.4 * ph);
      s.wz[k] = f.out_of_plane ? 200 * std::sin(0.05 * x) : 0.0;
    }
  };
  auto work_step = [](const std::vector<std::array<double, 6>>& f_old,
                      const std::vector<std::array<double, 6>>& f, const NodeState& s, double dt1) {
    double w = 0;
    for (std::size_t k = 0; k < s.n; ++k) {
      const double v[6] = {s.vx[k], s.vy[k], s.vz[k], s.wx[k], s.wy[k], s.wz[k]};
      for (std::size_t d = 0; d < 6; ++d) w += -0.5 * (f_old[k][d] + f[k][d]) * v[d] * dt1;
    }
    return w;
  };
  auto total = [](std::span<const double> v, int n) {
    double x = 0;
    for (int e = 0; e < n; ++e) x += v[static_cast<std::size_t>(e)];
    return x;
  };
  // Runs 12 cycles; cycle n > 0 first moves the nodes with v^{n-1/2} (if `moving`), then computes the
  // forces on X^n. Returns the work of the internal forces and the largest strain increment (rate dt1).
  struct Result {
    double work = 0, de_max = 0;
  };
  auto simulate = [&](ShellGroup& g, NodeState& s, const MaterialParams& mat, Field field, bool moving) {
    Result r;
    std::vector<std::array<double, 6>> f_old(s.n, std::array<double, 6>{});
    for (int cycle = 0; cycle < 12; ++cycle) {
      const double dt1 = cycle == 0 ? 0.0 : dt;
      if (cycle > 0) {
        velocity(s, cycle, field);
        if (moving)
          for (std::size_t k = 0; k < s.n; ++k)
            s.x[k] += dt * s.vx[k], s.y[k] += dt * s.vy[k], s.z[k] += dt * s.vz[k];
      }
      run(g, s, mat, dt1);
      const auto f = assemble(g, s.n);
      r.work += work_step(f_old, f, s, dt1);
      f_old = f;
      for (int e = 0; e < g.count; ++e)
        r.de_max = std::max(r.de_max, g.rate[static_cast<std::size_t>(e)] * dt1);
    }
    return r;
  };
  std::vector<std::array<int, 4>> tris;
  for (const auto& q : kPatchQuads) {
    tris.push_back({q[0], q[1], q[2], q[2]});
    tris.push_back({q[0], q[2], q[3], q[3]});
  }

  for (bool triangle : {false, true})
    for (int points : {0, 5}) {
      const bool plastic = points > 0;
      const MaterialParams& mat = plastic ? mat_jc : mat_el;
      const auto& conn = triangle ? tris : kPatchQuads;
      INFO((triangle ? "C0 triangles, " : "BT4 quads, ")
           << (plastic ? "Johnson-Cook, 5 points" : "LAW1, resultant"));
      {
        // Frozen geometry: equal to round-off. The triangles' Ish3n 2 correction also acts on in-plane
        // velocities, so they get rotations only (curvature and transverse shear, which exercise the
        // transpose of the shear-rotation terms of section 2).
        NodeState s = make_nodes(xyz);
        ShellGroup g = make_group(conn, t, points, triangle);
        g.props.hm = g.props.hf = g.props.hr = 0;
        const Result r = simulate(g, s, mat, Field{!triangle, false}, false);
        const double e = total(g.e_int, g.count);
        CHECK(e > 0);
        if (plastic) CHECK(total(g.w_plastic, g.count) > 0);  // the points did yield
        CHECK(close(e, r.work, 1e-12));
        CHECK(total(g.e_hg, g.count) == 0.0);
      }
      {
        // Moving geometry X^{n+1} = X^n + dt v^{n+1/2}, every velocity component. The forces f^{n-1} were
        // computed on X^{n-1} while 1.5 uses B(X^n) for both halves, and the second-order terms of 1.3 / 2
        // are not in B: the two sums differ by terms of relative order |de| (the largest strain increment
        // of one step, 1e-3 here; the difference seen is below 1e-4), so the tolerance is max|de|. Booking
        // only the new stress (rectangle rule) would miss by ~1/(2 x 11 cycles) = 4 %.
        NodeState s = make_nodes(xyz);
        ShellGroup g = make_group(conn, t, points, triangle);
        g.props.hm = g.props.hf = g.props.hr = 0;
        const Result r = simulate(g, s, mat, Field{true, true}, true);
        const double e = total(g.e_int, g.count);
        INFO("E_int " << e << " work " << r.work << " max strain increment " << r.de_max);
        CHECK(e > 0);
        CHECK(close(e, r.work, r.de_max));
      }
    }
}

TEST_CASE("BT4 failure: OFF decays by 0.8 per cycle after EPS_p_max, then the element is deleted",
          "[shell]") {
  // docs/theory/elements.md 6.4: the cycle a point reaches EPS_p_max, OFF = 0.8; each next cycle OFF *= 0.8;
  // the first cycle starting with OFF < 0.1 deletes the element (OFF = 0): no force, dt = +inf, energy kept.
  Material jc;
  jc.law = MaterialLaw::JohnsonCook;
  jc.rho = 7.85e-9;
  jc.young = 210000;
  jc.poisson = 0.3;
  jc.a = 200;
  jc.b = 0;
  jc.eps_p_max = 0.01;
  const MaterialParams mat = make_material_params(jc);
  const double a = 10, dt = 1e-6;
  NodeState s = make_nodes({{0, 0, 0}, {a, 0, 0}, {a, a, 0}, {0, a, 0}});
  for (std::size_t k = 0; k < 4; ++k)
    s.vx[k] = 500.0 * s.x[k];  // 5e-4 strain per cycle in x (frozen geometry)
  ShellGroup g = make_group({{0, 1, 2, 3}}, 1.0, 3);
  std::vector<double> offs;
  int trigger = -1;
  for (int cycle = 0; cycle < 60 && g.off[0] > 0; ++cycle) {
    const double off_start = g.off[0];
    run(g, s, mat, cycle == 0 ? 0.0 : dt);
    if (trigger < 0 && g.off[0] < 1) trigger = cycle;
    if (trigger < 0) {
      // Plastic work (6.5) of a perfectly plastic point (b = 0): sigma_y eps_p A t, less half the gap
      // sigma_y - svm_old of the first yielding step, whose deps_p is below one cycle's strain 5e-4.
      const double full = 200 * g.eps_p[0] * a * a * 1.0;
      CHECK(g.w_plastic[0] <= full * (1 + 1e-12));
      CHECK(g.w_plastic[0] >= full - 100 * 5e-4 * a * a * 1.0);
    }
    if (trigger >= 0) offs.push_back(g.off[0]);
    if (g.off[0] > 0) {
      // Forces scale with OFF: the membrane force at node 2 is OFF Nxx PX2, and radial return keeps
      // |sxx| <= 2/sqrt(3) sigma_y in plane stress, so |f| <= OFF 1.1548 sigma_y t a/2.
      CHECK(std::abs(g.nodal_force[6 * G]) <= g.off[0] * 1.1548 * 200 * 1.0 * a / 2);
    } else {
      CHECK(off_start < 0.1);
    }
  }
  REQUIRE(trigger > 0);
  REQUIRE(offs.size() == 12);  // 0.8^1 .. 0.8^11, then deletion
  for (std::size_t k = 0; k < 11; ++k) CHECK(offs[k] == Approx(std::pow(0.8, static_cast<double>(k + 1))));
  CHECK(offs[11] == 0.0);
  CHECK(std::isinf(g.dt[0]));
  CHECK(max_abs_force(g) == 0.0);
  const double e_kept = g.e_int[0];
  CHECK(e_kept > 0);
  run(g, s, mat, dt);
  CHECK(g.e_int[0] == e_kept);
}

TEST_CASE("Shell cycle 0: dt1 = 0 gives zero increments", "[shell]") {
  // Every increment is rate * dt1 = 0: stresses, energies and the strain rate stay 0. The only force is
  // the viscous hourglass force, which depends on the velocity and not on dt1 (1.7): on this square
  // gamma = h, qx = sum h_k vx_k = -100, force at node 1 = Cm |qx| qx with Cm = 12.5 rho Hm t sqrt(A).
  const double rho = 7.85e-9;
  const MaterialParams mat = elastic(210000, 0.3, rho);
  NodeState s = make_nodes({{0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {0, 10, 0}});
  for (std::size_t k = 0; k < 4; ++k)
    s.vx[k] = 1000 * s.x[k] + 50.0 * (k % 2), s.vz[k] = 30 * s.y[k], s.wy[k] = 3;
  ShellGroup g = make_group({{0, 1, 2, 3}}, 1.0, 3);
  run(g, s, mat, 0.0);
  for (double v : g.sig) CHECK(v == 0.0);
  CHECK(g.e_int[0] == 0.0);
  CHECK(g.e_hg[0] == 0.0);
  CHECK(g.rate[0] == 0.0);
  CHECK(g.dt[0] > 0);
  const double cm = 12.5 * rho * 0.01 * 1.0 * 10.0, qx = -100.0;
  CHECK(close(g.nodal_force[0], -cm * std::abs(qx) * qx, 1e-12));
  for (std::size_t d = 1; d < 6; ++d) CHECK(g.nodal_force[d * G] == 0.0);
}

TEST_CASE(
    "Ismstr 1 is small strain from the start: a stretch gives E (lambda - 1), Ismstr 2 gives E ln lambda",
    "[shell]") {
  // One square shell (nu = 0, so sigma_xx = E eps_xx in plane stress) stretched along X with the nodes'
  // velocity vx = r X0 (X0 their initial x): the length grows as L0 lambda, lambda = 1 + r t. Small strain
  // sums r dt over the initial length: eps = lambda - 1 exactly. Large strain sums the rate on the geometry
  // at the start of each step, r dt / lambda_n: eps = sum_n r dt / (1 + r n dt) exactly (round-off), which is
  // ln lambda to within r dt / 2 (1 - 1 / lambda).
  const double young = 1e5, t = 0.1, r = 0.25, dt = 1e-3;
  const int steps = 2000;
  const MaterialParams mat = elastic(young, 0.0, 1000.0);
  const double lambda = 1.0 + r * steps * dt;
  for (const int ismstr : {1, 2}) {
    DYNAMIC_SECTION("Ismstr " << ismstr) {
      NodeState s = make_nodes({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
      ShellGroup g = make_group({{0, 1, 2, 3}}, t, 1);
      g.props.ismstr = ismstr;
      for (int n = 0; n < steps; ++n) {
        for (std::size_t k = 0; k < 4; ++k) s.vx[k] = r * s.x0[k];
        run(g, s, mat, dt);
        for (std::size_t k = 0; k < 4; ++k) s.x[k] += dt * s.vx[k];
      }
      REQUIRE(std::abs(s.x[1] - lambda) <= 1e-12);
      double large = 0;
      for (int n = 0; n < steps; ++n) large += r * dt / (1.0 + r * n * dt);
      const double expect = ismstr == 1 ? young * (lambda - 1.0) : young * large;
      INFO("sigma_xx " << sig(g, 0, 0, 0) << " expected " << expect);
      CHECK(close(sig(g, 0, 0, 0), expect, 1e-9));
      if (ismstr == 2)
        CHECK(close(large, std::log(lambda), 0.5 * r * dt * (1.0 - 1.0 / lambda) / std::log(lambda) * 1.01));
      CHECK(std::abs(sig(g, 0, 1, 0)) <= 1e-9 * expect);  // nu = 0: no transverse stress
    }
  }
}

TEST_CASE("BT4 hourglass vector: gamma is blind to linear fields, the plain h of Ismstr 1 is not",
          "[shell]") {
  // A trapezoid (not a parallelogram) with the linear velocity vx = x: the gamma vector of [1.7] is
  // orthogonal to every linear field, so Ismstr 2 books no hourglass energy; Ismstr 1 takes the plain
  // h = (1, -1, 1, -1), and sum h_k vx_k = 0 - 2 + 1.5 - 0.5 = -1: hourglass energy > 0.
  const MaterialParams mat = elastic(1e5, 0.3, 1000.0);
  for (const int ismstr : {1, 2}) {
    DYNAMIC_SECTION("Ismstr " << ismstr) {
      NodeState s = make_nodes({{0, 0, 0}, {2, 0, 0}, {1.5, 1, 0}, {0.5, 1, 0}});
      for (std::size_t k = 0; k < 4; ++k) s.vx[k] = s.x[k];
      ShellGroup g = make_group({{0, 1, 2, 3}}, 0.1, 1);
      g.props.ismstr = ismstr;
      run(g, s, mat, 1e-4);
      if (ismstr == 2)
        CHECK(std::abs(g.e_hg[0]) <= 1e-12 * g.e_int[0]);
      else
        CHECK(g.e_hg[0] > 1e-3 * g.e_int[0]);
    }
  }
}

TEST_CASE(
    "BT4 Ishell 4: a warped quad turning rigidly has no membrane hourglass rate, and half the "
    "second-order membrane correction of Ishell 1",
    "[shell][ishell4]") {
  // Square a x a warped by w (z = 0, w, 0, w): the frame is (x, y, z) and z2 = w. Rigid rotation omega about
  // y: v = (omega z, 0, -omega x), rotation rate ry = omega. gamma = h here (hx = hy = 0), so Ishell 1 sees
  // the membrane hourglass rate qx = sum h vx = -2 omega w; Ishell 4 adds -4 (gzx w/2) with gzx = dvz/dx =
  // -omega: qx = 0 (the b terms cancel in the sum). The membrane rate of Ishell 1 carries -dt1 (dvz/dx)^2,
  // that of Ishell 4 -dt1/2 (dvz/dx)^2 (docs/theory/elements.md 1.3, cdefo3.F IHBE 4): after one cycle
  // sigma_xx = E/(1-nu^2) dexx with dexx = -dt^2 omega^2 (Ishell 1) or -dt^2 omega^2/2 (Ishell 4),
  // sigma_yy = nu sigma_xx.
  const double young = 210000, nu = 0.3, rho = 7.85e-9, t = 1.0, a = 10.0, w = 0.8, omega = 200.0, dt = 1e-6;
  const MaterialParams mat = elastic(young, nu, rho);
  for (const int ishell : {1, 4}) {
    DYNAMIC_SECTION("Ishell " << ishell) {
      NodeState s = make_nodes({{0, 0, 0}, {a, 0, w}, {a, a, 0}, {0, a, w}});
      for (std::size_t k = 0; k < 4; ++k) {
        s.vx[k] = omega * s.z[k];
        s.vz[k] = -omega * s.x[k];
        s.wy[k] = omega;
      }
      ShellGroup g = make_group({{0, 1, 2, 3}}, t, 3);
      g.props.ishell = ishell;
      run(g, s, mat, dt);
      const double km = young * g.props.hm / 8 * t * dt;
      const double qx = ishell == 1 ? -2 * omega * w : 0.0;
      // Stored membrane hourglass force: Km qx; Ishell 4 within round-off of the terms that cancel
      // (omega w Km, times 1e-12).
      CHECK(std::abs(g.hg[0] - km * qx) <= 1e-12 * km * omega * w);
      CHECK(std::abs(g.hg[G]) <= 1e-12 * km * omega * w);
      const double dexx = -(ishell == 1 ? 1.0 : 0.5) * dt * dt * omega * omega;
      const double sxx = young / (1 - nu * nu) * dexx;
      for (int p = 0; p < 3; ++p) {
        CHECK(close(sig(g, p, 0, 0), sxx, 1e-9));       // relative round-off of a dt^2 term
        CHECK(close(sig(g, p, 1, 0), nu * sxx, 1e-9));  // plane stress, deyy = 0
      }
    }
  }
}

TEST_CASE("BT4 Ishell 4 with N > 1: the membrane hourglass force has a moment about the warp",
          "[shell][ishell4]") {
  // The warped square above with the in-plane hourglass mode vy = delta h: no strain, qy = 4 delta, Hy = Km
  // qy
  // + Cm qy^2 (1.7). cfint3.F adds mx_k -= z2/4 (Hy_1 + Hy_3) = -z2/2 Hy on every node (gamma_1 + gamma_3 =
  // 2) to the internal moments; the nodal force is minus the internal one. Ishell 1 and Ishell 4 with N = 1
  // have no such moment.
  const double young = 210000, nu = 0.3, rho = 7.85e-9, t = 1.0, a = 10.0, w = 0.8, delta = 0.3, dt = 1e-7;
  const MaterialParams mat = elastic(young, nu, rho);
  struct Case {
    int ishell, points;
    bool moment;
  };
  for (const Case c : {Case{1, 3, false}, Case{4, 3, true}, Case{4, 1, false}}) {
    DYNAMIC_SECTION("Ishell " << c.ishell << ", N " << c.points) {
      NodeState s = make_nodes({{0, 0, 0}, {a, 0, w}, {a, a, 0}, {0, a, w}});
      const double h[4] = {1, -1, 1, -1};
      for (std::size_t k = 0; k < 4; ++k) s.vy[k] = delta * h[k];
      ShellGroup g = make_group({{0, 1, 2, 3}}, t, c.points);
      g.props.ishell = c.ishell;
      g.props.n_points = c.points;
      run(g, s, mat, dt);
      const double hm = g.props.hm;
      const double km = young * hm / 8 * t * dt, cm = 12.5 * rho * hm * t * a;
      const double qy = 4 * delta, hy = km * qy + cm * qy * qy;
      const double expected = c.moment ? 0.5 * w * hy : 0.0;
      for (std::size_t k = 0; k < 4; ++k)  // round-off relative to the moment z2 Hy
        CHECK(std::abs(g.nodal_force[(k * 6 + 3) * G] - expected) <= 1e-12 * w * hy);
    }
  }
}
