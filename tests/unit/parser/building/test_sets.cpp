// /SET/GENERAL and /SET/COLLECT (docs/sets.md) on a deck built in the test. Every expected member list below
// is counted from the construction of the mesh, not from the builder:
//
//   plate      part 1: 4-node shells 1 and 2 at z = 0 on nodes 1..6 (a 3 x 2 grid of spacing 1): shell 1 on
//              1 2 5 4, shell 2 on 2 3 6 5 (normal +z).
//   block      part 2: bricks 11 and 12 side by side along x, z from 1 to 2, on nodes 101 + i + 3j + 6k at
//              (i, j, 1 + k); brick 11 + i has corners i..i+1: 12 faces, one (x = 1) shared by the two.
//   triangle   part 3: 3-node shell 21 on nodes 201 (0,0,-1), 202 (1,0,-1), 203 (0,1,-1), normal +z.
//   box 1      x in [-0.1, 1.1], y and z in [-2, 3]: every node with x <= 1.
#include <catch2/catch.hpp>
#include <set>

#include "parser/building/model_builder.hpp"
#include "test_util.hpp"

using radx::test::Line;

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

std::string node_line(long long id, double x, double y, double z) {
  return Line().put(id, 1, 10).put(x, 11, 30).put(y, 31, 50).put(z, 51, 70).str() + "\n";
}

long long bid(int i, int j, int k) {
  return 101 + i + 3 * j + 6 * k;
}

std::string deck_text(const std::string& extra) {
  std::string s = radx::test::begin_block(2026) + "/NODE\n";
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) s += node_line(1 + i + 3 * j, i, j, 0.0);
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i) s += node_line(bid(i, j, k), i, j, 1.0 + k);
  s += node_line(201, 0, 0, -1) + node_line(202, 1, 0, -1) + node_line(203, 0, 1, -1);
  s += "/SHELL/1\n" + ids_line({1, 1, 2, 5, 4}) + "\n" + ids_line({2, 2, 3, 6, 5}) + "\n";
  s += "/BRICK/2\n";
  for (int i = 0; i < 2; ++i)
    s += ids_line({11 + i, bid(i, 0, 0), bid(i + 1, 0, 0), bid(i + 1, 1, 0), bid(i, 1, 0), bid(i, 0, 1),
                   bid(i + 1, 0, 1), bid(i + 1, 1, 1), bid(i, 1, 1)}) +
         "\n";
  s += "/SH3N/3\n" + ids_line({21, 201, 202, 203}) + "\n";
  s += "/PART/1\nplate\n" + ids_line({1, 1}) + "\n/PART/2\nblock\n" + ids_line({2, 2}) + "\n";
  s += "/PART/3\ntriangle\n" + ids_line({1, 1}) + "\n";
  const std::string thick = Line().put(1.0, 21, 40).str();
  s += "/PROP/SHELL/1\nshell\n\n\n" + thick + "\n/PROP/SOLID/2\nsolid\n\n\n";
  s += "/MAT/LAW1/1\nsteel\n" + Line().put(7.8e-9, 1, 20).str() + "\n" +
       Line().put(2.1e5, 1, 20).put(0.3, 21, 40).str() + "\n";
  s += "/MAT/LAW1/2\nalu\n" + Line().put(2.7e-9, 1, 20).str() + "\n" +
       Line().put(7e4, 1, 20).put(0.3, 21, 40).str() + "\n";
  s += "/BOX/RECTA/1\nbox\n\n" + Line().put(-0.1, 1, 20).put(-2.0, 21, 40).put(-2.0, 41, 60).str() + "\n" +
       Line().put(1.1, 1, 20).put(3.0, 21, 40).put(3.0, 41, 60).str() + "\n";
  s += extra + "/END\n";
  return s;
}

// One clause line: the word left-justified in columns 1-10, then the ids from column 11.
std::string clause(std::string word, std::initializer_list<long long> ids) {
  word.resize(10, ' ');
  Line l;
  int c = 1;
  for (auto id : ids) {
    l.put(id, 10 * c + 1, 10 * c + 10);
    ++c;
  }
  std::string text = l.str();
  if (text.size() < 10) text.resize(10, ' ');
  return word + text.substr(10) + "\n";
}

std::string set(const std::string& kind, long long id, const std::string& clauses) {
  return "/SET/" + kind + "/" + std::to_string(id) + "\nset\n" + clauses;
}

struct Built {
  radx::Diagnostics diags;
  radx::Deck deck;
  std::unique_ptr<radx::detail::ModelBuilder> builder;
  radx::model::Model model;

