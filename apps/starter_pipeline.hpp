// The starter as a function, shared by radx-starter and `radx check`: read the deck, build and check
// the model, prepare the contact interfaces, report, and (unless only checking) write the listing
// NAME_0000.out and the model file NAME_0000.hdf. Apps stay thin: they parse arguments and call this.
#pragma once

#include <iosfwd>
#include <string>

namespace radx::app {

struct StarterOptions {
  std::string deck;                // NAME_0000.rad, or a one-file deck
  std::string out_dir = ".";       // where outputs go (Radioss writes them in the current folder)
  bool write_outputs = true;       // false: `radx check`, nothing is written
  bool check_engine_deck = false;  // also read NAME_0001.rad beside the deck (or the one-file engine part)
  // Run the nearest implemented formulation instead of refusing one radx lacks; each is listed.
  bool allow_substitutions = false;
};

struct StarterResult {
  int exit_code = 0;  // 0 success, 1 input errors
  std::size_t errors = 0;
  std::size_t warnings = 0;
  std::string listing_path;
  std::string model_path;
};

StarterResult run_starter(const StarterOptions& opt, std::ostream& out, std::ostream& err);

}  // namespace radx::app
