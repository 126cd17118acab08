// Stages every solid kernel runs the same way, written once: the one-point brick (hex8_fb.cpp), HEPH
// (hex8_heph.cpp), the fully integrated brick (hex8_full.cpp) and the tetrahedron (tetra4.cpp) call these.
// Internal to the solver; not a public API.
//
// Small inline functions, one per quantity, each with its formula and the section of docs/theory/elements.md
// it comes from. The arithmetic is written in the order the kernels had it (left to right, no reassociation),
// so the kernels' results do not change to the bit; keep that order when editing. No allocation, no virtual
// call: the compiler inlines them into the element loops.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "solver/elements/element_groups.hpp"

namespace radx::solver {

// Faces of the eight-node brick (node positions 0..7) for the characteristic length; orientation does not
// matter there.
inline constexpr int kBrickFaces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                          {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};

// c = a x b.
inline void cross3(const double a[3], const double b[3], double c[3]) {
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

// a . b.
inline double dot3(const double a[3], const double b[3]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// One-point brick geometry (docs/theory/elements.md 3.2, sderi3.F), nodes 1-4 one face, 5-8 above them:
//   d17 = x7 - x1, d28 = x8 - x2, d35 = x5 - x3, d46 = x6 - x4,
//   j1 = d17 + d28 - d35 - d46 (8 dx/deta), j2 = d17 + d28 + d35 + d46 (8 dx/dzeta),
//   j3 = d17 - d28 - d35 + d46 (8 dx/dxi); c12 = j1 x j2, c23 = j2 x j3, c31 = j3 x j1;
//   returns V = j1 . c23 / 64 (8 det J(0), not the trilinear volume).
inline double brick_centre_jacobian(const double x[8][3], double j1[3], double j2[3], double j3[3],
                                    double c12[3], double c23[3], double c31[3]) {
#pragma GCC unroll 8
  for (int d = 0; d < 3; ++d) {
    const double d17 = x[6][d] - x[0][d];
    const double d28 = x[7][d] - x[1][d];
    const double d35 = x[4][d] - x[2][d];
    const double d46 = x[5][d] - x[3][d];
    j1[d] = d17 + d28 - d35 - d46;
    j2[d] = d17 + d28 + d35 + d46;
    j3[d] = d17 - d28 - d35 + d46;
  }
  cross3(j1, j2, c12);
  cross3(j2, j3, c23);
  cross3(j3, j1, c31);
  return (j1[0] * c23[0] + j1[1] * c23[1] + j1[2] * c23[2]) / 64.0;
}

// Centre gradients b_k = dN_k/dx(0) = [xi_k c12 + eta_k c23 + zeta_k c31] / (64 V)
// (docs/theory/elements.md 3.2), so b5 = -b3, b6 = -b4, b7 = -b1, b8 = -b2.
inline void brick_centre_gradients(const double c12[3], const double c23[3], const double c31[3], double vol,
                                   double b[8][3]) {
  const double inv = 1.0 / (64.0 * vol);
#pragma GCC unroll 8
  for (int d = 0; d < 3; ++d) {
    b[0][d] = -(c12[d] + c23[d] + c31[d]) * inv;
    b[1][d] = (c12[d] - c23[d] - c31[d]) * inv;
    b[2][d] = (c12[d] + c23[d] - c31[d]) * inv;
    b[3][d] = (-c12[d] + c23[d] - c31[d]) * inv;
    b[4][d] = -b[2][d];
    b[5][d] = -b[3][d];
    b[6][d] = -b[0][d];
    b[7][d] = -b[1][d];
  }
}

// Velocity gradient of the one-point brick, L[a][c] = dv_a/dx_c = sum_k v_k,a b_k,c, from the opposite-node
// differences (docs/theory/elements.md 3.2): (v1 - v7) b1 + (v2 - v8) b2 + (v3 - v5) b3 + (v4 - v6) b4.
inline void brick_velocity_gradient(const double v[8][3], const double b[8][3], double L[3][3]) {
  for (int a = 0; a < 3; ++a) L[a][0] = L[a][1] = L[a][2] = 0.0;
#pragma GCC unroll 8
  for (int k = 0; k < 4; ++k) {
    const int o = (k < 2) ? k + 6 : k + 2;  // opposite nodes: 1-7, 2-8, 3-5, 4-6
#pragma GCC unroll 8
    for (int a = 0; a < 3; ++a) {
      const double dv = v[k][a] - v[o][a];
      L[a][0] += dv * b[k][0];
      L[a][1] += dv * b[k][1];
      L[a][2] += dv * b[k][2];
    }
  }
}

// Mode sums r[j][d] = sum_k h_jk a_k of the one-point brick's hourglass vectors
// (docs/theory/elements.md 3.4), h1 = (1,-1,1,-1,1,-1,1,-1), h2 = (1,1,-1,-1,-1,-1,1,1),
// h3 = (1,-1,-1,1,-1,1,1,-1), h4 = (1,-1,1,-1,-1,1,-1,1), pairwise: with p = a1 - a4 - a6 + a7,
// m = a2 - a3 - a5 + a8, s = a1 - a2 - a5 + a6, t = a3 - a4 - a7 + a8:
// h1 = p - m, h2 = p + m, h3 = s - t, h4 = s + t.
inline void brick_mode_sums(double a1, double a2, double a3, double a4, double a5, double a6, double a7,
                            double a8, double r[4][3], int d) {
  const double p = a1 - a4 - a6 + a7, m = a2 - a3 - a5 + a8;
  const double s = a1 - a2 - a5 + a6, t = a3 - a4 - a7 + a8;
  r[0][d] = p - m;
  r[1][d] = p + m;
  r[2][d] = s - t;
  r[3][d] = s + t;
}

// Nodal forces f[k] (ADDED to node k) of a one-point brick with stress sn (xx yy zz xy yz zx), bulk
// viscosity q and hourglass forces H_j = hg[j] on the vectors h_j of brick_mode_sums, with
// G_jk = h_jk - hx_j . b_k (docs/theory/elements.md 3.2, 3.4): stress
// part -V (sigma - q I) b_k, hourglass part
//   -sum_j G_jk H_j = -sum_j h_jk H_j + M b_k with M = sum_j H_j (x) hx_j,
// so f_k = -T b_k - sum_j h_jk H_j with T = V (sigma - q I) - M, and b_{5..8} = -b_{3,4,1,2}: the same
// quantities as node by node, fewer operations. hx_j = 0 gives the plain vector h_j.
inline void brick_nodal_forces(const double sn[6], double q, double vol, const double hg[4][3],
                               const double hx[4][3], const double b[8][3], double f[8][3]) {
  double T[3][3];
  const double sg[3][3] = {{sn[0] - q, sn[3], sn[5]}, {sn[3], sn[1] - q, sn[4]}, {sn[5], sn[4], sn[2] - q}};
#pragma GCC unroll 8
  for (int a = 0; a < 3; ++a)
#pragma GCC unroll 8
    for (int e = 0; e < 3; ++e)
      T[a][e] = vol * sg[a][e] -
                (hg[0][a] * hx[0][e] + hg[1][a] * hx[1][e] + hg[2][a] * hx[2][e] + hg[3][a] * hx[3][e]);
#pragma GCC unroll 8
  for (int k = 0; k < 4; ++k) {
    const int o = (k < 2) ? k + 6 : k + 2;
#pragma GCC unroll 8
    for (int a = 0; a < 3; ++a) {
      const double tb = T[a][0] * b[k][0] + T[a][1] * b[k][1] + T[a][2] * b[k][2];
      f[k][a] = -tb;
      f[o][a] = tb;
    }
  }
#pragma GCC unroll 8
  for (int a = 0; a < 3; ++a) {
    const double h1 = hg[0][a], h2 = hg[1][a], h3 = hg[2][a], h4 = hg[3][a];
    f[0][a] -= h1 + h2 + h3 + h4;
    f[1][a] -= -h1 + h2 - h3 - h4;
    f[2][a] -= h1 - h2 - h3 + h4;
    f[3][a] -= -h1 - h2 + h3 - h4;
    f[4][a] -= h1 - h2 - h3 - h4;
    f[5][a] -= -h1 - h2 + h3 + h4;
    f[6][a] -= h1 + h2 + h3 - h4;
    f[7][a] -= -h1 + h2 - h3 + h4;
  }
}

// /DT/BRICK/CST small strain (docs/theory/elements.md 3.1, hex8_fb.cpp): freeze the brick's node coordinates
// in x_ref the first cycle after the switch (dt_fixed > 0), then take x from
// them every cycle (velocities stay current).
inline void brick_small_strain_geometry(BrickGroup& g, std::size_t i, double x[8][3]) {
  constexpr std::size_t G = kGroupSize;
  if (g.dt_fixed[i] > 0.0 && !g.small[i]) {
    for (std::size_t k = 0; k < 8; ++k)
      for (std::size_t d = 0; d < 3; ++d) g.x_ref[(k * 3 + d) * G + i] = x[k][d];
    g.small[i] = 1;
  }
  if (g.small[i]) {
    for (std::size_t k = 0; k < 8; ++k)
      for (std::size_t d = 0; d < 3; ++d) x[k][d] = g.x_ref[(k * 3 + d) * G + i];
  }
}

// Nodes and velocities of a brick into the element frame R = [e_x e_y e_z] (docs/theory/elements.md 3.6):
// x' = R^T x, v' = R^T v, i.e. x'_c = sum_r R[r][c] x_r.
inline void brick_into_frame(const double R[3][3], double x[8][3], double v[8][3]) {
#pragma GCC unroll 8
  for (int k = 0; k < 8; ++k) {
    double xl[3], vl[3];
#pragma GCC unroll 3
    for (int c = 0; c < 3; ++c) {
      xl[c] = R[0][c] * x[k][0] + R[1][c] * x[k][1] + R[2][c] * x[k][2];
      vl[c] = R[0][c] * v[k][0] + R[1][c] * v[k][1] + R[2][c] * v[k][2];
    }
    for (int c = 0; c < 3; ++c) {
      x[k][c] = xl[c];
      v[k][c] = vl[c];
    }
  }
}

// Nodal forces of a brick from its element frame back to global axes (docs/theory/elements.md 3.6): f = R f'.
inline void brick_from_frame(const double R[3][3], double f[8][3]) {
#pragma GCC unroll 8
  for (int k = 0; k < 8; ++k) {
    const double a = f[k][0], b = f[k][1], c = f[k][2];
#pragma GCC unroll 3
    for (int r = 0; r < 3; ++r) f[k][r] = R[r][0] * a + R[r][1] * b + R[r][2] * c;
  }
}

// Co-rotational frame of a block of one-point bricks (docs/theory/elements.md 3.6; srepiso3.F, sortho3.F),
// the formulas of brick_corotational_frame (hex8_fb.cpp, which runs this with B = 1): r = j1, s = j2, t = j3
// (eta, zeta, xi) normalised to u, v, w; three times u <- unit(v x w + u), v <- unit(w x u + v),
// w <- unit(u x v + w); e1 = u, e3 = unit(e1 x v), e2 = e3 x e1. A zero vector stays zero under unit().
// Columns (e_x e_y e_z) = (e1 e2 e3), or (e3 e1 e2) with heph_order (Isolid 24).
// Structure of arrays over the slots j < len (positions x, y, z [node][slot]), one vectorised pass between
// two rounds of square roots, so that the thirteen dependent square roots and divisions of an element overlap
// with those of the others; the same operations in the same order as element by element, so the same bits.
template <std::size_t B>
struct BrickFrameBlock {
  double R[3][3][B];  // R[row][column][slot]
  double u[3][B], v[3][B], w[3][B];
  double root[3][B];  // squared lengths, then lengths
};

template <std::size_t B>
inline void brick_corotational_frame_block(const double x[8][B], const double y[8][B], const double z[8][B],
                                           int len, bool heph_order, BrickFrameBlock<B>& f) {
  const double one = opaque(1.0);  // divisor of a zero length: the vector stays as it is
  auto roots = [&](int rows) {
    for (int r = 0; r < rows; ++r) sqrt_in_place(f.root[r], len);
  };
  const double(*p[3])[B] = {x, y, z};
  RADX_IVDEP
  for (int j = 0; j < len; ++j) {
#pragma GCC unroll 3
    for (int d = 0; d < 3; ++d) {
      const double d17 = p[d][6][j] - p[d][0][j], d28 = p[d][7][j] - p[d][1][j];
      const double d35 = p[d][4][j] - p[d][2][j], d46 = p[d][5][j] - p[d][3][j];
      f.u[d][j] = d17 + d28 - d35 - d46;
      f.v[d][j] = d17 + d28 + d35 + d46;
      f.w[d][j] = d17 - d28 - d35 + d46;
    }
    f.root[0][j] = f.u[0][j] * f.u[0][j] + f.u[1][j] * f.u[1][j] + f.u[2][j] * f.u[2][j];
    f.root[1][j] = f.v[0][j] * f.v[0][j] + f.v[1][j] * f.v[1][j] + f.v[2][j] * f.v[2][j];
    f.root[2][j] = f.w[0][j] * f.w[0][j] + f.w[1][j] * f.w[1][j] + f.w[2][j] * f.w[2][j];
  }
  roots(3);
  // Normalise with the roots just taken, then one symmetric step (all three from the previous values).
  for (int it = 0; it < 3; ++it) {
    RADX_IVDEP
    for (int j = 0; j < len; ++j) {
      const double ru = 1.0 / (f.root[0][j] != 0.0 ? f.root[0][j] : one);
      const double rv = 1.0 / (f.root[1][j] != 0.0 ? f.root[1][j] : one);
      const double rw = 1.0 / (f.root[2][j] != 0.0 ? f.root[2][j] : one);
      const double u[3] = {f.u[0][j] * ru, f.u[1][j] * ru, f.u[2][j] * ru};
      const double v[3] = {f.v[0][j] * rv, f.v[1][j] * rv, f.v[2][j] * rv};
      const double w[3] = {f.w[0][j] * rw, f.w[1][j] * rw, f.w[2][j] * rw};
      double a[3], b[3], c[3];
      cross3(v, w, a);
      cross3(w, u, b);
      cross3(u, v, c);
#pragma GCC unroll 3
      for (int d = 0; d < 3; ++d) {
        f.u[d][j] = a[d] + u[d];
        f.v[d][j] = b[d] + v[d];
        f.w[d][j] = c[d] + w[d];
      }
      f.root[0][j] = f.u[0][j] * f.u[0][j] + f.u[1][j] * f.u[1][j] + f.u[2][j] * f.u[2][j];
      f.root[1][j] = f.v[0][j] * f.v[0][j] + f.v[1][j] * f.v[1][j] + f.v[2][j] * f.v[2][j];
      f.root[2][j] = f.w[0][j] * f.w[0][j] + f.w[1][j] * f.w[1][j] + f.w[2][j] * f.w[2][j];
    }
    roots(3);
  }
  // e1 = u (normalised), e3 = e1 x v before its normalisation (kept in w).
  RADX_IVDEP
  for (int j = 0; j < len; ++j) {
    const double ru = 1.0 / (f.root[0][j] != 0.0 ? f.root[0][j] : one);
    const double rv = 1.0 / (f.root[1][j] != 0.0 ? f.root[1][j] : one);
    const double u[3] = {f.u[0][j] * ru, f.u[1][j] * ru, f.u[2][j] * ru};
    const double v[3] = {f.v[0][j] * rv, f.v[1][j] * rv, f.v[2][j] * rv};
    double e3[3];
    cross3(u, v, e3);
#pragma GCC unroll 3
    for (int d = 0; d < 3; ++d) {
      f.u[d][j] = u[d];
      f.w[d][j] = e3[d];
    }
    f.root[0][j] = e3[0] * e3[0] + e3[1] * e3[1] + e3[2] * e3[2];
  }
  roots(1);
  const int cu = heph_order ? 1 : 0, c2 = heph_order ? 2 : 1, c3 = heph_order ? 0 : 2;
  RADX_IVDEP
  for (int j = 0; j < len; ++j) {
    const double r3 = 1.0 / (f.root[0][j] != 0.0 ? f.root[0][j] : one);
    const double u[3] = {f.u[0][j], f.u[1][j], f.u[2][j]};
    const double e3[3] = {f.w[0][j] * r3, f.w[1][j] * r3, f.w[2][j] * r3};
    double e2[3];
    cross3(e3, u, e2);
#pragma GCC unroll 3
    for (int r = 0; r < 3; ++r) {
      f.R[r][cu][j] = u[r];
      f.R[r][c2][j] = e2[r];
      f.R[r][c3][j] = e3[r];
    }
  }
}

// Co-rotational strain rate (docs/theory/elements.md 3.6, sdefo3.F): D_aa = L_aa - dt1/2 (L^T L)_aa,
// D_ab = L_ab + L_ba - dt1 (L^T L)_ab (engineering shears), from the velocity gradient L in the frame.
inline void corotational_strain_rate(const double L[3][3], double dt1, double D[6]) {
  auto ltl = [&](int a, int e) { return L[0][a] * L[0][e] + L[1][a] * L[1][e] + L[2][a] * L[2][e]; };
  const double h = 0.5 * dt1;
  D[0] = L[0][0] - h * ltl(0, 0);
  D[1] = L[1][1] - h * ltl(1, 1);
  D[2] = L[2][2] - h * ltl(2, 2);
  D[3] = L[0][1] + L[1][0] - dt1 * ltl(0, 1);
  D[4] = L[1][2] + L[2][1] - dt1 * ltl(1, 2);
  D[5] = L[2][0] + L[0][2] - dt1 * ltl(2, 0);
}

// Half-step spin of the velocity gradient L[a][c] = dv_a/dx_c (docs/theory/elements.md 3.2):
// wx = dt1/2 (dvz/dy - dvy/dz), wy = dt1/2 (dvx/dz - dvz/dx), wz = dt1/2 (dvy/dx - dvx/dy).
inline void half_step_spin(const double L[3][3], double dt1, double& wx, double& wy, double& wz) {
  wz = 0.5 * dt1 * (L[1][0] - L[0][1]);
  wy = 0.5 * dt1 * (L[0][2] - L[2][0]);
  wx = 0.5 * dt1 * (L[2][1] - L[1][2]);
}

// First-order Jaumann rotation of the stored stress s (xx yy zz xy yz zx) into so, old values on the right
// (docs/theory/elements.md 3.2, srota3.F):
//   sxx += -2 sxy wz + 2 szx wy,  syy += 2 sxy wz - 2 syz wx,  szz += -2 szx wy + 2 syz wx,
//   sxy += wz (sxx - syy) + wy syz - wx szx,  syz += wx (syy - szz) + wz szx - wy sxy,
//   szx += wy (szz - sxx) + wx sxy - wz syz.
inline void jaumann_rotate(const double s[6], double wx, double wy, double wz, double so[6]) {
  so[0] = s[0] - 2.0 * s[3] * wz + 2.0 * s[5] * wy;
  so[1] = s[1] + 2.0 * s[3] * wz - 2.0 * s[4] * wx;
  so[2] = s[2] - 2.0 * s[5] * wy + 2.0 * s[4] * wx;
  so[3] = s[3] + wz * (s[0] - s[1]) + wy * s[4] - wx * s[5];
  so[4] = s[4] + wx * (s[1] - s[2]) + wz * s[5] - wy * s[3];
  so[5] = s[5] + wy * (s[2] - s[0]) + wx * s[3] - wz * s[4];
}

// Strain-rate measure of the Johnson-Cook rate term (docs/theory/elements.md 6.2), D with engineering shears:
//   e = sqrt(Dxx^2 + Dyy^2 + Dzz^2 + (D4^2 + D5^2 + D6^2) / 2); its square on its own for a block kernel
// that takes the roots in a pass of their own.
inline double strain_rate_measure2(const double D[6]) {
  return D[0] * D[0] + D[1] * D[1] + D[2] * D[2] + 0.5 * (D[3] * D[3] + D[4] * D[4] + D[5] * D[5]);
}
inline double strain_rate_measure(const double D[6]) {
  return std::sqrt(strain_rate_measure2(D));
}

// Its filter (docs/theory/elements.md 6.2): rate <- alpha e + (1 - alpha)
// rate, alpha = rate_filter_alpha(mat, dt1).
inline double filtered_rate(double alpha, double e_rate, double rate_old) {
  return alpha * e_rate + (1.0 - alpha) * rate_old;
}

// Density and volumetric strain of a solid (docs/theory/elements.md 3.2,
// srho3.F): rho = rho0 V0 / V, mu = rho/rho0 - 1.
inline double solid_density(double rho0, double vol0, double vol) {
  return rho0 * vol0 / vol;
}
inline double solid_mu(double rho, double rho0) {
  return rho / rho0 - 1.0;
}

// Compression rate of the bulk viscosity (docs/theory/elements.md 3.3): ec = max(0, -tr D).
inline double compression_rate(const double D[6]) {
  return std::max(0.0, -(D[0] + D[1] + D[2]));
}

// Bulk viscosity (docs/theory/elements.md 3.3, mqviscb.F), l = V^(1/3): q = rho ec l (qa^2 l ec + qb c).
inline double bulk_viscosity(double rho, double ec, double l, double qa2, double qb, double c) {
  return rho * ec * l * (qa2 * l * ec + qb * c);
}

// Brick characteristic length (docs/theory/elements.md 4.4, sdlen3.F): V / largest face area, a face's area
// |d13 x d24| / 2 (node positions from kBrickFaces). In two parts so that a block kernel can take the square
// root in a pass of its own: the largest |d13 x d24|^2, then the length from its root.
inline double brick_face_cross2_max(const double x[8][3]) {
  double area2_max = 0.0;
#pragma GCC unroll 8
  for (const auto& f : kBrickFaces) {
    double d13[3], d24[3];
#pragma GCC unroll 8
    for (int d = 0; d < 3; ++d) {
      d13[d] = x[f[2]][d] - x[f[0]][d];
      d24[d] = x[f[3]][d] - x[f[1]][d];
    }
    const double n0 = d13[1] * d24[2] - d13[2] * d24[1];
    const double n1 = d13[2] * d24[0] - d13[0] * d24[2];
    const double n2 = d13[0] * d24[1] - d13[1] * d24[0];
    area2_max = std::max(area2_max, n0 * n0 + n1 * n1 + n2 * n2);
  }
  return area2_max;
}
inline double brick_face_length_of_root(double vol, double cross_max) {
  return vol / (0.5 * cross_max);
}
inline double brick_face_length(const double x[8][3], double vol) {
  return brick_face_length_of_root(vol, std::sqrt(brick_face_cross2_max(x)));
}

// Element step of a solid before the /DT scale (docs/theory/elements.md 4.4, mqviscb.F): with qt = qb
// c + qa^2 l ec, c_eff = qt + sqrt(qt^2 + c^2) and dt = length / c_eff. In parts for a block kernel: qt, then
// the step from the root sqrt(qt^2 + c^2).
inline double solid_step_qt(double c, double qa2, double qb, double l, double ec) {
  return qb * c + qa2 * l * ec;
}
inline double solid_step_of_root(double length, double qt, double root) {
  return length / (qt + root);
}
inline double solid_step(double length, double c, double qa2, double qb, double l, double ec) {
  const double qt = solid_step_qt(c, qa2, qb, l, ec);
  return solid_step_of_root(length, qt, std::sqrt(qt * qt + c * c));
}

// Stress power sum of the energy trapezoid (docs/theory/elements.md 3.3): sum_m (sigma_old + sigma_new)_m
// D_m, engineering shears in D.
inline double stress_power_sum(const double so[6], const double sn[6], const double D[6]) {
  double work = 0.0;
#pragma GCC unroll 6
  for (int m = 0; m < 6; ++m) work += (so[m] + sn[m]) * D[m];
  return work;
}

// Internal energy increment of a one-point solid, total (docs/theory/elements.md 3.3, meint.F), with the
// bulk-viscosity work: dE = dt1/2 Vavg work - dV/2 (q_old + q_new), dV = V - V_old, Vavg = V - dV/2,
// work = stress_power_sum(...).
inline double solid_energy_increment(double dt1, double vol, double vol_old, double work, double q_old,
                                     double q_new) {
  const double dvol = vol - vol_old;
  const double vavg = vol - 0.5 * dvol;
  return 0.5 * dt1 * vavg * work - 0.5 * dvol * (q_old + q_new);
}

// Square of the von Mises stress (docs/theory/elements.md 6.5): 3/2 s_dev : s_dev with sm = tr(sigma)/3,
//   svm^2 = 1.5 ((sxx - sm)^2 + (syy - sm)^2 + (szz - sm)^2) + 3 (sxy^2 + syz^2 + szx^2).
inline double von_mises2(const double s[6]) {
  const double sm = (s[0] + s[1] + s[2]) / 3.0;
  return 1.5 * ((s[0] - sm) * (s[0] - sm) + (s[1] - sm) * (s[1] - sm) + (s[2] - sm) * (s[2] - sm)) +
         3.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]);
}

// Nodal stiffness of a solid (docs/theory/elements.md 4.5): k = share rho V / dt^2 for each node, share = 1/4
// for the bricks, 1/2 for the tetrahedron (s4cumu3.F).
inline double solid_nodal_stiffness(double share, double rho, double vol, double dt) {
  return share * rho * vol / (dt * dt);
}

}  // namespace radx::solver
