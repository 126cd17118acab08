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
//
// The one entry point material_point_update takes any law through these same functions: a shell point
// (plane stress) through the shell point of its law, with /FAIL/* when the material has one; a solid point
// through solid_point_update (laws 1, 2, 36 and their failure), ogden_point (law 42, from F) or foam_point
// (law 70, from the strain V - I of F and the increment).
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

PointState initial_point_state(const MaterialParams& p) {
  PointState st;
  st.brit[kBritCos] = 1.0;  // the crack frame is the element frame until the crack opens
  if (p.law == model::MaterialLaw::FoamTab) foam_initial_state(p, st.foam);
  return st;
}

namespace {

// A shell point: the stress and the increment in the shells' five components (xx yy xy yz zx).
PointResult plane_stress_point(const MaterialParams& p, const PointInput& in, PointState& st) {
  PointResult out;
  const double de[5] = {in.de[0], in.de[1], in.de[3], in.de[4], in.de[5]};
  double sig[5] = {st.sig[0], st.sig[1], st.sig[3], st.sig[4], st.sig[5]};
  const double gs = in.transverse_shear;
  ShellPointResult r;
  switch (p.law) {
    case model::MaterialLaw::PlasBrit:
      r = detail::law27_shell_point(p, in.iplas, in.rate, in.dt, in.off, de, gs, sig, st.eps_p, st.brit, 1);
      break;
    case model::MaterialLaw::Elastic:
    case model::MaterialLaw::JohnsonCook:
    case model::MaterialLaw::PlasTab:
      r = p.fail.on ? shell_point_update_fail(p, in.iplas, jc_rate_factor(p, in.rate), in.rate, in.fail_scale,
                                              in.off, de, gs, sig, st.eps_p, st.dmg)
                    : shell_point_update(p, in.iplas, in.rate, in.off, de, gs, sig, st.eps_p);
      // The laws' plastic-strain limits delete the element (shell_section.hpp): law 36 at once past
      // Eps_p_max, law 2 progressively from EPS_p_max on (6.4).
      r.fails = (p.law == model::MaterialLaw::PlasTab && in.off == 1.0 && st.eps_p > p.tab.eps_p_max) ||
                (p.law == model::MaterialLaw::JohnsonCook && st.eps_p >= p.jc.eps_p_max);
      break;
    case model::MaterialLaw::Void:
    case model::MaterialLaw::Rigid:
    case model::MaterialLaw::Ogden:
    case model::MaterialLaw::FoamTab: out.supported = false; return out;
  }
  st.sig[0] = sig[0];
  st.sig[1] = sig[1];
  st.sig[2] = 0.0;
  st.sig[3] = sig[2];
  st.sig[4] = sig[3];
  st.sig[5] = sig[4];
  out.deps_p = r.deps_p;
  out.dezz = r.dezz;
  out.w_plastic = r.w_plastic;
  out.wave_speed = p.c_shell;
  out.element_fails = r.fails;
  return out;
}

PointResult solid_point(const MaterialParams& p, const PointInput& in, PointState& st) {
  PointResult out;
  out.wave_speed = p.c_solid;
  switch (p.law) {
    case model::MaterialLaw::Elastic:
    case model::MaterialLaw::JohnsonCook:
    case model::MaterialLaw::PlasTab: {
      const SolidPointResult r =
          solid_point_update(p, in.rate, in.de, in.rho_ratio - 1.0, st.sig, st.eps_p, st.dmg, in.off);
      out.deps_p = r.deps_p;
      out.element_fails = r.element_fails;
      break;
    }
    case model::MaterialLaw::Ogden: {
      const OgdenPointResult r = ogden_point(p, in.F, st.sig);
      out.wave_speed = std::sqrt(r.modulus / (in.rho_ratio * p.rho0));
      out.element_fails = r.cut && in.off == 1.0;
      break;
    }
    case model::MaterialLaw::FoamTab: {
      double eps[6];
      foam_strain(in.F, eps);
      out.wave_speed = foam_point(p, eps, in.de, in.rate, in.rho_ratio, st.sig, st.foam);
      break;
    }
    case model::MaterialLaw::PlasBrit:  // shells only
    case model::MaterialLaw::Void:
    case model::MaterialLaw::Rigid: out.supported = false; break;
  }
  return out;
}

}  // namespace

PointResult material_point_update(const MaterialParams& p, const PointInput& in, PointState& st) {
  return in.plane_stress ? plane_stress_point(p, in, st) : solid_point(p, in, st);
}

}  // namespace radx::solver
