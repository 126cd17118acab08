// The 20-node serendipity brick (/BRIC20): shape functions, Gauss rules and the geometry the starter and the
// engine share (the starter's node checks, masses and step estimate; the kernel hex20_quadratic.cpp).
//
// Nodes in Radioss's order (OpenRadioss hm_read_solid.F reads the 8 corners then the 12 mid-side nodes;
// s20mass3.F's IPERM1/IPERM2 give each mid-side node's edge): corners 1..4 one face, 5..8 above them
// (5 joined to 1), mid-side 9..12 on edges 1-2, 2-3, 3-4, 4-1, 13..16 on 1-5, 2-6, 3-7, 4-8 and 17..20 on
// 5-6, 6-7, 7-8, 8-5. Natural coordinates (xi, eta, zeta) as the 8-node brick's: corners (-1,-1,-1),
// (1,-1,-1), (1,1,-1), (-1,1,-1), then the same with zeta = +1; a mid-side node at the mean of its edge's
// corners. (OpenRadioss's s20rst.F uses other axes, r = eta, s = zeta, t = xi: a cyclic relabelling, same
// handedness, so the same element; see hex20_rule_of_inpts for what that means for Inpts.)
//
// Shape functions (serendipity, e.g. Zienkiewicz and Taylor, The Finite Element Method, vol. 1, 8.7):
//   corner a:          N_a = 1/8 (1 + xi xi_a)(1 + eta eta_a)(1 + zeta zeta_a)(xi xi_a + eta eta_a + zeta
//   zeta_a - 2) mid-side, xi_a = 0: N_a = 1/4 (1 - xi^2)(1 + eta eta_a)(1 + zeta zeta_a)   (likewise for
//   eta_a, zeta_a = 0)
// sum_a N_a = 1 and sum_a x_a N_a reproduces any quadratic-complete field of the serendipity space, so a
// linear displacement field gives a constant strain (the patch test).
// Gauss-Legendre rules with n = 1, 2, 3 points per direction: points 0 | -+1/sqrt(3) | 0, -+sqrt(3/5),
// weights 2 | 1, 1 | 5/9, 8/9, 5/9.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include "solver/model/geometry.hpp"

namespace radx::model {

inline constexpr int kHex20Nodes = 20;

// Natural coordinates of the 20 nodes (position 0..19 = deck nodes 1..20).
inline constexpr int kHex20Nat[20][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1},  {-1, 1, -1}, {-1, -1, 1},
                                         {1, -1, 1},   {1, 1, 1},   {-1, 1, 1},  {0, -1, -1}, {1, 0, -1},
                                         {0, 1, -1},   {-1, 0, -1}, {-1, -1, 0}, {1, -1, 0},  {1, 1, 0},
                                         {-1, 1, 0},   {0, -1, 1},  {1, 0, 1},   {0, 1, 1},   {-1, 0, 1}};

// The two corners (positions) of each mid-side node's edge, mid-side position 8 + m.
inline constexpr int kHex20Edge[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 5},
                                          {2, 6}, {3, 7}, {4, 5}, {5, 6}, {6, 7}, {7, 4}};

