// The scalar force law of one spring degree of freedom, shared by the TYPE4 spring (its one axial law) and
// the TYPE8 general spring (one law per translation and rotation). OpenRadioss: redef3.F90 (read for the
// behaviour of each hardening flag H).
//
// x the elongation (an angle for a rotation), x_old that of the last cycle, dx = x - x_old,
// v = dx / dt1, f_old the static force of the last cycle (before the amplification a(v)), K = K_deck / A
// (the starter divides the stiffness by A, so that A K is the stiffness of the amplified force),
// f1(q) = fct_ID1(q / Ascale), f3 = fct_ID3. Without fct_ID1 every H is the linear f = K x.
//   H = 0  nonlinear elastic:      f = f1(x)
//   H = 1  elasto-plastic, isotropic hardening (tension and compression coupled); p >= 0 the accumulated
//          plastic elongation:
//            trial t = f_old + K dx;  q = p + t / K (t >= 0) or -p + t / K (t < 0);  y = f1(q)
//            t >= 0 and t > y, or t < 0 and t < y:  f = y,  p += |t - y| / K;  else f = t
//          Loading follows f1; unloading and reloading are elastic with slope K up to the largest force
//          reached; the yield in the other direction is at the force f1(p + |f| / K), so it grows with all
//          the plastic elongation of both directions.
//   H = 2  elasto-plastic, uncoupled: p_t >= 0 and p_c <= 0 the plastic elongations of tension and of
//          compression, each with its own yield on f1:
//            x > p_t:  f = min(K (x - p_t), f1(x)),  p_t = x - f / K
//            x < p_c:  f = max(K (x - p_c), f1(x)),  p_c = x - f / K
//            otherwise f = 0 (the spring is slack between the two plastic elongations)
//   H = 4  elasto-plastic, kinematic hardening: f1 the upper and f3 the lower yield curve, of x:
//            f = max(min(f_old + K dx, f1(x)), f3(x))
//   H = 5  nonlinear elastic-plastic with a residual elongation: x_t >= 0, x_c <= 0 the extremes of x
//          reached in tension and compression, f3(x_ext / Ascale) the residual elongation after the extreme
//          x_ext. In tension (compression is the mirror with x_c):
//            x > x_t:  f = f1(x), x_t = x                                        (loading)
//            0 < x <= x_t: r = max(f3(x_t / Ascale), 0);  when x > r and f1(x_t) != 0:
//              F = Ascale f1(x_t / Ascale),  r = min(r, x_t - F / K),  s = (x - r) / (x_t - r),
//              b = (x_t - r) K / F  (>= 1),
//              f = min(max(f_old + K dx, F s^b, 0), F s, f1(x))
//              (unloading follows the power curve F s^b, which leaves (x_t, F) with slope K and reaches 0
//              at the residual elongation r; reloading climbs with K to the chord F s back to (x_t, F));
//              when x <= r: f = 0
//          Radioss multiplies F by Ascale (its f1(x_t) / lscale, lscale = 1 / Ascale): kept as it runs.
//          At x = 0 exactly the force of the last cycle is kept (Radioss assigns none).
//   H = 6  elasto-plastic, isotropic, with a nonlinear unloading: Y >= 0 the yield force (the largest |f|
//          reached, 0 at the start), T the accumulated |dx| while yielding, k3 the slope of the segment of
//          f3 whose ordinates hold f_old (the first or last segment's slope beyond the curve's forces; 0
//          when none holds it, as in Radioss):
//            trial t = f_old + k3 dx;  q = T + dx (t >= 0) or -T + dx (t < 0)
//            t >= 0 and t > Y, or t < 0 and t < -Y:  f = f1(q), Y = |f|, T += |dx|;  else f = t
//          So loading follows f1 of the travel, unloading follows the shape of f3 shifted to pass through
//          the point of unloading, and yield in either direction resumes at the largest force reached.
//   H = 7  elastic hysteresis between the loading curve f1 and the unloading curve f3: the trial
//          f = f_old + K dx is bounded by the curve of the way the spring moves: while |x| grows
//          (x >= x_old in tension, x < x_old in compression) f is at most f1(x) in tension and at least f1 in
//          compression; while |x| shrinks, f is at least f3(x / Ascale) in tension and at most f3 in
//          compression.
//   H = 8  nonlinear elastic of the total length l: f = f1(l / Ascale) (the caller gives l; TYPE4 only).
//   a(v) = A + B ln(max(1, |v| / D)) + E g2(v / F)      (1 without fct_ID1: the starter sets A 1, B E 0)
//   N = a(v) f + C v + Hscale g4(v / F)
// The time step uses K (the caller's); H 6's unloading slope k3 comes from f3 and is not checked against it,
// as in Radioss. Failure and the work are the callers' (TYPE4 and TYPE8 test the limits differently).
#pragma once

#include <algorithm>
#include <cmath>

#include "solver/conditions/functions.hpp"
#include "solver/model/model.hpp"

