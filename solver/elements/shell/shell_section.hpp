// Shared by the shell kernels (shell_bt4.cpp, shell_c0_tri3.cpp, shell_qeph.cpp, shell_qbat.cpp): the
// through-thickness integration of a block of elements' sections, the element equivalent strain rate and the
// progressive failure factor. Internal to the solver; not a public API.
//
// The section runs point by point (up to kPassPoints points per pass) over the block's elements, vectorised:
// every point gets its elastic trial and the sums, and the points that may yield (shell_stays_elastic false,
// see material_point.hpp) get the exact update shell_point_update_r afterwards, with their element's sums
// redone in the order of the points. Either way each point's result and each sum are those of the
// element-by-element update, operation for operation.
//
// Equations (docs/theory/elements.md):
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
//        the cycle whose starting OFF is below 0.1. Law 36: a point above Eps_p_max deletes the element at
//        once (OFF 0 in that cycle: sigeps36c.F sets 0.8 without the progressive flag LAW2 sets, and
//        mulawc.F90 turns such a 0.8 into 0).
//   /FAIL/JOHNSON, /FAIL/TAB (failure_damage.cpp): every point of such a material takes the exact update with
//        its damage; a failed point carries no stress (unless /FAIL/TAB Ifail_sh 3 keeps it); the element is
//        deleted at once (OFF 0) when the weight sum of its failed points reaches 1e-6 (Ifail_sh 1) or
//        min(the model's fraction, P_thickfail of the property) within [1e-6, 1 - 1e-6] (Ifail_sh 2, 3).
//   6.5  plastic work: dW = 1/2 (svm_old + svm_new) deps_p w_i t A.
//   Law 27 (law27_plas_brit.cpp): every point takes the exact update with its crack state; the element is
//        deleted at once (OFF 0) when one of its points' largest principal strain passes EPS_f1.
#pragma once

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numbers>
#include <type_traits>
#include <utility>

#include "solver/elements/element_groups.hpp"
#include "solver/materials/material_point.hpp"

