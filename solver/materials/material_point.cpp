// The dispatch of the material laws at one integration point, and LAW1 (elastic), which is the elastic part
// every incremental law shares: one switch on the law per point, no virtual call. Each law's own update is in
// its file (law2_plas_johns.cpp, law27_plas_brit.cpp, law36_plas_tab.cpp, law42_ogden.cpp,
// law70_foam_tab.cpp), its failure model beside them (failure_damage.cpp).
//
// Sources: docs/theory/elements.md 1.4 (shell elasticity), 1.8 (thickness strain), 3.3 (solid pressure).
//
// Shell, plane stress (1.4). de = {dexx, deyy, dgxy, dgyz, dgzx} (engineering shears).
//   trial:  sxx += A11 dexx + A12 deyy,  syy += A12 dexx + A11 deyy,  sxy += G dgxy,
//           syz += GS dgyz,  szx += GS dgzx          (LAW1: the update; the other laws correct it)
//   thickness strain increment (1.8): dezz = [-nu (dexx + deyy) - (1 - 2 nu) d_ezz_p] / (1 - nu)
//                                     (d_ezz_p = 0 for LAW1)
// Solid (3.3). de = {dxx, dyy, dzz, dgxy, dgyz, dgzx} (engineering shears), sig = {xx yy zz xy yz zx}.
//   s = dev(sig_old);  s_ii += 2G (de_ii - tr(de)/3),  s_ij += G dg_ij   (LAW1: kept; LAW2, LAW36 return it)
//   pressure p = K mu (total; mu = rho/rho0 - 1 > 0 in compression),  sig = s - p I
#include <algorithm>
#include <cmath>
#include <limits>

#include "solver/materials/material_point.hpp"

namespace radx::solver {

double jc_rate_factor(const MaterialParams& p, double rate) {
  switch (p.law) {
    case model::MaterialLaw::JohnsonCook: return johnson_cook_rate_factor(p, rate);
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

namespace detail {

ShellPointResult elastic_shell_point(const MaterialParams& p, const double de[5], double gs, double sig[5]) {
  double sxx = sig[0], syy = sig[1], sxy = sig[2];
  shell_trial(p, gs, de[0], de[1], de[2], de[3], de[4], sxx, syy, sxy, sig[3], sig[4]);
  ShellPointResult out;
  sig[0] = sxx;
  sig[1] = syy;
  sig[2] = sxy;
  out.dezz = shell_dezz(p, de[0], de[1], 0.0);
  return out;
}

}  // namespace detail

ShellPointResult shell_point_update(const MaterialParams& p, int iplas, double rate, double off,
                                    const double de[5], double gs, double sig[5], double& eps_p) {
  return shell_point_update_r(p, iplas, jc_rate_factor(p, rate), off, de, gs, sig, eps_p);
}

ShellPointResult shell_point_update_r(const MaterialParams& p, int iplas, double rfac, double off,
                                      const double de[5], double gs, double sig[5], double& eps_p) {
  switch (p.law) {
    case model::MaterialLaw::PlasTab:
      return detail::law36_shell_point(p, iplas, rfac, off, de, gs, sig, eps_p);
    case model::MaterialLaw::JohnsonCook:
      return detail::law2_shell_point(p, iplas, rfac, off, de, gs, sig, eps_p);
    case model::MaterialLaw::Elastic:
    case model::MaterialLaw::PlasBrit:  // its own point (law27_shell_point) needs its state rows
    case model::MaterialLaw::Void:
    case model::MaterialLaw::Rigid:
    case model::MaterialLaw::Ogden:
    case model::MaterialLaw::FoamTab: break;
  }
  return detail::elastic_shell_point(p, de, gs, sig);
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
    deps_p = detail::law2_solid_deviator(p, rate, s, eps_p);
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
