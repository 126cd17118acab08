// `radx diff RUN_A RUN_B`: how far two runs of the same model lie apart, figure by figure of their
// NAME_summary.json and channel by channel of their NAME_th.h5 (docs/results.md, "Comparing two runs").
//
// A summary figure is one of the quantities a regression reference may hold
// (io/regress/regress_reference.hpp: cycles, time, masses, energies, momentum, ...). A channel is a
// time-history column, matched between the runs by its name "<group path>:<object id>:<variable>" (or
// "global:<variable>"), that is by /TH group, object and variable. The channels are compared on the common
// times: every row time of either run inside the span both cover, each run's channel read there by linear
// interpolation between its rows.
//
// Tolerance: B's value b passes against A's a where
//     |b - a| <= allowed = max(rel |a|, floor)
// and its score is |b - a| / allowed (at most 1 passes). The floor judges values near zero on the scale of
// what is compared rather than on their round-off: by default it is rel times the largest magnitude that the
// channels of the same /TH group and unit take in either run (over the common times: a section's lateral
// force, round-off, is judged against its axial force), for a summary figure rel times the largest magnitude
// of its family in either run (energy.*: every energy, so a zero hourglass energy is judged against the
// total; momentum.*: the three components; any other figure, and the energy error in %: itself); `abs`
// replaces it by one absolute floor, in each channel's own unit.
#pragma once

#include <cstddef>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace radx::io {

struct CompareOptions {
  double rel = 1e-3;          // relative tolerance
  std::optional<double> abs;  // absolute floor (each channel's unit); empty: the scale floor above
  std::size_t top = 10;       // deviations printed
};

// A run's files. `run` is its NAME_summary.json, the folder holding exactly one such file, or the prefix
// DIR/NAME; the time history is NAME_th.h5 beside the summary (`th` empty when there is none).
struct RunFiles {
  std::string name;  // what the report calls the run: the argument as given
  std::string summary;
  std::string th;
};
bool find_run_files(const std::string& run, RunFiles& out, std::string& error);

// The largest deviation of one summary figure or channel.
struct Deviation {
  std::string quantity;        // "energy.internal", "th:inter/1:1:FNX"
  std::optional<double> time;  // channels: where the score is largest
  double a = 0, b = 0;         // the two values there
  double allowed = 0, score = 0;
  std::string why;  // a quantity only one run has (its score is +infinity)
  [[nodiscard]] bool past() const { return !(score <= 1.0); }
};

struct RunComparison {
  std::vector<Deviation> deviations;  // one per figure and channel, largest score first
  std::size_t figures = 0, channels = 0, common_times = 0;
  double first_time = 0, last_time = 0;  // the common span
  std::string time_unit;
  std::vector<std::string> notes;  // what was not compared, and why
  [[nodiscard]] std::size_t past() const;
};

// Reads both runs and compares them. False with `error` ("FILE: what is wrong") when a file cannot be read,
// or when the runs cannot be compared (time histories in different time units, one run without a time
// history, time spans that do not overlap).
bool compare_runs(const RunFiles& a, const RunFiles& b, const CompareOptions& options, RunComparison& out,
                  std::string& error);

// The report: what was compared, how many deviations pass the tolerance, the `top` largest (quantity,
// time, A, B, allowed, score), and the notes.
void write_comparison(const RunFiles& a, const RunFiles& b, const CompareOptions& options,
                      const RunComparison& c, std::ostream& os);

}  // namespace radx::io
