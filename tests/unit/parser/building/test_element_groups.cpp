// Element groups (/GRSHEL, /GRSH3N, /GRBRIC) and the surfaces and node groups built from them, on a deck
// built in the test. Every expected set below follows from the construction of the mesh:
//
//   plate      part 1: 3 x 3 four-node shells 1..9 at z = 0, nodes 1..16 on a 4 x 4 grid of spacing 1;
//              shell 1 + i + 3j has nodes n1 = 1 + i + 4j, n1 + 1, n1 + 5, n1 + 4 (normal +z).
//   triangles  part 3: 3-node shells 21..24 at z = -1 on nodes 201..206 (a 2 x 1 strip), normal +z.
//   block      part 2: 2 x 2 x 2 bricks 31..38, side 1, from z = 1 to z = 3; brick 31 + i + 2j + 4k,
//              nodes 101 + i + 3j + 9k at (i, j, 1 + k).
//   cover      part 5: shell 50 lying on the top face of brick 35 (the corner brick i = j = 0, k = 1).
// Parts 1 and 3 use material 1 and property 1, part 5 material 1 and property 3, part 2 material 2 and
// property 2. Part 1 is in subset 10, part 3 in its child subset 11.
#include <catch2/catch.hpp>
#include <map>
#include <set>

#include "parser/building/model_builder.hpp"
#include "solver/model/geometry.hpp"
#include "test_util.hpp"

using radx::model::ElementType;
using radx::model::Vec3;
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

int bid(int i, int j, int k) {
  return 101 + i + 3 * j + 9 * k;
}

std::string deck_text(const std::string& extra) {
  std::string s = radx::test::begin_block(2026) + "/NODE\n";
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) s += node_line(1 + i + 4 * j, i, j, 0.0);
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) s += node_line(bid(i, j, k), i, j, 1.0 + k);
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) s += node_line(201 + i + 3 * j, i, j, -1.0);
  s += "/SHELL/1\n";
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      const int n1 = 1 + i + 4 * j;
      s += ids_line({1 + i + 3 * j, n1, n1 + 1, n1 + 5, n1 + 4}) + "\n";
    }
  s += "/SH3N/3\n" + ids_line({21, 201, 202, 205}) + "\n" + ids_line({22, 201, 205, 204}) + "\n" +
       ids_line({23, 202, 203, 206}) + "\n" + ids_line({24, 202, 206, 205}) + "\n";
  s += "/BRICK/2\n";
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) {
        Line l;
        l.put(31 + i + 2 * j + 4 * k, 1, 10);
        const int n[8] = {
            bid(i, j, k),     bid(i + 1, j, k),     bid(i + 1, j + 1, k),     bid(i, j + 1, k),
            bid(i, j, k + 1), bid(i + 1, j, k + 1), bid(i + 1, j + 1, k + 1), bid(i, j + 1, k + 1)};
        for (int q = 0; q < 8; ++q) l.put(n[q], 11 + 10 * q, 20 + 10 * q);
        s += l.str() + "\n";
      }
  s += "/SHELL/5\n" + ids_line({50, bid(0, 0, 2), bid(1, 0, 2), bid(1, 1, 2), bid(0, 1, 2)}) + "\n";
  s += "/PART/1\nplate\n" + ids_line({1, 1, 10}) + "\n/PART/2\nblock\n" + ids_line({2, 2}) + "\n";
  s += "/PART/3\ntriangles\n" + ids_line({1, 1, 11}) + "\n/PART/5\ncover\n" + ids_line({3, 1}) + "\n";
  const std::string thick = Line().put(1.0, 21, 40).str();
  s += "/PROP/SHELL/1\nshell\n\n\n" + thick + "\n/PROP/SOLID/2\nsolid\n\n\n/PROP/SHELL/3\ncover\n\n\n" +
       thick + "\n";
  s += "/MAT/LAW1/1\nsteel\n" + Line().put(7.8e-9, 1, 20).str() + "\n" +
       Line().put(2.1e5, 1, 20).put(0.3, 21, 40).str() + "\n";
  s += "/MAT/LAW1/2\nalu\n" + Line().put(2.7e-9, 1, 20).str() + "\n" +
       Line().put(7e4, 1, 20).put(0.3, 21, 40).str() + "\n";
  s += "/SUBSET/10\nall\n" + ids_line({11}) + "\n/SUBSET/11\nchild\n";
  s += extra + "/END\n";
  return s;
}

// An axis-aligned box given by its two corners.
std::string box(int id, Vec3 a, Vec3 b) {
  return "/BOX/RECTA/" + std::to_string(id) + "\nbox\n\n" +
         Line().put(a[0], 1, 20).put(a[1], 21, 40).put(a[2], 41, 60).str() + "\n" +
         Line().put(b[0], 1, 20).put(b[1], 21, 40).put(b[2], 41, 60).str() + "\n";
}

