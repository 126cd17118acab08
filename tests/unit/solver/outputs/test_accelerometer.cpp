// /ACCEL (solver/outputs/accelerometer.cpp): the reading of a node under constant acceleration, the
// integrated velocity, the skew axes, and the 4-pole Butterworth filter's gain (-3 dB at Fcut, -80 dB a
// decade above).
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "solver/engine/explicit_engine.hpp"
#include "solver/outputs/accelerometer.hpp"
#include "solver/outputs/time_history_values.hpp"
#include "test_util.hpp"

using radx::test::Line;
namespace m = radx::model;
namespace sv = radx::solver;

namespace {

// The steady amplitude of the filtered signal for a unit sine of frequency f sampled every dt.
double filtered_amplitude(double fcut, double f, double dt) {
  m::Model md;
  md.nodes.id = {1};
  md.nodes.x = md.nodes.y = md.nodes.z = {0.0};
  m::Accelerometer a;
  a.id = 1;
  a.node = 0;
  a.fcut = fcut;
  md.accelerometers.push_back(a);
  sv::NodeState s;
  s.resize(1);
  const sv::SkewFrames frames(md);
  sv::Accelerometers acc(md, frames);
  // The slowest pole decays as exp(-sin(pi/8) 2 pi fcut t): after 20 / fcut the start transient is down
  // by exp(-48); the peak is read over the last 5 periods.
  const int n = static_cast<int>(std::max(40.0 / f, 20.0 / fcut) / dt);
  const int tail = static_cast<int>(5.0 / (f * dt));
  double peak = 0;
  for (int k = 0; k < n; ++k) {
    s.ax[0] = std::sin(2 * std::numbers::pi * f * k * dt);
    acc.update(s, dt, dt);
    if (k > n - tail) peak = std::max(peak, std::abs(acc.readings()[0].acceleration[0]));
  }
  return peak;
}

// A free 10 mm steel cube (nodes 1-8, node 5 at (0, 0, 10)), without /END.
std::string falling_cube() {
  const double a = 10.0;
  std::string s = radx::test::begin_block(2026, "Mg mm s") + "/NODE\n";
  for (int k = 0; k < 8; ++k) {
    const double x = (k == 1 || k == 2 || k == 5 || k == 6) ? a : 0.0;
    const double y = (k == 2 || k == 3 || k == 6 || k == 7) ? a : 0.0;
    s += Line().put(k + 1, 1, 10).put(x, 11, 30).put(y, 31, 50).put(k >= 4 ? a : 0.0, 51, 70).str() + "\n";
  }
  Line b;
  b.put(1, 1, 10);
  for (int k = 0; k < 8; ++k) b.put(k + 1, 11 + 10 * k, 20 + 10 * k);
  s += "/BRICK/1\n" + b.str() + "\n/PART/1\ncube\n" + Line().put(1, 1, 10).put(1, 11, 20).str() + "\n";
  s += "/PROP/SOLID/1\nsolid\n\n\n/MAT/LAW1/1\nsteel\n" + Line().put(7.85e-9, 1, 20).str() + "\n" +
       Line().put(210000.0, 1, 20).put(0.3, 21, 40).str() + "\n";
  return s;
}

m::RunControls cube_controls(double t_stop) {
  m::RunControls rc;
  rc.t_stop = t_stop;
  // A lone one-point brick is unstable at its own step (docs/theory/elements.md 9: its checkerboard mode's
  // frequency is above 2 c / L): half the step keeps the cube rigid for the milliseconds the filter needs.
  rc.global.scale = 0.45;
  return rc;
}

}  // namespace

