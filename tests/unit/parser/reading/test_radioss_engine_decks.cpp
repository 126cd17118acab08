// Engine decks written for Radioss read as Radioss reads them: without /END the deck is read to the end of
// the file (a note says so); every keyword of the Radioss engine deck is known: those that change no result
// are accepted with one note each, outputs radx does not write with one warning each, and those that change
// the results and that radx cannot run are refused, one error each naming what radx would need. The runs use
// radx-engine on the model of decks/block_on_plate.
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

#include "parser/building/build_run_controls.hpp"
#include "parser/keywords/keyword_schema.hpp"
#include "test_util.hpp"

namespace fs = std::filesystem;
using radx::Diag;
using radx::Severity;
using radx::schema::Support;

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

namespace {

// One engine deck line per declared keyword of class `support`, each followed by a data line that is not
// even numbers (radx passes over the data lines of keywords it does not read). Catch-all paths get a
// sub-field so the written keyword is one a real deck would hold. Returns the text; `lines` receives, for
// each keyword, its 1-based line in a deck that starts with `first_line - 1` other lines.
std::string every_keyword_of(Support support, int first_line,
                             std::vector<std::pair<std::string, int>>& lines) {
  std::string text;
  int line = first_line;
  for (const auto& k : radx::schema::engine_keywords()) {
    if (k.support != support) continue;
    const std::string written = std::string(k.path) + (k.prefix_match ? "/SUB/1" : "");
    text += written + "\n1.5 2.5 some words\n";
    lines.emplace_back(written, line);
    line += 2;
  }
  return text;
}

const radx::Diagnostic* at_line(const radx::Diagnostics& d, int line) {
  for (const auto& x : d.items())
    if (x.line == line) return &x;
  return nullptr;
}

std::size_t count_at_line(const radx::Diagnostics& d, int line) {
  std::size_t n = 0;
  for (const auto& x : d.items()) n += x.line == line ? 1 : 0;
  return n;
}

}  // namespace

TEST_CASE(
    "keywords that change no result are accepted with one note each, outputs radx does not write with "
    "one warning each, and the run is unchanged",
    "[engine-deck]") {
  // The declared keywords of both classes, then output requests of real decks for fields radx does not
  // write (read by /ANIM/ELEM and /ANIM/VECT, which warn on the name).
  std::vector<std::pair<std::string, int>> notes, warnings;
  const std::string head = std::string(kEngineBody) + "/PROC/4\n";  // 10 lines, /PROC on line 10
  notes.emplace_back("/PROC/4", 10);
  std::string text = head + every_keyword_of(Support::Ignored, 11, notes);
  const int after_notes = 11 + 2 * static_cast<int>(notes.size() - 1);
  text += every_keyword_of(Support::NotWritten, after_notes, warnings);
  int line = after_notes + 2 * static_cast<int>(warnings.size());
  for (const char* w :
       {"/ANIM/ELEM/SIGX", "/ANIM/VECT/FOPT", "/ANIM/BRICK/TENS/STRESS/000", "/OUTP/ELEM/VONM"}) {
    text += std::string(w) + "\n";
    warnings.emplace_back(w, line++);
  }
  text += "/END\n";
  REQUIRE(notes.size() >= 15);
  REQUIRE(warnings.size() >= 15);

  radx::test::TempDir dir;
  SECTION("the reader: one diagnostic per keyword, at its line, saying why") {
    radx::Diagnostics diags;
    const auto rc = radx::read_run_controls(dir.write("BLOCK_ON_PLATE_0001.rad", text), diags);
    std::string all;
    for (const auto& d : diags.items()) all += radx::Diagnostics::format(d) + "\n";
    INFO(all);
    CHECK_FALSE(diags.has_errors());
    CHECK(diags.items().size() == notes.size() + warnings.size());
    for (const auto& [written, l] : notes) {
      INFO(written << " at line " << l);
      CHECK(count_at_line(diags, l) == 1);
      const auto* d = at_line(diags, l);
      REQUIRE(d);
      CHECK(d->severity == Severity::Note);
      CHECK(d->code == Diag::IgnoredControlCard);
      CHECK(d->message.find(written + ": ") == 0);  // names the keyword as written, then what it is
      CHECK(d->message.find(". Accepted and ignored: ") != std::string::npos);
    }
    for (const auto& [written, l] : warnings) {
      INFO(written << " at line " << l);
      CHECK(count_at_line(diags, l) == 1);
      const auto* d = at_line(diags, l);
      REQUIRE(d);
      CHECK(d->severity == Severity::Warning);
      CHECK(d->code == Diag::OutputNotWritten);
      CHECK(d->message.find("docs/results.md") != std::string::npos);
    }
    CHECK(rc.anim_elem == std::vector<std::string>{"VONM"});
  }
  SECTION("the run: notes and warnings in the listing, energies bit for bit those of the plain deck") {
    const std::string model = block_on_plate_model(dir);
    const EngineRun plain = run_engine(dir, model, "plain", std::string(kEngineBody) + "/END\n");
    const EngineRun all = run_engine(dir, model, "all", text);
    INFO(all.err);
    REQUIRE(plain.exit_code == 0);
    REQUIRE(all.exit_code == 0);
    for (const auto& [written, l] : notes)
      CHECK(all.listing.find("BLOCK_ON_PLATE_0001.rad:" + std::to_string(l) + ":1: note: RX303") !=
            std::string::npos);
    for (const auto& [written, l] : warnings)
      CHECK(all.listing.find("BLOCK_ON_PLATE_0001.rad:" + std::to_string(l) + ":1: warning: RX311") !=
            std::string::npos);
    REQUIRE_FALSE(energy_block(plain.summary).empty());
    CHECK(energy_block(all.summary) == energy_block(plain.summary));
  }
}

