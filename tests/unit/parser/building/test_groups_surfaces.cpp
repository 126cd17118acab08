// Node groups of every supported kind and surfaces (/SURF/PART, /SURF/PART/EXT, /SURF/SEG) on a deck
// built in the test: a 2 x 2 shell plate (part 1, at z = 0) and a 2 x 2 x 2 brick block (part 2, side 2,
// from z = 1 to z = 3). Expected sets come from the construction of the mesh.
#include <catch2/catch.hpp>
#include <set>

#include "parser/building/model_builder.hpp"
#include "solver/model/geometry.hpp"
#include "test_util.hpp"

using radx::test::Line;

namespace {

struct Built {
  radx::Diagnostics diags;
  radx::model::Model model;
};

std::string ids_line(std::initializer_list<long long> ids) {
  Line l;
  int c = 0;
  for (auto id : ids) {
    l.put(id, 10 * c + 1, 10 * c + 10);
    ++c;
  }
  return l.str();
}

// Node ids: plate 1..9 (3 x 3, spacing 1, z = 0); block 101.. (3 x 3 x 3, spacing 1, z from 1 to 3).
std::string deck_text(const std::string& extra) {
  std::string s = radx::test::begin_block(2026) + "/NODE\n";
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i)
      s += Line()
               .put(1 + i + 3 * j, 1, 10)
               .put(double(i), 11, 30)
               .put(double(j), 31, 50)
               .put(0.0, 51, 70)
               .str() +
           "\n";
  auto bid = [](int i, int j, int k) { return 101 + i + 3 * j + 9 * k; };
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i)
        s += Line()
                 .put(bid(i, j, k), 1, 10)
                 .put(double(i), 11, 30)
                 .put(double(j), 31, 50)
                 .put(1.0 + k, 51, 70)
                 .str() +
             "\n";
  s += "/SHELL/1\n";
  int e = 1;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const int n1 = 1 + i + 3 * j;
      s += Line()
               .put(e++, 1, 10)
               .put(n1, 11, 20)
               .put(n1 + 1, 21, 30)
               .put(n1 + 4, 31, 40)
               .put(n1 + 3, 41, 50)
               .str() +
           "\n";
    }
  s += "/BRICK/2\n";
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) {
        Line l;
        l.put(e++, 1, 10);
        const int n[8] = {
            bid(i, j, k),     bid(i + 1, j, k),     bid(i + 1, j + 1, k),     bid(i, j + 1, k),
            bid(i, j, k + 1), bid(i + 1, j, k + 1), bid(i + 1, j + 1, k + 1), bid(i, j + 1, k + 1)};
        for (int q = 0; q < 8; ++q) l.put(n[q], 11 + 10 * q, 20 + 10 * q);
        s += l.str() + "\n";
      }
  s += "/PART/1\nplate\n" + ids_line({1, 1, 10}) + "\n/PART/2\nblock\n" + ids_line({2, 2, 10}) + "\n";
  s += "/PROP/SHELL/1\nshell\n\n\n" + Line().put(1.0, 21, 40).str() + "\n/PROP/SOLID/2\nsolid\n\n\n";
  s += "/MAT/LAW1/1\nsteel\n" + Line().put(7.8e-9, 1, 20).str() + "\n" +
       Line().put(2.1e5, 1, 20).put(0.3, 21, 40).str() + "\n";
  s += "/MAT/LAW1/2\nalu\n" + Line().put(2.7e-9, 1, 20).str() + "\n" +
       Line().put(7e4, 1, 20).put(0.3, 21, 40).str() + "\n";
  s += "/SUBSET/10\nall\n" + ids_line({11}) + "\n/SUBSET/11\nchild\n";
  s += extra + "/END\n";
  return s;
}

Built build(const std::string& extra) {
  radx::test::TempDir dir;
  const auto path = dir.write("g_0000.rad", deck_text(extra));
  Built b;
  const auto deck = radx::read_starter_deck(path, b.diags);
  b.model = radx::build_model(deck, b.diags);
  return b;
}

std::set<long long> group_ids(const radx::model::Model& m, long long gid) {
  for (const auto& g : m.node_groups)
    if (g.id == gid) {
      std::set<long long> out;
      for (auto n : g.nodes) out.insert(m.nodes.id[n]);
      return out;
    }
  FAIL("no group " << gid);
  return {};
}

std::set<long long> range(long long a, long long b) {
  std::set<long long> s;
  for (auto i = a; i <= b; ++i) s.insert(i);
  return s;
}

}  // namespace

