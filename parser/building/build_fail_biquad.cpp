// /FAIL/BIQUAD/mat_ID: the biquadratic failure model attached to its material (law 2 or 36), read and
// resolved as OpenRadioss's starter does (hm_read_fail_biquad.F, biquad_coefficients.F):
//   C3 0 -> the M_Flag material's tension value: 1 mild steel 0.6, 2 HSS 0.5, 3 UHSS 0.12, 4 AA5182 0.3,
//      5 AA6082-T6 0.17, 6 PA6GF30 0.1, 7 PP T40 0.11, any other 0.6;
//   M_Flag != 0: C1, C2, C4, C5 = (r1, r2, r4, r5) C3 with the selector's ratios (99: the card's R1 R2 R4 R5;
//      an unknown selector: mild steel), whatever the card gives for them;
//   M_Flag 0 with C1 = C2 = C4 = C5 = 0: the mild-steel ratios (3.5, 1.6, 0.6, 1.5);
//   S_Flag 0 -> 2; S_Flag 3 with Inst_start <= 0 or >= C4 -> 2 (a warning);
//   P_thickfail clamped to [-1, 1], 0 -> 1e-6;
//   Ireg: 0 without fct_IDel, 0 -> 1 with it; EI_ref 0 -> 1;
//   DCRIT clamped to [0, 1]; DCRIT > 0 with ICOUP 0 -> ICOUP 1; ICOUP 2 without S_Flag 3 -> 0 (a warning).
// What radx does not run is refused by name (RX510): the stress softening (ICOUP > 0), Ireg 2 and 3 (the size
// factor by triaxiality), P_thickfail < 0 (a fraction of points). The size function on solids is refused in
// check_formulations.cpp.
#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "parser/building/model_builder.hpp"
#include "parser/reading/field_parse.hpp"

