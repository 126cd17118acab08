#include "solver/kinematics_driver.hpp"

namespace radx::solver {

struct KinematicsDriver::Parts {
  double external_work = 0;
};

KinematicsDriver::KinematicsDriver(const model::Model& m, const model::RunControls& c, NodeState& nodes)
    : model_(m), controls_(c), nodes_(nodes), parts_(std::make_unique<Parts>()) {}

KinematicsDriver::~KinematicsDriver() = default;

void KinematicsDriver::initial_conditions() {}
void KinematicsDriver::external_loads(double, double, double) {}
void KinematicsDriver::kinematic_conditions(double, double, double) {}
void KinematicsDriver::after_update(double) {}

void KinematicsDriver::kinetic_energy(double dt1, double& translational, double& rotational) const {
  const auto& s = nodes_;
  translational = rotational = 0;
  const double h = 0.5 * dt1;
  for (std::size_t n = 0; n < s.n; ++n) {
    const double vx = s.vx[n] + h * s.ax[n], vy = s.vy[n] + h * s.ay[n], vz = s.vz[n] + h * s.az[n];
    translational += 0.5 * s.mass[n] * (vx * vx + vy * vy + vz * vz);
    const double wx = s.wx[n] + h * s.awx[n], wy = s.wy[n] + h * s.awy[n], wz = s.wz[n] + h * s.awz[n];
    rotational += 0.5 * s.inertia[n] * (wx * wx + wy * wy + wz * wz);
  }
}

std::array<double, 3> KinematicsDriver::momentum(double dt1) const {
  const auto& s = nodes_;
  std::array<double, 3> p{};
  const double h = 0.5 * dt1;
  for (std::size_t n = 0; n < s.n; ++n) {
    p[0] += s.mass[n] * (s.vx[n] + h * s.ax[n]);
    p[1] += s.mass[n] * (s.vy[n] + h * s.ay[n]);
    p[2] += s.mass[n] * (s.vz[n] + h * s.az[n]);
  }
  return p;
}

double KinematicsDriver::external_work() const {
  return parts_->external_work;
}

}  // namespace radx::solver
