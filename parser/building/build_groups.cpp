// Deck -> Model: boxes, functions, element groups, node groups and surfaces (docs/keywords.md: /BOX/RECTA,
// /FUNCT, /GRNOD/*, /SURF/PART, /SURF/PART/EXT, /SURF/SEG, and section 5.5). Negative ids subtract in
// /GRNOD/PART and /GRNOD/GRNOD, and flip the segment normal in /SURF/PART (they never remove there).
// /SURF/PART/EXT keeps the brick and tetrahedron faces that no other solid of the listed parts shares,
// oriented outward (a tetrahedron face is a triangle segment, n4 = n3), plus the shell segments of the
// listed parts; /SURF/PART/ALL takes every face of both.
//
// Element groups (/GRSHEL, /GRSH3N, /GRBRIC) and what is built from them follow the OpenRadioss starter
// (starter/source/groups: hm_lecgre.F, hm_tagpart.F, hm_grogro.F, hm_elngr.F, hm_read_surf.F, hm_surfgr2.F,
// surftage.F, ssurftag.F; model/box/bigbox.F), read for behaviour only:
// * PART, SUBSET, MAT, PROP, GRSHEL/GRSH3N/GRBRIC: Radioss reads the positive ids, then the negative ones,
//   and a negative id's tag overrides, so a negative id removes (a set difference, whatever the order).
// * BOX selects the elements whose nodes all lie in the box (boundary included), BOX2 those with at least
//   one node in it. Radioss takes the first box id of the list only; the others are ignored (a warning).
// * /SURF/GRSHEL, /SURF/GRSH3N: one segment per element, as the element is numbered; an element reached
//   only through a negative id is flipped (positive ids are tagged first and the first tag stays).
// * /SURF/GRBRIC/EXT: the faces of the groups' bricks that no other brick of the groups shares; /FREE:
//   that no other brick of the model shares; plain /SURF/GRBRIC is refused, as Radioss refuses it.
// * /SURF/PART/ALL: every face of every brick of the listed parts, inner faces included (once from each
//   side, each pointing out of its brick), plus the shell segments. In /SURF/PART/EXT and /ALL a brick
//   face that a shell of a listed part covers is left out: the shell gives that segment.
// * /GRNOD/GRSHEL, /GRSH3N, /GRBRIC: the nodes of the groups' elements; Radioss ignores negative ids there.
// * /GRBRIC holds tetrahedra and 20-node bricks as well as bricks (/GRBRIC/BRIC lists /TETRA4 and /BRIC20
//   ids, PART, BOX and GENE take the parts' tetrahedra and 20-node bricks), as Radioss keeps them in one
//   solid table. Surfaces of a group's 20-node bricks are refused (OpenRadioss builds none).
// * GENE (pairs first, last) takes the ids of the range that exist, however wide the range (1 to 999999999
//   is common): a note says how many exist when the range is far wider than the model.
// * What Radioss only warns about, radx reads with a warning saying what it did: a part, subset, material,
//   property, box, group or surface a group lists that does not exist is left out (RX402 warning), and a
//   group or surface that ends up empty acts on nothing (RX403 warning). A node or element id that does not
//   exist stops Radioss, and radx (RX402 error).
#include <algorithm>
#include <array>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string_view>

#include "parser/building/group_geometry.hpp"
#include "parser/building/model_builder.hpp"
#include "parser/reading/field_parse.hpp"
#include "solver/model/geometry.hpp"

