// Every deck in decks/invalid/ carries its expected diagnostics as comment lines
//   # expect: RX402 line 93 [file inc/other.rad]
// The starter must report each of them (code, file and line) as an error or warning of that code,
// report no error that is not expected, exit with code 1 when any error is expected, and leave no
// model file (nor a .part file) behind.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "apps/starter_pipeline.hpp"
#include "parser/reading/deck.hpp"
#include "solver/model/run_files.hpp"
#include "test_util.hpp"

namespace fs = std::filesystem;

namespace {

struct Expected {
  int code = 0;
  int line = 0;
  std::string file;      // relative to the deck's folder; empty: the deck itself
  bool warning = false;  // "... warning": a warning; otherwise an error, and the deck must be refused
};

std::vector<Expected> read_expectations(const fs::path& deck) {
  std::vector<Expected> out;
  std::ifstream in(deck);
  std::string line;
  const std::regex re(R"(^#\s*expect:\s*RX(\d+)\s+line\s+(\d+)(?:\s+file\s+(\S+))?(\s+warning)?\s*$)");
  while (std::getline(in, line)) {
    std::smatch m;
    if (std::regex_search(line, m, re))
      out.push_back({std::stoi(m[1]), std::stoi(m[2]), m[3].matched ? m[3].str() : "", m[4].matched});
  }
  return out;
}

std::vector<fs::path> invalid_decks() {
  std::vector<fs::path> decks;
  for (const auto& e : fs::directory_iterator(fs::path(RADX_SOURCE_DIR) / "decks" / "invalid"))
    if (e.path().extension() == ".rad") decks.push_back(e.path());
  std::sort(decks.begin(), decks.end());
  return decks;
}

}  // namespace

TEST_CASE("there are at least 30 invalid decks and each states its expectations", "[invalid]") {
  const auto decks = invalid_decks();
  CHECK(decks.size() >= 30);
  for (const auto& d : decks) {
    INFO(d.string());
    CHECK_FALSE(read_expectations(d).empty());
  }
}

TEST_CASE("every invalid deck gives its diagnostics, exit code 1 and no model file", "[invalid]") {
  for (const auto& deck : invalid_decks()) {
    DYNAMIC_SECTION(deck.filename().string()) {
      const auto expected = read_expectations(deck);
      radx::test::TempDir out;
      radx::app::StarterOptions opt;
      opt.deck = deck.string();
      opt.out_dir = out.path().string();
      std::ostringstream so, se;
      const auto res = radx::app::run_starter(opt, so, se);
      const std::string report = se.str();
      INFO("stderr:\n" << report);
      // Parse the reported lines back: `file:line:col: severity: RXnnn: ...`.
      const std::regex line_re(R"(^(.*?):(\d+)(?::\d+)?: (error|warning|note): RX(\d+):)");
      struct Got {
        std::string file;
        int line;
        std::string severity;
        int code;
      };
      std::vector<Got> got;
      std::istringstream is(report);
      std::string l;
      while (std::getline(is, l)) {
        std::smatch m;
        if (std::regex_search(l, m, line_re)) got.push_back({m[1], std::stoi(m[2]), m[3], std::stoi(m[4])});
      }
      bool any_error_expected = false;
      for (const auto& e : expected) {
        const fs::path want = e.file.empty() ? deck : deck.parent_path() / e.file;
        const auto hit = std::find_if(got.begin(), got.end(), [&](const Got& g) {
          return g.code == e.code && g.line == e.line &&
                 fs::weakly_canonical(g.file) == fs::weakly_canonical(want);
        });
        INFO("expected RX" << e.code << " at " << want.filename().string() << ":" << e.line);
        REQUIRE(hit != got.end());
        CHECK(hit->severity == (e.warning ? "warning" : "error"));
        if (!e.warning) any_error_expected = true;
      }
      // No error beyond the expected ones.
      for (const auto& g : got) {
        if (g.severity != "error") continue;
        const bool expected_one = std::any_of(expected.begin(), expected.end(), [&](const Expected& e) {
          return e.code == g.code && e.line == g.line;
        });
        INFO("unexpected error RX" << g.code << " at line " << g.line);
        CHECK(expected_one);
      }
      CHECK(res.exit_code == (any_error_expected ? 1 : 0));
      if (any_error_expected) {
        const auto root = radx::model::starter_output_root(deck.string());
        CHECK_FALSE(fs::exists(out.path() / (root + ".hdf")));
        CHECK_FALSE(fs::exists(out.path() / (root + ".hdf.part")));
      }
    }
  }
}
