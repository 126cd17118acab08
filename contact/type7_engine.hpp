// TYPE7 contact in the engine: the penalty path of /INTER/TYPE7 and /INTER/LAGDT/TYPE7
// (docs/theory/type7-lagdt.md sections 3 to 5) for every interface of the model, one call per cycle
// (docs/architecture.md section 3, step 2). Contact does not know the time loop: it receives views of the
// node state and the time, and returns its nodal forces (in its own buffer, which the engine adds to the
// assembled forces), its time-step vote and its energies. The equations are in the opening comment of
// type7_engine.cpp. LAGDT: the pairs of /INTER/LAGDT/TYPE7 interfaces whose time step would fall below the
// Tmin of /DT/INTER/CST (or /DT/INTER/LAG) leave the penalty path for the cycle (no force, no stiffness, no
// time-step vote) and become rows of the Lagrange-multiplier system that lagrange_correction() solves at
// cycle step 6 (contact/lagrange_contact.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "contact/lagrange_contact.hpp"
#include "contact/parallel_for.hpp"
#include "solver/model/model.hpp"

namespace radx::contact {

// Views of the engine's node state, dense node indices, valid during the call.
struct ContactNodes {
  std::span<double> x, y, z;           // x^n (Inacti 3 at Tstart moves penetrating nodes out)
  std::span<const double> vx, vy, vz;  // v^{n-1/2}
  std::span<double> mass;              // lumped mass (grows with /DT/INTER/CST mass scaling)
  std::span<double> added_mass;        // mass added so far by /DT/.../CST
  std::span<std::uint8_t> fixed;       // boundary-condition bits; IBC clears bits 0..2 at first impact
  // 1 for a node whose motion a kinematic condition other than /BCS prescribes after step 6 (/IMPVEL,
  // rigid body, rigid wall): a LAGDT pair on such a node stays on the penalty path. Empty: none.
  std::span<const std::uint8_t> held;
};

// /DT/INTER/CST, /DT/INTER/DEL (and the scale of the interface steps).
struct ContactControls {
  double dt_scale = 0.9;  // Tscale of /DT/INTER/..., else of /DT
  double t_min = 0;       // Tmin (0: none)
  // AddMass (/DT/INTER/CST): plain TYPE7 nodes get mass, LAGDT pairs switch; Lagrange (/DT/INTER/LAG):
  // LAGDT pairs switch; Delete (/DT/INTER/DEL): pairs leave the interface.
  enum class Action : std::uint8_t { None, AddMass, Delete, Lagrange } action = Action::None;
};

// The smallest contact time step of the cycle and what imposes it.
struct ContactStep {
  double dt = std::numeric_limits<double>::infinity();
  std::int64_t interface_id = 0;
  std::int64_t node_id = 0;  // user id of the secondary node of the pair
};

// Per-interface results (listing, summary, time history).
struct InterfaceResult {
  std::int64_t id = 0;
  std::int64_t active_pairs = 0;             // pairs with p > 0 in the last cycle
  double max_penetration = 0;                // largest p seen during the run
  std::array<double, 3> normal_force{};      // sum over the secondary nodes of the normal forces, last cycle
  std::array<double, 3> tangential_force{};  // same for friction
  double e_elastic = 0, e_damping = 0, e_friction = 0;  // booked energies (work of the contact forces)
  std::int64_t deactivated_nodes = 0;  // nodes that reached the surface, or removed by Idel or /DT/INTER/DEL
  double added_mass = 0;               // by /DT/INTER/CST
  std::int64_t switched_pairs = 0;     // LAGDT: pairs switched to Lagrange multipliers in the last cycle
  std::int64_t switched_pairs_max = 0, switched_pairs_total = 0;  // most in one cycle; pair-cycles
  double e_lagrange = 0;                                          // work of the multipliers (dissipated)
  // Workload of the candidate search (Type7Search): the cycles the interface was active (inside [Tstart,
  // Tstop), its sensor on), the candidate pairs it held summed over those cycles, and the sorts it made.
  std::int64_t active_cycles = 0;
  std::int64_t candidate_pair_cycles = 0;
  std::int64_t search_sorts = 0;
  // Candidate pairs per active cycle, 0 before the first.
  [[nodiscard]] double mean_candidates() const {
    return active_cycles > 0 ? static_cast<double>(candidate_pair_cycles) / static_cast<double>(active_cycles)
                             : 0.0;
  }
};

// Views for cycle step 6: accelerations after a0 = f / m, corrected in place.
struct LagrangeNodesView {
  std::span<const double> mass;
  std::span<const double> vx, vy, vz;  // v^{n-1/2}
  std::span<double> ax, ay, az;
  std::span<const std::uint8_t> fixed;
};

// A force the multipliers put on a node this cycle (normal and friction), for the engine's force sum.
struct NodeForce {
  std::int32_t node;
  std::array<double, 3> f;
};

class Type7Contact {
 public:
  Type7Contact(const model::Model& m, ContactControls controls);
  ~Type7Contact();
  Type7Contact(const Type7Contact&) = delete;
  Type7Contact& operator=(const Type7Contact&) = delete;

  [[nodiscard]] bool empty() const;

  // The engine's threads for the pure parts of compute() (the search's displacement test, each secondary
  // node's closest segment); unset, they run in order on the calling thread. The results do not depend on
  // it (parallel_for.hpp).
  void set_parallel_for(ParallelFor parallel);

  // Cycle step 2 at time t (dt1 = t^n - t^{n-1}): books the work of the previous cycle's forces over the
  // step just taken, sorts when due, computes the penalty, damping and friction forces of every active
  // pair into force() and returns the contact time-step vote. Messages (a node deactivated, removed)
  // accumulate in messages(). `sensor_starts`: per model sensor, the time it switched on (model::kNever
  // while it is off; the engine's Sensors::starts()): an interface with a sensor acts only from then on. May
  // be empty when no interface has a sensor.
  ContactStep compute(double t, double dt1, const ContactNodes& nodes,
                      std::span<const double> sensor_starts = {});

  // Cycle step 6 (dt1 = t^n - t^{n-1}, dt2 = t^{n+1} - t^n): the switched pairs of this cycle get their
  // Lagrange multipliers; the accelerations are corrected in place, the multipliers' forces join force()
  // and are returned node by node (ascending) for the engine's force sum. Throws CholmodError on a solver
  // failure.
  const std::vector<NodeForce>& lagrange_correction(const LagrangeNodesView& nodes, double dt1, double dt2);
  [[nodiscard]] std::int64_t switched_pairs() const;  // this cycle, all interfaces
  [[nodiscard]] bool has_lagrange() const;            // a LAGDT interface can switch pairs in this run
  [[nodiscard]] const LagrangeStats& lagrange_stats() const;
  double energy_lagrange() const;

  // This cycle's contact forces: for each node in touched() (ascending), force()[3 n .. 3 n + 2].
  [[nodiscard]] const std::vector<double>& force() const;
  [[nodiscard]] const std::vector<std::int32_t>& touched() const;

  // Element deletion (Idel): `alive` per model cell (4-node shells, 3-node shells, bricks), 1 alive.
  void elements_deleted(std::span<const std::uint8_t> alive);

  [[nodiscard]] std::vector<InterfaceResult> results() const;
  double energy_elastic() const;
  double energy_damping() const;
  double energy_friction() const;
  // Warnings of the run so far, taken (emptied) by the call.
  std::vector<std::string> take_messages();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace radx::contact
