// The fully integrated brick (solver/elements/solid/hex8_full.cpp: Isolid 12, 14, 17, 18) on hand-built nodes
// and groups. Expected values come from closed-form kinematics and linear elasticity, computed here without
// the kernel's helpers. Units are consistent but arbitrary except in the steel time-step case (mm, s, tonne).
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "kernel_test_util.hpp"
#include "solver/elements/element_groups.hpp"
#include "solver/model/geometry.hpp"

using namespace radx::solver;

namespace {

using radx::test::elastic;
using radx::test::make_nodes;

constexpr std::size_t G = kGroupSize;
using P3 = std::array<double, 3>;
using M3 = std::array<std::array<double, 3>, 3>;

// A fully integrated group over the initial coordinates of `ns`, flags as the engine sets them for `isolid`.
BrickGroup make_group(const std::vector<std::array<int, 8>>& elems, const NodeState& ns,
                      const MaterialParams& mat, int isolid, int icpre = 0) {
  BrickGroup g;
  g.allocate(static_cast<int>(elems.size()));
  radx::model::SolidProperty prop;
  prop.isolid = isolid;
  prop.icpre = icpre;
  prop.iframe = 2;
  resolve_full_brick(prop, mat, g);
  for (std::size_t e = 0; e < elems.size(); ++e) {
    double x[8][3], vp[8];
    for (std::size_t k = 0; k < 8; ++k) {
      const auto nd = static_cast<std::size_t>(elems[e][k]);
      g.conn[k * G + e] = elems[e][k];
      x[k][0] = ns.x0[nd];
      x[k][1] = ns.y0[nd];
      x[k][2] = ns.z0[nd];
    }
    hex8_full_point_volumes(x, vp);
    double v = 0;
    for (std::size_t p = 0; p < 8; ++p) {
      g.vol0_p[p * G + e] = vp[p];
      v += vp[p];
    }
    g.vol0[e] = g.vol[e] = v;
    g.rho[e] = mat.rho0;
  }
  return g;
}

std::vector<P3> assemble(const BrickGroup& g, std::size_t n_nodes) {
  std::vector<P3> f(n_nodes, P3{0, 0, 0});
  for (std::size_t e = 0; e < static_cast<std::size_t>(g.count); ++e)
    for (std::size_t k = 0; k < 8; ++k)
      for (std::size_t d = 0; d < 3; ++d)
        f[static_cast<std::size_t>(g.conn[k * G + e])][d] += g.nodal_force[(k * 3 + d) * G + e];
  return f;
}

// The 7-element distorted patch of test_hex8.cpp (docs/theory/verification.md 13): unit cube, 8 interior
// nodes 8-15.
std::vector<P3> patch_points() {
  return {{0, 0, 0},
          {1, 0, 0},
          {1, 1, 0},
          {0, 1, 0},
          {0, 0, 1},
          {1, 0, 1},
          {1, 1, 1},
          {0, 1, 1},
          {0.249, 0.342, 0.192},
          {0.826, 0.288, 0.288},
          {0.850, 0.649, 0.263},
          {0.273, 0.750, 0.230},
          {0.320, 0.186, 0.643},
          {0.677, 0.305, 0.683},
          {0.788, 0.693, 0.644},
          {0.165, 0.745, 0.702}};
}
const std::vector<std::array<int, 8>> kPatch = {{8, 9, 10, 11, 12, 13, 14, 15}, {0, 1, 2, 3, 8, 9, 10, 11},
                                                {12, 13, 14, 15, 4, 5, 6, 7},   {0, 4, 5, 1, 8, 12, 13, 9},
                                                {3, 2, 6, 7, 11, 10, 14, 15},   {0, 3, 7, 4, 8, 11, 15, 12},
                                                {1, 5, 6, 2, 9, 13, 14, 10}};

std::vector<P3> cube(double a) {
  return {{0, 0, 0}, {a, 0, 0}, {a, a, 0}, {0, a, 0}, {0, 0, a}, {a, 0, a}, {a, a, a}, {0, a, a}};
}
const std::vector<std::array<int, 8>> kCube = {{0, 1, 2, 3, 4, 5, 6, 7}};

}  // namespace

