// The 4-node tetrahedron (/TETRA4, solver/elements/solid/tetra4.cpp) on hand-built nodes and groups, and
// through the starter (reading, renumbering, masses, surfaces). Expected values come from closed-form
// kinematics and from the formulas of the kernel's opening comment (OpenRadioss s4deri3.F, mqviscb.F,
// s4cumu3.F, s4mass3.F), computed here independently of the kernel.
//
// The linear tetrahedron reproduces a linear velocity field exactly on any shape (sum_k x_k (x) b_k = I
// holds for every tetrahedron) and, unlike the one-point brick, integrates its gradients exactly, so every
// interior node of a distorted tetra mesh is in equilibrium under a constant stress.
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "contact/type7_engine.hpp"
#include "contact/type7_prepare.hpp"
#include "kernel_test_util.hpp"
#include "parser/building/model_builder.hpp"
#include "solver/elements/element_groups.hpp"
#include "solver/model/geometry.hpp"
#include "solver/model/masses.hpp"
#include "solver/model/stable_step.hpp"
#include "test_util.hpp"

using namespace radx::solver;
using radx::test::Line;

namespace {

using radx::test::elastic;
using radx::test::make_nodes;

constexpr std::size_t G = kGroupSize;
using P3 = std::array<double, 3>;

radx::model::Vec3 at0(const NodeState& ns, int n) {
  const auto k = static_cast<std::size_t>(n);
  return {ns.x0[k], ns.y0[k], ns.z0[k]};
}

// A group of tetrahedra over `ns`, each turned positive (n2 and n4 swapped) as the starter does.
TetraGroup make_group(std::vector<std::array<int, 4>> elems, const NodeState& ns, double rho0) {
  TetraGroup g;
  g.allocate(static_cast<int>(elems.size()));
  for (std::size_t e = 0; e < elems.size(); ++e) {
    auto& t = elems[e];
    if (radx::model::tetra_volume(at0(ns, t[0]), at0(ns, t[1]), at0(ns, t[2]), at0(ns, t[3])) < 0)
      std::swap(t[1], t[3]);
    for (std::size_t k = 0; k < 4; ++k) g.conn[k * G + e] = t[k];
    g.vol0[e] = g.vol[e] =
        radx::model::tetra_volume(at0(ns, t[0]), at0(ns, t[1]), at0(ns, t[2]), at0(ns, t[3]));
    g.rho[e] = rho0;
  }
  return g;
}

// A unit cube (corners 0..7, corner k at (k & 1, (k >> 1) & 1, (k >> 2) & 1)) and one interior node 8 at
// `p`; every cube face split into two triangles, each joined to node 8: 12 tetrahedra. A p away from the
// centre makes them all differently shaped.
std::vector<P3> cube_points(const P3& p) {
  std::vector<P3> pts;
  for (int k = 0; k < 8; ++k) pts.push_back({double(k & 1), double((k >> 1) & 1), double((k >> 2) & 1)});
  pts.push_back(p);
  return pts;
}
std::vector<std::array<int, 4>> cube_tetras() {
  const int faces[6][4] = {{0, 1, 3, 2}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5}};
  std::vector<std::array<int, 4>> t;
  for (const auto& f : faces) {
    t.push_back({f[0], f[1], f[2], 8});
    t.push_back({f[0], f[2], f[3], 8});
  }
  return t;
}

// Sum of the forces a group puts on node `node`.
P3 node_force(const TetraGroup& g, int node) {
  P3 f{0, 0, 0};
  for (int i = 0; i < g.count; ++i)
    for (std::size_t k = 0; k < 4; ++k)
      if (g.conn[k * G + static_cast<std::size_t>(i)] == node)
        for (std::size_t d = 0; d < 3; ++d)
          f[d] += g.nodal_force[(k * 3 + d) * G + static_cast<std::size_t>(i)];
  return f;
}

}  // namespace

