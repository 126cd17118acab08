// Deck -> Model: /INTER/TYPE2, the kinematic tied interface. The options are those of OpenRadioss's reader
// (hm_read_inter_type02.F); the projection of each secondary node on its nearest main segment, once, is
// that of the starter's i2buc1.F / i2tid3.F (solver/model/tied_map.hpp for the map itself):
//   - the search distance is Dsearch, or when 0 the root mean square of the main segments' edge lengths
//     (i2buc1.F with Ignore < 2);
//   - a node whose nearest segment is farther than that is an error with Ignore = 0 (message 1078) and is
//     left out of the interface with a warning with Ignore >= 1 (1157); both list the nodes;
//   - a segment holding the secondary node itself is skipped.
// radx runs Spotflag 0 and 5 (5 is 0, hm_read_inter_type02.F) and 1 (the rigid tie,
// solver/conditions/tied_type2.hpp; the standard tie in a model without rotational degrees of freedom, as in
// OpenRadioss); the other formulations are refused by name. Kinematic conflicts: OpenRadioss only warns
// (kinset.F, message 147) and the outcome then depends on the order its engine applies the conditions in.
// radx refuses what it cannot run consistently: a node tied by two TYPE2 (its mass would be given away
// twice), a tied node in a rigid body, and a tie whose main segment holds another TYPE2's secondary node (the
// result would depend on the order of the ties). A /BCS on a tied node is a warning, as in OpenRadioss: the
// tie moves the node and the /BCS has no effect.
#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <sstream>

#include "parser/building/model_builder.hpp"
#include "parser/reading/field_parse.hpp"
#include "solver/model/tied_map.hpp"

