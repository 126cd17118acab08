// Small pieces the executables share: version text, the embedded default deck.
#pragma once

#include <string>

namespace radx::app {

inline constexpr int kExitOk = 0;
inline constexpr int kExitInputError = 1;
inline constexpr int kExitUsage = 2;

// The version and the instruction set the executables were built for (CMake RADX_ARCH, docs/build-arch.md),
// as `--version` and the listings' first line show them: "0.1.0 (x86-64-v2)".
inline constexpr const char* kVersionText = RADX_VERSION " (" RADX_ARCH ")";

// The default deck (decks/block_on_plate), compiled into the executables so a bare `radx-starter`
// runs a real model. Writes it into `dir` (unless an identical file is there) and returns its path.
std::string write_default_starter_deck(const std::string& dir);
std::string write_default_engine_deck(const std::string& dir);

}  // namespace radx::app
