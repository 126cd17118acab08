// Deck -> Model: /SKEW/FIX and /SKEW/MOV, the frames that /BCS, /IMPVEL, /IMPDISP, /INIVEL, /CLOAD, /GRAV,
// /ACCEL and /TH/NODE may name, and /FRAME/FIX and /FRAME/MOV, which only /TH/NODE reads among the keywords
// radx runs (docs/theory/frames.md). The four keywords share one id space, as in Radioss (its starter checks
// skew and frame ids together for duplicates).
//
// /SKEW/FIX: Y' = (X1, Y1, Z1), Z' = (X2, Y2, Z2) as given (a direction with only a Y (resp. Z) component is
//   taken as its sign, as Radioss does), x' = Y' x Z', y' = Z' x x', z' = Z'; each normalised. x' = 0 (Y'
//   and Z' parallel, or one of them zero) leaves no frame: an error naming the skew.
// /SKEW/MOV: nodes N1 N2 N3 and Dir (blank = X; the field exists from the 2019 layout, older decks are
//   Dir X): origin N1, the Dir axis along N1 -> N2, N3 in the plane of the Dir axis and the next one
//   (model::node_skew_axes). The three nodes must exist and be distinct, N2 must not sit on N1, and N3 must
//   not lie on the line N1 N2 at t = 0: the sine of the angle between N1N2 and N1N3 must exceed 1e-5.
//   Radioss only warns about the last (message 163) and bends N1N3 off the line; radx refuses the deck.
// /FRAME/FIX, /FRAME/MOV: the same cards and the same axes (OpenRadioss hm_read_frm.F), with one difference:
//   a frame's Y' or Z' direction is used as given, with no "only a Y component means its sign" rule, so a
//   zero direction leaves no frame (Radioss would keep zero axes) and is the same error as for a skew.
#include <cctype>
#include <cmath>
#include <string>

#include "parser/building/model_builder.hpp"
#include "parser/reading/field_parse.hpp"
#include "solver/model/geometry.hpp"