namespace radx {
namespace detail {

using model::kNone;

namespace {

std::string id_list(const std::vector<std::int64_t>& ids) {
  std::ostringstream o;
  const std::size_t shown = std::min<std::size_t>(ids.size(), 20);
  for (std::size_t k = 0; k < shown; ++k) o << (k ? " " : "") << ids[k];
  if (ids.size() > shown) o << " ... (" << ids.size() << " in all)";
  return o.str();
}

std::string_view spotflag_name(int f) {
  switch (f) {
    case 2: return "the formulation with the segment's rotations transmitted by moments (I2MOM3)";
    case 3: return "the rigid formulation of Spotflag 1 with its own mass update";
    case 4: return "the formulation without rotational degrees of freedom";
    case 10:
    case 11:
    case 12: return "the spot-weld formulation";
    case 20:
    case 21:
    case 22: return "the spot-weld formulation with rupture";
    case 25:
    case 26: return "the penalty formulation";
    case 27:
    case 28: return "the kinematic formulation that switches to penalty";
    case 30: return "the formulation with a cubic main segment";
    default: return "an unknown formulation";
  }
}

// The interface of one /INTER/TYPE2 record, its options read as OpenRadioss reads them (Ignore and Idel2
// 1000 are 0, Spotflag 5 is 0).
model::TiedInterface read_tied_interface(ModelBuilder& b, const KeywordRecord& r) {
  model::TiedInterface in;
  in.id = r.id;
  in.title = r.title;
  in.secondary_group = b.ref(b.grnod_ids_, r, "grnd_IDs", "node group", "/GRNOD", false);
  in.main_surface = b.ref(b.surf_ids_, r, "surf_IDm", "surface", "/SURF", false);
  in.ignore = static_cast<int>(r.get_int("Ignore"));
  if (in.ignore == 1000) in.ignore = 0;
  in.spotflag = static_cast<int>(r.get_int("Spotflag"));
  if (in.spotflag == 5) in.spotflag = 0;
  in.level = static_cast<int>(r.get_int("Level"));
  in.isearch = static_cast<int>(r.get_int("Isearch"));
  in.idel2 = static_cast<int>(r.get_int("Idel2"));
  if (in.idel2 == 1000) in.idel2 = 0;
  in.dsearch = r.get_real("Dsearch");
  return in;
}

// Whether radx runs the interface's options, with an error for each one it does not; false also for an
// interface id that an /INTER/TYPE7 already has.
bool tied_options_run(ModelBuilder& b, const KeywordRecord& r, const model::TiedInterface& in) {
  bool ok = true;
  // A value outside OpenRadioss's list is RX501 from the declaration already.
  static constexpr int kKnown[] = {1, 2, 3, 4, 10, 11, 12, 20, 21, 22, 25, 26, 27, 28, 30};
  if (in.spotflag != 0 && std::find(std::begin(kKnown), std::end(kKnown), in.spotflag) == std::end(kKnown)) {
    ok = false;
  } else if (in.spotflag != 0 && in.spotflag != 1) {
    b.error_at(r, "Spotflag", Diag::PhysicsNotImplemented,
               "Spotflag = " + std::to_string(in.spotflag) + " (" + std::string(spotflag_name(in.spotflag)) +
                   ") is not implemented in radx; radx runs Spotflag 0 or 5 (the standard kinematic tie) and "
                   "1 (the rigid "
                   "tie)");
    ok = false;
  }
  if (in.idel2 != 0) {
    b.error_at(r, "Idel2", Diag::PhysicsNotImplemented,
               "Idel2 = " + std::to_string(in.idel2) +
                   " (release the tie when the main elements are deleted) is not implemented in radx; "
                   "accepted: 0 or 1000 (the tie is kept)");
    ok = false;
  }
  if ((in.ignore == 2 || in.ignore == 3) && in.dsearch == 0) {
    b.error_at(r, "Dsearch", Diag::PhysicsNotImplemented,
               "Ignore = " + std::to_string(in.ignore) +
                   " with Dsearch = 0 asks for the search distance from the parts' thicknesses, which radx "
                   "does not compute; give Dsearch > 0, or Ignore = 0 or 1 (distance from the segment size)");
    ok = false;
  }
  // Interface ids are shared with TYPE7 (its index, inter_ids_, names TYPE7 records only).
  if (b.inter_ids_.count(in.id) != 0) {
    b.diags_.error(Diag::DuplicateId, b.at(r.pos, 1), ModelBuilder::about(r),
                   "interface id " + std::to_string(in.id) +
                       " is already used by an /INTER/TYPE7; interface ids must be unique");
    ok = false;
  }
  return ok;
}

model::Vec3 node_position(const model::Model& m, std::int32_t n) {
  const auto k = static_cast<std::size_t>(n);
  return model::Vec3{m.nodes.x[k], m.nodes.y[k], m.nodes.z[k]};
}

// The bounding box of each segment (x, y, z minima, then maxima), and in `sum2` the sum of the squared
// lengths of their edges.
std::vector<std::array<double, 6>> segment_boxes(const model::Model& m,
                                                 const std::vector<std::array<std::int32_t, 4>>& segs,
                                                 double& sum2) {
  std::vector<std::array<double, 6>> box(segs.size());
  for (std::size_t k = 0; k < segs.size(); ++k) {
    const auto& sg = segs[k];
    for (int e = 0; e < 4; ++e) {
      const auto a = node_position(m, sg[static_cast<std::size_t>(e)]),
                 b = node_position(m, sg[static_cast<std::size_t>((e + 1) % 4)]);
      const auto d = model::sub(a, b);
      sum2 += model::dot(d, d);
    }
    auto& bx = box[k];
    bx = {1e300, 1e300, 1e300, -1e300, -1e300, -1e300};
    for (int e = 0; e < 4; ++e) {
      const auto p = node_position(m, sg[static_cast<std::size_t>(e)]);
      for (std::size_t c = 0; c < 3; ++c) {
        bx[c] = std::min(bx[c], p[c]);
        bx[c + 3] = std::max(bx[c + 3], p[c]);
      }
    }
  }
  return box;
}

// Each node of `group` tied to its nearest segment within the search distance (a segment that holds the node
// skipped), or listed in in.not_found.
void tie_to_nearest_segments(const model::Model& m, model::TiedInterface& in,
                             const std::vector<std::array<std::int32_t, 4>>& segs,
                             const std::vector<std::array<double, 6>>& box,
                             const std::vector<std::int32_t>& group) {
  const double dist = in.search_distance;
  for (const auto n : group) {
    const auto p = node_position(m, n);
    double best = std::numeric_limits<double>::infinity();
    std::size_t best_k = segs.size();
    model::SegmentProjection best_proj;
    for (std::size_t k = 0; k < segs.size(); ++k) {
      const auto& bx = box[k];
      bool near = true;
      for (std::size_t c = 0; c < 3 && near; ++c) near = p[c] >= bx[c] - dist && p[c] <= bx[c + 3] + dist;
      if (!near) continue;
      const auto& sg = segs[k];
      if (std::find(sg.begin(), sg.end(), n) != sg.end()) continue;
      const std::array<model::Vec3, 4> xs{node_position(m, sg[0]), node_position(m, sg[1]),
                                          node_position(m, sg[2]), node_position(m, sg[3])};
      const auto proj = model::project_on_segment(xs, model::is_triangle(sg), p);
      if (proj.distance < best) {  // strict: the first of equally near segments wins
        best = proj.distance;
        best_k = k;
        best_proj = proj;
      }
    }
    if (best_k == segs.size() || best > dist) {
      in.not_found.push_back(m.nodes.id[static_cast<std::size_t>(n)]);
      continue;
    }
    in.tie_node.push_back(n);
    in.tie_segment.push_back(segs[best_k]);
    in.tie_r.push_back(best_proj.r);
    in.tie_s.push_back(best_proj.s);
    in.tie_offset.push_back(best_proj.offset);
  }
}

// The secondary nodes that found no segment: an error with Ignore = 0, else a warning.
void report_untied_nodes(ModelBuilder& b, const KeywordRecord& r, const model::TiedInterface& in) {
  if (in.not_found.empty()) return;
  const std::string what = std::to_string(in.not_found.size()) +
                           " secondary node(s) find no main segment within the search distance " +
                           number_text(in.search_distance) +
                           (in.dsearch > 0 ? " (Dsearch)" : " (automatic)") + ": " + id_list(in.not_found);
  if (in.ignore == 0)
    b.error_at(r, "grnd_IDs", Diag::TiedNodeWithoutSegment,
               what + "; move them onto the surface, raise Dsearch, or set Ignore = 1 to leave them untied");
  else
    b.warning_at(r, "grnd_IDs", Diag::TiedNodeWithoutSegment,
                 what + "; they are left out of the interface (Ignore = " + std::to_string(in.ignore) + ")");
}

// The projection of the interface's secondary nodes on its main segments, once, on the starting geometry.
void project_tied_nodes(ModelBuilder& b, const KeywordRecord& r, model::TiedInterface& in) {
  const auto& m = b.m_;
  const auto& segs = m.surfaces[static_cast<std::size_t>(in.main_surface)].segments;
  const auto* group = b.group_nodes(in.secondary_group);
  if (!group || segs.empty()) {
    b.error_at(r, segs.empty() ? "surf_IDm" : "grnd_IDs", Diag::EmptyGroup,
               segs.empty() ? "the main surface has no segment: there is nothing to tie the nodes to"
                            : "the secondary node group is empty or could not be built");
    return;
  }
  // A segment naming a node that does not exist has already been reported where the surface was read; the
  // starter goes on to collect further errors, so this interface is not projected.
  const auto n_nodes = static_cast<std::int64_t>(m.nodes.x.size());
  const bool nodes_known = std::all_of(segs.begin(), segs.end(), [&](const auto& sg) {
    return std::all_of(sg.begin(), sg.end(), [&](std::int32_t n) { return n >= 0 && n < n_nodes; });
  });
  if (!nodes_known) return;
  // Automatic distance: sqrt of the mean squared edge length (i2buc1.F, Ignore < 2).
  double sum2 = 0;
  const auto box = segment_boxes(m, segs, sum2);
  in.search_distance =
      in.dsearch > 0 ? in.dsearch : std::sqrt(sum2 / (4.0 * static_cast<double>(segs.size())));
  tie_to_nearest_segments(m, in, segs, box, *group);
  report_untied_nodes(b, r, in);
}

// A node tied by two interfaces is an error, on the later one; returns the interface that ties each node
// first.
std::map<std::int32_t, std::size_t> check_nodes_tied_twice(ModelBuilder& b,
                                                           const std::vector<const KeywordRecord*>& records) {
  const auto& ties = b.m_.tied_interfaces;
  std::map<std::int32_t, std::size_t> tied_by;  // secondary node -> interface
  for (std::size_t t = 0; t < ties.size(); ++t) {
    std::vector<std::int64_t> twice;
    std::int64_t other = 0;
    for (const auto n : ties[t].tie_node) {
      const auto [it, fresh] = tied_by.emplace(n, t);
      if (!fresh) {
        twice.push_back(b.m_.nodes.id[static_cast<std::size_t>(n)]);
        other = ties[it->second].id;
      }
    }
    if (!twice.empty())
      b.error_at(*records[t], "grnd_IDs", Diag::KinematicConflict,
                 std::to_string(twice.size()) + " secondary node(s) are already tied by /INTER/TYPE2/" +
                     std::to_string(other) + ": " + id_list(twice) +
                     "; a node can be tied by one TYPE2 only: remove it from one of the two groups");
  }
  return tied_by;
}

// A main segment holding a node that a tie moves as secondary is an error (ties are not chained).
void check_chained_ties(ModelBuilder& b, const std::vector<const KeywordRecord*>& records,
                        const std::map<std::int32_t, std::size_t>& tied_by) {
  const auto& ties = b.m_.tied_interfaces;
  for (std::size_t t = 0; t < ties.size(); ++t) {
    std::vector<std::int64_t> chained;
    std::int64_t other = 0;
    for (const auto& sg : ties[t].tie_segment)
      for (const auto n : sg) {
        const auto it = tied_by.find(n);
        if (it == tied_by.end()) continue;
        const auto id = b.m_.nodes.id[static_cast<std::size_t>(n)];
        if (std::find(chained.begin(), chained.end(), id) == chained.end()) chained.push_back(id);
        other = ties[it->second].id;
      }
    if (!chained.empty())
      b.error_at(*records[t], "surf_IDm", Diag::KinematicConflict,
                 "the main segments hold node(s) that /INTER/TYPE2/" + std::to_string(other) +
                     " ties as secondary: " + id_list(chained) +
                     "; radx does not chain ties (OpenRadioss orders them by Level): tie those nodes to the "
                     "first surface directly");
  }
}

// A tied secondary node in a rigid body is an error.
void check_tied_rigid_body_nodes(ModelBuilder& b, const std::vector<const KeywordRecord*>& records,
                                 const std::map<std::int32_t, std::size_t>& tied_by) {
  for (const auto& rb : b.m_.rigid_bodies) {
    std::vector<std::int64_t> both;
    std::size_t t_of = 0;
    auto check = [&](std::int32_t n) {
      const auto it = tied_by.find(n);
      if (it == tied_by.end()) return;
      both.push_back(b.m_.nodes.id[static_cast<std::size_t>(n)]);
      t_of = it->second;
    };
    if (rb.main_node != kNone) check(rb.main_node);
    for (const auto n : rb.secondary) check(n);
    if (!both.empty())
      b.error_at(*records[t_of], "grnd_IDs", Diag::KinematicConflict,
                 std::to_string(both.size()) + " tied secondary node(s) are also in /RBODY/" +
                     std::to_string(rb.id) + ": " + id_list(both) +
                     "; a node follows either the rigid body or the tie: remove it from one of them");
  }
}

// A /BCS on a tied secondary node is a warning: the tie moves the node.
void warn_tied_bcs_nodes(ModelBuilder& b, const std::vector<const KeywordRecord*>& records,
                         const std::map<std::int32_t, std::size_t>& tied_by) {
  for (const auto& bc : b.m_.bcs) {
    const auto* nodes = bc.group != kNone ? b.group_nodes(bc.group) : nullptr;
    if (!nodes) continue;
    std::vector<std::int64_t> both;
    std::size_t t_of = 0;
    for (const auto n : *nodes) {
      const auto it = tied_by.find(n);
      if (it == tied_by.end()) continue;
      both.push_back(b.m_.nodes.id[static_cast<std::size_t>(n)]);
      t_of = it->second;
    }
    if (!both.empty())
      b.warning_at(
          *records[t_of], "grnd_IDs", Diag::KinematicConflict,
          std::to_string(both.size()) + " tied secondary node(s) are also under /BCS/" +
              std::to_string(bc.id) + ": " + id_list(both) +
              "; the tie moves them and the /BCS has no effect on them (OpenRadioss warns of the same "
              "incompatible kinematic conditions)");
  }
}

}  // namespace

void ModelBuilder::build_tied_interfaces() {
  std::unordered_map<std::int64_t, SourcePos> first;
  IdIndex ids;
  std::vector<const KeywordRecord*> records;
  for (const auto* rp : deck_.of("/INTER/TYPE2")) {
    const auto& r = *rp;
    model::TiedInterface in = read_tied_interface(*this, r);
    const bool ok = tied_options_run(*this, r, in);
    if (register_id(ids, in.id, static_cast<std::int32_t>(m_.tied_interfaces.size()), r, "interface",
                    first) &&
        ok && in.secondary_group != kNone && in.main_surface != kNone) {
      records.push_back(&r);
      m_.tied_interfaces.push_back(std::move(in));
    }
  }
  for (std::size_t t = 0; t < m_.tied_interfaces.size(); ++t)
    project_tied_nodes(*this, *records[t], m_.tied_interfaces[t]);
  // Kinematic conflicts between ties, rigid bodies and /BCS.
  const auto tied_by = check_nodes_tied_twice(*this, records);
  check_chained_ties(*this, records, tied_by);
  check_tied_rigid_body_nodes(*this, records, tied_by);
  warn_tied_bcs_nodes(*this, records, tied_by);
}

}  // namespace detail
}  // namespace radx
