// The engine as a function, shared by radx-engine and `radx run`: read the engine deck and the
// starter's model file, run the explicit engine, write the listing NAME_0001.out (and stdout) and
// NAME_summary.json.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

namespace radx::solver::parallel {
class Comm;
}

namespace radx::app {

struct EngineOptions {
  std::string engine_deck;  // NAME_0001.rad (or a one-file deck)
  std::string model_file;   // default: NAME_0000.hdf in the output folder
  std::string out_dir = ".";
  int threads = 0;   // 0: OMP_NUM_THREADS or all cores
  bool plot = true;  // draw NAME_energy.png at the end (--no-plot)
  // --stop-if-runaway: a run whose step leaves more cycles to the end time than it can take
  // (apps/runaway_watch.hpp) stops with an error termination instead of going on with a warning.
  bool stop_if_runaway = false;
  // The ranks the run is on: radx-engine gives a SerialComm, radx-engine-mpi an MpiComm
  // (apps/engine_cli.hpp); null is one rank. Rank 0 alone prints and writes files. A run using what the
  // engine does not run on more than one rank yet (solver/parallel/engine_domain.hpp) is refused by name
  // before anything is written.
  solver::parallel::Comm* comm = nullptr;
  // --decompose P (P > 0): do not run; print and write the decomposition over P ranks
  // (apps/engine_decompose.hpp), the group ranks from `partition_file` when given (--partition FILE).
  int decompose_ranks = 0;
  // --partition FILE: with --decompose, the decomposition shown; else the run's group ranks instead of METIS,
  // read into group_ranks by run_engine (on every rank) before anything is written.
  std::string partition_file;
  std::vector<std::int32_t> group_ranks;
};

// 0 normal termination, 1 input error or error termination (also every rank of a run on more than one rank).
int run_engine(const EngineOptions& opt, std::ostream& out, std::ostream& err);

// Removes what an earlier engine run of `root` left in `out_dir` (summary, energy files, time history,
// states and their indexes), so no file beside a new run's outputs is older than the run. The starter calls
// it too: a new model makes the earlier results another model's. Throws naming a file it cannot remove.
void remove_earlier_engine_outputs(const std::string& out_dir, const std::string& root);

// An advisory lock (flock) on OUT_DIR/ROOT.lock for one run of that name in that folder, so two engines (or
// an engine and a starter) of the same name never write into each other's outputs. The kernel releases it
// when the process ends, however it ends. The file holds the holder's pid and is removed when the lock is
// released (a killed process leaves it, unlocked, for the next run to take). Throws std::runtime_error
// naming the other process when the lock is held.
class RunLock {
 public:
  RunLock() = default;
  RunLock(const std::string& out_dir, const std::string& root);
  RunLock(RunLock&& o) noexcept;
  RunLock& operator=(RunLock&& o) noexcept;
  RunLock(const RunLock&) = delete;
  RunLock& operator=(const RunLock&) = delete;
  ~RunLock();

 private:
  void release();
  int fd_ = -1;
  std::string path_;
};

}  // namespace radx::app
