// The local frame of the shell kernels and the two changes of axes every shell kernel makes: global node
// vectors into the element frame, and the element's local nodal forces and moments back to global axes.
// Used by shell_bt4.cpp, shell_c0_tri3.cpp, shell_qeph.cpp, shell_qbat.cpp and the result fields, so that the
// frame each of them sees is written once. Internal to the solver; not a public API.
//
// Equations (docs/theory/elements.md):
//   1.2  four-node (bisector) frame, rebuilt every cycle from X^n:
//        g1 = (X2 - X1) + (X3 - X4), g2 = (X3 - X2) + (X4 - X1), e3 = g1 x g2 / |g1 x g2|,
//        e1 = normalise(g1 + |g1|/|g2| (g2 x e3)), e2 = e3 x e1;
//   2    three-node frame: e1 = (X2 - X1)/|X2 - X1|, e3 = normalise((X3 - X1) x (X3 - X2)), e2 = e3 x e1;
//   1.6  the local forces (fx fy fz) and moments (mx my, no drilling) are rotated back with R = [e1 e2 e3]
//        and stored with a minus sign: the buffer holds the force ADDED to each node.
//
// The four-node frame runs over a block of elements in three vectorised passes, with the square roots taken
// in passes of their own (sqrt_in_place, see material_point.hpp): the same operations, in the same order, as
// the element-by-element version, so the results are the same to the bit.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "solver/elements/element_gather.hpp"
#include "solver/elements/shell/shell_section.hpp"
#include "solver/materials/material_point.hpp"

