// Plausibility warnings: decks that are valid but whose physics or run is absurd (a wave speed no material
// has, a tangled brick, a step below 1e-12 s, an end time beyond 1e9 cycles, an energy error past 10 % and
// 50 %) run on, but say so, located, with what is typical.
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "apps/starter_pipeline.hpp"
#include "io/listing/engine_listing.hpp"
#include "parser/building/build_run_controls.hpp"
#include "parser/building/plausibility.hpp"
#include "parser/reading/diagnostics.hpp"
#include "solver/model/geometry.hpp"
#include "solver/model/stable_step.hpp"
#include "test_util.hpp"

using radx::test::Line;

namespace {

// One cube of side a (mm, or the deck's length unit), nodes 1-4 on z = 0 and 5-8 on z = a, node 5 moved
// to `n5` (in units of a), LAW1 with rho, E and nu = 0 (the solid and bar wave speeds are then both
// sqrt(E/rho)). No /END.
std::string cube_deck(double a, double rho, double E, const char* units = "Mg mm s",
                      std::array<double, 3> n5 = {0, 0, 1}) {
  std::string s = radx::test::begin_block(2026, units) + "/NODE\n";
  for (int k = 0; k < 8; ++k) {
    double x = (k == 1 || k == 2 || k == 5 || k == 6) ? a : 0.0;
    double y = (k == 2 || k == 3 || k == 6 || k == 7) ? a : 0.0;
    double z = k >= 4 ? a : 0.0;
    if (k == 4) x = n5[0] * a, y = n5[1] * a, z = n5[2] * a;
    s += Line().put(k + 1, 1, 10).put(x, 11, 30).put(y, 31, 50).put(z, 51, 70).str() + "\n";
  }
  Line b;
  b.put(1, 1, 10);
  for (int k = 0; k < 8; ++k) b.put(k + 1, 11 + 10 * k, 20 + 10 * k);
  s += "/BRICK/1\n" + b.str() + "\n/PART/1\ncube\n" + Line().put(1, 1, 10).put(1, 11, 20).str() + "\n";
  s += "/PROP/SOLID/1\nsolid\n" + Line().put(0, 1, 10).str() + "\n\n/MAT/LAW1/1\nmat\n" +
       Line().put(rho, 1, 20).str() + "\n" + Line().put(E, 1, 20).put(0.0, 21, 40).str() + "\n";
  return s;
}

struct StarterRun {
  int exit_code = -1;
  std::string err;
  std::size_t warnings = 0;
};

// The starter on NAME_0000.rad (and NAME_0001.rad beside it when `engine` is not empty), nothing written.
StarterRun starter(const radx::test::TempDir& dir, const std::string& deck, const std::string& engine = {},
                   bool check_engine_deck = false) {
  radx::app::StarterOptions opt;
  opt.deck = dir.write("CUBE_0000.rad", deck);
  if (!engine.empty()) dir.write("CUBE_0001.rad", engine);
  opt.write_outputs = false;
  opt.check_engine_deck = check_engine_deck;
  std::ostringstream out, err;
  const auto r = radx::app::run_starter(opt, out, err);
  return {r.exit_code, err.str(), r.warnings};
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

TEST_CASE("a node pushed through the opposite face leaves a positive volume but a negative corner",
          "[plausibility]") {
  using radx::model::Vec3;
  std::array<Vec3, 8> x{
      {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}};
  const auto valid = radx::model::most_negative_brick_corner(x);
  CHECK(valid.node == -1);
  x[4] = {0.5, 0.5, -0.2};  // n5 below the n1-n4 face
  // The one-point volume still says 0.45 of the cube: the volume check cannot see it.
  REQUIRE(radx::model::brick_volume(x) == Approx(0.45));
  const auto tangled = radx::model::most_negative_brick_corner(x);
  CHECK(tangled.node == 4);
  // Corner n5: edges to n8, n6, n1 are (-.5,.5,1.2), (.5,-.5,1.2), (-.5,-.5,.2); det -1.2 over the lengths.
  CHECK(tangled.ratio == Approx(-1.2 / (1.94 * std::sqrt(0.54))));
  // A brick with a repeated node (a wedge) is degenerate, not tangled.
  std::array<Vec3, 8> wedge{
      {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {1, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {1, 1, 1}}};
  CHECK(radx::model::most_negative_brick_corner(wedge).node == -1);
}

TEST_CASE("the starter warns RX607 at a tangled brick's card and builds the model", "[plausibility]") {
  radx::test::TempDir dir;
  const auto r = starter(dir, cube_deck(10.0, 7.85e-9, 210000.0, "Mg mm s", {0.5, 0.5, -0.2}) + "/END\n");
  INFO(r.err);
  CHECK(r.exit_code == 0);
  CHECK(
      r.err.find("CUBE_0000.rad:16:1: warning: RX607: [/BRICK id 1] brick 1 is tangled: its corner at node 5 "
                 "(n5) is turned inside out") != std::string::npos);
  const auto plain = starter(dir, cube_deck(10.0, 7.85e-9, 210000.0) + "/END\n");
  CHECK(plain.err.find("RX607") == std::string::npos);
  CHECK(plain.warnings == 0);
}

TEST_CASE("the wave speed sqrt(E/rho) is checked in m/s with the deck's units", "[plausibility]") {
  radx::test::TempDir dir;
  // sqrt(E/rho) = 500 length units per time unit: 500 m/s in a kg m s deck (a rubber), 0.5 m/s in a
  // Mg mm s deck (nothing solid is that slow).
  const auto m_deck = starter(dir, cube_deck(0.01, 1.0, 250000.0, "kg m s") + "/END\n");
  CHECK(m_deck.err.find("RX512") == std::string::npos);
  const auto mm_deck = starter(dir, cube_deck(10.0, 1.0, 250000.0, "Mg mm s") + "/END\n");
  INFO(mm_deck.err);
  CHECK(mm_deck.exit_code == 0);
  CHECK(mm_deck.err.find("warning: RX512: [/MAT/LAW1 id 1 \"mat\"] the wave speed sqrt(E/RHO_I) = 0.5 m/s") !=
        std::string::npos);
  CHECK(mm_deck.err.find("below 1 m/s") != std::string::npos);
  // sqrt(E/rho) = 1e9 length units per time unit: 1e6 m/s in mm (no warning, fast but not absurd),
  // 1e9 m/s in m, above the speed of light.
  const auto fast_mm = starter(dir, cube_deck(10.0, 1.0, 1e18, "Mg mm s") + "/END\n");
  CHECK(fast_mm.err.find("RX512") == std::string::npos);
  const auto fast_m = starter(dir, cube_deck(0.01, 1.0, 1e18, "kg m s") + "/END\n");
  CHECK(fast_m.err.find("the wave speed sqrt(E/RHO_I) = 1e+09 m/s") != std::string::npos);
  CHECK(fast_m.err.find("above the speed of light") != std::string::npos);
}

TEST_CASE("a density of 1e-30 warns of the material and of the step it gives", "[plausibility]") {
  radx::test::TempDir dir;
  // Steel's E in Mg mm s with rho = 1e-30: c = sqrt(210000 / 1e-30) = 4.58e17 mm/s = 4.58e14 m/s, above
  // light; the step of the 10 mm cube is 10 / 4.58e17 = 2.18e-17 s (nu = 0: the solid speed is the same),
  // 2.08e-17 s with the default bulk viscosity qb = 0.05 (times sqrt(1 + qb^2) - qb = 0.951).
  const auto r = starter(dir, cube_deck(10.0, 1e-30, 210000.0) + "/END\n");
  INFO(r.err);
  CHECK(r.exit_code == 0);
  CHECK(r.err.find(
            "warning: RX512: [/MAT/LAW1 id 1 \"mat\"] the wave speed sqrt(E/RHO_I) = 4.58258e+14 m/s (E = "
            "210000, RHO_I = 1e-30 in the deck's work units Mg mm s) is above the speed of light") !=
        std::string::npos);
  CHECK(r.err.find("warning: RX513: [/BRICK id 1] the initial stable time step is about 2.08e-17 s") !=
        std::string::npos);
}

TEST_CASE("a deck that names no units is judged by the most plausible usual system", "[plausibility]") {
  radx::test::TempDir dir;
  // Aluminium in g cm us (E = 0.7173 Mbar, rho = 2.7 g/cm3): c = 0.515 cm/us = 5150 m/s. Read as SI it
  // would be 0.5 m/s; with no units named it is plausible in cm/us, so no warning.
  const auto al = starter(dir, cube_deck(1.0, 2.7, 0.7173, "") + "/END\n");
  INFO(al.err);
  CHECK(al.exit_code == 0);
  CHECK(al.err.find("RX512") == std::string::npos);
  // The same values with the units named kg m s: 0.515 m/s, a warning.
  const auto si = starter(dir, cube_deck(1.0, 2.7, 0.7173, "kg m s") + "/END\n");
  CHECK(si.err.find("the wave speed sqrt(E/RHO_I) = 0.515429 m/s") != std::string::npos);
  // A dummy modulus of 1e-31: c = sqrt(1e-31 / 8.48e-7) = 3.43e-13 units, 3.43e-9 m/s even in cm/us.
  const auto dummy = starter(dir, cube_deck(1.0, 8.48e-7, 1e-31, "") + "/END\n");
  CHECK(dummy.err.find("the wave speed sqrt(E/RHO_I) = 3.43401e-13 length per time unit (E = 1e-31, RHO_I = "
                       "8.48e-07; the deck names no units, so radx takes the most plausible of the usual "
                       "systems: 3.43401e-09 m/s if in cm/us) is below 1 m/s") != std::string::npos);
  // E = 1e30 with steel's density: c = 1.13e19 units, 1.13e16 m/s even in mm/s.
  const auto stiff = starter(dir, cube_deck(10.0, 7.85e-9, 1e30, "") + "/END\n");
  CHECK(stiff.err.find("1.12867e+16 m/s if in mm/s) is above the speed of light") != std::string::npos);
}

TEST_CASE("the initial step estimate is the element size over the wave speed", "[plausibility]") {
  // A cube of side 10 mm, nu = 0: L = V / largest face = 10, c = sqrt(E/rho) = sqrt(210000/7.85e-9), lowered
  // by the default linear bulk viscosity qb = 0.05 at rest: c_eff = c (qb + sqrt(1 + qb^2)).
  const auto m = radx::test::model_of_deck(cube_deck(10.0, 7.85e-9, 210000.0) + "/END\n");
  const auto step = radx::model::estimate_stable_step(m);
  const double qb = 0.05;
  CHECK(step.dt ==
        Approx(10.0 / std::sqrt(210000.0 / 7.85e-9) / (qb + std::sqrt(1 + qb * qb))).epsilon(1e-12));
  CHECK(step.element_id == 1);
  CHECK(step.type == radx::model::ElementType::Brick8);
}

TEST_CASE("a step below 1e-12 s is a warning RX513 at the element that sets it", "[plausibility]") {
  radx::test::TempDir dir;
  // E = 1e30 with steel's density in Mg mm s: c = 1.1e19 mm/s, step 10 mm / c = 8.86e-19 s, 8.43e-19 s with
  // the default bulk viscosity (times 0.951).
  const auto r = starter(dir, cube_deck(10.0, 7.85e-9, 1e30) + "/END\n");
  INFO(r.err);
  CHECK(r.exit_code == 0);
  CHECK(r.err.find("CUBE_0000.rad:16:1: warning: RX513: [/BRICK id 1] the initial stable time step is about "
                   "8.43e-19 s (element size over wave speed of brick 1), below 1e-12 s") !=
        std::string::npos);
  CHECK(r.err.find("RX512") != std::string::npos);  // and the material that causes it
  const auto steel = starter(dir, cube_deck(10.0, 7.85e-9, 210000.0) + "/END\n");
  CHECK(steel.err.find("RX513") == std::string::npos);
}

TEST_CASE("a run whose end time is absurd warns RX513 at /RUN in the starter and in the engine",
          "[plausibility]") {
  radx::test::TempDir dir;
  const std::string deck = cube_deck(10.0, 7.85e-9, 210000.0) + "/END\n";
  // Steel cube of 10 mm: step 0.9 x 0.951 (qb = 0.05) x 10 mm / 5172 m/s = 1.66e-6 s; 1e30 s needs 6.04e35
  // cycles.
  const std::string absurd = "/RUN/CUBE/1\n1e30\n/END\n";
  const std::string sane = "/RUN/CUBE/1\n1e-3\n/END\n";
  for (const bool check : {false, true}) {
    const auto r = starter(dir, deck, absurd, check);
    INFO(r.err);
    CHECK(r.exit_code == 0);
    CHECK(r.err.find("CUBE_0001.rad:1:1: warning: RX513: [/RUN] the end time 1e+30 s needs about 6.04e+35 "
                     "cycles of the initial step 1.66e-06 s (set by brick 1), more than 1e9") !=
          std::string::npos);
    const auto ok = starter(dir, deck, sane, check);
    CHECK(ok.err.find("RX513") == std::string::npos);
  }
  // The engine says it too, before it starts (a /DT minimum above the step stops it at once here).
  const std::string root = dir.path().string();
  REQUIRE(std::system((std::string(RADX_STARTER_EXE) + " " + dir.file("CUBE_0000.rad") + " --out " + root +
                       " >/dev/null 2>&1")
                          .c_str()) == 0);
  dir.write("CUBE_0001.rad", "/RUN/CUBE/1\n1e30\n/DT\n0.9 1.0\n/END\n");
  std::system((std::string(RADX_ENGINE_EXE) + " " + dir.file("CUBE_0001.rad") + " --out " + root +
               " --threads 1 --no-plot >/dev/null 2> " + dir.file("err.txt"))
                  .c_str());
  const std::string err = slurp(dir.file("err.txt"));
  INFO(err);
  CHECK(err.find("warning: RX513: [/RUN] the end time 1e+30 s needs about") != std::string::npos);
  CHECK(slurp(dir.file("CUBE_0001.out")).find("RX513") != std::string::npos);
  CHECK(
      slurp(dir.file("CUBE_summary.json")).find("warning: RX513: [/RUN] the end time 1e+30 s needs about") !=
      std::string::npos);
}

TEST_CASE("nodal mass scaling counts cycles at its Tmin", "[plausibility]") {
  // Steel cube of 10 mm: 0.9 x 0.951 x 1.93e-6 s = 1.66e-6 s a cycle; 1e4 s takes 6.04e9 cycles, past 1e9,
  // but /DT/NODA/CST holding the step at 1e-4 s takes 1e8.
  const auto m = radx::test::model_of_deck(cube_deck(10.0, 7.85e-9, 210000.0) + "/END\n");
  const auto step = radx::model::estimate_stable_step(m);
  radx::EngineDeck engine;
  radx::model::RunControls rc;
  rc.t_stop = 1e4;
  radx::Diagnostics plain;
  radx::check_cycle_count(engine, rc, m, step, plain);
  REQUIRE(plain.items().size() == 1);
  CHECK(plain.items()[0].message.find("needs about 6.04e+09 cycles") != std::string::npos);
  rc.nodal.given = true;
  rc.nodal.action = radx::model::DtAction::AddMass;
  rc.nodal.t_min = 1e-4;
  radx::Diagnostics scaled;
  radx::check_cycle_count(engine, rc, m, step, scaled);
  CHECK(scaled.items().empty());
}

TEST_CASE("an /ANIM/DT that writes more than 1e5 states is said with the count, at most one a cycle",
          "[plausibility]") {
  // Steel cube of 10 mm: a cycle of 0.9 x the estimated step (0.9 x 0.951 x 1.93e-6 s).
  const auto m = radx::test::model_of_deck(cube_deck(10.0, 7.85e-9, 210000.0) + "/END\n");
  const auto step = radx::model::estimate_stable_step(m);
  radx::test::TempDir dir;
  struct Written {
    std::size_t count;
    double states;
    std::string message;
  };
  auto check = [&](const std::string& run, const std::string& anim) {
    radx::EngineDeck deck;
    radx::Diagnostics read;
    auto rc = radx::read_run_controls(
        dir.write("CUBE_0001.rad", "/RUN/CUBE/1\n" + run + "\n/ANIM/DT\n" + anim + "\n/END\n"), read, &deck);
    REQUIRE_FALSE(read.has_errors());
    radx::Diagnostics d;
    radx::check_output_count(deck, rc, m, step, d);
    Written w{d.items().size(), 0.0, d.items().empty() ? "" : d.items()[0].message};
    if (const auto at = w.message.find("writes about "); at != std::string::npos)
      w.states = std::atof(w.message.c_str() + at + 13);
    return std::make_pair(w, radx::estimate_run_cycles(rc, step).cycles);
  };
  // 1 s at dT = 1e-9 s asks for 1e9 states; one a cycle is written: the run's cycles (printed to 3 digits).
  const auto [every_cycle, cycles] = check("1", "0 1e-9");
  REQUIRE(every_cycle.count == 1);
  INFO(every_cycle.message);
  CHECK(every_cycle.message.find("one every cycle") != std::string::npos);
  CHECK(every_cycle.states == Approx(cycles).epsilon(5e-3));
  CHECK(cycles > radx::kManyAnimStates);
  // 1e4 s at dT = 1e-2 s: 1e6 states, fewer than the cycles, each written.
  const auto [long_run, long_cycles] = check("1e4", "0 1e-2");
  REQUIRE(long_run.count == 1);
  CHECK(long_run.states == Approx(1e6).epsilon(5e-3));
  CHECK(long_cycles > 1e6);
  // 1 s at dT = 1e-4 s: 1e4 states, as a study reads them.
  CHECK(check("1", "0 1e-4").first.count == 0);
}

TEST_CASE("energy error warnings: at 10 % and at 50 %, each once, in either sign", "[plausibility]") {
  radx::io::EnergyErrorWarnings w;
  CHECK(w.check(9.99).empty());
  const auto ten = w.check(-12.0);
  REQUIRE(ten.size() == 1);
  CHECK(ten[0] ==
        "the energy error is -12 %, past 10 %: the run loses energy it cannot account for (a sound "
        "run stays within a few per cent); it goes on (/STOP Emax stops it)");
  CHECK(w.check(15.0).empty());  // past 10 % again: said already
  CHECK(w.check(std::nan("")).empty());
  const auto fifty = w.check(99.9);
  REQUIRE(fifty.size() == 1);
  CHECK(fifty[0].find("past 50 %: the run creates energy") != std::string::npos);
  CHECK(w.check(-99.9).empty());
  // Both levels passed at once: both said.
  radx::io::EnergyErrorWarnings jump;
  CHECK(jump.check(60.0).size() == 2);
}

TEST_CASE("energy error warnings on a balance drifting linearly come at the cycles the drift gives",
          "[plausibility]") {
  // E_total(k) = E0 (1 + 0.6 k / N) with no external work: the error is 60 k / N %, past 10 % first at
  // k = ceil(N / 6) and past 50 % first at k = ceil(5 N / 6).
  const int n = 100;
  const double e0 = 2.5e3;
  radx::io::EnergyErrorWarnings w;
  std::vector<int> at;
  for (int k = 0; k <= n; ++k) {
    const double error = radx::io::energy_error_percent(e0 * (1.0 + 0.6 * k / n), e0, 0.0);
    for (const auto& m : w.check(error)) {
      (void)m;
      at.push_back(k);
    }
  }
  REQUIRE(at.size() == 2);
  CHECK(at[0] == static_cast<int>(std::ceil(n / 6.0)));
  CHECK(at[1] == static_cast<int>(std::ceil(5.0 * n / 6.0)));
}

TEST_CASE("the engine warns once when the energy error passes 10 % and runs to its end time",
          "[plausibility]") {
  radx::test::TempDir dir;
  // One node of a lone steel cube thrown at 1000 mm/s: the element rings at its own step and the balance,
  // measured with half-step velocities, swings by tens of per cent from cycle 1 on, never to 50 %: the
  // 10 % warning must come once however often the error passes it again.
  const std::string deck = cube_deck(10.0, 7.85e-9, 210000.0) + "/GRNOD/NODE/1\nn7\n" +
                           Line().put(7, 1, 10).str() + "\n/INIVEL/TRA/1\nv\n" +
                           Line().put(0.0, 1, 20).put(0.0, 21, 40).put(-1000.0, 41, 60).put(1, 61, 70).str() +
                           "\n/END\n";
  dir.write("CUBE_0000.rad", deck);
  dir.write("CUBE_0001.rad", "/RUN/CUBE/1\n2e-5\n/PRINT/-1\n/END\n");
  const std::string root = dir.path().string();
  REQUIRE(std::system((std::string(RADX_STARTER_EXE) + " " + dir.file("CUBE_0000.rad") + " --out " + root +
                       " >/dev/null 2>&1")
                          .c_str()) == 0);
  const int rc =
      std::system((std::string(RADX_ENGINE_EXE) + " " + dir.file("CUBE_0001.rad") + " --out " + root +
                   " --threads 1 --no-plot > " + dir.file("out.txt") + " 2> " + dir.file("err.txt"))
                      .c_str());
  const std::string err = slurp(dir.file("err.txt"));
  const std::string listing = slurp(dir.file("CUBE_0001.out"));
  INFO(err);
  CHECK(rc == 0);
  // Each sink has the warning once (the levels and the message are the monitor's, tested above).
  CHECK(count(err, "radx-engine: warning: cycle ") == 1);
  CHECK(count(err, "past 10 %") == 1);
  CHECK(count(err, "past 50 %") == 0);
  CHECK(count(listing, "  WARNING (cycle ") == 1);
  CHECK(count(listing, "past 10 %") == 1);
  CHECK(count(slurp(dir.file("out.txt")), "past 10 %") == 1);
  const std::string summary = slurp(dir.file("CUBE_summary.json"));
  INFO(summary);
  CHECK(count(summary, "\"cycle ") == 1);
  CHECK(count(summary, "past 10 %: the run ") == 1);
  CHECK(count(summary, "past 50 %") == 0);
  CHECK(listing.find("NORMAL TERMINATION") != std::string::npos);
}

namespace {

// The spring oscillator sample deck (a TYPE4 spring of mass 1e-6 Mg, K = 1000 N/mm, C = 1 N s/mm between a
// clamped node and a heavy one): a model with no element but the spring.
std::string spring_deck() {
  std::ifstream in(std::string(RADX_SOURCE_DIR) + "/decks/spring_oscillator/SPRING_OSC_0000.rad");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

TEST_CASE("the step estimate counts springs: a spring-only run of more than 1e9 cycles warns RX513",
          "[plausibility]") {
  const auto m = radx::test::model_of_deck(spring_deck());
  const auto step = radx::model::estimate_stable_step(m);
  // r1len3.F: dt = min(m / (sqrt(c^2 + m k) + c), m / (2 c)) with m = 1e-6, k = 1000, c = 1.
  const double mass = 1e-6, k = 1000.0, c = 1.0;
  const double dt = std::min(mass / (std::sqrt(c * c + mass * k) + c), 0.5 * mass / c);
  CHECK(step.dt == Approx(dt).epsilon(1e-12));
  CHECK(step.type == radx::model::ElementType::Spring2);
  CHECK(step.element_id == 1);
  // 1000 s at 0.9 dt: 2.22e9 cycles, past 1e9; the sample's own 0.02 s is 4.4e4.
  radx::EngineDeck engine;
  radx::model::RunControls rc;
  rc.t_stop = 1000.0;
  radx::Diagnostics long_run;
  radx::check_cycle_count(engine, rc, m, step, long_run);
  REQUIRE(long_run.items().size() == 1);
  INFO(long_run.items()[0].message);
  CHECK(long_run.items()[0].message.find("needs about 2.22e+09 cycles of the initial step 4.5e-07 s (set by "
                                         "spring 1)") != std::string::npos);
  rc.t_stop = 0.02;
  radx::Diagnostics sample;
  radx::check_cycle_count(engine, rc, m, step, sample);
  CHECK(sample.items().empty());
}

TEST_CASE("a spring's property step: TYPE4 per unit length, TYPE8 and TYPE13 by family", "[plausibility]") {
  radx::model::SpringProperty p;
  p.type = 4;
  p.mass = 2.0;
  p.x.stiffness = 8.0;
  // Undamped: sqrt(m / k) = 0.5.
  CHECK(radx::model::spring_property_step(p, 3.0) == Approx(0.5).epsilon(1e-15));
  // Ileng 1: m = M l0, k = K / l0: sqrt(M l0^2 / K) = 1.5 at l0 = 3.
  p.ileng = 1;
  CHECK(radx::model::spring_property_step(p, 3.0) == Approx(1.5).epsilon(1e-15));
  // TYPE8: the smaller of sqrt(M / k_t) and sqrt(I / k_r).
  radx::model::SpringProperty g;
  g.type = 8;
  g.mass = 2.0;
  g.inertia = 1.0;
  g.y.stiffness = 8.0;
  g.rz.stiffness = 100.0;
  CHECK(radx::model::spring_property_step(g, 3.0) == Approx(0.1).epsilon(1e-15));
  // TYPE13: the shear laws add k l0^2 to the rotations: sqrt(1 / (100 + 8 x 9)).
  g.type = 13;
  CHECK(radx::model::spring_property_step(g, 3.0) == Approx(1.0 / std::sqrt(172.0)).epsilon(1e-15));
  // Bulk viscosity: qb = 0 leaves the step, qb = 0.75 halves it (sqrt(1.5625) - 0.75 = 0.5).
  CHECK(radx::model::bulk_viscosity_step_factor(0.0) == 1.0);
  CHECK(radx::model::bulk_viscosity_step_factor(0.75) == Approx(0.5).epsilon(1e-15));
}

TEST_CASE(
    "a contact law whose stiffness would vote a step below 1/100 of the elements' warns RX513 at the "
    "interface",
    "[plausibility]") {
  // ctclaw_drop's cube on the bilinear law Kc = 5.625e9 Pa/m: a pair Kc A_s = 1.4e7 N/m on a lower-face node
  // of 0.5625 kg votes sqrt(2 m / k) = 2.8e-4 s, above the bricks' step. Made 1e12 times steeper (a legal
  // law), it votes 2.83e-10 s, 1/3e4 of the bricks' 8.5e-6 s: said before the run.
  std::ifstream in(std::string(RADX_SOURCE_DIR) + "/decks/verification/ctclaw_drop/CTCLAW_DROP_N1_0000.rad");
  std::stringstream text;
  text << in.rdbuf();
  std::string deck = text.str();
  radx::test::TempDir dir;
  const auto ordinary = starter(dir, deck);
  INFO(ordinary.err);
  CHECK(ordinary.err.find("RX513") == std::string::npos);
  for (auto at = deck.find("n1{Kc5.625e9}"); at != std::string::npos; at = deck.find("n1{Kc5.625e9}"))
    deck.replace(at, 13, "n1{Kc5.625e21}");
  const auto steep = starter(dir, deck);
  INFO(steep.err);
  const double dt = std::sqrt(2 * 0.5625 / (5.625e21 * 0.0025));
  char expected[160];
  std::snprintf(expected, sizeof expected,
                "once in contact a pair of this interface votes a step of about %.3g s", dt);
  CHECK(steep.err.find(std::string("warning: RX513: [/INTER/TYPE7 id 1 \"Cube lower face on the plate\"] ") +
                       expected) != std::string::npos);
  CHECK(steep.err.find("Kc A_s = 1.41e+19 on secondary node 101 of mass 0.562") != std::string::npos);
}
