// /INTER/TYPE2 kinematic tie (solver/conditions/tied_type2.hpp, parser/building/build_tied.cpp): the
// starter's projection and its diagnostics, the force transfer's balance and virtual work, and a tied pair of
// bricks turned 90 degrees through the whole engine. The tied cantilever (bending as one beam) is in
// test_verification.cpp.
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "parser/building/model_builder.hpp"
#include "parser/reading/deck.hpp"
#include "solver/conditions/tied_type2.hpp"
#include "solver/engine/explicit_engine.hpp"
#include "solver/model/tied_map.hpp"
#include "test_util.hpp"

namespace md = radx::model;
namespace sv = radx::solver;
using radx::test::Line;

namespace {

// Brick A on [0,1]^3 (nodes 1-8), brick B on [0.2,0.8] x [0.3,0.7] x [1+gap, 1.5+gap] (nodes 11-18); B's
// bottom nodes tied to A's top face (5 6 7 8, normal +z). kg, m, s; steel, nu = 0.3. The TYPE2's Ignore,
// Spotflag and Dsearch are fields here; `extra`: more keywords before /END.
struct TiedPair {
  double gap = 0.05;
  int ignore = 0, spotflag = 0;
  double dsearch = 0;
  std::string extra;
  std::string deck() const {
    std::ostringstream os;
    const double a[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                            {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    const double b[8][3] = {{0.2, 0.3, 0},   {0.8, 0.3, 0},   {0.8, 0.7, 0},   {0.2, 0.7, 0},
                            {0.2, 0.3, 0.5}, {0.8, 0.3, 0.5}, {0.8, 0.7, 0.5}, {0.2, 0.7, 0.5}};
    Line e1, e2;
    e1.put(1, 1, 10);
    e2.put(2, 1, 10);
    for (int k = 0; k < 8; ++k) {
      e1.put(k + 1, 11 + 10 * k, 20 + 10 * k);
      e2.put(k + 11, 11 + 10 * k, 20 + 10 * k);
    }
    os << radx::test::begin_block(2026, "kg m s") << "/NODE\n";
    for (int k = 0; k < 8; ++k)
      os << Line().put(k + 1, 1, 10).put(a[k][0], 11, 30).put(a[k][1], 31, 50).put(a[k][2], 51, 70).str()
         << '\n';
    for (int k = 0; k < 8; ++k)
      os << Line()
                .put(k + 11, 1, 10)
                .put(b[k][0], 11, 30)
                .put(b[k][1], 31, 50)
                .put(1.0 + gap + b[k][2], 51, 70)
                .str()
         << '\n';
    os << "/BRICK/1\n" << e1.str() << '\n' << "/BRICK/2\n" << e2.str() << '\n';
    os << "/PART/1\nA\n" << Line().put(1, 1, 10).put(1, 11, 20).str() << '\n';
    os << "/PART/2\nB\n" << Line().put(1, 1, 10).put(1, 11, 20).str() << '\n';
    os << "/PROP/SOLID/1\nbrick\n" << Line().put(24, 1, 10).str() << "\n\n";
    os << "/MAT/LAW1/1\nsteel\n"
       << Line().put(7850.0, 1, 20).str() << '\n'
       << Line().put(2.1e11, 1, 20).put(0.3, 21, 40).str() << '\n';
    os << "/GRNOD/NODE/1\ntied\n"
       << Line().put(11, 1, 10).put(12, 11, 20).put(13, 21, 30).put(14, 31, 40).str() << '\n';
    os << "/SURF/SEG/2\ntop of A\n"
       << Line().put(1, 1, 10).put(5, 11, 20).put(6, 21, 30).put(7, 31, 40).put(8, 41, 50).str() << '\n';
    os << "/INTER/TYPE2/7\nB on A\n"
       << Line()
              .put(1, 1, 10)
              .put(2, 11, 20)
              .put(ignore, 21, 30)
              .put(spotflag, 31, 40)
              .put(dsearch, 81, 100)
              .str()
       << '\n';
    os << extra << "/END\n";
    return os.str();
  }
};

radx::model::Model build(const std::string& text, radx::Diagnostics& diags) {
  radx::test::TempDir dir;
  const auto deck = radx::read_starter_deck(dir.write("t_0000.rad", text), diags);
  return radx::build_model(deck, diags);
}

std::string all_diags(const radx::Diagnostics& d) {
  std::string s;
  for (const auto& x : d.items()) s += radx::Diagnostics::format(x) + "\n";
  return s;
}

md::Vec3 pos(const sv::NodeState& s, std::size_t n) {
  return {s.x[n], s.y[n], s.z[n]};
}

}  // namespace

TEST_CASE("TYPE2 starter: each node projected once on its segment, with its normal offset", "[tied]") {
  TiedPair p;
  radx::Diagnostics d;
  const auto m = build(p.deck(), d);
  INFO(all_diags(d));
  REQUIRE_FALSE(d.has_errors());
  REQUIRE(m.tied_interfaces.size() == 1);
  const auto& t = m.tied_interfaces[0];
  CHECK(t.id == 7);
  // Automatic distance: the r.m.s. edge of the unit square segment.
  CHECK(t.search_distance == Approx(1.0).epsilon(1e-14));
  REQUIRE(t.tie_node.size() == 4);
  CHECK(t.not_found.empty());
  // Node 11 at (0.2, 0.3): r = 2x - 1 = -0.6, s = 2y - 1 = -0.4; offset +gap along the +z normal.
  CHECK(m.nodes.id[static_cast<std::size_t>(t.tie_node[0])] == 11);
  CHECK(t.tie_r[0] == Approx(-0.6).margin(1e-12));
  CHECK(t.tie_s[0] == Approx(-0.4).margin(1e-12));
  for (const double off : t.tie_offset) CHECK(off == Approx(p.gap).margin(1e-12));
}

TEST_CASE("TYPE2 starter: nodes beyond the search distance are listed, error or warning by Ignore",
          "[tied]") {
  TiedPair p;
  p.dsearch = 0.01;  // below the 0.05 gap
  SECTION("Ignore = 0: an error naming the nodes (OpenRadioss message 1078)") {
    radx::Diagnostics d;
    build(p.deck(), d);
    const std::string all = all_diags(d);
    INFO(all);
    CHECK(d.has_errors());
    CHECK(all.find("RX705") != std::string::npos);
    CHECK(all.find("11 12 13 14") != std::string::npos);
    CHECK(all.find("/INTER/TYPE2") != std::string::npos);
  }
  SECTION("Ignore = 1: a warning naming the nodes, which stay untied (message 1157)") {
    p.ignore = 1;
    radx::Diagnostics d;
    const auto m = build(p.deck(), d);
    const std::string all = all_diags(d);
    INFO(all);
    CHECK_FALSE(d.has_errors());
    CHECK(all.find("RX705") != std::string::npos);
    REQUIRE(m.tied_interfaces.size() == 1);
    CHECK(m.tied_interfaces[0].tie_node.empty());
    CHECK(m.tied_interfaces[0].not_found == std::vector<std::int64_t>{11, 12, 13, 14});
  }
}

TEST_CASE("TYPE2 starter: a refused Spotflag and a /BCS on a tied node", "[tied]") {
  SECTION("Spotflag 27 is refused by name") {
    TiedPair p;
    p.spotflag = 27;
    radx::Diagnostics d;
    build(p.deck(), d);
    const std::string all = all_diags(d);
    INFO(all);
    CHECK(d.has_errors());
    CHECK(all.find("RX510") != std::string::npos);
    CHECK(all.find("Spotflag = 27") != std::string::npos);
    CHECK(all.find("switches to penalty") != std::string::npos);
  }
  SECTION("a /TH/INTER naming the TYPE2: left out with a warning (radx writes no tied-interface history)") {
    TiedPair p;
    p.extra = "/TH/INTER/3\nties\nDEF\n" + Line().put(7, 1, 10).str() + "\n";
    radx::Diagnostics d;
    build(p.deck(), d);
    const std::string all = all_diags(d);
    INFO(all);
    CHECK_FALSE(d.has_errors());
    CHECK(all.find("RX311") != std::string::npos);
    CHECK(all.find("interface 7 is an /INTER/TYPE2") != std::string::npos);
  }
  SECTION("a /BCS on a tied node: the OpenRadioss warning of incompatible kinematic conditions") {
    TiedPair p;
    p.extra = "/GRNOD/NODE/9\nfixed\n" + Line().put(11, 1, 10).str() + "\n/BCS/1\nfix\n" +
              Line().put("111 000", 1, 10).put(9, 21, 30).str() + "\n";
    radx::Diagnostics d;
    build(p.deck(), d);
    const std::string all = all_diags(d);
    INFO(all);
    CHECK_FALSE(d.has_errors());
    CHECK(all.find("RX706") != std::string::npos);
    CHECK(all.find("/BCS/1") != std::string::npos);
  }
}

// The force transfer is the transpose of the map's derivative: for any segment motion delta x_j, the work
// of the transferred forces equals the work of f_s on the secondary's motion delta x_s (the tie does no
// work), and the forces and their moment are those of f_s at x_s (momentum and angular momentum kept).
TEST_CASE("TYPE2 force transfer: balance of forces and moments, no work (virtual work)", "[tied]") {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const bool triangle : {false, true}) {
    for (int trial = 0; trial < 20; ++trial) {
      md::Model m;
      // A warped segment (nodes off the plane by up to 0.1) and a secondary node off it by up to 0.3.
      std::array<md::Vec3, 4> x{md::Vec3{0, 0, 0}, md::Vec3{1, 0, 0}, md::Vec3{1, 1, 0}, md::Vec3{0, 1, 0}};
      for (auto& p : x)
        for (auto& c : p) c += 0.1 * u(rng);
      if (triangle) x[3] = x[2];
      const double r = 0.8 * u(rng), s = triangle ? 0.3 + 0.2 * u(rng) : 0.8 * u(rng);
      const double rr = triangle ? 0.3 + 0.2 * u(rng) : r;
      const double d = 0.3 * u(rng);
      const auto h = md::tie_shape(rr, s, triangle);
      auto place = [&](const std::array<md::Vec3, 4>& y) {
        const auto nn = md::tie_normal(y, triangle);
        md::Vec3 q = md::scale(nn, d / md::norm(nn));
        for (std::size_t j = 0; j < 4; ++j) q = md::add(q, md::scale(y[j], h[j]));
        return q;
      };
      const md::Vec3 xs = place(x);
      for (std::size_t k = 0; k < 5; ++k) {
        const md::Vec3 q = k < 4 ? x[k] : xs;
        m.nodes.id.push_back(static_cast<std::int64_t>(k + 1));
        m.nodes.x.push_back(q[0]);
        m.nodes.y.push_back(q[1]);
        m.nodes.z.push_back(q[2]);
      }
      md::TiedInterface t;
      t.tie_node = {4};
      t.tie_segment = {triangle ? std::array<std::int32_t, 4>{0, 1, 2, 2}
                                : std::array<std::int32_t, 4>{0, 1, 2, 3}};
      t.tie_r = {rr};
      t.tie_s = {s};
      t.tie_offset = {d};
      m.tied_interfaces.push_back(t);
      sv::TiedInterfaces ties(m);
      sv::NodeState st;
      st.resize(5);
      for (std::size_t n = 0; n < 5; ++n) {
        st.x[n] = m.nodes.x[n];
        st.y[n] = m.nodes.y[n];
        st.z[n] = m.nodes.z[n];
      }
      const md::Vec3 f{u(rng), u(rng), u(rng)};
      st.fx[4] = f[0];
      st.fy[4] = f[1];
      st.fz[4] = f[2];
      ties.transfer_forces(st);
      md::Vec3 fsum{}, msum{};
      for (std::size_t n = 0; n < 4; ++n) {
        const md::Vec3 fj{st.fx[n], st.fy[n], st.fz[n]};
        fsum = md::add(fsum, fj);
        msum = md::add(msum, md::cross(pos(st, n), fj));
      }
      CHECK(st.fx[4] == 0.0);
      // Round-off of a few products of unit-size numbers.
      const md::Vec3 mref = md::cross(xs, f);
      for (std::size_t c = 0; c < 3; ++c) {
        CHECK(fsum[c] == Approx(f[c]).margin(1e-13));
        CHECK(msum[c] == Approx(mref[c]).margin(1e-12));
      }
      // Virtual work: central difference of the map along a random motion, step 1e-6 (error ~1e-12).
      std::array<md::Vec3, 4> dx{}, xp = x, xm = x;
      for (std::size_t j = 0; j < 4; ++j) {
        dx[j] = {u(rng), u(rng), u(rng)};
        if (triangle && j == 3) dx[3] = dx[2];
      }
      const double eps = 1e-6;
      for (std::size_t j = 0; j < 4; ++j) {
        xp[j] = md::add(x[j], md::scale(dx[j], eps));
        xm[j] = md::sub(x[j], md::scale(dx[j], eps));
      }
      const md::Vec3 dxs = md::scale(md::sub(place(xp), place(xm)), 0.5 / eps);
      double w_main = 0;
      for (std::size_t j = 0; j < (triangle ? 3u : 4u); ++j)
        w_main += st.fx[j] * dx[j][0] + st.fy[j] * dx[j][1] + st.fz[j] * dx[j][2];
      CHECK(w_main == Approx(md::dot(f, dxs)).margin(1e-8));
    }
  }
}

// Two bricks tied with an offset spin freely about Y through 90 degrees (a rigid rotation given as the
// initial velocity of every node): at the end the tied nodes are where the rotation puts them, their normal
// offset from A's top face is unchanged, momentum is kept and the energy balance holds (the tie does no
// work).
TEST_CASE("TYPE2 in the engine: tied nodes keep their offsets through a 90 degree rigid rotation", "[tied]") {
  TiedPair p;
  p.gap = 0.05;
  const double omega = 20.0;  // rad/s about Y through the centre of mass c
  // About the centre of mass (one density: A's unit volume at z = 0.5, B's 0.12 at z = 1.3), which then stays
  // at rest: the motion is the rotation alone.
  const md::Vec3 c{0.5, 0.5, (0.5 + 0.12 * 1.3) / 1.12};
  const double t_stop = 0.5 * std::numbers::pi / omega;
  // One group and one /INIVEL/TRA per node: v = omega e_y x (x - c).
  const double nodes[16][4] = {
      {1, 0, 0, 0},         {2, 1, 0, 0},         {3, 1, 1, 0},         {4, 0, 1, 0},
      {5, 0, 0, 1},         {6, 1, 0, 1},         {7, 1, 1, 1},         {8, 0, 1, 1},
      {11, 0.2, 0.3, 1.05}, {12, 0.8, 0.3, 1.05}, {13, 0.8, 0.7, 1.05}, {14, 0.2, 0.7, 1.05},
      {15, 0.2, 0.3, 1.55}, {16, 0.8, 0.3, 1.55}, {17, 0.8, 0.7, 1.55}, {18, 0.2, 0.7, 1.55}};
  for (const auto& n : nodes) {
    const int id = static_cast<int>(n[0]);
    const double vx = omega * (n[3] - c[2]), vz = -omega * (n[1] - c[0]);
    p.extra += "/GRNOD/NODE/" + std::to_string(100 + id) + "\nn\n" + Line().put(id, 1, 10).str() + "\n";
    p.extra += "/INIVEL/TRA/" + std::to_string(100 + id) + "\nv\n" +
               Line().put(vx, 1, 20).put(0.0, 21, 40).put(vz, 41, 60).put(100 + id, 61, 70).str() + "\n\n";
  }
  radx::Diagnostics d;
  const auto m = build(p.deck(), d);
  INFO(all_diags(d));
  REQUIRE_FALSE(d.has_errors());
  md::RunControls rc;
  rc.t_stop = t_stop;
  rc.global.scale = 0.9;
  sv::ExplicitEngine eng(m, rc, sv::EngineOptions{1});
  const auto& t = m.tied_interfaces.at(0);
  double worst_error = 0, mass = 0;
  std::array<double, 3> p0{}, pmax{};
  bool first = true;
  const auto res = eng.run([&](const sv::CycleReport& r) {
    if (!r.full) return true;
    worst_error = std::max(worst_error, std::abs(r.energy.error_percent));
    if (first) p0 = r.momentum;
    first = false;
    for (std::size_t k = 0; k < 3; ++k) pmax[k] = std::max(pmax[k], std::abs(r.momentum[k] - p0[k]));
    mass = r.mass;
    return true;
  });
  REQUIRE(res.status == sv::RunStatus::Normal);
  CHECK(res.time == Approx(t_stop));
  const auto& s = eng.nodes();
  // R(90 deg about Y): (x, y, z) - c -> (z, y, -x).
  for (std::size_t k = 0; k < t.tie_node.size(); ++k) {
    const auto n = static_cast<std::size_t>(t.tie_node[k]);
    const md::Vec3 r0 = md::sub(md::Vec3{m.nodes.x[n], m.nodes.y[n], m.nodes.z[n]}, c);
    const md::Vec3 expect = md::add(c, md::Vec3{r0[2], r0[1], -r0[0]});
    // Where the rotation puts the node, to 1 cm on the 1 m block: the tie's mass lumping moves the tied
    // nodes' mass (a quarter of B's) from the offset onto A's face at t = 0, which changes the assembly's
    // moment of inertia and momentum by a few 0.1 % and so the angle turned (measured: 0.35 %, 3 mm).
    for (std::size_t c3 = 0; c3 < 3; ++c3) CHECK(pos(s, n)[c3] == Approx(expect[c3]).margin(1e-2));
    // The offset is carried exactly: the node is at its place on the map of the current segment to
    // round-off (1e-12 m), and its distance from the face along the face's normal is still the gap.
    std::array<md::Vec3, 4> xs{};
    for (std::size_t j = 0; j < 4; ++j) xs[j] = pos(s, static_cast<std::size_t>(t.tie_segment[k][j]));
    const auto nn = md::tie_normal(xs, false);
    const auto h = md::tie_shape(t.tie_r[k], t.tie_s[k], false);
    md::Vec3 base{};
    for (std::size_t j = 0; j < 4; ++j) base = md::add(base, md::scale(xs[j], h[j]));
    const double dn = md::dot(md::sub(pos(s, n), base), md::scale(nn, 1.0 / md::norm(nn)));
    CHECK(dn == Approx(p.gap).margin(1e-12));
    CHECK(md::norm(md::sub(pos(s, n), md::add(base, md::scale(nn, p.gap / md::norm(nn))))) < 1e-12);
  }
  // A's top face has turned 90 degrees about Y: its normal, +z at the start, is now along +x (the angle to
  // within 0.01 rad, the lumping above).
  {
    std::array<md::Vec3, 4> xa{};
    for (std::size_t j = 0; j < 4; ++j) xa[j] = pos(s, static_cast<std::size_t>(t.tie_segment[0][j]));
    const auto nn = md::tie_normal(xa, false);
    CHECK(nn[0] / md::norm(nn) > std::cos(0.01));
  }
  // Momentum: no external force; the tie moves momentum between nodes only. Round-off of m v ~ 1e4 kg m/s.
  for (std::size_t k = 0; k < 3; ++k) CHECK(pmax[k] < 1e-7 * mass * omega);
  // Energy balance: the tie does no work; the remaining error is the central difference's on a rotation.
  CHECK(worst_error < 0.1);
}

// ---------------------------------------------------------------------------------------------------------
// Spotflag 1, the rigid tie (solver/conditions/tied_type2.hpp). The map is x_s = c + R q0 with R the
// least-squares rotation of the segment's nodes about their centroid c; the forces go back by its transpose.
namespace {

// A model of one tie: nodes 0..3 the segment (n4 = n3 for a triangle), node 4 the secondary, and one spring
// so that the model has rotational degrees of freedom (without them Spotflag 1 is the standard tie).
md::Model rigid_tie_model(const std::array<md::Vec3, 4>& x, const md::Vec3& xs, bool triangle) {
  md::Model m;
  for (std::size_t k = 0; k < 5; ++k) {
    const md::Vec3 q = k < 4 ? x[k] : xs;
    m.nodes.id.push_back(static_cast<std::int64_t>(k + 1));
    m.nodes.x.push_back(q[0]);
    m.nodes.y.push_back(q[1]);
    m.nodes.z.push_back(q[2]);
  }
  m.springs.id.push_back(1);
  md::TiedInterface t;
  t.spotflag = 1;
  t.tie_node = {4};
  t.tie_segment = {triangle ? std::array<std::int32_t, 4>{0, 1, 2, 2}
                            : std::array<std::int32_t, 4>{0, 1, 2, 3}};
  t.tie_r = {0.0};  // (r, s, d) are not used by the rigid tie
  t.tie_s = {0.0};
  t.tie_offset = {0.0};
  m.tied_interfaces.push_back(t);
  return m;
}

sv::NodeState state_of(const md::Model& m) {
  sv::NodeState st;
  st.resize(m.nodes.x.size());
  for (std::size_t n = 0; n < st.n; ++n) {
    st.x[n] = st.x0[n] = m.nodes.x[n];
    st.y[n] = st.y0[n] = m.nodes.y[n];
    st.z[n] = st.z0[n] = m.nodes.z[n];
  }
  return st;
}

// The secondary's displacement and rotation when the segment's nodes move by y_j - x_j in one step, read
// from secondary_kinematics (dt1 = dt2 = 1: v^{n+1/2} = target - x_s, w^{n+1/2} = log(R^{n+1} R^{nT})).
std::pair<md::Vec3, md::Vec3> rigid_step(const md::Model& m, const std::array<md::Vec3, 4>& y) {
  sv::TiedInterfaces ties(m);
  auto st = state_of(m);
  for (std::size_t j = 0; j < 4; ++j) {
    st.vx[j] = y[j][0] - st.x[j];
    st.vy[j] = y[j][1] - st.y[j];
    st.vz[j] = y[j][2] - st.z[j];
  }
  ties.secondary_kinematics(st, 1.0, 1.0);
  return {{st.ax[4], st.ay[4], st.az[4]}, {st.awx[4], st.awy[4], st.awz[4]}};
}

}  // namespace

TEST_CASE("TYPE2 Spotflag 1 force transfer: balance of forces and moments, no work (virtual work)",
          "[tied]") {
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const bool triangle : {false, true}) {
    for (int trial = 0; trial < 20; ++trial) {
      // A warped segment and a secondary node anywhere near it: beside it, off its plane, beyond its edges.
      std::array<md::Vec3, 4> x{md::Vec3{0, 0, 0}, md::Vec3{1, 0, 0}, md::Vec3{1, 1, 0}, md::Vec3{0, 1, 0}};
      for (auto& p : x)
        for (auto& c : p) c += 0.1 * u(rng);
      if (triangle) x[3] = x[2];
      const md::Vec3 xs{0.5 + u(rng), 0.5 + u(rng), 0.5 * u(rng)};
      const auto m = rigid_tie_model(x, xs, triangle);
      sv::TiedInterfaces ties(m);
      REQUIRE(ties.rigid_size() == 1);
      auto st = state_of(m);
      const md::Vec3 f{u(rng), u(rng), u(rng)}, mo{u(rng), u(rng), u(rng)};
      st.fx[4] = f[0], st.fy[4] = f[1], st.fz[4] = f[2];
      st.mx[4] = mo[0], st.my[4] = mo[1], st.mz[4] = mo[2];
      ties.transfer_forces(st);
      CHECK(st.fx[4] == 0.0);
      CHECK(st.mx[4] == 0.0);
      md::Vec3 fsum{}, msum{};
      for (std::size_t n = 0; n < (triangle ? 3u : 4u); ++n) {
        const md::Vec3 fj{st.fx[n], st.fy[n], st.fz[n]};
        fsum = md::add(fsum, fj);
        msum = md::add(msum, md::cross(pos(st, n), fj));
        CHECK(st.mx[n] == 0.0);  // the main nodes' rotations receive nothing (I2FOMO3)
      }
      // The secondary's force, and its moment about the origin (its couple included), carried by forces only.
      const md::Vec3 mref = md::add(md::cross(xs, f), mo);
      for (std::size_t c = 0; c < 3; ++c) {
        CHECK(fsum[c] == Approx(f[c]).margin(1e-13));
        CHECK(msum[c] == Approx(mref[c]).margin(1e-12));
      }
      // Virtual work f_s . dx_s + m_s . dtheta = sum f_j . dx_j, the map's derivative by a central difference
      // of the engine's own placement (step 1e-6: error ~1e-12 and round-off ~1e-10).
      std::array<md::Vec3, 4> dx{}, xp = x, xm = x;
      for (std::size_t j = 0; j < 4; ++j) dx[j] = {u(rng), u(rng), u(rng)};
      if (triangle) dx[3] = dx[2];
      const double eps = 1e-6;
      for (std::size_t j = 0; j < 4; ++j) {
        xp[j] = md::add(x[j], md::scale(dx[j], eps));
        xm[j] = md::sub(x[j], md::scale(dx[j], eps));
      }
      const auto [up, tp] = rigid_step(m, xp);
      const auto [um, tm] = rigid_step(m, xm);
      const md::Vec3 dxs = md::scale(md::sub(up, um), 0.5 / eps), dth = md::scale(md::sub(tp, tm), 0.5 / eps);
      double w_main = 0;
      for (std::size_t j = 0; j < (triangle ? 3u : 4u); ++j)
        w_main += st.fx[j] * dx[j][0] + st.fy[j] * dx[j][1] + st.fz[j] * dx[j][2];
      CHECK(w_main == Approx(md::dot(f, dxs) + md::dot(mo, dth)).margin(1e-8));
    }
  }
}

