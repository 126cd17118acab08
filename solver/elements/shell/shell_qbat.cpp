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
// Rotations and curvature of a warped element (z^2 >= 1e-12 of the longer half-diagonal squared, the
//   threshold of cbacoor.F, and not on the frozen coordinates of small strain, where OpenRadioss also sets
//   the warp to 0) [read: cbacoor.F's "full projection" and nodal frames, cbadef.F's curvature terms;
//   written as the first-order rates below]:
//   rigid spin   omega = D^-1 (sum p_k x v_k + W sum r_k), D = sum (|p_k|^2 I - p_k p_k^T) + 4 W I, p_k the
//                nodes from the centroid (with z_k), r_k the nodes' three rotation rates, W = 1 (model length
//                squared, OpenRadioss's weight);
//   rotations    the strains read the in-plane components of omega + P_k (r_k - omega), P_k = I - n_k n_k^T,
//                n_k the unit normal g_xi x g_eta of the bilinear surface at node k: each node's rate about
//                its own normal, which no shell resists, is taken out, and its rate about the element's mean
//                normal e3 (dropped on a flat element) bends the element through the tilt n_k - e3;
//   curvature    kxx += n,x . v',x, kyy += n,y . v',y, kxy += n,x . v',y + n,y . v',x at each Gauss point,
//                n,a = sum N_k,a n_k, v'_k = v_k - omega x p_k: the change of the surface's own curvature
//                (the twist of a warped element) under its in-plane motion, the n,a . v,b half of the
//                covariant curvature rate 1/2 (g_a . n',b + n,a . v,b) + (a <-> b), rigid-free by the spin.
//   Both are the transpose in the forces, through omega too: the moments (mx, my) on the projected rates
//   become moments about all three axes (store_local_forces writes none about e3; the kernel adds it).
//   Without them each node's rotation about e3 is free in the element, and in a twisted mesh (the
//   MacNeal-Harder beam, 12 x 2 elements twisted 7.5 degrees each) neighbouring elements let the strip bend
//   in its plane through those rotations almost freely: tip deflections 100 to 300 times the closed form,
//   against 5 to 8 % above it with them (OpenRadioss: within 2 %) once the rotations carry a restraint of
//   1e-7 of the bending stiffness. Left as OpenRadioss has it: without any drilling stiffness the rotations
//   about the mean normals are held only through the tilt of the nodal normals, and a held load excites a
//   slow mode through them (the beam's internal energy reaches 2.5 times the static one in 0.3 s in
//   OpenRadioss, 3.1 times in radx).
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

// OpenRadioss's weight of the nodal rotation rates against the velocities in the rigid-spin fit of a warped
// element (the 4 = 4 x 1 on the diagonal of cbacoor.F's matrix): 1 in the model's length units squared.
constexpr double kSpinFitWeight = 1.0;

// A warped element's rigid spin and surface (see the top comment), in the element frame: node positions p_k
// from the centroid, unit normals n_k of the bilinear surface at the nodes, D^-1 of the fit and the spin.
struct WarpedSurface {
  double p[4][3], n[4][3], dinv[3][3], om[3];
};

