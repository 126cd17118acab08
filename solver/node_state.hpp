// The one owner of nodal state during a run, structure of arrays indexed by dense node index.
// Velocities are the mid-step values v^{n-1/2}; forces are assembled external minus internal forces of
// the current cycle; `fixed` holds one bit per degree of freedom (bit 0..2 translations X Y Z, bit 3..5
// rotations) set by /BCS and rigid conditions.
#pragma once

#include <cstdint>
#include <vector>

namespace radx::solver {

struct NodeState {
  std::size_t n = 0;
  std::vector<double> x, y, z;                 // current coordinates x^n
  std::vector<double> x0, y0, z0;              // initial coordinates
  std::vector<double> vx, vy, vz;              // v^{n-1/2}
  std::vector<double> ax, ay, az;              // a^n
  std::vector<double> fx, fy, fz;              // assembled force of the cycle
  std::vector<double> wx, wy, wz;              // angular velocity (rotational dofs of shell nodes)
  std::vector<double> mx, my, mz;              // assembled moment of the cycle
  std::vector<double> awx, awy, awz;           // angular acceleration
  std::vector<double> mass;                    // lumped mass, including added mass
  std::vector<double> inertia;                 // scalar rotational inertia (0 for nodes of bricks only)
  std::vector<double> added_mass;              // mass added by /DT/NODA/CST and /DT/INTER/CST
  std::vector<double> stiffness;               // nodal stiffness estimate for the nodal time step
  std::vector<std::uint8_t> fixed;             // bit k: dof k held by a boundary condition
  std::vector<double> fx_ext, fy_ext, fz_ext;  // external part of the force (loads), for output and work

  void resize(std::size_t count) {
    n = count;
    for (auto* v : {&x,   &y,   &z,    &x0,      &y0,         &z0,        &vx,     &vy,     &vz,    &ax, &ay,
                    &az,  &fx,  &fy,   &fz,      &wx,         &wy,        &wz,     &mx,     &my,    &mz, &awx,
                    &awy, &awz, &mass, &inertia, &added_mass, &stiffness, &fx_ext, &fy_ext, &fz_ext})
      v->assign(count, 0.0);
    fixed.assign(count, 0);
  }
};

}  // namespace radx::solver