// A /BOX/CYLIN (axis from a to b, diameter d; with nodes n1 and n2 when given) and a /BOX/SPHER.
std::string cylinder(int id, Vec3 a, Vec3 b, double d, long long n1 = 0, long long n2 = 0) {
  Line l;
  if (n1) l.put(n1, 1, 10);
  if (n2) l.put(n2, 11, 20);
  return "/BOX/CYLIN/" + std::to_string(id) + "\ncylinder\n" + l.put(d, 31, 50).str() + "\n" +
         Line().put(a[0], 1, 20).put(a[1], 21, 40).put(a[2], 41, 60).str() + "\n" +
         Line().put(b[0], 1, 20).put(b[1], 21, 40).put(b[2], 41, 60).str() + "\n";
}
std::string sphere(int id, Vec3 c, double d, long long n1 = 0) {
  Line l;
  if (n1) l.put(n1, 1, 10);
  return "/BOX/SPHER/" + std::to_string(id) + "\nsphere\n" + l.put(d, 31, 50).str() + "\n" +
         Line().put(c[0], 1, 20).put(c[1], 21, 40).put(c[2], 41, 60).str() + "\n";
}

std::string kw(const std::string& head, std::initializer_list<long long> ids) {
  return head + "\ntitle\n" + ids_line(ids) + "\n";
}

// The deck read and built through the builder, whose element groups the tests read back.
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
  // The user ids of the elements of group `id` of `type`.
  std::set<long long> elements(ElementType type, long long id) const {
    const auto* g = builder->element_group(type, id);
    REQUIRE(g != nullptr);
    std::set<long long> out;
    const auto& block = type == ElementType::Shell4   ? model.shells
                        : type == ElementType::Shell3 ? model.shells3
                        : type == ElementType::Truss2 ? model.trusses
                        : type == ElementType::Beam2  ? model.beams
                                                      : model.bricks;
    for (auto e : g->elements) {
      // The builder's blocks were moved into `model`: a brick group's indices past the bricks are
      // tetrahedra.
      const auto n = static_cast<std::int32_t>(block.size());
      out.insert(e < n ? block.id[e] : model.tetras.id[static_cast<std::size_t>(e - n)]);
    }
    CHECK(out.size() == g->elements.size());
    return out;
  }
  const radx::model::Surface& surface(long long id) const {
    for (const auto& s : model.surfaces)
      if (s.id == id) return s;
    FAIL("no surface " << id);
    return model.surfaces.front();
  }
  std::set<long long> nodes(long long gid) const {
    for (const auto& g : model.node_groups)
      if (g.id == gid) {
        std::set<long long> out;
        for (auto n : g.nodes) out.insert(model.nodes.id[n]);
        return out;
      }
    FAIL("no node group " << gid);
    return {};
  }
  Vec3 x(std::int32_t n) const { return {model.nodes.x[n], model.nodes.y[n], model.nodes.z[n]}; }
  // Unnormalised normal of a segment (triangles repeat their third node, which the formula allows).
  Vec3 normal(const std::array<std::int32_t, 4>& s) const {
    return radx::model::quad_normal(x(s[0]), x(s[1]), x(s[2]), x(s[3]));
  }
  Vec3 centre(const std::array<std::int32_t, 4>& s) const {
    Vec3 c{0, 0, 0};
    for (auto n : s) c = radx::model::add(c, radx::model::scale(x(n), 0.25));
    return c;
  }
  // The element user ids behind the segments of surface `id`, with the sign of the z normal.
  std::map<long long, int> owners_with_z_sign(long long id) const {
    const auto& s = surface(id);
    std::map<long long, int> out;
    for (std::size_t k = 0; k < s.segments.size(); ++k) {
      const auto& block = s.owner_type[k] == radx::model::SegmentOwner::Shell3 ? model.shells3 : model.shells;
      const double nz = normal(s.segments[k])[2];
      CHECK(out.count(block.id[s.owner[k]]) == 0);  // one segment per element
      out[block.id[s.owner[k]]] = nz > 0 ? 1 : (nz < 0 ? -1 : 0);
    }
    return out;
  }
};

std::unique_ptr<Built> build(const std::string& extra) {
  radx::test::TempDir dir;
  const auto path = dir.write("eg_0000.rad", deck_text(extra));
  auto b = std::make_unique<Built>();
  b->deck = radx::read_starter_deck(path, b->diags);
  b->builder = std::make_unique<radx::detail::ModelBuilder>(b->deck, b->diags);
  b->model = b->builder->build();
  return b;
}

std::set<long long> range(long long a, long long b) {
  std::set<long long> s;
  for (auto i = a; i <= b; ++i) s.insert(i);
  return s;
}

bool has(const radx::Diagnostics& d, radx::Diag code, radx::Severity sev = radx::Severity::Error) {
  for (const auto& x : d.items())
    if (x.code == code && x.severity == sev) return true;
  return false;
}

}  // namespace

