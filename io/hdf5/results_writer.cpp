// Animation states for ParaView (docs/theory/results-format.md sections 1 to 5): P.mesh.hdf once, then per
// state P_%06d.hdf (topology and time-invariant arrays as external links into the mesh file) and the two
// indexes P.hdf.series and P.xmf, extended after every state.
//
// Crash safety, in the order of docs/theory/results-format.md section 5: a state is written to `name.part`,
// closed, flushed to disk and renamed; then each index gets the state's entry. So at any moment every index
// lists only complete state files, and no HDF5 file is open between two calls (a killed process cannot leave
// a file that HDF5 refuses to open, and ParaView can read a running job).
//
// Why the indexes are extended in place rather than rewritten: rewriting them whole costs a time growing
// with the states already written, so a long run's states would cost more and more. Each index is a fixed
// head, one entry per state and a fixed tail (the closing brackets or tags); the first state writes the
// whole index to `index.tmp`, flushed and renamed over the index, and each later state writes its entry
// and the tail again over the old tail, in one write, then flushes the file. The index is valid before and
// after that write; a reader that opens it during the write, or a kill inside the write, can see it cut
// (a later state, or the next run, writes it whole again).
//
// Speed: the state's big arrays are written straight from the caller's spans, without fill value and
// without type conversion, one H5Dwrite per dataset, in chunks of about 1 MiB with a Fletcher32 checksum
// each (hdf5_util.hpp; no compression: deflate would cost seconds per state of a million nodes).
#include "io/hdf5/results_writer.hpp"

#include <fcntl.h>
#include <hdf5.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>

#include "io/hdf5/hdf5_util.hpp"
#include "io/hdf5/vtkhdf_mesh.hpp"
#include "io/listing/unit_labels.hpp"
#include "io/xml_text.hpp"

namespace radx::io {

namespace {

namespace fs = std::filesystem;

// Arrays every state has, whose names the extra arrays must not take.
constexpr std::array<const char*, 7> kReservedNames{"displacement", "velocity", "element_status", "node_id",
                                                    "element_id",   "part_id",  "vtkGhostType"};

// vtkDataSetAttributes::HIDDENCELL: VTK's ghost-cell flag of a cell that filters and renderers skip (ParaView
// does not draw it), the VTK convention for a deleted element that still belongs to the mesh.
constexpr std::uint8_t kVtkHiddenCell = 32;

// Attaches the string attribute `units` to the object `name` of `loc`: a fixed-length UTF-8 string, not a
// variable-length one, whose bytes would sit in the file's global heap: HDF5 1.10 then fails to read the
// attribute of a dataset reached through an external link while the linked file is also open ("bad global
// heap collection signature"), which is how a state's node_id, part_id and element_id are reached.
void write_units_attr(hid_t loc, const std::string& name, const std::string& unit) {
  const std::string what = "cannot write the units of " + h5::path_of(loc, name);
  const std::string value = unit.empty() ? std::string("1") : unit;
  const h5::Handle object(H5Oopen(loc, name.c_str(), H5P_DEFAULT), H5Oclose, what);
  const h5::Handle type(H5Tcopy(H5T_C_S1), H5Tclose, what);
  h5::check(H5Tset_size(type, value.size()), what);
  h5::check(H5Tset_strpad(type, H5T_STR_NULLPAD), what);
  h5::check(H5Tset_cset(type, H5T_CSET_UTF8), what);
  const h5::Handle space(H5Screate(H5S_SCALAR), H5Sclose, what);
  const h5::Handle a(H5Acreate2(object, "units", type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose, what);
  h5::check(H5Awrite(a, type, value.data()), what);
}

// Lines of text as the bytes of a uint8 field-data array: ParaView 5.11's VTKHDF reader reads numeric
// arrays only (an HDF5 string dataset arrives as a vtkStringArray of empty strings), so the text that a
// ParaView script needs (units, part titles) goes as UTF-8 bytes, one line per entry.
std::vector<std::uint8_t> text_bytes(const std::vector<std::string>& lines) {
  std::vector<std::uint8_t> out;
  for (const std::string& l : lines) {
    out.insert(out.end(), l.begin(), l.end());
    out.push_back('\n');
  }
  return out;
}

// The 17 significant digits that give back the same double, in the C locale whatever the process locale
// is (std::to_chars ignores it; printf would print "0,5" under a German locale and break both indexes).
std::string exact_number(double v) {
  std::array<char, 32> buf{};
  const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), v, std::chars_format::general, 17);
  return std::string(buf.data(), r.ptr);
}

std::string state_file_name(const std::string& prefix, int index) {
  std::array<char, 16> digits{};
  std::snprintf(digits.data(), digits.size(), "%06d", index);
  return prefix + "_" + digits.data() + ".hdf";
}

// True for the state files of `prefix` and their leftovers: prefix_ + digits (at least 6) + .hdf or
// .hdf.part. Other names starting with the prefix (another prefix "P_x", "P_000001.hdf.bak") do not match.
bool is_state_file_name(const std::string& name, const std::string& prefix) {
  if (name.size() <= prefix.size() + 1 || name.compare(0, prefix.size(), prefix) != 0 ||
      name[prefix.size()] != '_') {
    return false;
  }
  std::size_t i = prefix.size() + 1;
  const std::size_t first_digit = i;
  while (i < name.size() && name[i] >= '0' && name[i] <= '9') ++i;
  if (i - first_digit < 6) return false;
  const std::string rest = name.substr(i);
  return rest == ".hdf" || rest == ".hdf.part";
}

std::string json_escape(const std::string& s) {
  std::string out;
  for (const char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      std::array<char, 8> u{};
      std::snprintf(u.data(), u.size(), "\\u%04x", static_cast<unsigned>(c));
      out += u.data();
    } else {
      out += c;
    }
  }
  return out;
}