TEST_CASE(
    "a keyword that changes the results and that radx cannot run is refused: one error each, named, "
    "located, saying what radx would need, nothing is run",
    "[engine-deck]") {
  radx::test::TempDir dir;
  SECTION("every refused keyword, at the reader") {
    std::vector<std::pair<std::string, int>> refused;
    const std::string text =
        std::string(kEngineBody) + every_keyword_of(Support::Unsupported, 10, refused) + "/END\n";
    REQUIRE(refused.size() >= 30);
    radx::Diagnostics diags;
    radx::read_run_controls(dir.write("BLOCK_ON_PLATE_0001.rad", text), diags);
    CHECK(diags.error_count() == refused.size());
    for (const auto& [written, l] : refused) {
      INFO(written << " at line " << l);
      CHECK(count_at_line(diags, l) == 1);
      const auto* d = at_line(diags, l);
      REQUIRE(d);
      CHECK(d->severity == Severity::Error);
      CHECK(d->code == Diag::UnsupportedKeyword);
      CHECK(d->message.find(written + ": ") == 0);
      CHECK(d->message.find(". It changes the results and radx cannot run it: radx would need") !=
            std::string::npos);
    }
  }
  SECTION("keywords of real decks through radx-engine: exit 1, errors on stderr, no file written") {
    const std::string model = block_on_plate_model(dir);
    const std::string text = std::string(kEngineBody) +
                             "/DEL/SHELL/1\n"  // line 10
                             "12 13\n"
                             "/VEL/TRA/Z\n"  // line 12
                             "2 0 1 0 0 0\n"
                             "/DAMP\n"  // line 14
                             "0.001 0.001\n"
                             "/KEREL\n"  // line 16
                             "/END\n";
    const EngineRun r = run_engine(dir, model, "refused", text);
    INFO(r.err);
    CHECK(r.exit_code == 1);
    const std::string file = "BLOCK_ON_PLATE_0001.rad:";
    CHECK(r.err.find(file +
                     "10:1: error: RX302: [/DEL] /DEL/SHELL/1: elements, parts or interfaces deleted at "
                     "the start of the run. It changes the results and radx cannot run it: radx would "
                     "need element and interface deletion") != std::string::npos);
    CHECK(r.err.find(file + "12:1: error: RX302: [/VEL] /VEL/TRA/Z") != std::string::npos);
    CHECK(r.err.find(file + "14:1: error: RX302: [/DAMP] /DAMP") != std::string::npos);
    CHECK(r.err.find("Rayleigh (mass and stiffness) damping") != std::string::npos);
    CHECK(r.err.find(file + "16:1: error: RX302: [/KEREL] /KEREL") != std::string::npos);
    CHECK(r.err.find("4 error(s)") != std::string::npos);
    // Nothing half-written: the engine deck is the only file of its folder.
    std::vector<std::string> files;
    for (const auto& e : fs::directory_iterator(dir.path() / "refused"))
      if (e.path().filename() != "stdout.txt" && e.path().filename() != "stderr.txt")
        files.push_back(e.path().filename().string());
    CHECK(files == std::vector<std::string>{"BLOCK_ON_PLATE_0001.rad"});
  }
}

