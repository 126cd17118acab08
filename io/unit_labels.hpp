// Unit labels for outputs (listing, time history, energy plot): a physical dimension given as
// exponents of mass, length and time, named in the model's work units. In kg, m, s the SI names are used
// (J, N, N/m, ...); otherwise the label is composed from the unit names, e.g. "g.mm2/ms2".
#pragma once

#include <string>

#include "solver/model/model.hpp"

namespace radx::io {

std::string unit_label(const model::Units& u, int mass, int length, int time);

}  // namespace radx::io