TEST_CASE("accelerometer filter: -3 dB at the cut-off, -80 dB a decade above, unit gain at low frequency",
          "[accel]") {
  const double dt = 1e-6, fcut = 1000.0;
  // Bilinear transform with pre-warping: the -3 dB point is exactly Fcut; the sampled peak of a sine with
  // 1000 samples a period is within 1e-5 of its amplitude.
  CHECK(std::abs(filtered_amplitude(fcut, fcut, dt) - std::sqrt(0.5)) <= 1e-3);
  // Butterworth of order 4: |H| = 1 / sqrt(1 + (f / fc)^8): 1e-4 at ten times Fcut (the warping at
  // f dt = 1e-2 changes it by under 1 %).
  CHECK(std::abs(filtered_amplitude(fcut, 10 * fcut, dt) / 1e-4 - 1.0) <= 0.02);
  CHECK(std::abs(filtered_amplitude(fcut, 0.1 * fcut, dt) - 1.0) <= 1e-3);
}

TEST_CASE("an accelerometer on a free-falling cube reads g on its skew axes, and integrates the velocity",
          "[accel][engine]") {
  // A 10 mm steel cube falls under g = 9810 mm/s^2 along -X: every node accelerates at a = (-g, 0, 0)
  // (no deformation). Skew 5 has Y' = (1, 1, 0)/sqrt2 and Z' = Z, so x' = Y' x Z' = (1, -1, 0)/sqrt2:
  // on its axes a reads (a.x', a.y', a.z') = (-g/sqrt2, -g/sqrt2, 0) (the transposed rotation would give
  // +g/sqrt2 on y'). Accelerometer 1 (node 5, skew 5, Fcut 2 kHz) reads that once the filter's start
  // transient has died (20 periods), on every cycle to the last; accelerometer 2 (global axes, no filter)
  // reads -g on X at every cycle; W is the velocity change, -g t to one step, on the skew's axes.
  const double g = 9810.0, r2 = std::sqrt(0.5);
  std::string s = falling_cube();
  s += "/GRAV/1\ng\n" + Line().put(0, 1, 10).put("X", 11, 20).put(0.0, 61, 80).put(-g, 81, 100).str() + "\n";
  s += "/SKEW/FIX/5\nrotated\n" + Line().put(0.0, 1, 20).str() + "\n" +
       Line().put(1.0, 1, 20).put(1.0, 21, 40).put(0.0, 41, 60).str() + "\n" +
       Line().put(0.0, 1, 20).put(0.0, 21, 40).put(1.0, 41, 60).str() + "\n";
  s += "/ACCEL/1\nfiltered, skew\n" + Line().put(5, 1, 10).put(5, 11, 20).put(2000.0, 31, 50).str() + "\n";
  s += "/ACCEL/2\nraw, global\n" + Line().put(5, 1, 10).str() + "\n";
  s += "/TH/ACCEL/7\nboth\n" + Line().put("DEF", 1, 10).put("W", 11, 20).str() + "\n" +
       Line().put(2, 1, 10).put(1, 11, 20).str() + "\n/END\n";
  const auto md = radx::test::model_of_deck(s);
  REQUIRE(md.accelerometers.size() == 2);
  REQUIRE(md.time_histories.size() == 1);
  const auto& th = md.time_histories[0];
  REQUIRE(th.kind == m::ThKind::Accel);
  // DEF is the accelerations, W the velocities (OpenRadioss's sets); the objects keep the deck's order.
  REQUIRE(th.variables == std::vector<std::string>{"AX", "AY", "AZ", "WX", "WY", "WZ"});
  sv::ExplicitEngine engine(md, cube_controls(1e-2), sv::EngineOptions{1, 1});
  sv::ThGroupSampler sampler(engine, th);
  std::vector<double> sampled(sampler.size());
  // The falling cube's strains are round-off (1e-16), their forces 1e-6 of m g at most: 1e-5 g.
  const double tol = 1e-5 * g;
  double worst_raw = 0, worst_filtered_late = 0, t_last = 0;
  engine.run([&](const sv::CycleReport& r) {
    sampler.sample(engine, r, sampled);
    const auto& raw = engine.accelerometers().readings()[1];
    worst_raw = std::max(worst_raw, std::abs(raw.acceleration[0] + g));
    const auto& f = engine.accelerometers().readings()[0];
    if (r.time > 20.0 / 2000.0 * 0.5)  // after 10 filter periods the transient is below exp(-24)
      worst_filtered_late = std::max({worst_filtered_late, std::abs(f.acceleration[0] + g * r2),
                                      std::abs(f.acceleration[1] + g * r2), std::abs(f.acceleration[2])});
    t_last = r.time;
    return true;
  });
  CHECK(worst_raw <= tol);
  // Every late cycle, the last one (where the next step is 0) included, reads the filtered value.
  CHECK(worst_filtered_late <= tol);
  const auto& f = engine.accelerometers().readings()[0];
  // W sums dt12 a over the cycles: dt2/2 on the first, (dt1 + dt2)/2 after, dt1/2 on the last (its dt2 is
  // 0), which adds up to t_n: W = -g t_n on x' and y' (times sqrt 1/2), to round-off.
  const double w = -g * t_last * r2;
  CHECK(std::abs(f.velocity[0] - w) <= 1e-6 * g * t_last);
  CHECK(std::abs(f.velocity[1] - w) <= 1e-6 * g * t_last);
  CHECK(std::abs(f.velocity[2]) <= 1e-6 * g * t_last);
  // The time history holds object 2 (accelerometer 2: raw) first, then object 1, as the deck lists them.
  REQUIRE(sampled.size() == 12u);
  CHECK(std::abs(sampled[0] + g) <= tol);      // AX of accelerometer 2
  CHECK(sampled[6 + 1] == f.acceleration[1]);  // AY of accelerometer 1, filtered
  CHECK(sampled[6 + 3] == f.velocity[0]);      // WX of accelerometer 1
}

