// The checks of a model read from a model file (io/hdf5/model_file_checks.hpp). One stage per section of
// the model, in the order of docs/model-file.md: nodes and masses, element blocks, materials and
// properties, parts and groups, surfaces and functions, conditions and loads, walls and bodies, frames and
// outputs, interfaces. Every stage reports each bad entry with the dataset that holds it.
//
// What is checked, and why the engine needs it:
// - a dense index (node, element, part, material, property, group, surface, function, skew, subset) lies in
//   its collection, or is -1 where the field may say "none": the engine indexes arrays with it unchecked;
// - the arrays of one record agree in length (a CSR column per member, each with its own offsets): the
//   engine walks them in parallel;
// - user ids are positive and unique where the engine or the outputs look objects up by id, and a skew,
//   frame or sensor user id names one the model has;
// - an enum code is one of its values: the engine switches on it;
// - every real is finite, and masses, densities, moduli, thicknesses and areas are not negative; the nodal
//   masses are not all zero: a run without mass has no step and no energies;
// - function abscissas increase strictly (solver/conditions/functions.hpp interpolates on them).
#include "io/hdf5/model_file_checks.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string_view>
#include <type_traits>
#include <utility>

#include "io/hdf5/model_schema.hpp"

namespace radx::io {

void ModelFileProblems::add(ModelFileCode code, std::string where, std::string message) {
  ++count;
  if (items.size() < kKept) items.push_back({code, std::move(where), std::move(message)});
}

namespace {

using model::kNone;
using model::Model;

// "dataset[row]" or "dataset[row, col]".
std::string entry(std::string_view dataset, std::size_t row, int col = -1) {
  std::string s(dataset);
  s += '[' + std::to_string(row);
  if (col >= 0) s += ", " + std::to_string(col);
  return s + ']';
}

std::string real_text(double v) {
  std::ostringstream os;
  os.precision(17);
  os << v;
  return os.str();
}

// std::array<double, K> and std::vector<double>: the members whose every value must be finite.
template <class M>
inline constexpr bool kIsRealArray = false;
template <std::size_t K>
inline constexpr bool kIsRealArray<std::array<double, K>> = true;
template <class M>
inline constexpr bool kIsRealVector = false;
template <>
inline constexpr bool kIsRealVector<std::vector<double>> = true;

// The record a value belongs to, as messages name it: "node group 5".
struct Owner {
  std::string_view kind;
  std::int64_t id = 0;
  [[nodiscard]] std::string text() const { return std::string(kind) + " " + std::to_string(id); }
};

// A collection an index points into: its size and how messages name its items.
struct Range {
  std::size_t size = 0;
  std::string_view items;  // "nodes"
};

// What one record of a table is called in messages: "material" for /radx/materials.
std::string_view record_kind(std::string_view table) {
  static constexpr std::pair<std::string_view, std::string_view> kKinds[] = {
      {"materials", "material"},
      {"properties", "property"},
      {"parts", "part"},
      {"subsets", "subset"},
      {"node_groups", "node group"},
      {"boxes", "box"},
      {"surfaces", "surface"},
      {"functions", "function"},
      {"bcs", "/BCS"},
      {"imposed_velocities", "/IMPVEL"},
      {"imposed_final_geometries", "/IMPDISP/FGEO"},
      {"initial_velocities", "/INIVEL"},
      {"concentrated_loads", "/CLOAD"},
      {"pressure_loads", "/PLOAD"},
      {"gravities", "/GRAV"},
      {"rigid_walls", "/RWALL"},
      {"rigid_bodies", "/RBODY"},
      {"added_masses", "/ADMAS"},
      {"skews", "skew"},
      {"sections", "/SECT"},
      {"accelerometers", "/ACCEL"},
      {"sensors", "/SENSOR"},
      {"time_histories", "/TH"},
      {"tied_interfaces", "/INTER/TYPE2"}};
  for (const auto& [t, kind] : kKinds)
    if (t == table) return kind;
  return table;
}

// Sorted user ids of a collection, for the references by user id (skew, sensor, frame).
template <class T>
std::vector<std::int64_t> sorted_ids(const std::vector<T>& recs) {
  std::vector<std::int64_t> ids;
  ids.reserve(recs.size());
  for (const auto& r : recs) ids.push_back(r.id);
  std::sort(ids.begin(), ids.end());
  return ids;
}

class Checker {
 public:
  Checker(const Model& m, ModelFileProblems& out)
      : m_(m), out_(out), skew_ids_(sorted_ids(m.skews)), sensor_ids_(sorted_ids(m.sensors)) {}

  void run() {
    check_nodes();
    check_node_masses();
    check_element_blocks();
    check_reals();
    check_materials();
    check_properties();
    check_parts_and_subsets();
    check_node_groups_and_boxes();
    check_surfaces();
    check_functions();
    check_kinematic_conditions();
    check_loads();
    check_rigid_walls();
    check_rigid_bodies();
    check_skews_and_sections();
    check_outputs();
    check_interfaces();
    check_tied_interfaces();
  }

 private:
  const Model& m_;
  ModelFileProblems& out_;
  std::vector<std::int64_t> skew_ids_, sensor_ids_;

  // ---- What each problem says

  void bad(std::string where, std::string message) {
    out_.add(ModelFileCode::BadReference, std::move(where), std::move(message));
  }
  void bad_value(std::string where, std::string message) {
    out_.add(ModelFileCode::BadValue, std::move(where), std::move(message));
  }

  // `value` indexes `range`; kNone is accepted when `optional`. True when it is valid.
  bool index(const std::string& where_ds, std::size_t row, int col, const Owner& o, std::string_view what,
             std::int64_t value, const Range& range, bool optional) {
    if (value >= 0 && static_cast<std::size_t>(value) < range.size) return true;
    if (optional && value == kNone) return true;
    bad(entry(where_ds, row, col), o.text() + ": " + std::string(what) + " " + std::to_string(value) +
                                       " is out of range; expected 0 to " +
                                       std::to_string(static_cast<std::int64_t>(range.size) - 1) + " (" +
                                       std::to_string(range.size) + " " + std::string(range.items) + ")" +
                                       (optional ? ", or -1 for none" : ""));
    return false;
  }

  // Every entry of a CSR column of indices; `base` is the position of the record's first value.
  void indices(const std::string& ds, std::size_t base, const Owner& o, std::string_view what,
               const std::vector<std::int32_t>& v, const Range& range) {
    for (std::size_t k = 0; k < v.size(); ++k) index(ds, base + k, -1, o, what, v[k], range, false);
  }

