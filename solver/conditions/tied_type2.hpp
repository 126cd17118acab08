// /INTER/TYPE2, the kinematic tie (Spotflag 0 and 5) and the rigid tie (Spotflag 1), as a kinematic
// condition of the cycle. It lives in
// solver/ beside the rigid bodies, not in contact/: nothing is searched or penalised after t = 0, the
// secondary nodes are moved by a constraint, and its three steps sit between the force assembly and the
// velocity update like /RBODY's (kinematics.hpp for the call order).
//
// Each tie k holds a secondary node s on the main segment (x1..x4) by the map of solver/model/tied_map.hpp:
//     x_s = sum_j h_j x_j + d n(x1..x4),   n = N/|N|,  N = (x3 - x1) x (x4 - x2)  (triangle: (x2-x1) x
//     (x3-x1)),
// (r, s, d) fixed at t = 0. OpenRadioss (i2for3.F I2FOR3N, i2vit3.F I2VIT3N/I2ROT3) moves the node by
// sum h_j v_j and turns its offset with the main nodes' rotational velocities, so an offset from a solid
// face does not turn at all; radx turns d with the segment's own normal, for shells and solids alike.
//
// Set-up (initialize, once, before the rigid bodies form, so a body holding main nodes weighs the tied mass):
//   m_j += hc_j m_s, I_j += hc_j I_s (only main nodes with rotational inertia, as I2MOM3N), m_s = I_s = 0,
//   with hc the shape functions at (r, s) clamped onto the segment (a node just beyond an edge gives no
//   negative mass); the total mass is unchanged.
// Each cycle, after the contact forces and before a = f/m (transfer_forces), the transpose of the map's
// derivative, so the tie does no work:
//   f_j += h_j f_s                                          (translation; sum_j h_j = 1: momentum kept)
//   offset couple, g = d (1 - n n^T) f_s / |N|:  quad     f3 += b x g, f1 -= b x g, f4 += g x a, f2 -= g x a,
//                                                         a = x3 - x1, b = x4 - x2 (delta n = (1 - n n^T)
//                                                         delta N / |N|, delta N = delta a x b + a x delta
//                                                         b);
//                                               triangle  f2 += b x g, f3 += g x a, f1 -= b x g + g x a,
//                                                         a = x2 - x1, b = x3 - x1;
//   m_j += hc_j m_s (moments, main nodes with inertia); f_s = m_s = 0 (I2FOR3N, I2MOM3N).
// For /DT/NODA, after the elements' nodal stiffness (transfer_stiffness): K_j += |h_j| K_s, K_s = 1e-20.
// The couple forces sum to zero and their moment is d n x f_s's tangential part: linear and angular
// momentum are transferred exactly.
// Last kinematic condition before v += dt12 a (secondary_kinematics): the main nodes' accelerations are
// final, x_j^{n+1} = x_j + dt2 (v_j + dt12 a_j), and the secondary node is sent to its place on the map
//   v_s^{n+1/2} = (x_s(x^{n+1}) - x_s^n) / dt2,   a_s = (v_s^{n+1/2} - v_s^{n-1/2}) / dt12,
//   w_s^{n+1/2} = sum hc_j w_j^{n+1/2} over the main nodes with rotational inertia.
// Placing the node on the map of the new positions (rather than integrating sum h_j v_j + d dn/dt) keeps
// the offset to round-off under any rotation: no drift accumulates.
// No allocation per cycle. Ties are visited in interface and node order: the result is deterministic.
//
// Spotflag 1, the rigid tie (OpenRadioss i2for3.F I2FOMO3, i2vit3.F I2VIROT3; used when the model has
// rotational degrees of freedom: shells, springs or rigid bodies, IRODDL = 1; otherwise OpenRadioss runs it
// as Spotflag 0 and so does radx). The secondary node is a point of a rigid body carried by the segment:
// with the segment's nj distinct nodes (4, or 3 for a triangle), c = (1/nj) sum x_j, r_j = x_j - c, r0_j
// and q0 = x_s - c at t = 0,
//     x_s = c + R q0,   R = argmin_R sum_j |r_j - R r0_j|^2   (the least-squares rotation of the nodes:
//                                                             R^T K symmetric, K = sum_j r_j r0_j^T),
// and the node's rotation is R (w_s = the rate of R), so an offset off the segment's plane, in any
// direction, turns with the segment. R is found by Newton's method on the rotations from the last cycle's:
//     G = R^T K,  g = (G32 - G23, G13 - G31, G21 - G12),  delta = (tr G I - sym G)^-1 g,  R <- R
//     exp([delta]x)
// (quadratic convergence; two or three passes a cycle, and exact for a rigid motion of the segment; where
// tr G I - sym G is not positive definite, far from the fit, a gradient step instead, at most 0.5 rad).
// Virtual motion of the map: delta theta = A^-1 sum_j q_j x delta x_j, A = tr P I - P, P = K R^T (symmetric),
// q_j = R r0_j (delta c drops out of K because sum r0_j = 0). Its transpose moves the secondary's force f_s
// and moment m_s to the segment:
//     f_j += f_s / nj + a x q_j,   a = A^-1 (m_s + (x_s - c) x f_s),
// whose sum is f_s and whose moment about c is m_s + (x_s - c) x f_s: momentum and angular momentum are
// kept and the tie does no work. The main nodes' rotations receive nothing (I2FOMO3).
// Mass, at t = 0 (I2FOMO3's explicit branch for Spotflag 1): the secondary's rotational inertia about c,
// I_c = I_s + m_s |q0|^2, becomes point masses on the segment's nodes, large enough that their inertia
// mr J0 (J0 = tr P0 I - P0, P0 = sum r0_j r0_j^T) is at least I_c about every axis:
//     m_j += m_s / nj + mr,   mr = I_c / lambda_min(J0),   booked as added mass nj mr;   m_s = I_s = 0.
// (OpenRadioss takes for 1/lambda_min(J0) the largest row sum of J0^-1, the same for a segment along the
// global axes; radx's does not depend on how the segment is turned.) /DT/NODA: K_j += K_s / nj +
// K_s |q0|^2 / lambda_min(J0) (I2FOMO3 without the rotational stiffness, which radx's nodes do not carry).
// Each cycle (secondary_kinematics): R^{n+1} from x_j^{n+1}, x_s^{n+1} = c^{n+1} + R^{n+1} q0 as above,
// w_s^{n+1/2} = log(R^{n+1} R^{nT}) / dt2, aw_s = (w_s^{n+1/2} - w_s^{n-1/2}) / dt12.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "solver/engine/node_state.hpp"
#include "solver/model/model.hpp"

