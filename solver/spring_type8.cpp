// TYPE8 general spring (/SPRING with /PROP/SPR_GENE): six uncoupled springs between two nodes, along the
// three axes of a fixed frame (global, or a /SKEW/FIX) for the translations and about them for the rotations.
// Each follows the scalar spring law of spring_law.hpp (linear or by curve, H 0 1 2 4 5 6 7, damping; H 8,
// the force of the total length, is refused by the starter for TYPE8).
//
// Sources, read for the behaviour (OpenRadioss): engine/source/elements/spring/r2def3.F (elongations,
// failure), redef3.F90 (the law), r2len3.F (time step), r2cum3.F (nodal forces); starter hm_read_prop08.F
// (defaults), rmass.F (mass and inertia).
//
// Frame rows E_X, E_Y, E_Z; nodes x1, x2 at x^n, angular velocities w1, w2 at t^{n-1/2}; dt1 = t^n - t^{n-1}.
//   u_j = (x2 - x1) . E_j - (x2^0 - x1^0) . E_j        j = X Y Z, total form (fixed frame)
//   r_j = r_j_old + dt1 (w2 - w1) . E_j                 j = X Y Z, rotations integrated incrementally
//   v_j = (u_j - u_j_old) / dt1                          (and likewise for r_j; 0 on the first cycle)
//   N_j = law_j(u_j, u_j_old, v_j)                       forces; moments M_j = law_{3+j}(r_j, ...)
//   nodal: F = sum_j N_j E_j, M = sum_j M_j E_j;  n1 += F, M;  n2 -= F, M
//     (Radioss's TYPE8 without Iequil: the couple of a shear force over the length is not balanced)
//   work: E += sum over the six (q - q_old) (N + N_old) / 2
//   failure (each limit scaled by its Ascale): d_j = q_j / delta_max_j when q_j > 0, q_j / delta_min_j
//     otherwise; Ifail 0: crit = max_j d_j; Ifail 1: crit = sum_j d_j^2; crit >= 1 breaks the spring
//     (no force from that cycle on). A limit of 0 in the deck is none (1e30).
// Time step (r2len3.F), M the mass, I the inertia, k and c the largest stiffness and damping of the three
// translations (resp. rotations):
//   dt = min( M / (sqrt(c_t^2 + M k_t) + c_t),  I / (sqrt(c_r^2 + I k_r) + c_r) )
//   (a family without stiffness nor damping sets no limit).
#include <algorithm>
#include <cmath>
#include <limits>

#include "solver/element_groups.hpp"
#include "solver/spring_law.hpp"

namespace radx::solver {

void spring_type8_forces(SpringGroup& g, const NodeState& nodes, const CycleInfo& cyc) {
  constexpr std::size_t G = kGroupSize;
  const auto& p = g.props;
  const auto& E = g.frame;
  const double inv_dt = cyc.dt1 > 0 ? 1.0 / cyc.dt1 : 0.0;
  // The step depends on the property only: once per group.
  double k_t = 0, c_t = 0, k_r = 0, c_r = 0;
  for (int d = 0; d < 3; ++d) {
    k_t = std::max(k_t, p.law(d).stiffness);
    c_t = std::max(c_t, p.law(d).damping);
    k_r = std::max(k_r, p.law(3 + d).stiffness);
    c_r = std::max(c_r, p.law(3 + d).damping);
  }
  const double dt_t = spring_step(p.mass, k_t, c_t);
  const double dt_r = spring_step(p.inertia, k_r, c_r);
  const double dt = std::min(dt_t, dt_r);
  // The nodal stiffness M / dt^2 carries the spring's step to the nodal time step (/DT/NODA); nodes have no
  // rotational stiffness, so the rotational step enters through the smaller of the two steps.
  const double k_nodal = dt < 1e30 ? p.mass / (dt * dt) : 0.0;
  for (int ii = 0; ii < g.count; ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    for (std::size_t d = 0; d < 12; ++d) g.nodal_force[d * G + i] = 0.0;
    if (g.off[i] <= 0) {
      for (std::size_t d = 0; d < 6; ++d) g.force[d * G + i] = 0.0;
      g.dt[i] = std::numeric_limits<double>::infinity();
      g.k_nodal[i] = 0.0;
      continue;
    }
    g.dt[i] = dt;
    g.k_nodal[i] = k_nodal;
    const auto n1 = static_cast<std::size_t>(g.conn[i]);
    const auto n2 = static_cast<std::size_t>(g.conn[G + i]);
    const double x21[3] = {nodes.x[n2] - nodes.x[n1], nodes.y[n2] - nodes.y[n1], nodes.z[n2] - nodes.z[n1]};
    const double w21[3] = {nodes.wx[n2] - nodes.wx[n1], nodes.wy[n2] - nodes.wy[n1],
                           nodes.wz[n2] - nodes.wz[n1]};
    double q[6], n[6];
    double crit = 0;
    for (std::size_t d = 0; d < 3; ++d) {
      const double* e = &E[3 * d];
      q[d] = x21[0] * e[0] + x21[1] * e[1] + x21[2] * e[2] - g.x0[d * G + i];
      q[3 + d] = g.dx[(3 + d) * G + i] + cyc.dt1 * (w21[0] * e[0] + w21[1] * e[1] + w21[2] * e[2]);
    }
    for (std::size_t d = 0; d < 6; ++d) {
      const auto& law = p.law(static_cast<int>(d));
      const double q_old = g.dx[d * G + i];
      const double v = (q[d] - q_old) * inv_dt;
      auto st = g.law_state(d * G + i);
      n[d] = spring_law_force(law, g.curves[d], q[d], q_old, v, 0.0, st);
      g.store(d * G + i, st);
      const double lim = q[d] > 0 ? q[d] / (law.delta_max * law.ascale) : q[d] / (law.delta_min * law.ascale);
      crit = p.ifail == 0 ? std::max(crit, lim) : crit + lim * lim;
    }
    if (crit >= 1.0) {
      g.off[i] = 0.0;
      for (double& v : n) v = 0.0;
    }
    double work = 0;
    for (std::size_t d = 0; d < 6; ++d) {
      work += (q[d] - g.dx[d * G + i]) * (n[d] + g.force[d * G + i]) * 0.5;
      g.force[d * G + i] = n[d];
      g.dx[d * G + i] = q[d];
    }
    g.e_int[i] += work;
    for (std::size_t c = 0; c < 3; ++c) {
      const double f = n[0] * E[c] + n[1] * E[3 + c] + n[2] * E[6 + c];
      const double m = n[3] * E[c] + n[4] * E[3 + c] + n[5] * E[6 + c];
      g.nodal_force[c * G + i] = f;
      g.nodal_force[(3 + c) * G + i] = m;
      g.nodal_force[(6 + c) * G + i] = -f;
      g.nodal_force[(9 + c) * G + i] = -m;
    }
  }
}

}  // namespace radx::solver
