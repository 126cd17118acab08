// Deck -> Model: sensors (/SENSOR/TIME), kinematic conditions and loads (/BCS, /IMPVEL, /IMPDISP,
// /IMPDISP/FGEO, /INIVEL/TRA, /CLOAD, /PLOAD, /GRAV), rigid walls (/RWALL/PLANE, CYL, SPHER, PARAL), rigid
// bodies (/RBODY) and time-history requests (/TH/NODE, /TH/PART, /TH/INTER, /TH/RWALL, /TH/SHEL, /TH/SH3N,
// /TH/BRIC, /TH/RBODY, /TH/SUBS); docs/theory/deck-format.md section 2
// and 5.5, docs/theory/elements.md section 7.
// * /SENSOR/TIME: Tstop 0 -> never; a Tstop at or before Tdelay is refused (Radioss would switch the
//   sensor off one cycle after it switches on). A sensor_ID (sens_ID) names one; the model keeps the user id.
// * Loads: value = Fscale_y f(t / Ascale_x), both scales 0 -> 1; the function is required except for
//   /GRAV (0 = constant); /GRAV grnod_ID 0 = all nodes.
// * /RWALL/PLANE: normal n = (M1 - M)/|M1 - M|; secondary nodes = grnd_ID1 + every node with
//   0 <= (X - M).n <= d at t = 0 (when d > 0) - grnd_ID2 (docs/theory/elements.md 7.1). /RWALL/CYL: the same
//   with the axis (M1 - M)/|M1 - M| and the height above the cylinder surface; /RWALL/SPHER: centre M, no M1.
//   /RWALL/PARAL: n = (M1 - M) x (M2 - M) normalised, the search along n as the infinite plane's
//   (hm_read_rwall_paral.F); for a moving wall M is the wall node.
// * /IMPDISP/FGEO: one object per keyword, its nodes and their final positions as listed.
// * /RBODY: the main node is removed from the secondary group; Ispher 0 -> 2,
//   ICoG 0 -> 1 (docs/theory/elements.md 7.2).
// * /TH/*: group names (DEF, D, V, ...) are expanded to variables; objects resolve to dense indices; the
//   variables radx accepts but writes as 0 are named in a warning.
// Skews are /SKEW/FIX and /SKEW/MOV, frames /FRAME/FIX and /FRAME/MOV (build_skews.cpp). Among the fields
// radx reads, only a /TH/NODE skew_ID may name a frame (as in Radioss, hm_read_thgrou.F); /IMPVEL's
// frame_ID names one too, and radx refuses it (it does not impose velocities relative to a frame).
#include <algorithm>
#include <array>
#include <cctype>
#include <iterator>
#include <map>
#include <sstream>
#include <unordered_map>

#include "parser/building/model_builder.hpp"
#include "parser/reading/field_parse.hpp"
#include "solver/model/geometry.hpp"