// Writes `text` to `tmp` and flushes it to disk, so that once renamed it is complete even after a
// system crash.
void write_text_file_synced(const std::string& tmp, const std::string& text) {
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw h5::Failure("cannot create " + tmp + ": " + std::generic_category().message(errno));
  std::size_t done = 0;
  bool ok = true;
  while (ok && done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    ok = n > 0;
    if (ok) done += static_cast<std::size_t>(n);
  }
  const int error = ok ? 0 : errno;
  ok = ok && ::fsync(fd) == 0;
  ok = (::close(fd) == 0) && ok;
  if (!ok) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw h5::Failure("cannot write " + tmp + ": " +
                      std::generic_category().message(error != 0 ? error : errno));
  }
}

// Replaces both indexes: each is written to `index.tmp` and flushed first, then both are renamed (atomic
// each) one right after the other, and the folder is synced once. Each index is always either the
// previous complete one or the new one; preparing both before renaming either keeps the moment when one
// lists a state that the other does not yet to two rename calls.
void replace_indexes(const std::array<std::pair<std::string, std::string>, 2>& path_and_text) {
  for (const auto& [path, text] : path_and_text) write_text_file_synced(path + ".tmp", text);
  for (const auto& [path, text] : path_and_text) {
    std::error_code ec;
    fs::rename(path + ".tmp", path, ec);
    if (ec) throw h5::Failure("cannot rename " + path + ".tmp to " + path + ": " + ec.message());
  }
  h5::sync_folder_of(path_and_text[0].first);
}

// Writes `text` at byte `offset` of the existing file `path` in one call and flushes the file to disk.
void write_at_synced(const std::string& path, std::uint64_t offset, const std::string& text) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd < 0) throw h5::Failure("cannot open " + path + ": " + std::generic_category().message(errno));
  std::size_t done = 0;
  bool ok = true;
  while (ok && done < text.size()) {
    const ssize_t n = ::pwrite(fd, text.data() + done, text.size() - done, static_cast<off_t>(offset + done));
    if (n < 0 && errno == EINTR) continue;
    ok = n > 0;
    if (ok) done += static_cast<std::size_t>(n);
  }
  const int error = ok ? 0 : errno;
  ok = ok && ::fdatasync(fd) == 0;
  ok = (::close(fd) == 0) && ok;
  if (!ok)
    throw h5::Failure("cannot write " + path + ": " +
                      std::generic_category().message(error != 0 ? error : errno));
}

