// //SUBMODEL ... //ENDSUB with their id offsets and units, /TRANSFORM/TRA, /ROT, /SCA and /SYM on submodels
// and node groups, and /MOVE_FUNCT (parser/reading/deck_reader.cpp, parser/building/build_transforms.cpp).
// Every expected value is a closed form written out independently of the code under test:
//   rotation   x' = c + (x - c) cos a + (u x (x - c)) sin a + u (u . (x - c)) (1 - cos a)  (Rodrigues)
//   scaling    x' = c + s (x - c) componentwise, volume V s_x s_y s_z
//   mirror     x' = x - 2 ((x - p) . n) n with |n| = 1, volume unchanged
//   function   g(x) = Fscaley f((x - Ashiftx) / Ascalex) + Fshifty.
// The included part ("part.inc") is a unit brick of part 1 (nodes 1..8, brick 1, material 1, property 1)
// with a node group 1 of its nodes and a function 1.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

#include "solver/conditions/functions.hpp"
#include "solver/model/geometry.hpp"
#include "test_util.hpp"

using radx::model::Vec3;
using radx::test::Line;
using radx::test::TempDir;

namespace {

const Vec3 kCorner[8] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                         {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};

std::string ids_line(std::initializer_list<long long> ids) {
  Line l;
  int c = 0;
  for (auto id : ids) {
    l.put(id, 10 * c + 1, 10 * c + 10);
    ++c;
  }
  return l.str() + "\n";
}

std::string reals_line(std::initializer_list<double> v, int first = 1) {
  Line l;
  int c = first;
  for (double x : v) {
    l.put(x, c, c + 19);
    c += 20;
  }
  return l.str() + "\n";
}

std::string part_text() {
  std::string s = "/NODE\n";
  for (int k = 0; k < 8; ++k)
    s += Line()
             .put(k + 1, 1, 10)
             .put(kCorner[k][0], 11, 30)
             .put(kCorner[k][1], 31, 50)
             .put(kCorner[k][2], 51, 70)
             .str() +
         "\n";
  s += "/MAT/LAW1/1\nsteel\n" + reals_line({7.8e-9}) + reals_line({210000.0, 0.3});
  s += "/PROP/SOLID/1\nsolid\n\n\n\n";
  s += "/PART/1\nblock\n" + ids_line({1, 1});
  s += "/BRICK/1\n" + ids_line({1, 1, 2, 3, 4, 5, 6, 7, 8});
  s += "/GRNOD/NODE/1\nits nodes\n" + ids_line({1, 2, 3, 4, 5, 6, 7, 8});
  s += "/FUNCT/1\nramp\n" + reals_line({0.0, 0.0}) + reals_line({1.0, 2.0}) + reals_line({3.0, 4.0});
  return s;
}

// //SUBMODEL/id[/unit] with its offsets card (off_def, off_nod, off_ele, off_part, off_mat, off_type,
// off_sub).
std::string submodel(long long id, std::initializer_list<long long> offsets, const std::string& body,
                     long long unit = 0) {
  std::string s = "//SUBMODEL/" + std::to_string(id) + (unit ? "/" + std::to_string(unit) : "") + "\ncopy " +
                  std::to_string(id) + "\n" + ids_line(offsets);
  return s + body + "//ENDSUB\n";
}

// /TRANSFORM/kind/id on a node group (grnod != 0) or a submodel (sub != 0), card 1 then card 2 (ROT, SYM).
std::string transform(const std::string& kind, long long id, long long grnod, Vec3 v, long long n1,
                      long long n2, long long sub, const std::string& card2 = "") {
  std::string s = "/TRANSFORM/" + kind + "/" + std::to_string(id) + "\n" + kind + "\n";
  s += Line()
           .put(grnod, 1, 10)
           .put(v[0], 11, 30)
           .put(v[1], 31, 50)
           .put(v[2], 51, 70)
           .put(n1 ? std::to_string(n1) : std::string(), 71, 80)
           .put(n2 ? std::to_string(n2) : std::string(), 81, 90)
           .put(sub ? std::to_string(sub) : std::string(), 91, 100)
           .str() +
       "\n";
  return s + card2;
}

std::string rot_card2(Vec3 p2, double angle) {
  return Line().put(p2[0], 11, 30).put(p2[1], 31, 50).put(p2[2], 51, 70).put(angle, 71, 90).str() + "\n";
}

// A deck: /BEGIN (2026, Mg mm s), `body`, /END; part.inc written beside it.
struct Deck {
  TempDir dir;
  std::string path;
  explicit Deck(const std::string& body) {
    dir.write("part.inc", part_text());
    path = dir.write("m_0000.rad", radx::test::begin_block(2026) + body + "/END\n");
  }
};

radx::model::Model build(const std::string& body) {
  Deck d(body);
  radx::Diagnostics diags;
  const auto deck = radx::read_starter_deck(d.path, diags);
  auto m = radx::build_model(deck, diags);
  for (const auto& x : diags.items()) INFO(radx::Diagnostics::format(x));
  REQUIRE_FALSE(diags.has_errors());
  return m;
}

// The diagnostics of a deck that must fail.
std::vector<radx::Diagnostic> errors_of(const std::string& body, const std::string& extra_file = "",
                                        const std::string& extra_text = "") {
  Deck d(body);
  if (!extra_file.empty()) d.dir.write(extra_file, extra_text);
  radx::Diagnostics diags;
  const auto deck = radx::read_starter_deck(d.path, diags);
  if (!diags.has_errors()) (void)radx::build_model(deck, diags);
  std::vector<radx::Diagnostic> out;
  for (const auto& x : diags.items())
    if (x.severity == radx::Severity::Error) out.push_back(x);
  return out;
}

Vec3 node(const radx::model::Model& m, long long id) {
  const auto k = m.nodes.index.find(id);
  REQUIRE(k >= 0);
  return {m.nodes.x[k], m.nodes.y[k], m.nodes.z[k]};
}

double brick_volume(const radx::model::Model& m, long long id) {
  const auto e = m.bricks.index.find(id);
  REQUIRE(e >= 0);
  std::array<Vec3, 8> p{};
  for (int k = 0; k < 8; ++k) {
    const auto n = m.bricks.conn[static_cast<std::size_t>(8 * e + k)];
    p[static_cast<std::size_t>(k)] = {m.nodes.x[n], m.nodes.y[n], m.nodes.z[n]};
  }
  return radx::model::brick_volume(p);
}

Vec3 rodrigues(Vec3 x, Vec3 c, Vec3 axis, double degrees) {
  const double l = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
  const Vec3 u{axis[0] / l, axis[1] / l, axis[2] / l};
  const Vec3 r{x[0] - c[0], x[1] - c[1], x[2] - c[2]};
  const double a = degrees * std::acos(-1.0) / 180.0;
  const Vec3 uxr{u[1] * r[2] - u[2] * r[1], u[2] * r[0] - u[0] * r[2], u[0] * r[1] - u[1] * r[0]};
  const double ur = u[0] * r[0] + u[1] * r[1] + u[2] * r[2];
  Vec3 out{};
  for (int i = 0; i < 3; ++i)
    out[i] = c[i] + r[i] * std::cos(a) + uxr[i] * std::sin(a) + u[i] * ur * (1 - std::cos(a));
  return out;
}

void require_near(const Vec3& a, const Vec3& b) {
  INFO("(" << a[0] << ", " << a[1] << ", " << a[2] << ") vs (" << b[0] << ", " << b[1] << ", " << b[2]
           << ")");
  for (int i = 0; i < 3; ++i) REQUIRE(a[i] == Approx(b[i]).margin(1e-12));
}

bool has(const std::vector<radx::Diagnostic>& ds, const std::string& code, int line,
         const std::string& file_suffix = "m_0000.rad") {
  for (const auto& d : ds)
    if (radx::diag_code(d.code) == code && d.line == line && d.file.size() >= file_suffix.size() &&
        d.file.compare(d.file.size() - file_suffix.size(), file_suffix.size(), file_suffix) == 0)
      return true;
  return false;
}

std::string dump(const std::vector<radx::Diagnostic>& ds) {
  std::string s;
  for (const auto& d : ds) s += radx::Diagnostics::format(d) + "\n";
  return s;
}

}  // namespace

