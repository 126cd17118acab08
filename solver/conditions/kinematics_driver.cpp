#include "solver/conditions/kinematics_driver.hpp"

#include "solver/conditions/kinematics.hpp"
#include "solver/conditions/tied_type2.hpp"

namespace radx::solver {

// The call order is the one documented in solver/conditions/kinematics.hpp.
struct KinematicsDriver::Parts {
  BoundaryConditions bcs;
  InitialVelocities inivel;
  RigidWalls walls;
  RigidBodies bodies;
  TiedInterfaces ties;
  ImposedVelocities impvel;
  std::unique_ptr<ExternalLoads> loads;
  double external_work = 0;
  Parts(const model::Model& m, const model::RunControls& c, const SkewFrames& skews)
      : bcs(m, skews), inivel(m, skews), walls(m), bodies(m, c.rbody_off), ties(m), impvel(m, skews) {}
};

KinematicsDriver::KinematicsDriver(const model::Model& m, const model::RunControls& c, NodeState& nodes,
                                   const SkewFrames& skews, std::span<const double> sensor_starts)
    : model_(m),
      controls_(c),
      nodes_(nodes),
      skews_(skews),
      sensor_starts_(sensor_starts),
      parts_(std::make_unique<Parts>(m, c, skews)) {}

KinematicsDriver::~KinematicsDriver() = default;

void KinematicsDriver::initial_conditions() {
  auto& p = *parts_;
  p.bcs.set_fixed_bits(nodes_);
  p.inivel.apply(nodes_, 0.0, sensor_starts_);  // initial kinetic energy, not work
  p.walls.initialize(nodes_);
  if (!p.ties.empty()) p.ties.initialize(nodes_);  // before the bodies: they weigh the tied mass
  p.bodies.initialize(nodes_, sensor_starts_);
  p.loads = std::make_unique<ExternalLoads>(model_, skews_,
                                            p.bodies.size() > 0
                                                ? std::span<const std::uint8_t>(p.bodies.secondary_flags())
                                                : std::span<const std::uint8_t>());
  p.bcs.apply(nodes_);
}

void KinematicsDriver::external_loads(double t, double dt1, double) {
  auto& p = *parts_;
  if (p.inivel.pending()) p.external_work += p.inivel.apply(nodes_, t, sensor_starts_);
  if (!p.loads->empty()) p.external_work += p.loads->apply(nodes_, t, dt1, sensor_starts_);
}

void KinematicsDriver::transfer_tied_forces() {
  if (!parts_->ties.empty()) parts_->ties.transfer_forces(nodes_);
}

bool KinematicsDriver::has_ties() const {
  return !parts_->ties.empty();
}

void KinematicsDriver::transfer_tied_stiffness() {
  if (!parts_->ties.empty()) parts_->ties.transfer_stiffness(nodes_);
}

void KinematicsDriver::kinematic_conditions(double t, double dt1, double dt2) {
  auto& p = *parts_;
  p.walls.apply_wall_node_forces(nodes_);
  if (p.bodies.size() > 0) p.bodies.gather_and_accelerate(nodes_, t, dt1, sensor_starts_);
  p.bcs.apply(nodes_);
  p.external_work += p.impvel.apply(nodes_, t, dt1, dt2, sensor_starts_);
  p.external_work += p.walls.apply(nodes_, dt1, dt2);
  p.bcs.apply(nodes_);
  if (p.bodies.size() > 0 && dt1 + dt2 > 0) p.bodies.secondary_kinematics(nodes_, dt1, dt2);
  // Last: a tie's main nodes may be moved by every condition above.
  if (!p.ties.empty() && dt1 + dt2 > 0) p.ties.secondary_kinematics(nodes_, dt1, dt2);
  if (!p.loads->empty()) p.external_work += p.loads->concentrated_load_work(dt2);
}

void KinematicsDriver::after_update(double) {}

// The node terms here and the rigid bodies' negated copies of them (RigidBodies::kinetic_correction) are the
// same expressions, so a secondary node's terms cancel exactly in the exact sums.
KineticSums KinematicsDriver::kinetic_sums(double dt1, std::span<const std::array<std::size_t, 2>> runs,
                                           bool with_bodies) const {
  const auto& s = nodes_;
  KineticSums sums;
  const double h = 0.5 * dt1;
  for (const auto& run : runs)
    for (std::size_t n = run[0]; n < run[1]; ++n) {
      const double vx = s.vx[n] + h * s.ax[n], vy = s.vy[n] + h * s.ay[n], vz = s.vz[n] + h * s.az[n];
      sums.translational.add(0.5 * s.mass[n] * (vx * vx + vy * vy + vz * vz));
      const double wx = s.wx[n] + h * s.awx[n], wy = s.wy[n] + h * s.awy[n], wz = s.wz[n] + h * s.awz[n];
      sums.rotational.add(0.5 * s.inertia[n] * (wx * wx + wy * wy + wz * wz));
      sums.momentum[0].add(s.mass[n] * vx);
      sums.momentum[1].add(s.mass[n] * vy);
      sums.momentum[2].add(s.mass[n] * vz);
    }
  if (with_bodies && parts_->bodies.size() > 0) parts_->bodies.kinetic_correction(s, dt1, sums);
  return sums;
}

double KinematicsDriver::external_work() const {
  return parts_->external_work;
}

model::ExactSum KinematicsDriver::mass_correction() const {
  KineticSums sums;
  if (parts_->bodies.size() > 0) parts_->bodies.kinetic_correction(nodes_, 0.0, sums);
  return sums.mass;
}

std::vector<std::uint8_t> KinematicsDriver::held_nodes() const {
  std::vector<std::uint8_t> held(nodes_.n, 0);
  parts_->impvel.mark_nodes(held);
  parts_->walls.mark_nodes(held);
  parts_->bcs.mark_skewed(held);
  parts_->ties.mark_nodes(held);
  for (const auto& b : parts_->bodies.bodies()) {
    if (b.main != model::kNone) held[static_cast<std::size_t>(b.main)] = 1;
    for (const auto n : b.secondary) held[static_cast<std::size_t>(n)] = 1;
  }
  return held;
}

const std::vector<RigidWallOutput>& KinematicsDriver::wall_outputs() const {
  return parts_->walls.outputs();
}

const RigidBodies& KinematicsDriver::rigid_bodies() const {
  return parts_->bodies;
}

std::vector<std::string> KinematicsDriver::take_messages() {
  return parts_->bodies.take_messages();
}

}  // namespace radx::solver
