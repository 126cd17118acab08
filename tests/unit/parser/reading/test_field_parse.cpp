// Numbers as decks write them: plain integers and every Fortran real form.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "parser/reading/field_parse.hpp"

using radx::NumberStatus;

namespace {
double real(const char* s) {
  double v = -12345;
  REQUIRE(radx::parse_real(s, v) == NumberStatus::Ok);
  return v;
}
}  // namespace

TEST_CASE("Fortran real forms parse to the value they denote", "[lexer]") {
  // Exact decimal values: the parse must give the nearest double, so compare with a relative
  // tolerance of a few ulps (parsing exactness, not physics).
  const double eps = 4 * std::numeric_limits<double>::epsilon();
  CHECK(real("1.D3") == Approx(1000.0).epsilon(eps));
  CHECK(real("1d3") == Approx(1000.0).epsilon(eps));
  CHECK(real("1E-3") == Approx(1e-3).epsilon(eps));
  CHECK(real(".5") == Approx(0.5).epsilon(eps));
  CHECK(real("5.") == Approx(5.0).epsilon(eps));
  CHECK(real("1.5d-3") == Approx(1.5e-3).epsilon(eps));
  CHECK(real("210000003000") == Approx(210000003000.0).epsilon(eps));
  CHECK(real("  -2.5E+2  ") == Approx(-250.0).epsilon(eps));
  CHECK(real("+7") == Approx(7.0).epsilon(eps));
  // Fixed-format Fortran accepts an exponent written with its sign only.
  CHECK(real("1.5-3") == Approx(1.5e-3).epsilon(eps));
  CHECK(real("2.+4") == Approx(2e4).epsilon(eps));
  // Far below the smallest double: zero for every purpose of a deck.
  CHECK(real("1e-400") == 0.0);
}

TEST_CASE("malformed and overflowing reals are told apart", "[lexer]") {
  double v = 0;
  CHECK(radx::parse_real("", v) == NumberStatus::Blank);
  CHECK(radx::parse_real("    ", v) == NumberStatus::Blank);
  CHECK(radx::parse_real("1.2.3", v) == NumberStatus::Malformed);
  CHECK(radx::parse_real("abc", v) == NumberStatus::Malformed);
  CHECK(radx::parse_real("1e", v) == NumberStatus::Malformed);
  CHECK(radx::parse_real("12x", v) == NumberStatus::Malformed);
  CHECK(radx::parse_real("1 2", v) == NumberStatus::Malformed);
  CHECK(radx::parse_real("1e400", v) == NumberStatus::Overflow);
  CHECK(radx::parse_real("-1D999", v) == NumberStatus::Overflow);
}

TEST_CASE("integers are plain digits with an optional sign", "[lexer]") {
  std::int64_t v = 0;
  CHECK(radx::parse_int("  42", v) == NumberStatus::Ok);
  CHECK(v == 42);
  CHECK(radx::parse_int("-7", v) == NumberStatus::Ok);
  CHECK(v == -7);
  CHECK(radx::parse_int("+9", v) == NumberStatus::Ok);
  CHECK(v == 9);
  CHECK(radx::parse_int("", v) == NumberStatus::Blank);
  CHECK(radx::parse_int("4a", v) == NumberStatus::Malformed);
  CHECK(radx::parse_int("1.5", v) == NumberStatus::Malformed);
  CHECK(radx::parse_int("99999999999999999999", v) == NumberStatus::Overflow);
}
