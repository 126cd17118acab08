// Eight-node brick HEPH (Isolid 24): one point at the centre, forced co-rotational frame, physical
// elasto-plastic hourglass stresses stored per element, plus a small viscous hourglass part (dn).
//
// Sources: docs/theory/elements.md 3.5 and 3.6-3.7, read from OpenRadioss
// engine/source/elements/solid/solidez/szforc3.F (order of work), szderi3.F (gradients and the hourglass
// shape vectors), szhour3.F (hourglass stresses, forces, energy), szsvm.F (equivalent stress of the
// hourglass stresses), solide/srcoor3.F + srepiso3.F + sortho3.F (frame), sdefo3.F (co-rotational strain
// rate), and starter/source/properties/solid/hm_read_prop14.F (defaults). Our own words and code.
//
// All in the element frame R = [e_x e_y e_z] of brick_corotational_frame(x, heph_order = true) (hex8_fb.cpp):
// e_x along xi, e_y along eta, e_z along zeta; x' = R^T x, v' = R^T v; the stored stress and hourglass
// stresses are in this frame; the nodal forces go back as f = R f'.
//   j_xi = d17 - d28 - d35 + d46, j_eta = d17 + d28 - d35 - d46, j_zeta = d17 + d28 + d35 + d46 (local),
//   V = j_eta . (j_zeta x j_xi) / 64, b_k as in hex8_fb.cpp, L' = sum_k v'_k (x) b_k,
//   D = sym L' - dt1/2 L'^T L' (engineering shears: twice the off-diagonal), no Jaumann rotation;
//   rho = rho0 V0 / V, material solid_point_update(de = D dt1, mu), bulk viscosity, internal energy of the
//   stress and the element step exactly as the one-point brick (docs/theory/elements.md 3.3, 4.4;
//   sdlen3.F + mqviscb.F: dt = (V / max face area) / c_eff), nodal
//   stiffness k = rho V / (4 dt^2) per node (4.5).
// Hourglass (szhour3.F). Modes, in this order, m1 = (1,1,-1,-1,-1,-1,1,1) (eta-zeta), m2 =
// (1,-1,-1,1,-1,1,1,-1) (zeta-xi), m3 = (1,-1,1,-1,1,-1,1,-1) (xi-eta), m4 = (-1,1,-1,1,1,-1,1,-1)
// (xi-eta-zeta);
//   gamma_jk = (m_jk - b_k . (m_j . x')) / 8,  hourglass rate q(d, j) = sum_k gamma_jk v'_k[d]
//   J = (J1, J2, J3) = (j_xi . e_x, j_eta . e_y, j_zeta . e_z) (current, local: 4 x the edge lengths)
//   G_h = rho0 c^2 (1 - 2 nu) / (2 (1 - nu))   (= G for LAW1 / LAW2; c the solid sound speed)
//   elastic increment  dS(d, j) = off G_h dt1 / (3 J_d) q(d, j),   S <- off S_old + dS
//   plastic reduction (laws that yield; sigma_y = solid_yield_stress): with sm the equivalent stress of
//     the element stress plus the hourglass stresses (szsvm.F, below), if sm1 > sigma_y and the hourglass
//     work of the step so far > 0: f = sigma_y / sm1, times min(1, (smo - sigma_y)/(sm1 - smo)) when the old
//     smo = 0.9 smo1 + 0.1 smo2 was already above sigma_y and below sm1; S <- S - (1 - f) dS
//   generalised forces T(d, j) = S(d, j) J_d + c_v q(d, j),  c_v = off (dn/4) rho V^(1/3) c / 150
//   N = H T with H11 = J2 J3 / J1, H22 = J1 J3 / J2, H33 = J1 J2 / J3, H12 = J3, H13 = J2, H23 = J1:
//     N(1,1) = (H22 + H33) T(1,1) + H12 T(2,2) + H13 T(3,3)   (and cyclic: N(2,2), N(3,3))
//     N(a,b) = nu1 Haa T(a,b) + nu2 Hab T(b,a)   for the shear modes (a, b) =
//     (1,2),(1,3),(2,1),(3,1),(2,3),(3,2) N(a,4) = nu3 Haa T(a,4)
//   Icpre 0: nu1 = 2/(1 - nu), nu2 = nu nu1, nu3 = 2/3 (1 + nu), nu4 = nu
//   Icpre 1: nu1 = 4/3, nu2 = -2/3, nu3 = 0.444, nu4 = 0   (incompressible hourglass modes: no locking)
//   forces f'_k[d] += -sum_j gamma_jk N(d, j)
//   energy: dE = dt1/2 sum_{d,j} (N_old(d, j) + N(d, j)) q(d, j), N_old from the stored S with the current
//     J, c_v and q; booked in e_int (the reference books the HEPH hourglass work in the internal energy),
//     and also in w_hg (diagnostic, not summed again). e_hg stays 0.
// szsvm.F (equivalent stress with the hourglass stresses, coefficient 324 = (3 8 0.75)^2), with S(d, j),
//   n1 = 1/(1 - nu4), n2 = nu4 n1:
//   r1 = n1 S13 + n2 S31, r2 = n1 S31 + n2 S13, r3 = S13 - S31, r4 = (J3/J1) S33 + (J1/J3) S11
//   s1 = S12 - S21, s2 = n1 S21 + n2 S12, s3 = n1 S12 + n2 S21, s4 = (J2/J1) S22 + (J1/J2) S11
//   t1 = n1 S23 + n2 S32, t2 = S23 - S32, t3 = n1 S32 + n2 S23, t4 = (J2/J3) S22 + (J3/J2) S33
//   A = svm0^2 + 324 sum_{x = r, s, t} (2 (x1^2 + x2^2 + x3^2) + 3 x4^2)
//   for i = 1..3, with p = r_i s_i, q = r_i t_i, u = s_i t_i: extremes of (p+q+u, p-q-u, -p+q-u, -p-q+u)
//   sm1 = sqrt|A + 324 sum max|, sm2 = min(sqrt(max(0, A + 324 sum min)), svm0)
//   (svm0: von Mises of the new element stress).
// Defaults (hm_read_prop14.F): Ismstr 4, Icpre 0 (from /DEF_SOLID otherwise), dn 0.1, h ignored, IHKT 1.
//
// Layout (as the shells, shell_bt4.cpp): the group runs in blocks of kBlock elements; each stage is a loop
// over the block's elements, element index innermost, on structure-of-arrays scratch (HephBlock), without
// branches so that GCC vectorises it, and so that the long dependent chains of one element (the frame's
// thirteen square roots and divisions) overlap with those of the others: gather; frame
// (brick_corotational_frame_block); local geometry, strain rate and hourglass rates; the material, element by
// element (the law is a call); bulk viscosity, energy, step; hourglass stresses; forces; state updates.
// Square roots are taken in passes of their own (sqrt_in_place). Elements deleted at entry or with a bad
// volume go through the arithmetic with every state update masked (pick) and get their zero forces at the
// end. The mode sums and the nodal forces are the one-point brick's (brick_mode_sums, brick_nodal_forces: the
// same quantities, fewer operations).
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

