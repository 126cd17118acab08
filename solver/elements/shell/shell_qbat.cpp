// Four-node shell QBAT (Ishell 12): four integration points in the plane (2 x 2 Gauss), each with the N
// through-thickness points of the section, and an assumed transverse shear field. Sources:
// docs/theory/elements.md 1.1 (flags), 1.10 (the step, shared with QEPH), 4.5 and 5, read from OpenRadioss
// cbaforc3.F (call sequence: four Gauss points, a material call at each, CNDT3 for the step as QEPH),
// cbacoor.F (frame), cbadef.F (rates at the Gauss points, transverse shear from values tied at the edge
// midpoints), cbafori.F (forces), cinmas.F (inertia). Written from the formulas, in our own words and
// structure; what is our interpretation is marked [inferred].
//
// Frame and local coordinates: shell_frame.hpp (1.2), rebuilt every cycle; stresses stay in that frame.
// Warp: the rows are those of the element projected on its mean plane, but the membrane rates take the
//   warp z_k of the nodes off that plane (z_k = +-Z h_k, h = (1, -1, 1, -1)): with the slopes z,x = sum
//   N_k,x z_k, z,y and w,x = sum N_k,x vz_k, w,y at the point,
//     exx += z,x w,x,  eyy += z,y w,y,  gxy += z,x w,y + z,y w,x,
//   the in-plane part of the surface's covariant rate 1/2 (g_a . v,b + g_b . v,a) once g_a = g_a(plane) +
//   z,a e3, which makes every rigid motion strain-free. Without it a rigid rotation of rate Om about an
//   in-plane axis gives the warped nodes the in-plane velocities Om z_k, an h pattern that the Gauss points
//   of an a x a element read as exx, eyy = +-Om Z 2/(sqrt(3) a): a warped element turning in a fold yields
//   where it does not deform (OpenRadioss's cbadef.F takes the nodes' velocities in the tangent frame of
//   each Gauss point of a warped element, which is free of it [read; our first-order equivalent]).
//   The forces carry the transpose: fz_k += det J(g) (Nxx z,x N_k,x + Nyy z,y N_k,y), the shear's through
//   the centre rows.
// At each Gauss point g (xi, eta = +-1/sqrt(3), weight det J(g); shell_quad_mindlin.hpp):
//   de(g) = rows(g) v dt1 with the second-order membrane correction of 1.3 at the point's slopes
//   (quad_second_order) (membrane exx eyy, curvature kxx kyy kxy, transverse shear gyz gzx from the
//   assumed field tied at the edge midpoints [inferred to be the Bathe-Dvorkin/Batoz Q4gamma field]);
//   the membrane shear gxy is the centre's, rows(0) v dt1, at every Gauss point (assumed membrane shear
//   strain: cbaforc3.F calls CBADEFSH, "use only the constant part", and the forces CBAFORCT with the
//   centre rows, whenever Idrill is 0, which radx always runs). Taken at the Gauss points, gxy would lock
//   in-plane bending: the bending mode u = c x y of an a x b element would store the shear energy
//   G c^2 b a^3/24 on top of the bending's E/(1 - nu^2) c^2 a b^3/24 (a square: 1.48 times the
//   beam's E I, against 1.10 with the centre's shear);
//   the section (shell_section.hpp: 1.4, 1.8, 6.3, 6.5) updates FOR(g), MOM(g) at its N points;
//   f_k = sum_g det J(g) rows(g)^T (N(g), M(g), Q(g)) times OFF, N = FOR t, M = MOM t^2, Q = FOR_shear t,
//   except that Nxy(g) acts through rows(0): the exact transpose of the constant gxy, so that the work
//   of the forces is the energy below [radx: OpenRadioss applies the plain mean of the four points' Nxy
//   with the area; the same on a parallelogram, where the det J(g) are equal];
//   E_int += sum_g 1/2 det J(g) t [(OFF_old FOR_old + OFF FOR_new).de_m + t (OFF_old MOM_old + OFF
//   MOM_new).dkappa] (1.5 summed over the points).
// Full 2 x 2 integration of the bilinear field has no zero-energy mode besides the drilling rotation (no
// stiffness, as Ishell 1): there is no hourglass control and no hourglass energy. Hm, Hf, Hr are not used.
// Element rate (1.3) and failure (6.4) are one value per element: the rate from the centre increments, OFF
// from the largest eps_p over all points of all Gauss points.
// Membrane damping (Dm > 0 only, 1.4) at each Gauss point, its work in the internal energy.
// Step (1.10; stored before the /DT scale): dt = L (sqrt(1 + Dn^2) - Dn)/c, c = sqrt(E/rho), L of
//   qeph_step_length; Dn stays 0 by default for QBAT (hm_read_prop01.F sets 0.015 for Ishell 24 only).
//   Nodal stiffness (4.5, cndt3.F): k = 1/2 A t A11 / L^2.
// Inertia (5): I = m/4 (A0/12 + t0^2/12), set by the engine.
// Outputs: the element's stress is the mean over the Gauss points of the through-thickness mean
//   (result_fields.cpp).
//
// Layout: as shell_qeph.cpp; the section runs four times per block, once per Gauss point, on that point's
// own rows of ShellGroup::sig and ::eps_p ([gauss][n_points]...).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "solver/elements/element_gather.hpp"
#include "solver/elements/element_groups.hpp"
#include "solver/elements/shell/shell_frame.hpp"
#include "solver/elements/shell/shell_quad_mindlin.hpp"
#include "solver/elements/shell/shell_section.hpp"
#include "solver/elements/shell/shell_stages.hpp"

