// LAW1 (elastic) and LAW2 (Johnson-Cook) at one integration point: the functions of material_point.hpp.
// LAW1 is the elastic part of the same updates and never yields. LAW36 (law36_plas_tab.cpp) and
// /FAIL/JOHNSON (fail_johnson.cpp) are dispatched from here: one switch on the law per point, no virtual
// call.
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
//
// Solid (3.3, 6.3). de = {dxx, dyy, dzz, dgxy, dgyz, dgzx} (engineering shears), sig = {xx yy zz xy yz zx}.
//   s = dev(sig_old);  s_ii += 2G (de_ii - tr(de)/3),  s_ij += G dg_ij
//   svm = sqrt(3 J2) = sqrt(3/2 (s_xx^2 + s_yy^2 + s_zz^2) + 3 (s_xy^2 + s_yz^2 + s_zx^2))
//   if svm > sigma_y:  d_eps_p = (svm - sigma_y) / (3G + H),  sigma_y <- sigma_y + d_eps_p H,
//                      s *= sigma_y / svm,  eps_p += d_eps_p
//   once eps_p (start of step) > EPS_p_max: sigma_y = H = 0, so s = 0 for ever (the element is kept)
//   pressure p = K mu (total; mu = rho/rho0 - 1 > 0 in compression),  sig = s - p I
#include <algorithm>
#include <cmath>
#include <limits>

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

double rate_factor(const MaterialParams& p, double rate) {
  // rate <= rate0: max(rate, rate0)/rate0 = 1 and ln 1 = 0, so R = 1 exactly; c = 0: R = 1 + 0 ln(.) = 1.
  if (p.jc.c == 0 || rate <= p.jc.eps_dot0) return 1.0;
  return 1.0 + p.jc.c * std::log(std::max(rate, p.jc.eps_dot0) / p.jc.eps_dot0);
}

JcRate jc_rate(const MaterialParams& p, double rate) {
  return jc_rate_of_factor(p, rate_factor(p, rate));
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

// The shell point update (1.4, 1.8, 6.3) for a known strain-rate factor: the one implementation behind
// shell_point_update, shell_point_update_r and (for the points that may yield) the shell kernels.
ShellPointResult shell_point_core(const MaterialParams& p, int iplas, const JcRate& jr, double off,
                                  const double de[5], double gs, double sig[5], double& eps_p) {
  double sxx = sig[0], syy = sig[1], sxy = sig[2];
  shell_trial(p, gs, de[0], de[1], de[2], de[3], de[4], sxx, syy, sxy, sig[3], sig[4]);

  ShellPointResult out;
  double dezz_p = 0;  // plastic in-plane trace term of 1.8
  if (p.law == model::MaterialLaw::JohnsonCook) {
    out.deps_p = jc_return_core(p, iplas, jr, off, sxx, syy, sxy, eps_p, dezz_p);
    if (out.deps_p > 0)
      out.w_plastic = 0.5 * (vm_work(sig[0], sig[1], sig[2]) + vm_work(sxx, syy, sxy)) * out.deps_p;
  }
  sig[0] = sxx;
  sig[1] = syy;
  sig[2] = sxy;
  out.dezz = shell_dezz(p, de[0], de[1], dezz_p);
  return out;
}

}  // namespace

