// Four-node tetrahedron, Itetra4 1000 (OpenRadioss's default): linear shape functions, so one point and a
// constant strain over the element; no hourglass modes exist, so there is no hourglass control.
//
// Sources, read for the behaviour (OpenRadioss engine/source/elements/solid/solide4/): s4forc3.F (order of
// the work), s4deri3.F (gradients, volume, characteristic length), s4defo3.F (strain rates), s4fint3.F
// (internal forces), s4cumu3.F (nodal stiffness); srota3.F, srho3.F, mqviscb.F shared with the brick;
// starter s4mass3.F (mass), hm_read_solid.F (node order). The stress update, bulk viscosity and energies are
// the one-point brick's (hex8_fb.cpp, docs/theory/elements.md 3.2, 3.3), which OpenRadioss runs through the
// same routines (mmain, mqviscb) for both.
//
// Nodes x_1..x_4 (current geometry x^n), velocities v^{n-1/2}; dt1 = t^n - t^{n-1}.
//   V = (x1 - x4) . ((x2 - x4) x (x3 - x4)) / 6      (Radioss's sign: > 0 when the right-hand normal of
//                                                      n1 n2 n3 points away from n4; the starter ensures it)
//   b_k = grad N_k = -(a_f)/(3 V) with a_f the outward area vector of the face opposite node k:
//         faces (outward) 1-2-3 opposite 4, 1-4-2 opposite 3, 1-3-4 opposite 2, 2-4-3 opposite 1, and
//         a_f = (xb - xa) x (xc - xa) / 2, so b_k = -((xb - xa) x (xc - xa)) / (6 V);
//         sum_k b_k = 0 and sum_k x_k (x) b_k = I (the linear field is reproduced exactly)
//   L  = sum_k v_k (x) b_k,  D = sym L (engineering shears D4 = Lxy + Lyx, ...), spin W as the brick (3.2)
//   Jaumann rotation of the stored stress, density rho = rho0 V0 / V, mu = rho / rho0 - 1,
//   material: solid_point_update(de = D dt1, mu) (LAW1, LAW2 and every law behind it),
//   strain-rate measure, bulk viscosity q = rho ec l (qa^2 l ec + qb c) with l = V^(1/3), ec = max(0, -tr D),
//   internal energy dE = dt1/2 Vavg (sigma_old + sigma_new) : D - dV/2 (q_old + q_new), plastic work
//   svm d_eps_p V: all exactly as the brick (hex8_fb.cpp)
//   internal forces (added to the nodes): f_k = -V (sigma - q I) b_k
//   characteristic length (s4deri3.F, default Idt1sol 0): dx = 1 / max_k |b_k| = the smallest height
//     = 3 V / largest face area
//   element step (before the /DT scale; mqviscb.F as the brick): qt = qb c + qa^2 l ec,
//     c_eff = qt + sqrt(qt^2 + c^2), dt = dx / c_eff
//   nodal stiffness (mqviscb.F gives rho V / dt^2, s4cumu3.F halves it for each of the 4 nodes):
//     k = rho V / (2 dt^2), so that a lone tetrahedron's nodal step sqrt(2 (rho V / 4) / k) equals dt
//
// An element with V <= 0 (or not a number) gets zero force, dt = 0 and k = 0, keeps its stress and energies
// and stores the bad volume in `vol`: the engine reports it and stops (Radioss's small-volume treatments,
// schkjabt3.F, are not reproduced). Elements with off == 0 give no force and dt = +inf; forces and energy
// increments are scaled by off. No tetrahedron switches to small strain under /DT/BRICK/CST.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "solver/elements/element_gather.hpp"
#include "solver/elements/element_groups.hpp"
#include "solver/elements/solid/solid_stages.hpp"

