// Material laws at one integration point, written once and used by shells (plane stress) and solids.
// Formulas: docs/theory/elements.md sections 1.4 (shell elasticity), 3.3 (solid pressure), 6 (LAW2
// Johnson-Cook). LAW1 is the elastic limit of the same updates (no yield).
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <memory>
#include <numbers>
#include <vector>

#include "solver/model/foam_table.hpp"
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

// Square roots of v[0 .. n), in a loop of their own: the kernels put the arguments in an array and take the
// roots here. The solver is compiled with -fno-math-errno (solver/CMakeLists.txt), so GCC vectorises this
// loop at the width of the copy it is inlined into (sqrtpd rounds exactly as sqrtsd and the library).
inline void sqrt_in_place(double* v, int n) {
  for (int i = 0; i < n; ++i) v[i] = std::sqrt(v[i]);
}

// One yield curve of law 36: a non-owning view of a /FUNCT's points (the engine's model owns them), its
// ordinate scale and its strain rate. sigma_y(eps_p) = scale f(eps_p), f linear between the points and
// extrapolated with the end segments (as every /FUNCT, functions.hpp).
struct TabCurve {
  const double* x = nullptr;
  const double* y = nullptr;
  int n = 0;
  double scale = 1;
  double rate = 0;
};

// Value and slope of a TabCurve's function (not scaled) at x: linear between the points, extrapolated with
// the end segments (as every /FUNCT, functions.hpp); a one-point function is constant.
inline void curve_at(const TabCurve& c, double x, double& y, double& dy) {
  if (c.n <= 1) {
    y = c.n == 1 ? c.y[0] : 0.0;
    dy = 0.0;
    return;
  }
  // Segment i: the number of interior abscissas x_1 .. x_{n-2} at or below x (0 before x_1, n-2 after).
  const auto i = static_cast<int>(std::upper_bound(c.x + 1, c.x + c.n - 1, x) - (c.x + 1));
  dy = (c.y[i + 1] - c.y[i]) / (c.x[i + 1] - c.x[i]);
  y = c.y[i] + dy * (x - c.x[i]);
}

// What a solid point does once its damage reaches 1 (failure_damage.cpp).
enum class SolidFailMode : std::uint8_t {
  Delete,           // the brick starts its deletion (OFF 0.8, then the decay)
  DeviatorZero,     // sigma = sigma_m I for ever, the brick stays
  DeviatorTension,  // sigma = min(sigma_m, 0) I
  StressZero,       // sigma = 0
  NormalToMean,     // the normal stresses take sigma_m, the shears are kept (/FAIL/TAB Ifail_so 2)
  Keep,             // the stress is kept (/FAIL/TAB Ifail_so 3: the damage is only an output)
};

// The failure model of a material as the points use it: /FAIL/JOHNSON (fail_johnson.cpp) or /FAIL/TAB
// (fail_tab.cpp) give the failure strain; the damage stage (failure_damage.cpp) is shared. The point's damage
// is kept normalised, d = D / Dcrit (Dcrit = 1 for Johnson-Cook): d reaches 1 when the point fails.
enum class FailKind : std::uint8_t { None, Johnson, Tab };
struct FailParams {
  bool on = false;
  FailKind kind = FailKind::None;
  // Johnson-Cook.
  double d1 = 0, d2 = 0, d3 = 0, d4 = 0, d5 = 0, eps_dot0 = 1e-20, eps_f_min = 0;
  // Tabulated: eps_f(triaxiality) rows by increasing strain rate (non-owning, see make_material_params), the
  // constant temperature factor, the size function (scale = Fscale_el) and its reference length.
  const TabCurve* rows = nullptr;
  int n_rows = 0;
  double temp_factor = 1;
  TabCurve size;
  bool has_size = false;
  double el_ref = 1;
  // Damage: dD = n D^(1 - 1/n) d_eps_p / eps_f (the factor is 1 at D = 0), the point fails at D = Dcrit.
  double dcrit = 1, n_exp = 1;
  // Shells: Ifail_sh, whether a failed point keeps its stress (/FAIL/TAB Ifail_sh 3) and the failed thickness
  // fraction that deletes the element (before the property's bound).
  int ifail_sh = 1;
  bool keep_failed_stress = false;
  double p_thick = 1.0 - 1e-6;
  SolidFailMode solid = SolidFailMode::Delete;
};

// /MAT/PLAS_BRIT's crack (law27_plas_brit.cpp): direction 1 only (OpenRadioss m27crak.F opens no other).
struct BritParams {
  double eps_t = 1e20, eps_m = 1.1e20, d_max = 0.999, eps_f = 1.2e22;
  bool point_rate = true;  // Fsmooth 0: the rate term takes the point's largest strain increment, else the
                           // element's filtered rate
};

