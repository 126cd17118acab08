// The /CTCLAW law family (docs/theory/contact-laws.md sections 2 and 3), per pair, no state.
//
// u: overclosure (m), positive when the surfaces overlap (u = p, the penetration into the TYPE7 gap). Each
// normal law returns P(u) >= 0 (Pa) and Kc(u) = dP/du (Pa/m); the pair's force is P A_s and its stiffness
// Kc A_s, A_s the tributary area of the secondary node.
//   1 linear       P = Kc u for u > 0, else 0;           Kc = Kc (u > 0), else 0.
//                  Kc = -1: Kc = K / A_s, the interface's penalty stiffness spread over the node's area.
//   2 exponential  P = pz exp(lambda u);                 Kc = lambda pz exp(lambda u), for every u;
//                  lambda = Kc_auto / pe when pe is given (Kc_auto = K / A_s);
//                  with KcMax, beyond u_knee = ln(KcMax / (pz lambda)) / lambda the law goes on linearly:
//                  P = KcMax / lambda + KcMax (u - u_knee), Kc = KcMax (P(u_knee) = KcMax / lambda);
//                  below P = 1e-12 pz (u < ln(1e-12) / lambda) there is no contact.
//   3 tabulated    a curve of (gap g_k, P_k), g = -u, gaps increasing and pressures not increasing:
//                  linear: P = P_k + (P_k+1 - P_k) (g - g_k) / (g_k+1 - g_k) on the bracketing segment,
//                  Kc = -(P_k+1 - P_k) / (g_k+1 - g_k); outside the table along the first or last segment;
//                  cubic: the monotone piecewise cubic Hermite interpolant (Fritsch and Carlson) with
//                  tangents m_k = 0 where the secants d_k-1, d_k change sign or one is 0, else the weighted
//                  harmonic mean (w1 + w2) / (w1 / d_k-1 + w2 / d_k), w1 = 2 h_k + h_k-1,
//                  w2 = h_k + 2 h_k-1 (h the segment lengths), and the end secants at both ends, so that it
//                  joins the linear extrapolation with a continuous slope; Kc = -dP/dg of the cubic.
//                  P is clamped at 0 where the extrapolation would go negative (no tension).
//   4 power        P = sum_m kp_m u^m for u > 0, else 0;  Kc = sum_m m kp_m u^(m-1).
//
// Friction (section 3), s = |w| the tangential slip speed, e = w / s, p the contact pressure:
//   1, 11 Coulomb          sliding |F_t| = mu p A_s; sticking by the tangential spring kappa A_s:
//                          trial = F_t,old - kappa A_s w dt, scaled back to mu p A_s when longer
//                          (kappa = K / A_s unless given, the normal penalty stiffness);
//   2, 12 linear           F_t = -min(ct s, mu p) A_s e;
//   3, 13 arctangent       F_t = -mu p (2/pi) atan(ct s) A_s e;
//   4, 14 scaled linear    F_t = -p min(ct s, mu) A_s e.
// 1..4 keep only the slip along the segment's first tangent t1 (w -> (w . t1) t1); 11..14 use the plane.
// The regularised laws are dashpots for small s, of slope (per area) ct, mu p (2/pi) ct and p ct. Computed
// explicitly with the slip of the last half step they would overshoot once C dt / m_slip > 1 (C the slope
// times A_s) and need dt <= m_slip / C, which a steep law (ct of 1e15 Pa s/m: practically exact Coulomb)
// makes absurdly small. Instead the force is bounded by what stops the slip within the step
// (docs/theory/contact-laws.md 3.5):
//   |F_t| = min(friction_traction(s, p) A_s, m_slip s / dt),  1 / m_slip = 1 / m_s + sum_j h_j^2 / m_j
// (the free nodes of the pair), so the slip after the step keeps its sign: unconditionally stable, the law
// unchanged wherever the step resolves it (C dt <= m_slip), and no step vote.
#include "contact/ctclaw_laws.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace radx::contact {

