// /MAT/VOID (law 0) and /MAT/RIGID (law 13), run through the starter and the engine: a void element carries
// its mass rho_I V and no force; the connected elements of a rigid material form one rigid body (OpenRadioss
// rigid_mat.F) that keeps its shape, conserves momentum in free flight and passes an impact on as one body.
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>

#include "solver/engine/explicit_engine.hpp"
#include "test_util.hpp"

using radx::test::Line;
namespace m = radx::model;
namespace sv = radx::solver;

namespace {

constexpr double kA = 10.0;        // cube edge (mm)
constexpr double kRho = 7.85e-9;   // steel (Mg/mm^3)
constexpr double kYoung = 210000;  // MPa

// Nodes first_id .. first_id + 7 of an a-cube with its corner at (x0, 0, 0), nodes 5-8 at z = a.
std::string cube_nodes(int first_id, double x0) {
  std::string s;
  for (int k = 0; k < 8; ++k) {
    const double x = x0 + ((k == 1 || k == 2 || k == 5 || k == 6) ? kA : 0.0);
    const double y = (k == 2 || k == 3 || k == 6 || k == 7) ? kA : 0.0;
    s += Line().put(first_id + k, 1, 10).put(x, 11, 30).put(y, 31, 50).put(k >= 4 ? kA : 0.0, 51, 70).str() +
         "\n";
  }
  return s;
}

std::string brick(int part, int id, const std::array<int, 8>& n) {
  Line b;
  b.put(id, 1, 10);
  for (int k = 0; k < 8; ++k) b.put(n[static_cast<std::size_t>(k)], 11 + 10 * k, 20 + 10 * k);
  return "/BRICK/" + std::to_string(part) + "\n" + b.str() + "\n";
}

std::string part(int id, int mat) {
  return "/PART/" + std::to_string(id) + "\npart\n" + Line().put(1, 1, 10).put(mat, 11, 20).str() + "\n";
}

std::string materials(const std::string& void_card) {
  return "/PROP/SOLID/1\nsolid\n\n\n/MAT/LAW1/1\nsteel\n" + Line().put(kRho, 1, 20).str() + "\n" +
         Line().put(kYoung, 1, 20).put(0.3, 21, 40).str() + "\n/MAT/RIGID/2\nrigid steel\n" +
         Line().put(kRho, 1, 20).str() + "\n" + Line().put(kYoung, 1, 20).put(0.3, 21, 40).str() +
         "\n/MAT/VOID/3\nvoid\n" + void_card;
}

std::string inivel(int id, double vx, double vy, double vz, const std::vector<int>& nodes) {
  std::string s = "/GRNOD/NODE/" + std::to_string(id) + "\ng\n";
  Line l;
  for (std::size_t k = 0; k < nodes.size(); ++k)
    l.put(nodes[k], 1 + 10 * static_cast<int>(k), 10 + 10 * static_cast<int>(k));
  s += l.str() + "\n/INIVEL/TRA/" + std::to_string(id) + "\nv\n" +
       Line().put(vx, 1, 20).put(vy, 21, 40).put(vz, 41, 60).put(id, 61, 70).str() + "\n";
  return s;
}

m::RunControls controls(double t_stop) {
  m::RunControls rc;
  rc.t_stop = t_stop;
  rc.global.scale = 0.45;  // a lone one-point brick needs half its step (test_accelerometer.cpp)
  return rc;
}

double dist(const sv::NodeState& s, std::size_t a, std::size_t b) {
  return std::hypot(s.x[a] - s.x[b], s.y[a] - s.y[b], s.z[a] - s.z[b]);
}

}  // namespace

