// Time history (io/hdf5/time_history.hpp, io/hdf5/time_history_export.hpp, `radx th`): rows appended across
// two flushes, read back by read_time_history and independently with the HDF5 C API (shape, chunking,
// attributes, values), the atomic rewrite (no .part left, a failed flush keeps the previous file), the
// listing, CSV export with selectors, and the exit codes of the `radx th` command.
//
// Tolerances: values are compared EXACTLY (==). The file stores the doubles' bits (float64 datasets),
// and the CSV writes 17 significant digits, which read back to the same double, so any difference is a
// bug, not rounding.
#include <hdf5.h>
#include <sys/stat.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>
#include "test_util.hpp"

#include "io/hdf5/time_history.hpp"
#include "io/hdf5/time_history_export.hpp"

namespace {

namespace fs = std::filesystem;
using radx::io::ThGroupData;
using radx::io::ThGroupLayout;
using radx::io::TimeHistoryWriter;
using radx::test::TempDir;

constexpr double kG = 9.81;         // m/s^2
constexpr double kDt = 1e-3 / 3.0;  // s; not a decimal number, so the CSV must carry all 17 digits
constexpr std::int64_t kBigId = 4'000'000'000LL;  // beyond 32 bits

// Free fall from rest: x(t) = 0.5 g t^2, v(t) = g t. Object `k` (0, 1) falls from its own offset so
// the two objects' columns differ.
double fall_x(double t, int k) {
  return 0.5 * kG * t * t + 10.0 * k;
}
double fall_v(double t, int k) {
  return kG * t * (1 + k);
}
// Global energies of a unit mass: kinetic 0.5 v^2, internal a made-up function of t.
double energy_ke(double t) {
  return 0.5 * kG * kG * t * t;
}
double energy_ie(double t) {
  return std::sin(t) / 7.0;
}

std::vector<ThGroupLayout> layouts() {
  ThGroupLayout global{"global", "", "", {}, {"IE", "KE"}, {"J", "J"}, {}};
  ThGroupLayout nodes{"node/1", "falling nodes, two", "node", {12, kBigId}, {"DX", "VX"}, {"m", "m/s"}, {}};
  return {global, nodes};
}

double time_of(int row) {
  return row * kDt;
}

void append_row(TimeHistoryWriter& w, int row) {
  const double t = time_of(row);
  const std::vector<double> global{energy_ie(t), energy_ke(t)};
  const std::vector<double> nodes{fall_x(t, 0), fall_v(t, 0), fall_x(t, 1), fall_v(t, 1)};
  w.append(t, {global, nodes});
}

// Expected [rows][1 + 4] values of node/1.
std::vector<double> node_rows(int rows) {
  std::vector<double> out;
  for (int r = 0; r < rows; ++r) {
    const double t = time_of(r);
    out.insert(out.end(), {t, fall_x(t, 0), fall_v(t, 0), fall_x(t, 1), fall_v(t, 1)});
  }
  return out;
}

std::vector<double> global_rows(int rows) {
  std::vector<double> out;
  for (int r = 0; r < rows; ++r) {
    const double t = time_of(r);
    out.insert(out.end(), {t, energy_ie(t), energy_ke(t)});
  }
  return out;
}

// Writes `rows` rows and flushes once.
std::string write_file(const TempDir& dir, int rows) {
  const std::string path = dir.file("P_th.h5");
  TimeHistoryWriter w(path, layouts(), "s");
  for (int r = 0; r < rows; ++r) append_row(w, r);
  w.flush();
  return path;
}

std::vector<ThGroupData> read_ok(const std::string& path) {
  std::vector<ThGroupData> groups;
  std::string error;
  INFO(error);
  REQUIRE(radx::io::read_time_history(path, groups, error));
  return groups;
}

// --- Independent reading with the HDF5 C API (no io/ code) -----------------------------------------

struct H5Id {
  hid_t id;
  herr_t (*close)(hid_t);
  ~H5Id() {
    if (id >= 0) close(id);
  }
};

std::vector<std::string> c_string_array_attr(hid_t obj, const char* name) {
  const H5Id a{H5Aopen(obj, name, H5P_DEFAULT), H5Aclose};
  REQUIRE(a.id >= 0);
  const H5Id space{H5Aget_space(a.id), H5Sclose};
  const auto n = static_cast<std::size_t>(H5Sget_simple_extent_npoints(space.id));
  const H5Id type{H5Tcopy(H5T_C_S1), H5Tclose};
  H5Tset_size(type.id, H5T_VARIABLE);
  H5Tset_cset(type.id, H5T_CSET_UTF8);  // radx writes UTF-8 strings (io/hdf5/hdf5_util.hpp)
  std::vector<char*> p(n, nullptr);
  if (n > 0) REQUIRE(H5Aread(a.id, type.id, p.data()) >= 0);
  std::vector<std::string> out;
  for (char* s : p) {
    out.emplace_back(s);
    std::free(s);  // NOLINT: HDF5 allocates variable-length strings with malloc
  }
  return out;
}

std::string c_string_attr(hid_t obj, const char* name) {
  const auto v = c_string_array_attr(obj, name);
  REQUIRE(v.size() == 1);
  return v[0];
}

// Runs a command line; stdout and stderr go to files of `dir`. Returns the exit code.
int run(const std::string& cmd, const TempDir& dir) {
  const int rc = std::system((cmd + " >" + dir.file("stdout.txt") + " 2>" + dir.file("stderr.txt")).c_str());
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// A CSV without quoted fields: its header fields and its rows of numbers.
struct Csv {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;
};

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string f;
  while (std::getline(ss, f, ',')) out.push_back(f);
  return out;
}

Csv parse_csv(const std::string& text) {
  Csv csv;
  std::stringstream ss(text);
  std::string line;
  REQUIRE(std::getline(ss, line));
  csv.header = split(line);
  while (std::getline(ss, line)) {
    std::vector<double> row;
    for (const auto& f : split(line)) {
      char* end = nullptr;
      row.push_back(std::strtod(f.c_str(), &end));
      REQUIRE(*end == '\0');
    }
    csv.rows.push_back(row);
  }
  return csv;
}

std::string export_csv(const std::vector<ThGroupData>& groups, const std::vector<std::string>& selectors) {
  std::vector<radx::io::ThColumnRef> chosen;
  std::string error;
  INFO(error);
  REQUIRE(radx::io::select_th_columns(groups, selectors, chosen, error));
  std::ostringstream os;
  REQUIRE(radx::io::write_th_csv(groups, chosen, os, error));
  return os.str();
}

}  // namespace