namespace radx::solver {

class TiedInterfaces {
 public:
  explicit TiedInterfaces(const model::Model& m);

  [[nodiscard]] bool empty() const { return node_.empty() && rnode_.empty(); }
  [[nodiscard]] std::size_t size() const { return node_.size() + rnode_.size(); }
  // Once, before the rigid bodies and after /INIVEL: masses and inertias to the main nodes, and the
  // secondary velocities put on the map.
  void initialize(NodeState& s);
  // Before a = f/m: forces and moments of the secondary nodes to their segments (the rigid ties' rotation
  // is fitted to the current positions first).
  void transfer_forces(NodeState& s);
  // /DT/NODA: the secondary nodes' stiffness to their segments, before the nodal steps are taken.
  void transfer_stiffness(NodeState& s) const;
  // Last condition before v += dt12 a. Precondition: dt1 + dt2 > 0; nothing is done when dt2 = 0.
  void secondary_kinematics(NodeState& s, double dt1, double dt2);
  // 1 for each tied secondary node.
  void mark_nodes(std::vector<std::uint8_t>& held) const;
  // The rigid ties' number (Spotflag 1 in a model with rotations) and, for tests, the rotation of tie k.
  [[nodiscard]] std::size_t rigid_size() const { return rnode_.size(); }
  [[nodiscard]] std::array<double, 9> rigid_rotation(std::size_t k) const;

 private:
  // One entry per tie, all interfaces in a row (structure of arrays).
  std::vector<std::int32_t> node_;
  std::vector<std::int32_t> seg_;  // 4 per tie
  std::vector<double> h_;          // 4 per tie: shape functions at (r, s)
  std::vector<double> hc_;         // 4 per tie: at (r, s) clamped onto the segment (mass, rotations)
  std::vector<double> offset_;
  std::vector<std::uint8_t> triangle_;
  // Rigid ties (Spotflag 1), apart so that neither loop branches on the formulation.
  std::vector<std::int32_t> rnode_;
  std::vector<std::int32_t> rseg_;  // 4 per tie (n4 == n3 for a triangle)
  std::vector<std::uint8_t> rnj_;   // 4, or 3 distinct nodes
  std::vector<double> r0_;          // 12 per tie: r0_j, the nodes about their centroid at t = 0
  std::vector<double> q0_;          // 3 per tie: x_s - c at t = 0
  std::vector<double> inv_lmin_;    // 1 / lambda_min(J0)
  std::vector<double> rot_;         // 9 per tie: R, row-major, of the last fit
};

}  // namespace radx::solver