TEST_CASE("void brick: mass rho_I V on its nodes, no force, and no stable step of its own",
          "[void][engine]") {
  // Cube 1 (nodes 1-8) elastic at rest gives the step; cube 2 (nodes 11-18, law 0 with rho_I = 1e-9) is
  // stretched and sheared by its initial velocities. With no force its nodes move at constant velocity:
  // x = x0 + v t to round-off, however much the element deforms.
  const double rho_v = 1e-9, v = 1000.0;
  SECTION("with a density") {
    std::string s =
        radx::test::begin_block(2026, "Mg mm s") + "/NODE\n" + cube_nodes(1, 0) + cube_nodes(11, 50);
    s += brick(1, 1, {1, 2, 3, 4, 5, 6, 7, 8}) + brick(3, 2, {11, 12, 13, 14, 15, 16, 17, 18});
    s += part(1, 1) + part(3, 3) + materials(Line().put(rho_v, 1, 20).put(1000.0, 21, 40).str() + "\n");
    s += inivel(1, v, 0, 0, {12, 13, 16, 17}) + inivel(2, 0, 0, v, {15, 18}) + "/END\n";
    const auto md = radx::test::model_of_deck(s);
    REQUIRE(md.materials[2].law == m::MaterialLaw::Void);
    // The void element's mass is rho_I V, an eighth on each node (as any brick; OpenRadioss takes PM(89)).
    const auto n11 = static_cast<std::size_t>(md.nodes.index.find(11));
    CHECK(md.node_mass[n11] == Approx(rho_v * kA * kA * kA / 8).epsilon(1e-12));
    CHECK(md.parts[1].mass == Approx(rho_v * kA * kA * kA).epsilon(1e-12));
    // Its contact stiffness uses K = E / 3 (nu blank).
    CHECK(md.materials[2].bulk == Approx(1000.0 / 3).epsilon(1e-15));
    sv::ExplicitEngine engine(md, controls(2e-3), sv::EngineOptions{1, 1});
    REQUIRE(engine.groups().bricks.size() == 1);  // only the elastic cube has a group
    double t = 0;
    engine.run([&](const sv::CycleReport& r) {
      t = r.time;
      return true;
    });
    const auto& ns = engine.nodes();
    REQUIRE(t > 0);
    // Constant velocity over 2 ms: 2 mm of stretch in X and Z on a 10 mm cube; round-off of x0 + sum v dt.
    for (int id = 11; id <= 18; ++id) {
      const auto k = static_cast<std::size_t>(md.nodes.index.find(id));
      const double vx = (id == 12 || id == 13 || id == 16 || id == 17) ? v : 0.0;
      const double vz = (id == 15 || id == 18) ? v : 0.0;
      CHECK(std::abs(ns.x[k] - (ns.x0[k] + vx * t)) <= 1e-9 * kA);
      CHECK(std::abs(ns.z[k] - (ns.z0[k] + vz * t)) <= 1e-9 * kA);
      CHECK(ns.ax[k] == 0.0);
    }
  }
  SECTION("without its card: no mass") {
    std::string s =
        radx::test::begin_block(2026, "Mg mm s") + "/NODE\n" + cube_nodes(1, 0) + cube_nodes(11, 50);
    s += brick(1, 1, {1, 2, 3, 4, 5, 6, 7, 8}) + brick(3, 2, {11, 12, 13, 14, 15, 16, 17, 18});
    s += part(1, 1) + part(3, 3) + materials("") + "/END\n";
    const auto md = radx::test::model_of_deck(s);
    REQUIRE(md.materials[2].law == m::MaterialLaw::Void);
    CHECK(md.parts[1].mass == 0.0);
    CHECK(md.materials[2].young == 0.0);
  }
}

TEST_CASE("rigid material: one body per connected set, on an added main node", "[rigid][engine]") {
  // Cubes 2 and 3 are law 13 and share no node: two bodies. Cube 1 is elastic.
  std::string s = radx::test::begin_block(2026, "Mg mm s") + "/NODE\n" + cube_nodes(1, 0) +
                  cube_nodes(11, 50) + cube_nodes(21, 100);
  s += brick(1, 1, {1, 2, 3, 4, 5, 6, 7, 8}) + brick(2, 2, {11, 12, 13, 14, 15, 16, 17, 18}) +
       brick(2, 3, {21, 22, 23, 24, 25, 26, 27, 28});
  s += part(1, 1) + part(2, 2) + materials("") + "/END\n";
  const auto md = radx::test::model_of_deck(s);
  REQUIRE(md.rigid_bodies.size() == 2);
  CHECK(md.nodes.size() == 26u);  // 24 of the deck and the 2 main nodes
  for (std::size_t b = 0; b < 2; ++b) {
    const auto& rb = md.rigid_bodies[b];
    CHECK(rb.rigid_material == 2);
    CHECK(rb.secondary.size() == 8u);
    CHECK(md.nodes.id[static_cast<std::size_t>(rb.main_node)] == 29 + static_cast<std::int64_t>(b));
    CHECK(md.nodes.id[static_cast<std::size_t>(rb.secondary.front())] ==
          11 + 10 * static_cast<std::int64_t>(b));
  }
}

