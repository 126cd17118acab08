// The 20-node quadratic brick (/BRIC20): its serendipity shape functions (solver/model/hex20_shape.hpp), the
// kernel (solver/elements/solid/hex20_quadratic.cpp) on hand-built nodes and groups, a bar's wave through an
// explicit loop of the kernel alone, and the starter's reading, masses and checks. Expected values come from
// closed forms (partition of unity, finite differences, the linear field's constant strain, the bar wave
// rho c v0) computed here independently of the code under test.
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "kernel_test_util.hpp"
#include "parser/building/model_builder.hpp"
#include "solver/elements/element_groups.hpp"
#include "solver/model/hex20_shape.hpp"
#include "solver/model/masses.hpp"
#include "test_util.hpp"

using namespace radx::solver;
namespace model = radx::model;

namespace {

using radx::test::elastic;
using radx::test::make_nodes;
constexpr std::size_t G = kGroupSize;
using P3 = std::array<double, 3>;

// The 20 node positions of the box [0, a] x [0, b] x [0, c], shifted by `warp` (node k moves by
// warp * (sin(k), cos(2k), sin(3k)): a distorted but valid element).
std::vector<P3> box_nodes(double a, double b, double c, double warp = 0.0, double x0 = 0.0) {
  std::vector<P3> p;
  for (int k = 0; k < 20; ++k) {
    const double s[3] = {0.5 * (1 + model::kHex20Nat[k][0]), 0.5 * (1 + model::kHex20Nat[k][1]),
                         0.5 * (1 + model::kHex20Nat[k][2])};
    p.push_back({x0 + a * s[0] + warp * std::sin(k), b * s[1] + warp * std::cos(2.0 * k),
                 c * s[2] + warp * std::sin(3.0 * k)});
  }
  return p;
}

struct Built {
  radx::Diagnostics diags;
  model::Model model;
};

Built build(const std::string& text) {
  radx::test::TempDir dir;
  const auto path = dir.write("t_0000.rad", text);
  Built b;
  const auto deck = radx::read_starter_deck(path, b.diags);
  b.model = radx::build_model(deck, b.diags);
  return b;
}

bool has_code(const radx::Diagnostics& d, radx::Diag code) {
  for (const auto& i : d.items())
    if (i.code == code) return true;
  return false;
}

Hex20Group make_group(const NodeState& ns, const std::vector<std::array<int, 20>>& elems,
                      std::array<int, 3> rule, double rho0) {
  Hex20Group g;
  g.rule = rule;
  g.allocate(static_cast<int>(elems.size()));
  for (std::size_t e = 0; e < elems.size(); ++e) {
    double x[20][3];
    for (std::size_t k = 0; k < 20; ++k) {
      const auto n = static_cast<std::size_t>(elems[e][k]);
      g.conn[k * G + e] = elems[e][k];
      x[k][0] = ns.x0[n], x[k][1] = ns.y0[n], x[k][2] = ns.z0[n];
    }
    hex20_init_geometry(g, e, x);
    g.rho[e] = rho0;
  }
  return g;
}

}  // namespace