// The XDMF AttributeType of an array of k components. Not Tensor6 for a 6-component array: ParaView
// 5.11's XDMF 2 reader expands it to 9 components in another order (XX XY XZ YY YZ ZZ), which would
// scramble stress (XX YY ZZ XY YZ XZ); "Matrix" keeps the k stored components in both XDMF readers.
const char* xdmf_attribute_type(int components) {
  switch (components) {
    case 1: return "Scalar";
    case 3: return "Vector";
    default: return "Matrix";
  }
}

// One array of a state as the indexes describe it.
struct IndexedArray {
  std::string name;
  bool on_points = true;
  int components = 1;
  const char* number_type = "Float";  // XDMF NumberType and Precision of the dataset
  int precision = 4;
  bool in_mesh = false;  // time-invariant: read from P.mesh.hdf
};

}  // namespace

struct ResultsWriter::Impl {
  std::string dir;
  std::string prefix;
  std::vector<ResultArray> arrays;
  std::string length_unit, velocity_unit, time_unit;
  VtkhdfMeshSizes mesh;
  std::vector<IndexedArray> indexed;                   // every array of a state, in the order of the indexes
  std::vector<std::pair<std::string, double>> states;  // file name, time
  // Where the tail of the .xmf and of the series starts; empty when the indexes must be written whole.
  std::vector<std::uint64_t> index_end;
  double seconds = 0;

  [[nodiscard]] std::string path(const std::string& name) const { return (fs::path(dir) / name).string(); }
  [[nodiscard]] std::string mesh_name() const { return prefix + ".mesh.hdf"; }

  void remove_earlier_run() const;
  void write_mesh(const model::Model& model);
  void write_mesh_extras(hid_t file, const model::Model& model) const;
  void write_state_file(const std::string& part, const ResultState& state, int index) const;
  [[nodiscard]] std::string series_entry(std::size_t i) const;
  [[nodiscard]] std::string series_text() const;
  [[nodiscard]] std::string xmf_head() const;
  [[nodiscard]] std::string xmf_entry(std::size_t i) const;
  [[nodiscard]] std::string xmf_text() const;
  void index_last_state();
};

void remove_result_set(const std::string& dir, const std::string& prefix) {
  const std::string mesh = prefix + ".mesh.hdf";
  const std::array<std::string, 6> fixed{
      prefix + ".hdf.series", prefix + ".hdf.series.tmp", prefix + ".xmf", prefix + ".xmf.tmp", mesh,
      mesh + ".part"};
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    bool stale = is_state_file_name(name, prefix);
    for (const std::string& f : fixed) stale = stale || name == f;
    if (!stale) continue;
    std::error_code removed;
    fs::remove(e.path(), removed);
    if (removed)
      throw h5::Failure("cannot remove " + e.path().string() + " of an earlier run: " + removed.message());
  }
  // A folder that does not exist holds nothing to remove.
  if (ec && ec != std::errc::no_such_file_or_directory)
    throw h5::Failure("cannot list folder " + dir + ": " + ec.message());
}

// Removes what an earlier run of the same prefix left in the folder, so the new indexes never sit next to
// states of another run (a longer earlier run would leave P_000042.hdf that no index lists but a user
// opening the folder as a file group would load).
void ResultsWriter::Impl::remove_earlier_run() const {
  remove_result_set(dir, prefix);
}

void ResultsWriter::Impl::write_mesh(const model::Model& model) {
  const std::string final_path = path(mesh_name());
  const std::string part = final_path + ".part";
  try {
    h5::WriteFile file = h5::create_file(part);
    mesh = write_vtkhdf_mesh(file, model);
    write_mesh_extras(file, model);
    file.close();
    h5::sync_file(part);
    h5::replace_file(part, final_path);
  } catch (...) {
    std::error_code ignored;
    fs::remove(part, ignored);
    throw;
  }
}

