// Material laws at one integration point, written once and used by shells (plane stress) and solids.
// Formulas: shared/spec/elements.md sections 1.4 (shell elasticity), 3.3 (solid pressure), 6 (LAW2
// Johnson-Cook). LAW1 is the elastic limit of the same updates (no yield).
#pragma once

#include <algorithm>

#include "solver/model/model.hpp"

// Lets GCC vectorise a hot loop over elements or points whose arrays it cannot prove distinct (they never
// overlap: each is one row of a structure of arrays). Empty elsewhere: clang's assume_safety also forces the
// vectorisation and warns (-Werror) where it cannot.
#if defined(__GNUC__) && !defined(__clang__)
#define RADX_IVDEP _Pragma("GCC ivdep")
#else
#define RADX_IVDEP
#endif

namespace radx::solver {

// v, hidden from the optimiser, for the constants of hot loops that must vectorise. Without it GCC folds a
// literal (x / 1e-20 in a floor, x * 0 in a select's zero arm) and moves the rest of the arithmetic into a
// branch; a floating-point operation in a branch may trap (-ftrapping-math), so the loop stays scalar.
inline double opaque(double v) {
#if defined(__GNUC__)
  __asm__("" : "+g"(v));
#endif
  return v;
}

// Parameters as the kernels use them (work units), derived once per material.
struct MaterialParams {
  model::MaterialLaw law = model::MaterialLaw::Elastic;
  double rho0 = 0;  // initial density rho_I
  double young = 0, nu = 0;
  double shear = 0, bulk = 0;  // G = E / 2(1 + nu), K = E / 3(1 - 2 nu)
  double a11 = 0, a12 = 0;     // plane stress: A11 = E / (1 - nu^2), A12 = nu A11
  double c_shell = 0;          // sqrt(E / rho0): shell sound speed (elements.md 4.1)
  double c_solid = 0;          // sqrt((K + 4G/3) / rho0): solid sound speed (3.3)
  // Johnson-Cook (law 2); unused for law 1.
  double a = 0, b = 0, n = 1, c = 0, eps_dot0 = 1, sig_max0 = 1e20, eps_p_max = 1e20;
  int icc = 1, flag_vp = 2;
  double f_cut = 0;
};

MaterialParams make_material_params(const model::Material& m);

// Johnson-Cook flow stress (6.2) at plastic strain eps_p and strain rate `rate`:
// sigma_y = min((a + b eps_p^n) R, SIG_max0 (R if ICC = 1 else 1)), R = 1 + c ln(max(rate, rate0)/rate0).
// `slope` (if not null) receives d sigma_y / d eps_p (0 when capped). Temperature term = 1 (radx has no
// adiabatic heating).
double jc_flow_stress(const MaterialParams& p, double eps_p, double rate, double* slope = nullptr);

// Shell point in plane stress (1.4, 6.3). de = {d_exx, d_eyy, d_gxy, d_gyz, d_gzx} (engineering shears),
// sig = {sxx, syy, sxy, syz, szx} updated in place, eps_p updated in place. gs = transverse shear
// modulus (Ashear G). iplas: 0 radial return (default), 1 iterative projection (3 Newton steps).
// off: element kill factor (Iplas 1 projection only when off == 1).
struct ShellPointResult {
  double deps_p = 0;     // plastic strain increment
  double dezz = 0;       // thickness strain increment (for the thickness output)
  double w_plastic = 0;  // plastic work per unit volume 1/2 (svm_old + svm_new) deps_p (elements.md 6.5)
};
ShellPointResult shell_point_update(const MaterialParams& p, int iplas, double rate, double off,
                                    const double de[5], double gs, double sig[5], double& eps_p);

// Johnson-Cook strain-rate factor R = 1 + c ln(max(rate, rate0)/rate0) of 6.2: 1 for law 1, and exactly 1
// without a logarithm when c = 0 or rate <= rate0. A shell's rate is one value per element (1.3), so the
// shell kernels take R once per element and update the points with shell_point_update_r.
double jc_rate_factor(const MaterialParams& p, double rate);

// shell_point_update with the strain-rate factor R = jc_rate_factor(p, rate) given instead of the rate:
// shell_point_update(p, iplas, rate, ...) is shell_point_update_r(p, iplas, jc_rate_factor(p, rate), ...).
ShellPointResult shell_point_update_r(const MaterialParams& p, int iplas, double rfac, double off,
                                      const double de[5], double gs, double sig[5], double& eps_p);

// The shell update in pieces, for the batched loops of the shell kernels (shell_section.hpp), which run the
// elastic trial of every point vectorised and call shell_point_update_r only for the points that may yield.
// shell_point_update_r is built from the same functions, so each formula is written once. All of them are
// branch-free, so that the loops that inline them vectorise.

// Elastic trial (1.4 / 6.3 step 1): in-plane trial stress into sxx syy sxy, transverse shear syz szx
// (elastic, outside the yield function) updated.
inline void shell_trial(const MaterialParams& p, double gs, double de0, double de1, double de2, double de3,
                        double de4, double& sxx, double& syy, double& sxy, double& syz, double& szx) {
  sxx = sxx + p.a11 * de0 + p.a12 * de1;
  syy = syy + p.a12 * de0 + p.a11 * de1;
  sxy = sxy + p.shear * de2;
  syz += gs * de3;
  szx += gs * de4;
}

// Thickness strain increment (1.8) from the in-plane increments and the plastic trace term d_ezz_p.
inline double shell_dezz(const MaterialParams& p, double de0, double de1, double dezz_p) {
  return (-p.nu * (de0 + de1) - (1.0 - 2.0 * p.nu) * dezz_p) / (1.0 - p.nu);
}

// Squared von Mises stress of the trial, as the radial return (Iplas 0) and the projection (Iplas 1) write
// it (their svm is the square root of these).
inline double shell_vm2_radial(double sxx, double syy, double sxy) {
  return sxx * sxx + syy * syy - sxx * syy + 3.0 * sxy * sxy;
}
inline double shell_vm2_newton(double sxx, double syy, double sxy) {
  const double s1 = sxx + syy;
  const double s2 = sxx - syy;
  return 0.25 * s1 * s1 + (0.75 * s2 * s2 + 3.0 * sxy * sxy);
}

// Lower bound of the flow stress: sigma_y(eps_p, R) >= min(a R, SIG_max0) for every eps_p >= 0 when b >= 0,
// SIG_max0 >= 0 and R >= 1 (c >= 0), since the hardening term and the cap only grow with eps_p and R.
struct ShellYieldBound {
  bool jc = false;      // law 2 (law 1 never yields)
  bool usable = false;  // the bound holds for this material
  double a = 0, sig_max0 = 0;
};
inline ShellYieldBound shell_yield_bound(const MaterialParams& p) {
  ShellYieldBound b;
  b.jc = p.law == model::MaterialLaw::JohnsonCook;
  b.usable = b.jc && p.b >= 0 && p.c >= 0 && p.sig_max0 >= 0;
  b.a = p.a;
  b.sig_max0 = p.sig_max0;
  return b;
}

// True when shell_point_update_r certainly takes no plastic step for this trial stress: law 1, Iplas 1 with
// off != 1, or a trial von Mises below the flow-stress bound (with a relative margin of 1e-12 on the squares,
// far above the rounding of the two sides). Then the update is the trial, d_eps_p = 0 and
// dezz = shell_dezz(p, de0, de1, 0). A false answer only means "take the exact update".
template <bool kNewton>
inline bool shell_stays_elastic(const ShellYieldBound& b, double rfac, double off, double eps_p, double sxx,
                                double syy, double sxy) {
  const double lb = std::min(b.a * rfac, b.sig_max0);
  const double q = kNewton ? shell_vm2_newton(sxx, syy, sxy) : shell_vm2_radial(sxx, syy, sxy);
  const bool below = b.usable & (lb >= 0) & (eps_p >= 0) & (q * (1.0 + 1e-12) <= lb * lb);
  return !b.jc | below | (kNewton & (off != 1.0));
}

// Solid point (3.3, 6.3). de = {d_xx, d_yy, d_zz, d_gxy, d_gyz, d_gzx} strain increments (engineering
// shears), mu = rho / rho0 - 1 (total volumetric strain measure), sig = {xx, yy, zz, xy, yz, zx}
// (already rotated by the element) updated in place. Pressure p = K mu (total), sig = s - p I; deviator
// incremental with radial return; once eps_p > EPS_p_max the deviator stays zero. Returns the plastic strain
// increment.
double solid_point_update(const MaterialParams& p, double rate, const double de[6], double mu, double sig[6],
                          double& eps_p);

// Current yield stress of a solid point at plastic strain eps_p and strain rate `rate` (after
// solid_point_update), for elements that limit other stresses by it (the physical hourglass of Isolid 24).
// A law that never yields returns 1e30 or more (LAW1).
double solid_yield_stress(const MaterialParams& p, double eps_p, double rate);

}  // namespace radx::solver
