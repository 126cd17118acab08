// Twenty-node quadratic brick (/BRIC20): serendipity shape functions (solver/model/hex20_shape.hpp), a
// product Gauss rule of 2 or 3 points along each natural direction (Isolid 16's Inpts, default 2 x 2 x 2),
// the stress updated at every point with the Jaumann rate. No hourglass control: OpenRadioss has none for
// this element either, and the rules built here leave no zero-energy mode on a regular element but the
// one mode of 2 x 2 x 2 that no neighbour shares (it does not propagate through a mesh).
//
// Sources, read for the behaviour (OpenRadioss, not copied): engine/source/elements/solid/solide20/
// s20forc3.F (order of the work, the characteristic length), s20deri3.F (Jacobian, point volumes,
// gradients, the U_a sums), s20defo3.F (strain rate and spin per point), s20fint3.F (forces per point),
// s20rst.F (shape functions); srota3.F, srho3.F and mqviscb.F shared with the other solids; starter
// s20mass3.F (lumped mass, nodal stiffness), hm_read_prop14.F and elbuf_ini.F (the rule from Isolid and
// Inpts).
//
// Nodes x_k (current geometry x^n) and velocities v_k^{n-1/2}, k = 1..20; dt1 = t^n - t^{n-1}. At each point
// p of the rule (natural coordinates xi_p, weight w_p):
//   J_p = sum_k x_k (x) dN_k/dxi (xi_p),  V_p = w_p det J_p,  b_pk = J_p^-T dN_k/dxi (xi_p) = grad N_k
//   L_p = sum_k v_k (x) b_pk,  D_p = sym L_p (engineering shears),  spin W_p as the brick's (3.2)
//   Jaumann rotation of the point's stress, mu_p = V0_p / V_p - 1 (the point's own density, srho3.F),
//   material: solid_point_update(de = D_p dt1, mu_p) (laws 1, 2, 36 and the other laws of the solid path)
// over the element: V = sum_p V_p, rho = rho0 V0 / V, D_mean = sum_p V_p D_p / V for the strain-rate filter
// and the bulk viscosity q = rho ec l (qa^2 l ec + qb c), ec = max(0, -tr D_mean), l = V^(1/3) (one q per
// element, as the fully integrated 8-node brick; OpenRadioss evaluates q point by point)
//   internal energy dE = sum_p dt1/2 V_p (V - dV/2)/V (sigma_old + sigma_new)_p : D_p - dV/2 (q_old + q_new)
//   plastic work sum_p svm_p d eps_p,p V_p
//   internal forces (added to the nodes): f_k = -sum_p V_p (sigma_p - q I) b_pk
//   characteristic length (s20forc3.F): U_k = sum_p V_p |b_pk|^2,
//     dx = sqrt(2 V / max(64 max_corners U_k, 96/7 max_mid-sides U_k))
//     (the quadratic modes and the corners' light lumped masses make it a fraction of the 8-node brick's
//     length of the same cube: test_hex20.cpp runs a bar at 0.9 of the step it gives)
//   element step (before the /DT scale; mqviscb.F): qt = qb c + qa^2 l ec, c_eff = qt + sqrt(qt^2 + c^2),
//     dt = dx / c_eff
//   nodal stiffness k = rho V (2/64) / dt^2 on each node (s20mass3.F's STI), so that a corner's nodal step
//     sqrt(2 (rho V / 64) / k) equals dt
//   output: sig = sum_p V_p sigma_p / V, eps_p the points' mean, dmg the largest point damage
//
// Deletion as the other solids: a point that fails (law 36 Eps_p_max, /FAIL/JOHNSON) starts the element's
// deletion (brick_next_off), this cycle's forces and energies scaled by the new factor. An element with a
// point volume V_p <= 0 (inverted, or not a number) gets zero force, dt = 0 and k = 0, keeps its state and
// stores the bad volume in `vol`: the engine reports it and stops (as s20deri3.F stops the run).
#include <algorithm>
#include <cmath>
#include <limits>

#include "solver/elements/element_gather.hpp"
#include "solver/elements/element_groups.hpp"
#include "solver/elements/solid/solid_stages.hpp"
#include "solver/model/hex20_shape.hpp"