TEST_CASE("element groups by id, part, subset, material, property and group resolve to the mesh's sets",
          "[element_groups]") {
  const auto b = build(kw("/GRSHEL/SHEL/1", {1, 5, 9, 5}) +  // a repeated id counts once
                       kw("/GRSHEL/PART/2", {1, 5}) +        // plate and cover
                       kw("/GRSHEL/PART/3", {1, 5, -5}) +    //
                       kw("/GRSHEL/PART/4", {-5, 1, 5}) +    // the negative id wins whatever the order
                       kw("/GRSHEL/GRSHEL/5", {2, -1}) +     //
                       kw("/GRSHEL/GRSHEL/6", {-1, 3}) +     //
                       kw("/GRSHEL/SUBSET/7", {10}) +        // part 1 (part 3 has no 4-node shell)
                       kw("/GRSHEL/MAT/8", {1}) +            // parts 1, 3 and 5
                       kw("/GRSHEL/PROP/9", {3}) +           // part 5
                       kw("/GRSH3N/SH3N/1", {22, 24}) +      //
                       kw("/GRSH3N/SUBSET/2", {10}) +        // part 3 through the child subset 11
                       kw("/GRSH3N/GRSH3N/3", {2, -1}) +     //
                       kw("/GRSH3N/PART/4", {3, 1}) +        // part 1 adds no 3-node shell
                       kw("/GRBRIC/BRIC/1", {31, 38}) +      //
                       kw("/GRBRIC/MAT/2", {2}) +            //
                       kw("/GRBRIC/PROP/3", {2, -2}) + kw("/GRBRIC/GRBRIC/4", {2, -1}) +
                       kw("/GRBRIC/PART/5", {2}) + kw("/GRBRIC/SUBSET/6", {10}));
  INFO(b->report());
  // /GRBRIC/PROP/3 removes all it adds and /GRBRIC/SUBSET/6 reaches no brick: two warnings (as in Radioss),
  // nothing else.
  CHECK_FALSE(b->diags.has_errors());
  std::vector<std::string> errors;
  for (const auto& d : b->diags.items())
    if (d.severity == radx::Severity::Warning) errors.push_back(radx::Diagnostics::format(d));
  REQUIRE(errors.size() == 2);
  CHECK(errors[0].find("RX403") != std::string::npos);
  CHECK(errors[0].find("brick group 3 holds no brick") != std::string::npos);
  CHECK(errors[1].find("brick group 6 holds no brick") != std::string::npos);

  CHECK(b->elements(ElementType::Shell4, 1) == std::set<long long>{1, 5, 9});
  auto plate_and_cover = range(1, 9);
  plate_and_cover.insert(50);
  CHECK(b->elements(ElementType::Shell4, 2) == plate_and_cover);
  CHECK(b->elements(ElementType::Shell4, 3) == range(1, 9));
  CHECK(b->elements(ElementType::Shell4, 4) == range(1, 9));
  CHECK(b->elements(ElementType::Shell4, 5) == std::set<long long>{2, 3, 4, 6, 7, 8, 50});
  CHECK(b->elements(ElementType::Shell4, 6) == std::set<long long>{2, 3, 4, 6, 7, 8});
  CHECK(b->elements(ElementType::Shell4, 7) == range(1, 9));
  CHECK(b->elements(ElementType::Shell4, 8) == plate_and_cover);
  CHECK(b->elements(ElementType::Shell4, 9) == std::set<long long>{50});
  CHECK(b->elements(ElementType::Shell3, 1) == std::set<long long>{22, 24});
  CHECK(b->elements(ElementType::Shell3, 2) == range(21, 24));
  CHECK(b->elements(ElementType::Shell3, 3) == std::set<long long>{21, 23});
  CHECK(b->elements(ElementType::Shell3, 4) == range(21, 24));
  CHECK(b->elements(ElementType::Brick8, 1) == std::set<long long>{31, 38});
  CHECK(b->elements(ElementType::Brick8, 2) == range(31, 38));
  CHECK(b->elements(ElementType::Brick8, 4) == range(32, 37));
  CHECK(b->elements(ElementType::Brick8, 5) == range(31, 38));
}

