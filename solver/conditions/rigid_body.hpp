// /RBODY: docs/theory/elements.md 7.2, docs/keywords.md /RBODY; OpenRadioss starter inirby.F (set-up), engine
// rgbodfp.F (force gathering, Euler step), rgbodv.F (secondary kinematics), rgbcor.F (energy correction).
// Notation: main node N, secondary nodes s with mass m_s, scalar nodal inertia I_s, r_s = x_s - x_N;
// v = v^{n-1/2}, w = angular velocity omega^{n-1/2}, dt12 = (dt1 + dt2)/2.
//
// Set-up (initialize, once before cycle 0). m_N = own mass + deck Mass (0 -> 1e-20), M0 = m_N:
//   ICoG 1: x_N moved to the centre of mass of {N, s}, M = M0 + sum m_s;
//   ICoG 2: x_N moved to the centre of mass of the secondaries, M = M0 + sum m_s;
//   ICoG 3: x_N kept, M = M0 + sum m_s;       ICoG 4: x_N kept, M = M0 (secondary masses ignored).
//   Inertia tensor about the (new) x_N:
//     I = J_deck + I_N 1 + M0 (|d|^2 1 - d d^T) + sum_s [I_s 1 + m_s (|r_s|^2 1 - r_s r_s^T)]
//     with d = old x_N - new x_N (ICoG 1; 0 otherwise); the secondary terms are left out for ICoG 4,
//     and 1e-20 is added to the diagonal for a single secondary node.
//   Principal values I1 I2 I3 and axes (Eigen, right-handed). Ispher 1: all three = their mean;
//   Ispher 2: each I_i < 1e-3 I_max gets + 0.1 I_max. The main node gets mass M and scalar inertia
//   min(I_i); the secondaries keep theirs and get v_s = v_N + w_N x r_s, w_s = w_N.
// Each cycle:
//   gather_and_accelerate (after a = f/m):  F = f_N + sum f_s,  Mom = m_N + sum (m_s + r_s x f_s)
//     (written to f_N and m_N for output; the sums over s alone are kept for /TH/RBODY), secondary
//     stiffness moved to the main node; rotation += omega^{n-1/2} dt1;
//     a_N = F / M;  the principal frame is advanced by the rotation omega^{n-1/2} dt1 (exact rotation);
//     Euler in the principal frame:  alpha_i = (Mom_i + (I_j - I_k) w_j w_k) / I_i   (i j k cyclic),
//     w = omega^{n-1/2}. With fixed rotations on the main node (/BCS) the global system
//     I alpha = Mom - w x (I w) is solved for the free components, the fixed ones are 0.
//   secondary_kinematics (last condition before the velocity update): with omega = w_N + dt12 aw_N
//     (= omega^{n+1/2}) and v_N^{n+1/2} = v_N + dt12 a_N, the secondaries' accelerations are overwritten
//     so that after v += dt12 a
//         v_s^{n+1/2} = v_N^{n+1/2} + (R(omega dt2) - 1) r_s / dt2
//                     = v_N^{n+1/2} + c1 omega x r_s + c2 dt2 omega x (omega x r_s),
//         c1 = sin(phi)/phi, c2 = (1 - cos(phi))/phi^2, phi = |omega| dt2,      w_s^{n+1/2} = omega.
//     Radioss (rgbodv.F) uses c1 = 1, c2 = 1/2, the first terms of these series; with the exact rotation
//     x_s^{n+1} - x_N^{n+1} = R r_s, so distances inside the body are kept to round-off (Radioss's form
//     stretches them by phi^4/8 per cycle). The difference in velocity is O(phi^2) relative.
//   kinetic_correction (energy balance, print time, v + dt1/2 a): subtract the secondaries' KE (both
//     parts), their mass and momentum, and replace the main node's isotropic rotational KE
//     1/2 I_N |w|^2 by 1/2 sum I_i w_i^2 in the principal frame (rgbcor.F).
// A body with a sensor (OpenRadioss hm_read_rbody.F, inirby.F INIRBYS, rbyonf.F RBYSENS, rbypid.F):
//   - it is formed from its secondary nodes alone: the main node's own mass and inertia become 0, the deck's
//     Mass and J are not used, and the set-up is ICoG 2's (main node at the secondaries' centre of mass); its
//     velocity and angular velocity are those that keep the secondaries' momentum and angular momentum
//     (v_N = sum m_s v_s / M, omega = I^-1 sum (r_s x m_s v_s + I_s w_s));
//   - when its sensor is already on at t = 0 it is never formed (the nodes move freely, the main node has no
//     mass);
//   - at the first cycle with t_n > T (the sensor's activation time) it is marked for release, and 2 cycles
//     later it is released: no more gathering nor secondary kinematics, the main node keeps no mass nor
//     inertia, the secondaries go on from the rigid velocities they had (and get their weight again).
//   Radioss forms the body again if the sensor switches off; the starter refuses that use (a sensor with
//   Tstop), so a released body stays released.
// A body of /MAT/RIGID (model::RigidBody::rigid_material) is formed as one with a sensor that never releases
// it: the starter gives it an added main node (OpenRadioss rigid_mat.F has none; the motion is the same).
// Not supported (construction throws std::runtime_error): a body without main node. Skews, /RBODY/ON and
// rigid-body hierarchies are not handled (the starter rejects skews).
// No allocation in the per-cycle calls, except the messages when a body is released.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "solver/engine/node_state.hpp"
#include "solver/model/exact_sum.hpp"
#include "solver/model/model.hpp"

