// Eight-node fully integrated bricks: Isolid 14 (HA8), 17 (H8C), 18 (H8D, run as 17 with automatic flags) and
// 12 (the older S8). One kernel: the four differ only in the flags the engine gives the group (frame,
// pressure treatment, assumed shear), see BrickGroup and resolve_full_brick in explicit_engine.cpp.
//
// Sources, OpenRadioss (read, not copied): engine/source/elements/forint.F (Isolid 14 -> S8ZFORC3, 17 and
// 18 -> S8EFORC3 in explicit, 12 -> S8FORC3 when the group has 8 points), solide8/s8deri3.F, s8defo3.F,
// s8fint3.F, basisf.F (Gauss points +-1/sqrt(3), per-point derivatives from the inverse Jacobian, per-point
// forces weighted by the point volume), solide8/s8lagr3.F (density per element), solide8z/s8zdefo3.F
// (constant-pressure option, spin set to zero in the co-rotational frame), solide/srepiso3.F and sortho3.F
// (the co-rotational frame from the three centre directions, orthonormalised), starter hm_read_prop14.F and
// sgrtails.F (defaults). Section numbers refer to shared/spec/elements.md.
//
// Nodes and natural coordinates as hex8_fb.cpp: (xi, eta, zeta)_k = (-1,-1,-1), (1,-1,-1), (1,1,-1),
// (-1,1,-1), then the same with zeta = +1. Points p = 0..7 at (xi, eta, zeta)_p = a (xi, eta, zeta)_k,
// a = 1/sqrt(3), weight 1 each. All on x^n with v^{n-1/2}.
//
//   frame (corot): g_xi = dx/dxi(0), g_eta, g_zeta at the centre; Q = [g/|g|] made orthogonal by the
//     iteration Q <- (Q + Q^-T)/2 (the rotation of its polar decomposition, symmetric in the three
//     directions), then e1 = q1, e3 = e1 x q2 / |.|, e2 = e3 x e1; R = rows e1 e2 e3. x_loc = R x, v_loc = R
//     v. Without corot (Iframe 1 for 12 and 17) R = I and the stress gets the Jaumann rotation of 3.2 per
//     point.
//   per point: J_p = sum_k x_k (x) dN_k/dxi(p), V_p = det J_p, b_pk = J_p^-T dN_k/dxi(p),
//     L_p = sum_k v_k (x) b_pk, D_p = sym L_p (engineering shears), V = sum_p V_p (exact trilinear volume)
//   assumed shear (shear_avg, Isolid 14, inferred): in the local frame the shear of point p is replaced by
//   its
//     volume-weighted mean over the four points that share p's third coordinate: gxy over equal zeta, gyz
//     over equal xi, gzx over equal eta. Bending in a plane then gives no parasitic shear (the part linear in
//     the in-plane coordinates averages out) while the twist modes keep their stiffness (no hourglass mode);
//     a linear field is untouched (patch test). The work-conjugate force replaces the shear stress of each
//     point by the same mean: f = sum_p V_p B_p^T sigma~_p.
//   volumetric strain for the material (LAW1/LAW2 take the pressure from mu only, the deviator from de):
//     per-point pressure (icpre 0): mu_p = V0_p / V_p - 1;
//     constant pressure (icpre 1, 2 and Isolid 12's per-element density): mu = V0 / V - 1 with V0 = sum V0_p,
//     the same at every point, so the volumetric part is under-integrated and does not lock at nu -> 1/2.
//   material: solid_point_update(de_p = D_p dt1, mu_p) per point, rate from the element-mean D (6.2)
//   bulk viscosity (3.3) per element from the mean tr D: q = rho ec l (qa^2 l ec + qb c), l = V^(1/3)
//   internal energy: dE = sum_p dt1/2 V_p,avg (sigma_old + sigma_new)_p : D_p - dV/2 (q_old + q_new),
//     V_p,avg = V_p (V - dV/2) / V; no hourglass energy (none is needed)
//   forces: f_k = -R^T sum_p V_p (sigma~_p - q I) b_pk
//   element step (4.4 applied to these elements, inferred): dx = V / max face area, dt = dx / c_eff,
//     c_eff = qt + sqrt(qt^2 + c^2), qt = qb c + qa^2 l ec; nodal stiffness k = rho V / (4 dt^2) (4.5)
//   output: g.sig = the volume-weighted point mean in global axes, g.eps_p = the point mean, g.rho = rho0
//   V0/V
//
// An element with a point volume V_p <= 0 (inverted, or not a number) gets zero force, dt = 0, k = 0, keeps
// its state and stores the bad volume in `vol`: the engine reports it and stops. Degenerate bricks (repeated
// nodes: the collapsed-edge pentahedra of /BRICK) keep V_p > 0 at the interior Gauss points.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "solver/element_gather.hpp"
#include "solver/element_groups.hpp"