  std::string report() const {
    std::string s;
    for (const auto& d : diags.items()) s += radx::Diagnostics::format(d) + "\n";
    return s;
  }
  const radx::detail::ModelBuilder::SetMembers& members(long long id) const {
    auto it = builder->set_ids_.find(id);
    if (it == builder->set_ids_.end()) it = builder->collect_set_ids_.find(id);
    REQUIRE(it != builder->collect_set_ids_.end());
    return builder->sets_[static_cast<std::size_t>(it->second)].members;
  }
  // The user ids of a kind of member of set `id`.
  std::set<long long> nodes(long long id) const { return user_ids(members(id).nodes, model.nodes.id); }
  std::set<long long> parts(long long id) const {
    std::set<long long> out;
    for (const auto p : members(id).parts) out.insert(model.parts[static_cast<std::size_t>(p)].id);
    return out;
  }
  std::set<long long> shells(long long id) const { return user_ids(members(id).shells, model.shells.id); }
  std::set<long long> shells3(long long id) const { return user_ids(members(id).shells3, model.shells3.id); }
  std::set<long long> solids(long long id) const { return user_ids(members(id).solids, model.bricks.id); }
  std::size_t segments(long long id) const { return members(id).segments.size(); }
  static std::set<long long> user_ids(const std::vector<std::int32_t>& dense,
                                      const std::vector<std::int64_t>& ids) {
    std::set<long long> out;
    for (const auto e : dense) out.insert(ids[static_cast<std::size_t>(e)]);
    return out;
  }
  // The user ids of the nodes of the model's node group `id` (a set becomes one where it is named).
  std::set<long long> node_group(long long id) const {
    for (const auto& g : model.node_groups)
      if (g.id == id) return user_ids(g.nodes, model.nodes.id);
    FAIL("no node group " << id);
    return {};
  }
  const radx::model::Surface& surface(long long id) const {
    for (const auto& s : model.surfaces)
      if (s.id == id) return s;
    FAIL("no surface " << id);
    return model.surfaces.front();
  }
  bool has(radx::Diag code, radx::Severity sev, const std::string& text = "") const {
    for (const auto& d : diags.items())
      if (d.code == code && d.severity == sev && radx::Diagnostics::format(d).find(text) != std::string::npos)
        return true;
    return false;
  }
};

std::unique_ptr<Built> build(const std::string& extra) {
  radx::test::TempDir dir;
  const auto path = dir.write("sets_0000.rad", deck_text(extra));
  auto b = std::make_unique<Built>();
  b->deck = radx::read_starter_deck(path, b->diags);
  b->builder = std::make_unique<radx::detail::ModelBuilder>(b->deck, b->diags);
  b->model = b->builder->build();
  return b;
}

std::set<long long> range(long long a, long long b, long long step = 1) {
  std::set<long long> s;
  for (auto i = a; i <= b; i += step) s.insert(i);
  return s;
}

std::set<long long> join(std::set<long long> a, const std::set<long long>& b) {
  a.insert(b.begin(), b.end());
  return a;
}

// A /BCS naming node group `id`, so that the set of that id becomes a node group.
std::string bcs(long long id) {
  return "/BCS/" + std::to_string(id) + "\nbc\n" +
         Line().put("111", 4, 6).put("111", 8, 10).put(id, 21, 30).str() + "\n";
}

const std::set<long long> kPlateNodes = range(1, 6);
const std::set<long long> kBlockNodes = range(101, 112);
const std::set<long long> kTriangleNodes = range(201, 203);

}  // namespace