TEST_CASE("tetra patch test: a linear field on a distorted tetra mesh gives one constant stress", "[tetra]") {
  // Velocity v = A x0 (a general matrix), nodes already moved to x = x0 + dt A x0, so v = A (I + dt A)^-1 x
  // is linear in the current coordinates: every element sees the same L and the same V / V0.
  const double E = 2.1e5, nu = 0.3, rho = 7.8e-9, dt = 1e-6;
  const auto mat = elastic(E, nu, rho);
  const double A[3][3] = {{0.9, 0.3, -0.2}, {0.1, -0.5, 0.4}, {-0.3, 0.2, 0.7}};  // 1/s
  auto ns = make_nodes(cube_points({0.31, 0.62, 0.44}));
  auto g = make_group(cube_tetras(), ns, rho);
  for (std::size_t n = 0; n < ns.n; ++n) {
    const double x0[3] = {ns.x0[n], ns.y0[n], ns.z0[n]};
    double v[3];
    for (int a = 0; a < 3; ++a) v[a] = A[a][0] * x0[0] + A[a][1] * x0[1] + A[a][2] * x0[2];
    ns.vx[n] = v[0];
    ns.vy[n] = v[1];
    ns.vz[n] = v[2];
    ns.x[n] += dt * v[0];
    ns.y[n] += dt * v[1];
    ns.z[n] += dt * v[2];
  }
  tetra4_forces(g, ns, mat, CycleInfo{dt, dt, 0});
  // Linear elasticity for the increment eps = sym(A) dt (first order in dt): the pressure comes from
  // mu = V0/V - 1 = -tr(eps) + O(eps^2) and the deviator from 2G dev(eps); the O(eps^2) terms are ~1e-6
  // of the stress, so 1e-5 relative is the tolerance of the linearisation, not of the element.
  const double tr = (A[0][0] + A[1][1] + A[2][2]) * dt;
  const double K = mat.bulk, Gs = mat.shear;
  const double expect[6] = {K * tr + 2 * Gs * (A[0][0] * dt - tr / 3),
                            K * tr + 2 * Gs * (A[1][1] * dt - tr / 3),
                            K * tr + 2 * Gs * (A[2][2] * dt - tr / 3),
                            Gs * (A[0][1] + A[1][0]) * dt,
                            Gs * (A[1][2] + A[2][1]) * dt,
                            Gs * (A[2][0] + A[0][2]) * dt};
  const double scale = K * std::abs(tr) + 2 * Gs * dt;  // the size of the stress components
  for (int e = 0; e < g.count; ++e)
    for (int m = 0; m < 6; ++m) {
      const double s = g.sig[static_cast<std::size_t>(m) * G + static_cast<std::size_t>(e)];
      CHECK(std::abs(s - expect[m]) < 1e-5 * scale);
      // Every element has the same stress to round-off: the pressure K mu comes from a volume change of 1e-6
      // known to 1e-16 of the volume, i.e. to 1e-10 of itself, so 1e-9 of the stress.
      CHECK(std::abs(s - g.sig[static_cast<std::size_t>(m) * G]) < 1e-9 * scale);
    }
  // The interior node is in equilibrium: its force is the round-off of the stresses above (1e-9 of the stress
  // times a face area of ~0.5).
  const auto f = node_force(g, 8);
  for (double c : f) CHECK(std::abs(c) < 1e-9 * scale);
  // The total force on the mesh is zero (internal forces are self-equilibrated).
  P3 total{0, 0, 0};
  for (int n = 0; n < 9; ++n) {
    const auto fn = node_force(g, n);
    for (int d = 0; d < 3; ++d) total[d] += fn[d];
  }
  for (double c : total) CHECK(std::abs(c) < 1e-9 * scale);
}

