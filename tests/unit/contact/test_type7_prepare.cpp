// TYPE7 starter computations against docs/theory/type7-lagdt.md sections 4.1 (gap), 4.2 (stiffness), 4.3
// (projection weights) and 4.6 (initial penetrations), on small models built in the test.
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>

#include "contact/type7_prepare.hpp"
#include "solver/model/masses.hpp"

using radx::model::Model;
namespace m = radx::model;

namespace {

// A flat plate of n x n shells of side h and thickness t (part 0, E, nu) at z = 0, and a cube of side a
// made of one brick (part 1, E2, nu2) whose bottom face is at z = z0 above the plate centre.
Model plate_and_brick(int n, double h, double t, double a, double z0) {
  Model mod;
  mod.materials.resize(2);
  mod.materials[0].young = 210000;
  mod.materials[0].poisson = 0.3;
  mod.materials[0].rho = 7.85e-9;
  mod.materials[1].young = 70000;
  mod.materials[1].poisson = 0.25;
  mod.materials[1].rho = 2.7e-9;
  for (auto& mat : mod.materials) mat.bulk = mat.young / (3 * (1 - 2 * mat.poisson));
  mod.properties.resize(2);
  mod.properties[0].kind = m::PropertyKind::Shell;
  mod.properties[0].shell.thickness = t;
  mod.properties[1].kind = m::PropertyKind::Solid;
  mod.parts.resize(2);
  mod.parts[0].property = 0;
  mod.parts[0].material = 0;
  mod.parts[1].property = 1;
  mod.parts[1].material = 1;
  auto add_node = [&](double x, double y, double z) {
    mod.nodes.id.push_back(static_cast<std::int64_t>(mod.nodes.id.size() + 1));
    mod.nodes.x.push_back(x);
    mod.nodes.y.push_back(y);
    mod.nodes.z.push_back(z);
    return static_cast<std::int32_t>(mod.nodes.id.size() - 1);
  };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) add_node(i * h, j * h, 0.0);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const auto n1 = j * (n + 1) + i;
      mod.shells.id.push_back(static_cast<std::int64_t>(mod.shells.id.size() + 1));
      mod.shells.part.push_back(0);
      mod.shells.thickness.push_back(0.0);
      mod.shells.phi.push_back(0.0);
      for (auto k : {n1, n1 + 1, n1 + n + 2, n1 + n + 1}) mod.shells.conn.push_back(k);
    }
  const double c = 0.5 * n * h;
  std::int32_t b[8];
  for (int k = 0; k < 8; ++k) {
    const double x = c + ((k == 1 || k == 2 || k == 5 || k == 6) ? 0.5 : -0.5) * a;
    const double y = c + ((k == 2 || k == 3 || k == 6 || k == 7) ? 0.5 : -0.5) * a;
    b[k] = add_node(x, y, z0 + (k >= 4 ? a : 0.0));
  }
  mod.bricks.id.push_back(1);
  mod.bricks.part.push_back(1);
  mod.bricks.thickness.push_back(0.0);
  mod.bricks.phi.push_back(0.0);
  for (auto k : b) mod.bricks.conn.push_back(k);
  // Surface 0: the plate; surface 1: the bottom face of the brick (outward normal -z).
  m::Surface plate;
  for (std::size_t e = 0; e < mod.shells.size(); ++e) {
    const auto* q = &mod.shells.conn[4 * e];
    plate.segments.push_back({q[0], q[1], q[2], q[3]});
    plate.owner_type.push_back(m::SegmentOwner::Shell4);
    plate.owner.push_back(static_cast<std::int32_t>(e));
  }
  mod.surfaces.push_back(plate);
  m::Surface bottom;
  bottom.segments.push_back({b[0], b[3], b[2], b[1]});
  bottom.owner_type.push_back(m::SegmentOwner::Brick8);
  bottom.owner.push_back(0);
  mod.surfaces.push_back(bottom);
  return mod;
}

m::Interface block_on_plate(const Model& mod) {
  m::Interface in;
  in.main_surface = 0;
  for (std::int32_t k = static_cast<std::int32_t>(mod.nodes.size()) - 8;
       k < static_cast<std::int32_t>(mod.nodes.size()); ++k)
    in.secondary_nodes.push_back(k);
  return in;
}

}  // namespace

