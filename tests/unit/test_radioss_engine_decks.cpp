// Engine decks written for Radioss read as Radioss reads them: without /END the deck is read to the end of
// the file (a note says so). Each case runs radx-engine on the model of decks/block_on_plate.
//
// Tolerances: none. Two runs of the same model with engine decks that ask for the same physics must give
// the same energies bit for bit (NAME_summary.json writes doubles with 17 significant digits, so the
// energy block is compared as text).
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "test_util.hpp"

namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The engine deck radx reads everywhere below: the run, its listing and animation controls. No /END.
const char* kEngineBody =
    "#RADIOSS ENGINE\n"
    "/RUN/BLOCK_ON_PLATE/1\n"
    "2e-4\n"
    "/ANIM/DT\n"
    "0 5e-6\n"
    "/ANIM/ELEM/VONM\n"
    "/PRINT/-20\n"
    "/DT\n"
    "0.9 0\n";

struct EngineRun {
  int exit_code = -1;
  std::string out, err, listing, summary;
};

// The model file of the sample deck decks/block_on_plate (a brick block dropped on a clamped shell plate
// through two TYPE7 interfaces), made once per test case by radx-starter in `dir`.
std::string block_on_plate_model(const radx::test::TempDir& dir) {
  const std::string cmd = std::string(RADX_STARTER_EXE) + " " + RADX_SOURCE_DIR +
                          "/decks/block_on_plate/BLOCK_ON_PLATE_0000.rad --out " + dir.file("model") + " > " +
                          dir.file("starter.log") + " 2>&1";
  REQUIRE(std::system(cmd.c_str()) == 0);
  return dir.file("model/BLOCK_ON_PLATE_0000.hdf");
}

// radx-engine on `engine_text` written as BLOCK_ON_PLATE_0001.rad in its own folder `name` of `dir`.
EngineRun run_engine(const radx::test::TempDir& dir, const std::string& model, const std::string& name,
                     const std::string& engine_text) {
  const fs::path folder = dir.path() / name;
  const std::string deck = dir.write(name + "/BLOCK_ON_PLATE_0001.rad", engine_text);
  const std::string cmd = std::string(RADX_ENGINE_EXE) + " " + deck + " --model " + model + " --out " +
                          folder.string() + " --threads 1 --no-plot > " + (folder / "stdout.txt").string() +
                          " 2> " + (folder / "stderr.txt").string();
  EngineRun r;
  const int status = std::system(cmd.c_str());
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(folder / "stdout.txt");
  r.err = slurp(folder / "stderr.txt");
  r.listing = slurp(folder / "BLOCK_ON_PLATE_0001.out");
  r.summary = slurp(folder / "BLOCK_ON_PLATE_summary.json");
  return r;
}

// The "energy": {...} object of NAME_summary.json, as written.
std::string energy_block(const std::string& summary) {
  const auto start = summary.find("\"energy\"");
  if (start == std::string::npos) return {};
  return summary.substr(start, summary.find('}', start) - start + 1);
}

}  // namespace

TEST_CASE("an engine deck without /END is read to the end of the file and runs as with /END",
          "[engine-deck]") {
  radx::test::TempDir dir;
  const std::string model = block_on_plate_model(dir);
  const EngineRun no_end = run_engine(dir, model, "no_end", kEngineBody);
  const EngineRun with_end = run_engine(dir, model, "with_end", std::string(kEngineBody) + "/END\n");
  INFO(no_end.err + no_end.out);
  REQUIRE(no_end.exit_code == 0);
  REQUIRE(with_end.exit_code == 0);
  // The note, at the last line of the file, in the listing file and on standard output; none with /END.
  const std::string note =
      "BLOCK_ON_PLATE_0001.rad:9:1: note: RX804: [/END] the engine deck has no /END line";
  CHECK(no_end.listing.find(note) != std::string::npos);
  CHECK(no_end.out.find(note) != std::string::npos);
  CHECK(with_end.listing.find("RX804") == std::string::npos);
  // The same run: energies bit for bit.
  REQUIRE_FALSE(energy_block(no_end.summary).empty());
  CHECK(energy_block(no_end.summary) == energy_block(with_end.summary));
  CHECK(no_end.summary.find("\"cycles\"") != std::string::npos);
}