TEST_CASE("time history: rows appended after the first flush are in the second file", "[th]") {
  TempDir dir;
  const std::string path = dir.file("P_th.h5");
  TimeHistoryWriter w(path, layouts(), "s");
  CHECK_FALSE(fs::exists(path));  // nothing before the first flush
  for (int r = 0; r < 5; ++r) append_row(w, r);
  w.flush();
  CHECK(w.rows() == 5);
  CHECK_FALSE(fs::exists(path + ".part"));
  auto groups = read_ok(path);
  REQUIRE(groups.size() == 2);
  CHECK(groups[0].rows == global_rows(5));
  CHECK(groups[1].rows == node_rows(5));

  for (int r = 5; r < 12; ++r) append_row(w, r);
  w.flush();
  CHECK(w.rows() == 12);
  CHECK_FALSE(fs::exists(path + ".part"));
  groups = read_ok(path);
  REQUIRE(groups.size() == 2);
  const auto& g = groups[0];
  CHECK(g.layout.path == "global");
  CHECK(g.layout.title.empty());
  CHECK(g.layout.object_kind.empty());
  CHECK(g.layout.objects.empty());
  CHECK(g.layout.variables == std::vector<std::string>{"IE", "KE"});
  CHECK(g.layout.units == std::vector<std::string>{"J", "J"});
  CHECK(g.columns == 3);
  CHECK(g.time_unit == "s");
  CHECK(g.rows == global_rows(12));
  const auto& n = groups[1];
  CHECK(n.layout.path == "node/1");
  CHECK(n.layout.title == "falling nodes, two");
  CHECK(n.layout.object_kind == "node");
  CHECK(n.layout.objects == std::vector<std::int64_t>{12, kBigId});
  CHECK(n.layout.variables == std::vector<std::string>{"DX", "VX"});
  CHECK(n.layout.units == std::vector<std::string>{"m", "m/s"});
  CHECK(n.columns == 5);
  CHECK(n.rows == node_rows(12));

  const auto cols = radx::io::th_columns(n.layout, n.time_unit);
  REQUIRE(cols.size() == 5);
  CHECK(cols[0].name == "time");
  CHECK(cols[0].unit == "s");
  CHECK(cols[1].name == "node/1:12:DX");
  CHECK(cols[4].name == "node/1:4000000000:VX");
  CHECK(cols[4].unit == "m/s");
  CHECK(radx::io::th_columns(g.layout, "s")[2].name == "global:KE");
}

