// Time-history groups of elements and rigid bodies (/TH/BRIC = /TH/BRICK, /TH/SH3N, /TH/RBODY): what the
// starter builds from a deck written here (kind, DEF and group names expanded in OpenRadioss's order, objects
// as dense indices of their own block, the warnings naming what radx writes as 0 and empty object lists, ids
// of the wrong element kind refused), and what the engine samples for a rigid body switched off by
// /RBODY/OFF. The values of computed variables are checked against closed forms by
// tests/scripts/check_th_outputs.py.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "parser/building/build_run_controls.hpp"
#include "parser/building/model_builder.hpp"
#include "parser/reading/deck.hpp"
#include "solver/conditions/kinematics_driver.hpp"
#include "solver/engine/explicit_engine.hpp"
#include "solver/outputs/time_history_values.hpp"
#include "test_util.hpp"

using radx::test::Line;

namespace {

namespace md = radx::model;
namespace sv = radx::solver;

struct Built {
  radx::Diagnostics diags;
  md::Model model;
};

std::string node(int id, double x, double y, double z) {
  return Line().put(id, 1, 10).put(x, 11, 30).put(y, 31, 50).put(z, 51, 70).str() + "\n";
}

std::string ints(std::initializer_list<long long> v, int first = 1) {
  Line l;
  int c = 0;
  for (auto x : v) {
    l.put(x, first + 10 * c, first + 10 * c + 9);
    ++c;
  }
  return l.str() + "\n";
}

std::string vars(std::initializer_list<const char*> names) {
  Line l;
  int c = 0;
  for (auto n : names) l.left(n, 1 + 10 * c++);
  return l.str() + "\n";
}

// Nodes 1..4 a unit square (z = 0) meshed by /SHELL 1 (part 1) and by /SH3N 7 and 8 (part 2); nodes 11..18 a
// unit cube above it, /BRICK 21 (part 3) and /RBODY 5 on its nodes with main node 19; then `extra`.
std::string deck_text(const std::string& extra) {
  std::string s = radx::test::begin_block(2026) + "/NODE\n";
  s += node(1, 0, 0, 0) + node(2, 1, 0, 0) + node(3, 1, 1, 0) + node(4, 0, 1, 0);
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) s += node(11 + i + 2 * j + 4 * k, i, j, 2.0 + k);
  s += node(19, 0.5, 0.5, 2.5);
  s += "/SHELL/1\n" + ints({1, 1, 2, 3, 4});
  s += "/SH3N/2\n" + ints({7, 1, 2, 3}) + ints({8, 1, 3, 4});
  s += "/BRICK/3\n" + ints({21, 11, 12, 14, 13, 15, 16, 18, 17});
  for (int p = 1; p <= 3; ++p) s += "/PART/" + std::to_string(p) + "\npart\n" + ints({p == 3 ? 2 : 1, 1});
  s += "/PROP/SHELL/1\nshell\n\n\n" + Line().put(0.1, 21, 40).str() + "\n/PROP/SOLID/2\nsolid\n\n\n";
  s += "/MAT/LAW1/1\nsteel\n" + Line().put(7.8e-9, 1, 20).str() + "\n" +
       Line().put(2.1e5, 1, 20).put(0.3, 21, 40).str() + "\n";
  s += "/GRNOD/NODE/1\ncube\n" + ints({11, 12, 13, 14, 15, 16, 17, 18});
  s += "/RBODY/5\ncube\n" + Line().put(19, 1, 10).put(1, 61, 70).str() + "\n\n\n\n";
  s += extra + "/END\n";
  return s;
}

Built build(const std::string& extra) {
  radx::test::TempDir dir;
  Built b;
  const auto deck = radx::read_starter_deck(dir.write("th_0000.rad", deck_text(extra)), b.diags);
  b.model = radx::build_model(deck, b.diags);
  return b;
}

std::string all_diags(const radx::Diagnostics& d) {
  std::string s;
  for (const auto& x : d.items()) s += radx::Diagnostics::format(x) + "\n";
  return s;
}

const md::TimeHistoryGroup& group(const md::Model& m, std::int64_t id) {
  const auto g = std::find_if(m.time_histories.begin(), m.time_histories.end(),
                              [&](const auto& x) { return x.id == id; });
  REQUIRE(g != m.time_histories.end());
  return *g;
}