TEST_CASE("fully integrated brick patch test: a linear field on the distorted patch", "[brick][full]") {
  // Deformed geometry x = F X (F = I + A), velocities v = B x, dt1 = 1e-3. Every Gauss point of every element
  // sees exactly L = B and V0_p / V_p = 1 / det F, so each point's stress is the same closed form
  //   sigma = 2 G dev(sym B dt1) - K (1/det F - 1) I,
  // with or without constant pressure (the point and element volume ratios are equal), and every interior
  // node is in equilibrium: the 2x2x2 rule integrates det J grad N of a trilinear brick exactly.
  // Tolerance 1e-9 relative: round-off only (coordinates of size 1, strains of 1e-3).
  const MaterialParams mat = elastic(2e5, 0.3, 1.0);
  const M3 A = {{{2e-3, 1e-3, -0.5e-3}, {0.7e-3, -1e-3, 0.4e-3}, {0.2e-3, 0.3e-3, 1.5e-3}}};
  const M3 B = {{{0.3, 0.1, -0.2}, {0.25, -0.4, 0.15}, {-0.05, 0.2, 0.5}}};
  const double dt1 = 1e-3;
  auto pts = patch_points();
  NodeState ns = make_nodes(pts);
  for (std::size_t k = 0; k < pts.size(); ++k) {
    double x[3];
    for (std::size_t a = 0; a < 3; ++a)
      x[a] = pts[k][a] + A[a][0] * pts[k][0] + A[a][1] * pts[k][1] + A[a][2] * pts[k][2];
    ns.x[k] = x[0], ns.y[k] = x[1], ns.z[k] = x[2];
    ns.vx[k] = B[0][0] * x[0] + B[0][1] * x[1] + B[0][2] * x[2];
    ns.vy[k] = B[1][0] * x[0] + B[1][1] * x[1] + B[1][2] * x[2];
    ns.vz[k] = B[2][0] * x[0] + B[2][1] * x[1] + B[2][2] * x[2];
  }
  const double detF = (1 + A[0][0]) * ((1 + A[1][1]) * (1 + A[2][2]) - A[1][2] * A[2][1]) -
                      A[0][1] * (A[1][0] * (1 + A[2][2]) - A[1][2] * A[2][0]) +
                      A[0][2] * (A[1][0] * A[2][1] - (1 + A[1][1]) * A[2][0]);
  const double tr = (B[0][0] + B[1][1] + B[2][2]) * dt1;
  const double p = mat.bulk * (1.0 / detF - 1.0);
  const std::array<double, 6> expect = {
      2 * mat.shear * (B[0][0] * dt1 - tr / 3) - p, 2 * mat.shear * (B[1][1] * dt1 - tr / 3) - p,
      2 * mat.shear * (B[2][2] * dt1 - tr / 3) - p, mat.shear * (B[0][1] + B[1][0]) * dt1,
      mat.shear * (B[1][2] + B[2][1]) * dt1,        mat.shear * (B[2][0] + B[0][2]) * dt1};
  double scale = 0;
  for (double s : expect) scale = std::max(scale, std::abs(s));
  CycleInfo cyc;
  cyc.dt1 = dt1;
  for (const int isolid : {14, 17, 18, 12}) {
    INFO("Isolid " << isolid);
    BrickGroup g = make_group(kPatch, ns, mat, isolid);
    g.corot = false;  // point stresses in global axes, comparable with the closed form
    hex8_full_forces(g, ns, mat, cyc);
    for (std::size_t e = 0; e < kPatch.size(); ++e)
      for (std::size_t q = 0; q < 8; ++q)
        for (std::size_t m = 0; m < 6; ++m) {
          INFO("element " << e << " point " << q << " component " << m);
          CHECK(std::abs(g.sig_p[(q * 6 + m) * G + e] - expect[m]) < 1e-9 * scale);
        }
    // The assumed strains of 14 and 18 are exact for a linear field (their extra terms act on the hourglass
    // part of the velocity only), so the stresses above hold; their force operators (the transpose, with
    // modes dropped from the shear and Poisson terms added) do not integrate a constant stress to zero at the
    // interior nodes of a distorted patch, so the force balance is checked for the plain 12 and 17 only.
    const bool plain = isolid == 12 || isolid == 17;
    const auto f = assemble(g, pts.size());
    // Force scale: stress times a face area of the patch (~1).
    for (std::size_t k = 8; k < 16 && plain; ++k)
      for (std::size_t d = 0; d < 3; ++d) CHECK(std::abs(f[k][d]) < 1e-9 * scale);
    // The same in the co-rotational frame (14 and 18 impose it): the element mean in global axes.
    BrickGroup gc = make_group(kPatch, ns, mat, isolid);
    gc.corot = true;
    hex8_full_forces(gc, ns, mat, cyc);
    for (std::size_t e = 0; e < kPatch.size(); ++e)
      for (std::size_t m = 0; m < 6; ++m) CHECK(std::abs(gc.sig[m * G + e] - expect[m]) < 1e-9 * scale);
    const auto fc = assemble(gc, pts.size());
    for (std::size_t k = 8; k < 16 && plain; ++k)
      for (std::size_t d = 0; d < 3; ++d) CHECK(std::abs(fc[k][d]) < 1e-9 * scale);
  }
}