TEST_CASE(
    "an engine keyword Radioss does not know is unknown, a known one in a form radx does not read is "
    "not supported",
    "[engine-deck]") {
  radx::test::TempDir dir;
  const std::string text = "/RUN/A/1\n1\n/FOOBAR/1\n/INIVEL/TRA/1\n/RBODY/FOO\n3\n/END\n";
  radx::Diagnostics diags;
  radx::read_run_controls(dir.write("A_0001.rad", text), diags);
  std::string all;
  for (const auto& d : diags.items()) all += radx::Diagnostics::format(d) + "\n";
  INFO(all);
  REQUIRE(diags.error_count() == 3);
  const auto* foobar = at_line(diags, 3);
  const auto* inivel = at_line(diags, 4);  // the engine's keyword is /INIV: INIVE is not a Radioss keyword
  const auto* rbody = at_line(diags, 5);
  REQUIRE((foobar && inivel && rbody));
  CHECK(foobar->code == Diag::UnknownKeyword);
  CHECK(inivel->code == Diag::UnknownKeyword);
  CHECK(rbody->code == Diag::UnsupportedKeyword);
  CHECK(rbody->message.find("radx reads /RBODY/ON, /RBODY/OFF") != std::string::npos);
}

TEST_CASE("/RBODY/OFF of a rigid body the model lacks is a warning and the run goes on unchanged",
          "[engine-deck]") {
  radx::test::TempDir dir;
  const std::string text = std::string(kEngineBody) +
                           "/RBODY/OFF\n"  // line 10
                           "7\n"           // line 11: the model (decks/block_on_plate) has no rigid body
                           "/END\n";
  const std::string warning =
      "BLOCK_ON_PLATE_0001.rad:11:1: warning: RX402: [/RBODY/OFF] /RBODY/OFF names rigid "
      "body 7, which the model does not have: it switches nothing";
  SECTION("radx-engine") {
    const std::string model = block_on_plate_model(dir);
    const EngineRun plain = run_engine(dir, model, "plain", std::string(kEngineBody) + "/END\n");
    const EngineRun off = run_engine(dir, model, "off", text);
    INFO(off.err);
    REQUIRE(plain.exit_code == 0);
    REQUIRE(off.exit_code == 0);
    CHECK(off.err.find(warning) != std::string::npos);
    CHECK(off.listing.find(warning) != std::string::npos);
    REQUIRE_FALSE(energy_block(plain.summary).empty());
    CHECK(energy_block(off.summary) == energy_block(plain.summary));
  }
  SECTION("radx check on the starter deck with the engine deck beside it") {
    dir.write("check/BLOCK_ON_PLATE_0000.rad",
              slurp(fs::path(RADX_SOURCE_DIR) / "decks/block_on_plate/BLOCK_ON_PLATE_0000.rad"));
    dir.write("check/BLOCK_ON_PLATE_0001.rad", text);
    const std::string cmd = std::string(RADX_DRIVER_EXE) + " check " +
                            dir.file("check/BLOCK_ON_PLATE_0000.rad") + " > " + dir.file("check.out") +
                            " 2> " + dir.file("check.err");
    const int status = std::system(cmd.c_str());
    const std::string err = slurp(dir.file("check.err"));
    INFO(err);
    CHECK((WIFEXITED(status) && WEXITSTATUS(status) == 0));
    CHECK(err.find(warning) != std::string::npos);
  }
}

TEST_CASE("/TFILE with dt_his 0 writes a time-history row every cycle, as Radioss does", "[engine-deck]") {
  radx::test::TempDir dir;
  const std::string model = block_on_plate_model(dir);
  const EngineRun r = run_engine(dir, model, "th", std::string(kEngineBody) + "/TFILE/4\n0.0\n/END\n");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(r.listing.find("time history every                cycle") != std::string::npos);
  // Rows: cycle 0 and every cycle after it.
  const auto at = r.summary.find("\"cycles\": ");
  REQUIRE(at != std::string::npos);
  const long cycles = std::stol(r.summary.substr(at + 10));
  const std::string cmd = std::string(RADX_DRIVER_EXE) + " th " +
                          (dir.path() / "th/BLOCK_ON_PLATE_th.h5").string() + " > " + dir.file("th.txt");
  REQUIRE(std::system(cmd.c_str()) == 0);
  const std::string listing = slurp(dir.file("th.txt"));
  CHECK(listing.find("rows:      " + std::to_string(cycles + 1) + ",") != std::string::npos);
  CHECK(cycles > 10);
}