TEST_CASE("tetra cube under uniaxial strain gives the elastic uniaxial-strain stress", "[tetra]") {
  // Nodes displaced by u = eps x, velocity eps_dot x: sxx = (K + 4G/3) eps, syy = szz = (K - 2G/3) eps, up
  // to the O(eps^2) of the volumetric measure mu = V0/V - 1 (eps = 1e-6: 1e-6 relative).
  const double E = 7e4, nu = 0.33, rho = 2.7e-9, dt = 1e-6, rate = 1.0;
  const auto mat = elastic(E, nu, rho);
  auto ns = make_nodes(cube_points({0.5, 0.5, 0.5}));
  auto g = make_group(cube_tetras(), ns, rho);
  for (std::size_t n = 0; n < ns.n; ++n) {
    ns.vx[n] = rate * ns.x0[n];
    ns.x[n] += dt * ns.vx[n];
  }
  tetra4_forces(g, ns, mat, CycleInfo{dt, dt, 0});
  const double eps = rate * dt;
  const double sxx = (mat.bulk + 4 * mat.shear / 3) * eps, syy = (mat.bulk - 2 * mat.shear / 3) * eps;
  for (int e = 0; e < g.count; ++e) {
    const auto i = static_cast<std::size_t>(e);
    CHECK(g.sig[0 * G + i] == Approx(sxx).epsilon(1e-5));
    CHECK(g.sig[1 * G + i] == Approx(syy).epsilon(1e-5));
    CHECK(g.sig[2 * G + i] == Approx(syy).epsilon(1e-5));
    for (int m = 3; m < 6; ++m) CHECK(std::abs(g.sig[static_cast<std::size_t>(m) * G + i]) < 1e-9 * sxx);
  }
  // The x = 1 face carries the resultant sxx * area (area 1 of the face, less the bulk viscosity term
  // q = rho l qb c tr(D) of a stretching element: 0 here, tr D > 0 gives no viscosity).
  double fx = 0;
  for (int n : {1, 3, 5, 7}) fx += node_force(g, n)[0];
  CHECK(fx == Approx(-sxx).epsilon(1e-5));
}

TEST_CASE("tetra rigid rotation: no strain, no stress, no force", "[tetra]") {
  const auto mat = elastic(2.1e5, 0.3, 7.8e-9);
  auto ns = make_nodes(cube_points({0.2, 0.7, 0.35}));
  auto g = make_group(cube_tetras(), ns, 7.8e-9);
  const double w[3] = {3.0, -2.0, 5.0};  // rad/s
  for (std::size_t n = 0; n < ns.n; ++n) {
    const double x[3] = {ns.x[n], ns.y[n], ns.z[n]};
    ns.vx[n] = w[1] * x[2] - w[2] * x[1];
    ns.vy[n] = w[2] * x[0] - w[0] * x[2];
    ns.vz[n] = w[0] * x[1] - w[1] * x[0];
  }
  tetra4_forces(g, ns, mat, CycleInfo{1e-6, 1e-6, 0});
  // A spin gives D = 0 exactly up to round-off of the velocities (|v| ~ 5): stresses below 1e-9 Pa-units
  // against the 2e5 modulus, forces likewise.
  for (int e = 0; e < g.count; ++e)
    for (int m = 0; m < 6; ++m)
      CHECK(std::abs(g.sig[static_cast<std::size_t>(m) * G + static_cast<std::size_t>(e)]) < 1e-9);
  for (int n = 0; n < 9; ++n)
    for (double c : node_force(g, n)) CHECK(std::abs(c) < 1e-9);
}