TEST_CASE("BOX takes the elements with every node in the box, BOX2 those with one node in it",
          "[element_groups]") {
  // Box 1: the plate's corner square [0, 1] x [0, 1], widened by 0.5 in-plane. Box 2: exactly that square,
  // flat (zero height) in the plate's plane: nodes on the boundary are inside. Box 3: the block's corner
  // cube [0, 1] x [0, 1] x [1, 2], widened by 0.5: it also holds the block's centre node (1, 1, 2), which
  // every brick has. Box 4: the strip's left end x in [-0.5, 0.5].
  const auto b =
      build(box(1, {-0.5, -0.5, -0.5}, {1.5, 1.5, 0.5}) + box(2, {1, 1, 0}, {0, 0, 0}) +
            box(3, {-0.5, -0.5, 0.5}, {1.5, 1.5, 2.5}) + box(4, {-0.5, -0.5, -1.5}, {0.5, 1.5, -0.5}) +
            kw("/GRSHEL/BOX/1", {1}) + kw("/GRSHEL/BOX2/2", {1}) + kw("/GRSHEL/BOX/3", {2}) +
            kw("/GRSHEL/BOX2/4", {2}) + kw("/GRBRIC/BOX/1", {3}) + kw("/GRBRIC/BOX2/2", {3}) +
            kw("/GRSH3N/BOX2/1", {4}) + kw("/GRSH3N/BOX/2", {1, 4}) + kw("/GRSHEL/BOX/5", {-3, 1, 3}));
  INFO(b->report());
  // /GRSH3N/BOX/2 takes box 1 only (the first id), which holds no triangle: an empty group, a warning as in
  // Radioss.
  std::size_t errors = 0;
  for (const auto& d : b->diags.items()) errors += d.severity == radx::Severity::Error;
  CHECK(errors == 0);
  CHECK(has(b->diags, radx::Diag::EmptyGroup, radx::Severity::Warning));
  // Shell 1 lies in the box; shells 2, 4 and 5 only touch it with nodes (1, 0), (0, 1) and (1, 1).
  CHECK(b->elements(ElementType::Shell4, 1) == std::set<long long>{1});
  CHECK(b->elements(ElementType::Shell4, 2) == std::set<long long>{1, 2, 4, 5});
  CHECK(b->elements(ElementType::Shell4, 3) == std::set<long long>{1});
  CHECK(b->elements(ElementType::Shell4, 4) == std::set<long long>{1, 2, 4, 5});
  CHECK(b->elements(ElementType::Brick8, 1) == std::set<long long>{31});
  CHECK(b->elements(ElementType::Brick8, 2) == range(31, 38));
  // Triangles with a node at x = 0: 21 and 22; none lies wholly in the strip's end.
  CHECK(b->elements(ElementType::Shell3, 1) == std::set<long long>{21, 22});
  CHECK(b->builder->element_group(ElementType::Shell3, 2)->elements.empty());
  // Only the first positive id counts; the others are ignored with a warning each.
  CHECK(b->elements(ElementType::Shell4, 5) == std::set<long long>{1});
  std::size_t ignored = 0;
  for (const auto& d : b->diags.items())
    ignored += d.code == radx::Diag::ExtraData && d.severity == radx::Severity::Warning;
  CHECK(ignored == 3);  // 4 in /GRSH3N/BOX/2; -3 and 3 in /GRSHEL/BOX/5
}

TEST_CASE("cylinder and sphere boxes select nodes and elements as the rectangular box does",
          "[element_groups]") {
  // Hand counts on the deck's grid: plate nodes 1 + i + 4 j at (i, j, 0), shell 1 + i + 3 j the unit square
  // of corner (i, j); brick nodes at (i, j, 1 + k), brick 31 + i + 2 j + 4 k the unit cube of corner
  // (i, j, 1 + k); triangle nodes 201.. at (i, j, -1). Boundaries are inside.
  // Sphere 1: centre (1, 1, 0), D = 2: the plate nodes at distance <= 1 (2, 5, 6, 7, 10), the brick node
  // (1, 1, 1) = 105 and the triangle node (1, 1, -1) = 205. Sphere 2: the same centre from node 6. Sphere 3:
  // D = 2.83 (radius just above sqrt(2)): shells 1, 2, 4, 5 lie in it. Sphere 4: centre (1, 0.5, -1), D
  // = 2.4, holds the six triangle nodes. Cylinder 5: the vertical axis (1, 1), z from 1 to 2, D = 2.83: the
  // 18 brick nodes of the lower layer, so the lower bricks 31..34 wholly, every brick with a node. Cylinder
  // 6: the plate's diagonal from (0, 0) to (4, 4), D = 0.2: the diagonal nodes 1, 6, 11, 16. Cylinder 7: from
  // node 6 to node 16, the same diagonal cut at (1, 1): 6, 11, 16 (its base node on the end face is inside).
  // Cylinder 8: N1 only, so its coordinates (those of cylinder 6) are read, with a warning.
  const double r2 = 2.83;
  const auto b = build(
      sphere(1, {1, 1, 0}, 2.0) + sphere(2, {9, 9, 9}, 2.0, 6) + sphere(3, {1, 1, 0}, r2) +
      sphere(4, {1, 0.5, -1}, 2.4) + cylinder(5, {1, 1, 1}, {1, 1, 2}, r2) +
      cylinder(6, {0, 0, 0}, {4, 4, 0}, 0.2) + cylinder(7, {9, 9, 9}, {8, 8, 8}, 0.2, 6, 16) +
      cylinder(8, {0, 0, 0}, {4, 4, 0}, 0.2, 6) + kw("/GRNOD/BOX/1", {1}) + kw("/GRNOD/BOX/2", {2}) +
      kw("/GRNOD/BOX/5", {5}) + kw("/GRNOD/BOX/6", {6}) + kw("/GRNOD/BOX/7", {7}) + kw("/GRNOD/BOX/8", {8}) +
      kw("/GRNOD/BOX/9", {1, 6}) + kw("/GRSHEL/BOX/1", {3}) + kw("/GRSHEL/BOX2/2", {1}) +
      kw("/GRSH3N/BOX/1", {4}) + kw("/GRBRIC/BOX/1", {5}) + kw("/GRBRIC/BOX2/2", {5}));
  INFO(b->report());
  std::size_t errors = 0, lone = 0;
  for (const auto& d : b->diags.items()) {
    errors += d.severity == radx::Severity::Error;
    lone += d.code == radx::Diag::InconsistentValues && d.severity == radx::Severity::Warning;
  }
  CHECK(errors == 0);
  CHECK(lone == 1);
  CHECK(b->nodes(1) == std::set<long long>{2, 5, 6, 7, 10, 105, 205});
  CHECK(b->nodes(2) == b->nodes(1));
  CHECK(b->nodes(5) == range(101, 118));
  CHECK(b->nodes(6) == std::set<long long>{1, 6, 11, 16});
  CHECK(b->nodes(7) == std::set<long long>{6, 11, 16});
  CHECK(b->nodes(8) == b->nodes(6));
  CHECK(b->nodes(9) == std::set<long long>{1, 2, 5, 6, 7, 10, 11, 16, 105, 205});  // union of two shapes
  CHECK(b->elements(ElementType::Shell4, 1) == std::set<long long>{1, 2, 4, 5});
  CHECK(b->elements(ElementType::Shell4, 2) == range(1, 8));  // every shell with a node of sphere 1
  CHECK(b->elements(ElementType::Shell3, 1) == range(21, 24));
  CHECK(b->elements(ElementType::Brick8, 1) == range(31, 34));
  CHECK(b->elements(ElementType::Brick8, 2) == range(31, 38));
}