TEST_CASE("automatic Gapmin is min(t, l/10, lmin/2) with missing terms left out", "[type7]") {
  // Plate main surface: only shells, so Gapmin = min(t, lmin/2).
  Model mod = plate_and_brick(4, 10.0, 1.5, 20.0, 5.0);
  mod.interfaces.push_back(block_on_plate(mod));
  // Brick main surface: only the brick term, Gapmin = min(l/10, lmin/2) with l = a.
  m::Interface brick_main;
  brick_main.main_surface = 1;
  for (std::int32_t k = 0; k < 25; ++k) brick_main.secondary_nodes.push_back(k);
  mod.interfaces.push_back(brick_main);
  radx::contact::prepare_type7_interfaces(mod);
  // Geometric identities, exact to round-off.
  CHECK(mod.interfaces[0].gapmin == Approx(std::min(1.5, 10.0 / 2)).epsilon(1e-14));
  CHECK(mod.interfaces[0].gapmin_automatic);
  CHECK(mod.interfaces[1].gapmin == Approx(std::min(20.0 / 10, 20.0 / 2)).epsilon(1e-14));
  // A thin plate: t wins over lmin/2.
  Model thin = plate_and_brick(4, 10.0, 0.4, 20.0, 5.0);
  thin.interfaces.push_back(block_on_plate(thin));
  radx::contact::prepare_type7_interfaces(thin);
  CHECK(thin.interfaces[0].gapmin == Approx(0.4).epsilon(1e-14));
}

TEST_CASE("variable gaps Igap 1 and 2 follow max(Gapmin, gs + gm) and the scaled, capped form", "[type7]") {
  m::Interface in;
  in.gapmin = 0.3;
  in.igap = 0;
  CHECK(radx::contact::pair_gap(in, 0.5, 0.5) == 0.3);
  in.igap = 1;
  CHECK(radx::contact::pair_gap(in, 0.5, 0.25) == Approx(0.75));
  CHECK(radx::contact::pair_gap(in, 0.1, 0.1) == Approx(0.3));  // never below Gapmin
  in.igap = 2;
  in.fscale_gap = 0.5;
  in.gap_max = 0;
  CHECK(radx::contact::pair_gap(in, 1.0, 1.0) == Approx(1.0));  // 0.5 * 2, no cap
  in.gap_max = 0.8;
  CHECK(radx::contact::pair_gap(in, 1.0, 1.0) == Approx(0.8));
  in.gap_max = 0.1;
  CHECK(radx::contact::pair_gap(in, 1.0, 1.0) == Approx(0.3));  // the cap never goes below Gapmin
}

TEST_CASE("shell and brick stiffnesses follow 0.5 E t, B S^2 / V and B V^(1/3)", "[type7]") {
  const double t = 1.2, a = 20.0, h = 10.0;
  Model mod = plate_and_brick(4, h, t, a, 5.0);
  auto in = block_on_plate(mod);
  in.stfac = 2.0;
  mod.interfaces.push_back(in);
  m::Interface brick_main;
  brick_main.main_surface = 1;
  brick_main.stfac = 0.5;
  for (std::int32_t k = 0; k < 25; ++k) brick_main.secondary_nodes.push_back(k);
  mod.interfaces.push_back(brick_main);
  radx::contact::prepare_type7_interfaces(mod);
  const double e_plate = 210000, b_brick = 70000 / (3 * (1 - 2 * 0.25));
  const auto& i0 = mod.interfaces[0];
  for (double km : i0.stiff_segment) CHECK(km == Approx(2.0 * 0.5 * e_plate * t).epsilon(1e-14));
  // Secondary brick nodes: Ks = Stfac B V^(1/3) = Stfac B a.
  for (double ks : i0.stiff_node) CHECK(ks == Approx(2.0 * b_brick * a).epsilon(1e-12));
  CHECK(i0.stiff_lo == Approx(2.0 * 0.5 * e_plate * t));  // Istf 0: K = Km
  const auto& i1 = mod.interfaces[1];
  // Brick face: Km = Stfac B S^2 / V = Stfac B a.
  CHECK(i1.stiff_segment[0] == Approx(0.5 * b_brick * a * a * a * a / (a * a * a)).epsilon(1e-12));
  // Plate nodes: Ks = Stfac 0.5 E t.
  for (double ks : i1.stiff_node) CHECK(ks == Approx(0.5 * 0.5 * e_plate * t).epsilon(1e-14));
}

