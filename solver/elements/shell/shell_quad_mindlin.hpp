// The bilinear four-node Mindlin plate in the element plane of the QBAT (Ishell 12, shell_qbat.cpp) and QEPH
// (Ishell 24, shell_qeph.cpp) kernels: the strain rows at one in-plane point (xi, eta), their transpose (the
// nodal forces of the resultants), and the element step length of OpenRadioss's cndt3.F/cncoef3.F. QBAT
// takes the rows point by point; QEPH evaluates the same rows in a projected form of its own (see there) for
// speed, and shares the Gauss points and the step length. Internal to the solver; not a public API.
//
// Equations (local frame of shell_frame.hpp, node k at (x_k, y_k), natural coordinates xi_k = (-1, 1, 1, -1),
// eta_k = (-1, -1, 1, 1); our own derivation of the standard isoparametric quadrilateral):
//   N_k,xi = xi_k (1 + eta_k eta)/4, N_k,eta = eta_k (1 + xi_k xi)/4; J = [[x,xi y,xi], [x,eta y,eta]];
//   N_k,x = (y,eta N_k,xi - y,xi N_k,eta)/det J, N_k,y = (x,xi N_k,eta - x,eta N_k,xi)/det J.
//   At the centre, A N_k,x = PX_k and A N_k,y = PY_k of docs/theory/elements.md 1.2 (A = 4 det J(0)): the
//   one-point rows of Ishell 1.
//   Membrane: exx = sum N_k,x vx_k, eyy = sum N_k,y vy_k, gxy = sum (N_k,y vx_k + N_k,x vy_k).
//   Curvature (Ishell 1's signs, 1.3): kxx = sum N_k,x ry_k, kyy = -sum N_k,y rx_k,
//   kxy = sum (N_k,y ry_k - N_k,x rx_k).
//   Transverse shear, assumed (covariant) strain tied at the edge midpoints (Bathe-Dvorkin MITC4, the
//   assumed shear field of Batoz's Q4gamma that QBAT and QEPH use [inferred from the tying-point structure
//   of cbadef.F and czdef.F]): with beta = (ry, -rx) (gxz = w,x + ry, gyz = w,y - rx as Ishell 1),
//   g_xi(A: eta = -1)  = (w2 - w1)/2 + (X2 - X1).(beta1 + beta2)/4,  g_xi(C: eta = +1) = the same on 4 -> 3,
//   g_eta(B: xi = -1)  = (w4 - w1)/2 + (X4 - X1).(beta1 + beta4)/4,  g_eta(D: xi = +1) = the same on 2 -> 3,
//   g_xi(xi, eta) = (1 - eta)/2 g_xi(A) + (1 + eta)/2 g_xi(C), g_eta = (1 - xi)/2 g_eta(B) + (1 + xi)/2
//   g_eta(D), and (gxz, gyz) = J^-1 (g_xi, g_eta). Exact (zero) for every rigid motion and for a constant
//   curvature field (w quadratic, rotations linear), so the patch tests hold on distorted meshes.
//   Nodal forces of the resultants (N, M, Q) at a point of weight W (virtual-power transpose of the rows):
//   f_k = W (Nxx N_k,x + Nxy N_k,y, Nxy N_k,x + Nyy N_k,y, Qx s_x,w_k + Qy s_y,w_k),
//   m_k = W (-(Myy N_k,y + Mxy N_k,x) + Qx s_x,rx_k + Qy s_y,rx_k, Mxx N_k,x + Mxy N_k,y + Qx s_x,ry_k
//   + Qy s_y,ry_k), s the rows of gzx (x) and gyz (y) on (w, rx, ry).
//   Step length (docs/theory/elements.md 1.10, read from cndt3.F and cncoef3.F, confirmed there by a run on a
//   square): L = A / sqrt(F (1.25 + Hs) D^2), D = half the longer diagonal, Hs = max(|c1|, |c2|)/A with c1,
//   c2 the 2-D cross products of opposite nodes' positions from the centroid, F = 2 F1 F2,
//   F1 = 1 + min(1/2, (max(r1, r2)/min(r1, r2) - 1)/4), F2 = 0.78 + 0.22 [3.413 max(0, 4A/(r1 r2) -
//   0.7071)]^3, r1 = |g1|, r2 = |g2| (the frame vectors of 1.2).
#pragma once

#include <algorithm>
#include <cmath>