namespace radx::detail {

namespace {

using V3 = model::Vec3;
using model::cross;
using model::norm;

// Smallest sine of the angle between N1N2 and N1N3 that /SKEW/MOV accepts at t = 0.
constexpr double kMinSine = 1e-5;

std::string direction_text(const V3& a) {
  return "(" + number_text(a[0]) + ", " + number_text(a[1]) + ", " + number_text(a[2]) + ")";
}

V3 position(const model::Nodes& n, std::int32_t k) {
  return {n.x[k], n.y[k], n.z[k]};
}

bool fixed_skew(ModelBuilder& b, const KeywordRecord& r, model::Skew& s) {
  s.origin = b.submodel_point(r, {r.get_real("Ox"), r.get_real("Oy"), r.get_real("Oz")});
  V3 y = {r.get_real("X1"), r.get_real("Y1"), r.get_real("Z1")};
  V3 z = {r.get_real("X2"), r.get_real("Y2"), r.get_real("Z2")};
  if (!s.frame) {
    if (y[0] == 0 && y[2] == 0) y[1] = y[1] < 0 ? -1.0 : 1.0;
    if (z[0] == 0 && z[1] == 0) z[2] = z[2] < 0 ? -1.0 : 1.0;
  }
  // Directions written inside a submodel turn with it.
  y = b.submodel_vector(r, y);
  z = b.submodel_vector(r, z);
  const V3 x = cross(y, z);
  const double lx = norm(x), lz = norm(z);
  if (!(lx > 1e-12 * norm(y) * lz) || !(lz > 0)) {
    b.error_at(r, "X2", Diag::InconsistentValues,
               "the Y' direction " + direction_text(y) + " and the Z' direction " + direction_text(z) +
                   " are parallel or zero: they define no frame; give two independent directions");
    return false;
  }
  const V3 yy = cross(z, x);
  const double ly = norm(yy);
  for (int k = 0; k < 3; ++k) {
    s.axes[static_cast<std::size_t>(k)] = x[static_cast<std::size_t>(k)] / lx;
    s.axes[static_cast<std::size_t>(3 + k)] = yy[static_cast<std::size_t>(k)] / ly;
    s.axes[static_cast<std::size_t>(6 + k)] = z[static_cast<std::size_t>(k)] / lz;
  }
  return true;
}

bool moving_skew(ModelBuilder& b, const KeywordRecord& r, model::Skew& s) {
  bool ok = true;
  std::string dir = r.get_string("Dir");
  for (auto& c : dir) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if (dir.empty() || dir == "X" || dir == "Y" || dir == "Z") {
    s.dir = dir.empty() ? 0 : dir[0] - 'X';
  } else {
    b.error_at(
        r, "Dir", Diag::ValueOutOfRange,
        "Dir = '" + dir + "' is not an axis; accepted: X, Y or Z (the axis N1 -> N2 gives), blank = X");
    ok = false;
  }
  // A blank or 0 id is already reported by the reader (the fields are required).
  std::int32_t* nodes[3] = {&s.n1, &s.n2, &s.n3};
  const char* fields[3] = {"N1", "N2", "N3"};
  const char* roles[3] = {"N1 (the skew's origin)", "N2 (the skew's Dir axis from N1)",
                          "N3 (the skew's plane)"};
  std::int64_t ids[3];
  for (int k = 0; k < 3; ++k) {
    ids[k] = r.get_int(fields[k]);
    const FieldValue* f = r.find(fields[k]);
    *nodes[k] = ids[k] == 0 ? model::kNone : b.node_ref(ids[k], r, f ? f->pos : r.pos, roles[k]);
    if (*nodes[k] == model::kNone)
      ok = false;
    else
      b.node_used_[static_cast<std::size_t>(*nodes[k])] = 1;
  }
  if (!ok) return false;
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j)
      if (ids[i] == ids[j]) {
        b.error_at(r, fields[j], Diag::InconsistentValues,
                   std::string(fields[i]) + " and " + fields[j] + " are the same node " +
                       std::to_string(ids[i]) + ": a moving " + std::string(s.frame ? "frame" : "skew") +
                       " needs three distinct nodes (N1 origin, N2 its axis, N3 its plane)");
        return false;
      }
  const auto& n = b.m_.nodes;
  const V3 p1 = position(n, s.n1), p2 = position(n, s.n2), p3 = position(n, s.n3);
  const V3 e = model::sub(p2, p1), t = model::sub(p3, p1);
  if (!(norm(e) > 0)) {
    b.error_at(r, "N2", Diag::InconsistentValues,
               "nodes " + std::to_string(ids[0]) + " (N1) and " + std::to_string(ids[1]) +
                   " (N2) are at the same point " + direction_text(p1) + ": N1 -> N2 gives no direction");
    return false;
  }
  if (!(norm(cross(e, t)) > kMinSine * norm(e) * norm(t))) {
    b.error_at(r, "N3", Diag::InconsistentValues,
               "node " + std::to_string(ids[2]) + " (N3) at " + direction_text(p3) +
                   " lies on the line through " + std::to_string(ids[0]) + " (N1) and " +
                   std::to_string(ids[1]) +
                   " (N2) at t = 0 (the sine of the angle between N1N2 and N1N3 is at most 1e-5): the three "
                   "nodes define no plane; choose an N3 off that line");
    return false;
  }
  s.origin = p1;
  s.axes = model::node_skew_axes(p1, p2, p3, s.dir);
  return true;
}

}  // namespace

void ModelBuilder::build_skews() {
  std::unordered_map<std::int64_t, SourcePos> first;
  for (const auto& [path, moving] : {std::pair{"/SKEW/FIX", false}, {"/SKEW/MOV", true}})
    for (const auto* r : deck_.of(path)) {
      model::Skew s;
      s.id = r->id;
      s.title = r->title;
      // Registered before the frame is checked: a degenerate frame is one error, not one more per use.
      if (!register_id(skew_ids_, s.id, static_cast<std::int32_t>(m_.skews.size()), *r, "skew", first))
        continue;
      if (moving ? moving_skew(*this, *r, s) : fixed_skew(*this, *r, s)) m_.skews.push_back(std::move(s));
    }
  for (const auto& [path, moving] : {std::pair{"/FRAME/FIX", false}, {"/FRAME/MOV", true}})
    for (const auto* r : deck_.of(path)) {
      model::Skew s;
      s.id = r->id;
      s.title = r->title;
      s.frame = true;
      if (skew_ids_.count(s.id) != 0) {
        const SourcePos p = first[s.id];
        diags_.error(Diag::DuplicateId, at(r->pos, 1), about(*r),
                     "frame id " + std::to_string(s.id) + " is already used by a skew at " +
                         deck_.files[p.file] + ":" + std::to_string(p.line) +
                         "; skews and frames share one id space (a skew_ID may name either)");
        continue;
      }
      if (!register_id(frame_ids_, s.id, static_cast<std::int32_t>(m_.skews.size()), *r, "frame", first))
        continue;
      if (moving ? moving_skew(*this, *r, s) : fixed_skew(*this, *r, s)) m_.skews.push_back(std::move(s));
    }
}

}  // namespace radx::detail
