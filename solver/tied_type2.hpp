// /INTER/TYPE2, the kinematic tie (Spotflag 0 and 5), as a kinematic condition of the cycle. It lives in
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
#pragma once

#include <cstdint>
#include <vector>

#include "solver/model/model.hpp"
#include "solver/node_state.hpp"

namespace radx::solver {

class TiedInterfaces {
 public:
  explicit TiedInterfaces(const model::Model& m);

  [[nodiscard]] bool empty() const { return node_.empty(); }
  [[nodiscard]] std::size_t size() const { return node_.size(); }
  // Once, before the rigid bodies and after /INIVEL: masses and inertias to the main nodes, and the
  // secondary velocities put on the map.
  void initialize(NodeState& s);
  // Before a = f/m: forces and moments of the secondary nodes to their segments.
  void transfer_forces(NodeState& s) const;
  // /DT/NODA: the secondary nodes' stiffness to their segments, before the nodal steps are taken.
  void transfer_stiffness(NodeState& s) const;
  // Last condition before v += dt12 a. Precondition: dt1 + dt2 > 0; nothing is done when dt2 = 0.
  void secondary_kinematics(NodeState& s, double dt1, double dt2) const;
  // 1 for each tied secondary node.
  void mark_nodes(std::vector<std::uint8_t>& held) const;

 private:
  // One entry per tie, all interfaces in a row (structure of arrays).
  std::vector<std::int32_t> node_;
  std::vector<std::int32_t> seg_;  // 4 per tie
  std::vector<double> h_;          // 4 per tie: shape functions at (r, s)
  std::vector<double> hc_;         // 4 per tie: at (r, s) clamped onto the segment (mass, rotations)
  std::vector<double> offset_;
  std::vector<std::uint8_t> triangle_;
};

}  // namespace radx::solver