// Diagnostics of `code` whose text holds `about` (the group's "/TH/... id N").
std::vector<std::string> diags_of(const radx::Diagnostics& d, const std::string& code,
                                  const std::string& about) {
  std::vector<std::string> out;
  for (const auto& x : d.items()) {
    const auto text = radx::Diagnostics::format(x);
    if (text.find(code) != std::string::npos && text.find(about) != std::string::npos) out.push_back(text);
  }
  return out;
}

using Names = std::vector<std::string>;

}  // namespace

TEST_CASE("/TH/BRIC, /TH/BRICK, /TH/SH3N, /TH/RBODY: kinds, DEF sets, objects and warnings", "[th]") {
  const std::string th = "/TH/BRIC/1\nbrick def\n" + vars({"DEF", "BULK"}) + ints({21}) +               //
                         "/TH/BRICK/2\nlong spelling\n" + vars({"STRESS", "VOL", "SX"}) + ints({21}) +  //
                         "/TH/SH3N/3\ntriangles\n" + vars({"DEF"}) + ints({8}) + ints({7}) +            //
                         "/TH/RBODY/4\nbody\n" + vars({"DEF", "FI", "MASS", "STATUS"}) + ints({5}) +    //
                         "/TH/RBODY/6\nbody, no id\n" + vars({"A"});
  const Built b = build(th);
  INFO(all_diags(b.diags));
  REQUIRE_FALSE(b.diags.has_errors());
  const auto& m = b.model;

  const auto& brick = group(m, 1);
  CHECK(brick.kind == md::ThKind::Brick);
  CHECK(brick.variables ==
        Names{"OFF", "SX", "SY", "SZ", "SXY", "SYZ", "SXZ", "IE", "DENS", "PLAS", "TEMP", "BULK"});
  CHECK(brick.objects == std::vector<std::int32_t>{0});
  const auto& brick2 = group(m, 2);
  CHECK(brick2.kind == md::ThKind::Brick);
  CHECK(brick2.variables == Names{"SX", "SY", "SZ", "SXY", "SYZ", "SXZ", "VOL"});  // SX once

  const auto& tri = group(m, 3);
  CHECK(tri.kind == md::ThKind::Shell3);
  CHECK(tri.variables == Names{"F1", "F2", "F12", "M1", "M2", "M12", "IEM", "IEB", "OFF", "EMIN", "EMAX"});
  REQUIRE(m.shells3.size() == 2u);
  CHECK(tri.objects == std::vector<std::int32_t>{1, 0});  // dense indices in the /SH3N block, as listed

  const auto& rb = group(m, 4);
  CHECK(rb.kind == md::ThKind::Rbody);
  CHECK(rb.variables ==
        Names{"FX", "FY", "FZ", "MX", "MY", "MZ", "RX", "RY", "RZ", "FXI", "FYI", "FZI", "MASS", "STATUS"});
  CHECK(rb.objects == std::vector<std::int32_t>{0});
  const auto& rb_empty = group(m, 6);
  CHECK(rb_empty.variables == Names{"AX", "AY", "AZ", "ARX", "ARY", "ARZ"});
  CHECK(rb_empty.objects.empty());

  // Warnings: what is written as 0, named with the reason; the group that lists no object.
  const auto w1 = diags_of(b.diags, "RX509", "/TH/BRIC id 1");
  REQUIRE(w1.size() == 1u);
  CHECK(w1[0].find("TEMP (radx has no thermal analysis)") != std::string::npos);
  CHECK(diags_of(b.diags, "RX509", "/TH/BRIC id 2").empty());  // STRESS VOL: all computed
  const auto w3 = diags_of(b.diags, "RX509", "/TH/SH3N id 3");
  REQUIRE(w3.size() == 1u);
  CHECK(w3[0].find("IEB (the bending share of the shell energy), EMIN EMAX (strains are not kept)") !=
        std::string::npos);
  const auto w4 = diags_of(b.diags, "RX509", "/TH/RBODY id 4");
  REQUIRE(w4.size() == 1u);
  CHECK(w4[0].find("FXI FYI FZI (") != std::string::npos);
  CHECK(w4[0].find("MXI") == std::string::npos);  // only what the group asks for
  CHECK(diags_of(b.diags, "RX403", "/TH/RBODY id 6").size() == 1u);
  CHECK(diags_of(b.diags, "RX403", "/TH/RBODY id 4").empty());
}

