// "Did you mean": the edit distance against counts made by hand, the slip bound, and the suggestions the
// readers add to a misspelt starter keyword, a misspelt engine keyword and a misspelt /ANIM field, beside
// the warning a real Radioss field that radx does not write keeps.
#include <catch2/catch.hpp>
#include <string>

#include "parser/building/build_run_controls.hpp"
#include "parser/reading/closest_names.hpp"
#include "parser/reading/deck.hpp"
#include "test_util.hpp"

using radx::Diag;
using radx::Severity;

namespace {

std::string all_messages(const radx::Diagnostics& d) {
  std::string s;
  for (const auto& x : d.items()) s += radx::Diagnostics::format(x) + "\n";
  return s;
}

}  // namespace

TEST_CASE("the edit distance counts insertions, deletions, substitutions and adjacent swaps", "[spelling]") {
  // Counted by hand: kitten -> sitten (k/s) -> sittin (e/i) -> sitting (+g).
  CHECK(radx::edit_distance("kitten", "sitting") == 3);
  CHECK(radx::edit_distance("", "abc") == 3);
  CHECK(radx::edit_distance("abc", "") == 3);
  CHECK(radx::edit_distance("VONM", "VONM") == 0);
  // One swap of neighbours is one edit (plain Levenshtein would count two).
  CHECK(radx::edit_distance("PLAS_JHONS", "PLAS_JOHNS") == 1);
  CHECK(radx::edit_distance("VNOM", "VONM") == 1);
  // Case does not count: the readers store keywords upper case, users type options lower case.
  CHECK(radx::edit_distance("/part", "/PART") == 0);
  CHECK(radx::edit_distance("--thread", "--threads") == 1);
}

TEST_CASE("a name is suggested only within the slip bound, all the nearest ones, none for a known name",
          "[spelling]") {
  const std::vector<std::string> known = {"--out", "--threads", "--no-plot", "--starter-only"};
  CHECK(radx::did_you_mean("--thread", known) == "did you mean --threads?");
  CHECK(radx::did_you_mean("--threads", known).empty());  // known: nothing to suggest
  // 9 characters allow 2 edits: "--nplot" is 2 from "--no-plot"; "--zzzzzz" is far from everything.
  CHECK(radx::did_you_mean("--noplot", known) == "did you mean --no-plot?");
  CHECK(radx::did_you_mean("--zzzzzz", known).empty());
  // Two at the same distance are both named.
  CHECK(radx::did_you_mean("--thread", {"--threads", "--thready"}) == "did you mean --threads or --thready?");
  // Members of a numbered family are not slips of one another: LAW3 is not LAW1, LAW2 or LAW36.
  CHECK(radx::did_you_mean("LAW3", {"LAW1", "LAW2", "LAW36"}).empty());
  CHECK(radx::did_you_mean("/MAT/LAW51", {"/MAT/LAW1", "/MAT/LAW2"}).empty());
  // Two characters: one edit reaches every short option, so none is suggested.
  CHECK(radx::did_you_mean("-x", {"-i", "-j"}).empty());
}

TEST_CASE("a misspelt starter keyword gets the keyword radx reads that it is one slip from", "[spelling]") {
  radx::test::TempDir dir;
  const auto path =
      dir.write("dym_0000.rad", radx::test::begin_block(2026) +
                                    "/MAT/PLAS_JHONS/1\nsteel\n/PRAT/1\n/MAT/LAW51/3\nmm\n/END\n");
  radx::Diagnostics diags;
  (void)radx::read_starter_deck(path, diags);
  const std::string all = all_messages(diags);
  INFO(all);
  CHECK(all.find("RX302: [/MAT/PLAS_JHONS id 1] /MAT/PLAS_JHONS is not a material law radx reads") !=
        std::string::npos);
  CHECK(all.find("did you mean /MAT/PLAS_JOHNS?") != std::string::npos);
  CHECK(all.find("RX301: [/PRAT] unknown keyword /PRAT") != std::string::npos);
  CHECK(all.find("did you mean /PART?") != std::string::npos);
  // A real Radioss law far from every law radx reads gets the list, not a guess.
  const auto law51 = all.find("[/MAT/LAW51 id 3]");
  REQUIRE(law51 != std::string::npos);
  CHECK(all.find("did you mean", law51) == std::string::npos);
}

TEST_CASE("a misspelt /ANIM field is an error naming the closest field, a Radioss field radx lacks a warning",
          "[spelling]") {
  radx::test::TempDir dir;
  const std::string deck =
      "/RUN/DYM/1\n1e-3\n/ANIM/DT\n0 1e-4\n/ANIM/ELEM/VNOM\n/ANIM/ELEM/TEMP\n/ANIM/VECT/VELL\n/STPO\n/END\n";
  radx::Diagnostics diags;
  const auto rc = radx::read_run_controls(dir.write("DYM_0001.rad", deck), diags);
  const std::string all = all_messages(diags);
  INFO(all);
  auto at = [&](int line) -> const radx::Diagnostic* {
    for (const auto& d : diags.items())
      if (d.line == line) return &d;
    return nullptr;
  };
  const auto* vnom = at(5);
  REQUIRE(vnom);
  CHECK(vnom->severity == Severity::Error);
  CHECK(vnom->code == Diag::UnknownKeyword);
  CHECK(vnom->message.find("did you mean VONM?") != std::string::npos);
  // TEMP is a Radioss field (temperature) radx does not write: the run may go on without it.
  const auto* temp = at(6);
  REQUIRE(temp);
  CHECK(temp->severity == Severity::Warning);
  CHECK(temp->code == Diag::OutputNotWritten);
  // VELL starts with VEL, which Radioss compares on three letters: it is the velocity, as in Radioss.
  CHECK(at(7) == nullptr);
  CHECK(rc.anim_vect == std::vector<std::string>{"VEL"});
  const auto* stpo = at(8);
  REQUIRE(stpo);
  CHECK(stpo->severity == Severity::Error);
  CHECK(stpo->code == Diag::UnknownKeyword);
  CHECK(stpo->message.find("did you mean /STOP?") != std::string::npos);
}