namespace radx::solver {

// The curves one law names (nullptr: none), resolved from the model's functions.
struct SpringLawCurves {
  const model::Function* load = nullptr;    // fct_ID1
  const model::Function* damp = nullptr;    // fct_ID2
  const model::Function* unload = nullptr;  // fct_ID3 (H = 4, 5, 6, 7)
  const model::Function* damp4 = nullptr;   // fct_ID4
};

// What one law carries from one cycle to the next (all 0 at the start).
struct SpringLawState {
  double f_static = 0;   // f of the last cycle, before the amplification a(v)
  double plastic = 0;    // H 1: accumulated plastic elongation p; H 2: p_t; H 5: x_t
  double plastic_c = 0;  // H 2: p_c; H 5: x_c
  double yield = 0;      // H 6: Y
  double travel = 0;     // H 6: T
};

namespace spring_law_detail {
// H 6's unloading slope: that of the segment of `c` whose ordinates hold f (y_i <= f < y_{i+1}); beyond the
// curve's forces the first or last segment's; 0 otherwise.
[[nodiscard]] inline double slope_at_force(const model::Function& c, double f) {
  const std::size_t n = std::min(c.x.size(), c.y.size());
  if (n < 2) return 0.0;
  for (std::size_t k = 0; k + 1 < n; ++k)
    if (f < c.y[k + 1] && f >= c.y[k]) return (c.y[k + 1] - c.y[k]) / (c.x[k + 1] - c.x[k]);
  if (f > c.y[n - 1]) return (c.y[n - 1] - c.y[n - 2]) / (c.x[n - 1] - c.x[n - 2]);
  if (f < c.y[0]) return (c.y[1] - c.y[0]) / (c.x[1] - c.x[0]);
  return 0.0;
}

// H 5 on one side, written for tension (sg = 1) and mirrored for compression (sg = -1): x, the extreme x_e
// and every force are multiplied by sg so that the tension formulas serve both.
[[nodiscard]] inline double residual_branch(const model::SpringLaw& p, const SpringLawCurves& c, double k,
                                            double sg, double x, double dx, double f_old, double x_e) {
  const double r3 = function_value(*c.unload, x_e / p.ascale);
  double r = std::max(sg * r3, 0.0);
  const double f1e = function_value(*c.load, x_e / p.ascale);
  if (!(sg * x > r) || f1e == 0) return 0.0;
  const double fm = sg * f1e * p.ascale;
  const double xe = sg * x_e, xs = sg * x;
  r = std::min(r, xe - fm / k);
  const double s = (xs - r) / (xe - r);
  const double b = (xe - r) * k / fm;
  double f = sg * f_old + k * sg * dx;
  f = std::max({f, fm * std::pow(s, b), 0.0});
  f = std::min({f, fm * s, sg * function_value(*c.load, x / p.ascale)});
  return sg * f;
}
}  // namespace spring_law_detail

// N of the law above. `length`: the spring's total length (H 8 only).
[[nodiscard]] inline double spring_law_force(const model::SpringLaw& p, const SpringLawCurves& c, double x,
                                             double x_old, double v, double length, SpringLawState& s) {
  double f = p.stiffness * x;
  double amp = 1.0;
  if (c.load) {
    const double k = p.stiffness / p.a;
    const double dx = x - x_old;
    auto f1 = [&](double q) { return function_value(*c.load, q / p.ascale); };
    switch (p.hardening) {
      case 1: {
        const double t = s.f_static + k * dx;
        const double y = f1((t >= 0 ? s.plastic : -s.plastic) + t / k);
        f = t;
        if ((t >= 0 && t > y) || (t < 0 && t < y)) {
          s.plastic += std::abs(t - y) / k;
          f = y;
        }
        break;
      }
      case 2:
        if (x > s.plastic) {
          f = std::min(k * (x - s.plastic), f1(x));
          s.plastic = x - f / k;
        } else if (x < s.plastic_c) {
          f = std::max(k * (x - s.plastic_c), f1(x));
          s.plastic_c = x - f / k;
        } else {
          f = 0.0;
        }
        break;
      case 4:
        f = std::max(std::min(s.f_static + k * dx, f1(x)), function_value(*c.unload, x / p.ascale));
        break;
      case 5:
        if (x > s.plastic) {
          f = f1(x);
          s.plastic = x;
        } else if (x > 0) {
          f = spring_law_detail::residual_branch(p, c, k, 1.0, x, dx, s.f_static, s.plastic);
        } else if (x < s.plastic_c) {
          f = f1(x);
          s.plastic_c = x;
        } else if (x < 0) {
          f = spring_law_detail::residual_branch(p, c, k, -1.0, x, dx, s.f_static, s.plastic_c);
        } else {
          f = s.f_static;
        }
        break;
      case 6: {
        const double t = s.f_static + spring_law_detail::slope_at_force(*c.unload, s.f_static) * dx;
        f = t;
        if ((t >= 0 && t > s.yield) || (t < 0 && t < -s.yield)) {
          f = f1((t >= 0 ? s.travel : -s.travel) + dx);
          s.yield = std::abs(f);
          s.travel += std::abs(dx);
        }
        break;
      }
      case 7: {
        const double load = f1(x), unload = function_value(*c.unload, x / p.ascale);
        f = s.f_static + k * dx;
        const bool growing = x >= x_old;
        if (x >= 0)
          f = growing ? std::min(f, load) : std::max(f, unload);
        else
          f = growing ? std::min(f, unload) : std::max(f, load);
        break;
      }
      case 8: f = f1(length); break;
      default: f = f1(x); break;
    }
    s.f_static = f;
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
