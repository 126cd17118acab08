// A deck's own regression reference NAME.ref (io/regress/regress_reference.hpp): its reader and every error,
// the pass rule |radx - ref| <= max(rel |ref|, floor) and the score, time-history values interpolated between
// rows, --update keeping everything but the values, and the reference a run writes when there is none.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "io/regress/regress_reference.hpp"
#include "io/xml_text.hpp"

using radx::io::RegressReference;

namespace {

RegressReference parse_ok(const std::string& text) {
  RegressReference r;
  std::vector<std::string> errors;
  const bool ok = radx::io::parse_regress_reference(text, "A.ref", r, errors);
  INFO((errors.empty() ? std::string() : errors.front()));
  REQUIRE(ok);
  return r;
}

std::vector<std::string> parse_errors(const std::string& text) {
  RegressReference r;
  std::vector<std::string> errors;
  CHECK_FALSE(radx::io::parse_regress_reference(text, "A.ref", r, errors));
  return errors;
}

// A run with round figures: KE_T 100, IE 50, external work 0, so the total is 150 and so is E_tot0.
radx::io::RunSummary summary() {
  radx::io::RunSummary s;
  s.cycles = 1000;
  s.time = 2e-3;
  s.mass = 1e-4;
  s.initial_mass = 1e-4;
  s.energy.kinetic_t = 100;
  s.energy.internal = 50;
  s.energy.initial_total = 150;
  radx::io::InterfaceSummary a, b;
  a.id = 1;
  a.max_penetration = 0.2;
  a.switched_pairs_max = 3;
  a.switched_pairs_total = 30;
  b.id = 2;
  b.max_penetration = 0.5;
  b.switched_pairs_max = 7;
  b.switched_pairs_total = 5;
  s.interfaces = {a, b};
  return s;
}

// One node group with DZ = 10 t (t in ms) at rows t = 0, 1, 2 ms.
std::vector<radx::io::ThGroupData> history() {
  radx::io::ThGroupData g;
  g.layout.path = "node/1";
  g.layout.object_kind = "node";
  g.layout.objects = {61};
  g.layout.variables = {"DZ"};
  g.layout.units = {"mm"};
  g.time_unit = "s";
  g.columns = 2;
  g.rows = {0.0, 0.0, 1e-3, 10.0, 2e-3, 20.0};
  return {g};
}

}  // namespace

TEST_CASE("NAME.ref: quantities, values and tolerances, comments and blank lines skipped", "[regress]") {
  const auto r = parse_ok(
      "# a comment\n"
      "\n"
      "cycles  1000  0.01  2   # why\n"
      "energy.internal  -  0.02 0.5\n"
      "th:node/1:61:DZ@1.5e-3  15  0 0.01\n");
  REQUIRE(r.quantities.size() == 3);
  CHECK(r.quantities[0].name == "cycles");
  CHECK(*r.quantities[0].value == 1000);
  CHECK(r.quantities[0].rel_tol == 0.01);
  CHECK(r.quantities[0].abs_floor == 2);
  CHECK(r.quantities[0].line == 3);
  CHECK_FALSE(r.quantities[1].value);  // '-': not recorded yet
  CHECK(r.quantities[2].line == 5);
}

TEST_CASE("NAME.ref: every problem is reported with its line, together", "[regress]") {
  const auto e = parse_errors(
      "cycles 1000 0.01\n"     // too few fields
      "energy.intern 1 0 0\n"  // unknown quantity
      "time x 0 0\n"           // not a number
      "mass 1 -0.1 0\n"        // negative tolerance
      "dt 1 0 0\n"
      "dt 1 0 0\n"                 // twice
      "th:node/1:61:DZ 1 0 0\n");  // no time
  REQUIRE(e.size() == 6);
  CHECK(e[0].rfind("A.ref:1: cycles: 3 field(s)", 0) == 0);
  CHECK(e[1].rfind("A.ref:2: energy.intern: unknown quantity; accepted: th:COLUMN@TIME or one of cycles",
                   0) == 0);
  CHECK(e[2].rfind("A.ref:3: time: value 'x' is not a number", 0) == 0);
  CHECK(e[3].rfind("A.ref:4: mass: REL_TOL '-0.1' is not a number >= 0", 0) == 0);
  CHECK(e[4] == "A.ref:6: dt: given twice; give each quantity once");
  CHECK(e[5].rfind("A.ref:7: th:node/1:61:DZ: a time-history quantity is th:COLUMN@TIME", 0) == 0);
}