// Law 27's state at one shell point, kBritVars rows of the group's `brit` buffer: the total in-plane strain
// exx eyy gxy (element frame, engineering shear), the crack frame's direction 1 (cos, sin in the element
// frame; (1, 0) until the crack opens), the damage of direction 1 and its crack strain.
inline constexpr int kBritVars = 7;
enum BritVar : int { kBritExx = 0, kBritEyy, kBritGxy, kBritCos, kBritSin, kBritDamage, kBritCrack };

// /MAT/OGDEN (law42_ogden.cpp): the terms with mu_p != 0, G = sum mu_p alpha_p, the tension cut-off on the
// principal Biot stress, the volumetric form (1: U = K/2 (J-1)^2, 2: U = K (J - 1 - ln J)) and the bulk
// stiffening of OpenRadioss's sigeps42.F for K > 24 G (below a stretch of 0.2 the bulk modulus is multiplied
// by max(1, nu1 / lambda_min), nu1 = 40 (1/2 - nu_G), nu_G = (3K - G) / (6K + G)).
struct OgdenParams {
  static constexpr int kMaxTerms = 10;
  int n = 0;
  double mu[kMaxTerms] = {}, alpha[kMaxTerms] = {};
  double g = 0;  // sum mu_p alpha_p = 2 mu0
  double sig_cut = 1e20;
  int iform = 1;
  bool stiffen = false;  // K > 24 G
  double nu1 = 0;
};

// /MAT/FOAM_TAB (law70_foam_tab.cpp): the loading and unloading tables (model/foam_table.hpp; shared, built
// once per material), the moduli the law runs with and its flags. `unload` is null when the unloading
// formulation needs no curve (Iflag 3, 4 without unloading curves).
struct FoamParams {
  std::shared_ptr<const model::FoamTable> load, unload;
  std::shared_ptr<const model::FoamTable> tension;  // Itens 1: the factor against 1 - rho / rho0 (one curve)
  double e0 = 0, e_max = 0, aa = 0, eps_max = 1, yld_emax = 0;
  double static_rate = 0;  // rate of the first loading curve (0)
  int iflag = 0;
  double shape = 1, hys = 1;
};

// Law 70's state at one point, kFoamVars rows of the brick group's `foam` buffer (the names of sigeps70.F's
// user variables in brackets): the strain past the curve (eps_s), the largest dissipation measure reached,
// the current modulus E, the strain norm of the last cycle, its loading direction (+1, -1), the stress norm
// of the last cycle, the dissipation measure W, the static curve's value of the last cycle and the tension
// factor of the last cycle.
inline constexpr int kFoamVars = 9;
enum FoamVar : int {
  kFoamEpsS = 0,
  kFoamWMax,
  kFoamE,
  kFoamEpstOld,
  kFoamLoad,
  kFoamYldOld,
  kFoamW,
  kFoamYldElasOld,
  kFoamTensOld
};

// Parameters as the kernels use them (work units), derived once per material.
struct MaterialParams {
  model::MaterialLaw law = model::MaterialLaw::Elastic;
  double rho0 = 0;  // initial density rho_I
  double young = 0, nu = 0;
  double shear = 0, bulk = 0;  // G = E / 2(1 + nu), K = E / 3(1 - 2 nu)
  double a11 = 0, a12 = 0;     // plane stress: A11 = E / (1 - nu^2), A12 = nu A11
  double c_shell = 0;          // sqrt(E / rho0): shell sound speed (docs/theory/elements.md 4.1)
  double c_solid = 0;          // sqrt((K + 4G/3) / rho0): solid sound speed (3.3)
  // Johnson-Cook (law 2); unused for law 1.
  double a = 0, b = 0, n = 1, c = 0, eps_dot0 = 1, sig_max0 = 1e20, eps_p_max = 1e20;
  int icc = 1, flag_vp = 2;
  double f_cut = 0;  // strain-rate filter (laws 2 and 36)
  // Tabulated plasticity (law 36, law36_plas_tab.cpp): curves[0 .. n_curves) by increasing rate, the rate-0
  // curve first when there are several (non-owning: see make_material_params). eps_p_max above is its
  // Eps_p_max.
  const TabCurve* curves = nullptr;
  int n_curves = 0;
  bool tab_log = false;  // Fsmooth 2: interpolation in ln(rate) between two curves, else linear in rate
  double tab_lower = 0;  // lower bound of sigma_y over eps_p >= 0 and rates <= tab_rate_max (fast path)
  double tab_rate_max = 0;
  bool tab_bound = false;  // tab_lower is a valid bound (every curve's last segment rises or is flat)
  FailParams fail;
  BritParams brit;    // law 27; its flow stress is law 2's (a, b, n, c, eps_dot0, sig_max0, icc above)
  OgdenParams ogden;  // law 42
  FoamParams foam;    // law 70
};

