// Deck -> Model, the transform stage: /TRANSFORM/TRA, /ROT, /SCA and /SYM move nodes, /MOVE_FUNCT moves a
// function's points. As OpenRadioss's starter does it (lectranssub.F, lecsubmod.F, lectrans.F, subrot.F,
// hm_read_move_funct.F):
//
// * Each transform is an affine map x -> A x + b:
//     TRA  A = I, b = t (t written, or X(node_ID2) - X(node_ID1));
//     ROT  A = R = cos(a) I + sin(a) [u]x + (1 - cos(a)) u u^T (right-handed about u = (P2 - P1)/|P2 - P1|,
//          a = Angle in degrees), b = P1 - R P1: the axis through P1 and P2 (or node_ID1 and node_ID2);
//     SCA  A = diag(Fscale_X, Fscale_Y, Fscale_Z) (0 means 1), b = C - A C about the centre node C (or the
//          origin);
//     SYM  A = I - 2 n n^T with n = (P2 - P1)/|P2 - P1|, b = 2 (n . P1) n: the mirror in the plane through P1
//          normal to P1 -> P2.
// * A transform names either a submodel (sub_ID) or a node group (grnod_ID), never both.
// * Submodel transforms come first, right after the nodes are read: every node written inside submodel S
//   gets S's transforms in deck order, then those of S's parent, and so on up (a nested submodel moves with
//   the one around it). The nodes that define a submodel transform are taken as written, except nodes of
//   that same submodel, which first get its earlier transforms. Points and vectors written inside a
//   submodel (box corners, skew frames, rigid-wall points, initial velocities) get the same chain.
// * Node-group transforms come after the groups are built (a /GRNOD/BOX selects by the coordinates before
//   them), in deck order, each on the coordinates the previous ones left; their defining nodes are taken
//   where they then are, and points written inside a submodel get the submodel's chain.
// * A mirror (SYM, or a negative scale) turns bricks inside out: as Radioss does, a brick whose volume has
//   become negative gets its faces n1-n4 and n5-n8 swapped, which makes it positive again. Shells keep their
//   connectivity (their normal flips with the mirror).
// * /MOVE_FUNCT: X = X Ascalex + Ashiftx, Y = Y Fscaley + Fshifty (0 scales mean 1), applied in deck order
//   after the functions are read; a negative Ascalex also reverses the order of the points so that the
//   abscissas stay increasing.
//
// Where radx is stricter than Radioss, which goes on silently: a rotation axis or a mirror normal of zero
// length (Radioss leaves the nodes where they are), a /MOVE_FUNCT naming no /FUNCT (Radioss ignores it).
// Where radx follows Radioss's documentation rather than its code: a submodel scaled about a centre node
// scales about that node (lecsubmod.F computes C + A x, not C + A (x - C)), and a node group's scale factors
// are not rotated by the submodel around the transform (subrot.F rotates them like a vector).
#include <algorithm>
#include <cmath>
#include <functional>

#include "parser/building/model_builder.hpp"
#include "parser/reading/field_parse.hpp"
#include "solver/model/geometry.hpp"