TEST_CASE("pair stiffness for Istf 0 to 5 with Stmin and Stmax", "[type7]") {
  m::Interface in;
  in.stmin = 0;
  in.stmax = 1e30;
  in.stfac = 123.0;
  const double km = 300, ks = 100;
  in.istf = 0;
  CHECK(radx::contact::pair_stiffness(in, km, ks) == km);
  in.istf = 1;
  CHECK(radx::contact::pair_stiffness(in, km, ks) == 123.0);
  in.istf = 2;
  CHECK(radx::contact::pair_stiffness(in, km, ks) == Approx((km + ks) / 2));
  in.istf = 3;
  CHECK(radx::contact::pair_stiffness(in, km, ks) == Approx(km));
  in.istf = 4;
  CHECK(radx::contact::pair_stiffness(in, km, ks) == Approx(ks));
  in.istf = 5;
  CHECK(radx::contact::pair_stiffness(in, km, ks) == Approx(km * ks / (km + ks)));
  in.stmin = 90;
  in.stmax = 95;
  CHECK(radx::contact::pair_stiffness(in, km, ks) == Approx(90));  // 75 clamped up to Stmin
  in.istf = 3;
  CHECK(radx::contact::pair_stiffness(in, km, ks) == Approx(95));  // 300 clamped down to Stmax
}

TEST_CASE("closest point on a quadrangle: distance and shape-function weights", "[type7]") {
  using V = std::array<double, 3>;
  const std::array<V, 4> quad = {V{0, 0, 0}, V{2, 0, 0}, V{2, 2, 0}, V{0, 2, 0}};
  std::array<double, 4> h{};
  // Above the centroid: distance is the height, weights 1/4 each.
  CHECK(radx::contact::closest_point_segment({1, 1, 0.7}, quad, false, h) == Approx(0.7));
  for (double w : h) CHECK(w == Approx(0.25));
  // Above a corner: all weight on that node.
  CHECK(radx::contact::closest_point_segment({2, 2, -0.5}, quad, false, h) == Approx(0.5));
  CHECK(h[2] == Approx(1.0));
  // Beyond an edge: distance to the edge, weights split on its two nodes, summing to 1.
  const double d = radx::contact::closest_point_segment({1, -1, 1}, quad, false, h);
  CHECK(d == Approx(std::sqrt(2.0)));
  CHECK(h[0] == Approx(0.5));
  CHECK(h[1] == Approx(0.5));
  CHECK(h[0] + h[1] + h[2] + h[3] == Approx(1.0));
  // A point inside the face: the weights reproduce the point (interpolation property).
  const V p{0.5, 1.5, 0.2};
  radx::contact::closest_point_segment(p, quad, false, h);
  double x = 0, y = 0;
  for (int k = 0; k < 4; ++k) x += h[k] * quad[k][0], y += h[k] * quad[k][1];
  CHECK(x == Approx(0.5));
  CHECK(y == Approx(1.5));
  // Triangle segment (n4 = n3).
  CHECK(radx::contact::closest_point_segment({0.2, 0.2, 3}, quad, true, h) == Approx(3.0));
  CHECK(h[3] == 0.0);
}