TEST_CASE("fully integrated brick: a 90 degree rigid rotation carries the stress without strain",
          "[brick][full]") {
  // A pre-stressed cube turned by 90 degrees about z in 90 steps: the velocity of each step is the exact
  // angular velocity omega x x at the current geometry, the geometry then turned exactly. In the
  // co-rotational frame L is skew at every point, so D = 0 and the stress in the frame never changes: the
  // global stress must end as Q sigma0 Q^T (sxx <-> syy swapped, sxy -> -sxy) and the forces stay those of
  // the rotated stress. Tolerance 1e-10 relative: round-off of 90 frame constructions.
  const MaterialParams mat = elastic(2e5, 0.3, 1.0);
  auto pts = cube(1.0);
  NodeState ns = make_nodes(pts);
  BrickGroup g = make_group(kCube, ns, mat, 14);
  // Deviatoric (trace 0): LAW1 takes the pressure from the volume ratio, which a rigid motion keeps at 0.
  const double s0[6] = {100.0, -70.0, -30.0, 15.0, 0.0, 0.0};
  for (std::size_t q = 0; q < 8; ++q)
    for (std::size_t m = 0; m < 6; ++m) g.sig_p[(q * 6 + m) * G] = s0[m];
  const int steps = 90;
  const double dth = std::numbers::pi / 2 / steps;
  const double dt1 = 1e-3, w = dth / dt1;
  CycleInfo cyc;
  cyc.dt1 = dt1;
  double e_start = 0;
  for (int n = 0; n <= steps; ++n) {
    const double th = n * dth;
    for (std::size_t k = 0; k < 8; ++k) {
      const double X = pts[k][0] - 0.5, Y = pts[k][1] - 0.5;
      ns.x[k] = 0.5 + std::cos(th) * X - std::sin(th) * Y;
      ns.y[k] = 0.5 + std::sin(th) * X + std::cos(th) * Y;
      ns.vx[k] = -w * (ns.y[k] - 0.5);
      ns.vy[k] = w * (ns.x[k] - 0.5);
      ns.vz[k] = 0;
    }
    hex8_full_forces(g, ns, mat, cyc);
    if (n == 0) e_start = g.e_int[0];
  }
  CHECK(std::abs(g.sig[0 * G] - s0[1]) < 1e-10 * 100);  // sxx <- syy
  CHECK(std::abs(g.sig[1 * G] - s0[0]) < 1e-10 * 100);  // syy <- sxx
  CHECK(std::abs(g.sig[2 * G] - s0[2]) < 1e-10 * 100);
  CHECK(std::abs(g.sig[3 * G] + s0[3]) < 1e-10 * 100);  // sxy -> -sxy
  for (std::size_t q = 0; q < 8; ++q)
    for (std::size_t m = 0; m < 6; ++m) CHECK(std::abs(g.sig_p[(q * 6 + m) * G] - s0[m]) < 1e-10 * 100);
  // A rigid motion does no work on the stress: no internal energy booked.
  CHECK(std::abs(g.e_int[0] - e_start) < 1e-10 * 100);
}

