// Result files (io/hdf5/results_writer.hpp, docs/theory/results-format.md sections 1 to 5): the mesh file,
// three states read back with the HDF5 C API (external links, values, field data), both indexes parsed as
// text, time ordering, removal of an earlier run's files of the same
// prefix only, and no .part/.tmp left behind.
//
// Tolerances: values are compared EXACTLY (==): the writer stores the caller's float32 and float64 bits
// without conversion, and the index times are printed with 17 significant digits, which give back the
// same double.
#include <hdf5.h>
#include <sys/stat.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>
#include "test_util.hpp"

#include "io/hdf5/results_writer.hpp"
#include "solver/model/model.hpp"

namespace {

namespace fs = std::filesystem;
using radx::io::ResultArray;
using radx::io::ResultState;
using radx::io::ResultsWriter;
using radx::test::TempDir;

// 13 nodes; cells in model order: 2 quads, 1 quad with n3 == n4 (a triangle), 1 three-node shell, 1 brick.
radx::model::Model make_model() {
  radx::model::Model m;
  m.run_name = "RESULTS_TEST";
  for (int i = 0; i < 13; ++i) {
    m.nodes.id.push_back(1000 + 10 * i);
    m.nodes.x.push_back(0.5 * (i % 4));
    m.nodes.y.push_back(1.0 / 3.0 * (i / 4));
    m.nodes.z.push_back(i >= 8 ? 1.0 : 0.0);
  }
  for (int i = 0; i < 2; ++i) {
    radx::model::Part p;
    p.id = 21 + i;
    p.title = i == 0 ? "Door panel" : "B-pillar, inner";
    m.parts.push_back(p);
  }
  m.units.mass_name = "Mg";
  m.units.length_name = "mm";
  m.units.time_name = "s";
  m.shells.id = {1, 2, 3};
  m.shells.part = {0, 0, 1};
  m.shells.conn = {0, 1, 5, 4, 1, 2, 6, 5, 2, 3, 7, 7};
  m.shells3.type = radx::model::ElementType::Shell3;
  m.shells3.id = {4};
  m.shells3.part = {1};
  m.shells3.conn = {4, 5, 8};
  m.bricks.type = radx::model::ElementType::Brick8;
  m.bricks.id = {5'000'000'000LL};
  m.bricks.part = {1};
  m.bricks.conn = {0, 1, 5, 4, 8, 9, 10, 11};
  return m;
}

constexpr std::size_t kNodes = 13, kCells = 5;

const std::vector<ResultArray> kArrays{
    {"plastic_strain", 1, false, ""}, {"stress", 6, false, "MPa"}, {"acceleration", 3, true, "mm/s2"}};

// The string attribute `name` of the object at `path` (fixed-length, as the writer stores units).
std::string string_attr(hid_t file, const std::string& path, const std::string& name) {
  const hid_t a = H5Aopen_by_name(file, path.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
  if (a < 0) return "<no attribute " + name + " on " + path + ">";
  const hid_t type = H5Aget_type(a);
  std::string out = "<not a fixed-length string>";
  if (H5Tget_class(type) == H5T_STRING && H5Tis_variable_str(type) == 0) {
    std::string text(H5Tget_size(type), '\0');
    if (H5Aread(a, type, text.data()) >= 0) out = text.substr(0, text.find('\0'));
  }
  H5Tclose(type);
  H5Aclose(a);
  return out;
}

// The arrays of state s, with values that differ per state, per entry and per component.
struct StateData {
  std::vector<double> points;
  std::vector<float> displacement, velocity, plastic_strain, stress, acceleration;
  std::vector<std::uint8_t> status;
  double time = 0;

  StateData(const radx::model::Model& m, int s, double t) : time(t) {
    for (std::size_t i = 0; i < kNodes; ++i) {
      const std::array<double, 3> x0{m.nodes.x[i], m.nodes.y[i], m.nodes.z[i]};
      for (int c = 0; c < 3; ++c) {
        const float d =
            0.001f * static_cast<float>(s) * static_cast<float>(i + 1) + 0.1f * static_cast<float>(c);
        displacement.push_back(d);
        points.push_back(x0[static_cast<std::size_t>(c)] + static_cast<double>(d) + 1e-12 * s);
        velocity.push_back(-d / 3.0f);
        acceleration.push_back(d * 7.0f);
      }
    }
    for (std::size_t e = 0; e < kCells; ++e) {
      plastic_strain.push_back(0.01f * static_cast<float>(s * 10 + static_cast<int>(e)));
      for (int c = 0; c < 6; ++c)
        stress.push_back(static_cast<float>(100 * s + 10 * static_cast<int>(e) + c) / 3.0f);
      status.push_back(s == 2 && e == 1 ? 0 : 1);
    }
  }
  [[nodiscard]] ResultState state() const {
    return ResultState{time, points, displacement, velocity, status, {plastic_strain, stress, acceleration}};
  }
};

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

std::set<std::string> files_in(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

template <class T>
std::vector<T> read_all(hid_t file, const std::string& path, hid_t mem_type) {
  const hid_t ds = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
  REQUIRE(ds >= 0);
  const hid_t space = H5Dget_space(ds);
  std::vector<T> out(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
  REQUIRE(H5Dread(ds, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) >= 0);
  H5Sclose(space);
  H5Dclose(ds);
  return out;
}

std::vector<hsize_t> dims_of(hid_t file, const std::string& path) {
  const hid_t ds = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
  REQUIRE(ds >= 0);
  const hid_t space = H5Dget_space(ds);
  std::vector<hsize_t> dims(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space)));
  H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  H5Sclose(space);
  H5Dclose(ds);
  return dims;
}

// The file type class and size of a dataset, e.g. {H5T_FLOAT, 4}.
std::pair<H5T_class_t, std::size_t> type_of(hid_t file, const std::string& path) {
  const hid_t ds = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
  REQUIRE(ds >= 0);
  const hid_t t = H5Dget_type(ds);
  const std::pair<H5T_class_t, std::size_t> out{H5Tget_class(t), H5Tget_size(t)};
  H5Tclose(t);
  H5Dclose(ds);
  return out;
}

// /VTKHDF@Type: scalar fixed-length string of exactly 16 bytes, NULLPAD, "UnstructuredGrid", no NUL.
void check_vtkhdf_type(hid_t file) {
  const hid_t a = H5Aopen_by_name(file, "/VTKHDF", "Type", H5P_DEFAULT, H5P_DEFAULT);
  REQUIRE(a >= 0);
  const hid_t type = H5Aget_type(a);
  CHECK(H5Tget_class(type) == H5T_STRING);
  CHECK(H5Tis_variable_str(type) == 0);
  CHECK(H5Tget_size(type) == 16);
  CHECK(H5Tget_strpad(type) == H5T_STR_NULLPAD);
  const hid_t space = H5Aget_space(a);
  CHECK(H5Sget_simple_extent_type(space) == H5S_SCALAR);
  char text[16];
  REQUIRE(H5Aread(a, type, text) >= 0);
  CHECK(std::string(text, 16) == "UnstructuredGrid");
  H5Sclose(space);
  H5Tclose(type);
  H5Aclose(a);
  std::int64_t version[2] = {-1, -1};
  const hid_t v = H5Aopen_by_name(file, "/VTKHDF", "Version", H5P_DEFAULT, H5P_DEFAULT);
  REQUIRE(v >= 0);
  REQUIRE(H5Aread(v, H5T_NATIVE_INT64, version) >= 0);
  H5Aclose(v);
  CHECK(version[0] == 1);
  CHECK(version[1] == 0);
}

// `path` of `file` is an external link to the same path in `target_file`.
void check_external_link(hid_t file, const std::string& path, const std::string& target_file) {
  H5L_info_t info;
  REQUIRE(H5Lget_info(file, path.c_str(), &info, H5P_DEFAULT) >= 0);
  REQUIRE(info.type == H5L_TYPE_EXTERNAL);
  std::vector<char> value(info.u.val_size);
  REQUIRE(H5Lget_val(file, path.c_str(), value.data(), value.size(), H5P_DEFAULT) >= 0);
  const char* link_file = nullptr;
  const char* link_object = nullptr;
  unsigned flags = 0;
  REQUIRE(H5Lunpack_elink_val(value.data(), value.size(), &flags, &link_file, &link_object) >= 0);
  CHECK(std::string(link_file) == target_file);
  CHECK(std::string(link_object) == path);
}

// Parses the series index: the (name, time) pairs, in file order.
std::vector<std::pair<std::string, double>> parse_series(const std::string& text) {
  const std::regex entry(R"re(\{\s*"name"\s*:\s*"([^"]+)"\s*,\s*"time"\s*:\s*([-+0-9.eE]+)\s*\})re");
  std::vector<std::pair<std::string, double>> out;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), entry); it != std::sregex_iterator(); ++it) {
    out.emplace_back((*it)[1].str(), std::strtod((*it)[2].str().c_str(), nullptr));
  }
  return out;
}

std::vector<std::string> all_matches(const std::string& text, const std::string& pattern) {
  const std::regex re(pattern);
  std::vector<std::string> out;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), re); it != std::sregex_iterator(); ++it) {
    out.push_back((*it)[1].str());
  }
  return out;
}

}  // namespace