TEST_CASE("time history: the file read with the HDF5 C API has the documented layout", "[th]") {
  TempDir dir;
  const std::string path = write_file(dir, 9);
  const H5Id file{H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose};
  REQUIRE(file.id >= 0);

  std::int64_t version = 0;
  {
    const H5Id a{H5Aopen(file.id, "radx_th_format_version", H5P_DEFAULT), H5Aclose};
    REQUIRE(a.id >= 0);
    REQUIRE(H5Aread(a.id, H5T_NATIVE_INT64, &version) >= 0);
  }
  CHECK(version == 1);
  CHECK(c_string_attr(file.id, "time_unit") == "s");
  CHECK(c_string_array_attr(file.id, "groups") == std::vector<std::string>{"global", "node/1"});

  struct Expect {
    const char* path;
    std::vector<std::string> columns, units;
    std::vector<double> values;
  };
  const std::vector<Expect> expect = {
      {"global", {"time", "IE", "KE"}, {"s", "J", "J"}, global_rows(9)},
      {"node/1",
       {"time", "12:DX", "12:VX", "4000000000:DX", "4000000000:VX"},
       {"s", "m", "m/s", "m", "m/s"},
       node_rows(9)},
  };
  for (const auto& e : expect) {
    INFO(e.path);
    const H5Id ds{H5Dopen2(file.id, e.path, H5P_DEFAULT), H5Dclose};
    REQUIRE(ds.id >= 0);
    const H5Id space{H5Dget_space(ds.id), H5Sclose};
    REQUIRE(H5Sget_simple_extent_ndims(space.id) == 2);
    hsize_t dims[2] = {0, 0}, max_dims[2] = {0, 0};
    H5Sget_simple_extent_dims(space.id, dims, max_dims);
    CHECK(dims[0] == 9);
    CHECK(dims[1] == e.columns.size());
    CHECK(max_dims[0] == H5S_UNLIMITED);  // extendible
    CHECK(max_dims[1] == e.columns.size());
    const H5Id dcpl{H5Dget_create_plist(ds.id), H5Pclose};
    CHECK(H5Pget_layout(dcpl.id) == H5D_CHUNKED);
    const H5Id type{H5Dget_type(ds.id), H5Tclose};
    CHECK(H5Tequal(type.id, H5T_IEEE_F64LE) > 0);

    std::vector<double> values(dims[0] * dims[1]);
    REQUIRE(H5Dread(ds.id, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) >= 0);
    CHECK(values == e.values);
    CHECK(c_string_array_attr(ds.id, "columns") == e.columns);
    CHECK(c_string_array_attr(ds.id, "units") == e.units);
  }
  const H5Id global{H5Dopen2(file.id, "global", H5P_DEFAULT), H5Dclose};
  CHECK(H5Aexists(global.id, "objects") == 0);  // a group without objects has no objects attribute
  CHECK(c_string_array_attr(global.id, "variables") == std::vector<std::string>{"IE", "KE"});
  CHECK(c_string_attr(global.id, "object_kind").empty());
  CHECK(c_string_attr(global.id, "title").empty());

  const H5Id node{H5Dopen2(file.id, "node/1", H5P_DEFAULT), H5Dclose};
  CHECK(c_string_array_attr(node.id, "variables") == std::vector<std::string>{"DX", "VX"});
  CHECK(c_string_array_attr(node.id, "variable_units") == std::vector<std::string>{"m", "m/s"});
  CHECK(c_string_attr(node.id, "object_kind") == "node");
  CHECK(c_string_attr(node.id, "title") == "falling nodes, two");
  const H5Id a{H5Aopen(node.id, "objects", H5P_DEFAULT), H5Aclose};
  REQUIRE(a.id >= 0);
  std::int64_t ids[2] = {0, 0};
  REQUIRE(H5Aread(a.id, H5T_NATIVE_INT64, ids) >= 0);
  CHECK(ids[0] == 12);
  CHECK(ids[1] == kBigId);
}