// The mesh file's additions to the shared VTKHDF mesh: units of its datasets, and the parts as field data
// (ids, and titles one per line in the same order; the titles also as a string attribute for HDF5 tools).
void ResultsWriter::Impl::write_mesh_extras(hid_t file, const model::Model& model) const {
  const h5::Handle vtk = h5::open_group(file, "VTKHDF");
  write_units_attr(vtk, "Points", length_unit);
  write_units_attr(vtk, "PointData/node_id", "1");
  write_units_attr(vtk, "CellData/part_id", "1");
  write_units_attr(vtk, "CellData/element_id", "1");
  std::vector<std::int64_t> ids;
  std::vector<std::string> titles;
  for (const model::Part& p : model.parts) {
    ids.push_back(p.id);
    // One line per title: a line break inside a title would shift the lines.
    std::string t = p.title;
    for (char& c : t)
      if (c == '\n' || c == '\r') c = ' ';
    titles.push_back(t);
  }
  const h5::Handle field_data = h5::create_group(vtk, "FieldData");
  h5::write_dataset(field_data, "part_ids", ids);
  h5::write_dataset(field_data, "part_titles", text_bytes(titles));
  h5::Handle ids_object(H5Oopen(field_data, "part_ids", H5P_DEFAULT), H5Oclose, "cannot open part_ids");
  h5::write_string_array_attr(ids_object, "titles", titles);
}

void ResultsWriter::Impl::write_state_file(const std::string& part, const ResultState& state,
                                           int index) const {
  h5::WriteFile file = h5::create_file(part);
  const std::string mesh_file = mesh_name();
  {
    const h5::Handle vtk = h5::create_group(file, "VTKHDF");
    const std::array<std::int64_t, 2> version{1, 0};
    h5::write_attr(vtk, "Version", version.data(), version.size());
    h5::write_fixed_string_attr(vtk, "Type", "UnstructuredGrid");
    for (const char* topology :
         {"NumberOfPoints", "NumberOfCells", "NumberOfConnectivityIds", "Connectivity", "Offsets", "Types"}) {
      h5::link_external(mesh_file, std::string("/VTKHDF/") + topology, vtk, topology);
    }
    h5::write_dataset(vtk, "Points", state.points, 3);

    const h5::Handle point_data = h5::create_group(vtk, "PointData");
    const h5::Handle cell_data = h5::create_group(vtk, "CellData");
    h5::link_external(mesh_file, "/VTKHDF/PointData/node_id", point_data, "node_id");
    h5::link_external(mesh_file, "/VTKHDF/CellData/part_id", cell_data, "part_id");
    h5::link_external(mesh_file, "/VTKHDF/CellData/element_id", cell_data, "element_id");
    h5::write_dataset(point_data, "displacement", state.displacement, 3);
    h5::write_dataset(point_data, "velocity", state.velocity, 3);
    h5::write_dataset(cell_data, "element_status", state.element_status);
    std::vector<std::uint8_t> ghost(state.element_status.size());
    for (std::size_t c = 0; c < ghost.size(); ++c)
      ghost[c] = state.element_status[c] == 0 ? kVtkHiddenCell : 0;
    h5::write_dataset(cell_data, "vtkGhostType", ghost);
    for (std::size_t a = 0; a < arrays.size(); ++a) {
      const ResultArray& r = arrays[a];
      const hsize_t cols = r.components > 1 ? static_cast<hsize_t>(r.components) : 0;
      h5::write_dataset(r.on_points ? point_data : cell_data, r.name, state.arrays[a], cols);
    }

    const h5::Handle field_data = h5::create_group(vtk, "FieldData");
    h5::write_dataset(field_data, "TimeValue", std::vector<double>{state.time});
    h5::write_dataset(field_data, "StateIndex", std::vector<std::int64_t>{index});
    h5::link_external(mesh_file, "/VTKHDF/FieldData/part_ids", field_data, "part_ids");
    h5::link_external(mesh_file, "/VTKHDF/FieldData/part_titles", field_data, "part_titles");

    // Units: an attribute on every dataset of the state, and the list as field data for ParaView.
    std::vector<std::string> unit_lines;
    const auto unit = [&](hid_t group, const std::string& name, const std::string& label) {
      write_units_attr(group, name, label);
      unit_lines.push_back(name + "\t" + label);
    };
    unit(vtk, "Points", length_unit);
    unit(point_data, "displacement", length_unit);
    unit(point_data, "velocity", velocity_unit);
    unit_lines.push_back("node_id\t1");
    unit(cell_data, "element_status", "1");
    unit(cell_data, "vtkGhostType", "1");
    unit_lines.push_back("part_id\t1");
    unit_lines.push_back("element_id\t1");
    for (const ResultArray& r : arrays) unit(r.on_points ? point_data : cell_data, r.name, r.unit);
    unit(field_data, "TimeValue", time_unit);
    unit(field_data, "StateIndex", "1");
    h5::write_dataset(field_data, "units", text_bytes(unit_lines));
  }
  file.close();
  // On disk before the rename: after a system crash a listed state is complete, not an empty file.
  h5::sync_file(part);
}

