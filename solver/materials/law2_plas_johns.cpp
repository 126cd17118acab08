// LAW2 (/MAT/PLAS_JOHNS): Johnson-Cook plasticity at one integration point, shells (plane stress) and solids:
// its flow stress, its rate factor, the shell return and the solid deviator's return. The elastic trial, the
// thickness strain and the pressure it shares with LAW1 (material_point.hpp, material_point.cpp); LAW27
// (law27_plas_brit.cpp) takes its flow stress and its shell return.
//
// Sources: docs/theory/elements.md 1.4 (shell elasticity), 1.8 (thickness strain), 3.3 (solid pressure),
// 6.1-6.3 (LAW2), read from OpenRadioss sigeps02c.F / m2cplr.F (shell) and m2law.F (solid).
//
// Johnson-Cook flow stress (6.2), eps_p at the START of the step (explicit hardening):
//   R       = 1 + c ln(max(rate, rate0) / rate0)                      (R = 1 below rate0)
//   sigma_y = min((a + b eps_p^n) R, SIG_max0 (R if ICC = 1 else 1))   (eps_p = 0: a R)
//   H       = d sigma_y / d eps_p = n b R eps_p^(n-1), 0 when capped   (solid, m2law.F: at eps_p = 0,
//             H = b R for n = 1, else 0)
//
// Shell, plane stress, per point (1.4, 6.3). de = {dexx, deyy, dgxy, dgyz, dgzx} (engineering shears).
//   trial:  sxx += A11 dexx + A12 deyy,  syy += A12 dexx + A11 deyy,  sxy += G dgxy,
//           syz += GS dgyz,  szx += GS dgzx  (transverse shear elastic, outside the yield function)
//   svm = sqrt(sxx^2 + syy^2 - sxx syy + 3 sxy^2)
//   Iplas 0 (radial return), if svm > sigma_y:  (sxx, syy, sxy) *= sigma_y / svm,
//           d_eps_p = OFF (svm - sigma_y) / E   (Young's modulus, not 3G + H),
//           d_ezz_p = d_eps_p (sxx + syy) / (2 sigma_y)   with the returned stresses
//   Iplas 1 (Newton projection, only when OFF = 1; with OFF < 1 the trial stress is kept):
//           s1 = sxx + syy, s2 = sxx - syy, A = s1^2/4, B = 3/4 s2^2 + 3 sxy^2,
//           H = n b R (eps_p + 1e-7)^(n-1) (0 when capped; m2cplr.F adds 1e-7 so H stays finite at 0),
//           d_eps_p = (svm - sigma_y) / (3G + H), then exactly three evaluations of
//             sy_i = sigma_y(eps_p + d_eps_p),  r = E d_eps_p / (2 sy_i),
//             P = 1 / (1 + r/(1 - nu)),  Q = 1 / (1 + 3r/(1 + nu)),
//             f = A P^2 + B Q^2 - sy_i^2,
//             df = -(A P^3/(1 - nu) + 3 B Q^3/(1 + nu)) (E - 2 r H) / sy_i - 2 H sy_i,
//             next d_eps_p = max(0, d_eps_p - f/df)  (stays 0 once 0);
//           the d_eps_p, r, P, Q of the third evaluation are used (its Newton update is discarded):
//           sxx + syy <- P s1, sxx - syy <- Q s2, sxy <- Q sxy,  d_ezz_p = r P s1 / E
//   thickness strain increment (1.8): dezz = [-nu (dexx + deyy) - (1 - 2 nu) d_ezz_p] / (1 - nu)
//   plastic work (6.5): 1/2 (svm_old + svm_new) d_eps_p
//
// Solid (3.3, 6.3). de = {dxx, dyy, dzz, dgxy, dgyz, dgzx} (engineering shears), sig = {xx yy zz xy yz zx}.
//   s = dev(sig_old);  s_ii += 2G (de_ii - tr(de)/3),  s_ij += G dg_ij          (material_point.cpp)
//   svm = sqrt(3 J2) = sqrt(3/2 (s_xx^2 + s_yy^2 + s_zz^2) + 3 (s_xy^2 + s_yz^2 + s_zx^2))
//   if svm > sigma_y:  d_eps_p = (svm - sigma_y) / (3G + H),  sigma_y <- sigma_y + d_eps_p H,
//                      s *= sigma_y / svm,  eps_p += d_eps_p
//   once eps_p (start of step) > EPS_p_max: sigma_y = H = 0, so s = 0 for ever (the element is kept)
//   pressure p = K mu (total; mu = rho/rho0 - 1 > 0 in compression),  sig = s - p I  (material_point.cpp)
#include <algorithm>
#include <cmath>

