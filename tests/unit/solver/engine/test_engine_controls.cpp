// Engine time-step controls and the run pipeline, with expected values from docs/theory/elements.md 4.4-4.5
// and docs/theory/deck-format.md section 3: nodal mass scaling (/DT/NODA/CST), the /DT minimum stop, inverted
// elements, and `radx run` on the default deck (energy balance and mass in NAME_summary.json).
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "parser/building/model_builder.hpp"
#include "parser/reading/deck.hpp"
#include "solver/engine/explicit_engine.hpp"
#include "test_util.hpp"

using radx::test::Line;

namespace {

// The deck text (no /END) of one steel cube of side a (LAW1): nodes 1-4 on z = 0, 5-8 on z = a. Ismstr of
// its /PROP/SOLID (0: the default 4; /DT/BRICK/CST switches only Ismstr 2 to small strain).
std::string cube_text(double a, int ismstr = 0) {
  std::string s = radx::test::begin_block(2026, "Mg mm s") + "/NODE\n";
  for (int k = 0; k < 8; ++k) {
    const double x = (k == 1 || k == 2 || k == 5 || k == 6) ? a : 0.0;
    const double y = (k == 2 || k == 3 || k == 6 || k == 7) ? a : 0.0;
    const double z = k >= 4 ? a : 0.0;
    s += Line().put(k + 1, 1, 10).put(x, 11, 30).put(y, 31, 50).put(z, 51, 70).str() + "\n";
  }
  Line b;
  b.put(1, 1, 10);
  for (int k = 0; k < 8; ++k) b.put(k + 1, 11 + 10 * k, 20 + 10 * k);
  s += "/BRICK/1\n" + b.str() + "\n/PART/1\ncube\n" + Line().put(1, 1, 10).put(1, 11, 20).str() + "\n";
  s += "/PROP/SOLID/1\nsolid\n" + Line().put(0, 1, 10).put(ismstr, 11, 20).str() +
       "\n\n/MAT/LAW1/1\nsteel\n" + Line().put(7.85e-9, 1, 20).str() + "\n" +
       Line().put(210000.0, 1, 20).put(0.3, 21, 40).str() + "\n";
  return s;
}

// One steel cube of side a (LAW1), at rest, nothing else.
radx::model::Model cube(double a, double vz = 0.0, int ismstr = 0) {
  std::string s = cube_text(a, ismstr);
  if (vz != 0.0)
    s += "/GRNOD/PART/1\nall\n" + Line().put(1, 1, 10).str() + "\n/INIVEL/TRA/1\nv\n" +
         Line().put(0.0, 1, 20).put(0.0, 21, 40).put(vz, 41, 60).put(1, 61, 70).str() + "\n";
  s += "/END\n";
  return radx::test::model_of_deck(s);
}

// /IMPVEL/1 moving node group `group` along `dir` at the constant speed `v` (with /FUNCT/1 = 1), then /END.
std::string constant_impvel_and_end(const char* dir, int group, double v) {
  return "/IMPVEL/1\nimposed\n" +
         Line().put(1, 1, 10).put(dir, 11, 20).put(0, 21, 30).put(0, 31, 40).put(group, 41, 50).str() + "\n" +
         Line().put(0.0, 1, 20).put(v, 21, 40).str() + "\n/FUNCT/1\none\n" +
         Line().put(0.0, 1, 20).put(1.0, 21, 40).str() + "\n" +
         Line().put(1.0, 1, 20).put(1.0, 21, 40).str() + "\n/END\n";
}

// The scaled step of cycle 0 of a run of `m` with `rc`.
double first_step(const radx::model::Model& m, const radx::model::RunControls& rc) {
  double dt = 0;
  radx::solver::ExplicitEngine e(m, rc, radx::solver::EngineOptions{1, 1});
  e.run([&](const radx::solver::CycleReport& r) {
    dt = r.dt;
    return false;
  });
  return dt;
}

// A run of `m` to `t_stop` with `family` (rc.brick or rc.shell) held at /DT/.../CST Tmin = 0.98 x the step of
// cycle 0, so the switch happens at once; records every cycle's step, the first element's own step and the
// final position of node index `watch`.
template <class Own>
radx::solver::RunResult run_held_at_tmin(const radx::model::Model& m, double t_stop,
                                         radx::model::DtControl radx::model::RunControls::*family,
                                         Own own_step, radx::model::RunControls& rc,
                                         std::vector<double>& steps, std::vector<double>& own,
                                         std::size_t watch, std::array<double, 3>& at) {
  rc.t_stop = t_stop;
  const double first_dt = first_step(m, rc);
  REQUIRE(first_dt > 0);
  auto& f = rc.*family;
  f.given = true;
  f.action = radx::model::DtAction::Constant;
  f.scale = 0.9;
  f.t_min = 0.98 * first_dt;
  radx::solver::ExplicitEngine engine(m, rc, radx::solver::EngineOptions{1, 1});
  const auto res = engine.run([&](const radx::solver::CycleReport& r) {
    steps.push_back(r.dt);
    own.push_back(own_step(engine));
    return true;
  });
  const auto& s = engine.nodes();
  at = {s.x[watch], s.y[watch], s.z[watch]};
  return res;
}

}  // namespace