constexpr const char* kSeriesHead = "{\n  \"file-series-version\": \"1.0\",\n  \"files\": [\n";
constexpr const char* kSeriesTail = "\n  ]\n}\n";
constexpr const char* kXmfTail = "    </Grid>\n  </Domain>\n</Xdmf>\n";

// Entry `i` of the series: the entries are separated by ",\n", the tail starts the line after the last.
std::string ResultsWriter::Impl::series_entry(std::size_t i) const {
  return std::string(i > 0 ? ",\n" : "") + "    { \"name\": \"" + json_escape(states[i].first) +
         "\", \"time\": " + exact_number(states[i].second) + " }";
}

std::string ResultsWriter::Impl::series_text() const {
  std::string s = kSeriesHead;
  for (std::size_t i = 0; i < states.size(); ++i) s += series_entry(i);
  return s + kSeriesTail;
}

// XDMF 3.0 temporal collection. Every DataItem names a whole dataset (no HyperSlab: ParaView 5.11's Xdmf3
// reader returns empty data for those); the topology and time-invariant arrays come from the mesh file.
std::string ResultsWriter::Impl::xmf_head() const {
  return "<?xml version=\"1.0\" ?>\n"
         "<Xdmf Version=\"3.0\" xmlns:xi=\"http://www.w3.org/2001/XInclude\">\n"
         "  <Domain>\n"
         "    <Grid Name=\"" +
         xml_escape(prefix) + "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
}

std::string ResultsWriter::Impl::xmf_entry(std::size_t i) const {
  const auto& [name, time] = states[i];
  const std::string np = std::to_string(mesh.points);
  const std::string nc = std::to_string(mesh.cells);
  const std::string mesh_file = xml_escape(mesh_name());
  const auto data_item = [](const std::string& dims, const char* number_type, int precision,
                            const std::string& file, const std::string& object) {
    return "<DataItem Dimensions=\"" + dims + "\" NumberType=\"" + number_type + "\" Precision=\"" +
           std::to_string(precision) + "\" Format=\"HDF\">" + file + ":" + object + "</DataItem>";
  };
  const std::string state_file = xml_escape(name);
  std::string s =
      "      <Grid Name=\"" + xml_escape(name.substr(0, name.size() - 4)) + "\" GridType=\"Uniform\">\n";
  s += "        <Time Value=\"" + exact_number(time) + "\"/>\n";
  s += "        <Topology TopologyType=\"Mixed\" NumberOfElements=\"" + nc + "\">\n          " +
       data_item(std::to_string(mesh.mixed_topology), "Int", 8, mesh_file, "/XDMF/MixedTopology") +
       "\n        </Topology>\n";
  s += "        <Geometry GeometryType=\"XYZ\">\n          " +
       data_item(np + " 3", "Float", 8, state_file, "/VTKHDF/Points") + "\n        </Geometry>\n";
  for (const IndexedArray& a : indexed) {
    const std::string& n = a.on_points ? np : nc;
    const std::string dims = a.components > 1 ? n + " " + std::to_string(a.components) : n;
    const std::string object = std::string("/VTKHDF/") + (a.on_points ? "PointData/" : "CellData/") + a.name;
    s += "        <Attribute Name=\"" + xml_escape(a.name) + "\" AttributeType=\"" +
         xdmf_attribute_type(a.components) + "\" Center=\"" + (a.on_points ? "Node" : "Cell") +
         "\">\n          " +
         data_item(dims, a.number_type, a.precision, a.in_mesh ? mesh_file : state_file, xml_escape(object)) +
         "\n        </Attribute>\n";
  }
  s += "      </Grid>\n";
  return s;
}