#include "solver/elements/element_gather.hpp"
#include "solver/elements/element_groups.hpp"
#include "solver/elements/solid/solid_stages.hpp"

namespace radx::solver {

namespace {

constexpr int kBlock = 32;  // elements per block: the scratch (about 50 KB) stays in the core's caches

// The four hourglass modes in the reference's order (opening comment) are the one-point brick's vectors
// (brick_mode_sums) h2, h3, h1 and -h4: mode m is kFbSign[m] h_{kFbMode[m]}.
constexpr int kFbMode[4] = {1, 2, 0, 3};
constexpr double kFbSign[4] = {1.0, 1.0, 1.0, -1.0};

constexpr double kSvmCoef = 324.0;  // (3 x 8 x 0.75)^2 (szsvm.F)

// N = H T of the opening comment; T and N indexed [direction][mode].
inline void hg_generalised(const double T[3][4], const double J[3], const double Ji[3], double nu1,
                           double nu2, double nu3, double N[3][4]) {
  const double h11 = J[1] * J[2] * Ji[0], h22 = J[0] * J[2] * Ji[1], h33 = J[0] * J[1] * Ji[2];
  const double h12 = J[2], h13 = J[1], h23 = J[0];
  N[0][0] = (h22 + h33) * T[0][0] + h12 * T[1][1] + h13 * T[2][2];
  N[1][1] = (h11 + h33) * T[1][1] + h23 * T[2][2] + h12 * T[0][0];
  N[2][2] = (h11 + h22) * T[2][2] + h13 * T[0][0] + h23 * T[1][1];
  N[0][1] = nu1 * h11 * T[0][1] + nu2 * h12 * T[1][0];
  N[0][2] = nu1 * h11 * T[0][2] + nu2 * h13 * T[2][0];
  N[1][0] = nu1 * h22 * T[1][0] + nu2 * h12 * T[0][1];
  N[2][0] = nu1 * h33 * T[2][0] + nu2 * h13 * T[0][2];
  N[1][2] = nu1 * h22 * T[1][2] + nu2 * h23 * T[2][1];
  N[2][1] = nu1 * h33 * T[2][1] + nu2 * h23 * T[1][2];
  N[0][3] = nu3 * h11 * T[0][3];
  N[1][3] = nu3 * h22 * T[1][3];
  N[2][3] = nu3 * h33 * T[2][3];
}

// Equivalent stresses of the element stress (von Mises squared svm0_2) with the hourglass stresses S
// (szsvm.F, opening comment), as the arguments of their square roots, taken in a pass of their own:
// sm1 = sqrt(a1), sm2 = min(sqrt(a2), sqrt(svm0_2)). Ji = 1 / J, n1 = 1 / (1 - nu4), n2 = nu4 n1.
inline void hg_equivalent_args(const double S[3][4], const double J[3], const double Ji[3], double n1,
                               double n2, double svm0_2, double& a1, double& a2) {
  const double r[4] = {n1 * S[0][2] + n2 * S[2][0], n1 * S[2][0] + n2 * S[0][2], S[0][2] - S[2][0],
                       J[2] * Ji[0] * S[2][2] + J[0] * Ji[2] * S[0][0]};
  const double s[4] = {S[0][1] - S[1][0], n1 * S[1][0] + n2 * S[0][1], n1 * S[0][1] + n2 * S[1][0],
                       J[1] * Ji[0] * S[1][1] + J[0] * Ji[1] * S[0][0]};
  const double t[4] = {n1 * S[1][2] + n2 * S[2][1], S[1][2] - S[2][1], n1 * S[2][1] + n2 * S[1][2],
                       J[1] * Ji[2] * S[1][1] + J[2] * Ji[1] * S[2][2]};
  auto sq = [](const double a[4]) {
    return 2.0 * (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]) + 3.0 * a[3] * a[3];
  };
  double mx = 0.0, mn = 0.0;
#pragma GCC unroll 3
  for (int i = 0; i < 3; ++i) {
    const double p = r[i] * s[i], q = r[i] * t[i], u = s[i] * t[i];
    const double c0 = p + q + u, c1 = p - q - u, c2 = -p + q - u, c3 = -p - q + u;
    // (nested std::max/min: the first extremum, as the initializer-list forms, and they vectorise)
    mx += std::max(std::max(std::max(c0, c1), c2), c3);
    mn += std::min(std::min(std::min(c0, c1), c2), c3);
  }
  const double a = svm0_2 + kSvmCoef * (sq(r) + sq(s) + sq(t));
  a1 = std::abs(a + kSvmCoef * mx);
  a2 = std::max(a + kSvmCoef * mn, 0.0);
}

// `old` where the mask is all ones, `fresh` where it is zero: a select GCC vectorises where it keeps `c ? a
// : b` of several stored values as a branch (conditional stores, which SSE cannot mask).
inline double pick(std::uint64_t keep, double old, double fresh) {
  return std::bit_cast<double>((std::bit_cast<std::uint64_t>(old) & keep) |
                               (std::bit_cast<std::uint64_t>(fresh) & ~keep));
}

// Scratch of one block, [quantity][slot]; all but the gathered nodes in the element frame.
struct HephBlock {
  NodeBlock<8, kBlock> nb;     // gathered positions and velocities, global axes
  BrickFrameBlock<kBlock> fr;  // frame R
  double b[4][3][kBlock];      // gradients b1 .. b4 (b5 .. b8 = -b3, -b4, -b1, -b2)
  double hx[4][3][kBlock];     // mode sums of the local coordinates on h1 .. h4 (brick_mode_sums)
  double q[3][4][kBlock];      // hourglass rates q(d, j)
  double D[6][kBlock];         // co-rotational strain rate
  double J[3][kBlock];         // J1 J2 J3
  double vol[kBlock], rho[kBlock], mu[kBlock], off[kBlock];
  std::int64_t good[kBlock];  // 1: off > 0 at entry and a valid geometry
  // Square-root arguments, then roots: largest face cross product, strain-rate measure, step, von Mises.
  double root[4][kBlock];
  // Material and after: new stress, plastic strain and its increment, rate, V^(1/3), factor after, bulk
  // viscosity, qt of the step, svm^2, stress energy increment.
  double sn[6][kBlock];
  double eps_p[kBlock], deps_p[kBlock], rate[kBlock], l[kBlock], off_new[kBlock];
  double q_new[kBlock], qt[kBlock], svm2[kBlock], de_int[kBlock];
  // Hourglass: stresses after the elastic increment, the increment, the old work rate, the square-root
  // arguments of the equivalent stresses (smo1, smo2, sm1), the generalised forces, the hourglass work.
  double S[3][4][kBlock], dS[3][4][kBlock];
  double p_old[kBlock], hg_root[3][kBlock];
  double N[3][4][kBlock];
  double de_hg[kBlock];
};

// The group's constants of the kernel.
struct HephConstants {
  double dt1, c, rho0, qa2, qb, alpha;
  double g_hg;           // hourglass modulus rho0 c^2 (1 - 2 nu) / (2 (1 - nu)): G for the isotropic laws
  double cv_coef;        // of the viscous hourglass part, Dn / 4 / 150
  double nu1, nu2, nu3;  // of H (opening comment); Icpre 1 takes the incompressible values
  double sv_n1, sv_n2;   // 1 / (1 - nu4) and nu4 / (1 - nu4) of the equivalent stresses
};

HephConstants heph_constants(const BrickGroup& g, const MaterialParams& mat, double dt1) {
  HephConstants k;
  k.dt1 = dt1;
  k.c = mat.c_solid;
  k.rho0 = mat.rho0;
  const double nu = mat.nu;
  k.qa2 = g.qa * g.qa;
  k.qb = g.qb;
  k.alpha = rate_filter_alpha(mat, dt1);
  k.g_hg = 0.5 * k.rho0 * k.c * k.c * (1.0 - 2.0 * nu) / (1.0 - nu);
  k.cv_coef = 0.25 * g.dn / 150.0;
  double nu1 = 2.0 / (1.0 - nu), nu2 = nu * nu1, nu3 = 2.0 / 3.0 * (1.0 + nu), nu4 = nu;
  if (g.icpre == 1) {
    nu1 = 4.0 / 3.0;
    nu2 = -2.0 / 3.0;
    nu3 = 0.444;
    nu4 = 0.0;
  }
  k.nu1 = nu1, k.nu2 = nu2, k.nu3 = nu3;
  k.sv_n1 = 1.0 / (1.0 - nu4), k.sv_n2 = nu4 * k.sv_n1;
  return k;
}

// The generalised hourglass forces N = H T of the stresses S with their viscous part, T = S J + cv q, and
// their work rate sum N q (d outer, m inner).
[[gnu::always_inline]] inline double hg_forces_and_power(const HephConstants& k, const double S[3][4],
                                                         const double q[3][4], const double J[3],
                                                         const double Ji[3], double cv, double N[3][4]) {
  double T[3][4];
#pragma GCC unroll 3
  for (int d = 0; d < 3; ++d)
#pragma GCC unroll 4
    for (int m = 0; m < 4; ++m) T[d][m] = S[d][m] * J[d] + cv * q[d][m];
  hg_generalised(T, J, Ji, k.nu1, k.nu2, k.nu3, N);
  double p = 0.0;
#pragma GCC unroll 3
  for (int d = 0; d < 3; ++d)
#pragma GCC unroll 4
    for (int m = 0; m < 4; ++m) p += N[d][m] * q[d][m];
  return p;
}

// Gather; /DT/BRICK/CST small strain (rare: element by element) for the live elements.
[[gnu::always_inline]] inline void heph_gather(HephBlock& bk, BrickGroup& g, const NodeState& nodes,
                                               std::size_t ib, int len) {
  gather_block<false>(g.conn.data(), kGroupSize, ib, static_cast<std::size_t>(len), nodes, bk.nb);
  for (int j = 0; j < len; ++j) {
    const std::size_t i = ib + static_cast<std::size_t>(j);
    bk.off[j] = g.off[i];
    if (bk.off[j] == 0.0 || (g.dt_fixed[i] <= 0.0 && !g.small[i])) continue;
    double x[8][3];
    for (int n = 0; n < 8; ++n) x[n][0] = bk.nb.x[n][j], x[n][1] = bk.nb.y[n][j], x[n][2] = bk.nb.z[n][j];
    brick_small_strain_geometry(g, i, x);
    for (int n = 0; n < 8; ++n) bk.nb.x[n][j] = x[n][0], bk.nb.y[n][j] = x[n][1], bk.nb.z[n][j] = x[n][2];
  }
}

// Hourglass rates of one element: the mode sums of its local coordinates and velocities on the vectors h_j,
// and q(d, m) = (m_m . v'_d - L'_d . (m_m . x')) / 8 of the reference's modes.
[[gnu::always_inline]] inline void heph_hourglass_rates(const double x[8][3], const double v[8][3],
                                                        const double L[3][3], double hx[4][3],
                                                        double q[3][4]) {
  double hv[4][3];
#pragma GCC unroll 3
  for (int d = 0; d < 3; ++d) {
    brick_mode_sums(x[0][d], x[1][d], x[2][d], x[3][d], x[4][d], x[5][d], x[6][d], x[7][d], hx, d);
    brick_mode_sums(v[0][d], v[1][d], v[2][d], v[3][d], v[4][d], v[5][d], v[6][d], v[7][d], hv, d);
  }
#pragma GCC unroll 3
  for (int d = 0; d < 3; ++d)
#pragma GCC unroll 4
    for (int m = 0; m < 4; ++m) {
      const int h = kFbMode[m];
      q[d][m] =
          kFbSign[m] * (hv[h][d] - (L[d][0] * hx[h][0] + L[d][1] * hx[h][1] + L[d][2] * hx[h][2])) / 8.0;
    }
}

// Nodes and velocities into the frame; centre Jacobian, volume, gradients, strain rate, density, the mode
// sums of the local coordinates and the hourglass rates; the square-root arguments of the face length and
// the strain-rate measure.
[[gnu::always_inline]] inline void heph_geometry_and_rates(HephBlock& bk, const HephConstants& k,
                                                           const BrickGroup& g, std::size_t ib, int len) {
  const double* vol0 = g.vol0.data();
  RADX_IVDEP
  for (int j = 0; j < len; ++j) {
    const std::size_t i = ib + static_cast<std::size_t>(j);
    double R[3][3], x[8][3], v[8][3];
#pragma GCC unroll 3
    for (int r = 0; r < 3; ++r)
#pragma GCC unroll 3
      for (int a = 0; a < 3; ++a) R[r][a] = bk.fr.R[r][a][j];
#pragma GCC unroll 8
    for (int n = 0; n < 8; ++n) {
      x[n][0] = bk.nb.x[n][j], x[n][1] = bk.nb.y[n][j], x[n][2] = bk.nb.z[n][j];
      v[n][0] = bk.nb.vx[n][j], v[n][1] = bk.nb.vy[n][j], v[n][2] = bk.nb.vz[n][j];
    }
    brick_into_frame(R, x, v);

    // Centre Jacobian (j1: eta, j2: zeta, j3: xi), volume, gradients.
    double j1[3], j2[3], j3[3], c12[3], c23[3], c31[3];
    const double vol = brick_centre_jacobian(x, j1, j2, j3, c12, c23, c31);
    const double J[3] = {j3[0], j1[1], j2[2]};
    bk.good[j] = (bk.off[j] != 0.0) & (vol > 0.0) & (J[0] > 0.0) & (J[1] > 0.0) & (J[2] > 0.0);
    double b[8][3];
    brick_centre_gradients(c12, c23, c31, vol, b);

    // Velocity gradient and the co-rotational strain rate.
    double L[3][3], D[6];
    brick_velocity_gradient(v, b, L);
    corotational_strain_rate(L, k.dt1, D);
    double hx[4][3], q[3][4];
    heph_hourglass_rates(x, v, L, hx, q);

    const double rho = solid_density(k.rho0, vol0[i], vol);
    bk.vol[j] = vol;
    bk.rho[j] = rho;
    bk.mu[j] = solid_mu(rho, k.rho0);
    bk.root[0][j] = brick_face_cross2_max(x);
    bk.root[1][j] = strain_rate_measure2(D);
#pragma GCC unroll 3
    for (int d = 0; d < 3; ++d) {
      bk.J[d][j] = J[d];
#pragma GCC unroll 4
      for (int n = 0; n < 4; ++n) bk.b[n][d][j] = b[n][d];
#pragma GCC unroll 4
      for (int m = 0; m < 4; ++m) {
        bk.hx[m][d][j] = hx[m][d];
        bk.q[d][m][j] = q[d][m];
      }
    }
#pragma GCC unroll 6
    for (int m = 0; m < 6; ++m) bk.D[m][j] = D[m];
  }
}

// Material in the frame, element by element (the law is a call), and the factor after it.
[[gnu::always_inline]] inline void heph_material(HephBlock& bk, const HephConstants& k,
                                                 const MaterialParams& mat, BrickGroup& g, std::size_t ib,
                                                 int len) {
  constexpr std::size_t G = kGroupSize;
  const double dt1 = k.dt1;
  const double* sig = g.sig.data();
  for (int j = 0; j < len; ++j) {
    if (!bk.good[j]) continue;
    const std::size_t i = ib + static_cast<std::size_t>(j);
    const double off = bk.off[j];
    const double D[6] = {bk.D[0][j], bk.D[1][j], bk.D[2][j], bk.D[3][j], bk.D[4][j], bk.D[5][j]};
    const double rate = filtered_rate(k.alpha, bk.root[1][j], g.rate[i]);
    const double de[6] = {D[0] * dt1, D[1] * dt1, D[2] * dt1, D[3] * dt1, D[4] * dt1, D[5] * dt1};
    double sn[6];
    for (int m = 0; m < 6; ++m) sn[m] = sig[static_cast<std::size_t>(m) * G + i];
    double eps_p = g.eps_p[i];
    double dmg = g.dmg[i];
    const SolidPointResult pr = solid_point_update(mat, rate, de, bk.mu[j], sn, eps_p, dmg, off);
    // Law 36 Eps_p_max and /FAIL/JOHNSON Ifail_so 1 start the brick's deletion (brick_next_off, as the
    // one-point brick). As in hex8_fb.cpp, this cycle's nodal forces and energies take the new factor: 0.8
    // in the failure cycle, none in the cycle that deletes the brick (with the factor at entry a brick
    // reported deleted still pushed on its nodes for one cycle). The hourglass state keeps its own factor
    // at entry.
    const double off_new = brick_next_off(off, pr.element_fails);
    for (int m = 0; m < 6; ++m) bk.sn[m][j] = sn[m];
    bk.eps_p[j] = eps_p;
    bk.deps_p[j] = pr.deps_p;
    bk.rate[j] = rate;
    bk.l[j] = std::cbrt(bk.vol[j]);
    bk.off_new[j] = off_new;
    g.eps_p[i] = eps_p;
    g.dmg[i] = dmg;
    g.off[i] = off_new;
    g.rate[i] = rate;
  }
}

// The others give no force (cleared at the end) and keep their state: dt = +inf when deleted; an inverted,
// flat or not-a-number volume is stored negative with dt = 0 (reported and stopped by the engine). Their
// slots go through the passes below with every state update masked.
[[gnu::always_inline]] inline void heph_mask_others(HephBlock& bk, BrickGroup& g, std::size_t ib, int len) {
  for (int j = 0; j < len; ++j) {
    if (bk.good[j]) continue;
    const std::size_t i = ib + static_cast<std::size_t>(j);
    if (bk.off[j] == 0.0) {
      g.dt[i] = std::numeric_limits<double>::infinity();
    } else {
      const double vol = bk.vol[j];
      g.vol[i] = vol > 0.0 ? -vol : vol;
      g.dt[i] = 0.0;
    }
    g.k_nodal[i] = 0.0;
    for (int m = 0; m < 6; ++m) bk.sn[m][j] = 0.0;
    bk.eps_p[j] = bk.deps_p[j] = bk.rate[j] = bk.l[j] = bk.off_new[j] = 0.0;
  }
}

// Bulk viscosity, the step's qt, stress energy and von Mises (as the one-point brick); the stress, volume,
// density and bulk viscosity of the live elements.
[[gnu::always_inline]] inline void heph_viscosity_and_energy(HephBlock& bk, const HephConstants& k,
                                                             BrickGroup& g, std::size_t ib, int len) {
  constexpr std::size_t G = kGroupSize;
  const double c = k.c;
  double* sig = g.sig.data();
  double* vols = g.vol.data();
  double* rhos = g.rho.data();
  double* qs = g.q.data();
  RADX_IVDEP
  for (int j = 0; j < len; ++j) {
    const std::size_t i = ib + static_cast<std::size_t>(j);
    const std::uint64_t keep = static_cast<std::uint64_t>(bk.good[j]) - 1;  // all ones for the others
    const double vol = bk.vol[j], rho = bk.rho[j], l = bk.l[j];
    const double D[6] = {bk.D[0][j], bk.D[1][j], bk.D[2][j], bk.D[3][j], bk.D[4][j], bk.D[5][j]};
    double so[6], sn[6];
#pragma GCC unroll 6
    for (int m = 0; m < 6; ++m) so[m] = sig[static_cast<std::size_t>(m) * G + i], sn[m] = bk.sn[m][j];
    const double ec = compression_rate(D);
    const double q_new = bulk_viscosity(rho, ec, l, k.qa2, k.qb, c);
    const double qt = solid_step_qt(c, k.qa2, k.qb, l, ec);
    const double svm2 = von_mises2(sn);
    bk.de_int[j] = solid_energy_increment(k.dt1, vol, vols[i], stress_power_sum(so, sn, D), qs[i], q_new);
    bk.q_new[j] = q_new;
    bk.qt[j] = qt;
    bk.svm2[j] = svm2;
    bk.root[2][j] = qt * qt + c * c;
    bk.root[3][j] = svm2;
#pragma GCC unroll 6
    for (int m = 0; m < 6; ++m) sig[static_cast<std::size_t>(m) * G + i] = pick(keep, so[m], sn[m]);
    vols[i] = pick(keep, vols[i], vol);
    rhos[i] = pick(keep, rhos[i], rho);
    qs[i] = pick(keep, qs[i], q_new);
  }
}

// Hourglass, first part: the work rate of the stored stresses (energy trapezoid, first half), the elastic
// increment, and (kYield) the square-root arguments of the equivalent stresses before and after it.
template <bool kYield>
[[gnu::always_inline]] inline void heph_hourglass_first(HephBlock& bk, const HephConstants& k,
                                                        const BrickGroup& g, std::size_t ib, int len) {
  constexpr std::size_t G = kGroupSize;
  const double* hg_stress = g.hg_stress.data();
  RADX_IVDEP
  for (int j = 0; j < len; ++j) {
    const std::size_t i = ib + static_cast<std::size_t>(j);
    const double off = bk.off[j];
    const double J[3] = {bk.J[0][j], bk.J[1][j], bk.J[2][j]};
    const double Ji[3] = {1.0 / J[0], 1.0 / J[1], 1.0 / J[2]};
    const double cv = off * k.cv_coef * bk.rho[j] * bk.l[j] * k.c;
    double q[3][4], S[3][4], N[3][4];
#pragma GCC unroll 3
    for (int d = 0; d < 3; ++d)
#pragma GCC unroll 4
      for (int m = 0; m < 4; ++m) {
        q[d][m] = bk.q[d][m][j];
        S[d][m] = off * hg_stress[static_cast<std::size_t>(4 * d + m) * G + i];
      }
    bk.p_old[j] = hg_forces_and_power(k, S, q, J, Ji, cv, N);
    if constexpr (kYield)
      hg_equivalent_args(S, J, Ji, k.sv_n1, k.sv_n2, bk.svm2[j], bk.hg_root[0][j], bk.hg_root[1][j]);
    const double g3dt = off * k.g_hg * k.dt1 / 3.0;
#pragma GCC unroll 3
    for (int d = 0; d < 3; ++d)
#pragma GCC unroll 4
      for (int m = 0; m < 4; ++m) {
        const double ds = g3dt * Ji[d] * q[d][m];
        S[d][m] += ds;
        bk.dS[d][m][j] = ds;
        bk.S[d][m][j] = S[d][m];
      }
    if constexpr (kYield) {
      double unused;
      hg_equivalent_args(S, J, Ji, k.sv_n1, k.sv_n2, bk.svm2[j], bk.hg_root[2][j], unused);
    }
  }
}

// Plastic reduction where sm1 > sigma_y with positive work so far (opening comment): element by element, as
// it takes few of them; the yield stress (pow and log for Johnson-Cook) only where the work is positive.
[[gnu::always_inline]] inline void heph_hourglass_plastic(HephBlock& bk, const MaterialParams& mat, int len) {
  for (int j = 0; j < len; ++j) {
    if (!bk.good[j] || !(bk.p_old[j] > 0.0)) continue;
    const double sig_y = solid_yield_stress(mat, bk.eps_p[j], bk.rate[j]), sm1 = bk.hg_root[2][j];
    if (!(sig_y < 0.9e30 && sm1 > sig_y)) continue;
    double fac = sig_y / sm1;
    const double smo = 0.9 * bk.hg_root[0][j] + 0.1 * std::min(bk.hg_root[1][j], bk.root[3][j]);
    if (smo > sig_y && sm1 > smo) fac *= std::min(1.0, (smo - sig_y) / (sm1 - smo));
    for (int d = 0; d < 3; ++d)
      for (int m = 0; m < 4; ++m) bk.S[d][m][j] -= (1.0 - fac) * bk.dS[d][m][j];
  }
}

// Hourglass, second part: the generalised forces and the hourglass work.
[[gnu::always_inline]] inline void heph_hourglass_second(HephBlock& bk, const HephConstants& k, int len) {
  RADX_IVDEP
  for (int j = 0; j < len; ++j) {
    const double off = bk.off[j];
    const double J[3] = {bk.J[0][j], bk.J[1][j], bk.J[2][j]};
    const double Ji[3] = {1.0 / J[0], 1.0 / J[1], 1.0 / J[2]};
    const double cv = off * k.cv_coef * bk.rho[j] * bk.l[j] * k.c;
    double S[3][4], q[3][4], N[3][4];
#pragma GCC unroll 3
    for (int d = 0; d < 3; ++d)
#pragma GCC unroll 4
      for (int m = 0; m < 4; ++m) S[d][m] = bk.S[d][m][j], q[d][m] = bk.q[d][m][j];
    const double p_new = hg_forces_and_power(k, S, q, J, Ji, cv, N);
#pragma GCC unroll 3
    for (int d = 0; d < 3; ++d)
#pragma GCC unroll 4
      for (int m = 0; m < 4; ++m) bk.N[d][m][j] = N[d][m];
    bk.de_hg[j] = 0.5 * k.dt1 * (bk.p_old[j] + p_new);
  }
}

// Nodal forces: stress part -V (sigma - q I) b_k, hourglass part -sum_m gamma_mk N(:, m) with gamma_mk =
// (m_mk - b_k . (m_m . x')) / 8 = kFbSign[m] G_jk / 8 (j = kFbMode[m]), i.e. the one-point brick's forces
// with H_j = kFbSign[m] N(:, m) / 8; in the frame, then back to global axes, times the factor (zero for the
// others, cleared by heph_clear_others).
[[gnu::always_inline]] inline void heph_nodal_forces(const HephBlock& bk, BrickGroup& g, std::size_t ib,
                                                     int len) {
  constexpr std::size_t G = kGroupSize;
  double* force = g.nodal_force.data();
  RADX_IVDEP
  for (int j = 0; j < len; ++j) {
    const std::size_t i = ib + static_cast<std::size_t>(j);
    double sn[6], b[8][3], hx[4][3], hg[4][3], R[3][3], f[8][3];
#pragma GCC unroll 6
    for (int m = 0; m < 6; ++m) sn[m] = bk.sn[m][j];
#pragma GCC unroll 3
    for (int d = 0; d < 3; ++d) {
#pragma GCC unroll 4
      for (int n = 0; n < 4; ++n) b[n][d] = bk.b[n][d][j];
      b[4][d] = -b[2][d], b[5][d] = -b[3][d], b[6][d] = -b[0][d], b[7][d] = -b[1][d];
#pragma GCC unroll 4
      for (int m = 0; m < 4; ++m) {
        hx[m][d] = bk.hx[m][d][j];
        hg[kFbMode[m]][d] = kFbSign[m] * bk.N[d][m][j] * 0.125;
      }
#pragma GCC unroll 3
      for (int a = 0; a < 3; ++a) R[d][a] = bk.fr.R[d][a][j];
    }
    brick_nodal_forces(sn, bk.q_new[j], bk.vol[j], hg, hx, b, f);
    brick_from_frame(R, f);
    const double scale = bk.off_new[j];
#pragma GCC unroll 8
    for (int n = 0; n < 8; ++n)
#pragma GCC unroll 3
      for (int r = 0; r < 3; ++r)
        force[(static_cast<std::size_t>(n) * 3 + static_cast<std::size_t>(r)) * G + i] = scale * f[n][r];
  }
}

// Hourglass stresses, frame, energies, step and nodal stiffness of the live elements; returns whether every
// element of the block is live.
[[gnu::always_inline]] inline std::int64_t heph_commit(const HephBlock& bk, BrickGroup& g, std::size_t ib,
                                                       int len) {
  constexpr std::size_t G = kGroupSize;
  double* hg_stress = g.hg_stress.data();
  double* frame = g.frame.data();
  double* e_int = g.e_int.data();
  double* w_hg = g.w_hg.data();
  double* w_plastic = g.w_plastic.data();
  double* dts = g.dt.data();
  double* k_nodal = g.k_nodal.data();
  std::int64_t all_good = 1;
  RADX_IVDEP
  for (int j = 0; j < len; ++j) {
    const std::size_t i = ib + static_cast<std::size_t>(j);
    const std::uint64_t keep = static_cast<std::uint64_t>(bk.good[j]) - 1;  // all ones for the others
    all_good &= bk.good[j];
#pragma GCC unroll 3
    for (int d = 0; d < 3; ++d)
#pragma GCC unroll 4
      for (int m = 0; m < 4; ++m) {
        const std::size_t at = static_cast<std::size_t>(4 * d + m) * G + i;
        hg_stress[at] = pick(keep, hg_stress[at], bk.S[d][m][j]);
      }
#pragma GCC unroll 3
    for (int a = 0; a < 3; ++a)
#pragma GCC unroll 3
      for (int r = 0; r < 3; ++r) {
        const std::size_t at = static_cast<std::size_t>(3 * a + r) * G + i;
        frame[at] = pick(keep, frame[at], bk.fr.R[r][a][j]);
      }
    const double vol = bk.vol[j], off_new = bk.off_new[j], de_hg = bk.de_hg[j];
    const double dt_e =
        solid_step_of_root(brick_face_length_of_root(vol, bk.root[0][j]), bk.qt[j], bk.root[2][j]);
    e_int[i] = pick(keep, e_int[i], e_int[i] + off_new * (bk.de_int[j] + de_hg));
    w_hg[i] = pick(keep, w_hg[i], w_hg[i] + off_new * de_hg);
    w_plastic[i] = pick(keep, w_plastic[i], w_plastic[i] + off_new * bk.root[3][j] * bk.deps_p[j] * vol);
    dts[i] = pick(keep, dts[i], dt_e);
    k_nodal[i] = pick(keep, k_nodal[i], solid_nodal_stiffness(0.25, bk.rho[j], vol, dt_e));
  }
  return all_good;
}

}  // namespace