TEST_CASE("element time histories refuse ids of another element kind, /TH/RBODY leaves a missing body out",
          "[th]") {
  const std::string th = "/TH/SH3N/1\ntriangles\n" + vars({"F1"}) + ints({1}) +   // 1 is the 4-node shell
                         "/TH/SHEL/2\nquads\n" + vars({"F1"}) + ints({7}) +       // 7 is a triangle
                         "/TH/BRIC/3\nbricks\n" + vars({"SX"}) + ints({1}) +      // 1 is a shell
                         "/TH/RBODY/4\nbodies\n" + vars({"FX"}) + ints({5, 6}) +  // 6: no such body
                         "/TH/RBODY/5\nbodies\n" + vars({"FX", "SX"}) + ints({5});
  const Built b = build(th);
  INFO(all_diags(b.diags));
  CHECK(b.diags.error_count() == 4u);
  CHECK(diags_of(b.diags, "RX402", "3-node shell 1 does not exist").size() == 1u);
  CHECK(diags_of(b.diags, "RX402", "4-node shell 7 does not exist").size() == 1u);
  CHECK(diags_of(b.diags, "RX402", "brick 1 does not exist").size() == 1u);
  // A missing body is left out with a warning, as Radioss does (its warning 257); elements stop the deck.
  const auto body = diags_of(b.diags, "RX402", "rigid body 6 does not exist");
  REQUIRE(body.size() == 1u);
  CHECK(body[0].find("warning: RX402") != std::string::npos);
  CHECK(diags_of(b.diags, "RX501", "unknown /TH/RBODY variable 'SX'").size() == 1u);
}

TEST_CASE("/TH/RBODY of a body switched off by /RBODY/OFF: STATUS 0, no force, the main node's motion",
          "[th]") {
  const std::string dir = std::string(RADX_SOURCE_DIR) + "/decks/verification/th_outputs/";
  radx::Diagnostics d;
  const auto deck = radx::read_starter_deck(dir + "TH_RBODY_0000.rad", d);
  const md::Model m = radx::build_model(deck, d);
  md::RunControls c = radx::read_run_controls(dir + "TH_RBODY_0001.rad", d);
  INFO(all_diags(d));
  REQUIRE_FALSE(d.has_errors());
  REQUIRE(m.rigid_bodies.size() == 1u);
  const md::TimeHistoryGroup& g = group(m, 1);
  REQUIRE(g.kind == md::ThKind::Rbody);
  for (const bool off : {false, true}) {
    INFO((off ? "/RBODY/OFF" : "formed"));
    if (off) c.rbody_off = {m.rigid_bodies[0].id};
    sv::ExplicitEngine eng(m, c, sv::EngineOptions(1));
    sv::ThGroupSampler sampler(eng, g);
    std::vector<double> v(sampler.size());
    const auto res = eng.run([&](const sv::CycleReport& r) {
      sampler.sample(eng, r, v);
      return r.cycle < 50;
    });
    REQUIRE(res.cycles >= 50);
    auto at = [&](const std::string& name) {
      const auto k = std::find(g.variables.begin(), g.variables.end(), name) - g.variables.begin();
      REQUIRE(static_cast<std::size_t>(k) < g.variables.size());
      return v[static_cast<std::size_t>(k)];
    };
    const auto main = static_cast<std::size_t>(m.rigid_bodies[0].main_node);
    const auto& s = eng.nodes();
    CHECK(at("STATUS") == (off ? 0.0 : 1.0));
    CHECK(at("X") == s.x[main]);
    CHECK(at("MASS") == s.mass[main]);
    if (off) {
      // The main node carries no element: massless, it does not move; the pulled corner is a free node now.
      CHECK(at("FX") == 0.0);
      CHECK(at("RY") == 0.0);
      CHECK(at("IXX") == 0.0);
      CHECK(at("DX") == 0.0);
    } else {
      CHECK(at("FX") > 0.0);
      CHECK(at("IXX") > 0.0);
      CHECK(at("DX") > 0.0);
    }
  }
}

