// A cheap estimate of the initial stable time step, for plausibility checks before a run: per element
// L / c with the element's step length and its material's sound speed (docs/theory/elements.md 3.3,
// 4.1, 4.2), a solid's lowered by its linear bulk viscosity qb at rest; per spring its property's step
// (mass, stiffness and damping); without the /DT scale. It is within a few per cent of the step the
// engine takes at cycle 0 and costs one pass over the elements. Trusses and beams are not counted.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "solver/model/geometry.hpp"
#include "solver/model/model.hpp"

namespace radx::model {

// One element's estimated step.
struct ElementStep {
  double dt = 0;  // work time units
  ElementType type = ElementType::Brick8;
  std::int64_t element_id = 0;
  std::int32_t element = kNone;  // dense index in its block
  std::int32_t part = kNone;     // dense part index
};

struct StepEstimate {
  double dt = 0;  // work time units; 0 when no element has a material with a step
  ElementType type = ElementType::Brick8;
  std::int64_t element_id = 0;
  std::int32_t element = kNone;  // dense index in its block
  // The smallest steps, smallest first (ties in block order: shells, 3-node shells, bricks, tetrahedra,
  // 20-node bricks, springs, then element order), as many as asked for; the first is the one above.
  std::vector<ElementStep> smallest;
};

// `keep`: how many of the smallest steps to list in `smallest` (the starter listing shows ten).
[[nodiscard]] StepEstimate estimate_stable_step(const Model& m, std::size_t keep = 1);

// The factor sqrt(1 + qb^2) - qb by which a solid's linear bulk viscosity qb lowers its step at rest
// (docs/theory/elements.md 4.4: c_eff = qb c + sqrt((qb c)^2 + c^2) with no volumetric strain rate).
[[nodiscard]] double bulk_viscosity_step_factor(double qb);

// A spring's stable step at rest from its property and initial length l0 (OpenRadioss r1len3.F, r2len3.F,
// as spring_type4.cpp, spring_six_laws.hpp and spring_type13.cpp take it): with mass (or inertia) m,
// stiffness k and damping c of a family, m / (sqrt(c^2 + m k) + c); TYPE4 with Ileng 1 per unit length, and
// at most m / (2 c); TYPE8 and TYPE13 the smaller of the translational and rotational families, TYPE13's
// rotations with the shear laws' k l0^2 and c l0^2. +infinity when nothing sets a step.
[[nodiscard]] double spring_property_step(const SpringProperty& p, double l0);

// Step lengths of a shell (docs/theory/elements.md 4.1 quad: max(A / longest diagonal, shortest side or
// diagonal, the side 3-4 and the diagonals left out when n3 = n4); 4.2
// triangle: 2 A / longest side); 0 when degenerate.
[[nodiscard]] double quad_length(const Vec3& x1, const Vec3& x2, const Vec3& x3, const Vec3& x4);
[[nodiscard]] double triangle_length(const Vec3& x1, const Vec3& x2, const Vec3& x3);

}  // namespace radx::model
