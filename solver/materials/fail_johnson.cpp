// /FAIL/JOHNSON: the Johnson-Cook failure strain of an integration point, on LAW2 and LAW36, shells and
// solids. The damage it feeds, the point's failure and the element deletion are the shared stage of
// failure_damage.cpp.
//
// Sources (read, not translated): OpenRadioss starter/source/materials/fail/johnson_cook/
// hm_read_fail_johnson.F (cards, defaults), engine/source/materials/fail/johnson_cook/fail_johnson_c.F
// (shells), fail_johnson.F (solids).
//
// Failure strain, with the stress AFTER the material update of the step:
//   sigma* = sigma_m / svm,  sigma_m = tr(sigma)/3 (tension > 0; shells: (sxx + syy)/3), svm von Mises
//            (floored at 1e-20)
//   eps_f  = (D1 + D2 exp(D3 sigma*)) (1 + D4 ln(max(1, rate / rate0))) (1 + D5 T*)
//            (the D4 factor only when D4 != 0; T* = 0 in radx, so the D5 factor is 1), then
//   eps_f  = max(eps_f, EPSF_MIN).
//   rate: the element's filtered strain rate (as the material uses); rate0 = Epsilon_Dot_0 (0 -> 1e-20).
// The damage is D += d_eps_p / eps_f (n = 1, Dcrit = 1 in the shared stage).
//
// What a failed point does: shells (Ifail_sh) a failed point carries no stress; the element is deleted at
// once when the thickness fraction of failed points reaches 1e-6 (Ifail_sh 1) or min(P_thickfail of the
// property, 1 - 1e-6) (Ifail_sh 2). Solids (Ifail_so): 1 the brick's deletion (0.8, then the decay), 2 the
// deviator zero, 3 the deviator zero and no tension, 4 the stress zero (SolidFailMode).
#include <algorithm>
#include <cmath>

#include "solver/materials/material_point.hpp"

namespace radx::solver {

namespace {
constexpr double kTiny = 1e-20;
}  // namespace

double fail_jc_strain(const FailParams& f, double sigma_m, double svm, double rate) {
  double eps_f = f.d1 + f.d2 * std::exp(f.d3 * sigma_m / std::max(kTiny, svm));
  if (f.d4 != 0) eps_f *= 1.0 + f.d4 * std::log(std::max(1.0, rate / f.eps_dot0));
  // (1 + D5 T*) = 1: radx has no temperature (T* = 0).
  return std::max(eps_f, f.eps_f_min);
}

}  // namespace radx::solver
