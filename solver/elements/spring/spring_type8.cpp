// TYPE8 general spring (/SPRING with /PROP/SPR_GENE): six uncoupled springs between two nodes, along the
// three axes of a frame (global, a /SKEW/FIX, or a /SKEW/MOV whose current axes the engine sets each cycle)
// for the translations and about them for the rotations.
// Each follows the scalar spring law of spring_law.hpp (linear or by curve, H 0 1 2 4 5 6 7, damping; H 8,
// the force of the total length, is refused by the starter for TYPE8).
//
// Sources, read for the behaviour (OpenRadioss): engine/source/elements/spring/r2def3.F (elongations,
// failure), redef3.F90 (the law), r2len3.F (time step), r2cum3.F (nodal forces); starter hm_read_prop08.F
// (defaults), rmass.F (mass and inertia).
//
// Frame rows E_X, E_Y, E_Z; nodes x1, x2 at x^n, angular velocities w1, w2 at t^{n-1/2}; dt1 = t^n - t^{n-1}.
//   u_j = (x2 - x1) . E_j - (x2^0 - x1^0) . E_j^0      j = X Y Z, total form: the current axes E_j, the
//                                                      offsets of t = 0 in the initial axes E_j^0
//   r_j = r_j_old + dt1 (w2 - w1) . E_j                 j = X Y Z, rotations integrated incrementally
//   N_j = law_j(u_j, ...) forces; moments M_j = law_{3+j}(r_j, ...); failure, work and step: the six laws of
//     spring_six_laws.hpp, with k_t, c_t (k_r, c_r) the largest stiffness and damping of the three
//     translations (rotations)
//   nodal: F = sum_j N_j E_j, M = sum_j M_j E_j;  n1 += F, M;  n2 -= F, M
//     (Radioss's TYPE8 without Iequil: the couple of a shear force over the length is not balanced)
#include "solver/elements/element_groups.hpp"
#include "solver/elements/spring/spring_six_laws.hpp"

namespace radx::solver {

void spring_type8_forces(SpringGroup& g, const NodeState& nodes, const CycleInfo& cyc) {
  constexpr std::size_t G = kGroupSize;
  const auto& E = g.frame;
  const double inv_dt = cyc.dt1 > 0 ? 1.0 / cyc.dt1 : 0.0;
  // The step depends on the property only: the same families for every slot.
  const auto t = spring_family(g.props, 0), r = spring_family(g.props, 3);
  for (int ii = 0; ii < g.count; ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    if (spring_six_released(g, i)) {
      spring_six_off(g, i);
      continue;
    }
    spring_six_step(g, i, t, r);
    const auto n1 = static_cast<std::size_t>(g.conn[i]);
    const auto n2 = static_cast<std::size_t>(g.conn[G + i]);
    const double x21[3] = {nodes.x[n2] - nodes.x[n1], nodes.y[n2] - nodes.y[n1], nodes.z[n2] - nodes.z[n1]};
    const double w21[3] = {nodes.wx[n2] - nodes.wx[n1], nodes.wy[n2] - nodes.wy[n1],
                           nodes.wz[n2] - nodes.wz[n1]};
    double q[6], n[6];
    for (std::size_t d = 0; d < 3; ++d) {
      const double* e = &E[3 * d];
      q[d] = x21[0] * e[0] + x21[1] * e[1] + x21[2] * e[2] - g.x0[d * G + i];
      q[3 + d] = g.dx[(3 + d) * G + i] + cyc.dt1 * (w21[0] * e[0] + w21[1] * e[1] + w21[2] * e[2]);
    }
    spring_six_laws(g, i, q, inv_dt, n);
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