TEST_CASE("results: mesh file, three states, external links, values and indexes", "[io][results]") {
  TempDir dir;
  const radx::model::Model model = make_model();
  // 1/3000 has no exact decimal form: the indexes must still give back the same double.
  const std::vector<double> times{0.0, 1.0 / 3000.0, 0.002};
  std::vector<StateData> data;
  for (int s = 0; s < 3; ++s) data.emplace_back(model, s, times[static_cast<std::size_t>(s)]);
  {
    ResultsWriter writer(model, dir.path().string(), "P", kArrays);
    CHECK(writer.mesh_path() == dir.file("P.mesh.hdf"));
    CHECK(writer.series_path() == dir.file("P.hdf.series"));
    CHECK(writer.xmf_path() == dir.file("P.xmf"));
    for (const StateData& d : data) REQUIRE(writer.write_state(d.state()));
    CHECK(writer.states_written() == 3);
    CHECK(writer.seconds_writing() > 0);
  }
  CHECK(files_in(dir.path()) == std::set<std::string>{"P.mesh.hdf", "P_000000.hdf", "P_000001.hdf",
                                                      "P_000002.hdf", "P.hdf.series", "P.xmf"});

  SECTION("mesh file") {
    const hid_t mesh = H5Fopen(dir.file("P.mesh.hdf").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    REQUIRE(mesh >= 0);
    check_vtkhdf_type(mesh);
    CHECK(read_all<std::int64_t>(mesh, "/VTKHDF/NumberOfCells", H5T_NATIVE_INT64) ==
          std::vector<std::int64_t>{static_cast<std::int64_t>(kCells)});
    CHECK(read_all<std::uint8_t>(mesh, "/VTKHDF/Types", H5T_NATIVE_UINT8) ==
          std::vector<std::uint8_t>{9, 9, 5, 5, 12});
    CHECK(read_all<std::int64_t>(mesh, "/VTKHDF/Offsets", H5T_NATIVE_INT64) ==
          std::vector<std::int64_t>{0, 4, 8, 11, 14, 22});
    CHECK(read_all<std::int64_t>(mesh, "/VTKHDF/CellData/part_id", H5T_NATIVE_INT64) ==
          std::vector<std::int64_t>{21, 21, 22, 22, 22});
    const auto points = read_all<double>(mesh, "/VTKHDF/Points", H5T_NATIVE_DOUBLE);
    REQUIRE(points.size() == 3 * kNodes);
    for (std::size_t i = 0; i < kNodes; ++i) CHECK(points[3 * i + 1] == model.nodes.y[i]);
    CHECK(read_all<std::int64_t>(mesh, "/XDMF/MixedTopology", H5T_NATIVE_INT64).size() == 22 + kCells);
    H5Fclose(mesh);
  }

  SECTION("state files") {
    // The links name the mesh file without a folder: HDF5 finds it next to the state file, wherever the
    // process runs (this test's working folder is not the result folder).
    REQUIRE(fs::current_path() != dir.path());
    const hid_t mesh = H5Fopen(dir.file("P.mesh.hdf").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    REQUIRE(mesh >= 0);
    for (int s = 0; s < 3; ++s) {
      const StateData& d = data[static_cast<std::size_t>(s)];
      const std::string name = "P_00000" + std::to_string(s) + ".hdf";
      INFO(name);
      const hid_t file = H5Fopen(dir.file(name).c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
      REQUIRE(file >= 0);
      check_vtkhdf_type(file);
      for (const char* path :
           {"/VTKHDF/NumberOfPoints", "/VTKHDF/NumberOfCells", "/VTKHDF/NumberOfConnectivityIds",
            "/VTKHDF/Connectivity", "/VTKHDF/Offsets", "/VTKHDF/Types", "/VTKHDF/PointData/node_id",
            "/VTKHDF/CellData/part_id", "/VTKHDF/CellData/element_id"}) {
        INFO(path);
        check_external_link(file, path, "P.mesh.hdf");
        CHECK(read_all<std::int64_t>(file, path, H5T_NATIVE_INT64) ==
              read_all<std::int64_t>(mesh, path, H5T_NATIVE_INT64));
      }
      CHECK(dims_of(file, "/VTKHDF/Points") == std::vector<hsize_t>{kNodes, 3});
      CHECK(type_of(file, "/VTKHDF/Points") == std::pair<H5T_class_t, std::size_t>{H5T_FLOAT, 8});
      CHECK(read_all<double>(file, "/VTKHDF/Points", H5T_NATIVE_DOUBLE) == d.points);
      CHECK(dims_of(file, "/VTKHDF/PointData/displacement") == std::vector<hsize_t>{kNodes, 3});
      CHECK(type_of(file, "/VTKHDF/PointData/displacement") ==
            std::pair<H5T_class_t, std::size_t>{H5T_FLOAT, 4});
      CHECK(read_all<float>(file, "/VTKHDF/PointData/displacement", H5T_NATIVE_FLOAT) == d.displacement);
      CHECK(read_all<float>(file, "/VTKHDF/PointData/velocity", H5T_NATIVE_FLOAT) == d.velocity);
      CHECK(read_all<float>(file, "/VTKHDF/PointData/acceleration", H5T_NATIVE_FLOAT) == d.acceleration);
      CHECK(dims_of(file, "/VTKHDF/CellData/plastic_strain") == std::vector<hsize_t>{kCells});
      CHECK(read_all<float>(file, "/VTKHDF/CellData/plastic_strain", H5T_NATIVE_FLOAT) == d.plastic_strain);
      CHECK(dims_of(file, "/VTKHDF/CellData/stress") == std::vector<hsize_t>{kCells, 6});
      CHECK(read_all<float>(file, "/VTKHDF/CellData/stress", H5T_NATIVE_FLOAT) == d.stress);
      CHECK(type_of(file, "/VTKHDF/CellData/element_status") ==
            std::pair<H5T_class_t, std::size_t>{H5T_INTEGER, 1});
      CHECK(read_all<std::uint8_t>(file, "/VTKHDF/CellData/element_status", H5T_NATIVE_UINT8) == d.status);
      CHECK(read_all<double>(file, "/VTKHDF/FieldData/TimeValue", H5T_NATIVE_DOUBLE) ==
            std::vector<double>{d.time});
      CHECK(read_all<std::int64_t>(file, "/VTKHDF/FieldData/StateIndex", H5T_NATIVE_INT64) ==
            std::vector<std::int64_t>{s});
      // Deleted elements are VTK hidden cells (vtkDataSetAttributes::HIDDENCELL = 32), the others 0.
      std::vector<std::uint8_t> ghost;
      for (const std::uint8_t st : d.status) ghost.push_back(st == 0 ? 32 : 0);
      CHECK(read_all<std::uint8_t>(file, "/VTKHDF/CellData/vtkGhostType", H5T_NATIVE_UINT8) == ghost);
      // Units: the attribute of every dataset, from the model's work units (Mg mm s) or the array's own, and
      // the same list as text in the field data.
      const std::vector<std::pair<std::string, std::string>> units{{"Points", "mm"},
                                                                   {"PointData/displacement", "mm"},
                                                                   {"PointData/velocity", "mm/s"},
                                                                   {"PointData/node_id", "1"},
                                                                   {"PointData/acceleration", "mm/s2"},
                                                                   {"CellData/element_status", "1"},
                                                                   {"CellData/vtkGhostType", "1"},
                                                                   {"CellData/part_id", "1"},
                                                                   {"CellData/element_id", "1"},
                                                                   {"CellData/plastic_strain", "1"},
                                                                   {"CellData/stress", "MPa"},
                                                                   {"FieldData/TimeValue", "s"}};
      for (const auto& [path, unit] : units) {
        INFO(path);
        CHECK(string_attr(file, "/VTKHDF/" + path, "units") == unit);
      }
      const auto text = read_all<std::uint8_t>(file, "/VTKHDF/FieldData/units", H5T_NATIVE_UINT8);
      const std::string listed(text.begin(), text.end());
      for (const auto& [path, unit] : units) {
        const std::string line = path.substr(path.find('/') + 1) + "\t" + unit + "\n";
        INFO(line);
        CHECK(listed.find(line) != std::string::npos);
      }
      // The parts, linked from the mesh file: ids, and titles one per line in the same order.
      CHECK(read_all<std::int64_t>(file, "/VTKHDF/FieldData/part_ids", H5T_NATIVE_INT64) ==
            std::vector<std::int64_t>{21, 22});
      const auto titles = read_all<std::uint8_t>(file, "/VTKHDF/FieldData/part_titles", H5T_NATIVE_UINT8);
      CHECK(std::string(titles.begin(), titles.end()) == "Door panel\nB-pillar, inner\n");
      H5Fclose(file);
    }
    H5Fclose(mesh);
  }

  SECTION("series index") {
    const std::string text = slurp(dir.file("P.hdf.series"));
    CHECK(text.find("\"file-series-version\": \"1.0\"") != std::string::npos);
    const auto entries = parse_series(text);
    REQUIRE(entries.size() == 3);
    for (std::size_t s = 0; s < 3; ++s) {
      CHECK(entries[s].first == "P_00000" + std::to_string(s) + ".hdf");
      CHECK(entries[s].second == times[s]);  // 17 digits give back the same double
      if (s > 0) CHECK(entries[s].second > entries[s - 1].second);
    }
    CHECK(text.find("0.00033333333333333332") != std::string::npos);  // 1/3000 with 17 digits
  }

  SECTION("xmf index") {
    const std::string text = slurp(dir.file("P.xmf"));
    CHECK(text.find("<Xdmf Version=\"3.0\"") != std::string::npos);
    CHECK(text.find("CollectionType=\"Temporal\"") != std::string::npos);
    CHECK(text.find("HyperSlab") == std::string::npos);
    const auto grids = all_matches(text, R"re(<Grid Name="([^"]+)" GridType="Uniform")re");
    CHECK(grids == std::vector<std::string>{"P_000000", "P_000001", "P_000002"});
    const auto time_text = all_matches(text, R"re(<Time Value="([^"]+)")re");
    REQUIRE(time_text.size() == 3);
    for (std::size_t s = 0; s < 3; ++s) CHECK(std::strtod(time_text[s].c_str(), nullptr) == times[s]);
    CHECK(all_matches(text, R"re(TopologyType="(Mixed)")re").size() == 3);
    CHECK(all_matches(text, R"re(>(P\.mesh\.hdf:/XDMF/MixedTopology)<)re").size() == 3);
    CHECK(all_matches(text, R"re(>(P_00000[0-2]\.hdf:/VTKHDF/Points)<)re") ==
          std::vector<std::string>{"P_000000.hdf:/VTKHDF/Points", "P_000001.hdf:/VTKHDF/Points",
                                   "P_000002.hdf:/VTKHDF/Points"});
    const auto names = all_matches(text, R"re(<Attribute Name="([^"]+)")re");
    REQUIRE(names.size() == 3 * 10);
    const std::set<std::string> per_state(names.begin(), names.begin() + 10);
    CHECK(per_state == std::set<std::string>{"displacement", "velocity", "acceleration", "node_id",
                                             "element_status", "vtkGhostType", "part_id", "element_id",
                                             "plastic_strain", "stress"});
    // Time-invariant arrays come from the mesh file, the others from their state file.
    CHECK(
        all_matches(
            text, R"re(>(P\.mesh\.hdf:/VTKHDF/(PointData/node_id|CellData/part_id|CellData/element_id))<)re")
            .size() == 9);
    CHECK(all_matches(text, R"re(>(P_000002\.hdf:/VTKHDF/CellData/stress)<)re").size() == 1);
    // 6 components as "Matrix": ParaView's XDMF 2 reader turns a Tensor6 into 9 reordered components.
    CHECK(
        all_matches(
            text,
            R"re(<Attribute Name="stress" AttributeType="(Matrix)" Center="Cell">\s*<DataItem Dimensions="5 6")re")
            .size() == 3);
  }
}

TEST_CASE("results: a state whose time does not increase is not written", "[io][results]") {
  TempDir dir;
  const radx::model::Model model = make_model();
  ResultsWriter writer(model, dir.path().string(), "P", kArrays);
  const StateData first(model, 0, 1.0);
  REQUIRE(writer.write_state(first.state()));
  for (const double t :
       {1.0, 0.5, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    INFO(t);
    const StateData d(model, 1, t);
    CHECK_FALSE(writer.write_state(d.state()));
  }
  CHECK(writer.states_written() == 1);
  CHECK_FALSE(fs::exists(dir.file("P_000001.hdf")));
  CHECK(parse_series(slurp(writer.series_path())).size() == 1);
  const StateData later(model, 1, 1.5);
  CHECK(writer.write_state(later.state()));
  CHECK(writer.states_written() == 2);
  CHECK(fs::exists(dir.file("P_000001.hdf")));
}

// Long runs: a state must cost the same whatever the states before it, so the indexes are extended in
// place (same file, earlier bytes kept) and not rewritten; each must still be complete after every state.
TEST_CASE("results: each state extends both indexes in place and leaves them complete", "[io][results]") {
  TempDir dir;
  const radx::model::Model model = make_model();
  ResultsWriter writer(model, dir.path().string(), "P", kArrays);
  const std::string xmf_tail = "    </Grid>\n  </Domain>\n</Xdmf>\n";
  const std::string series_tail = "\n  ]\n}\n";
  const auto inode = [](const std::string& path) {
    struct stat st {};
    REQUIRE(::stat(path.c_str(), &st) == 0);
    return st.st_ino;
  };
  std::string xmf_before, series_before;
  ino_t xmf_inode = 0, series_inode = 0;
  for (int s = 0; s < 4; ++s) {
    INFO("state " << s);
    const StateData d(model, s, 0.5 * s);
    REQUIRE(writer.write_state(d.state()));
    const std::string xmf = slurp(writer.xmf_path());
    const std::string series = slurp(writer.series_path());
    CHECK(xmf.ends_with(xmf_tail));
    CHECK(all_matches(xmf, R"re(<Grid Name="([^"]+)" GridType="Uniform")re").size() ==
          static_cast<std::size_t>(s + 1));
    CHECK(xmf.find("</Xdmf>") == xmf.size() - std::string("</Xdmf>\n").size());  // closed once, at the end
    CHECK(series.ends_with(series_tail));
    CHECK(parse_series(series).size() == static_cast<std::size_t>(s + 1));
    if (s > 0) {
      CHECK(inode(writer.xmf_path()) == xmf_inode);  // the same file, not a new one renamed over it
      CHECK(inode(writer.series_path()) == series_inode);
      CHECK(xmf.starts_with(xmf_before.substr(0, xmf_before.size() - xmf_tail.size())));
      CHECK(series.starts_with(series_before.substr(0, series_before.size() - series_tail.size())));
    }
    xmf_inode = inode(writer.xmf_path());
    series_inode = inode(writer.series_path());
    xmf_before = xmf;
    series_before = series;
  }
}

TEST_CASE("results: the constructor removes an earlier run's files of its prefix only", "[io][results]") {
  TempDir dir;
  const std::vector<std::string> stale{
      "P_000007.hdf", "P_000001.hdf.part", "P.hdf.series",    "P.hdf.series.tmp", "P.xmf",
      "P.xmf.tmp",    "P.mesh.hdf",        "P.mesh.hdf.part", "P_1234567.hdf"};
  const std::vector<std::string> kept{"OTHER_000001.hdf", "OTHER.hdf.series", "P_000001.hdf.bak",
                                      "P_00001.hdf",      "P_x_000001.hdf",   "P_000001.h5",
                                      "notes.txt",        "P_th.h5"};
  for (const auto& name : stale) dir.write(name, "earlier run");
  for (const auto& name : kept) dir.write(name, "keep me");
  const radx::model::Model model = make_model();
  ResultsWriter writer(model, dir.path().string(), "P", {});
  std::set<std::string> expected(kept.begin(), kept.end());
  expected.insert("P.mesh.hdf");
  CHECK(files_in(dir.path()) == expected);
  CHECK(slurp(dir.file("OTHER_000001.hdf")) == "keep me");
  CHECK(slurp(dir.file("P.mesh.hdf")) != "earlier run");

  const StateData d(model, 0, 0.0);
  ResultState state = d.state();
  state.arrays.clear();
  REQUIRE(writer.write_state(state));
  expected.insert({"P_000000.hdf", "P.hdf.series", "P.xmf"});
  CHECK(files_in(dir.path()) == expected);
}

TEST_CASE("results: invalid arrays and states are refused", "[io][results]") {
  TempDir dir;
  const radx::model::Model model = make_model();
  const std::string folder = dir.path().string();
  CHECK_THROWS_AS(ResultsWriter(model, folder, "P", {{"a/b", 1, true, ""}}), std::runtime_error);
  CHECK_THROWS_AS(ResultsWriter(model, folder, "P", {{"a.b", 1, true, ""}}), std::runtime_error);
  CHECK_THROWS_AS(ResultsWriter(model, folder, "P", {{"velocity", 3, true, ""}}), std::runtime_error);
  CHECK_THROWS_AS(ResultsWriter(model, folder, "P", {{"x", 1, true, ""}, {"x", 3, false, ""}}),
                  std::runtime_error);
  CHECK_THROWS_AS(ResultsWriter(model, folder, "P", {{"x", 0, true, ""}}), std::runtime_error);
  CHECK_THROWS_AS(ResultsWriter(model, folder, "a/P", {}), std::runtime_error);
  radx::model::Model broken = model;
  broken.bricks.conn[3] = 13;  // node index out of range
  CHECK_THROWS_AS(ResultsWriter(broken, folder, "P", {}), std::runtime_error);

  ResultsWriter writer(model, folder, "P", kArrays);
  const StateData d(model, 0, 0.0);
  ResultState short_points = d.state();
  short_points.points = short_points.points.first(3 * kNodes - 1);
  CHECK_THROWS_AS(writer.write_state(short_points), std::runtime_error);
  ResultState missing_array = d.state();
  missing_array.arrays.pop_back();
  CHECK_THROWS_AS(writer.write_state(missing_array), std::runtime_error);
  ResultState short_stress = d.state();
  short_stress.arrays[1] = short_stress.arrays[1].first(6 * kCells - 1);
  CHECK_THROWS_AS(writer.write_state(short_stress), std::runtime_error);
  CHECK(writer.states_written() == 0);
  CHECK(writer.write_state(d.state()));
}

// A result set left in $RADX_RESULTS_SAMPLE_DIR for the ParaView check (tests/scripts/
// check_results_paraview.py); hidden: run it explicitly with "[results_sample]". 3 states at 0, 1e-3 and
// 2.5e-3 s, arrays displacement, velocity, acceleration, plastic_strain, stress, cell types 9, 5 and 12.
TEST_CASE("results: sample result set for the ParaView check", "[.][results_sample]") {
  const char* folder = std::getenv("RADX_RESULTS_SAMPLE_DIR");
  REQUIRE(folder != nullptr);
  const radx::model::Model model = make_model();
  ResultsWriter writer(model, folder, "SAMPLE", kArrays);
  int s = 0;
  for (const double t : {0.0, 1e-3, 2.5e-3}) {
    const StateData d(model, s++, t);
    REQUIRE(writer.write_state(d.state()));
  }
}