TEST_CASE("initial penetrations are found and treated by Inacti", "[type7]") {
  // The brick bottom sits 0.4 above the plate; the gap is t = 1, so p0 = 0.6 at the 4 bottom nodes.
  const double t = 1.0, z0 = 0.4;
  for (int inacti : {0, 1, 3, 5, 6}) {
    Model mod = plate_and_brick(4, 10.0, t, 10.0, z0);
    auto in = block_on_plate(mod);
    in.inacti = inacti;
    mod.interfaces.push_back(in);
    radx::contact::prepare_type7_interfaces(mod);
    const auto& r = mod.interfaces[0];
    INFO("Inacti " << inacti);
    CHECK(r.initial_penetrations == 4);
    CHECK(r.max_initial_penetration == Approx(t - z0).epsilon(1e-12));
    if (inacti == 1) CHECK(r.inactive_nodes.size() == 4);
    if (inacti == 3) {
      // Moved out to the gap surface: z = g.
      for (std::size_t k = 0; k < 4; ++k)
        CHECK(mod.nodes.z[r.secondary_nodes[k]] == Approx(t).epsilon(1e-12));
    }
    if (inacti == 5)
      for (double red : r.initial_gap_reduction) CHECK(red == Approx(t - z0));
    if (inacti == 6)
      for (double red : r.initial_gap_reduction) CHECK(red == Approx((t - z0) + 0.05 * z0));
  }
  // Out of the gap: nothing found.
  Model clear = plate_and_brick(4, 10.0, t, 10.0, 1.5 * t);
  clear.interfaces.push_back(block_on_plate(clear));
  radx::contact::prepare_type7_interfaces(clear);
  CHECK(clear.interfaces[0].initial_penetrations == 0);
}

TEST_CASE("a node never pairs with a segment that contains it (self-contact)", "[type7]") {
  Model mod = plate_and_brick(3, 10.0, 1.0, 10.0, 5.0);
  m::Interface self;
  self.main_surface = 0;
  for (std::int32_t k = 0; k < 16; ++k) self.secondary_nodes.push_back(k);  // the plate's own nodes
  mod.interfaces.push_back(self);
  radx::contact::prepare_type7_interfaces(mod);
  CHECK(mod.interfaces[0].initial_penetrations == 0);
}

TEST_CASE("tributary areas: a quarter of each shell and open brick face around a node, a third of a triangle",
          "[type7]") {
  // A plate of 2 x 2 shells of side h (A = h^2) and a cube of side a made of one brick, apart.
  const double h = 10.0, a = 4.0;
  Model mod = plate_and_brick(2, h, 1.0, a, 20.0);
  const double area = h * h;
  std::vector<std::int32_t> all(mod.nodes.size());
  for (std::size_t k = 0; k < all.size(); ++k) all[k] = static_cast<std::int32_t>(k);
  const auto nodal = radx::contact::tributary_areas(mod, all);
  REQUIRE(nodal.size() == mod.nodes.size());
  // Plate nodes 0..8, row by row: corners A/4, edge middles A/2, centre A.
  for (int k : {0, 2, 6, 8}) CHECK(nodal[k] == Approx(area / 4).epsilon(1e-12));
  for (int k : {1, 3, 5, 7}) CHECK(nodal[k] == Approx(area / 2).epsilon(1e-12));
  CHECK(nodal[4] == Approx(area).epsilon(1e-12));
  // Each brick corner is on 3 faces of a^2: 3 a^2 / 4.
  for (int k = 9; k < 17; ++k) CHECK(nodal[k] == Approx(3 * a * a / 4).epsilon(1e-12));

  // Every interface gets the areas of its secondary nodes (a node without element: 0), counting only the
  // faces whose corners are all secondary nodes.
  mod.nodes.id.push_back(99);
  mod.nodes.x.push_back(0);
  mod.nodes.y.push_back(0);
  mod.nodes.z.push_back(50);
  auto in = block_on_plate(mod);  // the last 8 nodes: brick corners 1..7 (not corner 0) and the free node
  mod.interfaces.push_back(in);
  radx::contact::prepare_type7_interfaces(mod);
  const auto& r = mod.interfaces[0];
  REQUIRE(r.tributary_area.size() == 8);
  // Without corner 0 the brick keeps the 3 faces around corner 6: corner 6 is on all 3, the face diagonals of
  // corner 0 (2, 5, 7) on 2, its neighbours (1, 3, 4) on 1.
  const double q = a * a / 4;
  const std::array<double, 7> expected = {q, 2 * q, q, q, 2 * q, 3 * q, 2 * q};
  for (std::size_t k = 0; k < 7; ++k) CHECK(r.tributary_area[k] == Approx(expected[k]).epsilon(1e-12));
  CHECK(r.tributary_area[7] == 0.0);
}

