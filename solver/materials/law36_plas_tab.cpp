// LAW36 (/MAT/PLAS_TAB): isotropic elasto-plasticity with tabulated yield curves sigma_y(eps_p), one curve
// per strain rate, for shells (plane stress) and solids. The points call it through material_point.hpp
// (shell_point_update_r, solid_point_update), which dispatch on the law; the elastic trial, the thickness
// strain and the pressure are those of LAW1 and LAW2 (material_point.cpp).
//
// Sources: docs/elements-openradioss.md 6.6 (LAW36), docs/theory/elements.md 1.3 and 6.2 (the strain rates);
// read, not translated: OpenRadioss starter/source/materials/mat/mat036/hm_read_mat36.F (cards,
// defaults), engine/source/materials/mat/mat036/sigeps36c.F (shells) and sigeps36.F (solids), VP = 0
// (total strain rate), Chard = 0 (isotropic), no pressure or Young's-modulus function, no tension failure.
//
// Curves (reader). N curves (f_i, scale_i, rate_i), rates strictly increasing. N = 1: no rate effect. N > 1
// and rate_1 != 0: curve 1 is repeated at rate 0 (so below rate_1 the first curve holds). Scale 0 -> 1. Each
// curve is linear between its points and extrapolated with its end segments.
//
// Flow stress at the plastic strain of the START of the step (explicit hardening) and the element's filtered
// strain rate r (shells: the equivalent rate of docs/theory/elements.md 1.3;
// solids: sqrt(D:D) with tensor shears, 6.2):
//   N = 1:  sigma_y = s_1 f_1(eps_p),  H = s_1 f_1'(eps_p)
//   N > 1:  j = the last curve with rate_j <= r among 1 .. N-1 (j = 1 below rate_2),
//           w = (r - r_j) / (r_{j+1} - r_j)                                  (Fsmooth 0 or 1, linear)
//           w = ln(max(r, 1e-20) / max(r_j, 1e-20)) / ln(r_{j+1} / max(r_j, 1e-20))   (Fsmooth 2)
//           (w is not clamped: above the last rate the two last curves are extrapolated)
//           Y_k = s_k f_k(eps_p),  sigma_y = max(Y_j + w (Y_{j+1} - Y_j), 1e-20),
//           H = Y_j' + w (Y_{j+1}' - Y_j')
//   The rate is filtered: r <- a r_elem + (1 - a) r_old, a = min(1, 2 pi Fcut dt), Fcut 0 -> 10 kHz when
//   N > 1 (the kernels do it, as for LAW2).
//
// Shell, per point (trial as LAW2: sxx += A11 dexx + A12 deyy, ..., transverse shear elastic):
//   svm = sqrt(sxx^2 + syy^2 - sxx syy + 3 sxy^2)
//   Iplas 0 (radial return), if svm > sigma_y: (sxx, syy, sxy) *= sigma_y / svm,
//       d_eps_p = OFF (svm - sigma_y) / (3G + H)   (3G + H, where LAW2 divides by E),
//       d_ezz_p = d_eps_p (sxx + syy) / (2 sigma_y) with the returned stress
//   Iplas 1 (only when OFF = 1): H <- max(0, H), s1 = sxx + syy, s2 = sxx - syy, A = s1^2/4,
//       B = 3/4 s2^2 + 3 sxy^2; d_eps_p = (svm - sigma_y)/(3G + H); three evaluations of
//         sy_i = sigma_y + H d_eps_p (the tangent, not the curve: LAW2 re-evaluates the curve),
//         r = E d_eps_p / (2 sy_i), P = 1/(1 + r/(1 - nu)), Q = 1/(1 + 3r/(1 + nu)),
//         f = A P^2 + B Q^2 - sy_i^2, df = -(A P^3/(1 - nu) + 3 B Q^3/(1 + nu)) (E - 2 r H)/sy_i - 2 H sy_i,
//         df kept at least 1e-20 in size, next d_eps_p = max(0, d_eps_p - f/df) (stays 0 once 0);
//       the d_eps_p, r, P, Q of the third evaluation are used: sxx + syy <- P s1, sxx - syy <- Q s2,
//       sxy <- Q sxy, d_ezz_p = r P s1 / E
//   thickness strain (1.8): dezz = [-nu (dexx + deyy) - (1 - 2 nu) d_ezz_p] / (1 - nu)
//   Eps_p_max: a live element one of whose points has eps_p > Eps_p_max is deleted at once (OFF 0 in that
//   cycle): sigeps36c.F sets OFF = 0.8 without the progressive-rupture flag sigeps02c.F sets for LAW2, and
//   mulawc.F90 turns such a 0.8 into 0 (shell_section.hpp fail_now). Solids decay instead (below).
//
// Solid (deviatoric trial as LAW2, pressure p = K mu):
//   svm = sqrt(3 J2); if svm > sigma_y: R = sigma_y / svm, s *= R, d_eps_p = (1 - R) svm / max(3G + H, 1e-20)
//   (the deviator goes to sigma_y of the start of the step; LAW2 adds H d_eps_p). Eps_p_max: a live brick
//   with eps_p > Eps_p_max takes OFF = 0.8, then OFF <- 0.8 OFF per cycle, deleted once below 0.1 (LAW2 keeps
//   the brick and zeroes its deviator instead).
#include <algorithm>
#include <cmath>
#include <limits>

