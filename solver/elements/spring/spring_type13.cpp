// TYPE13 beam-type spring (/SPRING with /PROP/SPR_BEAM): six springs between two nodes in a frame that
// follows the element - X along n1 -> n2, Y and Z turned with the mean spin about X - with the shear forces
// balanced by end moments over the length, as a beam's are. Each of the six laws (tension X, shear Y Z,
// torsion RX, bending RY RZ) follows the scalar spring law of spring_law.hpp.
//
// Sources, read for the behaviour (OpenRadioss): engine/source/elements/spring/r4evec3.F (the frame),
// r4def3.F (elongations, laws, failure, step parameters), r2len3.F (time step), r4cum3.F (nodal forces and
// moments); starter hm_read_prop13.F (defaults), r4buf3.F (initial frame), rmass.F (mass and inertia).
//
// Nodes x1, x2 at x^n, velocities v1, v2 and angular velocities w1, w2 at t^{n-1/2}; dt1 = t^n - t^{n-1},
// h = dt1 / 2.
// Frame (r4evec3.F). At the end of the step: l = x2 - x1, L = |l|, e_x = l / L. At mid-step:
// lh = l - h (v2 - v1), Lh = |lh|, e_xh = lh / Lh. y_old the Y axis of the last cycle.
//   turn(e, a): z = unit(e x y_old), y = z x e (y_old made normal to e), then y' = y cos a + z sin a,
//     z' = e x y'  (y turned about e by the angle a)
//   theta = h (w1 + w2) / 2 . e_xh                       (half the step's mean spin about the axis)
//   mid-step frame (e_xh, turn(e_xh, theta)), end frame (e_x, turn(e_x, 2 theta)); y_old <- the end Y.
//   Initially (r4buf3.F) y_old = the part of r normal to e_x, with r = x3 - x1 (n3), or, without n3 or
//   with n3 on the axis (sin(l, r) < 1e-5), the skew's Y axis (global Y without skew), or its X axis if
//   that one lies along the spring too.
// Elongations, in the mid-step frame (e_xh, e_yh, e_zh) (r4def3.F):
//   u_x = L - L0                                                          (total: tension)
//   u_y = u_y_old + Lh (2 atan(h (v2 - v1) . e_yh / Lh) - h (w1 + w2) . e_zh)     (shear Y)
//   u_z = u_z_old + Lh (2 atan(h (v2 - v1) . e_zh / Lh) + h (w1 + w2) . e_yh)     (shear Z)
//     i.e. the transverse displacement less L times the mean rotation of the ends: the shear deformation
//     of a beam, 0 under a rigid rotation and under pure bending (end rotations -th, +th)
//   r_j = r_j_old + dt1 (w2 - w1) . e_jh                      j = X Y Z: torsion, bending (relative
//   rotations) N_x, N_y, N_z, M_x, M_y, M_z: the six laws of spring_six_laws.hpp (failure, work)
// Nodal forces and moments in the end frame (r4cum3.F), F = N_x e_x + N_y e_y + N_z e_z:
//   n1: +F,  M1 = M_x e_x + (M_y - L/2 N_z) e_y + (M_z + L/2 N_y) e_z
//   n2: -F,  M2 = -(M_x e_x + (M_y + L/2 N_z) e_y + (M_z - L/2 N_y) e_z)
//   M1 + M2 + l x (-F) = 0: the element is in moment equilibrium.
// Beam relation: with n1 clamped and n2 moved by v across the axis (Y) and turned by phi about Z,
//   N_y = K_y (v - L phi / 2), M_z = K_rz phi; on n2: F_y = -K_y (v - L phi/2),
//   M_z2 = -K_rz phi + (L/2) K_y (v - L phi/2). With K_y = 12 EI / L^3 and K_rz = EI / L these are the
//   Euler-Bernoulli beam's end force and moment (12 EI/L^3 v - 6 EI/L^2 phi, -6 EI/L^2 v + 4 EI/L phi).
// Time step (r4def3.F, r2len3.F), M the mass and I the inertia, K and C each law's stiffness and damping:
//   k_t = max(K_x, K_y, K_z), c_t = max(C_x, C_y, C_z),
//   k_r = max(K_y, K_z) L^2 + max(K_rx, K_ry, K_rz),  c_r = max(C_y, C_z) L^2 + max(C_rx, C_ry, C_rz)
//   (the shear stiffness over the length acts on the rotations); dt: spring_six_laws.hpp.
#include <algorithm>
#include <cmath>

#include "solver/elements/element_groups.hpp"
#include "solver/elements/spring/spring_six_laws.hpp"
#include "solver/model/geometry.hpp"

