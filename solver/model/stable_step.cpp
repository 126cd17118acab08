// Initial stable step estimate: min over elements of L / c. Bricks: L = V / largest face area,
// c = sqrt((K + 4G/3) / rho); shells: L from area over the longest diagonal bounded below by the shortest
// side, triangles: L = 2A / longest side, tetrahedra: L = the smallest height 3 V / largest face area, c =
// sqrt(E / rho) (docs/theory/elements.md 3.3, 4.1, 4.2); 20-node bricks: OpenRadioss's length of
// hex20_length (hex20_shape.hpp) over the 3 x 3 x 3 points.
#include "solver/model/stable_step.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "solver/model/geometry.hpp"
#include "solver/model/hex20_shape.hpp"

namespace radx::model {

namespace {

// Sound speed of the element's material, 0 when it has none (no material or no density) or computes no force
// (void and rigid elements: the engine gives them no step).
double sound_speed(const Model& m, std::int32_t part, bool solid) {
  if (part == kNone) return 0;
  const auto mi = m.parts[static_cast<std::size_t>(part)].material;
  if (mi == kNone) return 0;
  const Material& mat = m.materials[static_cast<std::size_t>(mi)];
  if (mat.law == MaterialLaw::Void || mat.law == MaterialLaw::Rigid) return 0;
  if (!(mat.rho > 0) || !(mat.young > 0)) return 0;
  return solid ? std::sqrt((mat.bulk + 4.0 * mat.shear / 3.0) / mat.rho) : std::sqrt(mat.young / mat.rho);
}

Vec3 node_at(const Model& m, std::int32_t n) {
  const auto i = static_cast<std::size_t>(n);
  return {m.nodes.x[i], m.nodes.y[i], m.nodes.z[i]};
}

double squared(const Vec3& a) {
  return dot(a, a);
}

// Step length of each element type, as the kernels take it at rest.
double brick_length(const std::array<Vec3, 8>& x) {
  double area_max = 0;
  for (const auto& f : kBrickFaces)
    area_max =
        std::max(area_max, quad_area(x[static_cast<std::size_t>(f[0])], x[static_cast<std::size_t>(f[1])],
                                     x[static_cast<std::size_t>(f[2])], x[static_cast<std::size_t>(f[3])]));
  const double v = brick_volume(x);
  return area_max > 0 && v > 0 ? v / area_max : 0;
}

}  // namespace

double quad_length(const Vec3& x1, const Vec3& x2, const Vec3& x3, const Vec3& x4) {
  const double area = quad_area(x1, x2, x3, x4);
  const double d13 = squared(sub(x3, x1)), d24 = squared(sub(x4, x2));
  const double l12 = squared(sub(x2, x1)), l23 = squared(sub(x3, x2)), l34 = squared(sub(x4, x3)),
               l41 = squared(sub(x1, x4));
  double lmin2 = std::min({l12, l23, l41});
  if (l34 != 0) lmin2 = std::min({lmin2, l34, d13, d24});
  const double diag2 = std::max(d13, d24);
  return std::sqrt(std::max(diag2 > 0 ? area * area / diag2 : 0.0, lmin2));
}

double triangle_length(const Vec3& x1, const Vec3& x2, const Vec3& x3) {
  const double longest =
      std::sqrt(std::max({squared(sub(x2, x1)), squared(sub(x3, x2)), squared(sub(x1, x3))}));
  return longest > 0 ? 2.0 * triangle_area(x1, x2, x3) / longest : 0;
}

namespace {

// Keeps the `keep` smallest steps seen, smallest first; a later element with an equal step stays after
// the earlier one.
void keep_smallest(std::vector<ElementStep>& smallest, std::size_t keep, const ElementStep& s) {
  if (keep == 0 || (smallest.size() == keep && !(s.dt < smallest.back().dt))) return;
  const auto at = std::upper_bound(smallest.begin(), smallest.end(), s.dt,
                                   [](double dt, const ElementStep& e) { return dt < e.dt; });
  smallest.insert(at, s);
  if (smallest.size() > keep) smallest.pop_back();
}

}  // namespace

StepEstimate estimate_stable_step(const Model& m, std::size_t keep) {
  StepEstimate best;
  double dt_min = std::numeric_limits<double>::infinity();
  for (const ElementBlock* b : {&m.shells, &m.shells3, &m.bricks, &m.tetras, &m.bricks20}) {
    const auto npe = static_cast<std::size_t>(b->npe());
    for (std::size_t e = 0; e < b->size(); ++e) {
      const double c = sound_speed(m, b->part[e],
                                   b->type == ElementType::Brick8 || b->type == ElementType::Tetra4 ||
                                       b->type == ElementType::Brick20);
      if (!(c > 0)) continue;
      const std::int32_t* conn = &b->conn[e * npe];
      bool valid = true;
      for (std::size_t k = 0; k < npe; ++k) valid = valid && conn[k] != kNone;
      if (!valid) continue;
      double l = 0;
      if (b->type == ElementType::Brick8) {
        std::array<Vec3, 8> x{};
        for (std::size_t k = 0; k < 8; ++k) x[k] = node_at(m, conn[k]);
        l = brick_length(x);
      } else if (b->type == ElementType::Brick20) {
        double x[20][3];
        for (std::size_t k = 0; k < 20; ++k) {
          const Vec3 p = node_at(m, conn[k]);
          for (std::size_t d = 0; d < 3; ++d) x[k][d] = p[d];
        }
        l = hex20_length(x, hex20_starter_rule());
      } else if (b->type == ElementType::Tetra4) {
        l = tetra_length(node_at(m, conn[0]), node_at(m, conn[1]), node_at(m, conn[2]), node_at(m, conn[3]));
      } else if (b->type == ElementType::Shell4 && conn[2] != conn[3]) {
        l = quad_length(node_at(m, conn[0]), node_at(m, conn[1]), node_at(m, conn[2]), node_at(m, conn[3]));
      } else {
        l = triangle_length(node_at(m, conn[0]), node_at(m, conn[1]), node_at(m, conn[2]));
      }
      if (!(l > 0)) continue;
      const double dt = l / c;
      if (dt < dt_min) {
        dt_min = dt;
        best.dt = dt;
        best.type = b->type;
        best.element_id = b->id[e];
        best.element = static_cast<std::int32_t>(e);
      }
      keep_smallest(best.smallest, keep, {dt, b->type, b->id[e], static_cast<std::int32_t>(e), b->part[e]});
    }
  }
  return best;
}

}  // namespace radx::model
