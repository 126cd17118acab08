// The damage stage of every failure model (/FAIL/JOHNSON, /FAIL/TAB, /FAIL/BIQUAD) at an integration point,
// and the point updates that carry it: one stage, the models differ only in their failure strain
// (fail_johnson.cpp, fail_tab.cpp, fail_biquad.cpp) and in what a failed point does (FailParams).
//
// Damage, normalised d = D / Dcrit (Dcrit = 1, n = 1 for Johnson-Cook), with the stress AFTER the material
// update of the step and d_eps_p its plastic increment:
//   eps_f = fail_strain(sigma_m, svm, rate) times the element's size factor;
//   D    += n D^(1 - 1/n) d_eps_p / eps_f   when eps_f > 0 (the factor is 1 at D = 0, and for n = 1);
//   d capped at 1; d = 1: the point has failed (OpenRadioss fail_tab_c.F: UVAR(1) >= DCRIT; its damage
//   output DFMAX = min(1, D / Dcrit) is d).
//   Under proportional straining at a constant triaxiality (eps_f constant) the integral is D = (eps_p /
//   eps_f)^n: the point fails at eps_p = eps_f Dcrit^(1/n).
//
// Shells (per point, only while the element is intact, OFF = 1, the point alive, and d_eps_p > 0): from the
// step the point fails on, its five stresses are zero unless the model keeps them (/FAIL/TAB Ifail_sh 3).
// The element's deletion from the failed points' thickness fraction is in shell_section.hpp.
// Solids (the brick's point), by SolidFailMode:
//   Delete: d accumulates while OFF = 1; when d reaches 1 the brick takes OFF = 0.8, then decays by 0.8 per
//           cycle and is deleted below 0.1 (brick_next_off);
//   DeviatorZero: once d = 1 the deviator is zero (sigma = sigma_m I) for ever, the brick stays;
//   DeviatorTension: once d = 1, sigma = min(sigma_m, 0) I (no tension, no deviator);
//   StressZero: once d = 1 the stress is zero, the brick stays (d accumulates whatever OFF);
//   NormalToMean: once d = 1 the normal stresses are sigma_m, the shears are kept;
//   Keep: the stress is kept; d is only an output.
#include <algorithm>
#include <cmath>

#include "solver/materials/material_point.hpp"

namespace radx::solver {

double fail_strain(const FailParams& f, double sigma_m, double svm, double rate, double escale) {
  switch (f.kind) {
    case FailKind::Johnson: return fail_jc_strain(f, sigma_m, svm, rate) * escale;
    case FailKind::Tab: return fail_tab_strain(f, sigma_m, svm, rate) * escale;
    // OpenRadioss fail_biquad_c.F / _s.F: D += d_eps_p / max(eps_f, 1e-6).
    case FailKind::Biquad: return std::max(fail_biquad_strain(f, sigma_m, svm) * escale, 1e-6);
    case FailKind::None: break;
  }
  return 0.0;
}

bool fail_accumulate(const FailParams& f, double sigma_m, double svm, double rate, double escale,
                     double deps_p, double& dmg) {
  if (dmg >= 1.0) return false;
  const double eps_f = fail_strain(f, sigma_m, svm, rate, escale);
  if (eps_f > 0) {
    const double d = dmg * f.dcrit;  // D
    const double factor = (f.n_exp == 1.0 || d == 0.0) ? 1.0 : f.n_exp * std::pow(d, 1.0 - 1.0 / f.n_exp);
    dmg += factor * deps_p / eps_f / f.dcrit;
  }
  if (dmg < 1.0) return false;
  dmg = 1.0;
  return true;
}

ShellPointResult shell_point_update_fail(const MaterialParams& p, int iplas, double rfac, double rate,
                                         double escale, double off, const double de[5], double gs,
                                         double sig[5], double& eps_p, double& dmg, double* dmg_inst) {
  const ShellPointResult r = shell_point_update_r(p, iplas, rfac, off, de, gs, sig, eps_p);
  if (!p.fail.on) return r;
  if (off == 1.0 && dmg < 1.0 && r.deps_p > 0) {
    const double svm = std::sqrt(std::max(0.0, shell_vm2_radial(sig[0], sig[1], sig[2])));
    const double sm = (sig[0] + sig[1]) / 3.0;
    // /FAIL/BIQUAD S_Flag 3: the instability damage, updated before the point's own (fail_biquad_c.F).
    if (dmg_inst != nullptr && p.fail.kind == FailKind::Biquad && p.fail.bq_s_flag == 3)
      fail_biquad_instability(p.fail, sm, svm, escale, r.deps_p, *dmg_inst);
    fail_accumulate(p.fail, sm, svm, rate, escale, r.deps_p, dmg);
  }
  if (dmg >= 1.0 && !p.fail.keep_failed_stress)
    for (int k = 0; k < 5; ++k) sig[k] = 0.0;
  return r;
}

SolidPointResult solid_point_update(const MaterialParams& p, double rate, const double de[6], double mu,
                                    double sig[6], double& eps_p, double& dmg, double off) {
  SolidPointResult out;
  out.deps_p = solid_point_update(p, rate, de, mu, sig, eps_p);
  // Law 36 Eps_p_max (sigeps36.F): strictly above it, a live brick starts its deletion.
  if (p.law == model::MaterialLaw::PlasTab && off == 1.0 && eps_p > p.tab.eps_p_max) out.element_fails = true;
  if (!p.fail.on) return out;
  const auto& f = p.fail;
  const double sm = (sig[0] + sig[1] + sig[2]) / 3.0;
  const double dx = sig[0] - sm, dy = sig[1] - sm, dz = sig[2] - sm;
  const double svm = std::sqrt(
      3.0 * (0.5 * (dx * dx + dy * dy + dz * dz) + sig[3] * sig[3] + sig[4] * sig[4] + sig[5] * sig[5]));
  switch (f.solid) {
    case SolidFailMode::DeviatorZero:
    case SolidFailMode::DeviatorTension:
      if (off != 1.0) break;
      if (dmg < 1.0 && out.deps_p != 0) fail_accumulate(f, sm, svm, rate, 1.0, out.deps_p, dmg);
      if (dmg >= 1.0) {
        const double pm = f.solid == SolidFailMode::DeviatorZero ? sm : std::min(sm, 0.0);
        sig[0] = sig[1] = sig[2] = pm;
        sig[3] = sig[4] = sig[5] = 0.0;
      }
      break;
    case SolidFailMode::NormalToMean:
      if (off != 1.0) break;
      if (dmg < 1.0 && out.deps_p != 0) fail_accumulate(f, sm, svm, rate, 1.0, out.deps_p, dmg);
      if (dmg >= 1.0) sig[0] = sig[1] = sig[2] = sm;
      break;
    case SolidFailMode::Keep:
      if (off == 1.0 && out.deps_p != 0) fail_accumulate(f, sm, svm, rate, 1.0, out.deps_p, dmg);
      break;
    case SolidFailMode::StressZero:
      if (out.deps_p != 0) fail_accumulate(f, sm, svm, rate, 1.0, out.deps_p, dmg);
      if (dmg >= 1.0 && off == 1.0)
        for (int k = 0; k < 6; ++k) sig[k] = 0.0;
      break;
    case SolidFailMode::Delete:
      if (off != 1.0) break;
      if (out.deps_p != 0) fail_accumulate(f, sm, svm, rate, 1.0, out.deps_p, dmg);
      if (dmg >= 1.0) out.element_fails = true;
      break;
  }
  return out;
}

}  // namespace radx::solver
