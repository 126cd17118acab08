// Initial stable step estimate: min over elements of L / c. Bricks: L = V / largest face area,
// c = sqrt((K + 4G/3) / rho); shells: L from area over the longest diagonal bounded below by the shortest
// side, triangles: L = 2A / longest side, tetrahedra: L = the smallest height 3 V / largest face area, c =
// sqrt(E / rho) (docs/theory/elements.md 3.3, 4.1, 4.2); 20-node bricks: OpenRadioss's length of
// hex20_length (hex20_shape.hpp) over the 3 x 3 x 3 points. Solids times sqrt(1 + qb^2) - qb, their bulk
// viscosity at rest (4.4). Springs: spring_property_step.
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

// The linear bulk viscosity a solid part runs with: its property's qb, none for law 70 when the property
// leaves qa and qb blank (as the engine's foam groups).
double solid_qb(const Model& m, std::int32_t part) {
  if (part == kNone) return 0;
  const Part& pt = m.parts[static_cast<std::size_t>(part)];
  if (pt.property == kNone) return 0;
  const SolidProperty& prop = m.properties[static_cast<std::size_t>(pt.property)].solid;
  const bool foam =
      pt.material != kNone && m.materials[static_cast<std::size_t>(pt.material)].law == MaterialLaw::FoamTab;
  return foam && prop.q_default ? 0.0 : prop.qb;
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

// The step length of one mesh element at its nodes' initial coordinates.
double element_length(const Model& m, const ElementBlock& b, const std::int32_t* conn) {
  if (b.type == ElementType::Brick8) {
    std::array<Vec3, 8> x{};
    for (std::size_t k = 0; k < 8; ++k) x[k] = node_at(m, conn[k]);
    return brick_length(x);
  }
  if (b.type == ElementType::Brick20) {
    double x[20][3];
    for (std::size_t k = 0; k < 20; ++k) {
      const Vec3 p = node_at(m, conn[k]);
      for (std::size_t d = 0; d < 3; ++d) x[k][d] = p[d];
    }
    return hex20_length(x, hex20_starter_rule());
  }
  if (b.type == ElementType::Tetra4)
    return tetra_length(node_at(m, conn[0]), node_at(m, conn[1]), node_at(m, conn[2]), node_at(m, conn[3]));
  if (b.type == ElementType::Shell4 && conn[2] != conn[3])
    return quad_length(node_at(m, conn[0]), node_at(m, conn[1]), node_at(m, conn[2]), node_at(m, conn[3]));
  return triangle_length(node_at(m, conn[0]), node_at(m, conn[1]), node_at(m, conn[2]));
}

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

double bulk_viscosity_step_factor(double qb) {
  return std::sqrt(1.0 + qb * qb) - qb;
}

namespace {

// m / (sqrt(c^2 + m k) + c) of one spring family; +infinity without stiffness and damping.
double spring_family_step(double m, double k, double c) {
  if (k + c < 1e-15) return std::numeric_limits<double>::infinity();
  return m / std::max(1e-15, std::sqrt(c * c + m * std::max(k, 1e-15)) + c);
}

struct FamilyStiffness {
  double k = 0, c = 0;
};
FamilyStiffness spring_family(const SpringProperty& p, int first) {
  FamilyStiffness s;
  for (int d = first; d < first + 3; ++d) {
    s.k = std::max(s.k, p.law(d).stiffness);
    s.c = std::max(s.c, p.law(d).damping);
  }
  return s;
}

}  // namespace

double spring_property_step(const SpringProperty& p, double l0) {
  if (p.type == 4) {
    const double s = p.ileng == 1 ? l0 : 1.0;
    if (!(s > 0)) return std::numeric_limits<double>::infinity();
    const double m = p.mass * s, k = p.x.stiffness / s, c = p.x.damping / s;
    return std::min(m / std::max(1e-15, std::sqrt(c * c + m * k) + c), 0.5 * m / std::max(1e-15, c));
  }
  const FamilyStiffness t = spring_family(p, 0);
  FamilyStiffness r = spring_family(p, 3);
  if (p.type == 13) {
    r.k += std::max(p.law(1).stiffness, p.law(2).stiffness) * l0 * l0;
    r.c += std::max(p.law(1).damping, p.law(2).damping) * l0 * l0;
  }
  return std::min(spring_family_step(p.mass, t.k, t.c), spring_family_step(p.inertia, r.k, r.c));
}

StepEstimate estimate_stable_step(const Model& m, std::size_t keep) {
  StepEstimate best;
  double dt_min = std::numeric_limits<double>::infinity();
  auto consider = [&](double dt, ElementType type, std::int64_t id, std::size_t e, std::int32_t part) {
    if (!(dt > 0) || !std::isfinite(dt)) return;
    if (dt < dt_min) {
      dt_min = dt;
      best.dt = dt;
      best.type = type;
      best.element_id = id;
      best.element = static_cast<std::int32_t>(e);
    }
    keep_smallest(best.smallest, keep, {dt, type, id, static_cast<std::int32_t>(e), part});
  };
  for (const ElementBlock* b : {&m.shells, &m.shells3, &m.bricks, &m.tetras, &m.bricks20}) {
    const auto npe = static_cast<std::size_t>(b->npe());
    const bool solid =
        b->type == ElementType::Brick8 || b->type == ElementType::Tetra4 || b->type == ElementType::Brick20;
    for (std::size_t e = 0; e < b->size(); ++e) {
      const double c = sound_speed(m, b->part[e], solid);
      if (!(c > 0)) continue;
      const std::int32_t* conn = &b->conn[e * npe];
      bool valid = true;
      for (std::size_t k = 0; k < npe; ++k) valid = valid && conn[k] != kNone;
      if (!valid) continue;
      const double l = element_length(m, *b, conn);
      if (!(l > 0)) continue;
      const double q = solid ? bulk_viscosity_step_factor(solid_qb(m, b->part[e])) : 1.0;
      consider(l / c * q, b->type, b->id[e], e, b->part[e]);
    }
  }
  const ElementBlock& springs = m.springs;
  const auto npe = static_cast<std::size_t>(springs.npe());
  for (std::size_t e = 0; e < springs.size(); ++e) {
    const std::int32_t part = springs.part[e];
    if (part == kNone) continue;
    const auto prop = m.parts[static_cast<std::size_t>(part)].property;
    if (prop == kNone) continue;
    const std::int32_t* conn = &springs.conn[e * npe];
    if (conn[0] == kNone || conn[1] == kNone) continue;
    const double l0 = std::sqrt(squared(sub(node_at(m, conn[1]), node_at(m, conn[0]))));
    consider(spring_property_step(m.properties[static_cast<std::size_t>(prop)].spring, l0), springs.type,
             springs.id[e], e, part);
  }
  return best;
}

}  // namespace radx::model
