#include "parser/reading/field_parse.hpp"

#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <sstream>

namespace radx {

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r");
  return s.substr(first, last - first + 1);
}

NumberStatus parse_int(std::string_view text, std::int64_t& out) {
  text = trim(text);
  out = 0;
  if (text.empty()) return NumberStatus::Blank;
  if (text.front() == '+') text.remove_prefix(1);
  if (text.empty()) return NumberStatus::Malformed;
  const auto* end = text.data() + text.size();
  const auto res = std::from_chars(text.data(), end, out);
  if (res.ec == std::errc::result_out_of_range) return NumberStatus::Overflow;
  if (res.ec != std::errc() || res.ptr != end) return NumberStatus::Malformed;
  return NumberStatus::Ok;
}

NumberStatus parse_real(std::string_view text, double& out) {
  text = trim(text);
  out = 0.0;
  if (text.empty()) return NumberStatus::Blank;
  // Normalise into a C-style number: sign, mantissa, optional 'e' exponent.
  std::array<char, 64> buf{};
  std::size_t n = 0;
  std::size_t i = 0;
  auto put = [&](char c) {
    if (n >= buf.size()) return false;
    buf[n++] = c;
    return true;
  };
  if (text[i] == '+' || text[i] == '-') {
    if (text[i] == '-') put('-');
    ++i;
  }
  bool digits = false;
  bool dot = false;
  for (; i < text.size(); ++i) {
    const char c = text[i];
    if (c >= '0' && c <= '9') {
      digits = true;
      if (!put(c)) return NumberStatus::Malformed;
    } else if (c == '.' && !dot) {
      dot = true;
      if (!put(c)) return NumberStatus::Malformed;
    } else {
      break;
    }
  }
  if (!digits) return NumberStatus::Malformed;
  if (i < text.size()) {
    char c = text[i];
    if (c == 'e' || c == 'E' || c == 'd' || c == 'D') {
      ++i;
      if (i >= text.size()) return NumberStatus::Malformed;
      c = text[i];
    } else if (c != '+' && c != '-') {
      return NumberStatus::Malformed;
    }
    put('e');
    if (c == '+' || c == '-') {
      if (c == '-') put('-');
      ++i;
    }
    bool exp_digits = false;
    for (; i < text.size(); ++i) {
      const char e = text[i];
      if (e < '0' || e > '9') return NumberStatus::Malformed;
      exp_digits = true;
      if (!put(e)) return NumberStatus::Malformed;
    }
    if (!exp_digits) return NumberStatus::Malformed;
  }
  const auto res = std::from_chars(buf.data(), buf.data() + n, out);
  if (res.ec == std::errc::result_out_of_range) {
    // Too small to represent is zero for every purpose of a deck; too large is an error.
    std::string_view s(buf.data(), n);
    const auto epos = s.find('e');
    if (epos != std::string_view::npos && epos + 1 < s.size() && s[epos + 1] == '-') {
      out = 0.0;
      return NumberStatus::Ok;
    }
    return NumberStatus::Overflow;
  }
  if (res.ec != std::errc() || res.ptr != buf.data() + n) return NumberStatus::Malformed;
  if (!std::isfinite(out)) return NumberStatus::Overflow;
  return NumberStatus::Ok;
}

std::vector<std::string> keyword_fields(std::string_view line) {
  std::vector<std::string> tokens;
  std::string cur;
  for (std::size_t i = 1; i < line.size(); ++i) {
    const char c = line[i];
    if (c == '/') {
      tokens.push_back(cur);
      cur.clear();
    } else if (c != ' ' && c != '\t') {
      cur += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    }
  }
  tokens.push_back(cur);
  while (!tokens.empty() && tokens.back().empty()) tokens.pop_back();
  return tokens;
}

std::string number_text(double v) {
  std::ostringstream os;
  os.precision(6);
  os << v;
  return os.str();
}

std::string point_text(const std::array<double, 3>& p) {
  return "(" + number_text(p[0]) + ", " + number_text(p[1]) + ", " + number_text(p[2]) + ")";
}

}  // namespace radx
