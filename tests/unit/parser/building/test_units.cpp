// Unit conversion from the deck's input units to its work units, including fields whose dimension
// depends on another field (docs/theory/type7-lagdt.md: Stfac is a stiffness when Istf = 1). Expected factors
// are computed here from the SI values of the units: g = 1e-3 kg, mm = 1e-3 m, ms = 1e-3 s.
#include <catch2/catch.hpp>

#include "parser/reading/deck.hpp"
#include "test_util.hpp"

using radx::test::Line;

namespace {

std::string type7(int id, int istf, double stfac) {
  return "/INTER/TYPE7/" + std::to_string(id) + "\ncontact\n" +
         Line().put(1, 1, 10).put(1, 11, 20).put(istf, 21, 30).str() + "\n\n\n" +
         Line().put(stfac, 1, 20).put(0.5, 41, 60).str() + "\n";
}

}  // namespace

TEST_CASE("input units g mm ms convert to work units kg m s, with dimension overrides", "[units]") {
  radx::test::TempDir dir;
  std::string s = "/BEGIN\nU\n" + Line().put(2026, 1, 10).str() + "\n" +
                  Line().put("g", 1, 20).put("mm", 21, 40).put("ms", 41, 60).str() + "\n" +
                  Line().put("kg", 1, 20).put("m", 21, 40).put("s", 41, 60).str() + "\n";
  s += "/MAT/LAW1/1\nsteel\n" + Line().put(7.8e-3, 1, 20).str() + "\n" +
       Line().put(210.0, 1, 20).put(0.3, 21, 40).str() + "\n";
  s += type7(1, 1, 5.0) + type7(2, 0, 2.0);
  s += "/END\n";
  const auto path = dir.write("u_0000.rad", s);
  radx::Diagnostics diags;
  const auto deck = radx::read_starter_deck(path, diags);
  for (const auto& d : diags.items()) INFO(radx::Diagnostics::format(d));
  REQUIRE_FALSE(diags.has_errors());
  const double g = 1e-3, mm = 1e-3, ms = 1e-3;
  // Conversion is one multiplication by a product of powers: a few ulps.
  const double eps = 1e-14;
  const auto mat = deck.of("/MAT/LAW1")[0];
  CHECK(mat->get_real("RHO_I") == Approx(7.8e-3 * g / (mm * mm * mm)).epsilon(eps));  // M L^-3
  CHECK(mat->get_real("E") == Approx(210.0 * g / (mm * ms * ms)).epsilon(eps));       // M L^-1 T^-2
  CHECK(mat->get_real("nu") == 0.3);                                                  // no unit
  const auto inters = deck.of("/INTER/TYPE7");
  REQUIRE(inters.size() == 2);
  CHECK(inters[0]->get_real("Stfac") == Approx(5.0 * g / (ms * ms)).epsilon(eps));  // Istf 1: M T^-2
  CHECK(inters[1]->get_real("Stfac") == 2.0);                                       // Istf 0: a factor
  CHECK(inters[0]->get_real("Gapmin") == Approx(0.5 * mm).epsilon(eps));            // L
}

TEST_CASE("an object in its own /UNIT system converts with that system's factors", "[units]") {
  radx::test::TempDir dir;
  std::string s = radx::test::begin_block(2026, "kg m s");
  s += "/UNIT/7\nmillimetre system\n" + Line().put("Mg", 1, 20).put("mm", 21, 40).put("s", 41, 60).str() +
       "\n";
  s += "/NODE/7\n" + Line().put(1, 1, 10).put(250.0, 11, 30).str() + "\n";
  s += "/MAT/LAW1/1/7\nsteel\n" + Line().put(7.85e-9, 1, 20).str() + "\n" +
       Line().put(210000.0, 1, 20).str() + "\n";
  s += "/END\n";
  const auto path = dir.write("u7_0000.rad", s);
  radx::Diagnostics diags;
  const auto deck = radx::read_starter_deck(path, diags);
  for (const auto& d : diags.items()) INFO(radx::Diagnostics::format(d));
  REQUIRE_FALSE(diags.has_errors());
  const auto& t = deck.of("/NODE")[0]->records;
  CHECK(t.reals[t.column("X")][0] == Approx(0.25).epsilon(1e-14));
  const auto mat = deck.of("/MAT/LAW1")[0];
  CHECK(mat->get_real("RHO_I") == Approx(7850.0).epsilon(1e-14));
  CHECK(mat->get_real("E") == Approx(2.1e11).epsilon(1e-14));
}

TEST_CASE("a unit id with no /UNIT and an unknown unit name are errors", "[units]") {
  radx::test::TempDir dir;
  std::string s = radx::test::begin_block(2026, "kg furlong s");
  s += "/NODE/3\n" + Line().put(1, 1, 10).str() + "\n/END\n";
  const auto path = dir.write("ubad_0000.rad", s);
  radx::Diagnostics diags;
  radx::read_starter_deck(path, diags);
  CHECK(diags.contains(radx::Diag::BadUnit));
  CHECK(diags.contains(radx::Diag::MissingReference));
}