TEST_CASE("node groups of every supported kind resolve to the nodes the mesh implies", "[groups]") {
  const std::string extra = "/GRNOD/NODE/1\nlisted\n" + ids_line({1, 5, 9}) + "\n" +             //
                            "/GRNOD/PART/2\nboth parts\n" + ids_line({1, 2}) + "\n" +            //
                            "/GRNOD/PART/3\nblock minus plate\n" + ids_line({2, -1}) + "\n" +    //
                            "/GRNOD/GRNOD/4\nparts minus listed\n" + ids_line({2, -1}) + "\n" +  //
                            "/BOX/RECTA/1\nbottom layer\n\n" +
                            Line().put(-0.5, 1, 20).put(-0.5, 21, 40).put(0.5, 41, 60).str() + "\n" +
                            Line().put(2.5, 1, 20).put(2.5, 21, 40).put(1.5, 41, 60).str() + "\n" +  //
                            "/GRNOD/BOX/5\nin box\n" + ids_line({1}) + "\n" +                        //
                            "/GRNOD/GENE/6\nranges\n" + ids_line({1, 3, 7, 100}) + "\n" +            //
                            "/GRNOD/GEN_INCR/7\nodd\n" + ids_line({101, 109, 2}) + "\n" +            //
                            "/GRNOD/MAT/8\nsteel\n" + ids_line({1}) + "\n" +                         //
                            "/GRNOD/PROP/9\nsolid\n" + ids_line({2}) + "\n" +                        //
                            "/SURF/PART/1\nplate\n" + ids_line({1}) + "\n" +                         //
                            "/GRNOD/SURF/10\nsurface nodes\n" + ids_line({1}) + "\n";
  auto b = build(extra);
  for (const auto& d : b.diags.items()) INFO(radx::Diagnostics::format(d));
  REQUIRE_FALSE(b.diags.has_errors());
  const auto& m = b.model;
  CHECK(group_ids(m, 1) == std::set<long long>{1, 5, 9});
  std::set<long long> all = range(1, 9);
  for (auto i : range(101, 127)) all.insert(i);
  CHECK(group_ids(m, 2) == all);
  CHECK(group_ids(m, 3) == range(101, 127));  // the plate's nodes removed (none shared)
  CHECK(group_ids(m, 4) == [&] {
    auto s = all;
    for (auto i : {1, 5, 9}) s.erase(i);
    return s;
  }());
  CHECK(group_ids(m, 5) == range(101, 109));  // the block's bottom layer z = 1
  CHECK(group_ids(m, 6) == [&] {              // 1..3 and the existing ids in 7..100
    auto s = range(1, 3);
    s.insert({7, 8, 9});
    return s;
  }());
  CHECK(group_ids(m, 7) == std::set<long long>{101, 103, 105, 107, 109});
  CHECK(group_ids(m, 8) == range(1, 9));
  CHECK(group_ids(m, 9) == range(101, 127));
  CHECK(group_ids(m, 10) == range(1, 9));
}

TEST_CASE("/SURF/PART/EXT keeps the 24 outer faces of a 2x2x2 block, all pointing outward", "[groups]") {
  auto b = build(
      "/SURF/PART/EXT/1\nblock skin\n" + ids_line({2}) + "\n/SURF/PART/2\nflipped plate\n" + ids_line({-1}) +
      "\n/SURF/SEG/3\none face\n" +
      Line().put(1, 1, 10).put(101, 11, 20).put(104, 21, 30).put(105, 31, 40).put(102, 41, 50).str() + "\n");
  for (const auto& d : b.diags.items()) INFO(radx::Diagnostics::format(d));
  REQUIRE_FALSE(b.diags.has_errors());
  const auto& m = b.model;
  REQUIRE(m.surfaces.size() == 3);
  const auto& skin = m.surfaces[0];
  CHECK(skin.segments.size() == 24);  // 6 sides x 4 faces; the 12 inner faces are shared and dropped
  const radx::model::Vec3 centre{1.0, 1.0, 2.0};
  for (const auto& seg : skin.segments) {
    radx::model::Vec3 x[4];
    radx::model::Vec3 c{0, 0, 0};
    for (int k = 0; k < 4; ++k) {
      x[k] = {m.nodes.x[seg[k]], m.nodes.y[seg[k]], m.nodes.z[seg[k]]};
      c = radx::model::add(c, radx::model::scale(x[k], 0.25));
    }
    const auto n = radx::model::quad_normal(x[0], x[1], x[2], x[3]);
    CHECK(radx::model::dot(n, radx::model::sub(c, centre)) > 0);
  }
  // A negative part id in /SURF/PART flips the normal: the plate's shells face +z, the segments -z.
  for (const auto& seg : m.surfaces[1].segments) {
    radx::model::Vec3 x[4];
    for (int k = 0; k < 4; ++k) x[k] = {m.nodes.x[seg[k]], m.nodes.y[seg[k]], m.nodes.z[seg[k]]};
    CHECK(radx::model::quad_normal(x[0], x[1], x[2], x[3])[2] < 0);
  }
  // An explicit segment on the block's bottom face finds the brick behind it.
  REQUIRE(m.surfaces[2].segments.size() == 1);
  CHECK(m.surfaces[2].owner_type[0] == radx::model::SegmentOwner::Brick8);
}