TEST_CASE("NAME.ref: the pass rule is |radx - ref| <= max(rel |ref|, floor), scored against it",
          "[regress]") {
  const auto s = summary();
  const auto th = history();
  // internal 50: 52 with 2 % (1.0) is 2 over an allowance of 1 -> score 2; the floor 4 allows it (0.5).
  const auto r = parse_ok(
      "energy.internal 52 0.02 0\n"
      "energy.kinetic_translational 98 0.02 4\n"
      "max_penetration 0.5 0 0\n"
      "switched_pairs_max 7 0 0\n"
      "switched_pairs_total 35 0 0\n"
      "energy.total 150 0 0\n"
      "energy.error_percent 0 0 0.5\n"
      "th:node/1:61:DZ@1.5e-3 15 0 1e-9\n"
      "th:node/1:61:DZ@3e-3 30 0 1\n"
      "th:node/1:61:DX@1e-3 0 0 1\n"
      "cycles - 0.01 0\n");
  const auto c = radx::io::check_reference(r, s, &th);
  REQUIRE(c.size() == 11);
  CHECK(c[0].allowed == Approx(1.04));  // 2 % of the reference 52
  CHECK(c[0].score == Approx(2.0 / 1.04));
  CHECK_FALSE(c[0].passed());
  CHECK(c[1].allowed == 4);
  CHECK(c[1].score == Approx(0.5));
  CHECK(c[1].passed());
  CHECK(*c[2].radx == 0.5);  // the largest over the interfaces
  CHECK(c[2].score == 0);
  CHECK(*c[3].radx == 7);
  CHECK(*c[4].radx == 35);  // summed over the interfaces
  CHECK(c[5].passed());
  CHECK(c[6].passed());
  CHECK(*c[7].radx == Approx(15.0).epsilon(1e-12));  // halfway between the rows at 1 and 2 ms
  CHECK(c[7].passed());
  CHECK_FALSE(c[8].radx);  // after the last row
  CHECK(c[8].why.find("outside the time history's rows") != std::string::npos);
  CHECK(std::isinf(c[8].score));
  CHECK_FALSE(c[9].radx);
  CHECK(c[9].why.find("no column node/1:61:DX") != std::string::npos);
  CHECK_FALSE(c[10].reference);  // not recorded: fails until --update
  CHECK_FALSE(c[10].passed());
  // A run without interfaces or a time history has no value for those.
  radx::io::RunSummary bare = s;
  bare.interfaces.clear();
  std::string why;
  CHECK_FALSE(radx::io::run_quantity("max_penetration", bare, nullptr, why));
  CHECK(why == "the run has no contact interface");
  CHECK_FALSE(radx::io::run_quantity("th:node/1:61:DZ@1e-3", bare, nullptr, why));
}

TEST_CASE("NAME.ref: --update rewrites the values and keeps every other character", "[regress]") {
  const std::string text =
      "# header\n"
      "cycles          1000    0.01  2   # the step rule\n"
      "energy.internal -       0.02  0.5 # mJ\n"
      "\n"
      "th:node/1:61:DZ@1e-3 9.5 0 0.1\n";
  const auto r = parse_ok(text);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK(radx::io::updated_reference_text(r, {1012, 49.87654321, nan}) ==
        "# header\n"
        "cycles          1012    0.01  2   # the step rule\n"
        "energy.internal 49.87654321 0.02  0.5 # mJ\n"
        "\n"
        "th:node/1:61:DZ@1e-3 9.5 0 0.1\n");
}

TEST_CASE("NAME.ref: a new reference holds the run's values and reads back as passing", "[regress]") {
  const auto s = summary();
  const std::string text = radx::io::new_reference_text("A_0000.rad", s);
  const auto r = parse_ok(text);
  std::vector<std::string> names;
  for (const auto& q : r.quantities) names.push_back(q.name);
  CHECK(names == std::vector<std::string>{"cycles", "time", "mass", "energy.kinetic_translational",
                                          "energy.internal", "energy.error_percent", "max_penetration",
                                          "switched_pairs_max"});
  for (const auto& c : radx::io::check_reference(r, s, nullptr)) {
    INFO(c.name);
    CHECK(c.passed());
    CHECK(c.score <= 1e-9);  // written with 10 digits: the run's own values
  }
  // An energy is allowed 2 % of its value or 0.5 % of the run's energy scale (150 here: 0.75), whichever is
  // larger: 1.0 for the internal energy of 50. 0.9 passes, 1.2 does not.
  radx::io::RunSummary drift = s;
  drift.energy.internal = 50.9;
  drift.energy.initial_total = 150.9;  // the balance unchanged
  CHECK(radx::io::check_reference(r, drift, nullptr)[4].passed());
  drift.energy.internal = 51.2;
  drift.energy.initial_total = 151.2;
  CHECK_FALSE(radx::io::check_reference(r, drift, nullptr)[4].passed());
}

TEST_CASE("NAME.ref: a reference with no quantity is an error, not a pass", "[regress]") {
  const auto e = parse_errors("# only comments\n\n");
  REQUIRE(e.size() == 1);
  CHECK(e[0].rfind("A.ref: holds no quantity, so it would pass whatever the run gives", 0) == 0);
  // Numbers beyond a double, and NaN, are not numbers a reference can hold.
  const auto big = parse_errors("time 1e400 0 0\ndt nan 0 0\n");
  CHECK(big.size() == 2);
}

TEST_CASE("NAME.ref: a run value that is not finite cannot be recorded", "[regress]") {
  auto s = summary();
  s.dt = std::numeric_limits<double>::quiet_NaN();
  std::string why;
  CHECK_FALSE(radx::io::run_quantity("dt", s, nullptr, why));
  CHECK(why == "the run's value is not a finite number");
}

TEST_CASE("XML text: special characters, control characters and bytes that are not UTF-8", "[regress]") {
  using radx::io::xml_escape;
  CHECK(xml_escape("a<b & \"c\" 'd'>") == "a&lt;b &amp; &quot;c&quot; &apos;d&apos;&gt;");
  CHECK(xml_escape("tab\there\x01") == "tab\there ");
  CHECK(xml_escape("caf\xC3\xA9") == "caf\xC3\xA9");            // UTF-8 kept
  CHECK(xml_escape("caf\xE9 x") == "caf? x");                   // Latin-1 byte
  CHECK(xml_escape("\xE2\x82") == "??");                        // a sequence cut short
  CHECK(xml_escape("\xED\xA0\x80") == "???");                   // a surrogate
  CHECK(xml_escape("\xF0\x9F\x98\x80") == "\xF0\x9F\x98\x80");  // four bytes
}