namespace radx {
namespace detail {

using model::kNone;

namespace {

using IdIndex = ModelBuilder::IdIndex;
using FirstPos = std::unordered_map<std::int64_t, SourcePos>;
using NodeList = std::vector<std::int32_t>;

int geti(const KeywordRecord& r, std::string_view field) {
  return static_cast<int>(r.get_int(field));
}
int int_or(const KeywordRecord& r, std::string_view field, int dflt) {
  const int v = geti(r, field);
  return v == 0 ? dflt : v;
}
double real_or(const KeywordRecord& r, std::string_view field, double dflt) {
  const double v = r.get_real(field);
  return v == 0 ? dflt : v;
}
model::Vec3 reals3(const KeywordRecord& r, std::string_view a, std::string_view b, std::string_view c) {
  return {r.get_real(a), r.get_real(b), r.get_real(c)};
}
SourcePos field_pos(const KeywordRecord& r, std::string_view field) {
  const FieldValue* f = r.find(field);
  return f ? f->pos : r.pos;
}

// An id reference. `optional`: 0 means none. Otherwise 0 is an error, reported here unless the field is
// declared required, in which case the reader has already reported it (RX502).
std::int32_t lookup(ModelBuilder& b, const IdIndex& index, const KeywordRecord& r, std::string_view field,
                    std::string_view what, std::string_view target, bool optional) {
  const FieldValue* f = r.find(field);
  return b.ref(index, r, field, what, target, optional || (f && f->decl->required));
}
std::int32_t function_ref(ModelBuilder& b, const KeywordRecord& r, bool optional) {
  return lookup(b, b.funct_ids_, r, "funct_IDT", "function", "/FUNCT", optional);
}
std::int32_t group_ref(ModelBuilder& b, const KeywordRecord& r, std::string_view field, bool optional) {
  return lookup(b, b.grnod_ids_, r, field, "node group", "/GRNOD", optional);
}
const NodeList& nodes_of(ModelBuilder& b, std::int32_t group) {
  static const NodeList kEmpty;
  const NodeList* nodes = b.group_nodes(group);
  return nodes ? *nodes : kEmpty;
}

// The /FRAME/FIX or /FRAME/MOV record with user id `id`, if the deck has one.
const KeywordRecord* frame_record(const ModelBuilder& b, std::int64_t id) {
  for (const char* path : {"/FRAME/FIX", "/FRAME/MOV"})
    for (const auto* r : b.deck_.of(path))
      if (r->id == id) return r;
  return nullptr;
}
// "there is no /SKEW/FIX/7 or /SKEW/MOV/7 in the deck; 0 = global axes" when skew `id` is not in the deck,
// empty when it is (or id is 0). Skews and frames share one id space, and Radioss resolves most skew fields
// among the skews only (hm_read_bcs.F, hm_read_cload.F, ...): a frame there is named as such.
std::string missing_skew_text(const ModelBuilder& b, std::string_view field, std::int64_t id) {
  if (id == 0 || b.skew_ids_.find(id) != b.skew_ids_.end()) return {};
  const std::string s = std::to_string(id);
  if (const KeywordRecord* f = frame_record(b, id)) {
    const Where w = b.deck_.where(f->pos);
    return std::string(field) + " = " + s + " names " + std::string(f->decl->path) + "/" + s + " (" +
           std::string(w.file) + ":" + std::to_string(w.line) +
           "), a frame: Radioss reads this field as a skew only; give a " +
           "/SKEW/FIX or /SKEW/MOV, or 0 for the global axes";
  }
  // Frames radx does not read (/FRAME/MOV2, /FRAME/NOD) are in the deck's unread keywords.
  const auto& unread = b.deck_.unread;
  const auto frame = std::find_if(unread.begin(), unread.end(), [&](const Deck::Unread& u) {
    return u.id == id && u.path.rfind("/FRAME/", 0) == 0;
  });
  if (frame != unread.end()) {
    const Where w = b.deck_.where(frame->pos);
    return std::string(field) + " = " + s + " names " + frame->path + " " + s + " (" + std::string(w.file) +
           ":" + std::to_string(w.line) + "), a frame radx does not read (reported there); give a " +
           "/SKEW/FIX or /SKEW/MOV, or 0 for the global axes";
  }
  return std::string(field) + " = " + s + ": there is no /SKEW/FIX/" + s + " or /SKEW/MOV/" + s +
         " in the deck; 0 = global axes";
}
// A /SKEW/FIX or /SKEW/MOV of the deck (its user id, 0 for the global axes).
std::int64_t skew_ref(ModelBuilder& b, const KeywordRecord& r) {
  const std::int64_t id = r.get_int("skew_ID");
  if (auto text = missing_skew_text(b, "skew_ID", id); !text.empty())
    b.error_at(r, "skew_ID", Diag::MissingReference, std::move(text));
  return id;
}
// Jxx Jyy Jzz Jxy Jyz Jxz given in the axes of a skew (rows of `axes`: its X Y Z axes at t = 0) in global
// axes: J_global = R J R^T with R's columns the skew's axes, as Radioss's starter turns an /RBODY's added
// inertia (inirby.F).
std::array<double, 6> inertia_in_global_axes(const std::array<double, 6>& j,
                                             const std::array<double, 9>& axes) {
  const double J[3][3] = {{j[0], j[3], j[5]}, {j[3], j[1], j[4]}, {j[5], j[4], j[2]}};
  auto R = [&](int row, int col) { return axes[static_cast<std::size_t>(3 * col + row)]; };
  double g[3][3] = {};
  for (int a = 0; a < 3; ++a)
    for (int c = 0; c < 3; ++c)
      for (int p = 0; p < 3; ++p)
        for (int q = 0; q < 3; ++q) g[a][c] += R(a, p) * J[p][q] * R(c, q);
  return {g[0][0], g[1][1], g[2][2], g[0][1], g[1][2], g[0][2]};
}

// Direction codes 0..5 = X Y Z XX YY ZZ; `count` 3 accepts the translations only.
int direction(ModelBuilder& b, const KeywordRecord& r, std::size_t count, std::string_view accepted) {
  static constexpr std::array<std::string_view, 6> kDirections = {"X", "Y", "Z", "XX", "YY", "ZZ"};
  std::string s = r.get_string("Dir");
  for (auto& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  for (std::size_t k = 0; k < count; ++k)
    if (s == kDirections[k]) return static_cast<int>(k);
  b.error_at(r, "Dir", Diag::ValueOutOfRange,
             (s.empty() ? std::string("Dir is blank") : "Dir = '" + s + "' is not a direction") +
                 "; accepted: " + std::string(accepted));
  return 0;
}
constexpr std::string_view kSixDirections = "X, Y, Z (translation) or XX, YY, ZZ (rotation)";
constexpr std::string_view kLoadDirections = "X, Y, Z (force) or XX, YY, ZZ (moment)";

double mass_field(ModelBuilder& b, const KeywordRecord& r, std::string_view meaning) {
  const double m = r.get_real("Mass");
  if (m < 0)
    b.error_at(r, "Mass", Diag::ValueOutOfRange,
               "Mass = " + number_text(m) + " is negative; it is the mass " + std::string(meaning) +
                   "; accepted: >= 0");
  return m;
}

// Builds one object per record of `path`, registers its id (duplicates are reported and dropped) and
// returns the records kept, in the order of `out`.
template <class T, class Make>
std::vector<const KeywordRecord*> build_each(ModelBuilder& b, std::string_view path, std::string_view what,
                                             std::vector<T>& out, IdIndex& ids, Make make) {
  FirstPos first;
  std::vector<const KeywordRecord*> kept;
  for (const auto* r : b.deck_.of(path)) {
    T obj = make(*r);
    obj.id = r->id;
    obj.title = r->title;
    if (b.register_id(ids, obj.id, static_cast<std::int32_t>(out.size()), *r, what, first)) {
      out.push_back(std::move(obj));
      kept.push_back(r);
    }
  }
  return kept;
}

// ---------------------------------------------------------------------------------------------------------
// Loads

// Several /BCS on one node are OR-ed, but in one frame: two different non-zero skews on a node are an error.
void check_bcs_skews(ModelBuilder& b, const std::vector<const KeywordRecord*>& recs) {
  const auto& bcs = b.m_.bcs;
  std::vector<std::int32_t> owner(b.m_.nodes.size(), kNone);  // first /BCS giving the node a skew
  for (std::size_t i = 0; i < bcs.size(); ++i) {
    if (bcs[i].skew == 0) continue;
    std::map<std::int32_t, std::pair<std::int32_t, std::size_t>> clashes;  // other /BCS -> first node, count
    for (const auto n : nodes_of(b, bcs[i].group)) {
      auto& o = owner[n];
      if (o == kNone) o = static_cast<std::int32_t>(i);
      if (bcs[o].skew == bcs[i].skew) continue;
      ++clashes.try_emplace(o, n, 0).first->second.second;
    }
    for (const auto& [o, clash] : clashes) {
      const SourcePos p = recs[o]->pos;
      const std::size_t others = clash.second - 1;
      b.error_at(
          *recs[i], "skew_ID", Diag::InconsistentValues,
          "node " + std::to_string(b.m_.nodes.id[clash.first]) +
              (others ? " (and " + std::to_string(others) + (others == 1 ? " other node)" : " other nodes)")
                      : std::string()) +
              " is fixed here in skew " + std::to_string(bcs[i].skew) + " and by /BCS/" +
              std::to_string(bcs[o].id) + " (" + b.deck_.files[p.file] + ":" + std::to_string(p.line) +
              ") in skew " + std::to_string(bcs[o].skew) +
              "; a node's fixed directions have one frame: use the same skew_ID or separate node groups");
    }
  }
}

// Two /BCS with one id are both applied, with a warning: OpenRadioss's starter reads them without a word
// (its QA deck LOIS/LOI13/solide does it) and nothing refers to a /BCS by its id.
void build_bcs(ModelBuilder& b) {
  std::unordered_map<std::int64_t, SourcePos> first;
  std::vector<const KeywordRecord*> recs;
  for (const auto* r : b.deck_.of("/BCS")) {
    static constexpr std::array<std::string_view, 6> kDofs = {"Tx", "Ty", "Tz", "Rx", "Ry", "Rz"};
    model::BoundaryCondition c;
    c.id = r->id;
    c.title = r->title;
    for (std::size_t k = 0; k < kDofs.size(); ++k) c.fixed[k] = r->get_int(kDofs[k]) != 0 ? 1 : 0;
    c.skew = skew_ref(b, *r);
    c.group = group_ref(b, *r, "grnod_ID", false);
    if (const auto [it, fresh] = first.emplace(c.id, r->pos); !fresh)
      b.warning_at(*r, "id", Diag::DuplicateId,
                   "/BCS id " + std::to_string(c.id) + " is also used at " + b.deck_.files[it->second.file] +
                       ":" + std::to_string(it->second.line) +
                       "; both are applied, their fixed directions OR-ed, as OpenRadioss does");
    b.m_.bcs.push_back(c);
    recs.push_back(r);
  }
  check_bcs_skews(b, recs);
}

// /ALE/BCS: the codes of ALE nodes' grid and material velocities, which OpenRadioss keeps in bits of the
// node code that only its ALE solver reads (hm_read_alebcs.F: IC1 * 8 + IC2, where /BCS uses IC1 * 512 +
// IC2 * 64). radx runs Lagrangian nodes only (every ALE keyword and Iale flag is refused), on which these
// codes act on nothing: the group and skew are checked, and a warning says so.
void build_ale_bcs(ModelBuilder& b) {
  for (const auto* r : b.deck_.of("/ALE/BCS")) {
    (void)skew_ref(b, *r);
    const auto group = group_ref(b, *r, "grnod_ID", false);
    if (group == kNone) continue;
    b.warning_at(
        *r, "grnod_ID", Diag::UnimplementedOption,
        "/ALE/BCS fixes grid and material velocities of ALE nodes; radx runs no ALE element, so on its "
        "Lagrangian nodes it changes nothing, as in Radioss for a Lagrangian node (use /BCS to fix a "
        "node)");
  }
}

// /IMPVEL (a velocity) and /IMPDISP (a displacement from the initial position): the same cards, one model
// object each; the engine turns the displacement into the velocity that reaches it at the end of the step.
void build_imposed_velocities(ModelBuilder& b) {
  for (const bool displacement : {false, true}) {
    IdIndex ids;
    const std::string_view path = displacement ? "/IMPDISP" : "/IMPVEL";
    const std::string_view what = displacement ? "imposed displacement" : "imposed velocity";
    build_each(b, path, what, b.m_.imposed_velocities, ids, [&](const KeywordRecord& r) {
      model::ImposedVelocity v;
      v.displacement = displacement;
      v.function = function_ref(b, r, false);
      v.dir = direction(b, r, 6, kSixDirections);
      if (displacement && v.dir >= 3)
        b.error_at(
            r, "Dir", Diag::PhysicsNotImplemented,
            "Dir = " + std::string(r.get_string("Dir")) +
                ": an imposed rotation angle is not implemented by radx (nodes carry no rotation angle); "
                "accepted: X, Y, Z, or /IMPVEL with the rotational velocity");
      v.skew = skew_ref(b, r);
      v.sensor = b.sensor_ref(r);
      v.frame = r.get_int("frame_ID");
      if (v.frame != 0 && b.frame_ids_.count(v.frame) == 0)
        b.error_at(r, "frame_ID", Diag::MissingReference,
                   "frame_ID = " + std::to_string(v.frame) + ": there is no /FRAME/FIX/" +
                       std::to_string(v.frame) + " or /FRAME/MOV/" + std::to_string(v.frame) +
                       " in the deck; 0 = none");
      else if (v.frame != 0)
        b.error_at(
            r, "frame_ID", Diag::PhysicsNotImplemented,
            "frame_ID = " + std::to_string(v.frame) + ": radx does not impose " +
                std::string(displacement ? "displacements" : "velocities") +
                " relative to a frame (Radioss adds the frame's own motion); leave frame_ID blank or 0, "
                "or give the direction in a skew_ID");
      v.icoor = geti(r, "Icoor");
      v.group = group_ref(b, r, "grnod_ID", false);
      v.ascale_x = real_or(r, "Ascale_x", 1.0);
      v.fscale_y = real_or(r, "Fscale_y", 1.0);
      v.t_start = r.get_real("Tstart");
      v.t_stop = real_or(r, "Tstop", model::kNever);
      if (r.get_real("Tstop") != 0 && v.t_stop <= v.t_start)
        b.error_at(r, "Tstop", Diag::InconsistentValues,
                   "Tstop = " + number_text(v.t_stop) + " is not after Tstart = " + number_text(v.t_start) +
                       ": the " + std::string(displacement ? "displacement" : "velocity") +
                       " would never be imposed; need Tstop > Tstart (0 = never stop)");
      if (v.icoor == 1 && v.frame == 0)
        b.error_at(r, "Icoor", Diag::InconsistentValues,
                   "Icoor = 1 (cylindrical) needs a frame (frame_ID), which radx does not run; use "
                   "Icoor = 0 (Cartesian)");
      return v;
    });
  }
}

// /IMPDISP/FGEO: the listed nodes and their final positions (read_impdisp_fgeo.F). Each listed node is used
// (it moves even without an element). The spring-part form needs /SPRING elements, which radx does not read.
void build_imposed_final_geometries(ModelBuilder& b) {
  IdIndex ids;
  build_each(
      b, "/IMPDISP/FGEO", "imposed final geometry", b.m_.imposed_final_geometries, ids,
      [&](const KeywordRecord& r) {
        model::ImposedFinalGeometry g;
        g.function = lookup(b, b.funct_ids_, r, "fct_ID", "function", "/FUNCT", false);
        if (r.get_int("part_ID") != 0)
          b.error_at(
              r, "part_ID", Diag::UnimplementedOption,
              "part_ID = " + std::to_string(r.get_int("part_ID")) +
                  ": the spring-part form (each spring's first node moves to its second node) needs "
                  "/SPRING elements, which radx does not read; leave part_ID 0 and list the nodes with "
                  "their final positions");
        g.sensor = b.sensor_ref(r, "sens_ID");
        g.ascale_x = real_or(r, "Ascale", 1.0);
        if (g.ascale_x != 1.0)
          b.warning_at(
              r, "Ascale", Diag::InconsistentValues,
              "Ascale = " + number_text(g.ascale_x) +
                  ": the function is evaluated at t * Ascale, as Radioss does for /IMPDISP/FGEO (where "
                  "/IMPDISP evaluates it at t / Ascale_x)");
        g.t_start = r.get_real("Tstart");
        g.t_stop = real_or(r, "Tstop", model::kNever);
        if (r.get_real("Tstop") != 0 && g.t_stop <= g.t_start)
          b.error_at(r, "Tstop", Diag::InconsistentValues,
                     "Tstop = " + number_text(g.t_stop) + " is not after Tstart = " + number_text(g.t_start) +
                         ": the motion would never be imposed; need Tstop > Tstart (0 = never stop)");
        const auto& t = r.records;
        const int cn = t.column("node_IDN"), cx = t.column("Xn"), cy = t.column("Yn"), cz = t.column("Zn");
        for (std::size_t k = 0; cn >= 0 && k < t.size(); ++k) {
          if (t.bad[k]) continue;
          const auto n = b.node_ref(t.ints[cn][k], r, t.pos[k], "node_IDN (a node to move)");
          if (n == kNone) continue;
          b.node_used_[static_cast<std::size_t>(n)] = 1;
          g.nodes.push_back(n);
          // As written, also inside a moved submodel: Radioss does not transform these targets
          // (read_impdisp_fgeo.F), whatever the transforms do to the node.
          g.targets.push_back({t.reals[cx][k], t.reals[cy][k], t.reals[cz][k]});
        }
        if (g.nodes.empty() && r.get_int("part_ID") == 0)
          b.diags_.error(Diag::EmptyRecordList, b.at(r.pos, 1), ModelBuilder::about(r),
                         "no node is listed: each line after card 2 gives a node and its final position "
                         "(node_IDN, Xn, Yn, Zn)");
        return g;
      });
}

// /INIVEL/TRA (and /INIVEL/T+G, its alias) and /INIVEL/ROT: one model object each.
// /ADMAS/0 and /ADMAS/1: the masses join the nodes in compute_lumped_masses; a node with added mass and no
// element is a point mass of the run, not an unused node.
void build_added_masses(ModelBuilder& b) {
  for (const int type : {0, 1}) {
    IdIndex ids;
    const std::string path = "/ADMAS/" + std::to_string(type);
    build_each(b, path, "added mass", b.m_.added_masses, ids, [&](const KeywordRecord& r) {
      model::AddedMass a;
      a.type = type;
      a.mass = r.get_real("MASS");
      a.group = group_ref(b, r, "grnod_ID", false);
      if (a.group != kNone)
        for (const auto n : nodes_of(b, a.group)) b.node_used_[static_cast<std::size_t>(n)] = 1;
      return a;
    });
  }
}

// /ACCEL: the node and the skew must exist; the node is used (a sensor on a free node still moves).
void build_accelerometers(ModelBuilder& b) {
  build_each(b, "/ACCEL", "accelerometer", b.m_.accelerometers, b.accel_ids_, [&](const KeywordRecord& r) {
    model::Accelerometer a;
    a.node =
        b.node_ref(r.get_int("node_ID"), r, field_pos(r, "node_ID"), "node_ID (the accelerometer's node)");
    if (a.node != kNone) b.node_used_[static_cast<std::size_t>(a.node)] = 1;
    a.skew = skew_ref(b, r);
    a.fcut = r.get_real("Fcut");
    return a;
  });
}

void build_initial_velocities(ModelBuilder& b) {
  for (const bool rotational : {false, true}) {
    IdIndex ids;
    build_each(b, rotational ? "/INIVEL/ROT" : "/INIVEL/TRA",
               rotational ? "initial angular velocity" : "initial velocity", b.m_.initial_velocities, ids,
               [&](const KeywordRecord& r) {
                 model::InitialVelocity v;
                 v.rotational = rotational;
                 v.v = reals3(r, "Vx", "Vy", "Vz");
                 v.group = group_ref(b, r, "grnod_ID", false);
                 v.skew = skew_ref(b, r);
                 // Written inside a submodel without a skew: in the submodel's frame, as Radioss reads it.
                 if (r.get_int("skew_ID") == 0) v.v = b.submodel_vector(r, v.v);
                 v.sensor = b.sensor_ref(r);
                 v.t_start = r.get_real("Tstart");
                 return v;
               });
  }
}

void build_concentrated_loads(ModelBuilder& b) {
  IdIndex ids;
  build_each(b, "/CLOAD", "concentrated load", b.m_.concentrated_loads, ids, [&](const KeywordRecord& r) {
    model::ConcentratedLoad c;
    c.function = function_ref(b, r, false);
    c.dir = direction(b, r, 6, kLoadDirections);
    c.skew = skew_ref(b, r);
    c.sensor = b.sensor_ref(r);
    c.group = group_ref(b, r, "grnod_ID", false);
    c.itypfun = int_or(r, "Itypfun", 1);
    c.ascale_x = real_or(r, "Ascale_x", 1.0);
    c.fscale_y = real_or(r, "Fscale_y", 1.0);
    return c;
  });
}

void build_pressure_loads(ModelBuilder& b) {
  IdIndex ids;
  build_each(b, "/PLOAD", "pressure load", b.m_.pressure_loads, ids, [&](const KeywordRecord& r) {
    model::PressureLoad p;
    p.surface = lookup(b, b.surf_ids_, r, "surf_ID", "surface", "/SURF", false);
    p.function = function_ref(b, r, false);
    p.sensor = b.sensor_ref(r);
    p.ipinch = geti(r, "Ipinch");
    p.idel = int_or(r, "Idel", 1);
    p.itypfun = int_or(r, "Itypfun", 1);
    p.ascale_x = real_or(r, "Ascale_x", 1.0);
    p.fscale_y = real_or(r, "Fscale_y", 1.0);
    return p;
  });
}

void build_gravities(ModelBuilder& b) {
  IdIndex ids;
  build_each(b, "/GRAV", "gravity", b.m_.gravities, ids, [&](const KeywordRecord& r) {
    model::Gravity g;
    g.function = function_ref(b, r, true);  // 0: constant
    g.dir = direction(b, r, 3, "X, Y or Z (the sign of Fscale_y gives the sense)");
    g.skew = skew_ref(b, r);
    g.sensor = b.sensor_ref(r);
    g.group = group_ref(b, r, "grnod_ID", true);  // 0: all nodes
    g.ascale_x = real_or(r, "Ascale_x", 1.0);
    g.fscale_y = real_or(r, "Fscale_y", 1.0);
    return g;
  });
}

// ---------------------------------------------------------------------------------------------------------
// Rigid walls

double model_size(const model::Nodes& n) {
  if (n.size() == 0) return 0.0;
  const auto [x0, x1] = std::minmax_element(n.x.begin(), n.x.end());
  const auto [y0, y1] = std::minmax_element(n.y.begin(), n.y.end());
  const auto [z0, z1] = std::minmax_element(n.z.begin(), n.z.end());
  return model::norm({*x1 - *x0, *y1 - *y0, *z1 - *z0});
}

model::Vec3 node_point(const model::Nodes& n, std::int32_t k) {
  return {n.x[k], n.y[k], n.z[k]};
}

// grnd_ID1 + nodes within d on the positive side - grnd_ID2, without the wall's own node; sorted, unique.
// The height of a point above the wall: along the normal (plane), from the surface of the cylinder (radial
// distance to the axis minus the radius) or of the sphere.
// The parallelogram searches as its infinite plane (hm_read_rwall_paral.F).
double wall_height(const model::RigidWall& w, const model::Vec3& x) {
  const model::Vec3 d = model::sub(x, w.m);
  if (w.shape == 0 || w.shape == 3) return model::dot(d, w.normal);
  const double along = w.shape == 1 ? model::dot(d, w.normal) : 0.0;
  return model::norm(model::sub(d, model::scale(w.normal, along))) - 0.5 * w.diameter;
}

NodeList wall_secondary(ModelBuilder& b, const model::RigidWall& w, bool normal_ok) {
  NodeList s = nodes_of(b, w.group1);
  if (normal_ok && w.distance > 0) {
    for (std::size_t n = 0; n < b.m_.nodes.size(); ++n) {
      const auto k = static_cast<std::int32_t>(n);
      const double h = wall_height(w, node_point(b.m_.nodes, k));
      if (h >= 0 && h <= w.distance) s.push_back(k);
    }
  }
  std::sort(s.begin(), s.end());
  s.erase(std::unique(s.begin(), s.end()), s.end());
  NodeList removed = nodes_of(b, w.group2);
  if (w.node != kNone) removed.insert(std::lower_bound(removed.begin(), removed.end(), w.node), w.node);
  NodeList out;
  std::set_difference(s.begin(), s.end(), removed.begin(), removed.end(), std::back_inserter(out));
  return out;
}

// n = (M1 - M)/|M1 - M|; false (and an error) when M1 and M coincide at the scale of the model.
bool wall_normal(ModelBuilder& b, const KeywordRecord& r, model::RigidWall& w, double size) {
  const model::Vec3 axis = model::sub(w.m1, w.m);
  const double len = model::norm(axis);
  if (len > 1e-12 * size && len > 0) {
    w.normal = model::scale(axis, 1.0 / len);
    return true;
  }
  b.error_at(
      r, "XM1", Diag::InconsistentValues,
      "M1 = " + point_text(w.m1) + " and M = " + point_text(w.m) +
          (w.node != kNone ? " (the wall node)" : "") + " coincide (|M1 - M| = " + number_text(len) +
          "): the wall normal (M1 - M)/|M1 - M| is undefined; M1 must be a distinct point on the side the "
          "wall acts on");
  return false;
}

// /RWALL/PARAL: n = (M1 - M) x (M2 - M) / |...|; false (and an error) when the corners are aligned at the
// scale of the model.
bool parallelogram_normal(ModelBuilder& b, const KeywordRecord& r, model::RigidWall& w, double size) {
  const model::Vec3 n = model::cross(model::sub(w.m1, w.m), model::sub(w.m2, w.m));
  const double area = model::norm(n);
  if (area > 1e-12 * size * size && area > 0) {
    w.normal = model::scale(n, 1.0 / area);
    return true;
  }
  b.error_at(r, "XM2", Diag::InconsistentValues,
             "M = " + point_text(w.m) + (w.node != kNone ? " (the wall node)" : "") +
                 ", M1 = " + point_text(w.m1) + " and M2 = " + point_text(w.m2) +
                 " are aligned (|(M1 - M) x (M2 - M)| = " + number_text(area) +
                 "): the parallelogram has no area and no normal; M1 and M2 must be the corners next to M");
  return false;
}

model::RigidWall make_rigid_wall(ModelBuilder& b, const KeywordRecord& r, double size, int shape) {
  model::RigidWall w;
  w.shape = shape;
  bool placed = true;  // M is known
  if (const std::int64_t node = r.get_int("node_ID"); node != 0) {
    w.node = b.node_ref(node, r, field_pos(r, "node_ID"), "node_ID (node carrying the moving wall)");
    placed = w.node != kNone;
    if (placed) {
      b.node_used_[w.node] = 1;
      w.m = node_point(b.m_.nodes, w.node);
    }
    w.mass = mass_field(b, r, "added to the wall node");
    w.v0 = b.submodel_vector(r, reals3(r, "VX0", "VY0", "VZ0"));
  } else {
    w.m = b.submodel_point(r, reals3(r, "XM", "YM", "ZM"));
  }
  w.slide = geti(r, "Slide");
  w.iform = geti(r, "Iform");
  w.ifq = geti(r, "ifq");
  w.group1 = group_ref(b, r, "grnd_ID1", true);
  w.group2 = group_ref(b, r, "grnd_ID2", true);
  w.distance = r.get_real("d");
  if (w.distance < 0)
    b.error_at(
        r, "d", Diag::ValueOutOfRange,
        "d = " + number_text(w.distance) +
            " is negative; it is the search distance on the positive side of the wall; accepted: 0 (no "
            "search) or > 0");
  w.friction = r.get_real("fric");
  w.diameter = r.get_real("Diameter");
  w.ffac = r.get_real("ffac");
  w.m1 = b.submodel_point(r, reals3(r, "XM1", "YM1", "ZM1"));
  if (shape == 3) w.m2 = b.submodel_point(r, reals3(r, "XM2", "YM2", "ZM2"));
  // A sphere has no axis: its normal is radial at each node (the engine computes it).
  const bool oriented = shape == 2   ? true
                        : shape == 3 ? parallelogram_normal(b, r, w, size)
                                     : wall_normal(b, r, w, size);
  const bool defined = placed && oriented && (shape == 0 || shape == 3 || w.diameter > 0);
  w.secondary = wall_secondary(b, w, defined);
  if (defined && w.secondary.empty())
    b.warning_at(
        r, "grnd_ID1", Diag::EmptyGroup,
        "the rigid wall has no secondary node (grnd_ID1, plus the nodes within d = " +
            number_text(w.distance) +
            " on the positive side, minus grnd_ID2, is empty): it acts on nothing; give a grnd_ID1 group or "
            "a search distance d > 0");
  return w;
}

// ---------------------------------------------------------------------------------------------------------
// Rigid bodies

// A body with a sensor (OpenRadioss hm_read_rbody.F, inirby.F INIRBYS, rbyonf.F RBYSENS): rigid from the
// start, formed from its secondary nodes alone (main node at their centre of mass; the main node's own mass,
// Mass, Jxx..Jxz, skew_ID and ICoG are not used), released 2 cycles after the sensor switches on. When the
// sensor switches off again (its Tstop) Radioss forms the body again from the current positions and
// velocities: radx does not, and refuses that use.
void check_sensor_body(ModelBuilder& b, const KeywordRecord& r, const model::RigidBody& rb) {
  const auto it = b.sensor_ids_.find(rb.sensor);
  if (it == b.sensor_ids_.end()) return;  // reported by sensor_ref
  const model::Sensor& sensor = b.m_.sensors[static_cast<std::size_t>(it->second)];
  if (sensor.t_stop < model::kNever)
    b.error_at(r, "sens_ID", Diag::PhysicsNotImplemented,
               "sens_ID = " + std::to_string(rb.sensor) + ": /SENSOR/TIME/" + std::to_string(rb.sensor) +
                   " switches off again at Tstop = " + number_text(sensor.t_stop) +
                   ", when Radioss forms the released rigid body again from the current positions and "
                   "velocities; radx does not re-form a rigid body: use a sensor without Tstop (the body is "
                   "then released once, for the rest of the run)");
  std::string unused;
  auto add = [&](const std::string& what) { unused += (unused.empty() ? "" : ", ") + what; };
  if (rb.mass != 0) add("Mass = " + number_text(rb.mass));
  if (std::any_of(rb.inertia.begin(), rb.inertia.end(), [](double j) { return j != 0; })) add("Jxx..Jxz");
  if (rb.skew != 0) add("skew_ID = " + std::to_string(rb.skew));
  if (rb.icog == 3 || rb.icog == 4) add("ICoG = " + std::to_string(rb.icog));
  if (!unused.empty())
    b.warning_at(
        r, "sens_ID", Diag::UnimplementedOption,
        unused +
            " not used: a rigid body with a sensor is formed from its secondary nodes alone, its main "
            "node at their centre of mass (as Radioss does)");
}

// Whether node n is a node of an element that gives nodes rotational inertia (shells, beams, springs).
bool node_of_rotational_element(const model::Model& m, std::int32_t n) {
  for (const auto* block : {&m.shells, &m.shells3, &m.beams, &m.springs})
    if (std::find(block->conn.begin(), block->conn.end(), n) != block->conn.end()) return true;
  return false;
}

// A body with no secondary node, no added inertia and a main node that no shell, beam or spring gives
// inertia cannot turn: Radioss's starter stops on it (its error 274); the engine would stop at its start.
void check_body_inertia(ModelBuilder& b, const KeywordRecord& r, const model::RigidBody& rb) {
  if (rb.sensor != 0 || rb.main_node == kNone || rb.group == kNone || !rb.secondary.empty()) return;
  if (rb.inertia[0] > 0 || rb.inertia[1] > 0 || rb.inertia[2] > 0) return;
  if (node_of_rotational_element(b.m_, rb.main_node)) return;
  b.error_at(r, "grnd_ID", Diag::RequiredValueMissing,
             "the rigid body has no secondary node, no added inertia (Jxx, Jyy, Jzz) and a main node of no "
             "shell, beam or spring: it has no rotational inertia (Radioss stops on it too, its error 274); "
             "give secondary nodes in grnd_ID or the inertia");
}

model::RigidBody make_rigid_body(ModelBuilder& b, const KeywordRecord& r) {
  model::RigidBody rb;
  if (const std::int64_t node = r.get_int("node_ID"); node == 0) {
    b.error_at(
        r, "node_ID", Diag::RequiredIdMissing,
        "node_ID is blank or 0: radx does not create main nodes automatically (Radioss does); give the id "
        "of a main node, usually a node of no element (ICoG 1 and 2 move it to the centre of gravity)");
  } else {
    rb.main_node = b.node_ref(node, r, field_pos(r, "node_ID"), "node_ID (main node of the rigid body)");
    if (rb.main_node != kNone) b.node_used_[rb.main_node] = 1;
  }
  rb.sensor = b.sensor_ref(r, "sens_ID");
  // With a sensor the added inertia is not used, so neither is its frame.
  // The frame of the added inertia Jxx..Jxz (with a sensor the inertia is not used, nor its frame).
  rb.skew = rb.sensor != 0 ? r.get_int("skew_ID") : skew_ref(b, r);
  rb.ispher = int_or(r, "Ispher", 2);
  rb.mass = mass_field(b, r, "added to the main node");
  rb.group = group_ref(b, r, "grnd_ID", false);
  rb.ikrem = geti(r, "Ikrem");
  rb.icog = int_or(r, "ICoG", 1);
  rb.surface = lookup(b, b.surf_ids_, r, "surf_ID", "surface", "/SURF", true);
  static constexpr std::array<std::string_view, 6> kInertia = {"Jxx", "Jyy", "Jzz", "Jxy", "Jyz", "Jxz"};
  for (std::size_t k = 0; k < kInertia.size(); ++k) rb.inertia[k] = r.get_real(kInertia[k]);
  if (rb.sensor == 0 && rb.skew != 0) {
    const auto it = b.skew_ids_.find(rb.skew);
    if (it != b.skew_ids_.end() && static_cast<std::size_t>(it->second) < b.m_.skews.size())
      rb.inertia = inertia_in_global_axes(rb.inertia, b.m_.skews[static_cast<std::size_t>(it->second)].axes);
  }
  if (rb.sensor != 0) check_sensor_body(b, r, rb);
  rb.ioptoff = geti(r, "Ioptoff");
  rb.iexpams = geti(r, "Iexpams");
  rb.ifail = geti(r, "Ifail");
  rb.fn = real_or(r, "FN", 1e20);
  rb.ft = real_or(r, "FT", 1e20);
  rb.exp_n = real_or(r, "expN", 2.0);
  rb.exp_t = real_or(r, "expT", 2.0);
  const NodeList& group = nodes_of(b, rb.group);
  std::copy_if(group.begin(), group.end(), std::back_inserter(rb.secondary),
               [&](std::int32_t n) { return n != rb.main_node; });
  // Nodes carried by a rigid body take part in the run even without elements (lumped masses).
  for (auto n : rb.secondary) b.node_used_[n] = 1;
  if (!group.empty() && rb.secondary.empty())
    b.warning_at(
        r, "grnd_ID", Diag::EmptyGroup,
        "grnd_ID holds only the main node, which is removed from the secondary nodes: the rigid body "
        "drives no node");
  check_body_inertia(b, r, rb);
  return rb;
}

// ---------------------------------------------------------------------------------------------------------
// Time histories: the accepted names per kind (docs/keywords.md /TH/*, docs/theory/results-format.md
// section 7).

struct ThGroup {
  std::string_view name;
  std::vector<std::string_view> variables;
};
// A variable radx accepts but does not compute: written as 0 (solver/outputs/time_history_values.hpp), and
// the starter warns naming it and why.
struct ThZero {
  std::string_view name;
  std::string_view why;
};
struct ThKindDef {
  std::string_view path;
  model::ThKind kind;
  std::string_view object;              // what an id names, for messages
  std::string_view target;              // the keyword defining those objects
  std::vector<ThGroup> groups;          // DEF first
  std::vector<std::string_view> names;  // single variables
  std::vector<ThZero> zero;             // of `names`, those written as 0
};

// Names and DEF sets as OpenRadioss defines them (its starter's /TH variable tables; docs/keywords.md /TH),
// one function for each kind whose table is long.
ThKindDef th_node_kind() {
  return {"/TH/NODE",
          model::ThKind::Node,
          "node",
          "/NODE",
          {{"DEF", {"DX", "DY", "DZ", "VX", "VY", "VZ"}},
           {"D", {"DX", "DY", "DZ"}},
           {"V", {"VX", "VY", "VZ"}},
           {"A", {"AX", "AY", "AZ"}},
           {"VR", {"VRX", "VRY", "VRZ"}},
           {"AR", {"ARX", "ARY", "ARZ"}},
           {"XYZ", {"X", "Y", "Z"}}},
          {"DX",  "DY",  "DZ",  "VX",    "VY",    "VZ",    "AX",     "AY",     "AZ",
           "VRX", "VRY", "VRZ", "ARX",   "ARY",   "ARZ",   "DRX",    "DRY",    "DRZ",
           "X",   "Y",   "Z",   "REACX", "REACY", "REACZ", "REACXX", "REACYY", "REACZZ"},
          {{"DRX", "rotation angles are not integrated"},
           {"DRY", "rotation angles are not integrated"},
           {"DRZ", "rotation angles are not integrated"}}};
}

ThKindDef th_rbody_kind() {
  static const std::vector<std::string_view> kRbody = {
      "FX",  "FY",  "FZ",  "MX",  "MY",  "MZ",   "RX",  "RY",  "RZ",  "FXI", "FYI", "FZI", "MXI",   "MYI",
      "MZI", "X",   "Y",   "Z",   "DX",  "DY",   "DZ",  "VX",  "VY",  "VZ",  "AX",  "AY",  "AZ",    "VRX",
      "VRY", "VRZ", "ARX", "ARY", "ARZ", "MASS", "IXX", "IYY", "IZZ", "IXY", "IYZ", "IZX", "STATUS"};
  static const std::string_view kNoType14 =
      "forces of TYPE14 and TYPE15 interfaces, which radx does not have";
  return {"/TH/RBODY",
          model::ThKind::Rbody,
          "rigid body",
          "/RBODY",
          {{"DEF", {"FX", "FY", "FZ", "MX", "MY", "MZ", "RX", "RY", "RZ"}},
           {"F", {"FX", "FY", "FZ"}},
           {"M", {"MX", "MY", "MZ"}},
           {"R", {"RX", "RY", "RZ"}},
           {"FI", {"FXI", "FYI", "FZI"}},
           {"MI", {"MXI", "MYI", "MZI"}},
           {"D", {"DX", "DY", "DZ"}},
           {"V", {"VX", "VY", "VZ", "VRX", "VRY", "VRZ"}},
           {"A", {"AX", "AY", "AZ", "ARX", "ARY", "ARZ"}},
           {"XYZ", {"X", "Y", "Z"}}},
          kRbody,
          {{"FXI", kNoType14},
           {"FYI", kNoType14},
           {"FZI", kNoType14},
           {"MXI", kNoType14},
           {"MYI", kNoType14},
           {"MZI", kNoType14}}};
}

// OpenRadioss's DEF set and groups (hm_read_thgrou.F); of its 39 names radx computes the forces,
// moments and centre, not the work, kinetic energies and cut-file errors.
ThKindDef th_section_kind() {
  return {"/TH/SECTIO",
          model::ThKind::Section,
          "section",
          "/SECT",
          {{"DEF", {"FNX", "FNY", "FNZ", "FTX", "FTY", "FTZ", "M1", "M2", "M3"}},
           {"FN", {"FNX", "FNY", "FNZ"}},
           {"FT", {"FTX", "FTY", "FTZ"}},
           {"M", {"M1", "M2", "M3"}},
           {"CENTER", {"CX", "CY", "CZ"}},
           {"GLOBAL", {"FNX", "FNY", "FNZ", "FTX", "FTY", "FTZ", "MX", "MY", "MZ"}},
           {"LOCAL", {"M1", "M2", "M3", "F1", "F2", "F3"}}},
          {"FNX", "FNY", "FNZ", "FTX", "FTY", "FTZ", "M1", "M2", "M3", "MX", "MY", "MZ", "F1", "F2", "F3",
           "CX", "CY", "CZ"},
          {}};
}

// OpenRadioss's spring names (hm_read_thgrou.F): on a TYPE4 spring FX is the axial force (> 0 in tension)
// and LX the elongation; the other directions and the moments are those of 6-dof springs. DEF is the only
// group name: OpenRadioss refuses F, M, L and R on /TH/SPRING, so radx does too.
ThKindDef th_spring_kind() {
  static const std::string_view kAxialSpring =
      "a TYPE4 spring is axial: FX and LX only (TYPE8 and TYPE13 springs write them)";
  return {"/TH/SPRING",
          model::ThKind::Spring,
          "spring",
          "/SPRING",
          {{"DEF", {"OFF", "FX", "LX", "IE"}}},
          {"OFF", "FX", "FY", "FZ", "MX", "MY", "MZ", "LX", "LY", "LZ", "RX", "RY", "RZ", "IE"},
          {{"FY", kAxialSpring},
           {"FZ", kAxialSpring},
           {"MX", kAxialSpring},
           {"MY", kAxialSpring},
           {"MZ", kAxialSpring},
           {"LY", kAxialSpring},
           {"LZ", kAxialSpring},
           {"RX", kAxialSpring},
           {"RY", kAxialSpring},
           {"RZ", kAxialSpring}}};
}

const std::vector<ThKindDef>& th_kinds() {
  using K = model::ThKind;
  static const std::vector<std::string_view> kForces = {"FNX", "FNY", "FNZ", "FTX", "FTY", "FTZ"};
  static const std::vector<std::string_view> kPart = {"IE",   "KE", "XMOM",   "YMOM", "ZMOM",
                                                      "MASS", "HE", "ERODED", "HEAT"};
  static const std::vector<std::string_view> kShell = {"F1",  "F2",  "F12", "M1",   "M2",  "M12",
                                                       "IEM", "IEB", "OFF", "EMIN", "EMAX"};
  // Single names beyond the DEF set: the element's filtered equivalent strain rate and its thickness.
  static const std::vector<std::string_view> kShellNames = {
      "F1", "F2", "F12", "M1", "M2", "M12", "IEM", "IEB", "OFF", "EMIN", "EMAX", "EPSD", "THIC"};
  static const std::vector<ThZero> kShellZero = {{"IEB", "the bending share of the shell energy"},
                                                 {"EMIN", "strains are not kept"},
                                                 {"EMAX", "strains are not kept"}};
  static const std::vector<std::string_view> kStress = {"SX", "SY", "SZ", "SXY", "SYZ", "SXZ"};
  static const std::vector<std::string_view> kBrickDef = {"OFF", "SX", "SY",   "SZ",   "SXY", "SYZ",
                                                          "SXZ", "IE", "DENS", "PLAS", "TEMP"};
  static const std::vector<std::string_view> kBrick = {"OFF",  "SX",   "SY",   "SZ",   "SXY", "SYZ",
                                                       "SXZ",  "IE",   "DENS", "BULK", "VOL", "PLAS",
                                                       "TEMP", "PLSR", "VX",   "VY",   "VZ"};
  static const std::vector<ThKindDef> kinds = {
      th_node_kind(),
      {"/TH/PART", K::Part, "part", "/PART", {{"DEF", kPart}}, kPart, {}},
      {"/TH/SUBS", K::Subset, "subset", "/SUBSET", {{"DEF", kPart}}, kPart, {}},
      {"/TH/INTER",
       K::Inter,
       "interface",
       "/INTER",
       {{"DEF", kForces}, {"FN", {"FNX", "FNY", "FNZ"}}, {"FT", {"FTX", "FTY", "FTZ"}}},
       {"FNX", "FNY", "FNZ", "FTX", "FTY", "FTZ", "CE_ELAST", "CE_FRIC", "CE_DAMP"},
       {}},
      {"/TH/RWALL", K::Rwall, "rigid wall", "/RWALL", {{"DEF", kForces}}, kForces, {}},
      {"/TH/SHEL", K::Shell, "4-node shell", "/SHELL", {{"DEF", kShell}}, kShellNames, kShellZero},
      {"/TH/SH3N", K::Shell3, "3-node shell", "/SH3N", {{"DEF", kShell}}, kShellNames, kShellZero},
      {"/TH/BRIC",
       K::Brick,
       "brick",
       "/BRICK",
       {{"DEF", kBrickDef}, {"STRESS", kStress}},
       kBrick,
       {{"TEMP", "radx has no thermal analysis"}}},
      th_rbody_kind(),
      th_section_kind(),
      // AX AY AZ: the filtered acceleration on the skew axes; WX WY WZ: the velocity integrated from the
      // unfiltered acceleration on the same axes (OpenRadioss's names and sets: DEF is the accelerations).
      {"/TH/ACCEL",
       K::Accel,
       "accelerometer",
       "/ACCEL",
       {{"DEF", {"AX", "AY", "AZ"}}, {"W", {"WX", "WY", "WZ"}}},
       {"AX", "AY", "AZ", "WX", "WY", "WZ"},
       {}},
      th_spring_kind(),
      // OpenRadioss's truss names (hm_read_thgrou.F, thtrus.F): F the axial force (> 0 in tension), IE the
      // work of that force, A the current area, L the initial length, PLAS the plastic strain.
      {"/TH/TRUSS",
       K::Truss,
       "truss",
       "/TRUSS",
       {{"DEF", {"OFF", "F", "IE", "PLAS"}}},
       {"OFF", "F", "IE", "A", "L", "PLAS"},
       {}},
      // OpenRadioss's type-3 beam names (hm_read_thgrou.F): the section's resultants in the beam's frame, the
      // work of the section and the plastic strain.
      {"/TH/BEAM",
       K::Beam,
       "beam",
       "/BEAM",
       {{"DEF", {"OFF", "F1", "F2", "F3", "M1", "M2", "M3", "IE"}}},
       {"OFF", "F1", "F2", "F3", "M1", "M2", "M3", "IE", "EPSP"},
       {}},
  };
  return kinds;
}

// "IEB (the bending share of the shell energy), EMIN EMAX (strains are not kept)": the requested
// variables radx writes as 0, grouped by reason in the order of the request.
std::string zero_variables_text(const ThKindDef& k, const std::vector<std::string>& variables) {
  std::vector<std::pair<std::string_view, std::string>> by_reason;
  for (const auto& v : variables) {
    const auto z = std::find_if(k.zero.begin(), k.zero.end(), [&](const ThZero& x) { return x.name == v; });
    if (z == k.zero.end()) continue;
    const auto r =
        std::find_if(by_reason.begin(), by_reason.end(), [&](const auto& p) { return p.first == z->why; });
    if (r == by_reason.end())
      by_reason.emplace_back(z->why, v);
    else
      r->second += " " + v;
  }
  std::string out;
  for (const auto& [why, names] : by_reason)
    out += (out.empty() ? "" : ", ") + names + " (" + std::string(why) + ")";
  return out;
}

std::string accepted_th_names(const ThKindDef& k) {
  std::string groups, names;
  for (const auto& g : k.groups) groups += (groups.empty() ? "" : ", ") + std::string(g.name);
  for (const auto& n : k.names) names += (names.empty() ? "" : ", ") + std::string(n);
  return "groups " + groups + "; variables " + names;
}

std::vector<std::string> th_variables(ModelBuilder& b, const KeywordRecord& r, const ThKindDef& k) {
  std::vector<std::string> out;
  auto add = [&](std::string_view v) {
    if (std::find(out.begin(), out.end(), v) == out.end()) out.emplace_back(v);
  };
  for (const auto& name : r.th_variables) {
    const auto g =
        std::find_if(k.groups.begin(), k.groups.end(), [&](const ThGroup& x) { return x.name == name; });
    if (g != k.groups.end()) {
      for (const auto v : g->variables) add(v);
    } else if (std::find(k.names.begin(), k.names.end(), name) != k.names.end()) {
      add(name);
    } else {
      b.diags_.error(Diag::ValueOutOfRange, b.at(r.pos, 1), ModelBuilder::about(r),
                     "unknown " + std::string(k.path) + " variable '" + name +
                         "' in the variable lines; accepted: " + accepted_th_names(k));
    }
  }
  if (r.th_variables.empty())
    b.diags_.error(
        Diag::RequiredValueMissing, b.at(r.pos, 1), ModelBuilder::about(r),
        "no variable names: the line after the title lists the variables, 10 columns each (DEF for the "
        "default set); accepted: " +
            accepted_th_names(k));
  return out;
}

std::int32_t th_object(const ModelBuilder& b, model::ThKind kind, std::int64_t id) {
  auto in = [id](const IdIndex& index) {
    const auto it = index.find(id);
    return it == index.end() ? kNone : it->second;
  };
  switch (kind) {
    case model::ThKind::Node: return b.m_.nodes.index.find(id);  // -1 when unknown, = kNone
    case model::ThKind::Part: return in(b.part_ids_);
    case model::ThKind::Inter: return in(b.inter_ids_);
    case model::ThKind::Rwall: return in(b.rwall_ids_);
    case model::ThKind::Shell: return b.m_.shells.index.find(id);
    case model::ThKind::Subset: return in(b.subset_ids_);
    case model::ThKind::Brick: {
      // 20-node bricks after the 8-node ones (model::TimeHistoryGroup::objects)
      const auto e = b.m_.bricks.index.find(id);
      if (e >= 0) return e;
      const auto e20 = b.m_.bricks20.index.find(id);
      return e20 < 0 ? kNone : static_cast<std::int32_t>(b.m_.bricks.size()) + e20;
    }
    case model::ThKind::Shell3: return b.m_.shells3.index.find(id);
    case model::ThKind::Rbody: return in(b.rbody_ids_);
    case model::ThKind::Section: return in(b.sect_ids_);
    case model::ThKind::Accel: return in(b.accel_ids_);
    case model::ThKind::Spring: return b.m_.springs.index.find(id);
    case model::ThKind::Truss: return b.m_.trusses.index.find(id);
    case model::ThKind::Beam: return b.m_.beams.index.find(id);
  }
  return kNone;
}

// The objects of a /TH group, and for /TH/NODE the skew of each (g.skews). /TH/SHEL and /TH/SH3N accept
// only the global axes (radx does not turn shell results into a skew).
void th_objects(ModelBuilder& b, const KeywordRecord& r, const ThKindDef& k, model::TimeHistoryGroup& g) {
  std::vector<std::int32_t>& out = g.objects;
  bool missing = false;
  auto take = [&](std::int64_t id, SourcePos pos) {
    const auto o = th_object(b, k.kind, id);
    if (o != kNone) {
      out.push_back(o);
      return;
    }
    // A tied interface (TYPE2) has no contact forces radx records: the output is left out, the run goes on.
    if (k.kind == model::ThKind::Inter) {
      const auto t2 = b.deck_.of("/INTER/TYPE2");
      if (std::any_of(t2.begin(), t2.end(), [id](const KeywordRecord* t) { return t->id == id; })) {
        b.diags_.warning(
            Diag::OutputNotWritten, b.at(pos, 1), ModelBuilder::about(r),
            "interface " + std::to_string(id) +
                " is an /INTER/TYPE2: radx writes no time history of tied interfaces; the run goes "
                "on without it");
        return;
      }
    }
    // Radioss records a tetrahedron under /TH/BRIC (it stores tetrahedra as bricks); radx writes no time
    // history of tetrahedra: the output is left out by name, the run goes on.
    if (k.kind == model::ThKind::Brick && b.m_.tetras.index.find(id) >= 0) {
      b.diags_.warning(
          Diag::OutputNotWritten, b.at(pos, 1), ModelBuilder::about(r),
          "element " + std::to_string(id) +
              " is a /TETRA4: radx writes no time history of tetrahedra; the run goes on without it");
      return;
    }
    missing = true;
    // Radioss stops on a missing node or element (its errors 78 and 69) but leaves a missing part, subset,
    // interface, wall, body, section or accelerometer out with a warning (257, 1610).
    const bool named_object = k.kind == model::ThKind::Part || k.kind == model::ThKind::Subset ||
                              k.kind == model::ThKind::Inter || k.kind == model::ThKind::Rwall ||
                              k.kind == model::ThKind::Rbody || k.kind == model::ThKind::Section ||
                              k.kind == model::ThKind::Accel;
    const std::string text = std::string(k.object) + " " + std::to_string(id) + " does not exist: no " +
                             std::string(k.target) + " defines it";
    if (named_object)
      b.diags_.warning(Diag::MissingReference, b.at(pos, 1), ModelBuilder::about(r),
                       text + "; it is left out, as Radioss does");
    else
      b.diags_.error(Diag::MissingReference, b.at(pos, 1), ModelBuilder::about(r), text);
  };
  if (r.decl->tail == schema::Tail::ThVarsThenRecords) {
    const auto& t = r.records;
    const int cid = t.column("id"), cskew = t.column("skew_ID");
    for (std::size_t i = 0; cid >= 0 && i < t.size(); ++i) {
      const std::size_t before = out.size();
      take(t.ints[cid][i], t.pos[i]);
      const std::int64_t skew = cskew >= 0 ? t.ints[cskew][i] : 0;
      if (k.kind == model::ThKind::Node && out.size() > before) g.skews.push_back(skew);
      // A TH skew_ID may name a frame (Radioss looks among the skews, then the frames, hm_read_thgrou.F);
      // radx writes a node in a /FRAME/FIX but not in a /FRAME/MOV, whose velocities Radioss gives relative
      // to the moving frame (the frame's own velocity and rotation taken out), which radx does not compute.
      const KeywordRecord* f = b.frame_ids_.count(skew) != 0 ? frame_record(b, skew) : nullptr;
      if (f && k.kind == model::ThKind::Node) {
        if (f->decl->path == std::string_view("/FRAME/MOV"))
          b.diags_.error(Diag::UnimplementedOption, b.at(t.pos[i], 11), ModelBuilder::about(r),
                         "skew_ID = " + std::to_string(skew) + " names /FRAME/MOV/" + std::to_string(skew) +
                             ": radx does not write a node's motion relative to a moving frame; give a "
                             "/FRAME/FIX, a /SKEW/MOV (the same axes, absolute motion) or 0");
      } else if (auto text = f ? std::string() : missing_skew_text(b, "skew_ID", skew); !text.empty()) {
        b.diags_.error(Diag::MissingReference, b.at(t.pos[i], 11), ModelBuilder::about(r), std::move(text));
      } else if (skew != 0 && k.kind != model::ThKind::Node) {
        b.diags_.error(Diag::UnimplementedOption, b.at(t.pos[i], 11), ModelBuilder::about(r),
                       "skew_ID = " + std::to_string(skew) + ": radx writes " + std::string(k.object) +
                           " results in the element frame only, not in a skew or frame; leave skew_ID blank "
                           "or 0");
      }
    }
  } else {
    for (std::size_t i = 0; i < r.ids.size(); ++i) take(r.ids[i], r.id_pos[i]);
  }
  if (out.empty() && !missing)
    b.diags_.warning(Diag::EmptyGroup, b.at(r.pos, 1), ModelBuilder::about(r),
                     std::string(k.path) + " lists no " + std::string(k.object) +
                         ": nothing will be written for it; give the ids after the variable lines");
}

}  // namespace

void ModelBuilder::build_sensors() {
  build_each(*this, "/SENSOR/TIME", "sensor", m_.sensors, sensor_ids_, [&](const KeywordRecord& r) {
    model::Sensor s;
    s.type = model::SensorType::Time;
    s.t_delay = r.get_real("Tdelay");
    if (const double t_stop = r.get_real("Tstop"); t_stop != 0) {
      s.t_stop = t_stop;
      if (t_stop <= s.t_delay)
        error_at(r, "Tstop", Diag::InconsistentValues,
                 "Tstop = " + number_text(t_stop) + " is not after Tdelay = " + number_text(s.t_delay) +
                     ": the sensor would switch off as it switches on; need Tstop > Tdelay (0 = never)");
    }
    return s;
  });
}

std::int64_t ModelBuilder::sensor_ref(const KeywordRecord& r, std::string_view field) {
  ref(sensor_ids_, r, field, "sensor", "/SENSOR", true);
  return r.get_int(field);
}

void ModelBuilder::build_loads() {
  build_added_masses(*this);
  build_accelerometers(*this);
  build_bcs(*this);
  build_ale_bcs(*this);
  build_imposed_velocities(*this);
  build_imposed_final_geometries(*this);
  build_initial_velocities(*this);
  build_concentrated_loads(*this);
  build_pressure_loads(*this);
  build_gravities(*this);
}

void ModelBuilder::build_rigid_walls() {
  const double size = model_size(m_.nodes);
  // One id space for the wall shapes.
  for (const auto& [path, shape] :
       {std::pair{"/RWALL/PLANE", 0}, {"/RWALL/CYL", 1}, {"/RWALL/SPHER", 2}, {"/RWALL/PARAL", 3}})
    build_each(
        *this, path, "rigid wall", m_.rigid_walls, rwall_ids_,
        // A copy: clang before 16 cannot capture a structured binding (scripts/fuzz.sh builds with it).
        [&, shape = shape](const KeywordRecord& r) { return make_rigid_wall(*this, r, size, shape); });
}

void ModelBuilder::build_rigid_bodies() {
  build_each(*this, "/RBODY", "rigid body", m_.rigid_bodies, rbody_ids_,
             [&](const KeywordRecord& r) { return make_rigid_body(*this, r); });
}

void ModelBuilder::build_time_histories() {
  const auto& kinds = th_kinds();
  std::vector<IdIndex> ids(kinds.size());
  std::vector<FirstPos> first(kinds.size());
  for (const auto& r : deck_.records) {
    const auto k =
        std::find_if(kinds.begin(), kinds.end(), [&](const ThKindDef& d) { return d.path == r.decl->path; });
    if (k == kinds.end()) continue;
    model::TimeHistoryGroup g;
    g.id = r.id;
    g.title = r.title;
    g.kind = k->kind;
    g.variables = th_variables(*this, r, *k);
    if (const auto zero = zero_variables_text(*k, g.variables); !zero.empty())
      diags_.warning(Diag::UnimplementedOption, at(r.pos, 1), about(r),
                     "radx does not compute " + zero + ": written as 0 in the time history");
    th_objects(*this, r, *k, g);
    const auto i = static_cast<std::size_t>(k - kinds.begin());
    const std::string what = std::string(k->path) + " group";
    if (register_id(ids[i], g.id, static_cast<std::int32_t>(m_.time_histories.size()), r, what, first[i]))
      m_.time_histories.push_back(std::move(g));
  }
}

}  // namespace detail
}  // namespace radx
