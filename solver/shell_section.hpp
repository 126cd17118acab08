// Shared by the shell kernels (shell_bt4.cpp, shell_c0_tri3.cpp): the through-thickness integration of one
// element's section, the element equivalent strain rate and the progressive failure factor. Internal to the
// solver; not a public API.
//
// Equations (shared/spec/elements.md):
//   1.4  point i of n at z_i = zeta_i t, zeta_i = -1/2 + (i-1)/(n-1) (n = 1: zeta = 0);
//        de(z_i) = de_m + z_i dkappa (membrane and bending parts), transverse shear constant;
//        FOR = sum w_i sigma_i (w = 1/(2(n-1)) at the surfaces, 1/(n-1) inside),
//        MOM = sum m_i sigma_i (m_i = zeta_i/(n-1) inside, +-(1/(n-1))(1/4 - 1/(6(n-1))) at the surfaces);
//        N = 0 (LAW1 only): resultant elasticity FOR += A de_m, MOM += (A t/12) dkappa.
//   1.3  element equivalent strain rate
//        rate = (1/dt1) sqrt(4/3 (dexx^2 + deyy^2 + dexx deyy + dgxy^2/4)
//                            + t^2/9 (dkxx^2 + dkyy^2 + dkxx dkyy + dkxy^2/4)), filtered (6.1)
//        rate <- alpha rate + (1 - alpha) rate_old, alpha = min(1, 2 pi Fcut dt1), Fcut = 0 -> alpha = 1.
//   1.8  thickness: t_cur += sum_i dezz_i w_i t OFF.
//   6.4  OFF: 1 -> 0.8 the cycle a point reaches EPS_p_max; then OFF <- 0.8 OFF each cycle; deleted (0) in
//        the cycle whose starting OFF is below 0.1.
//   6.5  plastic work: dW = 1/2 (svm_old + svm_new) deps_p w_i t A.
#pragma once

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <numbers>

#include "solver/element_groups.hpp"
#include "solver/material_point.hpp"