TEST_CASE("hex20 shape functions: partition of unity, nodal values and derivatives by finite difference",
          "[hex20]") {
  // Kronecker property at the nodes: N_a(xi_b) = delta_ab (to rounding, 1e-14).
  for (int b = 0; b < 20; ++b) {
    double N[20], dN[20][3];
    model::hex20_shape(model::kHex20Nat[b][0], model::kHex20Nat[b][1], model::kHex20Nat[b][2], N, dN);
    for (int a = 0; a < 20; ++a) CHECK(N[a] == Approx(a == b ? 1.0 : 0.0).margin(1e-14));
  }
  // At arbitrary points: sum N = 1 and sum dN = 0 (a rigid translation gives no strain), and each derivative
  // matches a central difference with h = 1e-5 (truncation error ~h^2 = 1e-10 on functions of order 1).
  const double pts[4][3] = {{0.1, -0.3, 0.7}, {-0.9, 0.2, 0.05}, {0.57, 0.57, -0.57}, {0.0, 0.0, 0.0}};
  for (const auto& p : pts) {
    double N[20], dN[20][3];
    model::hex20_shape(p[0], p[1], p[2], N, dN);
    double sum = 0, dsum[3] = {0, 0, 0};
    for (int a = 0; a < 20; ++a) {
      sum += N[a];
      for (int c = 0; c < 3; ++c) dsum[c] += dN[a][c];
    }
    CHECK(sum == Approx(1.0).margin(1e-14));
    for (double d : dsum) CHECK(d == Approx(0.0).margin(1e-13));
    const double h = 1e-5;
    for (int c = 0; c < 3; ++c) {
      double pp[3] = {p[0], p[1], p[2]}, pm[3] = {p[0], p[1], p[2]};
      pp[c] += h;
      pm[c] -= h;
      double Np[20], Nm[20], d2[20][3];
      model::hex20_shape(pp[0], pp[1], pp[2], Np, d2);
      model::hex20_shape(pm[0], pm[1], pm[2], Nm, d2);
      for (int a = 0; a < 20; ++a) CHECK(dN[a][c] == Approx((Np[a] - Nm[a]) / (2 * h)).margin(1e-9));
    }
  }
  // The volume of a box by any rule is its volume; the lumped shares sum to 1.
  double x[20][3];
  const auto p = box_nodes(2.0, 3.0, 5.0);
  for (int k = 0; k < 20; ++k)
    for (int d = 0; d < 3; ++d) x[k][d] = p[static_cast<std::size_t>(k)][static_cast<std::size_t>(d)];
  for (const auto& n :
       {std::array<int, 3>{2, 2, 2}, std::array<int, 3>{3, 3, 3}, std::array<int, 3>{2, 3, 2}}) {
    model::Hex20Rule r;
    r.n = n;
    CHECK(model::hex20_volume(x, r) == Approx(30.0).epsilon(1e-13));
  }
  double share = 0;
  for (int a = 0; a < 20; ++a) share += model::hex20_mass_share(a);
  CHECK(share == Approx(1.0).epsilon(1e-15));
}

TEST_CASE("hex20 patch test: a linear velocity field gives the same strain rate at every point", "[hex20]") {
  // A distorted element (every node moved by up to 0.08 of the 1 x 1.2 x 0.9 box) and the field v = A x:
  // the serendipity space holds every linear field, so D = sym(A) exactly at each of the 27 points, on any
  // shape. With the geometry not moved (mu = 0), LAW1's point stresses are then 2 G dev(sym A) dt1 at
  // every point, equal to rounding (1e-9 of their size).
  const auto pts = box_nodes(1.0, 1.2, 0.9, 0.08);
  NodeState ns = make_nodes(pts);
  const double A[3][3] = {{0.3, -0.2, 0.1}, {0.05, -0.4, 0.25}, {-0.15, 0.2, 0.6}};
  for (std::size_t k = 0; k < 20; ++k) {
    const double p[3] = {ns.x[k], ns.y[k], ns.z[k]};
    ns.vx[k] = A[0][0] * p[0] + A[0][1] * p[1] + A[0][2] * p[2];
    ns.vy[k] = A[1][0] * p[0] + A[1][1] * p[1] + A[1][2] * p[2];
    ns.vz[k] = A[2][0] * p[0] + A[2][1] * p[1] + A[2][2] * p[2];
  }
  std::array<int, 20> e{};
  for (int k = 0; k < 20; ++k) e[static_cast<std::size_t>(k)] = k;
  const double young = 210000.0, nu = 0.3, rho = 7.85e-9;
  const auto mat = elastic(young, nu, rho);
  auto g = make_group(ns, {e}, {3, 3, 3}, rho);
  g.qa = g.qb = 0.0;  // no bulk viscosity: the stress is the material's alone
  CycleInfo cyc;
  cyc.dt1 = 1e-6;
  hex20_forces(g, ns, mat, cyc);
  const double gmod = young / (2 * (1 + nu));
  const double tr = (A[0][0] + A[1][1] + A[2][2]) / 3.0;
  const double expect[6] = {2 * gmod * (A[0][0] - tr) * cyc.dt1,  2 * gmod * (A[1][1] - tr) * cyc.dt1,
                            2 * gmod * (A[2][2] - tr) * cyc.dt1,  gmod * (A[0][1] + A[1][0]) * cyc.dt1,
                            gmod * (A[1][2] + A[2][1]) * cyc.dt1, gmod * (A[2][0] + A[0][2]) * cyc.dt1};
  for (int p = 0; p < 27; ++p)
    for (std::size_t m = 0; m < 6; ++m)
      CHECK(g.sig_p[(static_cast<std::size_t>(p) * 6 + m) * G] == Approx(expect[m]).margin(1e-9 * 0.3));
  // A rigid translation gives no stress and no force.
  for (std::size_t k = 0; k < 20; ++k) ns.vx[k] = 1.0, ns.vy[k] = -2.0, ns.vz[k] = 0.5;
  auto g2 = make_group(ns, {e}, {2, 2, 2}, rho);
  hex20_forces(g2, ns, mat, cyc);
  for (std::size_t r = 0; r < 60; ++r) CHECK(g2.nodal_force[r * G] == Approx(0.0).margin(1e-12));
}