namespace radx::solver {

struct RigidBodyInfo {
  std::int64_t id = 0;
  std::string name;  // "/RBODY/id", or the /MAT/RIGID material's body, for messages
  std::int32_t main = model::kNone;
  std::vector<std::int32_t> secondary;
  std::int32_t sensor = model::kNone;  // dense index into model.sensors: the sensor that releases the body
  bool active = true;                  // false once released by its sensor (or never formed)
  int release_in = 0;                  // cycles left before the release (0: none pending)
  int ispher = 2, icog = 1;
  // Formed from its secondary nodes alone (a body with a sensor, or one of /MAT/RIGID's): no own mass or
  // inertia at the main node, ICoG 2, and the velocities that keep the secondaries' momenta.
  bool from_secondaries = false;
  double mass = 0;                          // M, the main node's mass after set-up
  std::array<double, 6> tensor{};           // global inertia tensor at set-up: Ixx Iyy Izz Ixy Iyz Ixz
  std::array<double, 3> principal{};        // I1 I2 I3 in use (after Ispher)
  std::array<double, 9> axes{};             // row i = principal axis i in global components (R: w_p = R w)
  std::array<double, 3> force{}, moment{};  // gathered in the last cycle (global, about x_N)
  // The secondary nodes' share of force and moment (about x_N) in the last cycle: what the body receives
  // through them (elements, contact, loads on them), without what acts on the main node itself (its own
  // loads, the body's weight). OpenRadioss's /TH/RBODY FX.. MZ (rgbodfp.F).
  std::array<double, 3> secondary_force{}, secondary_moment{};
  std::array<double, 3> rotation{};  // sum of omega^{n-1/2} dt1 since t = 0, global axes (/TH/RBODY RX..)
};

// Inertia tensor of body b in use at its current orientation, global axes, about x_N: R^T diag(I_i) R
// (the principal values after Ispher). Ixx Iyy Izz Ixy Iyz Ixz.
std::array<double, 6> current_inertia(const RigidBodyInfo& b);

// The reported sums over the nodes (translational and rotational KE, mass, momentum), exact and order-free
// (docs/theory/elements.md 8.1): a rigid body's correction added to them cancels its secondaries' node
// terms exactly.
struct KineticSums {
  model::ExactSum translational, rotational, mass;
  std::array<model::ExactSum, 3> momentum;
};

class RigidBodies {
 public:
  // `inactive`: user ids of the bodies switched off for this run (/RBODY/OFF).
  explicit RigidBodies(const model::Model& m, std::span<const std::int64_t> inactive = {});

  // Once before cycle 0, after the nodal masses and inertias, /INIVEL and rigid walls are in the state.
  // `sensor_starts`: Sensors::starts() after the check at t = 0 (may be empty when no body has a sensor).
  void initialize(NodeState& s, std::span<const double> sensor_starts = {});
  // Per node: 1 for a secondary node of an active rigid body (for ExternalLoads; a released body's nodes
  // are cleared).
  [[nodiscard]] const std::vector<std::uint8_t>& secondary_flags() const { return secondary_flag_; }

  // Cycle step 5, after a = f/m (before the boundary conditions). t = t_n, dt1 = t_n - t_{n-1}. Releases the
  // bodies whose sensor asks for it first (see above).
  void gather_and_accelerate(NodeState& s, double t, double dt1, std::span<const double> sensor_starts = {});
  // Cycle step 5, last kinematic condition before v += dt12 a. Precondition: dt1 + dt2 > 0.
  void secondary_kinematics(NodeState& s, double dt1, double dt2) const;
  // Energy balance at print time (velocities v + dt1/2 a): adds to `sums` what makes each rigid body count
  // once in the sums over all nodes (docs/theory/elements.md 7.2 point 5).
  void kinetic_correction(const NodeState& s, double dt1, KineticSums& sums) const;
  // Kinetic energy of body b at print time: 1/2 M |v_N|^2 + 1/2 sum I_i w_i^2.
  [[nodiscard]] double kinetic_energy(std::size_t b, const NodeState& s, double dt1) const;

  [[nodiscard]] const std::vector<RigidBodyInfo>& bodies() const { return bodies_; }
  [[nodiscard]] std::size_t size() const { return bodies_.size(); }
  // One line per body marked for release or released since the last call; taken (emptied) by the call.
  std::vector<std::string> take_messages();

 private:
  void release(RigidBodyInfo& b, NodeState& s);
  std::vector<std::string> messages_;
  std::vector<RigidBodyInfo> bodies_;
  std::vector<double> deck_mass_;
  std::vector<std::array<double, 6>> deck_inertia_;
  std::vector<std::uint8_t> secondary_flag_;
};

}  // namespace radx::solver
