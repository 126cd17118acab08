// Model file writer and reader (layout: docs/model-file.md; VTKHDF part:
// docs/theory/results-format.md section 2).
//
// How the code is organised:
// - HDF5 calls go through the helpers of io/hdf5/hdf5_util.hpp (Handle, check, typed datasets and
//   attributes), which throw h5::Failure with the path of the HDF5 object and the innermost message of
//   the HDF5 error stack. write_model_file / read_model_file catch it and return false: nothing else
//   escapes.
// - The /VTKHDF mesh is written by io/hdf5/vtkhdf_mesh.cpp, shared with the result mesh file P.mesh.hdf.
// - Schema<S> (io/hdf5/model_schema.hpp): one table per Model struct of (member name, member pointer). It
//   drives both directions: a collection (vector of records) is written as a "table" group: attribute
//   count, one dataset per member (a column), variable-length members as CSR (values + <name>_offsets),
//   nested structs flattened as <outer>_<inner>. Interfaces and Units are written one group per record:
//   scalars as attributes, vectors as datasets.
// - Big arrays (points, connectivity, element blocks) are written with one H5Dwrite each, in checksummed
//   chunks, no fill, no conversion (memory and file types are both little-endian).
#include "io/hdf5/model_file.hpp"

#include <hdf5.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "io/hdf5/hdf5_util.hpp"
#include "io/hdf5/model_file_checks.hpp"
#include "io/hdf5/model_file_hash.hpp"
#include "io/hdf5/model_schema.hpp"
#include "io/hdf5/vtkhdf_mesh.hpp"

#ifndef RADX_VERSION
#define RADX_VERSION "unknown"
#endif