// Shape functions N[a] and their natural derivatives dN[a][c] = dN_a / dxi_c at (xi, eta, zeta).
inline void hex20_shape(double xi, double eta, double zeta, double N[20], double dN[20][3]) {
  const double p[3] = {xi, eta, zeta};
  for (int a = 0; a < 20; ++a) {
    const double s[3] = {static_cast<double>(kHex20Nat[a][0]), static_cast<double>(kHex20Nat[a][1]),
                         static_cast<double>(kHex20Nat[a][2])};
    if (a < 8) {
      const double f[3] = {1 + p[0] * s[0], 1 + p[1] * s[1], 1 + p[2] * s[2]};
      const double g = p[0] * s[0] + p[1] * s[1] + p[2] * s[2] - 2.0;
      N[a] = 0.125 * f[0] * f[1] * f[2] * g;
      // d/dp_c: 1/8 s_c [prod_{d != c} f_d] (g + f_c)
      dN[a][0] = 0.125 * s[0] * f[1] * f[2] * (g + f[0]);
      dN[a][1] = 0.125 * s[1] * f[0] * f[2] * (g + f[1]);
      dN[a][2] = 0.125 * s[2] * f[0] * f[1] * (g + f[2]);
    } else {
      // The direction c0 along which the node sits mid-edge (s = 0), the other two d1, d2.
      const int c0 = s[0] == 0 ? 0 : (s[1] == 0 ? 1 : 2);
      const int d1 = (c0 + 1) % 3, d2 = (c0 + 2) % 3;
      const double q = 1 - p[c0] * p[c0];
      const double f1 = 1 + p[d1] * s[d1], f2 = 1 + p[d2] * s[d2];
      N[a] = 0.25 * q * f1 * f2;
      dN[a][c0] = -0.5 * p[c0] * f1 * f2;
      dN[a][d1] = 0.25 * q * s[d1] * f2;
      dN[a][d2] = 0.25 * q * f1 * s[d2];
    }
  }
}

// Gauss-Legendre points and weights with n = 1, 2 or 3 points on [-1, 1].
inline double gauss_point(int n, int k) {
  switch (n) {
    case 1: return 0.0;
    case 2: return (k == 0 ? -1.0 : 1.0) / std::sqrt(3.0);
    default: return k == 1 ? 0.0 : (k == 0 ? -1.0 : 1.0) * std::sqrt(0.6);
  }
}
inline double gauss_weight(int n, int k) {
  switch (n) {
    case 1: return 2.0;
    case 2: return 1.0;
    default: return k == 1 ? 8.0 / 9.0 : 5.0 / 9.0;
  }
}

// A product Gauss rule: n[c] points along xi, eta, zeta. Point p = i + n0 (j + n1 k).
struct Hex20Rule {
  std::array<int, 3> n{2, 2, 2};
  [[nodiscard]] int points() const { return n[0] * n[1] * n[2]; }
  // Natural coordinates and weight of point p.
  void point(int p, double xi[3], double& w) const {
    const int idx[3] = {p % n[0], (p / n[0]) % n[1], p / (n[0] * n[1])};
    w = 1.0;
    for (int c = 0; c < 3; ++c) {
      xi[c] = gauss_point(n[c], idx[c]);
      w *= gauss_weight(n[c], idx[c]);
    }
  }
};

// The rule of a /PROP/SOLID Inpts digit triple "abc" on a 20-node brick, as OpenRadioss assigns the digits:
// Isolid 16 (elbuf_ini.F) a = NPTR, b = NPTS, c = NPTT on its axes r, s, t; Isolid 14 a = NPTS, b = NPTT,
// c = NPTR. With r = eta, s = zeta, t = xi here: Isolid 16 gives n = (c, a, b), Isolid 14 n = (b, c, a).
// Inpts 0 is 222.
inline Hex20Rule hex20_rule_of_inpts(int inpts, int isolid) {
  if (inpts == 0) inpts = 222;
  const int a = inpts / 100, b = (inpts / 10) % 10, c = inpts % 10;
  Hex20Rule r;
  r.n = isolid == 14 ? std::array<int, 3>{b, c, a} : std::array<int, 3>{c, a, b};
  return r;
}

// Jacobian J[a][c] = dx_a / dxi_c of nodes x at natural derivatives dN; returns det J.
inline double hex20_jacobian(const double x[20][3], const double dN[20][3], double J[3][3]) {
  for (int a = 0; a < 3; ++a)
    for (int c = 0; c < 3; ++c) {
      double s = 0;
      for (int k = 0; k < 20; ++k) s += x[k][a] * dN[k][c];
      J[a][c] = s;
    }
  return J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) -
         J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
         J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
}

