// make_material_params: a material's parameters in the form the points and the kernels use, derived once per
// material. The constants every law has (docs/theory/elements.md 1.4 for the plane-stress moduli, 4.1 and 3.3
// for the sound speeds):
//   G = E / 2(1 + nu),  K = E / 3(1 - 2 nu),  A11 = E / (1 - nu^2),  A12 = nu A11,
//   c_shell = sqrt(E / rho0),  c_solid = sqrt((K + 4G/3) / rho0);
// then each law's own constants, filled by the law's file (johnson_cook_params, plas_brit_params,
// tab_curves_params, ogden_params, foam_params), and the failure model's (/FAIL/JOHNSON, /FAIL/TAB,
// /FAIL/BIQUAD; their cards and defaults: docs/elements-openradioss.md 6.7, fail_johnson.cpp, fail_tab.cpp,
// fail_biquad.cpp).
#include <algorithm>
#include <cmath>

#include "solver/materials/material_params.hpp"

namespace radx::solver {

namespace {

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
  } else if (m.fail_bq.on) {
    // A failed shell point carries no stress and the element goes at the thickness fraction P_thickfail
    // (Ifail_sh 2's rule); a failed solid point deletes its brick.
    const auto& f = m.fail_bq;
    p.fail.on = true;
    p.fail.kind = FailKind::Biquad;
    fail_biquad_fit(f.c1, f.c2, f.c3, f.c4, f.c5, p.fail);
    p.fail.bq_s_flag = f.s_flag;
    p.fail.bq_inst = f.inst_start;
    p.fail.el_ref = f.el_ref > 0 ? f.el_ref : 1.0;
    p.fail.ifail_sh = 2;
    p.fail.p_thick = f.p_thickfail;
    p.fail.solid = SolidFailMode::Delete;
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
  switch (m.law) {
    case model::MaterialLaw::JohnsonCook: johnson_cook_params(m, p); break;
    case model::MaterialLaw::PlasTab:
      // The curves need the model's functions (the overload below); the rest is here.
      p.tab.eps_p_max = m.eps_p_max == 0 ? 1e20 : m.eps_p_max;
      p.f_cut = m.f_cut;
      break;
    case model::MaterialLaw::PlasBrit: plas_brit_params(m, p); break;
    case model::MaterialLaw::Ogden: ogden_params(m, p); break;
    case model::MaterialLaw::Elastic:
    case model::MaterialLaw::Void:
    case model::MaterialLaw::Rigid:
    case model::MaterialLaw::FoamTab: break;  // law 70's tables need the model's functions
  }
  set_failure_params(m, p);
  return p;
}

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
  if (m.fail_bq.on && m.fail_bq.size_function >= 0) {
    const auto& fn = functions[static_cast<std::size_t>(m.fail_bq.size_function)];
    p.fail.has_size = true;
    p.fail.size.x = fn.x.data();
    p.fail.size.y = fn.y.data();
    p.fail.size.n = static_cast<int>(std::min(fn.x.size(), fn.y.size()));
    p.fail.size.scale = 1.0;
  }
  return p;
}

}  // namespace radx::solver
