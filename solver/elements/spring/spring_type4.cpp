// TYPE4 spring (/SPRING with /PROP/SPRING, H = 0, 1, 2, 4, 5, 6, 7, 8): a 2-node axial spring, elastic
// (linear or by curve), elasto-plastic or with elastic hysteresis, and damping. The force acts along the
// current line n1 -> n2; the third node plays no part.
//
// Sources, read for the behaviour (OpenRadioss): engine/source/elements/spring/r1def3.F (length, elongation,
// Ileng, failure), redef3.F90 (the force law and the energy), r1len3.F (time step), r1cum3.F (nodal forces);
// starter hm_read_prop04.F (defaults), rmass.F (mass).
//
// Nodes x1, x2 at x^n; dt1 = t^n - t^{n-1}. l = |x2 - x1|, e = (x2 - x1) / l, L0 the initial length.
//   s = L0 with Ileng 1 (a spring per unit length), 1 otherwise
//   x = (l - L0) / s                          elongation (strain with Ileng 1), total form
//   v = (x - x_old) / dt1                     (0 on the first cycle)
//   N = the scalar spring law of x, x_old, v  (spring_law.hpp: linear or by curve, the hardening flag H,
//                                             damping; K, C per unit length with Ileng 1; H 8 takes the
//                                             length l itself, as Radioss does even with Ileng 1)
//   work: E += (x - x_old) (N + N_old) / 2 * s   (trapezoid; elastic and damping work together, as Radioss)
//   nodal forces: n1 += N e, n2 -= N e        (tension pulls the nodes together)
//   failure: the spring breaks when s x leaves [delta_min Ascale, delta_max Ascale] (hm_read_prop04.F
//     scales both limits by Ascale); N of the breaking cycle still acts, as in r1def3.F, and the spring
//     leaves the step vote; the next cycle N = 0 and the trapezoid books (x - x_old) N_old / 2, the work
//     of the last force over that step; after that the spring is skipped
// Time step (r1len3.F), with the spring's own mass m = M s, stiffness k = K / s, damping c = C / s:
//   dt = min( m / (sqrt(c^2 + m k) + c),  m / (2 c) )
//   which is sqrt(m / k) without damping: the period 2 pi sqrt((m/2) / (2 k)) of the spring's two half
//   masses divided by pi. The nodal stiffness for /DT/NODA is m / dt^2 on each node.
#include <algorithm>
#include <cmath>
#include <limits>

#include "solver/elements/element_groups.hpp"
#include "solver/elements/spring/spring_law.hpp"

namespace radx::solver {

void spring_type4_forces(SpringGroup& g, const NodeState& nodes, const CycleInfo& cyc) {
  constexpr std::size_t G = kGroupSize;
  const auto& p = g.props;
  const auto& law = p.x;
  const double inv_dt = cyc.dt1 > 0 ? 1.0 / cyc.dt1 : 0.0;
  for (int ii = 0; ii < g.count; ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    for (int d = 0; d < 6; ++d) g.nodal_force[static_cast<std::size_t>(d) * G + i] = 0.0;
    const auto n1 = static_cast<std::size_t>(g.conn[i]);
    const auto n2 = static_cast<std::size_t>(g.conn[G + i]);
    const double l0 = g.l0[i];
    const double s = p.ileng == 1 ? l0 : 1.0;
    // Step from the property: the same every cycle (r1len3.F has no geometric term for TYPE4).
    const double m = p.mass * s, k = law.stiffness / s, c = law.damping / s;
    double dt = m / std::max(1e-15, std::sqrt(c * c + m * k) + c);
    dt = std::min(dt, 0.5 * m / std::max(1e-15, c));
    // A broken spring that has released its last force is skipped; the cycle after the break still books
    // the work of that force (its force is 0 now).
    const bool broken = g.off[i] <= 0;
    if (broken && g.force[i] == 0.0) {
      g.dt[i] = std::numeric_limits<double>::infinity();
      g.k_nodal[i] = 0.0;
      continue;
    }
    const double ex = nodes.x[n2] - nodes.x[n1], ey = nodes.y[n2] - nodes.y[n1],
                 ez = nodes.z[n2] - nodes.z[n1];
    const double l = std::sqrt(ex * ex + ey * ey + ez * ez);
    const double inv_l = 1.0 / std::max(l, 1e-15);
    const double x = (l - l0) / s;
    const double x_old = g.dx[i] / s;
    const double v = (x - x_old) * inv_dt;
    double n = 0.0;
    const double elong = x * s;
    if (!broken) {
      auto st = g.law_state(i);
      n = spring_law_force(law, g.curves[0], x, x_old, v, l, st);
      g.store(i, st);
      if (elong > law.delta_max * law.ascale || elong < law.delta_min * law.ascale) g.off[i] = 0.0;
    }
    // A broken spring leaves the step vote from the cycle that breaks it on (r1len3.F reads the new OFF).
    g.dt[i] = g.off[i] > 0 ? dt : std::numeric_limits<double>::infinity();
    g.k_nodal[i] = g.off[i] > 0 ? m / (dt * dt) : 0.0;
    g.e_int[i] += (x - x_old) * (n + g.force[i]) * 0.5 * s;
    g.force[i] = n;
    g.dx[i] = elong;
    const double fx = n * ex * inv_l, fy = n * ey * inv_l, fz = n * ez * inv_l;
    g.nodal_force[0 * G + i] = fx;
    g.nodal_force[1 * G + i] = fy;
    g.nodal_force[2 * G + i] = fz;
    g.nodal_force[3 * G + i] = -fx;
    g.nodal_force[4 * G + i] = -fy;
    g.nodal_force[5 * G + i] = -fz;
  }
}

}  // namespace radx::solver
