// Eight-node one-point brick with Flanagan-Belytschko viscous hourglass control (Isolid 1; Isolid 2 =
// plain Hallquist h vectors for all modes; every other Isolid value is treated as 1).
//
// Source: docs/theory/elements.md 3.1-3.4 (kinematics, material call, bulk viscosity, energy, hourglass),
// 4.4-4.5 (element step, nodal stiffness), 6.2 (strain-rate measure), read from OpenRadioss sderi3.F,
// sdefo3.F, srota3.F, srho3.F, mqviscb.F, meint.F, shvis3.F, sdlen3.F.
//
// Nodes 1-4 one face, 5-8 the opposite face (node i + 4 above node i); natural coordinates
// (xi, eta, zeta)_k of node k = (-1,-1,-1), (1,-1,-1), (1,1,-1), (-1,1,-1), then the same with zeta = +1.
// All on the current geometry x^n with the mid-step velocities v^{n-1/2}; dt1 = t^n - t^{n-1}.
//
//   d17 = x7 - x1, d28 = x8 - x2, d35 = x5 - x3, d46 = x6 - x4
//   j1 = d17 + d28 - d35 - d46 (= 8 dx/deta),  j2 = d17 + d28 + d35 + d46 (= 8 dx/dzeta),
//   j3 = d17 - d28 - d35 + d46 (= 8 dx/dxi)
//   V  = j1 . (j2 x j3) / 64 = 8 det J(0)                    (one-point volume, not the trilinear one)
//   b_k = dN_k/dx(0) = [xi_k (j1 x j2) + eta_k (j2 x j3) + zeta_k (j3 x j1)] / (64 V)
//         so b5 = -b3, b6 = -b4, b7 = -b1, b8 = -b2, sum_k b_k = 0, sum_k x_k (x) b_k = I
//   L  = sum_k v_k (x) b_k = (v1 - v7)(x)b1 + (v2 - v8)(x)b2 + (v3 - v5)(x)b3 + (v4 - v6)(x)b4
//   D  = sym L: Dxx, Dyy, Dzz, D4 = Lxy + Lyx, D5 = Lyz + Lzy, D6 = Lzx + Lxz (engineering shears)
//   Wz = dt1/2 (dvy/dx - dvx/dy), Wy = dt1/2 (dvx/dz - dvz/dx), Wx = dt1/2 (dvz/dy - dvy/dz)
//   Jaumann rotation of the stored stress, first order, old values on the right (3.2):
//     sxx += -2 sxy Wz + 2 szx Wy,  syy += 2 sxy Wz - 2 syz Wx,  szz += -2 szx Wy + 2 syz Wx,
//     sxy += Wz (sxx - syy) + Wy syz - Wx szx,  syz += Wx (syy - szz) + Wz szx - Wy sxy,
//     szx += Wy (szz - sxx) + Wx sxy - Wz syz
//   rho = rho0 V0 / V,  mu = rho / rho0 - 1,  material: solid_point_update(de = D dt1, mu)
//   strain-rate measure (JC, 6.2): e = sqrt(Dxx^2 + Dyy^2 + Dzz^2 + (D4^2 + D5^2 + D6^2) / 2),
//     rate <- alpha e + (1 - alpha) rate, alpha = min(1, 2 pi Fcut dt1) (alpha = 1 when Fcut = 0)
//   bulk viscosity (3.3): l = V^(1/3), ec = max(0, -tr D), q = rho ec l (qa^2 l ec + qb c),
//     c = sqrt((K + 4G/3) / rho0); acts as an extra pressure: sigma - q I in the force integral
//   internal energy (3.3), total (not per volume), including the bulk-viscosity work:
//     dE = dt1/2 Vavg (sigma_old + sigma_new) : D - dV/2 (q_old + q_new),  dV = V - V_old,
//     Vavg = V - dV/2; sigma_old is the stored stress after the Jaumann rotation
//   plastic work (6.5): dW = svm_new d_eps_p V
//   internal forces (added to the nodes): f_k = -V (sigma - q I) b_k
//   hourglass (3.4), modes h1 = (1,-1,1,-1,1,-1,1,-1), h2 = (1,1,-1,-1,-1,-1,1,1),
//     h3 = (1,-1,-1,1,-1,1,1,-1), h4 = (1,-1,1,-1,-1,1,-1,1):
//     Isolid 1: G_j = h_j - (h_j . x) b for j = 1..3 ((h_j . x) = sum_k h_jk x_k, a 3-vector),
//               G_4 = h4 (plain); Isolid 2: G_j = h_j for all four
//     q_j = sum_k G_jk v_k (per direction),  a = h/4,  Cl = a rho V^(2/3) c,  Cq = 100 a^2 rho V^(2/3)
//     H_j = q_j (Cl + Cq |q_j|) per direction,  f_k += -sum_j G_jk H_j,
//     dE_hg = dt1 sum_j (H_j^old + H_j) / 2 . q_j   (H_j^old: the last cycle's, stored per element)
//   Deliberate difference from 3.4 (OpenRadioss books dt1 H_j . q_j): the force H_j of this cycle acts while
//   the velocity goes to v^{n+1/2}, so the rectangle books work it has not done. The trapezoid sums by parts
//   to the work the hourglass forces do on the nodes (as the stress trapezoid above does), which matters
//   when a mode rings at the highest frequency: a one-step stop of a brick face (a LAGDT contact, a rigid
//   wall) made the rectangle over-book 3 % of the energy of an impact; see docs/engine.md.
//   computed as q_j = hv_j - L hx_j (hv_j = sum_k h_jk v_k) and f_k = -T b_k - sum_j h_jk H_j with
//     T = V (sigma - q I) - sum_j H_j (x) hx_j: the same quantities, fewer operations
//   element step (4.4), before the /DT scale: dx = V / max face area (face area = |d13 x d24| / 2),
//     qt = qb c + qa^2 l ec,  c_eff = qt + sqrt(qt^2 + c^2),  dt = dx / c_eff
//   nodal stiffness (4.5): k = rho V / (4 dt^2) for each of the 8 nodes
//
// Co-rotational frame (Iframe 2; docs/theory/elements.md 3.6, read from OpenRadioss srcoor3.F, srepiso3.F,
// sortho3.F, sdefo3.F, srrota3.F): every cycle the element frame R = [e_x e_y e_z] is built from the current
// nodes (brick_corotational_frame below), the nodes and velocities are taken into it (x' = R^T x, v' = R^T
// v), all of the above runs in that frame with the stored stress expressed in it and with no Jaumann rotation
// (the frame carries the rotation), and the nodal forces go back to global axes (f = R f'). The strain rate
// gets the second-order term of the co-rotational update (sdefo3.F, explicit): with L' the velocity gradient
// in the frame, D_aa = L'_aa - dt1/2 (L'^T L')_aa and D_ab = L'_ab + L'_ba - dt1 (L'^T L')_ab (engineering
// shear), i.e. the Almansi strain increment of the step. Frame construction: r = j1, s = j2, t = j3 (centre
// directions eta, zeta, xi), normalised to u, v, w; three times u <- unit(v x w + u), v <- unit(w x u + v),
// w <- unit(u x v + w) (all three from the previous values); then e1 = u, e3 = unit(e1 x v), e2 = e3 x e1.
// Isolid 1/2 take (e_x, e_y, e_z) = (e1, e2, e3); Isolid 24 takes (e3, e1, e2), so its x axis follows xi.
//
// Total-strain laws (law 42, /MAT/OGDEN; kTotal): the stress is not integrated from D but computed from the
// total deformation gradient at the centre, F = sum_k x_k (x) B_k with B_k = dN_k/dX(0) of the initial
// geometry (g.b_ref, global axes; the same opposite-node pairs as L), in the frame x is in: with Iframe 2,
// x' = R^T x gives F' = R^T F and the stress R^T sigma R kept in the frame. The law's wave speed
// c = sqrt(M / rho) of the cycle (law42_ogden.cpp: the current tangent) replaces the material's constant c in
// the bulk viscosity, the hourglass coefficient and the step. The energy trapezoid is unchanged (the
// stress power of the old and new stresses). Laws 1, 2, 36 instantiate the kernel without it.
// Law 70 (/MAT/FOAM_TAB) takes the same F: its strain is V - I from the principal stretches of F F^T
// (law70_foam_tab.cpp), its state the group's `foam` rows, and its wave speed sqrt(A11(E) / rho0) replaces c
// as law 42's does. One instance per law (TotalLaw), chosen per group.
//
// Small strain (after a /DT/BRICK/CST switch, g.dt_fixed > 0): the node coordinates are frozen in g.x_ref at
// the first cycle after the switch and replace x^n in every formula above, so b_k, V, rho and the step stay
// those of that geometry (the step constant, as Radioss's small-strain switch); velocities stay v^{n-1/2}.
// Degenerate bricks (repeated nodes: pentahedra, tetrahedra) go through the same formulas. An element
// with V <= 0 (or not a number) gets zero force, dt = 0 and k = 0, keeps its stress and energies and
// stores the bad volume in `vol`: the engine reports it and stops. Elements with off == 0 give no force
// and dt = +inf. Forces and energy increments are scaled by off (1 for a live brick).
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "solver/elements/element_gather.hpp"
#include "solver/elements/element_groups.hpp"
#include "solver/elements/solid/solid_stages.hpp"