TEST_CASE("hex20 bar: the wave behind the front carries rho c0 v0, and the element step runs stably",
          "[hex20]") {
  // A bar of 12 elements of 10 mm along X, 10 x 10 mm, steel (nu = 0.3), laterally free, with the engine's
  // default bulk viscosity. The nodes of its x = 0 face are driven along +X at v0 = 1 m/s; at t = L / (2 c0),
  // c0 = sqrt(E / rho) the bar speed, the front is half-way: the stress of the elements well behind it is
  // -rho c0 v0 (within 10 %: the one-dimensional value, which the bar reaches once the front, a few widths
  // long, has passed; the discrete front rings behind it) and that of the elements well ahead of it is still
  // 0 (within 2 % of rho c0 v0). Run at 0.9 of the element step, the engine's default /DT scale.
  // (With nu = 0, OpenRadioss's step for this element is too long: the same bar diverges in OpenRadioss's run
  // of it at 0.9 as in radx's, docs/elements-openradioss.md 3.10.)
  const int ne = 12;
  const double a = 10.0, young = 210000.0, rho = 7.85e-9, v0 = 1000.0;  // mm, MPa, Mg/mm^3, mm/s
  std::vector<P3> pts;
  std::vector<std::array<int, 20>> elems;
  // Nodes of each element, those it shares with its neighbour merged by position.
  auto node_of = [&](const P3& p) {
    for (std::size_t k = 0; k < pts.size(); ++k)
      if (std::abs(pts[k][0] - p[0]) + std::abs(pts[k][1] - p[1]) + std::abs(pts[k][2] - p[2]) < 1e-9)
        return static_cast<int>(k);
    pts.push_back(p);
    return static_cast<int>(pts.size() - 1);
  };
  for (int e = 0; e < ne; ++e) {
    const auto p = box_nodes(a, a, a, 0.0, a * e);
    std::array<int, 20> el{};
    for (std::size_t k = 0; k < 20; ++k) el[k] = node_of(p[k]);
    elems.push_back(el);
  }
  NodeState ns = make_nodes(pts);
  const auto mat = elastic(young, 0.3, rho);
  auto g = make_group(ns, elems, {2, 2, 2}, rho);  // qa 1.1, qb 0.05
  std::vector<double> mass(pts.size(), 0.0);
  for (const auto& el : elems)
    for (int k = 0; k < 20; ++k)
      mass[static_cast<std::size_t>(el[static_cast<std::size_t>(k)])] +=
          model::hex20_mass_share(k) * rho * a * a * a;
  const double c = std::sqrt(young / rho);
  const double t_end = 0.5 * ne * a / c;
  CycleInfo cyc;
  double t = 0, dt = 0;
  hex20_forces(g, ns, mat, cyc);  // the first step from the element step at rest
  for (int i = 0; i < g.count; ++i) dt = i == 0 ? g.dt[0] : std::min(dt, g.dt[static_cast<std::size_t>(i)]);
  dt *= 0.9;
  REQUIRE(dt > 0);
  for (std::size_t k = 0; k < pts.size(); ++k)
    if (ns.x0[k] < 1e-9) ns.vx[k] = v0;
  while (t < t_end) {
    cyc.dt1 = dt;
    for (std::size_t k = 0; k < pts.size(); ++k) {  // x^{n+1} = x^n + dt v^{n+1/2}
      ns.x[k] += dt * ns.vx[k];
      ns.y[k] += dt * ns.vy[k];
      ns.z[k] += dt * ns.vz[k];
    }
    hex20_forces(g, ns, mat, cyc);
    std::vector<double> f(3 * pts.size(), 0.0);
    for (int i = 0; i < g.count; ++i)
      for (std::size_t k = 0; k < 20; ++k)
        for (std::size_t d = 0; d < 3; ++d)
          f[3 * static_cast<std::size_t>(g.conn[k * G + static_cast<std::size_t>(i)]) + d] +=
              g.nodal_force[(k * 3 + d) * G + static_cast<std::size_t>(i)];
    for (std::size_t k = 0; k < pts.size(); ++k) {
      if (ns.x0[k] < 1e-9) continue;  // driven face
      ns.vx[k] += dt * f[3 * k] / mass[k];
      ns.vy[k] += dt * f[3 * k + 1] / mass[k];
      ns.vz[k] += dt * f[3 * k + 2] / mass[k];
    }
    t += dt;
  }
  const double wave = rho * c * v0;
  // Elements 1-3 (behind the front at 6 elements) are compressed by rho c0 v0, elements 9-11 untouched.
  double behind = 0;
  for (int e = 1; e <= 3; ++e) behind += g.sig[static_cast<std::size_t>(e)] / 3.0;
  CHECK(behind == Approx(-wave).epsilon(0.10));
  for (int e = 9; e < ne; ++e) CHECK(std::abs(g.sig[static_cast<std::size_t>(e)]) < 0.02 * wave);
  // Every element stayed stable (finite, positive step).
  for (int i = 0; i < g.count; ++i) CHECK(g.dt[static_cast<std::size_t>(i)] > 0);
}

