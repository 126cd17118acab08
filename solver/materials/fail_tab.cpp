// /FAIL/TAB: the tabulated failure strain of an integration point, on LAW2 and LAW36, shells and solids.
// The damage it feeds, the point's failure and the element deletion are the shared stage of
// failure_damage.cpp.
//
// Sources (read, not translated): OpenRadioss starter/source/materials/fail/tabulated/
// hm_read_fail_tab_old.F (cards, defaults) and the starter's conversion of /FAIL/TAB into /FAIL/TAB1 with a
// /TABLE of order 2 (reader/.../GlobalModelSdi.cpp GlobalEntitySDIConvertFailTab), hm_read_fail_tab1.F,
// engine/source/materials/fail/tabulated/fail_tab_c.F (shells), fail_tab_s.F (solids),
// engine/source/materials/fail/fail_setoff_c.F (shell deletion), starter .../coque/cfailini.F (the length).
//
// Failure strain, with the stress AFTER the material update of the step:
//   eta   = sigma_m / max(svm, 1e-20)  (shells: sigma_m = (sxx + syy)/3, plane-stress von Mises)
//   row k: Fscale_k f_k(eta) at the strain rate Epsdot_k (f_k linear between its points, extrapolated with
//          its end segments);
//   one row: eps_f0 = Fscale_1 f_1(eta) (OpenRadioss builds two identical rows: no rate effect);
//   several: the rows k, k+1 around the rate (the first or last two beyond the ends), linear in the rate,
//            extrapolated beyond:  eps_f0 = e_k + (rate - Epsdot_k) / (Epsdot_k+1 - Epsdot_k) (e_k+1 - e_k)
//   eps_f = eps_f0 * Fscale_el f_el(L0 / EI_ref) * FscaleT f_T
//   rate: the element's filtered strain rate (the material's, as OpenRadioss passes EPSD);
//   L0: the element's characteristic length at t = 0 (the starter's ALDT, kept for the run: shells only,
//       radx refuses a size function on solids, where OpenRadioss takes the length of the cycle);
//   f_T: the temperature function, accepted by the starter only when constant (radx has no temperature).
// The damage: D += n D^(1 - 1/n) d_eps_p / eps_f (1 at D = 0), for eps_f > 0; the point fails at D = Dcrit.
// There is no softening: /FAIL/TAB's D is the instability damage of /FAIL/TAB1's fading, whose exponent
// (Fad_exp) /FAIL/TAB does not have (0 after the conversion), so the stress is never scaled before failure.
//
// What a failed point does: shells (Ifail_sh) 1 and 2 no stress any more, 3 the stress kept; the element is
// deleted at once when the thickness fraction of failed points reaches 1e-6 (Ifail_sh 1) or
// min(P_thickfail (0: 1 - 1e-6), the property's P_thickfail) kept in [1e-6, 1 - 1e-6] (Ifail_sh 2, 3).
// Solids (Ifail_so): 1 the brick's deletion (0.8, then the decay), 2 the normal stresses set to sigma_m (the
// shears kept, as fail_tab_s.F does), 3 the stress kept.
#include <algorithm>

#include "solver/materials/material_point.hpp"

namespace radx::solver {

namespace {
constexpr double kTiny = 1e-20;

double row_value(const TabCurve& c, double eta) {
  double y = 0, dy = 0;
  curve_at(c, eta, y, dy);
  return c.scale * y;
}
}  // namespace

double fail_tab_strain(const FailParams& f, double sigma_m, double svm, double rate) {
  const double eta = sigma_m / std::max(kTiny, svm);
  double eps_f = 0;
  if (f.n_rows == 1) {
    eps_f = row_value(f.rows[0], eta);
  } else if (f.n_rows > 1) {
    int k = 0;  // the segment of rows around the rate; the end segments extrapolate
    while (k + 2 < f.n_rows && rate > f.rows[k + 1].rate) ++k;
    const TabCurve& a = f.rows[k];
    const TabCurve& b = f.rows[k + 1];
    const double e1 = row_value(a, eta);
    const double e2 = row_value(b, eta);
    eps_f = e1 + (rate - a.rate) / (b.rate - a.rate) * (e2 - e1);
  }
  return eps_f * f.temp_factor;
}

double fail_size_factor(const FailParams& f, double len) {
  if (!f.has_size) return 1.0;
  double y = 0, dy = 0;
  curve_at(f.size, len / f.el_ref, y, dy);
  return f.size.scale * y;
}

}  // namespace radx::solver