namespace {

using Vec = std::array<double, 3>;
constexpr double kInf = std::numeric_limits<double>::infinity();
// The exponential law's pressure below which a pair is out of contact, relative to pz.
constexpr double kExponentialCutoff = 1e-12;

double dot(const Vec& a, const Vec& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// The monotone tangent at interior point k of a curve with secants d0 (left) and d1 (right) over segment
// lengths h0 and h1.
double monotone_tangent(double d0, double d1, double h0, double h1) {
  if (d0 * d1 <= 0) return 0;
  const double w1 = 2 * h1 + h0, w2 = h1 + 2 * h0;
  return (w1 + w2) / (w1 / d0 + w2 / d1);
}

// P(g) and dP/dg of the table at gap g (unclamped).
std::array<double, 2> table_at(std::span<const double> x, std::span<const double> y, bool cubic, double g) {
  const std::size_t n = x.size();
  if (n == 0) return {0, 0};
  if (n == 1) return {y[0], 0};
  // Segment k = [x_k, x_k+1] that brackets g, or the end segment for g outside the table.
  std::size_t k = 0;
  if (g >= x[n - 1]) {
    k = n - 2;
  } else if (g > x[0]) {
    k = static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), g) - x.begin()) - 1;
  }
  const double h = x[k + 1] - x[k];
  const double d = (y[k + 1] - y[k]) / h;
  const bool outside = g <= x[0] || g >= x[n - 1];
  if (!cubic || outside) return {y[k] + d * (g - x[k]), d};
  auto secant = [&](std::size_t j) { return (y[j + 1] - y[j]) / (x[j + 1] - x[j]); };
  const double m0 = k == 0 ? d : monotone_tangent(secant(k - 1), d, x[k] - x[k - 1], h);
  const double m1 = k + 2 == n ? d : monotone_tangent(d, secant(k + 1), h, x[k + 2] - x[k + 1]);
  const double t = (g - x[k]) / h, t2 = t * t, t3 = t2 * t;
  const double h00 = 2 * t3 - 3 * t2 + 1, h10 = t3 - 2 * t2 + t, h01 = -2 * t3 + 3 * t2, h11 = t3 - t2;
  const double p = h00 * y[k] + h10 * h * m0 + h01 * y[k + 1] + h11 * h * m1;
  const double dh00 = 6 * t2 - 6 * t, dh10 = 3 * t2 - 4 * t + 1, dh01 = -6 * t2 + 6 * t,
               dh11 = 3 * t2 - 2 * t;
  const double dp = (dh00 * y[k] + dh01 * y[k + 1]) / h + dh10 * m0 + dh11 * m1;
  return {p, dp};
}

}  // namespace

double exponential_lambda(double kc_auto, double pe) {
  return kc_auto / pe;
}

double exponential_knee(double pz, double lambda, double kc_max) {
  if (!(kc_max > 0)) return kInf;
  return std::log(kc_max / (pz * lambda)) / lambda;
}

PairLaw resolve_pair_law(const model::ContactLaw& law, const model::Model& m, double K, double area) {
  PairLaw out;
  out.normal = law.normal;
  out.friction = law.friction;
  out.bidirectional = law.bidirectional;
  const double kc_auto = area > 0 ? K / area : 0.0;
  out.kc = law.kc == -1 ? kc_auto : law.kc;
  out.pz = law.pz;
  out.lambda = law.lambda > 0 ? law.lambda : exponential_lambda(kc_auto, law.pe);
  out.kc_max = law.kc_max;
  if (law.normal == model::NormalLaw::Exponential)
    out.u_knee = exponential_knee(out.pz, out.lambda, law.kc_max);
  if (law.curve != model::kNone) {
    const auto& f = m.functions[static_cast<std::size_t>(law.curve)];
    out.gap = f.x;
    out.pressure = f.y;
  }
  out.cubic = law.cubic;
  out.power_m = law.power_m;
  out.power_k = law.power_k;
  out.mu = law.mu;
  out.ct = law.ct;
  out.kappa = law.kappa > 0 ? law.kappa : kc_auto;
  return out;
}

Pressure linear_pressure(double kc, double u) {
  if (!(u > 0)) return {};
  return {kc * u, kc};
}

Pressure exponential_pressure(double pz, double lambda, double kc_max, double u_knee, double u) {
  if (u > u_knee) return {kc_max / lambda + kc_max * (u - u_knee), kc_max};
  const double p = pz * std::exp(lambda * u);
  if (p < kExponentialCutoff * pz) return {};
  return {p, lambda * p};
}

