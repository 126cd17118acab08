// Numbers as Radioss decks write them. Integers are plain (optional sign, digits). Reals take every
// Fortran form: 1E-15, 1.D0, 1.5d-3, .005, 5., 210000003000, and the exponent without a letter
// (1.5-3 = 1.5e-3) that fixed-format Fortran accepts.
#pragma once

#include <cstdint>
#include <string_view>

namespace radx {

enum class NumberStatus : std::uint8_t { Ok, Blank, Malformed, Overflow };

std::string_view trim(std::string_view s);
NumberStatus parse_int(std::string_view text, std::int64_t& out);
NumberStatus parse_real(std::string_view text, double& out);

}  // namespace radx