namespace radx::solver {

namespace {

constexpr int kMaxPoints = 27;  // 3 x 3 x 3
constexpr std::size_t kN = 20;

// The rule's natural derivatives and weights, computed once per group and cycle (no allocation).
struct RuleTable {
  int np = 0;
  double w[kMaxPoints];
  double dN[kMaxPoints][20][3];
};

void make_rule_table(const std::array<int, 3>& n, RuleTable& t) {
  model::Hex20Rule rule;
  rule.n = n;
  t.np = rule.points();
  for (int p = 0; p < t.np; ++p) {
    double xi[3], N[20];
    rule.point(p, xi, t.w[p]);
    model::hex20_shape(xi[0], xi[1], xi[2], N, t.dN[p]);
  }
}

// Point p's volume V_p = w_p det J_p and gradients b[k][a] = dN_k/dx_a; false when det J_p <= 0 (or NaN).
bool point_gradients(const RuleTable& t, int p, const double x[20][3], double& vp, double b[20][3]) {
  double J[3][3];
  const double det = model::hex20_jacobian(x, t.dN[p], J);
  vp = t.w[p] * det;
  if (!(det > 0.0)) return false;
  const double id = 1.0 / det;
  // inv[c][a] = dxi_c / dx_a
  const double inv[3][3] = {
      {(J[1][1] * J[2][2] - J[1][2] * J[2][1]) * id, (J[0][2] * J[2][1] - J[0][1] * J[2][2]) * id,
       (J[0][1] * J[1][2] - J[0][2] * J[1][1]) * id},
      {(J[1][2] * J[2][0] - J[1][0] * J[2][2]) * id, (J[0][0] * J[2][2] - J[0][2] * J[2][0]) * id,
       (J[0][2] * J[1][0] - J[0][0] * J[1][2]) * id},
      {(J[1][0] * J[2][1] - J[1][1] * J[2][0]) * id, (J[0][1] * J[2][0] - J[0][0] * J[2][1]) * id,
       (J[0][0] * J[1][1] - J[0][1] * J[1][0]) * id}};
  for (std::size_t k = 0; k < kN; ++k)
    for (int a = 0; a < 3; ++a)
      b[k][a] = t.dN[p][k][0] * inv[0][a] + t.dN[p][k][1] * inv[1][a] + t.dN[p][k][2] * inv[2][a];
  return true;
}

// The element's per-point kinematics: volumes, gradients, strain rates and spins; false on a bad point.
struct Kinematics {
  double vp[kMaxPoints];
  double b[kMaxPoints][20][3];
  double D[kMaxPoints][6];
  double W[kMaxPoints][3];
  double U[20];
  double vol = 0;
};

bool element_kinematics(const RuleTable& t, const double x[20][3], const double v[20][3], double dt1,
                        Kinematics& k) {
  std::fill(std::begin(k.U), std::end(k.U), 0.0);
  k.vol = 0;
  for (int p = 0; p < t.np; ++p) {
    if (!point_gradients(t, p, x, k.vp[p], k.b[p])) return false;
    k.vol += k.vp[p];
    double L[3][3] = {};
    for (std::size_t n = 0; n < kN; ++n) {
      const double* bn = k.b[p][n];
      k.U[n] += k.vp[p] * (bn[0] * bn[0] + bn[1] * bn[1] + bn[2] * bn[2]);
      for (int a = 0; a < 3; ++a) {
        L[a][0] += v[n][a] * bn[0];
        L[a][1] += v[n][a] * bn[1];
        L[a][2] += v[n][a] * bn[2];
      }
    }
    double* D = k.D[p];
    D[0] = L[0][0], D[1] = L[1][1], D[2] = L[2][2];
    D[3] = L[0][1] + L[1][0], D[4] = L[1][2] + L[2][1], D[5] = L[2][0] + L[0][2];
    half_step_spin(L, dt1, k.W[p][0], k.W[p][1], k.W[p][2]);
  }
  return true;
}

// OpenRadioss's characteristic length of the element (s20forc3.F), from the U_k sums.
double step_length(const Kinematics& k) {
  double uc = 0, um = 0;
  for (std::size_t n = 0; n < 8; ++n) uc = std::max(uc, k.U[n]);
  for (std::size_t n = 8; n < kN; ++n) um = std::max(um, k.U[n]);
  return std::sqrt(2.0 * k.vol / std::max(64.0 * uc, 96.0 / 7.0 * um));
}

// What the material stage gives the element.
struct MaterialResult {
  double work = 0, w_pl = 0, eps_mean = 0, dmg_max = 0;
  bool fails = false;
};

// Material per point: the new stresses sn[p], the stress work over the step, the plastic work, the mean
// plastic strain and the largest damage.
MaterialResult point_materials(Hex20Group& g, std::size_t i, const RuleTable& t, const MaterialParams& mat,
                               double dt1, double off, double rate, double vavg_ratio, const Kinematics& k,
                               double sn[kMaxPoints][6]) {
  constexpr std::size_t G = kGroupSize;
  MaterialResult r;
  for (int p = 0; p < t.np; ++p) {
    const auto pp = static_cast<std::size_t>(p);
    double s[6], so[6];
    for (std::size_t m = 0; m < 6; ++m) s[m] = g.sig_p[(pp * 6 + m) * G + i];
    jaumann_rotate(s, k.W[p][0], k.W[p][1], k.W[p][2], so);
    const double mu = g.vol0_p[pp * G + i] / k.vp[p] - 1.0;
    const double* D = k.D[p];
    const double de[6] = {D[0] * dt1, D[1] * dt1, D[2] * dt1, D[3] * dt1, D[4] * dt1, D[5] * dt1};
    for (std::size_t m = 0; m < 6; ++m) sn[p][m] = so[m];
    double& ep = g.eps_p_p[pp * G + i];
    const SolidPointResult pr = solid_point_update(mat, rate, de, mu, sn[p], ep, g.dmg_p[pp * G + i], off);
    r.fails = r.fails || pr.element_fails;
    r.dmg_max = std::max(r.dmg_max, g.dmg_p[pp * G + i]);
    r.eps_mean += ep / t.np;
    r.work += 0.5 * dt1 * k.vp[p] * vavg_ratio * stress_power_sum(so, sn[p], D);
    r.w_pl += std::sqrt(von_mises2(sn[p])) * pr.deps_p * k.vp[p];
  }
  return r;
}

// Nodal forces f_k = -sum_p V_p (sigma_p - q I) b_pk and the volume-weighted mean stress.
void nodal_forces(const RuleTable& t, const Kinematics& k, const double sn[kMaxPoints][6], double q,
                  double f[20][3], double smean[6]) {
  for (std::size_t n = 0; n < kN; ++n) f[n][0] = f[n][1] = f[n][2] = 0.0;
  for (int m = 0; m < 6; ++m) smean[m] = 0.0;
  for (int p = 0; p < t.np; ++p) {
    const double* s = sn[p];
    const double vp = k.vp[p];
    const double T[3][3] = {{vp * (s[0] - q), vp * s[3], vp * s[5]},
                            {vp * s[3], vp * (s[1] - q), vp * s[4]},
                            {vp * s[5], vp * s[4], vp * (s[2] - q)}};
    for (std::size_t n = 0; n < kN; ++n) {
      const double* b = k.b[p][n];
      for (int a = 0; a < 3; ++a) f[n][a] -= T[a][0] * b[0] + T[a][1] * b[1] + T[a][2] * b[2];
    }
    for (int m = 0; m < 6; ++m) smean[m] += vp * s[m] / k.vol;
  }
}

// An element that does not run this cycle: deleted (dt = +inf), or with a point of non-positive volume (the
// volume stored as that point's, not-a-number kept, dt = 0: reported and stopped by the engine).
void element_off(Hex20Group& g, std::size_t i, bool deleted, double bad_volume) {
  clear_nodal_forces<20, 3>(g.nodal_force.data(), kGroupSize, i);
  if (deleted) {
    g.dt[i] = std::numeric_limits<double>::infinity();
  } else {
    g.vol[i] = std::isnan(bad_volume) ? bad_volume : std::min(bad_volume, 0.0);
    g.dt[i] = 0.0;
  }
  g.k_nodal[i] = 0.0;
}

}  // namespace

void hex20_init_geometry(Hex20Group& g, std::size_t i, const double x0[20][3]) {
  constexpr std::size_t G = kGroupSize;
  RuleTable t;
  make_rule_table(g.rule, t);
  double sum = 0;
  for (int p = 0; p < t.np; ++p) {
    double J[3][3];
    const double vp = t.w[p] * model::hex20_jacobian(x0, t.dN[p], J);
    g.vol0_p[static_cast<std::size_t>(p) * G + i] = vp;
    sum += vp;
  }
  g.vol0[i] = g.vol[i] = sum;
}

void hex20_forces(Hex20Group& g, const NodeState& nodes, const MaterialParams& mat, const CycleInfo& cyc) {
  constexpr std::size_t G = kGroupSize;
  const double dt1 = cyc.dt1;
  const double c = mat.c_solid;
  const double rho0 = mat.rho0;
  const double qa2 = g.qa * g.qa;
  const double qb = g.qb;
  const double alpha = rate_filter_alpha(mat, dt1);
  RuleTable t;  // per group and cycle, on the stack
  make_rule_table(g.rule, t);
  Kinematics k;
  double sn[kMaxPoints][6];

  const auto n = static_cast<std::size_t>(g.count);
  for (std::size_t i = 0; i < n; ++i) {
    const double off = g.off[i];
    if (off == 0.0) {
      element_off(g, i, true, 0.0);
      continue;
    }
    double x[20][3], v[20][3];
    gather_element<20>(g.conn.data(), G, i, nodes, x, v);
    if (!element_kinematics(t, x, v, dt1, k)) {
      double bad = 0;
      for (int p = 0; p < t.np; ++p) {
        double J[3][3];
        const double vp = t.w[p] * model::hex20_jacobian(x, t.dN[p], J);
        if (!(vp > 0.0)) {
          bad = vp;
          break;
        }
      }
      element_off(g, i, false, bad);
      continue;
    }
    const double vol = k.vol;
    double Dm[6] = {0, 0, 0, 0, 0, 0};
    for (int p = 0; p < t.np; ++p)
      for (int m = 0; m < 6; ++m) Dm[m] += k.vp[p] * k.D[p][m] / vol;

    const double rho = solid_density(rho0, g.vol0[i], vol);
    const double rate = filtered_rate(alpha, strain_rate_measure(Dm), g.rate[i]);
    const double dvol = vol - g.vol[i];
    const double vavg_ratio = (vol - 0.5 * dvol) / vol;
    const MaterialResult mr = point_materials(g, i, t, mat, dt1, off, rate, vavg_ratio, k, sn);

    // Bulk viscosity, step, energy.
    const double l = std::cbrt(vol);
    const double ec = compression_rate(Dm);
    const double q_new = bulk_viscosity(rho, ec, l, qa2, qb, c);
    const double dt_e = solid_step(step_length(k), c, qa2, qb, l, ec);
    const double de_int = mr.work - 0.5 * dvol * (g.q[i] + q_new);

    double f[20][3], smean[6];
    nodal_forces(t, k, sn, q_new, f, smean);
    const double off_new = brick_next_off(off, mr.fails);
    store_nodal_forces<20, 3>(g.nodal_force.data(), G, i, off_new, f);

    for (int p = 0; p < t.np; ++p)
      for (std::size_t m = 0; m < 6; ++m) g.sig_p[(static_cast<std::size_t>(p) * 6 + m) * G + i] = sn[p][m];
    for (std::size_t m = 0; m < 6; ++m) g.sig[m * G + i] = smean[m];
    g.eps_p[i] = mr.eps_mean;
    g.dmg[i] = mr.dmg_max;
    g.off[i] = off_new;
    g.vol[i] = vol;
    g.rho[i] = rho;
    g.q[i] = q_new;
    g.rate[i] = rate;
    g.e_int[i] += off_new * de_int;
    g.w_plastic[i] += off_new * mr.w_pl;
    g.dt[i] = dt_e;
    g.k_nodal[i] = solid_nodal_stiffness(2.0 / 64.0, rho, vol, dt_e);
  }
}

}  // namespace radx::solver
