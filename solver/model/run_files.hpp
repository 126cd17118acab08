// The names of a run's files: a deck is a starter deck NAME_0000.rad with its engine deck NAME_0001.rad
// beside it, or a one-file deck NAME.rad holding both; the starter's outputs take the root NAME_0000, the
// engine's NAME. The parser (the /RUN name check), the executables and `radx regress` (io/regress/) all name
// files this way, and the model library is the one all of them see.
#pragma once

#include <string>
#include <vector>

namespace radx::model {

// The stem of `path` and, when it ends with _NNNN, the stem without it and the number (else -1).
std::string split_run_suffix(const std::string& path, int& number);

// The root name of a run's outputs from the engine deck path: NAME_0001.rad -> NAME (any _NNNN suffix of
// four digits is removed, so the one-file NAME_0000.rad also gives NAME); a one-file NAME.rad -> NAME.
std::string run_output_root(const std::string& engine_deck_path);

// Output root of a deck: NAME_0000.rad -> NAME_0000; NAME.rad (one-file) -> NAME_0000.
std::string starter_output_root(const std::string& deck);

// The later engine decks of the run of `engine_deck` (NAME_0001.rad): NAME_0002.rad, NAME_0003.rad, ...
// beside it, by name. OpenRadioss runs them one after another as restarts; radx does not. Empty for a deck
// not numbered _0001.
std::vector<std::string> later_engine_decks(const std::string& engine_deck);

// True when the file has a line starting with /END/ENGINE (a one-file deck).
bool is_one_file_deck(const std::string& path);

}  // namespace radx::model
