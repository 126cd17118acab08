// The explicit engine: central differences with lumped mass over the model's element groups.
//
// One cycle (docs/architecture.md section 3; docs/theory/elements.md section 0), cycle n at time t_n:
//   0. the moving skews (/SKEW/MOV) rebuilt from x^n (SkewFrames): every later use in the cycle sees them;
//   1. external loads at t_n (gravity, concentrated loads, pressures);
//   2. contact (TYPE7 penalty, contact/type7_engine.hpp): forces at t_n into the contact buffer, time-step
//   vote;
//   3. element groups: gather, strain rate, material update, internal forces, element time step; each
//   group's nodal forces added to the nodes' sums in group order (solver/engine/ordered_commit.hpp);
//   4. deterministic assembly f = f_ext + those sums node by node, then the contact forces;
//   4b. /INTER/TYPE2 ties: the secondary nodes' forces and moments onto their main segments
//   (solver/conditions/tied_type2.hpp; their masses were moved there at t = 0);
//   5. accelerations a = f / m (rotations: moment / scalar inertia);
//   6. Lagrange-multiplier correction of the switched LAGDT pairs (contact/lagrange_contact.hpp);
//   7. kinematic conditions: rigid bodies, boundary conditions, imposed velocities, rigid walls, and last
//   the tied nodes put on their segments;
//   8. v^{n+1/2} = v^{n-1/2} + dt12 a^n,  x^{n+1} = x^n + dt2 v^{n+1/2},  dt12 = (dt1 + dt2) / 2;
//   9. next time step dt = min(scale * element steps, 1.1 dt_previous), then the sensors' check with it
//      (solver/conditions/sensors.hpp: a sensor switches on when t + dt reaches its Tdelay);
//  10. outputs when due (listing, states); 11. t += dt.
// Energies follow docs/theory/elements.md section 8: internal (element work), hourglass, kinetic (at the full
// step, v^{n-1/2} + dt1/2 a^n), external work; error % = 100 (E / (E0 + W) - 1).
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <memory_resource>
#include <string>
#include <vector>

#include "contact/type7_engine.hpp"
#include "solver/conditions/sensors.hpp"
#include "solver/conditions/skew_frames.hpp"
#include "solver/elements/element_groups.hpp"
#include "solver/engine/huge_page_allocator.hpp"
#include "solver/engine/node_state.hpp"
#include "solver/engine/ordered_commit.hpp"
#include "solver/engine/thread_team.hpp"
#include "solver/model/model.hpp"
#include "solver/model/run_controls.hpp"
#include "solver/outputs/accelerometer.hpp"
#include "solver/parallel/comm.hpp"