TEST_CASE("/DT/NODA/CST adds the mass that keeps the nodal step at Tmin", "[engine]") {
  const double a = 10.0;
  auto m = cube(a);
  const double E = 210000, nu = 0.3, rho = 7.85e-9;
  const double K = E / (3 * (1 - 2 * nu)), G = E / (2 * (1 + nu));
  const double c = std::sqrt((K + 4 * G / 3) / rho);
  const double dt_e = a / (c * (0.05 + std::sqrt(1 + 0.05 * 0.05)));  // docs/theory/elements.md 4.4, at rest
  radx::model::RunControls rc;
  rc.t_stop = 1e-5;
  rc.nodal.given = true;
  rc.nodal.action = radx::model::DtAction::AddMass;
  rc.nodal.scale = 0.9;
  rc.nodal.t_min = 2 * 0.9 * dt_e;  // twice the natural nodal step: the mass must grow 4 times
  radx::solver::ExplicitEngine engine(m, rc, radx::solver::EngineOptions{1, 1});
  const auto res = engine.run({});
  REQUIRE(res.status == radx::solver::RunStatus::Normal);
  const double m0 = rho * a * a * a;
  // A cube alone reproduces its own step at the nodes (docs/theory/elements.md 4.5): sqrt(2
  // (m/8) / K_e) = dt_e. Holding the step at 2 x 0.9 dt_e needs (2)^2 = 4 times the mass: 3 m0 added.
  // Round-off tolerance.
  CHECK(res.last.added_mass == Approx(3 * m0).epsilon(1e-9));
  CHECK(res.last.control.kind == radx::solver::StepControl::Kind::Node);
  CHECK(res.dt <= rc.nodal.t_min * (1 + 1e-12));
}

TEST_CASE("/DT/NODA (no action) runs at the nodal step and adds no mass below Tmin", "[engine]") {
  // OpenRadioss's freform.F leaves /DT/NODA and /DT/NODA/0 without an action (IDT 0): the nodal step is the
  // run's step, Tmin changes nothing.
  const double a = 10.0;
  auto m = cube(a);
  const double E = 210000, nu = 0.3, rho = 7.85e-9;
  const double K = E / (3 * (1 - 2 * nu)), G = E / (2 * (1 + nu));
  const double c = std::sqrt((K + 4 * G / 3) / rho);
  const double dt_e = a / (c * (0.05 + std::sqrt(1 + 0.05 * 0.05)));  // docs/theory/elements.md 4.4, at rest
  radx::model::RunControls rc;
  rc.t_stop = 1e-5;
  rc.nodal.given = true;
  rc.nodal.action = radx::model::DtAction::None;
  rc.nodal.scale = 0.67;
  rc.nodal.t_min = 2 * dt_e;  // above the nodal step: /DT/NODA/CST would add mass here
  double first = 0;
  radx::solver::ExplicitEngine engine(m, rc, radx::solver::EngineOptions{1, 1});
  const auto res = engine.run([&](const radx::solver::CycleReport& r) {
    if (first == 0) first = r.dt;
    return true;
  });
  REQUIRE(res.status == radx::solver::RunStatus::Normal);
  CHECK(res.last.added_mass == 0.0);
  CHECK(res.last.control.kind == radx::solver::StepControl::Kind::Node);
  // A lone cube's nodal step is its element step (docs/theory/elements.md 4.5), here at the /DT/NODA
  // scale 0.67 instead of /DT's 0.9; relative round-off tolerance.
  CHECK(first == Approx(0.67 * dt_e).epsilon(1e-9));
}

TEST_CASE("a run of N equal steps ends at its end time in N cycles, without a round-off cycle", "[engine]") {
  // 3000 steps of 1e-9 s summed in floating point end 1e-22 s away from 3e-6 s; the run must not add a cycle
  // of that size (it would evaluate the loads at the end time once more) and must end exactly at Tstop.
  auto m = cube(10.0, -1000.0);
  radx::model::RunControls rc;
  // A step far below the cube's own (about 1.6e-6 s), chosen so that the sum falls short of 3000 dt: the case
  // the rule is for (a sum above it is cut by the last step anyway).
  double summed = 0;
  for (int tries = 0; tries < 100; ++tries) {
    rc.dt_max = 1e-9 * (1.0 + 0.01 * tries);
    rc.t_stop = 3000 * rc.dt_max;
    summed = 0;
    for (int k = 0; k < 3000; ++k) summed += rc.dt_max;
    if (summed < rc.t_stop) break;
  }
  INFO("dt " << rc.dt_max << ": summed " << summed << " vs " << rc.t_stop);
  REQUIRE(summed < rc.t_stop);
  radx::solver::ExplicitEngine engine(m, rc, radx::solver::EngineOptions{1, 1});
  const auto res = engine.run({});
  REQUIRE(res.status == radx::solver::RunStatus::Normal);
  CHECK(res.cycles == 3000);
  CHECK(res.time == rc.t_stop);
}

TEST_CASE("the /DT minimum stops the run with a message, the step grows by at most 10 % a cycle",
          "[engine]") {
  auto m = cube(10.0);
  radx::model::RunControls rc;
  rc.t_stop = 1e-4;
  rc.global.t_min = 1.0;  // far above any step of this cube
  radx::solver::ExplicitEngine engine(m, rc, radx::solver::EngineOptions{1, 1});
  const auto res = engine.run({});
  CHECK(res.status == radx::solver::RunStatus::Error);
  CHECK(res.message.find("minimum") != std::string::npos);

  radx::model::RunControls free_run;
  free_run.t_stop = 2e-5;
  radx::solver::ExplicitEngine e2(m, free_run, radx::solver::EngineOptions{1, 1});
  double previous = 0;
  bool growth_ok = true;
  e2.run([&](const radx::solver::CycleReport& r) {
    if (previous > 0 && r.time < free_run.t_stop)
      growth_ok = growth_ok && r.dt <= 1.1 * previous * (1 + 1e-12);
    previous = r.dt;
    return true;
  });
  CHECK(growth_ok);
}