TEST_CASE("tetra time step and nodal stiffness from the formula", "[tetra]") {
  // Corner tetrahedron of side a (mm, tonne, s): V = a^3/6, largest face the slanted one sqrt(3) a^2/2,
  // so dx = 3V / A_max = a / sqrt(3); at rest c_eff = c (qb + sqrt(qb^2 + 1)) with qb 0.05.
  const double a = 10.0, E = 2.1e5, nu = 0.3, rho = 7.8e-9;
  const auto mat = elastic(E, nu, rho);
  auto ns = make_nodes({{0, 0, 0}, {0, a, 0}, {a, 0, 0}, {0, 0, a}});
  auto g = make_group({{0, 1, 2, 3}}, ns, rho);
  REQUIRE(g.conn[1 * G] == 1);  // already positive in Radioss's orientation: not renumbered
  CHECK(g.vol0[0] == Approx(a * a * a / 6).epsilon(1e-14));
  tetra4_forces(g, ns, mat, CycleInfo{0, 0, 0});
  const double c = std::sqrt((mat.bulk + 4 * mat.shear / 3) / rho);
  const double dt = (a / std::sqrt(3.0)) / (c * (0.05 + std::sqrt(1.0 + 0.05 * 0.05)));
  CHECK(g.dt[0] == Approx(dt).epsilon(1e-12));
  const double V = a * a * a / 6;
  CHECK(g.k_nodal[0] == Approx(0.5 * rho * V / (dt * dt)).epsilon(1e-12));
  // A lone tetrahedron's nodal step sqrt(2 m / k) with m = rho V / 4 is its element step.
  CHECK(std::sqrt(2 * (rho * V / 4) / g.k_nodal[0]) == Approx(dt).epsilon(1e-12));
  // The starter's estimate uses the same length (and no bulk viscosity).
  CHECK(radx::model::tetra_length({0, 0, 0}, {0, a, 0}, {a, 0, 0}, {0, 0, a}) ==
        Approx(a / std::sqrt(3.0)).epsilon(1e-14));
}

TEST_CASE("tetra inverted and deleted elements", "[tetra]") {
  const auto mat = elastic(2.1e5, 0.3, 7.8e-9);
  auto ns = make_nodes({{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}, {0, 0, -1}});
  auto g = make_group({{0, 1, 2, 3}, {0, 1, 2, 3}}, ns, 7.8e-9);
  g.off[1] = 0.0;
  ns.z[3] = -1.0;  // node 4 pushed through the face n1 n2 n3: inverted
  tetra4_forces(g, ns, mat, CycleInfo{1e-6, 1e-6, 0});
  CHECK(g.dt[0] == 0.0);
  CHECK(g.vol[0] < 0);
  CHECK(std::isinf(g.dt[1]));
  for (std::size_t r = 0; r < 12; ++r) CHECK(g.nodal_force[r * G + 1] == 0.0);
}

namespace {

std::string ids_line(std::initializer_list<long long> ids) {
  Line l;
  int c = 0;
  for (auto id : ids) {
    l.put(id, 10 * c + 1, 10 * c + 10);
    ++c;
  }
  return l.str();
}

// The 12-tetra cube of side 2 (nodes 1..8 corners, 9 the centre at (1, 1, 1)) in part 1 (a /PROP/SOLID),
// LAW1 steel; the tetra list in the deck's order, each as written.
std::string tetra_deck(const std::string& extra, bool invert_first = false) {
  std::string s = radx::test::begin_block(2026) + "/NODE\n";
  const auto pts = cube_points({0.5, 0.5, 0.5});
  for (std::size_t k = 0; k < pts.size(); ++k)
    s += Line()
             .put(static_cast<long long>(k + 1), 1, 10)
             .put(2 * pts[k][0], 11, 30)
             .put(2 * pts[k][1], 31, 50)
             .put(2 * pts[k][2], 51, 70)
             .str() +
         "\n";
  s += "/TETRA4/1\n";
  int e = 1;
  for (auto t : cube_tetras()) {
    // Written in the positive order, except the first one when asked.
    const bool neg = radx::model::tetra_volume({2 * pts[t[0]][0], 2 * pts[t[0]][1], 2 * pts[t[0]][2]},
                                               {2 * pts[t[1]][0], 2 * pts[t[1]][1], 2 * pts[t[1]][2]},
                                               {2 * pts[t[2]][0], 2 * pts[t[2]][1], 2 * pts[t[2]][2]},
                                               {2 * pts[t[3]][0], 2 * pts[t[3]][1], 2 * pts[t[3]][2]}) < 0;
    if (neg != (invert_first && e == 1)) std::swap(t[1], t[3]);
    Line l;
    l.put(e++, 1, 10);
    for (int q = 0; q < 4; ++q) l.put(t[static_cast<std::size_t>(q)] + 1, 11 + 10 * q, 20 + 10 * q);
    s += l.str() + "\n";
  }
  s += "/PART/1\nblock\n" + ids_line({1, 1}) + "\n/PROP/SOLID/1\nsolid\n\n\n";
  s += "/MAT/LAW1/1\nsteel\n" + Line().put(7.8e-9, 1, 20).str() + "\n" +
       Line().put(2.1e5, 1, 20).put(0.3, 21, 40).str() + "\n";
  s += extra + "/END\n";
  return s;
}

struct Built {
  radx::Diagnostics diags;
  radx::model::Model model;
};

Built build(const std::string& text) {
  radx::test::TempDir dir;
  const auto path = dir.write("t_0000.rad", text);
  Built b;
  const auto deck = radx::read_starter_deck(path, b.diags);
  b.model = radx::build_model(deck, b.diags);
  return b;
}

}  // namespace