TEST_CASE("fully integrated brick time step and nodal stiffness", "[brick][full]") {
  // Steel cube of 10 mm at rest (docs/theory/elements.md 4.4, 4.5): dx = V / max face area = a,
  // dt = a / (c (qb + sqrt(1 + qb^2))), c = sqrt((K + 4G/3) / rho0), k = rho V / (4 dt^2) per node.
  const MaterialParams mat = elastic(210000.0, 0.3, 7.85e-9);
  NodeState ns = make_nodes(cube(10.0));
  BrickGroup g = make_group(kCube, ns, mat, 14);
  CycleInfo cyc;
  cyc.dt1 = 1e-7;
  hex8_full_forces(g, ns, mat, cyc);
  const double c = std::sqrt((mat.bulk + 4.0 * mat.shear / 3.0) / mat.rho0);
  const double dt = 10.0 / (c * (0.05 + std::sqrt(1.0 + 0.05 * 0.05)));
  CHECK(std::abs(g.dt[0] / dt - 1.0) < 1e-12);
  const double k = 7.85e-9 * 1000.0 / (4.0 * dt * dt);
  CHECK(std::abs(g.k_nodal[0] / k - 1.0) < 1e-12);
}

TEST_CASE("fully integrated brick: constant pressure avoids volumetric locking", "[brick][full]") {
  // A cube of side 2 (natural = physical coordinates, centred) given the bending displacement
  // u_x = s x y (s = 1e-6) in one cycle (x^n = X + u, v = u / dt1). At the Gauss points (x, y = +-1/sqrt 3)
  //   eps_xx = s y, gamma_xy = s x: e:e = (2/3) s^2/3 + 2 (s/2)^2/3 = 7 s^2 / 18, (tr eps)^2 = s^2 / 3,
  // and the energy booked in the cycle is 1/2 sum_p V_p sigma : eps (V_p = 1):
  //   per-point pressure (Icpre 0):    E0 = 8 G 7 s^2/18 + 8 K s^2 / 6
  //   constant pressure (Icpre 1):     E1 = 8 G 7 s^2/18   (the mean of tr eps is zero)
  //   with the assumed shear (14):     gamma_xy averages to 0 over each zeta layer: E = 8 G (2/9) s^2.
  // At nu = 0.4999 (K / G = 5000) E0 is 2144 times E1: the element locks unless the pressure is constant.
  // Tolerance 1e-4 relative: the geometric nonlinearity of a strain of 1e-6 and the second-order volume
  // change of the mode (both O(s)).
  const double s = 1e-6;
  auto pts = cube(2.0);
  for (auto& p : pts)
    for (double& c : p) c -= 1.0;
  for (const double nu : {0.3, 0.4999}) {
    const MaterialParams mat = elastic(1000.0, nu, 1.0);
    const double Gm = mat.shear, K = mat.bulk;
    const double e_dev = 8.0 * Gm * 7.0 * s * s / 18.0;
    const double e_vol = 8.0 * K * s * s / 6.0;
    NodeState ns = make_nodes(pts);
    const double dt1 = 1.0;
    for (std::size_t k = 0; k < 8; ++k) {
      const double u = s * pts[k][0] * pts[k][1];
      ns.x[k] += u;
      ns.vx[k] = u / dt1;
    }
    CycleInfo cyc;
    cyc.dt1 = dt1;
    struct Case {
      int isolid, icpre;
      bool shear_avg;
      double expect;
    };
    for (const Case cs : {Case{17, 3, false, e_dev + e_vol}, Case{17, 1, false, e_dev},
                          Case{14, 1, true, 8.0 * Gm * 2.0 * s * s / 9.0}}) {
      INFO("nu " << nu << " Isolid " << cs.isolid << " Icpre " << cs.icpre);
      BrickGroup g = make_group(kCube, ns, mat, cs.isolid, cs.icpre);
      g.corot = false;
      g.strain = cs.shear_avg ? BrickGroup::FullStrain::Asqbi : BrickGroup::FullStrain::Plain;
      g.coupled = false;
      g.qb = 0;  // no bulk viscosity: the mode is slow (v = 1e-6), and q would only add O(qb c) damping work
      g.qa = 0;
      hex8_full_forces(g, ns, mat, cyc);
      CHECK(std::abs(g.e_int[0] / cs.expect - 1.0) < 1e-4);
    }
  }
}