TEST_CASE("/DT/BRICK/STOP and /DT/SPRING/STOP stop the run when an element's scaled step falls below Tmin",
          "[engine]") {
  // The cube's brick: 0.9 x 10 mm / c_eff, about 1.7e-6 s. A Tmin above it stops the run at once, naming the
  // brick; one below it lets the run end normally.
  auto m = cube(10.0);
  radx::model::RunControls rc;
  rc.t_stop = 2e-5;
  rc.brick.given = true;
  rc.brick.action = radx::model::DtAction::Stop;
  rc.brick.t_min = 1e-5;
  radx::solver::ExplicitEngine stopped(m, rc, radx::solver::EngineOptions{1, 1});
  const auto res = stopped.run({});
  CHECK(res.status == radx::solver::RunStatus::Error);
  CHECK(res.cycles == 0);
  CHECK(res.message.find("brick 1 has the step ") != std::string::npos);
  CHECK(res.message.find("below the /DT/BRICK/STOP minimum 1e-05") != std::string::npos);
  rc.brick.t_min = 1e-7;
  radx::solver::ExplicitEngine runs(m, rc, radx::solver::EngineOptions{1, 1});
  CHECK(runs.run({}).status == radx::solver::RunStatus::Normal);

  // The spring oscillator: dt = min(m / (sqrt(c^2 + m k) + c), m / (2 c)) = 4.9988e-7 s (m 1e-6, k 1000, c
  // 1), 4.4989e-7 s scaled by 0.9: a Tmin of 4.5e-7 s stops it, one of 4.49e-7 s does not.
  std::ifstream in(std::string(RADX_SOURCE_DIR) + "/decks/spring_oscillator/SPRING_OSC_0000.rad");
  std::stringstream text;
  text << in.rdbuf();
  const auto springs = radx::test::model_of_deck(text.str());
  radx::model::RunControls sc;
  sc.t_stop = 1e-5;
  sc.spring.given = true;
  sc.spring.action = radx::model::DtAction::Stop;
  sc.spring.t_min = 4.5e-7;
  radx::solver::ExplicitEngine spring_stop(springs, sc, radx::solver::EngineOptions{1, 1});
  const auto sres = spring_stop.run({});
  CHECK(sres.status == radx::solver::RunStatus::Error);
  CHECK(sres.message.find("spring 1 has the step 4.499e-07, below the /DT/SPRING/STOP minimum 4.5e-07") !=
        std::string::npos);
  sc.spring.t_min = 4.49e-7;
  radx::solver::ExplicitEngine spring_runs(springs, sc, radx::solver::EngineOptions{1, 1});
  CHECK(spring_runs.run({}).status == radx::solver::RunStatus::Normal);
}

TEST_CASE("a free cube with an initial velocity keeps its momentum and energy", "[engine]") {
  auto m = cube(10.0, -1000.0);
  radx::model::RunControls rc;
  // A lone one-point brick becomes unstable at its own step after some tens of cycles
  // (docs/theory/elements.md 9, a property of the element seeded by round-off): the run is kept to about 14
  // cycles.
  rc.t_stop = 2e-5;
  radx::solver::ExplicitEngine engine(m, rc, radx::solver::EngineOptions{1, 1});
  const double mass = 7.85e-9 * 1000.0;
  bool ok = true;
  double worst = 0;
  engine.run([&](const radx::solver::CycleReport& r) {
    if (!r.full) return true;
    // No external force: momentum m v0 to round-off (1e-12 of m v0), energy unchanged (rigid translation).
    worst = std::max(worst, std::abs(r.momentum[2] - mass * -1000.0) / (mass * 1000.0));
    ok = ok && std::abs(r.energy.error_percent) < 1e-9;
    return true;
  });
  CHECK(worst < 1e-12);
  CHECK(ok);
}

TEST_CASE("radx run on the default deck closes its energy balance and writes NAME_summary.json", "[engine]") {
  radx::test::TempDir dir;
  const std::string cmd = std::string(RADX_DRIVER_EXE) + " run " + RADX_SOURCE_DIR +
                          "/decks/block_on_plate/BLOCK_ON_PLATE_0000.rad --out " + dir.path().string() +
                          " --threads 1 > " + dir.file("log.txt") + " 2>&1";
  REQUIRE(std::system(cmd.c_str()) == 0);
  // Read the JSON with Python's json module (an independent parser).
  const std::string check =
      "/usr/bin/python3 -c \"import json,sys; s=json.load(open(sys.argv[1])); e=s['energy'];"
      " assert s['status']=='normal', s['status'];"
      " assert abs(e['error_percent'])<1.0, e['error_percent'];"  // balance closes within 1 %
      " assert s['cycles']>0 and s['us_per_element_cycle']>0;"
      " assert abs(s['mass']-1.001e-4)<1e-12, s['mass'];"  // rho t A + rho V of the deck: 7.85e-5 + 2.16e-5
      "\" " +
      dir.file("BLOCK_ON_PLATE_summary.json");
  CHECK(std::system(check.c_str()) == 0);
  std::ifstream log(dir.file("log.txt"));
  std::stringstream ss;
  ss << log.rdbuf();
  CHECK(ss.str().find("us per element per cycle") != std::string::npos);
  CHECK(ss.str().find("ENERGY BALANCE") != std::string::npos);
}

