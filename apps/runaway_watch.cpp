// The runaway test (apps/runaway_watch.hpp): with the step dt of the cycle at time t,
//   cycles_left = (t_stop - t) / dt,  a runaway when cycles_left > min(100 N_est, 1e9)
// (N_est the starter's cycles for the whole run, plausibility.hpp; 1e9 alone when it has none) on every call
// for 1000 cycles, and the wall time it would take, cycles_left * (wall time so far / cycles so far).
#include "apps/runaway_watch.hpp"

#include <algorithm>
#include <cstdio>

#include "solver/engine/step_control_names.hpp"

namespace radx::app {

namespace {

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

}  // namespace

std::string wall_time_words(double seconds) {
  constexpr double kMinute = 60, kHour = 3600, kDay = 86400, kYear = 365.25 * kDay;
  if (seconds < 2 * kMinute) return num(seconds) + " s";
  if (seconds < 2 * kHour) return num(seconds / kMinute) + " min";
  if (seconds < 2 * kDay) return num(seconds / kHour) + " h";
  if (seconds < kYear) return num(seconds / kDay) + " days";
  return num(seconds / kYear) + " years";
}

std::string RunawayWatch::check(const solver::CycleReport& r, double wall_seconds, bool stops) {
  if (said_ || !(r.dt > 0) || !(r.time < t_stop_)) return {};
  const double left = (t_stop_ - r.time) / r.dt;
  const double limit =
      estimated_cycles_ > 0 ? std::min(kEstimateFactor * estimated_cycles_, kCycleLimit) : kCycleLimit;
  const bool recovering = r.control.kind == solver::StepControl::Kind::Imposed ||
                          (r.dt1 > 0 && r.dt >= 1.0999 * r.dt1);  // on its way up at the growth bound
  if (!(left > limit) || recovering) {
    since_ = -1;
    return {};
  }
  if (since_ < 0) since_ = r.cycle;
  if (r.cycle < kMeasuredCycles || r.cycle - since_ < kLastingCycles) return {};
  said_ = true;
  const double per_cycle = wall_seconds / static_cast<double>(r.cycle);
  std::string m = "the run will not end in any reasonable time: the time step has fallen to " + num(r.dt) +
                  " " + time_unit_ + " (since cycle " + std::to_string(since_) + "), set by " +
                  solver::step_control_name(r.control) + "; the " + num(t_stop_ - r.time) + " " + time_unit_ +
                  " left to the end time take about " + num(left) + " more cycles";
  if (estimated_cycles_ > 0)
    m += ", " + num(left / estimated_cycles_) + " times the starter's estimate of the whole run (" +
         num(estimated_cycles_) + " cycles)";
  m += "; at the " + num(per_cycle * 1e6) + " us per cycle measured so far that is " +
       wall_time_words(left * per_cycle) + " of wall time";
  if (!stops)
    m += ". The run goes on; --stop-if-runaway (or " + solver::step_stop_keyword(r.control.kind) +
         " with a Tmin) stops such a run";
  return m +
         "; check what sets the step (a steep contact or spring law, a tiny or crushed element, the units)";
}

}  // namespace radx::app
