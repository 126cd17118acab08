// A run that will not end says so (apps/runaway_watch.hpp): the cycles left to the end time at the cycle's
// step against 100 times the starter's estimate of the whole run, or 1e9; once; with what sets the step and
// the wall time it would take.
#include <catch2/catch.hpp>
#include <string>

#include "apps/runaway_watch.hpp"

namespace {

using radx::solver::CycleReport;
using radx::solver::StepControl;

CycleReport cycle(std::int64_t n, double time, double dt, double dt1, StepControl control) {
  CycleReport r;
  r.cycle = n;
  r.time = time;
  r.dt = dt;
  r.dt1 = dt1;
  r.control = control;
  return r;
}

const StepControl kPair{StepControl::Kind::Interface, 1, 101};

}  // namespace

TEST_CASE(
    "runaway: cycles left beyond 100 times the estimate for 1000 cycles warn once, with the pair and the "
    "wall time",
    "[runaway]") {
  // Estimate: 1e4 cycles for a run to t = 1 s. At t = 0.5 s, a step of 0.5 / (100 x 1e4) = 5e-7 s leaves
  // 100 estimates: 5.1e-7 s leaves fewer, 4.9e-7 s more.
  radx::app::RunawayWatch w(1e4, 1.0, "s");
  CHECK(w.check(cycle(1000, 0.5, 5.1e-7, 5.1e-7, kPair), 1.0).empty());
  CHECK(w.check(cycle(1001, 0.5, 4.9e-7, 5.1e-7, kPair), 1.0).empty());  // the fall starts
  CHECK(w.check(cycle(2000, 0.5, 4.9e-7, 4.9e-7, kPair), 1.0).empty());  // 999 cycles into it
  const std::string m = w.check(cycle(2001, 0.5, 4.9e-7, 4.9e-7, kPair), 1.0);
  INFO(m);
  CHECK(m.find("the time step has fallen to 4.9e-07 s (since cycle 1001), set by interface 1 (secondary node "
               "101)") != std::string::npos);
  // 0.5 / 4.9e-7 = 1.02e6 cycles left, 102 estimates; 1 s over 2001 cycles is 500 us a cycle, 510 s (8.5
  // min).
  CHECK(m.find("take about 1.02e+06 more cycles, 102 times the starter's estimate of the whole run (1e+04 "
               "cycles); at the 500 us per cycle measured so far that is 8.5 min of wall time") !=
        std::string::npos);
  CHECK(m.find("--stop-if-runaway (or /DT/INTER/STOP with a Tmin)") != std::string::npos);
  CHECK(w.said());
  CHECK(w.check(cycle(5000, 0.5, 1e-9, 4.9e-7, kPair), 1.0).empty());  // once
}

TEST_CASE(
    "runaway: 1e9 cycles left warn whatever the estimate, a fall that ends or a step on its way back "
    "restarts the count",
    "[runaway]") {
  // An estimate of 1e9 cycles (100 of them would be 1e11): 1e9 cycles left are the limit.
  radx::app::RunawayWatch big(1e9, 1.0, "ms");
  const StepControl spring{StepControl::Kind::Spring, 7, 0};
  CHECK(big.check(cycle(500, 0.0, 1.01e-9, 1.01e-9, spring), 1.0).empty());
  CHECK(big.check(cycle(501, 0.0, 0.9e-9, 1.01e-9, spring), 1.0).empty());
  const std::string m = big.check(cycle(1501, 0.0, 0.9e-9, 0.9e-9, spring), 1.0);
  CHECK(m.find("set by spring 7") != std::string::npos);
  CHECK(m.find("/DT/SPRING/STOP") != std::string::npos);
  // No estimate: the 1e9 limit alone.
  radx::app::RunawayWatch none(0, 1.0, "s");
  const StepControl brick{StepControl::Kind::Brick, 3, 0};
  CHECK(none.check(cycle(500, 0.0, 0.9e-9, 0.9e-9, brick), 1.0).empty());
  CHECK_FALSE(none.check(cycle(1500, 0.0, 0.9e-9, 0.9e-9, brick), 1.0).empty());
  // A fall that passes (a step back above the limit), a step imposed by /DTIX or one growing at its 10 %
  // bound ends the count: 1000 cycles are needed again.
  radx::app::RunawayWatch w(10, 1.0, "s");  // limit 1000 cycles; a step of 1e-9 s leaves 1e9
  CHECK(w.check(cycle(50, 0.0, 1e-9, 1e-9, brick), 1.0).empty());
  CHECK(w.check(cycle(600, 0.0, 1e-2, 1e-9, brick), 1.0).empty());  // back up: 100 cycles left
  CHECK(w.check(cycle(1100, 0.0, 1e-9, 1e-9, brick), 1.0).empty());
  CHECK(w.check(cycle(1200, 0.0, 1e-9, 1e-9, {StepControl::Kind::Imposed, 0, 0}), 1.0).empty());
  CHECK(w.check(cycle(2150, 0.0, 1e-9, 1e-9, brick), 1.0).empty());    // the count restarts at 2150
  CHECK(w.check(cycle(2200, 0.0, 1.1e-9, 1e-9, brick), 1.0).empty());  // growing
  CHECK(w.check(cycle(3000, 0.0, 1e-9, 1e-9, brick), 1.0).empty());    // restarts at 3000
  CHECK(w.check(cycle(3999, 0.0, 1e-9, 1e-9, brick), 1.0).empty());
  // When the run stops on it, the message does not offer the ways to stop it.
  const std::string stop = w.check(cycle(4000, 0.0, 1e-9, 1e-9, brick), 1.0, true);
  CHECK(stop.find("(since cycle 3000), set by brick 3") != std::string::npos);
  CHECK(stop.find("--stop-if-runaway") == std::string::npos);
}

TEST_CASE("runaway: wall times in the unit that reads best", "[runaway]") {
  CHECK(radx::app::wall_time_words(42) == "42 s");
  CHECK(radx::app::wall_time_words(3 * 3600 + 1800) == "3.5 h");
  CHECK(radx::app::wall_time_words(12 * 86400) == "12 days");
  CHECK(radx::app::wall_time_words(1e12) == "3.17e+04 years");
}
