// The scalar force law of one spring degree of freedom, shared by the TYPE4 spring (its one axial law) and
// the TYPE8 general spring (one law per translation and rotation). OpenRadioss: redef3.F90 (H 0 and 7).
//
// With x the elongation (an angle for a rotation), x_old that of the last cycle, v = (x - x_old) / dt1:
//   f(x) = K x                                without fct_ID1
//        = f1(x / Ascale)                     with it, H = 0
//   H = 7 (elastic hysteresis between the loading curve f1 and the unloading curve f3): the trial
//        f = f_old + (K / A) (x - x_old) is bounded by the curve of the way the spring moves: while |x| grows
//        (x >= x_old in tension, x < x_old in compression) f is at most f1(x / Ascale) in tension and at
//        least f1 in compression; while |x| shrinks, f is at least f3(x / Ascale) in tension and at most f3
//        in compression. f_old is this static force of the last cycle (before the amplification).
//   a(v) = A + B ln(max(1, |v| / D)) + E g2(v / F)      (1 without fct_ID1: the starter sets A 1, B E 0)
//   N = a(v) f(x) + C v + Hscale g4(v / F)
// Failure and the work are the callers' (TYPE4 and TYPE8 test the limits differently).
#pragma once

#include <algorithm>
#include <cmath>

#include "solver/functions.hpp"
#include "solver/model/model.hpp"

namespace radx::solver {

// The curves one law names (nullptr: none), resolved from the model's functions.
struct SpringLawCurves {
  const model::Function* load = nullptr;    // fct_ID1
  const model::Function* damp = nullptr;    // fct_ID2
  const model::Function* unload = nullptr;  // fct_ID3 (H = 7)
  const model::Function* damp4 = nullptr;   // fct_ID4
};

// N of the law above; `f_static` carries the static force of H 7 from one cycle to the next.
[[nodiscard]] inline double spring_law_force(const model::SpringLaw& p, const SpringLawCurves& c, double x,
                                             double x_old, double v, double& f_static) {
  double f = p.stiffness * x;
  double amp = 1.0;
  if (c.load) {
    const double load = function_value(*c.load, x / p.ascale);
    f = load;
    if (p.hardening == 7) {
      const double unload = function_value(*c.unload, x / p.ascale);
      f = f_static + p.stiffness / p.a * (x - x_old);
      const bool growing = x >= x_old;
      if (x >= 0)
        f = growing ? std::min(f, load) : std::max(f, unload);
      else
        f = growing ? std::min(f, unload) : std::max(f, load);
    }
    f_static = f;
    amp = p.a + p.b * std::log(std::max(1.0, std::abs(v / p.d)));
    if (c.damp) amp += p.e * function_value(*c.damp, v / p.fscale);
  }
  double n = amp * f + p.damping * v;
  if (c.damp4) n += p.hscale * function_value(*c.damp4, v / p.fscale);
  return n;
}

// The stable step of one spring family (Radioss r1len3.F, r2len3.F): m / (sqrt(c^2 + m k) + c), with m the
// mass (or the inertia), k and c the largest stiffness and damping of the family's laws; +infinity when the
// family has neither.
[[nodiscard]] inline double spring_step(double m, double k, double c) {
  if (k + c < 1e-15) return 1e30;
  return m / std::max(1e-15, std::sqrt(c * c + m * std::max(k, 1e-15)) + c);
}

}  // namespace radx::solver
