// Deck -> Model: /SET/GENERAL and /SET/COLLECT (docs/sets.md), as the OpenRadioss starter builds them
// (starter/source/model/sets: hm_set.F, set_operator.F, insert_clause_in_set.F, create_*_clause.F,
// create_surface_from_element.F, solid_surface_buffer.F, create_node_from_element.F, fill_igr.F), read for
// behaviour only:
// * A set holds, separately, nodes, parts, 4-node shells, 3-node shells, solids and surface segments. Each
//   clause builds all the kinds it gives, then joins the set kind by kind: a plain clause adds (union), a
//   clause with option D removes (difference), one with option I keeps what both hold (intersection; D wins
//   over I). An empty kind of a clause leaves the set's kind as it is, except under I, which empties it.
// * PART: the parts, their elements, the elements' nodes and a surface: the shells as numbered (option O:
//   flipped), the faces of their solids that no other solid of the clause's parts shares (option A: every
//   face). SHELL, SH3N, SOLID: the elements listed (SOLID takes /BRICK, /TETRA4 and /BRIC20 ids), their nodes
//   and surface the same way (a solid face is inner when another solid of the clause has it). NODE: the
//   nodes. BOX, BOX2: the nodes inside the boxes, the elements with all (BOX) or at least one (BOX2) node
//   inside, and their surface (a solid face is inner when any solid of the model has it). ALL: every node,
//   part and element of the model. SET (SETCOL): the union of the /SET/GENERAL (/SET/COLLECT) sets listed.
// * Option G reads triples (first, last, step; step 0 is 1) and takes the ids of each range that exist. A
//   listed id that does not exist is left out with a warning (Radioss's message 1902), nodes included.
// * Every /SET/COLLECT with one id adds to one set.
// * A set becomes a node group, a surface or an element group of its id where a keyword names one; a
//   /GRNOD, /SURF or element group of the same id is used instead (checked with OpenRadioss for /GRNOD).
#include <algorithm>
#include <array>
#include <cctype>
#include <iterator>
#include <set>
#include <string>
#include <utility>

#include "parser/building/group_geometry.hpp"
#include "parser/building/model_builder.hpp"
#include "parser/reading/field_parse.hpp"