TEST_CASE("tetra starter: reading, masses, renumbering and the outer-face surface", "[tetra][groups]") {
  auto b = build(tetra_deck("/SURF/PART/EXT/1\nskin\n" + ids_line({1}) + "\n", true));
  for (const auto& d : b.diags.items()) INFO(radx::Diagnostics::format(d));
  REQUIRE_FALSE(b.diags.has_errors());
  const auto& m = b.model;
  REQUIRE(m.tetras.size() == 12);
  // The inverted first tetrahedron was renumbered (n2 <-> n4) with a warning, as Radioss does.
  bool warned = false;
  for (const auto& d : b.diags.items()) warned = warned || d.code == radx::Diag::RenumberedTetra;
  CHECK(warned);
  auto X = [&](std::int32_t n) {
    const auto k = static_cast<std::size_t>(n);
    return radx::model::Vec3{m.nodes.x[k], m.nodes.y[k], m.nodes.z[k]};
  };
  double volume = 0;
  for (std::size_t e = 0; e < m.tetras.size(); ++e) {
    const auto* c = &m.tetras.conn[4 * e];
    const double v = radx::model::tetra_volume(X(c[0]), X(c[1]), X(c[2]), X(c[3]));
    CHECK(v > 0);
    volume += v;
  }
  CHECK(volume == Approx(8.0).epsilon(1e-14));
  // Mass rho V split in quarters: the total is rho 8, the centre node has a quarter of every tetra.
  CHECK(m.total_mass == Approx(7.8e-9 * 8).epsilon(1e-14));
  CHECK(m.node_mass[8] == Approx(7.8e-9 * 8 / 4).epsilon(1e-14));
  CHECK(m.parts[0].mass == Approx(7.8e-9 * 8).epsilon(1e-14));
  // The stable-step estimate sees a tetrahedron: each has height 1 from the centre to its face.
  const auto step = radx::model::estimate_stable_step(m);
  CHECK(step.type == radx::model::ElementType::Tetra4);
  // Outer faces: 12 triangles (n4 = n3), total area 6 sides x 4, each pointing out of the cube.
  REQUIRE(m.surfaces.size() == 1);
  const auto& skin = m.surfaces[0];
  CHECK(skin.segments.size() == 12);
  double area = 0;
  const radx::model::Vec3 centre{1, 1, 1};
  for (std::size_t s = 0; s < skin.segments.size(); ++s) {
    const auto& seg = skin.segments[s];
    CHECK(seg[2] == seg[3]);
    CHECK(skin.owner_type[s] == radx::model::SegmentOwner::Tetra4);
    area += radx::model::triangle_area(X(seg[0]), X(seg[1]), X(seg[2]));
    const auto n =
        radx::model::cross(radx::model::sub(X(seg[1]), X(seg[0])), radx::model::sub(X(seg[2]), X(seg[0])));
    const auto mid =
        radx::model::scale(radx::model::add(radx::model::add(X(seg[0]), X(seg[1])), X(seg[2])), 1.0 / 3);
    CHECK(radx::model::dot(n, radx::model::sub(mid, centre)) > 0);
  }
  CHECK(area == Approx(24.0).epsilon(1e-14));
}