TEST_CASE("tributary areas: a face shared by two bricks is inner, a 3-node shell gives a third", "[type7]") {
  Model mod;
  auto add_node = [&](double x, double y, double z) {
    mod.nodes.id.push_back(static_cast<std::int64_t>(mod.nodes.id.size() + 1));
    mod.nodes.x.push_back(x);
    mod.nodes.y.push_back(y);
    mod.nodes.z.push_back(z);
  };
  // Two unit cubes side by side along x: nodes (i, j, k) for i = 0..2, j, k = 0..1.
  auto node = [](int i, int j, int k) { return static_cast<std::int32_t>(i + 3 * j + 6 * k); };
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i) add_node(i, j, k);
  for (int i = 0; i < 2; ++i) {
    mod.bricks.id.push_back(i + 1);
    mod.bricks.part.push_back(0);
    for (auto n : {node(i, 0, 0), node(i + 1, 0, 0), node(i + 1, 1, 0), node(i, 1, 0), node(i, 0, 1),
                   node(i + 1, 0, 1), node(i + 1, 1, 1), node(i, 1, 1)})
      mod.bricks.conn.push_back(n);
  }
  // A right triangle of legs 3 and 4 (area 6) on three new nodes.
  add_node(10, 0, 0);
  add_node(13, 0, 0);
  add_node(10, 4, 0);
  mod.shells3.id.push_back(1);
  mod.shells3.part.push_back(0);
  for (std::int32_t n : {12, 13, 14}) mod.shells3.conn.push_back(n);
  std::vector<std::int32_t> all(mod.nodes.size());
  for (std::size_t k = 0; k < all.size(); ++k) all[k] = static_cast<std::int32_t>(k);
  const auto nodal = radx::contact::tributary_areas(mod, all);
  // An end corner (i = 0 or 2) is on 3 outer faces of area 1; a middle node (i = 1) on 4 (two faces of each
  // brick, the shared face left out).
  for (int j = 0; j < 2; ++j)
    for (int k = 0; k < 2; ++k) {
      CHECK(nodal[node(0, j, k)] == Approx(0.75).epsilon(1e-12));
      CHECK(nodal[node(2, j, k)] == Approx(0.75).epsilon(1e-12));
      CHECK(nodal[node(1, j, k)] == Approx(1.0).epsilon(1e-12));
    }
  for (int n : {12, 13, 14}) CHECK(nodal[n] == Approx(2.0).epsilon(1e-12));

  // The lower face of both bricks as the contact surface: only the two lower faces count; a lone node of it
  // takes every face around it; a deleted brick leaves its neighbour's shared face outer.
  std::vector<std::int32_t> lower;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) lower.push_back(node(i, j, 0));
  std::sort(lower.begin(), lower.end());
  const auto on_lower = radx::contact::tributary_areas(mod, lower);
  for (std::size_t k = 0; k < lower.size(); ++k) {
    const bool middle = lower[k] % 3 == 1;
    CHECK(on_lower[k] == Approx(middle ? 0.5 : 0.25).epsilon(1e-12));
  }
  const std::vector<std::int32_t> lone = {node(1, 0, 0)};
  CHECK(radx::contact::tributary_areas(mod, lone)[0] == Approx(1.0).epsilon(1e-12));
  std::vector<std::uint8_t> alive(1 + 2, 1);  // cells: the 3-node shell, then the two bricks
  alive[2] = 0;                               // the second brick (i = 1) deleted
  const auto after = radx::contact::tributary_areas(mod, lone, alive);
  CHECK(after[0] == Approx(0.75).epsilon(1e-12));  // its 3 faces of the first brick, the shared one now outer
}

TEST_CASE("an exponential law given by pe: the largest initial stiffness pz (K / A_s) / pe", "[type7]") {
  m::Interface in;
  in.contact_law_id = 3;
  in.law.normal = m::NormalLaw::Exponential;
  in.law.pz = 2.0;
  in.law.pe = 5.0;
  in.stiff_lo = 100.0;
  in.stiff_hi = 400.0;
  in.tributary_area = {0.0, 8.0, 2.0, 4.0};
  const auto s = radx::contact::pe_law_initial_stiffness_max(in);
  CHECK(s.k == 400.0);
  CHECK(s.area == 2.0);
  CHECK(s.stiffness == Approx(2.0 * (400.0 / 2.0) / 5.0));
  in.law.pe = 0;
  in.law.lambda = 3;
  CHECK(radx::contact::pe_law_initial_stiffness_max(in).stiffness == 0.0);
}