TEST_CASE("time history: a flush before any row writes empty datasets", "[th]") {
  TempDir dir;
  const std::string path = write_file(dir, 0);
  const auto groups = read_ok(path);
  REQUIRE(groups.size() == 2);
  CHECK(groups[1].rows.empty());
  CHECK(groups[1].columns == 5);
}

TEST_CASE("time history: a /TH group with no objects has no columns, a repeated object repeats its columns",
          "[th]") {
  TempDir dir;
  const std::string path = dir.file("P_th.h5");
  std::vector<ThGroupLayout> l = {{"global", "", "", {}, {"KE"}, {"J"}, {}},
                                  {"node/5", "listed none", "node", {}, {"DX"}, {"m"}, {}},
                                  {"part/3", "twice", "part", {3, 3}, {"IE"}, {"J"}, {}}};
  TimeHistoryWriter w(path, l, "ms");
  const std::vector<double> ke{1.5}, none{}, ie{2.5, 2.5};
  w.append(0.25, {ke, none, ie});
  w.flush();
  const auto groups = read_ok(path);
  REQUIRE(groups.size() == 3);
  CHECK(groups[1].layout.object_kind == "node");
  CHECK(groups[1].layout.objects.empty());
  CHECK(groups[1].columns == 1);
  CHECK(groups[1].rows == std::vector<double>{0.25});
  CHECK(groups[2].layout.objects == std::vector<std::int64_t>{3, 3});
  CHECK(groups[2].rows == std::vector<double>{0.25, 2.5, 2.5});
  // The empty group is listed, and takes no place in the CSV.
  std::ostringstream os;
  radx::io::list_time_history(path, groups, os);
  CHECK_THAT(os.str(), Catch::Contains("node/5") && Catch::Contains("none (no node listed: no columns)"));
  CHECK(parse_csv(export_csv(groups, {})).header ==
        std::vector<std::string>{"time [ms]", "global:KE [J]", "part/3:3:IE [J]", "part/3:3:IE [J]"});
}

namespace {

// Rows in the file, read independently of io/ (0 when there is no file yet).
std::size_t rows_in_file(const std::string& path) {
  if (!fs::exists(path)) return 0;
  const H5Id file{H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose};
  REQUIRE(file.id >= 0);
  const H5Id ds{H5Dopen2(file.id, "node/1", H5P_DEFAULT), H5Dclose};
  const H5Id space{H5Dget_space(ds.id), H5Sclose};
  hsize_t dims[2] = {0, 0};
  H5Sget_simple_extent_dims(space.id, dims, nullptr);
  return static_cast<std::size_t>(dims[0]);
}

ino_t inode_of(const std::string& path) {
  struct stat st {};
  REQUIRE(::stat(path.c_str(), &st) == 0);
  return st.st_ino;
}

}  // namespace

// Memory independent of the run length: append flushes by itself once it holds the bound, so no more
// rows than that are ever held, and every other row is already in the file.
TEST_CASE("time history: append never holds more rows than the bound, the others are in the file", "[th]") {
  TempDir dir;
  const std::string path = dir.file("P_th.h5");
  // 8 values per row (global 1 + 2, node/1 1 + 4): 40 values hold 5 rows, fewer than max_rows.
  TimeHistoryWriter w(path, layouts(), "s",
                      {.max_rows = 100, .max_values = 40, .max_seconds = 1e9, .min_seconds = 0});
  REQUIRE(w.max_buffered_rows() == 5);
  for (int r = 0; r < 23; ++r) {
    INFO("row " << r);
    append_row(w, r);
    CHECK(w.buffered_rows() < 5);
    CHECK(rows_in_file(path) == w.rows() - w.buffered_rows());
  }
  CHECK(w.buffered_rows() == 3);  // 23 = 4 * 5 + 3
  w.flush();
  const auto groups = read_ok(path);
  CHECK(groups[0].rows == global_rows(23));
  CHECK(groups[1].rows == node_rows(23));

  TimeHistoryWriter few(dir.file("Q_th.h5"), layouts(), "s", {.max_rows = 3, .max_values = 1000});
  CHECK(few.max_buffered_rows() == 3);
  // A row wider than max_values is still held alone, then written.
  TimeHistoryWriter wide(dir.file("R_th.h5"), layouts(), "s", {.max_values = 2});
  CHECK(wide.max_buffered_rows() == 1);
}

