// External loads of the cycle at t = t_n: /GRAV, /CLOAD, /PLOAD, and the external work they do
// (docs/theory/elements.md section 8, docs/keywords.md /GRAV /CLOAD /PLOAD, OpenRadioss
// loads/general/force.F90 and grav/gravit.F). v below is the state's v^{n-1/2};
// g(t), F(t), p(t) = Fscale_y f(t / Ascale_x).
//
//   /GRAV    force m g e_dir on every node of the group (all nodes when grnod_ID = 0), m = state.mass.
//            Rigid-body secondary nodes are skipped: their weight is carried by the main node, whose
//            mass is the whole body's mass after RigidBodies::initialize (Radioss skips them in the
//            work the same way; docs/theory/elements.md 7.2). Work: W += 1/2 (g(t - dt1) + g(t)) m v_dir dt1.
//   /CLOAD   every node of the group receives the full value F(t) along Dir (X Y Z: force into
//            f*_ext and f*; XX YY ZZ: moment into m*). Work (booked once dt2 is known):
//            W += 1/2 (F(t - dt1) + F(t)) v_dir dt2   (v_dir: angular velocity for a moment).
//   /PLOAD   on each segment of the surface, current geometry, normal by the right-hand rule
//            n1 -> n2 -> n3:  quad  F_node = p (x3 - x1) x (x4 - x2) / 8   = p A n / 4 on each node;
//                             triangle (n4 == n3)  F_node = p (x2 - x1) x (x3 - x1) / 6 = p A n / 3.
//            A positive pressure pushes along n. Work (as force.F90): W += dt1 sum_nodes F_node . v.
//            Idel = 1: the load of a segment stops when its owner element is deleted (remove_element).
// A load with a sensor (solver/conditions/sensors.hpp) acts only from the sensor's activation time T on,
// while the sensor is on, and reads its function at tau = t - T instead of t. Its work takes for g_old, F_old
// the value it applied at the previous cycle (0 where it did not act), and books the cycle after it stops
// with g_new, F_new = 0: the trapezoid of the force that acted, so that switching a load on or off keeps the
// energy balance (OpenRadioss books nothing then). Not supported (construction throws std::runtime_error
// naming the load): Itypfun 2 or 3 (function of displacement or velocity), /PLOAD Ipinch != 0. A direction in
// a skew is read from SkewFrames at every apply(): a /SKEW/MOV turns the load with the frame of x^n.
//
// Forces are ADDED to fx_ext.. and to fx.. (moments to mx..): the engine zeroes fx_ext.. and mx.. before
// apply() and builds fx = fx_ext + element forces (or zeroes fx too and adds the element forces).
// No allocation in apply(); the functions are copied at construction.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "solver/conditions/skew_frames.hpp"
#include "solver/engine/node_state.hpp"
#include "solver/model/model.hpp"

namespace radx::solver {

class ExternalLoads {
 public:
  // `rigid_secondary`: one flag per node, 1 for the secondary nodes of an active rigid body
  // (RigidBodies::secondary_flags(), a view read at every apply(): a released body's nodes get their weight
  // again); empty when there is no rigid body. `skews` must outlive this object.
  ExternalLoads(const model::Model& m, const SkewFrames& skews,
                std::span<const std::uint8_t> rigid_secondary = {});

  // Cycle step 1, time t = t_n, dt1 = t_n - t_{n-1} (0 at cycle 0). Adds the loads to the state and
  // returns the external work booked now (gravity and pressure). Remembers the /CLOAD power for
  // concentrated_load_work(). `sensor_starts`: Sensors::starts() (may be empty when no load has a sensor).
  double apply(NodeState& s, double t, double dt1, std::span<const double> sensor_starts = {});

  // /CLOAD work of the last apply(): 1/2 (F(t - dt1) + F(t)) v^{n-1/2} dt2, summed over loads and nodes.
  // Call once per cycle, when dt2 is known (with the kinematic conditions).
  [[nodiscard]] double concentrated_load_work(double dt2) const { return cload_power_ * dt2; }

  // /PLOAD Idel = 1: stop loading the segments owned by this element (type, index in its model block).
  void remove_element(model::SegmentOwner type, std::int32_t element);

  [[nodiscard]] bool empty() const { return gravity_.empty() && cloads_.empty() && ploads_.empty(); }

 private:
  // The stages of apply(): gravity and pressures add their work to `work`, in this order.
  void apply_gravity(NodeState& s, double t, double dt1, std::span<const double> sensor_starts, double& work);
  void apply_concentrated_loads(NodeState& s, double t, double dt1, std::span<const double> sensor_starts);
  void apply_pressures(NodeState& s, double t, double dt1, std::span<const double> sensor_starts,
                       double& work);

  struct Curve {
    model::Function f;
    bool constant = false;  // /GRAV without function: value = fscale
    double ascale = 1, fscale = 1;
    [[nodiscard]] double at(double t) const;
  };
  // The on/off history of a load with a sensor, for its work.
  struct Switch {
    bool on = false;  // the load acted at the last call
    double last = 0;  // the value it applied then
    // The values at t_{n-1} and t_n for the work, {f(t - dt1), f(t)} without a sensor; nullopt when the load
    // neither acts now nor did at the last call.
    std::optional<std::pair<double, double>> ends(const Curve& c, std::int32_t sensor, double t, double dt1,
                                                  std::span<const double> sensor_starts);
  };
  struct Gravity {
    Curve g;
    Switch sw;
    std::int32_t sensor = model::kNone;  // dense index into model.sensors
    int dir = 0;
    std::int32_t skew = model::kNone;  // dense index: along axis `dir` of this skew
    std::vector<std::int32_t> nodes;
  };
  struct Concentrated {
    Curve f;
    Switch sw;
    std::int32_t sensor = model::kNone;
    int dir = 0;                       // 0..2 force, 3..5 moment
    std::int32_t skew = model::kNone;  // dense index: along axis dir % 3 of this skew
    std::vector<std::int32_t> nodes;
  };
  struct Pressure {
    Curve p;
    std::int32_t sensor = model::kNone;
    std::vector<std::array<std::int32_t, 4>> segments;  // triangles: n4 == n3
    std::vector<std::uint8_t> active;
  };
  struct Owner {  // index for remove_element: (type, element) -> (load, segment)
    std::uint8_t type;
    std::int32_t element;
    std::uint32_t load, segment;
  };

  const SkewFrames* skews_;
  std::vector<Gravity> gravity_;
  std::vector<Concentrated> cloads_;
  std::vector<Pressure> ploads_;
  std::vector<Owner> owners_;  // sorted by (type, element)
  std::span<const std::uint8_t> rigid_secondary_;
  double cload_power_ = 0;
};

}  // namespace radx::solver