namespace radx::detail {

namespace {

// C1, C2, C4, C5 as multiples of C3 for each material selector (biquad_coefficients.F).
std::array<double, 4> selector_ratios(std::int64_t m_flag) {
  switch (m_flag) {
    case 2: return {4.3, 1.4, 0.6, 1.6};   // HSS, DP600
    case 3: return {5.2, 3.1, 0.8, 3.5};   // UHSS, boron steel
    case 4: return {5.0, 1.0, 0.4, 0.8};   // aluminium AA5182
    case 5: return {7.8, 3.5, 0.6, 2.8};   // aluminium AA6082-T6
    case 6: return {3.6, 0.6, 0.5, 0.6};   // PA6GF30
    case 7: return {10.0, 2.7, 0.6, 0.7};  // PP T40
    default: return {3.5, 1.6, 0.6, 1.5};  // 1 mild steel, and any other selector
  }
}

double selector_c3(std::int64_t m_flag) {
  switch (m_flag) {
    case 2: return 0.5;
    case 3: return 0.12;
    case 4: return 0.3;
    case 5: return 0.17;
    case 6: return 0.1;
    case 7: return 0.11;
    default: return 0.6;
  }
}

// The minimum of a + b x + c x^2 over all x when it opens upwards (the starter's warnings 3004, 3005).
bool parabola_dips_below_zero(double a, double b, double c) {
  if (c <= 0) return false;
  const double x = -b / (2.0 * c);
  return a + b * x + c * x * x < 0;
}

}  // namespace

// C1..C5 after the material selector, with a warning where the selector replaces values the card gives.
void ModelBuilder::resolve_biquad_strains(const KeywordRecord& r, model::FailBiquad& f) {
  f.c1 = r.get_real("C1");
  f.c2 = r.get_real("C2");
  f.c3 = r.get_real("C3");
  f.c4 = r.get_real("C4");
  f.c5 = r.get_real("C5");
  const std::int64_t m_flag = r.get_int("M_Flag");
  f.m_flag = static_cast<int>(m_flag);
  if (f.c3 == 0) f.c3 = selector_c3(m_flag);
  const bool all_blank = f.c1 == 0 && f.c2 == 0 && f.c4 == 0 && f.c5 == 0;
  if (m_flag == 0 && !all_blank) return;
  std::array<double, 4> k = selector_ratios(m_flag);
  if (m_flag == 99) k = {r.get_real("R1"), r.get_real("R2"), r.get_real("R4"), r.get_real("R5")};
  const bool known = (m_flag >= 0 && m_flag <= 7) || m_flag == 99;
  if (!known)
    warning_at(r, "M_Flag", Diag::DefaultApplied,
               "M_Flag = " + std::to_string(m_flag) +
                   " is no material selector (1 to 7, 99): the mild-steel ratios are used, as Radioss does");
  if (m_flag != 0 && !all_blank)
    warning_at(r, "M_Flag", Diag::DefaultApplied,
               "M_Flag = " + std::to_string(m_flag) +
                   " replaces the card's C1, C2, C4, C5 by its multiples of C3 = " + number_text(f.c3));
  f.c1 = k[0] * f.c3;
  f.c2 = k[1] * f.c3;
  f.c4 = k[2] * f.c3;
  f.c5 = k[3] * f.c3;
}

// S_Flag, Inst_start and the softening card: what runs, or the refusal of what does not.
void ModelBuilder::resolve_biquad_options(const KeywordRecord& r, model::FailBiquad& f) {
  f.s_flag = static_cast<int>(r.get_int("S_Flag"));
  if (f.s_flag == 0) f.s_flag = 2;
  const double inst = r.get_real("Inst_start");
  if (f.s_flag == 3 && (inst <= 0 || inst >= f.c4)) {
    warning_at(r, "Inst_start", Diag::DefaultApplied,
               "S_Flag = 3 with Inst_start = " + number_text(inst) +
                   (inst <= 0 ? std::string(" <= 0") : " >= C4 = " + number_text(f.c4)) +
                   ": no instability, S_Flag 2 is used (as Radioss does)");
    f.s_flag = 2;
  }
  if (f.s_flag == 3) f.inst_start = inst;
  const double dcrit = std::clamp(r.get_real("DCRIT"), 0.0, 1.0);
  std::int64_t icoup = r.get_int("ICOUP");
  if (dcrit != 0 && icoup == 0) icoup = 1;
  if (icoup == 2 && f.s_flag != 3) {
    warning_at(r, "ICOUP", Diag::DefaultApplied,
               "ICOUP = 2 couples the softening to the necking instability of S_Flag 3: no softening (as "
               "Radioss does)");
    icoup = 0;
  }
  if (icoup != 0) {
    const bool from_dcrit = r.get_int("ICOUP") == 0;
    error_at(r, from_dcrit ? "DCRIT" : "ICOUP", Diag::PhysicsNotImplemented,
             (from_dcrit ? "DCRIT = " + number_text(dcrit) + " > 0 asks for the stress softening (ICOUP 1)"
                         : "ICOUP = " + std::to_string(icoup) + " (stress softening)") +
                 ", which radx does not implement; accepted: ICOUP 0 and DCRIT 0 (no softening before the "
                 "point fails)");
  }
}

void ModelBuilder::build_fail_biquad() {
  for (const auto* rp : deck_.of("/FAIL/BIQUAD")) {
    const auto& r = *rp;
    model::Material* target = failure_material(r, "/FAIL/BIQUAD");
    if (!target) continue;
    auto& f = target->fail_bq;
    f.on = true;
    f.fail_id = r.get_int("fail_ID");
    resolve_biquad_strains(r, f);
    resolve_biquad_options(r, f);
    double pthk = std::clamp(r.get_real("P_thickfail"), -1.0, 1.0);
    if (pthk == 0) pthk = 1e-6;
    if (pthk < 0)
      error_at(
          r, "P_thickfail", Diag::PhysicsNotImplemented,
          "P_thickfail = " + number_text(pthk) +
              " < 0 (a fraction of failed points) is not implemented by radx: give the failed fraction of "
              "the thickness, 0 to 1");
    f.p_thickfail = pthk;
    f.size_function_id = r.get_int("fct_IDel");
    f.el_ref = r.get_real("EI_ref");
    const std::int64_t ireg = f.size_function_id == 0 ? 0 : std::max<std::int64_t>(r.get_int("Ireg"), 1);
    if (ireg > 1)
      error_at(r, "Ireg", Diag::PhysicsNotImplemented,
               "Ireg = " + std::to_string(ireg) +
                   " (the element size factor weighted by the triaxiality) is not implemented by radx; "
                   "accepted: Ireg 0 or 1 (eps_f times fct_IDel(size / EI_ref))");
    // The starter's warnings on curves that dip below zero (there a point fails at once: eps_f floored at
    // 1e-6). First parabola c2 + b x + a x^2 through C1 at -1/3 and C3 at 1/3.
    const double b1 = 1.5 * (f.c3 - f.c1), a1 = 4.5 * (f.c1 + f.c3) - 9.0 * f.c2;
    if (parabola_dips_below_zero(f.c2, b1, a1))
      warning_at(r, "C2", Diag::ImplausibleMaterial,
                 "the failure strain's parabola through C1, C2, C3 falls below zero between its points: "
                 "points at those triaxialities fail at once");
  }
}

// /FAIL/BIQUAD's element size function, once the functions exist.
void ModelBuilder::resolve_fail_biquad_functions() {
  for (const auto* rp : deck_.of("/FAIL/BIQUAD")) {
    const auto& r = *rp;
    const auto it = mat_ids_.find(r.id);
    if (it == mat_ids_.end()) continue;
    auto& f = m_.materials[static_cast<std::size_t>(it->second)].fail_bq;
    if (!f.on) continue;
    f.size_function = ref(funct_ids_, r, "fct_IDel", "element size factor function", "/FUNCT", true);
  }
}

}  // namespace radx::detail
