// A cheap estimate of the initial stable time step, for plausibility checks before a run: per element
// L / c with the element's step length and its material's sound speed (docs/theory/elements.md 3.3,
// 4.1, 4.2), without the bulk viscosity and the /DT scale. It is within a few per cent of the step the
// engine takes at cycle 0 and costs one pass over the elements.
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
  // 20-node bricks, then element order), as many as asked for; the first is the one above.
  std::vector<ElementStep> smallest;
};

// `keep`: how many of the smallest steps to list in `smallest` (the starter listing shows ten).
[[nodiscard]] StepEstimate estimate_stable_step(const Model& m, std::size_t keep = 1);

// Step lengths of a shell (docs/theory/elements.md 4.1 quad: max(A / longest diagonal, shortest side or
// diagonal, the side 3-4 and the diagonals left out when n3 = n4); 4.2
// triangle: 2 A / longest side); 0 when degenerate.
[[nodiscard]] double quad_length(const Vec3& x1, const Vec3& x2, const Vec3& x3, const Vec3& x4);
[[nodiscard]] double triangle_length(const Vec3& x1, const Vec3& x2, const Vec3& x3);

}  // namespace radx::model