TEST_CASE("boxes share one id space, a cylinder needs an axis and a diameter", "[element_groups]") {
  const auto b = build(box(1, {0, 0, 0}, {1, 1, 1}) + sphere(1, {0, 0, 0}, 1.0) +
                       cylinder(2, {1, 1, 1}, {1, 1, 1}, 1.0) + cylinder(3, {0, 0, 0}, {0, 0, 1}, 0.0));
  INFO(b->report());
  CHECK(has(b->diags, radx::Diag::DuplicateId));
  CHECK(b->report().find("unique among boxes") != std::string::npos);
  CHECK(has(b->diags, radx::Diag::InconsistentValues));    // cylinder 2: P1 = P2
  CHECK(has(b->diags, radx::Diag::RequiredValueMissing));  // cylinder 3: no diameter
}

TEST_CASE(
    "a loop of element groups and missing or negative element ids are errors and a missing part or group is "
    "left out with a warning as in Radioss",
    "[element_groups]") {
  const auto b =
      build(kw("/GRSHEL/GRSHEL/1", {2}) + kw("/GRSHEL/GRSHEL/2", {1}) +  //
            kw("/GRBRIC/BRIC/3", {31, 99}) + kw("/GRSH3N/SH3N/4", {-21, 22}) + kw("/GRSHEL/PART/5", {1, 7}) +
            kw("/GRSHEL/MAT/6", {1, 8}) + kw("/GRSHEL/PROP/7", {1, 9}) + kw("/GRSHEL/SUBSET/8", {10, 12}) +
            kw("/GRSHEL/BOX/9", {4}) + kw("/GRSHEL/GRSHEL/10", {8, 11}));
  INFO(b->report());
  std::map<int, std::vector<int>> by_code, warned;  // code -> lines
  for (const auto& d : b->diags.items()) {
    if (d.severity == radx::Severity::Error) by_code[static_cast<int>(d.code)].push_back(d.line);
    if (d.severity == radx::Severity::Warning) warned[static_cast<int>(d.code)].push_back(d.line);
  }
  // One loop error for the 1 -> 2 -> 1 loop, at group 1's keyword line; missing element 99 and negative
  // element -21: two errors. Part 7, material 8, property 9, subset 12, box 4, group 11: six warnings, and
  // group 9 (box 4 only) ends up empty: a warning.
  REQUIRE(by_code[507].size() == 1);
  CHECK(by_code[402].size() == 2);
  CHECK(by_code.size() == 2);
  CHECK(warned[402].size() == 6);
  CHECK(warned[403].size() == 1);
  const auto text = b->report();
  CHECK(text.find("4-node shell group 1 includes itself through /GRSHEL/GRSHEL") != std::string::npos);
  CHECK(text.find("brick 99 does not exist: no /BRICK, /TETRA4 or /BRIC20 line defines it (listed in brick "
                  "group 3)") != std::string::npos);
  CHECK(text.find("there is no 3-node shell -21") != std::string::npos);
}