namespace radx::solver::shell_detail {

// Frame of a block of elements, [component][slot]; root is the scratch of its square roots.
template <std::size_t B>
struct FrameBlock {
  double e1[3][B], e2[3][B], e3[3][B];
  double root[3][B];
};

// The four-node frame (1.2) of the block's elements 0 .. len - 1 from their gathered positions.
template <std::size_t B>
inline void quad_frame_block(const NodeBlock<4, B>& nb, int len, FrameBlock<B>& f) {
  const double tiny30 = opaque(1e-30);  // floor of the divisors
  // g1, g2 (kept in e1, e2 until the last pass), g1 x g2 and the squares of the three norms.
  RADX_IVDEP
  for (int j = 0; j < len; ++j) {
    const double g1x = (nb.x[1][j] - nb.x[0][j]) + (nb.x[2][j] - nb.x[3][j]),
                 g1y = (nb.y[1][j] - nb.y[0][j]) + (nb.y[2][j] - nb.y[3][j]),
                 g1z = (nb.z[1][j] - nb.z[0][j]) + (nb.z[2][j] - nb.z[3][j]);
    const double g2x = (nb.x[2][j] - nb.x[1][j]) + (nb.x[3][j] - nb.x[0][j]),
                 g2y = (nb.y[2][j] - nb.y[1][j]) + (nb.y[3][j] - nb.y[0][j]),
                 g2z = (nb.z[2][j] - nb.z[1][j]) + (nb.z[3][j] - nb.z[0][j]);
    const double e3x = g1y * g2z - g1z * g2y, e3y = g1z * g2x - g1x * g2z, e3z = g1x * g2y - g1y * g2x;
    f.e1[0][j] = g1x, f.e1[1][j] = g1y, f.e1[2][j] = g1z;
    f.e2[0][j] = g2x, f.e2[1][j] = g2y, f.e2[2][j] = g2z;
    f.e3[0][j] = e3x, f.e3[1][j] = e3y, f.e3[2][j] = e3z;
    f.root[0][j] = e3x * e3x + e3y * e3y + e3z * e3z;
    f.root[1][j] = g1x * g1x + g1y * g1y + g1z * g1z;
    f.root[2][j] = g2x * g2x + g2y * g2y + g2z * g2z;
  }
  sqrt_in_place(f.root[0], static_cast<int>(3 * B));
  // e3 = g1 x g2 / |g1 x g2|, e1 before its normalisation.
  RADX_IVDEP
  for (int j = 0; j < len; ++j) {
    const double n3 = f.root[0][j], ng1 = f.root[1][j], ng2 = f.root[2][j];
    const double inv = 1.0 / std::max(n3, tiny30);
    const double e3x = f.e3[0][j] * inv, e3y = f.e3[1][j] * inv, e3z = f.e3[2][j] * inv;
    f.e3[0][j] = e3x, f.e3[1][j] = e3y, f.e3[2][j] = e3z;
    const double f12 = ng1 / std::max(ng2, tiny30);
    const double g2x = f.e2[0][j], g2y = f.e2[1][j], g2z = f.e2[2][j];
    const double e1x = f.e1[0][j] + f12 * (g2y * e3z - g2z * e3y),
                 e1y = f.e1[1][j] + f12 * (g2z * e3x - g2x * e3z),
                 e1z = f.e1[2][j] + f12 * (g2x * e3y - g2y * e3x);
    f.e1[0][j] = e1x, f.e1[1][j] = e1y, f.e1[2][j] = e1z;
    f.root[0][j] = e1x * e1x + e1y * e1y + e1z * e1z;
  }
  sqrt_in_place(f.root[0], static_cast<int>(B));
  // e1 normalised, e2 = e3 x e1.
  RADX_IVDEP
  for (int j = 0; j < len; ++j) {
    const double inv = 1.0 / std::max(f.root[0][j], tiny30);
    const double e1x = f.e1[0][j] * inv, e1y = f.e1[1][j] * inv, e1z = f.e1[2][j] * inv;
    const double e3x = f.e3[0][j], e3y = f.e3[1][j], e3z = f.e3[2][j];
    f.e1[0][j] = e1x, f.e1[1][j] = e1y, f.e1[2][j] = e1z;
    f.e2[0][j] = e3y * e1z - e3z * e1y, f.e2[1][j] = e3z * e1x - e3x * e1z,
    f.e2[2][j] = e3x * e1y - e3y * e1x;
  }
}

// The three-node frame (2) from the positions of the three nodes; returns |X2 - X1|.
inline double tri_frame(const double px[3], const double py[3], const double pz[3], double e1[3],
                        double e2[3], double e3[3]) {
  const double d21x = px[1] - px[0], d21y = py[1] - py[0], d21z = pz[1] - pz[0];
  const double d31x = px[2] - px[0], d31y = py[2] - py[0], d31z = pz[2] - pz[0];
  const double d32x = px[2] - px[1], d32y = py[2] - py[1], d32z = pz[2] - pz[1];
  const double len12 = std::sqrt(d21x * d21x + d21y * d21y + d21z * d21z);
  double inv = 1.0 / std::max(len12, 1e-30);
  e1[0] = d21x * inv, e1[1] = d21y * inv, e1[2] = d21z * inv;
  double e3x = d31y * d32z - d31z * d32y, e3y = d31z * d32x - d31x * d32z, e3z = d31x * d32y - d31y * d32x;
  inv = 1.0 / std::max(std::sqrt(e3x * e3x + e3y * e3y + e3z * e3z), 1e-30);
  e3[0] = e3x * inv, e3[1] = e3y * inv, e3[2] = e3z * inv;
  e2[0] = e3[1] * e1[2] - e3[2] * e1[1];
  e2[1] = e3[2] * e1[0] - e3[0] * e1[2];
  e2[2] = e3[0] * e1[1] - e3[1] * e1[0];
  return len12;
}

// Components of the global vector (ux, uy, uz) on the axes e1, e2, e3.
inline void to_local(double e1x, double e1y, double e1z, double e2x, double e2y, double e2z, double e3x,
                     double e3y, double e3z, double ux, double uy, double uz, double& l1, double& l2,
                     double& l3) {
  l1 = e1x * ux + e1y * uy + e1z * uz;
  l2 = e2x * ux + e2y * uy + e2z * uz;
  l3 = e3x * ux + e3y * uy + e3z * uz;
}

// Node k's local internal force (fx fy fz) and moment (mx my) of element ii, rotated to global axes and
// stored with the minus sign in a force buffer laid out [node][6][G] (fx fy fz mx my mz, force ADDED).
inline void store_local_forces(double* nf, std::size_t stride, std::size_t k, std::size_t ii, double e1x,
                               double e1y, double e1z, double e2x, double e2y, double e2z, double e3x,
                               double e3y, double e3z, double fx, double fy, double fz, double mx,
                               double my) {
  double* o = nf + k * 6 * stride + ii;
  o[0] = -(fx * e1x + fy * e2x + fz * e3x);
  o[stride] = -(fx * e1y + fy * e2y + fz * e3y);
  o[2 * stride] = -(fx * e1z + fy * e2z + fz * e3z);
  o[3 * stride] = -(mx * e1x + my * e2x);
  o[4 * stride] = -(mx * e1y + my * e2y);
  o[5 * stride] = -(mx * e1z + my * e2z);
}

// Node k's in-plane coordinates (lx, ly) relative to node 1 through the small-strain switch, branch-free so
// that the vectorised BT4 and QEPH loops stay vectorised: on the capture cycle (capture = 1) the current ones
// (cx, cy) are stored in the reference slots (rx0, ry0); while frozen (frozen = 1) the stored ones are used.
// With 0 for both the current values come back exactly and the slots are unchanged.
inline void small_strain_coordinates(double cx, double cy, double capture, double frozen, double& rx0,
                                     double& ry0, double& lx, double& ly) {
  rx0 = capture * cx + (1.0 - capture) * rx0;
  ry0 = capture * cy + (1.0 - capture) * ry0;
  lx = frozen * rx0 + (1.0 - frozen) * cx;
  ly = frozen * ry0 + (1.0 - frozen) * cy;
}

// Local geometry and velocities of element j of a four-node block (QBAT's front stage,
// docs/theory/elements.md 1.2; QEPH takes the same steps in its vectorised loop): the node coordinates
// relative to node 1 in the frame (lx, ly), under small strain (frozen: /DT/SHELL/CST switch or Ismstr 1) the
// first cycle's ones, kept in g.ref_local (x2 x3 x4 y2 y3 y4); the nodal velocities (vx vy vz) and rotation
// rates (rx ry) on the frame's axes. The values are also stored in the block's local
// rows (bk.vx ... bk.ly) for the back stage.
template <class Block>
inline void quad_local_state(Block& bk, int j, ShellGroup& g, std::size_t ii, bool frozen, double lx[4],
                             double ly[4], double vx[4], double vy[4], double vz[4], double rx[4],
                             double ry[4]) {
  constexpr std::size_t G = kGroupSize;
  const double e1[3] = {bk.fr.e1[0][j], bk.fr.e1[1][j], bk.fr.e1[2][j]};
  const double e2[3] = {bk.fr.e2[0][j], bk.fr.e2[1][j], bk.fr.e2[2][j]};
  const double e3[3] = {bk.fr.e3[0][j], bk.fr.e3[1][j], bk.fr.e3[2][j]};
  lx[0] = ly[0] = 0.0;
  for (int k = 1; k < 4; ++k) {
    double lz = 0;
    to_local(e1[0], e1[1], e1[2], e2[0], e2[1], e2[2], e3[0], e3[1], e3[2], bk.nb.x[k][j] - bk.nb.x[0][j],
             bk.nb.y[k][j] - bk.nb.y[0][j], bk.nb.z[k][j] - bk.nb.z[0][j], lx[k], ly[k], lz);
  }
  if (frozen) {  // small strain: the local coordinates of the first cycle
    if (g.small[ii] == 0.0) {
      for (int k = 1; k < 4; ++k) {
        g.ref_local[static_cast<std::size_t>(k - 1) * G + ii] = lx[k];
        g.ref_local[static_cast<std::size_t>(k + 2) * G + ii] = ly[k];
      }
      g.small[ii] = 1.0;
    }
    for (int k = 1; k < 4; ++k) {
      lx[k] = g.ref_local[static_cast<std::size_t>(k - 1) * G + ii];
      ly[k] = g.ref_local[static_cast<std::size_t>(k + 2) * G + ii];
    }
  }
  for (int k = 0; k < 4; ++k) {
    double rz_unused = 0;
    to_local(e1[0], e1[1], e1[2], e2[0], e2[1], e2[2], e3[0], e3[1], e3[2], bk.nb.vx[k][j], bk.nb.vy[k][j],
             bk.nb.vz[k][j], vx[k], vy[k], vz[k]);
    to_local(e1[0], e1[1], e1[2], e2[0], e2[1], e2[2], e3[0], e3[1], e3[2], bk.nb.rx[k][j], bk.nb.ry[k][j],
             bk.nb.rz[k][j], rx[k], ry[k], rz_unused);
    bk.vx[k][j] = vx[k], bk.vy[k][j] = vy[k], bk.vz[k][j] = vz[k], bk.rx[k][j] = rx[k], bk.ry[k][j] = ry[k];
    bk.lx[k][j] = lx[k], bk.ly[k][j] = ly[k];
  }
}

// A deleted (or deleting) shell: no nodal force on rows 0 .. rows - 1 of element ii, dt = +inf, k = 0.
inline void clear_shell_element(ShellGroup& g, double* nf, std::size_t ii, int rows) {
  constexpr std::size_t G = kGroupSize;
  for (int r = 0; r < rows; ++r) nf[r * G + ii] = 0.0;
  g.dt[ii] = std::numeric_limits<double>::infinity();
  g.k_nodal[ii] = 0.0;
}

// Membrane damping stresses (docs/theory/elements.md 1.4) of a point of area A from the membrane increments
// dem (xx yy xy): visc = visc0 sqrt(A), fv = visc (dexx + deyy/2, deyy + dexx/2, dgxy/3); 0 when visc0 = 0.
inline void membrane_damping(double visc0, double area, const double dem[5], double fv[3]) {
  fv[0] = fv[1] = fv[2] = 0.0;
  if (visc0 > 0) {
    const double visc = visc0 * std::sqrt(area);
    fv[0] = visc * (dem[0] + 0.5 * dem[1]);
    fv[1] = visc * (dem[1] + 0.5 * dem[0]);
    fv[2] = visc * dem[2] / 3.0;
  }
}

// Internal energy increment of a point of weight w (area) and thickness t, docs/theory/elements.md 1.5: the
// trapezoid of the resultants before (times off_start) and after (times off)
// the section update, plus the damping work,
//   dE = w t / 2 (sum_q (off0 F_old + off F_new)_q dem_q + t sum_q (off0 M_old + off M_new)_q dk_q)
//        + w t off fv . dem,
// with F, M the averaged stresses N/t and M/t^2 of element j of the section rows (SectionBlock layout).
template <int B>
inline double shell_energy_increment(double w, double t, double off_start, double off,
                                     const double (&for_old)[5][B], const double (&for_new)[5][B],
                                     const double (&mom_old)[3][B], const double (&mom_new)[3][B], int j,
                                     const double dem[5], const double dk[3], const double fv[3]) {
  double de_mem = 0, de_bend = 0;
  for (int q = 0; q < 5; ++q) de_mem += (off_start * for_old[q][j] + off * for_new[q][j]) * dem[q];
  for (int q = 0; q < 3; ++q) de_bend += (off_start * mom_old[q][j] + off * mom_new[q][j]) * dk[q];
  return 0.5 * w * t * (de_mem + t * de_bend) +
         w * t * off * (fv[0] * dem[0] + fv[1] * dem[1] + fv[2] * dem[2]);
}

}  // namespace radx::solver::shell_detail
