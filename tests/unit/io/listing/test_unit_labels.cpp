// Unit labels of outputs (io/listing/unit_labels.hpp): a named unit must be worth, in SI, what the work units
// give for its dimension (mass^a length^b time^c of the system's SI factors), to round-off (relative 1e-12);
// other dimensions are spelled from the unit names.
#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <string>

#include "io/listing/unit_labels.hpp"

TEST_CASE("named output units are worth what the work units give", "[units]") {
  const std::map<std::string, double> si = {{"J", 1.0},   {"mJ", 1e-3},  {"N", 1.0},     {"kN", 1e3},
                                            {"N/m", 1.0}, {"N/mm", 1e3}, {"kN/mm", 1e6}, {"Pa", 1.0},
                                            {"MPa", 1e6}, {"GPa", 1e9}};
  struct System {
    const char *m, *l, *t;
    double fm, fl, ft;  // SI value of one work unit
  };
  const System systems[] = {{"kg", "m", "s", 1, 1, 1},
                            {"Mg", "mm", "s", 1e3, 1e-3, 1},
                            {"kg", "mm", "ms", 1, 1e-3, 1e-3},
                            {"g", "mm", "ms", 1e-3, 1e-3, 1e-3}};
  const int dims[4][3] = {{1, 2, -2}, {1, 1, -2}, {1, 0, -2}, {1, -1, -2}};
  for (const auto& s : systems) {
    radx::model::Units u;
    u.mass_name = s.m, u.length_name = s.l, u.time_name = s.t;
    for (const auto& d : dims) {
      const std::string label = radx::io::unit_label(u, d[0], d[1], d[2]);
      INFO(s.m << " " << s.l << " " << s.t << ": " << label);
      REQUIRE(si.count(label) == 1);
      const double factor = std::pow(s.fm, d[0]) * std::pow(s.fl, d[1]) * std::pow(s.ft, d[2]);
      CHECK(si.at(label) == Approx(factor).epsilon(1e-12));
    }
  }
  radx::model::Units u;
  u.mass_name = "Mg", u.length_name = "mm", u.time_name = "s";
  CHECK(radx::io::unit_label(u, 1, 1, -1) == "Mg.mm/s");  // momentum: spelled out
  CHECK(radx::io::unit_label(u, 0, 1, -2) == "mm/s2");
  CHECK(radx::io::unit_label(u, 0, 0, 0) == "1");
}