TEST_CASE("a part included in two submodels is built twice, the second copy's ids shifted by its offsets",
          "[submodel]") {
  const auto m = build(submodel(1, {0}, "#include part.inc\n") + submodel(2, {1000}, "#include part.inc\n"));
  REQUIRE(m.nodes.size() == 16);
  REQUIRE(m.bricks.size() == 2);
  for (int k = 0; k < 8; ++k) {
    require_near(node(m, k + 1), kCorner[k]);
    require_near(node(m, 1001 + k), kCorner[k]);  // not moved: no transform names submodel 2
  }
  REQUIRE(m.bricks.index.find(1001) >= 0);
  REQUIRE(m.parts.size() == 2);
  REQUIRE(m.parts[1].id == 1001);
  REQUIRE(m.materials[static_cast<std::size_t>(m.parts[1].material)].id == 1001);
  REQUIRE(m.properties[static_cast<std::size_t>(m.parts[1].property)].id == 1001);
  // The brick of the copy uses the copy's nodes.
  const auto e = m.bricks.index.find(1001);
  REQUIRE(m.nodes.id[static_cast<std::size_t>(m.bricks.conn[static_cast<std::size_t>(8 * e)])] == 1001);
  REQUIRE(m.functions.size() == 2);
  REQUIRE(m.functions[1].id == 1001);
}

