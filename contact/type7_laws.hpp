// The TYPE7 pair laws as pure functions (docs/theory/type7-lagdt.md 4.3 to 4.5): the hyperbolic penalty
// force, its tangent stiffness and stored energy, the VISs damping coefficient, the friction coefficient of
// each Ifric law, the friction filters and the two tangential force formulations. No state, no allocation:
// the penalty kernel calls them per pair.
#pragma once

#include <array>

namespace radx::contact {

// Normal law, x = p / g in [0, 1): F = K p g / (g - p), k_t = K (g / (g - p))^2,
// E = K g^2 (-x - ln(1 - x)). Returned for p > 0; 0 for p <= 0.
double penalty_force(double K, double g, double p);
double penalty_tangent_stiffness(double K, double g, double p);
double penalty_energy(double K, double g, double p);

// VISs damping coefficient: c = VISs sqrt(2 k m / r) + 0.32 m max(0, -v_n) / (g - p), k = K g / (g - p)
// the secant stiffness, r = (g - p) / g when approaching (v_n < 0), else 1. The damping force is c v_n.
double damping_coefficient(double vis_s, double K, double g, double p, double m, double v_n);

// Friction coefficient (4.5) for law ifric 0..3 with Fric and C1..C6, at contact pressure `pressure` and
// tangential speed `speed`.
double friction_coefficient(int ifric, double fric, const std::array<double, 6>& c, double pressure,
                            double speed);

// Filter factor alpha (clamped to [0, 1]) of Ifiltr 1..3 with Xfreq and the time step dt; 1 for Ifiltr 0.
double friction_filter_alpha(int ifiltr, double xfreq, double dt);

// Tangential force (a vector in the tangent plane, global axes) for one pair.
// Iform 1 (viscous): F_t = -min(mu |F_n|, C V) v_t / V, C = VISF sqrt(2 K m).
// Iform 2 (incremental): trial = F_t,old - K v_t dt (F_t,old already rotated into the current tangent
// plane), F_t = trial scaled down to mu |F_n| if longer.
// Then the filter: F_t = alpha F_t + (1 - alpha) F_t,previous.
struct FrictionInput {
  int iform = 1;
  double mu = 0, normal_force = 0, K = 0, mass = 0, vis_f = 1.0, dt = 0, alpha = 1.0;
  std::array<double, 3> v_t{};    // tangential relative velocity of the node with respect to the segment
  std::array<double, 3> f_old{};  // previous tangential force in the current tangent plane (Iform 2, filter)
};
std::array<double, 3> tangential_force(const FrictionInput& in);

}  // namespace radx::contact