TEST_CASE("fully integrated brick: degenerate pentahedron and inverted element", "[brick][full]") {
  // A /BRICK with node 4 = node 1 and node 8 = node 5 (the pentahedra of the QA deck PA6): interior Gauss
  // points keep det J > 0, the volume is the prism's (1/2 for a unit prism) and a rigid translation gives no
  // force. An inverted element (nodes 5-8 below 1-4) stops with dt = 0 and a non-positive volume.
  const MaterialParams mat = elastic(2e5, 0.3, 1.0);
  std::vector<P3> pts = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
  NodeState ns = make_nodes(pts);
  for (std::size_t k = 0; k < 6; ++k) ns.vx[k] = 1.0;
  BrickGroup g = make_group({{0, 1, 2, 0, 3, 4, 5, 3}}, ns, mat, 14);
  CHECK(std::abs(g.vol0[0] - 0.5) < 1e-14);
  CycleInfo cyc;
  cyc.dt1 = 1e-3;
  hex8_full_forces(g, ns, mat, cyc);
  // Round-off: E (2e5) times the machine epsilon on gradients of size 1.
  for (std::size_t r = 0; r < 24; ++r) CHECK(std::abs(g.nodal_force[r * G]) < 1e-9);
  CHECK(g.dt[0] > 0);

  auto c = cube(1.0);
  NodeState nc = make_nodes(c);
  BrickGroup gi = make_group(kCube, nc, mat, 17);
  for (std::size_t k = 4; k < 8; ++k) nc.z[k] = -1.0;
  hex8_full_forces(gi, nc, mat, cyc);
  CHECK(gi.dt[0] == 0.0);
  CHECK(gi.vol[0] <= 0.0);
}