namespace {

// LAW42 (Ogden): its terms, cut-off and form, and the starter's moduli.
void set_ogden_params(const model::Material& m, MaterialParams& p) {
  auto& o = p.ogden;
  o.n = static_cast<int>(std::min<std::size_t>(m.ogden.mu.size(), OgdenParams::kMaxTerms));
  for (int k = 0; k < o.n; ++k) {
    o.mu[k] = m.ogden.mu[static_cast<std::size_t>(k)];
    o.alpha[k] = m.ogden.alpha[static_cast<std::size_t>(k)];
    o.g += o.mu[k] * o.alpha[k];
  }
  o.sig_cut = m.ogden.sig_cut > 0 ? m.ogden.sig_cut : 1e20;
  o.iform = m.ogden.iform == 2 ? 2 : 1;
  // The starter's moduli (build_hyperelastic.cpp): G0 = g / 2, K = g (1 + nu) / 3 (1 - 2 nu).
  p.shear = m.shear;
  p.bulk = m.bulk;
  p.c_solid = p.rho0 > 0 ? std::sqrt((p.bulk + 4.0 * p.shear / 3.0) / p.rho0) : 0.0;
  o.stiffen = p.bulk > 24.0 * o.g;
  o.nu1 = 40.0 * (0.5 - (3.0 * p.bulk - o.g) / (6.0 * p.bulk + o.g));
}

// The failure model on the material (/FAIL/JOHNSON or /FAIL/TAB), with their defaults.
void set_failure_params(const model::Material& m, MaterialParams& p) {
  if (m.fail_jc.on) {
    const auto& f = m.fail_jc;
    p.fail.on = true;
    p.fail.kind = FailKind::Johnson;
    p.fail.d1 = f.d1;
    p.fail.d2 = f.d2;
    p.fail.d3 = f.d3;
    p.fail.d4 = f.d4;
    p.fail.d5 = f.d5;
    p.fail.eps_dot0 = f.eps_dot_0 > 0 ? f.eps_dot_0 : 1e-20;
    p.fail.eps_f_min = f.eps_f_min;
    p.fail.ifail_sh = f.ifail_sh == 0 ? 1 : f.ifail_sh;
    switch (f.ifail_so) {
      case 2: p.fail.solid = SolidFailMode::DeviatorZero; break;
      case 3: p.fail.solid = SolidFailMode::DeviatorTension; break;
      case 4: p.fail.solid = SolidFailMode::StressZero; break;
      default: p.fail.solid = SolidFailMode::Delete; break;
    }
  } else if (m.fail_tab.on) {
    // The rows (functions) are set by the overload with the model's functions.
    const auto& f = m.fail_tab;
    p.fail.on = true;
    p.fail.kind = FailKind::Tab;
    p.fail.temp_factor = f.temp_factor;
    p.fail.el_ref = f.el_ref > 0 ? f.el_ref : 1.0;
    p.fail.dcrit = f.dcrit > 0 ? f.dcrit : 1.0;
    p.fail.n_exp = f.n > 0 ? f.n : 1.0;
    p.fail.ifail_sh = f.ifail_sh == 0 ? 1 : f.ifail_sh;
    p.fail.keep_failed_stress = p.fail.ifail_sh == 3;
    p.fail.p_thick = f.p_thickfail > 0 ? f.p_thickfail : 1.0 - 1e-6;
    switch (f.ifail_so) {
      case 2: p.fail.solid = SolidFailMode::NormalToMean; break;
      case 3: p.fail.solid = SolidFailMode::Keep; break;
      default: p.fail.solid = SolidFailMode::Delete; break;
    }
  }
}

}  // namespace