namespace radx::io {

namespace {

namespace fs = std::filesystem;
using model::Model;
// The generic HDF5 helpers are this file's vocabulary: used unqualified.
using namespace radx::io::h5;      // NOLINT(google-build-using-namespace)
using namespace radx::io::schema;  // NOLINT(google-build-using-namespace)

// ---------------------------------------------------------------------------------------------------
// Types

// How a member type is stored: bool as uint8 (0/1), enums as their underlying integer.
template <class M>
struct StoredT {
  using type = M;
};
template <>
struct StoredT<bool> {
  using type = std::uint8_t;
};
template <class M>
requires std::is_enum_v<M>
struct StoredT<M> {
  using type = std::underlying_type_t<M>;
};
template <class M>
using Stored = typename StoredT<M>::type;

// An item of a dataset row: a scalar (one value) or a std::array (K values, dataset [n, K]).
template <class E>
struct Item {
  using value = E;
  static constexpr hsize_t k = 0;  // 0: scalar, 1-D dataset
};
template <class E, std::size_t K>
struct Item<std::array<E, K>> {
  using value = E;
  static constexpr hsize_t k = K;
};

// ---------------------------------------------------------------------------------------------------
// Items: a vector of scalars or std::arrays of scalars, stored as [n] or [n, K] with the stored type.

template <class E>
void write_items(hid_t loc, const std::string& name, const std::vector<E>& items) {
  using V = typename Item<E>::value;
  using S = Stored<V>;
  constexpr hsize_t k = Item<E>::k;
  if constexpr (k == 0 && std::is_same_v<S, E>) {
    write_dataset(loc, name, items);
  } else {
    std::vector<S> flat;
    flat.reserve(items.size() * (k > 0 ? k : 1));
    for (const E& e : items) {
      if constexpr (k == 0) {
        flat.push_back(static_cast<S>(e));
      } else {
        for (const V& x : e) flat.push_back(static_cast<S>(x));
      }
    }
    write_dataset(loc, name, flat, k);
  }
}

template <class E>
std::vector<E> read_items(hid_t loc, const std::string& name) {
  using V = typename Item<E>::value;
  using S = Stored<V>;
  constexpr hsize_t k = Item<E>::k;
  if constexpr (k == 0 && std::is_same_v<S, E>) {
    return read_dataset<S>(loc, name);
  } else {
    const std::vector<S> flat = read_dataset<S>(loc, name, k);
    std::vector<E> items(flat.size() / (k > 0 ? k : 1));
    for (std::size_t i = 0; i < items.size(); ++i) {
      if constexpr (k == 0) {
        items[i] = static_cast<E>(flat[i]);
      } else {
        for (std::size_t j = 0; j < k; ++j) items[i][j] = static_cast<V>(flat[i * k + j]);
      }
    }
    return items;
  }
}

std::string join_lines(const std::vector<std::string>& v) {
  std::string s;
  for (std::size_t i = 0; i < v.size(); ++i) s += (i > 0 ? "\n" : "") + v[i];
  return s;
}

std::vector<std::string> split_lines(const std::string& s) {
  std::vector<std::string> v;
  if (s.empty()) return v;
  std::size_t start = 0;
  for (std::size_t nl = s.find('\n'); nl != std::string::npos; nl = s.find('\n', start)) {
    v.push_back(s.substr(start, nl - start));
    start = nl + 1;
  }
  v.push_back(s.substr(start));
  return v;
}

// CSR offsets of n rows over `total` values: offsets[0] = 0, non-decreasing, offsets[n] = total.
void check_offsets(const std::vector<std::int64_t>& off, std::size_t n, std::size_t total,
                   const std::string& where) {
  bool ok = off.size() == n + 1 && off.front() == 0 && off.back() == static_cast<std::int64_t>(total);
  for (std::size_t i = 1; ok && i < off.size(); ++i) ok = off[i] >= off[i - 1];
  if (!ok) {
    throw Failure(where + " is not a valid CSR offsets array for " + std::to_string(n) + " rows and " +
                  std::to_string(total) + " values");
  }
}

// ---------------------------------------------------------------------------------------------------
// Tables: one group per collection, attribute count, one column per member.

// Accessors of a member (and of a member of a member), usable on const and non-const records.
template <class P>
struct MemberOf {
  P member;
  template <class R>
  auto& operator()(R& r) const {
    return r.*member;
  }
};
template <class Outer, class P>
struct NestedMemberOf {
  const Outer& outer;
  P member;
  template <class R>
  auto& operator()(R& r) const {
    return outer(r).*member;
  }
};
template <class P>
MemberOf<P> member_of(P member) {
  return {member};
}
template <class Outer, class P>
NestedMemberOf<Outer, P> member_of(const Outer& outer, P member) {
  return {outer, member};
}

template <class T, class Get>
void write_column(hid_t g, const std::string& name, const std::vector<T>& recs, const Get& get) {
  using M = std::remove_cvref_t<decltype(get(std::declval<const T&>()))>;
  if constexpr (Record<M>) {
    for_each_field<M>([&](const char* sub, auto member) {
      write_column(g, name + "_" + sub, recs, member_of(get, member));
    });
  } else if constexpr (std::is_same_v<M, std::string> || std::is_same_v<M, std::vector<std::string>>) {
    std::vector<std::string> col;
    col.reserve(recs.size());
    for (const T& r : recs) {
      if constexpr (std::is_same_v<M, std::string>) {
        col.push_back(get(r));
      } else {
        col.push_back(join_lines(get(r)));
      }
    }
    write_strings(g, name, col);
  } else if constexpr (kIsVector<M>) {  // CSR
    M values;
    std::vector<std::int64_t> offsets{0};
    for (const T& r : recs) {
      values.insert(values.end(), get(r).begin(), get(r).end());
      offsets.push_back(static_cast<std::int64_t>(values.size()));
    }
    write_items(g, name, values);
    write_dataset(g, name + "_offsets", offsets);
  } else {
    std::vector<M> col;
    col.reserve(recs.size());
    for (const T& r : recs) col.push_back(get(r));
    write_items(g, name, col);
  }
}

template <class T, class Get>
void read_column(hid_t g, const std::string& name, std::vector<T>& recs, const Get& get) {
  using M = std::remove_cvref_t<decltype(get(std::declval<T&>()))>;
  const std::size_t n = recs.size();
  const auto check_rows = [&](std::size_t have) {
    if (have != n) {
      throw Failure("dataset " + path_of(g, name) + " has " + std::to_string(have) + " rows, expected " +
                    std::to_string(n) + " (attribute count of " + path_of(g, "") + ")");
    }
  };
  if constexpr (Record<M>) {
    for_each_field<M>([&](const char* sub, auto member) {
      read_column(g, name + "_" + sub, recs, member_of(get, member));
    });
  } else if constexpr (std::is_same_v<M, std::string> || std::is_same_v<M, std::vector<std::string>>) {
    const std::vector<std::string> col = read_strings(g, name);
    check_rows(col.size());
    for (std::size_t i = 0; i < n; ++i) {
      if constexpr (std::is_same_v<M, std::string>) {
        get(recs[i]) = col[i];
      } else {
        get(recs[i]) = split_lines(col[i]);
      }
    }
  } else if constexpr (kIsVector<M>) {
    const M values = read_items<typename M::value_type>(g, name);
    const std::vector<std::int64_t> offsets = read_dataset<std::int64_t>(g, name + "_offsets");
    check_offsets(offsets, n, values.size(), "dataset " + path_of(g, name + "_offsets"));
    for (std::size_t i = 0; i < n; ++i) {
      get(recs[i]).assign(values.begin() + offsets[i], values.begin() + offsets[i + 1]);
    }
  } else {
    const std::vector<M> col = read_items<M>(g, name);
    check_rows(col.size());
    for (std::size_t i = 0; i < n; ++i) get(recs[i]) = col[i];
  }
}

template <class T>
void write_table(hid_t parent, const std::string& name, const std::vector<T>& recs) {
  const Handle g = create_group(parent, name);
  const auto count = static_cast<std::int64_t>(recs.size());
  write_attr(g, "count", &count);
  for_each_field<T>([&](const char* col, auto member) { write_column(g, col, recs, member_of(member)); });
}

std::size_t read_count(hid_t g) {
  const auto count = read_attr<std::int64_t>(g, "count");
  if (count < 0 || count > std::numeric_limits<std::int32_t>::max()) {
    throw Failure("attribute count of " + path_of(g, "") + " is out of range: " + std::to_string(count));
  }
  return static_cast<std::size_t>(count);
}

// A table's count bounded by its columns before anything is allocated for it: every column has count rows
// (a CSR column's offsets count + 1), so a count above the longest column's rows is damage, and allocating
// it first could take the memory of the machine.
std::size_t read_table_count(hid_t g) {
  const std::size_t count = read_count(g);
  if (count == 0) return 0;
  H5G_info_t info{};
  check(H5Gget_info(g, &info), "cannot read group " + path_of(g, ""));
  hsize_t longest = 0;
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    const Handle obj(H5Oopen_by_idx(g, ".", H5_INDEX_NAME, H5_ITER_INC, i, H5P_DEFAULT), H5Oclose,
                     "cannot open a member of " + path_of(g, ""));
    if (H5Iget_type(obj) != H5I_DATASET) continue;
    const Handle space(H5Dget_space(obj), H5Sclose, "cannot read a dataset of " + path_of(g, ""));
    hsize_t dims[2] = {0, 0};
    if (H5Sget_simple_extent_ndims(space) >= 1) H5Sget_simple_extent_dims(space, dims, nullptr);
    longest = std::max(longest, dims[0]);
  }
  if (count > longest) {
    throw Failure("attribute count of " + path_of(g, "") + " is " + std::to_string(count) +
                  ", more than its longest column holds (" + std::to_string(longest) + " rows)");
  }
  return count;
}

// A record list's count bounded by its record groups ("0", "1", ...) before anything is allocated.
std::size_t read_record_count(hid_t g) {
  const std::size_t count = read_count(g);
  H5G_info_t info{};
  check(H5Gget_info(g, &info), "cannot read group " + path_of(g, ""));
  if (count > info.nlinks) {
    throw Failure("attribute count of " + path_of(g, "") + " is " + std::to_string(count) +
                  ", more than its " + std::to_string(info.nlinks) + " records");
  }
  return count;
}

template <class T>
void read_table(hid_t parent, const std::string& name, std::vector<T>& recs) {
  const Handle g = open_group(parent, name);
  recs.assign(read_table_count(g), T{});
  for_each_field<T>([&](const char* col, auto member) { read_column(g, col, recs, member_of(member)); });
}

// ---------------------------------------------------------------------------------------------------
// Records: one group per record, scalars and fixed arrays as attributes, vectors as datasets.

template <class R>
void write_record(hid_t g, const R& r, const std::string& prefix = "") {
  for_each_field<R>([&](const char* field_name, auto member) {
    using M = std::remove_cvref_t<decltype(r.*member)>;
    const std::string name = prefix + field_name;
    const M& v = r.*member;
    if constexpr (Record<M>) {
      write_record(g, v, name + "_");
    } else if constexpr (std::is_same_v<M, std::string>) {
      write_string_attr(g, name, v);
    } else if constexpr (std::is_same_v<M, std::vector<std::string>>) {
      write_string_attr(g, name, join_lines(v));
    } else if constexpr (kIsVector<M>) {
      write_items(g, name, v);
    } else if constexpr (kIsArray<M>) {
      using S = Stored<typename M::value_type>;
      std::array<S, std::tuple_size_v<M>> s{};
      for (std::size_t i = 0; i < s.size(); ++i) s[i] = static_cast<S>(v[i]);
      write_attr(g, name, s.data(), s.size());
    } else {
      const auto s = static_cast<Stored<M>>(v);
      write_attr(g, name, &s);
    }
  });
}

template <class R>
void read_record(hid_t g, R& r, const std::string& prefix = "") {
  for_each_field<R>([&](const char* field_name, auto member) {
    using M = std::remove_cvref_t<decltype(r.*member)>;
    const std::string name = prefix + field_name;
    M& v = r.*member;
    if constexpr (Record<M>) {
      read_record(g, v, name + "_");
    } else if constexpr (std::is_same_v<M, std::string>) {
      v = read_string_attr(g, name);
    } else if constexpr (std::is_same_v<M, std::vector<std::string>>) {
      v = split_lines(read_string_attr(g, name));
    } else if constexpr (kIsVector<M>) {
      v = read_items<typename M::value_type>(g, name);
    } else if constexpr (kIsArray<M>) {
      using S = Stored<typename M::value_type>;
      std::array<S, std::tuple_size_v<M>> s{};
      read_attr(g, name, s.data(), s.size());
      for (std::size_t i = 0; i < s.size(); ++i) v[i] = static_cast<typename M::value_type>(s[i]);
    } else {
      v = static_cast<M>(read_attr<Stored<M>>(g, name));
    }
  });
}

// Group `name` with attribute count and sub-groups "0", "1", ... one per record.
template <class T>
void write_record_list(hid_t parent, const std::string& name, const std::vector<T>& recs) {
  const Handle g = create_group(parent, name);
  const auto count = static_cast<std::int64_t>(recs.size());
  write_attr(g, "count", &count);
  for (std::size_t i = 0; i < recs.size(); ++i) write_record(create_group(g, std::to_string(i)), recs[i]);
}

template <class T>
void read_record_list(hid_t parent, const std::string& name, std::vector<T>& recs) {
  const Handle g = open_group(parent, name);
  recs.assign(read_record_count(g), T{});
  for (std::size_t i = 0; i < recs.size(); ++i) read_record(open_group(g, std::to_string(i)), recs[i]);
}

// ---------------------------------------------------------------------------------------------------
// Writing

void write_block(hid_t elements, const std::string& name, const model::ElementBlock& b) {
  const Handle g = create_group(elements, name);
  const auto type = static_cast<std::uint8_t>(b.type);
  const auto count = static_cast<std::int64_t>(b.size());
  write_attr(g, "type", &type);
  write_attr(g, "count", &count);
  write_dataset(g, "id", b.id);
  write_dataset(g, "part", b.part);
  write_dataset(g, "conn", b.conn, static_cast<hsize_t>(b.npe()));
  write_dataset(g, "thickness", b.thickness);
  write_dataset(g, "phi", b.phi);
}

void write_radx(hid_t file, const Model& m) {
  const Handle radx = create_group(file, "radx");
  write_string_attr(radx, "title", m.title);
  write_string_attr(radx, "run_name", m.run_name);
  const auto deck_version = static_cast<std::int32_t>(m.deck_version);
  write_attr(radx, "deck_version", &deck_version);
  write_attr(radx, "total_mass", &m.total_mass);
  write_record(create_group(radx, "units"), m.units);
  {  // The node arrays are already in /VTKHDF: hard links, not copies.
    const Handle nodes = create_group(radx, "nodes");
    const auto count = static_cast<std::int64_t>(m.nodes.size());
    write_attr(nodes, "count", &count);
    link_hard(file, "/VTKHDF/PointData/node_id", nodes, "id");
    link_hard(file, "/VTKHDF/Points", nodes, "xyz");
  }
  write_dataset(radx, "node_mass", m.node_mass);
  const Handle elements = create_group(radx, "elements");
  for_each_block(m, [&](const char* name, const model::ElementBlock& b) { write_block(elements, name, b); });
  for_each_table(m, [&](const char* name, const auto& recs) { write_table(radx, name, recs); });
  write_record_list(radx, "interfaces", m.interfaces);
  write_strings(radx, "ignored_keywords", m.ignored_keywords);
  write_strings(radx, "substitutions", m.substitutions);
}

// The fingerprint beside the model (docs/model-file.md section 3): where the model comes from, and last the
// hash of everything else in the file.
void write_fingerprint(hid_t file, const ModelFileOrigin& origin) {
  const std::string version = RADX_VERSION;
  write_attr(file, "radx_model_format_version", &kModelFormatVersion);
  write_string_attr(file, "radx_version", version);
  write_string_attr(file, "radx_commit", origin.radx_commit.empty() ? "unknown" : origin.radx_commit);
  write_string_attr(file, "radx_run", origin.run);
  write_string_attr(file, "radx_deck_hash", origin.deck_hash);
  write_string_array_attr(file, "radx_deck_files", origin.deck_files);
}

// Writes the whole file at `part`; closes it (and flushes it to disk) before returning.
void write_file(const Model& m, const ModelFileOrigin& origin, const std::string& part) {
  check_vtkhdf_mesh(m);
  WriteFile file = create_file(part);
  write_fingerprint(file, origin);
  write_vtkhdf_mesh(file, m);
  write_radx(file, m);
  file.flush();
  write_string_attr(file, kContentHashAttribute, model_content_hash(file));
  file.close();
  sync_file(part);
}

// ---------------------------------------------------------------------------------------------------
// Reading

// The arrays of one element block; their lengths, indices and ids are checked with the rest of the model
// (model_file_checks.cpp) before its IdMap is built.
void read_block(hid_t elements, const std::string& name, model::ElementBlock& b) {
  const Handle g = open_group(elements, name);
  const auto type = read_attr<std::uint8_t>(g, "type");
  if (type != static_cast<std::uint8_t>(b.type)) {
    throw Failure("attribute type of " + path_of(g, "") + " is " + std::to_string(type) + ", expected " +
                  std::to_string(static_cast<int>(b.type)));
  }
  b.id = read_dataset<std::int64_t>(g, "id");
  b.part = read_dataset<std::int32_t>(g, "part");
  b.conn = read_dataset<std::int32_t>(g, "conn", static_cast<hsize_t>(b.npe()));
  b.thickness = read_dataset<double>(g, "thickness");
  b.phi = read_dataset<double>(g, "phi");
}

void read_nodes(hid_t radx, Model& m) {
  const Handle nodes = open_group(radx, "nodes");
  m.nodes.id = read_dataset<std::int64_t>(nodes, "id");
  const std::vector<double> xyz = read_dataset<double>(nodes, "xyz", 3);
  const std::size_t nn = std::min(m.nodes.id.size(), xyz.size() / 3);
  m.nodes.x.resize(nn);
  m.nodes.y.resize(nn);
  m.nodes.z.resize(nn);
  for (std::size_t i = 0; i < nn; ++i) {
    m.nodes.x[i] = xyz[3 * i];
    m.nodes.y[i] = xyz[3 * i + 1];
    m.nodes.z[i] = xyz[3 * i + 2];
  }
}

void read_radx(hid_t file, Model& m) {
  const Handle radx = open_group(file, "radx");
  m.title = read_string_attr(radx, "title");
  m.run_name = read_string_attr(radx, "run_name");
  m.deck_version = read_attr<std::int32_t>(radx, "deck_version");
  m.total_mass = read_attr<double>(radx, "total_mass");
  read_record(open_group(radx, "units"), m.units);
  read_nodes(radx, m);
  m.node_mass = read_dataset<double>(radx, "node_mass");
  const Handle elements = open_group(radx, "elements");
  for_each_block(m, [&](const char* name, model::ElementBlock& b) { read_block(elements, name, b); });
  for_each_table(m, [&](const char* name, auto& recs) { read_table(radx, name, recs); });
  read_record_list(radx, "interfaces", m.interfaces);
  m.ignored_keywords = read_strings(radx, "ignored_keywords");
  m.substitutions = read_strings(radx, "substitutions");
}

// The stored fingerprint; missing attributes stay empty (reported by the caller).
ModelFileFingerprint read_fingerprint(hid_t file) {
  ModelFileFingerprint f;
  f.format_version = read_attr<std::int64_t>(file, "radx_model_format_version");
  f.radx_version = read_string_attr(file, "radx_version");
  if (has_attr(file, "radx_commit")) f.radx_commit = read_string_attr(file, "radx_commit");
  if (has_attr(file, "radx_run")) f.run = read_string_attr(file, "radx_run");
  if (has_attr(file, "radx_deck_hash")) f.deck_hash = read_string_attr(file, "radx_deck_hash");
  if (has_attr(file, "radx_deck_files")) f.deck_files = read_string_array_attr(file, "radx_deck_files");
  if (has_attr(file, kContentHashAttribute)) f.content_hash = read_string_attr(file, kContentHashAttribute);
  return f;
}

// Another layout cannot be read at all: the one problem, with both radx versions.
bool same_format(const ModelFileFingerprint& f, ModelFileReading& r) {
  if (f.format_version == kModelFormatVersion) return true;
  r.problems.add(ModelFileCode::OtherFormat, "/@radx_model_format_version",
                 "model-file format version " + std::to_string(f.format_version) + ", written by radx " +
                     f.radx_version + (f.radx_commit.empty() ? "" : " (commit " + f.radx_commit + ")") +
                     "; this radx " RADX_VERSION " reads version " + std::to_string(kModelFormatVersion) +
                     " only: run the starter of this radx on the deck again");
  return false;
}

void check_content_hash(hid_t file, ModelFileReading& r) {
  auto& f = r.fingerprint;
  f.computed_hash = model_content_hash(file);
  if (f.content_hash == f.computed_hash) return;
  r.problems.add(ModelFileCode::Changed, std::string("/@") + kContentHashAttribute,
                 f.content_hash.empty()
                     ? std::string("the file has no content hash: it was not written by a radx starter")
                     : "the file was changed after the starter wrote it: its content hash is " +
                           f.computed_hash + ", the starter stored " + f.content_hash +
                           "; run the starter on the deck again rather than edit the model file");
}

// The IdMaps of a model whose ids passed the checks (positive and unique).
void build_id_maps(Model& m) {
  std::int64_t ignored = 0;
  m.nodes.index.build(m.nodes.id, ignored);
  for_each_block(m, [&](const char*, model::ElementBlock& b) { b.index.build(b.id, ignored); });
}

void read_file(const std::string& path, Model& m, ModelFileReading& r) {
  Handle file = open_file_read_only(path);
  r.fingerprint = read_fingerprint(file);
  if (!same_format(r.fingerprint, r)) return;
  check_content_hash(file, r);
  m = Model{};
  read_radx(file, m);
  r.fingerprint.run_name = m.run_name;
  file.close("cannot close file " + path);
  const ModelFileProblems content = check_model_content(m);
  for (const auto& p : content.items) r.problems.add(p.code, p.where, p.message);
  r.problems.count += content.count - content.items.size();
  if (r.problems.empty()) build_id_maps(m);
}

}  // namespace

