// The checks of a model read from a model file (io/hdf5/model_file_checks.hpp) and its fingerprint
// (io/hdf5/model_file.hpp, io/hdf5/model_file_hash.hpp).
//
// The checks must refuse every entry the engine cannot use and nothing the starter writes: each case below
// damages one entry of the block-on-plate sample's model, in memory, and expects exactly the problem that
// names it (its dataset, its entry and its record's user id); every sample deck's model, written by the
// starter and read back, must pass. The content hash must change with any byte of content and with nothing
// else (not with the file's layout in HDF5, not with the hash attribute itself).
#include <hdf5.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "apps/starter_pipeline.hpp"
#include "io/hdf5/model_file.hpp"
#include "io/hdf5/model_file_checks.hpp"
#include "io/hdf5/model_file_hash.hpp"
#include "solver/model/run_files.hpp"
#include "test_util.hpp"

namespace fs = std::filesystem;
using radx::io::ModelFileCode;
using radx::io::ModelFileProblems;
using radx::model::Model;

namespace {

// The sample deck's model as the starter writes it, read back through the model file.
const Model& sample_model() {
  static const Model model = [] {
    radx::test::TempDir dir;
    radx::app::StarterOptions opt;
    opt.deck = std::string(RADX_SOURCE_DIR) + "/decks/block_on_plate/BLOCK_ON_PLATE_0000.rad";
    opt.out_dir = dir.path().string();
    std::ostringstream out, err;
    const auto res = radx::app::run_starter(opt, out, err);
    REQUIRE(res.exit_code == 0);
    Model m;
    const auto r = radx::io::read_model_file(res.model_path, m);
    REQUIRE(r.ok());
    return m;
  }();
  return model;
}

std::string listed(const ModelFileProblems& p) {
  std::string s;
  for (const auto& i : p.items)
    s += "RX" + std::to_string(static_cast<int>(i.code)) + " " + i.where + ": " + i.message + "\n";
  return s;
}

// The one problem `m` has: its code, where it is, and words of its message.
void expect_one(const Model& m, ModelFileCode code, const std::string& where,
                const std::vector<std::string>& words) {
  const ModelFileProblems p = radx::io::check_model_content(m);
  INFO(listed(p));
  REQUIRE(p.count == 1);
  CHECK(p.items[0].code == code);
  CHECK(p.items[0].where == where);
  for (const auto& w : words) CHECK(p.items[0].message.find(w) != std::string::npos);
}

}  // namespace

TEST_CASE("model-file checks: the sample model passes", "[io][model_file_checks]") {
  const ModelFileProblems p = radx::io::check_model_content(sample_model());
  INFO(listed(p));
  CHECK(p.empty());
}

TEST_CASE("model-file checks: the probe's damaged indices are named by dataset and entry",
          "[io][model_file_checks]") {
  const Model& ok = sample_model();
  REQUIRE(ok.node_groups.size() >= 2);
  REQUIRE(!ok.interfaces.empty());
  REQUIRE(!ok.time_histories.empty());

  SECTION("a node-group member") {
    Model m = ok;
    m.node_groups[1].nodes.back() = 10'000'000;
    const std::size_t flat = ok.node_groups[0].nodes.size() + ok.node_groups[1].nodes.size() - 1;
    expect_one(m, ModelFileCode::BadReference, "/radx/node_groups/nodes[" + std::to_string(flat) + "]",
               {"node group " + std::to_string(ok.node_groups[1].id), "node index 10000000", "out of range",
                "expected 0 to " + std::to_string(ok.nodes.size() - 1)});
  }
  SECTION("a surface segment's node") {
    Model m = ok;
    m.surfaces[0].segments[1][2] = 10'000'000;
    expect_one(m, ModelFileCode::BadReference, "/radx/surfaces/segments[1, 2]",
               {"surface " + std::to_string(ok.surfaces[0].id), "10000000"});
  }
  SECTION("an interface's secondary node") {
    Model m = ok;
    m.interfaces[0].secondary_nodes.back() = 10'000'000;
    const std::size_t k = ok.interfaces[0].secondary_nodes.size() - 1;
    expect_one(m, ModelFileCode::BadReference,
               "/radx/interfaces/0/secondary_nodes[" + std::to_string(k) + "]",
               {"interface " + std::to_string(ok.interfaces[0].id), "10000000"});
  }
  SECTION("a time-history object") {
    Model m = ok;
    m.time_histories[0].objects[1] = 10'000'000;
    expect_one(m, ModelFileCode::BadReference, "/radx/time_histories/objects[1]",
               {"/TH " + std::to_string(ok.time_histories[0].id), "object index 10000000"});
  }
  SECTION("a part's material and property") {
    Model m = ok;
    m.parts[0].material = 99;
    expect_one(m, ModelFileCode::BadReference, "/radx/parts/material[0]",
               {"part " + std::to_string(ok.parts[0].id), "material index 99",
                "(" + std::to_string(ok.materials.size()) + " materials)"});
    m = ok;
    m.parts[0].property = 99;
    const ModelFileProblems p = radx::io::check_model_content(m);
    INFO(listed(p));
    // The part's own entry; its elements, whose property kind cannot be told, are not reported again.
    REQUIRE(p.count == 1);
    CHECK(p.items[0].where == "/radx/parts/property[0]");
  }
  SECTION("a /BCS and an /INIVEL node group") {
    Model m = ok;
    m.bcs[0].group = 99;
    expect_one(m, ModelFileCode::BadReference, "/radx/bcs/group[0]",
               {"/BCS " + std::to_string(ok.bcs[0].id), "node group index 99"});
    m = ok;
    m.initial_velocities[0].group = -1;  // -1 is "none", which an /INIVEL cannot be
    expect_one(m, ModelFileCode::BadReference, "/radx/initial_velocities/group[0]", {"node group index -1"});
  }
}

