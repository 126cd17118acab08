// The failure models of a material, /FAIL/JOHNSON (fail_johnson.cpp), /FAIL/TAB (fail_tab.cpp) and
// /FAIL/BIQUAD (fail_biquad.cpp): their parameters, their failure strains and the damage stage they share
// (failure_damage.cpp).
#pragma once

#include <cstdint>

#include "solver/materials/law36_plas_tab.hpp"

namespace radx::solver {

// What a solid point does once its damage reaches 1 (failure_damage.cpp).
enum class SolidFailMode : std::uint8_t {
  Delete,           // the brick starts its deletion (OFF 0.8, then the decay)
  DeviatorZero,     // sigma = sigma_m I for ever, the brick stays
  DeviatorTension,  // sigma = min(sigma_m, 0) I
  StressZero,       // sigma = 0
  NormalToMean,     // the normal stresses take sigma_m, the shears are kept (/FAIL/TAB Ifail_so 2)
  Keep,             // the stress is kept (/FAIL/TAB Ifail_so 3: the damage is only an output)
};

// The failure model of a material as the points use it: /FAIL/JOHNSON, /FAIL/TAB or /FAIL/BIQUAD give the
// failure strain;
// the damage stage is shared. The point's damage is kept normalised, d = D / Dcrit (Dcrit = 1 for
// Johnson-Cook): d reaches 1 when the point fails.
enum class FailKind : std::uint8_t { None, Johnson, Tab, Biquad };
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
  // Biquadratic: eps_f = p1(eta) up to eta = 1/3, p2 or the plane-strain vertex form above (fail_biquad.cpp);
  // p(eta) = c[0] + c[1] eta + c[2] eta^2. The size function and its reference length are `size`, `el_ref`.
  double bq_low[3] = {0, 0, 0};
  double bq_high[3] = {0, 0, 0};
  int bq_s_flag = 2;   // 1, 2, or 3: 2 with the shells' necking instability
  double bq_inst = 0;  // S_Flag 3: Inst_start, the instability strain at plane strain
  // Damage: dD = n D^(1 - 1/n) d_eps_p / eps_f (the factor is 1 at D = 0), the point fails at D = Dcrit.
  double dcrit = 1, n_exp = 1;
  // Shells: Ifail_sh, whether a failed point keeps its stress (/FAIL/TAB Ifail_sh 3) and the failed thickness
  // fraction that deletes the element (before the property's bound).
  int ifail_sh = 1;
  bool keep_failed_stress = false;
  double p_thick = 1.0 - 1e-6;
  SolidFailMode solid = SolidFailMode::Delete;
};

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
// /FAIL/BIQUAD (fail_biquad.cpp): the two parabolas through the plastic strains at failure C1..C5 (at the
// triaxialities -1/3, 0, 1/3, 1/sqrt(3), 2/3) into f.bq_low and f.bq_high.
void fail_biquad_fit(double c1, double c2, double c3, double c4, double c5, FailParams& f);
// /FAIL/BIQUAD's failure strain at the triaxiality eta, before the size factor and the floor.
double fail_biquad_curve(const FailParams& f, double eta);
// The same at the stress state: eta = sigma_m / max(svm, 1e-20) kept in [-2/3, 2/3].
double fail_biquad_strain(const FailParams& f, double sigma_m, double svm);
// /FAIL/BIQUAD S_Flag 3 (fail_biquad.cpp): the instability strain at eta, 0 (no instability) up to 1/3.
double fail_biquad_instability_curve(const FailParams& f, double eta);
// The instability damage of a shell point: D_i += d_eps_p / (escale eps_i(eta)) while eps_i > 0, capped at 1.
void fail_biquad_instability(const FailParams& f, double sigma_m, double svm, double escale, double deps_p,
                             double& dmg_inst);
// The failure strain of any model, times the element's size factor `escale`.
double fail_strain(const FailParams& f, double sigma_m, double svm, double rate, double escale);

// The damage stage (failure_damage.cpp), shared by every failure model: with d = D / Dcrit,
// D += n D^(1 - 1/n) d_eps_p / eps_f when eps_f > 0 (the factor is 1 at D = 0 and for n = 1), d capped at 1.
// Returns true when d reaches 1 in this call.
bool fail_accumulate(const FailParams& f, double sigma_m, double svm, double rate, double escale,
                     double deps_p, double& dmg);

}  // namespace radx::solver