namespace radx::solver {

namespace {

using namespace shell_detail;  // the shared shell stages and the quad rows (shell_quad_mindlin.hpp)

constexpr int kBlock = 64;  // elements per block (see shell_bt4.cpp)

struct QbatBlock {
  NodeBlock<4, kBlock> nb;
  shell_detail::FrameBlock<kBlock> fr;
  double vx[4][kBlock], vy[4][kBlock], vz[4][kBlock], rx[4][kBlock], ry[4][kBlock];  // local
  double lx[4][kBlock], ly[4][kBlock];                                               // local coordinates
  double t[kBlock], area[kBlock], rfac[kBlock], rate[kBlock], off[kBlock];
  // Per Gauss point: increments and the section's resultants before and after the update.
  double dem[4][5][kBlock], dk[4][3][kBlock];
  double for_old[4][5][kBlock], for_new[4][5][kBlock], mom_old[4][3][kBlock], mom_new[4][3][kBlock];
  double detj[4][kBlock];
  double nx0[4][kBlock], ny0[4][kBlock];  // the centre rows N_k,x, N_k,y of the membrane shear
  double zx0[kBlock], zy0[kBlock], zx[4][kBlock], zy[4][kBlock];  // warp slopes z,x z,y: centre, points
  double dthick[kBlock], w_plastic[kBlock], eps_p_max[kBlock], fail_now[kBlock], unstable[kBlock];
  shell_detail::SectionBlock<kBlock> sec;
};

// Local geometry and velocities, the increments at the Gauss points and the element rate.
[[gnu::always_inline]] inline void qbat_local_rates(QbatBlock& bk, const ShellConstants& k,
                                                    const MaterialParams& mat, ShellGroup& g, int i0,
                                                    int len) {
  const double dt1 = k.dt1, alpha = k.alpha;
  for (int j = 0; j < len; ++j) {
    const std::size_t ii = static_cast<std::size_t>(i0 + j);
    bk.off[j] = g.off[ii];
    g.thick[ii] = first_use_thickness(FirstUseThickness::EveryElement, bk.off[j], g.thick[ii], g.t0[ii]);
    bk.t[j] = k.update_thick ? g.thick[ii] : g.t0[ii];
    // Local geometry (small strain: the first cycle's), velocities and rotation rates (shell_frame.hpp).
    double lx[4], ly[4], vx[4], vy[4], vz[4], rx[4], ry[4];
    quad_local_state(bk, j, g, ii, g.dt_fixed[ii] > 0.0 || g.props.ismstr == 1, lx, ly, vx, vy, vz, rx, ry);
    double e[5], kap[3];
    const QuadRows r0 = quad_rows(lx, ly, 0.0, 0.0);
    bk.area[j] = 4.0 * r0.detj;
    // Warp: the nodes' heights off the mean plane through their centroid (z1 = z3 and z2 = z4, since e3 is
    // normal to both diagonals), and the membrane terms z,x w,x, z,y w,y, z,x w,y + z,y w,x at a point.
    double lz[4], zc = 0;
    for (int n = 0; n < 4; ++n) {
      lz[n] = bk.fr.e3[0][j] * (bk.nb.x[n][j] - bk.nb.x[0][j]) +
              bk.fr.e3[1][j] * (bk.nb.y[n][j] - bk.nb.y[0][j]) +
              bk.fr.e3[2][j] * (bk.nb.z[n][j] - bk.nb.z[0][j]);
      zc += 0.25 * lz[n];
    }
    for (int n = 0; n < 4; ++n) lz[n] -= zc;
    auto add_warp = [&lz, &vz](const QuadRows& r, double rate[5], double& zx, double& zy) {
      double wx = 0, wy = 0;
      zx = zy = 0;
      for (int n = 0; n < 4; ++n) {
        zx += r.nx[n] * lz[n], zy += r.ny[n] * lz[n];
        wx += r.nx[n] * vz[n], wy += r.ny[n] * vz[n];
      }
      rate[0] += zx * wx;
      rate[1] += zy * wy;
      rate[2] += zx * wy + zy * wx;
    };
    quad_rates(r0, vx, vy, vz, rx, ry, e, kap);
    add_warp(r0, e, bk.zx0[j], bk.zy0[j]);
    const double gxy0 = e[2];  // the assumed membrane shear of every Gauss point
    for (int n = 0; n < 4; ++n) bk.nx0[n][j] = r0.nx[n], bk.ny0[n][j] = r0.ny[n];
    const double eq = dt1 > 0
                          ? std::sqrt(equivalent_rate_arg(e[0] * dt1, e[1] * dt1, e[2] * dt1, kap[0] * dt1,
                                                          kap[1] * dt1, kap[2] * dt1, g.thick[ii])) /
                                dt1
                          : 0.0;
    const double rate = alpha * eq + (1.0 - alpha) * g.rate[ii];
    if (bk.off[j] > 0.0) g.rate[ii] = rate;
    bk.rfac[j] = jc_rate_factor(mat, rate);
    bk.rate[j] = rate;
    for (int gp = 0; gp < 4; ++gp) {
      const QuadRows r = quad_rows(lx, ly, kXiGauss[gp], kEtaGauss[gp]);
      bk.detj[gp][j] = r.detj;
      quad_rates(r, vx, vy, vz, rx, ry, e, kap);
      add_warp(r, e, bk.zx[gp][j], bk.zy[gp][j]);
      quad_second_order(r, vz, dt1, e);
      e[2] = gxy0;
      for (int q = 0; q < 5; ++q) bk.dem[gp][q][j] = e[q] * dt1;
      for (int q = 0; q < 3; ++q) bk.dk[gp][q][j] = kap[q] * dt1;
    }
    bk.dthick[j] = bk.w_plastic[j] = bk.eps_p_max[j] = bk.fail_now[j] = 0.0;
    bk.unstable[j] = 1.0;
  }
}

// The section at each Gauss point, on its own rows of the state; the element's thickness change, plastic
// work, largest plastic strain and failure gathered over the points.
[[gnu::always_inline]] inline void qbat_gauss_point_sections(QbatBlock& bk, const ShellConstants& k,
                                                             const MaterialParams& mat, ShellGroup& g, int i0,
                                                             int len) {
  constexpr std::size_t G = kGroupSize;
  const ShellProps& pr = g.props;
  // Rows of one Gauss point's state: [n][5] stresses, or 8 resultants for N = 0 (allocate() made 4 of them).
  const std::size_t sig_rows = static_cast<std::size_t>(pr.n_points > 0 ? 5 * pr.n_points : 8);
  const std::size_t eps_rows = static_cast<std::size_t>(std::max(pr.n_points, 1));
  SectionBlock<kBlock>& sec = bk.sec;
  for (int gp = 0; gp < 4; ++gp) {
    for (int j = 0; j < len; ++j) {
      for (int q = 0; q < 5; ++q) sec.dem[q][j] = bk.dem[gp][q][j];
      for (int q = 0; q < 3; ++q) sec.dk[q][j] = bk.dk[gp][q][j];
      sec.t[j] = bk.t[j];
      sec.area[j] = bk.detj[gp][j];
      sec.rfac[j] = bk.rfac[j];
      sec.rate[j] = bk.rate[j];  // the /FAIL/JOHNSON D4 term
      sec.off[j] = bk.off[j];
    }
    const auto gpz = static_cast<std::size_t>(gp);
    section_update_block(g, i0, len, mat, k.rule, k.gs, sec, g.sig.data() + gpz * sig_rows * G,
                         g.eps_p.data() + gpz * eps_rows * G, g.dmg.data() + gpz * eps_rows * G,
                         g.brit.empty() ? nullptr : g.brit.data() + gpz * eps_rows * kBritVars * G,
                         g.res.data() + gpz * 8 * G);
    for (int j = 0; j < len; ++j) {
      for (int q = 0; q < 5; ++q)
        bk.for_old[gp][q][j] = sec.for_old[q][j], bk.for_new[gp][q][j] = sec.for_new[q][j];
      for (int q = 0; q < 3; ++q)
        bk.mom_old[gp][q][j] = sec.mom_old[q][j], bk.mom_new[gp][q][j] = sec.mom_new[q][j];
      // Thickness change: the area-weighted mean of the points' (1.8).
      bk.dthick[j] += sec.dthick[j] * bk.detj[gp][j] / bk.area[j];
      bk.w_plastic[j] += sec.w_plastic[j];
      bk.eps_p_max[j] = std::max(bk.eps_p_max[j], sec.eps_p_max[j]);
      // Deletion at once when any Gauss point's section reaches its failure threshold.
      bk.fail_now[j] = std::max(bk.fail_now[j], sec.fail_now[j]);
      // /FAIL/BIQUAD's instability deletes when every point of every Gauss point has reached it.
      bk.unstable[j] = std::min(bk.unstable[j], sec.unstable[j]);
    }
  }
  for (int j = 0; j < len; ++j) bk.fail_now[j] = std::max(bk.fail_now[j], bk.unstable[j]);
}

// Element j's energy increment over the Gauss points and its local nodal forces (none once it is deleted).
[[gnu::always_inline]] inline double qbat_energy_and_forces(const QbatBlock& bk, double visc0, int j,
                                                            double off_start, double off, const double lx[4],
                                                            const double ly[4], double fx[4], double fy[4],
                                                            double fz[4], double mx[4], double my[4]) {
  const double t = bk.t[j], area = bk.area[j];
  double de_int = 0;
  const double ot = off * t, ot2 = off * t * t;
  double nxy_sum = 0;  // sum_g det J(g) Nxy(g): the membrane shear force, through the centre rows
  for (int gp = 0; gp < 4; ++gp) {
    const double w = bk.detj[gp][j];
    double dem[5], dk[3];
    for (int q = 0; q < 5; ++q) dem[q] = bk.dem[gp][q][j];
    for (int q = 0; q < 3; ++q) dk[q] = bk.dk[gp][q][j];
    double fv[3];
    membrane_damping(visc0, area, dem, fv);
    de_int += shell_energy_increment(w, t, off_start, off, bk.for_old[gp], bk.for_new[gp], bk.mom_old[gp],
                                     bk.mom_new[gp], j, dem, dk, fv);
    if (off <= 0.0) continue;
    const QuadRows r = quad_rows(lx, ly, kXiGauss[gp], kEtaGauss[gp]);
    const double n[5] = {ot * (bk.for_new[gp][0][j] + fv[0]), ot * (bk.for_new[gp][1][j] + fv[1]), 0.0,
                         ot * bk.for_new[gp][3][j], ot * bk.for_new[gp][4][j]};
    nxy_sum += w * ot * (bk.for_new[gp][2][j] + fv[2]);
    const double m[3] = {ot2 * bk.mom_new[gp][0][j], ot2 * bk.mom_new[gp][1][j], ot2 * bk.mom_new[gp][2][j]};
    quad_add_forces(r, w, n, m, fx, fy, fz, mx, my);
    for (int k = 0; k < 4; ++k) fz[k] += w * (n[0] * bk.zx[gp][j] * r.nx[k] + n[1] * bk.zy[gp][j] * r.ny[k]);
  }
  if (off > 0.0)
    for (int k = 0; k < 4; ++k) {
      fx[k] += nxy_sum * bk.ny0[k][j];
      fy[k] += nxy_sum * bk.nx0[k][j];
      fz[k] += nxy_sum * (bk.zx0[j] * bk.ny0[k][j] + bk.zy0[j] * bk.nx0[k][j]);
    }
  return de_int;
}

// Failure, energy, forces rotated to global axes, step (1.10) and nodal stiffness (4.5).
[[gnu::always_inline]] inline void qbat_close_block(const QbatBlock& bk, const ShellConstants& k,
                                                    ShellGroup& g, int i0, int len) {
  constexpr std::size_t G = kGroupSize;
  double* nf = g.nodal_force.data();
  for (int j = 0; j < len; ++j) {
    const std::size_t ii = static_cast<std::size_t>(i0 + j);
    const double off_start = bk.off[j];
    if (off_start <= 0.0) {
      clear_shell_element(g, nf, ii, 24);
      continue;
    }
    const double t = bk.t[j], area = bk.area[j];
    const double off = next_off(k.fail_limit, off_start, bk.eps_p_max[j], bk.fail_now[j]);
    g.off[ii] = off;
    g.w_plastic[ii] += bk.w_plastic[j];
    g.thick[ii] += bk.dthick[j] * off;

    double lx[4], ly[4];
    for (int n = 0; n < 4; ++n) lx[n] = bk.lx[n][j], ly[n] = bk.ly[n][j];
    double fx[4] = {}, fy[4] = {}, fz[4] = {}, mx[4] = {}, my[4] = {};
    g.e_int[ii] += qbat_energy_and_forces(bk, k.visc0, j, off_start, off, lx, ly, fx, fy, fz, mx, my);
    if (off <= 0.0) {
      clear_shell_element(g, nf, ii, 24);
      continue;
    }
    const double e1x = bk.fr.e1[0][j], e1y = bk.fr.e1[1][j], e1z = bk.fr.e1[2][j];
    const double e2x = bk.fr.e2[0][j], e2y = bk.fr.e2[1][j], e2z = bk.fr.e2[2][j];
    const double e3x = bk.fr.e3[0][j], e3y = bk.fr.e3[1][j], e3z = bk.fr.e3[2][j];
    for (int n = 0; n < 4; ++n)
      store_local_forces(nf, G, static_cast<std::size_t>(n), ii, e1x, e1y, e1z, e2x, e2y, e2z, e3x, e3y, e3z,
                         fx[n], fy[n], fz[n], mx[n], my[n]);
    const double l = qeph_step_length(lx, ly, area);
    g.dt[ii] = l * k.phi / k.c;
    g.k_nodal[ii] = 0.5 * area * t * k.a11 / (l * l);
  }
}

}  // namespace

// The kernel: the list of its stages over each block of the group.
void shell_qbat_forces(ShellGroup& g, const NodeState& nodes, const MaterialParams& mat,
                       const CycleInfo& cyc) {
  const ShellConstants k = shell_constants(g.props, mat, cyc.dt1, g.props.dn);
  QbatBlock bk;
  bk.sec.dt1 = k.dt1;  // law 27's rate term
  for (int i0 = 0; i0 < g.count; i0 += kBlock) {
    const int len = std::min(kBlock, g.count - i0);
    open_quad_block(g, nodes, i0, len, bk.nb, bk.fr);
    qbat_local_rates(bk, k, mat, g, i0, len);
    qbat_gauss_point_sections(bk, k, mat, g, i0, len);
    qbat_close_block(bk, k, g, i0, len);
  }
}

}  // namespace radx::solver