TEST_CASE("each kind of id takes its own offset, 0 meaning off_def", "[submodel]") {
  // off_def 100, off_nod 2000, off_ele 0 (-> 100), off_part 30, off_mat 0 (-> 100), off_type 50.
  const auto m = build(submodel(7, {100, 2000, 0, 30, 0, 50}, "#include part.inc\n"));
  REQUIRE(m.nodes.index.find(2001) >= 0);
  REQUIRE(m.bricks.index.find(101) >= 0);
  REQUIRE(m.parts[0].id == 31);
  REQUIRE(m.materials[0].id == 101);
  REQUIRE(m.properties[0].id == 51);
  REQUIRE(m.functions[0].id == 101);
  REQUIRE(m.node_groups[0].id == 101);
}

TEST_CASE("a submodel rotated about an axis through two points, then translated, in deck order",
          "[submodel][transform]") {
  const Vec3 p1{1, 2, 3}, p2{2, 3, 4};  // axis (1, 1, 1) through (1, 2, 3)
  const auto m = build(submodel(1, {0}, "#include part.inc\n") + submodel(2, {1000}, "#include part.inc\n") +
                       transform("ROT", 1, 0, p1, 0, 0, 2, rot_card2(p2, 30.0)) +
                       transform("TRA", 2, 0, {10, -5, 2}, 0, 0, 2));
  for (int k = 0; k < 8; ++k) {
    require_near(node(m, k + 1), kCorner[k]);
    Vec3 want = rodrigues(kCorner[k], p1, {1, 1, 1}, 30.0);
    want = {want[0] + 10, want[1] - 5, want[2] + 2};
    require_near(node(m, 1001 + k), want);
  }
  REQUIRE(brick_volume(m, 1001) == Approx(1.0));
}

TEST_CASE("a rotation about two nodes: the axis from node_ID1 to node_ID2, right-handed", "[transform]") {
  // Nodes 1 (0,0,0) and 5 (0,0,1) of the part: the z axis through the origin; +90 degrees takes x to y.
  const auto m = build(submodel(1, {0}, "#include part.inc\n") +
                       transform("ROT", 1, 0, {}, 1, 5, 1, rot_card2({}, 90.0)));
  require_near(node(m, 2), {0, 1, 0});
  require_near(node(m, 3), {-1, 1, 0});
  require_near(node(m, 7), {-1, 1, 1});
}

TEST_CASE("scaling about a centre node multiplies the distances to it and the volume by the factors",
          "[transform]") {
  // Node 7 is (1, 1, 1). Factors 2, 3, 0 (0 means 1).
  const auto m = build("#include part.inc\n" + transform("SCA", 1, 1, {2, 3, 0}, 7, 0, 0));
  for (int k = 0; k < 8; ++k)
    require_near(node(m, k + 1), {1 + 2 * (kCorner[k][0] - 1), 1 + 3 * (kCorner[k][1] - 1), kCorner[k][2]});
  REQUIRE(brick_volume(m, 1) == Approx(6.0));
}

