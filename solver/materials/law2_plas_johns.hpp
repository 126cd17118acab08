// /MAT/PLAS_JOHNS (law 2): Johnson-Cook plasticity, its parameters and its flow stress (law2_plas_johns.cpp).
// Law 27 (law27_plas_brit.hpp) takes the same parameters for its flow stress.
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>
#include <numbers>

#include "solver/model/model.hpp"

namespace radx::solver {

struct MaterialParams;

// The Johnson-Cook constants in work units, with the defaults of docs/theory/elements.md 6.1 applied:
// sigma_y = min((a + b eps_p^n) R, sig_max0 (R if icc = 1 else 1)), R = 1 + c ln(max(rate, eps_dot0) /
// eps_dot0); eps_p_max the plastic strain past which a point has no deviatoric strength (6.4); flag_vp the
// strain-rate formulation (only 2, the total strain rate, is run).
struct JohnsonCookParams {
  double a = 0, b = 0, n = 1, c = 0, eps_dot0 = 1, sig_max0 = 1e20, eps_p_max = 1e20;
  int icc = 1, flag_vp = 2;
};

// Johnson-Cook flow stress (6.2) at plastic strain eps_p and strain rate `rate`:
// sigma_y = min((a + b eps_p^n) R, SIG_max0 (R if ICC = 1 else 1)), R = 1 + c ln(max(rate, rate0)/rate0).
// `slope` (if not null) receives d sigma_y / d eps_p (0 when capped). Temperature term = 1 (radx has no
// adiabatic heating).
double jc_flow_stress(const MaterialParams& p, double eps_p, double rate, double* slope = nullptr);

// The Johnson-Cook rate factor R = 1 + c ln(max(rate, rate0)/rate0) of 6.2, exactly 1 (without a logarithm)
// when c = 0 or rate <= rate0.
double johnson_cook_rate_factor(const MaterialParams& p, double rate);

// Fills p.jc and the rate filter of a law-2 material, with the defaults of 6.1 applied again so that a
// Material built by hand behaves like one from the starter.
void johnson_cook_params(const model::Material& m, MaterialParams& p);

// A lower bound of law 2's jc_rate_factor, R_lo <= R = 1 + c ln(max(rate, rate0)/rate0), without a
// logarithm and without a branch (the kernels' vectorised loops take it for every element and the logarithm
// only for the elements with a point that may yield): for x = rate/rate0 = 2^e m, m in [1, 2),
// ln x = e ln 2 + ln m >= ln 2 (e + m - 1), the chord of the concave ln over [1, 2] (at most 0.061 below it),
// less 1e-9 for the rounding of these few operations; max(., 0) keeps R_lo = 1 at or below rate0 (and for
// rate 0 or subnormal). c >= 0 and inv_rate0 = 1/rate0 > 0.
inline double jc_rate_factor_lower(double c, double inv_rate0, double rate) {
  const double x = rate * inv_rate0;
  const auto bits = std::bit_cast<std::uint64_t>(x);
  // The biased exponent as a double, exactly: 2^52 + k has k in its low mantissa bits.
  constexpr std::uint64_t kTwo52 = 0x4330000000000000ULL;
  const double e = std::bit_cast<double>(((bits >> 52) & 0x7FFULL) | kTwo52) - 4503599627370496.0 - 1023.0;
  const double m = std::bit_cast<double>((bits & 0x000FFFFFFFFFFFFFULL) | 0x3FF0000000000000ULL);
  const double ln_lo = std::numbers::ln2 * (e + (m - 1.0)) - 1e-9;
  return 1.0 + c * std::max(ln_lo, 0.0);
}

}  // namespace radx::solver
