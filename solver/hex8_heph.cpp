// Eight-node brick HEPH (Isolid 24): one point at the centre, forced co-rotational frame, physical
// elasto-plastic hourglass stresses stored per element, plus a small viscous hourglass part (dn).
//
// Sources: shared/spec/elements.md 3.5 and 3.6-3.7 (added with this kernel), read from OpenRadioss
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
//   stress and the element step exactly as the one-point brick (elements.md 3.3, 4.4; sdlen3.F + mqviscb.F:
//   dt = (V / max face area) / c_eff), nodal stiffness k = rho V / (4 dt^2) per node (4.5).
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
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "solver/element_gather.hpp"
#include "solver/element_groups.hpp"
#include "solver/solid_stages.hpp"

namespace radx::solver {

namespace {

// The four hourglass modes in the reference's order (see the opening comment).
constexpr double kMode[4][8] = {{1, 1, -1, -1, -1, -1, 1, 1},
                                {1, -1, -1, 1, -1, 1, 1, -1},
                                {1, -1, 1, -1, 1, -1, 1, -1},
                                {-1, 1, -1, 1, 1, -1, 1, -1}};

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

// Equivalent stresses sm1 >= sm2 of the element stress (von Mises squared svm0_2) with the hourglass
// stresses S (szsvm.F, opening comment); Ji = 1 / J, n1 = 1 / (1 - nu4), n2 = nu4 n1.
inline void hg_equivalent(const double S[3][4], const double J[3], const double Ji[3], double n1, double n2,
                          double svm0_2, double& sm1, double& sm2) {
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
  for (int i = 0; i < 3; ++i) {
    const double p = r[i] * s[i], q = r[i] * t[i], u = s[i] * t[i];
    const double c[4] = {p + q + u, p - q - u, -p + q - u, -p - q + u};
    mx += std::max({c[0], c[1], c[2], c[3]});
    mn += std::min({c[0], c[1], c[2], c[3]});
  }
  const double a = svm0_2 + kSvmCoef * (sq(r) + sq(s) + sq(t));
  sm1 = std::sqrt(std::abs(a + kSvmCoef * mx));
  sm2 = std::min(std::sqrt(std::max(a + kSvmCoef * mn, 0.0)), std::sqrt(svm0_2));
}

}  // namespace

void hex8_heph_forces(BrickGroup& g, const NodeState& nodes, const MaterialParams& mat,
                      const CycleInfo& cyc) {
  constexpr std::size_t G = kGroupSize;
  const double dt1 = cyc.dt1;
  const double c = mat.c_solid;
  const double rho0 = mat.rho0;
  const double nu = mat.nu;
  const double qa2 = g.qa * g.qa;
  const double qb = g.qb;
  const double alpha = rate_filter_alpha(mat, dt1);
  const double inf = std::numeric_limits<double>::infinity();
  // Hourglass modulus rho0 c^2 (1 - 2 nu) / (2 (1 - nu)): G for the isotropic laws.
  const double g_hg = 0.5 * rho0 * c * c * (1.0 - 2.0 * nu) / (1.0 - nu);
  const double cv_coef = 0.25 * g.dn / 150.0;
  double nu1 = 2.0 / (1.0 - nu), nu2 = nu * nu1, nu3 = 2.0 / 3.0 * (1.0 + nu), nu4 = nu;
  if (g.icpre == 1) {
    nu1 = 4.0 / 3.0;
    nu2 = -2.0 / 3.0;
    nu3 = 0.444;
    nu4 = 0.0;
  }
  const double sv_n1 = 1.0 / (1.0 - nu4), sv_n2 = nu4 * sv_n1;

  const std::int32_t* conn = g.conn.data();
  double* force = g.nodal_force.data();

  const auto n = static_cast<std::size_t>(g.count);
  for (std::size_t i = 0; i < n; ++i) {
    const double off = g.off[i];
    if (off == 0.0) {
      clear_nodal_forces<8, 3>(force, G, i);
      g.dt[i] = inf;
      g.k_nodal[i] = 0.0;
      continue;
    }
    double x[8][3], v[8][3];
    gather_element<8>(conn, G, i, nodes, x, v);
    brick_small_strain_geometry(g, i, x);

    // Element frame; nodes and velocities into it.
    double R[3][3];
    brick_corotational_frame(x, true, R);
    brick_into_frame(R, x, v);

    // Centre Jacobian (j1: eta, j2: zeta, j3: xi), volume, gradients.
    double j1[3], j2[3], j3[3], c12[3], c23[3], c31[3];
    const double vol = brick_centre_jacobian(x, j1, j2, j3, c12, c23, c31);
    const double J[3] = {j3[0], j1[1], j2[2]};
    if (!(vol > 0.0) || !(J[0] > 0.0) || !(J[1] > 0.0) || !(J[2] > 0.0)) {
      clear_nodal_forces<8, 3>(force, G, i);
      g.vol[i] = vol > 0.0 ? -vol : vol;  // reported and stopped by the engine
      g.dt[i] = 0.0;
      g.k_nodal[i] = 0.0;
      continue;
    }
    const double Ji[3] = {1.0 / J[0], 1.0 / J[1], 1.0 / J[2]};
    double b[8][3];
    brick_centre_gradients(c12, c23, c31, vol, b);

    // Velocity gradient and the co-rotational strain rate.
    double L[3][3], D[6];
    brick_velocity_gradient(v, b, L);
    corotational_strain_rate(L, dt1, D);

    // Material in the frame.
    double so[6];
    for (int m = 0; m < 6; ++m) so[m] = g.sig[static_cast<std::size_t>(m) * G + i];
    const double rho = solid_density(rho0, g.vol0[i], vol);
    const double mu = solid_mu(rho, rho0);
    const double rate = filtered_rate(alpha, strain_rate_measure(D), g.rate[i]);
    const double de[6] = {D[0] * dt1, D[1] * dt1, D[2] * dt1, D[3] * dt1, D[4] * dt1, D[5] * dt1};
    double sn[6] = {so[0], so[1], so[2], so[3], so[4], so[5]};
    double eps_p = g.eps_p[i];
    double dmg = g.dmg[i];
    const SolidPointResult pr = solid_point_update(mat, rate, de, mu, sn, eps_p, dmg, off);
    const double deps_p = pr.deps_p;
    const double sig_y = solid_yield_stress(mat, eps_p, rate);
    // Law 36 Eps_p_max and /FAIL/JOHNSON Ifail_so 1 start the brick's deletion (brick_next_off, as the
    // one-point brick). As in hex8_fb.cpp, this cycle's nodal forces and energies take the new factor: 0.8 in
    // the failure cycle, none in the cycle that deletes the brick (with the factor at entry a brick reported
    // deleted still pushed on its nodes for one cycle). The hourglass state keeps its own factor at entry.
    g.dmg[i] = dmg;
    const double off_new = brick_next_off(off, pr.element_fails);
    g.off[i] = off_new;

    // Bulk viscosity, element step.
    const double l = std::cbrt(vol);
    const double ec = compression_rate(D);
    const double q_new = bulk_viscosity(rho, ec, l, qa2, qb, c);
    const double dt_e = solid_step(brick_face_length(x, vol), c, qa2, qb, l, ec);

    // Stress energy (as the one-point brick).
    double de_int = solid_energy_increment(dt1, vol, g.vol[i], stress_power_sum(so, sn, D), g.q[i], q_new);
    const double svm2 = von_mises2(sn);

    // Hourglass: mode sums of the local coordinates and the rates q(d, j).
    double hx[4][3], q[3][4];
#pragma GCC unroll 4
    for (int j = 0; j < 4; ++j)
#pragma GCC unroll 3
      for (int d = 0; d < 3; ++d) {
        double sx = 0.0, sv = 0.0;
#pragma GCC unroll 8
        for (int k = 0; k < 8; ++k) {
          sx += kMode[j][k] * x[k][d];
          sv += kMode[j][k] * v[k][d];
        }
        hx[j][d] = sx;
        q[d][j] = sv;  // completed below
      }
    for (int d = 0; d < 3; ++d)
      for (int j = 0; j < 4; ++j)
        q[d][j] = (q[d][j] - (L[d][0] * hx[j][0] + L[d][1] * hx[j][1] + L[d][2] * hx[j][2])) / 8.0;

    const double cv = off * cv_coef * rho * l * c;
    double S[3][4], dS[3][4], T[3][4], N[3][4];
    for (int d = 0; d < 3; ++d)
      for (int j = 0; j < 4; ++j) S[d][j] = off * g.hg_stress[static_cast<std::size_t>(4 * d + j) * G + i];
    // Work rate of the stored hourglass stresses (energy trapezoid, first half).
    for (int d = 0; d < 3; ++d)
      for (int j = 0; j < 4; ++j) T[d][j] = S[d][j] * J[d] + cv * q[d][j];
    hg_generalised(T, J, Ji, nu1, nu2, nu3, N);
    double p_old = 0.0;
    for (int d = 0; d < 3; ++d)
      for (int j = 0; j < 4; ++j) p_old += N[d][j] * q[d][j];
    const bool yields = sig_y < 0.9e30;
    double smo1 = 0.0, smo2 = 0.0;
    if (yields) hg_equivalent(S, J, Ji, sv_n1, sv_n2, svm2, smo1, smo2);
    const double g3dt = off * g_hg * dt1 / 3.0;
    for (int d = 0; d < 3; ++d)
      for (int j = 0; j < 4; ++j) {
        dS[d][j] = g3dt * Ji[d] * q[d][j];
        S[d][j] += dS[d][j];
      }
    if (yields) {
      double sm1 = 0.0, sm2 = 0.0;
      hg_equivalent(S, J, Ji, sv_n1, sv_n2, svm2, sm1, sm2);
      if (sm1 > sig_y && p_old > 0.0) {
        double fac = sig_y / sm1;
        const double smo = 0.9 * smo1 + 0.1 * smo2;
        if (smo > sig_y && sm1 > smo) fac *= std::min(1.0, (smo - sig_y) / (sm1 - smo));
        for (int d = 0; d < 3; ++d)
          for (int j = 0; j < 4; ++j) S[d][j] -= (1.0 - fac) * dS[d][j];
      }
    }
    for (int d = 0; d < 3; ++d)
      for (int j = 0; j < 4; ++j) T[d][j] = S[d][j] * J[d] + cv * q[d][j];
    hg_generalised(T, J, Ji, nu1, nu2, nu3, N);
    double p_new = 0.0;
    for (int d = 0; d < 3; ++d)
      for (int j = 0; j < 4; ++j) p_new += N[d][j] * q[d][j];
    const double de_hg = 0.5 * dt1 * (p_old + p_new);

    // Nodal forces in the frame: stress part -V (sigma - q I) b_k, hourglass part -sum_j gamma_jk N(d, j),
    // gamma_jk = (m_jk - b_k . hx_j) / 8 formed once per element.
    const double sg[3][3] = {
        {sn[0] - q_new, sn[3], sn[5]}, {sn[3], sn[1] - q_new, sn[4]}, {sn[5], sn[4], sn[2] - q_new}};
    double f[8][3];
#pragma GCC unroll 8
    for (int k = 0; k < 8; ++k) {
      double gam[4];
#pragma GCC unroll 4
      for (int j = 0; j < 4; ++j)
        gam[j] = (kMode[j][k] - (b[k][0] * hx[j][0] + b[k][1] * hx[j][1] + b[k][2] * hx[j][2])) * 0.125;
#pragma GCC unroll 3
      for (int a = 0; a < 3; ++a)
        f[k][a] = -vol * (sg[a][0] * b[k][0] + sg[a][1] * b[k][1] + sg[a][2] * b[k][2]) -
                  (gam[0] * N[a][0] + gam[1] * N[a][1] + gam[2] * N[a][2] + gam[3] * N[a][3]);
    }
    // Back to global axes.
#pragma GCC unroll 8
    for (int k = 0; k < 8; ++k) {
      const double a0 = f[k][0], a1 = f[k][1], a2 = f[k][2];
      for (int r = 0; r < 3; ++r) f[k][r] = R[r][0] * a0 + R[r][1] * a1 + R[r][2] * a2;
    }

    store_nodal_forces<8, 3>(force, G, i, off_new, f);
    for (int m = 0; m < 6; ++m) g.sig[static_cast<std::size_t>(m) * G + i] = sn[m];
    for (int d = 0; d < 3; ++d)
      for (int j = 0; j < 4; ++j) g.hg_stress[static_cast<std::size_t>(4 * d + j) * G + i] = S[d][j];
    for (int a = 0; a < 3; ++a)
      for (int r = 0; r < 3; ++r) g.frame[static_cast<std::size_t>(3 * a + r) * G + i] = R[r][a];
    de_int += de_hg;
    g.eps_p[i] = eps_p;
    g.vol[i] = vol;
    g.rho[i] = rho;
    g.q[i] = q_new;
    g.rate[i] = rate;
    g.e_int[i] += off_new * de_int;
    g.w_hg[i] += off_new * de_hg;
    g.w_plastic[i] += off_new * std::sqrt(svm2) * deps_p * vol;
    g.dt[i] = dt_e;
    g.k_nodal[i] = solid_nodal_stiffness(0.25, rho, vol, dt_e);
  }
}

}  // namespace radx::solver
