// The six laws of a 6-degree-of-freedom spring (TYPE8 spring_type8.cpp, TYPE13 spring_type13.cpp), shared by
// both kernels once each has measured its six elongations q_j (j = X Y Z RX RY RZ) in its own frame.
//
//   N_j = law_j(q_j, q_j_old, v_j),  v_j = (q_j - q_j_old) / dt1 (0 on the first cycle)   (spring_law.hpp)
//   failure (each limit scaled by its Ascale): d_j = q_j / delta_max_j when q_j > 0, q_j / delta_min_j
//     otherwise; Ifail 0: crit = max_j d_j; Ifail 1: crit = sum_j d_j^2; crit >= 1 breaks the spring. As
//     Radioss tests the limits after the laws, the forces of the breaking cycle still act on the nodes, and
//     the spring no longer votes for that cycle's step; the next cycle the forces are 0 and the trapezoid
//     books the half increment (q - q_old) N_old / 2 that the last forces did over that step; after that the
//     slot is skipped. A limit of 0 in the deck is none (1e30). OpenRadioss r2def3.F, r4def3.F, r2len3.F
//     with Ifail2 = 0 (the other failure modes are refused by the starter).
//   work: E += sum_j (q_j - q_j_old) (N_j + N_j_old) / 2   (elastic and damping work together, as Radioss)
// Stable step (OpenRadioss r2len3.F), M the mass, I the inertia, k and c the translational (resp.
// rotational) stiffness and damping the caller gives:
//   dt = min( M / (sqrt(c_t^2 + M k_t) + c_t),  I / (sqrt(c_r^2 + I k_r) + c_r) )
//   (a family without stiffness nor damping sets no limit); nodal stiffness for /DT/NODA: M / dt^2.
#pragma once

#include <algorithm>
#include <cstddef>
#include <limits>

#include "solver/elements/element_groups.hpp"
#include "solver/elements/spring/spring_law.hpp"

namespace radx::solver {

// The largest stiffness and damping of laws [first, first + 3): a family's step parameters.
struct SpringFamilyStiffness {
  double k = 0, c = 0;
};
[[nodiscard]] inline SpringFamilyStiffness spring_family(const model::SpringProperty& p, int first) {
  SpringFamilyStiffness s;
  for (int d = first; d < first + 3; ++d) {
    s.k = std::max(s.k, p.law(d).stiffness);
    s.c = std::max(s.c, p.law(d).damping);
  }
  return s;
}

// Sets slot i's step and nodal stiffness from its translational and rotational families.
inline void spring_six_step(SpringGroup& g, std::size_t i, SpringFamilyStiffness t, SpringFamilyStiffness r) {
  const double dt = std::min(spring_step(g.props.mass, t.k, t.c), spring_step(g.props.inertia, r.k, r.c));
  g.dt[i] = dt;
  // Nodes have no rotational stiffness, so the rotational step enters /DT/NODA through the smaller step.
  g.k_nodal[i] = dt < 1e30 ? g.props.mass / (dt * dt) : 0.0;
}

// True once a broken slot's forces are all 0: nothing more happens in it, and the kernels skip it.
[[nodiscard]] inline bool spring_six_released(const SpringGroup& g, std::size_t i) {
  constexpr std::size_t G = kGroupSize;
  if (g.off[i] > 0) return false;
  for (std::size_t d = 0; d < 6; ++d)
    if (g.force[d * G + i] != 0.0) return false;
  return true;
}

// A released slot: no force, no step.
inline void spring_six_off(SpringGroup& g, std::size_t i) {
  constexpr std::size_t G = kGroupSize;
  for (std::size_t d = 0; d < 6; ++d) g.force[d * G + i] = 0.0;
  for (std::size_t d = 0; d < 12; ++d) g.nodal_force[d * G + i] = 0.0;
  g.dt[i] = std::numeric_limits<double>::infinity();
  g.k_nodal[i] = 0.0;
}

// Books the trapezoid work of the step from the stored state to (q, n) and stores them.
inline void spring_six_commit(SpringGroup& g, std::size_t i, const double (&q)[6], const double (&n)[6]) {
  constexpr std::size_t G = kGroupSize;
  double work = 0;
  for (std::size_t d = 0; d < 6; ++d) {
    work += (q[d] - g.dx[d * G + i]) * (n[d] + g.force[d * G + i]) * 0.5;
    g.force[d * G + i] = n[d];
    g.dx[d * G + i] = q[d];
  }
  g.e_int[i] += work;
}

// The six forces (moments) n of slot i from its elongations (rotations) q; tests failure, accumulates the
// work and stores q and n as the slot's state. Returns false when the spring is broken: in the cycle that
// breaks it n still holds the cycle's forces (and the slot leaves the step vote); in the cycle after, n = 0.
inline bool spring_six_laws(SpringGroup& g, std::size_t i, const double (&q)[6], double inv_dt,
                            double (&n)[6]) {
  constexpr std::size_t G = kGroupSize;
  const auto& p = g.props;
  if (g.off[i] <= 0) {
    for (std::size_t d = 0; d < 6; ++d) n[d] = 0.0;
    spring_six_commit(g, i, q, n);
    g.dt[i] = std::numeric_limits<double>::infinity();
    g.k_nodal[i] = 0.0;
    return false;
  }
  double crit = 0;
  for (std::size_t d = 0; d < 6; ++d) {
    const auto& law = p.law(static_cast<int>(d));
    const double q_old = g.dx[d * G + i];
    const double v = (q[d] - q_old) * inv_dt;
    auto st = g.law_state(d * G + i);
    // The length argument is H 8's, refused on six-law springs (check_formulations.cpp).
    n[d] = spring_law_force(law, g.curves[d], q[d], q_old, v, 0.0, st);
    g.store(d * G + i, st);
    const double lim = q[d] > 0 ? q[d] / (law.delta_max * law.ascale) : q[d] / (law.delta_min * law.ascale);
    crit = p.ifail == 0 ? std::max(crit, lim) : crit + lim * lim;
  }
  const bool alive = crit < 1.0;
  if (!alive) {
    g.off[i] = 0.0;
    g.dt[i] = std::numeric_limits<double>::infinity();
    g.k_nodal[i] = 0.0;
  }
  spring_six_commit(g, i, q, n);
  return alive;
}

}  // namespace radx::solver
