// Deck -> Model: section cuts (/SECT), as the OpenRadioss starter defines them (hm_read_sect.F):
// * the cut is the node group grnod_ID; the elements of grbric_ID, grshel_ID and grtria_ID that have at least
//   one node in it are kept (the others add nothing), and the engine sums the forces those elements apply to
//   the cut's nodes;
// * N1 N2 N3 define the frame (model::Section). Radioss refuses N1 = N2 and three aligned nodes (its message
//   508); radx does too. N1 = 0 is accepted only with Iframe >= 10 (global axes, normal Z), where no node is
//   needed;
// * what radx does not do is refused by name: a moving frame (Frame_ID), contact forces added to the cut
//   (Ninter), cut files (I_SAVE: writing them is an output radx does not write, reading them changes the
//   results), and truss, beam and spring groups (radx has none of those elements).
#include <algorithm>
#include <cmath>
#include <string>

#include "parser/building/model_builder.hpp"

namespace radx {
namespace detail {

using model::kNone;

namespace {

using Vec = std::array<double, 3>;

Vec node_point(const model::Nodes& n, std::int32_t i) {
  const auto k = static_cast<std::size_t>(i);
  return {n.x[k], n.y[k], n.z[k]};
}

// The elements of `elements` with at least one node in the sorted list `nodes`.
std::vector<std::int32_t> touching(const model::ElementBlock& block,
                                   const std::vector<std::int32_t>& elements,
                                   const std::vector<std::int32_t>& nodes) {
  std::vector<std::int32_t> out;
  const auto npe = static_cast<std::size_t>(block.npe());
  // A beam's orientation node carries no force: only its two end nodes can be on the cut.
  const std::size_t force_nodes = block.type == model::ElementType::Beam2 ? 2 : npe;
  for (const auto e : elements) {
    const auto* c = &block.conn[static_cast<std::size_t>(e) * npe];
    if (std::any_of(c, c + force_nodes,
                    [&](std::int32_t n) { return std::binary_search(nodes.begin(), nodes.end(), n); }))
      out.push_back(e);
  }
  return out;
}

// A frame node (node_ID1..3): kNone when blank (reported by the caller when it is needed).
std::int32_t frame_node(ModelBuilder& b, const KeywordRecord& r, std::string_view field) {
  const std::int64_t id = r.get_int(field);
  if (id == 0) return kNone;
  const FieldValue* f = r.find(field);
  const auto n = b.node_ref(id, r, f ? f->pos : r.pos, std::string(field) + " (section frame node)");
  if (n != kNone) b.node_used_[static_cast<std::size_t>(n)] = 1;
  return n;
}

// The frame nodes N1 N2 N3: all three given, or none with Iframe >= 10; given, they must span a plane.
void check_section_frame(ModelBuilder& b, const KeywordRecord& r, const model::Section& s) {
  const bool none = r.get_int("node_ID1") == 0 && r.get_int("node_ID2") == 0 && r.get_int("node_ID3") == 0;
  const bool all = r.get_int("node_ID1") != 0 && r.get_int("node_ID2") != 0 && r.get_int("node_ID3") != 0;
  if (!all && !(none && s.iframe >= 10)) {
    b.error_at(r, "node_ID1", Diag::RequiredIdMissing,
               "node_ID1, node_ID2 and node_ID3 define the section frame and plane: give all three (with "
               "Iframe >= 10 all three may be 0: global axes, section normal Z)");
  } else if (all && s.n1 != kNone && s.n2 != kNone && s.n3 != kNone) {
    const auto& nodes = b.m_.nodes;
    const Vec p1 = node_point(nodes, s.n1), p2 = node_point(nodes, s.n2), p3 = node_point(nodes, s.n3);
    const Vec a{p2[0] - p1[0], p2[1] - p1[1], p2[2] - p1[2]}, c{p3[0] - p1[0], p3[1] - p1[1], p3[2] - p1[2]};
    const Vec n{a[1] * c[2] - a[2] * c[1], a[2] * c[0] - a[0] * c[2], a[0] * c[1] - a[1] * c[0]};
    const double la = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    const double lc = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    const double ln = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    // sin of the angle N2-N1-N3 below 1e-5: the plane, hence the normal, is undefined.
    if (la <= 0 || lc <= 0 || ln < 1e-5 * la * lc)
      b.error_at(r, "node_ID1", Diag::InconsistentValues,
                 "nodes " + std::to_string(r.get_int("node_ID1")) + ", " +
                     std::to_string(r.get_int("node_ID2")) + " and " + std::to_string(r.get_int("node_ID3")) +
                     " coincide or are aligned: the section plane and its normal are undefined; N3 must lie "
                     "in the section plane, off the line N1 N2");
  }
}

// What radx does not do, refused by name: a moving frame, contact forces, cut files, truss, beam and spring
// groups.
void refuse_section_options(ModelBuilder& b, const KeywordRecord& r) {
  if (const auto frame = r.get_int("Frame_ID"); frame != 0)
    b.error_at(r, "Frame_ID", Diag::PhysicsNotImplemented,
               "Frame_ID = " + std::to_string(frame) +
                   ": a section carried by a moving frame (/FRAME) is not implemented; leave it 0 to use the "
                   "frame of node_ID1, node_ID2, node_ID3");
  if (const auto ninter = r.get_int("Ninter"); ninter != 0)
    b.error_at(r, "Ninter", Diag::PhysicsNotImplemented,
               "Ninter = " + std::to_string(ninter) +
                   ": adding interface contact forces to a section is not implemented; leave it 0 (the "
                   "section then sums element forces only)");
  if (const auto isave = r.get_int("I_SAVE"); isave == 1 || isave == 2)
    b.warning_at(r, "I_SAVE", Diag::OutputNotWritten,
                 "I_SAVE = " + std::to_string(isave) +
                     ": radx does not write section cut files; the section "
                     "forces are in the time history (/TH/SECTIO)");
  else if (isave >= 100)
    b.error_at(r, "I_SAVE", Diag::PhysicsNotImplemented,
               "I_SAVE = " + std::to_string(isave) +
                   ": reading a section cut file as input is not implemented; accepted: 0, or 1 and 2 (cut "
                   "file not written)");
  // Springs run, but a section sums the forces of bricks, shells, trusses and beams only: the section's
  // forces would leave theirs out.
  if (const auto g = r.get_int("grsprg_ID"); g != 0)
    b.error_at(r, "grsprg_ID", Diag::PhysicsNotImplemented,
               "grsprg_ID = " + std::to_string(g) +
                   ": radx sums the forces of bricks, shells, trusses and beams in a section, not those of "
                   "springs; leave it 0");
}

// The cut's node group grnod_ID and its nodes, which must not be empty.
void read_section_nodes(ModelBuilder& b, const KeywordRecord& r, model::Section& s) {
  s.node_group = b.ref(b.grnod_ids_, r, "grnod_ID", "node group", "/GRNOD", false);
  if (s.node_group == kNone) return;
  if (const auto* nodes = b.group_nodes(s.node_group)) s.nodes = *nodes;
  if (s.nodes.empty())
    b.error_at(r, "grnod_ID", Diag::EmptyGroup,
               "node group " + std::to_string(r.get_int("grnod_ID")) +
                   " is empty: the section has no node to sum the element forces at");
}

// The elements of the groups grbric_ID, grshel_ID, grtria_ID, grtrus_ID and grbeam_ID that touch the cut's
// nodes; at least one group is needed, and together they must touch the cut.
void read_section_elements(ModelBuilder& b, const KeywordRecord& r, model::Section& s) {
  bool any_group = false, group_missing = false;
  auto elements = [&](std::string_view field, model::ElementType type, std::string_view keyword,
                      std::vector<std::int32_t>& out) {
    const auto id = r.get_int(field);
    if (id == 0) return;
    any_group = true;
    const auto* g = b.element_group(type, id);
    if (g == nullptr) {
      group_missing = true;
      b.error_at(r, field, Diag::MissingReference,
                 std::string(field) + " = " + std::to_string(id) + ": there is no " + std::string(keyword) +
                     "/.../" + std::to_string(id) + " in the deck");
      return;
    }
    if (type != model::ElementType::Brick8) {
      out = touching(b.block(type), g->elements, s.nodes);
      return;
    }
    // A brick group may hold tetrahedra and 20-node bricks (past the bricks): radx sums neither's force in a
    // section.
    std::vector<std::int32_t> bricks, tetras, quadratic;
    for (const auto e : g->elements) {
      const auto ge = b.group_element(type, e);
      (ge.block == &b.m_.tetras     ? tetras
       : ge.block == &b.m_.bricks20 ? quadratic
                                    : bricks)
          .push_back(ge.index);
    }
    out = touching(b.block(type), bricks, s.nodes);
    if (const auto q = touching(b.m_.bricks20, quadratic, s.nodes); !q.empty())
      b.error_at(r, field, Diag::PhysicsNotImplemented,
                 std::string(field) + " = " + std::to_string(id) + ": " + std::to_string(q.size()) +
                     " 20-node bricks of the group touch the cut, and radx sums no 20-node brick force in a "
                     "section (bricks, shells, trusses and beams only); leave them out of the group");
    if (const auto t = touching(b.m_.tetras, tetras, s.nodes); !t.empty())
      b.error_at(
          r, field, Diag::PhysicsNotImplemented,
          std::string(field) + " = " + std::to_string(id) + ": " + std::to_string(t.size()) +
              " tetrahedra of the group touch the cut, and radx sums no tetrahedron force in a section "
              "(bricks, shells, trusses and beams only); leave them out of the group");
  };
  elements("grbric_ID", model::ElementType::Brick8, "/GRBRIC", s.bricks);
  elements("grshel_ID", model::ElementType::Shell4, "/GRSHEL", s.shells);
  elements("grtria_ID", model::ElementType::Shell3, "/GRSH3N", s.shells3);
  elements("grtrus_ID", model::ElementType::Truss2, "/GRTRUS", s.trusses);
  elements("grbeam_ID", model::ElementType::Beam2, "/GRBEAM", s.beams);
  if (!any_group)
    b.error_at(r, "grshel_ID", Diag::RequiredIdMissing,
               "no element group: give grbric_ID, grshel_ID, grtria_ID, grtrus_ID or grbeam_ID, the elements "
               "whose forces on the section's nodes are summed");
  else if (!group_missing && !s.nodes.empty() && s.bricks.empty() && s.shells.empty() && s.shells3.empty() &&
           s.trusses.empty() && s.beams.empty())
    b.error_at(
        r, "grshel_ID", Diag::EmptyGroup,
        "no element of the groups has a node in grnod_ID " + std::to_string(r.get_int("grnod_ID")) +
            ": the section would sum nothing; the groups must hold the elements on one side of the cut");
}

}  // namespace

void ModelBuilder::build_sections() {
  std::unordered_map<std::int64_t, SourcePos> first;
  for (const auto* rp : deck_.of("/SECT")) {
    const auto& r = *rp;
    model::Section s;
    s.id = r.id;
    s.title = r.title;
    s.iframe = static_cast<int>(r.get_int("Iframe"));
    s.n1 = frame_node(*this, r, "node_ID1");
    s.n2 = frame_node(*this, r, "node_ID2");
    s.n3 = frame_node(*this, r, "node_ID3");
    check_section_frame(*this, r, s);
    refuse_section_options(*this, r);
    read_section_nodes(*this, r, s);
    read_section_elements(*this, r, s);
    if (register_id(sect_ids_, s.id, static_cast<std::int32_t>(m_.sections.size()), r, "section", first))
      m_.sections.push_back(std::move(s));
  }
}

}  // namespace detail
}  // namespace radx