TEST_CASE("model-file checks: masses and values the physics cannot take", "[io][model_file_checks]") {
  const Model& ok = sample_model();

  SECTION("every nodal mass 0") {
    Model m = ok;
    std::fill(m.node_mass.begin(), m.node_mass.end(), 0.0);
    expect_one(m, ModelFileCode::BadValue, "/radx/node_mass", {"every node has mass 0"});
  }
  SECTION("one negative, one infinite nodal mass") {
    Model m = ok;
    m.node_mass[5] = -1.0;
    m.node_mass[6] = std::numeric_limits<double>::infinity();
    const ModelFileProblems p = radx::io::check_model_content(m);
    INFO(listed(p));
    REQUIRE(p.count == 2);
    CHECK(p.items[0].where == "/radx/node_mass[5]");
    CHECK(p.items[0].message.find("node " + std::to_string(ok.nodes.id[5])) != std::string::npos);
    CHECK(p.items[1].where == "/radx/node_mass[6]");
  }
  SECTION("a coordinate that is not a number") {
    Model m = ok;
    m.nodes.z[7] = std::nan("");
    expect_one(m, ModelFileCode::BadValue, "/radx/nodes/xyz[7, 2]", {"not a finite number"});
  }
  SECTION("a material constant and a shell thickness") {
    Model m = ok;
    m.materials[1].young = std::numeric_limits<double>::infinity();
    expect_one(m, ModelFileCode::BadValue, "/radx/materials/young[1]",
               {"material " + std::to_string(ok.materials[1].id), "inf"});
    m = ok;
    REQUIRE(!ok.shells.thickness.empty());
    m.shells.thickness[2] = -0.5;
    expect_one(m, ModelFileCode::BadValue, "/radx/elements/shell4/thickness[2]",
               {"shell " + std::to_string(ok.shells.id[2]), "thickness -0.5"});
  }
  SECTION("Poisson's ratio 0.5") {
    Model m = ok;
    m.materials[0].poisson = 0.5;
    expect_one(m, ModelFileCode::BadValue, "/radx/materials/poisson[0]", {"expected -1 < nu < 0.5"});
  }
}

