// Material laws at one integration point, written once and used by shells (plane stress) and solids.
// Formulas: shared/spec/elements.md sections 1.4 (shell elasticity), 3.3 (solid pressure), 6 (LAW2
// Johnson-Cook). LAW1 is the elastic limit of the same updates (no yield).
#pragma once

#include "solver/model/model.hpp"

namespace radx::solver {

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
  double deps_p = 0;  // plastic strain increment
  double dezz = 0;    // thickness strain increment (for the thickness output)
};
ShellPointResult shell_point_update(const MaterialParams& p, int iplas, double rate, double off,
                                    const double de[5], double gs, double sig[5], double& eps_p);

// Solid point (3.3, 6.3). de = {d_xx, d_yy, d_zz, d_gxy, d_gyz, d_gzx} strain increments (engineering
// shears), mu = rho / rho0 - 1 (total volumetric strain measure), sig = {xx, yy, zz, xy, yz, zx}
// (already rotated by the element) updated in place. Pressure p = K mu (total), sig = s - p I; deviator
// incremental with radial return; once eps_p > EPS_p_max the deviator stays zero. Returns the plastic strain
// increment.
double solid_point_update(const MaterialParams& p, double rate, const double de[6], double mu, double sig[6],
                          double& eps_p);

}  // namespace radx::solver