// Law 42 (law42_ogden.cpp) at one point: the Cauchy stress sig (xx yy zz xy yz zx, in the axes F maps into)
// from the total deformation gradient F[a][c] = dx_a / dX_c. Returns the modulus M = K' + 4/3 G_t of the
// point's wave speed c = sqrt(M / rho) (K' the bulk modulus with its stiffening, G_t the tangent shear
// estimate), J = det F, and `cut` when a principal Biot stress passed sigma_cut (sig is then 0).
struct OgdenPointResult {
  double modulus = 0;
  double j = 1;
  bool cut = false;
};
OgdenPointResult ogden_point(const MaterialParams& p, const double F[3][3], double sig[6]);

// Strain energy per unit reference volume W(F) of law 42 (without the bulk stiffening), for tests and
// checks: W = sum_p mu_p / alpha_p (lb1^alpha_p + lb2^alpha_p + lb3^alpha_p - 3) + U(J).
double ogden_energy_density(const MaterialParams& p, const double F[3][3]);

// Law 70 (law70_foam_tab.cpp) at one point. In: eps, the total strain of the point (xx yy zz, then the
// engineering shears, in the axes of the stress), de the strain increment of the step (same layout), rate
// the filtered strain rate, rho_ratio = rho / rho0, sig the stress of the last cycle (in the same axes; the
// law divides out the last tension factor itself). Out: sig the new stress, st[kFoamVars] updated. Returns
// the wave speed c = sqrt(A11 / rho0), A11 = E (1 - nu) / ((1 + nu)(1 - 2 nu)) with the current modulus E.
double foam_point(const MaterialParams& p, const double eps[6], const double de[6], double rate,
                  double rho_ratio, double sig[6], double st[kFoamVars]);

// A law-70 point's state before its first cycle (OpenRadioss m70init.F): modulus E0, tension factor 1.
void foam_initial_state(const MaterialParams& p, double st[kFoamVars]);

// Principal stretches lambda_i and directions n_i (column i of n) of a deformation gradient F: the
// eigen-decomposition of B = F F^T (law42_ogden.cpp; shared by laws 42 and 70).
void principal_stretches(const double F[3][3], double lam[3], double n[3][3]);

// Factor of the strain-rate filter (docs/theory/elements.md 6.1 shells, 6.2 solids): rate <- alpha
// e + (1 - alpha) rate, alpha = min(1, 2 pi Fcut dt1), 1 when Fcut = 0 (no
// filter). Shared by the shell and solid kernels.
inline double rate_filter_alpha(const MaterialParams& mat, double dt1) {
  if (mat.f_cut <= 0) return 1.0;
  return std::min(1.0, 2.0 * std::numbers::pi * mat.f_cut * dt1);
}

// Parameters of laws 1 and 2 (and of a /FAIL/JOHNSON on them). A law-36 material needs the overload below.
MaterialParams make_material_params(const model::Material& m);

// Any law: law 36 gets its curves from `functions` (the model's) through `curves`, which receives them and
// must outlive the parameters and not be resized afterwards (the parameters point into it). The curves'
// points stay in `functions`, which must outlive them too.
MaterialParams make_material_params(const model::Material& m, const std::vector<model::Function>& functions,
                                    std::vector<TabCurve>& curves);

// Law 36 flow stress (law36_plas_tab.cpp) at plastic strain eps_p and strain rate `rate`:
// sigma_y = max(Y1 + f (Y2 - Y1), 1e-20), Y_k = scale_k f_k(eps_p) of the two curves around the rate,
// f = (rate - r1)/(r2 - r1) (or the same in ln(rate)). `slope` receives H = d sigma_y / d eps_p.
double tab_flow_stress(const MaterialParams& p, double eps_p, double rate, double* slope = nullptr);

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