ModelFileOrigin model_file_origin(std::string run, const std::vector<std::string>& deck_files,
                                  std::string radx_commit) {
  ModelFileOrigin o;
  o.run = std::move(run);
  o.deck_files = deck_files;
  o.radx_commit = std::move(radx_commit);
  std::uint64_t h = 0;
  for (const auto& name : deck_files) {
    h = hash_bytes(name.data(), name.size(), h);
    std::ifstream in(name, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    h = hash_bytes(text.data(), text.size(), h);
  }
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  o.deck_hash = hex;
  return o;
}

bool write_model_file(const Model& m, const std::string& path, const ModelFileOrigin& origin,
                      std::string& error) {
  const std::string part = path + ".part";
  try {
    const QuietHdf5 quiet;
    write_file(m, origin, part);
    replace_file(part, path);
    return true;
  } catch (const std::exception& e) {
    error = "cannot write model file " + path + ": " + e.what();
  }
  std::error_code ignored;
  fs::remove(part, ignored);
  return false;
}

bool write_model_file(const Model& m, const std::string& path, std::string& error) {
  return write_model_file(m, path, ModelFileOrigin{}, error);
}

ModelFileReading read_model_file(const std::string& path, Model& m) {
  ModelFileReading r;
  try {
    const QuietHdf5 quiet;
    read_file(path, m, r);
  } catch (const std::exception& e) {
    r.error = e.what();
  }
  return r;
}

bool read_model_file(const std::string& path, Model& m, std::string& error) {
  const ModelFileReading r = read_model_file(path, m);
  if (r.ok()) return true;
  error = "cannot read model file " + path + ": " + (r.error.empty() ? "" : r.error);
  for (const auto& p : r.problems.items)
    error += (error.back() == ' ' ? "" : "; ") + p.where + ": " + p.message;
  if (r.problems.count > r.problems.items.size())
    error += "; and " + std::to_string(r.problems.count - r.problems.items.size()) + " more";
  return false;
}

}  // namespace radx::io
