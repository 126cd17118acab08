// Material laws at one integration point, written once and used by shells (plane stress) and solids
// (material_point.cpp dispatches to the law files). Two ways in:
// - material_point_update, the one entry point for any law at one point: a strain increment and the
//   deformation gradient in, the stress and the point's state updated (the point tests drive every law
//   through it);
// - the specialised paths the element kernels take (shell_point_update_r and the shell pieces their batched
//   loops inline, solid_point_update, and the law functions of the total-strain laws), from which
//   material_point_update is built.
// Formulas: docs/theory/elements.md sections 1.4 (shell elasticity), 3.3 (solid pressure), 6 (LAW2
// Johnson-Cook). LAW1 is the elastic limit of the same updates (no yield).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "solver/materials/material_params.hpp"

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

// Square roots of v[0 .. n), in a loop of their own: the kernels put the arguments in an array and take the
// roots here. The solver is compiled with -fno-math-errno (solver/CMakeLists.txt), so GCC vectorises this
// loop at the width of the copy it is inlined into (sqrtpd rounds exactly as sqrtsd and the library).
inline void sqrt_in_place(double* v, int n) {
  for (int i = 0; i < n; ++i) v[i] = std::sqrt(v[i]);
}

// Shell point in plane stress (1.4, 6.3). de = {d_exx, d_eyy, d_gxy, d_gyz, d_gzx} (engineering shears),
// sig = {sxx, syy, sxy, syz, szx} updated in place, eps_p updated in place. gs = transverse shear
// modulus (Ashear G). iplas: 0 radial return (default), 1 iterative projection (3 Newton steps).
// off: element kill factor (Iplas 1 projection only when off == 1).
struct ShellPointResult {
  double deps_p = 0;  // plastic strain increment
  double dezz = 0;    // thickness strain increment (for the thickness output)
  // plastic work per unit volume 1/2 (svm_old + svm_new) deps_p (docs/theory/elements.md 6.5)
  double w_plastic = 0;
  bool fails = false;  // law 27: the point's principal strain passed EPS_f1, the element is deleted
};
ShellPointResult shell_point_update(const MaterialParams& p, int iplas, double rate, double off,
                                    const double de[5], double gs, double sig[5], double& eps_p);

// The strain-rate term of a shell element, taken once per element since a shell's rate is one value per
// element (1.3), with which the kernels update the points through shell_point_update_r: for law 2 the
// Johnson-Cook factor R = 1 + c ln(max(rate, rate0)/rate0) of 6.2 (exactly 1 without a logarithm when c = 0
// or rate <= rate0); for law 36 the rate itself (the curves are chosen per point); 1 for law 1.
double jc_rate_factor(const MaterialParams& p, double rate);

// Rate at or below which jc_rate_factor is 1 (+infinity: always 1); the kernels call jc_rate_factor only
// above it. -infinity for law 36 with several curves (the term is the rate).
double shell_rate_threshold(const MaterialParams& p);

// shell_point_update with the rate term jc_rate_factor(p, rate) given instead of the rate:
// shell_point_update(p, iplas, rate, ...) is shell_point_update_r(p, iplas, jc_rate_factor(p, rate), ...).
ShellPointResult shell_point_update_r(const MaterialParams& p, int iplas, double rfac, double off,
                                      const double de[5], double gs, double sig[5], double& eps_p);

// The shell update in pieces, for the batched loops of the shell kernels (shell_section.hpp), which run the
// elastic trial of every point vectorised and call shell_point_update_r only for the points that may yield.
// shell_point_update_r is built from the same functions, so each formula is written once. All of them are
// branch-free, so that the loops that inline them vectorise.

// Elastic trial (1.4 / 6.3 step 1): in-plane trial stress into sxx syy sxy, transverse shear syz szx
// (elastic, outside the yield function) updated.
// (P: MaterialParams, or any struct with its a11, a12, shear and nu: the batched loops copy those four.)
template <class P>
inline void shell_trial(const P& p, double gs, double de0, double de1, double de2, double de3, double de4,
                        double& sxx, double& syy, double& sxy, double& syz, double& szx) {
  sxx = sxx + p.a11 * de0 + p.a12 * de1;
  syy = syy + p.a12 * de0 + p.a11 * de1;
  sxy = sxy + p.shear * de2;
  syz += gs * de3;
  szx += gs * de4;
}

