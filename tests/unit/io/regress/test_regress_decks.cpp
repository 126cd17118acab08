// The decks of `radx regress` (io/regress/regress_decks.hpp): deck discovery, labels, references and run
// folders, the "# expect:" lines, and --filter.
#include <catch2/catch.hpp>
#include <filesystem>
#include <string>
#include <vector>

#include "io/regress/regress_decks.hpp"
#include "ref_extract_sample.hpp"
#include "test_util.hpp"

namespace fs = std::filesystem;
using radx::test::kExtract;

TEST_CASE("regress: deck folders, labels, references and restart notes", "[regress]") {
  radx::test::TempDir dir;
  const fs::path root = dir.path() / "qa";
  dir.write("qa/A/data/CASE_0000.rad", "/BEGIN\n");
  dir.write("qa/A/data/CASE_0001.rad", "/RUN\n");
  dir.write("qa/A/data/ref.extract", kExtract);
  dir.write("qa/B/ONE_0000.rad", "");
  dir.write("qa/B/TWO_0000.rad", "");
  dir.write("qa/B/TWO_0001.rad", "");
  dir.write("qa/B/ref.extract", kExtract);
  dir.write("qa/C/Single.rad", "#RADIOSS STARTER\n/BEGIN\n/END\n/END/ENGINE\n");
  dir.write("qa/C/include.rad", "/NODE\n");  // neither a starter deck nor a one-file deck
  dir.write("qa/D/R_0000.rad", "");
  dir.write("qa/D/R_0001.rad", "");
  dir.write("qa/D/R_0002.rad", "");
  dir.write("qa/D/R_0003.rad", "");
  dir.write("qa/.hidden/H_0000.rad", "");
  dir.write("qa/E/only_include.rad", "/NODE\n");
  dir.write("qa/TOP_0000.rad", "");

  const auto decks = radx::io::find_regress_decks({root});
  REQUIRE(decks.size() == 6);
  CHECK(decks[0].label == "qa");  // a deck directly in DIR: DIR's name
  CHECK(decks[0].starter_deck.filename() == "TOP_0000.rad");
  CHECK(decks[1].label == "A/data");
  CHECK(decks[1].reference == root / "A/data/ref.extract");
  CHECK(decks[1].work_subdir == fs::path("A~data"));
  CHECK(decks[1].note.empty());
  CHECK(decks[2].label == "B/ONE_0000.rad");
  CHECK(decks[2].reference.empty());
  CHECK(decks[2].note == "ref.extract not used: the folder holds 2 decks");
  CHECK(decks[3].label == "B/TWO_0000.rad");
  CHECK(decks[3].work_subdir == fs::path("B~TWO_0000"));
  CHECK(decks[4].label == "C");
  CHECK(decks[4].starter_deck.filename() == "Single.rad");
  CHECK(decks[5].label == "D");
  CHECK(decks[5].note == "R_0002.rad, R_0003.rad not run (radx runs R_0001.rad only: it has no restart)");

  // Several DIRs: labels start with each DIR as given; a deck reached twice runs once; the work folder
  // is skipped.
  const auto two = radx::io::find_regress_decks({root / "A", root / "D", root}, root / "B");
  REQUIRE(two.size() == 4);
  CHECK(two[0].label == (root / "A/data").generic_string());
  CHECK(two[0].work_subdir == fs::path("1_A~data"));
  CHECK(two[1].label == (root / "D").generic_string());
  CHECK(two[2].starter_deck.filename() == "TOP_0000.rad");
  CHECK(two[3].starter_deck.filename() == "Single.rad");
}

TEST_CASE("regress: a deck's run folder never holds another deck's", "[regress]") {
  // Deck A and deck A/B: each run folder is cleared before its run and removed when it passes, so A's must
  // not contain A/B's.
  radx::test::TempDir dir;
  dir.write("qa/A/X_0000.rad", "");
  dir.write("qa/A/B/Y_0000.rad", "");
  dir.write("qa/A~B/Z_0000.rad", "");  // a folder whose flat name is A/B's
  const auto decks = radx::io::find_regress_decks({dir.path() / "qa"});
  REQUIRE(decks.size() == 3);
  for (const auto& a : decks) {
    CHECK(a.work_subdir.has_filename());
    CHECK(a.work_subdir.parent_path().empty());  // one level: no deck's folder inside another's
    for (const auto& b : decks)
      if (&a != &b) CHECK(a.work_subdir != b.work_subdir);
  }
}

TEST_CASE("regress: # expect: lines, their severity and their problems", "[regress]") {
  radx::test::TempDir dir;
  const fs::path deck =
      dir.write("d/x.rad",
                "# expect: RX402 line 37\n"
                "# expect: RX102 line 5 file inc/b.rad\n"
                "# expect: RX512 line 84 warning\n"
                "# expect: RX301\n"
                "# expect: RX9 line 99999999999999999999\n"  // a line number too long: a problem
                "# expect: line 3\n"                         // no code
                "# fault: text\n"
                "/BEGIN\n"
                "# expect: RX1 line 1\n");  // after the opening comment block: not read
  std::vector<std::string> problems;
  const auto e = radx::io::read_expected_errors(deck, problems);
  REQUIRE(e.size() == 4);
  CHECK(e[0].code == "RX402");
  CHECK(e[0].line == 37);
  CHECK_FALSE(e[0].warning);
  CHECK(e[0].file == deck.lexically_normal());
  CHECK(e[1].file == (dir.path() / "d/inc/b.rad").lexically_normal());
  CHECK(e[2].warning);
  CHECK(e[2].text() == "RX512 line 84 in x.rad (warning)");
  CHECK(e[3].line == 0);  // any line
  REQUIRE(problems.size() == 2);
  CHECK(problems[0].find("x.rad:5: an expectation is \"# expect: RXnnn [line L] [file PATH] [warning]\"") !=
        std::string::npos);
  CHECK(problems[1].find("x.rad:6:") != std::string::npos);
}

TEST_CASE("regress: --filter is a glob on the whole name, or a part of it", "[regress]") {
  using radx::io::label_matches;
  CHECK(label_matches("verification/ctclaw_drop/CTCLAW_DROP_N1_0000.rad", "ctclaw"));
  CHECK_FALSE(label_matches("taylor_bar", "ctclaw"));
  CHECK(label_matches("ctclaw_laws", "ctclaw*"));
  CHECK_FALSE(label_matches("verification/ctclaw_drop", "ctclaw*"));  // a glob matches the whole name
  CHECK(label_matches("verification/ctclaw_drop", "*/ctclaw_[dl]*"));
}