std::string ResultsWriter::Impl::xmf_text() const {
  std::string s = xmf_head();
  for (std::size_t i = 0; i < states.size(); ++i) s += xmf_entry(i);
  return s + kXmfTail;
}

// Adds the last state to both indexes (the .xmf first: the series is what users and a watcher open, so
// when it lists a state the .xmf does too). After a failure both are written whole at the next state.
void ResultsWriter::Impl::index_last_state() {
  const std::size_t last = states.size() - 1;
  if (index_end.empty()) {
    const std::string xmf = xmf_text();
    const std::string series = series_text();
    replace_indexes({{{path(prefix + ".xmf"), xmf}, {path(prefix + ".hdf.series"), series}}});
    index_end = {xmf.size() - std::char_traits<char>::length(kXmfTail),
                 series.size() - std::char_traits<char>::length(kSeriesTail)};
    return;
  }
  try {
    const std::array<std::pair<std::string, std::string>, 2> add{
        {{prefix + ".xmf", xmf_entry(last)}, {prefix + ".hdf.series", series_entry(last)}}};
    const std::array<const char*, 2> tails{kXmfTail, kSeriesTail};
    for (std::size_t k = 0; k < 2; ++k) {
      write_at_synced(path(add[k].first), index_end[k], add[k].second + tails[k]);
      index_end[k] += add[k].second.size();
    }
  } catch (...) {
    index_end.clear();
    throw;
  }
}

