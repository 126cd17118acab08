// The one gather and scatter path of the element families. Every element kernel reads its nodes' state
// through these functions and writes its nodal forces through store_nodal_forces, so the node ordering of a
// group (`conn` rows [node k][element i], k * kGroupSize + i) and of its force buffer ([node][component][i])
// is written once. The engine then adds the force buffers to the nodes' sums group by group, in a fixed
// order.
//
// Two shapes of gather:
//   gather_element: one element into local [N][3] arrays (bricks, tetrahedra: kernels that run one element
//                   at a time through local arrays);
//   gather_block:   a run of up to B consecutive elements into [N][B] rows (shells: kernels whose stages run
//                   vectorised across the elements of a block).
#pragma once

#include <cstddef>
#include <cstdint>

#include "solver/engine/node_state.hpp"

namespace radx::solver {

// Node positions and mid-step velocities of element i of a group with `stride` slots: x[k], v[k] of its
// k-th node (k < N), in global axes.
template <std::size_t N>
inline void gather_element(const std::int32_t* conn, std::size_t stride, std::size_t i,
                           const NodeState& nodes, double x[N][3], double v[N][3]) {
#pragma GCC unroll 10
  for (std::size_t k = 0; k < N; ++k) {
    const auto nd = static_cast<std::size_t>(conn[k * stride + i]);
    x[k][0] = nodes.x[nd];
    x[k][1] = nodes.y[nd];
    x[k][2] = nodes.z[nd];
    v[k][0] = nodes.vx[nd];
    v[k][1] = nodes.vy[nd];
    v[k][2] = nodes.vz[nd];
  }
}

// Rows of a block gather: element j of the block in column j.
template <std::size_t N, std::size_t B>
struct NodeBlock {
  double x[N][B], y[N][B], z[N][B];     // positions x^n
  double vx[N][B], vy[N][B], vz[N][B];  // velocities v^{n-1/2}
  double rx[N][B], ry[N][B], rz[N][B];  // angular velocities (filled when asked for)
  std::int32_t node[N][B];              // dense node indices
};

// Elements i0 .. i0 + len - 1 of a group with `stride` slots into the block's columns 0 .. len - 1.
// kRotations: also gather the angular velocities (shells).
template <bool kRotations, std::size_t N, std::size_t B>
inline void gather_block(const std::int32_t* conn, std::size_t stride, std::size_t i0, std::size_t len,
                         const NodeState& nodes, NodeBlock<N, B>& b) {
  const double* X = nodes.x.data();
  const double* Y = nodes.y.data();
  const double* Z = nodes.z.data();
  const double* VX = nodes.vx.data();
  const double* VY = nodes.vy.data();
  const double* VZ = nodes.vz.data();
  for (std::size_t j = 0; j < len; ++j) {
    for (std::size_t k = 0; k < N; ++k) {
      const std::int32_t n = conn[k * stride + i0 + j];
      b.node[k][j] = n;
      b.x[k][j] = X[n];
      b.y[k][j] = Y[n];
      b.z[k][j] = Z[n];
      b.vx[k][j] = VX[n];
      b.vy[k][j] = VY[n];
      b.vz[k][j] = VZ[n];
      if constexpr (kRotations) {
        b.rx[k][j] = nodes.wx[static_cast<std::size_t>(n)];
        b.ry[k][j] = nodes.wy[static_cast<std::size_t>(n)];
        b.rz[k][j] = nodes.wz[static_cast<std::size_t>(n)];
      }
    }
  }
}

// Element i's nodal forces f[k][c] (ADDED to node k, component c < C, global axes), times `scale` (the
// element's kill factor), into the group's force buffer laid out [N][C][stride].
template <std::size_t N, std::size_t C>
inline void store_nodal_forces(double* buf, std::size_t stride, std::size_t i, double scale,
                               const double f[N][C]) {
#pragma GCC unroll 10
  for (std::size_t k = 0; k < N; ++k)
#pragma GCC unroll 6
    for (std::size_t c = 0; c < C; ++c) buf[(k * C + c) * stride + i] = scale * f[k][c];
}

// Element i gives no force (deleted, or a bad geometry).
template <std::size_t N, std::size_t C>
inline void clear_nodal_forces(double* buf, std::size_t stride, std::size_t i) {
  for (std::size_t r = 0; r < N * C; ++r) buf[r * stride + i] = 0.0;
}

}  // namespace radx::solver
