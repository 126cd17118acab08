// One deck's run in `radx regress` (io/regress/regress_run.hpp): the first error line and its group, how a
// deck's status follows from its run, and a reference that stops before the run's end.
#include <catch2/catch.hpp>
#include <string>

#include "io/listing/engine_listing.hpp"
#include "io/regress/regress_report.hpp"
#include "io/regress/regress_run.hpp"
#include "ref_extract_sample.hpp"
#include "test_util.hpp"

using radx::test::kExtract;
using radx::test::with_line;

TEST_CASE("regress: the first error line, shortened, and its group", "[regress]") {
  const auto e = radx::io::first_error(
      "radx starter 0.1.0\n  0 error(s), 3 warning(s)\n"
      "/a/b/LOI14_0000.rad:12:1: warning: RX900: something\n"
      "/a/b/LOI14_0000.rad:40:11: error: RX402: [/PART id 1 \"x\"] mat_ID = 1: there is no /MAT/1\n"
      "/a/b/LOI14_0000.rad:59:1: error: RX301: [/MAT/LAW14] unknown keyword /MAT/LAW14: not a keyword\n"
      "/a/b/LOI14_0000.rad:60:1: error: RX402: second\n");
  CHECK(e.location == "LOI14_0000.rad:59");
  CHECK(e.message == "RX301: [/MAT/LAW14] unknown keyword /MAT/LAW14: not a keyword");
  CHECK(radx::io::refusal_group(e.message) == "RX301 /MAT/LAW14");
  CHECK(radx::io::refusal_group("RX402: [/PART id 1 \"x\"] prop_ID = 2: no /PROP/2") == "RX402 /PART");
  CHECK(radx::io::refusal_group("cannot write the results: disk full") == "cannot write the results");

  // Only dangling references: the first of them.
  CHECK(
      radx::io::first_error("F.rad:7:1: error: RX402: [/PART id 2] no /PROP/3\nF.rad:9:1: error: RX402: b\n")
          .location == "F.rad:7");

  const auto p = radx::io::first_error("radx-engine: error: cannot write the results\r\n");
  CHECK(p.location == "radx-engine");
  CHECK(p.message == "cannot write the results");
  const auto none = radx::io::first_error("radx-engine: 1 error(s) in X; nothing was run\nterror: no\n");
  CHECK(none.message.empty());
  CHECK(radx::io::first_error("error: bare\n").message == "bare");

  CHECK(radx::io::shorten("short", 10) == "short");
  CHECK(radx::io::shorten("the Radioss keyword /MAT/LAW36 is not supported", 30) == "the Radioss keyword...");
  CHECK(radx::io::shorten("the Radioss keyword /MAT/LAW36 is not supported", 30).size() <= 30);
}

TEST_CASE("regress: a deck's status follows from its run", "[regress]") {
  radx::test::TempDir dir;
  radx::io::RegressDeck deck;
  deck.label = "X";
  radx::io::ChildOutcome exited;
  exited.exit_code = 0;
  radx::io::RegressRunFiles files;
  using radx::io::RegressStatus;

  // No model file: the starter refused it.
  auto failed = exited;
  failed.exit_code = 1;
  files.output = "X_0000.rad:3:1: error: RX302: [/MAT/LAW36] not supported\n";
  auto r = radx::io::evaluate_deck(deck, failed, files, 0.05);
  CHECK(r.status == RegressStatus::ReadError);
  CHECK(r.refusal.message == "RX302: [/MAT/LAW36] not supported");
  CHECK(r.detail.empty());
  CHECK(radx::io::is_failure(r.status));

  // A model file, then the time limit: the engine ran out of time.
  files.model_written = true;
  files.output.clear();
  auto late = failed;
  late.exit_code = -1;
  late.timed_out = true;
  late.signal = 9;
  late.seconds = 3.0;
  r = radx::io::evaluate_deck(deck, late, files, 0.05);
  CHECK(r.status == RegressStatus::RunError);
  CHECK(r.detail == "the engine ran out of time (3.0 s)");

  // An error termination.
  radx::io::RunSummary s;
  s.status = radx::io::RunStatus::Error;
  s.message = "/STOP: energy error above 10 %";
  files.summary = s;
  r = radx::io::evaluate_deck(deck, failed, files, 0.05);
  CHECK(r.status == RegressStatus::RunError);
  CHECK(r.detail == "error termination: /STOP: energy error above 10 %");

  // Stopped by SIGTERM (the engine exits 143), or killed outright so the summary written at the start is
  // left: a run error even with exit code 0, since the figures are not those of the finished run.
  s.status = radx::io::RunStatus::Interrupted;
  s.message = "interrupted by SIGTERM at cycle 12, time 1.00000E-03";
  files.summary = s;
  r = radx::io::evaluate_deck(deck, exited, files, 0.05);
  CHECK(r.status == RegressStatus::RunError);
  CHECK(r.detail == "the engine was interrupted by SIGTERM at cycle 12, time 1.00000E-03");
  s.status = radx::io::RunStatus::Running;
  files.summary = s;
  r = radx::io::evaluate_deck(deck, exited, files, 0.05);
  CHECK(r.status == RegressStatus::RunError);
  CHECK(r.detail == "the engine did not finish (its summary still says \"running\")");

  // A normal run: ran without a reference, compared or deviates with one, ref-error with a broken one.
  s.status = radx::io::RunStatus::Normal;
  s.cycles = 40;
  s.time = 2.5380e-02;
  s.energy.internal = 8.8150e-02;
  s.energy.kinetic_t = 1.4560e-01 + 0.04 * 2.3330e-01;  // 4 % of the magnitude
  s.energy.kinetic_r = 0;
  s.energy.external_work = 2.3330e-01;
  s.energy.hourglass = 1.0;  // not compared: IENERGY is the listing's I-ENERGY
  files.summary = s;
  r = radx::io::evaluate_deck(deck, exited, files, 0.05);
  CHECK(r.status == RegressStatus::Ran);
  REQUIRE(r.radx);
  CHECK(r.radx->cycles == 40);
  CHECK_FALSE(radx::io::is_failure(r.status));

  deck.reference = dir.write("ref.extract", kExtract);
  r = radx::io::evaluate_deck(deck, exited, files, 0.05);
  CHECK(r.status == RegressStatus::Compared);
  REQUIRE(r.comparison);
  CHECK(r.comparison->energy[1] == Approx(0.04).epsilon(1e-9));
  CHECK(r.comparison->energy[0] == 0.0);
  CHECK(r.comparison->cycle_ratio == Approx(40.0 / 29.0));
  CHECK(radx::io::format_regress_line(r).find("compared  cycles 40/29 (x1.38)") != std::string::npos);
  r = radx::io::evaluate_deck(deck, exited, files, 0.03);
  CHECK(r.status == RegressStatus::Deviates);
  CHECK(radx::io::is_failure(r.status));

  deck.reference = dir.write("bad.extract", with_line(9, "    9 KENERGYT\t 1.4560e-01"));
  r = radx::io::evaluate_deck(deck, exited, files, 0.05);
  CHECK(r.status == RegressStatus::RefError);
  CHECK(r.detail.find("bad.extract:9: KENERGYT") != std::string::npos);
}