// What makes the tie rigid: the node keeps its place in the segment's fitted frame whatever the segment does.
// Under a rigid motion (here 90 degrees about a skew axis, in 90 steps of one degree) R is that rotation
// exactly and the node, 0.4 off the segment's plane, turns with it; under an in-plane stretch of the segment
// the fitted rotation is the identity and the node keeps its distance from the centroid (the standard tie
// would stretch its in-plane offset with the segment).
TEST_CASE(
    "TYPE2 Spotflag 1 map: a node off the plane follows a rigid turn exactly, a stretch does not move it",
    "[tied]") {
  const std::array<md::Vec3, 4> x{md::Vec3{0, 0, 0}, md::Vec3{2, 0, 0}, md::Vec3{2, 1, 0}, md::Vec3{0, 1, 0}};
  const md::Vec3 c{1, 0.5, 0}, xs{1.7, 0.1, 0.4};  // 0.4 off the plane, 0.8 beside the centre
  const auto m = rigid_tie_model(x, xs, false);
  sv::TiedInterfaces ties(m);
  auto st = state_of(m);
  SECTION("90 degrees about a skew axis through a moving point") {
    const md::Vec3 axis = md::scale(md::Vec3{1, 2, 2}, 1.0 / 3.0), shift{0.3, -0.2, 0.5};
    auto rotate = [&](const md::Vec3& p, double a) {  // Rodrigues
      const md::Vec3 r = md::sub(p, c);
      const md::Vec3 rr =
          md::add(md::add(md::scale(r, std::cos(a)), md::scale(md::cross(axis, r), std::sin(a))),
                  md::scale(axis, md::dot(axis, r) * (1 - std::cos(a))));
      return md::add(md::add(c, md::scale(shift, a)), rr);
    };
    const int steps = 90;
    const double da = 0.5 * std::numbers::pi / steps;
    for (int i = 1; i <= steps; ++i) {
      for (std::size_t j = 0; j < 4; ++j) {
        const md::Vec3 y = rotate(x[j], i * da);
        st.vx[j] = y[0] - st.x[j], st.vy[j] = y[1] - st.y[j], st.vz[j] = y[2] - st.z[j];
        st.ax[j] = st.ay[j] = st.az[j] = 0;
      }
      ties.secondary_kinematics(st, 1.0, 1.0);  // dt = 1: the step's displacement is v + a
      for (std::size_t n = 0; n < 5; ++n) {
        st.vx[n] += st.ax[n], st.vy[n] += st.ay[n], st.vz[n] += st.az[n];
        st.wx[n] += st.awx[n], st.wy[n] += st.awy[n], st.wz[n] += st.awz[n];
        st.x[n] += st.vx[n], st.y[n] += st.vy[n], st.z[n] += st.vz[n];
      }
      // The node's rotation rate is the segment's: da about the axis each step (round-off of the log).
      for (std::size_t k = 0; k < 3; ++k)
        CHECK(md::Vec3{st.wx[4], st.wy[4], st.wz[4]}[k] == Approx(da * axis[k]).margin(1e-12));
    }
    const md::Vec3 expect = rotate(xs, 0.5 * std::numbers::pi);
    // The offset turned with the segment to round-off of 90 products of rotations on unit lengths.
    for (std::size_t k = 0; k < 3; ++k) CHECK(pos(st, 4)[k] == Approx(expect[k]).margin(1e-12));
  }
  SECTION("a turn of 90, 150 and 179 degrees in one step: the fit still finds it") {
    const md::Vec3 axis = md::scale(md::Vec3{2, -1, 2}, 1.0 / 3.0);
    for (const double deg : {90.0, 150.0, 179.0}) {
      const double a = deg * std::numbers::pi / 180.0;
      auto rotate = [&](const md::Vec3& p) {
        const md::Vec3 r = md::sub(p, c);
        return md::add(c,
                       md::add(md::add(md::scale(r, std::cos(a)), md::scale(md::cross(axis, r), std::sin(a))),
                               md::scale(axis, md::dot(axis, r) * (1 - std::cos(a)))));
      };
      std::array<md::Vec3, 4> y{};
      for (std::size_t j = 0; j < 4; ++j) y[j] = rotate(x[j]);
      const auto [moved, turned] = rigid_step(m, y);
      const md::Vec3 expect = md::sub(rotate(xs), xs);
      INFO(deg << " degrees");
      for (std::size_t k = 0; k < 3; ++k) {
        CHECK(moved[k] == Approx(expect[k]).margin(1e-12));
        CHECK(turned[k] == Approx(a * axis[k]).margin(1e-12));
      }
    }
  }
  SECTION("an in-plane stretch by 10 % along the segment's long side") {
    std::array<md::Vec3, 4> y = x;
    for (auto& p : y) p[0] = c[0] + 1.1 * (p[0] - c[0]);
    for (std::size_t j = 0; j < 4; ++j) st.vx[j] = y[j][0] - st.x[j];
    ties.secondary_kinematics(st, 1.0, 1.0);
    const md::Vec3 moved{st.vx[4] + st.ax[4], st.vy[4] + st.ay[4], st.vz[4] + st.az[4]};
    // The centroid does not move and the fitted rotation is the identity: the node stays (round-off).
    for (std::size_t k = 0; k < 3; ++k) CHECK(moved[k] == Approx(0.0).margin(1e-14));
  }
}

