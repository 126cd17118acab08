// Inputs that are not decks at all, and values at the edges of what fits: a directory, a FIFO or a device
// given as a deck or an #include, a real default beyond the integer range, a part id beyond 32 bits, an
// unreadable number that is also required. Each is a located diagnostic and an exit code, never a crash.
#include <sys/stat.h>
#include <sys/wait.h>

#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "parser/building/build_run_controls.hpp"
#include "parser/reading/deck.hpp"
#include "solver/model/run_files.hpp"
#include "test_util.hpp"

namespace fs = std::filesystem;
using radx::Diag;
using radx::test::TempDir;

namespace {

const std::string kJcDeck =
    std::string(RADX_SOURCE_DIR) + "/decks/verification/jc_single_brick/JC_SINGLE_BRICK_0000.rad";

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string all(const radx::Diagnostics& d) {
  std::string s;
  for (const auto& i : d.items()) s += radx::Diagnostics::format(i) + "\n";
  return s;
}

struct Run {
  int code = -1;  // exit code; -1 when the program died on a signal
  std::string err;
};

Run run(const std::string& cmd, const TempDir& dir) {
  const std::string err_file = dir.file("stderr.txt");
  const int rc = std::system((cmd + " >/dev/null 2>" + err_file).c_str());
  return Run{WIFEXITED(rc) ? WEXITSTATUS(rc) : -1, slurp(err_file)};
}

}  // namespace

TEST_CASE("a directory as the deck or as an #include is a located error, not a crash", "[lexer][robust]") {
  TempDir dir;
  fs::create_directories(dir.path() / "sub");
  {
    radx::Diagnostics diags;
    const auto deck = radx::read_starter_deck(dir.path().string(), diags);
    INFO(all(diags));
    REQUIRE(diags.error_count() == 1);
    CHECK(diags.items()[0].code == Diag::FileNotFound);
    CHECK(diags.items()[0].message.find("is a directory") != std::string::npos);
    CHECK(deck.records.empty());
  }
  for (const char* target : {"/", ".", "sub"}) {
    const std::string deck_path =
        dir.write("inc_0000.rad", radx::test::begin_block(2026) + "#include " + target + "\n/END\n");
    radx::Diagnostics diags;
    radx::read_starter_deck(deck_path, diags);
    INFO(target << "\n" << all(diags));
    REQUIRE(diags.error_count() == 1);
    const auto& e = diags.items()[0];
    CHECK(e.code == Diag::IncludeNotFound);
    CHECK(e.file == deck_path);
    CHECK(e.line == 6);  // the #include line, after the five /BEGIN lines
    CHECK(e.keyword == "#include");
    CHECK(e.message.find("is a directory") != std::string::npos);
  }
  {
    radx::Diagnostics diags;
    radx::read_run_controls(dir.path().string(), diags);
    INFO(all(diags));
    CHECK(diags.contains(Diag::FileNotFound));
  }
}

TEST_CASE("a FIFO or a device as the deck or as an #include is refused without reading it",
          "[lexer][robust]") {
  TempDir dir;
  const std::string fifo = dir.file("pipe_0000.rad");
  REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
  // Opening the FIFO would block this test for ever (no writer), /dev/zero would fill memory.
  for (const std::string& path : {fifo, std::string("/dev/zero")}) {
    radx::Diagnostics diags;
    radx::read_starter_deck(path, diags);
    INFO(all(diags));
    REQUIRE(diags.error_count() == 1);
    CHECK(diags.items()[0].code == Diag::FileNotFound);
    CHECK(diags.items()[0].message.find("regular text files") != std::string::npos);
    CHECK_FALSE(radx::model::is_one_file_deck(path));
  }
  const std::string deck_path = dir.write(
      "inc_0000.rad", radx::test::begin_block(2026) + "#include pipe_0000.rad\n#include /dev/zero\n/END\n");
  radx::Diagnostics diags;
  radx::read_starter_deck(deck_path, diags);
  INFO(all(diags));
  REQUIRE(diags.error_count() == 2);
  CHECK(diags.items()[0].line == 6);
  CHECK(diags.items()[0].message.find("FIFO") != std::string::npos);
  CHECK(diags.items()[1].line == 7);
  CHECK(diags.items()[1].message.find("device") != std::string::npos);
}

TEST_CASE("the starter, the engine, radx check and radx run exit 1 with a message on a directory",
          "[app][robust]") {
  TempDir dir;
  const std::string folder = dir.path().string();
  const std::string out = " --out " + dir.file("out");
  for (const std::string& cmd :
       {std::string(RADX_STARTER_EXE) + " " + folder + out, std::string(RADX_ENGINE_EXE) + " " + folder + out,
        std::string(RADX_DRIVER_EXE) + " check " + folder,
        std::string(RADX_DRIVER_EXE) + " run " + folder + out,
        std::string(RADX_DRIVER_EXE) + " run " + folder + "/" + out}) {
    const Run r = run(cmd, dir);
    INFO(cmd << "\n" << r.err);
    CHECK(r.code == 1);
    CHECK(r.err.find("RX101") != std::string::npos);
    CHECK(r.err.find("is a directory") != std::string::npos);
  }
  // A folder given as the model file: the advice is to name the file, not to run the starter again.
  {
    const std::string engine_deck = dir.write(
        "JC_SINGLE_BRICK_0001.rad",
        slurp(std::string(RADX_SOURCE_DIR) + "/decks/verification/jc_single_brick/JC_SINGLE_BRICK_0001.rad"));
    const Run r = run(std::string(RADX_ENGINE_EXE) + " " + engine_deck + " --model " + folder + out, dir);
    INFO(r.err);
    CHECK(r.code == 1);
    CHECK(r.err.find(folder + " is a directory: give the starter's model file itself") != std::string::npos);
    CHECK(r.err.find("run the starter first") == std::string::npos);
  }
  // An #include of "/" in a deck the starter runs.
  const std::string deck = dir.write("INC_0000.rad", radx::test::begin_block(2026) + "#include /\n/END\n");
  const Run r = run(std::string(RADX_STARTER_EXE) + " " + deck + out, dir);
  INFO(r.err);
  CHECK(r.code == 1);
  CHECK(r.err.find(deck + ":6:1: error: RX103: [#include] cannot read the included file '/': it is a "
                          "directory") != std::string::npos);
}

