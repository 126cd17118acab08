// What an engine run writes besides its listing and summary: the animation states for ParaView
// (P.mesh.hdf, P_%06d.hdf, P.hdf.series, P.xmf), the time history P_th.h5, and the energy balance
// P_energy.csv + P_energy.png. It decides when each is due:
//   states: the first cycle, every /ANIM/DT interval from Tstart to Tstop (at the first cycle whose time
//     reaches the due time), and the last cycle of the run, also when the run stops on an error;
//   time-history rows: the first cycle, every /TFILE interval, and the last cycle (when the deck has
//     /TFILE or any /TH group); interface and section forces in them are means over the interval since the
//     previous row, summed from every cycle;
//   energy samples: every full report (the /PRINT cycles and every output cycle).
#pragma once

#include <cstdint>
#include <memory>
#include <ostream>
#include <string>

#include "solver/engine/explicit_engine.hpp"
#include "solver/model/model.hpp"
#include "solver/model/run_controls.hpp"

namespace radx::app {

// Removes what an earlier run of prefix `root` left in `out_dir` besides its states and listing (which
// EngineOutputs and the listing replace): the summary, the energy CSV and chart, the time history and their
// stray .part files. A run calls it before it writes anything, so no file beside its outputs is older than
// the run. Throws std::runtime_error naming a file it cannot remove.
void remove_earlier_outputs(const std::string& out_dir, const std::string& root);

class EngineOutputs {
 public:
  // Removes what an earlier run of the same name left (states, indexes, stray .part files) and writes
  // the mesh file. Throws std::runtime_error naming the file on an I/O failure.
  EngineOutputs(const model::Model& m, const model::RunControls& c, const solver::ExplicitEngine& engine,
                const std::string& out_dir, const std::string& root);
  ~EngineOutputs();
  EngineOutputs(const EngineOutputs&) = delete;
  EngineOutputs& operator=(const EngineOutputs&) = delete;

  // True when a state or a time-history row is due at `time` (the engine then makes a full report).
  [[nodiscard]] bool due(double time) const;
  // Whether a state (animation) is due at `time`: the engine gathers whole states on more than one rank.
  [[nodiscard]] bool state_due(double time) const;
  // Called with every cycle's report, before on_report: the time-history groups that write interval means
  // (interfaces, sections: solver/outputs/time_history_values.hpp) add the cycle to their integrals.
  void accumulate(const solver::CycleReport& r);
  // Called with every full report: writes what is due.
  void on_report(const solver::CycleReport& r);
  // At the end of the run (normal or error): the last state and time-history row if not yet written,
  // the final time-history flush, the energy CSV and the energy plot (a missing plotting tool is a warning
  // on `warn`). Throws std::runtime_error naming the file that cannot be written.
  void finish(const solver::RunResult& result, bool plot, std::ostream& warn);

  [[nodiscard]] int states_written() const;
  // Wall time spent writing states and time-history rows during the run (not the mesh file written
  // before it, nor the last state and plot written after it).
  [[nodiscard]] double seconds_writing() const;
  [[nodiscard]] std::string series_path() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace radx::app