// The brick pair of the tests above tied by Spotflag 1, with the tied nodes 0.2 above A's top face and a free
// spring far away (rotational degrees of freedom in the model), spinning freely about Y through 90 degrees.
TEST_CASE(
    "TYPE2 Spotflag 1 in the engine: offsets, rotation, added mass, momentum and energy through a 90 degree "
    "turn",
    "[tied]") {
  TiedPair p;
  p.gap = 0.2;
  p.spotflag = 1;
  const double omega = 20.0;
  // Centre of mass of the two bricks (one density): A's unit volume at z = 0.5, B's 0.12 at z = 1.45.
  const md::Vec3 c{0.5, 0.5, (0.5 + 0.12 * 1.45) / 1.12};
  const double t_stop = 0.5 * std::numbers::pi / omega;
  p.extra = "/NODE\n" + Line().put(901, 1, 10).put(5.0, 11, 30).put(0.0, 31, 50).put(0.0, 51, 70).str() +
            "\n" + Line().put(902, 1, 10).put(5.1, 11, 30).put(0.0, 31, 50).put(0.0, 51, 70).str() + "\n" +
            "/SPRING/3\n" + Line().put(1, 1, 10).put(901, 11, 20).put(902, 21, 30).str() + "\n" +
            "/PART/3\nfree spring\n" + Line().put(3, 1, 10).put(0, 11, 20).str() + "\n" +
            "/PROP/SPRING/3\nfree spring\n" + Line().put(1e-3, 1, 20).str() + "\n" +
            Line().put(1.0, 1, 20).str() + "\n\n\n";
  for (int id = 1; id <= 18; ++id) {
    if (id > 8 && id < 11) continue;
    const double x = (id <= 8) ? ((id == 2 || id == 3 || id == 6 || id == 7) ? 1.0 : 0.0)
                               : ((id == 12 || id == 13 || id == 16 || id == 17) ? 0.8 : 0.2);
    const double z = id <= 4 ? 0.0 : id <= 8 ? 1.0 : id <= 14 ? 1.0 + p.gap : 1.5 + p.gap;
    const double vx = omega * (z - c[2]), vz = -omega * (x - c[0]);
    p.extra += "/GRNOD/NODE/" + std::to_string(100 + id) + "\nn\n" + Line().put(id, 1, 10).str() + "\n";
    p.extra += "/INIVEL/TRA/" + std::to_string(100 + id) + "\nv\n" +
               Line().put(vx, 1, 20).put(0.0, 21, 40).put(vz, 41, 60).put(100 + id, 61, 70).str() + "\n\n";
  }
  radx::Diagnostics d;
  const auto m = build(p.deck(), d);
  INFO(all_diags(d));
  REQUIRE_FALSE(d.has_errors());
  md::RunControls rc;
  rc.t_stop = t_stop;
  rc.global.scale = 0.9;
  sv::ExplicitEngine eng(m, rc, sv::EngineOptions{1});
  const auto& t = m.tied_interfaces.at(0);
  REQUIRE(t.tie_node.size() == 4);
  // Added mass, closed form: A's top face about its centre has J0 = diag(1, 1, 2) (lambda_min = 1), so each
  // tied node of mass m_s (an eighth of B: 0.6 x 0.4 x 0.5 x 7850 / 8) adds m_s |q0|^2 on each of the four
  // face nodes, q0 its offset from the face's centre (0.3, 0.2, 0.2 in size for every node).
  const double m_s = 0.6 * 0.4 * 0.5 * 7850.0 / 8.0;
  const double added_expect = 4.0 * 4.0 * m_s * (0.3 * 0.3 + 0.2 * 0.2 + p.gap * p.gap);
  double worst_error = 0, mass = 0, added = 0, mass0 = 0;
  std::array<double, 3> p0{}, pmax{};
  bool first = true;
  const auto res = eng.run([&](const sv::CycleReport& r) {
    if (!r.full) return true;
    worst_error = std::max(worst_error, std::abs(r.energy.error_percent));
    if (first) p0 = r.momentum;
    first = false;
    for (std::size_t k = 0; k < 3; ++k) pmax[k] = std::max(pmax[k], std::abs(r.momentum[k] - p0[k]));
    mass = r.mass;
    mass0 = r.mass0;
    added = r.added_mass;
    return true;
  });
  REQUIRE(res.status == sv::RunStatus::Normal);
  CHECK(added == Approx(added_expect).epsilon(1e-12));  // round-off
  CHECK(mass == Approx(mass0).epsilon(1e-12));
  const auto& s = eng.nodes();
  std::array<md::Vec3, 4> xa{};
  for (std::size_t j = 0; j < 4; ++j) xa[j] = pos(s, static_cast<std::size_t>(t.tie_segment[0][j]));
  md::Vec3 ca{};
  for (const auto& q : xa) ca = md::add(ca, md::scale(q, 0.25));
  // The face's own frame (e1 along its 5-6 edge, e3 its normal), at t = 0 the global axes.
  const md::Vec3 e1 = md::scale(md::sub(xa[1], xa[0]), 1.0 / md::norm(md::sub(xa[1], xa[0])));
  const auto nn = md::tie_normal(xa, false);
  const md::Vec3 e3 = md::scale(nn, 1.0 / md::norm(nn)), e2 = md::cross(e3, e1);
  // The face turned 90 degrees about Y: its normal, +z at the start, is now along +x (to 0.01 rad: the tie's
  // mass lumping changes the assembly's inertia by a few 0.1 %, as with Spotflag 0).
  CHECK(e3[0] > std::cos(0.01));
  for (std::size_t k = 0; k < t.tie_node.size(); ++k) {
    const auto n = static_cast<std::size_t>(t.tie_node[k]);
    const md::Vec3 q0 = md::sub(md::Vec3{m.nodes.x[n], m.nodes.y[n], m.nodes.z[n]}, md::Vec3{0.5, 0.5, 1.0});
    const md::Vec3 q = md::sub(pos(s, n), ca);
    // The offset, 0.2 off the face's plane, in the face's frame is the one of t = 0: to 1e-4 m, the face's
    // elastic strain under the spin (rho omega^2 L^2 / E ~ 1e-5) times its size.
    CHECK(md::dot(q, e1) == Approx(q0[0]).margin(1e-4));
    CHECK(md::dot(q, e2) == Approx(q0[1]).margin(1e-4));
    CHECK(md::dot(q, e3) == Approx(q0[2]).margin(1e-4));
    // The tied node turns with the face: its angular velocity is the spin (B's brick nodes carry none of
    // their own; the standard tie would give them the face nodes' rotations, which bricks do not have).
    CHECK(s.wy[n] == Approx(omega).epsilon(1e-2));
    CHECK(std::abs(s.wx[n]) + std::abs(s.wz[n]) < 1e-2 * omega);
  }
  // Momentum: no external force; round-off of m v ~ 1e4 kg m/s.
  for (std::size_t k = 0; k < 3; ++k) CHECK(pmax[k] < 1e-7 * mass * omega);
  // Energy balance: the tie does no work.
  CHECK(worst_error < 0.1);
}