#include "solver/materials/material_point.hpp"

namespace radx::solver {

namespace {

constexpr double kTiny =
    1e-20;  // OpenRadioss EM20: the floor of sigma_y, of rates in logarithms, of divisors

}  // namespace

double tab_flow_stress(const MaterialParams& p, double eps_p, double rate, double* slope) {
  double y1 = 0, d1 = 0;
  if (p.tab.n_curves <= 1) {
    if (p.tab.n_curves == 1) {
      curve_at(p.tab.curves[0], eps_p, y1, d1);
      y1 *= p.tab.curves[0].scale;
      d1 *= p.tab.curves[0].scale;
    }
    if (slope != nullptr) *slope = d1;
    return y1;
  }
  int j = 0;
  for (int k = 1; k < p.tab.n_curves - 1; ++k)
    if (rate >= p.tab.curves[k].rate) j = k;
  const TabCurve& c1 = p.tab.curves[j];
  const TabCurve& c2 = p.tab.curves[j + 1];
  double w = 0;
  if (p.tab.log_rate) {
    const double r1 = std::max(c1.rate, kTiny);
    w = std::log(std::max(rate, kTiny) / r1) / std::log(c2.rate / r1);
  } else {
    w = (rate - c1.rate) / (c2.rate - c1.rate);
  }
  double y2 = 0, d2 = 0;
  curve_at(c1, eps_p, y1, d1);
  curve_at(c2, eps_p, y2, d2);
  y1 *= c1.scale;
  d1 *= c1.scale;
  y2 *= c2.scale;
  d2 *= c2.scale;
  if (slope != nullptr) *slope = d1 + w * (d2 - d1);
  return std::max(y1 + w * (y2 - y1), kTiny);
}

namespace detail {

ShellPointResult law36_shell_point(const MaterialParams& p, int iplas, double rate, double off,
                                   const double de[5], double gs, double sig[5], double& eps_p) {
  double sxx = sig[0], syy = sig[1], sxy = sig[2];
  shell_trial(p, gs, de[0], de[1], de[2], de[3], de[4], sxx, syy, sxy, sig[3], sig[4]);
  ShellPointResult out;
  double dezz_p = 0;
  double h = 0;
  const double sy = tab_flow_stress(p, eps_p, rate, &h);
  const double g3 = 3.0 * p.shear;
  if (iplas != 1) {
    const double q = shell_vm2_radial(sxx, syy, sxy);
    if (q > sy * sy) {
      const double svm = std::sqrt(q);
      const double scale = sy / svm;
      sxx *= scale;
      syy *= scale;
      sxy *= scale;
      out.deps_p = off * (svm - sy) / std::max(g3 + h, kTiny);
      dezz_p = out.deps_p * 0.5 * (sxx + syy) / sy;
    }
  } else if (off == 1.0) {
    h = std::max(0.0, h);
    const double s1 = sxx + syy;
    const double s2 = sxx - syy;
    const double a = 0.25 * s1 * s1;
    const double b = 0.75 * s2 * s2 + 3.0 * sxy * sxy;
    if (a + b > sy * sy) {
      const double nu1 = 1.0 / (1.0 - p.nu);
      const double nu2 = 3.0 / (1.0 + p.nu);
      double next = (std::sqrt(a + b) - sy) / (g3 + h);
      double dp = 0, r = 0, pp = 1, qq = 1;
      for (int it = 0; it < 3; ++it) {
        dp = next;
        const double sy_i = sy + h * dp;
        r = 0.5 * p.young * dp / sy_i;
        pp = 1.0 / (1.0 + r * nu1);
        qq = 1.0 / (1.0 + r * nu2);
        const double f = a * pp * pp + b * qq * qq - sy_i * sy_i;
        double df = -(a * nu1 * pp * pp * pp + b * nu2 * qq * qq * qq) * (p.young - 2.0 * r * h) / sy_i -
                    2.0 * h * sy_i;
        df = std::copysign(std::max(std::abs(df), kTiny), df);
        next = dp > 0 ? std::max(0.0, dp - f / df) : 0.0;
      }
      const double t1 = pp * s1;
      const double t2 = qq * s2;
      sxx = 0.5 * (t1 + t2);
      syy = 0.5 * (t1 - t2);
      sxy *= qq;
      out.deps_p = dp;
      dezz_p = r * t1 / p.young;
    }
  }
  eps_p += out.deps_p;
  if (out.deps_p > 0) {
    const double vm_old = std::sqrt(std::max(0.0, shell_vm2_radial(sig[0], sig[1], sig[2])));
    const double vm_new = std::sqrt(std::max(0.0, shell_vm2_radial(sxx, syy, sxy)));
    out.w_plastic = 0.5 * (vm_old + vm_new) * out.deps_p;
  }
  sig[0] = sxx;
  sig[1] = syy;
  sig[2] = sxy;
  out.dezz = shell_dezz(p, de[0], de[1], dezz_p);
  return out;
}

double law36_solid_deviator(const MaterialParams& p, double rate, double s[6], double& eps_p) {
  double h = 0;
  const double sy = tab_flow_stress(p, eps_p, rate, &h);
  const double q =
      1.5 * (s[0] * s[0] + s[1] * s[1] + s[2] * s[2]) + 3.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]);
  if (!(q > sy * sy)) return 0.0;
  const double svm = std::sqrt(q);
  const double r = sy / std::max(svm, kTiny);
  for (int k = 0; k < 6; ++k) s[k] *= r;
  const double deps_p = (1.0 - r) * svm / std::max(3.0 * p.shear + h, kTiny);
  eps_p += deps_p;
  return deps_p;
}

}  // namespace detail