MaterialParams make_material_params(const model::Material& m) {
  MaterialParams p;
  p.law = m.law;
  p.rho0 = m.rho;
  p.young = m.young;
  p.nu = m.poisson;
  p.shear = p.young / (2.0 * (1.0 + p.nu));
  p.bulk = p.young / (3.0 * (1.0 - 2.0 * p.nu));
  p.a11 = p.young / (1.0 - p.nu * p.nu);
  p.a12 = p.nu * p.a11;
  p.c_shell = p.rho0 > 0 ? std::sqrt(p.young / p.rho0) : 0.0;
  p.c_solid = p.rho0 > 0 ? std::sqrt((p.bulk + 4.0 * p.shear / 3.0) / p.rho0) : 0.0;
  if (m.law == model::MaterialLaw::JohnsonCook) {
    // 6.1 defaults, applied again here so that a Material built by hand behaves like one from the starter.
    p.jc.a = m.a;
    p.jc.b = m.b;
    p.jc.n = m.n == 0 ? 1.0 : m.n;
    p.jc.c = m.c;
    p.jc.eps_dot0 = (m.c == 0 || m.eps_dot_0 <= 0) ? 1.0 : m.eps_dot_0;
    p.jc.sig_max0 = m.sig_max0 == 0 ? 1e20 : m.sig_max0;
    p.jc.eps_p_max = m.eps_p_max == 0 ? 1e20 : m.eps_p_max;
    p.jc.icc = m.icc == 0 ? 1 : m.icc;
    p.jc.flag_vp = m.flag_vp == 0 ? 2 : m.flag_vp;
    p.f_cut = m.f_cut;
  }
  if (m.law == model::MaterialLaw::PlasTab) {
    p.tab.eps_p_max = m.eps_p_max == 0 ? 1e20 : m.eps_p_max;
    p.f_cut = m.f_cut;
  }
  if (m.law == model::MaterialLaw::PlasBrit) {
    // hm_read_mat27.F's defaults, applied again for a Material built by hand.
    p.jc.a = m.a == 0 ? 1e20 : m.a;
    p.jc.b = m.b;
    p.jc.n = m.n == 0 ? 1.0 : m.n;
    p.jc.c = m.c;
    p.jc.eps_dot0 = (m.c == 0 || m.eps_dot_0 <= 0) ? 1.0 : m.eps_dot_0;
    p.jc.sig_max0 = m.sig_max0 == 0 ? 1e20 : m.sig_max0;
    p.jc.icc = m.icc == 0 ? 1 : m.icc;
    p.f_cut = m.f_cut;
    const auto& b = m.brit;
    p.brit.eps_t = b.eps_t1 == 0 ? 1e20 : b.eps_t1;
    p.brit.eps_m = b.eps_m1 == 0 ? 1.1e20 : b.eps_m1;
    p.brit.d_max = b.d_max1 == 0 ? 0.999 : b.d_max1;
    p.brit.eps_f = b.eps_f1 == 0 ? 1.2e22 : b.eps_f1;
    p.brit.point_rate = m.fsmooth == 0 && m.f_cut == 0;
  }
  if (m.law == model::MaterialLaw::Ogden) set_ogden_params(m, p);
  set_failure_params(m, p);
  return p;
}

namespace detail {
double jc_shell_return(const MaterialParams& p, int iplas, double rfac, double off, double& sxx, double& syy,
                       double& sxy, double& eps_p, double& dezz_p) {
  return jc_return_core(p, iplas, jc_rate_of_factor(p, rfac), off, sxx, syy, sxy, eps_p, dezz_p);
}
}  // namespace detail

