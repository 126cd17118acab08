// Deck -> Model: boxes, functions, node groups and surfaces (deck-format.md: /BOX/RECTA, /FUNCT,
// /GRNOD/*, /SURF/PART, /SURF/PART/EXT, /SURF/SEG, and section 5.5). Negative ids subtract in
// /GRNOD/PART and /GRNOD/GRNOD, and flip the segment normal in /SURF/PART (they never remove there).
// /SURF/PART/EXT keeps the brick faces that no other brick of the listed parts shares, oriented
// outward, plus the shell segments of the listed parts.
#include <algorithm>
#include <map>
#include <sstream>

#include "parser/field_parse.hpp"
#include "parser/model_builder.hpp"
#include "solver/model/geometry.hpp"

namespace radx {
namespace detail {

using model::kNone;

namespace {

std::string num(double v) {
  return number_text(v);
}

using FaceKey = std::array<std::int32_t, 4>;
FaceKey face_key(std::array<std::int32_t, 4> f) {
  std::sort(f.begin(), f.end());
  return f;
}

void sort_unique(std::vector<std::int32_t>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

}  // namespace

void ModelBuilder::build_boxes() {
  std::unordered_map<std::int64_t, SourcePos> first;
  for (const auto* r : deck_.of("/BOX/RECTA")) {
    model::Box b;
    b.id = r->id;
    b.title = r->title;
    model::Vec3 p1{r->get_real("Xp1"), r->get_real("Yp1"), r->get_real("Zp1")};
    model::Vec3 p2{r->get_real("Xp2"), r->get_real("Yp2"), r->get_real("Zp2")};
    if (r->get_int("N1") != 0) {
      const auto n = node_ref(r->get_int("N1"), *r, r->find("N1") ? r->find("N1")->pos : r->pos, "N1");
      if (n >= 0) p1 = {m_.nodes.x[n], m_.nodes.y[n], m_.nodes.z[n]};
    }
    if (r->get_int("N2") != 0) {
      const auto n = node_ref(r->get_int("N2"), *r, r->find("N2") ? r->find("N2")->pos : r->pos, "N2");
      if (n >= 0) p2 = {m_.nodes.x[n], m_.nodes.y[n], m_.nodes.z[n]};
    }
    if (r->get_int("Iskew") != 0)
      error_at(*r, "Iskew", Diag::UnimplementedOption,
               "boxes aligned with a skew frame are not supported (radx has no /SKEW); use Iskew = 0");
    for (int k = 0; k < 3; ++k) {
      b.lo[k] = std::min(p1[k], p2[k]);
      b.hi[k] = std::max(p1[k], p2[k]);
    }
    if (register_id(box_ids_, b.id, static_cast<std::int32_t>(m_.boxes.size()), *r, "box", first))
      m_.boxes.push_back(std::move(b));
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
    for (std::size_t k = 1; k < f.x.size(); ++k) {
      if (!(f.x[k] > f.x[k - 1])) {
        diags_.error(Diag::NonMonotonicFunction, at(t.pos[k], 1), about(*r),
                     "abscissa X = " + num(f.x[k]) + " is not greater than the previous one (" +
                         num(f.x[k - 1]) + "); function abscissas must be strictly increasing");
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
  std::vector<std::int32_t> add, remove;
  auto part_nodes = [&](std::int32_t part, std::vector<std::int32_t>& out) {
    for (const auto* b : {&m_.shells, &m_.shells3, &m_.bricks}) {
      const auto npe = static_cast<std::size_t>(b->npe());
      for (std::size_t e = 0; e < b->size(); ++e) {
        if (b->part[e] != part) continue;
        for (std::size_t k = 0; k < npe; ++k)
          if (b->conn[e * npe + k] >= 0) out.push_back(b->conn[e * npe + k]);
      }
    }
  };
  const std::string& kind = group.kind;
  auto missing = [&](std::size_t k, const std::string& what, std::int64_t id) {
    diags_.error(Diag::MissingReference, at(r.id_pos[k], 1), about(r),
                 what + " " + std::to_string(id) + " does not exist (listed in node group " +
                     std::to_string(group.id) + ")");
  };
  if (kind == "NODE") {
    for (std::size_t k = 0; k < r.ids.size(); ++k) {
      const auto n = m_.nodes.index.find(r.ids[k]);
      if (n < 0)
        missing(k, "node", r.ids[k]);
      else
        add.push_back(n);
    }
  } else if (kind == "PART") {
    for (std::size_t k = 0; k < r.ids.size(); ++k) {
      const std::int64_t id = r.ids[k] < 0 ? -r.ids[k] : r.ids[k];
      const auto it = part_ids_.find(id);
      if (it == part_ids_.end())
        missing(k, "part", id);
      else
        part_nodes(it->second, r.ids[k] < 0 ? remove : add);
    }
  } else if (kind == "GRNOD") {
    for (std::size_t k = 0; k < r.ids.size(); ++k) {
      const std::int64_t id = r.ids[k] < 0 ? -r.ids[k] : r.ids[k];
      const auto it = grnod_ids_.find(id);
      if (it == grnod_ids_.end()) {
        missing(k, "node group", id);
        continue;
      }
      if (const auto* sub = group_nodes(it->second)) {
        auto& dst = r.ids[k] < 0 ? remove : add;
        dst.insert(dst.end(), sub->begin(), sub->end());
      }
    }
  } else if (kind == "BOX") {
    for (std::size_t k = 0; k < r.ids.size(); ++k) {
      const auto it = box_ids_.find(r.ids[k]);
      if (it == box_ids_.end()) {
        missing(k, "box", r.ids[k]);
        continue;
      }
      const auto& b = m_.boxes[it->second];
      for (std::size_t n = 0; n < m_.nodes.size(); ++n) {
        const double x = m_.nodes.x[n], y = m_.nodes.y[n], z = m_.nodes.z[n];
        if (x >= b.lo[0] && x <= b.hi[0] && y >= b.lo[1] && y <= b.hi[1] && z >= b.lo[2] && z <= b.hi[2])
          add.push_back(static_cast<std::int32_t>(n));
      }
    }
  } else if (kind == "GENE" || kind == "GEN_INCR") {
    // GENE: pairs (first, last); GEN_INCR: records (first, last, incr).
    std::vector<std::array<std::int64_t, 3>> ranges;
    if (kind == "GENE") {
      if (r.ids.size() % 2 != 0)
        diags_.error(Diag::InconsistentValues, at(r.id_pos.back(), 1), about(r),
                     "/GRNOD/GENE lists pairs 'first last'; the last pair is incomplete");
      for (std::size_t k = 0; k + 1 < r.ids.size(); k += 2) ranges.push_back({r.ids[k], r.ids[k + 1], 1});
    } else {
      const auto& t = r.records;
      const int c1 = t.column("first"), c2 = t.column("last"), c3 = t.column("incr");
      for (std::size_t k = 0; c1 >= 0 && c2 >= 0 && k < t.size(); ++k)
        ranges.push_back({t.ints[c1][k], t.ints[c2][k], c3 >= 0 && t.ints[c3][k] > 0 ? t.ints[c3][k] : 1});
    }
    for (const auto& [lo, hi, step] : ranges) {
      if (hi - lo > 100 * static_cast<std::int64_t>(m_.nodes.size()) + 1000000) {
        diags_.error(
            Diag::ValueOutOfRange, at(r.pos, 1), about(r),
            "range " + std::to_string(lo) + " to " + std::to_string(hi) + " is far wider than the model");
        continue;
      }
      for (std::int64_t id = lo; id <= hi; id += step) {
        const auto n = m_.nodes.index.find(id);
        if (n >= 0) add.push_back(n);
      }
    }
  } else if (kind == "MAT" || kind == "PROP") {
    const bool mat = kind == "MAT";
    for (std::size_t k = 0; k < r.ids.size(); ++k) {
      const auto& index = mat ? mat_ids_ : prop_ids_;
      const auto it = index.find(r.ids[k]);
      if (it == index.end()) {
        missing(k, mat ? "material" : "property", r.ids[k]);
        continue;
      }
      for (std::size_t p = 0; p < m_.parts.size(); ++p)
        if ((mat ? m_.parts[p].material : m_.parts[p].property) == it->second)
          part_nodes(static_cast<std::int32_t>(p), add);
    }
  } else if (kind == "SURF") {
    for (std::size_t k = 0; k < r.ids.size(); ++k) {
      const auto it = surf_ids_.find(r.ids[k]);
      if (it == surf_ids_.end()) {
        missing(k, "surface", r.ids[k]);
        continue;
      }
      for (const auto& seg : m_.surfaces[it->second].segments) add.insert(add.end(), seg.begin(), seg.end());
    }
  } else if (kind == "SUBSET") {
    for (std::size_t k = 0; k < r.ids.size(); ++k) {
      const auto it = subset_ids_.find(r.ids[k]);
      if (it == subset_ids_.end()) {
        missing(k, "subset", r.ids[k]);
        continue;
      }
      std::vector<std::int32_t> stack{it->second};
      std::vector<std::uint8_t> seen(m_.subsets.size(), 0);
      while (!stack.empty()) {
        const auto s = stack.back();
        stack.pop_back();
        if (seen[s]) continue;
        seen[s] = 1;
        for (auto p : m_.subsets[s].parts) part_nodes(p, add);
        for (auto c : m_.subsets[s].children) stack.push_back(c);
      }
    }
  }
  sort_unique(add);
  sort_unique(remove);
  group.nodes.clear();
  std::set_difference(add.begin(), add.end(), remove.begin(), remove.end(), std::back_inserter(group.nodes));
  if (group.nodes.empty()) {
    diags_.error(Diag::EmptyGroup, at(r.pos, 1), about(r),
                 "node group " + std::to_string(group.id) +
                     " holds no node: check its list (an empty group makes whatever uses it act on nothing)");
  }
  grnod_state_[g] = 2;
  return &group.nodes;
}

void ModelBuilder::build_surfaces() {
  std::unordered_map<std::int64_t, SourcePos> first;
  // Face lookup for /SURF/SEG owners, built only when needed.
  std::map<FaceKey, std::pair<model::SegmentOwner, std::int32_t>> faces;
  bool faces_built = false;
  auto build_faces = [&] {
    for (std::size_t e = 0; e < m_.shells.size(); ++e) {
      const auto* c = &m_.shells.conn[4 * e];
      faces.emplace(face_key({c[0], c[1], c[2], c[3]}),
                    std::pair{model::SegmentOwner::Shell4, static_cast<std::int32_t>(e)});
    }
    for (std::size_t e = 0; e < m_.shells3.size(); ++e) {
      const auto* c = &m_.shells3.conn[3 * e];
      faces.emplace(face_key({c[0], c[1], c[2], c[2]}),
                    std::pair{model::SegmentOwner::Shell3, static_cast<std::int32_t>(e)});
    }
    for (std::size_t e = 0; e < m_.bricks.size(); ++e) {
      const auto* c = &m_.bricks.conn[8 * e];
      for (const auto& f : model::kBrickFaces)
        faces.emplace(face_key({c[f[0]], c[f[1]], c[f[2]], c[f[3]]}),
                      std::pair{model::SegmentOwner::Brick8, static_cast<std::int32_t>(e)});
    }
    faces_built = true;
  };
  for (const auto& r : deck_.records) {
    const auto path = r.decl->path;
    if (path != "/SURF/PART" && path != "/SURF/PART/EXT" && path != "/SURF/SEG") continue;
    const std::size_t errors_before = diags_.error_count();
    model::Surface s;
    s.id = r.id;
    s.title = r.title;
    s.kind = std::string(path.substr(6));
    auto push = [&](std::array<std::int32_t, 4> seg, model::SegmentOwner type, std::int32_t owner) {
      s.segments.push_back(seg);
      s.owner_type.push_back(type);
      s.owner.push_back(owner);
    };
    if (path == "/SURF/SEG") {
      const auto& t = r.records;
      const int c[4] = {t.column("n1"), t.column("n2"), t.column("n3"), t.column("n4")};
      for (std::size_t k = 0; k < t.size(); ++k) {
        std::array<std::int32_t, 4> seg{};
        bool ok = true;
        for (int j = 0; j < 4; ++j) {
          std::int64_t uid = c[j] >= 0 ? t.ints[c[j]][k] : 0;
          if (j == 3 && uid == 0) uid = c[2] >= 0 ? t.ints[c[2]][k] : 0;
          seg[j] = uid == 0 ? -1 : m_.nodes.index.find(uid);
          if (seg[j] < 0) {
            diags_.error(
                Diag::MissingReference, at(t.pos[k], 11 + 10 * j), about(r),
                "segment node n" + std::to_string(j + 1) + " = " + std::to_string(uid) + " does not exist");
            ok = false;
          }
        }
        if (!ok) continue;
        if (!faces_built) build_faces();
        const auto it = faces.find(face_key(seg));
        push(seg, it == faces.end() ? model::SegmentOwner::None : it->second.first,
             it == faces.end() ? kNone : it->second.second);
      }
    } else {
      const bool ext = path == "/SURF/PART/EXT";
      std::vector<std::uint8_t> listed(m_.parts.size(), 0);
      for (std::size_t k = 0; k < r.ids.size(); ++k) {
        const bool flip = r.ids[k] < 0;
        const std::int64_t id = flip ? -r.ids[k] : r.ids[k];
        const auto it = part_ids_.find(id);
        if (it == part_ids_.end()) {
          diags_.error(
              Diag::MissingReference, at(r.id_pos[k], 1), about(r),
              "part " + std::to_string(id) + " does not exist (no /PART/" + std::to_string(id) + ")");
          continue;
        }
        const auto part = it->second;
        listed[part] = 1;
        bool has_solid = false;
        for (std::size_t e = 0; e < m_.bricks.size() && !has_solid; ++e)
          has_solid = m_.bricks.part[e] == part;
        if (has_solid && !ext) {
          diags_.error(
              Diag::PartWrongKind, at(r.id_pos[k], 1), about(r),
              "part " + std::to_string(id) +
                  " is a solid part: /SURF/PART takes shell parts only; use /SURF/PART/EXT for the outer "
                  "faces of solid parts");
        }
        for (std::size_t e = 0; e < m_.shells.size(); ++e) {
          if (m_.shells.part[e] != part) continue;
          const auto* c = &m_.shells.conn[4 * e];
          if (flip)
            push({c[0], c[3], c[2], c[1]}, model::SegmentOwner::Shell4, static_cast<std::int32_t>(e));
          else
            push({c[0], c[1], c[2], c[3]}, model::SegmentOwner::Shell4, static_cast<std::int32_t>(e));
          if (c[2] == c[3] && flip) s.segments.back() = {c[0], c[2], c[1], c[1]};
        }
        for (std::size_t e = 0; e < m_.shells3.size(); ++e) {
          if (m_.shells3.part[e] != part) continue;
          const auto* c = &m_.shells3.conn[3 * e];
          if (flip)
            push({c[0], c[2], c[1], c[1]}, model::SegmentOwner::Shell3, static_cast<std::int32_t>(e));
          else
            push({c[0], c[1], c[2], c[2]}, model::SegmentOwner::Shell3, static_cast<std::int32_t>(e));
        }
      }
      if (ext) {
        // Outer faces: count each face over the bricks of the listed parts; keep those seen once.
        std::map<FaceKey, int> count;
        for (std::size_t e = 0; e < m_.bricks.size(); ++e) {
          if (m_.bricks.part[e] == kNone || !listed[m_.bricks.part[e]]) continue;
          const auto* c = &m_.bricks.conn[8 * e];
          for (const auto& f : model::kBrickFaces) ++count[face_key({c[f[0]], c[f[1]], c[f[2]], c[f[3]]})];
        }
        for (std::size_t e = 0; e < m_.bricks.size(); ++e) {
          if (m_.bricks.part[e] == kNone || !listed[m_.bricks.part[e]]) continue;
          const auto* c = &m_.bricks.conn[8 * e];
          for (const auto& f : model::kBrickFaces) {
            std::array<std::int32_t, 4> seg{c[f[0]], c[f[1]], c[f[2]], c[f[3]]};
            if (count[face_key(seg)] != 1) continue;
            // A face of a degenerate brick may collapse to an edge or a point: not a segment.
            auto key = face_key(seg);
            const int distinct = 1 + (key[1] != key[0]) + (key[2] != key[1]) + (key[3] != key[2]);
            if (distinct < 3) continue;
            // Triangle faces of degenerate bricks keep the repeated node last (n4 = n3).
            for (int j = 0; j < 4 && seg[2] != seg[3]; ++j) {
              if (seg[j] == seg[(j + 1) % 4]) {
                std::array<std::int32_t, 4> tri{};
                int m = 0;
                for (int q = 0; q < 4; ++q)
                  if (q != j) tri[m++] = seg[q];
                tri[3] = tri[2];
                seg = tri;
                break;
              }
            }
            push(seg, model::SegmentOwner::Brick8, static_cast<std::int32_t>(e));
          }
        }
      }
    }
    if (s.segments.empty() && diags_.error_count() == errors_before) {
      diags_.error(Diag::EmptyGroup, at(r.pos, 1), about(r),
                   "surface " + std::to_string(s.id) + " holds no segment: check its part list");
    }
    if (register_id(surf_ids_, s.id, static_cast<std::int32_t>(m_.surfaces.size()), r, "surface", first))
      m_.surfaces.push_back(std::move(s));
  }
}

}  // namespace detail
}  // namespace radx