// Volume sum_p w_p det J_p of the rule, and the smallest det J_p (<= 0: inverted or degenerate at a point).
inline double hex20_volume(const double x[20][3], const Hex20Rule& rule, double* det_min = nullptr) {
  double v = 0, dmin = 0;
  for (int p = 0; p < rule.points(); ++p) {
    double xi[3], w, N[20], dN[20][3], J[3][3];
    rule.point(p, xi, w);
    hex20_shape(xi[0], xi[1], xi[2], N, dN);
    const double d = hex20_jacobian(x, dN, J);
    dmin = p == 0 ? d : std::min(dmin, d);
    v += w * d;
  }
  if (det_min) *det_min = dmin;
  return v;
}

// Characteristic length of the element's step, OpenRadioss's for the 20-node brick (s20forc3.F with
// s20deri3.F): U_a = sum_p V_p |grad N_a(p)|^2 over the rule's points (V_p = w_p det J_p), then
//   l = sqrt(2 V / max(64 max_corners U_a, 96/7 max_mid-sides U_a)),
// the factors 64 and 96/7 being the inverse mass shares 1/64 (corners) and 7/96 (mid-side nodes) of the
// lumped mass (hex20_mass_share). 0 when a point's det J <= 0. `ul` optional: the U_a.
inline double hex20_length(const double x[20][3], const Hex20Rule& rule) {
  double U[20] = {}, vol = 0;
  for (int p = 0; p < rule.points(); ++p) {
    double xi[3], w, N[20], dN[20][3], J[3][3];
    rule.point(p, xi, w);
    hex20_shape(xi[0], xi[1], xi[2], N, dN);
    const double d = hex20_jacobian(x, dN, J);
    if (!(d > 0)) return 0.0;
    // Inverse Jacobian (transpose of cofactors / det): b_a = J^-T dN_a.
    const double inv[3][3] = {
        {(J[1][1] * J[2][2] - J[1][2] * J[2][1]) / d, (J[0][2] * J[2][1] - J[0][1] * J[2][2]) / d,
         (J[0][1] * J[1][2] - J[0][2] * J[1][1]) / d},
        {(J[1][2] * J[2][0] - J[1][0] * J[2][2]) / d, (J[0][0] * J[2][2] - J[0][2] * J[2][0]) / d,
         (J[0][2] * J[1][0] - J[0][0] * J[1][2]) / d},
        {(J[1][0] * J[2][1] - J[1][1] * J[2][0]) / d, (J[0][1] * J[2][0] - J[0][0] * J[2][1]) / d,
         (J[0][0] * J[1][1] - J[0][1] * J[1][0]) / d}};
    const double vp = w * d;
    vol += vp;
    for (int a = 0; a < 20; ++a) {
      double g2 = 0;
      for (int e = 0; e < 3; ++e) {
        const double g = dN[a][0] * inv[0][e] + dN[a][1] * inv[1][e] + dN[a][2] * inv[2][e];
        g2 += g * g;
      }
      U[a] += vp * g2;
    }
  }
  double uc = 0, um = 0;
  for (int a = 0; a < 8; ++a) uc = std::max(uc, U[a]);
  for (int a = 8; a < 20; ++a) um = std::max(um, U[a]);
  const double den = std::max(64.0 * uc, 96.0 / 7.0 * um);
  return den > 0 ? std::sqrt(2.0 * vol / den) : 0.0;
}

// Lumped mass share of node position a (OpenRadioss starter s20mass3.F): with f = 3/14, a corner takes
// f / (8 f + 12) = 1/64 of the element's mass rho V, a mid-side node 1 / (8 f + 12) = 7/96; 8/64 + 12 * 7/96
// = 1. (Row-sum lumping would give the corners negative masses; this is a positive diagonal.)
inline constexpr double hex20_mass_share(int a) {
  return a < 8 ? 1.0 / 64.0 : 7.0 / 96.0;
}

// The rule the starter's volume, mass and step estimate use: 3 x 3 x 3 integrates the volume of an element
// with straight edges exactly and that of a curved one closely.
inline Hex20Rule hex20_starter_rule() {
  Hex20Rule r;
  r.n = {3, 3, 3};
  return r;
}

}  // namespace radx::model
