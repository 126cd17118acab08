// The engine as a function, shared by radx-engine and `radx run`: read the engine deck and the
// starter's model file, run the explicit engine, write the listing NAME_0001.out (and stdout) and
// NAME_summary.json.
#pragma once

#include <iosfwd>
#include <string>

namespace radx::app {

struct EngineOptions {
  std::string engine_deck;  // NAME_0001.rad (or a one-file deck)
  std::string model_file;   // default: NAME_0000.hdf in the output folder
  std::string out_dir = ".";
  int threads = 0;   // 0: OMP_NUM_THREADS or all cores
  bool plot = true;  // draw NAME_energy.png at the end (--no-plot)
};

// 0 normal termination, 1 input error or error termination.
int run_engine(const EngineOptions& opt, std::ostream& out, std::ostream& err);

}  // namespace radx::app
