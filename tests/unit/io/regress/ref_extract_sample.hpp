// The ref.extract the regress tests share: the example of the OpenRadioss format, and copies of it with one
// line changed (tests/unit/io/regress/).
#pragma once

#include <sstream>
#include <string>

namespace radx::test {

// The example of the brief, as OpenRadioss writes it: blanks then tabs.
inline const std::string kExtract =
    "    1 Start                    0\n"
    "    2 CYCLE\t        29\n"
    "    3 TIME\t 2.5380e-02\n"
    "    4 TSTEP\t 8.7470e-04\n"
    "    5 ELEMENT\t0\n"
    "    6 ELTID\t        70\n"
    "    7 ERROR\t  0.2\n"
    "    8 IENERGY\t 8.8150e-02 2.3330e-01\n"
    "    9 KENERGYT\t 1.4560e-01 2.3330e-01\n"
    "   10 KENERGYR\t 7.0160e-18 2.3330e-01\n"
    "   11 EXTWORK\t 2.3330e-01 2.3330e-01\n"
    "   12 MASERR\t0.000\n"
    "   13 Stop                    0\n";

// kExtract with line `n` (1-based) replaced by `line`, or removed when `line` is empty.
inline std::string with_line(int n, const std::string& line) {
  std::istringstream in(kExtract);
  std::string out, l;
  for (int k = 1; std::getline(in, l); ++k) {
    if (k != n)
      out += l + "\n";
    else if (!line.empty())
      out += line + "\n";
  }
  return out;
}

}  // namespace radx::test