TEST_CASE("rigid material in free flight: no strain, momentum and angular momentum kept", "[rigid][engine]") {
  // Cube 2 (law 13) starts with different velocities on its faces: the body takes the velocity that keeps
  // their momentum, P / M, and the angular velocity that keeps their angular momentum about the centre of
  // mass. Its lumped corner masses M/8 at +-a/2 give the isotropic I = sum m (dx^2 + dz^2) = M a^2 / 2. The
  // faces x = 50 and x = 60 move at -u and +u in Z: L_y = -sum m dx v_z = -M a u / 2, so omega_y = -u / a;
  // v = (vx, 0, 0). A free body of isotropic inertia keeps omega.
  const double u = 200.0, vx = 3000.0;
  std::string s =
      radx::test::begin_block(2026, "Mg mm s") + "/NODE\n" + cube_nodes(1, 0) + cube_nodes(11, 50);
  s += brick(1, 1, {1, 2, 3, 4, 5, 6, 7, 8}) + brick(2, 2, {11, 12, 13, 14, 15, 16, 17, 18});
  s += part(1, 1) + part(2, 2) + materials("");
  s += inivel(1, vx, 0, -u, {11, 14, 15, 18}) + inivel(2, vx, 0, u, {12, 13, 16, 17}) + "/END\n";
  const auto md = radx::test::model_of_deck(s);
  REQUIRE(md.rigid_bodies.size() == 1);
  const auto main = static_cast<std::size_t>(md.rigid_bodies[0].main_node);
  const double mass = kRho * kA * kA * kA;
  sv::ExplicitEngine engine(md, controls(1e-3), sv::EngineOptions{1, 1});
  REQUIRE(engine.groups().bricks.size() == 1);
  std::vector<std::size_t> sec;
  for (const auto n : md.rigid_bodies[0].secondary) sec.push_back(static_cast<std::size_t>(n));
  const auto& ns = engine.nodes();
  std::vector<double> d0;
  for (std::size_t i = 0; i < 8; ++i)
    for (std::size_t j = i + 1; j < 8; ++j) d0.push_back(dist(ns, sec[i], sec[j]));
  double worst_strain = 0, worst_p = 0, worst_w = 0;
  engine.run([&](const sv::CycleReport&) {
    std::size_t k = 0;
    for (std::size_t i = 0; i < 8; ++i)
      for (std::size_t j = i + 1; j < 8; ++j)
        worst_strain = std::max(worst_strain, std::abs(dist(ns, sec[i], sec[j]) / d0[k++] - 1));
    // The body's momentum M v_N, its spin omega (free rotation of a cube: I is isotropic, so omega stays).
    worst_p = std::max({worst_p, std::abs(ns.vx[main] - vx), std::abs(ns.vy[main]), std::abs(ns.vz[main])});
    worst_w =
        std::max({worst_w, std::abs(ns.wx[main]), std::abs(ns.wy[main] + u / kA), std::abs(ns.wz[main])});
    return true;
  });
  CHECK(ns.mass[main] == Approx(mass).epsilon(1e-12));
  // The exact rotation of rigid_body.cpp keeps distances to round-off (1e-12 over the 1000-odd cycles).
  CHECK(worst_strain <= 1e-12);
  // No force acts: momentum and spin stay at their initial values to round-off of the velocities.
  CHECK(worst_p <= 1e-9 * vx);
  CHECK(worst_w <= 1e-9 * u / kA);
}