TEST_CASE("a mirrored brick keeps a positive volume: its faces n1-n4 and n5-n8 are swapped", "[transform]") {
  // Plane through (5, 0, 0) normal to x (point 2 = (6, 0, 0)).
  const std::string sym = transform("SYM", 1, 1, {5, 0, 0}, 0, 0, 0, reals_line({6.0, 0.0, 0.0}, 11));
  const auto m = build("#include part.inc\n" + sym);
  for (int k = 0; k < 8; ++k)
    require_near(node(m, k + 1), {10 - kCorner[k][0], kCorner[k][1], kCorner[k][2]});
  REQUIRE(brick_volume(m, 1) == Approx(1.0));
  // Swapped connectivity: n1..n4 now the written n5..n8.
  std::vector<long long> conn;
  for (int k = 0; k < 8; ++k) conn.push_back(m.nodes.id[static_cast<std::size_t>(m.bricks.conn[k])]);
  REQUIRE(conn == std::vector<long long>{5, 6, 7, 8, 1, 2, 3, 4});
  SECTION("a negative scale factor mirrors too") {
    const auto s = build("#include part.inc\n" + transform("SCA", 1, 1, {-1, 1, 1}, 0, 0, 0));
    require_near(node(s, 2), {-1, 0, 0});
    REQUIRE(brick_volume(s, 1) == Approx(1.0));
  }
  SECTION("a mirrored submodel: the copy is the mirror image, the original is untouched") {
    const std::string sub_sym = transform("SYM", 1, 0, {0, 0, 0}, 0, 0, 2, reals_line({0.0, 1.0, 1.0}, 11));
    const auto s =
        build(submodel(1, {0}, "#include part.inc\n") + submodel(2, {1000}, "#include part.inc\n") + sub_sym);
    const double r = 1.0 / std::sqrt(2.0);
    const Vec3 n{0, r, r};
    for (int k = 0; k < 8; ++k) {
      const double d = kCorner[k][1] * n[1] + kCorner[k][2] * n[2];
      require_near(node(s, 1001 + k),
                   {kCorner[k][0], kCorner[k][1] - 2 * d * n[1], kCorner[k][2] - 2 * d * n[2]});
    }
    REQUIRE(brick_volume(s, 1) == Approx(1.0));
    REQUIRE(brick_volume(s, 1001) == Approx(1.0));
  }
}

TEST_CASE("node-group transforms compose in deck order, each on the coordinates the previous left",
          "[transform]") {
  // Translate by (1, 0, 0) then rotate 90 degrees about z through the origin, and the other way round.
  const std::string rot = transform("ROT", 2, 1, {0, 0, 0}, 0, 0, 0, rot_card2({0, 0, 1}, 90.0));
  const std::string tra = transform("TRA", 1, 1, {1, 0, 0}, 0, 0, 0);
  const auto a = build("#include part.inc\n" + tra + rot);
  const auto b = build("#include part.inc\n" + rot + tra);
  // Node 2 (1, 0, 0): a: (2, 0, 0) -> (0, 2, 0); b: (0, 1, 0) -> (1, 1, 0).
  require_near(node(a, 2), {0, 2, 0});
  require_near(node(b, 2), {1, 1, 0});
}

TEST_CASE("a nested submodel moves with its parent: its own transforms first, offsets added up",
          "[submodel][transform]") {
  // Outer submodel 1 (offset 1000) holds inner submodel 2 (offset 100, id shifted to 1002 by the outer
  // off_sub). Inner: translate (0, 0, 5); outer: rotate 90 degrees about z. Inner nodes: 1101..1108.
  const std::string inner = submodel(2, {100}, "#include part.inc\n");
  const std::string body = submodel(1, {1000}, inner) + transform("TRA", 1, 0, {0, 0, 5}, 0, 0, 1002) +
                           transform("ROT", 2, 0, {0, 0, 0}, 0, 0, 1, rot_card2({0, 0, 1}, 90.0));
  const auto m = build(body);
  REQUIRE(m.nodes.size() == 8);
  for (int k = 0; k < 8; ++k) {
    const Vec3 moved{kCorner[k][0], kCorner[k][1], kCorner[k][2] + 5};
    require_near(node(m, 1101 + k), {-moved[1], moved[0], moved[2]});
  }
}

