// Text for XML documents (the XDMF index of the results, the JUnit report of `radx regress`).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace radx::io {

// The length of the valid UTF-8 sequence that starts text[k] (1 to 4), or 0 when it is not one (a Latin-1
// byte of an old deck's title, a stray continuation byte, an overlong or surrogate form).
inline std::size_t utf8_sequence_length(std::string_view text, std::size_t k) {
  const auto b = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  const unsigned char c = b(k);
  if (c < 0x80) return 1;
  const std::size_t n = c >= 0xC2 && c <= 0xDF   ? 2
                        : c >= 0xE0 && c <= 0xEF ? 3
                        : c >= 0xF0 && c <= 0xF4 ? 4
                                                 : 0;
  if (n == 0 || k + n > text.size()) return 0;
  for (std::size_t i = 1; i < n; ++i)
    if ((b(k + i) & 0xC0) != 0x80) return 0;
  if ((c == 0xE0 && b(k + 1) < 0xA0) || (c == 0xED && b(k + 1) > 0x9F) || (c == 0xF0 && b(k + 1) < 0x90) ||
      (c == 0xF4 && b(k + 1) > 0x8F))
    return 0;
  return n;
}

// `text` with the five XML special characters as entities, the control characters XML 1.0 cannot hold (all
// but tab, line feed and carriage return) as blanks, and bytes that are not UTF-8 as '?': the documents say
// they are UTF-8, and a deck title or an error message with a stray byte must not make them unreadable.
inline std::string xml_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t k = 0; k < text.size(); ++k) {
    const char c = text[k];
    if (static_cast<unsigned char>(c) >= 0x80) {
      const std::size_t n = utf8_sequence_length(text, k);
      if (n == 0) {
        out += '?';
      } else {
        out.append(text.substr(k, n));
        k += n - 1;
      }
      continue;
    }
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' && c != '\r')
          out += ' ';
        else
          out += c;
    }
  }
  return out;
}

}  // namespace radx::io