TEST_CASE("rigid material: an impact passes through it as through one body", "[rigid][engine]") {
  // A rigid cube (nodes 1-8) moving at v0 in X drives an elastic cube (nodes 2, 3, 6, 7 shared, then
  // 9-12) at rest. The only forces are the elastic brick's, internal to the system: total momentum stays
  // its initial 1.5 m v0 (the shared nodes carry half the elastic brick's mass at v0) to round-off, the rigid
  // cube's nodes keep their distances, and its nodes all share the body's motion, while the elastic cube's
  // free face picks up velocity (the impact is transmitted).
  const double v0 = 5000.0;
  std::string s = radx::test::begin_block(2026, "Mg mm s") + "/NODE\n" + cube_nodes(1, 0);
  for (int k : {1, 2, 5, 6}) {  // the far face of the elastic cube at x = 2a
    const double y = (k == 2 || k == 6) ? kA : 0.0;
    s += Line()
             .put(9 + (k == 1   ? 0
                       : k == 2 ? 1
                       : k == 5 ? 2
                                : 3),
                  1, 10)
             .put(2 * kA, 11, 30)
             .put(y, 31, 50)
             .put(k >= 5 ? kA : 0.0, 51, 70)
             .str() +
         "\n";
  }
  s += brick(2, 1, {1, 2, 3, 4, 5, 6, 7, 8}) + brick(1, 2, {2, 9, 10, 3, 6, 11, 12, 7});
  s += part(1, 1) + part(2, 2) + materials("");
  s += inivel(1, v0, 0, 0, {1, 2, 3, 4, 5, 6, 7, 8}) + "/END\n";
  const auto md = radx::test::model_of_deck(s);
  REQUIRE(md.rigid_bodies.size() == 1);
  const auto main = static_cast<std::size_t>(md.rigid_bodies[0].main_node);
  // The body's mass: its brick and the elastic brick's share on the 4 shared nodes (rigid_mat.F sums the
  // nodal masses).
  const double m_brick = kRho * kA * kA * kA;
  const double p0 = 1.5 * m_brick * v0;
  sv::ExplicitEngine engine(md, controls(2e-4), sv::EngineOptions{1, 1});
  const auto& ns = engine.nodes();
  std::vector<std::size_t> sec;
  for (const auto n : md.rigid_bodies[0].secondary) sec.push_back(static_cast<std::size_t>(n));
  std::vector<std::size_t> free_face;
  for (int id : {9, 10, 11, 12}) free_face.push_back(static_cast<std::size_t>(md.nodes.index.find(id)));
  std::vector<double> d0;
  for (std::size_t i = 0; i < 8; ++i)
    for (std::size_t j = i + 1; j < 8; ++j) d0.push_back(dist(ns, sec[i], sec[j]));
  double worst_strain = 0, worst_p = 0, v_free = 0;
  engine.run([&](const sv::CycleReport&) {
    std::size_t k = 0;
    for (std::size_t i = 0; i < 8; ++i)
      for (std::size_t j = i + 1; j < 8; ++j)
        worst_strain = std::max(worst_strain, std::abs(dist(ns, sec[i], sec[j]) / d0[k++] - 1));
    // Momentum at v^{n-1/2}: the body counted once (its main node), the elastic cube's free face.
    double px = ns.mass[main] * ns.vx[main];
    for (const auto n : free_face) px += ns.mass[n] * ns.vx[n];
    worst_p = std::max(worst_p, std::abs(px / p0 - 1));
    v_free = std::max(v_free, ns.vx[free_face[0]]);
    return true;
  });
  CHECK(ns.mass[main] == Approx(1.5 * m_brick).epsilon(1e-12));
  CHECK(worst_strain <= 1e-12);
  // Round-off of some 300 cycles of sums: 1e-10 relative.
  CHECK(worst_p <= 1e-10);
  // The elastic cube is a spring between the body (1.5 m) and its free face (m/2): the face's velocity swings
  // about the centre-of-mass velocity 0.75 v0 with amplitude 0.75 v0 (27 periods of about 7 us in 0.2 ms), so
  // it passes v0: the impact went through the rigid cube.
  CHECK(v_free > v0);
}