TEST_CASE("each clause selects the members Radioss gives it", "[sets]") {
  const auto b = build(set("GENERAL", 1, clause("PART", {1})) + set("GENERAL", 2, clause("PART", {2})) +
                       set("GENERAL", 3, clause("PART_A", {2})) +
                       set("GENERAL", 4, clause("NODE", {1, 3, 5}) + clause("NODE_G", {101, 112, 2})) +
                       set("GENERAL", 5, clause("SHELL", {2}) + clause("SH3N", {21})) +
                       set("GENERAL", 6, clause("SOLID", {12})) + set("GENERAL", 7, clause("ALL", {})) +
                       set("GENERAL", 8, clause("BOX", {1})) + set("GENERAL", 9, clause("BOX2", {1})));
  INFO(b->report());
  REQUIRE_FALSE(b->diags.has_errors());
  // PART: the part's elements, their nodes; a surface of its shells (2) or its bricks' outer faces (12 faces
  // less the shared one, counted from each brick: 10); PART_A keeps the shared face from both sides (12).
  CHECK(b->parts(1) == std::set<long long>{1});
  CHECK(b->shells(1) == std::set<long long>{1, 2});
  CHECK(b->nodes(1) == kPlateNodes);
  CHECK(b->segments(1) == 2);
  CHECK(b->solids(2) == std::set<long long>{11, 12});
  CHECK(b->nodes(2) == kBlockNodes);
  CHECK(b->segments(2) == 10);
  CHECK(b->segments(3) == 12);
  // NODE lists, NODE_G takes every other id from 101 to 112 (step 2): 101, 103, ..., 111.
  CHECK(b->nodes(4) == join({1, 3, 5}, range(101, 111, 2)));
  CHECK(b->segments(4) == 0);
  // SHELL and SH3N: the elements listed, their nodes and one segment each.
  CHECK(b->shells(5) == std::set<long long>{2});
  CHECK(b->shells3(5) == std::set<long long>{21});
  CHECK(b->nodes(5) == join({2, 3, 5, 6}, kTriangleNodes));
  CHECK(b->segments(5) == 2);
  // SOLID: brick 12 alone in its clause has six outer faces; its eight nodes are those with i = 1, 2.
  CHECK(b->solids(6) == std::set<long long>{12});
  CHECK(b->nodes(6) == std::set<long long>{102, 103, 105, 106, 108, 109, 111, 112});
  CHECK(b->segments(6) == 6);
  // ALL: the whole model; its surface is 2 shells, the triangle and the block's 10 outer faces.
  CHECK(b->nodes(7) == join(join(kPlateNodes, kBlockNodes), kTriangleNodes));
  CHECK(b->parts(7) == std::set<long long>{1, 2, 3});
  CHECK(b->segments(7) == 13);
  // BOX 1 (x <= 1): the nodes inside; the elements with every node inside (shell 1, brick 11, the triangle);
  // BOX2 adds those with one node inside (shell 2, brick 12).
  CHECK(b->nodes(8) ==
        std::set<long long>{1, 2, 4, 5, 101, 102, 104, 105, 107, 108, 110, 111, 201, 202, 203});
  CHECK(b->shells(8) == std::set<long long>{1});
  CHECK(b->solids(8) == std::set<long long>{11});
  CHECK(b->shells3(8) == std::set<long long>{21});
  // Brick 11's face x = 1 is shared with brick 12 of the model: inner for a box clause (5 faces), plus the
  // shell and the triangle.
  CHECK(b->segments(8) == 7);
  CHECK(b->nodes(9) == b->nodes(8));
  CHECK(b->shells(9) == std::set<long long>{1, 2});
  CHECK(b->solids(9) == std::set<long long>{11, 12});
  CHECK(b->segments(9) == 13);
  CHECK(b->parts(8).empty());  // a box selects no part
}

TEST_CASE("clauses join the set kind by kind: union, _D difference, _I intersection, SET and COLLECT",
          "[sets]") {
  const auto b = build(set("GENERAL", 1, clause("PART", {1})) + set("GENERAL", 2, clause("PART", {2})) +
                       set("GENERAL", 5, clause("SHELL", {2}) + clause("SH3N", {21})) +
                       set("GENERAL", 10, clause("ALL", {}) + clause("PART_D", {2})) +
                       set("GENERAL", 11, clause("SET", {1, 2}) + clause("SET_I", {5})) +
                       set("GENERAL", 12, clause("SET_G", {1, 2, 1}) + clause("NODE_D", {1, 2, 3})) +
                       set("GENERAL", 13, clause("NODE_D", {1}) + clause("NODE", {1, 2})) +
                       set("COLLECT", 20, clause("NODE", {1})) + set("COLLECT", 20, clause("NODE", {2})) +
                       set("GENERAL", 21, clause("SETCOL", {20}) + clause("NODE", {3})));
  INFO(b->report());
  REQUIRE_FALSE(b->diags.has_errors());
  // ALL less part 2: every node but the block's, parts 1 and 3, no brick; the block's faces removed.
  CHECK(b->nodes(10) == join(kPlateNodes, kTriangleNodes));
  CHECK(b->parts(10) == std::set<long long>{1, 3});
  CHECK(b->solids(10).empty());
  CHECK(b->shells(10) == std::set<long long>{1, 2});
  CHECK(b->segments(10) == 3);
  // (set 1 or set 2) and set 5: nodes {1..6, 101..112} and {2, 3, 5, 6, 201..203} share 2, 3, 5, 6; shells
  // {1, 2} and {2}: 2; the bricks meet an empty kind under _I and go; the triangle was never in the union;
  // the one segment both have is shell 2's.
  CHECK(b->nodes(11) == std::set<long long>{2, 3, 5, 6});
  CHECK(b->shells(11) == std::set<long long>{2});
  CHECK(b->solids(11).empty());
  CHECK(b->shells3(11).empty());
  CHECK(b->segments(11) == 1);
  // SET_G 1 2 1 takes sets 1 and 2; NODE_D then removes nodes 1, 2, 3 only.
  CHECK(b->nodes(12) == join({4, 5, 6}, kBlockNodes));
  CHECK(b->solids(12) == std::set<long long>{11, 12});
  // In order: removing from an empty set does nothing, the later NODE adds.
  CHECK(b->nodes(13) == std::set<long long>{1, 2});
  // Both /SET/COLLECT/20 add to one set; SETCOL takes it.
  CHECK(b->nodes(20) == std::set<long long>{1, 2});
  CHECK(b->nodes(21) == std::set<long long>{1, 2, 3});
}

