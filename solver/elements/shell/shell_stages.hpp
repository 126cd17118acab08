// The stages every shell kernel shares (shell_bt4.cpp, shell_qeph.cpp, shell_qbat.cpp, shell_c0_tri3.cpp),
// written once so that they cannot drift apart:
//   constants    the group's material and property figures (docs/theory/elements.md 1.4, 4.1):
//                c = sqrt(E / rho) (or the material's shell sound speed), A11 = E / (1 - nu^2),
//                Gs = SHF G (SHF = 0 with one point), phi = sqrt(1 + D^2) - D for the step's damping D
//                (Dm for BT4 and the triangle, Dn for QEPH and QBAT), visc0 = 1.414 Dm rho c / dt1 of the
//                membrane damping, alpha of the strain-rate filter (6.1), EPS_p_max (6.4);
//   opening      gather of the block's nodes, the four-node frame (1.2), and the thickness at first use;
//   closing      local forces rotated to global axes and stored with the minus sign (1.6), the element step
//                and nodal stiffness beside them; deleted elements cleared (no force, no stiffness, no step).
//
// Thickness at first use: thick = 0 marks a thickness not taken yet, and a shell then takes t0. The kernels
// differ in which elements take it, and each keeps its rule through FirstUseThickness: BT4 and the triangle
// only live elements (OFF > 0), QEPH and QBAT every element.
//
// Every stage is inline on the kernel's block scratch, with the arithmetic of the loops it replaces, in the
// same order: the kernels give the same results to the bit as when each wrote its own.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "solver/elements/element_gather.hpp"
#include "solver/elements/element_groups.hpp"
#include "solver/elements/shell/shell_frame.hpp"
#include "solver/elements/shell/shell_section.hpp"

namespace radx::solver::shell_detail {

// The group's constants of a shell kernel; step_damping is the D of phi (Dm or Dn).
struct ShellConstants {
  double dt1, young, nu, rho, c, a11, shf, gs, phi, visc0, alpha, fail_limit;
  bool update_thick;
  ThicknessRule rule;
};

inline ShellConstants shell_constants(const ShellProps& pr, const MaterialParams& mat, double dt1,
                                      double step_damping) {
  ShellConstants k;
  k.dt1 = dt1;
  k.young = mat.young, k.nu = mat.nu, k.rho = mat.rho0;
  k.c = mat.c_shell > 0 ? mat.c_shell : std::sqrt(k.young / k.rho);
  k.a11 = mat.a11 > 0 ? mat.a11 : k.young / (1.0 - k.nu * k.nu);
  k.shf = pr.n_points == 1 ? 0.0 : pr.ashear;
  k.gs = k.shf * mat.shear;
  k.phi = std::sqrt(1.0 + step_damping * step_damping) - step_damping;
  k.visc0 = (pr.dm > 0 && dt1 > 0) ? 1.414 * pr.dm * k.rho * k.c / dt1 : 0.0;
  k.alpha = rate_filter_alpha(mat, dt1);
  k.fail_limit = failure_limit(mat);
  k.update_thick = pr.ithick == 1;
  k.rule = thickness_rule(std::max(pr.n_points, 0));
  return k;
}

enum class FirstUseThickness : std::uint8_t {
  LiveElements,  // BT4, the triangle: OFF > 0 and thick <= 0
  EveryElement,  // QEPH, QBAT: thick <= 0
};

// The thickness of an element whose factor is off and whose stored thickness is th, after its first use.
[[gnu::always_inline]] inline double first_use_thickness(FirstUseThickness rule, double off, double th,
                                                         double t0) {
  const bool take = rule == FirstUseThickness::LiveElements ? (off > 0.0 && th <= 0.0) : th <= 0.0;
  return take ? t0 : th;
}

// Opening of a four-node block: the nodes of elements i0 .. i0 + len - 1 gathered, and their frame (1.2).
template <std::size_t B>
[[gnu::always_inline]] inline void open_quad_block(const ShellGroup& g, const NodeState& nodes, int i0,
                                                   int len, NodeBlock<4, B>& nb, FrameBlock<B>& fr) {
  gather_block<true>(g.conn.data(), kGroupSize, static_cast<std::size_t>(i0), static_cast<std::size_t>(len),
                     nodes, nb);
  quad_frame_block(nb, len, fr);
}

// The block's factors at entry and thicknesses: the stored thickness after its first use, and the mechanics
// thickness t (the current one with Ithick 1, t0 otherwise), into the section's inputs.
template <int B>
[[gnu::always_inline]] inline void open_thickness_block(FirstUseThickness first_use, bool update_thick,
                                                        ShellGroup& g, int i0, int len,
                                                        SectionBlock<B>& sec) {
  const double* offs = g.off.data();
  double* thick = g.thick.data();
  const double* t0 = g.t0.data();
  RADX_IVDEP
  for (int j = 0; j < len; ++j) {
    const std::size_t ii = static_cast<std::size_t>(i0 + j);
    const double off0 = offs[ii], t0i = t0[ii];
    sec.off[j] = off0;
    const double th = first_use_thickness(first_use, off0, thick[ii], t0i);
    thick[ii] = th;
    sec.t[j] = update_thick ? th : t0i;
  }
}

// Closing of a four-node block: node k's local forces fl[0..2][k] and moments fl[3..4][k] rotated to global
// axes and stored (force ADDED), and step(j, ii) writing the element's step and nodal stiffness, in the same
// loop (the frame is in registers once).
template <std::size_t B, class Step>
[[gnu::always_inline]] inline void store_quad_block(const FrameBlock<B>& fr, const double (&fl)[5][4][B],
                                                    ShellGroup& g, int i0, int len, Step&& step) {
  constexpr std::size_t G = kGroupSize;
  double* nf = g.nodal_force.data();
  RADX_IVDEP
  for (int j = 0; j < len; ++j) {
    const std::size_t ii = static_cast<std::size_t>(i0 + j);
    const double e1x = fr.e1[0][j], e1y = fr.e1[1][j], e1z = fr.e1[2][j];
    const double e2x = fr.e2[0][j], e2y = fr.e2[1][j], e2z = fr.e2[2][j];
    const double e3x = fr.e3[0][j], e3y = fr.e3[1][j], e3z = fr.e3[2][j];
#pragma GCC unroll 4
    for (int k = 0; k < 4; ++k)
      store_local_forces(nf, G, static_cast<std::size_t>(k), ii, e1x, e1y, e1z, e2x, e2y, e2z, e3x, e3y, e3z,
                         fl[0][k][j], fl[1][k][j], fl[2][k][j], fl[3][k][j], fl[4][k][j]);
    step(j, ii);
  }
}

// Elements of the block deleted at entry or in this cycle (gone[j] != 0): no force, no stiffness, no step.
// any_gone = 0 skips the pass.
[[gnu::always_inline]] inline void clear_deleted_block(ShellGroup& g, int i0, int len,
                                                       const std::int64_t* gone, std::int64_t any_gone) {
  if (any_gone == 0) return;
  double* nf = g.nodal_force.data();
  for (int j = 0; j < len; ++j)
    if (gone[j] != 0) clear_shell_element(g, nf, static_cast<std::size_t>(i0 + j), 24);
}

}  // namespace radx::solver::shell_detail
