// Three-node C0 shell (Ish3n 2, the default, and Ish3n 1): constant-strain membrane, Mindlin transverse
// shear, one point in the plane, no hourglass. Source of every formula: docs/theory/elements.md (sections in
// brackets), read from OpenRadioss c3forc3.F, c3evec3.F, c3deri3.F, c3defo3.F, c3curv3.F, c3fint3.F, c3dt3.F.
//
// Geometry [2], rebuilt every cycle from X^n: e1 = (X2 - X1)/|X2 - X1|, e3 = normalise((X3 - X1) x (X3 -
// X2)),
//   e2 = e3 x e1; local x2 = |X2 - X1|, x3 = e1.(X3 - X1), y3 = e2.(X3 - X1); A = x2 y3 / 2 (>= 1e-20);
//   PX1 = -y3/2, PY1 = (x3 - x2)/2, PY2 = -x3/2, PX2 = -PX1, PX3 = 0, PY3 = -(PY1 + PY2).
// Large-rotation velocity correction (tau = dt1/4; T11, T22 are the Ish3n 2 terms, 0 for Ish3n 1):
//   T1 = tau (vz1 - vz2)/(PY1 + PY2), T2 = tau [(PY1 vz1 + PY2 vz2)/(PY1 + PY2) - vz3]/PX1,
//   T11 = tau (vy1 - vy2)/(PY1 + PY2), T22 = tau [(PY1 vx1 + PY2 vx2)/(PY1 + PY2) - vx3]/PX1,
//   vx_k <- vx_k - vz_k T1 - vy_k T11, vy_k <- vy_k - vz_k T2 - vx_k(old) T22 (vz unchanged).
// Rates times A: exx = PX1 (vx1 - vx2), eyy = PY1 (vy1 - vy3) + PY2 (vy2 - vy3),
//   gxy = PY1 (vx1 - vx3) + PY2 (vx2 - vx3) + PX1 (vy1 - vy2);
//   kxx = PX1 (ry1 - ry2), kyy = -[PY1 (rx1 - rx3) + PY2 (rx2 - rx3)],
//   kxy = PY1 (ry1 - ry3) + PY2 (ry2 - ry3) - PX1 (rx1 - rx2);
//   gzx = PX1 (vz1 - vz2) + PX1/3 [PX1 (rx2 - rx1) + (2PY1 + 3PY2) ry1 + (3PY1 + 2PY2) ry2 + (PY1 + PY2)
//   ry3], gyz = PY1 (vz1 - vz3) + PY2 (vz2 - vz3) + 1/3 {-PX1 [(2PY1 + PY2) rx1 + (PY1 + 2PY2) rx2
//         + 3 (PY1 + PY2) rx3] + PY1 (PY1 + 2PY2) ry1 - PY2 (2PY1 + PY2) ry2 + (PY2^2 - PY1^2) ry3};
//   increments = rates dt1 / A.
// Section, energy, failure, thickness: as the quad [1.3-1.5, 1.8, 6.4, 6.5] (shell_section.hpp).
// Nodal forces: the virtual-power transpose of the rates above (as c3fint3.F), N = FOR t, M = MOM t^2,
//   times OFF; rotated to global axes and stored with the minus sign (force added to the node).
// Small strain (after a /DT/SH_3N/CST switch, g.dt_fixed > 0): x2, x3, y3 are frozen at the first cycle after
//   the switch and used from then on, so the B terms, A and the step stay constant.
// Element step [4.2] (before the /DT scale): dt = L phi / c, L = 2A / longest side, c = sqrt(E/rho),
//   phi = sqrt(1 + Dm^2) - Dm (1 by default). Nodal stiffness [4.5]: 0.81^2 A t A11 / L^2 per node.
//
// Layout: the group is run in blocks of kBlock elements: geometry and increments element by element, the
// through-thickness section of the whole block (shell_section.hpp, vectorised), then forces and steps
// element by element.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "solver/elements/element_gather.hpp"
#include "solver/elements/element_groups.hpp"
#include "solver/elements/shell/shell_frame.hpp"
#include "solver/elements/shell/shell_section.hpp"
#include "solver/elements/shell/shell_stages.hpp"