namespace radx::solver {

class KinematicsDriver;
namespace parallel {
class EngineDomain;
}

struct EnergyBalance {
  // `internal` includes the springs' work, as OpenRadioss's balance does; `spring` is that part alone.
  double kinetic_t = 0, kinetic_r = 0, internal = 0, hourglass = 0, external_work = 0, plastic_work = 0;
  double spring = 0;
  double contact_elastic = 0, contact_damping = 0, contact_friction = 0, contact_lagrange = 0;
  double initial_total = 0;  // E_tot at cycle 0
  double error_percent = 0;
  [[nodiscard]] double total() const {
    return kinetic_t + kinetic_r + internal + hourglass + contact_elastic + contact_damping +
           contact_friction + contact_lagrange;
  }
};

// What controls the time step this cycle.
struct StepControl {
  // Imposed: /DTIX (the first step DT_ini or the bound DT_max).
  enum class Kind : std::uint8_t {
    None,
    Shell,
    Shell3,
    Brick,
    Node,
    Interface,
    Imposed,
    Tetra,
    Spring,
    Truss,
    Beam
  } kind = Kind::None;
  std::int64_t user_id = 0;
  std::int64_t node_id = 0;  // Interface: the secondary node of the controlling pair
};

// The state the listing and outputs read after each cycle.
struct CycleReport {
  bool full = false;  // energies, masses and momentum are filled only on report cycles
  std::int64_t cycle = 0;
  double time = 0, dt = 0;
  double dt1 =
      0;  // the step that led to this cycle, t^n - t^{n-1} (full-step velocity v^{n-1/2} + dt1/2 a^n)
  StepControl control;
  std::int64_t switched_pairs = 0;  // LAGDT pairs solved with Lagrange multipliers this cycle
  EnergyBalance energy;
  double mass = 0, mass0 = 0, added_mass = 0;
  std::array<double, 3> momentum{};
};

struct EngineOptions {
  explicit EngineOptions(int threads_ = 0, int report_every_ = 1)
      : threads(threads_), report_every(report_every_) {}
  int threads = 0;  // 0: ThreadTeam::default_threads() (OMP_NUM_THREADS, else the cores this process has)
  // Energies are summed every report_every cycles (and at the first and last): the listing's /PRINT
  // frequency. /STOP criteria are checked on those cycles.
  int report_every = 1;
  // Also a full report on cycles where this returns true for the cycle's time (outputs due: animation
  // states, time-history rows). Called once per cycle; empty: never.
  std::function<bool(double time)> output_due;
  // Of those, the cycles that write a state (animation, the last state of a stop): on more than one rank
  // rank 0 then gathers every group's whole state; on the other full cycles (listing, time history) only
  // what the energies and the time history's nodes and parts read, unless the time history has element
  // objects. Empty: every full cycle is a state cycle.
  std::function<bool(double time)> state_due;
  // The ranks the run is split over (solver/parallel/engine_domain.hpp); null or one rank: the whole model
  // here. Every rank builds its engine from the same model and controls.
  parallel::Comm* comm = nullptr;
  // The rank of each flat element group, given (radx-engine-mpi --partition FILE) instead of the METIS
  // partition; empty: METIS. Rank 0's are used and broadcast (parallel::engine_group_ranks).
  std::vector<std::int32_t> group_ranks;
};

enum class RunStatus : std::uint8_t { Normal, Error };

struct RunResult {
  RunStatus status = RunStatus::Normal;
  std::string message;
  std::int64_t cycles = 0;
  double time = 0, dt = 0;
  double dt1 = 0;  // t^n - t^{n-1} of the last cycle reached
  // element_seconds: the element loop, the passes bench/cycle_traffic.cpp counts (element forces, their sums,
  // the assembly, the integration); contact_seconds: the contact step (search, forces, LAGDT solve).
  double wall_seconds = 0, element_seconds = 0, contact_seconds = 0;
  int threads = 1;
  CycleReport last;
};

// One element group's share of the cycle beyond its forces: its time-step vote and deleted elements.
struct GroupVote {
  double dt = 0;  // the smallest scaled (or frozen) step of the group
  StepControl::Kind kind = StepControl::Kind::None;
  std::int64_t user_id = 0;
  std::int64_t switched = 0;      // elements frozen by /DT/<family>/CST this cycle
  std::int64_t deleted = 0;       // elements with off <= 0 (contact's Idel); springs count none
  std::int64_t ended = 0;         // elements of any kind with off <= 0 (the listing's deletion lines)
  std::int64_t violation_id = 0;  // the first element whose own step fell below half its frozen step
  double violation_frozen = 0, violation_dt = 0;
};

// The element stage's step vote of one rank, then of all: its groups' votes taken in group order as the
// serial scan takes them (the first group with the smallest step, the first below its /DT/.../STOP minimum,
// the first /DT/.../CST violation, each with its flat group index; counts summed), and the rank's flags.
// Ranks' votes combine into the same result in any order: firsts by flat index, counts by integer sums.
struct StepVote {
  static constexpr std::int64_t kNoGroup = std::numeric_limits<std::int64_t>::max();
  static constexpr std::uint32_t kOutputDue = 1;  // an output or a stop signal makes this cycle full
  static constexpr std::uint32_t kStateDue = 2;   // and a state is written
  GroupVote best{std::numeric_limits<double>::infinity()};
  std::int64_t best_flat = kNoGroup;
  GroupVote stop{};
  std::int64_t stop_flat = kNoGroup;
  GroupVote violation{};
  std::int64_t violation_flat = kNoGroup;
  std::int64_t switched = 0, deleted = 0, ended = 0;
  std::uint32_t flags = 0;
};

class ExplicitEngine {
 public:
  ExplicitEngine(const model::Model& model, const model::RunControls& controls, EngineOptions options);
  ~ExplicitEngine();
  ExplicitEngine(const ExplicitEngine&) = delete;
  ExplicitEngine& operator=(const ExplicitEngine&) = delete;

  // Runs to the end time. `on_cycle` is called after every cycle with the cycle's report (the caller
  // decides what to print or write); returning false stops the run (status Error, its message kept). On
  // more than one rank the ranks agree to stop on full cycles only (report.full): a false on a partial cycle
  // stops the run at the next full one.
  RunResult run(const std::function<bool(const CycleReport&)>& on_cycle);