TEST_CASE("hex20 starter: /BRIC20 read on three lines, masses 1/64 and 7/96, Isolid and Inpts checked",
          "[hex20]") {
  // One 10 mm cube of steel: rho V = 7.85e-6, corners 7.85e-6 / 64, mid-side nodes 7.85e-6 * 7 / 96.
  auto deck_text = [](int isolid, int inpts) {
    std::string d =
        "/BEGIN\nHEX20\n      2026\n                  Mg                  mm                   s\n"
        "                  Mg                  mm                   s\n/NODE\n";
    const auto p = box_nodes(10.0, 10.0, 10.0);
    for (int k = 0; k < 20; ++k) {
      char line[120];
      std::snprintf(line, sizeof line, "%10d%20.6f%20.6f%20.6f\n", k + 1, p[static_cast<std::size_t>(k)][0],
                    p[static_cast<std::size_t>(k)][1], p[static_cast<std::size_t>(k)][2]);
      d += line;
    }
    d += "/BRIC20/1\n         7         1         2         3         4         5         6         7        "
         " 8\n"
         "         9        10        11        12        13        14        15        16\n"
         "        17        18        19        20\n";
    char prop[200];
    std::snprintf(prop, sizeof prop, "/PROP/SOLID/1\nsolid\n%10d%10d%10d%10d%10d%10d\n", isolid, 0, 0, 0, 0,
                  inpts);
    d += "/PART/1\npart\n         1         1\n";
    d += prop;
    d += "                                                  \n"
         "/MAT/LAW1/1\nsteel\n             7.85e-9\n              210000                 0.3\n/END\n";
    return d;
  };
  {
    const auto r = build(deck_text(16, 0));
    for (const auto& d : r.diags.items()) INFO(radx::Diagnostics::format(d));
    REQUIRE_FALSE(r.diags.has_errors());
    REQUIRE(r.model.bricks20.size() == 1);
    CHECK(r.model.bricks20.id[0] == 7);
    for (int k = 0; k < 20; ++k)
      CHECK(r.model.nodes.id[static_cast<std::size_t>(r.model.bricks20.conn[static_cast<std::size_t>(k)])] ==
            k + 1);
    const double me = 7.85e-9 * 1000.0;
    CHECK(r.model.node_mass[0] == Approx(me / 64.0).epsilon(1e-12));
    CHECK(r.model.node_mass[8] == Approx(me * 7.0 / 96.0).epsilon(1e-12));
    CHECK(r.model.total_mass == Approx(me).epsilon(1e-12));
  }
  // Isolid 1 (one Gauss point, zero-energy modes) and Inpts 111 are refused by name (RX510).
  CHECK(has_code(build(deck_text(1, 0)).diags, radx::Diag::PhysicsNotImplemented));
  CHECK(has_code(build(deck_text(16, 111)).diags, radx::Diag::PhysicsNotImplemented));
  CHECK_FALSE(build(deck_text(16, 333)).diags.has_errors());
}