  // A user id reference: 0 (none) or an id of `ids` (sorted).
  void user_id(const std::string& where, const Owner& o, std::string_view what, std::int64_t id,
               const std::vector<std::int64_t>& ids, std::string_view kinds) {
    if (id == 0 || std::binary_search(ids.begin(), ids.end(), id)) return;
    bad(where, o.text() + ": " + std::string(what) + " " + std::to_string(id) + " names no " +
                   std::string(kinds) + " of the model; expected one of its ids, or 0 for none");
  }
  void skew_id(const std::string& where, const Owner& o, std::string_view what, std::int64_t id) {
    user_id(where, o, what, id, skew_ids_, "skew or frame");
  }
  void sensor_id(const std::string& where, const Owner& o, std::string_view what, std::int64_t id) {
    user_id(where, o, what, id, sensor_ids_, "sensor");
  }

  // Two parallel arrays of one record, or an array and the count it must have.
  void same_size(const std::string& where, const Owner& o, std::string_view what, std::size_t have,
                 std::size_t want, std::string_view want_what) {
    if (have == want) return;
    bad(where, o.text() + ": " + std::string(what) + " has " + std::to_string(have) + " entries; expected " +
                   std::to_string(want) + " (" + std::string(want_what) + ")");
  }

  // A code of a closed set, as stored.
  void code(const std::string& where, const Owner& o, std::string_view what, int value,
            std::initializer_list<int> valid, std::string_view meaning) {
    if (std::find(valid.begin(), valid.end(), value) != valid.end()) return;
    bad(where, o.text() + ": " + std::string(what) + " " + std::to_string(value) +
                   " is not a valid code; expected " + std::string(meaning));
  }

  void not_negative(const std::string& where, const Owner& o, std::string_view what, double v) {
    if (v >= 0) return;  // NaN is reported by check_reals
    bad_value(where,
              o.text() + ": " + std::string(what) + " " + real_text(v) + " is negative; expected >= 0");
  }

  // Ids of a collection: positive (or 0 where `zero_allowed`: objects the starter makes without an id),
  // and each non-zero one once.
  void unique_ids(const std::string& ds, std::string_view kind, const std::vector<std::int64_t>& ids,
                  bool zero_allowed) {
    bool all_positive = true;
    for (std::size_t i = 0; i < ids.size(); ++i) {
      if (ids[i] > 0) continue;
      all_positive = false;
      if (ids[i] < 0 || !zero_allowed)
        bad(entry(ds, i),
            std::string(kind) + " id " + std::to_string(ids[i]) + " is not a valid id; expected > 0");
    }
    // The usual case in O(n): the map the reader builds anyway takes every id once.
    std::int64_t duplicate = 0;
    if (all_positive && model::IdMap().build(ids, duplicate)) return;
    std::vector<std::pair<std::int64_t, std::size_t>> sorted;
    sorted.reserve(ids.size());
    for (std::size_t i = 0; i < ids.size(); ++i)
      if (ids[i] > 0) sorted.emplace_back(ids[i], i);
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t k = 1; k < sorted.size(); ++k) {
      if (sorted[k].first != sorted[k - 1].first) continue;
      bad(entry(ds, sorted[k].second), std::string(kind) + " id " + std::to_string(sorted[k].first) +
                                           " repeats the id of entry " +
                                           std::to_string(sorted[k - 1].second) + "; expected each id once");
    }
  }
  template <class T>
  void unique_record_ids(const std::string& table, std::string_view kind, const std::vector<T>& recs,
                         bool zero_allowed = false) {
    std::vector<std::int64_t> ids;
    ids.reserve(recs.size());
    for (const auto& r : recs) ids.push_back(r.id);
    unique_ids("/radx/" + table + "/id", kind, ids, zero_allowed);
  }

  // ---- Stages

  void check_nodes();
  void check_node_masses();
  void check_element_blocks();
  void check_block(const std::string& name, const model::ElementBlock& b);
  void check_block_parts(const std::string& ds, const model::ElementBlock& b);
  void check_reals();
  template <class T, class Get>
  void finite_column(const std::string& ds, std::string_view kind, const std::vector<T>& recs,
                     const Get& get);
  template <class R>
  void finite_record(const std::string& path, const Owner& o, const R& r, const std::string& prefix);
  void check_materials();
  void check_material_curves(std::size_t i, const model::Material& mat, std::vector<std::size_t>& base);
  void check_properties();
  void check_parts_and_subsets();
  void check_node_groups_and_boxes();
  void check_surfaces();
  void check_functions();
  void check_kinematic_conditions();
  void check_loads();
  void check_rigid_walls();
  void check_rigid_bodies();
  void check_skews_and_sections();
  void check_outputs();
  void check_time_history_objects(std::size_t i, const model::TimeHistoryGroup& th, std::size_t base);
  void check_interfaces();
  void check_interface(std::size_t i, const model::Interface& in);
  void check_tied_interfaces();