  // On more than one rank, rank 0 holds every node after a full cycle (and at the run's end); the other
  // ranks hold their owned and replicated nodes and ghosts, the rest stale.
  [[nodiscard]] const NodeState& nodes() const { return nodes_; }
  [[nodiscard]] const ElementGroups& groups() const { return groups_; }
  [[nodiscard]] std::size_t element_count() const { return element_count_; }
  [[nodiscard]] const model::Model& model() const { return model_; }
  [[nodiscard]] const std::vector<MaterialParams>& materials() const { return materials_; }
  [[nodiscard]] const KinematicsDriver& kinematics() const { return *kinematics_; }
  // The skews' axes of the current cycle (a /SKEW/MOV follows its nodes).
  [[nodiscard]] const SkewFrames& skews() const { return skews_; }
  // /ACCEL readings of the last cycle.
  [[nodiscard]] const Accelerometers& accelerometers() const { return *accelerometers_; }
  // TYPE7 contact (nullptr when the model has no interface).
  [[nodiscard]] const contact::Type7Contact* contact() const { return contact_.get(); }
  // Contact warnings since the last call (a node deactivated or removed), each naming node and interface.
  std::vector<std::string> take_messages() {
    return contact_ ? contact_->take_messages() : std::vector<std::string>{};
  }
  // Events since the last call, in Radioss's words: sensors switching on or off, rigid bodies released by
  // their sensor. One line each; taken (emptied) by the call.
  std::vector<std::string> take_events();
  // Deleted elements so far (failed material, broken spring, truss or beam): how many per part (by dense
  // part index), and the first kFirstDeleted of them with when they went, for the listing and the summary.
  struct DeletedElement {
    std::string kind;  // "shell", "brick", ...
    std::int64_t element_id = 0, part_id = 0, cycle = 0;
    double time = 0;
  };
  static constexpr std::size_t kFirstDeleted = 10;
  [[nodiscard]] const std::vector<std::int64_t>& deleted_by_part() const { return deleted_by_part_; }
  [[nodiscard]] const std::vector<DeletedElement>& first_deleted() const { return first_deleted_; }
  // The sensors' state (activation times).
  [[nodiscard]] const Sensors& sensors() const { return sensors_; }
  // Whether the assembly pass also computes a = f / m (see fuse_accelerations_).
  [[nodiscard]] bool fuses_accelerations() const { return fuse_accelerations_; }
  // The engine's threads, for passes over its state between cycles (result fields); idle then.
  [[nodiscard]] ThreadTeam& team() const { return *team_; }

 private:
  void build_nodes();
  void build_groups();
  [[nodiscard]] std::int64_t group_count() const { return groups_.count(); }
  void compute_element_forces(const CycleInfo& cyc);
  void group_forces_and_vote(std::int64_t flat, const CycleInfo& cyc);
  void add_group_forces(std::int64_t flat, std::int32_t slot);
  void build_sum_regions();
  template <class F>
  void visit_group_sums(std::int64_t flat, F&& f) const;
  [[nodiscard]] Chunks node_chunks() const;
  void build_node_pass_chunks();
  [[nodiscard]] std::int64_t first_nonfinite_node() const;
  template <class Body>
  void node_pass(Body&& body);
  void assemble_and_accelerate(bool accelerate);
  double element_time_step(StepControl& control);
  double nodal_time_step(StepControl& control);
  [[nodiscard]] std::string bad_element(double time, std::int64_t cycle) const;
  CycleReport report(std::int64_t cycle, double time, double dt, const StepControl& control) const;
  [[nodiscard]] double total_mass() const;