Pressure tabulated_pressure(std::span<const double> gap, std::span<const double> pressure, bool cubic,
                            double u) {
  const auto [p, dp_dgap] = table_at(gap, pressure, cubic, -u);
  if (!(p > 0)) return {};
  return {p, -dp_dgap};
}

Pressure power_pressure(std::span<const double> m, std::span<const double> kpm, double u) {
  if (!(u > 0)) return {};
  Pressure out;
  for (std::size_t k = 0; k < m.size(); ++k) {
    const double um1 = std::pow(u, m[k] - 1);
    out.p += kpm[k] * um1 * u;
    out.kc += m[k] * kpm[k] * um1;
  }
  return out;
}

Pressure normal_pressure(const PairLaw& law, double u) {
  switch (law.normal) {
    case model::NormalLaw::Linear: return linear_pressure(law.kc, u);
    case model::NormalLaw::Exponential:
      return exponential_pressure(law.pz, law.lambda, law.kc_max, law.u_knee, u);
    case model::NormalLaw::Tabulated: return tabulated_pressure(law.gap, law.pressure, law.cubic, u);
    case model::NormalLaw::Power: return power_pressure(law.power_m, law.power_k, u);
    case model::NormalLaw::Interface: break;
  }
  return {};
}

double contact_onset(const PairLaw& law) {
  switch (law.normal) {
    case model::NormalLaw::Exponential: return std::min(0.0, std::log(kExponentialCutoff) / law.lambda);
    case model::NormalLaw::Tabulated: {
      const auto& x = law.gap;
      const auto& y = law.pressure;
      const std::size_t n = x.size();
      if (n == 0) return 0;
      if (n == 1) return y[0] > 0 ? -kInf : kInf;
      // Pressures do not increase with the gap: the last point, or the last segment's extrapolation,
      // decides where the pressure ends.
      if (!(y[n - 1] > 0)) {
        std::size_t k = n - 1;
        while (k > 0 && !(y[k - 1] > 0)) --k;
        return k == 0 ? kInf : -x[k];
      }
      const double slope = (y[n - 1] - y[n - 2]) / (x[n - 1] - x[n - 2]);
      if (!(slope < 0)) return -kInf;
      return -(x[n - 1] - y[n - 1] / slope);
    }
    default: return 0;
  }
}

double friction_traction(const PairLaw& law, double slip_speed, double pressure) {
  const double s = slip_speed, p = std::max(0.0, pressure);
  switch (law.friction) {
    case model::FrictionLaw::Coulomb: return law.mu * p;
    case model::FrictionLaw::Linear: return std::min(law.ct * s, law.mu * p);
    case model::FrictionLaw::Arctangent: return law.mu * p * (2 / std::numbers::pi) * std::atan(law.ct * s);
    case model::FrictionLaw::ScaledLinear: return p * std::min(law.ct * s, law.mu);
    default: return 0;
  }
}

std::array<double, 3> law_friction_force(const PairLaw& law, const LawFrictionInput& in) {
  Vec w = in.w, f_old = in.f_old;
  if (!law.bidirectional) {
    const double w1 = dot(w, in.t1), f1 = dot(f_old, in.t1);
    for (std::size_t d = 0; d < 3; ++d) {
      w[d] = w1 * in.t1[d];
      f_old[d] = f1 * in.t1[d];
    }
  }
  Vec f{};
  if (law.friction == model::FrictionLaw::Coulomb) {
    const double cap = law.mu * std::max(0.0, in.pressure) * in.area;
    for (std::size_t d = 0; d < 3; ++d) f[d] = f_old[d] - law.kappa * in.area * w[d] * in.dt;
    const double trial = std::sqrt(dot(f, f));
    if (trial > cap) {
      const double scale = trial > 0 ? cap / trial : 0.0;
      for (auto& fd : f) fd *= scale;
    }
    return f;
  }
  const double s = std::sqrt(dot(w, w));
  if (!(s > 0)) return f;
  double magnitude = friction_traction(law, s, in.pressure) * in.area;
  if (in.mobility > 0 && in.dt > 0) magnitude = std::min(magnitude, s / (in.mobility * in.dt));
  for (std::size_t d = 0; d < 3; ++d) f[d] = -magnitude * w[d] / s;
  return f;
}

}  // namespace radx::contact