TEST_CASE("/SURF/GRSHEL and /SURF/GRSH3N give one segment per element, flipped for a negative id",
          "[element_groups]") {
  const auto b =
      build(kw("/GRSHEL/SHEL/1", {1, 5, 9}) + kw("/GRSHEL/SHEL/2", {2, 5}) + kw("/GRSH3N/SH3N/1", {21, 22}) +
            kw("/GRSH3N/SH3N/2", {22, 23}) + kw("/SURF/GRSHEL/1", {1}) + kw("/SURF/GRSHEL/2", {-2}) +
            kw("/SURF/GRSHEL/3", {-2, 1}) +  // shell 5 in both: the positive id wins
            kw("/SURF/GRSH3N/4", {1, -2}) + kw("/SURF/PART/5", {-1, 1}) + kw("/SURF/PART/6", {-3}));
  INFO(b->report());
  REQUIRE_FALSE(b->diags.has_errors());
  using M = std::map<long long, int>;
  CHECK(b->owners_with_z_sign(1) == M{{1, 1}, {5, 1}, {9, 1}});
  CHECK(b->owners_with_z_sign(2) == M{{2, -1}, {5, -1}});
  CHECK(b->owners_with_z_sign(3) == M{{1, 1}, {2, -1}, {5, 1}, {9, 1}});
  CHECK(b->owners_with_z_sign(4) == M{{21, 1}, {22, 1}, {23, -1}});
  // /SURF/PART reads the part once, with the orientation of its positive id.
  M plate;
  for (long long e = 1; e <= 9; ++e) plate[e] = 1;
  CHECK(b->owners_with_z_sign(5) == plate);
  CHECK(b->owners_with_z_sign(6) == M{{21, -1}, {22, -1}, {23, -1}, {24, -1}});
  // Segments are the element's nodes in its order (triangles repeat n3), or reversed.
  const auto& s1 = b->surface(1);
  for (std::size_t k = 0; k < s1.segments.size(); ++k) {
    const auto* c = &b->model.shells.conn[4 * static_cast<std::size_t>(s1.owner[k])];
    CHECK(s1.segments[k] == std::array<std::int32_t, 4>{c[0], c[1], c[2], c[3]});
  }
  for (const auto& seg : b->surface(4).segments) CHECK(seg[3] == seg[2]);
}

TEST_CASE("/SURF/GRBRIC/EXT and /FREE keep outer faces, /SURF/PART/ALL keeps every face of the bricks",
          "[element_groups]") {
  const auto b =
      build(kw("/GRBRIC/PART/1", {2}) + kw("/GRBRIC/BRIC/2", {31, 32, 33, 34}) +  // bottom layer
            kw("/SURF/GRBRIC/EXT/1", {1}) + kw("/SURF/GRBRIC/EXT/2", {2}) + kw("/SURF/GRBRIC/FREE/3", {2}) +
            kw("/SURF/PART/ALL/4", {2}) + kw("/SURF/PART/EXT/5", {2}) + kw("/SURF/PART/EXT/6", {2, 5}) +
            kw("/SURF/PART/ALL/7", {2, 5}) + kw("/SURF/GRBRIC/EXT/8", {-2}));
  INFO(b->report());
  REQUIRE_FALSE(b->diags.has_errors());
  const auto& m = b->model;
  // Every brick segment points out of its own brick.
  for (long long sid : {1, 2, 3, 4, 5, 6, 7, 8}) {
    const auto& s = b->surface(sid);
    for (std::size_t k = 0; k < s.segments.size(); ++k) {
      if (s.owner_type[k] != radx::model::SegmentOwner::Brick8) continue;
      Vec3 c{0, 0, 0};
      for (int q = 0; q < 8; ++q)
        c = radx::model::add(
            c, radx::model::scale(b->x(m.bricks.conn[8 * static_cast<std::size_t>(s.owner[k]) + q]), 0.125));
      INFO("surface " << sid << " segment " << k);
      CHECK(radx::model::dot(b->normal(s.segments[k]), radx::model::sub(b->centre(s.segments[k]), c)) > 0);
    }
  }
  // The whole block: 6 sides x 4 faces; its 12 inner faces are dropped.
  CHECK(b->surface(1).segments.size() == 24);
  // The bottom layer alone: 4 bottom, 4 top, 8 side faces. Its top faces touch the upper layer, which is
  // not in the group (EXT keeps them) but is in the model (FREE drops them).
  CHECK(b->surface(2).segments.size() == 16);
  CHECK(b->surface(3).segments.size() == 12);
  for (const auto& seg : b->surface(3).segments) CHECK(b->centre(seg)[2] < 2.0);
  // ALL: the 8 bricks' 48 faces; each of the 12 inner faces twice, once from each side.
  const auto& all = b->surface(4);
  REQUIRE(all.segments.size() == 48);
  std::map<std::array<std::int32_t, 4>, std::vector<std::size_t>> by_nodes;
  for (std::size_t k = 0; k < all.segments.size(); ++k) {
    auto key = all.segments[k];
    std::sort(key.begin(), key.end());
    by_nodes[key].push_back(k);
  }
  CHECK(by_nodes.size() == 36);
  std::size_t twice = 0;
  for (const auto& [key, segs] : by_nodes) {
    if (segs.size() != 2) continue;
    ++twice;
    CHECK(radx::model::dot(b->normal(all.segments[segs[0]]), b->normal(all.segments[segs[1]])) < 0);
    CHECK(all.owner[segs[0]] != all.owner[segs[1]]);
  }
  CHECK(twice == 12);
  CHECK(b->surface(5).segments.size() == 24);
  // Shell 50 of the listed part 5 covers the top face of brick 35: its segment replaces the brick's face.
  for (long long sid : {6, 7}) {
    const auto& s = b->surface(sid);
    CHECK(s.segments.size() == (sid == 6 ? 24u : 48u));
    std::size_t shells = 0, top_of_35 = 0;
    for (std::size_t k = 0; k < s.segments.size(); ++k) {
      if (s.owner_type[k] == radx::model::SegmentOwner::Shell4) {
        ++shells;
        CHECK(m.shells.id[s.owner[k]] == 50);
      } else if (m.bricks.id[s.owner[k]] == 35 && b->centre(s.segments[k])[2] == Approx(3.0)) {
        ++top_of_35;
      }
    }
    CHECK(shells == 1);
    CHECK(top_of_35 == 0);
  }
  // A negative brick group id counts as a positive one: the bottom layer's 16 outer faces.
  CHECK(b->surface(8).segments.size() == 16);
}