// The flush policy alone, with the wall times given: rows = rows held, row_values = values a row.
TEST_CASE("time history: flushes are due by rows held, memory cap and wall time", "[th]") {
  using radx::io::th_flush_due;
  const radx::io::ThFlushPolicy p{
      .max_rows = 10, .max_values = 100, .max_seconds = 1.0, .min_seconds = 0.2, .cap_values = 1000};
  // Narrow rows (8 values): 10 rows are enough, once 0.2 s have passed since the last flush.
  CHECK_FALSE(th_flush_due(p, 0, 8, 5.0, 5.0));  // nothing held
  CHECK_FALSE(th_flush_due(p, 9, 8, 0.5, 0.0));
  CHECK(th_flush_due(p, 10, 8, 0.2, 0.0));
  CHECK_FALSE(th_flush_due(p, 10, 8, 0.1, 0.0));
  // The narrow rows' cap is max_values: 12 rows (96 values) are the most it holds, flushed whatever the time.
  CHECK_FALSE(th_flush_due(p, 11, 8, 0.1, 0.0));
  CHECK(th_flush_due(p, 12, 8, 0.1, 0.0));
  // Wide rows (250 values, more than max_values): one row is enough, but held for 0.2 s unless the cap
  // cap_values (4 rows) is reached: at most five flushes a second.
  CHECK_FALSE(th_flush_due(p, 1, 250, 0.0, 0.0));
  CHECK_FALSE(th_flush_due(p, 3, 250, 0.19, 0.0));
  CHECK(th_flush_due(p, 4, 250, 0.0, 0.0));
  CHECK(th_flush_due(p, 2, 250, 0.2, 0.0));
  // A row wider than the cap is held alone and written.
  CHECK(th_flush_due(p, 1, 5000, 0.0, 0.0));
  // One second since the last flush, or a row after a pause of a second: written at once.
  CHECK(th_flush_due(p, 1, 8, 1.0, 0.0));
  CHECK(th_flush_due(p, 1, 8, 0.0, 1.0));
}

// A run killed inside a flush leaves rows past radx_rows (the flush not completed): they are not read.
TEST_CASE("time history: rows past the count of complete rows are left out", "[th]") {
  TempDir dir;
  const std::string path = dir.file("P_th.h5");
  {
    TimeHistoryWriter w(path, layouts(), "s");
    for (int r = 0; r < 6; ++r) append_row(w, r);
    w.flush();
  }
  {
    const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    REQUIRE(f >= 0);
    const hid_t attr = H5Aopen(f, "radx_rows", H5P_DEFAULT);
    REQUIRE(attr >= 0);
    const std::int64_t four = 4;
    CHECK(H5Awrite(attr, H5T_NATIVE_INT64, &four) >= 0);
    H5Aclose(attr);
    H5Fclose(f);
  }
  const auto groups = read_ok(path);
  CHECK(groups[0].rows == global_rows(4));
  CHECK(groups[1].rows == node_rows(4));
}

TEST_CASE("time history: with no wall time between flushes every row is written as it comes", "[th]") {
  TempDir dir;
  const std::string path = dir.file("P_th.h5");
  TimeHistoryWriter w(path, layouts(), "s", {.max_seconds = 0});
  for (int r = 0; r < 4; ++r) {
    append_row(w, r);
    CHECK(w.buffered_rows() == 0);
    CHECK(rows_in_file(path) == static_cast<std::size_t>(r + 1));
  }
}