namespace radx::solver {

namespace {

constexpr int kNat[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                            {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};

constexpr int kFaces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                              {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};

// Points sharing a natural coordinate, for the assumed shear: kSet[c][p] = 0 or 1 is the side of point p
// along natural direction c (0 xi, 1 eta, 2 zeta).
constexpr int side(int p, int c) {
  return kNat[p][c] > 0 ? 1 : 0;
}

// dN_k/dxi_c at point p (a = 1/sqrt(3)).
struct ShapeDerivs {
  double d[8][8][3];
};

ShapeDerivs make_derivs() {
  ShapeDerivs s{};
  const double a = 1.0 / std::sqrt(3.0);
  for (int p = 0; p < 8; ++p) {
    const double xi = a * kNat[p][0], eta = a * kNat[p][1], zeta = a * kNat[p][2];
    for (int k = 0; k < 8; ++k) {
      const double xk = kNat[k][0], ek = kNat[k][1], zk = kNat[k][2];
      s.d[p][k][0] = 0.125 * xk * (1 + ek * eta) * (1 + zk * zeta);
      s.d[p][k][1] = 0.125 * ek * (1 + xk * xi) * (1 + zk * zeta);
      s.d[p][k][2] = 0.125 * zk * (1 + xk * xi) * (1 + ek * eta);
    }
  }
  return s;
}

const ShapeDerivs& derivs() {
  static const ShapeDerivs s = make_derivs();  // constant table, built once
  return s;
}

inline void cross(const double a[3], const double b[3], double c[3]) {
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

inline double dot3(const double a[3], const double b[3]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// Inverse of a 3x3 matrix m with determinant det (not zero).
inline void inverse3(const double m[3][3], double det, double inv[3][3]) {
  const double id = 1.0 / det;
  inv[0][0] = (m[1][1] * m[2][2] - m[1][2] * m[2][1]) * id;
  inv[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) * id;
  inv[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) * id;
  inv[1][0] = (m[1][2] * m[2][0] - m[1][0] * m[2][2]) * id;
  inv[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) * id;
  inv[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) * id;
  inv[2][0] = (m[1][0] * m[2][1] - m[1][1] * m[2][0]) * id;
  inv[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) * id;
  inv[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) * id;
}

inline double det3(const double m[3][3]) {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
         m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

// Co-rotational frame R (rows e1 e2 e3) from the centre directions of the element.
void corot_frame(const double x[8][3], double R[3][3]) {
  double q[3][3];  // columns: unit centre directions along xi, eta, zeta
  for (int c = 0; c < 3; ++c) {
    double g[3] = {0, 0, 0};
    for (int k = 0; k < 8; ++k)
      for (int d = 0; d < 3; ++d) g[d] += 0.125 * kNat[k][c] * x[k][d];
    const double n = std::sqrt(dot3(g, g));
    for (int d = 0; d < 3; ++d) q[d][c] = n > 0 ? g[d] / n : (d == c ? 1.0 : 0.0);
  }
  // Polar rotation by the averaging iteration: converges quadratically from a nearly orthogonal start.
  for (int it = 0; it < 4; ++it) {
    const double det = det3(q);
    if (!(std::abs(det) > 1e-12)) break;
    double inv[3][3];
    inverse3(q, det, inv);
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) q[a][b] = 0.5 * (q[a][b] + inv[b][a]);
  }
  double e1[3] = {q[0][0], q[1][0], q[2][0]}, q2[3] = {q[0][1], q[1][1], q[2][1]}, e2[3], e3[3];
  double n = std::sqrt(dot3(e1, e1));
  for (double& v : e1) v /= n;
  cross(e1, q2, e3);
  n = std::sqrt(dot3(e3, e3));
  for (double& v : e3) v /= n;
  cross(e3, e1, e2);
  for (int d = 0; d < 3; ++d) {
    R[0][d] = e1[d];
    R[1][d] = e2[d];
    R[2][d] = e3[d];
  }
}

// Point volumes V_p = det J_p and gradients b_pk of the geometry x. Returns false when a V_p <= 0 (or NaN);
// vp then holds the point volumes computed so far.
bool point_gradients(const double x[8][3], double vp[8], double b[8][8][3]) {
  const auto& s = derivs();
  for (int p = 0; p < 8; ++p) {
    double J[3][3] = {};  // J[a][c] = dx_a / dxi_c
    for (int k = 0; k < 8; ++k)
      for (int a = 0; a < 3; ++a)
        for (int c = 0; c < 3; ++c) J[a][c] += x[k][a] * s.d[p][k][c];
    const double det = det3(J);
    vp[p] = det;
    if (!(det > 0.0)) return false;
    double inv[3][3];  // inv[c][a] = dxi_c / dx_a
    inverse3(J, det, inv);
    for (int k = 0; k < 8; ++k)
      for (int a = 0; a < 3; ++a)
        b[p][k][a] = s.d[p][k][0] * inv[0][a] + s.d[p][k][1] * inv[1][a] + s.d[p][k][2] * inv[2][a];
  }
  return true;
}

}  // namespace

void resolve_full_brick(const model::SolidProperty& prop, const MaterialParams& mat, BrickGroup& g) {
  const int isolid = prop.isolid;
  if (isolid != 12 && isolid != 14 && isolid != 17 && isolid != 18) return;
  g.n_points = 8;
  g.allocate_points();
  const int asked = prop.icpre == 3 ? -3 : prop.icpre;  // 3: explicitly off
  switch (isolid) {
    case 14:  // HA8: co-rotational imposed, Icpre as given (default 0), assumed shear
      g.corot = true;
      g.icpre = asked > 0 ? asked : 0;
      g.shear_avg = true;
      break;
    case 17:  // H8C: the deck's frame, Icpre 0 -> 1 (constant pressure), 3 -> 0
      g.corot = prop.iframe == 2;
      g.icpre = asked == 0 ? 1 : (asked > 0 ? asked : 0);
      break;
    case 18:  // H8D: runs as 17, co-rotational, Icpre chosen by the law unless given
      g.corot = true;
      if (asked != 0) {
        g.icpre = asked > 0 ? asked : 0;
      } else if (mat.law == model::MaterialLaw::Elastic) {
        g.icpre = mat.nu >= 0.49 ? 1 : 0;
      } else {
        g.icpre = 2;
      }
      break;
    default:  // 12: the deck's frame; density per element, so the pressure is constant over the element
      g.corot = prop.iframe == 2;
      g.icpre = 1;
      break;
  }
}

void hex8_full_point_volumes(const double x[8][3], double vp[8]) {
  double b[8][8][3];
  point_gradients(x, vp, b);
}

void hex8_full_forces(BrickGroup& g, const NodeState& nodes, const MaterialParams& mat,
                      const CycleInfo& cyc) {
  constexpr std::size_t G = kGroupSize;
  constexpr std::size_t NP = 8;
  const double dt1 = cyc.dt1;
  const double c = mat.c_solid;
  const double rho0 = mat.rho0;
  const double qa2 = g.qa * g.qa;
  const double qb = g.qb;
  const bool const_p = g.icpre != 0;
  const double alpha = mat.f_cut > 0 ? std::min(1.0, 2.0 * std::numbers::pi * mat.f_cut * dt1) : 1.0;
  const double inf = std::numeric_limits<double>::infinity();

  const std::int32_t* conn = g.conn.data();
  double* force = g.nodal_force.data();
  auto sp = [&](std::size_t p, std::size_t m, std::size_t i) -> double& {
    return g.sig_p[(p * 6 + m) * G + i];
  };

  const auto n = static_cast<std::size_t>(g.count);
  for (std::size_t i = 0; i < n; ++i) {
    const double off = g.off[i];
    if (off == 0.0) {
      clear_nodal_forces<8, 3>(force, G, i);
      g.dt[i] = inf;
      g.k_nodal[i] = 0.0;
      continue;
    }
    double xg[8][3], vg[8][3];
    gather_element<8>(conn, G, i, nodes, xg, vg);
    if (g.dt_fixed[i] > 0.0 && !g.small[i]) {  // /DT/BRICK/CST: freeze the geometry once (as hex8_fb.cpp)
      for (std::size_t k = 0; k < 8; ++k)
        for (std::size_t d = 0; d < 3; ++d) g.x_ref[(k * 3 + d) * G + i] = xg[k][d];
      g.small[i] = 1;
    }
    if (g.small[i]) {
      for (std::size_t k = 0; k < 8; ++k)
        for (std::size_t d = 0; d < 3; ++d) xg[k][d] = g.x_ref[(k * 3 + d) * G + i];
    }

    // Frame and local coordinates.
    double R[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    if (g.corot) corot_frame(xg, R);
    double x[8][3], v[8][3];
    for (int k = 0; k < 8; ++k)
      for (int a = 0; a < 3; ++a) {
        x[k][a] = R[a][0] * xg[k][0] + R[a][1] * xg[k][1] + R[a][2] * xg[k][2];
        v[k][a] = R[a][0] * vg[k][0] + R[a][1] * vg[k][1] + R[a][2] * vg[k][2];
      }

    double vp[NP], b[NP][8][3];
    if (!point_gradients(x, vp, b)) {
      clear_nodal_forces<8, 3>(force, G, i);
      double bad = 0;
      for (std::size_t p = 0; p < NP; ++p) bad = std::min(bad, vp[p]);
      g.vol[i] = std::isnan(bad) ? bad : std::min(bad, 0.0);
      g.dt[i] = 0.0;
      g.k_nodal[i] = 0.0;
      continue;
    }
    double vol = 0, vol0 = 0;
    for (std::size_t p = 0; p < NP; ++p) {
      vol += vp[p];
      vol0 += g.vol0_p[p * G + i];
    }

    // Strain rates per point, the element mean.
    double D[NP][6], W[NP][3], Dm[6] = {0, 0, 0, 0, 0, 0};
    for (std::size_t p = 0; p < NP; ++p) {
      double L[3][3] = {};
      for (int k = 0; k < 8; ++k)
        for (int a = 0; a < 3; ++a)
          for (int e = 0; e < 3; ++e) L[a][e] += v[k][a] * b[p][k][e];
      D[p][0] = L[0][0];
      D[p][1] = L[1][1];
      D[p][2] = L[2][2];
      D[p][3] = L[0][1] + L[1][0];
      D[p][4] = L[1][2] + L[2][1];
      D[p][5] = L[2][0] + L[0][2];
      W[p][0] = 0.5 * dt1 * (L[2][1] - L[1][2]);  // wx
      W[p][1] = 0.5 * dt1 * (L[0][2] - L[2][0]);  // wy
      W[p][2] = 0.5 * dt1 * (L[1][0] - L[0][1]);  // wz
    }
    // Assumed shear: gxy (3) over equal zeta (c = 2), gyz (4) over equal xi (c = 0), gzx (5) over equal eta.
    constexpr int kShearDir[3] = {2, 0, 1};
    if (g.shear_avg) {
      for (int m = 0; m < 3; ++m) {
        const int cdir = kShearDir[m];
        double sum[2] = {0, 0}, vs[2] = {0, 0};
        for (int p = 0; p < 8; ++p) {
          sum[side(p, cdir)] += vp[p] * D[p][3 + m];
          vs[side(p, cdir)] += vp[p];
        }
        for (int p = 0; p < 8; ++p) D[p][3 + m] = sum[side(p, cdir)] / vs[side(p, cdir)];
      }
    }
    for (std::size_t p = 0; p < NP; ++p)
      for (int m = 0; m < 6; ++m) Dm[m] += vp[p] * D[p][m] / vol;

    // Material per point.
    const double rho = rho0 * vol0 / vol;
    const double mu_el = vol0 / vol - 1.0;
    const double e_rate = std::sqrt(Dm[0] * Dm[0] + Dm[1] * Dm[1] + Dm[2] * Dm[2] +
                                    0.5 * (Dm[3] * Dm[3] + Dm[4] * Dm[4] + Dm[5] * Dm[5]));
    const double rate = alpha * e_rate + (1.0 - alpha) * g.rate[i];
    const double dvol = vol - g.vol[i];
    const double vavg_ratio = (vol - 0.5 * dvol) / vol;
    double sn[NP][6];
    double work = 0, w_pl = 0, eps_mean = 0;
    for (std::size_t p = 0; p < NP; ++p) {
      double so[6];
      for (std::size_t m = 0; m < 6; ++m) so[m] = sp(p, m, i);
      if (!g.corot) {  // Jaumann rotation of the point's stress (3.2), old values on the right
        const double wx = W[p][0], wy = W[p][1], wz = W[p][2];
        const double s0[6] = {so[0], so[1], so[2], so[3], so[4], so[5]};
        so[0] = s0[0] - 2.0 * s0[3] * wz + 2.0 * s0[5] * wy;
        so[1] = s0[1] + 2.0 * s0[3] * wz - 2.0 * s0[4] * wx;
        so[2] = s0[2] - 2.0 * s0[5] * wy + 2.0 * s0[4] * wx;
        so[3] = s0[3] + wz * (s0[0] - s0[1]) + wy * s0[4] - wx * s0[5];
        so[4] = s0[4] + wx * (s0[1] - s0[2]) + wz * s0[5] - wy * s0[3];
        so[5] = s0[5] + wy * (s0[2] - s0[0]) + wx * s0[3] - wz * s0[4];
      }
      const double mu = const_p ? mu_el : g.vol0_p[p * G + i] / vp[p] - 1.0;
      const double de[6] = {D[p][0] * dt1, D[p][1] * dt1, D[p][2] * dt1,
                            D[p][3] * dt1, D[p][4] * dt1, D[p][5] * dt1};
      for (std::size_t m = 0; m < 6; ++m) sn[p][m] = so[m];
      double& ep = g.eps_p_p[p * G + i];
      const double deps_p = solid_point_update(mat, rate, de, mu, sn[p], ep);
      eps_mean += ep / 8.0;
      double wp = 0;
      for (std::size_t m = 0; m < 6; ++m) wp += (so[m] + sn[p][m]) * D[p][m];
      work += 0.5 * dt1 * vp[p] * vavg_ratio * wp;
      const double sm = (sn[p][0] + sn[p][1] + sn[p][2]) / 3.0;
      const double svm =
          std::sqrt(1.5 * ((sn[p][0] - sm) * (sn[p][0] - sm) + (sn[p][1] - sm) * (sn[p][1] - sm) +
                           (sn[p][2] - sm) * (sn[p][2] - sm)) +
                    3.0 * (sn[p][3] * sn[p][3] + sn[p][4] * sn[p][4] + sn[p][5] * sn[p][5]));
      w_pl += svm * deps_p * vp[p];
    }

    // Bulk viscosity and step.
    const double l = std::cbrt(vol);
    const double ec = std::max(0.0, -(Dm[0] + Dm[1] + Dm[2]));
    const double q_new = rho * ec * l * (qa2 * l * ec + qb * c);
    double area_max = 0.0;
    for (const auto& f : kFaces) {
      double d13[3], d24[3], nf[3];
      for (int d = 0; d < 3; ++d) {
        d13[d] = x[f[2]][d] - x[f[0]][d];
        d24[d] = x[f[3]][d] - x[f[1]][d];
      }
      cross(d13, d24, nf);
      area_max = std::max(area_max, dot3(nf, nf));
    }
    area_max = 0.5 * std::sqrt(area_max);
    const double qt = qb * c + qa2 * l * ec;
    const double dt_e = (vol / area_max) / (qt + std::sqrt(qt * qt + c * c));
    const double de_int = work - 0.5 * dvol * (g.q[i] + q_new);

    // Stresses of the force integral: the assumed shear takes each point's shear stress as its set's mean.
    double st[NP][6];
    for (std::size_t p = 0; p < NP; ++p)
      for (int m = 0; m < 6; ++m) st[p][m] = sn[p][m];
    if (g.shear_avg) {
      for (int m = 0; m < 3; ++m) {
        const int cdir = kShearDir[m];
        double sum[2] = {0, 0}, vs[2] = {0, 0};
        for (int p = 0; p < 8; ++p) {
          sum[side(p, cdir)] += vp[p] * sn[p][3 + m];
          vs[side(p, cdir)] += vp[p];
        }
        for (int p = 0; p < 8; ++p) st[p][3 + m] = sum[side(p, cdir)] / vs[side(p, cdir)];
      }
    }
    double fl[8][3] = {};
    double smean[6] = {0, 0, 0, 0, 0, 0};
    for (std::size_t p = 0; p < NP; ++p) {
      const double s[3][3] = {{st[p][0] - q_new, st[p][3], st[p][5]},
                              {st[p][3], st[p][1] - q_new, st[p][4]},
                              {st[p][5], st[p][4], st[p][2] - q_new}};
      for (int k = 0; k < 8; ++k)
        for (int a = 0; a < 3; ++a)
          fl[k][a] -= vp[p] * (s[a][0] * b[p][k][0] + s[a][1] * b[p][k][1] + s[a][2] * b[p][k][2]);
      for (int m = 0; m < 6; ++m) smean[m] += vp[p] * sn[p][m] / vol;
    }
    double f[8][3];
    for (int k = 0; k < 8; ++k)
      for (int a = 0; a < 3; ++a) f[k][a] = R[0][a] * fl[k][0] + R[1][a] * fl[k][1] + R[2][a] * fl[k][2];
    store_nodal_forces<8, 3>(force, G, i, off, f);

    // Element output: the mean stress in global axes, sigma_g = R^T sigma_loc R.
    const double S[3][3] = {
        {smean[0], smean[3], smean[5]}, {smean[3], smean[1], smean[4]}, {smean[5], smean[4], smean[2]}};
    double T[3][3] = {};
    for (int a = 0; a < 3; ++a)
      for (int e = 0; e < 3; ++e)
        for (int r = 0; r < 3; ++r)
          for (int t = 0; t < 3; ++t) T[a][e] += R[r][a] * S[r][t] * R[t][e];
    const double out[6] = {T[0][0], T[1][1], T[2][2], T[0][1], T[1][2], T[2][0]};
    for (std::size_t p = 0; p < NP; ++p)
      for (std::size_t m = 0; m < 6; ++m) sp(p, m, i) = sn[p][m];
    for (std::size_t m = 0; m < 6; ++m) g.sig[m * G + i] = out[m];
    g.eps_p[i] = eps_mean;
    g.vol[i] = vol;
    g.rho[i] = rho;
    g.q[i] = q_new;
    g.rate[i] = rate;
    g.e_int[i] += off * de_int;
    g.w_plastic[i] += off * w_pl;
    g.dt[i] = dt_e;
    g.k_nodal[i] = 0.25 * rho * vol / (dt_e * dt_e);
  }
}

}  // namespace radx::solver