TEST_CASE("/GRNOD/GRSHEL, /GRSH3N and /GRBRIC take the nodes of the groups' elements", "[element_groups]") {
  const auto b = build(kw("/GRSHEL/SHEL/1", {1}) + kw("/GRSHEL/SHEL/2", {9}) + kw("/GRSH3N/SH3N/1", {23}) +
                       kw("/GRBRIC/BRIC/1", {31}) + kw("/GRNOD/GRSHEL/1", {1, 2}) +
                       kw("/GRNOD/GRSHEL/2", {1, -2}) +  // a negative id removes nothing: ignored
                       kw("/GRNOD/GRSH3N/3", {1}) + kw("/GRNOD/GRBRIC/4", {1}) + kw("/GRNOD/GRSHEL/5", {-1}));
  INFO(b->report());
  CHECK(b->nodes(1) == std::set<long long>{1, 2, 5, 6, 11, 12, 15, 16});
  CHECK(b->nodes(2) == std::set<long long>{1, 2, 5, 6});
  CHECK(b->nodes(3) == std::set<long long>{202, 203, 206});
  CHECK(b->nodes(4) == std::set<long long>{bid(0, 0, 0), bid(1, 0, 0), bid(1, 1, 0), bid(0, 1, 0),
                                           bid(0, 0, 1), bid(1, 0, 1), bid(1, 1, 1), bid(0, 1, 1)});
  // Group 5 lists only a negative id: it holds no node, a warning as in Radioss; the two negative ids warn.
  std::size_t errors = 0, warnings = 0;
  for (const auto& d : b->diags.items()) {
    errors += d.severity == radx::Severity::Error;
    warnings += d.severity == radx::Severity::Warning && d.code == radx::Diag::ValueOutOfRange;
  }
  CHECK(errors == 0);
  CHECK(has(b->diags, radx::Diag::EmptyGroup, radx::Severity::Warning));
  CHECK(warnings == 2);
}

TEST_CASE("/SURF/GRBRIC without /EXT or /FREE is refused, as Radioss refuses it", "[element_groups]") {
  const auto b = build(kw("/GRBRIC/PART/1", {2}) + kw("/SURF/GRBRIC/1", {1}));
  INFO(b->report());
  CHECK(has(b->diags, radx::Diag::PartWrongKind));
  std::size_t errors = 0;
  for (const auto& d : b->diags.items()) errors += d.severity == radx::Severity::Error;
  CHECK(errors == 1);
}

namespace {
// A tetrahedron 61 of part 6 (nodes 301..304 above the block, positive as written) for the tests below.
std::string tetra_part() {
  return "/NODE\n" + node_line(301, 0, 0, 5) + node_line(302, 0, 1, 5) + node_line(303, 1, 0, 5) +
         node_line(304, 0, 0, 6) + "/TETRA4/6\n" + ids_line({61, 301, 302, 303, 304}) + "\n/PART/6\ntetra\n" +
         ids_line({2, 2}) + "\n";
}
}  // namespace

TEST_CASE("/GRBRIC holds tetrahedra as Radioss does: by id, part, range and box, and what is built from it",
          "[element_groups]") {
  const auto b =
      build(tetra_part() + box(7, {-0.5, -0.5, 4.5}, {1.5, 1.5, 6.5}) + kw("/GRBRIC/BRIC/11", {31, 61}) +
            kw("/GRBRIC/PART/12", {6}) + kw("/GRBRIC/GENE/13", {36, 70}) + kw("/GRBRIC/BOX/14", {7}) +
            kw("/GRNOD/GRBRIC/15", {12}) + kw("/SURF/GRBRIC/EXT/16", {12}));
  INFO(b->report());
  CHECK_FALSE(b->diags.has_errors());
  CHECK(b->elements(ElementType::Brick8, 11) == std::set<long long>{31, 61});
  CHECK(b->elements(ElementType::Brick8, 12) == std::set<long long>{61});
  CHECK(b->elements(ElementType::Brick8, 13) == std::set<long long>{36, 37, 38, 61});
  CHECK(b->elements(ElementType::Brick8, 14) == std::set<long long>{61});
  CHECK(b->nodes(15) == std::set<long long>{301, 302, 303, 304});
  const auto& s = b->surface(16);
  REQUIRE(s.segments.size() == 4);
  for (std::size_t k = 0; k < 4; ++k) CHECK(s.owner_type[k] == radx::model::SegmentOwner::Tetra4);
}