// A flush costs the same whatever the rows before it: after the first, the file is extended in place,
// not written again and renamed.
TEST_CASE("time history: flushes after the first extend the same file", "[th]") {
  TempDir dir;
  const std::string path = dir.file("P_th.h5");
  TimeHistoryWriter w(path, layouts(), "s", {.max_seconds = 1e9});
  append_row(w, 0);
  w.flush();
  const ino_t first = inode_of(path);
  for (int r = 1; r < 7; ++r) {
    append_row(w, r);
    w.flush();
    CHECK(inode_of(path) == first);
    CHECK_FALSE(fs::exists(path + ".part"));
  }
  w.flush();  // nothing held: nothing written
  const auto groups = read_ok(path);
  CHECK(groups[0].rows == global_rows(7));
  CHECK(groups[1].rows == node_rows(7));
}

TEST_CASE("time history: a failed flush throws naming the file and keeps the previous file", "[th]") {
  TempDir dir;
  const std::string path = write_file(dir, 3);
  const auto before = slurp(path);
  // A folder in the way of the .part file makes the HDF5 create fail.
  fs::create_directories(dir.path() / "P_th.h5.part" / "blocker");
  TimeHistoryWriter w(path, layouts(), "s");
  append_row(w, 0);
  try {
    w.flush();
    FAIL("flush did not throw");
  } catch (const std::runtime_error& e) {
    CHECK_THAT(e.what(), Catch::Contains(path));
  }
  CHECK(slurp(path) == before);

  TimeHistoryWriter nowhere(dir.file("no/such/folder/P_th.h5"), layouts(), "s");
  CHECK_THROWS_AS(nowhere.flush(), std::runtime_error);
}

TEST_CASE("time history: wrong rows and layouts are refused", "[th]") {
  TempDir dir;
  TimeHistoryWriter w(dir.file("P_th.h5"), layouts(), "s");
  append_row(w, 1);
  const std::vector<double> two{1, 2}, four{1, 2, 3, 4}, three{1, 2, 3};
  CHECK_THROWS_AS(w.append(1.0, {two}), std::invalid_argument);                 // one group missing
  CHECK_THROWS_AS(w.append(1.0, {two, three}), std::invalid_argument);          // 3 values for 2 x 2
  CHECK_THROWS_AS(w.append(0.0, {two, four}), std::invalid_argument);           // time goes back
  CHECK_THROWS_AS(w.append(std::nan(""), {two, four}), std::invalid_argument);  // not a time
  CHECK(w.rows() == 1);                                                         // nothing stored
  w.append(time_of(1), {two, four});                                            // equal time: kept
  CHECK(w.rows() == 2);

  auto with = [](auto change) {
    auto l = layouts();
    change(l);
    return l;
  };
  const std::string p = dir.file("bad_th.h5");
  CHECK_THROWS_AS(TimeHistoryWriter(p, with([](auto& l) { l[1].path = "global"; }), "s"),
                  std::invalid_argument);
  CHECK_THROWS_AS(TimeHistoryWriter(p, with([](auto& l) { l[0].path = "node"; }), "s"),
                  std::invalid_argument);
  CHECK_THROWS_AS(TimeHistoryWriter(p, with([](auto& l) { l[1].path = "node:1"; }), "s"),
                  std::invalid_argument);
  CHECK_THROWS_AS(TimeHistoryWriter(p, with([](auto& l) { l[1].path = "/node/1"; }), "s"),
                  std::invalid_argument);
  CHECK_THROWS_AS(TimeHistoryWriter(p, with([](auto& l) { l[1].units.pop_back(); }), "s"),
                  std::invalid_argument);
  CHECK_THROWS_AS(TimeHistoryWriter(p, with([](auto& l) {
                                      l[1].variables = {"DX", "DX"};
                                    }),
                                    "s"),
                  std::invalid_argument);
  CHECK_THROWS_AS(
      TimeHistoryWriter(p, with([](auto& l) { l[0].variables.clear(), l[0].units.clear(); }), "s"),
      std::invalid_argument);
}

TEST_CASE("time history: reading a missing or foreign file fails with a clear error", "[th]") {
  TempDir dir;
  std::vector<ThGroupData> groups;
  std::string error;
  CHECK_FALSE(radx::io::read_time_history(dir.file("missing_th.h5"), groups, error));
  CHECK_THAT(error, Catch::Contains("missing_th.h5") && Catch::Contains("no such file"));

  const std::string plain = dir.file("plain.h5");
  H5Fclose(H5Fcreate(plain.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT));
  CHECK_FALSE(radx::io::read_time_history(plain, groups, error));
  CHECK_THAT(error, Catch::Contains("not a radx time-history file"));

  const std::string text = dir.write("text_th.h5", "not HDF5\n");
  CHECK_FALSE(radx::io::read_time_history(text, groups, error));
  CHECK_THAT(error, Catch::Contains("text_th.h5"));
}

