// NAME_energy.csv and NAME_energy.png: the energy balance of a run against time, as a table for users and
// scripts and as a chart drawn by Python's matplotlib (Debian python3-matplotlib, run through
// /usr/bin/python3 because only that interpreter sees the Debian modules).
//
// The plotting script is io/listing/plot_energy.py, embedded in the binary at build time (io/CMakeLists.txt),
// so a run needs no source tree. It is started without a shell (paths with spaces and quotes pass unchanged),
// with MPLBACKEND=Agg (no display needed) and its output captured to explain a failure. A missing plotting
// tool is never an error of the run: the functions return false and a warning the caller prints.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace radx::io {

// One row of the energy balance; energies in the model's energy unit, time in its time unit.
struct EnergySample {
  double time;
  double kinetic;
  double internal;
  double hourglass;
  double contact;
  double external_work;
  double total;
};

struct EnergyPlotRequest {
  std::string csv_path;     // NAME_energy.csv (kept for users and scripts)
  std::string png_path;     // NAME_energy.png
  std::string title;        // chart title, any text
  std::string time_unit;    // e.g. "s" or "ms"; empty leaves the unit out of labels
  std::string energy_unit;  // e.g. "J" or "mJ"; empty leaves the unit out of labels
  std::vector<EnergySample> samples;
};

// The interpreter that has the Debian modules (the python3 on PATH may be another one).
inline constexpr const char* kDebianPython = "/usr/bin/python3";

// Writes the samples to r.csv_path (one header line "time [s],kinetic [J],...", then one line per sample
// with 17 significant digits, so every value reads back to the same double), then draws r.png_path with the
// embedded script. Both files are written through a temporary name and renamed when complete, so a previous
// file stays whole until its replacement is. Returns true when both are written; otherwise false with
// `warning` saying what is missing and how to get it (the CSV is still kept when only the chart failed).
// Never throws for a missing tool; blocks until the script ends (at most about two minutes).
bool write_energy_plot(const EnergyPlotRequest& r, std::string& warning);

// The CSV step alone: false with `error` set when the file cannot be written.
bool write_energy_csv(const EnergyPlotRequest& r, std::string& error);

// The chart step alone, from the CSV already at r.csv_path, with the interpreter `python` (an absolute
// path; tests pass a missing one to check the warning). False with `warning` set on failure; the previous
// PNG, if any, is then left untouched and no temporary file remains.
bool draw_energy_png(const EnergyPlotRequest& r, const std::string& python, std::string& warning);

// The text of io/listing/plot_energy.py as compiled into this binary.
std::string_view energy_plot_script();

}  // namespace radx::io
