// Small pieces the executables share: exit codes, the embedded default deck (the version text is in
// apps/build_info.hpp).
#pragma once

#include <string>

namespace radx::app {

inline constexpr int kExitOk = 0;
inline constexpr int kExitInputError = 1;
inline constexpr int kExitUsage = 2;

// The default deck (decks/block_on_plate), compiled into the executables so a bare `radx-starter`
// runs a real model. Writes it into `dir` (unless an identical file is there) and returns its path.
std::string write_default_starter_deck(const std::string& dir);
std::string write_default_engine_deck(const std::string& dir);

}  // namespace radx::app
