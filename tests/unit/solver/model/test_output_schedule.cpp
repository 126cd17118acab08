// The next time of a periodic output schedule (solver/model/output_schedule.hpp): never a loop that cannot
// pass the current time, whatever the interval.
#include <catch2/catch.hpp>

#include <cmath>

#include "solver/model/output_schedule.hpp"

using radx::model::next_output_time;
using radx::model::time_resolution;

TEST_CASE("output schedule: the first multiple of the interval strictly after the time") {
  // Exact binary fractions: the expected times are exact, so equality is the right test.
  CHECK(next_output_time(0.0, 0.25, 0.0) == 0.25);
  CHECK(next_output_time(0.0, 0.25, 0.3) == 0.5);
  CHECK(next_output_time(0.0, 0.25, 0.5) == 0.75);  // strictly after: a time on the grid moves on
  CHECK(next_output_time(1.0, 0.5, 0.2) == 1.0);    // before the origin: the origin
  CHECK(next_output_time(1.0, 0.5, 2.75) == 3.0);
}

TEST_CASE("output schedule: decimal intervals land within one rounding of k dt") {
  // 1e-3 is not a binary fraction; the schedule is k dt up to the rounding of one product and one sum.
  for (int k = 1; k < 2000; k += 37) {
    const double t = (k - 0.5) * 1e-3;
    const double next = next_output_time(0.0, 1e-3, t);
    CHECK(next > t);
    CHECK(std::fabs(next - k * 1e-3) <= 4 * time_resolution(k * 1e-3));
  }
}

TEST_CASE("output schedule: an interval below the time resolution still advances, one double at a time") {
  // dt = 1e-30 at t = 1e-3: t + dt == t in double, so adding dt never passes t; the next output is the next
  // representable time (one per cycle), never a time at or before t.
  for (const double dt : {1e-30, 1e-300, 4.9e-324}) {
    const double t = 1e-3;
    const double next = next_output_time(0.0, dt, t);
    CHECK(next > t);
    CHECK(next == std::nextafter(t, 1.0));
  }
}

TEST_CASE("output schedule: a huge interval puts the next output far away, never at or before the time") {
  CHECK(next_output_time(0.0, 1e300, 5.0) == 1e300);
  CHECK(next_output_time(0.0, 1e308, 1e-3) == 1e308);
  // k dt overflowing to infinity falls back to the next double instead of an infinite time.
  CHECK(next_output_time(-1e308, 1e308, 1.5e308) > 1.5e308);
}

TEST_CASE("output schedule: the time resolution is the spacing of doubles at the time") {
  CHECK(time_resolution(1.0) == std::ldexp(1.0, -52));
  CHECK(time_resolution(-1.0) == std::ldexp(1.0, -52));
  CHECK(time_resolution(0.25) == std::ldexp(1.0, -54));
}