TEST_CASE("model-file checks: counts, ids and codes", "[io][model_file_checks]") {
  const Model& ok = sample_model();

  SECTION("a repeated node id names both entries") {
    Model m = ok;
    m.nodes.id[9] = m.nodes.id[4];
    expect_one(m, ModelFileCode::BadReference, "/radx/nodes/id[9]",
               {"node id " + std::to_string(ok.nodes.id[4]), "repeats the id of entry 4"});
  }
  SECTION("an element id 0") {
    Model m = ok;
    m.bricks.id[0] = 0;
    expect_one(m, ModelFileCode::BadReference, "/radx/elements/brick8/id[0]", {"expected > 0"});
  }
  SECTION("a connectivity shorter than its ids") {
    Model m = ok;
    m.shells.conn.resize(m.shells.conn.size() - 4);
    expect_one(m, ModelFileCode::BadReference, "/radx/elements/shell4/conn", {"4 per shell"});
  }
  SECTION("an unknown material law") {
    Model m = ok;
    m.materials[0].law = static_cast<radx::model::MaterialLaw>(99);
    expect_one(m, ModelFileCode::BadReference, "/radx/materials/law[0]", {"law 99 is not a valid code"});
  }
  SECTION("a skew user id the model lacks") {
    Model m = ok;
    m.bcs[0].skew = 424242;
    expect_one(m, ModelFileCode::BadReference, "/radx/bcs/skew[0]", {"skew 424242 names no skew"});
  }
  SECTION("a moving skew missing one of its three nodes, a fixed skew naming one") {
    // The fuzzer's finding: a /SKEW/MOV whose second node reads -1 made the engine index node -1 each cycle.
    Model m = ok;
    radx::model::Skew moving;
    moving.id = 71;
    moving.n1 = 0;
    moving.n2 = radx::model::kNone;
    moving.n3 = 2;
    m.skews.push_back(moving);
    expect_one(m, ModelFileCode::BadReference, "/radx/skews/n2[" + std::to_string(m.skews.size() - 1) + "]",
               {"skew 71", "node index -1 is out of range"});
    m.skews.back().n1 = radx::model::kNone;
    m.skews.back().n2 = 1;
    m.skews.back().n3 = radx::model::kNone;
    expect_one(m, ModelFileCode::BadReference, "/radx/skews/n2[" + std::to_string(m.skews.size() - 1) + "]",
               {"skew 71", "given to a fixed skew"});
  }
  SECTION("function abscissas that do not increase") {
    Model m = ok;
    REQUIRE(!m.functions.empty());
    REQUIRE(m.functions[0].x.size() >= 2);
    m.functions[0].x[1] = m.functions[0].x[0];
    expect_one(m, ModelFileCode::BadValue, "/radx/functions/x[1]", {"strictly increasing"});
  }
  SECTION("a part without a material under elements that need one") {
    Model m = ok;
    const auto part = static_cast<std::size_t>(ok.bricks.part[0]);
    m.parts[part].material = radx::model::kNone;
    const ModelFileProblems p = radx::io::check_model_content(m);
    INFO(listed(p));
    std::size_t bricks = 0;
    for (const auto q : ok.bricks.part) bricks += static_cast<std::size_t>(q) == part ? 1 : 0;
    REQUIRE(p.count == bricks);  // each brick of the part names it
    CHECK(p.items[0].where == "/radx/elements/brick8/part[0]");
    CHECK(p.items[0].message.find("has no material; a brick needs one") != std::string::npos);
  }
  SECTION("an element whose part has a property of another kind") {
    Model m = ok;
    const std::int32_t brick_part = ok.bricks.part[0];
    const std::int32_t shell_part = ok.shells.part[0];
    REQUIRE(brick_part != shell_part);
    m.shells.part[3] = brick_part;
    expect_one(m, ModelFileCode::BadReference, "/radx/elements/shell4/part[3]",
               {"shell " + std::to_string(ok.shells.id[3]), "needs a property of kind 1"});
  }
}

TEST_CASE("model-file checks: a damaged file lists the first problems and counts them all",
          "[io][model_file_checks]") {
  Model m = sample_model();
  for (auto& n : m.shells.conn) n = -7;
  const ModelFileProblems p = radx::io::check_model_content(m);
  CHECK(p.count == m.shells.conn.size());
  CHECK(p.items.size() == ModelFileProblems::kKept);
  CHECK(p.items[0].where == "/radx/elements/shell4/conn[0, 0]");
}

TEST_CASE("every sample deck's model file is read back without a problem", "[io][model_file_checks][decks]") {
  radx::test::TempDir dir;
  int decks = 0;
  for (const auto& e : fs::recursive_directory_iterator(fs::path(RADX_SOURCE_DIR) / "decks")) {
    const std::string p = e.path().string();
    if (e.path().extension() != ".rad" || p.find("/invalid/") != std::string::npos) continue;
    const std::string stem = e.path().stem().string();
    if (stem.size() < 5 || stem.substr(stem.size() - 5) != "_0000") continue;
    radx::app::StarterOptions opt;
    opt.deck = p;
    opt.out_dir = (dir.path() / std::to_string(decks)).string();
    std::ostringstream out, err;
    const auto res = radx::app::run_starter(opt, out, err);
    if (res.exit_code != 0)
      continue;  // decks the starter refuses on purpose (none expected outside invalid/)
    ++decks;
    Model m;
    const auto r = radx::io::read_model_file(res.model_path, m);
    INFO(p << "\n" << r.error << listed(r.problems));
    CHECK(r.ok());
    CHECK(r.fingerprint.content_hash == r.fingerprint.computed_hash);
    CHECK(r.fingerprint.deck_files.front() == p);
    CHECK(r.fingerprint.run == radx::model::run_output_root(p));
  }
  CHECK(decks > 50);
}

