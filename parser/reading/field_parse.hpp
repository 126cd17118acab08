// Numbers as Radioss decks write them. Integers are plain (optional sign, digits). Reals take every
// Fortran form: 1E-15, 1.D0, 1.5d-3, .005, 5., 210000003000, and the exponent without a letter
// (1.5-3 = 1.5e-3) that fixed-format Fortran accepts.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace radx {

enum class NumberStatus : std::uint8_t { Ok, Blank, Malformed, Overflow };

std::string_view trim(std::string_view s);
NumberStatus parse_int(std::string_view text, std::int64_t& out);
NumberStatus parse_real(std::string_view text, double& out);

// "/INTER/TYPE7/ 12" -> {"INTER", "TYPE7", "12"}: the fields of a keyword line, upper-cased, blanks
// inside a field dropped, trailing empty fields removed.
std::vector<std::string> keyword_fields(std::string_view line);

// A number for a message: 6 significant digits ("0.0025", "2.1e+11").
std::string number_text(double v);
// A point for a message: "(x, y, z)", each as number_text.
std::string point_text(const std::array<double, 3>& p);

}  // namespace radx