ResultsWriter::ResultsWriter(const model::Model& model, std::string dir, std::string prefix,
                             std::vector<ResultArray> arrays)
    : impl_(std::make_unique<Impl>()) {
  const auto start = std::chrono::steady_clock::now();
  Impl& w = *impl_;
  w.dir = dir.empty() ? std::string(".") : std::move(dir);
  w.prefix = std::move(prefix);
  w.arrays = std::move(arrays);
  w.length_unit = unit_label(model.units, 0, 1, 0);
  w.velocity_unit = unit_label(model.units, 0, 1, -1);
  w.time_unit = unit_label(model.units, 0, 0, 1);
  for (ResultArray& a : w.arrays)
    if (a.unit.empty()) a.unit = "1";
  if (w.prefix.empty() || w.prefix.find('/') != std::string::npos) {
    throw std::runtime_error("invalid result prefix '" + w.prefix + "': a file name without '/' is expected");
  }
  w.indexed.push_back({"displacement", true, 3, "Float", 4, false});
  w.indexed.push_back({"velocity", true, 3, "Float", 4, false});
  w.indexed.push_back({"node_id", true, 1, "Int", 8, true});
  for (const ResultArray& a : w.arrays) {
    bool clash = false;
    for (const IndexedArray& b : w.indexed) clash = clash || a.name == b.name;
    for (const char* r : kReservedNames) clash = clash || a.name == r;
    if (a.name.empty() || a.name.find_first_of("/.") != std::string::npos || a.components < 1 || clash) {
      throw std::runtime_error("invalid result array '" + a.name + "' with " + std::to_string(a.components) +
                               " components: names are unique, not empty, without '/' or '.', and not one of "
                               "the arrays every state has");
    }
    if (a.on_points) w.indexed.push_back({a.name, true, a.components, "Float", 4, false});
  }
  w.indexed.push_back({"element_status", false, 1, "UChar", 1, false});
  w.indexed.push_back({"vtkGhostType", false, 1, "UChar", 1, false});
  w.indexed.push_back({"part_id", false, 1, "Int", 8, true});
  w.indexed.push_back({"element_id", false, 1, "Int", 8, true});
  for (const ResultArray& a : w.arrays) {
    if (!a.on_points) w.indexed.push_back({a.name, false, a.components, "Float", 4, false});
  }

  const h5::QuietHdf5 quiet;
  check_vtkhdf_mesh(model);
  std::error_code ec;
  fs::create_directories(w.dir, ec);
  if (ec) throw std::runtime_error("cannot create result folder " + w.dir + ": " + ec.message());
  w.remove_earlier_run();
  try {
    w.write_mesh(model);
  } catch (const std::exception& e) {
    throw std::runtime_error("cannot write result mesh file " + w.path(w.mesh_name()) + ": " + e.what());
  }
  w.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

ResultsWriter::~ResultsWriter() = default;

bool ResultsWriter::write_state(const ResultState& state) {
  Impl& w = *impl_;
  if (!std::isfinite(state.time) || (!w.states.empty() && !(state.time > w.states.back().second)))
    return false;
  const auto start = std::chrono::steady_clock::now();

  const auto np = static_cast<std::size_t>(w.mesh.points);
  const auto nc = static_cast<std::size_t>(w.mesh.cells);
  const auto expect = [](std::size_t have, std::size_t want, const std::string& what) {
    if (have != want) {
      throw std::runtime_error("result state: " + what + " has " + std::to_string(have) +
                               " values, expected " + std::to_string(want));
    }
  };
  expect(state.points.size(), 3 * np, "points");
  expect(state.displacement.size(), 3 * np, "displacement");
  expect(state.velocity.size(), 3 * np, "velocity");
  expect(state.element_status.size(), nc, "element_status");
  expect(state.arrays.size(), w.arrays.size(), "the list of arrays");
  for (std::size_t a = 0; a < w.arrays.size(); ++a) {
    const ResultArray& r = w.arrays[a];
    expect(state.arrays[a].size(), (r.on_points ? np : nc) * static_cast<std::size_t>(r.components), r.name);
  }

  const int index = static_cast<int>(w.states.size());
  const std::string name = state_file_name(w.prefix, index);
  const std::string final_path = w.path(name);
  const std::string part = final_path + ".part";
  try {
    const h5::QuietHdf5 quiet;
    w.write_state_file(part, state, index);
    h5::replace_file(part, final_path);
  } catch (const std::exception& e) {
    std::error_code ignored;
    fs::remove(part, ignored);
    throw std::runtime_error("cannot write result state " + final_path + ": " + e.what());
  }
  w.states.emplace_back(name, state.time);
  // The state file is complete and kept even if an index cannot be written: the next state's indexes
  // list it.
  try {
    w.index_last_state();
  } catch (const std::exception& e) {
    throw std::runtime_error(std::string("cannot write a result index: ") + e.what());
  }
  w.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return true;
}

int ResultsWriter::states_written() const {
  return static_cast<int>(impl_->states.size());
}
double ResultsWriter::seconds_writing() const {
  return impl_->seconds;
}
std::string ResultsWriter::series_path() const {
  return impl_->path(impl_->prefix + ".hdf.series");
}
std::string ResultsWriter::xmf_path() const {
  return impl_->path(impl_->prefix + ".xmf");
}
std::string ResultsWriter::mesh_path() const {
  return impl_->path(impl_->mesh_name());
}

}  // namespace radx::io
