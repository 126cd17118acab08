// The engine's single entry point to loads and kinematic conditions: it owns the objects of
// /GRAV, /CLOAD, /PLOAD, /BCS, /IMPVEL, /INIVEL, /RWALL, /RBODY and /INTER/TYPE2 and calls them in the order
// of the cycle (explicit_engine.hpp). It also computes the kinetic energy and momentum with the rigid-body
// corrections, so the time loop never needs to know which conditions exist.
#pragma once

#include <array>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "solver/conditions/rigid_body.hpp"
#include "solver/conditions/rigid_wall_plane.hpp"
#include "solver/conditions/skew_frames.hpp"
#include "solver/engine/node_state.hpp"
#include "solver/model/exact_sum.hpp"
#include "solver/model/model.hpp"
#include "solver/model/run_controls.hpp"

namespace radx::solver {

class RigidBodies;

class KinematicsDriver {
 public:
  // `skews`: the engine's current skew frames (updated by the engine at the start of each cycle);
  // `sensor_starts`: Sensors::starts() of the run, read at every call (may be empty when the model has no
  // sensor); both must outlive the driver.
  KinematicsDriver(const model::Model& m, const model::RunControls& c, NodeState& nodes,
                   const SkewFrames& skews, std::span<const double> sensor_starts = {});
  ~KinematicsDriver();
  KinematicsDriver(const KinematicsDriver&) = delete;
  KinematicsDriver& operator=(const KinematicsDriver&) = delete;

  // t = 0: fixed dofs, initial velocities, rigid-body set-up.
  void initial_conditions();
  // Step 1 of the cycle: external forces at time t into f*_ext (and moments into m*).
  void external_loads(double t, double dt1, double dt2);
  // Before a = f/m (after the contact forces): /INTER/TYPE2 secondary forces and moments to the main nodes.
  void transfer_tied_forces();
  // Whether transfer_tied_forces() moves anything (the model has /INTER/TYPE2 ties).
  [[nodiscard]] bool has_ties() const;
  // /DT/NODA, after the elements' nodal stiffness: the tied nodes' stiffness to their main nodes.
  void transfer_tied_stiffness();
  // Step 7: after a = f/m, before v += dt12 a.
  void kinematic_conditions(double t, double dt1, double dt2);
  // After x += dt2 v (moving frames of rigid bodies).
  void after_update(double dt2);
  // KE and momentum at the full step, v = v^{n-1/2} + dt1/2 a^n (docs/theory/elements.md section 8), as
  // exact sums (model::ExactSum: the same bits in any order of the nodes) over the nodes [first, last) of
  // each run, with the rigid bodies' correction (each body counted once) when `with_bodies`: on several
  // ranks each adds the nodes it owns and one the bodies, and the sums' bins add up to one rank's
  // (Comm::sum_exact).
  [[nodiscard]] KineticSums kinetic_sums(double dt1, std::span<const std::array<std::size_t, 2>> runs,
                                         bool with_bodies) const;
  [[nodiscard]] double external_work() const;
  // Correction to the nodal mass sum so that each rigid body counts once (exact: merge it into the sum of
  // the nodal masses before rounding).
  [[nodiscard]] model::ExactSum mass_correction() const;
  // Per node, 1 where a condition applied after the accelerations moves the node (/IMPVEL, rigid bodies
  // with their main node, rigid walls' secondary and moving nodes); /BCS only holds dofs and is not marked.
  [[nodiscard]] std::vector<std::uint8_t> held_nodes() const;
  // Rigid-wall forces of the last cycle and impulses since the start, one per /RWALL in model order.
  [[nodiscard]] const std::vector<RigidWallOutput>& wall_outputs() const;
  // The rigid bodies formed in this run (not those switched off by /RBODY/OFF), read-only for outputs.
  [[nodiscard]] const RigidBodies& rigid_bodies() const;
  // Rigid bodies released by their sensor since the last call, one line each; taken by the call.
  std::vector<std::string> take_messages();

 private:
  struct Parts;
  const model::Model& model_;
  const model::RunControls& controls_;
  NodeState& nodes_;
  const SkewFrames& skews_;
  std::span<const double> sensor_starts_;
  std::unique_ptr<Parts> parts_;
};

}  // namespace radx::solver