TEST_CASE("every sample deck runs to its end time with the energy balance closed within 1 %", "[engine]") {
  // docs/theory/verification.md C: kinetic + internal + hourglass + contact (elastic, damping,
  // friction) - external work stays within 1 % of the initial total; the sample decks' blocks hit their
  // plates through two TYPE7 interfaces.
  for (const char* deck :
       {"block_on_plate/BLOCK_ON_PLATE_0000.rad", "block_on_plate_lagdt/BLOCK_ON_PLATE_LAGDT_0000.rad",
        "one_file/ONE_FILE_0000.rad"}) {
    DYNAMIC_SECTION(deck) {
      radx::test::TempDir dir;
      const std::string cmd = std::string(RADX_DRIVER_EXE) + " run " + RADX_SOURCE_DIR + "/decks/" + deck +
                              " --out " + dir.path().string() + " --threads 1 > " + dir.file("log.txt") +
                              " 2>&1";
      REQUIRE(std::system(cmd.c_str()) == 0);
      std::string summary;
      for (const auto& e : std::filesystem::directory_iterator(dir.path()))
        if (e.path().string().find("_summary.json") != std::string::npos) summary = e.path().string();
      REQUIRE_FALSE(summary.empty());
      const std::string check =
          "/usr/bin/python3 -c \"import json,sys; s=json.load(open(sys.argv[1])); e=s['energy'];"
          " assert s['status']=='normal', s['message']; assert abs(e['error_percent'])<1.0, "
          "e['error_percent']\" " +
          summary;
      CHECK(std::system(check.c_str()) == 0);
    }
  }
}

TEST_CASE("/RBODY/OFF leaves the body out of the run, its nodes move freely", "[engine]") {
  // A brick whose 8 nodes are the secondary nodes of a rigid body with a separate main node at rest; the
  // brick's nodes start at v0. Active, the body takes its motion from the main node (at rest: the nodes
  // are stopped and the brick's momentum goes to 0); switched off, the brick keeps m v0 exactly.
  std::string s = radx::test::begin_block(2026, "Mg mm s") + "/NODE\n";
  for (int k = 0; k < 8; ++k) {
    const double x = (k == 1 || k == 2 || k == 5 || k == 6) ? 10.0 : 0.0;
    const double y = (k == 2 || k == 3 || k == 6 || k == 7) ? 10.0 : 0.0;
    s += Line().put(k + 1, 1, 10).put(x, 11, 30).put(y, 31, 50).put(k >= 4 ? 10.0 : 0.0, 51, 70).str() + "\n";
  }
  s += Line().put(9, 1, 10).put(5.0, 11, 30).put(5.0, 31, 50).put(5.0, 51, 70).str() + "\n";
  Line b;
  b.put(1, 1, 10);
  for (int k = 0; k < 8; ++k) b.put(k + 1, 11 + 10 * k, 20 + 10 * k);
  s += "/BRICK/1\n" + b.str() + "\n/PART/1\ncube\n" + Line().put(1, 1, 10).put(1, 11, 20).str() + "\n";
  s += "/PROP/SOLID/1\nsolid\n\n\n/MAT/LAW1/1\nsteel\n" + Line().put(7.85e-9, 1, 20).str() + "\n" +
       Line().put(210000.0, 1, 20).put(0.3, 21, 40).str() + "\n";
  s += "/GRNOD/PART/1\ncube nodes\n" + Line().put(1, 1, 10).str() + "\n";
  s += "/INIVEL/TRA/1\nv\n" +
       Line().put(0.0, 1, 20).put(0.0, 21, 40).put(-1000.0, 41, 60).put(1, 61, 70).str() + "\n";
  s += "/RBODY/1\nbody\n" + Line().put(9, 1, 10).put(1.0e-9, 41, 60).put(1, 61, 70).put(3, 81, 90).str() +
       "\n";
  s += "\n\n/END\n";
  radx::test::TempDir dir;
  const auto path = dir.write("rb_0000.rad", s);
  radx::Diagnostics diags;
  const auto deck = radx::read_starter_deck(path, diags);
  const auto m = radx::build_model(deck, diags);
  for (const auto& d : diags.items()) INFO(radx::Diagnostics::format(d));
  REQUIRE_FALSE(diags.has_errors());
  REQUIRE(m.rigid_bodies.size() == 1);
  const double cube_mass = 7.85e-9 * 1000.0;
  auto final_pz = [&](bool off) {
    radx::model::RunControls rc;
    rc.t_stop = 1e-5;
    if (off) rc.rbody_off = {1};
    radx::solver::ExplicitEngine engine(m, rc, radx::solver::EngineOptions{1, 1});
    const auto res = engine.run({});
    REQUIRE(res.status == radx::solver::RunStatus::Normal);
    double pz = 0;
    for (std::size_t n = 0; n < 8; ++n) pz += engine.nodes().mass[n] * engine.nodes().vz[n];
    return pz;
  };
  // Switched off: no force acts on the free brick: its momentum stays m v0 (round-off).
  CHECK(final_pz(true) == Approx(cube_mass * -1000.0).epsilon(1e-12));
  // Active: the secondary nodes follow the main node at rest.
  CHECK(std::abs(final_pz(false)) < 1e-9 * cube_mass * 1000.0);
}

