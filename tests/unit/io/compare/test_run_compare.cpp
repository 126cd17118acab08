// The comparison of two runs (io/compare/run_compare.hpp) on runs written here,
// whose deviations have closed forms: B scales A's channel and energy, so the
// largest scores follow from the tolerance's definition.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <vector>

#include "io/compare/run_compare.hpp"
#include "io/hdf5/time_history.hpp"
#include "io/listing/summary_json.hpp"
#include "test_util.hpp"

namespace {

namespace fs = std::filesystem;
using radx::io::compare_runs;
using radx::io::CompareOptions;
using radx::io::RunComparison;
using radx::io::RunFiles;

// A run R in `dir`: a summary whose internal energy is 10 s^2 (kinetic 5), and
// node/1's DX = 2 s t for object 7 on rows every `step` from 0 to 1 s.
void write_run(const fs::path& dir, double s, double step) {
  fs::create_directories(dir);
  radx::io::RunSummary sum;
  sum.run_name = "R";
  sum.cycles = 100;
  sum.time = 1.0;
  sum.initial_mass = sum.mass = 2.0;
  sum.energy.internal = 10 * s * s;
  sum.energy.kinetic_t = 5;
  std::string error;
  REQUIRE(radx::io::write_summary_json((dir / "R_summary.json").string(), sum, error));
  radx::io::ThGroupLayout node;
  node.path = "node/1";
  node.object_kind = "node";
  node.objects = {7};
  node.variables = {"DX"};
  node.units = {"m"};
  radx::io::TimeHistoryWriter w((dir / "R_th.h5").string(), {node}, "s");
  const int n = static_cast<int>(std::lround(1.0 / step));
  for (int i = 0; i <= n; ++i) {
    const double t = i * step, dx = 2 * s * t;
    w.append(t, {std::span<const double>(&dx, 1)});
  }
  w.flush();
}

double score_of(const RunComparison& c, const std::string& quantity) {
  for (const auto& d : c.deviations)
    if (d.quantity == quantity) return d.score;
  return -1;
}

}  // namespace

TEST_CASE(
    "run comparison: scores of a scaled run, a run against itself, and "
    "bad input") {
  radx::test::TempDir dir;
  const double eps = 0.02;
  write_run(dir.path() / "a", 1.0, 0.1);
  write_run(dir.path() / "b", 1.0 + eps,
            0.05);  // other row times: B is read at A's by interpolation
  RunFiles a, b;
  std::string error;
  REQUIRE(radx::io::find_run_files((dir.path() / "a").string(), a, error));
  REQUIRE(radx::io::find_run_files((dir.path() / "b" / "R").string(), b, error));
  CHECK(fs::path(b.th).filename() == "R_th.h5");

  RunComparison c;
  CompareOptions o;
  o.rel = 0.01;
  REQUIRE(compare_runs(a, b, o, c, error));
  CHECK(c.channels == 1);
  CHECK(c.common_times == 21);  // the union of both runs' rows
  // DX: |b - a| = 2 eps t, allowed = max(rel 2 t, rel 2 (1 + eps)) (the floor:
  // rel x the largest magnitude, B's at t = 1); the score is largest at t = 1:
  // eps / (rel (1 + eps)).
  const auto& dx = *std::find_if(c.deviations.begin(), c.deviations.end(),
                                 [](const auto& d) { return d.quantity == "th:node/1:7:DX"; });
  CHECK(dx.score == Approx(eps / (o.rel * (1 + eps))).epsilon(1e-12));
  REQUIRE(dx.time);
  CHECK(*dx.time == 1.0);
  CHECK(dx.a == Approx(2.0));
  CHECK(dx.b == Approx(2 * (1 + eps)));
  // energy.internal: |b - a| = 10 ((1 + eps)^2 - 1), against rel x the family's
  // largest magnitude, B's total energy 10 (1 + eps)^2 + 5.
  const double d_ie = 10 * ((1 + eps) * (1 + eps) - 1);
  CHECK(score_of(c, "energy.internal") == Approx(d_ie / (o.rel * (10 * (1 + eps) * (1 + eps) + 5))));
  CHECK(score_of(c, "energy.kinetic_translational") == 0);
  CHECK(score_of(c, "cycles") == 0);
  CHECK(score_of(c, "energy.total") == Approx(d_ie / (o.rel * (10 * (1 + eps) * (1 + eps) + 5))));
  CHECK(c.past() == 3);  // DX (1.96), the internal and the total energy (2.62); the rest agree
  CHECK(c.deviations.front().score >= c.deviations.back().score);  // largest first

  // An absolute floor of 1 m makes DX pass (2 eps = 0.04 m at most), and rel =
  // 0.2 every figure.
  o.abs = 1.0;
  REQUIRE(compare_runs(a, b, o, c, error));
  CHECK(score_of(c, "th:node/1:7:DX") == Approx(2 * eps / 1.0));
  o.abs.reset();
  o.rel = 0.2;
  REQUIRE(compare_runs(a, b, o, c, error));
  CHECK(c.past() == 0);

  // A run against itself: every score 0.
  REQUIRE(compare_runs(a, a, CompareOptions{}, c, error));
  CHECK(c.past() == 0);
  for (const auto& d : c.deviations) CHECK(d.score == 0);
  std::ostringstream report;
  radx::io::write_comparison(a, a, CompareOptions{}, c, report);
  CHECK(report.str().find("within the tolerance: 0 of") != std::string::npos);

  // Bad input: no summary, a time history on one side only.
  CHECK_FALSE(radx::io::find_run_files((dir.path() / "nowhere").string(), b, error));
  CHECK(error.find("no run summary") != std::string::npos);
  fs::remove(dir.path() / "b" / "R_th.h5");
  REQUIRE(radx::io::find_run_files((dir.path() / "b").string(), b, error));
  CHECK_FALSE(compare_runs(a, b, CompareOptions{}, c, error));
  CHECK(error.find("both runs need a time history") != std::string::npos);
}
