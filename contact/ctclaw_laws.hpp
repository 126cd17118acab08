// The /CTCLAW contact and friction law family (docs/theory/contact-laws.md) as pure functions: a normal law
// gives the contact pressure and its tangent stiffness density at an overclosure, a friction law the
// tangential force of one pair. No state, no allocation: the penalty kernel and the Lagrange-multiplier
// friction call them per pair, with the law resolved for the pair's stiffness and area (PairLaw).
#pragma once

#include <array>
#include <limits>
#include <span>

#include "solver/model/model.hpp"

namespace radx::contact {

// P (Pa) and Kc = dP/du (Pa/m) at one overclosure u (m, positive when the surfaces overlap).
struct Pressure {
  double p = 0;
  double kc = 0;
};

// A law's parameters for one pair, with what depends on the pair resolved: the automatic stiffness density
// Kc_auto = K / A_s (Kc = -1, lambda from pe, default kappa) and the curve's points.
struct PairLaw {
  model::NormalLaw normal = model::NormalLaw::Interface;
  model::FrictionLaw friction = model::FrictionLaw::Interface;
  bool bidirectional = false;
  double kc = 0;                                            // Linear
  double pz = 0, lambda = 0;                                // Exponential
  double kc_max = 0;                                        // Exponential: KcMax (0: none)
  double u_knee = std::numeric_limits<double>::infinity();  // and its overclosure (+inf without KcMax)
  std::span<const double> gap, pressure;  // Tabulated: the curve's abscissas (gap = -u) and pressures
  bool cubic = false;
  std::span<const double> power_m, power_k;  // Power
  double mu = 0, ct = 0, kappa = 0;          // friction; kappa in Pa/m
};

// The law of a pair with penalty stiffness K (N/m) and tributary area A_s (m^2) > 0.
PairLaw resolve_pair_law(const model::ContactLaw& law, const model::Model& m, double K, double area);

// lambda of an exponential law given by pe: Kc_auto / pe; u_knee of a law with KcMax:
// ln(KcMax / (pz lambda)) / lambda (+inf without KcMax).
double exponential_lambda(double kc_auto, double pe);
double exponential_knee(double pz, double lambda, double kc_max);

// The normal laws of docs/theory/contact-laws.md section 2.
Pressure linear_pressure(double kc, double u);
Pressure exponential_pressure(double pz, double lambda, double kc_max, double u_knee, double u);
Pressure tabulated_pressure(std::span<const double> gap, std::span<const double> pressure, bool cubic,
                            double u);
Pressure power_pressure(std::span<const double> m, std::span<const double> kpm, double u);
// The one of the pair's law (normal != Interface).
Pressure normal_pressure(const PairLaw& law, double u);

// The overclosure below which the pair's law gives no contact: 0 for the laws that vanish there (linear,
// power, a table whose pressure reaches 0), the cut-off P = 1e-12 pz of the exponential law, the gap where
// a table's extrapolation reaches 0 (-inf when it never does: the search margin bounds it).
double contact_onset(const PairLaw& law);

// The friction magnitude |F_t| / A_s (Pa) of a regularised law at slip speed s >= 0 and pressure p >= 0
// (Linear: min(ct s, mu p); Arctangent: mu p (2/pi) atan(ct s); ScaledLinear: p min(ct s, mu)); for the
// exact Coulomb law its sliding value mu p.
double friction_traction(const PairLaw& law, double slip_speed, double pressure);

// The tangential force on the secondary node of one penalty pair, global axes.
// w: the tangential relative velocity; n: the contact normal; t1: the segment's first tangent (unit, in the
// tangent plane), to which s1..s4 restrict the slip; f_old: the previous force already rotated into the
// current tangent plane (Coulomb's sticking spring); area A_s; dt the step; mobility 1 / m_slip (1/kg), the
// change of the relative tangential velocity per unit force on the pair (0: none bounds the force).
//   Coulomb: trial = f_old - kappa A_s w dt, scaled back to mu p A_s when longer;
//   regularised: -min(friction_traction(|w|, p) A_s, |w| / (mobility dt)) e, e = w / |w|: never more than
//   what stops the slip within the step, so a steep law cannot overshoot and sets no step.
struct LawFrictionInput {
  std::array<double, 3> w{}, n{}, t1{}, f_old{};
  double pressure = 0, area = 0, dt = 0;
  double mobility = 0;
};
std::array<double, 3> law_friction_force(const PairLaw& law, const LawFrictionInput& in);

}  // namespace radx::contact