// The fit omega = D^-1 (sum p_k x v_k + W sum r_k), D = sum (|p_k|^2 I - p_k p_k^T) + 4 W I, the nodal
// normals, and the rotation rates the strains read: rx, ry (in) become the in-plane components of
// omega + P_k (r_k - omega), P_k = I - n_k n_k^T; rz is the rate about e3.
inline void warped_surface(WarpedSurface& ws, const double px[4], const double py[4], const double pz[4],
                           const double vx[4], const double vy[4], const double vz[4], double rx[4],
                           double ry[4], const double rz[4]) {
  double sxx = 0, syy = 0, szz = 0, sxy = 0, sxz = 0, syz = 0;
  for (int k = 0; k < 4; ++k) {
    ws.p[k][0] = px[k], ws.p[k][1] = py[k], ws.p[k][2] = pz[k];
    sxx += px[k] * px[k], syy += py[k] * py[k], szz += pz[k] * pz[k];
    sxy += px[k] * py[k], sxz += px[k] * pz[k], syz += py[k] * pz[k];
  }
  const double w4 = 4.0 * kSpinFitWeight;
  const double d00 = syy + szz + w4, d11 = sxx + szz + w4, d22 = sxx + syy + w4;
  const double d01 = -sxy, d02 = -sxz, d12 = -syz;
  const double c00 = d11 * d22 - d12 * d12, c01 = d12 * d02 - d01 * d22, c02 = d01 * d12 - d11 * d02;
  const double inv = 1.0 / (d00 * c00 + d01 * c01 + d02 * c02);  // D is positive definite (W > 0)
  ws.dinv[0][0] = c00 * inv, ws.dinv[0][1] = ws.dinv[1][0] = c01 * inv,
  ws.dinv[0][2] = ws.dinv[2][0] = c02 * inv;
  ws.dinv[1][1] = (d00 * d22 - d02 * d02) * inv;
  ws.dinv[1][2] = ws.dinv[2][1] = (d02 * d01 - d00 * d12) * inv;
  ws.dinv[2][2] = (d00 * d11 - d01 * d01) * inv;
  double ar[3] = {0, 0, 0};
  for (int k = 0; k < 4; ++k) {
    ar[0] += py[k] * vz[k] - pz[k] * vy[k] + kSpinFitWeight * rx[k];
    ar[1] += pz[k] * vx[k] - px[k] * vz[k] + kSpinFitWeight * ry[k];
    ar[2] += px[k] * vy[k] - py[k] * vx[k] + kSpinFitWeight * rz[k];
  }
  for (int a = 0; a < 3; ++a)
    ws.om[a] = ws.dinv[a][0] * ar[0] + ws.dinv[a][1] * ar[1] + ws.dinv[a][2] * ar[2];
  // n_k = g_xi x g_eta at node k: node 1 on the edges 1-2 and 1-4, node 2 on 1-2 and 2-3, node 3 on 4-3 and
  // 2-3, node 4 on 4-3 and 1-4.
  constexpr int xa[4] = {0, 0, 3, 3}, xb[4] = {1, 1, 2, 2}, ea[4] = {0, 1, 1, 0}, eb[4] = {3, 2, 2, 3};
  for (int k = 0; k < 4; ++k) {
    const double gx[3] = {px[xb[k]] - px[xa[k]], py[xb[k]] - py[xa[k]], pz[xb[k]] - pz[xa[k]]};
    const double ge[3] = {px[eb[k]] - px[ea[k]], py[eb[k]] - py[ea[k]], pz[eb[k]] - pz[ea[k]]};
    const double nn[3] = {gx[1] * ge[2] - gx[2] * ge[1], gx[2] * ge[0] - gx[0] * ge[2],
                          gx[0] * ge[1] - gx[1] * ge[0]};
    const double l = std::sqrt(nn[0] * nn[0] + nn[1] * nn[1] + nn[2] * nn[2]);
    for (int a = 0; a < 3; ++a) ws.n[k][a] = l > 0 ? nn[a] / l : (a == 2 ? 1.0 : 0.0);
    const double q[3] = {rx[k] - ws.om[0], ry[k] - ws.om[1], rz[k] - ws.om[2]};
    const double qn = q[0] * ws.n[k][0] + q[1] * ws.n[k][1] + q[2] * ws.n[k][2];
    rx[k] = ws.om[0] + q[0] - qn * ws.n[k][0];
    ry[k] = ws.om[1] + q[1] - qn * ws.n[k][1];
  }
}