namespace radx::solver {

namespace {

using namespace shell_detail;  // the shared shell stages

constexpr int kBlock = 64;  // elements per block (see shell_bt4.cpp)
constexpr double kThird = 1.0 / 3.0;

inline double signed_floor3(double v, double eps) {
  return v >= 0 ? std::max(v, eps) : std::min(v, -eps);
}

// What the force stage needs from the geometry stage, [quantity][slot].
struct Tri3Block {
  NodeBlock<3, kBlock> nb;  // gathered positions and velocities, global axes
  double e1[3][kBlock], e2[3][kBlock], e3[3][kBlock];
  double px1[kBlock], py1[kBlock], py2[kBlock], x2[kBlock], x3[kBlock], y3[kBlock];
  shell_detail::SectionBlock<kBlock> sec;
};

// The group's constants of the kernel: the shared ones (shell_stages.hpp) and the triangle's own.
struct Tri3Constants {
  ShellConstants s;
  double tau;           // dt1 / 4 of the large-rotation correction
  bool in_plane_terms;  // Ish3n 2: T11 and T22 too
};

// Frame [2] of element j and its local coordinates x2, x3, y3 (node 1 at the origin, node 2 on e1). Small
// strain after a /DT/SH_3N/CST switch, or from the start with Ismstr 1: the local coordinates are frozen at
// the first cycle after it and used from then on (the frame and velocities stay current), so the step stays
// constant.
[[gnu::always_inline]] inline void tri3_local_geometry(const Tri3Block& bk, ShellGroup& g, int j,
                                                       std::size_t ii, double e1[3], double e2[3],
                                                       double e3[3], double& x2, double& x3, double& y3) {
  constexpr std::size_t G = kGroupSize;
  const double px[3] = {bk.nb.x[0][j], bk.nb.x[1][j], bk.nb.x[2][j]};
  const double py[3] = {bk.nb.y[0][j], bk.nb.y[1][j], bk.nb.y[2][j]};
  const double pz[3] = {bk.nb.z[0][j], bk.nb.z[1][j], bk.nb.z[2][j]};
  const double x2_now = tri_frame(px, py, pz, e1, e2, e3);
  const double d31x = px[2] - px[0], d31y = py[2] - py[0], d31z = pz[2] - pz[0];
  x2 = x2_now;
  x3 = e1[0] * d31x + e1[1] * d31y + e1[2] * d31z;
  y3 = e2[0] * d31x + e2[1] * d31y + e2[2] * d31z;
  if (g.dt_fixed[ii] > 0.0 || g.props.ismstr == 1) {
    if (g.small[ii] == 0.0) {
      g.ref_local[0 * G + ii] = x2, g.ref_local[1 * G + ii] = x3, g.ref_local[2 * G + ii] = y3;
      g.small[ii] = 1.0;
    }
    x2 = g.ref_local[0 * G + ii], x3 = g.ref_local[1 * G + ii], y3 = g.ref_local[2 * G + ii];
  }
}

// Element j's membrane, shear and curvature increments from its local velocities and rotation rates (PX1,
// PY1, PY2 are the area times dN/dx of its nodes 1 and 2, f = dt1 / A): the large-rotation correction (T11,
// T22 only for Ish3n 2), then the rates times A.
[[gnu::always_inline]] inline void tri3_increments(const Tri3Constants& k, double PX1, double PY1, double PY2,
                                                   double f, const double vx[3], const double vy[3],
                                                   const double vz[3], const double rx[3], const double ry[3],
                                                   double dem[5], double dk[3]) {
  const double tau = k.tau;
  const double s12 = signed_floor3(PY1 + PY2, 1e-20), sx1 = signed_floor3(PX1, 1e-20);
  const double T1 = tau * (vz[0] - vz[1]) / s12;
  const double T2 = tau * ((PY1 * vz[0] + PY2 * vz[1]) / s12 - vz[2]) / sx1;
  const double T11 = k.in_plane_terms ? tau * (vy[0] - vy[1]) / s12 : 0.0;
  const double T22 = k.in_plane_terms ? tau * ((PY1 * vx[0] + PY2 * vx[1]) / s12 - vx[2]) / sx1 : 0.0;
  double cx[3], cy[3];
  for (int n = 0; n < 3; ++n) {
    cx[n] = vx[n] - vz[n] * T1 - vy[n] * T11;
    cy[n] = vy[n] - vz[n] * T2 - vx[n] * T22;
  }
  const double sp = PY1 + PY2;
  const double gzx_r =
      kThird * PX1 *
      (PX1 * (rx[1] - rx[0]) + (2 * PY1 + 3 * PY2) * ry[0] + (3 * PY1 + 2 * PY2) * ry[1] + sp * ry[2]);
  const double gyz_r = kThird * (-PX1 * ((2 * PY1 + PY2) * rx[0] + (PY1 + 2 * PY2) * rx[1] + 3 * sp * rx[2]) +
                                 PY1 * (PY1 + 2 * PY2) * ry[0] - PY2 * (2 * PY1 + PY2) * ry[1] +
                                 (PY2 * PY2 - PY1 * PY1) * ry[2]);
  dem[0] = f * PX1 * (cx[0] - cx[1]);
  dem[1] = f * (PY1 * (cy[0] - cy[2]) + PY2 * (cy[1] - cy[2]));
  dem[2] = f * (PY1 * (cx[0] - cx[2]) + PY2 * (cx[1] - cx[2]) + PX1 * (cy[0] - cy[1]));
  dem[3] = f * (PY1 * (vz[0] - vz[2]) + PY2 * (vz[1] - vz[2]) + gyz_r);
  dem[4] = f * (PX1 * (vz[0] - vz[1]) + gzx_r);
  dk[0] = f * PX1 * (ry[0] - ry[1]);
  dk[1] = -f * (PY1 * (rx[0] - rx[2]) + PY2 * (rx[1] - rx[2]));
  dk[2] = f * (PY1 * (ry[0] - ry[2]) + PY2 * (ry[1] - ry[2]) - PX1 * (rx[0] - rx[1]));
}

// Geometry, rates and increments of the block's elements into the section's inputs; a deleted element is
// left alone by the section.
[[gnu::always_inline]] inline void tri3_geometry_and_increments(Tri3Block& bk, const Tri3Constants& k,
                                                                const MaterialParams& mat, ShellGroup& g,
                                                                int i0, int len) {
  SectionBlock<kBlock>& sec = bk.sec;
  const double dt1 = k.s.dt1, alpha = k.s.alpha;
  for (int j = 0; j < len; ++j) {
    const std::size_t ii = static_cast<std::size_t>(i0 + j);
    const double off_start = g.off[ii];
    sec.off[j] = off_start;
    if (off_start <= 0.0) {  // deleted: the section leaves it alone
      for (int q = 0; q < 5; ++q) sec.dem[q][j] = 0.0;
      for (int q = 0; q < 3; ++q) sec.dk[q][j] = 0.0;
      sec.t[j] = sec.area[j] = 0.0;
      sec.rfac[j] = 1.0;
      sec.rate[j] = 0.0;
      continue;
    }
    g.thick[ii] = first_use_thickness(FirstUseThickness::LiveElements, off_start, g.thick[ii], g.t0[ii]);
    const double t = k.s.update_thick ? g.thick[ii] : g.t0[ii];

    double e1[3], e2[3], e3[3], x2 = 0, x3 = 0, y3 = 0;
    tri3_local_geometry(bk, g, j, ii, e1, e2, e3, x2, x3, y3);
    const double e1x = e1[0], e1y = e1[1], e1z = e1[2], e2x = e2[0], e2y = e2[1], e2z = e2[2];
    const double e3x = e3[0], e3y = e3[1], e3z = e3[2];
    const double area = std::max(0.5 * x2 * y3, 1e-20);
    const double ainv = 1.0 / area;
    const double PX1 = -0.5 * y3, PY1 = 0.5 * (x3 - x2), PY2 = -0.5 * x3;

    double vx[3], vy[3], vz[3], rx[3], ry[3];
    for (int n = 0; n < 3; ++n) {
      double rz_unused = 0;
      to_local(e1x, e1y, e1z, e2x, e2y, e2z, e3x, e3y, e3z, bk.nb.vx[n][j], bk.nb.vy[n][j], bk.nb.vz[n][j],
               vx[n], vy[n], vz[n]);
      to_local(e1x, e1y, e1z, e2x, e2y, e2z, e3x, e3y, e3z, bk.nb.rx[n][j], bk.nb.ry[n][j], bk.nb.rz[n][j],
               rx[n], ry[n], rz_unused);
    }
    double dem[5], dk[3];
    tri3_increments(k, PX1, PY1, PY2, dt1 * ainv, vx, vy, vz, rx, ry, dem, dk);

    const double eq =
        dt1 > 0
            ? std::sqrt(equivalent_rate_arg(dem[0], dem[1], dem[2], dk[0], dk[1], dk[2], g.thick[ii])) / dt1
            : 0.0;
    const double rate = alpha * eq + (1.0 - alpha) * g.rate[ii];
    g.rate[ii] = rate;

    for (int q = 0; q < 5; ++q) sec.dem[q][j] = dem[q];
    for (int q = 0; q < 3; ++q) sec.dk[q][j] = dk[q];
    sec.t[j] = t;
    sec.area[j] = area;
    sec.rfac[j] = jc_rate_factor(mat, rate);
    sec.rate[j] = rate;
    bk.e1[0][j] = e1x, bk.e1[1][j] = e1y, bk.e1[2][j] = e1z;
    bk.e2[0][j] = e2x, bk.e2[1][j] = e2y, bk.e2[2][j] = e2z;
    bk.e3[0][j] = e3x, bk.e3[1][j] = e3y, bk.e3[2][j] = e3z;
    bk.px1[j] = PX1, bk.py1[j] = PY1, bk.py2[j] = PY2;
    bk.x2[j] = x2, bk.x3[j] = x3, bk.y3[j] = y3;
  }
}

// Element j's local nodal forces and moments: the transpose of the rates.
[[gnu::always_inline]] inline void tri3_local_forces(const Tri3Block& bk, int j, double off,
                                                     const double fv[3], double fx[3], double fy[3],
                                                     double fz[3], double mx[3], double my[3]) {
  const SectionBlock<kBlock>& sec = bk.sec;
  const double t = sec.t[j];
  const double PX1 = bk.px1[j], PY1 = bk.py1[j], PY2 = bk.py2[j], sp = PY1 + PY2;
  const double PX[3] = {PX1, -PX1, 0.0};
  const double PY[3] = {PY1, PY2, -(PY1 + PY2)};
  const double ot = off * t, ot2 = off * t * t;
  const double Nxx = ot * (sec.for_new[0][j] + fv[0]), Nyy = ot * (sec.for_new[1][j] + fv[1]),
               Nxy = ot * (sec.for_new[2][j] + fv[2]);
  const double Qy = ot * sec.for_new[3][j], Qx = ot * sec.for_new[4][j];
  const double Mxx = ot2 * sec.mom_new[0][j], Myy = ot2 * sec.mom_new[1][j], Mxy = ot2 * sec.mom_new[2][j];
  for (int n = 0; n < 3; ++n) {
    fx[n] = Nxx * PX[n] + Nxy * PY[n];
    fy[n] = Nxy * PX[n] + Nyy * PY[n];
    fz[n] = Qx * PX[n] + Qy * PY[n];
    mx[n] = -(Myy * PY[n] + Mxy * PX[n]);
    my[n] = Mxx * PX[n] + Mxy * PY[n];
  }
  // Transverse shear rotation terms (transpose of gzx_r and gyz_r).
  const double qx3 = kThird * Qx * PX1, qy3 = kThird * Qy;
  my[0] += qx3 * (2 * PY1 + 3 * PY2) + qy3 * PY1 * (PY1 + 2 * PY2);
  my[1] += qx3 * (3 * PY1 + 2 * PY2) - qy3 * PY2 * (2 * PY1 + PY2);
  my[2] += qx3 * sp + qy3 * (PY2 * PY2 - PY1 * PY1);
  mx[0] += -qx3 * PX1 - qy3 * PX1 * (2 * PY1 + PY2);
  mx[1] += qx3 * PX1 - qy3 * PX1 * (PY1 + 2 * PY2);
  mx[2] += -qy3 * PX1 * 3 * sp;
}

// Failure, thickness, energy, forces rotated to global axes, element step [4.2] and nodal stiffness [4.5].
[[gnu::always_inline]] inline void tri3_close_block(const Tri3Block& bk, const Tri3Constants& k,
                                                    ShellGroup& g, int i0, int len) {
  constexpr std::size_t G = kGroupSize;
  const SectionBlock<kBlock>& sec = bk.sec;
  double* nf = g.nodal_force.data();
  for (int j = 0; j < len; ++j) {
    const std::size_t ii = static_cast<std::size_t>(i0 + j);
    for (int r = 18; r < 24; ++r) nf[r * G + ii] = 0.0;  // row 3 is unused by triangles
    const double off_start = sec.off[j];
    if (off_start <= 0.0) {
      clear_shell_element(g, nf, ii, 18);
      continue;
    }
    const double t = sec.t[j], area = sec.area[j];
    const double dem[5] = {sec.dem[0][j], sec.dem[1][j], sec.dem[2][j], sec.dem[3][j], sec.dem[4][j]};
    const double dk[3] = {sec.dk[0][j], sec.dk[1][j], sec.dk[2][j]};
    const double off = next_off(k.s.fail_limit, off_start, sec.eps_p_max[j], sec.fail_now[j]);
    g.off[ii] = off;
    g.w_plastic[ii] += sec.w_plastic[j];
    g.thick[ii] += sec.dthick[j] * off;

    double fv[3];
    membrane_damping(k.s.visc0, area, dem, fv);
    g.e_int[ii] += shell_energy_increment(area, t, off_start, off, sec.for_old, sec.for_new, sec.mom_old,
                                          sec.mom_new, j, dem, dk, fv);
    if (off <= 0.0) {
      clear_shell_element(g, nf, ii, 18);
      continue;
    }
    double fx[3], fy[3], fz[3], mx[3], my[3];
    tri3_local_forces(bk, j, off, fv, fx, fy, fz, mx, my);
    const double e1x = bk.e1[0][j], e1y = bk.e1[1][j], e1z = bk.e1[2][j];
    const double e2x = bk.e2[0][j], e2y = bk.e2[1][j], e2z = bk.e2[2][j];
    const double e3x = bk.e3[0][j], e3y = bk.e3[1][j], e3z = bk.e3[2][j];
    for (int n = 0; n < 3; ++n)
      store_local_forces(nf, G, static_cast<std::size_t>(n), ii, e1x, e1y, e1z, e2x, e2y, e2z, e3x, e3y, e3z,
                         fx[n], fy[n], fz[n], mx[n], my[n]);

    const double x2 = bk.x2[j], x3 = bk.x3[j], y3 = bk.y3[j];
    const double l12 = x2 * x2, l23 = (x3 - x2) * (x3 - x2) + y3 * y3, l31 = x3 * x3 + y3 * y3;
    const double lmax2 = std::max({l12, l23, l31, 1e-40});
    const double l = 2.0 * area / std::sqrt(lmax2);
    g.dt[ii] = l * k.s.phi / k.s.c;
    g.k_nodal[ii] = 0.81 * 0.81 * area * t * k.s.a11 / (l * l);
  }
}

}  // namespace

// The kernel: the list of its stages over each block of the group.
void shell_c0_tri3_forces(ShellGroup& g, const NodeState& nodes, const MaterialParams& mat,
                          const CycleInfo& cyc) {
  ensure_resultant_storage(g);
  const Tri3Constants k{shell_constants(g.props, mat, cyc.dt1, g.props.dm), 0.25 * cyc.dt1,
                        g.props.ish3n == 2};
  Tri3Block bk;
  SectionBlock<kBlock>& sec = bk.sec;
  sec.dt1 = k.s.dt1;  // law 27's rate term
  for (int i0 = 0; i0 < g.count; i0 += kBlock) {
    const int len = std::min(kBlock, g.count - i0);
    // Gather [docs/architecture.md 3], geometry, rates and increments.
    gather_block<true>(g.conn.data(), kGroupSize, static_cast<std::size_t>(i0), static_cast<std::size_t>(len),
                       nodes, bk.nb);
    tri3_geometry_and_increments(bk, k, mat, g, i0, len);
    // Section [1.4, 1.8, 6].
    section_update_block(g, i0, len, mat, k.s.rule, k.s.gs, sec);
    tri3_close_block(bk, k, g, i0, len);
  }
}

}  // namespace radx::solver
