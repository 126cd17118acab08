// Text for XML documents (the XDMF index of the results, the JUnit report of `radx regress`).
#pragma once

#include <string>
#include <string_view>

namespace radx::io {

// `text` with the five XML special characters as entities, and the control characters XML 1.0 cannot hold
// (all but tab, line feed and carriage return) as blanks: a deck title or an error message with a stray
// control character must not make the whole document unreadable.
inline std::string xml_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
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
