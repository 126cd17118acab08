// TYPE7 pair laws (docs/theory/type7-lagdt.md 4.3 to 4.5), per pair, no state:
//
// Normal penalty, 4.3, with p the penetration into the gap g and x = p / g in [0, 1):
//   F_n = K p g / (g - p)                      force along the contact normal
//   k_t = dF_n/dp = K (g / (g - p))^2          tangent stiffness (time step)
//   E_c = K g^2 (-x - ln(1 - x))               stored energy, the integral of F_n from 0 to p
// All three are 0 for p <= 0 (pair open) and +infinity for p >= g: the law has a pole at p = g, which
// the penalty kernel never reaches (it deactivates or switches a pair whose (g - p)/g falls below 1e-6).
//
// Damping, 4.3, with the secant stiffness k = K g / (g - p), m the secondary nodal mass and v_n the
// normal relative velocity (negative when approaching):
//   c = VISs sqrt(2 k m / r) + 0.32 m max(0, -v_n) / (g - p),  r = (g - p)/g if v_n < 0, else 1.
//
// Friction coefficient, 4.5, with the contact pressure P and the tangential speed V:
//   Ifric 0  mu = Fric
//   Ifric 1  mu = Fric + C1 P + C2 V + C3 P V + C4 P^2 + C5 V^2
//   Ifric 2  mu = C1 exp(C2 V) P^2 + C3 exp(C4 V) P + C5 exp(C6 V)
//   Ifric 3  (Renard) C1 = mu_s, C2 = mu_d, C3 = mu_max, C4 = mu_min, C5 = V_cr1, C6 = V_cr2:
//            V <= C5:       mu = C1 + (C3 - C1) (V/C5) (2 - V/C5)
//            C5 < V < C6:   mu = C3 - (C3 - C4) s^2 (3 - 2 s),  s = (V - C5)/(C6 - C5)
//            V >= C6:       mu = C2 - 1 / (1/(C2 - C4) + (V - C6)^2)
//            (value and slope are continuous at C5 and C6.)
//
// Friction filter, 4.5: alpha = 1 (Ifiltr 0), Xfreq (1), 2 pi Xfreq (2), 2 pi Xfreq dt (3), clamped to
// [0, 1]; the filtered force is alpha F_t + (1 - alpha) F_t,previous.
//
// Tangential force, 4.5, opposite to the tangential relative velocity v_t (V = |v_t|), capped by mu |F_n|:
//   Iform 1 (viscous, total):        F_t = -min(mu |F_n|, C V) v_t / V,  C = VISF sqrt(2 K m)
//   Iform 2 (stiffness, incremental): trial = F_t,old - K v_t dt, scaled back to mu |F_n| if longer.
#include "contact/type7_laws.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace radx::contact {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// -x - ln(1 - x) for x in [0, 1). For small x the two terms cancel to x^2/2 + x^3/3 + ..., and the
// direct difference would lose about log10(1/x) digits; the series keeps full relative precision there.
double hyperbolic_energy_factor(double x) {
  if (x < 0.05) {
    // Terms fall by at least a factor 20 each: 14 terms leave a relative error below 1e-17.
    double term = x * x, sum = 0;
    for (int k = 2; k < 16; ++k) {
      sum += term / k;
      term *= x;
    }
    return sum;
  }
  return -x - std::log1p(-x);
}

}  // namespace

double penalty_force(double K, double g, double p) {
  if (p <= 0) return 0;
  if (p >= g) return kInfinity;
  return K * p * g / (g - p);
}

double penalty_tangent_stiffness(double K, double g, double p) {
  if (p <= 0) return 0;
  if (p >= g) return kInfinity;
  const double ratio = g / (g - p);
  return K * ratio * ratio;
}

double penalty_energy(double K, double g, double p) {
  if (p <= 0) return 0;
  if (p >= g) return kInfinity;
  return K * g * g * hyperbolic_energy_factor(p / g);
}

double damping_coefficient(double vis_s, double K, double g, double p, double m, double v_n) {
  if (p <= 0) return 0;
  if (p >= g) return kInfinity;
  const double remaining = g - p;
  const double k_secant = K * g / remaining;
  // Approaching, the linear term is raised by 1/sqrt(r) so that the damping keeps pace with the
  // stiffening law as the gap closes; separating, it is the plain critical-damping fraction.
  const double r = v_n < 0 ? remaining / g : 1.0;
  const double linear = vis_s * std::sqrt(2 * k_secant * m / r);
  const double quadratic = 0.32 * m * std::max(0.0, -v_n) / remaining;
  return linear + quadratic;
}

double friction_coefficient(int ifric, double fric, const std::array<double, 6>& c, double pressure,
                            double speed) {
  const double P = pressure, V = speed;
  switch (ifric) {
    case 1: return fric + c[0] * P + c[1] * V + c[2] * P * V + c[3] * P * P + c[4] * V * V;
    case 2:
      return c[0] * std::exp(c[1] * V) * P * P + c[2] * std::exp(c[3] * V) * P + c[4] * std::exp(c[5] * V);
    case 3: {
      const double mu_s = c[0], mu_d = c[1], mu_max = c[2], mu_min = c[3], v1 = c[4], v2 = c[5];
      if (V <= v1) {
        const double u = V / v1;
        return mu_s + (mu_max - mu_s) * u * (2 - u);
      }
      if (V < v2) {
        const double s = (V - v1) / (v2 - v1);
        return mu_max - (mu_max - mu_min) * s * s * (3 - 2 * s);
      }
      // mu_d == mu_min gives 1/0 = +inf and mu = mu_d, the limit of the formula.
      const double dv = V - v2;
      return mu_d - 1 / (1 / (mu_d - mu_min) + dv * dv);
    }
    default: return fric;  // Ifric 0; the starter rejects other values
  }
}

double friction_filter_alpha(int ifiltr, double xfreq, double dt) {
  double alpha = 1;
  switch (ifiltr) {
    case 1: alpha = xfreq; break;
    case 2: alpha = 2 * std::numbers::pi * xfreq; break;
    case 3: alpha = 2 * std::numbers::pi * xfreq * dt; break;
    default: break;  // Ifiltr 0: no filter
  }
  return std::clamp(alpha, 0.0, 1.0);
}

std::array<double, 3> tangential_force(const FrictionInput& in) {
  const auto& v = in.v_t;
  const double speed = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  // A law that yields mu < 0 (Darmstad with negative coefficients) would make friction push the
  // sliding; the cap is kept at 0 instead.
  const double cap = std::max(0.0, in.mu) * std::abs(in.normal_force);
  std::array<double, 3> f{};
  if (in.iform == 2) {
    for (int k = 0; k < 3; ++k) f[k] = in.f_old[k] - in.K * v[k] * in.dt;
    const double trial = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    if (trial > cap) {
      const double scale = trial > 0 ? cap / trial : 0.0;
      for (auto& fk : f) fk *= scale;
    }
  } else if (speed > 0) {
    const double viscous = in.vis_f * std::sqrt(2 * in.K * in.mass) * speed;
    const double magnitude = std::min(cap, viscous);
    for (int k = 0; k < 3; ++k) f[k] = -magnitude * v[k] / speed;
  }
  // alpha = 1 (no filter) returns f unchanged: 1 * f + 0 * f_old is exact.
  for (int k = 0; k < 3; ++k) f[k] = in.alpha * f[k] + (1 - in.alpha) * in.f_old[k];
  return f;
}

}  // namespace radx::contact