TEST_CASE("time history: the listing names groups, objects, variables, units, rows and times", "[th]") {
  TempDir dir;
  const std::string path = write_file(dir, 4);
  std::ostringstream os;
  radx::io::list_time_history(path, read_ok(path), os);
  const std::string s = os.str();
  INFO(s);
  for (const char* want :
       {"2 groups, time in s", "\nglobal\n", "\nnode/1\n", "falling nodes, two", "2 nodes: 12 4000000000",
        "IE [J], KE [J]", "DX [m], VX [m/s]", "rows:      4, time 0 to "}) {
    CHECK_THAT(s, Catch::Contains(want));
  }
}

TEST_CASE("time history: a long object list is listed whole, wrapped to short lines", "[th]") {
  ThGroupData g;
  g.layout = {"node/2", "many", "node", {}, {"DX"}, {"m"}, {}};
  for (std::int64_t id = 1'000'001; id <= 1'000'040; ++id) g.layout.objects.push_back(id);
  g.columns = 1 + 40;
  std::ostringstream os;
  radx::io::list_time_history("x_th.h5", {g}, os);
  std::istringstream lines(os.str());
  std::string line, all;
  while (std::getline(lines, line)) {
    CHECK(line.size() <= 100);
    all += line + '\n';
  }
  CHECK_THAT(all, Catch::Contains("40 nodes: 1000001 1000002") && Catch::Contains(" 1000040\n") &&
                      Catch::Contains("rows:      0\n"));
}

TEST_CASE("time history: CSV export of every column reads back to the same doubles", "[th]") {
  TempDir dir;
  const std::string path = write_file(dir, 7);
  const auto groups = read_ok(path);
  const Csv csv = parse_csv(export_csv(groups, {}));
  CHECK(csv.header == std::vector<std::string>{"time [s]", "global:IE [J]", "global:KE [J]",
                                               "node/1:12:DX [m]", "node/1:12:VX [m/s]",
                                               "node/1:4000000000:DX [m]", "node/1:4000000000:VX [m/s]"});
  REQUIRE(csv.rows.size() == 7);
  const auto g = global_rows(7), n = node_rows(7);
  for (std::size_t r = 0; r < 7; ++r) {
    INFO("row " << r);
    const std::vector<double> want{g[3 * r],     g[3 * r + 1], g[3 * r + 2], n[5 * r + 1],
                                   n[5 * r + 2], n[5 * r + 3], n[5 * r + 4]};
    CHECK(csv.rows[r] == want);
  }
}

TEST_CASE("time history: selectors choose columns, groups, objects and wildcards in order", "[th]") {
  TempDir dir;
  const auto groups = read_ok(write_file(dir, 3));
  auto header = [&](const std::vector<std::string>& sel) {
    return parse_csv(export_csv(groups, sel)).header;
  };
  using H = std::vector<std::string>;
  CHECK(header({"global:KE"}) == H{"time [s]", "global:KE [J]"});
  CHECK(header({"node/1:4000000000:VX", "global:IE"}) ==
        H{"time [s]", "node/1:4000000000:VX [m/s]", "global:IE [J]"});
  CHECK(header({"node/1:12"}) == H{"time [s]", "node/1:12:DX [m]", "node/1:12:VX [m/s]"});
  CHECK(header({"*:VX"}) == H{"time [s]", "node/1:12:VX [m/s]", "node/1:4000000000:VX [m/s]"});
  CHECK(header({"global", "global:IE"}) == H{"time [s]", "global:IE [J]", "global:KE [J]"});  // no repeat
  CHECK(header({"node/*:4?????????:DX"}) == H{"time [s]", "node/1:4000000000:DX [m]"});
  CHECK(header({"node/1"}).size() == 5);

  // The values follow their header: node/1:12:DX is x(t) of object 0.
  const Csv csv = parse_csv(export_csv(groups, {"node/1:12:DX"}));
  REQUIRE(csv.rows.size() == 3);
  for (std::size_t r = 0; r < 3; ++r)
    CHECK(csv.rows[r] == std::vector<double>{time_of(int(r)), fall_x(time_of(int(r)), 0)});
}

