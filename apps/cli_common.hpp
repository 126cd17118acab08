// Small pieces the executables share: exit codes, the embedded default deck (the version text is in
// apps/build_info.hpp).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "parser/reading/closest_names.hpp"

namespace radx::app {

inline constexpr int kExitOk = 0;
inline constexpr int kExitInputError = 1;
inline constexpr int kExitUsage = 2;

// The default deck (decks/block_impact), compiled into the executables so a bare `radx-starter`
// runs a real model. Writes it into `dir` (unless an identical file is there) and returns its path.
std::string write_default_starter_deck(const std::string& dir);
std::string write_default_engine_deck(const std::string& dir);

// The message for an option `who` does not take: "radx run: unknown option --thread (did you mean
// --threads?)".
inline std::string unknown_option(std::string_view who, std::string_view option,
                                  const std::vector<std::string>& known) {
  const std::string hint = did_you_mean(option, known);
  return std::string(who) + ": unknown option " + std::string(option) +
         (hint.empty() ? "" : " (" + hint + ")");
}

}  // namespace radx::app