TEST_CASE("regress: a reference that stops before the run's end is compared at its time, from the listing",
          "[regress]") {
  // The listing lines as the engine writes them (io::format_listing_line), read back by listing_points.
  std::string listing = "  some header line\n";
  for (int k = 0; k <= 4; ++k) {
    radx::io::ListingLine l;
    l.cycle = 10 * k;
    l.time = 0.01 * k;
    l.dt = 1e-3;
    l.source = radx::io::StepSource::Brick;
    l.source_id = 7;
    l.internal_energy = 1.0 + k;  // linear in time: the interpolation is exact
    l.kinetic_t = 10.0 - k;
    l.kinetic_r = 0.5 * k;
    l.external_work = 2.0 * k;
    listing += radx::io::format_listing_line(l) + "\n";
  }
  const auto points = radx::io::listing_points(listing);
  REQUIRE(points.size() == 5);
  CHECK(points[3].cycle == 30);
  CHECK(points[3].time == Approx(0.03));
  CHECK(points[3].energy[0] == Approx(4.0));
  CHECK(points[3].energy[2] == Approx(1.5));

  // The run ended at 0.04; the reference's last line is at t = 0.025 with the values the line above gives
  // there: IE 3.5, KE 7.5, KER 1.25, EXT 5 (magnitude 10).
  radx::test::TempDir dir;
  radx::io::RegressDeck deck;
  deck.reference =
      dir.write("ref.extract",
                "    1 Start                    0\n    2 CYCLE\t        25\n    3 TIME\t 2.5000e-02\n"
                "    4 TSTEP\t 1.0000e-03\n    5 ELEMENT\t0\n    6 ELTID\t        7\n"
                "    7 ERROR\t  0.0\n    8 IENERGY\t 3.5000e+00 1.0000e+01\n"
                "    9 KENERGYT\t 7.5000e+00 1.0000e+01\n   10 KENERGYR\t 1.2500e+00 1.0000e+01\n"
                "   11 EXTWORK\t 5.0000e+00 1.0000e+01\n   12 MASERR\t0.000\n"
                "   13 Stop                    0\n");
  radx::io::ChildOutcome exited;
  exited.exit_code = 0;
  radx::io::RegressRunFiles files;
  files.model_written = true;
  radx::io::RunSummary s;
  s.cycles = 40;
  s.time = 0.04;
  s.energy.internal = 5.0;
  s.energy.kinetic_t = 6.0;
  s.energy.kinetic_r = 2.0;
  s.energy.external_work = 8.0;
  files.summary = s;
  files.listing = points;
  const auto r = radx::io::evaluate_deck(deck, exited, files, 0.01);
  INFO(r.detail);
  REQUIRE(r.comparison);
  CHECK(r.at_reference_time);
  CHECK(r.status == radx::io::RegressStatus::Compared);
  for (const double d : r.comparison->energy) CHECK(d <= 1e-12);
  CHECK(r.radx->time == Approx(0.025));
  // Without the listing the run's end is compared: the deviation shows.
  files.listing.clear();
  const auto end = radx::io::evaluate_deck(deck, exited, files, 0.01);
  CHECK_FALSE(end.at_reference_time);
  CHECK(end.status == radx::io::RegressStatus::Deviates);
}