TEST_CASE("a submodel's unit system converts what it holds", "[submodel]") {
  // The deck works in mm; the submodel is written in m: coordinates are multiplied by 1000.
  const std::string unit =
      "/UNIT/9\nmetre\n" + Line().put("Mg", 1, 20).put("m", 21, 40).put("s", 41, 60).str() + "\n";
  const auto m = build(unit + submodel(1, {0}, "#include part.inc\n", 9));
  require_near(node(m, 7), {1000, 1000, 1000});
}

TEST_CASE("/MOVE_FUNCT scales then shifts the points of a function", "[move_funct]") {
  // f: (0, 0), (1, 2), (3, 4). Ascalex 2, Fscaley 3, Ashiftx 8, Fshifty -3 (the values of BOULE1V5).
  const std::string move = "/MOVE_FUNCT/1\nmoved\n" + reals_line({2.0, 3.0, 8.0, -3.0});
  const auto m = build("#include part.inc\n" + move);
  const auto& g = m.functions[0];
  REQUIRE(g.x == std::vector<double>{8.0, 10.0, 14.0});
  REQUIRE(g.y == std::vector<double>{-3.0, 3.0, 9.0});
  auto f = [](double x) { return x <= 1 ? 2 * x : 2 + (x - 1); };
  for (double x : {8.0, 9.0, 11.5, 13.0}) {
    INFO("x = " << x);
    REQUIRE(radx::solver::function_value(g, x) == Approx(3.0 * f((x - 8.0) / 2.0) - 3.0));
  }
  SECTION("a negative abscissa scale reverses the points, which stay increasing") {
    const auto r = build("#include part.inc\n/MOVE_FUNCT/1\nflipped\n" + reals_line({-1.0, 0.0, 0.0, 0.0}));
    REQUIRE(r.functions[0].x == std::vector<double>{-3.0, -1.0, 0.0});
    REQUIRE(r.functions[0].y == std::vector<double>{4.0, 2.0, 0.0});
    REQUIRE(radx::solver::function_value(r.functions[0], -2.0) == Approx(f(2.0)));
  }
}

TEST_CASE("submodel and transform errors are reported at their file and line", "[submodel][errors]") {
  // Line numbers: /BEGIN takes lines 1-5, so the body starts at line 6.
  SECTION("//ENDSUB without a //SUBMODEL, and a //SUBMODEL never closed") {
    const auto a = errors_of("#include part.inc\n//ENDSUB\n");
    REQUIRE(has(a, "RX312", 7));
    const auto b = errors_of(std::string("//SUBMODEL/3\nopen\n\n") + "#include part.inc\n");
    REQUIRE(has(b, "RX312", 6));
  }
  SECTION("a transform naming a node group or a submodel that does not exist") {
    const auto a = errors_of("#include part.inc\n" + transform("TRA", 1, 77, {1, 0, 0}, 0, 0, 0));
    INFO(dump(a));
    REQUIRE(has(a, "RX402", 9));
    const auto b =
        errors_of(submodel(1, {0}, "#include part.inc\n") + transform("TRA", 1, 0, {1, 0, 0}, 0, 0, 5));
    INFO(dump(b));
    REQUIRE(has(b, "RX402", 13));
  }
  SECTION("grnod_ID and sub_ID together, neither, or only one node of a pair") {
    const auto a =
        errors_of(submodel(1, {0}, "#include part.inc\n") + transform("TRA", 1, 1, {1, 0, 0}, 0, 0, 1));
    REQUIRE(has(a, "RX507", 13));
    const auto b = errors_of("#include part.inc\n" + transform("TRA", 1, 0, {1, 0, 0}, 0, 0, 0));
    REQUIRE(has(b, "RX404", 9));
    const auto c = errors_of("#include part.inc\n" + transform("TRA", 1, 1, {}, 3, 0, 0));
    REQUIRE(has(c, "RX404", 9));
  }
  SECTION("a rotation axis or a mirror normal of zero length") {
    const auto a = errors_of("#include part.inc\n" +
                             transform("ROT", 1, 1, {1, 1, 1}, 0, 0, 0, rot_card2({1, 1, 1}, 45.0)));
    INFO(dump(a));
    REQUIRE(has(a, "RX605", 10));
    const auto b = errors_of("#include part.inc\n" + transform("SYM", 1, 1, {}, 2, 2, 0, "\n"));
    REQUIRE(has(b, "RX605", 9));
  }
  SECTION("/MOVE_FUNCT of a function that does not exist") {
    const auto a = errors_of("#include part.inc\n/MOVE_FUNCT/9\nnone\n" + reals_line({2.0}));
    REQUIRE(has(a, "RX402", 7));
  }
  SECTION("an error inside a submodel's included file points at that file's line, ids as written there") {
    // The included file's /PART names material 5, which is material 1005 in the submodel: missing.
    const std::string bad = "/PART/1\nbad\n" + ids_line({1, 5});
    const auto a = errors_of(submodel(1, {1000}, "#include part.inc\n#include bad.inc\n"), "bad.inc", bad);
    INFO(dump(a));
    REQUIRE(has(a, "RX402", 3, "bad.inc"));
  }
}