// A lower bound of law 2's jc_rate_factor, R_lo <= R = 1 + c ln(max(rate, rate0)/rate0), without a
// logarithm and without a branch (the kernels' vectorised loops take it for every element and the logarithm
// only for the elements with a point that may yield): for x = rate/rate0 = 2^e m, m in [1, 2),
// ln x = e ln 2 + ln m >= ln 2 (e + m - 1), the chord of the concave ln over [1, 2] (at most 0.061 below it),
// less 1e-9 for the rounding of these few operations; max(., 0) keeps R_lo = 1 at or below rate0 (and for
// rate 0 or subnormal). c >= 0 and inv_rate0 = 1/rate0 > 0.
inline double jc_rate_factor_lower(double c, double inv_rate0, double rate) {
  const double x = rate * inv_rate0;
  const auto bits = std::bit_cast<std::uint64_t>(x);
  // The biased exponent as a double, exactly: 2^52 + k has k in its low mantissa bits.
  constexpr std::uint64_t kTwo52 = 0x4330000000000000ULL;
  const double e = std::bit_cast<double>(((bits >> 52) & 0x7FFULL) | kTwo52) - 4503599627370496.0 - 1023.0;
  const double m = std::bit_cast<double>((bits & 0x000FFFFFFFFFFFFFULL) | 0x3FF0000000000000ULL);
  const double ln_lo = std::numbers::ln2 * (e + (m - 1.0)) - 1e-9;
  return 1.0 + c * std::max(ln_lo, 0.0);
}

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
// Law 36: sigma_y >= tab_lower, the smallest scaled ordinate of the curves over eps_p >= 0, while the rate is
// at most the highest curve rate (then the rate weight is in [0, 1], so sigma_y lies between two curves'
// values); the rate term rfac is the rate, hence a = tab_lower, r_scale = 0 and r_max = tab_rate_max. With a
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
    b.usable = p.tab_bound && !p.fail.on;
    b.a = p.tab_lower;
    b.sig_max0 = 1e300;
    b.r_scale = 0;
    b.r_max = p.tab_rate_max;
    return b;
  }
  b.jc = p.law == model::MaterialLaw::JohnsonCook;
  b.usable = b.jc && p.b >= 0 && p.c >= 0 && p.sig_max0 >= 0 && !p.fail.on;
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

// /FAIL/JOHNSON's failure strain (fail_johnson.cpp):
// eps_f = max(EPSF_MIN, (D1 + D2 exp(D3 sigma_m / svm)) (1 + D4 ln(max(1, rate / rate0))) (1 + D5 T*)), T* =
// 0.
double fail_jc_strain(const FailParams& f, double sigma_m, double svm, double rate);
// /FAIL/TAB's failure strain before the element-size factor (fail_tab.cpp): the rows at the triaxiality
// sigma_m / max(svm, 1e-20), linear in the rate between the rows around it (extrapolated beyond), times the
// temperature factor.
double fail_tab_strain(const FailParams& f, double sigma_m, double svm, double rate);
// /FAIL/TAB's element-size factor Fscale_el f_el(len / EI_ref) of an element of characteristic length len
// (1 without a size function): computed once per element from its initial length (fail_tab.cpp).
double fail_size_factor(const FailParams& f, double len);
// The failure strain of either model, times the element's size factor `escale`.
double fail_strain(const FailParams& f, double sigma_m, double svm, double rate, double escale);

// The damage stage (failure_damage.cpp), shared by every failure model: with d = D / Dcrit,
// D += n D^(1 - 1/n) d_eps_p / eps_f when eps_f > 0 (the factor is 1 at D = 0 and for n = 1), d capped at 1.
// Returns true when d reaches 1 in this call.
bool fail_accumulate(const FailParams& f, double sigma_m, double svm, double rate, double escale,
                     double deps_p, double& dmg);

// The shell point with its failure model: shell_point_update_r, then, while the element is intact (off = 1)
// and the point alive (dmg < 1), the damage stage with the plane-stress sigma_m = (sxx + syy)/3 and svm of
// the updated stress; a failed point (dmg >= 1) carries no stress any more (all five components zero) unless
// the model keeps it (/FAIL/TAB Ifail_sh 3). rate: the element's strain rate; escale: its size factor.
ShellPointResult shell_point_update_fail(const MaterialParams& p, int iplas, double rfac, double rate,
                                         double escale, double off, const double de[5], double gs,
                                         double sig[5], double& eps_p, double& dmg);

// Internal pieces of the law files, for law_point_updates.cpp's dispatch (not for the kernels).
namespace detail {
// LAW2's plastic correction of a plane-stress trial (sxx, syy, sxy) in place, for the rate factor rfac
// (law_point_updates.cpp): radial return (Iplas 0) or the Newton projection (Iplas 1, off = 1 only).
// eps_p is updated; returns d_eps_p, and dezz_p receives the plastic trace term of 1.8.
double jc_shell_return(const MaterialParams& p, int iplas, double rfac, double off, double& sxx, double& syy,
                       double& sxy, double& eps_p, double& dezz_p);
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

// Fills p's law-36 curves from the material (law36_plas_tab.cpp); see make_material_params.
void tab_curves_params(const model::Material& m, const std::vector<model::Function>& functions,
                       std::vector<TabCurve>& curves, MaterialParams& p);

}  // namespace radx::solver