  [[nodiscard]] Range nodes() const { return {m_.nodes.size(), "nodes"}; }
  [[nodiscard]] Range groups() const { return {m_.node_groups.size(), "node groups"}; }
  [[nodiscard]] Range functions() const { return {m_.functions.size(), "functions"}; }
  [[nodiscard]] Range surfaces() const { return {m_.surfaces.size(), "surfaces"}; }
};

// ---------------------------------------------------------------------------------------------------
// Nodes and their masses

void Checker::check_nodes() {
  const std::size_t nn = m_.nodes.size();
  if (m_.nodes.x.size() != nn || m_.nodes.y.size() != nn || m_.nodes.z.size() != nn) {
    bad("/radx/nodes/xyz", "the coordinates have " + std::to_string(m_.nodes.x.size()) + " rows; expected " +
                               std::to_string(nn) + " (one per node id)");
    return;
  }
  unique_ids("/radx/nodes/id", "node", m_.nodes.id, false);
  for (std::size_t i = 0; i < nn; ++i) {
    const std::array<double, 3> p{m_.nodes.x[i], m_.nodes.y[i], m_.nodes.z[i]};
    for (int c = 0; c < 3; ++c) {
      if (std::isfinite(p[static_cast<std::size_t>(c)])) continue;
      bad_value(entry("/radx/nodes/xyz", i, c), "node " + std::to_string(m_.nodes.id[i]) + ": coordinate " +
                                                    real_text(p[static_cast<std::size_t>(c)]) +
                                                    " is not a finite number");
    }
  }
}

void Checker::check_node_masses() {
  const std::size_t nn = m_.nodes.size();
  if (m_.node_mass.size() != nn) {
    bad("/radx/node_mass", "has " + std::to_string(m_.node_mass.size()) + " entries; expected " +
                               std::to_string(nn) + " (one per node)");
    return;
  }
  double sum = 0;
  for (std::size_t i = 0; i < nn; ++i) {
    const double mass = m_.node_mass[i];
    if (!std::isfinite(mass) || mass < 0) {
      bad_value(entry("/radx/node_mass", i), "node " + std::to_string(m_.nodes.id[i]) + ": mass " +
                                                 real_text(mass) + "; expected a finite number >= 0");
    } else {
      sum += mass;
    }
  }
  if (nn > 0 && !(sum > 0)) {
    bad_value("/radx/node_mass",
              "every node has mass 0: the model has no mass to move (the starter gives each "
              "node the mass of its elements)");
  }
  if (!std::isfinite(m_.total_mass) || m_.total_mass < 0) {
    bad_value("/radx@total_mass",
              "total mass " + real_text(m_.total_mass) + "; expected a finite number >= 0");
  }
}

// ---------------------------------------------------------------------------------------------------
// Element blocks

void Checker::check_element_blocks() {
  check_block("shell4", m_.shells);
  check_block("shell3", m_.shells3);
  check_block("brick8", m_.bricks);
  check_block("tetra4", m_.tetras);
  check_block("brick20", m_.bricks20);
  check_block("spring2", m_.springs);
  check_block("truss2", m_.trusses);
  check_block("beam2", m_.beams);
}

void Checker::check_block(const std::string& name, const model::ElementBlock& b) {
  const std::string ds = "/radx/elements/" + name;
  const std::string_view kind = model::element_type_name(b.type);
  const std::size_t n = b.size();
  const auto npe = static_cast<std::size_t>(b.npe());
  bool sizes_ok = true;
  // `per` values for each element id; thickness and phi may also be empty (only shells use them).
  const auto column_size = [&](const char* column, std::size_t have, std::size_t per, bool may_be_empty) {
    if (have == n * per || (may_be_empty && have == 0)) return;
    sizes_ok = false;
    bad(ds + "/" + column, "has " + std::to_string(have) + " values; expected " + std::to_string(n * per) +
                               " (" + std::to_string(per) + " per " + std::string(kind) + " of " + ds +
                               "/id" + (may_be_empty ? ", or none)" : ")"));
  };
  column_size("part", b.part.size(), 1, false);
  column_size("conn", b.conn.size(), npe, false);
  column_size("thickness", b.thickness.size(), 1, true);
  column_size("phi", b.phi.size(), 1, true);
  if (!sizes_ok) return;
  unique_ids(ds + "/id", kind, b.id, false);
  // The third node of a spring and of a beam orients it and may be blank.
  const bool optional_third = b.type == model::ElementType::Spring2 || b.type == model::ElementType::Beam2;
  for (std::size_t e = 0; e < n; ++e) {
    for (std::size_t k = 0; k < npe; ++k) {
      const std::int32_t node = b.conn[e * npe + k];
      if (node >= 0 && static_cast<std::size_t>(node) < m_.nodes.size()) continue;
      index(ds + "/conn", e, static_cast<int>(k), {kind, b.id[e]}, "node index", node, nodes(),
            optional_third && k == 2);
    }
  }
  for (std::size_t e = 0; e < b.thickness.size(); ++e) {
    if (!std::isfinite(b.thickness[e]) || b.thickness[e] < 0)
      bad_value(entry(ds + "/thickness", e), Owner{kind, b.id[e]}.text() + ": thickness " +
                                                 real_text(b.thickness[e]) +
                                                 "; expected a finite number >= 0");
  }
  for (std::size_t e = 0; e < b.phi.size(); ++e) {
    if (!std::isfinite(b.phi[e]))
      bad_value(entry(ds + "/phi", e),
                Owner{kind, b.id[e]}.text() + ": angle " + real_text(b.phi[e]) + " is not a finite number");
  }
  check_block_parts(ds, b);
}

// Each element's part, that the part has a material (but for a spring), and that its property is of the
// element's kind: the engine reads the property's fields of that kind (a shell's thickness, a solid's
// formulation).
void Checker::check_block_parts(const std::string& ds, const model::ElementBlock& b) {
  using model::ElementType;
  using model::PropertyKind;
  PropertyKind want = PropertyKind::Shell;
  switch (b.type) {
    case ElementType::Shell4:
    case ElementType::Shell3: want = PropertyKind::Shell; break;
    case ElementType::Brick8:
    case ElementType::Tetra4:
    case ElementType::Brick20: want = PropertyKind::Solid; break;
    case ElementType::Spring2: want = PropertyKind::Spring; break;
    case ElementType::Truss2: want = PropertyKind::Truss; break;
    case ElementType::Beam2: want = PropertyKind::Beam; break;
  }
  const Range parts{m_.parts.size(), "parts"};
  const std::string part_ds = ds + "/part";
  for (std::size_t e = 0; e < b.size(); ++e) {
    const Owner o{model::element_type_name(b.type), b.id[e]};
    if (!index(part_ds, e, -1, o, "part index", b.part[e], parts, false)) continue;
    const auto& part = m_.parts[static_cast<std::size_t>(b.part[e])];
    // Every element but a spring computes its force through its part's material.
    if (part.material == kNone && b.type != ElementType::Spring2) {
      bad(entry(part_ds, e), o.text() + ": its part " + std::to_string(part.id) + " has no material; a " +
                                 std::string(model::element_type_name(b.type)) + " needs one");
    }
    if (part.property < 0 || static_cast<std::size_t>(part.property) >= m_.properties.size()) continue;
    const auto& prop = m_.properties[static_cast<std::size_t>(part.property)];
    if (prop.kind == want) continue;
    bad(entry(part_ds, e), o.text() + ": its part " + std::to_string(part.id) + " has property " +
                               std::to_string(prop.id) + " of kind " +
                               std::to_string(static_cast<int>(prop.kind)) + "; a " +
                               std::string(model::element_type_name(b.type)) + " needs a property of kind " +
                               std::to_string(static_cast<int>(want)));
  }
}

// ---------------------------------------------------------------------------------------------------
// Every real of every table and interface finite

template <class T, class Get>
void Checker::finite_column(const std::string& ds, std::string_view kind, const std::vector<T>& recs,
                            const Get& get) {
  using M = std::remove_cvref_t<decltype(get(std::declval<const T&>()))>;
  const auto report = [&](std::size_t row, int col, std::int64_t id, double v) {
    bad_value(entry(ds, row, col),
              std::string(kind) + " " + std::to_string(id) + ": " + real_text(v) + " is not a finite number");
  };
  if constexpr (schema::Record<M>) {
    schema::for_each_field<M>([&](const char* sub, auto member) {
      finite_column(
          ds + "_" + sub, kind, recs, [&](const T& r) -> const auto& { return get(r).*member; });
    });
  } else if constexpr (std::is_same_v<M, double>) {
    for (std::size_t r = 0; r < recs.size(); ++r)
      if (!std::isfinite(get(recs[r]))) report(r, -1, recs[r].id, get(recs[r]));
  } else if constexpr (kIsRealArray<M>) {
    for (std::size_t r = 0; r < recs.size(); ++r)
      for (std::size_t j = 0; j < get(recs[r]).size(); ++j)
        if (!std::isfinite(get(recs[r])[j])) report(r, static_cast<int>(j), recs[r].id, get(recs[r])[j]);
  } else if constexpr (schema::kIsVector<M>) {
    using V = typename M::value_type;
    std::size_t base = 0;
    for (const T& rec : recs) {
      const auto& v = get(rec);
      for (std::size_t k = 0; k < v.size(); ++k) {
        if constexpr (std::is_same_v<V, double>) {
          if (!std::isfinite(v[k])) report(base + k, -1, rec.id, v[k]);
        } else if constexpr (kIsRealArray<V>) {
          for (std::size_t j = 0; j < v[k].size(); ++j)
            if (!std::isfinite(v[k][j])) report(base + k, static_cast<int>(j), rec.id, v[k][j]);
        }
      }
      base += v.size();
    }
  }
}

// One record stored as a group (an interface): scalars as attributes, vectors as datasets.
template <class R>
void Checker::finite_record(const std::string& path, const Owner& o, const R& r, const std::string& prefix) {
  schema::for_each_field<R>([&](const char* field_name, auto member) {
    using M = std::remove_cvref_t<decltype(r.*member)>;
    const std::string name = prefix + field_name;
    const M& v = r.*member;
    const auto report = [&](const std::string& where, double x) {
      bad_value(where, o.text() + ": " + real_text(x) + " is not a finite number");
    };
    if constexpr (schema::Record<M>) {
      finite_record(path, o, v, name + "_");
    } else if constexpr (std::is_same_v<M, double>) {
      if (!std::isfinite(v)) report(path + "@" + name, v);
    } else if constexpr (kIsRealArray<M>) {
      for (std::size_t j = 0; j < v.size(); ++j)
        if (!std::isfinite(v[j])) report(entry(path + "@" + name, j), v[j]);
    } else if constexpr (kIsRealVector<M>) {
      for (std::size_t k = 0; k < v.size(); ++k)
        if (!std::isfinite(v[k])) report(entry(path + "/" + name, k), v[k]);
    }
  });
}

void Checker::check_reals() {
  for (const auto& [what, value] : {std::pair{"mass", m_.units.mass}, std::pair{"length", m_.units.length},
                                    std::pair{"time", m_.units.time}}) {
    if (std::isfinite(value) && value > 0) continue;
    bad_value(std::string("/radx/units@") + what, "the SI value of the work unit of " + std::string(what) +
                                                      " is " + real_text(value) +
                                                      "; expected a finite number > 0");
  }
  schema::for_each_table(m_, [&](const char* table, const auto& recs) {
    using T = typename std::remove_cvref_t<decltype(recs)>::value_type;
    schema::for_each_field<T>([&](const char* col, auto member) {
      finite_column(
          "/radx/" + std::string(table) + "/" + col, record_kind(table),
          recs, [&](const T& r) -> const auto& { return r.*member; });
    });
  });
  for (std::size_t i = 0; i < m_.interfaces.size(); ++i)
    finite_record("/radx/interfaces/" + std::to_string(i), {"interface", m_.interfaces[i].id},
                  m_.interfaces[i], "");
}

// ---------------------------------------------------------------------------------------------------
// Materials and properties

void Checker::check_materials() {
  unique_record_ids("materials", "material", m_.materials);
  std::vector<std::size_t> base(6, 0);  // running CSR positions of the curve columns
  for (std::size_t i = 0; i < m_.materials.size(); ++i) {
    const auto& mat = m_.materials[i];
    const Owner o{"material", mat.id};
    code(entry("/radx/materials/law", i), o, "law", static_cast<int>(mat.law), {0, 1, 2, 13, 27, 36, 42, 70},
         "0, 1, 2, 13, 27, 36, 42 or 70 (docs/model-file.md section 6)");
    for (const auto& [column, v] :
         {std::pair{"rho", mat.rho}, std::pair{"rho_ref", mat.rho_ref}, std::pair{"young", mat.young},
          std::pair{"shear", mat.shear}, std::pair{"bulk", mat.bulk}}) {
      not_negative(entry(std::string("/radx/materials/") + column, i), o, column, v);
    }
    if (!(mat.poisson > -1 && mat.poisson < 0.5) && std::isfinite(mat.poisson)) {
      bad_value(entry("/radx/materials/poisson", i),
                o.text() + ": Poisson's ratio " + real_text(mat.poisson) + "; expected -1 < nu < 0.5");
    }
    check_material_curves(i, mat, base);
  }
}

// The curves a material names (law 36, 70, /FAIL/TAB, /FAIL/BIQUAD): function indices, and the parallel
// columns of each curve list of equal length.
void Checker::check_material_curves(std::size_t i, const model::Material& mat,
                                    std::vector<std::size_t>& base) {
  const Owner o{"material", mat.id};
  const auto curves = [&](std::size_t slot, const std::string& column, const std::vector<std::int32_t>& fn,
                          std::initializer_list<std::size_t> parallel) {
    const std::string ds = "/radx/materials/" + column;
    indices(ds, base[slot], o, "function index", fn, functions());
    for (const std::size_t size : parallel)
      same_size(entry(ds, base[slot]), o, column, fn.size(), size, "one per scale and rate");
    base[slot] += fn.size();
  };
  curves(0, "tab_function", mat.tab.function, {mat.tab.scale.size(), mat.tab.rate.size()});
  curves(1, "fail_tab_function", mat.fail_tab.function,
         {mat.fail_tab.scale.size(), mat.fail_tab.rate.size()});
  curves(2, "foam_load_function", mat.foam.load_function,
         {mat.foam.load_scale.size(), mat.foam.load_rate.size()});
  curves(3, "foam_unload_function", mat.foam.unload_function,
         {mat.foam.unload_scale.size(), mat.foam.unload_rate.size()});
  same_size(entry("/radx/materials/ogden_mu", base[4]), o, "ogden_mu", mat.ogden.mu.size(),
            mat.ogden.alpha.size(), "one per ogden_alpha");
  base[4] += mat.ogden.mu.size();
  index("/radx/materials/fail_tab_size_function", i, -1, o, "function index", mat.fail_tab.size_function,
        functions(), true);
  index("/radx/materials/fail_bq_size_function", i, -1, o, "function index", mat.fail_bq.size_function,
        functions(), true);
  index("/radx/materials/foam_tens_function", i, -1, o, "function index", mat.foam.tens_function, functions(),
        true);
}

void Checker::check_properties() {
  unique_record_ids("properties", "property", m_.properties);
  const Range skews{m_.skews.size(), "skews"};
  for (std::size_t i = 0; i < m_.properties.size(); ++i) {
    const auto& p = m_.properties[i];
    const Owner o{"property", p.id};
    code(entry("/radx/properties/kind", i), o, "kind", static_cast<int>(p.kind), {1, 2, 3, 4, 14},
         "1 shell, 2 truss, 3 beam, 4 spring or 14 solid");
    not_negative(entry("/radx/properties/shell_thickness", i), o, "shell thickness", p.shell.thickness);
    not_negative(entry("/radx/properties/spring_mass", i), o, "spring mass", p.spring.mass);
    not_negative(entry("/radx/properties/spring_inertia", i), o, "spring inertia", p.spring.inertia);
    not_negative(entry("/radx/properties/truss_area", i), o, "truss area", p.truss.area);
    not_negative(entry("/radx/properties/beam_area", i), o, "beam area", p.beam.area);
    index("/radx/properties/spring_skew", i, -1, o, "skew index", p.spring.skew, skews, true);
    if (p.kind == model::PropertyKind::Spring) {
      code(entry("/radx/properties/spring_type", i), o, "spring type", p.spring.type, {4, 8, 13},
           "4, 8 or 13");
    }
    const char* dofs[6] = {"x", "y", "z", "rx", "ry", "rz"};
    for (int d = 0; d < 6; ++d) {
      const model::SpringLaw& law = p.spring.law(d);
      const std::string col = std::string("/radx/properties/spring_") + dofs[d] + "_";
      index(col + "f_load", i, -1, o, "function index", law.f_load, functions(), true);
      index(col + "f_damp", i, -1, o, "function index", law.f_damp, functions(), true);
      index(col + "f_unload", i, -1, o, "function index", law.f_unload, functions(), true);
      index(col + "f_damp4", i, -1, o, "function index", law.f_damp4, functions(), true);
    }
  }
}

// ---------------------------------------------------------------------------------------------------
// Parts, subsets, node groups, boxes

void Checker::check_parts_and_subsets() {
  unique_record_ids("parts", "part", m_.parts);
  unique_record_ids("subsets", "subset", m_.subsets);
  const Range properties{m_.properties.size(), "properties"};
  const Range materials{m_.materials.size(), "materials"};
  const Range subsets{m_.subsets.size(), "subsets"};
  const Range parts{m_.parts.size(), "parts"};
  for (std::size_t i = 0; i < m_.parts.size(); ++i) {
    const auto& p = m_.parts[i];
    const Owner o{"part", p.id};
    index("/radx/parts/property", i, -1, o, "property index", p.property, properties, false);
    index("/radx/parts/material", i, -1, o, "material index", p.material, materials, true);
    index("/radx/parts/subset", i, -1, o, "subset index", p.subset, subsets, true);
    not_negative(entry("/radx/parts/mass", i), o, "mass", p.mass);
  }
  std::size_t children = 0, members = 0;
  for (const auto& s : m_.subsets) {
    const Owner o{"subset", s.id};
    indices("/radx/subsets/children", children, o, "subset index", s.children, subsets);
    indices("/radx/subsets/parts", members, o, "part index", s.parts, parts);
    children += s.children.size();
    members += s.parts.size();
  }
}

void Checker::check_node_groups_and_boxes() {
  std::size_t base = 0;
  for (const auto& g : m_.node_groups) {
    const Owner o{"node group", g.id};
    indices("/radx/node_groups/nodes", base, o, "node index", g.nodes, nodes());
    // Sorted and unique (model.hpp): the engine merges groups and looks nodes up by bisection.
    for (std::size_t k = 1; k < g.nodes.size(); ++k) {
      if (g.nodes[k] > g.nodes[k - 1]) continue;
      bad(entry("/radx/node_groups/nodes", base + k),
          o.text() + ": node index " + std::to_string(g.nodes[k]) + " after " +
              std::to_string(g.nodes[k - 1]) + "; expected increasing node indices, each once");
    }
    base += g.nodes.size();
  }
  for (std::size_t i = 0; i < m_.boxes.size(); ++i) {
    const Owner o{"box", m_.boxes[i].id};
    code(entry("/radx/boxes/shape", i), o, "shape", static_cast<int>(m_.boxes[i].shape), {0, 1, 2},
         "0 RECTA, 1 CYLIN or 2 SPHER");
    not_negative(entry("/radx/boxes/diameter", i), o, "diameter", m_.boxes[i].diameter);
  }
}

// ---------------------------------------------------------------------------------------------------
// Surfaces and functions

void Checker::check_surfaces() {
  using model::SegmentOwner;
  std::size_t base = 0;
  for (const auto& s : m_.surfaces) {
    const Owner o{"surface", s.id};
    const std::size_t n = s.segments.size();
    same_size(entry("/radx/surfaces/owner_type", base), o, "owner_type", s.owner_type.size(), n,
              "one per segment");
    same_size(entry("/radx/surfaces/owner", base), o, "owner", s.owner.size(), n, "one per segment");
    for (std::size_t k = 0; k < n; ++k) {
      for (int j = 0; j < 4; ++j)
        index("/radx/surfaces/segments", base + k, j, o, "node index",
              s.segments[k][static_cast<std::size_t>(j)], nodes(), false);
      if (k >= s.owner_type.size() || k >= s.owner.size()) continue;
      const auto type = s.owner_type[k];
      const model::ElementBlock* block = type == SegmentOwner::Shell4   ? &m_.shells
                                         : type == SegmentOwner::Shell3 ? &m_.shells3
                                         : type == SegmentOwner::Brick8 ? &m_.bricks
                                         : type == SegmentOwner::Tetra4 ? &m_.tetras
                                                                        : nullptr;
      if (block == nullptr && type != SegmentOwner::None) {
        code(entry("/radx/surfaces/owner_type", base + k), o, "owner type", static_cast<int>(type),
             {0, 1, 2, 3, 4}, "0 none, 1 shell, 2 3-node shell, 3 brick or 4 tetrahedron");
        continue;
      }
      const std::string items = block ? std::string(model::element_type_name(block->type)) + "s" : "elements";
      index("/radx/surfaces/owner", base + k, -1, o, "owner element index", s.owner[k],
            {block ? block->size() : 0, items}, true);
    }
    base += n;
  }
}

void Checker::check_functions() {
  unique_record_ids("functions", "function", m_.functions);
  std::size_t base = 0;
  for (const auto& f : m_.functions) {
    const Owner o{"function", f.id};
    same_size(entry("/radx/functions/y", base), o, "y", f.y.size(), f.x.size(), "one per abscissa x");
    for (std::size_t k = 1; k < f.x.size(); ++k) {
      if (f.x[k] > f.x[k - 1] || !std::isfinite(f.x[k])) continue;
      bad_value(entry("/radx/functions/x", base + k), o.text() + ": abscissa " + real_text(f.x[k]) +
                                                          " after " + real_text(f.x[k - 1]) +
                                                          "; expected strictly increasing abscissas");
    }
    base += f.x.size();
  }
}

// ---------------------------------------------------------------------------------------------------
// Conditions and loads

void Checker::check_kinematic_conditions() {
  for (std::size_t i = 0; i < m_.bcs.size(); ++i) {
    const auto& c = m_.bcs[i];
    const Owner o{"/BCS", c.id};
    index("/radx/bcs/group", i, -1, o, "node group index", c.group, groups(), false);
    skew_id(entry("/radx/bcs/skew", i), o, "skew", c.skew);
    for (std::size_t j = 0; j < 6; ++j)
      code(entry("/radx/bcs/fixed", i, static_cast<int>(j)), o, "fixed flag", c.fixed[j], {0, 1}, "0 or 1");
  }
  for (std::size_t i = 0; i < m_.imposed_velocities.size(); ++i) {
    const auto& c = m_.imposed_velocities[i];
    const Owner o{c.displacement ? "/IMPDISP" : "/IMPVEL", c.id};
    index("/radx/imposed_velocities/group", i, -1, o, "node group index", c.group, groups(), false);
    index("/radx/imposed_velocities/function", i, -1, o, "function index", c.function, functions(), false);
    code(entry("/radx/imposed_velocities/dir", i), o, "direction", c.dir, {0, 1, 2, 3, 4, 5}, "0 to 5");
    skew_id(entry("/radx/imposed_velocities/skew", i), o, "skew", c.skew);
    skew_id(entry("/radx/imposed_velocities/frame", i), o, "frame", c.frame);
    sensor_id(entry("/radx/imposed_velocities/sensor", i), o, "sensor", c.sensor);
    if (c.ascale_x == 0)
      bad_value(entry("/radx/imposed_velocities/ascale_x", i), o.text() + ": Ascale_x 0; expected != 0");
  }
  std::size_t base = 0;
  for (std::size_t i = 0; i < m_.imposed_final_geometries.size(); ++i) {
    const auto& c = m_.imposed_final_geometries[i];
    const Owner o{"/IMPDISP/FGEO", c.id};
    index("/radx/imposed_final_geometries/function", i, -1, o, "function index", c.function, functions(),
          false);
    sensor_id(entry("/radx/imposed_final_geometries/sensor", i), o, "sensor", c.sensor);
    indices("/radx/imposed_final_geometries/nodes", base, o, "node index", c.nodes, nodes());
    same_size(entry("/radx/imposed_final_geometries/targets", base), o, "targets", c.targets.size(),
              c.nodes.size(), "one per node");
    base += c.nodes.size();
  }
  for (std::size_t i = 0; i < m_.initial_velocities.size(); ++i) {
    const auto& c = m_.initial_velocities[i];
    const Owner o{c.rotational ? "/INIVEL/ROT" : "/INIVEL/TRA", c.id};
    index("/radx/initial_velocities/group", i, -1, o, "node group index", c.group, groups(), false);
    skew_id(entry("/radx/initial_velocities/skew", i), o, "skew", c.skew);
    sensor_id(entry("/radx/initial_velocities/sensor", i), o, "sensor", c.sensor);
  }
}

void Checker::check_loads() {
  for (std::size_t i = 0; i < m_.concentrated_loads.size(); ++i) {
    const auto& c = m_.concentrated_loads[i];
    const Owner o{"/CLOAD", c.id};
    index("/radx/concentrated_loads/group", i, -1, o, "node group index", c.group, groups(), false);
    index("/radx/concentrated_loads/function", i, -1, o, "function index", c.function, functions(), false);
    code(entry("/radx/concentrated_loads/dir", i), o, "direction", c.dir, {0, 1, 2, 3, 4, 5}, "0 to 5");
    skew_id(entry("/radx/concentrated_loads/skew", i), o, "skew", c.skew);
    sensor_id(entry("/radx/concentrated_loads/sensor", i), o, "sensor", c.sensor);
    if (c.ascale_x == 0)
      bad_value(entry("/radx/concentrated_loads/ascale_x", i), o.text() + ": Ascale_x 0; expected != 0");
  }
  for (std::size_t i = 0; i < m_.pressure_loads.size(); ++i) {
    const auto& c = m_.pressure_loads[i];
    const Owner o{"/PLOAD", c.id};
    index("/radx/pressure_loads/surface", i, -1, o, "surface index", c.surface, surfaces(), false);
    index("/radx/pressure_loads/function", i, -1, o, "function index", c.function, functions(), false);
    sensor_id(entry("/radx/pressure_loads/sensor", i), o, "sensor", c.sensor);
    if (c.ascale_x == 0)
      bad_value(entry("/radx/pressure_loads/ascale_x", i), o.text() + ": Ascale_x 0; expected != 0");
  }
  for (std::size_t i = 0; i < m_.gravities.size(); ++i) {
    const auto& c = m_.gravities[i];
    const Owner o{"/GRAV", c.id};
    index("/radx/gravities/group", i, -1, o, "node group index", c.group, groups(), true);
    index("/radx/gravities/function", i, -1, o, "function index", c.function, functions(), true);
    code(entry("/radx/gravities/dir", i), o, "direction", c.dir, {0, 1, 2}, "0, 1 or 2");
    skew_id(entry("/radx/gravities/skew", i), o, "skew", c.skew);
    sensor_id(entry("/radx/gravities/sensor", i), o, "sensor", c.sensor);
    if (c.ascale_x == 0)
      bad_value(entry("/radx/gravities/ascale_x", i), o.text() + ": Ascale_x 0; expected != 0");
  }
  for (std::size_t i = 0; i < m_.added_masses.size(); ++i) {
    const auto& c = m_.added_masses[i];
    const Owner o{"/ADMAS", c.id};
    index("/radx/added_masses/group", i, -1, o, "node group index", c.group, groups(), false);
    code(entry("/radx/added_masses/type", i), o, "type", c.type, {0, 1}, "0 or 1");
    not_negative(entry("/radx/added_masses/mass", i), o, "mass", c.mass);
  }
}

// ---------------------------------------------------------------------------------------------------
// Rigid walls and rigid bodies

void Checker::check_rigid_walls() {
  std::size_t base = 0;
  for (std::size_t i = 0; i < m_.rigid_walls.size(); ++i) {
    const auto& w = m_.rigid_walls[i];
    const Owner o{"/RWALL", w.id};
    index("/radx/rigid_walls/node", i, -1, o, "node index", w.node, nodes(), true);
    index("/radx/rigid_walls/group1", i, -1, o, "node group index", w.group1, groups(), true);
    index("/radx/rigid_walls/group2", i, -1, o, "node group index", w.group2, groups(), true);
    indices("/radx/rigid_walls/secondary", base, o, "node index", w.secondary, nodes());
    code(entry("/radx/rigid_walls/shape", i), o, "shape", w.shape, {0, 1, 2, 3},
         "0 plane, 1 cylinder, 2 sphere or 3 parallelogram");
    not_negative(entry("/radx/rigid_walls/mass", i), o, "mass", w.mass);
    base += w.secondary.size();
  }
}

void Checker::check_rigid_bodies() {
  unique_record_ids("rigid_bodies", "rigid body", m_.rigid_bodies, true);
  std::size_t base = 0;
  for (std::size_t i = 0; i < m_.rigid_bodies.size(); ++i) {
    const auto& b = m_.rigid_bodies[i];
    const Owner o{"/RBODY", b.id};
    index("/radx/rigid_bodies/main_node", i, -1, o, "main node index", b.main_node, nodes(), false);
    index("/radx/rigid_bodies/group", i, -1, o, "node group index", b.group, groups(), true);
    index("/radx/rigid_bodies/surface", i, -1, o, "surface index", b.surface, surfaces(), true);
    indices("/radx/rigid_bodies/secondary", base, o, "node index", b.secondary, nodes());
    skew_id(entry("/radx/rigid_bodies/skew", i), o, "skew", b.skew);
    sensor_id(entry("/radx/rigid_bodies/sensor", i), o, "sensor", b.sensor);
    not_negative(entry("/radx/rigid_bodies/mass", i), o, "mass", b.mass);
    for (std::size_t j = 0; j < 3; ++j)
      not_negative(entry("/radx/rigid_bodies/inertia", i, static_cast<int>(j)), o, "inertia", b.inertia[j]);
    base += b.secondary.size();
  }
}

// ---------------------------------------------------------------------------------------------------
// Skews, sections, accelerometers, sensors, time histories

void Checker::check_skews_and_sections() {
  unique_record_ids("skews", "skew", m_.skews);
  for (std::size_t i = 0; i < m_.skews.size(); ++i) {
    const auto& s = m_.skews[i];
    const Owner o{"skew", s.id};
    // A moving skew follows three nodes, all needed every cycle; a fixed one names none.
    const bool fixed = !s.moving();
    for (const auto& [column, n] : {std::pair{"n1", s.n1}, std::pair{"n2", s.n2}, std::pair{"n3", s.n3}}) {
      if (fixed && n != kNone)
        bad(entry(std::string("/radx/skews/") + column, i),
            o.text() + ": node index " + std::to_string(n) +
                " given to a fixed skew (n1 is -1); expected -1");
      else if (!fixed)
        index(std::string("/radx/skews/") + column, i, -1, o, "node index", n, nodes(), false);
    }
    code(entry("/radx/skews/dir", i), o, "direction", s.dir, {0, 1, 2}, "0, 1 or 2");
  }
  unique_record_ids("sections", "section", m_.sections);
  std::vector<std::size_t> base(6, 0);
  for (std::size_t i = 0; i < m_.sections.size(); ++i) {
    const auto& s = m_.sections[i];
    const Owner o{"/SECT", s.id};
    for (const auto& [column, n] : {std::pair{"n1", s.n1}, std::pair{"n2", s.n2}, std::pair{"n3", s.n3}})
      index(std::string("/radx/sections/") + column, i, -1, o, "node index", n, nodes(), true);
    index("/radx/sections/node_group", i, -1, o, "node group index", s.node_group, groups(), true);
    const std::pair<const char*, std::pair<const std::vector<std::int32_t>*, Range>> lists[6] = {
        {"nodes", {&s.nodes, nodes()}},
        {"shells", {&s.shells, {m_.shells.size(), "shells"}}},
        {"shells3", {&s.shells3, {m_.shells3.size(), "3-node shells"}}},
        {"bricks", {&s.bricks, {m_.bricks.size(), "bricks"}}},
        {"trusses", {&s.trusses, {m_.trusses.size(), "trusses"}}},
        {"beams", {&s.beams, {m_.beams.size(), "beams"}}}};
    for (std::size_t l = 0; l < 6; ++l) {
      const auto& [column, list] = lists[l];
      indices(std::string("/radx/sections/") + column, base[l], o, "index", *list.first, list.second);
      base[l] += list.first->size();
    }
  }
}

void Checker::check_outputs() {
  unique_record_ids("accelerometers", "accelerometer", m_.accelerometers);
  for (std::size_t i = 0; i < m_.accelerometers.size(); ++i) {
    const auto& a = m_.accelerometers[i];
    const Owner o{"/ACCEL", a.id};
    index("/radx/accelerometers/node", i, -1, o, "node index", a.node, nodes(), false);
    skew_id(entry("/radx/accelerometers/skew", i), o, "skew", a.skew);
  }
  unique_record_ids("sensors", "sensor", m_.sensors);
  for (std::size_t i = 0; i < m_.sensors.size(); ++i)
    code(entry("/radx/sensors/type", i), {"/SENSOR", m_.sensors[i].id}, "type",
         static_cast<int>(m_.sensors[i].type), {0}, "0 (TIME)");
  std::size_t base = 0, skews = 0;
  for (std::size_t i = 0; i < m_.time_histories.size(); ++i) {
    const auto& th = m_.time_histories[i];
    const Owner o{"/TH", th.id};
    check_time_history_objects(i, th, base);
    if (th.kind == model::ThKind::Node || !th.skews.empty())
      same_size(entry("/radx/time_histories/skews", skews), o, "skews", th.skews.size(),
                th.kind == model::ThKind::Node ? th.objects.size() : 0,
                th.kind == model::ThKind::Node ? "one per node" : "none for this kind");
    for (std::size_t k = 0; k < th.skews.size(); ++k)
      skew_id(entry("/radx/time_histories/skews", skews + k), o, "skew", th.skews[k]);
    base += th.objects.size();
    skews += th.skews.size();
  }
}

void Checker::check_time_history_objects(std::size_t i, const model::TimeHistoryGroup& th, std::size_t base) {
  using model::ThKind;
  const Owner o{"/TH", th.id};
  Range r;
  switch (th.kind) {
    case ThKind::Node: r = nodes(); break;
    case ThKind::Part: r = {m_.parts.size(), "parts"}; break;
    case ThKind::Inter: r = {m_.interfaces.size(), "interfaces"}; break;
    case ThKind::Rwall: r = {m_.rigid_walls.size(), "rigid walls"}; break;
    case ThKind::Shell: r = {m_.shells.size(), "shells"}; break;
    case ThKind::Subset: r = {m_.subsets.size(), "subsets"}; break;
    case ThKind::Brick: r = {m_.bricks.size() + m_.bricks20.size(), "bricks and 20-node bricks"}; break;
    case ThKind::Shell3: r = {m_.shells3.size(), "3-node shells"}; break;
    case ThKind::Rbody: r = {m_.rigid_bodies.size(), "rigid bodies"}; break;
    case ThKind::Section: r = {m_.sections.size(), "sections"}; break;
    case ThKind::Accel: r = {m_.accelerometers.size(), "accelerometers"}; break;
    case ThKind::Spring: r = {m_.springs.size(), "springs"}; break;
    case ThKind::Truss: r = {m_.trusses.size(), "trusses"}; break;
    case ThKind::Beam: r = {m_.beams.size(), "beams"}; break;
    default:
      code(entry("/radx/time_histories/kind", i), o, "kind", static_cast<int>(th.kind), {}, "0 to 13");
      return;
  }
  indices("/radx/time_histories/objects", base, o, "object index", th.objects, r);
}

// ---------------------------------------------------------------------------------------------------
// Contact interfaces

void Checker::check_interfaces() {
  unique_record_ids("interfaces", "interface", m_.interfaces);
  for (std::size_t i = 0; i < m_.interfaces.size(); ++i) check_interface(i, m_.interfaces[i]);
}

void Checker::check_interface(std::size_t i, const model::Interface& in) {
  const std::string g = "/radx/interfaces/" + std::to_string(i);
  const Owner o{"interface", in.id};
  index(g + "@secondary_group", 0, -1, o, "node group index", in.secondary_group, groups(), true);
  const bool surface_ok =
      index(g + "@main_surface", 0, -1, o, "surface index", in.main_surface, surfaces(), true);
  const std::size_t segments = surface_ok && in.main_surface >= 0
                                   ? m_.surfaces[static_cast<std::size_t>(in.main_surface)].segments.size()
                                   : 0;
  const std::size_t secondary = in.secondary_nodes.size();
  indices(g + "/secondary_nodes", 0, o, "node index", in.secondary_nodes, nodes());
  for (std::size_t k = 1; k < secondary; ++k) {
    if (in.secondary_nodes[k] > in.secondary_nodes[k - 1]) continue;
    bad(entry(g + "/secondary_nodes", k), o.text() + ": node index " + std::to_string(in.secondary_nodes[k]) +
                                              " after " + std::to_string(in.secondary_nodes[k - 1]) +
                                              "; expected increasing node indices, each once");
  }
  // Per secondary node and per main segment, or none (an interface the starter computed nothing for).
  const auto per = [&](const char* column, std::size_t have, std::size_t want, const char* each) {
    if (have != 0) same_size(g + "/" + column, o, column, have, want, each);
  };
  per("gap_node", in.gap_node.size(), secondary, "one per secondary node");
  per("stiff_node", in.stiff_node.size(), secondary, "one per secondary node");
  per("tributary_area", in.tributary_area.size(), secondary, "one per secondary node");
  per("gap_segment", in.gap_segment.size(), segments, "one per segment of the main surface");
  per("stiff_segment", in.stiff_segment.size(), segments, "one per segment of the main surface");
  indices(g + "/inactive_nodes", 0, o, "node index", in.inactive_nodes, nodes());
  indices(g + "/inactive_segments", 0, o, "segment index", in.inactive_segments, {segments, "main segments"});
  indices(g + "/penetrating_nodes", 0, o, "node index", in.penetrating_nodes, nodes());
  same_size(g + "/initial_gap_reduction", o, "initial_gap_reduction", in.initial_gap_reduction.size(),
            in.penetrating_nodes.size(), "one per penetrating node");
  index(g + "@law_curve", 0, -1, o, "function index", in.law.curve, functions(), true);
  code(g + "@law_normal", o, "normal law", static_cast<int>(in.law.normal), {0, 1, 2, 3, 4}, "0 to 4");
  code(g + "@law_friction", o, "friction law", static_cast<int>(in.law.friction), {0, 1, 2, 3, 4, 5},
       "0 to 5");
  same_size(g + "/law_power_k", o, "law_power_k", in.law.power_k.size(), in.law.power_m.size(),
            "one per law_power_m");
  sensor_id(g + "@sens_id", o, "sensor", in.sens_id);
}

void Checker::check_tied_interfaces() {
  unique_record_ids("tied_interfaces", "tied interface", m_.tied_interfaces);
  std::size_t base = 0;
  for (std::size_t i = 0; i < m_.tied_interfaces.size(); ++i) {
    const auto& t = m_.tied_interfaces[i];
    const Owner o{"/INTER/TYPE2", t.id};
    index("/radx/tied_interfaces/secondary_group", i, -1, o, "node group index", t.secondary_group, groups(),
          true);
    index("/radx/tied_interfaces/main_surface", i, -1, o, "surface index", t.main_surface, surfaces(), true);
    const std::size_t n = t.tie_node.size();
    indices("/radx/tied_interfaces/tie_node", base, o, "node index", t.tie_node, nodes());
    for (const auto& [column, have] :
         {std::pair{"tie_segment", t.tie_segment.size()}, std::pair{"tie_r", t.tie_r.size()},
          std::pair{"tie_s", t.tie_s.size()}, std::pair{"tie_offset", t.tie_offset.size()}})
      same_size(entry(std::string("/radx/tied_interfaces/") + column, base), o, column, have, n,
                "one per tie_node");
    for (std::size_t k = 0; k < std::min(n, t.tie_segment.size()); ++k)
      for (int j = 0; j < 4; ++j)
        index("/radx/tied_interfaces/tie_segment", base + k, j, o, "node index",
              t.tie_segment[k][static_cast<std::size_t>(j)], nodes(), false);
    base += n;
  }
}

}  // namespace

ModelFileProblems check_model_content(const Model& m) {
  ModelFileProblems problems;
  Checker(m, problems).run();
  return problems;
}

}  // namespace radx::io