TEST_CASE("rigid material: a node also in a /RBODY is refused by name", "[rigid]") {
  // Node 12 is a node of the law-13 cube and a secondary node of /RBODY 7 (main node 30): two rigid bodies
  // would drive it; Radioss builds a hierarchy, radx refuses (RX510 at the /RBODY's grnd_ID).
  std::string s = radx::test::begin_block(2026, "Mg mm s") + "/NODE\n" + cube_nodes(1, 0) +
                  cube_nodes(11, 50) + Line().put(30, 1, 10).put(80.0, 11, 30).str() + "\n";
  s += brick(1, 1, {1, 2, 3, 4, 5, 6, 7, 8}) + brick(2, 2, {11, 12, 13, 14, 15, 16, 17, 18});
  s += part(1, 1) + part(2, 2) + materials("");
  s += "/GRNOD/NODE/9\nbody nodes\n" + Line().put(12, 1, 10).str() + "\n";
  s += "/RBODY/7\nbody\n" + Line().put(30, 1, 10).put(9, 61, 70).str() + "\n\n\n/END\n";
  radx::test::TempDir dir;
  radx::Diagnostics diags;
  const auto deck = radx::read_starter_deck(dir.write("m_0000.rad", s), diags);
  (void)radx::build_model(deck, diags);
  bool found = false;
  for (const auto& d : diags.items()) {
    const std::string text = radx::Diagnostics::format(d);
    INFO(text);
    if (text.find("RX510") != std::string::npos && text.find("node 12 of /RBODY 7") != std::string::npos &&
        text.find("/MAT/RIGID 2") != std::string::npos)
      found = true;
  }
  CHECK(found);
}

TEST_CASE("rigid material: a /BCS on one of its nodes is refused by name", "[rigid]") {
  // OpenRadioss constrains the body through a held node; radx's body would overwrite the node's motion.
  std::string s =
      radx::test::begin_block(2026, "Mg mm s") + "/NODE\n" + cube_nodes(1, 0) + cube_nodes(11, 50);
  s += brick(1, 1, {1, 2, 3, 4, 5, 6, 7, 8}) + brick(2, 2, {11, 12, 13, 14, 15, 16, 17, 18});
  s += part(1, 1) + part(2, 2) + materials("");
  s += "/GRNOD/NODE/9\nheld\n" + Line().put(13, 1, 10).str() + "\n";
  s += "/BCS/4\nheld\n" + Line().put("111 000", 1, 10).put(0, 11, 20).put(9, 21, 30).str() + "\n/END\n";
  radx::test::TempDir dir;
  radx::Diagnostics diags;
  const auto deck = radx::read_starter_deck(dir.write("m_0000.rad", s), diags);
  (void)radx::build_model(deck, diags);
  bool found = false;
  for (const auto& d : diags.items()) {
    const std::string text = radx::Diagnostics::format(d);
    INFO(text);
    if (text.find("RX510") != std::string::npos && text.find("/BCS on node 13") != std::string::npos)
      found = true;
  }
  CHECK(found);
}

TEST_CASE("rigid material: an element naming a missing node is reported, not gathered into a body",
          "[rigid]") {
  // The brick of law 13 names node 99, which no /NODE line defines: the starter reports it
  // (ElementNodeMissing) and leaves the slot empty; the rigid sets must not read that slot (a fuzzed deck
  // found the index -1).
  std::string s =
      radx::test::begin_block(2026, "Mg mm s") + "/NODE\n" + cube_nodes(1, 0) + cube_nodes(11, 50);
  s += brick(1, 1, {1, 2, 3, 4, 5, 6, 7, 8}) + brick(2, 2, {11, 12, 13, 14, 15, 16, 17, 99});
  s += part(1, 1) + part(2, 2) + materials("") + "/END\n";
  radx::test::TempDir dir;
  radx::Diagnostics diags;
  const auto deck = radx::read_starter_deck(dir.write("m_0000.rad", s), diags);
  const auto md = radx::build_model(deck, diags);
  int missing = 0;
  for (const auto& d : diags.items()) {
    const std::string text = radx::Diagnostics::format(d);
    INFO(text);
    if (text.find("uses node 99") != std::string::npos) ++missing;
  }
  CHECK(missing == 1);
  CHECK(md.rigid_bodies.empty());  // the only law-13 element is incomplete
}