TEST_CASE("model-file fingerprint: the content hash follows the content only", "[io][model_file_checks]") {
  radx::test::TempDir dir;
  const Model& m = sample_model();
  const auto origin = radx::io::model_file_origin(
      "BLOCK_ON_PLATE", {std::string(RADX_SOURCE_DIR) + "/decks/block_on_plate/BLOCK_ON_PLATE_0000.rad"},
      "abc1234");
  std::string error;
  REQUIRE(radx::io::write_model_file(m, dir.file("A_0000.hdf"), origin, error));
  REQUIRE(radx::io::write_model_file(m, dir.file("B_0000.hdf"), origin, error));
  Model back;
  const auto a = radx::io::read_model_file(dir.file("A_0000.hdf"), back);
  const auto b = radx::io::read_model_file(dir.file("B_0000.hdf"), back);
  REQUIRE(a.ok());
  // The same model twice: the same hash (it does not depend on where HDF5 put things in the file).
  CHECK(a.fingerprint.content_hash == b.fingerprint.content_hash);
  CHECK(a.fingerprint.radx_commit == "abc1234");
  CHECK(a.fingerprint.run == "BLOCK_ON_PLATE");
  CHECK(a.fingerprint.deck_hash.size() == 16);
  CHECK(a.fingerprint.run_name == m.run_name);

  // One mass changed in its last bit: another hash, and the reader says the file changed.
  Model c = m;
  c.node_mass[0] = std::nextafter(c.node_mass[0], 1e300);
  REQUIRE(radx::io::write_model_file(c, dir.file("C_0000.hdf"), origin, error));
  const auto cr = radx::io::read_model_file(dir.file("C_0000.hdf"), back);
  CHECK(cr.fingerprint.content_hash != a.fingerprint.content_hash);
  const hid_t f = H5Fopen(dir.file("C_0000.hdf").c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  REQUIRE(f >= 0);
  const hid_t ds = H5Dopen2(f, "/radx/node_mass", H5P_DEFAULT);
  const hsize_t one = 1, at = 0;
  const hid_t file_space = H5Dget_space(ds);
  H5Sselect_hyperslab(file_space, H5S_SELECT_SET, &at, nullptr, &one, nullptr);
  const hid_t mem_space = H5Screate_simple(1, &one, nullptr);
  REQUIRE(H5Dwrite(ds, H5T_NATIVE_DOUBLE, mem_space, file_space, H5P_DEFAULT, &m.node_mass[0]) >= 0);
  H5Sclose(mem_space);
  H5Sclose(file_space);
  H5Dclose(ds);
  H5Fclose(f);
  // C's content is now A's byte for byte, under C's stored hash: the reader finds the change.
  const auto changed = radx::io::read_model_file(dir.file("C_0000.hdf"), back);
  CHECK(changed.fingerprint.computed_hash == a.fingerprint.content_hash);
  REQUIRE(changed.problems.count == 1);
  CHECK(changed.problems.items[0].code == ModelFileCode::Changed);
  CHECK(changed.problems.items[0].message.find("changed after the starter wrote it") != std::string::npos);
}

TEST_CASE("model-file fingerprint: hash_bytes sees every byte and its place", "[io][model_file_checks]") {
  std::vector<unsigned char> bytes(1000);
  for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<unsigned char>(i * 37 + 11);
  const std::uint64_t h = radx::io::hash_bytes(bytes.data(), bytes.size(), 0);
  CHECK(radx::io::hash_bytes(bytes.data(), bytes.size(), 0) == h);
  CHECK(radx::io::hash_bytes(bytes.data(), bytes.size(), 1) != h);  // the seed chains the pieces
  // Every single-bit change of every length class (stripes, words, tail bytes) changes the hash.
  for (const std::size_t n : {std::size_t{3}, std::size_t{8}, std::size_t{31}, std::size_t{32},
                              std::size_t{77}, std::size_t{1000}}) {
    const std::uint64_t base = radx::io::hash_bytes(bytes.data(), n, 0);
    for (std::size_t i = 0; i < n; ++i) {
      for (int bit = 0; bit < 8; ++bit) {
        bytes[i] ^= static_cast<unsigned char>(1u << bit);
        const bool differs = radx::io::hash_bytes(bytes.data(), n, 0) != base;
        bytes[i] ^= static_cast<unsigned char>(1u << bit);
        if (!differs) FAIL("length " << n << ", byte " << i << ", bit " << bit << ": same hash");
      }
    }
  }
  // Two words swapped: another hash (the lanes are not a plain sum).
  std::swap(bytes[0], bytes[8]);
  CHECK(radx::io::hash_bytes(bytes.data(), bytes.size(), 0) != h);
}