// Thickness strain increment (1.8) from the in-plane increments and the plastic trace term d_ezz_p.
template <class P>
inline double shell_dezz(const P& p, double de0, double de1, double dezz_p) {
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

// Lower bound of the flow stress.
// Law 2: sigma_y(eps_p, R) >= min(a R, SIG_max0) for every eps_p >= 0 when b >= 0, SIG_max0 >= 0 and R >= 1
// (c >= 0), since the hardening term and the cap only grow with eps_p and R.
// Law 36: sigma_y >= tab.lower, the smallest scaled ordinate of the curves over eps_p >= 0, while the rate is
// at most the highest curve rate (then the rate weight is in [0, 1], so sigma_y lies between two curves'
// values); the rate term rfac is the rate, hence a = tab.lower, r_scale = 0 and r_max = tab.rate_max. With a
// /FAIL/JOHNSON no bound is used: every point takes the exact update, which also handles the damage.
struct ShellYieldBound {
  bool jc = false;      // the law may yield (laws 2 and 36; law 1 never yields)
  bool usable = false;  // the bound holds for this material
  double a = 0, sig_max0 = 0;
  double r_scale = 1;  // 1: the bound scales with the rate term (law 2); 0: it does not (law 36)
  double r_max = 1e300;
};
inline ShellYieldBound shell_yield_bound(const MaterialParams& p) {
  ShellYieldBound b;
  if (p.law == model::MaterialLaw::PlasBrit) {  // damaged stiffness: every point takes the exact update
    b.jc = true;
    return b;
  }
  if (p.law == model::MaterialLaw::PlasTab) {
    b.jc = true;
    b.usable = p.tab.bound && !p.fail.on;
    b.a = p.tab.lower;
    b.sig_max0 = 1e300;
    b.r_scale = 0;
    b.r_max = p.tab.rate_max;
    return b;
  }
  b.jc = p.law == model::MaterialLaw::JohnsonCook;
  b.usable = b.jc && p.jc.b >= 0 && p.jc.c >= 0 && p.jc.sig_max0 >= 0 && !p.fail.on;
  b.a = p.jc.a;
  b.sig_max0 = p.jc.sig_max0;
  return b;
}

// True when shell_point_update_r certainly takes no plastic step for this trial stress: law 1, Iplas 1 with
// off != 1, or a trial von Mises below the flow-stress bound (with a relative margin of 1e-12 on the squares,
// far above the rounding of the two sides). Then the update is the trial, d_eps_p = 0 and
// dezz = shell_dezz(p, de0, de1, 0). A false answer only means "take the exact update".
template <bool kNewton>
inline bool shell_stays_elastic(const ShellYieldBound& b, double rfac, double off, double eps_p, double sxx,
                                double syy, double sxy) {
  const double lb = std::min(b.a * (b.r_scale * rfac + (1.0 - b.r_scale)), b.sig_max0);
  const double q = kNewton ? shell_vm2_newton(sxx, syy, sxy) : shell_vm2_radial(sxx, syy, sxy);
  const bool below = b.usable & (lb >= 0) & (eps_p >= 0) & (rfac <= b.r_max) & (q * (1.0 + 1e-12) <= lb * lb);
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
// False for a law whose solid_yield_stress is 1e30 whatever the state (LAW1): a kernel then skips the work
// only a finite yield stress needs.
inline bool solid_law_yields(const MaterialParams& p) {
  return p.law != model::MaterialLaw::Elastic;
}

// The solid point with its failure state: law 36 Eps_p_max and the failure model (SolidFailMode) on top of
// the update above. dmg: the point's normalised damage D / Dcrit (0 .. 1), updated. off: the element factor
// at the start of the cycle (the damage accumulates only while it is 1). element_fails: the element starts
// its deletion this cycle (law 36 eps_p > Eps_p_max, or SolidFailMode::Delete with d reaching 1); the caller
// sets its factor to 0.8 and lets it decay as for shells (brick_next_off).
struct SolidPointResult {
  double deps_p = 0;
  bool element_fails = false;
};
SolidPointResult solid_point_update(const MaterialParams& p, double rate, const double de[6], double mu,
                                    double sig[6], double& eps_p, double& dmg, double off);

// Element factor of a brick after its update (OpenRadioss sigeps36.F, fail_johnson.F): a factor below 1
// decays by 0.8 per cycle and becomes 0 (deleted) once below 0.1; a live brick that fails this cycle takes
// 0.8.
inline double brick_next_off(double off_start, bool fails) {
  if (off_start < 1.0) return off_start < 0.1 ? 0.0 : 0.8 * off_start;
  return fails ? 0.8 : off_start;
}

// The shell point with its failure model: shell_point_update_r, then, while the element is intact (off = 1)
// and the point alive (dmg < 1), the damage stage with the plane-stress sigma_m = (sxx + syy)/3 and svm of
// the updated stress; a failed point (dmg >= 1) carries no stress any more (all five components zero) unless
// the model keeps it (/FAIL/TAB Ifail_sh 3). rate: the element's strain rate; escale: its size factor;
// dmg_inst: the point's /FAIL/BIQUAD instability damage (S_Flag 3), updated, or nullptr.
ShellPointResult shell_point_update_fail(const MaterialParams& p, int iplas, double rfac, double rate,
                                         double escale, double off, const double de[5], double gs,
                                         double sig[5], double& eps_p, double& dmg,
                                         double* dmg_inst = nullptr);

// Internal pieces of the law files, for material_point.cpp's dispatch (the shell section also calls law 27's
// point directly, with the group's state rows).
namespace detail {
// Law 1 shell point (material_point.cpp): the elastic trial and the thickness strain increment.
ShellPointResult elastic_shell_point(const MaterialParams& p, const double de[5], double gs, double sig[5]);
// Law 2 shell point (law2_plas_johns.cpp) for the rate factor rfac: the elastic trial, the plastic
// correction, its plastic work and the thickness strain increment.
ShellPointResult law2_shell_point(const MaterialParams& p, int iplas, double rfac, double off,
                                  const double de[5], double gs, double sig[5], double& eps_p);
// LAW2's plastic correction of a plane-stress trial (sxx, syy, sxy) in place, for the rate factor rfac
// (law2_plas_johns.cpp): radial return (Iplas 0) or the Newton projection (Iplas 1, off = 1 only).
// eps_p is updated; returns d_eps_p, and dezz_p receives the plastic trace term of 1.8.
double jc_shell_return(const MaterialParams& p, int iplas, double rfac, double off, double& sxx, double& syy,
                       double& sxy, double& eps_p, double& dezz_p);
// Law 2 radial return of a solid's trial deviator s (in place, law2_plas_johns.cpp); returns d_eps_p and
// updates eps_p.
double law2_solid_deviator(const MaterialParams& p, double rate, double s[6], double& eps_p);
// Law 27 shell point (law27_plas_brit.cpp). rate: the element's filtered strain rate; dt1: the step of the
// increments; st: the point's state, row k at st[k * stride] (BritVar).
ShellPointResult law27_shell_point(const MaterialParams& p, int iplas, double rate, double dt1, double off,
                                   const double de[5], double gs, double sig[5], double& eps_p, double* st,
                                   std::size_t stride);
// Law 36 shell point (law36_plas_tab.cpp); rate = the element's filtered strain rate.
ShellPointResult law36_shell_point(const MaterialParams& p, int iplas, double rate, double off,
                                   const double de[5], double gs, double sig[5], double& eps_p);
// Law 36 radial return of a solid's trial deviator s (in place); returns d_eps_p and updates eps_p.
double law36_solid_deviator(const MaterialParams& p, double rate, double s[6], double& eps_p);
}  // namespace detail

// ---- The one entry point: any law at one integration point ----

// What a point is given for one step. Strains in the axes of the stress; shears engineering (2 e_ab).
// plane_stress (shells): sigma_zz = 0, de[2] is not read (the law gives the thickness strain increment in
// PointResult::dezz); the laws that run on shells are 1, 2, 27 and 36.
struct PointInput {
  double de[6] = {};  // strain increment of the step: xx yy zz xy yz zx
  // Total deformation gradient F[a][c] = dx_a / dX_c, for the total-strain laws (42, and 70's strain).
  double F[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  double rho_ratio = 1;  // rho / rho0 (solids: the pressure's mu = rho / rho0 - 1, law 70's tension)
  double rate = 0;       // the element's filtered strain rate
  double dt = 0;         // the step of the increments (law 27's rate term)
  bool plane_stress = false;
  // Shells: the transverse shear modulus (the property's shear factor times G), Iplas, the element size
  // factor of /FAIL/TAB.
  double transverse_shear = 0;
  int iplas = 0;
  double fail_scale = 1;
  double off = 1;  // the element's life factor at the start of the step
};

// The point's state, carried from step to step: the stress (xx yy zz xy yz zx; sig[2] stays 0 in plane
// stress), the plastic strain, the normalised damage of the failure model, and the law's own rows.
struct PointState {
  double sig[6] = {};
  double eps_p = 0;
  double dmg = 0;
  double brit[kBritVars] = {};  // law 27 (BritVar)
  double foam[kFoamVars] = {};  // law 70 (FoamVar)
};

// A point's state before its first step: zero stress and strains, the law's own initial rows.
PointState initial_point_state(const MaterialParams& p);

struct PointResult {
  bool supported = true;  // false: the law does not run in this state of stress (nothing was updated)
  double deps_p = 0;
  double dezz = 0;        // plane stress: the thickness strain increment
  double w_plastic = 0;   // plane stress: plastic work per unit volume of the step (6.5)
  double wave_speed = 0;  // the point's sound speed: the material's, or the current one of laws 42 and 70
  // The point's law or failure model starts the element's deletion: on shells law 27's EPS_f1 and the
  // plastic-strain limits of laws 2 and 36 (a shell's failed points delete it by their thickness fraction,
  // which is the section's: see PointState::dmg); on solids SolidFailMode::Delete, law 36's Eps_p_max and
  // law 42's tension cut-off.
  bool element_fails = false;
};

// Updates any law at one integration point through the functions the element kernels use (no formula of its
// own): shells through the shell point of their law (with the failure model when there is one), solids
// through solid_point_update, law 42 from F, law 70 from F's strain and the increment.
PointResult material_point_update(const MaterialParams& p, const PointInput& in, PointState& st);

}  // namespace radx::solver
