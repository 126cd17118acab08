// The map of a /INTER/TYPE2 tie, shared by the starter (projection) and the engine
// (solver/conditions/tied_type2.cpp). A secondary node s tied to the main segment (x1, x2, x3, x4) sits at
//     x_s = sum_j h_j(r, s) x_j + d n,        n = N / |N|,
//   quad:     h = (1-r)(1-s)/4, (1+r)(1-s)/4, (1+r)(1+s)/4, (1-r)(1+s)/4,   N = (x3 - x1) x (x4 - x2);
//   triangle: h = 1 - r - s, r, s, 0 (n4 == n3),                            N = (x2 - x1) x (x3 - x1).
// (r, s, d) are found once at t = 0 (project_on_segment) and kept. d is the offset along the normal, so
// the offset turns with the segment: n is rebuilt from the current nodes each cycle. The quad's N is the
// cross product of its diagonals, the normal OpenRadioss uses for a segment (i2cor3.F), so n is constant
// over a warped segment and the map above is exact for it.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include "solver/model/geometry.hpp"

namespace radx::model {

inline bool is_triangle(const std::array<std::int32_t, 4>& seg) {
  return seg[2] == seg[3];
}

inline std::array<double, 4> tie_shape(double r, double s, bool triangle) {
  if (triangle) return {1.0 - r - s, r, s, 0.0};
  return {0.25 * (1 - r) * (1 - s), 0.25 * (1 + r) * (1 - s), 0.25 * (1 + r) * (1 + s),
          0.25 * (1 - r) * (1 + s)};
}

// N (not normalised): the diagonals' cross product, or the triangle's edges'.
inline Vec3 tie_normal(const std::array<Vec3, 4>& x, bool triangle) {
  return triangle ? cross(sub(x[1], x[0]), sub(x[2], x[0])) : cross(sub(x[2], x[0]), sub(x[3], x[1]));
}

struct SegmentProjection {
  double r = 0, s = 0, offset = 0;
  double distance = std::numeric_limits<double>::infinity();  // to the nearest point of the segment
};

// (r, s, d) with x_s = sum h_j x_j + d n exactly (Newton on the bilinear quad, converged to 1e-12 of the
// segment size; a linear solve for a triangle). `distance` is the distance from p to the segment itself
// (its coordinates clamped to the segment), the measure the search distance applies to. A degenerate
// segment, or a quad where Newton does not converge, gives an infinite distance.
inline SegmentProjection project_on_segment(const std::array<Vec3, 4>& x, bool triangle, const Vec3& p) {
  SegmentProjection out;
  const Vec3 nn = tie_normal(x, triangle);
  const double len = norm(nn);
  if (!(len > 0)) return out;
  const Vec3 n = scale(nn, 1.0 / len);
  const double size = std::sqrt(len);
  double r = triangle ? 1.0 / 3.0 : 0.0, s = r, d = 0;
  bool converged = false;
  for (int it = 0; it < 30 && !converged; ++it) {
    const auto h = tie_shape(r, s, triangle);
    Vec3 f = scale(n, d);
    for (int j = 0; j < 4; ++j)
      f = add(f, scale(x[static_cast<std::size_t>(j)], h[static_cast<std::size_t>(j)]));
    f = sub(f, p);
    Vec3 xr, xs;
    if (triangle) {
      xr = sub(x[1], x[0]);
      xs = sub(x[2], x[0]);
    } else {
      for (int c = 0; c < 3; ++c) {
        const auto k = static_cast<std::size_t>(c);
        xr[k] = 0.25 * ((1 - s) * (x[1][k] - x[0][k]) + (1 + s) * (x[2][k] - x[3][k]));
        xs[k] = 0.25 * ((1 - r) * (x[3][k] - x[0][k]) + (1 + r) * (x[2][k] - x[1][k]));
      }
    }
    // Solve [xr xs n] (dr, ds, dd) = -f by Cramer's rule.
    const double det = dot(xr, cross(xs, n));
    if (!(std::abs(det) > 0)) return out;
    const Vec3 mf = scale(f, -1.0);
    const double dr = dot(mf, cross(xs, n)) / det;
    const double ds = dot(xr, cross(mf, n)) / det;
    const double dd = dot(xr, cross(xs, mf)) / det;
    r += dr;
    s += ds;
    d += dd;
    converged = std::abs(dr) + std::abs(ds) < 1e-12 && std::abs(dd) < 1e-12 * size;
    if (triangle) converged = true;  // linear: one step is exact
  }
  if (!converged) return out;
  out.r = r;
  out.s = s;
  out.offset = d;
  double rc = r, sc = s;
  if (triangle) {
    rc = std::max(rc, 0.0);
    sc = std::max(sc, 0.0);
    if (rc + sc > 1) {
      const double t = rc + sc;
      rc /= t;
      sc /= t;
    }
  } else {
    rc = std::clamp(rc, -1.0, 1.0);
    sc = std::clamp(sc, -1.0, 1.0);
  }
  const auto h = tie_shape(rc, sc, triangle);
  Vec3 q{};
  for (int j = 0; j < 4; ++j)
    q = add(q, scale(x[static_cast<std::size_t>(j)], h[static_cast<std::size_t>(j)]));
  out.distance = norm(sub(p, q));
  return out;
}

}  // namespace radx::model