#include "solver/materials/material_point.hpp"

namespace radx::solver {

namespace {

constexpr double kTiny = 1e-30;          // floor of a flow stress used as a divisor
constexpr double kShellSlopeEps = 1e-7;  // m2cplr.F: H evaluated at eps_p + 1e-7

// Strain-rate factor R and the flow-stress cap of 6.2.
struct JcRate {
  double r = 1;
  double cap = 1e20;
};

JcRate jc_rate_of_factor(const MaterialParams& p, double r) {
  JcRate out;
  out.r = r;
  out.cap = p.jc.sig_max0 * (p.jc.icc == 1 ? r : 1.0);
  return out;
}

JcRate jc_rate(const MaterialParams& p, double rate) {
  return jc_rate_of_factor(p, johnson_cook_rate_factor(p, rate));
}

// Flow stress (6.2) for a known rate factor: the one implementation behind jc_flow_stress and the shells.
inline double jc_flow_stress_at(const MaterialParams& p, double eps_p, const JcRate& jr, double* slope) {
  const JohnsonCookParams& jc = p.jc;
  double hard = jc.a;
  double h = 0;
  if (jc.n == 1.0) {
    hard += jc.b * eps_p;
    h = jc.b;
  } else if (eps_p > 0) {
    const double en = std::pow(eps_p, jc.n);
    hard += jc.b * en;
    h = jc.n * jc.b * en / eps_p;
  }
  double sy = hard * jr.r;
  h *= jr.r;
  if (sy >= jr.cap) {
    sy = jr.cap;
    h = 0;
  }
  if (slope != nullptr) *slope = h;
  return sy;
}

double plane_stress_vm(double sxx, double syy, double sxy) {
  return std::sqrt(std::max(0.0, shell_vm2_radial(sxx, syy, sxy)));
}

// von Mises stress of the plastic work (6.5).
inline double vm_work(double sxx, double syy, double sxy) {
  return std::sqrt(sxx * sxx + syy * syy - sxx * syy + 3.0 * sxy * sxy);
}

// LAW2's plastic correction (6.3) of a plane-stress trial for a known strain-rate factor: the one
// implementation behind the shells of law 2 and law 27. Returns d_eps_p; eps_p is updated.
double jc_return_core(const MaterialParams& p, int iplas, const JcRate& jr, double off, double& sxx,
                      double& syy, double& sxy, double& eps_p, double& dezz_p) {
  double deps_p = 0;
  dezz_p = 0;
  const double sy = jc_flow_stress_at(p, eps_p, jr, nullptr);
  if (iplas != 1) {
    const double svm = plane_stress_vm(sxx, syy, sxy);
    if (svm > sy) {
      const double scale = sy / svm;
      sxx *= scale;
      syy *= scale;
      sxy *= scale;
      deps_p = off * (svm - sy) / p.young;
      dezz_p = deps_p * 0.5 * (sxx + syy) / std::max(sy, kTiny);
    }
  } else if (off == 1.0) {
    const double s1 = sxx + syy;
    const double s2 = sxx - syy;
    const double a = 0.25 * s1 * s1;
    const double b = 0.75 * s2 * s2 + 3.0 * sxy * sxy;
    const double svm = std::sqrt(a + b);
    if (svm > sy) {
      const double h =
          sy >= jr.cap ? 0.0 : p.jc.n * p.jc.b * jr.r * std::pow(eps_p + kShellSlopeEps, p.jc.n - 1.0);
      const double nu1 = 1.0 / (1.0 - p.nu);
      const double nu2 = 1.0 / (1.0 + p.nu);
      double next = (svm - sy) / (3.0 * p.shear + h);
      double dp = 0, r = 0, pp = 1, qq = 1;
      for (int it = 0; it < 3; ++it) {
        dp = next;
        const double sy_i = std::max(jc_flow_stress_at(p, eps_p + dp, jr, nullptr), kTiny);
        r = 0.5 * p.young * dp / sy_i;
        pp = 1.0 / (1.0 + r * nu1);
        qq = 1.0 / (1.0 + 3.0 * r * nu2);
        const double f = a * pp * pp + b * qq * qq - sy_i * sy_i;
        const double df =
            -(a * nu1 * pp * pp * pp + 3.0 * b * nu2 * qq * qq * qq) * (p.young - 2.0 * r * h) / sy_i -
            2.0 * h * sy_i;
        next = dp > 0 ? std::max(0.0, dp - f / df) : 0.0;
      }
      const double t1 = pp * s1;
      const double t2 = qq * s2;
      sxx = 0.5 * (t1 + t2);
      syy = 0.5 * (t1 - t2);
      sxy *= qq;
      deps_p = dp;
      dezz_p = r * t1 / p.young;
    }
  }
  eps_p += deps_p;
  return deps_p;
}

}  // namespace

void johnson_cook_params(const model::Material& m, MaterialParams& p) {
  JohnsonCookParams& jc = p.jc;
  jc.a = m.a;
  jc.b = m.b;
  jc.n = m.n == 0 ? 1.0 : m.n;
  jc.c = m.c;
  jc.eps_dot0 = (m.c == 0 || m.eps_dot_0 <= 0) ? 1.0 : m.eps_dot_0;
  jc.sig_max0 = m.sig_max0 == 0 ? 1e20 : m.sig_max0;
  jc.eps_p_max = m.eps_p_max == 0 ? 1e20 : m.eps_p_max;
  jc.icc = m.icc == 0 ? 1 : m.icc;
  jc.flag_vp = m.flag_vp == 0 ? 2 : m.flag_vp;
  p.f_cut = m.f_cut;
}

double johnson_cook_rate_factor(const MaterialParams& p, double rate) {
  // rate <= rate0: max(rate, rate0)/rate0 = 1 and ln 1 = 0, so R = 1 exactly; c = 0: R = 1 + 0 ln(.) = 1.
  if (p.jc.c == 0 || rate <= p.jc.eps_dot0) return 1.0;
  return 1.0 + p.jc.c * std::log(std::max(rate, p.jc.eps_dot0) / p.jc.eps_dot0);
}

double jc_flow_stress(const MaterialParams& p, double eps_p, double rate, double* slope) {
  return jc_flow_stress_at(p, eps_p, jc_rate(p, rate), slope);
}

namespace detail {

double jc_shell_return(const MaterialParams& p, int iplas, double rfac, double off, double& sxx, double& syy,
                       double& sxy, double& eps_p, double& dezz_p) {
  return jc_return_core(p, iplas, jc_rate_of_factor(p, rfac), off, sxx, syy, sxy, eps_p, dezz_p);
}

ShellPointResult law2_shell_point(const MaterialParams& p, int iplas, double rfac, double off,
                                  const double de[5], double gs, double sig[5], double& eps_p) {
  double sxx = sig[0], syy = sig[1], sxy = sig[2];
  shell_trial(p, gs, de[0], de[1], de[2], de[3], de[4], sxx, syy, sxy, sig[3], sig[4]);

  ShellPointResult out;
  double dezz_p = 0;  // plastic in-plane trace term of 1.8
  out.deps_p = jc_return_core(p, iplas, jc_rate_of_factor(p, rfac), off, sxx, syy, sxy, eps_p, dezz_p);
  if (out.deps_p > 0)
    out.w_plastic = 0.5 * (vm_work(sig[0], sig[1], sig[2]) + vm_work(sxx, syy, sxy)) * out.deps_p;
  sig[0] = sxx;
  sig[1] = syy;
  sig[2] = sxy;
  out.dezz = shell_dezz(p, de[0], de[1], dezz_p);
  return out;
}

double law2_solid_deviator(const MaterialParams& p, double rate, double s[6], double& eps_p) {
  double deps_p = 0;
  double h = 0;
  double sy = jc_flow_stress(p, eps_p, rate, &h);
  if (eps_p > p.jc.eps_p_max) {  // failed point: no deviatoric strength any more
    sy = 0;
    h = 0;
  }
  const double svm = std::sqrt(1.5 * (s[0] * s[0] + s[1] * s[1] + s[2] * s[2]) +
                               3.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
  if (svm > sy) {
    deps_p = (svm - sy) / (3.0 * p.shear + h);
    const double scale = (sy + deps_p * h) / svm;
    for (int k = 0; k < 6; ++k) s[k] *= scale;
    eps_p += deps_p;
  }
  return deps_p;
}

}  // namespace detail

}  // namespace radx::solver
