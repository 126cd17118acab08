// A run that will not end says so: after each cycle, whether the step has fallen so far that the cycles
// left to the end time exceed 100 times the starter's estimate of the whole run (or 1e9), said once with
// what controls the step and the wall time it would take at the cost per cycle measured so far.
#pragma once

#include <cstdint>
#include <string>
#include <utility>

#include "solver/engine/explicit_engine.hpp"

namespace radx::app {

class RunawayWatch {
 public:
  static constexpr double kEstimateFactor = 100;        // cycles left beyond this many times the estimate
  static constexpr double kCycleLimit = 1e9;            // or beyond this many cycles
  static constexpr std::int64_t kMeasuredCycles = 100;  // cycles timed before the wall time is projected
  // The fall must last: a steep contact's impact drops the step for a few hundred cycles and the run then
  // goes on at its own step (a projection from the dip would be a false alarm).
  static constexpr std::int64_t kLastingCycles = 1000;

  // estimated_cycles: the starter's estimate of the whole run's cycles (plausibility.hpp
  // estimate_run_cycles; 0 when it has none); t_stop the end time; time_unit_name for the message.
  RunawayWatch() = default;
  RunawayWatch(double estimated_cycles, double t_stop, std::string time_unit_name)
      : estimated_cycles_(estimated_cycles), t_stop_(t_stop), time_unit_(std::move(time_unit_name)) {}

  // The message, the first time the cycle's step leaves more cycles to the end time than the limit and has
  // done so on every call for at least kLastingCycles cycles; empty otherwise and after it. wall_seconds: the
  // wall time the run has taken so far; stops: the run stops on it (--stop-if-runaway), else the message says
  // how to stop such a run. A step imposed (/DTIX) or growing at its 10 % per cycle bound is on its way back:
  // it ends the count. Nothing before kMeasuredCycles.
  std::string check(const solver::CycleReport& r, double wall_seconds, bool stops = false);

  [[nodiscard]] bool said() const { return said_; }

 private:
  double estimated_cycles_ = 0, t_stop_ = 0;
  std::string time_unit_;
  bool said_ = false;
  std::int64_t since_ = -1;  // the first cycle of the current fall, -1 when the step is not fallen
};

// A wall time in the unit that reads best: "42 s", "3.5 h", "12 days", "3.1e+04 years".
std::string wall_time_words(double seconds);

}  // namespace radx::app