TEST_CASE("tetra starter: a solid tetra part refused by /SURF/PART and a shell property", "[tetra][groups]") {
  auto b = build(tetra_deck("/SURF/PART/1\nskin\n" + ids_line({1}) + "\n"));
  bool wrong_kind = false;
  for (const auto& d : b.diags.items()) wrong_kind = wrong_kind || d.code == radx::Diag::PartWrongKind;
  CHECK(wrong_kind);
}

TEST_CASE("tetra faces leave TYPE7 with Idel when their tetrahedra are deleted", "[tetra][type7]") {
  // decks/verification/tetra_drop: the plate's nodes against the outer tetra faces of a block. The plate's
  // centre node is put inside the gap under the block's bottom face; the face pushes it while its tetrahedra
  // live, and with Idel 1 no more once they are deleted (the plate's shells stay, so the node stays).
  const std::string dir = std::string(RADX_SOURCE_DIR) + "/decks/verification/tetra_drop/";
  radx::Diagnostics d;
  const auto deck = radx::read_starter_deck(dir + "TETRA_DROP_0000.rad", d);
  auto m = radx::build_model(deck, d);
  REQUIRE_FALSE(d.has_errors());
  REQUIRE(m.interfaces.size() == 1);
  m.interfaces[0].idel = 1;
  double z_bottom = 1e300;
  for (const auto n : m.tetras.conn) z_bottom = std::min(z_bottom, m.nodes.z[static_cast<std::size_t>(n)]);
  const auto centre = static_cast<std::size_t>(m.nodes.index.find(1041));  // plate node at (0, 0, 0)
  REQUIRE(m.nodes.x[centre] == 0.0);
  REQUIRE(m.nodes.y[centre] == 0.0);
  radx::contact::prepare_type7_interfaces(m);
  const double gap = m.interfaces[0].gapmin;
  m.nodes.z[centre] = z_bottom - 0.5 * gap;  // half the gap left: penetration g / 2
  radx::contact::Type7Contact contact(m, radx::contact::ContactControls{});
  const std::size_t nn = m.nodes.size();
  std::vector<double> x = m.nodes.x, y = m.nodes.y, z = m.nodes.z, v(nn, 0.0), mass = m.node_mass,
                      added(nn, 0.0);
  std::vector<std::uint8_t> fixed(nn, 0);
  const radx::contact::ContactNodes nodes{x, y, z, v, v, v, mass, added, fixed, {}};
  auto centre_force = [&] {
    for (const auto n : contact.touched())
      if (static_cast<std::size_t>(n) == centre) return contact.force()[3 * centre + 2];
    return 0.0;
  };
  contact.compute(0.0, 1e-7, nodes);
  CHECK(centre_force() < 0);  // the face pushes the plate node down, away from the block
  std::vector<std::uint8_t> alive(m.element_count(), 1);
  const std::size_t tetra0 = m.shells.size() + m.shells3.size() + m.bricks.size();
  for (std::size_t e = 0; e < m.tetras.size(); ++e) alive[tetra0 + e] = 0;
  contact.elements_deleted(alive);
  contact.compute(1e-7, 1e-7, nodes);
  CHECK(centre_force() == 0.0);
  CHECK(contact.take_messages().empty());  // the plate node keeps its shells: not removed
}