namespace radx {
namespace detail {

using model::kNone;

namespace {

FaceKey face_key(std::array<std::int32_t, 4> f) {
  std::sort(f.begin(), f.end());
  return f;
}

void sort_unique(std::vector<std::int32_t>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

}  // namespace

// Inside the box or on its boundary (OpenRadioss rdbox.F: INSIDE_CYLINDER, INSIDE_SPHERE). Cylinder: the
// projection on the axis p1 -> p2 lies between the end faces and the distance to the axis is at most D/2;
// sphere: |x - p1| <= D/2.
bool inside_box(const model::Box& b, double x, double y, double z) {
  const model::Vec3 d = model::sub({x, y, z}, b.p1);
  switch (b.shape) {
    case model::BoxShape::Recta:
      return x >= b.p1[0] && x <= b.p2[0] && y >= b.p1[1] && y <= b.p2[1] && z >= b.p1[2] && z <= b.p2[2];
    case model::BoxShape::Cylinder: {
      const model::Vec3 axis = model::sub(b.p2, b.p1);
      const double length = model::norm(axis);
      if (!(length > 0)) return false;  // no axis (an error already): nothing inside, as in Radioss
      const model::Vec3 u = model::scale(axis, 1.0 / length);
      const double along = model::dot(d, u);
      return along >= 0 && along <= length &&
             model::norm(model::sub(d, model::scale(u, along))) <= 0.5 * b.diameter;
    }
    case model::BoxShape::Sphere: return 4.0 * model::dot(d, d) <= b.diameter * b.diameter;
  }
  return false;
}

namespace {

// The element group families: the keyword root, the subtype that lists element ids, the words messages
// use. Indexed by model::ElementType; tetrahedra are grouped as bricks and springs are not grouped (empty
// root).
struct ElementGroupFamily {
  std::string_view root;             // "/GRSHEL"
  std::string_view list_kind;        // "SHEL": the subtype that lists element ids
  std::string_view element;          // "4-node shell"
  std::string_view element_keyword;  // "/SHELL"
};
constexpr std::array<ElementGroupFamily, ModelBuilder::kElementTypes> kFamilies = {{
    {"/GRSHEL", "SHEL", "4-node shell", "/SHELL"},
    {"/GRSH3N", "SH3N", "3-node shell", "/SH3N"},
    {"/GRBRIC", "BRIC", "brick", "/BRICK"},
    {"", "", "tetrahedron", "/TETRA4"},
    {"", "", "spring", "/SPRING"},
    {"/GRTRUS", "TRUS", "truss", "/TRUSS"},
    {"/GRBEAM", "BEAM", "beam", "/BEAM"},
    {"", "", "20-node brick", "/BRIC20"},
}};
static_assert(static_cast<int>(model::ElementType::Shell4) == 0 &&
              static_cast<int>(model::ElementType::Shell3) == 1 &&
              static_cast<int>(model::ElementType::Brick8) == 2 &&
              static_cast<int>(model::ElementType::Truss2) == 5 &&
              static_cast<int>(model::ElementType::Beam2) == 6);
const ElementGroupFamily& family(model::ElementType t) {
  return kFamilies[static_cast<std::size_t>(t)];
}

// The nodes of an element of block b that make its shape: all its nodes, but a beam's two (its third only
// orients it), as Radioss's groups take them (hm_lecgrn.F: columns 2 and 3 of trusses and beams).
std::size_t shape_nodes(const model::ElementBlock& b) {
  return b.type == model::ElementType::Beam2 ? 2 : static_cast<std::size_t>(b.npe());
}

// Keeps the distinct nodes of a face in their order and returns how many there are: a degenerate brick
// repeats nodes, and its face is then a triangle (written n1 n2 n3 n3, as every triangle segment) or,
// below 3 nodes, no face at all.
int keep_distinct(std::array<std::int32_t, 4>& f) {
  int n = 0;
  for (int k = 0; k < 4; ++k) {
    bool seen = false;
    for (int j = 0; j < n; ++j) seen = seen || f[j] == f[k];
    if (!seen) f[n++] = f[k];
  }
  if (n == 3) f[3] = f[2];
  return n;
}

// The sorted distinct nodes of a face (-1 fills a triangle's fourth slot): two faces with the same key
// are one face seen from its two sides.
FaceKey distinct_key(const std::array<std::int32_t, 4>& f, int n) {
  FaceKey k{-1, -1, -1, -1};
  for (int j = 0; j < n; ++j) k[j] = f[j];
  std::sort(k.begin(), k.end());
  return k;
}

}  // namespace

const model::ElementBlock& ModelBuilder::block(model::ElementType type) const {
  switch (type) {
    case model::ElementType::Shell4: return m_.shells;
    case model::ElementType::Shell3: return m_.shells3;
    case model::ElementType::Brick8: return m_.bricks;
    case model::ElementType::Tetra4: return m_.tetras;
    case model::ElementType::Spring2: return m_.springs;
    case model::ElementType::Truss2: return m_.trusses;
    case model::ElementType::Beam2: return m_.beams;
    case model::ElementType::Brick20: return m_.bricks20;
  }
  return m_.shells;
}

// A brick group's index runs through the bricks, then the tetrahedra, then the 20-node bricks (Radioss keeps
// all three in one solid table and groups them together).
ModelBuilder::GroupElement ModelBuilder::group_element(model::ElementType type, std::int32_t e) const {
  const auto& b = block(type);
  if (type == model::ElementType::Brick8 && e >= static_cast<std::int32_t>(b.size())) {
    const auto t = e - static_cast<std::int32_t>(b.size());
    if (t < static_cast<std::int32_t>(m_.tetras.size())) return {&m_.tetras, t};
    return {&m_.bricks20, t - static_cast<std::int32_t>(m_.tetras.size())};
  }
  return {&b, e};
}

std::size_t ModelBuilder::group_capacity(model::ElementType type) const {
  return block(type).size() +
         (type == model::ElementType::Brick8 ? m_.tetras.size() + m_.bricks20.size() : 0);
}

void ModelBuilder::subset_parts(std::int32_t s, std::vector<std::int32_t>& out) const {
  std::vector<std::int32_t> stack{s};
  std::vector<std::uint8_t> seen(m_.subsets.size(), 0);
  while (!stack.empty()) {
    const auto t = stack.back();
    stack.pop_back();
    if (seen[t]) continue;
    seen[t] = 1;
    out.insert(out.end(), m_.subsets[t].parts.begin(), m_.subsets[t].parts.end());
    for (auto c : m_.subsets[t].children) stack.push_back(c);
  }
}

const ModelBuilder::ElementGroup* ModelBuilder::element_group(model::ElementType type,
                                                              std::int64_t id) const {
  const auto& ids = element_group_ids_[static_cast<std::size_t>(type)];
  const auto it = ids.find(id);
  return it == ids.end() ? nullptr : &element_groups_[it->second];
}

void ModelBuilder::build_element_groups() {
  std::unordered_map<std::int64_t, SourcePos> first[kElementTypes];
  for (const auto& r : deck_.records) {
    const auto path = r.decl->path;
    for (std::size_t f = 0; f < kFamilies.size(); ++f) {
      const auto root = kFamilies[f].root;
      if (root.empty() || path.size() <= root.size() || path.compare(0, root.size(), root) != 0 ||
          path[root.size()] != '/')
        continue;
      ElementGroup g;
      g.record = &r;
      g.type = static_cast<model::ElementType>(f);
      if (register_id(element_group_ids_[f], r.id, static_cast<std::int32_t>(element_groups_.size()), r,
                      std::string(kFamilies[f].element) + " group", first[f]))
        element_groups_.push_back(std::move(g));
    }
  }
  for (std::size_t g = 0; g < element_groups_.size(); ++g) group_elements(static_cast<std::int32_t>(g));
}

namespace {

// An element group's list while it is resolved: the elements it adds and those it takes out.
struct ElementGroupList {
  ModelBuilder& b;
  const KeywordRecord& r;
  model::ElementType type;
  const ElementGroupFamily& fam;
  const model::ElementBlock& elems;
  std::string gname;      // "brick group 5", for messages
  std::string self_kind;  // GRSHEL, GRSH3N, GRBRIC: the subtype that lists groups of the group's family
  std::vector<std::int32_t> add, remove;
};

// RX402 warning for entry k of the list: `what` does not exist, and the group goes on without it, as
// Radioss goes on (a warning in its hierarchy references).
void report_missing_in_element_group(const ElementGroupList& l, std::size_t k, const std::string& what) {
  l.b.diags_.warning(Diag::MissingReference, l.b.at(l.r.id_pos[k], 1), ModelBuilder::about(l.r),
                     what + " does not exist (listed in " + l.gname + "): it is left out, as Radioss does");
}

// The index, in a group of the list's type, of the element with user id `id`; -1 when none. A brick group
// looks among the tetrahedra, then the 20-node bricks, when no brick has the id.
std::int32_t group_index_of(const ElementGroupList& l, std::int64_t id) {
  const auto e = l.elems.index.find(id);
  if (e >= 0 || l.type != model::ElementType::Brick8) return e;
  const auto t = l.b.m_.tetras.index.find(id);
  if (t >= 0) return static_cast<std::int32_t>(l.elems.size()) + t;
  const auto q = l.b.m_.bricks20.index.find(id);
  return q < 0 ? -1 : static_cast<std::int32_t>(l.elems.size() + l.b.m_.tetras.size()) + q;
}

// Calls f(group index, part) for every element a group of the list's type can hold.
template <class F>
void for_each_group_element(const ElementGroupList& l, F&& f) {
  const auto n = l.b.group_capacity(l.type);
  for (std::size_t e = 0; e < n; ++e) {
    const auto ge = l.b.group_element(l.type, static_cast<std::int32_t>(e));
    f(static_cast<std::int32_t>(e), ge);
  }
}

// /GRSHEL/SHEL, /GRSH3N/SH3N, /GRBRIC/BRIC: the element ids themselves.
void add_listed_elements(ElementGroupList& l) {
  const auto& r = l.r;
  const auto& fam = l.fam;
  for (std::size_t k = 0; k < r.ids.size(); ++k) {
    const std::int64_t id = r.ids[k];
    const auto e = id > 0 ? group_index_of(l, id) : -1;
    if (id <= 0)
      l.b.diags_.error(Diag::MissingReference, l.b.at(r.id_pos[k], 1), ModelBuilder::about(r),
                       "there is no " + std::string(fam.element) + " " + std::to_string(id) + ": " +
                           std::string(r.decl->path) + " lists element ids, which are positive (to leave " +
                           "elements out, subtract a group with " + std::string(fam.root) + "/" +
                           l.self_kind + ")");
    else if (e < 0)
      l.b.diags_.error(Diag::MissingReference, l.b.at(r.id_pos[k], 1), ModelBuilder::about(r),
                       std::string(fam.element) + " " + std::to_string(id) + " does not exist: no " +
                           std::string(fam.element_keyword) +
                           (l.type == model::ElementType::Brick8 ? ", /TETRA4 or /BRIC20" : "") +
                           " line defines it (listed in " + l.gname + ")");
    else
      l.add.push_back(e);
  }
}

// The parts that entry k of a PART, SUBSET, MAT or PROP list names by `id` (its absolute value), added to
// `parts`; false, with RX402, when nothing has that id.
bool parts_named_by(const ElementGroupList& l, std::string_view kind, std::size_t k, std::int64_t id,
                    std::vector<std::int32_t>& parts) {
  const auto& b = l.b;
  if (kind == "PART") {
    const auto it = b.part_ids_.find(id);
    if (it == b.part_ids_.end()) {
      report_missing_in_element_group(l, k, "part " + std::to_string(id));
      return false;
    }
    parts.push_back(it->second);
  } else if (kind == "SUBSET") {
    const auto it = b.subset_ids_.find(id);
    if (it == b.subset_ids_.end()) {
      report_missing_in_element_group(l, k, "subset " + std::to_string(id));
      return false;
    }
    b.subset_parts(it->second, parts);
  } else {
    const bool mat = kind == "MAT";
    const auto& index = mat ? b.mat_ids_ : b.prop_ids_;
    const auto it = index.find(id);
    if (it == index.end()) {
      report_missing_in_element_group(l, k, (mat ? "material " : "property ") + std::to_string(id));
      return false;
    }
    for (std::size_t p = 0; p < b.m_.parts.size(); ++p)
      if ((mat ? b.m_.parts[p].material : b.m_.parts[p].property) == it->second)
        parts.push_back(static_cast<std::int32_t>(p));
  }
  return true;
}

// /GR.../PART, SUBSET, MAT, PROP: the elements of the parts listed, less those of the parts a negative id
// names.
void add_elements_of_parts(ElementGroupList& l, std::string_view kind) {
  const auto& r = l.r;
  // +1 for a part brought in, -1 for a part taken out; -1 wins whatever the order of the ids.
  std::vector<std::int8_t> tag(l.b.m_.parts.size(), 0);
  for (std::size_t k = 0; k < r.ids.size(); ++k) {
    const bool negative = r.ids[k] < 0;
    const std::int64_t id = negative ? -r.ids[k] : r.ids[k];
    std::vector<std::int32_t> parts;
    if (!parts_named_by(l, kind, k, id, parts)) continue;
    for (const auto p : parts) tag[p] = negative ? -1 : (tag[p] == 0 ? 1 : tag[p]);
  }
  for_each_group_element(l, [&](std::int32_t e, ModelBuilder::GroupElement ge) {
    const auto part = ge.block->part[static_cast<std::size_t>(ge.index)];
    if (part != kNone && tag[part] == 1) l.add.push_back(e);
  });
}

// /GRSHEL/GRSHEL and the like: the elements of the groups listed; a negative id subtracts its group.
void add_elements_of_groups(ElementGroupList& l) {
  const auto& r = l.r;
  for (std::size_t k = 0; k < r.ids.size(); ++k) {
    const bool negative = r.ids[k] < 0;
    const std::int64_t id = negative ? -r.ids[k] : r.ids[k];
    const auto& ids = l.b.element_group_ids_[static_cast<std::size_t>(l.type)];
    const auto it = ids.find(id);
    if (it == ids.end()) {
      report_missing_in_element_group(l, k, std::string(l.fam.element) + " group " + std::to_string(id));
      continue;
    }
    if (const auto* sub = l.b.group_elements(it->second)) {
      auto& dst = negative ? l.remove : l.add;
      dst.insert(dst.end(), sub->begin(), sub->end());
    }
  }
}

// The entry of a BOX or BOX2 list that names the box, with a warning for every other entry; the list's
// size when no entry does.
std::size_t first_box_entry(const ElementGroupList& l) {
  const auto& r = l.r;
  // Radioss reads one box: the first positive id. Boxes are combined with /BOX/BOX, not by listing.
  std::size_t box_k = r.ids.size();
  for (std::size_t k = 0; k < r.ids.size(); ++k) {
    if (box_k == r.ids.size() && r.ids[k] > 0) {
      box_k = k;
      continue;
    }
    l.b.diags_.warning(Diag::ExtraData, l.b.at(r.id_pos[k], 1), ModelBuilder::about(r),
                       "box id " + std::to_string(r.ids[k]) + " is ignored: " + std::string(r.decl->path) +
                           " takes one box, the first positive id of its list, as Radioss does");
  }
  return box_k;
}

// /GR.../BOX and BOX2: the elements in the box of the list's first positive id.
void add_elements_in_box(ElementGroupList& l, bool every_node) {
  const auto& r = l.r;
  const auto& m = l.b.m_;
  const std::size_t box_k = first_box_entry(l);
  const bool line_elements = l.type == model::ElementType::Truss2 || l.type == model::ElementType::Beam2;
  if (box_k >= r.ids.size()) {
    // No positive box id: Radioss stops on it in truss and beam groups (its error 798 on box 0).
    if (line_elements)
      l.b.diags_.error(Diag::RequiredIdMissing, l.b.at(r.pos, 1), ModelBuilder::about(r),
                       l.gname +
                           " names no box (no positive box id): Radioss stops on it in truss and beam "
                           "groups; give the id of a /BOX");
    return;
  }
  const auto it = l.b.box_ids_.find(r.ids[box_k]);
  if (it == l.b.box_ids_.end()) {
    // Radioss finds nothing in a box that does not exist and goes on for shells and solids (the group is
    // only reported empty), but stops on it for trusses and beams (its error 798).
    const std::string text = "box " + std::to_string(r.ids[box_k]) +
                             " does not exist: there is no /BOX/RECTA, /BOX/CYLIN or /BOX/SPHER with id " +
                             std::to_string(r.ids[box_k]) + " (listed in " + l.gname + ")";
    if (line_elements)
      l.b.diags_.error(Diag::MissingReference, l.b.at(r.id_pos[box_k], 1), ModelBuilder::about(r),
                       text + "; Radioss stops on it in truss and beam groups");
    else
      l.b.diags_.warning(Diag::MissingReference, l.b.at(r.id_pos[box_k], 1), ModelBuilder::about(r),
                         text + "; it selects nothing, as in Radioss");
    return;
  }
  const auto& b = m.boxes[it->second];
  // BOX: every node of the element inside; BOX2: one node inside is enough. A beam's orientation node is not
  // one of its nodes there.
  for_each_group_element(l, [&](std::int32_t e, ModelBuilder::GroupElement ge) {
    const auto npe = static_cast<std::size_t>(ge.block->npe());
    const std::size_t nodes = shape_nodes(*ge.block);
    std::size_t in = 0;
    for (std::size_t k = 0; k < nodes; ++k) {
      const auto n = ge.block->conn[static_cast<std::size_t>(ge.index) * npe + k];
      if (n >= 0 && inside_box(b, m.nodes.x[n], m.nodes.y[n], m.nodes.z[n])) ++in;
    }
    if (every_node ? in == nodes : in > 0) l.add.push_back(e);
  });
}

// The (first, last, increment) ranges of a GENE list, pairs 'first last'.
std::vector<std::array<std::int64_t, 3>> gene_ranges(ModelBuilder& b, const KeywordRecord& r) {
  std::vector<std::array<std::int64_t, 3>> ranges;
  if (r.ids.size() % 2 != 0)
    b.diags_.error(Diag::InconsistentValues, b.at(r.id_pos.back(), 1), ModelBuilder::about(r),
                   std::string(r.decl->path) + " lists pairs 'first last'; the last pair is incomplete");
  for (std::size_t k = 0; k + 1 < r.ids.size(); k += 2) ranges.push_back({r.ids[k], r.ids[k + 1], 1});
  return ranges;
}

// The indices of the ids of `ids` (user ids by index, looked up by `find`) in each range to `out`, as
// Radioss takes the ids of a range that exist. A range far wider than the model walks the model's ids
// rather than the range, and a note says how many of its ids exist.
template <class Find>
void add_ids_in_ranges(ModelBuilder& b, const KeywordRecord& r, const std::vector<std::int64_t>& ids,
                       Find&& find, const std::vector<std::array<std::int64_t, 3>>& ranges,
                       std::vector<std::int32_t>& out) {
  const auto size = static_cast<std::uint64_t>(ids.size());
  for (const auto& [lo, hi, step] : ranges) {
    if (hi < lo) continue;
    // In unsigned arithmetic: a range may span the whole of int64 (-9e18 to 9e18) without overflow.
    const std::uint64_t span =
        (static_cast<std::uint64_t>(hi) - static_cast<std::uint64_t>(lo)) / static_cast<std::uint64_t>(step) +
        1;
    const std::size_t before = out.size();
    if (span <= size) {
      for (std::uint64_t k = 0; k < span; ++k)
        if (const std::int32_t e = find(lo + static_cast<std::int64_t>(k) * step); e >= 0) out.push_back(e);
      continue;
    }
    for (std::size_t e = 0; e < ids.size(); ++e) {
      if (ids[e] < lo || ids[e] > hi) continue;
      if ((static_cast<std::uint64_t>(ids[e]) - static_cast<std::uint64_t>(lo)) %
          static_cast<std::uint64_t>(step))
        continue;
      // An id the index does not hold (a duplicate or refused entity) is not a member.
      if (const std::int32_t found = find(ids[e]); found >= 0) out.push_back(found);
    }
    if (span / 100 > size + 10)
      b.diags_.note(Diag::DefaultApplied, b.at(r.pos, 1), ModelBuilder::about(r),
                    "range " + std::to_string(lo) + " to " + std::to_string(hi) + " (" +
                        std::to_string(span) +
                        " ids) is far wider than the model: " + std::to_string(out.size() - before) +
                        " of its ids exist and are taken, as Radioss takes them");
  }
}

// /GRSHEL/GENE, /GRSH3N/GENE, /GRBRIC/GENE: the existing elements of each id range (a brick group's
// tetrahedra and 20-node bricks too).
void add_elements_in_ranges(ElementGroupList& l) {
  const auto ranges = gene_ranges(l.b, l.r);
  std::vector<std::int64_t> ids(l.elems.id);
  if (l.type == model::ElementType::Brick8) {
    ids.insert(ids.end(), l.b.m_.tetras.id.begin(), l.b.m_.tetras.id.end());
    ids.insert(ids.end(), l.b.m_.bricks20.id.begin(), l.b.m_.bricks20.id.end());
  }
  add_ids_in_ranges(
      l.b, l.r, ids, [&](std::int64_t id) { return group_index_of(l, id); }, ranges, l.add);
}

}  // namespace

const std::vector<std::int32_t>* ModelBuilder::group_elements(std::int32_t g) {
  auto& group = element_groups_[static_cast<std::size_t>(g)];
  if (group.state == 2) return &group.elements;
  const KeywordRecord& r = *group.record;
  const auto& fam = family(group.type);
  ElementGroupList l{*this,
                     r,
                     group.type,
                     fam,
                     block(group.type),
                     std::string(fam.element) + " group " + std::to_string(r.id),
                     std::string(fam.root.substr(1)),
                     {},
                     {}};
  if (group.state == 1) {
    diags_.error(Diag::InconsistentValues, at(r.pos, 1), about(r),
                 l.gname + " includes itself through " + std::string(fam.root) + "/" + l.self_kind +
                     "; remove the loop");
    return nullptr;
  }
  group.state = 1;
  const std::size_t errors_before = diags_.error_count();
  const std::string_view kind = r.decl->path.substr(fam.root.size() + 1);
  if (kind == fam.list_kind)
    add_listed_elements(l);
  else if (kind == "PART" || kind == "SUBSET" || kind == "MAT" || kind == "PROP")
    add_elements_of_parts(l, kind);
  else if (kind == l.self_kind)
    add_elements_of_groups(l);
  else if (kind == "BOX" || kind == "BOX2")
    add_elements_in_box(l, kind == "BOX");
  else if (kind == "GENE")
    add_elements_in_ranges(l);
  sort_unique(l.add);
  sort_unique(l.remove);
  group.elements.clear();
  std::set_difference(l.add.begin(), l.add.end(), l.remove.begin(), l.remove.end(),
                      std::back_inserter(group.elements));
  if (group.elements.empty() && diags_.error_count() == errors_before) {
    // Radioss warns and goes on; what is built from the group then holds nothing.
    diags_.warning(Diag::EmptyGroup, at(r.pos, 1), about(r),
                   l.gname + " holds no " + std::string(fam.element) +
                       (group.type == model::ElementType::Brick8 ? ", tetrahedron or 20-node brick" : "") +
                       ": the surfaces and node groups built from it hold nothing of it (as in Radioss)");
  }
  group.state = 2;
  return &group.elements;
}

// /BOX/RECTA, /BOX/CYLIN and /BOX/SPHER, one id space (hm_read_box.F). The points come from the nodes N1 and
// N2 when both are given (the sphere: N1), as Radioss reads them (read_box_rect.F, read_box_cyl.F,
// read_box_spher.F); with one node only, Radioss reads the coordinates.
void ModelBuilder::build_boxes() {
  std::unordered_map<std::int64_t, SourcePos> first;
  // The point of node `field` (when `use`), else the coordinates `xyz`.
  auto point = [&](const KeywordRecord& r, std::string_view field, bool use,
                   std::array<std::string_view, 3> xyz) -> model::Vec3 {
    if (use) {
      const auto n = node_ref(r.get_int(field), r, r.find(field) ? r.find(field)->pos : r.pos, field);
      if (n >= 0) return {m_.nodes.x[n], m_.nodes.y[n], m_.nodes.z[n]};
    }
    // Coordinates written inside a submodel move with it (a box stays aligned with the global axes).
    return submodel_point(r, {r.get_real(xyz[0]), r.get_real(xyz[1]), r.get_real(xyz[2])});
  };
  // Both N1 and N2, or the coordinates; a lone node is ignored, as Radioss ignores it.
  auto two_nodes = [&](const KeywordRecord& r) {
    const bool n1 = r.get_int("N1") != 0, n2 = r.get_int("N2") != 0;
    if (n1 != n2)
      warning_at(r, n1 ? "N1" : "N2", Diag::InconsistentValues,
                 std::string(n1 ? "N1" : "N2") +
                     " is ignored: the points come from the nodes only when both N1 and N2 are given (as in "
                     "Radioss); the coordinates Xp1 ... Zp2 are used");
    return n1 && n2;
  };
  const std::array<std::string_view, 3> xyz1{"Xp1", "Yp1", "Zp1"}, xyz2{"Xp2", "Yp2", "Zp2"};
  for (const auto& [path, shape] : {std::pair{"/BOX/RECTA", model::BoxShape::Recta},
                                    {"/BOX/CYLIN", model::BoxShape::Cylinder},
                                    {"/BOX/SPHER", model::BoxShape::Sphere}}) {
    for (const auto* r : deck_.of(path)) {
      model::Box b;
      b.id = r->id;
      b.title = r->title;
      b.shape = shape;
      const bool nodes = shape == model::BoxShape::Sphere ? r->get_int("N1") != 0 : two_nodes(*r);
      b.p1 = point(*r, "N1", nodes, xyz1);
      if (shape != model::BoxShape::Sphere) b.p2 = point(*r, "N2", nodes, xyz2);
      if (shape == model::BoxShape::Recta) {
        if (r->get_int("Iskew") != 0)
          error_at(
              *r, "Iskew", Diag::UnimplementedOption,
              "boxes aligned with a skew frame are not supported (radx builds boxes on the global axes); "
              "use Iskew = 0");
        for (std::size_t k = 0; k < 3; ++k) {
          const double lo = std::min(b.p1[k], b.p2[k]), hi = std::max(b.p1[k], b.p2[k]);
          b.p1[k] = lo;
          b.p2[k] = hi;
        }
      } else {
        b.diameter = r->get_real("Diameter");  // > 0: the reader checks it
      }
      if (shape == model::BoxShape::Cylinder && b.p1 == b.p2)
        error_at(
            *r, nodes ? "N2" : "Xp2", Diag::InconsistentValues,
            "P1 and P2 coincide at " + point_text(b.p1) +
                ": the cylinder has no axis (Radioss finds nothing inside it); give two distinct centres "
                "of its end faces");
      if (register_id(box_ids_, b.id, static_cast<std::int32_t>(m_.boxes.size()), *r, "box", first))
        m_.boxes.push_back(std::move(b));
    }
  }
}

void ModelBuilder::build_functions() {
  std::unordered_map<std::int64_t, SourcePos> first;
  for (const auto* r : deck_.of("/FUNCT")) {
    model::Function f;
    f.id = r->id;
    f.title = r->title;
    const auto& t = r->records;
    const int cx = t.column("X"), cy = t.column("Y");
    if (cx >= 0 && cy >= 0) {
      f.x = t.reals[cx];
      f.y = t.reals[cy];
    }
    if (f.x.empty()) {
      diags_.error(Diag::EmptyRecordList, at(r->pos, 1), about(*r),
                   "the function has no points; write one 'X Y' pair per line after the title");
    } else if (f.x.size() == 1) {
      diags_.warning(Diag::EmptyRecordList, at(t.pos[0], 1), about(*r),
                     "the function has a single point: it is constant");
    }
    // The Radioss starter stops too on an abscissa not above the one before (it does not sort them);
    // radx reports every such point rather than the first.
    for (std::size_t k = 1; k < f.x.size(); ++k) {
      if (!(f.x[k] > f.x[k - 1])) {
        diags_.error(Diag::NonMonotonicFunction, at(t.pos[k], 1), about(*r),
                     "abscissa X = " + number_text(f.x[k]) + " is not greater than the previous one (" +
                         number_text(f.x[k - 1]) + "); function abscissas must be strictly increasing");
      }
    }
    if (register_id(funct_ids_, f.id, static_cast<std::int32_t>(m_.functions.size()), *r, "function", first))
      m_.functions.push_back(std::move(f));
  }
}

void ModelBuilder::build_groups() {
  std::unordered_map<std::int64_t, SourcePos> first;
  for (const auto& r : deck_.records) {
    if (r.decl->path.rfind("/GRNOD/", 0) != 0) continue;
    model::NodeGroup g;
    g.id = r.id;
    g.title = r.title;
    g.kind = std::string(r.decl->path.substr(7));
    if (register_id(grnod_ids_, g.id, static_cast<std::int32_t>(m_.node_groups.size()), r, "node group",
                    first)) {
      m_.node_groups.push_back(std::move(g));
      grnod_records_.push_back(&r);
    }
  }
  grnod_state_.assign(m_.node_groups.size(), 0);
  for (std::size_t g = 0; g < m_.node_groups.size(); ++g) group_nodes(static_cast<std::int32_t>(g));
}

namespace {

// A node group's list while it is resolved: the nodes it adds and those it takes out.
struct NodeGroupList {
  ModelBuilder& b;
  const KeywordRecord& r;
  std::int64_t id;  // the group's, for messages
  std::vector<std::int32_t> add, remove;
};

// The nodes of the elements of `part`, to `out`.
void add_part_nodes(const model::Model& m, std::int32_t part, std::vector<std::int32_t>& out) {
  for (const auto* b : {&m.shells, &m.shells3, &m.bricks, &m.tetras, &m.bricks20, &m.trusses, &m.beams}) {
    const auto npe = static_cast<std::size_t>(b->npe());
    for (std::size_t e = 0; e < b->size(); ++e) {
      if (b->part[e] != part) continue;
      for (std::size_t k = 0; k < shape_nodes(*b); ++k)
        if (b->conn[e * npe + k] >= 0) out.push_back(b->conn[e * npe + k]);
    }
  }
}

// RX402 for entry k of the list: `what` `id` does not exist. An error for a node id, as Radioss stops
// there; a warning for anything else (a part, group, box ...), left out as Radioss leaves it out.
void report_missing_in_node_group(const NodeGroupList& l, std::size_t k, const std::string& what,
                                  std::int64_t id) {
  const bool node = what == "node";
  l.b.diags_.add(node ? Severity::Error : Severity::Warning, Diag::MissingReference, l.b.at(l.r.id_pos[k], 1),
                 ModelBuilder::about(l.r),
                 what + " " + std::to_string(id) + " does not exist (listed in node group " +
                     std::to_string(l.id) + ")" + (node ? "" : ": it is left out, as Radioss does"));
}

// /GRNOD/NODE: the node ids themselves.
void add_listed_nodes(NodeGroupList& l) {
  const auto& r = l.r;
  for (std::size_t k = 0; k < r.ids.size(); ++k) {
    const auto n = l.b.m_.nodes.index.find(r.ids[k]);
    if (n < 0)
      report_missing_in_node_group(l, k, "node", r.ids[k]);
    else
      l.add.push_back(n);
  }
}

// /GRNOD/PART: the nodes of the parts listed; a negative id subtracts its part's nodes.
void add_nodes_of_parts(NodeGroupList& l) {
  const auto& r = l.r;
  for (std::size_t k = 0; k < r.ids.size(); ++k) {
    const std::int64_t id = r.ids[k] < 0 ? -r.ids[k] : r.ids[k];
    const auto it = l.b.part_ids_.find(id);
    if (it == l.b.part_ids_.end())
      report_missing_in_node_group(l, k, "part", id);
    else
      add_part_nodes(l.b.m_, it->second, r.ids[k] < 0 ? l.remove : l.add);
  }
}

// /GRNOD/GRNOD: the nodes of the node groups listed; a negative id subtracts its group.
void add_nodes_of_node_groups(NodeGroupList& l) {
  const auto& r = l.r;
  for (std::size_t k = 0; k < r.ids.size(); ++k) {
    const std::int64_t id = r.ids[k] < 0 ? -r.ids[k] : r.ids[k];
    const auto it = l.b.grnod_ids_.find(id);
    if (it == l.b.grnod_ids_.end()) {
      report_missing_in_node_group(l, k, "node group", id);
      continue;
    }
    if (const auto* sub = l.b.group_nodes(it->second)) {
      auto& dst = r.ids[k] < 0 ? l.remove : l.add;
      dst.insert(dst.end(), sub->begin(), sub->end());
    }
  }
}

// /GRNOD/BOX: the nodes inside each box listed.
void add_nodes_in_boxes(NodeGroupList& l) {
  const auto& r = l.r;
  const auto& m = l.b.m_;
  for (std::size_t k = 0; k < r.ids.size(); ++k) {
    const auto it = l.b.box_ids_.find(r.ids[k]);
    if (it == l.b.box_ids_.end()) {
      report_missing_in_node_group(l, k, "box", r.ids[k]);
      continue;
    }
    const auto& b = m.boxes[it->second];
    for (std::size_t n = 0; n < m.nodes.size(); ++n) {
      if (inside_box(b, m.nodes.x[n], m.nodes.y[n], m.nodes.z[n]))
        l.add.push_back(static_cast<std::int32_t>(n));
    }
  }
}

// The id ranges (first, last, increment) of /GRNOD/GENE (`gene`) or /GRNOD/GEN_INCR.
std::vector<std::array<std::int64_t, 3>> node_id_ranges(const NodeGroupList& l, bool gene) {
  const auto& r = l.r;
  // GENE: pairs (first, last); GEN_INCR: records (first, last, incr).
  std::vector<std::array<std::int64_t, 3>> ranges;
  if (gene) {
    ranges = gene_ranges(l.b, r);
  } else {
    const auto& t = r.records;
    const int c1 = t.column("first"), c2 = t.column("last"), c3 = t.column("incr");
    for (std::size_t k = 0; c1 >= 0 && c2 >= 0 && k < t.size(); ++k)
      ranges.push_back({t.ints[c1][k], t.ints[c2][k], c3 >= 0 && t.ints[c3][k] > 0 ? t.ints[c3][k] : 1});
  }
  return ranges;
}

// /GRNOD/GENE and /GRNOD/GEN_INCR: the existing nodes of each id range.
void add_nodes_in_ranges(NodeGroupList& l, bool gene) {
  const auto& nodes = l.b.m_.nodes;
  add_ids_in_ranges(
      l.b, l.r, nodes.id, [&](std::int64_t id) { return nodes.index.find(id); }, node_id_ranges(l, gene),
      l.add);
}

// /GRNOD/MAT (`mat`) and /GRNOD/PROP: the nodes of the parts of each material or property listed.
void add_nodes_of_materials_or_properties(NodeGroupList& l, bool mat) {
  const auto& r = l.r;
  const auto& m = l.b.m_;
  for (std::size_t k = 0; k < r.ids.size(); ++k) {
    const auto& index = mat ? l.b.mat_ids_ : l.b.prop_ids_;
    const auto it = index.find(r.ids[k]);
    if (it == index.end()) {
      report_missing_in_node_group(l, k, mat ? "material" : "property", r.ids[k]);
      continue;
    }
    for (std::size_t p = 0; p < m.parts.size(); ++p)
      if ((mat ? m.parts[p].material : m.parts[p].property) == it->second)
        add_part_nodes(m, static_cast<std::int32_t>(p), l.add);
  }
}

// /GRNOD/SURF: the nodes of the segments of each surface listed.
void add_nodes_of_surfaces(NodeGroupList& l) {
  const auto& r = l.r;
  for (std::size_t k = 0; k < r.ids.size(); ++k) {
    const auto it = l.b.surf_ids_.find(r.ids[k]);
    if (it == l.b.surf_ids_.end()) {
      report_missing_in_node_group(l, k, "surface", r.ids[k]);
      continue;
    }
    for (const auto& seg : l.b.m_.surfaces[it->second].segments)
      for (const auto n : seg)
        if (n >= 0) l.add.push_back(n);  // a segment whose node was refused keeps kNone there
  }
}

// /GRNOD/SUBSET: the nodes of the parts of each subset listed (and of its descendants).
void add_nodes_of_subsets(NodeGroupList& l) {
  const auto& r = l.r;
  for (std::size_t k = 0; k < r.ids.size(); ++k) {
    const auto it = l.b.subset_ids_.find(r.ids[k]);
    if (it == l.b.subset_ids_.end()) {
      report_missing_in_node_group(l, k, "subset", r.ids[k]);
      continue;
    }
    std::vector<std::int32_t> parts;
    l.b.subset_parts(it->second, parts);
    for (auto p : parts) add_part_nodes(l.b.m_, p, l.add);
  }
}

// /GRNOD/GRSHEL, /GRSH3N, /GRBRIC (`kind`): the nodes of the elements of each element group listed.
void add_nodes_of_element_groups(NodeGroupList& l, const std::string& kind) {
  const auto& r = l.r;
  const auto type = kind == "GRSHEL"   ? model::ElementType::Shell4
                    : kind == "GRSH3N" ? model::ElementType::Shell3
                    : kind == "GRTRUS" ? model::ElementType::Truss2
                    : kind == "GRBEAM" ? model::ElementType::Beam2
                                       : model::ElementType::Brick8;
  const auto& fam = family(type);
  for (std::size_t k = 0; k < r.ids.size(); ++k) {
    if (r.ids[k] < 0) {
      l.b.diags_.warning(Diag::ValueOutOfRange, l.b.at(r.id_pos[k], 1), ModelBuilder::about(r),
                         "id " + std::to_string(r.ids[k]) +
                             " is ignored: a negative id removes nothing in /GRNOD/" + kind +
                             ", as in Radioss; subtract node groups with /GRNOD/GRNOD");
      continue;
    }
    const auto* eg = l.b.element_group(type, r.ids[k]);
    if (!eg) {
      report_missing_in_node_group(l, k, std::string(fam.element) + " group", r.ids[k]);
      continue;
    }
    for (const auto e : eg->elements) {
      const auto ge = l.b.group_element(type, e);
      const auto npe = static_cast<std::size_t>(ge.block->npe());
      const auto* c = &ge.block->conn[static_cast<std::size_t>(ge.index) * npe];
      for (std::size_t j = 0; j < shape_nodes(*ge.block); ++j)
        if (c[j] >= 0) l.add.push_back(c[j]);
    }
  }
}

}  // namespace

const std::vector<std::int32_t>* ModelBuilder::group_nodes(std::int32_t g) {
  if (g < 0 || g >= static_cast<std::int32_t>(m_.node_groups.size())) return nullptr;
  auto& group = m_.node_groups[g];
  if (grnod_state_[g] == 2) return &group.nodes;
  const KeywordRecord& r = *grnod_records_[g];
  if (grnod_state_[g] == 1) {
    diags_.error(
        Diag::InconsistentValues, at(r.pos, 1), about(r),
        "node group " + std::to_string(group.id) + " includes itself through /GRNOD/GRNOD; remove the loop");
    return nullptr;
  }
  grnod_state_[g] = 1;
  NodeGroupList l{*this, r, group.id, {}, {}};
  const std::string& kind = group.kind;
  if (kind == "NODE")
    add_listed_nodes(l);
  else if (kind == "PART")
    add_nodes_of_parts(l);
  else if (kind == "GRNOD")
    add_nodes_of_node_groups(l);
  else if (kind == "BOX")
    add_nodes_in_boxes(l);
  else if (kind == "GENE" || kind == "GEN_INCR")
    add_nodes_in_ranges(l, kind == "GENE");
  else if (kind == "MAT" || kind == "PROP")
    add_nodes_of_materials_or_properties(l, kind == "MAT");
  else if (kind == "SURF")
    add_nodes_of_surfaces(l);
  else if (kind == "SUBSET")
    add_nodes_of_subsets(l);
  else if (kind == "GRSHEL" || kind == "GRSH3N" || kind == "GRBRIC" || kind == "GRTRUS" || kind == "GRBEAM")
    add_nodes_of_element_groups(l, kind);
  sort_unique(l.add);
  sort_unique(l.remove);
  group.nodes.clear();
  std::set_difference(l.add.begin(), l.add.end(), l.remove.begin(), l.remove.end(),
                      std::back_inserter(group.nodes));
  if (group.nodes.empty()) {
    // Radioss warns and goes on. After an error the group may be empty only because what it lists was not
    // built (a part whose property radx refused has no elements): say so rather than blame the list alone.
    diags_.warning(
        Diag::EmptyGroup, at(r.pos, 1), about(r),
        "node group " + std::to_string(group.id) +
            " holds no node: whatever uses it acts on nothing, as in Radioss; check its list" +
            (diags_.has_errors() ? " (other errors of this deck may have left out what it lists)" : ""));
  }
  grnod_state_[g] = 2;
  return &group.nodes;
}

namespace {

// Every element face by its sorted nodes, with the first element that has it: the owners of /SURF/SEG's
// segments.
using FaceOwners = std::map<FaceKey, std::pair<model::SegmentOwner, std::int32_t>>;

FaceOwners face_owners(const model::Model& m) {
  FaceOwners faces;
  for (std::size_t e = 0; e < m.shells.size(); ++e) {
    const auto* c = &m.shells.conn[4 * e];
    faces.emplace(face_key({c[0], c[1], c[2], c[3]}),
                  std::pair{model::SegmentOwner::Shell4, static_cast<std::int32_t>(e)});
  }
  for (std::size_t e = 0; e < m.shells3.size(); ++e) {
    const auto* c = &m.shells3.conn[3 * e];
    faces.emplace(face_key({c[0], c[1], c[2], c[2]}),
                  std::pair{model::SegmentOwner::Shell3, static_cast<std::int32_t>(e)});
  }
  for (std::size_t e = 0; e < m.bricks.size(); ++e) {
    const auto* c = &m.bricks.conn[8 * e];
    for (const auto& f : model::kBrickFaces)
      faces.emplace(face_key({c[f[0]], c[f[1]], c[f[2]], c[f[3]]}),
                    std::pair{model::SegmentOwner::Brick8, static_cast<std::int32_t>(e)});
  }
  for (std::size_t e = 0; e < m.tetras.size(); ++e) {
    const auto* c = &m.tetras.conn[4 * e];
    for (const auto& f : model::kTetraFaces)
      faces.emplace(face_key({c[f[0]], c[f[1]], c[f[2]], c[f[2]]}),
                    std::pair{model::SegmentOwner::Tetra4, static_cast<std::int32_t>(e)});
  }
  return faces;
}

void push_segment(model::Surface& s, std::array<std::int32_t, 4> seg, model::SegmentOwner type,
                  std::int32_t owner) {
  s.segments.push_back(seg);
  s.owner_type.push_back(type);
  s.owner.push_back(owner);
}

}  // namespace

void push_shell(const model::Model& m, model::Surface& s, std::int32_t e, bool flip) {
  const auto* c = &m.shells.conn[4 * static_cast<std::size_t>(e)];
  if (!flip)
    push_segment(s, {c[0], c[1], c[2], c[3]}, model::SegmentOwner::Shell4, e);
  else if (c[2] == c[3])
    push_segment(s, {c[0], c[2], c[1], c[1]}, model::SegmentOwner::Shell4, e);
  else
    push_segment(s, {c[0], c[3], c[2], c[1]}, model::SegmentOwner::Shell4, e);
}

void push_shell3(const model::Model& m, model::Surface& s, std::int32_t e, bool flip) {
  const auto* c = &m.shells3.conn[3 * static_cast<std::size_t>(e)];
  if (flip)
    push_segment(s, {c[0], c[2], c[1], c[1]}, model::SegmentOwner::Shell3, e);
  else
    push_segment(s, {c[0], c[1], c[2], c[2]}, model::SegmentOwner::Shell3, e);
}

namespace {

// How many marked solids have each face (each solid counted once): the tetrahedra marked in
// `tetra_neighbours`, the bricks marked in `neighbours` (either may be null).
std::map<FaceKey, int> solids_sharing_faces(const model::Model& m,
                                            const std::vector<std::uint8_t>* neighbours,
                                            const std::vector<std::uint8_t>* tetra_neighbours) {
  std::map<FaceKey, int> sharing;
  if (tetra_neighbours) {
    for (std::size_t e = 0; e < m.tetras.size(); ++e) {
      if (!(*tetra_neighbours)[e]) continue;
      const auto* c = &m.tetras.conn[4 * e];
      for (const auto& f : model::kTetraFaces) {
        std::array<std::int32_t, 4> seg{c[f[0]], c[f[1]], c[f[2]], c[f[2]]};
        const int n = keep_distinct(seg);
        if (n >= 3) ++sharing[distinct_key(seg, n)];
      }
    }
  }
  if (neighbours) {
    for (std::size_t e = 0; e < m.bricks.size(); ++e) {
      if (!(*neighbours)[e]) continue;
      const auto* c = &m.bricks.conn[8 * e];
      std::set<FaceKey> own;
      for (const auto& f : model::kBrickFaces) {
        std::array<std::int32_t, 4> seg{c[f[0]], c[f[1]], c[f[2]], c[f[3]]};
        const int n = keep_distinct(seg);
        if (n >= 3) own.insert(distinct_key(seg, n));
      }
      for (const auto& k : own) ++sharing[k];
    }
  }
  return sharing;
}

}  // namespace

// A tetrahedron face is a triangle segment (n4 = n3); a key in `covered` is a face a shell already gives.
void push_solid_faces(const model::Model& m, model::Surface& s, const std::vector<std::int32_t>& bricks,
                      const std::vector<std::int32_t>& tetras, const std::vector<std::uint8_t>* neighbours,
                      const std::vector<std::uint8_t>* tetra_neighbours, const std::set<FaceKey>& covered) {
  auto sharing = solids_sharing_faces(m, neighbours, tetra_neighbours);
  for (const auto e : bricks) {
    const auto* c = &m.bricks.conn[8 * static_cast<std::size_t>(e)];
    for (const auto& f : model::kBrickFaces) {
      std::array<std::int32_t, 4> seg{c[f[0]], c[f[1]], c[f[2]], c[f[3]]};
      const int n = keep_distinct(seg);
      if (n < 3) continue;
      const auto key = distinct_key(seg, n);
      if (neighbours && sharing[key] > 1) continue;
      if (covered.count(key)) continue;
      push_segment(s, seg, model::SegmentOwner::Brick8, e);
    }
  }
  for (const auto e : tetras) {
    const auto* c = &m.tetras.conn[4 * static_cast<std::size_t>(e)];
    for (const auto& f : model::kTetraFaces) {
      std::array<std::int32_t, 4> seg{c[f[0]], c[f[1]], c[f[2]], c[f[2]]};
      const int n = keep_distinct(seg);
      if (n < 3) continue;
      const auto key = distinct_key(seg, n);
      if (tetra_neighbours && sharing[key] > 1) continue;
      if (covered.count(key)) continue;
      push_segment(s, seg, model::SegmentOwner::Tetra4, e);
    }
  }
}

namespace {

// /SURF/SEG: one segment per record line, owned by the element that has that face (built at the first
// segment whose nodes all exist, kept in `owners` for the surfaces after it).
void surface_from_segments(ModelBuilder& b, const KeywordRecord& r, model::Surface& s,
                           std::optional<FaceOwners>& owners) {
  const auto& t = r.records;
  const int c[4] = {t.column("n1"), t.column("n2"), t.column("n3"), t.column("n4")};
  for (std::size_t k = 0; k < t.size(); ++k) {
    std::array<std::int32_t, 4> seg{};
    bool ok = true;
    for (int j = 0; j < 4; ++j) {
      std::int64_t uid = c[j] >= 0 ? t.ints[c[j]][k] : 0;
      if (j == 3 && uid == 0) uid = c[2] >= 0 ? t.ints[c[2]][k] : 0;
      seg[j] = uid == 0 ? -1 : b.m_.nodes.index.find(uid);
      if (seg[j] < 0) {
        b.diags_.error(
            Diag::MissingReference, b.at(t.pos[k], 11 + 10 * j), ModelBuilder::about(r),
            "segment node n" + std::to_string(j + 1) + " = " + std::to_string(uid) + " does not exist");
        ok = false;
      }
    }
    if (!ok) continue;
    if (!owners) owners = face_owners(b.m_);
    const auto it = owners->find(face_key(seg));
    push_segment(s, seg, it == owners->end() ? model::SegmentOwner::None : it->second.first,
                 it == owners->end() ? kNone : it->second.second);
  }
}

bool part_has_solid(const model::Model& m, std::int32_t part) {
  bool has_solid = false;
  for (std::size_t e = 0; e < m.bricks.size() && !has_solid; ++e) has_solid = m.bricks.part[e] == part;
  for (std::size_t e = 0; e < m.tetras.size() && !has_solid; ++e) has_solid = m.tetras.part[e] == part;
  for (std::size_t e = 0; e < m.bricks20.size() && !has_solid; ++e) has_solid = m.bricks20.part[e] == part;
  return has_solid;
}

// The parts a /SURF/PART list names, in tagging order, with their tags in `tag` (1, or -1 for a flipped
// part); `shells_only` (plain /SURF/PART) refuses solid parts.
std::vector<std::int32_t> tag_surface_parts(ModelBuilder& b, const KeywordRecord& r, bool shells_only,
                                            std::vector<std::int8_t>& tag) {
  // Each part once: the positive ids are tagged first, then the negative ones, and the first tag stays,
  // so a part listed both ways keeps its elements' orientation.
  std::vector<std::int32_t> order;  // tagged parts in tagging order
  for (const bool negatives : {false, true}) {
    for (std::size_t k = 0; k < r.ids.size(); ++k) {
      const bool flip = r.ids[k] < 0;
      if (flip != negatives) continue;
      const std::int64_t id = flip ? -r.ids[k] : r.ids[k];
      const auto it = b.part_ids_.find(id);
      if (it == b.part_ids_.end()) {
        // Radioss leaves it out with a warning (a hierarchy reference).
        b.diags_.warning(Diag::MissingReference, b.at(r.id_pos[k], 1), ModelBuilder::about(r),
                         "part " + std::to_string(id) + " does not exist (no /PART/" + std::to_string(id) +
                             "): it is left out, as Radioss does");
        continue;
      }
      const auto part = it->second;
      // OpenRadioss's surface search takes the faces of 8- and 10-node solids only (ssurftag.F loops over
      // NUMELS8 + NUMELS10): a 20-node brick part would add no segment. Refused by name rather than run
      // with a surface that silently lacks them.
      if (std::any_of(b.m_.bricks20.part.begin(), b.m_.bricks20.part.end(),
                      [part](std::int32_t p) { return p == part; }))
        b.diags_.error(
            Diag::PhysicsNotImplemented, b.at(r.id_pos[k], 1), ModelBuilder::about(r),
            "part " + std::to_string(id) +
                " has 20-node bricks (/BRIC20): surfaces of 20-node bricks are not built (OpenRadioss "
                "gives them no segment either); use the part's nodes as secondary nodes of the "
                "contact, or a /SURF/SEG of its faces' corner nodes");
      if (shells_only && part_has_solid(b.m_, part))
        b.diags_.error(Diag::PartWrongKind, b.at(r.id_pos[k], 1), ModelBuilder::about(r),
                       "part " + std::to_string(id) +
                           " is a solid part: /SURF/PART takes shell parts only; use /SURF/PART/EXT for the "
                           "outer faces of solid parts, or /SURF/PART/ALL for all their faces");
      if (tag[part] == 0) {
        tag[part] = flip ? -1 : 1;
        order.push_back(part);
      }
    }
  }
  return order;
}

// The faces of the solids of the tagged parts, less those a shell of a tagged part covers; `ext` leaves
// out the inner faces too.
void push_part_solid_faces(const model::Model& m, model::Surface& s, const std::vector<std::int8_t>& tag,
                           bool ext) {
  auto listed = [&](std::int32_t part) { return part != kNone && tag[part] != 0; };
  std::set<FaceKey> covered;
  for (std::size_t e = 0; e < m.shells.size(); ++e) {
    if (!listed(m.shells.part[e])) continue;
    const auto* c = &m.shells.conn[4 * e];
    std::array<std::int32_t, 4> f{c[0], c[1], c[2], c[3]};
    // A degenerate 4-node shell covers no triangle face: Radioss looks for 3-node shells there.
    if (keep_distinct(f) == 4) covered.insert(distinct_key(f, 4));
  }
  for (std::size_t e = 0; e < m.shells3.size(); ++e) {
    if (!listed(m.shells3.part[e])) continue;
    const auto* c = &m.shells3.conn[3 * e];
    std::array<std::int32_t, 4> f{c[0], c[1], c[2], c[2]};
    if (keep_distinct(f) == 3) covered.insert(distinct_key(f, 3));
  }
  std::vector<std::uint8_t> chosen(m.bricks.size(), 0);
  std::vector<std::int32_t> bricks;
  for (std::size_t e = 0; e < m.bricks.size(); ++e) {
    if (!listed(m.bricks.part[e])) continue;
    chosen[e] = 1;
    bricks.push_back(static_cast<std::int32_t>(e));
  }
  std::vector<std::uint8_t> chosen_tetras(m.tetras.size(), 0);
  std::vector<std::int32_t> tetras;
  for (std::size_t e = 0; e < m.tetras.size(); ++e) {
    if (!listed(m.tetras.part[e])) continue;
    chosen_tetras[e] = 1;
    tetras.push_back(static_cast<std::int32_t>(e));
  }
  push_solid_faces(m, s, bricks, tetras, ext ? &chosen : nullptr, ext ? &chosen_tetras : nullptr, covered);
}

// /SURF/PART, /SURF/PART/EXT, /SURF/PART/ALL: the shells of the parts listed, then for EXT and ALL the
// faces of their solids.
void surface_from_parts(ModelBuilder& b, const KeywordRecord& r, model::Surface& s, std::string_view path) {
  const bool ext = path == "/SURF/PART/EXT";
  const bool all = path == "/SURF/PART/ALL";
  const auto& m = b.m_;
  std::vector<std::int8_t> tag(m.parts.size(), 0);
  for (const auto part : tag_surface_parts(b, r, !ext && !all, tag)) {
    for (std::size_t e = 0; e < m.shells.size(); ++e)
      if (m.shells.part[e] == part) push_shell(m, s, static_cast<std::int32_t>(e), tag[part] < 0);
    for (std::size_t e = 0; e < m.shells3.size(); ++e)
      if (m.shells3.part[e] == part) push_shell3(m, s, static_cast<std::int32_t>(e), tag[part] < 0);
  }
  if (ext || all) push_part_solid_faces(m, s, tag, ext);
}

// /SURF/GRSHEL, /SURF/GRSH3N: one segment per element of the groups listed.
void surface_from_shell_groups(ModelBuilder& b, const KeywordRecord& r, model::Surface& s,
                               model::ElementType type) {
  const auto& fam = family(type);
  // As for parts: positive ids tagged first, the first tag stays, a negative tag flips the segment.
  std::vector<std::int8_t> tag(b.block(type).size(), 0);
  std::vector<std::int32_t> order;
  for (const bool negatives : {false, true}) {
    for (std::size_t k = 0; k < r.ids.size(); ++k) {
      const bool flip = r.ids[k] < 0;
      if (flip != negatives) continue;
      const std::int64_t id = flip ? -r.ids[k] : r.ids[k];
      const auto* g = b.element_group(type, id);
      if (!g) {
        // Radioss's warning 192: the group is left out (the surface may end up empty: a warning too).
        b.diags_.warning(Diag::MissingReference, b.at(r.id_pos[k], 1), ModelBuilder::about(r),
                         std::string(fam.element) + " group " + std::to_string(id) + " does not exist (no " +
                             std::string(fam.root) + "/.../" + std::to_string(id) +
                             "): it is left out, as Radioss does");
        continue;
      }
      for (const auto e : g->elements) {
        if (tag[e] != 0) continue;
        tag[e] = flip ? -1 : 1;
        order.push_back(e);
      }
    }
  }
  for (const auto e : order) {
    if (type == model::ElementType::Shell4)
      push_shell(b.m_, s, e, tag[e] < 0);
    else
      push_shell3(b.m_, s, e, tag[e] < 0);
  }
}

// /SURF/GRBRIC/EXT, /SURF/GRBRIC/FREE (`free`): the outer faces of the bricks of the groups listed.
void surface_from_brick_groups(ModelBuilder& b, const KeywordRecord& r, model::Surface& s, bool free) {
  // Brick faces keep their outward orientation: a negative group id counts as a positive one. A group's
  // tetrahedra give their faces as the bricks do.
  std::vector<std::uint8_t> chosen(b.m_.bricks.size(), 0), chosen_tetras(b.m_.tetras.size(), 0);
  std::vector<std::int32_t> bricks, tetras;
  for (std::size_t k = 0; k < r.ids.size(); ++k) {
    const std::int64_t id = r.ids[k] < 0 ? -r.ids[k] : r.ids[k];
    const auto* g = b.element_group(model::ElementType::Brick8, id);
    if (!g) {
      b.diags_.warning(Diag::MissingReference, b.at(r.id_pos[k], 1), ModelBuilder::about(r),
                       "brick group " + std::to_string(id) + " does not exist (no /GRBRIC/.../" +
                           std::to_string(id) + "): it is left out, as Radioss does");
      continue;
    }
    bool quadratic = false;
    for (const auto e : g->elements) {
      const auto ge = b.group_element(model::ElementType::Brick8, e);
      if (ge.block == &b.m_.bricks20) {
        quadratic = true;  // no faces of 20-node bricks, as in OpenRadioss (ssurftag.F): refused below
        continue;
      }
      const bool tetra = ge.block == &b.m_.tetras;
      auto& mark = tetra ? chosen_tetras : chosen;
      if (mark[ge.index]) continue;
      mark[ge.index] = 1;
      (tetra ? tetras : bricks).push_back(ge.index);
    }
    if (quadratic)
      b.diags_.error(
          Diag::PhysicsNotImplemented, b.at(r.id_pos[k], 1), ModelBuilder::about(r),
          "brick group " + std::to_string(id) +
              " holds 20-node bricks (/BRIC20): surfaces of 20-node bricks are not built (OpenRadioss "
              "gives them no segment either); leave them out of the group");
  }
  // EXT: a face is inner when another solid of the groups has it; FREE: when any solid of the model has
  // it.
  const std::vector<std::uint8_t> every(free ? b.m_.bricks.size() : 0, 1);
  const std::vector<std::uint8_t> every_tetra(free ? b.m_.tetras.size() : 0, 1);
  push_solid_faces(b.m_, s, bricks, tetras, free ? &every : &chosen, free ? &every_tetra : &chosen_tetras,
                   {});
}

}  // namespace

void ModelBuilder::build_surfaces() {
  std::unordered_map<std::int64_t, SourcePos> first;
  // Face lookup for /SURF/SEG owners, built only when needed.
  std::optional<FaceOwners> owners;
  for (const auto& r : deck_.records) {
    const auto path = r.decl->path;
    if (path.rfind("/SURF/", 0) != 0) continue;
    const std::size_t errors_before = diags_.error_count();
    model::Surface s;
    s.id = r.id;
    s.title = r.title;
    s.kind = std::string(path.substr(6));
    if (path == "/SURF/SEG") {
      surface_from_segments(*this, r, s, owners);
    } else if (path == "/SURF/PART" || path == "/SURF/PART/EXT" || path == "/SURF/PART/ALL") {
      surface_from_parts(*this, r, s, path);
    } else if (path == "/SURF/GRSHEL" || path == "/SURF/GRSH3N") {
      surface_from_shell_groups(
          *this, r, s, path == "/SURF/GRSHEL" ? model::ElementType::Shell4 : model::ElementType::Shell3);
    } else if (path == "/SURF/GRBRIC/EXT" || path == "/SURF/GRBRIC/FREE") {
      surface_from_brick_groups(*this, r, s, path == "/SURF/GRBRIC/FREE");
    } else if (path == "/SURF/GRBRIC") {
      diags_.error(Diag::PartWrongKind, at(r.pos, 1), about(r),
                   "a brick group makes a surface only as /SURF/GRBRIC/EXT (the faces no other brick of the "
                   "groups shares) or /SURF/GRBRIC/FREE (the faces no other brick of the model shares); "
                   "Radioss refuses /SURF/GRBRIC alone too");
    }
    if (s.segments.empty() && diags_.error_count() == errors_before) {
      // Radioss warns and goes on: what uses the surface finds no segment on it.
      diags_.warning(
          Diag::EmptyGroup, at(r.pos, 1), about(r),
          "surface " + std::to_string(s.id) +
              " holds no segment: whatever uses it finds nothing on it, as in Radioss; check its list");
    }
    if (register_id(surf_ids_, s.id, static_cast<std::int32_t>(m_.surfaces.size()), r, "surface", first))
      m_.surfaces.push_back(std::move(s));
  }
}

}  // namespace detail
}  // namespace radx