  const model::Model& model_;  // the caller keeps the model alive for the engine's lifetime
  // A copy: controls are small, and a temporary passed to the constructor must not dangle.
  const model::RunControls controls_;
  EngineOptions options_;
  Sensors sensors_;
  NodeState nodes_;
  std::vector<MaterialParams> materials_;
  std::vector<std::vector<TabCurve>> material_curves_;  // law 36: what materials_[i].tab.curves points to
  // The groups' arrays (GroupArray): a monotonic buffer over huge pages, its first buffer small enough for a
  // small model, the next ones 1.5 x larger (libstdc++'s growth). Declared before the groups, which it must
  // outlive; groups are built once, in the constructor, so nothing is freed into it during a run.
  HugePageResource huge_pages_;
  std::pmr::monotonic_buffer_resource group_arena_{std::size_t{64} << 10, &huge_pages_};
  ElementGroups groups_;  // group_votes_ and the nodal sums follow its flat order
  std::size_t element_count_ = 0;
  // Assembly: the element forces of every node summed in group order (group, element, node of the element),
  // [node][fx fy fz mx my mz]; filled by the element stage through element_sums_order_, read and cleared by
  // assemble_and_accelerate.
  HugeVector<double> element_sums_;
  // Regions are runs of node chunks (kMaxSumRegions); a group's part in a region is its entries (element i,
  // node q of the element) whose node lies there, listed as codes 8 i + q in sum_entries_ when the group
  // writes into more than one region (a group within one region adds all its entries, unlisted).
  OrderedCommit element_sums_order_;
  std::vector<std::int64_t> sum_part_begin_;     // [groups + 1]: group k's parts, one per region it writes
  std::vector<std::int64_t> sum_entries_begin_;  // [parts + 1]: each part's codes in sum_entries_
  std::vector<std::uint16_t> sum_entries_;
  SkewFrames skews_;                                // read by the loads, conditions and outputs below
  std::unique_ptr<KinematicsDriver> kinematics_;    // loads and kinematic conditions
  std::unique_ptr<Accelerometers> accelerometers_;  // /ACCEL, read every cycle after the conditions
  std::unique_ptr<ThreadTeam> team_;  // before contact_, whose ParallelFor calls it: destroyed after it
  std::unique_ptr<contact::Type7Contact> contact_;
  // On more than one rank: this rank's groups and the exchanges that keep one rank's results (null: one
  // rank).
  std::unique_ptr<parallel::EngineDomain> domain_;
  // `whole`: every array the result fields read; else those of the energies and the parts' time history.
  void share_output_state(bool whole);
  bool th_reads_elements_ = false;  // a /TH of elements: every full cycle gathers whole states
  void kinetic_sums(double dt1);
  std::array<double, 3> momentum_{};  // at the last full cycle (kinetic_sums)
  [[nodiscard]] bool any_rank(bool mine) const;
  std::int64_t deleted_elements_ = 0;  // elements with off == 0, to tell contact (Idel) when it changes
  // Elements of any kind whose deletion the listing has been told (by cell), their count, and the lines.
  std::vector<std::uint8_t> deletion_listed_;
  std::int64_t ended_elements_ = 0;
  std::vector<std::string> deletion_events_;
  std::vector<std::int64_t> deleted_by_part_;
  std::vector<DeletedElement> first_deleted_;
  // The time loop's state between stages (run() lists the stages).
  struct LoopState {
    double time = 0, dt1 = 0, dt2 = 0;
    std::int64_t cycle = 0;
    bool first = true;
    bool reaches_end = false;     // this cycle's step ends exactly at the /RUN end time
    StepControl control;          // what set the step of the last cycle
    double dt_contact = 0;        // this cycle's contact vote
    StepControl contact_control;  // and its pair
    double element_seconds = 0, contact_seconds = 0;
    // The step centred on t^n that takes v^{n-1/2} to v^{n+1/2} (half a step on the first cycle).
    [[nodiscard]] double dt12() const { return first ? 0.5 * dt2 : 0.5 * (dt1 + dt2); }
  };
  void external_loads(LoopState& L);
  void element_forces(LoopState& L);
  void contact_forces(LoopState& L);
  void tell_contact_deleted_elements();
  void list_deleted_elements(std::int64_t cycle, double time);
  void follow_moving_skews();
  bool choose_time_step(LoopState& L, RunResult& res);
  void accelerations(LoopState& L);
  bool lagrange_correction(LoopState& L, RunResult& res);
  bool outputs(LoopState& L, bool last, const std::function<bool(const CycleReport&)>& on_cycle,
               RunResult& res);
  void sum_energies(const LoopState& L);
  bool integrate(LoopState& L, RunResult& res);
  std::vector<std::uint8_t>
      held_;  // nodes moved by /IMPVEL, rigid bodies or rigid walls (LAGDT stays penalty)
  std::int64_t count_deleted() const;
  std::vector<GroupVote> group_votes_;  // filled by the element stage for this rank's groups
  StepVote step_vote_;                  // their combination with every rank's (combine_step_votes)
  bool stop_wanted_ = false;            // on_cycle asked to stop (on more than one rank: acted on when full)
  void combine_step_votes(double time);
  bool loads_zeroed_ = false;
  // The node passes' chunks [first, last): every node in kNodeChunk blocks on one rank; on more than one,
  // the nodes this rank integrates (EngineDomain::pass_runs), each run cut into such blocks.
  struct NodeSpan {
    std::size_t first = 0, last = 0;
  };
  std::vector<NodeSpan> pass_chunks_;
  std::size_t pass_nodes_ = 0;
  // The assembly pass also computes a = f / m when nothing changes f or m between it and step 5: no TYPE2
  // ties, no /DT/NODA (it may add mass), no /DT/INTER/CST added mass; contact then updates a where it adds.
  bool fuse_accelerations_ = false;  // integrate() zeroed f_ext and the moments for the next cycle's loads
  EnergyBalance energy_;
  double mass0_ = 0;
  std::int64_t switched_elements_ = 0;  // elements whose step was frozen by /DT/<family>/CST
  std::string cst_violation_;  // set when a frozen element's own step falls below half the frozen step
  std::string step_stop_;      // set when a step falls below a /DT/<family>/STOP or /DT/INTER/STOP minimum
};

}  // namespace radx::solver
