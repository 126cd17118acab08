// When the next output of a periodic schedule falls: the first time origin + k dt (k a whole number) strictly
// after the current time t.
//
//   base = origin + dt floor((t - origin) / dt),  next = base + j dt for the least j in {0, 1, 2} with next >
//   t,
//
// and, when no such j exists, the next double after t. Two additions settle the rounding of the floor; a
// third cannot help: then dt is below the spacing of doubles at t (dt < ulp(t)), base + dt rounds back to
// base, and a loop adding dt would never pass t. Falling back to the next representable time makes such a
// schedule "every cycle", which is what an interval that small asks for; the engine deck's reader warns about
// it.
#pragma once

#include <cmath>
#include <limits>

namespace radx::model {

[[nodiscard]] inline double next_output_time(double origin, double dt, double t) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  if (t < origin) return origin;
  double next = origin + dt * std::floor((t - origin) / dt);
  for (int j = 0; j < 3 && std::isfinite(next) && next <= t; ++j) next += dt;
  return std::isfinite(next) && next > t ? next : std::nextafter(t, kInf);
}

// The spacing of doubles at |t|: an interval below it cannot advance a time near t.
[[nodiscard]] inline double time_resolution(double t) {
  const double a = std::fabs(t);
  return std::nextafter(a, std::numeric_limits<double>::infinity()) - a;
}

}  // namespace radx::model