// The curvature rates of the surface's own curvature at a point of rows r: with n,a = sum N_k,a n_k and the
// velocities less the rigid spin, v'_k = v_k - omega x p_k, v',a = sum N_k,a v'_k:
// kxx += n,x . v',x, kyy += n,y . v',y, kxy += n,x . v',y + n,y . v',x.
inline void warped_curvature(const WarpedSurface& ws, const QuadRows& r, const double vx[4],
                             const double vy[4], const double vz[4], double kap[3]) {
  double nx[3] = {0, 0, 0}, ny[3] = {0, 0, 0}, gx[3] = {0, 0, 0}, gy[3] = {0, 0, 0};
  for (int k = 0; k < 4; ++k) {
    const double* p = ws.p[k];
    const double* om = ws.om;
    const double v[3] = {vx[k] - (om[1] * p[2] - om[2] * p[1]), vy[k] - (om[2] * p[0] - om[0] * p[2]),
                         vz[k] - (om[0] * p[1] - om[1] * p[0])};
    for (int a = 0; a < 3; ++a) {
      nx[a] += r.nx[k] * ws.n[k][a], ny[a] += r.ny[k] * ws.n[k][a];
      gx[a] += r.nx[k] * v[a], gy[a] += r.ny[k] * v[a];
    }
  }
  kap[0] += nx[0] * gx[0] + nx[1] * gx[1] + nx[2] * gx[2];
  kap[1] += ny[0] * gy[0] + ny[1] * gy[1] + ny[2] * gy[2];
  kap[2] += nx[0] * gy[0] + nx[1] * gy[1] + nx[2] * gy[2] + ny[0] * gx[0] + ny[1] * gx[1] + ny[2] * gx[2];
}

// Transpose of warped_curvature at a point of weight w and moments m (Mxx Myy Mxy): the forces F_k on the
// velocities v'_k, accumulated in fc[k] (local axes).
inline void warped_curvature_forces(const WarpedSurface& ws, const QuadRows& r, double w, const double m[3],
                                    double fc[4][3]) {
  double nx[3] = {0, 0, 0}, ny[3] = {0, 0, 0};
  for (int k = 0; k < 4; ++k)
    for (int a = 0; a < 3; ++a) nx[a] += r.nx[k] * ws.n[k][a], ny[a] += r.ny[k] * ws.n[k][a];
  for (int k = 0; k < 4; ++k)
    for (int a = 0; a < 3; ++a)
      fc[k][a] +=
          w * (m[0] * nx[a] * r.nx[k] + m[1] * ny[a] * r.ny[k] + m[2] * (nx[a] * r.ny[k] + ny[a] * r.nx[k]));
}