TEST_CASE("a set stands for a node group, a surface or an element group where no group has its id",
          "[sets]") {
  const std::string inter =
      "/INTER/TYPE7/1\ncontact\n" + Line().put(2, 1, 10).put(3, 11, 20).str() + "\n\n\n\n\n\n";
  const auto b =
      build(set("GENERAL", 2, clause("PART", {2})) + set("GENERAL", 3, clause("PART_O", {1})) +
            set("GENERAL", 7, clause("NODE", {2})) + "/GRNOD/NODE/7\ngroup\n" + ids_line({1}) + "\n" +
            bcs(7) + inter + "/GRNOD/GRSHEL/8\nnodes of the shells of set 3\n" + ids_line({3}) + "\n");
  INFO(b->report());
  REQUIRE_FALSE(b->diags.has_errors());
  // The interface's secondary node group is set 2's nodes, its main surface set 3's shells, flipped by
  // PART_O (normals -z: the first segment's nodes turn 1 4 5 2).
  const auto& m = b->model;
  REQUIRE(m.interfaces.size() == 1);
  const auto& in = m.interfaces.front();
  REQUIRE(in.secondary_group >= 0);
  REQUIRE(in.main_surface >= 0);
  CHECK(Built::user_ids(m.node_groups[static_cast<std::size_t>(in.secondary_group)].nodes, m.nodes.id) ==
        kBlockNodes);
  const auto& s = m.surfaces[static_cast<std::size_t>(in.main_surface)];
  CHECK(s.id == 3);
  REQUIRE(s.segments.size() == 2);
  CHECK(m.nodes.id[static_cast<std::size_t>(s.segments[0][1])] == 4);
  // /GRNOD/NODE/7 (node 1) and /SET/GENERAL/7 (node 2): the /BCS takes the group, as Radioss does.
  REQUIRE(m.bcs.size() == 1);
  REQUIRE(m.bcs.front().group >= 0);
  CHECK(Built::user_ids(m.node_groups[static_cast<std::size_t>(m.bcs.front().group)].nodes, m.nodes.id) ==
        std::set<long long>{1});
  // /GRNOD/GRSHEL names set 3 as a 4-node shell group: the plate's nodes.
  CHECK(b->node_group(8) == kPlateNodes);
}

TEST_CASE("set errors and warnings: missing ids, unknown and unsupported clauses, loops, empty sets",
          "[sets]") {
  SECTION("an id that does not exist is left out with a warning, as Radioss leaves it out") {
    const auto b = build(set("GENERAL", 1, clause("PART", {1, 99}) + clause("NODE", {1000})) + bcs(1));
    INFO(b->report());
    CHECK_FALSE(b->diags.has_errors());
    CHECK(b->has(radx::Diag::MissingReference, radx::Severity::Warning, "part 99 does not exist"));
    CHECK(b->has(radx::Diag::MissingReference, radx::Severity::Warning, "node 1000 does not exist"));
    CHECK(b->node_group(1) == kPlateNodes);
  }
  SECTION("a word that is not a clause stops the starter; Radioss would drop it without a word") {
    const auto b = build(set("GENERAL", 1, clause("SH4N", {1})) + bcs(1));
    INFO(b->report());
    CHECK(b->has(radx::Diag::InconsistentValues, radx::Severity::Error, "'SH4N' is not a /SET clause"));
  }
  SECTION("a Radioss clause or option radx does not apply is refused by name") {
    const auto b = build(set("GENERAL", 1, clause("SEG", {1, 1, 2, 5, 4}) + clause("PART_E", {2})) + bcs(1));
    INFO(b->report());
    CHECK(b->has(radx::Diag::PhysicsNotImplemented, radx::Severity::Error, "clause SEG"));
    CHECK(b->has(radx::Diag::PhysicsNotImplemented, radx::Severity::Error, "option E"));
  }
  SECTION("a set that includes itself is an error") {
    const auto b = build(set("GENERAL", 1, clause("SET", {2})) + set("GENERAL", 2, clause("SET", {1})));
    INFO(b->report());
    CHECK(b->has(radx::Diag::InconsistentValues, radx::Severity::Error, "includes itself"));
  }
  SECTION("an empty set named as a node group is warned of, as Radioss warns of the empty group") {
    const auto b = build(set("GENERAL", 1, clause("NODE", {1}) + clause("NODE_D", {1})) + bcs(1));
    INFO(b->report());
    CHECK_FALSE(b->diags.has_errors());
    CHECK(b->has(radx::Diag::EmptyGroup, radx::Severity::Warning, "set 1 holds no node"));
  }
}