namespace {

// Law 70's tables and moduli (solver/model/foam_table.hpp) from the model's curves. The unloading table is
// the first loading curve when the deck gives none and Iflag <= 2 (hm_read_mat70.F; Iflag is then 0); Iflag 3
// and 4 need no unloading curve.
void foam_params(const model::Material& m, const std::vector<model::Function>& functions, MaterialParams& p) {
  const auto& ft = m.foam;
  auto input = [&](std::int32_t fi, double scale, double rate) {
    model::FoamCurveInput c;
    if (fi >= 0 && static_cast<std::size_t>(fi) < functions.size()) {
      const auto& fn = functions[static_cast<std::size_t>(fi)];
      c.x = fn.x.data();
      c.y = fn.y.data();
      c.n = std::min(fn.x.size(), fn.y.size());
    }
    c.scale = scale == 0 ? 1.0 : scale;
    c.rate = rate;
    return c;
  };
  std::vector<model::FoamCurveInput> load, unload;
  for (std::size_t i = 0; i < ft.load_function.size(); ++i)
    load.push_back(input(ft.load_function[i], ft.load_scale[i], ft.load_rate[i]));
  for (std::size_t i = 0; i < ft.unload_function.size(); ++i)
    unload.push_back(input(ft.unload_function[i], ft.unload_scale[i], ft.unload_rate[i]));
  auto by_rate = [](const model::FoamCurveInput& a, const model::FoamCurveInput& b) {
    return a.rate < b.rate;
  };
  std::stable_sort(load.begin(), load.end(), by_rate);
  std::stable_sort(unload.begin(), unload.end(), by_rate);
  if (load.size() > 1) load[0].rate = 0;  // the static curve's rate is 0 (hm_read_mat70.F)
  if (unload.size() > 1) unload[0].rate = 0;
  auto& f = p.foam;
  f.iflag = ft.iflag;
  if (unload.empty() && ft.iflag <= 2 && !load.empty()) {
    unload.push_back(load[0]);
    f.iflag = 0;
  }
  f.shape = ft.shape == 0 ? 1.0 : ft.shape;
  f.hys = ft.hys == 0 ? 1.0 : ft.hys;
  auto table = std::make_shared<model::FoamTable>(model::build_foam_table(load));
  const auto mod = model::foam_moduli(*table, m.young, ft.e_max, ft.eps_max);
  f.e0 = mod.e0;
  f.e_max = mod.e_max;
  f.aa = mod.aa;
  f.eps_max = mod.eps_max;
  f.yld_emax = mod.yld_emax;
  f.static_rate = table->rate.empty() ? 0.0 : table->rate[0];
  f.load = std::move(table);
  if (!unload.empty()) f.unload = std::make_shared<model::FoamTable>(model::build_foam_table(unload));
  if (ft.itens == 1 && ft.tens_function >= 0 &&
      static_cast<std::size_t>(ft.tens_function) < functions.size()) {
    // The tension factor is the function itself (no processing), times its scale.
    const auto& fn = functions[static_cast<std::size_t>(ft.tens_function)];
    auto t = std::make_shared<model::FoamTable>();
    t->x = fn.x;
    t->rate = {0.0};
    const double sc = ft.tens_scale == 0 ? 1.0 : ft.tens_scale;
    for (double v : fn.y) t->y.push_back(sc * v);
    f.tension = std::move(t);
  }
  // The moduli of E0 (the initial wave speed, the contact stiffness).
  p.young = f.e0;
  p.shear = p.young / (2.0 * (1.0 + p.nu));
  p.bulk = p.young / (3.0 * (1.0 - 2.0 * p.nu));
  p.c_solid = p.rho0 > 0 ? std::sqrt((p.bulk + 4.0 * p.shear / 3.0) / p.rho0) : 0.0;
  p.f_cut = ft.israte > 0 || m.f_cut > 0 ? m.f_cut : 0.0;
}

}  // namespace

MaterialParams make_material_params(const model::Material& m, const std::vector<model::Function>& functions,
                                    std::vector<TabCurve>& curves) {
  MaterialParams p = make_material_params(m);
  curves.clear();
  if (m.law == model::MaterialLaw::PlasTab) tab_curves_params(m, functions, curves, p);
  if (m.law == model::MaterialLaw::FoamTab) foam_params(m, functions, p);
  if (m.fail_tab.on) {
    // /FAIL/TAB's rows after the law-36 curves in the same vector; the pointers are taken once it is full.
    const auto view = [&](std::int32_t fi, double scale, double rate) {
      TabCurve c;
      if (fi >= 0 && static_cast<std::size_t>(fi) < functions.size()) {
        const auto& fn = functions[static_cast<std::size_t>(fi)];
        c.x = fn.x.data();
        c.y = fn.y.data();
        c.n = static_cast<int>(std::min(fn.x.size(), fn.y.size()));
      }
      c.scale = scale == 0 ? 1.0 : scale;
      c.rate = rate;
      return c;
    };
    const auto& f = m.fail_tab;
    const std::size_t first = curves.size();
    for (std::size_t i = 0; i < f.function.size(); ++i)
      curves.push_back(view(f.function[i], f.scale[i], f.rate[i]));
    if (p.tab.n_curves > 0) p.tab.curves = curves.data();
    p.fail.rows = curves.data() + first;
    p.fail.n_rows = static_cast<int>(f.function.size());
    p.fail.has_size = f.size_function >= 0;
    if (p.fail.has_size) p.fail.size = view(f.size_function, f.size_scale, 0.0);
  }
  return p;
}

double jc_flow_stress(const MaterialParams& p, double eps_p, double rate, double* slope) {
  return jc_flow_stress_at(p, eps_p, jc_rate(p, rate), slope);
}