namespace radx {
namespace detail {

using model::kNone;

namespace {

// How a clause joins the set.
enum class SetOperation { Add, Remove, Keep };

// A clause as written: its word (key and option letters after '_') and the cells of its lines.
struct Clause {
  const KeywordRecord* record = nullptr;
  SourcePos pos;
  std::string key;                  // PART, NODE, SHELL, ...
  std::string options;              // D, G, I, O, A, ...: the letters after '_'
  std::vector<std::int64_t> cells;  // every cell of its lines, blanks as 0 (G reads triples)
  std::vector<SourcePos> cell_pos;
  [[nodiscard]] bool has(char option) const { return options.find(option) != std::string::npos; }
  [[nodiscard]] std::string word() const { return key + (options.empty() ? "" : "_" + options); }
};

std::string upper(std::string s) {
  for (auto& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

// The clauses of one /SET record: a line with a word starts a clause, a line without one carries it on.
std::vector<Clause> clauses_of(ModelBuilder& b, const KeywordRecord& r) {
  std::vector<Clause> out;
  const auto& t = r.records;
  const int word = t.column("clause");
  if (word < 0) return out;
  for (std::size_t k = 0; k < t.size(); ++k) {
    const std::string w = upper(std::string(trim(t.strings[word][k])));
    if (!w.empty()) {
      Clause c;
      c.record = &r;
      c.pos = t.pos[k];
      const auto bar = w.find('_');
      c.key = w.substr(0, bar);
      if (bar != std::string::npos) c.options = w.substr(bar + 1);
      out.push_back(std::move(c));
    } else if (out.empty()) {
      b.diags_.error(Diag::InconsistentValues, b.at(t.pos[k], 1), ModelBuilder::about(r),
                     "ids before any clause word: a /SET line starts with a clause (PART, NODE, SHELL, SH3N, "
                     "SOLID, SET, BOX, ALL ...) in columns 1-10; a blank word carries on the clause above");
      continue;
    }
    for (int i = 1; i <= 9; ++i) {
      const int c = t.column("item" + std::to_string(i));
      if (c < 0) continue;
      out.back().cells.push_back(t.ints[c][k]);
      out.back().cell_pos.push_back(t.pos[k]);
    }
  }
  return out;
}

// The ids a clause names: its non-blank cells, or with option G the existing ids of each (first, last, step)
// triple among `ids` (the model's user ids of the clause's kind).
struct NamedIds {
  std::vector<std::int64_t> ids;
  std::vector<SourcePos> pos;
};
NamedIds named_ids(const Clause& c, const std::vector<std::int64_t>& model_ids) {
  NamedIds n;
  if (!c.has('G')) {
    for (std::size_t k = 0; k < c.cells.size(); ++k)
      if (c.cells[k] != 0) {
        n.ids.push_back(c.cells[k]);
        n.pos.push_back(c.cell_pos[k]);
      }
    return n;
  }
  for (std::size_t k = 0; k < c.cells.size(); k += 3) {
    const std::int64_t lo = c.cells[k], hi = k + 1 < c.cells.size() ? c.cells[k + 1] : 0;
    const std::int64_t step = k + 2 < c.cells.size() && c.cells[k + 2] > 0 ? c.cells[k + 2] : 1;
    if (lo == 0 && hi == 0) continue;
    for (const auto id : model_ids)
      if (id >= lo && id <= hi && (id - lo) % step == 0) {
        n.ids.push_back(id);
        n.pos.push_back(c.cell_pos[k]);
      }
  }
  return n;
}

void sort_unique(std::vector<std::int32_t>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

// RX402 warning: a listed id names nothing; Radioss leaves it out (its message 1902).
void report_missing(ModelBuilder& b, const Clause& c, SourcePos pos, const std::string& what,
                    std::int64_t id) {
  b.diags_.warning(Diag::MissingReference, b.at(pos, 1), ModelBuilder::about(*c.record),
                   what + " " + std::to_string(id) + " does not exist (clause " + c.word() +
                       "): it is left out, as Radioss leaves it out");
}

// The dense indices of the ids a clause names, looked up by `find` (-1: none, reported as `what`).
template <class Find>
std::vector<std::int32_t> resolve_ids(ModelBuilder& b, const Clause& c,
                                      const std::vector<std::int64_t>& model_ids, Find&& find,
                                      const std::string& what) {
  const auto n = named_ids(c, model_ids);
  std::vector<std::int32_t> out;
  for (std::size_t k = 0; k < n.ids.size(); ++k) {
    const auto e = find(n.ids[k]);
    if (e < 0)
      report_missing(b, c, n.pos[k], what, n.ids[k]);
    else
      out.push_back(e);
  }
  sort_unique(out);
  return out;
}

// What the builder of one clause needs.
struct ClauseContext {
  ModelBuilder& b;
  const model::Model& m;
  const Clause& c;
};

// The nodes of the set's shells, 3-node shells and solids, and of the springs of its parts (n1, n2).
void add_element_nodes(const model::Model& m, ModelBuilder::SetMembers& s,
                       const std::vector<std::int32_t>& springs) {
  auto take = [&](const model::ElementBlock& blk, std::int32_t e, int count) {
    const auto npe = static_cast<std::size_t>(blk.npe());
    for (int k = 0; k < count; ++k) {
      const auto n = blk.conn[static_cast<std::size_t>(e) * npe + static_cast<std::size_t>(k)];
      if (n >= 0) s.nodes.push_back(n);
    }
  };
  for (const auto e : s.shells) take(m.shells, e, 4);
  for (const auto e : s.shells3) take(m.shells3, e, 3);
  const auto bricks = static_cast<std::int32_t>(m.bricks.size());
  const auto tetras = static_cast<std::int32_t>(m.tetras.size());
  for (const auto e : s.solids) {
    if (e < bricks)
      take(m.bricks, e, 8);
    else if (e < bricks + tetras)
      take(m.tetras, e - bricks, 4);
    else
      take(m.bricks20, e - bricks - tetras, 20);
  }
  for (const auto e : springs) take(m.springs, e, 2);
  sort_unique(s.nodes);
}

// Which solids count as neighbours when a face is told inner from outer.
enum class FaceNeighbours { Clause, Model, None };

// The surface of the clause's elements: shells (flipped with O), then the solids' faces.
void add_element_surface(const ClauseContext& x, ModelBuilder::SetMembers& s, FaceNeighbours neighbours) {
  model::Surface surf;
  const bool flip = x.c.has('O');
  for (const auto e : s.shells) push_shell(x.m, surf, e, flip);
  for (const auto e : s.shells3) push_shell3(x.m, surf, e, flip);
  const auto nb = x.m.bricks.size();
  std::vector<std::int32_t> bricks, tetras;
  std::vector<std::uint8_t> brick_mark(nb, neighbours == FaceNeighbours::Model ? 1 : 0);
  std::vector<std::uint8_t> tetra_mark(x.m.tetras.size(), neighbours == FaceNeighbours::Model ? 1 : 0);
  for (const auto e : s.solids) {
    // 20-node bricks (after the tetrahedra) give no faces, as OpenRadioss's surface search (ssurftag.F)
    if (static_cast<std::size_t>(e) >= nb + x.m.tetras.size()) continue;
    const bool tetra = static_cast<std::size_t>(e) >= nb;
    const auto i = tetra ? e - static_cast<std::int32_t>(nb) : e;
    (tetra ? tetras : bricks).push_back(i);
    (tetra ? tetra_mark : brick_mark)[static_cast<std::size_t>(i)] = 1;
  }
  const bool all = neighbours == FaceNeighbours::None || x.c.has('A');
  push_solid_faces(x.m, surf, bricks, tetras, all ? nullptr : &brick_mark, all ? nullptr : &tetra_mark, {});
  for (std::size_t k = 0; k < surf.segments.size(); ++k)
    s.segments.push_back({surf.segments[k], surf.owner_type[k], surf.owner[k]});
}

// The group index (solids: tetrahedra after the bricks, 20-node bricks after them) of the solid with user id
// `id`, or -1.
std::int32_t solid_index(const model::Model& m, std::int64_t id) {
  const auto e = m.bricks.index.find(id);
  if (e >= 0) return e;
  const auto t = m.tetras.index.find(id);
  if (t >= 0) return static_cast<std::int32_t>(m.bricks.size()) + t;
  const auto q = m.bricks20.index.find(id);
  return q < 0 ? -1 : static_cast<std::int32_t>(m.bricks.size() + m.tetras.size()) + q;
}

// The elements of `parts` (sorted dense part indices) into s, and the parts' springs into `springs`.
void add_elements_of_parts(const model::Model& m, ModelBuilder::SetMembers& s,
                           std::vector<std::int32_t>& springs) {
  std::vector<std::uint8_t> listed(m.parts.size(), 0);
  for (const auto p : s.parts) listed[static_cast<std::size_t>(p)] = 1;
  auto in = [&](std::int32_t part) { return part >= 0 && listed[static_cast<std::size_t>(part)]; };
  for (std::size_t e = 0; e < m.shells.size(); ++e)
    if (in(m.shells.part[e])) s.shells.push_back(static_cast<std::int32_t>(e));
  for (std::size_t e = 0; e < m.shells3.size(); ++e)
    if (in(m.shells3.part[e])) s.shells3.push_back(static_cast<std::int32_t>(e));
  for (std::size_t e = 0; e < m.bricks.size(); ++e)
    if (in(m.bricks.part[e])) s.solids.push_back(static_cast<std::int32_t>(e));
  for (std::size_t e = 0; e < m.tetras.size(); ++e)
    if (in(m.tetras.part[e])) s.solids.push_back(static_cast<std::int32_t>(m.bricks.size() + e));
  for (std::size_t e = 0; e < m.bricks20.size(); ++e)
    if (in(m.bricks20.part[e]))
      s.solids.push_back(static_cast<std::int32_t>(m.bricks.size() + m.tetras.size() + e));
  for (std::size_t e = 0; e < m.springs.size(); ++e)
    if (in(m.springs.part[e])) springs.push_back(static_cast<std::int32_t>(e));
}

// PART: the parts, their elements, the elements' nodes and surface.
ModelBuilder::SetMembers part_clause(const ClauseContext& x) {
  ModelBuilder::SetMembers s;
  std::vector<std::int64_t> part_ids;
  for (const auto& p : x.m.parts) part_ids.push_back(p.id);
  s.parts = resolve_ids(
      x.b, x.c, part_ids,
      [&](std::int64_t id) {
        const auto it = x.b.part_ids_.find(id);
        return it == x.b.part_ids_.end() ? -1 : it->second;
      },
      "part");
  std::vector<std::int32_t> springs;
  add_elements_of_parts(x.m, s, springs);
  add_element_surface(x, s, FaceNeighbours::Clause);
  add_element_nodes(x.m, s, springs);
  return s;
}

// SHELL, SH3N, SOLID: the elements listed, their nodes and surface.
ModelBuilder::SetMembers element_clause(const ClauseContext& x) {
  ModelBuilder::SetMembers s;
  const auto& m = x.m;
  if (x.c.key == "SHELL") {
    s.shells = resolve_ids(
        x.b, x.c, m.shells.id, [&](std::int64_t id) { return m.shells.index.find(id); }, "4-node shell");
  } else if (x.c.key == "SH3N") {
    s.shells3 = resolve_ids(
        x.b, x.c, m.shells3.id, [&](std::int64_t id) { return m.shells3.index.find(id); }, "3-node shell");
  } else {
    std::vector<std::int64_t> ids(m.bricks.id);
    ids.insert(ids.end(), m.tetras.id.begin(), m.tetras.id.end());
    ids.insert(ids.end(), m.bricks20.id.begin(), m.bricks20.id.end());
    s.solids = resolve_ids(
        x.b, x.c, ids, [&](std::int64_t id) { return solid_index(m, id); }, "solid");
  }
  add_element_surface(x, s, FaceNeighbours::Clause);
  add_element_nodes(m, s, {});
  return s;
}

// NODE: the nodes listed.
ModelBuilder::SetMembers node_clause(const ClauseContext& x) {
  ModelBuilder::SetMembers s;
  s.nodes = resolve_ids(
      x.b, x.c, x.m.nodes.id, [&](std::int64_t id) { return x.m.nodes.index.find(id); }, "node");
  return s;
}

// BOX, BOX2: the nodes inside the boxes, the elements with all (BOX) or one (BOX2) node inside.
ModelBuilder::SetMembers box_clause(const ClauseContext& x) {
  ModelBuilder::SetMembers s;
  const auto& m = x.m;
  std::vector<std::int64_t> box_ids;
  for (const auto& bx : m.boxes) box_ids.push_back(bx.id);
  const auto boxes = resolve_ids(
      x.b, x.c, box_ids,
      [&](std::int64_t id) {
        const auto it = x.b.box_ids_.find(id);
        return it == x.b.box_ids_.end() ? -1 : it->second;
      },
      "box");
  std::vector<std::uint8_t> in(m.nodes.size(), 0);
  for (const auto bi : boxes) {
    const auto& bx = m.boxes[static_cast<std::size_t>(bi)];
    for (std::size_t n = 0; n < m.nodes.size(); ++n)
      if (inside_box(bx, m.nodes.x[n], m.nodes.y[n], m.nodes.z[n])) in[n] = 1;
  }
  for (std::size_t n = 0; n < in.size(); ++n)
    if (in[n]) s.nodes.push_back(static_cast<std::int32_t>(n));
  const bool every_node = x.c.key == "BOX";
  auto select = [&](const model::ElementBlock& blk, std::vector<std::int32_t>& out, std::int32_t base) {
    const auto npe = static_cast<std::size_t>(blk.npe());
    for (std::size_t e = 0; e < blk.size(); ++e) {
      std::size_t count = 0;
      for (std::size_t k = 0; k < npe; ++k) count += in[static_cast<std::size_t>(blk.conn[e * npe + k])];
      if (every_node ? count == npe : count > 0) out.push_back(base + static_cast<std::int32_t>(e));
    }
  };
  select(m.shells, s.shells, 0);
  select(m.shells3, s.shells3, 0);
  select(m.bricks, s.solids, 0);
  select(m.tetras, s.solids, static_cast<std::int32_t>(m.bricks.size()));
  select(m.bricks20, s.solids, static_cast<std::int32_t>(m.bricks.size() + m.tetras.size()));
  add_element_surface(x, s, FaceNeighbours::Model);
  return s;
}

// ALL: every node, part and element of the model.
ModelBuilder::SetMembers all_clause(const ClauseContext& x) {
  ModelBuilder::SetMembers s;
  const auto& m = x.m;
  auto every = [](std::size_t n, std::vector<std::int32_t>& out) {
    for (std::size_t k = 0; k < n; ++k) out.push_back(static_cast<std::int32_t>(k));
  };
  every(m.nodes.size(), s.nodes);
  every(m.parts.size(), s.parts);
  every(m.shells.size(), s.shells);
  every(m.shells3.size(), s.shells3);
  every(m.bricks.size() + m.tetras.size() + m.bricks20.size(), s.solids);
  add_element_surface(x, s, FaceNeighbours::Model);
  return s;
}

// The sorted-vector operation of `op` on a kind of member.
void join_kind(std::vector<std::int32_t>& set, const std::vector<std::int32_t>& clause, SetOperation op) {
  std::vector<std::int32_t> out;
  switch (op) {
    case SetOperation::Add:
      std::set_union(set.begin(), set.end(), clause.begin(), clause.end(), std::back_inserter(out));
      break;
    case SetOperation::Remove:
      std::set_difference(set.begin(), set.end(), clause.begin(), clause.end(), std::back_inserter(out));
      break;
    case SetOperation::Keep:
      std::set_intersection(set.begin(), set.end(), clause.begin(), clause.end(), std::back_inserter(out));
      break;
  }
  set = std::move(out);
}

// The segments joined as the other kinds, keeping the set's order and appending the clause's new ones.
void join_segments(std::vector<ModelBuilder::SetSegment>& set,
                   const std::vector<ModelBuilder::SetSegment>& clause, SetOperation op) {
  const std::set<ModelBuilder::SetSegment> in_clause(clause.begin(), clause.end());
  if (op == SetOperation::Add) {
    std::set<ModelBuilder::SetSegment> have(set.begin(), set.end());
    for (const auto& g : clause)
      if (have.insert(g).second) set.push_back(g);
    return;
  }
  const bool keep = op == SetOperation::Keep;
  std::erase_if(set, [&](const ModelBuilder::SetSegment& g) { return (in_clause.count(g) > 0) != keep; });
}

void join(ModelBuilder::SetMembers& set, const ModelBuilder::SetMembers& clause, SetOperation op) {
  join_kind(set.nodes, clause.nodes, op);
  join_kind(set.parts, clause.parts, op);
  join_kind(set.shells, clause.shells, op);
  join_kind(set.shells3, clause.shells3, op);
  join_kind(set.solids, clause.solids, op);
  join_segments(set.segments, clause.segments, op);
}

// SET, SETCOL: the union of the /SET/GENERAL (SETCOL: /SET/COLLECT) sets listed.
ModelBuilder::SetMembers set_clause(const ClauseContext& x) {
  const bool collect = x.c.key == "SETCOL";
  const auto& index = collect ? x.b.collect_set_ids_ : x.b.set_ids_;
  std::vector<std::int64_t> ids;
  for (const auto& entry : index) ids.push_back(entry.first);
  std::sort(ids.begin(), ids.end());
  const auto listed = resolve_ids(
      x.b, x.c, ids,
      [&](std::int64_t id) {
        const auto it = index.find(id);
        return it == index.end() ? -1 : it->second;
      },
      collect ? "/SET/COLLECT set" : "/SET/GENERAL set");
  ModelBuilder::SetMembers s;
  for (const auto k : listed)
    if (const auto* members = x.b.set_members(k)) join(s, *members, SetOperation::Add);
  return s;
}

// The clause words Radioss knows that radx does not build, with what they select.
constexpr std::array<std::pair<std::string_view, std::string_view>, 12> kRefusedClauses = {{
    {"SEG", "segments given by their nodes"},
    {"SUBS", "the parts of subsets"},
    {"SUBM", "the parts of submodels"},
    {"RBODY", "rigid bodies"},
    {"ELLIPS", "an analytical ellipsoid surface"},
    {"PLANE", "an analytical plane surface"},
    {"NODENS", "an unsorted node list"},
    {"BEAM", "beams"},
    {"TRUSS", "trusses"},
    {"SPRING", "springs"},
    {"QUAD", "2D quads"},
    {"TRIA", "2D triangles"},
}};

constexpr std::string_view kBuiltClauses = "PART, NODE, SHELL, SH3N, SOLID, SET, SETCOL, BOX, BOX2 and ALL";

// False, with the error, for a clause radx does not build: a Radioss clause radx lacks, a word Radioss does
// not know, or an option that changes what the clause selects and that radx does not apply.
bool clause_is_built(ModelBuilder& b, const Clause& c) {
  const auto about = ModelBuilder::about(*c.record);
  for (const auto& [key, what] : kRefusedClauses)
    if (c.key == key) {
      b.diags_.error(Diag::PhysicsNotImplemented, b.at(c.pos, 1), about,
                     "clause " + c.word() + " (" + std::string(what) + ") is not built by radx; it builds " +
                         std::string(kBuiltClauses));
      return false;
    }
  static const std::set<std::string_view> built = {"PART", "NODE",   "SHELL", "SH3N", "SOLID",
                                                   "SET",  "SETCOL", "BOX",   "BOX2", "ALL"};
  if (!built.count(c.key)) {
    // OpenRadioss drops a clause word it does not know without a word, emptying what uses the set.
    b.diags_.error(
        Diag::InconsistentValues, b.at(c.pos, 1), about,
        "'" + c.word() + "' is not a /SET clause (Radioss would skip it silently); the clauses are " +
            std::string(kBuiltClauses) + " (4-node shells are SHELL, bricks and tetrahedra SOLID)");
    return false;
  }
  for (const char o : c.options) {
    if (std::string_view("DGIOA").find(o) != std::string_view::npos) continue;
    const std::string_view what = o == 'B'   ? "adds what lies in a box"
                                  : o == 'C' ? "adds the elements with a node in a box"
                                  : o == 'E' ? "takes only the nodes of the outer faces and free edges"
                                             : "";
    if (what.empty())
      b.diags_.error(Diag::InconsistentValues, b.at(c.pos, 1), about,
                     "'" + c.word() + "': option " + std::string(1, o) +
                         " is not a /SET option; the options after '_' are D, G, I, O, A (and B, C, E)");
    else
      b.diags_.error(
          Diag::PhysicsNotImplemented, b.at(c.pos, 1), about,
          "'" + c.word() + "': option " + std::string(1, o) + " (" + std::string(what) +
              ") is not applied by radx; it applies D (remove), G (ranges), I (intersect), O (flip "
              "shells) and A (every solid face)");
    return false;
  }
  return true;
}

}  // namespace

void ModelBuilder::build_sets() {
  std::unordered_map<std::int64_t, SourcePos> first;
  for (const auto& r : deck_.records) {
    const auto path = r.decl->path;
    if (path != "/SET/GENERAL" && path != "/SET/COLLECT") continue;
    if (r.submodel >= 0) {
      error_at(
          r, "", Diag::PhysicsNotImplemented,
          "a /SET inside a //SUBMODEL is not read by radx: the kind of each of its ids (and so the offset "
          "Radioss shifts it by) depends on its clause; write the set outside the submodel with the "
          "shifted ids");
      continue;
    }
    const bool collect = path == "/SET/COLLECT";
    auto& own = collect ? collect_set_ids_ : set_ids_;
    const auto& other = collect ? set_ids_ : collect_set_ids_;
    if (other.count(r.id)) {
      error_at(r, "", Diag::DuplicateId,
               "set id " + std::to_string(r.id) + " is both a /SET/GENERAL and a /SET/COLLECT: what names " +
                   std::to_string(r.id) + " would be ambiguous; give one of them another id");
      continue;
    }
    if (collect && own.count(r.id)) {
      sets_[static_cast<std::size_t>(own[r.id])].records.push_back(&r);
      continue;
    }
    if (register_id(own, r.id, static_cast<std::int32_t>(sets_.size()), r, "set", first))
      sets_.push_back(Set{{&r}, collect, {}, 0, false});
  }
  // In deck order, so that what a set reports comes in a fixed order. Each set is an element group of its id
  // too, unless a /GRSHEL, /GRSH3N or /GRBRIC has the id.
  for (std::size_t s = 0; s < sets_.size(); ++s) {
    const auto* members = set_members(static_cast<std::int32_t>(s));
    if (!members) continue;
    const std::int64_t id = sets_[s].records.front()->id;
    const std::vector<std::int32_t>* by_type[3] = {&members->shells, &members->shells3, &members->solids};
    for (std::size_t f = 0; f < 3; ++f) {
      if (element_group_ids_[f].count(id)) continue;
      element_group_ids_[f].emplace(id, static_cast<std::int32_t>(element_groups_.size()));
      ElementGroup g;
      g.record = sets_[s].records.front();
      g.type = static_cast<model::ElementType>(f);
      g.elements = *by_type[f];
      g.state = 2;
      element_groups_.push_back(std::move(g));
    }
  }
}

const ModelBuilder::SetMembers* ModelBuilder::set_members(std::int32_t s) {
  auto& set = sets_[static_cast<std::size_t>(s)];
  if (set.state == 2) return &set.members;
  const KeywordRecord& head = *set.records.front();
  if (set.state == 1) {
    diags_.error(Diag::InconsistentValues, at(head.pos, 1), about(head),
                 "set " + std::to_string(head.id) + " includes itself through a SET clause; remove the loop");
    return nullptr;
  }
  set.state = 1;
  const std::size_t errors_before = diags_.error_count();
  SetMembers result;
  for (const auto* r : set.records) {
    for (const auto& c : clauses_of(*this, *r)) {
      if (!clause_is_built(*this, c)) continue;
      const ClauseContext x{*this, m_, c};
      SetMembers clause;
      if (c.key == "PART")
        clause = part_clause(x);
      else if (c.key == "NODE")
        clause = node_clause(x);
      else if (c.key == "SHELL" || c.key == "SH3N" || c.key == "SOLID")
        clause = element_clause(x);
      else if (c.key == "BOX" || c.key == "BOX2")
        clause = box_clause(x);
      else if (c.key == "ALL")
        clause = all_clause(x);
      else
        clause = set_clause(x);
      join(result, clause,
           c.has('D')   ? SetOperation::Remove
           : c.has('I') ? SetOperation::Keep
                        : SetOperation::Add);
    }
  }
  set.members = std::move(result);
  set.had_errors = diags_.error_count() > errors_before;
  set.state = 2;
  return &set.members;
}

}  // namespace detail
}  // namespace radx

namespace radx {
namespace detail {

namespace {

// The sets_ index of set `id` (general or collect), or kNone.
std::int32_t set_index(const ModelBuilder& b, std::int64_t id) {
  for (const auto* ids : {&b.set_ids_, &b.collect_set_ids_}) {
    const auto it = ids->find(id);
    if (it != ids->end()) return it->second;
  }
  return kNone;
}

}  // namespace

std::int32_t ModelBuilder::node_group_from_set(std::int64_t id) {
  const auto s = set_index(*this, id);
  if (s == kNone) return kNone;
  const auto* members = set_members(s);
  const KeywordRecord& r = *sets_[static_cast<std::size_t>(s)].records.front();
  model::NodeGroup g;
  g.id = id;
  g.title = r.title;
  g.kind = std::string(r.decl->path.substr(1));
  if (members) g.nodes = members->nodes;
  // A set emptied by its own errors is not warned of again.
  if (g.nodes.empty() && !sets_[static_cast<std::size_t>(s)].had_errors)
    diags_.warning(
        Diag::EmptyGroup, at(r.pos, 1), about(r),
        "set " + std::to_string(id) +
            " holds no node: what names it as a node group acts on nothing, as in Radioss; check its "
            "clauses");
  const auto index = static_cast<std::int32_t>(m_.node_groups.size());
  m_.node_groups.push_back(std::move(g));
  grnod_records_.push_back(&r);
  grnod_state_.push_back(2);
  grnod_ids_.emplace(id, index);
  return index;
}

std::int32_t ModelBuilder::surface_from_set(std::int64_t id) {
  const auto s = set_index(*this, id);
  if (s == kNone) return kNone;
  const auto* members = set_members(s);
  const KeywordRecord& r = *sets_[static_cast<std::size_t>(s)].records.front();
  model::Surface surf;
  surf.id = id;
  surf.title = r.title;
  surf.kind = std::string(r.decl->path.substr(1));
  if (members)
    for (const auto& g : members->segments) {
      surf.segments.push_back(g.nodes);
      surf.owner_type.push_back(g.type);
      surf.owner.push_back(g.owner);
    }
  if (surf.segments.empty() && !sets_[static_cast<std::size_t>(s)].had_errors)
    diags_.warning(
        Diag::EmptyGroup, at(r.pos, 1), about(r),
        "set " + std::to_string(id) +
            " holds no segment (no shell or solid): what names it as a surface finds nothing on it, "
            "as in Radioss; check its clauses");
  const auto index = static_cast<std::int32_t>(m_.surfaces.size());
  m_.surfaces.push_back(std::move(surf));
  surf_ids_.emplace(id, index);
  return index;
}

}  // namespace detail
}  // namespace radx