void tab_curves_params(const model::Material& m, const std::vector<model::Function>& functions,
                       std::vector<TabCurve>& curves, MaterialParams& p) {
  curves.clear();
  const auto& tab = m.tab;
  for (std::size_t i = 0; i < tab.function.size(); ++i) {
    TabCurve c;
    const auto fi = tab.function[i];
    if (fi >= 0 && static_cast<std::size_t>(fi) < functions.size()) {
      const auto& f = functions[static_cast<std::size_t>(fi)];
      c.x = f.x.data();
      c.y = f.y.data();
      c.n = static_cast<int>(std::min(f.x.size(), f.y.size()));
    }
    c.scale = tab.scale[i] == 0 ? 1.0 : tab.scale[i];
    c.rate = tab.rate[i];
    curves.push_back(c);
  }
  // Several curves with a first rate above 0: the first curve also holds at rate 0 (hm_read_mat36.F).
  if (curves.size() > 1 && curves.front().rate != 0) {
    TabCurve c0 = curves.front();
    c0.rate = 0;
    curves.insert(curves.begin(), c0);
  }
  p.tab.curves = curves.data();
  p.tab.n_curves = static_cast<int>(curves.size());
  p.tab.log_rate = curves.size() > 1 && tab.fsmooth == 2;
  p.tab.rate_max = curves.size() > 1 ? curves.back().rate : 1e300;
  // Lower bound of sigma_y for the shells' elastic fast path: a curve over eps_p >= 0 is smallest at eps_p =
  // 0 or at one of its points, unless its last segment falls (then it has no lower bound).
  p.tab.bound = !curves.empty();
  p.tab.lower = std::numeric_limits<double>::infinity();
  for (const auto& c : curves) {
    if (c.n >= 2 && c.y[c.n - 1] < c.y[c.n - 2]) p.tab.bound = false;
    double y0 = 0, d0 = 0;
    curve_at(c, 0.0, y0, d0);
    double lo = y0;
    for (int k = 0; k < c.n; ++k)
      if (c.x[k] > 0) lo = std::min(lo, c.y[k]);
    p.tab.lower = std::min(p.tab.lower, lo * c.scale);
  }
  if (!p.tab.bound || !(p.tab.lower >= 0)) {
    p.tab.bound = false;
    p.tab.lower = 0;
  }
}

}  // namespace radx::solver