TEST_CASE("assumed-strain bricks: closed-form bending stiffness of one element", "[brick][full]") {
  // A cube of side 2 (natural = physical coordinates, centred) bent in one cycle: u_a = s x_a x_b (s = 1e-6),
  // x^n = X + u, v = u / dt1, for each of the six ordered pairs (a, b): the bending of a beam along a in the
  // plane a-b, whose in-element part is the hourglass mode of that plane. Isolid 14 drops the mode from the
  // shear of the plane; Isolid 18 averages the shear of the plane over the four points sharing the natural
  // coordinate normal to it (the plane's own mean). Both then add the Poisson term -nu/(1-nu) eps_aa to the
  // in-plane transverse strain, so every point is in plane strain with sigma_bb = 0: sigma_aa = E' eps_aa,
  // E' = E / (1 - nu^2), eps_aa = s x_b. The energy of the cycle 1/2 sum_p V_p sigma : eps (V_p = 1, x_b^2 =
  // 1/3) is E' s^2 (8/6) = 4 E' s^2 / 3, the bending stiffness E' I of a plane-strain beam, in all six
  // modes. The plain 2x2x2 element (17, Icpre 3) adds the shear s^2 x_a^2 G.
  // Tolerance 1e-4 relative: the geometric nonlinearity of a strain of 1e-6 (O(s)) and the volume update.
  const double s = 1e-6;
  auto pts = cube(2.0);
  for (auto& p : pts)
    for (double& c : p) c -= 1.0;
  for (const double nu : {0.0, 0.25, 0.3}) {
    const MaterialParams mat = elastic(1000.0, nu, 1.0);
    const double e_bend = 4.0 * mat.young / (1.0 - nu * nu) * s * s / 3.0;
    struct Case {
      int isolid, icpre;
      double expect;
    };
    const double e_plain =
        e_bend * (1.0 - nu * nu) * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu)) +
        8.0 * mat.shear * s * s / 6.0;  // eps = (s y, 0, 0) (uniaxial strain) + gamma = s x
    for (const Case cs : {Case{14, 0, e_bend}, Case{18, 0, e_bend}, Case{17, 3, e_plain}})
      for (std::size_t a = 0; a < 3; ++a)
        for (std::size_t b = 0; b < 3; ++b) {
          if (a == b) continue;
          INFO("nu " << nu << " Isolid " << cs.isolid << " u_" << a << " = s x_" << a << " x_" << b);
          NodeState ns = make_nodes(pts);
          for (std::size_t k = 0; k < 8; ++k) {
            const double u = s * pts[k][a] * pts[k][b];
            (a == 0 ? ns.x : a == 1 ? ns.y : ns.z)[k] += u;
            (a == 0 ? ns.vx : a == 1 ? ns.vy : ns.vz)[k] = u;  // dt1 = 1
          }
          CycleInfo cyc;
          cyc.dt1 = 1.0;
          BrickGroup g = make_group(kCube, ns, mat, cs.isolid, cs.icpre);
          g.corot = false;
          g.qa = g.qb = 0;  // no bulk viscosity (its damping work is not part of the closed form)
          hex8_full_forces(g, ns, mat, cyc);
          CHECK(std::abs(g.e_int[0] / cs.expect - 1.0) < 1e-4);
        }
  }
}

TEST_CASE("fully integrated brick: time step of a degenerate brick (S8Z length)", "[brick][full]") {
  // The unit prism of the PA6 pentahedra (node 4 = node 1, node 8 = node 5): x = (1+xi)(1-eta)/4,
  // y = (1+xi)(1+eta)/4, z = (1+zeta)/2, so det J = (1+xi)/16 and the smallest point volume is
  // (1 - 1/sqrt 3)/16. Centre directions g_xi = (1/4, 1/4, 0), g_eta = (-1/4, 1/4, 0), g_zeta = (0, 0, 1/2):
  // the largest mid-section 4 |g x g| is sqrt(2)/2. Length 8 V_p,min / A_mid = (1 - 1/sqrt 3) / sqrt 2 =
  // 0.299, shorter than the one-point V / max face area = 0.5 / sqrt 2 = 0.354. At rest dt = l / (c (qb +
  // sqrt(1 + qb^2))).
  const MaterialParams mat = elastic(2e5, 0.3, 1e-8);
  std::vector<P3> pts = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
  NodeState ns = make_nodes(pts);
  CycleInfo cyc;
  cyc.dt1 = 1e-9;
  const double len = (1.0 - 1.0 / std::sqrt(3.0)) / std::sqrt(2.0);
  const double c = std::sqrt((mat.bulk + 4.0 * mat.shear / 3.0) / mat.rho0);
  for (const int isolid : {14, 18}) {
    BrickGroup g = make_group({{0, 1, 2, 0, 3, 4, 5, 3}}, ns, mat, isolid);
    hex8_full_forces(g, ns, mat, cyc);
    // Round-off only: the formula is evaluated in closed form.
    CHECK(std::abs(g.dt[0] / (len / (c * (0.05 + std::sqrt(1.0 + 0.05 * 0.05)))) - 1.0) < 1e-12);
  }
}