namespace radx::solver {

namespace {

struct V3 {
  double x, y, z;
};
inline V3 operator-(V3 a, V3 b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline V3 operator+(V3 a, V3 b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline V3 operator*(double s, V3 a) {
  return {s * a.x, s * a.y, s * a.z};
}
inline double dot(V3 a, V3 b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline V3 cross(V3 a, V3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline V3 unit(V3 a) {
  return (1.0 / std::max(1e-15, std::sqrt(dot(a, a)))) * a;
}

struct Frame {
  V3 x, y, z;
};

// The frame of axis e (unit) whose Y axis is y_old made normal to e, then turned about e by the angle a.
Frame turn(V3 e, V3 y_old, double a) {
  const V3 z = unit(cross(e, y_old));
  const V3 y = cross(z, e);
  const V3 y2 = unit(std::cos(a) * y + std::sin(a) * z);
  return {e, y2, unit(cross(e, y2))};
}

}  // namespace

model::Vec3 spring_type13_initial_y(const model::Vec3& l, const std::optional<model::Vec3>& r3,
                                    const std::array<double, 9>& skew_axes) {
  const V3 e{l[0], l[1], l[2]};
  // sin of the angle between the spring and r: below 1e-5 r lies along the spring and cannot orient it.
  auto off_axis = [&](V3 r) {
    const double lr = std::sqrt(dot(e, e) * dot(r, r));
    return lr > 0 && std::sqrt(dot(cross(e, r), cross(e, r))) / lr >= 1e-5;
  };
  V3 r{skew_axes[3], skew_axes[4], skew_axes[5]};
  if (r3 && off_axis(V3{(*r3)[0], (*r3)[1], (*r3)[2]}))
    r = V3{(*r3)[0], (*r3)[1], (*r3)[2]};
  else if (!off_axis(r))
    r = V3{skew_axes[0], skew_axes[1], skew_axes[2]};
  if (dot(e, e) <= 1e-30) return {0, 1, 0};  // no axis: the engine takes global X and Y
  const V3 y = unit(cross(cross(e, r), e));
  return {y.x, y.y, y.z};
}

void spring_type13_forces(SpringGroup& g, const NodeState& nodes, const CycleInfo& cyc) {
  constexpr std::size_t G = kGroupSize;
  const auto& p = g.props;
  const double dt1 = cyc.dt1, h = 0.5 * cyc.dt1;
  const double inv_dt = dt1 > 0 ? 1.0 / dt1 : 0.0;
  const auto t = spring_family(p, 0), r = spring_family(p, 3);
  // The shear laws' share of the rotational step, per unit length squared.
  const double k_sh = std::max(p.law(1).stiffness, p.law(2).stiffness);
  const double c_sh = std::max(p.law(1).damping, p.law(2).damping);
  for (int ii = 0; ii < g.count; ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    if (spring_six_released(g, i)) {
      spring_six_off(g, i);
      continue;
    }
    const auto n1 = static_cast<std::size_t>(g.conn[i]);
    const auto n2 = static_cast<std::size_t>(g.conn[G + i]);
    const V3 l{nodes.x[n2] - nodes.x[n1], nodes.y[n2] - nodes.y[n1], nodes.z[n2] - nodes.z[n1]};
    const V3 v21{nodes.vx[n2] - nodes.vx[n1], nodes.vy[n2] - nodes.vy[n1], nodes.vz[n2] - nodes.vz[n1]};
    const V3 w1{nodes.wx[n1], nodes.wy[n1], nodes.wz[n1]};
    const V3 w2{nodes.wx[n2], nodes.wy[n2], nodes.wz[n2]};
    const V3 lh = l - h * v21;
    const double len = std::sqrt(dot(l, l)), len_h = std::sqrt(dot(lh, lh));
    V3 y_old{g.ey[i], g.ey[G + i], g.ey[2 * G + i]};
    // A spring of zero length has no axis: global X, with global Y (as Radioss).
    V3 ex = unit(l), exh = unit(lh);
    if (len <= 1e-15 || len_h <= 1e-15) {
      ex = exh = V3{1, 0, 0};
      y_old = V3{0, 1, 0};
    }
    const V3 wsum = w1 + w2;
    const double theta = h * 0.5 * dot(wsum, exh);
    const Frame fh = turn(exh, y_old, theta);
    const Frame fe = turn(ex, y_old, 2 * theta);
    g.ey[i] = fe.y.x;
    g.ey[G + i] = fe.y.y;
    g.ey[2 * G + i] = fe.y.z;

    spring_six_step(g, i, t, {k_sh * len * len + r.k, c_sh * len * len + r.c});

    const double lh_safe = std::max(len_h, 1e-30);
    const double chord_y = 2 * std::atan(h * dot(v21, fh.y) / lh_safe);  // chord's turn towards Y
    const double chord_z = 2 * std::atan(h * dot(v21, fh.z) / lh_safe);  // and towards Z
    const V3 w21 = w2 - w1;
    double q[6], n[6];
    q[0] = len - g.l0[i];
    q[1] = g.dx[G + i] + len_h * (chord_y - h * dot(wsum, fh.z));
    q[2] = g.dx[2 * G + i] + len_h * (chord_z + h * dot(wsum, fh.y));
    q[3] = g.dx[3 * G + i] + dt1 * dot(w21, fh.x);
    q[4] = g.dx[4 * G + i] + dt1 * dot(w21, fh.y);
    q[5] = g.dx[5 * G + i] + dt1 * dot(w21, fh.z);
    spring_six_laws(g, i, q, inv_dt, n);

    const double half = 0.5 * len;
    const V3 f = n[0] * fe.x + n[1] * fe.y + n[2] * fe.z;
    const V3 m1 = n[3] * fe.x + (n[4] - half * n[2]) * fe.y + (n[5] + half * n[1]) * fe.z;
    const V3 m2 = n[3] * fe.x + (n[4] + half * n[2]) * fe.y + (n[5] - half * n[1]) * fe.z;
    const double out[12] = {f.x, f.y, f.z, m1.x, m1.y, m1.z, -f.x, -f.y, -f.z, -m2.x, -m2.y, -m2.z};
    for (std::size_t d = 0; d < 12; ++d) g.nodal_force[d * G + i] = out[d];
  }
}

}  // namespace radx::solver