namespace radx::solver::shell_detail {

inline constexpr double kXiNode[4] = {-1.0, 1.0, 1.0, -1.0};
inline constexpr double kEtaNode[4] = {-1.0, -1.0, 1.0, 1.0};
inline constexpr double kGauss = 0.577350269189625764509148780502;  // 1/sqrt(3)
inline constexpr double kXiGauss[4] = {-kGauss, kGauss, kGauss, -kGauss};
inline constexpr double kEtaGauss[4] = {-kGauss, -kGauss, kGauss, kGauss};

// Strain rows at one in-plane point of one element, and the point's det J (its weight per unit Gauss weight).
struct QuadRows {
  double nx[4], ny[4];            // N_k,x, N_k,y
  double sxw[4], sxr[4], sxs[4];  // gzx on w_k, rx_k, ry_k
  double syw[4], syr[4], sys[4];  // gyz on w_k, rx_k, ry_k
  double detj;
};

// Rows at (xi, eta) for local node coordinates lx, ly (node 1 at the origin). det J is floored at 1e-30 of
// the same sign rule as the area of Ishell 1 (a degenerate element gives finite rows).
inline QuadRows quad_rows(const double lx[4], const double ly[4], double xi, double eta) {
  QuadRows r{};
  double dxi[4], deta[4];
  double xx = 0, yx = 0, xe = 0, ye = 0;  // x,xi y,xi x,eta y,eta
  for (int k = 0; k < 4; ++k) {
    dxi[k] = 0.25 * kXiNode[k] * (1.0 + kEtaNode[k] * eta);
    deta[k] = 0.25 * kEtaNode[k] * (1.0 + kXiNode[k] * xi);
    xx += dxi[k] * lx[k], yx += dxi[k] * ly[k];
    xe += deta[k] * lx[k], ye += deta[k] * ly[k];
  }
  const double det = std::max(xx * ye - yx * xe, 1e-30);
  const double inv = 1.0 / det;
  r.detj = det;
  for (int k = 0; k < 4; ++k) {
    r.nx[k] = (ye * dxi[k] - yx * deta[k]) * inv;
    r.ny[k] = (xx * deta[k] - xe * dxi[k]) * inv;
  }
  // Covariant shear at the tying points, as rows on (w, beta_x, beta_y) of the nodes: edge (a -> b) gives
  // (w_b - w_a)/2 + (X_b - X_a).(beta_a + beta_b)/4.
  struct Edge {
    double w[4] = {}, bx[4] = {}, by[4] = {};
  };
  auto edge = [&](int a, int b) {
    Edge e;
    const double dx = 0.25 * (lx[b] - lx[a]), dy = 0.25 * (ly[b] - ly[a]);
    e.w[a] = -0.5, e.w[b] = 0.5;
    e.bx[a] = e.bx[b] = dx;
    e.by[a] = e.by[b] = dy;
    return e;
  };
  const Edge ea = edge(0, 1), ec = edge(3, 2), eb = edge(0, 3), ed = edge(1, 2);
  const double ca = 0.5 * (1.0 - eta), cc = 0.5 * (1.0 + eta), cb = 0.5 * (1.0 - xi), cd = 0.5 * (1.0 + xi);
  // J^-1 = [[y,eta, -y,xi], [-x,eta, x,xi]] / det J.
  const double i11 = ye * inv, i12 = -yx * inv, i21 = -xe * inv, i22 = xx * inv;
  for (int k = 0; k < 4; ++k) {
    const double gxw = ca * ea.w[k] + cc * ec.w[k], gew = cb * eb.w[k] + cd * ed.w[k];
    const double gxbx = ca * ea.bx[k] + cc * ec.bx[k], gebx = cb * eb.bx[k] + cd * ed.bx[k];
    const double gxby = ca * ea.by[k] + cc * ec.by[k], geby = cb * eb.by[k] + cd * ed.by[k];
    // beta_x = ry, beta_y = -rx.
    r.sxw[k] = i11 * gxw + i12 * gew;
    r.sxs[k] = i11 * gxbx + i12 * gebx;
    r.sxr[k] = -(i11 * gxby + i12 * geby);
    r.syw[k] = i21 * gxw + i22 * gew;
    r.sys[k] = i21 * gxbx + i22 * gebx;
    r.syr[k] = -(i21 * gxby + i22 * geby);
  }
  return r;
}

// Local rates at a point: membrane e[0..2] = exx eyy gxy, shears e[3] = gyz, e[4] = gzx (the order of the
// section, shell_section.hpp), curvatures k[0..2] = kxx kyy kxy.
inline void quad_rates(const QuadRows& r, const double vx[4], const double vy[4], const double vz[4],
                       const double rx[4], const double ry[4], double e[5], double kap[3]) {
  for (int c = 0; c < 5; ++c) e[c] = 0;
  for (int c = 0; c < 3; ++c) kap[c] = 0;
  for (int k = 0; k < 4; ++k) {
    e[0] += r.nx[k] * vx[k];
    e[1] += r.ny[k] * vy[k];
    e[2] += r.ny[k] * vx[k] + r.nx[k] * vy[k];
    e[3] += r.syw[k] * vz[k] + r.syr[k] * rx[k] + r.sys[k] * ry[k];
    e[4] += r.sxw[k] * vz[k] + r.sxr[k] * rx[k] + r.sxs[k] * ry[k];
    kap[0] += r.nx[k] * ry[k];
    kap[1] -= r.ny[k] * rx[k];
    kap[2] += r.ny[k] * ry[k] - r.nx[k] * rx[k];
  }
}

// Second-order (large-rotation) correction of the membrane rates at a point, docs/theory/elements.md 1.3
// generalised to the point's own slopes: exx -= dt1 (w,x)^2, eyy -= dt1 (w,y)^2 (what Ishell 1's correction
// amounts to on a rectangle). The rates use B(X^n) with v^{n-1/2}; without it an element turning out of its
// plane would be stretched by the update x + dt v and book that stretch as
// strain energy [inferred for QEPH and QBAT].
inline void quad_second_order(const QuadRows& r, const double vz[4], double dt1, double e[5]) {
  double gx = 0, gy = 0;
  for (int k = 0; k < 4; ++k) gx += r.nx[k] * vz[k], gy += r.ny[k] * vz[k];
  e[0] -= dt1 * gx * gx;
  e[1] -= dt1 * gy * gy;
}

// Adds the nodal forces of the resultants at a point, times its weight w (transpose of quad_rates):
// n = Nxx Nyy Nxy Qy Qx (force per length), m = Mxx Myy Mxy (moment per length).
inline void quad_add_forces(const QuadRows& r, double w, const double n[5], const double m[3], double fx[4],
                            double fy[4], double fz[4], double mx[4], double my[4]) {
  for (int k = 0; k < 4; ++k) {
    fx[k] += w * (n[0] * r.nx[k] + n[2] * r.ny[k]);
    fy[k] += w * (n[2] * r.nx[k] + n[1] * r.ny[k]);
    fz[k] += w * (n[4] * r.sxw[k] + n[3] * r.syw[k]);
    mx[k] += w * (-(m[1] * r.ny[k] + m[2] * r.nx[k]) + n[4] * r.sxr[k] + n[3] * r.syr[k]);
    my[k] += w * (m[0] * r.nx[k] + m[2] * r.ny[k] + n[4] * r.sxs[k] + n[3] * r.sys[k]);
  }
}

// Element step length of QEPH and QBAT (1.10), in the pieces a vectorised kernel needs around its square
// roots (shell_section.hpp, sqrt_in_place): the squares of r1 = |g1| and r2 = |g2|, then the argument of the
// last root from r1 and r2, L = A / sqrt(arg).
// The constants of the argument: a vectorised kernel passes them through opaque() (material_point.hpp),
// since GCC would turn min/max against a literal into a branch and keep the loop scalar.
struct StepConstants {
  double tiny30 = 1e-30, tiny60 = 1e-60;  // floors of the divisors and of arg
  double half = 0.5, zero = 0.0;
};

inline void qeph_step_axes_sq(const double lx[4], const double ly[4], double& r1_sq, double& r2_sq) {
  const double g1x = (lx[1] - lx[0]) + (lx[2] - lx[3]), g1y = (ly[1] - ly[0]) + (ly[2] - ly[3]);
  const double g2x = (lx[2] - lx[1]) + (lx[3] - lx[0]), g2y = (ly[2] - ly[1]) + (ly[3] - ly[0]);
  r1_sq = g1x * g1x + g1y * g1y;
  r2_sq = g2x * g2x + g2y * g2y;
}

inline double qeph_step_arg(const double lx[4], const double ly[4], double area, double r1, double r2,
                            const StepConstants& k = {}) {
  const double rmin = std::max(std::min(r1, r2), k.tiny30), rmax = std::max(r1, r2);
  const double f1 = 1.0 + std::min(k.half, 0.25 * (rmax / rmin - 1.0));
  const double s = 3.413 * std::max(k.zero, 4.0 * area / std::max(r1 * r2, k.tiny30) - 0.7071);
  const double f2 = 0.78 + 0.22 * s * s * s;
  const double cx = 0.25 * (lx[0] + lx[1] + lx[2] + lx[3]), cy = 0.25 * (ly[0] + ly[1] + ly[2] + ly[3]);
  double px[4], py[4];
  for (int n = 0; n < 4; ++n) px[n] = lx[n] - cx, py[n] = ly[n] - cy;
  const double c1 = px[0] * py[2] - py[0] * px[2], c2 = px[1] * py[3] - py[1] * px[3];
  const double hs = std::max(std::abs(c1), std::abs(c2)) / area;
  const double d13 = (lx[2] - lx[0]) * (lx[2] - lx[0]) + (ly[2] - ly[0]) * (ly[2] - ly[0]);
  const double d24 = (lx[3] - lx[1]) * (lx[3] - lx[1]) + (ly[3] - ly[1]) * (ly[3] - ly[1]);
  const double dd = 0.25 * std::max(d13, d24);  // D^2
  return std::max(2.0 * f1 * f2 * (1.25 + hs) * dd, k.tiny60);
}

// The step length L of one element from its local node coordinates and area.
inline double qeph_step_length(const double lx[4], const double ly[4], double area) {
  double r1_sq = 0, r2_sq = 0;
  qeph_step_axes_sq(lx, ly, r1_sq, r2_sq);
  return area / std::sqrt(qeph_step_arg(lx, ly, area, std::sqrt(r1_sq), std::sqrt(r2_sq)));
}

}  // namespace radx::solver::shell_detail