namespace radx::detail {

using model::Vec3;

namespace {

constexpr double kPi = 3.14159265358979323846;

bool is_transform(const KeywordRecord& r) {
  return r.decl->path.rfind("/TRANSFORM/", 0) == 0;
}

std::string point_text(const Vec3& p) {
  return "(" + number_text(p[0]) + ", " + number_text(p[1]) + ", " + number_text(p[2]) + ")";
}

}  // namespace

Vec3 ModelBuilder::Affine::apply(const Vec3& x) const {
  return {a[0] * x[0] + a[1] * x[1] + a[2] * x[2] + b[0], a[3] * x[0] + a[4] * x[1] + a[5] * x[2] + b[1],
          a[6] * x[0] + a[7] * x[1] + a[8] * x[2] + b[2]};
}

Vec3 ModelBuilder::Affine::linear(const Vec3& v) const {
  return {a[0] * v[0] + a[1] * v[1] + a[2] * v[2], a[3] * v[0] + a[4] * v[1] + a[5] * v[2],
          a[6] * v[0] + a[7] * v[1] + a[8] * v[2]};
}

double ModelBuilder::Affine::det() const {
  return a[0] * (a[4] * a[8] - a[5] * a[7]) - a[1] * (a[3] * a[8] - a[5] * a[6]) +
         a[2] * (a[3] * a[7] - a[4] * a[6]);
}

Vec3 ModelBuilder::submodel_point(const KeywordRecord& r, Vec3 p) const {
  for (std::int32_t s = r.submodel; s >= 0; s = deck_.submodels[static_cast<std::size_t>(s)].parent)
    for (const auto& t : submodel_transforms_[static_cast<std::size_t>(s)]) p = t.apply(p);
  return p;
}

Vec3 ModelBuilder::submodel_vector(const KeywordRecord& r, Vec3 v) const {
  for (std::int32_t s = r.submodel; s >= 0; s = deck_.submodels[static_cast<std::size_t>(s)].parent)
    for (const auto& t : submodel_transforms_[static_cast<std::size_t>(s)]) v = t.linear(v);
  return v;
}

// The affine map of one /TRANSFORM record. `where` gives a node's position (dense index) as this stage sees
// it; `in_submodel` says whether coordinates written in the card are to be taken through the submodel chain
// of the record (node-group transforms). Returns false after reporting an error.
bool ModelBuilder::transform_of(const KeywordRecord& r, const std::function<Vec3(std::int32_t)>& where,
                                bool in_submodel, Affine& out) {
  const std::string_view kind = r.decl->path.substr(11);
  // Two optional nodes that replace two points (or a vector): both or neither.
  auto node_pair = [&](std::int32_t& n1, std::int32_t& n2) {
    const std::int64_t id1 = r.get_int("node_ID1"), id2 = r.get_int("node_ID2");
    n1 = n2 = model::kNone;
    if (id1 == 0 && id2 == 0) return true;
    if (id1 == 0 || id2 == 0) {
      error_at(r, id1 == 0 ? "node_ID1" : "node_ID2", Diag::RequiredIdMissing,
               std::string(id1 == 0 ? "node_ID1" : "node_ID2") +
                   " is blank or 0 while the other node is given: give both nodes, or neither (then the "
                   "coordinates of the card are used)");
      return false;
    }
    n1 = node_ref(id1, r, r.find("node_ID1")->pos, "node_ID1");
    n2 = node_ref(id2, r, r.find("node_ID2")->pos, "node_ID2");
    return n1 >= 0 && n2 >= 0;
  };
  auto card_point = [&](std::string_view x, std::string_view y, std::string_view z) {
    const Vec3 p{r.get_real(x), r.get_real(y), r.get_real(z)};
    return in_submodel ? submodel_point(r, p) : p;
  };
  Affine t;
  if (kind == "TRA") {
    std::int32_t n1 = 0, n2 = 0;
    if (!node_pair(n1, n2)) return false;
    if (n1 >= 0) {
      t.b = model::sub(where(n2), where(n1));
    } else {
      const Vec3 v{r.get_real("X_translation"), r.get_real("Y_translation"), r.get_real("Z_translation")};
      t.b = in_submodel ? submodel_vector(r, v) : v;
    }
  } else if (kind == "ROT" || kind == "SYM") {
    std::int32_t n1 = 0, n2 = 0;
    if (!node_pair(n1, n2)) return false;
    const Vec3 p1 = n1 >= 0 ? where(n1) : card_point("X_point_1", "Y_point_1", "Z_point_1");
    const Vec3 p2 = n1 >= 0 ? where(n2) : card_point("X_point_2", "Y_point_2", "Z_point_2");
    const Vec3 d = model::sub(p2, p1);
    const double len = model::norm(d);
    const double angle = kind == "ROT" ? r.get_real("Angle") : 0.0;
    if (kind == "ROT" && angle == 0.0) {
      out = t;  // no rotation, whatever the axis
      return true;
    }
    if (!(len > 0.0)) {
      error_at(r, n1 >= 0 ? "node_ID2" : "X_point_2", Diag::DegenerateTransform,
               std::string(kind == "ROT" ? "the rotation axis" : "the mirror plane's normal") + " from " +
                   (n1 >= 0 ? "node_ID1 to node_ID2" : "point 1 to point 2") + " has zero length (both at " +
                   point_text(p1) + "): give two distinct " + (n1 >= 0 ? "nodes" : "points"));
      return false;
    }
    const Vec3 u = model::scale(d, 1.0 / len);
    if (kind == "ROT") {
      const double th = angle * kPi / 180.0, c = std::cos(th), s = std::sin(th);
      t.a = {c + (1 - c) * u[0] * u[0],        (1 - c) * u[0] * u[1] - s * u[2],
             (1 - c) * u[0] * u[2] + s * u[1], (1 - c) * u[1] * u[0] + s * u[2],
             c + (1 - c) * u[1] * u[1],        (1 - c) * u[1] * u[2] - s * u[0],
             (1 - c) * u[2] * u[0] - s * u[1], (1 - c) * u[2] * u[1] + s * u[0],
             c + (1 - c) * u[2] * u[2]};
    } else {
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          t.a[static_cast<std::size_t>(3 * i + j)] =
              (i == j ? 1.0 : 0.0) - 2.0 * u[static_cast<std::size_t>(i)] * u[static_cast<std::size_t>(j)];
    }
    t.b = model::sub(p1, t.linear(p1));
  } else {  // SCA
    t.a = {r.get_real("Fscale_X"), 0, 0, 0, r.get_real("Fscale_Y"), 0, 0, 0, r.get_real("Fscale_Z")};
    Vec3 c{};
    if (const std::int64_t id = r.get_int("node_IDc"); id != 0) {
      const auto n = node_ref(id, r, r.find("node_IDc")->pos, "node_IDc");
      if (n < 0) return false;
      c = where(n);
    }
    t.b = model::sub(c, t.linear(c));
  }
  out = t;
  return true;
}

void ModelBuilder::transform_submodels() {
  const auto& subs = deck_.submodels;
  submodel_transforms_.assign(subs.size(), {});
  std::unordered_map<std::int64_t, std::size_t> first;
  for (std::size_t s = 0; s < subs.size(); ++s) {
    const auto [it, inserted] = first.emplace(subs[s].id, s);
    if (!inserted) {
      const SourcePos p = subs[it->second].pos;
      diags_.error(Diag::DuplicateId, at(subs[s].pos, 1), About{"//SUBMODEL", subs[s].id, subs[s].title},
                   "submodel id " + std::to_string(subs[s].id) + " is already used at " +
                       deck_.files[p.file] + ":" + std::to_string(p.line) +
                       "; submodel ids must be unique (after the offsets)");
    } else {
      submodel_ids_.emplace(subs[s].id, static_cast<std::int32_t>(s));
    }
  }
  const auto& n = m_.nodes;
  for (const auto& r : deck_.records) {
    if (!is_transform(r)) continue;
    const bool by_group = r.get_int("grnod_ID") != 0;
    const bool by_submodel = r.get_int("sub_ID") != 0;
    if (by_group && by_submodel) {
      error_at(r, "sub_ID", Diag::InconsistentValues,
               "grnod_ID and sub_ID are both given: a transform moves either a node group or a submodel, not "
               "both; write it twice");
      continue;
    }
    if (!by_group && !by_submodel) {
      error_at(r, "grnod_ID", Diag::RequiredIdMissing,
               "grnod_ID is blank or 0 and there is no sub_ID: give the node group to move (/GRNOD) or the "
               "submodel to move (//SUBMODEL)");
      continue;
    }
    if (!by_submodel) continue;
    const std::int32_t s = ref(submodel_ids_, r, "sub_ID", "submodel", "//SUBMODEL", false);
    if (s < 0) continue;
    // Defining nodes: as written, or after the earlier transforms of this submodel when they belong to it.
    auto where = [&](std::int32_t k) {
      Vec3 p{n.x[k], n.y[k], n.z[k]};
      if (node_submodel_[k] == s)
        for (const auto& t : submodel_transforms_[static_cast<std::size_t>(s)]) p = t.apply(p);
      return p;
    };
    Affine t;
    if (transform_of(r, where, false, t)) {
      submodel_transforms_[static_cast<std::size_t>(s)].push_back(t);
      mirrored_ = mirrored_ || t.det() < 0;
    }
  }
  auto& x = m_.nodes;
  for (std::size_t k = 0; k < x.size(); ++k) {
    const std::int32_t s = node_submodel_[k];
    if (s < 0) continue;
    Vec3 p{x.x[k], x.y[k], x.z[k]};
    for (std::int32_t c = s; c >= 0; c = subs[static_cast<std::size_t>(c)].parent)
      for (const auto& t : submodel_transforms_[static_cast<std::size_t>(c)]) p = t.apply(p);
    x.x[k] = p[0];
    x.y[k] = p[1];
    x.z[k] = p[2];
  }
  reorient_inverted_bricks();
}

void ModelBuilder::transform_node_groups() {
  auto& x = m_.nodes;
  auto where = [&](std::int32_t k) { return Vec3{x.x[k], x.y[k], x.z[k]}; };
  for (const auto& r : deck_.records) {
    if (!is_transform(r) || r.get_int("grnod_ID") == 0 || r.get_int("sub_ID") != 0) continue;
    const std::int32_t g = ref(grnod_ids_, r, "grnod_ID", "node group", "/GRNOD", false);
    if (g < 0) continue;
    const auto* nodes = group_nodes(g);
    Affine t;
    if (nodes == nullptr || !transform_of(r, where, true, t)) continue;
    for (const std::int32_t k : *nodes) {
      const Vec3 p = t.apply(where(k));
      x.x[k] = p[0];
      x.y[k] = p[1];
      x.z[k] = p[2];
    }
    mirrored_ = mirrored_ || t.det() < 0;
  }
  reorient_inverted_bricks();
}

void ModelBuilder::reorient_inverted_bricks() {
  if (!mirrored_) return;
  auto& b = m_.bricks;
  const auto& n = m_.nodes;
  std::size_t swapped = 0;
  std::size_t first = 0;
  for (std::size_t e = 0; e < b.size(); ++e) {
    const std::size_t base = 8 * e;
    std::array<Vec3, 8> p{};
    bool valid = true;
    for (std::size_t k = 0; k < 8; ++k) {
      const auto i = b.conn[base + k];
      valid = valid && i >= 0;
      if (valid) p[k] = {n.x[i], n.y[i], n.z[i]};
    }
    if (!valid || !(model::brick_volume(p) < 0)) continue;
    std::swap_ranges(b.conn.begin() + static_cast<std::ptrdiff_t>(base),
                     b.conn.begin() + static_cast<std::ptrdiff_t>(base + 4),
                     b.conn.begin() + static_cast<std::ptrdiff_t>(base + 4));
    if (swapped++ == 0) first = e;
  }
  if (swapped > 0) {
    diags_.note(
        Diag::DefaultApplied, at(brick_pos_[first], 1), About{"/BRICK", b.id[first]},
        std::to_string(swapped) +
            " brick(s) turned inside out by a mirroring /TRANSFORM (SYM, or a negative scale) had their "
            "faces n1-n4 and n5-n8 swapped so that their volume stays positive, as Radioss does (brick " +
            std::to_string(b.id[first]) + " is the first)");
  }
  // Tetrahedra turned inside out the same way get n2 and n4 swapped, as the starter does for one given
  // inverted (model_builder.cpp check_tetra).
  auto& t = m_.tetras;
  for (std::size_t e = 0; e < t.size(); ++e) {
    const auto* c = &t.conn[4 * e];
    if (c[0] < 0 || c[1] < 0 || c[2] < 0 || c[3] < 0) continue;
    auto X = [&](std::int32_t i) { return Vec3{n.x[i], n.y[i], n.z[i]}; };
    if (model::tetra_volume(X(c[0]), X(c[1]), X(c[2]), X(c[3])) < 0)
      std::swap(t.conn[4 * e + 1], t.conn[4 * e + 3]);
  }
  mirrored_ = false;
}

void ModelBuilder::move_functions() {
  for (const auto* r : deck_.of("/MOVE_FUNCT")) {
    const auto it = funct_ids_.find(r->id);
    if (it == funct_ids_.end()) {
      diags_.error(Diag::MissingReference, at(r->pos, 1), about(*r),
                   "/MOVE_FUNCT/" + std::to_string(r->id) + ": there is no /FUNCT/" + std::to_string(r->id) +
                       " to move (the keyword line names the function)");
      continue;
    }
    auto& f = m_.functions[static_cast<std::size_t>(it->second)];
    const double sx = r->get_real("Ascalex"), sy = r->get_real("Fscaley");
    const double dx = r->get_real("Ashiftx"), dy = r->get_real("Fshifty");
    for (std::size_t k = 0; k < f.x.size(); ++k) {
      f.x[k] = f.x[k] * sx + dx;
      f.y[k] = f.y[k] * sy + dy;
    }
    if (sx < 0) {
      std::reverse(f.x.begin(), f.x.end());
      std::reverse(f.y.begin(), f.y.end());
    }
  }
}

}  // namespace radx::detail