TEST_CASE("every integer field that names an object declares the kind of id it holds", "[submodel]") {
  // A field whose name says it holds an id ("..._ID...", a node n1..n8 or N1/N2) is shifted by a submodel's
  // offsets only if its declaration gives the kind; one left out would silently keep its written value.
  using radx::schema::FieldType;
  using radx::schema::IdKind;
  auto names_an_object = [](std::string_view n) {
    const bool node = n.size() == 2 && (n[0] == 'n' || n[0] == 'N') && n[1] >= '1' && n[1] <= '8';
    return node || n.find("ID") != std::string_view::npos;
  };
  auto check = [&](const radx::schema::KeywordDecl& k, const radx::schema::FieldDecl& f) {
    if (f.type != FieldType::Int || !names_an_object(f.name) || f.name == "seg_ID") return;
    INFO(k.path << " " << f.name);
    CHECK(f.ref != IdKind::None);
  };
  for (const auto& k : radx::schema::starter_keywords()) {
    for (const auto& c : k.cards)
      for (const auto& f : c.fields) check(k, f);
    for (const auto& f : k.record.fields) check(k, f);
    const bool lists = k.tail == radx::schema::Tail::IdList || k.tail == radx::schema::Tail::ThVarsThenIds;
    INFO(k.path);
    CHECK((!lists || k.list_kind != IdKind::None));
  }
}

TEST_CASE("points written inside a moved submodel move with it: a box selects the copy's nodes",
          "[submodel][transform]") {
  // Inside submodel 2 (offset 1000): box 2 -> 1002 around the bottom face of the part (z = 0), and node group
  // 2 -> 1002 of the nodes in it. Submodel 2 is translated by (10, 0, 0): the box's corners follow, so the
  // group holds the copy's bottom nodes 1001..1004, not the original's 1..4 left at the written place.
  const std::string box =
      "/BOX/RECTA/2\nbottom\n\n" + reals_line({-0.1, -0.1, -0.1}) + reals_line({1.1, 1.1, 0.1});
  const std::string group = "/GRNOD/BOX/2\nin the box\n" + ids_line({2});
  const auto m = build(submodel(1, {0}, "#include part.inc\n") +
                       submodel(2, {1000}, "#include part.inc\n" + box + group) +
                       transform("TRA", 1, 0, {10, 0, 0}, 0, 0, 2));
  const radx::model::NodeGroup* g = nullptr;
  for (const auto& x : m.node_groups)
    if (x.id == 1002) g = &x;
  REQUIRE(g != nullptr);
  std::vector<long long> ids;
  for (const auto k : g->nodes) ids.push_back(m.nodes.id[static_cast<std::size_t>(k)]);
  std::sort(ids.begin(), ids.end());
  REQUIRE(ids == std::vector<long long>{1001, 1002, 1003, 1004});
}
