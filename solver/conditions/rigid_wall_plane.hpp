// /RWALL/PLANE, kinematic formulation (Iform 0): docs/theory/elements.md 7.1, OpenRadioss
// constraints/general/rwall/rgwall.F (explicit branch, no friction filter) and rgwal0.F (RGWALF, RGWALT).
// Run after the accelerations are final and before the velocity update; v = v^{n-1/2}, a = a^n,
// dt12 = (dt1 + dt2)/2, n the unit normal (M1 - M)/|M1 - M|; the wall acts on the positive side.
//
// Wall point and velocity: fixed wall x_w = M, v_w = 0; moving wall (node_ID > 0, node N):
//     v_w = v_N + a_N dt12,   x_w = x_N + dt2 v_w        (predicted like the secondary nodes).
// For each secondary node (mass m):
//     v* = v + dt12 a,  x* = x + dt2 v*;   free if (x* - x_w).n > 0, or if (v* - v_w).n > 0 (separating).
//     Otherwise   u = (v - v_w).n,  p = a.n,  normal impulse  Fn = m (u + p dt12) n,
//     and the normal work  W += -1/2 dt1 m u (u + p dt12) / dt12   (~ -1/2 m u^2 on impact).
//   Slide 0 (sliding):   a <- a - p n,  v <- v - u n  (normal velocity becomes the wall's: perfectly
//                        plastic; positions are never pushed back).
//   Slide 1 (tied):      v <- v_w, a <- 0;  tangential impulse Ft = m ((v - v_w) + a dt12) - Fn (output).
//   Slide 2 (Coulomb mu, no filter): Ft = m ((v - v_w) + a dt12) - Fn;
//                        |Ft| <= mu |Fn|: stick (v <- v_w, a <- 0);
//                        else slip: Ft <- mu |Fn| Ft/|Ft|,  a <- a - p n - Ft/(m dt12),  v <- v - u n,
//                        tangential work W += -(v - v_w).Ft  (v after the normal correction).
// Wall force of the cycle (output, force of the nodes ON the wall): F = sum(Fn + Ft) / dt12; the
// normal and tangential parts are kept separately, and their impulses are accumulated for time history.
// /RWALL/PARAL (rgwalp.F): the plane law above on the parallelogram of corner x_w and edges e1 = M1 - M,
// e2 = M2 - M (carried along by a moving wall, never rotated), normal n = e1 x e2 / |e1 x e2|:
//     d0 = (x - x_w0).n (x_w0 the wall point now), v_r = v* - v_w, d* = d0 + (v_r.n) dt2,
//     tol = 2 dt1 max(|v_r.n|, |v_w.n - v_w.n of the last cycle|);
//   free if d* > 0 or d0 <= -tol (a node well behind the wall passes it), or if the point
//   c = x - x_w0 + v_r dt2 - d* n projected on the plane is outside the parallelogram: c = a e1 + b e2 with
//   a or b outside [0, 1] (Radioss's cross-product tests); free as well when separating (v_r.n > 0) above
//   the wall (d0 > 0). A node found behind the wall (d0 < 0) is also brought back onto it within the step:
//   the normal velocity it takes is v_p = -min(d0, 0)/dt2 relative to the wall instead of 0, so
//   Fn = m (u + p dt12 - v_p) n,  v <- v - (u - v_p) n,  tied or stuck: v <- v_w + v_p n, and the tangential
//   impulse is m ((v - v_w) + a dt12 - v_p n) - Fn. Radioss does not filter its friction (ifq is ignored).
// Moving wall dynamics (RGWALF): the force of the previous cycle acts on the wall node with the masses
// of the nodes that were in contact added to its inertia,
//     a_N <- (m_N a_N + F_prev) / (m_N + sum m_contact,prev)          (apply_wall_node_forces).
// This lagged coupling is Radioss's; it does not conserve momentum exactly when contact nodes separate
// at once (error m^2 V / (m_N + m) for one node of mass m hit at speed V).
// Not supported (construction throws std::runtime_error naming the wall): Iform 1 (penalty), friction
// filtering (ifq != 0, except on a parallelogram, which ignores it), a slide value other than 0, 1, 2.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "solver/engine/node_state.hpp"
#include "solver/model/model.hpp"

namespace radx::solver {

struct RigidWallOutput {
  std::int64_t id = 0;
  int contacts = 0;                                              // nodes treated in the last cycle
  std::array<double, 3> normal_force{}, tangential_force{};      // last cycle: sum of impulses / dt12
  std::array<double, 3> normal_impulse{}, tangential_impulse{};  // accumulated since the start
};

class RigidWalls {
 public:
  explicit RigidWalls(const model::Model& m);

  // Once, before cycle 0 (after /INIVEL): a moving wall's node gets the wall Mass added to its mass and
  // the velocity (VX0, VY0, VZ0).
  // A moving wall's node may have no mass, as in Radioss: it follows the directions /IMPVEL or /BCS impose
  // and, in the free ones, the lagged contact force over the contact mass.
  void initialize(NodeState& s) const;
  // Cycle step 5, right after a = f/m: moving walls receive the previous cycle's wall force.
  void apply_wall_node_forces(NodeState& s) const;
  // Cycle step 5, after the imposed velocities: the kinematic contact above. Returns the external work
  // booked this cycle. Precondition: dt1 + dt2 > 0.
  double apply(NodeState& s, double dt1, double dt2);

  [[nodiscard]] const std::vector<RigidWallOutput>& outputs() const { return out_; }
  [[nodiscard]] std::size_t size() const { return walls_.size(); }
  // Sets flags[n] = 1 for every secondary node and moving-wall node.
  void mark_nodes(std::vector<std::uint8_t>& flags) const {
    for (const auto& w : walls_) {
      if (w.node != model::kNone) flags[static_cast<std::size_t>(w.node)] = 1;
      for (const auto n : w.secondary) flags[static_cast<std::size_t>(n)] = 1;
    }
  }

 private:
  struct Wall {
    std::int32_t node = model::kNone;  // moving wall node
    int shape = 0;      // 0 plane (normal), 1 cylinder (axis `normal`), 2 sphere, 3 parallelogram
    double radius = 0;  // cylinder and sphere
    std::array<double, 3> edge1{}, edge2{}, edge12{};  // parallelogram: M1 - M, M2 - M, edge1 x edge2
    double edge12_sq = 0;                              // |edge1 x edge2|^2
    double vn_prev = 0;                                // parallelogram: v_w.n of the last cycle
    int slide = 0;
    double friction = 0, added_mass = 0;
    std::array<double, 3> point{}, normal{}, v0{};
    std::vector<std::int32_t> secondary;
    std::array<double, 3> force_prev{};  // sum(Fn + Ft)/dt12 of the last cycle, on the wall
    double contact_mass_prev = 0;
  };
  static bool curved_contact(const Wall& w, const NodeState& s, std::size_t n, double vsx, double vsy,
                             double vsz, double dt2, double xwx, double xwy, double xwz, double xw0x,
                             double xw0y, double xw0z, double& nx, double& ny, double& nz);
  // Parallelogram: whether the node meets the wall this cycle (and its push-back velocity v_p).
  static bool parallelogram_contact(const Wall& w, const NodeState& s, std::size_t n, double vsx, double vsy,
                                    double vsz, double dt1, double dt2, double xw0x, double xw0y, double xw0z,
                                    double vwx, double vwy, double vwz, double tol_wall, double& v_push);
  std::vector<Wall> walls_;
  std::vector<RigidWallOutput> out_;
};

}  // namespace radx::solver