// The kernel: the list of its stages over each block of the group.
void hex8_heph_forces(BrickGroup& g, const NodeState& nodes, const MaterialParams& mat,
                      const CycleInfo& cyc) {
  const HephConstants k = heph_constants(g, mat, cyc.dt1);
  const bool yields = solid_law_yields(mat);
  HephBlock bk;
  for (int i0 = 0; i0 < g.count; i0 += kBlock) {
    const int len = std::min(kBlock, g.count - i0);
    const auto ib = static_cast<std::size_t>(i0);
    heph_gather(bk, g, nodes, ib, len);
    brick_corotational_frame_block<kBlock>(bk.nb.x, bk.nb.y, bk.nb.z, len, true, bk.fr);
    heph_geometry_and_rates(bk, k, g, ib, len);
    for (int r = 0; r < 2; ++r) sqrt_in_place(bk.root[r], len);
    heph_material(bk, k, mat, g, ib, len);
    heph_mask_others(bk, g, ib, len);
    heph_viscosity_and_energy(bk, k, g, ib, len);
    for (int r = 2; r < 4; ++r) sqrt_in_place(bk.root[r], len);
    if (yields) {
      heph_hourglass_first<true>(bk, k, g, ib, len);
      for (int r = 0; r < 3; ++r) sqrt_in_place(bk.hg_root[r], len);
      heph_hourglass_plastic(bk, mat, len);
    } else {
      heph_hourglass_first<false>(bk, k, g, ib, len);
    }
    heph_hourglass_second(bk, k, len);
    heph_nodal_forces(bk, g, ib, len);
    if (!heph_commit(bk, g, ib, len))
      for (int j = 0; j < len; ++j)
        if (!bk.good[j])
          clear_nodal_forces<8, 3>(g.nodal_force.data(), kGroupSize, ib + static_cast<std::size_t>(j));
  }
}

}  // namespace radx::solver
