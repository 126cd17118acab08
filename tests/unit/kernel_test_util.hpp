// Set-up shared by the element kernel tests: an elastic material with the constants the engine derives from
// it (make_material_params), nodes at given points, and a relative difference.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "solver/engine/node_state.hpp"
#include "solver/materials/material_point.hpp"

namespace radx::test {

// LAW1 with Young's modulus, Poisson's ratio and density, derived as the starter's materials are.
inline solver::MaterialParams elastic(double young, double nu, double rho) {
  model::Material m;
  m.law = model::MaterialLaw::Elastic;
  m.rho = rho;
  m.young = young;
  m.poisson = nu;
  return solver::make_material_params(m);
}

// Nodes at `pts` (current = initial), at rest.
inline solver::NodeState make_nodes(const std::vector<std::array<double, 3>>& pts) {
  solver::NodeState ns;
  ns.resize(pts.size());
  for (std::size_t k = 0; k < pts.size(); ++k) {
    ns.x[k] = ns.x0[k] = pts[k][0];
    ns.y[k] = ns.y0[k] = pts[k][1];
    ns.z[k] = ns.z0[k] = pts[k][2];
  }
  return ns;
}

// |a - b| / |b| (b = 0 is taken as the smallest normal double).
inline double rel(double a, double b) {
  return std::abs(a - b) / std::max(std::abs(b), std::numeric_limits<double>::min());
}

}  // namespace radx::test