TEST_CASE("a blank real field whose default lies beyond int64 keeps the default and no integer view",
          "[lexer][robust]") {
  // Pmin of /MAT/PLAS_JOHNS is 0 in this deck, so it takes its default -1e20; converting that to int64 was
  // undefined behaviour (x86 gave INT64_MIN).
  radx::Diagnostics diags;
  const auto deck = radx::read_starter_deck(kJcDeck, diags);
  INFO(all(diags));
  REQUIRE_FALSE(diags.has_errors());
  const auto mats = deck.of("/MAT/LAW2");
  REQUIRE(mats.size() == 1);
  const auto* pmin = mats[0]->find("Pmin");
  REQUIRE(pmin != nullptr);
  CHECK(pmin->defaulted);
  CHECK(pmin->r == -1e20);  // the default itself, exactly
  CHECK(pmin->i == 0);
  const auto* eps = mats[0]->find("EPS_p_max");
  REQUIRE(eps != nullptr);
  CHECK(eps->r == 1e20);
  CHECK(eps->i == 0);
}

TEST_CASE("an unreadable required number is reported once, not again as blank", "[lexer][robust]") {
  TempDir dir;
  std::string text = slurp(kJcDeck);
  // RHO_I of the material (required): its line is the first one after the "#              RHO_I" comment.
  const std::string rho = "            7.85e-09\n";
  const auto at = text.find(rho);
  REQUIRE(at != std::string::npos);
  text.replace(at, rho.size(), "                 nan\n");
  const std::string path = dir.write("JC_0000.rad", text);
  radx::Diagnostics diags;
  const auto deck = radx::read_starter_deck(path, diags);
  radx::build_model(deck, diags);
  INFO(all(diags));
  REQUIRE(diags.contains(Diag::BadReal));
  CHECK(diags.error_count() == 1);
  CHECK_FALSE(diags.contains(Diag::RequiredValueMissing));
}

TEST_CASE("the engine after a failed starter says the starter failed and where its listing is",
          "[app][robust]") {
  TempDir dir;
  const std::string src = std::string(RADX_SOURCE_DIR) + "/decks/verification/jc_single_brick/";
  std::string text = slurp(kJcDeck);
  const std::string rho = "            7.85e-09\n";
  REQUIRE(text.find(rho) != std::string::npos);
  text.replace(text.find(rho), rho.size(), "                 nan\n");
  const std::string starter = dir.write("JC_SINGLE_BRICK_0000.rad", text);
  const std::string engine = dir.write("JC_SINGLE_BRICK_0001.rad", slurp(src + "JC_SINGLE_BRICK_0001.rad"));
  const std::string out = " --out " + dir.file("out");
  // Before any starter run the advice is to run it.
  Run r = run(std::string(RADX_ENGINE_EXE) + " " + engine + out, dir);
  INFO(r.err);
  CHECK(r.code == 1);
  CHECK(r.err.find("run the starter first") != std::string::npos);
  REQUIRE(run(std::string(RADX_STARTER_EXE) + " " + starter + out, dir).code == 1);
  REQUIRE(fs::exists(dir.path() / "out" / "JC_SINGLE_BRICK_0000.out"));
  r = run(std::string(RADX_ENGINE_EXE) + " " + engine + out, dir);
  INFO(r.err);
  CHECK(r.code == 1);
  CHECK(r.err.find("run the starter first") == std::string::npos);
  CHECK(r.err.find("the starter ran but found errors in the deck, so it wrote no model file") !=
        std::string::npos);
  CHECK(r.err.find((dir.path() / "out" / "JC_SINGLE_BRICK_0000.out").string()) != std::string::npos);
}

TEST_CASE("an engine value that is not a number is reported once, not again as out of range",
          "[engine][robust]") {
  TempDir dir;
  const std::string src = std::string(RADX_SOURCE_DIR) + "/decks/verification/jc_single_brick/";
  std::string text = slurp(src + "JC_SINGLE_BRICK_0001.rad");
  // Tstop on the line after /RUN: an unreadable Tstop reads as 0, which is also below the accepted range.
  const std::string tstop = "                 0.1\n";
  REQUIRE(text.find(tstop) != std::string::npos);
  text.replace(text.find(tstop), tstop.size(), "                 abc\n");
  const std::string engine = dir.write("JC_SINGLE_BRICK_0001.rad", text);
  radx::Diagnostics diags;
  radx::read_run_controls(engine, diags);
  INFO(all(diags));
  REQUIRE(diags.contains(Diag::BadReal));
  CHECK(diags.error_count() == 1);
  CHECK_FALSE(diags.contains(Diag::ValueOutOfRange));
}