TEST_CASE("/DT/BRICK/CST holds a brick's step at Tmin and stops if the brick's own step falls too far",
          "[engine]") {
  const double a = 10.0;
  auto m = cube(a, 0.0, 2);  // Ismstr 2: the brick may switch
  const double E = 210000, nu = 0.3, rho = 7.85e-9;
  const double K = E / (3 * (1 - 2 * nu)), G = E / (2 * (1 + nu));
  const double c = std::sqrt((K + 4 * G / 3) / rho);
  // docs/theory/elements.md 4.4 at rest
  const double dt_own = 0.9 * a / (c * (0.05 + std::sqrt(1 + 0.05 * 0.05)));
  double second_dt = 0;
  auto run_with = [&](double t_min) {
    radx::model::RunControls rc;
    rc.t_stop = 20 * dt_own;
    rc.brick.given = true;
    rc.brick.action = radx::model::DtAction::Constant;
    rc.brick.scale = 0.9;
    rc.brick.t_min = t_min;
    radx::solver::ExplicitEngine engine(m, rc, radx::solver::EngineOptions{1, 1});
    return engine.run([&](const radx::solver::CycleReport& r) {
      if (r.cycle == 1) second_dt = r.dt;
      return true;
    });
  };
  // Tmin 1.2 x the brick's step: the step is Tmin exactly (the frozen value), the run ends normally.
  const auto held = run_with(1.2 * dt_own);
  CHECK(held.status == radx::solver::RunStatus::Normal);
  CHECK(second_dt == Approx(1.2 * dt_own).epsilon(1e-12));
  // Tmin 3 x the brick's step: the element's own step is below half the held step: the run stops and
  // names the brick.
  const auto stopped = run_with(3.0 * dt_own);
  CHECK(stopped.status == radx::solver::RunStatus::Error);
  CHECK(stopped.message.find("element 1") != std::string::npos);
  // The default Ismstr 4 never switches (docs/theory/deck-format.md: only Ismstr 2): the brick keeps its own
  // step.
  m = cube(a);
  const auto own = run_with(1.2 * dt_own);
  CHECK(own.status == radx::solver::RunStatus::Normal);
  CHECK(second_dt == Approx(dt_own).epsilon(1e-9));
}

TEST_CASE("/DT/BRICK/CST switches the brick to small strain: its step stays constant while it is crushed",
          "[engine]") {
  // One steel cube (side a) on symmetry supports (x = 0, y = 0, z = 0 faces), its top face pushed down at
  // constant speed V so that it is crushed by 40 % in the run. Large strain would shrink its step with its
  // height (dt ~ V / A_max); after the switch at Tmin the geometry of the switch is kept, so the element's
  // own step (before the scale) and the run's step stay constant ("its step stays constant",
  // docs/theory/elements.md section 4).
  const double a = 10.0, V = 2.0e5;  // mm/s: 40 % of a in 2e-5 s, some tens of brick steps
  std::string s = cube_text(a, 2);
  auto group = [&](int id, std::vector<int> nodes) {
    Line l;
    for (std::size_t k = 0; k < nodes.size(); ++k)
      l.put(nodes[k], 1 + 10 * static_cast<int>(k), 10 + 10 * static_cast<int>(k));
    s += "/GRNOD/NODE/" + std::to_string(id) + "\ng\n" + l.str() + "\n";
  };
  group(1, {1, 4, 5, 8});  // x = 0
  group(2, {1, 2, 5, 6});  // y = 0
  group(3, {1, 2, 3, 4});  // z = 0
  group(4, {5, 6, 7, 8});  // top
  const char* codes[3] = {"   100 000", "   010 000", "   001 000"};
  for (int k = 0; k < 3; ++k)
    s += "/BCS/" + std::to_string(k + 1) + "\nsym\n" +
         Line().put(codes[k], 1, 10).put(0, 11, 20).put(k + 1, 21, 30).str() + "\n";
  s += constant_impvel_and_end("Z", 4, -V);
  const auto m = radx::test::model_of_deck(s);

  radx::model::RunControls rc;
  std::vector<double> steps, own;
  std::array<double, 3> top{};
  const auto res = run_held_at_tmin(
      m, 0.4 * a / V, &radx::model::RunControls::brick,
      [](const radx::solver::ExplicitEngine& e) { return e.groups().bricks.at(0).dt[0]; }, rc, steps, own, 4,
      top);
  INFO(res.message);
  REQUIRE(res.status == radx::solver::RunStatus::Normal);
  REQUIRE(steps.size() > 10);
  // The crush really happened: the top face moved down by V t_stop (imposed).
  CHECK(top[2] == Approx(a - V * rc.t_stop).epsilon(1e-9));
  // After the switch (from the third cycle on, once the frozen geometry is captured) every step is Tmin (the
  // last two cycles are cut to end at t_stop). The element's own step is that of the frozen geometry: its
  // length V/A_max no longer shrinks with the height (0.6 a at the end: a large-strain step would be about
  // 0.6 of the first one); it varies only through the bulk-viscosity term qb c + qa^2 l ec of the compression
  // rate, some per cent here, so it stays above 0.85 of its value at the switch.
  for (std::size_t k = 3; k + 2 < steps.size(); ++k) {
    INFO("cycle " << k);
    CHECK(steps[k] == Approx(rc.brick.t_min).epsilon(1e-12));
  }
  const double own_min = *std::min_element(own.begin() + 3, own.end() - 1);
  CHECK(own_min > 0.85 * own[3]);
}