// At t = 0 a tied node takes the velocity of its place on the map, whatever its own /INIVEL says (as
// OpenRadioss's first I2VIT3 / I2VIROT3): the derivative of the map along the segment's velocities, taken
// here by a central difference of the map itself (Spotflag 0: sum h_j x_j + d n; Spotflag 1: the engine's own
// placement, rigid_step above).
TEST_CASE(
    "TYPE2 set-up: a tied node starts with the velocity of its place, its own initial velocity replaced",
    "[tied]") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const int flag : {0, 1}) {
    for (int trial = 0; trial < 10; ++trial) {
      std::array<md::Vec3, 4> x{md::Vec3{0, 0, 0}, md::Vec3{1, 0, 0}, md::Vec3{1, 1, 0}, md::Vec3{0, 1, 0}};
      for (auto& p : x)
        for (auto& c : p) c += 0.1 * u(rng);
      const double r = 0.8 * u(rng), s = 0.8 * u(rng), d = 0.3 * u(rng);
      const auto h = md::tie_shape(r, s, false);
      auto place = [&](const std::array<md::Vec3, 4>& y) {
        const auto nn = md::tie_normal(y, false);
        md::Vec3 q = md::scale(nn, d / md::norm(nn));
        for (std::size_t j = 0; j < 4; ++j) q = md::add(q, md::scale(y[j], h[j]));
        return q;
      };
      auto m = rigid_tie_model(x, place(x), false);
      auto& t = m.tied_interfaces[0];
      t.spotflag = flag;
      t.tie_r = {r};
      t.tie_s = {s};
      t.tie_offset = {d};
      sv::TiedInterfaces ties(m);
      auto st = state_of(m);
      std::array<md::Vec3, 4> v{};
      for (std::size_t j = 0; j < 4; ++j) {
        v[j] = {u(rng), u(rng), u(rng)};
        st.vx[j] = v[j][0], st.vy[j] = v[j][1], st.vz[j] = v[j][2];
        st.mass[j] = 1.0;
      }
      st.mass[4] = 0.5;
      st.vx[4] = 10.0, st.vy[4] = -10.0, st.vz[4] = 10.0;  // its own, to be replaced
      ties.initialize(st);
      const double eps = 1e-6;
      std::array<md::Vec3, 4> xp = x, xm = x;
      for (std::size_t j = 0; j < 4; ++j) {
        xp[j] = md::add(x[j], md::scale(v[j], eps));
        xm[j] = md::sub(x[j], md::scale(v[j], eps));
      }
      const md::Vec3 expect =
          flag == 0 ? md::scale(md::sub(place(xp), place(xm)), 0.5 / eps)
                    : md::scale(md::sub(rigid_step(m, xp).first, rigid_step(m, xm).first), 0.5 / eps);
      // Central difference of unit-size maps: error ~1e-12, round-off ~1e-10.
      INFO("Spotflag " << flag);
      CHECK(st.vx[4] == Approx(expect[0]).margin(1e-8));
      CHECK(st.vy[4] == Approx(expect[1]).margin(1e-8));
      CHECK(st.vz[4] == Approx(expect[2]).margin(1e-8));
    }
  }
}

