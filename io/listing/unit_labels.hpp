// Unit labels for outputs (listing, time history, energy plot): a physical dimension given as exponents of
// mass, length and time, named in the model's work units. Energy, force, force per length and stress get
// their usual names in the common consistent systems (kg m s: J N N/m Pa; Mg mm s: mJ N N/mm MPa; kg mm ms:
// J kN kN/mm GPa; g mm ms: mJ N N/mm MPa); anything else is composed from the unit names, e.g. "Mg.mm/s".
#pragma once

#include <string>

#include "solver/model/model.hpp"

namespace radx::io {

std::string unit_label(const model::Units& u, int mass, int length, int time);

}  // namespace radx::io