// The transpose of the rigid-spin fit and of the tangent projection, so that the forces' work is the energy:
// (mx, my) conjugate to the rates warped_surface gave become moments (mx, my, mz) on the nodes' rotation
// rates (b_k = P_k a_k, a_k = (mx, my, 0)); the forces fc on v'_k are added to the velocities' forces. Both
// pass through omega: its power omega . c, c = sum (a_k - b_k) - sum p_k x fc_k, is AR . D^-1 c.
inline void warped_surface_forces(const WarpedSurface& ws, const double fc[4][3], double fx[4], double fy[4],
                                  double fz[4], double mx[4], double my[4], double mz[4]) {
  double c[3] = {0, 0, 0};
  for (int k = 0; k < 4; ++k) {
    const double* n = ws.n[k];
    const double an = mx[k] * n[0] + my[k] * n[1];
    for (int a = 0; a < 3; ++a) c[a] += an * n[a];
    mx[k] -= an * n[0], my[k] -= an * n[1], mz[k] = -an * n[2];
    const double* p = ws.p[k];
    const double* f = fc[k];
    c[0] -= p[1] * f[2] - p[2] * f[1], c[1] -= p[2] * f[0] - p[0] * f[2], c[2] -= p[0] * f[1] - p[1] * f[0];
    fx[k] += f[0], fy[k] += f[1], fz[k] += f[2];
  }
  double d[3];
  for (int a = 0; a < 3; ++a) d[a] = ws.dinv[a][0] * c[0] + ws.dinv[a][1] * c[1] + ws.dinv[a][2] * c[2];
  for (int k = 0; k < 4; ++k) {
    const double* p = ws.p[k];
    mx[k] += kSpinFitWeight * d[0], my[k] += kSpinFitWeight * d[1], mz[k] += kSpinFitWeight * d[2];
    fx[k] += d[1] * p[2] - d[2] * p[1];
    fy[k] += d[2] * p[0] - d[0] * p[2];
    fz[k] += d[0] * p[1] - d[1] * p[0];
  }
}

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
  WarpedSurface ws[kBlock];
  bool warped[kBlock];
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
    const bool frozen = g.dt_fixed[ii] > 0.0 || g.props.ismstr == 1;
    quad_local_state(bk, j, g, ii, frozen, lx, ly, vx, vy, vz, rx, ry);
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
    // Warped as OpenRadioss counts it (cbacoor.F): z^2 >= 1e-12 of the longer half-diagonal squared, and not
    // on the frozen small-strain coordinates (there OpenRadioss sets the warp to 0).
    const double hd13 = 0.25 * ((lx[2] - lx[0]) * (lx[2] - lx[0]) + (ly[2] - ly[0]) * (ly[2] - ly[0]));
    const double hd24 = 0.25 * ((lx[3] - lx[1]) * (lx[3] - lx[1]) + (ly[3] - ly[1]) * (ly[3] - ly[1]));
    const bool warped = !frozen && lz[0] * lz[0] >= 1e-12 * std::max(hd13, hd24);
    bk.warped[j] = warped;
    if (warped) {
      double rz[4], px[4], py[4];
      const double cx = 0.25 * (lx[0] + lx[1] + lx[2] + lx[3]), cy = 0.25 * (ly[0] + ly[1] + ly[2] + ly[3]);
      for (int n = 0; n < 4; ++n) {
        rz[n] = bk.fr.e3[0][j] * bk.nb.rx[n][j] + bk.fr.e3[1][j] * bk.nb.ry[n][j] +
                bk.fr.e3[2][j] * bk.nb.rz[n][j];
        px[n] = lx[n] - cx, py[n] = ly[n] - cy;
      }
      warped_surface(bk.ws[j], px, py, lz, vx, vy, vz, rx, ry, rz);
    }
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
      if (warped) warped_curvature(bk.ws[j], r, vx, vy, vz, kap);
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
                                                            double fz[4], double mx[4], double my[4],
                                                            double fc[4][3]) {
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
    if (bk.warped[j]) warped_curvature_forces(bk.ws[j], r, w, m, fc);
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
    double fx[4] = {}, fy[4] = {}, fz[4] = {}, mx[4] = {}, my[4] = {}, mz[4] = {}, fc[4][3] = {};
    g.e_int[ii] += qbat_energy_and_forces(bk, k.visc0, j, off_start, off, lx, ly, fx, fy, fz, mx, my, fc);
    if (off <= 0.0) {
      clear_shell_element(g, nf, ii, 24);
      continue;
    }
    const double e1x = bk.fr.e1[0][j], e1y = bk.fr.e1[1][j], e1z = bk.fr.e1[2][j];
    const double e2x = bk.fr.e2[0][j], e2y = bk.fr.e2[1][j], e2z = bk.fr.e2[2][j];
    const double e3x = bk.fr.e3[0][j], e3y = bk.fr.e3[1][j], e3z = bk.fr.e3[2][j];
    if (bk.warped[j]) warped_surface_forces(bk.ws[j], fc, fx, fy, fz, mx, my, mz);
    for (int n = 0; n < 4; ++n) {
      store_local_forces(nf, G, static_cast<std::size_t>(n), ii, e1x, e1y, e1z, e2x, e2y, e2z, e3x, e3y, e3z,
                         fx[n], fy[n], fz[n], mx[n], my[n]);
      // The moment about e3 of a warped element (store_local_forces writes none), with the same minus sign.
      double* o = nf + static_cast<std::size_t>(n) * 6 * G + ii;
      o[3 * G] -= mz[n] * e3x, o[4 * G] -= mz[n] * e3y, o[5 * G] -= mz[n] * e3z;
    }
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
