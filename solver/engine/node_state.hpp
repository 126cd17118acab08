// The one owner of nodal state during a run, structure of arrays indexed by dense node index.
// Velocities are the mid-step values v^{n-1/2}; forces are assembled external minus internal forces of
// the current cycle; `fixed` holds one bit per degree of freedom (bit 0..2 translations X Y Z, bit 3..5
// rotations) set by /BCS and rigid conditions.
#pragma once

#include <cstdint>
#include <vector>

#include "solver/engine/huge_page_allocator.hpp"

namespace radx::solver {

struct NodeState {
  std::size_t n = 0;
  HugeVector<double> x, y, z;                 // current coordinates x^n
  HugeVector<double> x0, y0, z0;              // initial coordinates
  HugeVector<double> vx, vy, vz;              // v^{n-1/2}
  HugeVector<double> ax, ay, az;              // a^n
  HugeVector<double> fx, fy, fz;              // assembled force of the cycle
  HugeVector<double> wx, wy, wz;              // angular velocity (rotational dofs of shell nodes)
  HugeVector<double> mx, my, mz;              // assembled moment of the cycle
  HugeVector<double> awx, awy, awz;           // angular acceleration
  HugeVector<double> mass;                    // lumped mass, including added mass
  HugeVector<double> inertia;                 // scalar rotational inertia (0 for nodes of bricks only)
  HugeVector<double> added_mass;              // mass added by /DT/NODA/CST and /DT/INTER/CST
  HugeVector<double> stiffness;               // nodal stiffness estimate for the nodal time step
  HugeVector<std::uint8_t> fixed;             // bit k: dof k held by a boundary condition
  HugeVector<double> fx_ext, fy_ext, fz_ext;  // external part of the force (loads), for output and work

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