namespace radx::solver::shell_detail {

inline constexpr int kMaxPoints = 10;  // N > 10 is rejected by the starter (elements.md 1.1)

// Integration points and weights of one property (1.4). n = 0: resultant elasticity (no points).
struct ThicknessRule {
  int n = 0;
  double zeta[kMaxPoints] = {};  // z_i / t
  double w[kMaxPoints] = {};     // force weights (sum 1)
  double m[kMaxPoints] = {};     // moment weights: MOM = sum m_i sigma_i = M / t^2
};

inline ThicknessRule thickness_rule(int n) {
  assert(n >= 0 && n <= kMaxPoints);
  n = std::clamp(n, 0, kMaxPoints);  // the starter rejects N > 10; never write past the arrays below
  ThicknessRule r;
  r.n = n;
  if (n == 1) {
    r.w[0] = 1.0;  // zeta 0, m 0: no bending stiffness
  } else if (n >= 2) {
    const double h = 1.0 / (n - 1);
    for (int i = 0; i < n; ++i) {
      r.zeta[i] = -0.5 + i * h;
      r.w[i] = h;
      r.m[i] = r.zeta[i] * h;
    }
    r.w[0] = r.w[n - 1] = 0.5 * h;
    const double me = h * (0.25 - h / 6.0);
    r.m[0] = -me;
    r.m[n - 1] = me;
  }
  return r;
}

// Index of component c of point p of element i in ShellGroup::sig ([n_points][5][G]).
inline std::size_t sig_index(int p, int c, int i) {
  return (static_cast<std::size_t>(p) * 5 + static_cast<std::size_t>(c)) * kGroupSize +
         static_cast<std::size_t>(i);
}

// N = 0 stores the resultants in `sig` as [8][G]: FOR xx yy xy yz zx, then MOM xx yy xy. allocate() gives
// [5][G] for N = 0; grow the buffer once (outside the element loop).
inline void ensure_resultant_storage(ShellGroup& g) {
  const std::size_t need = 8 * static_cast<std::size_t>(kGroupSize);
  if (g.props.n_points <= 0 && g.sig.size() < need) g.sig.resize(need, 0.0);
}

// Equivalent strain rate of the element (1.3), before the filter. Zero when dt1 = 0 (cycle 0).
inline double equivalent_rate(const double dem[5], const double dk[3], double t, double dt1) {
  if (dt1 <= 0) return 0.0;
  const double m = dem[0] * dem[0] + dem[1] * dem[1] + dem[0] * dem[1] + 0.25 * dem[2] * dem[2];
  const double b = dk[0] * dk[0] + dk[1] * dk[1] + dk[0] * dk[1] + 0.25 * dk[2] * dk[2];
  return std::sqrt((4.0 / 3.0) * m + (t * t / 9.0) * b) / dt1;
}

// Filter factor of 6.1.
inline double rate_filter_alpha(const MaterialParams& mat, double dt1) {
  if (mat.f_cut <= 0) return 1.0;
  return std::min(1.0, 2.0 * std::numbers::pi * mat.f_cut * dt1);
}

// Result of one element's section update. FOR, MOM are the raw (not yet multiplied by OFF) averaged
// stress N/t and M/t^2 before and after the update, in the order xx yy xy yz zx / xx yy xy.
struct SectionUpdate {
  double for_old[5] = {}, for_new[5] = {};
  double mom_old[3] = {}, mom_new[3] = {};
  double dthick = 0;     // thickness increment before the OFF factor (1.8)
  double w_plastic = 0;  // plastic work increment (6.5)
  double eps_p_max = 0;  // largest plastic strain over the points after the update
};

inline double von_mises_plane(const double s[5]) {
  return std::sqrt(s[0] * s[0] + s[1] * s[1] - s[0] * s[1] + 3.0 * s[2] * s[2]);
}

// Through-thickness update of element i: dem = membrane + transverse shear increments (xx yy xy yz zx,
// engineering shears), dk = curvature increments (xx yy xy), t = mechanics thickness, area = current area,
// gs = transverse shear modulus, off = element factor at the start of the cycle.
inline void section_update(ShellGroup& g, int i, const MaterialParams& mat, const ThicknessRule& rule,
                           double gs, double t, double area, double rate, double off, const double dem[5],
                           const double dk[3], SectionUpdate& out) {
  if (rule.n == 0) {
    // Resultant elasticity (LAW1, N = 0).
    double* s = g.sig.data();
    const std::size_t G = kGroupSize;
    for (int c = 0; c < 5; ++c) out.for_old[c] = s[c * G + i];
    for (int c = 0; c < 3; ++c) out.mom_old[c] = s[(5 + c) * G + i];
    const double a11 = mat.a11, a12 = mat.a12, gm = mat.shear, t12 = t / 12.0;
    out.for_new[0] = out.for_old[0] + a11 * dem[0] + a12 * dem[1];
    out.for_new[1] = out.for_old[1] + a12 * dem[0] + a11 * dem[1];
    out.for_new[2] = out.for_old[2] + gm * dem[2];
    out.for_new[3] = out.for_old[3] + gs * dem[3];
    out.for_new[4] = out.for_old[4] + gs * dem[4];
    out.mom_new[0] = out.mom_old[0] + t12 * (a11 * dk[0] + a12 * dk[1]);
    out.mom_new[1] = out.mom_old[1] + t12 * (a12 * dk[0] + a11 * dk[1]);
    out.mom_new[2] = out.mom_old[2] + t12 * gm * dk[2];
    for (int c = 0; c < 5; ++c) s[c * G + i] = out.for_new[c];
    for (int c = 0; c < 3; ++c) s[(5 + c) * G + i] = out.mom_new[c];
    // Elastic plane stress: dezz = -nu/(1 - nu) (dexx + deyy) at mid-surface.
    out.dthick = -mat.nu / (1.0 - mat.nu) * (dem[0] + dem[1]) * t;
    return;
  }
  const int iplas = g.props.iplas;
  const bool elastic = mat.law == model::MaterialLaw::Elastic;
  double dthk = 0, wpl = 0, epmax = 0;
  for (int p = 0; p < rule.n; ++p) {
    double* sp = g.sig.data() + sig_index(p, 0, i);
    double& ep = g.eps_p[static_cast<std::size_t>(p) * kGroupSize + static_cast<std::size_t>(i)];
    const double z = rule.zeta[p] * t, w = rule.w[p], m = rule.m[p];
    const double de[5] = {dem[0] + z * dk[0], dem[1] + z * dk[1], dem[2] + z * dk[2], dem[3], dem[4]};
    double s[5];
    for (int c = 0; c < 5; ++c) s[c] = sp[c * kGroupSize];
    for (int c = 0; c < 5; ++c) out.for_old[c] += w * s[c];
    for (int c = 0; c < 3; ++c) out.mom_old[c] += m * s[c];
    const double svm_old = elastic ? 0.0 : von_mises_plane(s);
    const ShellPointResult r = shell_point_update(mat, iplas, rate, off, de, gs, s, ep);
    for (int c = 0; c < 5; ++c) sp[c * kGroupSize] = s[c];
    for (int c = 0; c < 5; ++c) out.for_new[c] += w * s[c];
    for (int c = 0; c < 3; ++c) out.mom_new[c] += m * s[c];
    if (r.deps_p > 0) wpl += 0.5 * (svm_old + von_mises_plane(s)) * r.deps_p * w * t * area;
    dthk += r.dezz * w;
    epmax = std::max(epmax, ep);
  }
  out.dthick = dthk * t;
  out.w_plastic = wpl;
  out.eps_p_max = epmax;
}

// Element factor after this cycle's material update (6.4). off_start = factor at the start of the cycle.
inline double next_off(const MaterialParams& mat, double off_start, double eps_p_max) {
  if (off_start < 1.0) return off_start < 0.1 ? 0.0 : 0.8 * off_start;
  if (mat.law == model::MaterialLaw::JohnsonCook && eps_p_max >= mat.eps_p_max) return 0.8;
  return off_start;
}

}  // namespace radx::solver::shell_detail