TEST_CASE("the accelerometer filter holds to the last cycle of the run, where the next step is 0",
          "[accel][engine]") {
  // The cube falls under a(t) = -g sin(2 pi f t) along X with f = 2 kHz, ten times the 200 Hz cut-off: the
  // filtered reading's amplitude is g / sqrt(1 + 10^8) = 1e-4 g. The run stops at 40.25 periods, where the
  // raw signal is at its peak g: a reading that fell back to the raw signal there would read g.
  const double g = 9810.0, f = 2000.0, fcut = 200.0, pi = std::numbers::pi;
  std::string s = falling_cube();
  s += "/FUNCT/3\nsine\n";
  const int per_period = 64, periods = 42;
  for (int k = 0; k <= per_period * periods; ++k) {
    const double t = k / (f * per_period);
    s += Line().put(t, 1, 20).put(std::sin(2 * pi * f * t), 21, 40).str() + "\n";
  }
  s += "/GRAV/1\ng\n" + Line().put(3, 1, 10).put("X", 11, 20).put(0.0, 61, 80).put(-g, 81, 100).str() + "\n";
  s += "/ACCEL/1\nfiltered\n" + Line().put(5, 1, 10).put(0, 11, 20).put(fcut, 31, 50).str() + "\n/END\n";
  const auto md = radx::test::model_of_deck(s);
  const double t_stop = 40.25 / f;
  sv::ExplicitEngine engine(md, cube_controls(t_stop), sv::EngineOptions{1, 1});
  double worst_late = 0, raw_last = 0, t_last = 0;
  engine.run([&](const sv::CycleReport& r) {
    // The start transient decays as exp(-sin(pi/8) 2 pi fcut t): after 15 ms, by 7e-4 from at most 0.1 g.
    if (r.time > 15e-3)
      worst_late = std::max(worst_late, std::abs(engine.accelerometers().readings()[0].acceleration[0]));
    raw_last = engine.nodes().ax[4];
    t_last = r.time;
    return true;
  });
  REQUIRE(t_last == Approx(t_stop).epsilon(1e-12));
  CHECK(std::abs(raw_last) >= 0.99 * g);  // the last cycle sits on the raw peak
  // 1e-4 g of steady amplitude, 1e-4 g of decayed transient, and the corners of the piecewise-linear sine
  // (harmonics near 64 f, filtered far below): 1e-3 g.
  CHECK(worst_late <= 1e-3 * g);
}
