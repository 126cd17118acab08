// The small text forms the parts of `radx regress` share (io/regress/regress_decks.hpp, regress_run.hpp,
// regress_report.hpp and the command, apps/regress_command.cpp): digits, line numbers, seconds and the
// tolerance as printed.
#pragma once

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>
#include <system_error>

namespace radx::io {

inline bool all_digits(std::string_view s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// A line number: digits that fit, else false (a number too long for any deck is no line of it).
inline bool parse_line_number(std::string_view digits, std::int64_t& out) {
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), out);
  return ec == std::errc() && end == digits.data() + digits.size() && all_digits(digits);
}

// The tolerance as the user gave it: "5", "2.5".
inline std::string tolerance_text(double fraction) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", 100.0 * fraction);
  return buf;
}

inline std::string seconds_text(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f s", s);
  return buf;
}

}  // namespace radx::io