TEST_CASE("Isolid 18 with LAW1: S8E's hourglass viscosity in closed form", "[brick][full]") {
  // A centred cube of side 2 (J_d = 8, so every H term is 8; gamma_jk = m_jk / 8) with the velocity v_z =
  // s m3_k (the xi-eta hourglass mode): q(z, m3) = s, T = cv s, N(z, m3) = (h11 + h22) T = 16 cv s, power
  // 16 cv s^2 with cv = 0.0025 rho c V^(1/3) = 0.005 rho c. Booked as hourglass energy over the cycle:
  // e_hg = dt1 16 cv s^2. A linear velocity field (no hourglass part) dissipates nothing.
  // Tolerance 1e-9 relative: the only geometry change is dt1 s (1e-9) of the side.
  const MaterialParams mat = elastic(2e5, 0.25, 1e-8);
  constexpr int m3[8] = {1, -1, 1, -1, 1, -1, 1, -1};
  const double s = 1.0, dt1 = 1e-9;
  for (const bool hourglass : {true, false}) {
    auto pts = cube(2.0);
    for (auto& p : pts)
      for (double& c : p) c -= 1.0;
    NodeState ns = make_nodes(pts);
    for (std::size_t k = 0; k < 8; ++k) ns.vz[k] = hourglass ? s * m3[k] : s * pts[k][0];
    BrickGroup g = make_group(kCube, ns, mat, 18);
    REQUIRE(g.s8e_visc);
    CycleInfo cyc;
    cyc.dt1 = dt1;
    hex8_full_forces(g, ns, mat, cyc);
    const double cv = 0.0025 * mat.rho0 * mat.c_solid * 2.0;
    if (hourglass)
      CHECK(std::abs(g.e_hg[0] / (dt1 * 16.0 * cv * s * s) - 1.0) < 1e-9);
    else
      CHECK(std::abs(g.e_hg[0]) < 1e-12 * dt1 * 16.0 * cv * s * s);
  }
}

TEST_CASE("Isolid 18 with LAW1: S8E's viscosity damps a uniform strain rate on a warped brick",
          "[brick][full]") {
  // OpenRadioss's S8E projects its hourglass rates with gamma_jk = m_jk / 8 - bc_k . (m_j . x) (no 1/8 on the
  // projection, hex8_full.cpp), so a linear velocity field is damped on a brick that is not a parallelepiped.
  // The centred cube of side 2 with z_k += eps m3_k keeps bc, J and V (m3 is orthogonal to xi, eta, zeta) and
  // gets m3 . x = (0, 0, 8 eps). With v_z = s z (a uniform strain rate): q(z, m3) = s eps - 8 eps s = -7 eps
  // s, N(z, m3) = (h11 + h22) cv q = 16 cv q, e_hg = dt1 16 cv 49 eps^2 s^2. Flanagan-Belytschko's gamma
  // would give 0. Tolerance 1e-6 relative: the geometry moves by dt1 s (1e-9) of the side in the cycle.
  const MaterialParams mat = elastic(2e5, 0.25, 1e-8);
  constexpr int m3[8] = {1, -1, 1, -1, 1, -1, 1, -1};
  const double s = 1.0, dt1 = 1e-9, eps = 0.1;
  auto pts = cube(2.0);
  for (auto& p : pts)
    for (double& c : p) c -= 1.0;
  for (std::size_t k = 0; k < 8; ++k) pts[k][2] += eps * m3[k];
  NodeState ns = make_nodes(pts);
  for (std::size_t k = 0; k < 8; ++k) ns.vz[k] = s * pts[k][2];
  BrickGroup g = make_group(kCube, ns, mat, 18);
  REQUIRE(g.s8e_visc);
  CycleInfo cyc;
  cyc.dt1 = dt1;
  hex8_full_forces(g, ns, mat, cyc);
  const double cv = 0.0025 * mat.rho0 * mat.c_solid * 2.0;
  const double expected = dt1 * 16.0 * cv * 49.0 * eps * eps * s * s;
  CHECK(std::abs(g.e_hg[0] / expected - 1.0) < 1e-6);
}