TEST_CASE("/DT/SHELL/CST switches the shell to small strain: its step stays exactly constant", "[engine]") {
  // One square steel shell (side a): the edge x = 0 clamped, the edge x = a pushed towards it at speed V
  // (in plane, z and rotations held), 40 % of a in the run. Large strain would shrink the step with the
  // side (dt = L / c); after the switch the frozen local geometry gives the same L every cycle, and with no
  // membrane damping (Dm = 0) the shell step has no rate term: the element's own step is constant exactly.
  const double a = 10.0, V = 2.0e5;
  std::string s = radx::test::begin_block(2026, "Mg mm s") + "/NODE\n";
  const double xy[4][2] = {{0, 0}, {a, 0}, {a, a}, {0, a}};
  for (int k = 0; k < 4; ++k)
    s += Line().put(k + 1, 1, 10).put(xy[k][0], 11, 30).put(xy[k][1], 31, 50).put(0.0, 51, 70).str() + "\n";
  s += "/SHELL/1\n" + Line().put(1, 1, 10).put(1, 11, 20).put(2, 21, 30).put(3, 31, 40).put(4, 41, 50).str() +
       "\n";
  s += "/PART/1\nplate\n" + Line().put(1, 1, 10).put(1, 11, 20).str() + "\n";
  s += "/PROP/SHELL/1\nshell\n\n\n" + Line().put(1.0, 21, 40).str() + "\n";
  s += "/MAT/LAW1/1\nsteel\n" + Line().put(7.85e-9, 1, 20).str() + "\n" +
       Line().put(210000.0, 1, 20).put(0.3, 21, 40).str() + "\n";
  s += "/GRNOD/NODE/1\nclamped\n" + Line().put(1, 1, 10).put(4, 11, 20).str() + "\n";
  s += "/GRNOD/NODE/2\npushed\n" + Line().put(2, 1, 10).put(3, 11, 20).str() + "\n";
  s += "/BCS/1\nclamp\n" + Line().put("   111 111", 1, 10).put(0, 11, 20).put(1, 21, 30).str() + "\n";
  s += "/BCS/2\nin plane\n" + Line().put("   011 111", 1, 10).put(0, 11, 20).put(2, 21, 30).str() + "\n";
  s += constant_impvel_and_end("X", 2, -V);
  const auto m = radx::test::model_of_deck(s);

  radx::model::RunControls rc;
  std::vector<double> steps, own;
  std::array<double, 3> pushed{};
  const auto res = run_held_at_tmin(
      m, 0.4 * a / V, &radx::model::RunControls::shell,
      [](const radx::solver::ExplicitEngine& e) { return e.groups().shells.at(0).dt[0]; }, rc, steps, own, 1,
      pushed);
  INFO(res.message);
  REQUIRE(res.status == radx::solver::RunStatus::Normal);
  CHECK(pushed[0] == Approx(a - V * rc.t_stop).epsilon(1e-9));  // pushed by 0.4 a
  for (std::size_t k = 3; k + 2 < steps.size(); ++k) {
    INFO("cycle " << k);
    CHECK(steps[k] == Approx(rc.shell.t_min).epsilon(1e-12));
    CHECK(own[k] == own[3]);
  }
}

TEST_CASE("/IMPDISP through the engine: the pulled face is at u(t) at every cycle, the balance closes",
          "[engine]") {
  // A 10 mm steel cube, its lower face fixed (/BCS 111 000), its upper face pulled along Z by
  // u(t) = 0.01 mm x t / 1e-4 s (a ramp /FUNCT): the upper nodes must sit at z0 + u(t_n) at every cycle
  // (the engine reaches the displacement at the end of each step), the lower ones at z0, and the work of
  // the imposed displacement must equal the internal + kinetic energy (1 %).
  const double a = 10.0, t_ramp = 1e-4, u_ramp = 0.01;
  std::string s = cube_text(a);
  s += "/GRNOD/NODE/1\nbottom\n" + Line().put(1, 1, 10).put(2, 11, 20).put(3, 21, 30).put(4, 31, 40).str() +
       "\n/GRNOD/NODE/2\ntop\n" + Line().put(5, 1, 10).put(6, 11, 20).put(7, 21, 30).put(8, 31, 40).str() +
       "\n/BCS/1\nfixed bottom\n" + Line().put("   111 000", 1, 10).put(0, 11, 20).put(1, 21, 30).str() +
       "\n/IMPDISP/1\npulled top\n" +
       Line().put(1, 1, 10).put("Z", 11, 20).put(0, 21, 30).put(0, 31, 40).put(2, 41, 50).str() + "\n" +
       Line().put(t_ramp, 1, 20).put(u_ramp, 21, 40).str() + "\n/FUNCT/1\nramp\n" +
       Line().put(0.0, 1, 20).put(0.0, 21, 40).str() + "\n" + Line().put(1.0, 1, 20).put(1.0, 21, 40).str() +
       "\n/END\n";
  const auto m = radx::test::model_of_deck(s);
  REQUIRE(m.imposed_velocities.size() == 1);
  REQUIRE(m.imposed_velocities[0].displacement);
  radx::model::RunControls rc;
  rc.t_stop = 2e-5;
  radx::solver::ExplicitEngine engine(m, rc, radx::solver::EngineOptions{1, 1});
  double worst = 0, last_error = 100;
  const auto res = engine.run([&](const radx::solver::CycleReport& r) {
    const auto& st = engine.nodes();
    // The state passed here is x^n at t_n (before the update of this cycle).
    for (std::size_t k = 0; k < 8; ++k) {
      const double expect = k >= 4 ? u_ramp * r.time / t_ramp : 0.0;
      worst = std::max(worst, std::abs((st.z[k] - st.z0[k]) - expect));
    }
    if (r.full) last_error = r.energy.error_percent;
    return true;
  });
  REQUIRE(res.status == radx::solver::RunStatus::Normal);
  CHECK(worst <= 1e-12 * a);  // round-off of a 10 mm coordinate
  CHECK(std::abs(last_error) < 1.0);
}