TEST_CASE("/TH/RWALL of a parallelogram wall: the impact force of the node hitting inside it, none beside it",
          "[th]") {
  // Point masses (m = 0.001 Mg each) 31 at (0.9, 0.5, -1) and 32 at (0.2, 0.5, -1) fall at v0 = 25 m/s onto
  // the fixed parallelogram of corner (0, 0, -1.5) and edges (2, 0, 0), (1, 1, 0): node 31 lies over it
  // (0.2 e1 + 0.5 e2), node 32 beside it (-0.15 e1 + 0.5 e2). The wall stops node 31 in one cycle (impulse
  // -m v0 along Z, docs/theory/elements.md 7.1) and lets node 32 fall on: z = -1 - v0 t. The /TH/RWALL row of
  // the impact cycle holds the force of the nodes on the wall, FN = impulse / dt12 (the wall's own output);
  // every other row 0.
  const double m0 = 0.001, v0 = 25000.0;
  const std::string extra = "/NODE\n" + node(31, 0.9, 0.5, -1.0) + node(32, 0.2, 0.5, -1.0) +
                            "/GRNOD/NODE/2\nfalling\n" + ints({31, 32}) + "/ADMAS/0/1\npoint masses\n" +
                            Line().put(m0, 1, 20).put(2, 21, 30).str() + "\n" + "/INIVEL/TRA/1\nfall\n" +
                            Line().put(-v0, 41, 60).put(2, 61, 70).str() + "\n" + "/RWALL/PARAL/7\nfloor\n" +
                            ints({0, 0, 2, 0}) + "\n" +
                            Line().put(0.0, 1, 20).put(0.0, 21, 40).put(-1.5, 41, 60).str() + "\n" +
                            Line().put(2.0, 1, 20).put(0.0, 21, 40).put(-1.5, 41, 60).str() + "\n" +
                            Line().put(1.0, 1, 20).put(1.0, 21, 40).put(-1.5, 41, 60).str() + "\n" +
                            "/TH/RWALL/3\nwall\n" + vars({"DEF"}) + ints({7});
  radx::test::TempDir dir;
  radx::Diagnostics d;
  const auto deck = radx::read_starter_deck(dir.write("th_0000.rad", deck_text(extra)), d);
  const md::Model m = radx::build_model(deck, d);
  const md::RunControls c =
      radx::read_run_controls(dir.write("th_0001.rad", "/RUN/th/1\n0.00004\n/END\n"), d);
  INFO(all_diags(d));
  REQUIRE_FALSE(d.has_errors());
  REQUIRE(m.rigid_walls.size() == 1u);
  REQUIRE(m.rigid_walls[0].shape == 3);
  const md::TimeHistoryGroup& g = group(m, 3);
  REQUIRE(g.kind == md::ThKind::Rwall);
  sv::ExplicitEngine eng(m, c, sv::EngineOptions(1));
  sv::ThGroupSampler sampler(eng, g);
  std::vector<double> v(sampler.size());
  auto at = [&](const std::string& name) {
    const auto k = std::find(g.variables.begin(), g.variables.end(), name) - g.variables.begin();
    REQUIRE(static_cast<std::size_t>(k) < g.variables.size());
    return v[static_cast<std::size_t>(k)];
  };
  int impacts = 0;
  const auto res = eng.run([&](const sv::CycleReport& r) {
    sampler.sample(eng, r, v);
    const auto& w = eng.kinematics().wall_outputs()[0];
    if (at("FNZ") != 0.0) {
      ++impacts;
      CHECK(at("FNZ") == w.normal_force[2]);
      CHECK(at("FNZ") < 0.0);  // the node pushes the wall down
    }
    CHECK(at("FNX") == 0.0);
    CHECK(at("FNY") == 0.0);
    CHECK(at("FTX") == 0.0);
    CHECK(at("FTZ") == 0.0);
    return true;
  });
  REQUIRE(res.time > 0.00003);  // past the impact at t = 0.5 mm / v0 = 2e-5 s
  CHECK(impacts == 1);
  // The impulse is m v0, to the round-off of the velocity.
  CHECK(std::abs(eng.kinematics().wall_outputs()[0].normal_impulse[2] + m0 * v0) <= 1e-12 * m0 * v0);
  const auto& s = eng.nodes();
  const auto n31 = static_cast<std::size_t>(m.nodes.index.find(31));
  const auto n32 = static_cast<std::size_t>(m.nodes.index.find(32));
  CHECK(s.vz[n31] == 0.0);
  CHECK(s.z[n31] > -1.5);
  CHECK(s.vz[n32] == -v0);
  CHECK(std::abs(s.z[n32] - (-1.0 - v0 * res.time)) <= 1e-12 * v0 * res.time);  // free flight, round-off
}