namespace radx::solver {

void brick_corotational_frame(const double x[8][3], bool heph_order, double R[3][3]) {
  // A block of one: the formulas are written once, in solid_stages.hpp, for HEPH's blocks.
  double px[8][1], py[8][1], pz[8][1];
  for (int k = 0; k < 8; ++k) {
    px[k][0] = x[k][0];
    py[k][0] = x[k][1];
    pz[k][0] = x[k][2];
  }
  BrickFrameBlock<1> f;
  brick_corotational_frame_block<1>(px, py, pz, 1, heph_order, f);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) R[r][c] = f.R[r][c][0];
}

namespace {

// The stress of a total-strain law, chosen per group (never per element).
enum class TotalLaw : std::uint8_t { None, Ogden, Foam };

// The group's constants of the kernel.
struct FbConstants {
  double dt1, c, rho0, qa2, qb, a_hg, alpha;
  bool plain_h;  // Isolid 2: the plain hourglass vectors for every mode
};

inline FbConstants fb_constants(const BrickGroup& g, const MaterialParams& mat, double dt1) {
  return FbConstants{
      dt1, mat.c_solid, mat.rho0, g.qa * g.qa, g.qb, 0.25 * g.h, rate_filter_alpha(mat, dt1), g.isolid == 2};
}

// The strain rate D (engineering shears) and the stress the update starts from, so: co-rotational, the
// second-order term of the strain increment and no spin (the frame turns with the element); otherwise the
// stored stress turned by the Jaumann spin of the half step (old values on the right-hand side).
template <bool kCorot>
[[gnu::always_inline]] inline void fb_strain_rate(const BrickGroup& g, std::size_t i, const double L[3][3],
                                                  double dt1, double D[6], double so[6]) {
  constexpr std::size_t G = kGroupSize;
  double s[6];
#pragma GCC unroll 8
  for (int m = 0; m < 6; ++m) s[m] = g.sig[static_cast<std::size_t>(m) * G + i];
  if constexpr (kCorot) {
    corotational_strain_rate(L, dt1, D);
    for (int m = 0; m < 6; ++m) so[m] = s[m];
  } else {
    D[0] = L[0][0], D[1] = L[1][1], D[2] = L[2][2];
    D[3] = L[0][1] + L[1][0], D[4] = L[1][2] + L[2][1], D[5] = L[2][0] + L[0][2];
    double wx, wy, wz;
    half_step_spin(L, dt1, wx, wy, wz);
    jaumann_rotate(s, wx, wy, wz, so);
  }
}

// The material at the element's point: sn from the start stress, the plastic strain and damage updated.
// The total-strain laws (Ogden, the foam) take the deformation gradient F = sum_k x_k (x) B_k and give the
// element's wave speed c_e of this cycle; the others keep the material's.
template <TotalLaw kLaw>
[[gnu::always_inline]] inline SolidPointResult fb_material(BrickGroup& g, std::size_t i, const FbConstants& k,
                                                           const MaterialParams& mat, const double x[8][3],
                                                           const double D[6], double rate, double rho,
                                                           double mu, double off, double sn[6], double& eps_p,
                                                           double& dmg, double& c_e) {
  constexpr std::size_t G = kGroupSize;
  const double dt1 = k.dt1;
  SolidPointResult pr;
  c_e = k.c;
  if constexpr (kLaw != TotalLaw::None) {
    double B[8][3], F[3][3];
    for (std::size_t n = 0; n < 4; ++n)
      for (std::size_t d = 0; d < 3; ++d) B[n][d] = g.b_ref[(3 * n + d) * G + i];
    brick_velocity_gradient(x, B, F);  // sum_k x_k (x) B_k, by the opposite-node pairs (B_5..8 unused)
    if constexpr (kLaw == TotalLaw::Ogden) {
      const OgdenPointResult op = ogden_point(mat, F, sn);
      c_e = std::sqrt(op.modulus / rho);
      pr.element_fails = op.cut && off == 1.0;
    } else {
      double eps[6], st[kFoamVars];
      foam_strain(F, eps);
      const double de[6] = {D[0] * dt1, D[1] * dt1, D[2] * dt1, D[3] * dt1, D[4] * dt1, D[5] * dt1};
      for (std::size_t v = 0; v < static_cast<std::size_t>(kFoamVars); ++v) st[v] = g.foam[v * G + i];
      c_e = foam_point(mat, eps, de, rate, rho / k.rho0, sn, st);
      for (std::size_t v = 0; v < static_cast<std::size_t>(kFoamVars); ++v) g.foam[v * G + i] = st[v];
    }
    (void)mu, (void)eps_p, (void)dmg;
  } else {
    const double de[6] = {D[0] * dt1, D[1] * dt1, D[2] * dt1, D[3] * dt1, D[4] * dt1, D[5] * dt1};
    pr = solid_point_update(mat, rate, de, mu, sn, eps_p, dmg, off);
  }
  return pr;
}

// Hourglass forces H_j = q_j (Cl + Cq |q_j|) per direction, Cl = a rho V^(2/3) c, Cq = 100 a^2 rho V^(2/3),
// with the rates q_j = sum_k (h_jk - hx_j . b_k) v_k = hv_j - L hx_j, hx_j = sum_k h_jk x_k and hv_j = sum_k
// h_jk v_k (hx_j taken as 0 for the plain modes: mode 4 always, every mode with Isolid 2); the stored forces
// updated and the hourglass work rate returned (trapezoid over the step).
[[gnu::always_inline]] inline double fb_hourglass(BrickGroup& g, std::size_t i, const FbConstants& k,
                                                  const double x[8][3], const double v[8][3],
                                                  const double L[3][3], double rho, double l, double c_w,
                                                  double hx[4][3], double hg[4][3]) {
  constexpr std::size_t G = kGroupSize;
  double hv[4][3];
#pragma GCC unroll 8
  for (int d = 0; d < 3; ++d) {
    brick_mode_sums(x[0][d], x[1][d], x[2][d], x[3][d], x[4][d], x[5][d], x[6][d], x[7][d], hx, d);
    brick_mode_sums(v[0][d], v[1][d], v[2][d], v[3][d], v[4][d], v[5][d], v[6][d], v[7][d], hv, d);
  }
#pragma GCC unroll 8
  for (int d = 0; d < 3; ++d) {
    hx[3][d] = 0.0;  // mode 4: plain h4 for Isolid 1 and 2
    if (k.plain_h) hx[0][d] = hx[1][d] = hx[2][d] = 0.0;
  }
  const double v23 = l * l;  // V^(2/3)
  const double cl = k.a_hg * rho * v23 * c_w;
  const double cq = 100.0 * k.a_hg * k.a_hg * rho * v23;
  double de_hg = 0.0;
  for (int j = 0; j < 4; ++j)
#pragma GCC unroll 8
    for (int d = 0; d < 3; ++d) {
      const double qj = hv[j][d] - (L[d][0] * hx[j][0] + L[d][1] * hx[j][1] + L[d][2] * hx[j][2]);
      hg[j][d] = qj * (cl + cq * std::abs(qj));
      auto& h_old = g.hg_force[static_cast<std::size_t>(3 * j + d) * G + i];
      de_hg += 0.5 * (h_old + hg[j][d]) * qj;
      h_old = hg[j][d];
    }
  return de_hg;
}

// An element that does not run this cycle: deleted (dt = +inf), or inverted, flat or not a number (its
// volume stored, dt = 0: reported and stopped by the engine).
inline void fb_element_off(BrickGroup& g, std::size_t i, bool deleted, double vol) {
  clear_nodal_forces<8, 3>(g.nodal_force.data(), kGroupSize, i);
  if (deleted) {
    g.dt[i] = std::numeric_limits<double>::infinity();
  } else {
    g.vol[i] = vol;
    g.dt[i] = 0.0;
  }
  g.k_nodal[i] = 0.0;
}

// One element at a time through local arrays. The short fixed-count loops carry "GCC unroll": GCC does not
// unroll them completely at -O2, and unrolled the kernel runs about 35 % fewer instructions.
template <bool kCorot, TotalLaw kLaw>
void hex8_forces_impl(BrickGroup& g, const NodeState& nodes, const MaterialParams& mat,
                      const CycleInfo& cyc) {
  constexpr std::size_t G = kGroupSize;
  const FbConstants k = fb_constants(g, mat, cyc.dt1);
  const double dt1 = k.dt1;
  const auto n = static_cast<std::size_t>(g.count);
  for (std::size_t i = 0; i < n; ++i) {
    const double off = g.off[i];
    if (off == 0.0) {
      fb_element_off(g, i, true, 0.0);
      continue;
    }
    // Gather; /DT/BRICK/CST switched this element: freeze its coordinates once, then take the geometry
    // (gradients, volume, density, step) from them; the velocities stay current (small strain).
    double x[8][3], v[8][3];
    gather_element<8>(g.conn.data(), G, i, nodes, x, v);
    brick_small_strain_geometry(g, i, x);
    // Co-rotational: into the element frame (x' = R^T x, v' = R^T v).
    [[maybe_unused]] double R[3][3];
    if constexpr (kCorot) {
      brick_corotational_frame(x, false, R);
      brick_into_frame(R, x, v);
    }

    // Centre Jacobian, volume, gradients; the velocity gradient L[a][c] = d v_a / d x_c from the
    // opposite-node differences, the strain rate and the stress the update starts from.
    double j1[3], j2[3], j3[3], c12[3], c23[3], c31[3];
    const double vol = brick_centre_jacobian(x, j1, j2, j3, c12, c23, c31);
    if (!(vol > 0.0)) {
      fb_element_off(g, i, false, vol);
      continue;
    }
    double b[8][3], L[3][3], D[6], so[6];
    brick_centre_gradients(c12, c23, c31, vol, b);
    brick_velocity_gradient(v, b, L);
    fb_strain_rate<kCorot>(g, i, L, dt1, D, so);

    // Density, strain rate, material.
    const double rho = solid_density(k.rho0, g.vol0[i], vol);
    const double mu = solid_mu(rho, k.rho0);
    const double rate = filtered_rate(k.alpha, strain_rate_measure(D), g.rate[i]);
    double sn[6] = {so[0], so[1], so[2], so[3], so[4], so[5]};
    double eps_p = g.eps_p[i], dmg = g.dmg[i], c_e = k.c;
    const SolidPointResult pr =
        fb_material<kLaw>(g, i, k, mat, x, D, rate, rho, mu, off, sn, eps_p, dmg, c_e);
    // Law 36 Eps_p_max and /FAIL/JOHNSON Ifail_so 1: 0.8 when the brick fails, then 0.8 per cycle, 0 below
    // 0.1; the forces and energies of this cycle take the new factor (as the
    // shells do, docs/theory/elements.md 6.4).
    const double off_new = brick_next_off(off, pr.element_fails);

    // Bulk viscosity, element step, energies, hourglass.
    const double l = std::cbrt(vol);
    const double ec = compression_rate(D);
    const double c_w = kLaw != TotalLaw::None ? c_e : k.c;
    const double q_new = bulk_viscosity(rho, ec, l, k.qa2, k.qb, c_w);
    const double dt_e = solid_step(brick_face_length(x, vol), c_w, k.qa2, k.qb, l, ec);
    const double de_int =
        solid_energy_increment(dt1, vol, g.vol[i], stress_power_sum(so, sn, D), g.q[i], q_new);
    const double svm = std::sqrt(von_mises2(sn));
    double hx[4][3], hg[4][3];
    const double de_hg = fb_hourglass(g, i, k, x, v, L, rho, l, c_w, hx, hg);

    // Nodal forces: stress part -V (sigma - q I) b_k, hourglass part -sum_j G_jk H_j; co-rotational: back to
    // global axes (f = R f'), and the frame kept for the stress output.
    double f[8][3];
    brick_nodal_forces(sn, q_new, vol, hg, hx, b, f);
    if constexpr (kCorot) {
      brick_from_frame(R, f);
      for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) g.frame[static_cast<std::size_t>(3 * c + r) * G + i] = R[r][c];
    }

    // Store.
    store_nodal_forces<8, 3>(g.nodal_force.data(), G, i, off_new, f);
#pragma GCC unroll 8
    for (int m = 0; m < 6; ++m) g.sig[static_cast<std::size_t>(m) * G + i] = sn[m];
    g.eps_p[i] = eps_p;
    g.dmg[i] = dmg;
    g.off[i] = off_new;
    g.vol[i] = vol;
    g.rho[i] = rho;
    g.q[i] = q_new;
    g.rate[i] = rate;
    g.e_int[i] += off_new * de_int;
    g.e_hg[i] += off_new * dt1 * de_hg;
    g.w_plastic[i] += off_new * svm * pr.deps_p * vol;
    g.dt[i] = dt_e;
    g.k_nodal[i] = solid_nodal_stiffness(0.25, rho, vol, dt_e);
  }
}

}  // namespace

void hex8_forces(BrickGroup& g, const NodeState& nodes, const MaterialParams& mat, const CycleInfo& cyc) {
  const TotalLaw law = mat.law == model::MaterialLaw::Ogden     ? TotalLaw::Ogden
                       : mat.law == model::MaterialLaw::FoamTab ? TotalLaw::Foam
                                                                : TotalLaw::None;
  const bool corot = g.iframe == 2;
  switch (law) {
    case TotalLaw::Ogden:
      if (corot)
        hex8_forces_impl<true, TotalLaw::Ogden>(g, nodes, mat, cyc);
      else
        hex8_forces_impl<false, TotalLaw::Ogden>(g, nodes, mat, cyc);
      break;
    case TotalLaw::Foam:
      if (corot)
        hex8_forces_impl<true, TotalLaw::Foam>(g, nodes, mat, cyc);
      else
        hex8_forces_impl<false, TotalLaw::Foam>(g, nodes, mat, cyc);
      break;
    case TotalLaw::None:
      if (corot)
        hex8_forces_impl<true, TotalLaw::None>(g, nodes, mat, cyc);
      else
        hex8_forces_impl<false, TotalLaw::None>(g, nodes, mat, cyc);
      break;
  }
}

}  // namespace radx::solver