TEST_CASE("/INIVEL/ROT on a rigid body's main node gives the rigid rotation's kinetic energy", "[engine]") {
  // A 10 mm steel brick made a rigid body (ICoG 1, main node 9 at its centre, no mass of its own): its 8
  // nodes (M/8 each, no nodal inertia for brick nodes) at r_perp^2 = 50 mm^2 from the Z axis through the
  // centre, so I_zz = 50 M. /INIVEL/ROT wz = 100 rad/s on the main node: KE = 1/2 I_zz wz^2 = 25 M wz^2 at
  // cycle 0, translational (the secondaries' v = w x r) and nothing else; the spin keeps it (rigid, free).
  std::string s = radx::test::begin_block(2026, "Mg mm s") + "/NODE\n";
  for (int k = 0; k < 8; ++k) {
    const double x = (k == 1 || k == 2 || k == 5 || k == 6) ? 10.0 : 0.0;
    const double y = (k == 2 || k == 3 || k == 6 || k == 7) ? 10.0 : 0.0;
    s += Line().put(k + 1, 1, 10).put(x, 11, 30).put(y, 31, 50).put(k >= 4 ? 10.0 : 0.0, 51, 70).str() + "\n";
  }
  s += Line().put(9, 1, 10).put(5.0, 11, 30).put(5.0, 31, 50).put(5.0, 51, 70).str() + "\n";
  Line b;
  b.put(1, 1, 10);
  for (int k = 0; k < 8; ++k) b.put(k + 1, 11 + 10 * k, 20 + 10 * k);
  s += "/BRICK/1\n" + b.str() + "\n/PART/1\ncube\n" + Line().put(1, 1, 10).put(1, 11, 20).str() + "\n";
  s += "/PROP/SOLID/1\nsolid\n\n\n/MAT/LAW1/1\nsteel\n" + Line().put(7.85e-9, 1, 20).str() + "\n" +
       Line().put(210000.0, 1, 20).put(0.3, 21, 40).str() + "\n";
  s += "/GRNOD/PART/1\ncube nodes\n" + Line().put(1, 1, 10).str() + "\n";
  s += "/GRNOD/NODE/2\nmain node\n" + Line().put(9, 1, 10).str() + "\n";
  const double wz = 100.0;
  s += "/INIVEL/ROT/1\nspin\n" +
       Line().put(0.0, 1, 20).put(0.0, 21, 40).put(wz, 41, 60).put(2, 61, 70).str() + "\n";
  s += "/RBODY/1\nbody\n" + Line().put(9, 1, 10).put(1, 61, 70).put(1, 81, 90).str() + "\n\n\n/END\n";
  const auto m = radx::test::model_of_deck(s);
  REQUIRE(m.initial_velocities.size() == 1);
  REQUIRE(m.initial_velocities[0].rotational);
  const double M = 7.85e-9 * 1000.0, ke = 25.0 * M * wz * wz;
  radx::model::RunControls rc;
  rc.t_stop = 2e-5;
  radx::solver::ExplicitEngine engine(m, rc, radx::solver::EngineOptions{1, 1});
  double ke0 = -1, ke_end = -1;
  engine.run([&](const radx::solver::CycleReport& r) {
    if (r.full) {
      const double k = r.energy.kinetic_t + r.energy.kinetic_r;
      if (ke0 < 0) ke0 = k;
      ke_end = k;
    }
    return true;
  });
  CHECK(std::abs(ke0 - ke) <= 1e-9 * ke);  // the closed form, to round-off
  // A few degrees of rotation later: the rigid spin keeps its energy to the central-difference error of the
  // rotation update, far below 1e-3.
  CHECK(std::abs(ke_end - ke) <= 1e-3 * ke);
}

TEST_CASE("/ADMAS/0 adds its mass to each node, /ADMAS/1 shares it, the engine runs with it", "[engine]") {
  // A 10 mm steel cube (M = 7.85e-6 Mg, M/8 per node); /ADMAS/0 puts m0 on each of the 4 upper nodes,
  // /ADMAS/1 shares m1 over the same 4; all nodes start at vz = -1000 mm/s: the momentum is the total mass
  // times the velocity, with the added masses in it.
  const double a = 10.0, m0 = 1e-6, m1 = 2e-6, vz = -1000.0;
  std::string s = cube_text(a);
  s += "/GRNOD/NODE/2\ntop\n" + Line().put(5, 1, 10).put(6, 11, 20).put(7, 21, 30).put(8, 31, 40).str() +
       "\n/ADMAS/0/1\non each\n" + Line().put(m0, 1, 20).put(2, 21, 30).str() + "\n/ADMAS/1/2\nshared\n" +
       Line().put(m1, 1, 20).put(2, 21, 30).str() + "\n/GRNOD/PART/1\nall\n" + Line().put(1, 1, 10).str() +
       "\n/INIVEL/TRA/1\nv\n" + Line().put(0.0, 1, 20).put(0.0, 21, 40).put(vz, 41, 60).put(1, 61, 70).str() +
       "\n/END\n";
  const auto m = radx::test::model_of_deck(s);
  const double M = 7.85e-9 * a * a * a;
  REQUIRE(m.added_masses.size() == 2);
  CHECK(std::abs(m.total_mass - (M + 4 * m0 + m1)) <= 1e-12 * M);
  for (std::size_t n = 0; n < 8; ++n) {
    const double expect = M / 8 + (n >= 4 ? m0 + m1 / 4 : 0.0);
    CHECK(std::abs(m.node_mass[n] - expect) <= 1e-12 * M);
  }
  radx::model::RunControls rc;
  rc.t_stop = 1e-6;
  radx::solver::ExplicitEngine engine(m, rc, radx::solver::EngineOptions{1, 1});
  double mass0 = 0, pz = 0;
  engine.run([&](const radx::solver::CycleReport& r) {
    if (r.full) {
      mass0 = r.mass0;
      pz = r.momentum[2];
    }
    return true;
  });
  CHECK(std::abs(mass0 - (M + 4 * m0 + m1)) <= 1e-12 * M);
  CHECK(std::abs(pz - (M + 4 * m0 + m1) * vz) <= 1e-9 * std::abs(M * vz));  // free flight, no force
}

