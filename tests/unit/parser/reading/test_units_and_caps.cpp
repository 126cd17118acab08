// Unit names with any SI prefix, as Radioss reads them, and the cap on one cause repeated in the printed
// diagnostics.
#include <catch2/catch.hpp>
#include <sstream>

#include "parser/reading/deck.hpp"
#include "parser/reading/diagnostics.hpp"

using radx::Diag;

TEST_CASE("unit names are an SI prefix before g, m or s, as Radioss reads them", "[lexer]") {
  using radx::unit_factor;
  CHECK(unit_factor("Tg", 'M') == Approx(1e9));
  CHECK(unit_factor("kg", 'M') == Approx(1.0));
  CHECK(unit_factor("Mg", 'M') == Approx(1e3));
  CHECK(unit_factor("mg", 'M') == Approx(1e-6));
  CHECK(unit_factor("hg", 'M') == Approx(0.1));
  CHECK(unit_factor("dam", 'L') == Approx(10.0));
  CHECK(unit_factor("nm", 'L') == Approx(1e-9));
  CHECK(unit_factor("mum", 'L') == Approx(1e-6));
  CHECK(unit_factor("\xc2\xb5m", 'L') == Approx(1e-6));
  CHECK(unit_factor("ps", 'T') == Approx(1e-12));
  CHECK(unit_factor("Gs", 'T') == Approx(1e9));
  // radx's own names stay: the hour, the minute, the tonne, the pound, the inch and the foot.
  CHECK(unit_factor("h", 'T') == Approx(3600.0));
  CHECK(unit_factor("min", 'T') == Approx(60.0));
  CHECK(unit_factor("t", 'M') == Approx(1e3));
  CHECK(unit_factor("in", 'L') == Approx(0.0254));
  // The base unit must be the kind's: a gram is no length, a prefix alone no unit.
  CHECK_FALSE(unit_factor("Tm", 'M'));
  CHECK_FALSE(unit_factor("kg", 'L'));
  CHECK_FALSE(unit_factor("k", 'L'));
  CHECK_FALSE(unit_factor("xm", 'L'));
  CHECK_FALSE(unit_factor("furlong", 'L'));
}

TEST_CASE("one cause repeated is shown a few times, then counted in one closing line", "[lexer]") {
  radx::Diagnostics d;
  for (int k = 1; k <= 12; ++k)
    d.error(
        Diag::ElementNodeMissing, radx::Where{"a.rad", k, 11}, radx::About{"/SHELL", 1},
        "shell " + std::to_string(k) + " uses node " + std::to_string(900 + k) + ", which does not exist");
  d.error(Diag::MissingReference, radx::Where{"a.rad", 20, 1}, radx::About{"/BCS", 1}, "group 9 is missing");
  REQUIRE(d.error_count() == 13);
  const auto lines = d.lines();
  REQUIRE(lines.size() == radx::Diagnostics::kRepeatsShown + 2);
  CHECK(lines[radx::Diagnostics::kRepeatsShown].find("RX402") != std::string::npos);
  const std::string& last = lines.back();
  CHECK(last.find("RX406") != std::string::npos);
  CHECK(last.find("and 7 more of the same") != std::string::npos);
  CHECK(last.find("12 in all") != std::string::npos);
  std::ostringstream os;
  d.print(os);
  CHECK(os.str().find("and 7 more of the same") != std::string::npos);
}

TEST_CASE("the same message about different objects is not one cause", "[lexer]") {
  radx::Diagnostics d;
  for (int k = 1; k <= 8; ++k)
    d.warning(Diag::InitialPenetration, radx::Where{"a.rad", 10 * k, 1}, radx::About{"/INTER/TYPE7", k},
              "4 secondary node(s) start inside the gap");
  CHECK(d.lines().size() == 8);
}