namespace radx::solver {

namespace {

// Outward faces of a positive tetrahedron (node positions 0..3), face f opposite node kOpposite[f];
// the same table as model::kTetraFaces.
constexpr int kFaces[4][3] = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
constexpr int kOpposite[4] = {3, 2, 1, 0};

// Face area vectors af_f (twice the face's area, outward) and the largest |af_f|^2; the volume V = d14 . (d24
// x d34) / 6 (returned; not positive for an inverted, flat or not-a-number element, whose gradients are then
// not computed) and the gradients b_k = -af_f / (6 V) of the node k opposite face f.
[[gnu::always_inline]] inline double tetra_geometry(const double x[4][3], double b[4][3], double& area2_max) {
  double af[4][3];
#pragma GCC unroll 4
  for (int f = 0; f < 4; ++f) {
    double e1[3], e2[3];
#pragma GCC unroll 3
    for (int d = 0; d < 3; ++d) {
      e1[d] = x[kFaces[f][1]][d] - x[kFaces[f][0]][d];
      e2[d] = x[kFaces[f][2]][d] - x[kFaces[f][0]][d];
    }
    cross3(e1, e2, af[f]);
    area2_max = std::max(area2_max, af[f][0] * af[f][0] + af[f][1] * af[f][1] + af[f][2] * af[f][2]);
  }
  double d14[3], d24[3], d34[3], c23[3];
#pragma GCC unroll 3
  for (int d = 0; d < 3; ++d) {
    d14[d] = x[0][d] - x[3][d];
    d24[d] = x[1][d] - x[3][d];
    d34[d] = x[2][d] - x[3][d];
  }
  cross3(d24, d34, c23);
  const double vol = (d14[0] * c23[0] + d14[1] * c23[1] + d14[2] * c23[2]) / 6.0;
  if (!(vol > 0.0)) return vol;
  const double inv6v = -1.0 / (6.0 * vol);
#pragma GCC unroll 4
  for (int f = 0; f < 4; ++f)
#pragma GCC unroll 3
    for (int d = 0; d < 3; ++d) b[kOpposite[f]][d] = af[f][d] * inv6v;
  return vol;
}

// Nodal forces f_k = -V (sigma - q I) b_k.
[[gnu::always_inline]] inline void tetra_nodal_forces(const double sn[6], double q_new, double vol,
                                                      const double b[4][3], double f[4][3]) {
  const double T[3][3] = {{vol * (sn[0] - q_new), vol * sn[3], vol * sn[5]},
                          {vol * sn[3], vol * (sn[1] - q_new), vol * sn[4]},
                          {vol * sn[5], vol * sn[4], vol * (sn[2] - q_new)}};
#pragma GCC unroll 4
  for (int k = 0; k < 4; ++k)
#pragma GCC unroll 3
    for (int a = 0; a < 3; ++a) f[k][a] = -(T[a][0] * b[k][0] + T[a][1] * b[k][1] + T[a][2] * b[k][2]);
}

// The strain rate D (engineering shears) from the velocity gradient L[a][c] = d v_a / d x_c, and the stored
// stress turned by the Jaumann spin of the half step (old values on the right-hand side).
[[gnu::always_inline]] inline void tetra_strain_rate(const TetraGroup& g, std::size_t i, const double v[4][3],
                                                     const double b[4][3], double dt1, double D[6],
                                                     double so[6]) {
  constexpr std::size_t G = kGroupSize;
  double L[3][3] = {};
#pragma GCC unroll 4
  for (int k = 0; k < 4; ++k)
#pragma GCC unroll 3
    for (int a = 0; a < 3; ++a) {
      L[a][0] += v[k][a] * b[k][0];
      L[a][1] += v[k][a] * b[k][1];
      L[a][2] += v[k][a] * b[k][2];
    }
  D[0] = L[0][0], D[1] = L[1][1], D[2] = L[2][2];
  D[3] = L[0][1] + L[1][0], D[4] = L[1][2] + L[2][1], D[5] = L[2][0] + L[0][2];
  double wx, wy, wz;
  half_step_spin(L, dt1, wx, wy, wz);
  double s[6];
#pragma GCC unroll 6
  for (int m = 0; m < 6; ++m) s[m] = g.sig[static_cast<std::size_t>(m) * G + i];
  jaumann_rotate(s, wx, wy, wz, so);
}

}  // namespace

void tetra4_forces(TetraGroup& g, const NodeState& nodes, const MaterialParams& mat, const CycleInfo& cyc) {
  constexpr std::size_t G = kGroupSize;
  const double dt1 = cyc.dt1;
  const double c = mat.c_solid;
  const double rho0 = mat.rho0;
  const double qa2 = g.qa * g.qa;
  const double qb = g.qb;
  const double alpha = rate_filter_alpha(mat, dt1);
  const double inf = std::numeric_limits<double>::infinity();

  const std::int32_t* conn = g.conn.data();
  double* force = g.nodal_force.data();

  const auto n = static_cast<std::size_t>(g.count);
  for (std::size_t i = 0; i < n; ++i) {
    const double off = g.off[i];
    if (off == 0.0) {
      clear_nodal_forces<4, 3>(force, G, i);
      g.dt[i] = inf;
      g.k_nodal[i] = 0.0;
      continue;
    }

    double x[4][3], v[4][3];
    gather_element<4>(conn, G, i, nodes, x, v);

    // Face area vectors (twice the area, outward), volume, gradients.
    double b[4][3], area2_max = 0.0;
    const double vol = tetra_geometry(x, b, area2_max);
    if (!(vol > 0.0)) {  // inverted, flat or not a number: reported and stopped by the engine
      clear_nodal_forces<4, 3>(force, G, i);
      g.vol[i] = vol;
      g.dt[i] = 0.0;
      g.k_nodal[i] = 0.0;
      continue;
    }

    // Strain rate and the stored stress turned by the half-step spin.
    double D[6], so[6];
    tetra_strain_rate(g, i, v, b, dt1, D, so);

    // Density, strain rate, material.
    const double rho = solid_density(rho0, g.vol0[i], vol);
    const double mu = solid_mu(rho, rho0);
    const double rate = filtered_rate(alpha, strain_rate_measure(D), g.rate[i]);
    const double de[6] = {D[0] * dt1, D[1] * dt1, D[2] * dt1, D[3] * dt1, D[4] * dt1, D[5] * dt1};
    double sn[6] = {so[0], so[1], so[2], so[3], so[4], so[5]};
    double eps_p = g.eps_p[i];
    double dmg = g.dmg[i];
    const SolidPointResult pr = solid_point_update(mat, rate, de, mu, sn, eps_p, dmg, off);
    const double deps_p = pr.deps_p;
    // Law 36 Eps_p_max and /FAIL/JOHNSON Ifail_so 1 start the deletion as for the one-point brick
    // (brick_next_off). As in hex8_fb.cpp, this cycle's forces and energies take the new factor: 0.8 in the
    // failure cycle, none in the cycle that deletes it (with the factor at entry a tetrahedron reported
    // deleted still pushed on its nodes for one cycle).
    g.dmg[i] = dmg;
    const double off_new = brick_next_off(off, pr.element_fails);
    g.off[i] = off_new;

    // Bulk viscosity and element step.
    const double l = std::cbrt(vol);
    const double ec = compression_rate(D);
    const double q_new = bulk_viscosity(rho, ec, l, qa2, qb, c);
    const double dx = 6.0 * vol / std::sqrt(area2_max);  // 3 V / (largest face area)
    const double dt_e = solid_step(dx, c, qa2, qb, l, ec);

    // Energies.
    const double de_int =
        solid_energy_increment(dt1, vol, g.vol[i], stress_power_sum(so, sn, D), g.q[i], q_new);
    const double svm = std::sqrt(von_mises2(sn));

    // Nodal forces f_k = -V (sigma - q I) b_k.
    double f[4][3];
    tetra_nodal_forces(sn, q_new, vol, b, f);
    store_nodal_forces<4, 3>(force, G, i, off_new, f);
#pragma GCC unroll 6
    for (int m = 0; m < 6; ++m) g.sig[static_cast<std::size_t>(m) * G + i] = sn[m];
    g.eps_p[i] = eps_p;
    g.vol[i] = vol;
    g.rho[i] = rho;
    g.q[i] = q_new;
    g.rate[i] = rate;
    g.e_int[i] += off_new * de_int;
    g.w_plastic[i] += off_new * svm * deps_p * vol;
    g.dt[i] = dt_e;
    g.k_nodal[i] = solid_nodal_stiffness(0.5, rho, vol, dt_e);
  }
}

}  // namespace radx::solver