TEST_CASE("time history: a selector that matches nothing is an error listing what exists", "[th]") {
  TempDir dir;
  const auto groups = read_ok(write_file(dir, 2));
  std::vector<radx::io::ThColumnRef> chosen;
  std::string error;
  for (const char* bad : {"global:XX", "node/2", "node/1:13:DX", "node", "DX"}) {
    INFO(bad);
    CHECK_FALSE(radx::io::select_th_columns(groups, {"global:IE", bad}, chosen, error));
    CHECK_THAT(error, Catch::Contains(std::string("'") + bad + "'") &&
                          Catch::Contains("node/1, objects 12 4000000000") &&
                          Catch::Contains("global, variables IE KE"));
  }
}

TEST_CASE("time history: CSV export refuses groups whose times differ", "[th]") {
  TempDir dir;
  auto groups = read_ok(write_file(dir, 3));
  std::vector<radx::io::ThColumnRef> chosen;
  std::string error;
  REQUIRE(radx::io::select_th_columns(groups, {}, chosen, error));
  std::ostringstream os;
  groups[1].rows[5] += 1e-9;  // time of row 2 of node/1
  CHECK_FALSE(radx::io::write_th_csv(groups, chosen, os, error));
  CHECK_THAT(error, Catch::Contains("global and node/1 do not hold the same times"));
  groups[1].rows.resize(10);  // 2 rows
  CHECK_FALSE(radx::io::write_th_csv(groups, chosen, os, error));
  CHECK_THAT(error, Catch::Contains("3 and 2 rows"));
}

TEST_CASE("radx th lists and exports a time history, bad input exits 1, bad usage 2", "[th][app]") {
  TempDir dir;
  const std::string path = write_file(dir, 5);
  const std::string radx = std::string(RADX_DRIVER_EXE) + " th ";

  CHECK(run(radx + path, dir) == 0);
  CHECK_THAT(slurp(dir.file("stdout.txt")), Catch::Contains("node/1") && Catch::Contains("DX [m], VX [m/s]"));

  const std::string out = dir.file("out.csv");
  CHECK(run(radx + path + " --csv -o " + out + " --var global:KE --var node/1:12", dir) == 0);
  CHECK_FALSE(fs::exists(out + ".part"));
  const Csv csv = parse_csv(slurp(out));
  CHECK(csv.header ==
        std::vector<std::string>{"time [s]", "global:KE [J]", "node/1:12:DX [m]", "node/1:12:VX [m/s]"});
  REQUIRE(csv.rows.size() == 5);
  CHECK(csv.rows[4] ==
        std::vector<double>{time_of(4), energy_ke(time_of(4)), fall_x(time_of(4), 0), fall_v(time_of(4), 0)});

  CHECK(run(radx + path + " --csv", dir) == 0);  // standard output
  CHECK(parse_csv(slurp(dir.file("stdout.txt"))).rows.size() == 5);

  CHECK(run(radx + path + " --csv --var global:XX", dir) == 1);
  CHECK_THAT(slurp(dir.file("stderr.txt")), Catch::Contains("'global:XX'") && Catch::Contains("node/1"));
  CHECK(run(radx + dir.file("missing_th.h5"), dir) == 1);
  CHECK_THAT(slurp(dir.file("stderr.txt")), Catch::Contains("missing_th.h5"));

  CHECK(run(radx, dir) == 2);                              // no file
  CHECK(run(radx + path + " --var global:IE", dir) == 2);  // --var without --csv
  CHECK(run(radx + path + " --csv --var", dir) == 2);      // --var without a value
  CHECK(run(radx + path + " --frobnicate", dir) == 2);     // unknown option
  CHECK(run(radx + path + " " + path, dir) == 2);          // two files
  CHECK(run(std::string(RADX_DRIVER_EXE) + " --help", dir) == 0);
  CHECK_THAT(slurp(dir.file("stdout.txt")), Catch::Contains("th FILE"));
}
