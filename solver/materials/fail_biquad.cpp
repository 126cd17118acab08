// /FAIL/BIQUAD: the biquadratic failure strain of an integration point, on LAW2 and LAW36, shells and solids.
// The damage it feeds, the point's failure and the element deletion are the shared stage of
// failure_damage.cpp (n = 1, Dcrit = 1).
//
// Sources (read, not translated): OpenRadioss starter/source/materials/fail/biquad/hm_read_fail_biquad.F
// (cards, defaults), biquad_coefficients.F (the fits), engine/source/materials/fail/biquad/fail_biquad_c.F
// (shells), fail_biquad_s.F (solids); docs/theory/failure-biquad.md.
//
// The card gives the plastic strain at failure at five triaxialities (after the material selector):
//   C1 at eta = -1/3 (compression), C2 at 0 (shear), C3 at 1/3 (uniaxial tension), C4 at 1/sqrt(3) (plane
//   strain), C5 at 2/3 (equibiaxial tension).
// Two parabolas are fitted through them:
//   p1(eta) = C2 + b1 eta + a1 eta^2 through (-1/3, C1), (0, C2), (1/3, C3):
//             b1 = 3/2 (C3 - C1),  a1 = 9 ((C1 + C3)/2 - C2);
//   p2(eta) = a0 + b2 eta + a2 eta^2 through (1/3, C3), (1/sqrt(3), C4), (2/3, C5) (Lagrange's form).
// Failure strain, with the stress AFTER the material update of the step, eta = sigma_m / max(svm, 1e-20)
// (shells: sigma_m = (sxx + syy)/3 and the plane-stress von Mises, where |eta| <= 2/3; solids: eta kept in
// [-2/3, 2/3] as fail_biquad_s.F does):
//   eta <= 1/3:              eps_f = p1(eta);
//   eta >  1/3, S_Flag 1:    eps_f = p2(eta);
//   eta >  1/3, S_Flag 2:    plane strain is the minimum: a parabola with its vertex at (1/sqrt(3),
//   p2(1/sqrt(3)))
//                            through (1/3, p1(1/3)) up to 1/sqrt(3), through (2/3, p2(2/3)) beyond:
//                            eps_f = p2(s) + (P - p2(s)) (eta - s)^2 / (x_P - s)^2,  s = 1/sqrt(3),
//                            (x_P, P) = (1/3, p1(1/3)) for eta <= s, (2/3, p2(2/3)) for eta > s;
//   then eps_f times the element's size factor f_el(L0 / EI_ref) (Ireg 1), floored at 1e-6 (a curve below
//   zero fails the point at once, as OpenRadioss's max(eps_f, 1e-6) does).
// The damage: D += d_eps_p / eps_f; the point fails at D = 1.
// S_Flag 3 (shells; solids run it as 2): the failure curve of S_Flag 2, and an instability damage
//   D_i += d_eps_p / (escale eps_i(eta)) while eps_i > 0, capped at 1, with eps_i = 0 for eta <= 1/3 and
//   above eps_i = I + (P - I) (eta - s)^2 / (x_P - s)^2,  I = Inst_start, (x_P, P) as for S_Flag 2; the shell
//   goes at once when all its points have D_i = 1 (shell_section.hpp section_instability).
// OpenRadioss solves the two fits numerically with the triaxialities rounded (1/sqrt(3) to 0.57735, the
// squares to 6 digits): its curve misses C1..C5 by up to about 1e-5 relative; radx's closed forms meet them
// to round-off.
//
// What a failed point does: shells: no stress any more; the element is deleted when the failed fraction of
// the thickness reaches min(P_thickfail (0: 1e-6), the property's P_thickfail) kept in [1e-6, 1 - 1e-6].
// Solids: the brick's deletion (0.8, then the decay).
#include <algorithm>
#include <cmath>

#include "solver/materials/material_point.hpp"

namespace radx::solver {

namespace {
constexpr double kTiny = 1e-20;
const double kPlaneStrain = 1.0 / std::sqrt(3.0);  // the triaxiality of plane strain, 1/sqrt(3)

double poly(const double c[3], double x) {
  return c[0] + c[1] * x + c[2] * x * x;
}
}  // namespace

void fail_biquad_fit(double c1, double c2, double c3, double c4, double c5, FailParams& f) {
  f.bq_low[0] = c2;
  f.bq_low[1] = 1.5 * (c3 - c1);
  f.bq_low[2] = 9.0 * (0.5 * (c1 + c3) - c2);
  // Lagrange's basis on x = 1/3, 1/sqrt(3), 2/3, summed into the monomial coefficients.
  const double x[3] = {1.0 / 3.0, kPlaneStrain, 2.0 / 3.0};
  const double y[3] = {c3, c4, c5};
  for (double& c : f.bq_high) c = 0;
  for (int i = 0; i < 3; ++i) {
    const double xj = x[(i + 1) % 3], xk = x[(i + 2) % 3];
    const double w = y[i] / ((x[i] - xj) * (x[i] - xk));
    f.bq_high[0] += w * xj * xk;
    f.bq_high[1] -= w * (xj + xk);
    f.bq_high[2] += w;
  }
}

double fail_biquad_curve(const FailParams& f, double eta) {
  if (eta <= 1.0 / 3.0) return poly(f.bq_low, eta);
  if (f.bq_s_flag == 1) return poly(f.bq_high, eta);  // S_Flag 2 and 3: the vertex form
  const double s = kPlaneStrain;
  const double vertex = poly(f.bq_high, s);
  const double xp = eta <= s ? 1.0 / 3.0 : 2.0 / 3.0;
  const double yp = eta <= s ? poly(f.bq_low, xp) : poly(f.bq_high, xp);
  return vertex + (yp - vertex) * (eta - s) * (eta - s) / ((xp - s) * (xp - s));
}

double fail_biquad_instability_curve(const FailParams& f, double eta) {
  if (eta <= 1.0 / 3.0) return 0.0;
  const double s = kPlaneStrain;
  const double xp = eta <= s ? 1.0 / 3.0 : 2.0 / 3.0;
  const double yp = eta <= s ? poly(f.bq_low, xp) : poly(f.bq_high, xp);
  return f.bq_inst + (yp - f.bq_inst) * (eta - s) * (eta - s) / ((xp - s) * (xp - s));
}

void fail_biquad_instability(const FailParams& f, double sigma_m, double svm, double escale, double deps_p,
                             double& dmg_inst) {
  const double eta = std::clamp(sigma_m / std::max(kTiny, svm), -2.0 / 3.0, 2.0 / 3.0);
  const double eps_i = fail_biquad_instability_curve(f, eta) * escale;
  if (eps_i > 0) dmg_inst = std::min(1.0, dmg_inst + deps_p / eps_i);
}

double fail_biquad_strain(const FailParams& f, double sigma_m, double svm) {
  const double eta = std::clamp(sigma_m / std::max(kTiny, svm), -2.0 / 3.0, 2.0 / 3.0);
  return fail_biquad_curve(f, eta);
}

}  // namespace radx::solver
