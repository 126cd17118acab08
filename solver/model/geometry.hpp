// Element geometry shared by the starter's checks and masses and by the engine. Formulas follow
// OpenRadioss's one-point elements (docs/theory/elements.md):
//   quad area      A = 1/2 |d13 x d24|                         (d13 = x3 - x1, d24 = x4 - x2)
//   triangle area  A = 1/2 |d12 x d13|
//   brick volume   V = j1 . (j2 x j3) / 64 = 8 det J(0)        with d17 = x7 - x1, d28 = x8 - x2,
//                  j1 = d17 + d28 - d35 - d46, j2 = d17 + d46 + d28 + d35, j3 = d17 + d46 - d28 - d35
//   tetra volume   V = (x1 - x4) . ((x2 - x4) x (x3 - x4)) / 6    (OpenRadioss's sign: positive when the
//                  right-hand normal of n1 n2 n3 points away from n4; starter checksvolume.F, s4deri3.F)
// The one-point brick volume is not the exact trilinear volume of a distorted brick; it is the volume
// the element uses, so the mass and the density agree with the element.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

namespace radx::model {

using Vec3 = std::array<double, 3>;

inline Vec3 sub(const Vec3& a, const Vec3& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
inline Vec3 add(const Vec3& a, const Vec3& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
inline Vec3 scale(const Vec3& a, double s) {
  return {a[0] * s, a[1] * s, a[2] * s};
}
inline double dot(const Vec3& a, const Vec3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double norm(const Vec3& a) {
  return std::sqrt(dot(a, a));
}

inline double quad_area(const Vec3& x1, const Vec3& x2, const Vec3& x3, const Vec3& x4) {
  return 0.5 * norm(cross(sub(x3, x1), sub(x4, x2)));
}
inline double triangle_area(const Vec3& x1, const Vec3& x2, const Vec3& x3) {
  return 0.5 * norm(cross(sub(x2, x1), sub(x3, x1)));
}
// Unnormalised quad normal d13 x d24 (its length is twice the area).
inline Vec3 quad_normal(const Vec3& x1, const Vec3& x2, const Vec3& x3, const Vec3& x4) {
  return cross(sub(x3, x1), sub(x4, x2));
}

inline double brick_volume(const std::array<Vec3, 8>& x) {
  const Vec3 d17 = sub(x[6], x[0]);
  const Vec3 d28 = sub(x[7], x[1]);
  const Vec3 d35 = sub(x[4], x[2]);
  const Vec3 d46 = sub(x[5], x[3]);
  const Vec3 j1 = sub(add(d17, d28), add(d35, d46));
  const Vec3 j2 = add(add(d17, d46), add(d28, d35));
  const Vec3 j3 = sub(add(d17, d46), add(d28, d35));
  return dot(j1, cross(j2, j3)) / 64.0;
}

// The corner of a brick whose tetrahedron (the node and its three edge neighbours, taken in the
// right-hand order of a positive brick) has the most negative signed volume relative to its edge
// lengths, and that ratio: det(e1, e2, e3) / (|e1| |e2| |e3|), -1 for a right corner turned inside out.
// A valid brick has every corner >= 0 (0 where a degenerate brick repeats a node); a brick whose node
// was pushed through the opposite face keeps a positive one-point volume but has a negative corner,
// the standard sign of a tangled hexahedron.
struct BrickCorner {
  int node = -1;  // position 0..7, -1 when no corner is negative
  double ratio = 0;
};
inline BrickCorner most_negative_brick_corner(const std::array<Vec3, 8>& x) {
  static constexpr std::array<std::array<int, 3>, 8> kNeighbours = {{
      {1, 3, 4},
      {2, 0, 5},
      {3, 1, 6},
      {0, 2, 7},
      {7, 5, 0},
      {4, 6, 1},
      {5, 7, 2},
      {6, 4, 3},
  }};
  BrickCorner worst;
  for (int k = 0; k < 8; ++k) {
    const auto& nb = kNeighbours[static_cast<std::size_t>(k)];
    const Vec3 e1 = sub(x[static_cast<std::size_t>(nb[0])], x[static_cast<std::size_t>(k)]);
    const Vec3 e2 = sub(x[static_cast<std::size_t>(nb[1])], x[static_cast<std::size_t>(k)]);
    const Vec3 e3 = sub(x[static_cast<std::size_t>(nb[2])], x[static_cast<std::size_t>(k)]);
    const double lengths = norm(e1) * norm(e2) * norm(e3);
    if (!(lengths > 0)) continue;  // a repeated node: a degenerate brick, not a tangled one
    const double r = dot(e1, cross(e2, e3)) / lengths;
    if (r < worst.ratio) worst = {k, r};
  }
  return worst;
}

// The frame of a /SKEW/MOV from the positions of its nodes N1 N2 N3 (OpenRadioss starter hm_read_skw.F,
// engine newskw.F). Axis a = dir (0 x', 1 y', 2 z') runs along N1 -> N2; with b = a + 1 and c = a + 2
// (mod 3):
//   e_a = N2 - N1,   e_c = e_a x (N3 - N1),   e_b = e_c x e_a,   each normalised,
// so N3 lies in the (e_a, e_b) plane, on the positive side of e_b (Dir X: x' = N1N2, z' = x' x N1N3).
// Positions the starter refuses (N1 = N2, N3 on the line N1 N2) can still arise during a run; they get
// newskw.F's fallbacks: e_a = 0 becomes the global axis a, and N3 - N1 parallel to e_a is replaced by e_a
// with its X component set to |e_a| when that component is 0, else its Y component set to |e_a_y| + |e_a|.
// Returns the rows x', y', z' (global components), as Skew::axes.
inline std::array<double, 9> node_skew_axes(const Vec3& n1, const Vec3& n2, const Vec3& n3, int dir) {
  const auto a = static_cast<std::size_t>(dir), b = (a + 1) % 3, c = (a + 2) % 3;
  std::array<Vec3, 3> e{};
  e[a] = sub(n2, n1);
  double la = norm(e[a]);
  if (la == 0) {
    e[a] = {0, 0, 0};
    e[a][a] = 1;
    la = 1;
  }
  Vec3 t = sub(n3, n1);
  e[c] = cross(e[a], t);
  if (norm(e[c]) == 0) {
    t = e[a];
    if (t[0] == 0)
      t[0] = la;
    else
      t[1] = std::abs(t[1]) + la;
    e[c] = cross(e[a], t);
  }
  e[b] = cross(e[c], e[a]);
  std::array<double, 9> axes{};
  for (std::size_t k = 0; k < 3; ++k) {
    const double l = norm(e[k]);
    for (std::size_t d = 0; d < 3; ++d) axes[3 * k + d] = e[k][d] / l;
  }
  return axes;
}

// The six faces of a brick, node positions 0..7, ordered so that the right-hand normal points out of
// a positively oriented brick (nodes 1-4 bottom counter-clockwise seen from outside below... i.e. the
// normal of 1-2-3-4 by the right-hand rule points to 5-8 for a positive volume, so the bottom face is
// written reversed).
inline constexpr std::array<std::array<int, 4>, 6> kBrickFaces = {{
    {0, 3, 2, 1},  // bottom (1-4 reversed)
    {4, 5, 6, 7},  // top
    {0, 1, 5, 4},
    {1, 2, 6, 5},
    {2, 3, 7, 6},
    {3, 0, 4, 7},
}};

// Signed volume of a 4-node tetrahedron in Radioss's orientation (see the head of this file): a tetra the
// starter accepts has V > 0.
inline double tetra_volume(const Vec3& x1, const Vec3& x2, const Vec3& x3, const Vec3& x4) {
  return dot(sub(x1, x4), cross(sub(x2, x4), sub(x3, x4))) / 6.0;
}

// The four faces of a positive tetrahedron (node positions 0..3), each with its right-hand normal pointing
// out of the element; face f is the one opposite node kTetraOpposite[f].
inline constexpr std::array<std::array<int, 3>, 4> kTetraFaces = {{
    {0, 1, 2},
    {0, 3, 1},
    {0, 2, 3},
    {1, 3, 2},
}};
inline constexpr std::array<int, 4> kTetraOpposite = {3, 2, 1, 0};

// Characteristic length of the tetrahedron for its time step: the smallest of its four heights,
// 3 V / (largest face area), i.e. 1 / max_k |grad N_k| (OpenRadioss s4deri3.F with its default Idt1sol 0).
// 0 for a flat or inverted tetrahedron.
inline double tetra_length(const Vec3& x1, const Vec3& x2, const Vec3& x3, const Vec3& x4) {
  const double v = tetra_volume(x1, x2, x3, x4);
  const double a = std::max(std::max(triangle_area(x1, x2, x3), triangle_area(x1, x2, x4)),
                            std::max(triangle_area(x1, x3, x4), triangle_area(x2, x3, x4)));
  return v > 0 && a > 0 ? 3.0 * v / a : 0.0;
}

}  // namespace radx::model