// The terms the tests above do not reach, in closed form on a unit square segment with the node at
// (r, s) = (-0.6, -0.4), 0.2 above it: h = (0.56, 0.14, 0.06, 0.24); about the square's centre q0 = (-0.3,
// -0.2, 0.2), |q0|^2 = 0.17, J0 = diag(1, 1, 2) (lambda_min = 1). Main nodes: mass 1, inertia 1, stiffness 3;
// the secondary: mass 0.5, inertia 0.3, stiffness 2, moment (1, -2, 3).
TEST_CASE(
    "TYPE2 masses, inertias, moments, nodal stiffness and rotations moved in closed form (Spotflag 0, 1)",
    "[tied]") {
  const std::array<md::Vec3, 4> x{md::Vec3{0, 0, 0}, md::Vec3{1, 0, 0}, md::Vec3{1, 1, 0}, md::Vec3{0, 1, 0}};
  const std::array<double, 4> h{0.56, 0.14, 0.06, 0.24};
  const md::Vec3 mo{1, -2, 3};
  for (const int flag : {0, 1}) {
    INFO("Spotflag " << flag);
    auto m = rigid_tie_model(x, md::Vec3{0.2, 0.3, 0.2}, false);
    auto& t = m.tied_interfaces[0];
    t.spotflag = flag;
    t.tie_r = {-0.6};
    t.tie_s = {-0.4};
    t.tie_offset = {0.2};
    sv::TiedInterfaces ties(m);
    auto st = state_of(m);
    for (std::size_t j = 0; j < 4; ++j) st.mass[j] = st.inertia[j] = 1.0;
    st.mass[4] = 0.5;
    st.inertia[4] = 0.3;
    ties.initialize(st);
    st.mx[4] = mo[0], st.my[4] = mo[1], st.mz[4] = mo[2];
    ties.transfer_forces(st);
    for (std::size_t n = 0; n < 5; ++n) st.stiffness[n] = n < 4 ? 3.0 : 2.0;
    ties.transfer_stiffness(st);
    CHECK(st.mass[4] == 0.0);
    CHECK(st.inertia[4] == 0.0);
    CHECK(st.stiffness[4] == 1e-20);
    for (std::size_t j = 0; j < 4; ++j) {
      if (flag == 0) {
        // Shares h_j of the mass, inertia, moment and stiffness (I2FOR3N, I2MOM3N; |h_j| for the stiffness).
        CHECK(st.mass[j] == Approx(1.0 + 0.5 * h[j]).epsilon(1e-14));
        CHECK(st.inertia[j] == Approx(1.0 + 0.3 * h[j]).epsilon(1e-14));
        CHECK(st.mx[j] == Approx(mo[0] * h[j]).epsilon(1e-14));
        CHECK(st.mz[j] == Approx(mo[2] * h[j]).epsilon(1e-14));
        CHECK(st.stiffness[j] == Approx(3.0 + 2.0 * h[j]).epsilon(1e-14));
        CHECK(st.added_mass[j] == 0.0);
      } else {
        // A quarter of the mass plus the inertia about the centre, (0.3 + 0.5 x 0.17) / 1, as added mass; the
        // rotations get nothing; the stiffness 2 (1/4 + 0.17).
        CHECK(st.mass[j] == Approx(1.0 + 0.125 + 0.385).epsilon(1e-14));
        CHECK(st.added_mass[j] == Approx(0.385).epsilon(1e-14));
        CHECK(st.inertia[j] == 1.0);
        CHECK(st.mx[j] == 0.0);
        CHECK(st.stiffness[j] == Approx(3.0 + 2.0 * (0.25 + 0.17)).epsilon(1e-14));
      }
    }
    if (flag == 0) {
      // The node's rotation: the h-weighted mean of the main nodes' (their rotational velocities w_j).
      const std::array<md::Vec3, 4> w{md::Vec3{1, 0, 0}, md::Vec3{0, 2, 0}, md::Vec3{0, 0, 3},
                                      md::Vec3{-1, 1, 1}};
      for (std::size_t j = 0; j < 4; ++j) st.wx[j] = w[j][0], st.wy[j] = w[j][1], st.wz[j] = w[j][2];
      ties.secondary_kinematics(st, 1e-3, 1e-3);
      md::Vec3 expect{};
      for (std::size_t j = 0; j < 4; ++j) expect = md::add(expect, md::scale(w[j], h[j]));
      const double dt12 = 1e-3;
      CHECK(st.wx[4] + dt12 * st.awx[4] == Approx(expect[0]).margin(1e-12));
      CHECK(st.wy[4] + dt12 * st.awy[4] == Approx(expect[1]).margin(1e-12));
      CHECK(st.wz[4] + dt12 * st.awz[4] == Approx(expect[2]).margin(1e-12));
    }
  }
}