double jc_rate_factor(const MaterialParams& p, double rate) {
  switch (p.law) {
    case model::MaterialLaw::JohnsonCook: return rate_factor(p, rate);
    case model::MaterialLaw::PlasTab: return p.tab.n_curves > 1 ? rate : 1.0;
    case model::MaterialLaw::Elastic:
    case model::MaterialLaw::Void:
    case model::MaterialLaw::Rigid:
    case model::MaterialLaw::Ogden:            // bricks only, no rate term
    case model::MaterialLaw::FoamTab:          // bricks only, its rate enters its curves
    case model::MaterialLaw::PlasBrit: break;  // law 27 takes its rate term per point (law27_plas_brit.cpp)
  }
  return 1.0;
}

double shell_rate_threshold(const MaterialParams& p) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  switch (p.law) {
    case model::MaterialLaw::JohnsonCook: return p.jc.c != 0 ? p.jc.eps_dot0 : kInf;
    case model::MaterialLaw::PlasTab: return p.tab.n_curves > 1 ? -kInf : kInf;
    case model::MaterialLaw::Elastic:
    case model::MaterialLaw::PlasBrit:
    case model::MaterialLaw::Void:
    case model::MaterialLaw::Ogden:
    case model::MaterialLaw::FoamTab:
    case model::MaterialLaw::Rigid: break;
  }
  return kInf;
}

ShellPointResult shell_point_update(const MaterialParams& p, int iplas, double rate, double off,
                                    const double de[5], double gs, double sig[5], double& eps_p) {
  return shell_point_update_r(p, iplas, jc_rate_factor(p, rate), off, de, gs, sig, eps_p);
}

ShellPointResult shell_point_update_r(const MaterialParams& p, int iplas, double rfac, double off,
                                      const double de[5], double gs, double sig[5], double& eps_p) {
  if (p.law == model::MaterialLaw::PlasTab)
    return detail::law36_shell_point(p, iplas, rfac, off, de, gs, sig, eps_p);
  return shell_point_core(p, iplas, jc_rate_of_factor(p, rfac), off, de, gs, sig, eps_p);
}

double solid_point_update(const MaterialParams& p, double rate, const double de[6], double mu, double sig[6],
                          double& eps_p) {
  const double mean = (sig[0] + sig[1] + sig[2]) / 3.0;
  const double ev3 = (de[0] + de[1] + de[2]) / 3.0;
  const double g2 = 2.0 * p.shear;
  double s[6] = {sig[0] - mean + g2 * (de[0] - ev3), sig[1] - mean + g2 * (de[1] - ev3),
                 sig[2] - mean + g2 * (de[2] - ev3), sig[3] + p.shear * de[3],
                 sig[4] + p.shear * de[4],           sig[5] + p.shear * de[5]};

  double deps_p = 0;
  if (p.law == model::MaterialLaw::JohnsonCook) {
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
      for (double& v : s) v *= scale;
      eps_p += deps_p;
    }
  } else if (p.law == model::MaterialLaw::PlasTab) {
    deps_p = detail::law36_solid_deviator(p, rate, s, eps_p);
  }
  const double pressure = p.bulk * mu;
  sig[0] = s[0] - pressure;
  sig[1] = s[1] - pressure;
  sig[2] = s[2] - pressure;
  sig[3] = s[3];
  sig[4] = s[4];
  sig[5] = s[5];
  return deps_p;
}

double solid_yield_stress(const MaterialParams& p, double eps_p, double rate) {
  switch (p.law) {
    case model::MaterialLaw::JohnsonCook:
      // A failed point (eps_p beyond EPS_p_max) has no deviatoric strength left (solid_point_update).
      return eps_p > p.jc.eps_p_max ? 0.0 : jc_flow_stress(p, eps_p, rate);
    case model::MaterialLaw::PlasTab: return tab_flow_stress(p, eps_p, rate);
    default: return 1e30;  // LAW1: elastic
  }
}

}  // namespace radx::solver
