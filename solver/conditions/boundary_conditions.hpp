// Nodal kinematic conditions: /BCS, /IMPVEL, /IMPDISP, /IMPDISP/FGEO, /INIVEL/TRA (docs/keywords.md;
// docs/theory/elements.md sections 0 and 8; OpenRadioss constraints/general/impvel/fixvel.F, fixfingeo.F,
// loads/general/inivel/inivel_start.F90). v is the state's v^{n-1/2}, a the accelerations of the cycle, dt12
// = (dt1 + dt2) / 2.
//
//   /BCS      the fixed bits (bit 0..2 Tx Ty Tz, 3..5 Rx Ry Rz) are OR-ed into state.fixed once; each call
//             of apply() zeroes both v and a of the fixed components (translations and rotations).
//             It does no work (docs/theory/elements.md 8).
//   /IMPVEL   active for Tstart <= t <= Tstop. With v_imp(t) = Fscale_y f(t / Ascale_x), the imposed
//             dof gets
//                 a_imp = (v_imp(t + dt2/2) - v^{n-1/2}) / dt12,
//             so that v^{n+1/2} = v_imp(t_n + dt2/2). Reaction R = m (a_imp - a_free) (m: scalar
//             inertia for XX YY ZZ). Work of the cycle
//                 DW = 1/4 m (a_imp dt12 + 2 v^{n-1/2}) (a_imp - a_free) = 1/2 R vbar,
//                 vbar = v^{n-1/2} + 1/2 a_imp dt12,
//             booked as dt1 DW now and dt2 DW at the next apply() (total dt12 R vbar). For a free node
//             this is exactly 1/2 m ((v^{n+1/2})^2 - (v^{n-1/2})^2) per cycle.
//   /IMPDISP  the same with the velocity that reaches the imposed displacement u(t) = Fscale_y f(t /
//   Ascale_x)
//             from the initial position X0 at the end of the step (translations only):
//                 v_imp = (u(t_n + dt2) - (x^n - X0)) / dt2,   so x^{n+1} = X0 + u(t_{n+1}) exactly;
//             the reaction and work as /IMPVEL.
//   /IMPDISP/FGEO  (fixfingeo.F) the same along a direction u_k and with a scale D_k per node: the
//             straight line from X0 to the final position XF, u = (XF - X0)/D, D = |XF - X0|; the
//             displacement along u is u(t) = D f(t Ascale) (Radioss's time scale, the inverse of /IMPDISP's),
//             and the node's whole acceleration is replaced by a_imp u (the components across the line are
//             removed, so a node starting at rest stays on it). A node already at its final position
//             (D = 0) keeps its velocity: its acceleration is zeroed.
//   /INIVEL/ROT  omega = (Vx, Vy, Vz) on the group's nodes (their rotational dofs; a rigid body takes its
//             main node's), as /INIVEL/TRA otherwise.
//   /INIVEL/TRA  v = (Vx, Vy, Vz) on the group's nodes, at t = 0 (Tstart = 0) or at the first cycle
//             with t_n >= Tstart.
// Skews: every direction named in a skew is read from SkewFrames when the condition acts, so a /SKEW/MOV
// gives the frame of the cycle's x^n (a /BCS holds the directions of the current axes, an /IMPVEL or
// /IMPDISP acts along the current axis, an /INIVEL takes the axes of the time it applies: t = 0 unless
// Tstart or a sensor says otherwise).
// Sensors (solver/conditions/sensors.hpp; OpenRadioss fixvel.F, inivel_start.F90), T the sensor's activation
// time (model::kNever while it is off), tau = t - T:
//   /IMPVEL   also needs tau >= 0 (Tstart and Tstop still bound t itself); v_imp = Fscale_y f((tau + dt2/2) /
//             Ascale_x): the function's time origin is the activation.
//   /IMPDISP  also needs tau >= 0. At tau = 0 as without a sensor, v_imp = (u(tau + dt2) - (x^n - X0)) / dt2;
//             for tau > 0 the displacement follows the function's increments from where the node was,
//             v_imp = (u(tau + dt2) - u(tau)) / dt2 (fixvel.F's YC - YC0).
//   /IMPDISP/FGEO  also needs tau >= 0, and always drives the node to its absolute place on its line,
//             v_imp = (D f(tau + dt2) - (x^n - X0).u) / dt2 (OpenRadioss fixfingeo.F: no increments).
//   /INIVEL   applied at the first cycle with t_n >= T (Tstart = 0), or >= min(Tstart, T).
// Frames are 0 in a valid model (the starter rejects them). No allocation in the per-cycle calls.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "solver/conditions/skew_frames.hpp"
#include "solver/engine/node_state.hpp"
#include "solver/model/model.hpp"

