// The starter listing NAME_0000.out: what the starter understood of the deck, in work units: counts,
// materials, properties with the formulation each flag maps to, parts with their masses, every
// interface with its fields as used (defaults marked) and its computed gap and stiffness ranges and
// initial penetrations, the smallest element time steps, and every diagnostic. After errors the figures the
// starter computes from a whole model (masses, gaps, stiffnesses, steps) are said to be not computed rather
// than printed from a model that is not whole.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "solver/model/model.hpp"
#include "solver/model/stable_step.hpp"

namespace radx::io {

struct StarterListingInput {
  std::string deck_path;
  std::string program_version;
  const model::Model* model = nullptr;
  // Per interface (same order as model->interfaces): its echoed fields.
  std::vector<std::vector<std::string>> interface_echo;
  std::vector<std::string> diagnostics;  // formatted, one per line
  std::size_t errors = 0;
  std::size_t warnings = 0;
  double seconds = 0;      // wall time of the starter so far
  std::string model_file;  // written model file, empty when none
  // The smallest element steps at rest (model::estimate_stable_step), smallest first; empty after errors.
  std::vector<model::ElementStep> smallest_steps;
};

void write_starter_listing(std::ostream& os, const StarterListingInput& in);

}  // namespace radx::io