TEST_CASE("GENE groups take the ids of a range that exist, however wide, with a note for a far wider range",
          "[element_groups]") {
  const auto b = build(kw("/GRSHEL/GENE/1", {1, 999999999}) + kw("/GRSH3N/GENE/2", {22, 23}) +
                       kw("/GRBRIC/GENE/3", {1, 999999999}) + kw("/GRNOD/GENE/4", {1, 999999999}) +
                       kw("/GRNOD/GENE/5", {3, 6}));
  INFO(b->report());
  CHECK_FALSE(b->diags.has_errors());
  CHECK(b->diags.warning_count() == 0);
  CHECK(b->elements(ElementType::Shell4, 1) == std::set<long long>{1, 2, 3, 4, 5, 6, 7, 8, 9, 50});
  CHECK(b->elements(ElementType::Shell3, 2) == std::set<long long>{22, 23});
  CHECK(b->elements(ElementType::Brick8, 3) == range(31, 38));
  CHECK(b->nodes(4).size() == 16 + 27 + 6);
  CHECK(b->nodes(5) == std::set<long long>{3, 4, 5, 6});
  std::size_t notes = 0;
  for (const auto& d : b->diags.items())
    if (d.severity == radx::Severity::Note && d.code == radx::Diag::DefaultApplied &&
        d.message.find("far wider than the model") != std::string::npos)
      ++notes;
  CHECK(notes == 3);
  CHECK(b->report().find("range 1 to 999999999 (999999999 ids) is far wider than the model: 49 of its ids "
                         "exist") != std::string::npos);
}

TEST_CASE("A GENE range from the most negative to the largest id a field holds takes every existing id",
          "[element_groups]") {
  const auto b = build(kw("/GRNOD/GENE/4", {-999999999LL, 9999999999LL}) +
                       kw("/GRSHEL/GENE/1", {-999999999LL, 9999999999LL}));
  INFO(b->report());
  CHECK_FALSE(b->diags.has_errors());
  CHECK(b->nodes(4).size() == 16 + 27 + 6);
  CHECK(b->elements(ElementType::Shell4, 1) == std::set<long long>{1, 2, 3, 4, 5, 6, 7, 8, 9, 50});
}

TEST_CASE("/GRTRUS and /GRBEAM take trusses and beams by id, part, range, group and box",
          "[element_groups]") {
  // Trusses 71, 72 of part 7 along the plate's first row of nodes; beams 81, 82 of part 8 along its second
  // row, beam 81 oriented by node 16 (x = 3, y = 3), outside the box below, which its own nodes lie in.
  const std::string lines =
      "/NODE\n" + node_line(401, 0, 0, 10) + node_line(402, 1, 0, 10) + node_line(403, 2, 0, 10) +
      node_line(411, 0, 1, 10) + node_line(412, 1, 1, 10) + node_line(413, 2, 1, 10) +
      node_line(420, 5, 5, 5) + "/TRUSS/7\n" + ids_line({71, 401, 402}) + "\n" + ids_line({72, 402, 403}) +
      "\n" + "/BEAM/8\n" + ids_line({81, 411, 412, 420}) + "\n" + ids_line({82, 412, 413}) + "\n" +
      "/PART/7\ntruss\n" + ids_line({7, 1}) + "\n/PART/8\nbeam\n" + ids_line({8, 1}) + "\n" +
      "/PROP/TRUSS/7\ntruss\n" + Line().put(1.0, 1, 20).str() + "\n/PROP/BEAM/8\nbeam\n\n\n" +
      Line().put(1.0, 1, 20).put(0.1, 21, 40).put(0.1, 41, 60).put(0.2, 61, 80).str() + "\n\n";
  const auto b = build(lines + kw("/GRTRUS/TRUS/1", {72}) + kw("/GRTRUS/PART/2", {7}) +
                       kw("/GRBEAM/GENE/3", {80, 90}) + kw("/GRBEAM/GRBEAM/4", {3, -5}) +
                       kw("/GRBEAM/BEAM/5", {82}) + box(9, {-0.5, 0.5, 9.5}, {1.5, 1.5, 10.5}) +
                       kw("/GRBEAM/BOX/6", {9}) + kw("/GRTRUS/BOX2/7", {9}) + kw("/GRNOD/PART/40", {8, 7}) +
                       kw("/GRNOD/GRBEAM/41", {4}) + kw("/GRNOD/GRTRUS/42", {1}));
  INFO(b->report());
  CHECK_FALSE(b->diags.has_errors());
  CHECK(b->elements(ElementType::Truss2, 1) == std::set<long long>{72});
  CHECK(b->elements(ElementType::Truss2, 2) == std::set<long long>{71, 72});
  CHECK(b->elements(ElementType::Beam2, 3) == std::set<long long>{81, 82});
  CHECK(b->elements(ElementType::Beam2, 4) == std::set<long long>{81});
  // BOX: beam 81's two nodes (411, 412) lie in the box; its orientation node 420 does not count.
  CHECK(b->elements(ElementType::Beam2, 6) == std::set<long long>{81});
  // BOX2: a truss with one node in the box (node 401 or 402 at y = 0 are outside it: none).
  CHECK(b->elements(ElementType::Truss2, 7).empty());
  // Node groups take the nodes of trusses and beams, a beam's two: never its orientation node 420.
  CHECK(b->nodes(40) == std::set<long long>{401, 402, 403, 411, 412, 413});
  CHECK(b->nodes(41) == std::set<long long>{411, 412});
  CHECK(b->nodes(42) == std::set<long long>{402, 403});
}