TEST_CASE("/DTIX: the first step is DT_ini, it grows by 1.1 per cycle, never above DT_max", "[engine]") {
  // A 10 mm steel cube at rest: its own step dt_e (docs/theory/elements.md 4.4) is far above both bounds
  // here.
  const auto m = cube(10.0);
  radx::model::RunControls rc;
  rc.t_stop = 2e-5;
  const double dt_e = first_step(m, rc);
  REQUIRE(dt_e > 0);
  rc.dt_initial = dt_e / 20;
  rc.dt_max = dt_e / 4;
  std::vector<double> steps;
  radx::solver::ExplicitEngine engine(m, rc, radx::solver::EngineOptions{1, 1});
  const auto res = engine.run([&](const radx::solver::CycleReport& r) {
    steps.push_back(r.dt);
    return true;
  });
  REQUIRE(res.status == radx::solver::RunStatus::Normal);
  REQUIRE(steps.size() > 30);
  CHECK(steps[0] == rc.dt_initial);
  double expect = rc.dt_initial;
  for (std::size_t k = 1; k + 2 < steps.size(); ++k) {  // the last steps: cut at Tstop, then the end
    expect = std::min(1.1 * expect, rc.dt_max);
    CHECK(std::abs(steps[k] - expect) <= 1e-12 * expect);
  }
  CHECK(*std::max_element(steps.begin(), steps.end()) <= rc.dt_max);
}

TEST_CASE("a brick whose step is 0 with a positive volume is not called inverted", "[engine]") {
  // Linear bulk viscosity qb = 1e300 (card 2 of /PROP/SOLID): the step l / (c (qb + ...)) underflows to 0
  // while the cube is whole; the stop must name the brick and the step, not an inverted mesh.
  std::string s = cube_text(10.0);
  const std::string blank_card2 = "\n\n/MAT/LAW1";
  REQUIRE(s.find(blank_card2) != std::string::npos);
  s.replace(s.find(blank_card2), blank_card2.size(),
            "\n" + Line().put(0.0, 1, 20).put("1e300", 21, 40).str() + "\n/MAT/LAW1");
  const auto m = radx::test::model_of_deck(s + "/END\n");
  radx::model::RunControls rc;
  rc.t_stop = 1e-4;
  radx::solver::ExplicitEngine engine(m, rc, radx::solver::EngineOptions{1, 1});
  const auto res = engine.run({});
  INFO(res.message);
  CHECK(res.status == radx::solver::RunStatus::Error);
  CHECK(res.message.find("brick 1 has no valid time step") != std::string::npos);
  CHECK(res.message.find("volume is positive (1000)") != std::string::npos);
  CHECK(res.message.find("inverted") == std::string::npos);
}

TEST_CASE("a run whose kinetic energy overflows stops with an error naming a node, not a normal end",
          "[engine]") {
  // Density 1e300 (a converter's placeholder): the node masses, 1e300 x 1000 mm^3 / 8 = 1.25e302, are finite
  // and so are the coordinates, but m v^2 at 1e4 mm/s, 1.25e310, is past the largest double (1.8e308). The
  // run must not end "normal" with non-finite energies.
  std::string s = cube_text(10.0);
  const std::string material = "/MAT/LAW1/1\nsteel\n";
  const auto at = s.find(material);
  REQUIRE(at != std::string::npos);
  const auto density_line = at + material.size();
  s.replace(density_line, s.find('\n', density_line) - density_line, Line().put("1e300", 1, 20).str());
  s += "/GRNOD/PART/1\nall\n" + Line().put(1, 1, 10).str() + "\n/INIVEL/TRA/1\nv\n" +
       Line().put(0.0, 1, 20).put(0.0, 21, 40).put(1e4, 41, 60).put(1, 61, 70).str() + "\n/END\n";
  const auto m = radx::test::model_of_deck(s);
  radx::model::RunControls rc;
  rc.t_stop = 1e-4;
  radx::solver::ExplicitEngine engine(m, rc, radx::solver::EngineOptions{1, 1});
  const auto res = engine.run({});
  INFO(res.message);
  CHECK(res.status == radx::solver::RunStatus::Error);
  CHECK(res.message.find("the kinetic energy is not finite (node 1: mass") != std::string::npos);
  CHECK(res.cycles == 0);  // caught at the first report, before anything else is written
}