namespace radx::solver::shell_detail {

inline constexpr int kMaxPoints = 10;  // N > 10 is rejected by the starter (docs/theory/elements.md 1.1)
// Points per pass of section_point_pass. The usual 3 and 5 points take one pass: the sums stay in registers
// (or the core's spill slots) instead of going through SectionBlock between passes.
inline constexpr int kPassPoints = 5;

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
// [8][G] for N = 0; a group whose N was set to 0 after it is grown here, once (outside the element loop).
inline void ensure_resultant_storage(ShellGroup& g) {
  const std::size_t need = 8 * static_cast<std::size_t>(kGroupSize);
  if (g.props.n_points <= 0 && g.sig.size() < need) g.sig.resize(need, 0.0);
}

// Argument of the square root of the element equivalent strain rate (1.3): rate = sqrt(arg) / dt1.
inline double equivalent_rate_arg(double dexx, double deyy, double dgxy, double dkxx, double dkyy,
                                  double dkxy, double t) {
  const double m = dexx * dexx + deyy * deyy + dexx * deyy + 0.25 * dgxy * dgxy;
  const double b = dkxx * dkxx + dkyy * dkyy + dkxx * dkyy + 0.25 * dkxy * dkxy;
  return (4.0 / 3.0) * m + (t * t / 9.0) * b;
}

// Section update of a block of B elements (slots j = 0 .. len of the group's elements i0 + j), structure of
// arrays. The kernel fills the inputs; FOR, MOM are the raw (not yet multiplied by OFF) averaged stress N/t
// and M/t^2 before and after the update, in the order xx yy xy yz zx / xx yy xy.
template <int B>
struct SectionBlock {
  // Inputs.
  double dem[5][B];  // membrane and transverse shear increments xx yy xy yz zx (engineering shears)
  double dk[3][B];   // curvature increments xx yy xy
  double t[B];       // mechanics thickness
  double area[B];    // current area
  double rfac[B];    // strain-rate term of the element rate (jc_rate_factor: R for law 2, the rate for 36)
  double rate[B];    // the element's filtered strain rate (the /FAIL/JOHNSON D4 term, law 27's rate term)
  double dt1 = 0;    // the step of the increments (law 27's rate term)
  // rfac_lower: rfac holds law 2's jc_rate_factor_lower, a lower bound (enough for shell_stays_elastic), and
  // is made exact (jc_rate_factor of rate) for an element when one of its points takes the exact update;
  // rfac_exact[j] = 1 once it is. False: rfac is exact from the start.
  bool rfac_lower = false;
  unsigned char rfac_exact[B] = {};
  double off[B];  // element factor at the start of the cycle; <= 0: deleted, its state is left alone
  // Results.
  double for_old[5][B], for_new[5][B];
  double mom_old[3][B], mom_new[3][B];
  double dthick[B];      // thickness increment before the OFF factor (1.8)
  double w_plastic[B];   // plastic work increment (6.5)
  double eps_p_max[B];   // largest plastic strain over the points after the update
  double fail_now[B];    // 1: /FAIL/JOHNSON deletes the element in this cycle (next_off)
  double unstable[B];    // 1: every point of the section reached /FAIL/BIQUAD's instability (S_Flag 3)
  double crack_fail[B];  // 1: a law-27 point passed EPS_f1 in this cycle
  // Scratch of the points that take the exact update (shell_point_update_r).
  double old[kPassPoints][5][B];                      // their stress before the update (points of the pass)
  std::int64_t exact[kPassPoints][B];                 // 1: that point of element j takes it
  std::int64_t redo[B] = {};                          // 1: element j has such a point, its sums are redone
  unsigned char point_exact[kMaxPoints][B] = {};      // which points of element j took it
  double dezz_x[kMaxPoints][B], wp_x[kMaxPoints][B];  // their dezz and plastic work per volume
};

// Through-thickness points p0 .. p0 + kPts - 1 (kPts <= kPassPoints) of the block, vectorised. For each
// point: strain increment de(z) = de_m + z dkappa, the sums of FOR/MOM before the update, the elastic trial
// (stored), the sums after it, the thickness strain and the largest eps_p, all as if the point stayed
// elastic; the sums are taken point after point, as one point at a time would. exact[q][j] = 1 marks the
// points the caller must finish: those that may yield (shell_stays_elastic false), updated exactly, with
// their element's sums redone, and those of deleted elements (off <= 0), whose stress is put back.
template <bool kFirst, bool kNewton, int kPts, int B>
std::int64_t section_point_pass(SectionBlock<B>& s, int len, const MaterialParams& mat,
                                const ShellYieldBound& yb, double gs, const ThicknessRule& rule, int p0,
                                double* sig, double* eps_p) {
  // Local copies: the stores of the loop could alias the caller's objects, which would keep the compiler
  // from holding their fields in registers. Only the four constants the loop reads: a copy of the whole
  // MaterialParams (736 bytes) per pass cost more than the loop's loads it saved.
  const struct { double a11, a12, shear, nu; } mp{mat.a11, mat.a12, mat.shear, mat.nu};
  const ShellYieldBound bound = yb;
  double zeta[kPts], w[kPts], m[kPts];
  double* sp[kPts][5];
  const double* ep[kPts];
  for (int q = 0; q < kPts; ++q) {
    zeta[q] = rule.zeta[p0 + q], w[q] = rule.w[p0 + q], m[q] = rule.m[p0 + q];
    for (int c = 0; c < 5; ++c) sp[q][c] = sig + (static_cast<std::size_t>(p0 + q) * 5 + c) * kGroupSize;
    ep[q] = eps_p + static_cast<std::size_t>(p0 + q) * kGroupSize;
  }
  std::int64_t any = 0;
  RADX_IVDEP
  for (int j = 0; j < len; ++j) {
    const double off = s.off[j], t = s.t[j], rfac = s.rfac[j];
    const double dm[5] = {s.dem[0][j], s.dem[1][j], s.dem[2][j], s.dem[3][j], s.dem[4][j]};
    const double dk[3] = {s.dk[0][j], s.dk[1][j], s.dk[2][j]};
    double fn[5], mn[3], dth = 0, epm = 0;
    if constexpr (!kFirst) {
      for (int c = 0; c < 5; ++c) fn[c] = s.for_new[c][j];
      for (int c = 0; c < 3; ++c) mn[c] = s.mom_new[c][j];
      dth = s.dthick[j];
      epm = s.eps_p_max[j];
    }
    // One point, q a compile-time constant (so that the first point's sums start without a branch).
    const auto point = [&](auto q_constant) {
      constexpr int q = decltype(q_constant)::value;
      const double z = zeta[q] * t;
      const double d0 = dm[0] + z * dk[0], d1 = dm[1] + z * dk[1], d2 = dm[2] + z * dk[2];
      const double o[5] = {sp[q][0][j], sp[q][1][j], sp[q][2][j], sp[q][3][j], sp[q][4][j]};
      double n[5] = {o[0], o[1], o[2], o[3], o[4]};
      shell_trial(mp, gs, d0, d1, d2, dm[3], dm[4], n[0], n[1], n[2], n[3], n[4]);
      const double eps = ep[q][j];
      const bool elastic = shell_stays_elastic<kNewton>(bound, rfac, off, eps, n[0], n[1], n[2]);
      const std::int64_t e = ((off > 0) & elastic) ? 0 : 1;
      s.exact[q][j] = e;
      any |= e;
      const double dz = shell_dezz(mp, d0, d1, 0.0) * w[q];
      for (int c = 0; c < 5; ++c) {
        s.old[q][c][j] = o[c];
        sp[q][c][j] = n[c];
      }
      if constexpr (kFirst && q == 0) {
        for (int c = 0; c < 5; ++c) fn[c] = w[q] * n[c];
        for (int c = 0; c < 3; ++c) mn[c] = m[q] * n[c];
        dth = dz;
        epm = std::max(0.0, eps);
      } else {
        for (int c = 0; c < 5; ++c) fn[c] += w[q] * n[c];
        for (int c = 0; c < 3; ++c) mn[c] += m[q] * n[c];
        dth += dz;
        epm = std::max(epm, eps);
      }
    };
    [&]<int... q>(std::integer_sequence<int, q...>) {
      (point(std::integral_constant<int, q>{}), ...);  // in order: the sums are taken point after point
    }
    (std::make_integer_sequence<int, kPts>{});
    for (int c = 0; c < 5; ++c) s.for_new[c][j] = fn[c];
    for (int c = 0; c < 3; ++c) s.mom_new[c][j] = mn[c];
    s.dthick[j] = dth;
    s.eps_p_max[j] = epm;
    if constexpr (kFirst) s.w_plastic[j] = 0;
  }
  return any;
}

template <bool kNewton, int B>
std::int64_t section_point_pass(SectionBlock<B>& s, int len, const MaterialParams& mat,
                                const ShellYieldBound& yb, double gs, const ThicknessRule& rule, int p0,
                                int pts, double* sig, double* eps_p) {
  static_assert(kPassPoints == 5, "the dispatch below lists the pass sizes 1 .. kPassPoints");
  const auto run = [&]<int kPts>(std::integral_constant<int, kPts>) {
    return p0 == 0 ? section_point_pass<true, kNewton, kPts>(s, len, mat, yb, gs, rule, p0, sig, eps_p)
                   : section_point_pass<false, kNewton, kPts>(s, len, mat, yb, gs, rule, p0, sig, eps_p);
  };
  switch (pts) {
    case 1: return run(std::integral_constant<int, 1>{});
    case 2: return run(std::integral_constant<int, 2>{});
    case 3: return run(std::integral_constant<int, 3>{});
    case 4: return run(std::integral_constant<int, 4>{});
    default: return run(std::integral_constant<int, 5>{});
  }
}

// Section update of the block: N = 0 resultant elasticity, or the N points (1.4) with the material update
// (6.3), thickness strain (1.8), plastic work (6.5) and the largest eps_p (6.4).
//
// sig_rows, eps_rows, dmg_rows, brit_rows, res_rows: the first rows of the state this section updates, laid
// out as ShellGroup::sig, ::eps_p, ::dmg, ::brit and ::res ([points][5][G] or [8][G], [points][G],
// [points][G], [points][kBritVars][G], [8][G]); the group's own rows by default. QBAT keeps one such state
// per in-plane Gauss point and passes each in turn.
//
// The old resultants (FOR, MOM before the update, for the energy) are those the last cycle left in res: the
// sums over the same stored stresses in the same order, so the same numbers as summing the points again
// (a Debug build checks it), without their 16 operations per point.
// The rows of the state one section update works on (see section_update_block).
struct SectionRows {
  double* sig;       // [points][5][G], or the [8][G] resultants for N = 0
  double* eps;       // [points][G]
  double* dmg;       // [points][G]
  double* dmg_inst;  // [points][G] the same rows of ShellGroup::dmg_inst
  double* brit;      // [points][kBritVars][G]
  double* res;       // [8][G]
};

// Resultant elasticity (LAW1, N = 0): FOR and MOM are the state, updated from the increments.
template <int B>
[[gnu::always_inline]] inline void section_resultant_elastic(const SectionRows& rows, int i0, int len,
                                                             const MaterialParams& mat, double gs,
                                                             SectionBlock<B>& s) {
  constexpr std::size_t G = kGroupSize;
  double* r = rows.sig + i0;
  const double a11 = mat.a11, a12 = mat.a12, gm = mat.shear;
  const double fz = -mat.nu / (1.0 - mat.nu);
  RADX_IVDEP
  for (int j = 0; j < len; ++j) {
    const double t12 = s.t[j] / 12.0;
    const bool live = s.off[j] > 0;
    double fo[5], mo[3];
    for (int c = 0; c < 5; ++c) fo[c] = r[c * G + j];
    for (int c = 0; c < 3; ++c) mo[c] = r[(5 + c) * G + j];
    const double fn[5] = {fo[0] + a11 * s.dem[0][j] + a12 * s.dem[1][j],
                          fo[1] + a12 * s.dem[0][j] + a11 * s.dem[1][j], fo[2] + gm * s.dem[2][j],
                          fo[3] + gs * s.dem[3][j], fo[4] + gs * s.dem[4][j]};
    const double mn[3] = {mo[0] + t12 * (a11 * s.dk[0][j] + a12 * s.dk[1][j]),
                          mo[1] + t12 * (a12 * s.dk[0][j] + a11 * s.dk[1][j]), mo[2] + t12 * gm * s.dk[2][j]};
    for (int c = 0; c < 5; ++c) {
      s.for_old[c][j] = fo[c];
      s.for_new[c][j] = fn[c];
      r[c * G + j] = live ? fn[c] : fo[c];
    }
    for (int c = 0; c < 3; ++c) {
      s.mom_old[c][j] = mo[c];
      s.mom_new[c][j] = mn[c];
      r[(5 + c) * G + j] = live ? mn[c] : mo[c];
    }
    // Elastic plane stress: dezz = -nu/(1 - nu) (dexx + deyy) at mid-surface.
    s.dthick[j] = fz * (s.dem[0][j] + s.dem[1][j]) * s.t[j];
    s.w_plastic[j] = 0;
    s.eps_p_max[j] = 0;
    s.fail_now[j] = 0;
  }
}

// The old resultants: those the last cycle left in res. A Debug build checks them against the sums over the
// stored stresses.
template <int B>
[[gnu::always_inline]] inline void section_old_resultants(const SectionRows& rows, int i0, int len,
                                                          [[maybe_unused]] const ThicknessRule& rule,
                                                          SectionBlock<B>& s) {
  constexpr std::size_t G = kGroupSize;
  const double* res = rows.res + i0;
  RADX_IVDEP
  for (int j = 0; j < len; ++j) {
    for (int c = 0; c < 5; ++c) s.for_old[c][j] = res[static_cast<std::size_t>(c) * G + j];
    for (int c = 0; c < 3; ++c) s.mom_old[c][j] = res[static_cast<std::size_t>(5 + c) * G + j];
  }
#ifndef NDEBUG
  for (int j = 0; j < len; ++j)
    for (int c = 0; c < 5; ++c) {
      double f = 0, mm = 0;
      for (int p = 0; p < rule.n; ++p) {
        f += rule.w[p] * rows.sig[sig_index(p, c, i0 + j)];
        mm += rule.m[p] * rows.sig[sig_index(p, c, i0 + j)];
      }
      // (a NaN, left by an element deleted with a non-finite stress, equals itself here)
      const auto same = [](double a, double b) { return a == b || (a != a && b != b); };
      assert(same(f, s.for_old[c][j]) && "ShellGroup::res out of date: sig written without its resultants");
      assert((c >= 3 || same(mm, s.mom_old[c][j])) && "ShellGroup::res out of date");
    }
#endif
}

// After a pass over points p0 .. p0 + pts - 1: the stress of deleted elements put back, and the points that
// may yield given the exact update from their stress before the step. Sets any_redo when an element's sums
// must be redone, any_put_back when a deleted element's stress was put back.
template <int B>
[[gnu::always_inline]] inline void section_exact_points(ShellGroup& g, const SectionRows& rows, int i0,
                                                        int len, const MaterialParams& mat,
                                                        const ThicknessRule& rule, double gs, int p0, int pts,
                                                        SectionBlock<B>& s, bool& any_redo,
                                                        bool& any_put_back) {
  constexpr std::size_t G = kGroupSize;
  const int iplas = g.props.iplas;
  const bool fail = mat.fail.on;
  const bool brit = mat.law == model::MaterialLaw::PlasBrit;
  for (int q = 0; q < pts; ++q) {
    const int p = p0 + q;
    const double zeta = rule.zeta[p];
    double* sp[5];
    for (int c = 0; c < 5; ++c) sp[c] = rows.sig + sig_index(p, c, i0);
    double* ep = rows.eps + static_cast<std::size_t>(p) * G + static_cast<std::size_t>(i0);
    for (int j = 0; j < len; ++j) {
      if (s.exact[q][j] == 0) continue;
      if (s.off[j] <= 0) {
        for (int c = 0; c < 5; ++c) sp[c][j] = s.old[q][c][j];
        any_put_back = true;
        continue;
      }
      any_redo = true;
      if (s.rfac_lower && s.rfac_exact[j] == 0) {
        s.rfac[j] = jc_rate_factor(mat, s.rate[j]);
        s.rfac_exact[j] = 1;
      }
      const double z = zeta * s.t[j];
      const double de[5] = {s.dem[0][j] + z * s.dk[0][j], s.dem[1][j] + z * s.dk[1][j],
                            s.dem[2][j] + z * s.dk[2][j], s.dem[3][j], s.dem[4][j]};
      double sg[5] = {s.old[q][0][j], s.old[q][1][j], s.old[q][2][j], s.old[q][3][j], s.old[q][4][j]};
      const std::size_t pj = static_cast<std::size_t>(p) * G + static_cast<std::size_t>(i0 + j);
      const ShellPointResult r =
          brit   ? detail::law27_shell_point(mat, iplas, s.rate[j], s.dt1, s.off[j], de, gs, sg, ep[j],
                                             rows.brit + static_cast<std::size_t>(p) * kBritVars * G +
                                                 static_cast<std::size_t>(i0 + j),
                                             G)
          : fail ? shell_point_update_fail(mat, iplas, s.rfac[j], s.rate[j],
                                           g.fail_scale[static_cast<std::size_t>(i0 + j)], s.off[j], de, gs,
                                           sg, ep[j], rows.dmg[pj], rows.dmg_inst + pj)
                 : shell_point_update_r(mat, iplas, s.rfac[j], s.off[j], de, gs, sg, ep[j]);
      if (r.fails) s.crack_fail[j] = 1;
      for (int c = 0; c < 5; ++c) sp[c][j] = sg[c];
      s.point_exact[p][j] = 1;
      s.dezz_x[p][j] = r.dezz;
      s.wp_x[p][j] = r.w_plastic;
      s.redo[j] = 1;
    }
  }
}

// Sums after the update of the elements with an exactly updated point, redone in the order of the points.
template <int B>
[[gnu::always_inline]] inline void section_redo_sums(const SectionRows& rows, int i0, int len,
                                                     const MaterialParams& mat, const ThicknessRule& rule,
                                                     SectionBlock<B>& s) {
  constexpr std::size_t G = kGroupSize;
  for (int j = 0; j < len; ++j) {
    if (s.redo[j] == 0) continue;
    s.redo[j] = 0;
    const double t = s.t[j];
    double fn[5] = {0, 0, 0, 0, 0}, mn[3] = {0, 0, 0}, dthk = 0, wpl = 0, epmax = 0;
    for (int p = 0; p < rule.n; ++p) {
      const double w = rule.w[p], m = rule.m[p];
      for (int c = 0; c < 5; ++c) fn[c] += w * rows.sig[sig_index(p, c, i0 + j)];
      for (int c = 0; c < 3; ++c) mn[c] += m * rows.sig[sig_index(p, c, i0 + j)];
      double dezz = 0, wp = 0;
      if (s.point_exact[p][j] != 0) {
        s.point_exact[p][j] = 0;
        dezz = s.dezz_x[p][j];
        wp = s.wp_x[p][j];
      } else {
        const double z = rule.zeta[p] * t;
        dezz = shell_dezz(mat, s.dem[0][j] + z * s.dk[0][j], s.dem[1][j] + z * s.dk[1][j], 0.0);
      }
      wpl += wp * w * t * s.area[j];  // wp = 0 unless d_eps_p > 0
      dthk += dezz * w;
      epmax = std::max(epmax, rows.eps[static_cast<std::size_t>(p) * G + static_cast<std::size_t>(i0 + j)]);
    }
    for (int c = 0; c < 5; ++c) s.for_new[c][j] = fn[c];
    for (int c = 0; c < 3; ++c) s.mom_new[c][j] = mn[c];
    s.dthick[j] = dthk;
    s.w_plastic[j] = wpl;
    s.eps_p_max[j] = epmax;
  }
}

// The next cycle's old resultants: those of sig as it is left, the old ones where a deleted element's stress
// was put back.
template <int B>
[[gnu::always_inline]] inline void section_keep_resultants(const SectionRows& rows, int i0, int len,
                                                           bool any_put_back, const SectionBlock<B>& s) {
  constexpr std::size_t G = kGroupSize;
  double* const res = rows.res + i0;
  RADX_IVDEP
  for (int j = 0; j < len; ++j) {
    for (int c = 0; c < 5; ++c) res[static_cast<std::size_t>(c) * G + j] = s.for_new[c][j];
    for (int c = 0; c < 3; ++c) res[static_cast<std::size_t>(5 + c) * G + j] = s.mom_new[c][j];
  }
  if (any_put_back)
    for (int j = 0; j < len; ++j) {
      if (s.off[j] > 0) continue;
      for (int c = 0; c < 5; ++c) res[static_cast<std::size_t>(c) * G + j] = s.for_old[c][j];
      for (int c = 0; c < 3; ++c) res[static_cast<std::size_t>(5 + c) * G + j] = s.mom_old[c][j];
    }
}

// Deletion at once (next_off): law 36 with a point above Eps_p_max; a failure model with the thickness
// fraction of failed points (their weights) at Ifail_sh's threshold (fail_setoff_c.F: 1e-6, or the model's
// fraction bounded by the property's P_thickfail, kept within [1e-6, 1 - 1e-6]); law 27 with a crack past
// /FAIL/BIQUAD S_Flag 3 (OpenRadioss fail_biquad_c.F): unstable[j] = 1 when every point of the section has
// reached the instability (its instability damage is 1). With one in-plane point the section is the element,
// which is then deleted at once; QBAT deletes when all four of its sections are unstable (shell_qbat.cpp).
template <int B>
[[gnu::always_inline]] inline void section_instability(const ShellGroup& g, const SectionRows& rows, int i0,
                                                       int len, const ThicknessRule& rule,
                                                       SectionBlock<B>& s) {
  constexpr std::size_t G = kGroupSize;
  for (int j = 0; j < len; ++j) {
    if (s.off[j] != 1.0) continue;
    bool all = rule.n > 0;
    for (int p = 0; p < rule.n; ++p)
      all = all && rows.dmg_inst[static_cast<std::size_t>(p) * G + static_cast<std::size_t>(i0 + j)] >= 1.0;
    s.unstable[j] = all ? 1.0 : 0.0;
    if (all && g.gauss == 1) s.fail_now[j] = 1.0;
  }
}

// EPS_f1.
template <int B>
[[gnu::always_inline]] inline void section_failure(const ShellGroup& g, const SectionRows& rows, int i0,
                                                   int len, const MaterialParams& mat,
                                                   const ThicknessRule& rule, SectionBlock<B>& s) {
  constexpr std::size_t G = kGroupSize;
  const bool fail = mat.fail.on;
  const bool brit = mat.law == model::MaterialLaw::PlasBrit;
  for (int j = 0; j < len; ++j) s.fail_now[j] = 0;
  const bool tab_limit = mat.law == model::MaterialLaw::PlasTab && mat.tab.eps_p_max < 1e20;
  if (brit)
    for (int j = 0; j < len; ++j) s.fail_now[j] = s.off[j] == 1.0 ? s.crack_fail[j] : 0.0;
  if (!(fail || tab_limit)) return;
  const double pt = std::clamp(std::min(mat.fail.p_thick, std::abs(g.props.p_thick_fail)), 1e-6, 1.0 - 1e-6);
  const double limit = mat.fail.ifail_sh >= 2 ? pt : 1e-6;
  for (int j = 0; j < len; ++j) {
    if (s.off[j] != 1.0) continue;
    bool gone = tab_limit && s.eps_p_max[j] > mat.tab.eps_p_max;
    if (fail) {
      double frac = 0;
      for (int p = 0; p < rule.n; ++p)
        if (rows.dmg[static_cast<std::size_t>(p) * G + static_cast<std::size_t>(i0 + j)] >= 1.0)
          frac += rule.w[p];
      gone = gone || frac >= limit;
    }
    s.fail_now[j] = gone ? 1.0 : 0.0;
  }
  if (mat.fail.kind == FailKind::Biquad && mat.fail.bq_s_flag == 3)
    section_instability(g, rows, i0, len, rule, s);
}

template <int B>
void section_update_block(ShellGroup& g, int i0, int len, const MaterialParams& mat,
                          const ThicknessRule& rule, double gs, SectionBlock<B>& s,
                          double* sig_rows = nullptr, double* eps_rows = nullptr, double* dmg_rows = nullptr,
                          double* brit_rows = nullptr, double* res_rows = nullptr) {
  double* dmg = dmg_rows != nullptr ? dmg_rows : g.dmg.data();
  const SectionRows rows{sig_rows != nullptr ? sig_rows : g.sig.data(),
                         eps_rows != nullptr ? eps_rows : g.eps_p.data(),
                         dmg,
                         g.dmg_inst.data() + (dmg - g.dmg.data()),
                         brit_rows != nullptr ? brit_rows : g.brit.data(),
                         res_rows != nullptr ? res_rows : g.res.data()};
  for (int j = 0; j < len; ++j) s.unstable[j] = 0;
  if (rule.n == 0) {
    section_resultant_elastic(rows, i0, len, mat, gs, s);
    return;
  }
  const int iplas = g.props.iplas;
  const ShellYieldBound yb = shell_yield_bound(mat);
  if (mat.law == model::MaterialLaw::PlasBrit)
    for (int j = 0; j < len; ++j) s.crack_fail[j] = 0;
  double* sig = rows.sig + i0;
  double* eps_p = rows.eps + i0;
  section_old_resultants(rows, i0, len, rule, s);
  bool any_redo = false, any_put_back = false;
  for (int p0 = 0; p0 < rule.n; p0 += kPassPoints) {
    const int pts = std::min(kPassPoints, rule.n - p0);
    const std::int64_t any = iplas == 1
                                 ? section_point_pass<true>(s, len, mat, yb, gs, rule, p0, pts, sig, eps_p)
                                 : section_point_pass<false>(s, len, mat, yb, gs, rule, p0, pts, sig, eps_p);
    if (any != 0) section_exact_points(g, rows, i0, len, mat, rule, gs, p0, pts, s, any_redo, any_put_back);
  }
  if (any_redo) section_redo_sums(rows, i0, len, mat, rule, s);
  RADX_IVDEP
  for (int j = 0; j < len; ++j) s.dthick[j] *= s.t[j];
  section_keep_resultants(rows, i0, len, any_put_back, s);
  section_failure(g, rows, i0, len, mat, rule, s);
}

// limit = EPS_p_max of a Johnson-Cook material, +infinity for a law that does not fail (failure_limit).
inline double next_off(double limit, double off_start, double eps_p_max) {
  if (off_start < 1.0) return off_start < 0.1 ? 0.0 : 0.8 * off_start;
  return eps_p_max >= limit ? 0.8 : off_start;
}

// With the section's verdict of deletion at once (fail_now 1: OFF 0; /FAIL/JOHNSON, law 36 Eps_p_max).
inline double next_off(double limit, double off_start, double eps_p_max, double fail_now) {
  return fail_now != 0 ? 0.0 : next_off(limit, off_start, eps_p_max);
}

// The progressive failure limit: law 2's EPS_p_max (law 36 deletes at once through fail_now instead).
inline double failure_limit(const MaterialParams& mat) {
  return mat.law == model::MaterialLaw::JohnsonCook ? mat.jc.eps_p_max
                                                    : std::numeric_limits<double>::infinity();
}

}  // namespace radx::solver::shell_detail