namespace radx::solver {

class BoundaryConditions {
 public:
  // `skews` must outlive this object (as for the classes below).
  BoundaryConditions(const model::Model& m, const SkewFrames& skews);
  // Once, before cycle 0: state.fixed |= the /BCS bits.
  void set_fixed_bits(NodeState& s) const;
  // Zero v and a of the fixed components (called twice per cycle, around the imposed velocities and
  // rigid walls).
  void apply(NodeState& s) const;
  // Sets flags[n] = 1 for every node held in a skew frame (its fixed directions are not global bits).
  void mark_skewed(std::vector<std::uint8_t>& flags) const {
    for (const auto& k : skewed_) flags[static_cast<std::size_t>(k.node)] = 1;
  }

 private:
  std::vector<std::int32_t> node_;  // nodes with at least one fixed dof, sorted
  std::vector<std::uint8_t> mask_;  // their OR-ed bits
  // /BCS with a skew: the components of v and a along the fixed skew axes are zeroed.
  struct Skewed {
    std::int32_t node = 0;
    std::uint8_t mask = 0;  // bit k: axis k (0..2 translation, 3..5 rotation) fixed
    std::int32_t skew = 0;  // dense skew index
  };
  const SkewFrames* skews_;
  std::vector<Skewed> skewed_;
};

class ImposedVelocities {
 public:
  ImposedVelocities(const model::Model& m, const SkewFrames& skews);
  // Cycle step 5, after the first BoundaryConditions::apply. t = t_n. Returns the work booked now
  // (this cycle's dt1 part plus the previous cycle's dt2 part). Precondition: dt1 + dt2 > 0.
  // `sensor_starts`: Sensors::starts() (may be empty when no entry has a sensor).
  double apply(NodeState& s, double t, double dt1, double dt2, std::span<const double> sensor_starts = {});
  // Work of the last cycle not booked yet (its dt2 part); the next apply() books it.
  [[nodiscard]] double pending_work() const;
  [[nodiscard]] bool empty() const { return entries_.empty(); }
  // Sets flags[n] = 1 for every node with an imposed velocity.
  void mark_nodes(std::vector<std::uint8_t>& flags) const {
    for (const auto& e : entries_)
      for (const auto n : e.nodes) flags[static_cast<std::size_t>(n)] = 1;
  }

 private:
  struct Entry {
    model::Function f;
    std::int32_t sensor = model::kNone;  // dense index into model.sensors
    int dir = 0;                         // 0..2 translation, 3..5 rotation
    bool displacement = false;           // /IMPDISP: f gives the displacement from the initial position
    std::int32_t skew = model::kNone;    // dense index: the direction is axis dir % 3 of this skew
    double ascale = 1, fscale = 1, t_start = 0, t_stop = model::kNever;
    std::vector<std::int32_t> nodes;
    std::size_t first = 0;  // offset of its nodes in pending_
    // /IMPDISP/FGEO: per node, the unit direction of its line (zero when it does not move) and the length
    // of the way, which scales f; the whole acceleration is then along the direction.
    std::vector<std::array<double, 3>> node_axis;
    std::vector<double> node_scale;
  };
  const SkewFrames* skews_;
  std::vector<Entry> entries_;
  std::vector<double> pending_;  // dt2 DW per (entry, node)
};

class InitialVelocities {
 public:
  InitialVelocities(const model::Model& m, const SkewFrames& skews);
  // Sets the velocity of every /INIVEL/TRA not applied yet whose time has come (Tstart, or its sensor's, see
  // above): call once with t = 0 before cycle 0, then at the start of each cycle with t = t_n (cheap when
  // nothing is pending). Returns the kinetic-energy change 1/2 m (|v_new|^2 - |v_old|^2) it caused: initial
  // energy at t = 0, to be booked as external work when a later time applies it. `sensor_starts`:
  // Sensors::starts() (may be empty when no entry has a sensor).
  double apply(NodeState& s, double t, std::span<const double> sensor_starts = {});
  [[nodiscard]] bool pending() const { return remaining_ > 0; }

 private:
  struct Entry {
    std::array<double, 3> v{};         // components on the axes of `skew`
    std::int32_t skew = model::kNone;  // dense skew index (kNone: global axes)
    double t_start = 0;
    std::int32_t sensor = model::kNone;
    bool rotational = false;  // /INIVEL/ROT: sets the angular velocity
    bool applied = false;
    std::vector<std::int32_t> nodes;
  };
  const SkewFrames* skews_;
  std::vector<Entry> entries_;
  std::size_t remaining_ = 0;
};

}  // namespace radx::solver
