// /FAIL/JOHNSON: Johnson-Cook ductile damage at each integration point, on LAW2 and LAW36, shells and solids.
//
// Sources (read, not translated): OpenRadioss starter/source/materials/fail/johnson_cook/
// hm_read_fail_johnson.F (cards, defaults), engine/source/materials/fail/johnson_cook/fail_johnson_c.F
// (shells), fail_johnson.F (solids), engine/source/materials/mat_share/mulawc.F90 and
// engine/source/materials/fail/fail_setoff_c.F (shell deletion).
//
// Failure strain, with the stress AFTER the material update of the step and d_eps_p its plastic increment:
//   sigma* = sigma_m / svm,  sigma_m = tr(sigma)/3 (tension > 0; shells: (sxx + syy)/3), svm von Mises
//            (floored at 1e-20)
//   eps_f  = (D1 + D2 exp(D3 sigma*)) (1 + D4 ln(max(1, rate / rate0))) (1 + D5 T*)
//            (the D4 factor only when D4 != 0; T* = 0 in radx, so the D5 factor is 1), then
//   eps_f  = max(eps_f, EPSF_MIN);  D += d_eps_p / eps_f when eps_f > 0; D capped at 1.
//   rate: the element's filtered strain rate (as the material uses); rate0 = Epsilon_Dot_0 (0 -> 1e-20).
//
// Shells (per point, only while the element is intact, OFF = 1, the point alive, and d_eps_p > 0): a point
// with D = 1 has failed; from then on its five stresses are zero (in the step it fails too). The element is
// deleted (OFF = 0 at once, not the progressive 0.8 decay of EPS_p_max) when the thickness fraction of failed
// points, sum of the failed points' weights w_i (elements.md 1.4), reaches
//   Ifail_sh 1: 1e-6 (one failed point deletes the element);
//   Ifail_sh 2: min(P_thickfail of the property, 1 - 1e-6) (every point, with the default P_thickfail).
//
// Solids (the one point of the brick), by Ifail_so:
//   1: D accumulates while OFF = 1; when D reaches 1 the brick takes OFF = 0.8, then decays by 0.8 per cycle
//   and
//      is deleted below 0.1 (brick_next_off);
//   2: once D = 1 the deviator is zero (sigma = sigma_m I) for ever, the brick stays;
//   3: once D = 1, sigma = min(sigma_m, 0) I (no tension, no deviator);
//   4: once D = 1 the stress is zero, the brick stays.
#include <algorithm>
#include <cmath>

#include "solver/material_point.hpp"

namespace radx::solver {

namespace {
constexpr double kTiny = 1e-20;
}  // namespace

double fail_jc_strain(const FailJcParams& f, double sigma_m, double svm, double rate) {
  double eps_f = f.d1 + f.d2 * std::exp(f.d3 * sigma_m / std::max(kTiny, svm));
  if (f.d4 != 0) eps_f *= 1.0 + f.d4 * std::log(std::max(1.0, rate / f.eps_dot0));
  // (1 + D5 T*) = 1: radx has no temperature (T* = 0).
  return std::max(eps_f, f.eps_f_min);
}

bool fail_jc_accumulate(const FailJcParams& f, double sigma_m, double svm, double rate, double deps_p,
                        double& dmg) {
  if (dmg >= 1.0) return false;
  const double eps_f = fail_jc_strain(f, sigma_m, svm, rate);
  if (eps_f > 0) dmg += deps_p / eps_f;
  if (dmg < 1.0) return false;
  dmg = 1.0;
  return true;
}

ShellPointResult shell_point_update_fail(const MaterialParams& p, int iplas, double rfac, double rate,
                                         double off, const double de[5], double gs, double sig[5],
                                         double& eps_p, double& dmg) {
  const ShellPointResult r = shell_point_update_r(p, iplas, rfac, off, de, gs, sig, eps_p);
  if (!p.fail.on) return r;
  if (off == 1.0 && dmg < 1.0 && r.deps_p > 0) {
    const double svm = std::sqrt(std::max(0.0, shell_vm2_radial(sig[0], sig[1], sig[2])));
    fail_jc_accumulate(p.fail, (sig[0] + sig[1]) / 3.0, svm, rate, r.deps_p, dmg);
  }
  if (dmg >= 1.0)
    for (int k = 0; k < 5; ++k) sig[k] = 0.0;
  return r;
}

SolidPointResult solid_point_update(const MaterialParams& p, double rate, const double de[6], double mu,
                                    double sig[6], double& eps_p, double& dmg, double off) {
  SolidPointResult out;
  out.deps_p = solid_point_update(p, rate, de, mu, sig, eps_p);
  // Law 36 Eps_p_max (sigeps36.F): strictly above it, a live brick starts its deletion.
  if (p.law == model::MaterialLaw::PlasTab && off == 1.0 && eps_p > p.eps_p_max) out.element_fails = true;
  if (!p.fail.on) return out;
  const auto& f = p.fail;
  const double sm = (sig[0] + sig[1] + sig[2]) / 3.0;
  const double dx = sig[0] - sm, dy = sig[1] - sm, dz = sig[2] - sm;
  const double svm = std::sqrt(
      3.0 * (0.5 * (dx * dx + dy * dy + dz * dz) + sig[3] * sig[3] + sig[4] * sig[4] + sig[5] * sig[5]));
  switch (f.ifail_so) {
    case 2:
    case 3:
      if (off != 1.0) break;
      if (dmg < 1.0 && out.deps_p != 0) fail_jc_accumulate(f, sm, svm, rate, out.deps_p, dmg);
      if (dmg >= 1.0) {
        const double pm = f.ifail_so == 2 ? sm : std::min(sm, 0.0);
        sig[0] = sig[1] = sig[2] = pm;
        sig[3] = sig[4] = sig[5] = 0.0;
      }
      break;
    case 4:
      if (out.deps_p != 0) fail_jc_accumulate(f, sm, svm, rate, out.deps_p, dmg);
      if (dmg >= 1.0 && off == 1.0)
        for (int k = 0; k < 6; ++k) sig[k] = 0.0;
      break;
    default:  // 1
      if (off != 1.0) break;
      if (out.deps_p != 0) fail_jc_accumulate(f, sm, svm, rate, out.deps_p, dmg);
      if (dmg >= 1.0) out.element_fails = true;
      break;
  }
  return out;
}

}  // namespace radx::solver
