// Four-node Belytschko-Tsay shell, Ishell 1 (and 0), one point in the plane, as OpenRadioss runs it by
// default, and Ishell 4, its variant with the warp correction (cdefo3.F and cfint3.F, internal IHBE 4).
// Source of every formula: docs/theory/elements.md (sections in brackets), itself read from OpenRadioss
// cforc3.F, ccoor3.F, cnvec3.F, cderi3.F, cdefo3.F, ccurv3.F, cstra3.F, mulawc.F90, cfint3.F, chvis3.F,
// cdlen3.F, cdt3.F.
//
// Geometry [1.2], rebuilt every cycle from X^n (stresses stay in this convected frame, never rotated):
//   g1 = (X2 - X1) + (X3 - X4), g2 = (X3 - X2) + (X4 - X1), e3 = g1 x g2 / |g1 x g2|,
//   e1 = normalise(g1 + |g1|/|g2| (g2 x e3)), e2 = e3 x e1; x_k = e1.(X_k - X1), y_k = e2.(X_k - X1).
//   PX1 = (y2 - y4)/2, PY1 = (x4 - x2)/2, PX2 = y3/2, PY2 = -x3/2, PX3 = -PX1, PY3 = -PY1, PX4 = -PX2,
//   PY4 = -PY2 (area times dN/dx at the centre); A = 2 (PY2 PX1 - PY1 PX2) >= 1e-20;
//   hx = (-x2 + x3 - x4)/A, hy = (-y2 + y3 - y4)/A.
// Rates [1.3], with v, omega = v^{n-1/2}, omega^{n-1/2} projected on (e1, e2, e3), rx = e1.omega, ry =
// e2.omega:
//   second-order correction: a = PY1 + PY2, b = PX2 - PX1 (|.| >= 1e-20, sign kept),
//   t1 = dt1/4 (w13 - w24)^2/a, t2 = dt1/4 (w13 + w24)^2/b; u13 -= t1, u24 += t1, v13 += t2, v24 += t2;
//   A exx = PX1 u13 + PX2 u24, A eyy = PY1 v13 + PY2 v24, A gxy = PY1 u13 + PY2 u24 + PX1 v13 + PX2 v24;
//   A kxx = sum PX_k ry_k, A kyy = -sum PY_k rx_k, A kxy = sum (PY_k ry_k - PX_k rx_k);
//   A gxz = sum PX_k vz_k + A/4 sum ry_k, A gyz = sum PY_k vz_k - A/4 sum rx_k;
//   increments = rates dt1 / A.
// Ishell 4 replaces the second-order correction: with the warp z2 = e3.(X2 - X1) (0 in small strain),
//   gzx = (PX1 w13 + PX2 w24)/A, gzy = (PY1 w13 + PY2 w24)/A, a = gzx z2/2, b = dt1 gzx^2/2, c = gzy z2/2,
//   d = dt1 gzy^2/2, the local velocities change by dvx = (-a - b PY2, a + b PY1, -a + b PY2, a - b PY1),
//   dvy = (-c + d PX2, c - d PX1, -c - d PX2, c + d PX1) before the rates and the hourglass rates are taken:
//   the membrane rates lose dt1/2 (dvz/dx)^2 and dt1/2 (dvz/dy)^2, and a warped element turning rigidly about
//   an in-plane axis has no membrane hourglass rate; with N > 1 the moments of the membrane hourglass forces
//   about the warp are added: mx_k -= z2/4 (Hy_1 + Hy_3), my_k += z2/4 (Hx_1 + Hx_3) (H_k = H gamma_k).
// Section [1.4], energy [1.5] (A current area, t the mechanics thickness):
//   E_int += 1/2 A t [(OFF_old FOR_old + OFF FOR_new).de_m + t (OFF_old MOM_old + OFF MOM_new).dkappa].
//   Membrane damping (Dm > 0 only): visc = 1.414 Dm rho c sqrt(A)/dt1, FOR += visc (dexx + deyy/2,
//   deyy + dexx/2, dgxy/3); its work is booked as FOR_visc.de_m A t (no stored old value).
// Nodal forces [1.6], local, N = FOR t, M = MOM t^2, Qx = FOR_zx t, Qy = FOR_yz t, all times OFF:
//   f_k = (Nxx PX_k + Nxy PY_k, Nxy PX_k + Nyy PY_k, Qx PX_k + Qy PY_k),
//   m_k = (-(Myy PY_k + Mxy PX_k) - Qy A/4, Mxx PX_k + Mxy PY_k + Qx A/4), no drilling moment.
// Hourglass [1.7] (HELAS = HVISC = 1/2, HVLIN = 0), none for a degenerate quad (n3 = n4):
//   gamma = OFF (1 - (PX1 hx + PY1 hy), -1 - (PX2 hx + PY2 hy), 1 + (PX1 hx + PY1 hy), -1 + (PX2 hx + PY2
//   hy)), q = sum gamma_k v_k (local), rxh = sum h_k rx_k, ryh = sum h_k ry_k, h = (1, -1, 1, -1); Cm = 12.5
//   rho Hm t sqrt(A), Cf = 12.5 rho Hf sqrt(SHF/(3(1+nu))) t^2, Cr = 0.90211 rho Hr t^2 A, Km = E Hm/8 t dt1,
//   Kf = E Hf SHF/(24(1+nu)) t^3 dt1/(B1 + B2), B1 = PX1^2 + PY1^2, B2 = PX2^2 + PY2^2; S += (Km qx, Km qy,
//   Kf qz); H = S + (Cm |qx| qx, Cm |qy| qy, Cf |qz| qz); Mh = Cr (|rxh| rxh, |ryh| ryh); f_k += H gamma_k,
//   m_k += Mh h_k; E_hg += dt1 OFF (H.q + Mh.(rxh, ryh)) (not internal energy).
// Thickness [1.8], failure [6.4], plastic work [6.5]: shell_section.hpp.
// Element step [4.1] (stored before the /DT scale): L^2 = max(A^2/max(d13^2, d24^2), Lmin^2), Lmin over the
//   sides (and the diagonals, n3 != n4), hourglass guard L^2 <= (Lmin^2 + L^2)/(2 max(Hm, Hf));
//   dt = L phi / c, c = sqrt(E/rho), phi = sqrt(1 + Dm^2) - Dm.
// Nodal stiffness [4.5]: k_nodal = 0.81 * 1/2 A t E / L^2 for each of the 4 nodes.
// Ismstr 1 (small strain from the start): the small-strain state below from the first cycle, and the plain
// h = (1, -1, 1, -1) as the hourglass gamma [1.7].
// Small strain (after a /DT/SHELL/CST switch, g.dt_fixed > 0): the local coordinates x_k, y_k are frozen at
// the first cycle after the switch and replace the current ones from then on; the frame and the velocities
// stay current, so PX, PY, A, L and the step stay those of the frozen geometry (the step is constant).
//
// Conventions: nodal_force ([4][6][G], fx fy fz mx my mz) is the force ADDED to each node (minus the
// internal force), global axes; dt is in the model's time unit, before the /DT scale; at cycle 0
// (dt1 = 0) every increment is zero and the forces come from the stored state (plus the viscous hourglass
// forces, which depend on the velocity only); an element whose OFF is 0 at entry gives no force, no energy
// and dt = +inf; thick = 0 is taken as t0 on first use. N = 0 keeps FOR and MOM in sig as [8][G]
// (shell_section.hpp; the buffer is grown once if allocate() made it [5][G]).
//
// Layout (docs/architecture.md): the group is run in blocks of kBlock elements; each stage is a loop over the
// block's elements with the element index innermost, on structure-of-arrays scratch (Bt4Block), written
// without branches so that GCC vectorises it: gather; frame; local geometry, velocities and increments;
// strain rate; section (shell_section.hpp); energy, forces and hourglass; rotation to global axes and the
// element step. Square roots are taken in passes of their own (sqrt_in_place). Law 2's rate term
// R = 1 + c ln(rate/rate0) is first a lower bound without a logarithm (jc_rate_factor_lower), which is all
// the elastic check of the section needs; the logarithm is taken only for the elements with a point that may
// yield (SectionBlock::rfac_lower). Elements deleted at entry go
// through the arithmetic with every state update masked, and get their zero forces and infinite step in a
// scalar pass. The arithmetic is that of the element-by-element version, operation for operation, so the
// results are the same to the bit. The kernel is compiled twice, for the build's x86-64-v2 and for x86-64-v3
// (AVX2, four elements per vector), and runs the second where the processor has it (kernel_isa.hpp): the same
// results to the bit, about half the instructions.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "solver/elements/element_gather.hpp"
#include "solver/elements/element_groups.hpp"
#include "solver/elements/kernel_isa.hpp"
#include "solver/elements/shell/shell_frame.hpp"
#include "solver/elements/shell/shell_section.hpp"
#include "solver/elements/shell/shell_stages.hpp"

namespace radx::solver {

namespace {

constexpr int kBlock = 64;  // elements per block: the scratch (about 100 KB) stays in the core's caches

inline double signed_floor(double v, double eps) {
  return v >= 0 ? std::max(v, eps) : std::min(v, -eps);
}

// Scratch of one block, [quantity][slot].
struct Bt4Block {
  NodeBlock<4, kBlock> nb;                             // gathered positions and velocities, global axes
  shell_detail::FrameBlock<kBlock> fr;                 // frame e1 e2 e3
  double vx[4][kBlock], vy[4][kBlock], vz[4][kBlock];  // node velocities, local
  double rxh[kBlock], ryh[kBlock];                     // local hourglass rotation rates
  double z2[kBlock];                                   // warp e3.(X2 - X1), Ishell 4 (0 in small strain)
  double lx[4][kBlock], ly[4][kBlock];                 // local coordinates (node 1 at 0)
  double px1[kBlock], py1[kBlock], px2[kBlock], py2[kBlock];
  double area[kBlock], ainv[kBlock], l2[kBlock], nondeg[kBlock], off[kBlock], rate[kBlock];
  std::int64_t flag[kBlock];
  double root[3][kBlock];   // arguments, then values, of square roots
  double fl[5][4][kBlock];  // local nodal forces fx fy fz and moments mx my
  shell_detail::SectionBlock<kBlock> sec;
};

// Current in-plane coordinates of node k (1..3) of block element j relative to node 1: e1.(X_k - X_1),
// e2.(X_k - X_1) [1.2].
inline void local_xy(const Bt4Block& bk, int k, int j, double& cx, double& cy) {
  const double dx = bk.nb.x[k][j] - bk.nb.x[0][j], dy = bk.nb.y[k][j] - bk.nb.y[0][j],
               dz = bk.nb.z[k][j] - bk.nb.z[0][j];
  cx = bk.fr.e1[0][j] * dx + bk.fr.e1[1][j] * dy + bk.fr.e1[2][j] * dz;
  cy = bk.fr.e2[0][j] * dx + bk.fr.e2[1][j] * dy + bk.fr.e2[2][j] * dz;
}

// Warp e3.(X_2 - X_1) of block element j (Ishell 4) [1.3].
inline double warp_z2(const Bt4Block& bk, int j) {
  return bk.fr.e3[0][j] * (bk.nb.x[1][j] - bk.nb.x[0][j]) + bk.fr.e3[1][j] * (bk.nb.y[1][j] - bk.nb.y[0][j]) +
         bk.fr.e3[2][j] * (bk.nb.z[1][j] - bk.nb.z[0][j]);
}

// The group's constants of the kernel: the shared ones (shell_stages.hpp) and BT4's own.
struct Bt4Constants {
  shell_detail::ShellConstants s;
  double wh;                       // [1.7] Ismstr 1 takes the plain h = (1, -1, 1, -1) as gamma: wh = 0
  double w4, w1, w4_moment;        // Ishell 4 or 1 as arithmetic weights (w = 0 adds exact zeros)
  double hdiv, hoff;               // the hourglass guard of 4.1, switched off by hoff = inf
  double cm0, cf0, cr0, km0, kf0;  // hourglass coefficients without their geometric factors
  bool r_lower;                    // law 2 with c != 0: R's lower bound first (SectionBlock::rfac_lower)
  double c_lower, inv_rate0, rate_one;
  double tiny20, tiny30, one, zero;  // opaque floors of divisors, and the masks of the state updates
};

Bt4Constants bt4_constants(const ShellProps& pr, const MaterialParams& mat, double dt1) {
  Bt4Constants k;
  k.s = shell_detail::shell_constants(pr, mat, dt1, pr.dm);
  // [1.7]: Ismstr 1 takes the plain h = (1, -1, 1, -1) as gamma: wh = 0 (wh x, x finite, is +-0, and 1 +- 0 =
  // 1).
  k.wh = pr.ismstr == 1 ? 0.0 : 1.0;
  // Ishell 4 or 1, as arithmetic weights so that one vectorised loop runs both (w = 0 adds exact zeros).
  k.w4 = pr.ishell == 4 ? 1.0 : 0.0, k.w1 = 1.0 - k.w4;
  k.w4_moment = pr.n_points != 1 ? k.w4 : 0.0;  // cfint3.F: not with one point through the thickness
  const double nu = k.s.nu, rho = k.s.rho, shf = k.s.shf;
  const double hmax = std::max(pr.hm, pr.hf);
  // The guard of 4.1 is computed for every element (a division in a branch would not vectorise); hoff = inf
  // switches it off: x + 0 = x, and min(l2, inf) = l2.
  k.hdiv = hmax > 0 ? hmax : 1.0, k.hoff = hmax > 0 ? 0.0 : std::numeric_limits<double>::infinity();
  k.cm0 = 12.5 * rho * pr.hm;
  k.cf0 = 12.5 * rho * pr.hf * std::sqrt(shf / (3.0 * (1.0 + nu)));
  k.cr0 = 0.90211 * rho * pr.hr;
  k.km0 = k.s.young * pr.hm / 8.0 * dt1;
  k.kf0 = k.s.young * pr.hf * shf / (24.0 * (1.0 + nu)) * dt1;
  // Law 2 with c != 0 takes a lower bound of R in the vectorised loop and the logarithm only for the elements
  // with a point that may yield (SectionBlock::rfac_lower): c_lower = 0 makes the bound exactly 1 otherwise.
  k.r_lower = mat.law == model::MaterialLaw::JohnsonCook && mat.jc.c != 0;
  k.c_lower = k.r_lower ? mat.jc.c : 0.0, k.inv_rate0 = k.r_lower ? 1.0 / mat.jc.eps_dot0 : 1.0;
  // Strain rate above which the element's rate term differs from 1 (jc_rate_factor).
  k.rate_one = k.r_lower ? std::numeric_limits<double>::infinity() : shell_rate_threshold(mat);
  k.tiny20 = opaque(1e-20), k.tiny30 = opaque(1e-30);
  // Masks. State updates of the last stage are written x + m * dx (m = 1, or 0 for an element deleted at
  // entry or in this cycle, whose increments are finite) rather than selected: a select of a computed value
  // is moved into a branch, which may trap (-ftrapping-math), and the loop would not vectorise.
  k.one = opaque(1.0), k.zero = opaque(0.0);
  return k;
}

// /DT/SHELL/CST switch: elements switched since the last cycle capture their local geometry now (capture[i] =
// 1). Ismstr 1 is small strain from the start: the same frozen geometry, captured at the first cycle.
// (Written without branches: the loop vectorises.) Returns whether any element of the group is in small
// strain.
[[gnu::always_inline]] inline std::int64_t bt4_small_strain_capture(ShellGroup& g, double* capture) {
  double* small = g.small.data();
  const bool ismstr1 = g.props.ismstr == 1;
  const double* dt_fixed = g.dt_fixed.data();
  std::int64_t any_small = 0;
  RADX_IVDEP
  for (int i = 0; i < g.count; ++i) {
    const auto ii = static_cast<std::size_t>(i);
    const double sm = small[ii];
    const bool cap = ((dt_fixed[ii] > 0.0) | ismstr1) & (sm == 0.0);
    capture[ii] = cap ? 1.0 : 0.0;
    const double sm_new = cap ? 1.0 : sm;
    small[ii] = sm_new;
    any_small |= sm_new != 0.0 ? 1 : 0;
  }
  return any_small;
}

// Local coordinates (node 1 at 0) and the warp [1.2, 1.3]. Small strain after a /DT/SHELL/CST switch (or
// Ismstr 1): the local coordinates are frozen at the first cycle after it (cap = 1) and used from then on
// (sm = 1), so PX, PY, A and the step stay constant; the selects are arithmetic so the loop stays
// vectorised. A group without such an element (the usual case) takes the current coordinates without
// reading or writing the frozen ones (sm = 0 would return them exactly).
[[gnu::always_inline]] inline void bt4_local_coordinates(Bt4Block& bk, ShellGroup& g, int i0, int len,
                                                         std::int64_t any_small, const double* capture) {
  constexpr std::size_t G = kGroupSize;
  if (any_small != 0) {
    const double* small = g.small.data();
    double* ref = g.ref_local.data();
    RADX_IVDEP
    for (int j = 0; j < len; ++j) {
      const std::size_t ii = static_cast<std::size_t>(i0 + j);
      const double sm = small[ii], cap = capture[ii];
      for (int k = 1; k < 4; ++k) {
        double cx = 0, cy = 0;
        local_xy(bk, k, j, cx, cy);
        shell_detail::small_strain_coordinates(cx, cy, cap, sm, ref[static_cast<std::size_t>(k - 1) * G + ii],
                                               ref[static_cast<std::size_t>(k + 2) * G + ii], bk.lx[k][j],
                                               bk.ly[k][j]);
      }
      bk.z2[j] = (1.0 - sm) * warp_z2(bk, j);
    }
  } else {
    RADX_IVDEP
    for (int j = 0; j < len; ++j) {
      for (int k = 1; k < 4; ++k) local_xy(bk, k, j, bk.lx[k][j], bk.ly[k][j]);
      bk.z2[j] = warp_z2(bk, j);
    }
  }
}

// Local geometry, local velocities and the increments [1.3]; the element step length [4.1]; the arguments of
// the block's square roots.
[[gnu::always_inline]] inline void bt4_geometry_and_increments(Bt4Block& bk, const Bt4Constants& k,
                                                               const ShellGroup& g, int i0, int len) {
  using shell_detail::to_local;
  shell_detail::SectionBlock<kBlock>& sec = bk.sec;
  const double dt1 = k.s.dt1, w4 = k.w4, w1 = k.w1, tiny20 = k.tiny20, hdiv = k.hdiv, hoff = k.hoff;
  const double* thick = g.thick.data();
  RADX_IVDEP
  for (int j = 0; j < len; ++j) {
    const double e1x = bk.fr.e1[0][j], e1y = bk.fr.e1[1][j], e1z = bk.fr.e1[2][j];
    const double e2x = bk.fr.e2[0][j], e2y = bk.fr.e2[1][j], e2z = bk.fr.e2[2][j];
    const double e3x = bk.fr.e3[0][j], e3y = bk.fr.e3[1][j], e3z = bk.fr.e3[2][j];
    const double lx[4] = {0.0, bk.lx[1][j], bk.lx[2][j], bk.lx[3][j]};
    const double ly[4] = {0.0, bk.ly[1][j], bk.ly[2][j], bk.ly[3][j]};
    const double z2 = bk.z2[j];
    const double PX1 = 0.5 * (ly[1] - ly[3]), PY1 = 0.5 * (lx[3] - lx[1]);
    const double PX2 = 0.5 * ly[2], PY2 = -0.5 * lx[2];
    const double area = std::max(2.0 * (PY2 * PX1 - PY1 * PX2), tiny20);
    const double ainv = 1.0 / area;
    bk.px1[j] = PX1, bk.py1[j] = PY1, bk.px2[j] = PX2, bk.py2[j] = PY2;
    bk.area[j] = area, bk.ainv[j] = ainv;
    sec.area[j] = area;

    double vx[4], vy[4], vz[4], rx[4], ry[4];
    for (int n = 0; n < 4; ++n) {
      double rz_unused = 0;
      to_local(e1x, e1y, e1z, e2x, e2y, e2z, e3x, e3y, e3z, bk.nb.vx[n][j], bk.nb.vy[n][j], bk.nb.vz[n][j],
               vx[n], vy[n], vz[n]);
      to_local(e1x, e1y, e1z, e2x, e2y, e2z, e3x, e3y, e3z, bk.nb.rx[n][j], bk.nb.ry[n][j], bk.nb.rz[n][j],
               rx[n], ry[n], rz_unused);
    }
    bk.rxh[j] = rx[0] - rx[1] + rx[2] - rx[3];  // hourglass rotation rates [1.7]
    bk.ryh[j] = ry[0] - ry[1] + ry[2] - ry[3];

    // Rates times A [1.3], after Ishell 4's velocity changes (zero for Ishell 1).
    const double w13 = vz[0] - vz[2], w24 = vz[1] - vz[3];
    const double gzx = (PX1 * w13 + PX2 * w24) * ainv, gzy = (PY1 * w13 + PY2 * w24) * ainv;
    const double wa = w4 * (0.5 * gzx * z2), wb = w4 * (0.5 * dt1 * gzx * gzx);
    const double wc = w4 * (0.5 * gzy * z2), wd = w4 * (0.5 * dt1 * gzy * gzy);
    vx[0] += -wa - wb * PY2, vx[1] += wa + wb * PY1, vx[2] += -wa + wb * PY2, vx[3] += wa - wb * PY1;
    vy[0] += -wc + wd * PX2, vy[1] += wc - wd * PX1, vy[2] += -wc - wd * PX2, vy[3] += wc + wd * PX1;
    for (int n = 0; n < 4; ++n) bk.vx[n][j] = vx[n], bk.vy[n][j] = vy[n], bk.vz[n][j] = vz[n];
    const double ta = signed_floor(PY1 + PY2, tiny20), tb = signed_floor(PX2 - PX1, tiny20);
    const double t1 = w1 * (0.25 * dt1 * (w13 - w24) * (w13 - w24) / ta);
    const double t2 = w1 * (0.25 * dt1 * (w13 + w24) * (w13 + w24) / tb);
    const double u13 = vx[0] - vx[2] - t1, u24 = vx[1] - vx[3] + t1;
    const double v13 = vy[0] - vy[2] + t2, v24 = vy[1] - vy[3] + t2;
    const double rx13 = rx[0] - rx[2], rx24 = rx[1] - rx[3], ry13 = ry[0] - ry[2], ry24 = ry[1] - ry[3];
    const double rxs = rx[0] + rx[1] + rx[2] + rx[3], rys = ry[0] + ry[1] + ry[2] + ry[3];
    const double f = dt1 * ainv;  // rate * A -> increment
    sec.dem[0][j] = f * (PX1 * u13 + PX2 * u24);
    sec.dem[1][j] = f * (PY1 * v13 + PY2 * v24);
    sec.dem[2][j] = f * (PY1 * u13 + PY2 * u24 + PX1 * v13 + PX2 * v24);
    sec.dem[3][j] = f * (PY1 * w13 + PY2 * w24 - 0.25 * area * rxs);  // gyz
    sec.dem[4][j] = f * (PX1 * w13 + PX2 * w24 + 0.25 * area * rys);  // gzx
    sec.dk[0][j] = f * (PX1 * ry13 + PX2 * ry24);
    sec.dk[1][j] = -f * (PY1 * rx13 + PY2 * rx24);
    sec.dk[2][j] = f * (PY1 * ry13 + PY2 * ry24 - PX1 * rx13 - PX2 * rx24);

    // Element step length [4.1].
    const double l12 = lx[1] * lx[1] + ly[1] * ly[1];
    const double l23 = (lx[2] - lx[1]) * (lx[2] - lx[1]) + (ly[2] - ly[1]) * (ly[2] - ly[1]);
    const double l34 = (lx[3] - lx[2]) * (lx[3] - lx[2]) + (ly[3] - ly[2]) * (ly[3] - ly[2]);
    const double l41 = lx[3] * lx[3] + ly[3] * ly[3];
    const double d13 = lx[2] * lx[2] + ly[2] * ly[2];
    const double d24 = (lx[3] - lx[1]) * (lx[3] - lx[1]) + (ly[3] - ly[1]) * (ly[3] - ly[1]);
    // (std::min/max of locals, not of initializer lists: the same first-extremum rule, and it vectorises)
    double lmin2 = std::min(std::min(l12, l23), l41);
    if (l34 != 0.0) lmin2 = std::min(std::min(std::min(lmin2, l34), d13), d24);
    double l2 = std::max(area * area / std::max(std::max(d13, d24), tiny20), lmin2);
    l2 = std::min(l2, 0.5 * (lmin2 + l2) / hdiv + hoff);  // hourglass guard (hmax > 0 only)
    bk.l2[j] = l2;

    // Square-root arguments: equivalent strain rate (1.3, with the current thickness), step, sqrt(A).
    const double th = thick[i0 + j];
    bk.root[0][j] = shell_detail::equivalent_rate_arg(sec.dem[0][j], sec.dem[1][j], sec.dem[2][j],
                                                      sec.dk[0][j], sec.dk[1][j], sec.dk[2][j], th);
    bk.root[1][j] = l2;
    bk.root[2][j] = area;
  }
}

// Filtered strain rate (6.1) and its rate term (law 2: the lower bound; law 36: the rate).
[[gnu::always_inline]] inline void bt4_filtered_rate(Bt4Block& bk, const Bt4Constants& k,
                                                     const MaterialParams& mat, ShellGroup& g, int i0,
                                                     int len) {
  shell_detail::SectionBlock<kBlock>& sec = bk.sec;
  const double dt1 = k.s.dt1, alpha = k.s.alpha;
  double* rates = g.rate.data();
  std::int64_t any_rate = 0;
  RADX_IVDEP
  for (int j = 0; j < len; ++j) {
    const std::size_t ii = static_cast<std::size_t>(i0 + j);
    const double root = bk.root[0][j], old = rates[ii];
    const double eq = dt1 > 0 ? root / dt1 : 0.0;
    const double rate = alpha * eq + (1.0 - alpha) * old;
    rates[ii] = sec.off[j] > 0.0 ? rate : old;
    bk.rate[j] = rate;
    sec.rate[j] = rate;
    sec.rfac[j] = jc_rate_factor_lower(k.c_lower, k.inv_rate0, rate);  // 1 unless r_lower
    sec.rfac_exact[j] = 0;
    const std::int64_t r = rate <= k.rate_one ? 0 : 1;  // law 36's rate term (R = 1 otherwise)
    bk.flag[j] = r;
    any_rate |= r;
  }
  if (any_rate != 0)
    for (int j = 0; j < len; ++j)
      if (bk.flag[j] != 0) sec.rfac[j] = jc_rate_factor(mat, bk.rate[j]);
}

// Hourglass forces and moments of element j [1.7] added to its local nodal forces, its stored hourglass
// resultants (hg) and energy (e_hg) updated; hourglass = false (deleted, or a degenerate quad) adds exact
// zeros.
[[gnu::always_inline]] inline void bt4_hourglass(const Bt4Block& bk, const Bt4Constants& k, double* hg,
                                                 double* e_hg, int j, std::size_t ii, double off,
                                                 bool hourglass, double fx[4], double fy[4], double fz[4],
                                                 double mx[4], double my[4]) {
  constexpr std::size_t G = kGroupSize;
  const shell_detail::SectionBlock<kBlock>& sec = bk.sec;
  const double dt1 = k.s.dt1, one = k.one, zero = k.zero, wh = k.wh;
  const double area = bk.area[j], ainv = bk.ainv[j], t = sec.t[j], sqrt_area = bk.root[2][j];
  const double PX1 = bk.px1[j], PY1 = bk.py1[j], PX2 = bk.px2[j], PY2 = bk.py2[j];
  const double lx1 = bk.lx[1][j], lx2 = bk.lx[2][j], lx3 = bk.lx[3][j];
  const double ly1 = bk.ly[1][j], ly2 = bk.ly[2][j], ly3 = bk.ly[3][j];
  const double hx = (-lx1 + lx2 - lx3) * ainv, hy = (-ly1 + ly2 - ly3) * ainv;
  const double c1 = wh * (PX1 * hx + PY1 * hy), c2 = wh * (PX2 * hx + PY2 * hy);
  const double gam[4] = {off * (1.0 - c1), off * (-1.0 - c2), off * (1.0 + c1), off * (-1.0 + c2)};
  double qx = 0, qy = 0, qz = 0;
  for (int n = 0; n < 4; ++n) {
    qx += gam[n] * bk.vx[n][j];
    qy += gam[n] * bk.vy[n][j];
    qz += gam[n] * bk.vz[n][j];
  }
  const double rxh = bk.rxh[j], ryh = bk.ryh[j];
  const double b12 = PX1 * PX1 + PY1 * PY1 + PX2 * PX2 + PY2 * PY2;
  const double cm = k.cm0 * t * sqrt_area, cf = k.cf0 * t * t, cr = k.cr0 * t * t * area;
  const double km = k.km0 * t, kf = k.kf0 * t * t * t / std::max(b12, k.tiny30);
  const double sx0 = hg[ii], sy0 = hg[G + ii], sz0 = hg[2 * G + ii];
  const double sx = sx0 + km * qx, sy = sy0 + km * qy, sz = sz0 + kf * qz;
  const double mhg = hourglass ? one : zero;
  hg[ii] = sx0 + mhg * (km * qx);
  hg[G + ii] = sy0 + mhg * (km * qy);
  hg[2 * G + ii] = sz0 + mhg * (kf * qz);
  const double hxf = mhg * (sx + cm * std::abs(qx) * qx);
  const double hyf = mhg * (sy + cm * std::abs(qy) * qy);
  const double hzf = mhg * (sz + cf * std::abs(qz) * qz);
  const double mxh = mhg * (cr * std::abs(rxh) * rxh);
  const double myh = mhg * (cr * std::abs(ryh) * ryh);
  constexpr double h[4] = {1.0, -1.0, 1.0, -1.0};
  const double warp = k.w4_moment * 0.25 * bk.z2[j] * (gam[0] + gam[2]);  // Ishell 4, N > 1
  for (int n = 0; n < 4; ++n) {
    fx[n] += hxf * gam[n];
    fy[n] += hyf * gam[n];
    fz[n] += hzf * gam[n];
    mx[n] += mxh * h[n] - warp * hyf;
    my[n] += myh * h[n] + warp * hxf;
  }
  const double de_hg = dt1 * off * (hxf * qx + hyf * qy + hzf * qz + mxh * rxh + myh * ryh);
  const double eh = e_hg[ii];
  e_hg[ii] = eh + mhg * de_hg;
}

// Failure, thickness, energy [1.5], forces [1.6] and hourglass [1.7], in local axes into bk.fl; returns
// whether an element of the block is deleted (at entry or in this cycle: bk.flag).
[[gnu::always_inline]] inline std::int64_t bt4_energy_forces_hourglass(Bt4Block& bk, const Bt4Constants& k,
                                                                       ShellGroup& g, int i0, int len) {
  shell_detail::SectionBlock<kBlock>& sec = bk.sec;
  const double visc0 = k.s.visc0, one = k.one, zero = k.zero;
  double* offs = g.off.data();
  double* w_plastic = g.w_plastic.data();
  double* thick = g.thick.data();
  double* e_int = g.e_int.data();
  double* e_hg = g.e_hg.data();
  double* hg = g.hg.data();
  std::int64_t any_gone = 0;
  RADX_IVDEP
  for (int j = 0; j < len; ++j) {
    const std::size_t ii = static_cast<std::size_t>(i0 + j);
    const double off_start = sec.off[j];
    const bool live = off_start > 0.0;
    const double area = bk.area[j], t = sec.t[j], sqrt_area = bk.root[2][j];
    const double PX1 = bk.px1[j], PY1 = bk.py1[j], PX2 = bk.px2[j], PY2 = bk.py2[j];
    const double dem[5] = {sec.dem[0][j], sec.dem[1][j], sec.dem[2][j], sec.dem[3][j], sec.dem[4][j]};
    const double dk[3] = {sec.dk[0][j], sec.dk[1][j], sec.dk[2][j]};

    const double off = bk.off[j];
    offs[ii] = live ? off : off_start;
    const double wp0 = w_plastic[ii], wp1 = sec.w_plastic[j], th0 = thick[ii], dth = sec.dthick[j];
    const double mlive = live ? one : zero;
    w_plastic[ii] = wp0 + mlive * wp1;
    thick[ii] = th0 + mlive * (dth * off);

    // Membrane damping (Dm > 0 only: visc0 = 0 otherwise, and fv = 0).
    const double visc = visc0 * sqrt_area;
    const double fv[3] = {visc * (dem[0] + 0.5 * dem[1]), visc * (dem[1] + 0.5 * dem[0]),
                          visc * dem[2] / 3.0};

    // Internal energy [1.5].
    double de_mem = 0, de_bend = 0;
    for (int q = 0; q < 5; ++q) de_mem += (off_start * sec.for_old[q][j] + off * sec.for_new[q][j]) * dem[q];
    for (int q = 0; q < 3; ++q) de_bend += (off_start * sec.mom_old[q][j] + off * sec.mom_new[q][j]) * dk[q];
    const double de_int = 0.5 * area * t * (de_mem + t * de_bend) +
                          area * t * off * (fv[0] * dem[0] + fv[1] * dem[1] + fv[2] * dem[2]);
    const double ei = e_int[ii];
    e_int[ii] = ei + mlive * de_int;

    // Internal nodal forces [1.6], local axes.
    const bool alive = live & (off > 0.0);  // not deleted at entry nor in this cycle
    const std::int64_t gone = alive ? 0 : 1;
    bk.flag[j] = gone;
    any_gone |= gone;
    const double ot = off * t, ot2 = off * t * t;
    const double Nxx = ot * (sec.for_new[0][j] + fv[0]), Nyy = ot * (sec.for_new[1][j] + fv[1]),
                 Nxy = ot * (sec.for_new[2][j] + fv[2]);
    const double Qy = ot * sec.for_new[3][j], Qx = ot * sec.for_new[4][j];
    const double Mxx = ot2 * sec.mom_new[0][j], Myy = ot2 * sec.mom_new[1][j], Mxy = ot2 * sec.mom_new[2][j];
    const double PX[4] = {PX1, PX2, -PX1, -PX2};
    const double PY[4] = {PY1, PY2, -PY1, -PY2};
    double fx[4], fy[4], fz[4], mx[4], my[4];
    for (int n = 0; n < 4; ++n) {
      fx[n] = Nxx * PX[n] + Nxy * PY[n];
      fy[n] = Nxy * PX[n] + Nyy * PY[n];
      fz[n] = Qx * PX[n] + Qy * PY[n];
      mx[n] = -(Myy * PY[n] + Mxy * PX[n]) - 0.25 * area * Qy;
      my[n] = Mxx * PX[n] + Mxy * PY[n] + 0.25 * area * Qx;
    }

    // Hourglass [1.7]: none for a degenerate quad.
    bt4_hourglass(bk, k, hg, e_hg, j, ii, off, alive & (bk.nondeg[j] != 0.0), fx, fy, fz, mx, my);

    for (int n = 0; n < 4; ++n) {
      bk.fl[0][n][j] = fx[n], bk.fl[1][n][j] = fy[n], bk.fl[2][n][j] = fz[n];
      bk.fl[3][n][j] = mx[n], bk.fl[4][n][j] = my[n];
    }
  }
  return any_gone;
}

// The kernel, compiled once per instruction-set variant (kernel_isa.hpp) by the wrappers below: the list of
// its stages over each block of the group.
void bt4_body(ShellGroup& g, const NodeState& nodes, const MaterialParams& mat, const CycleInfo& cyc) {
  using namespace shell_detail;
  ensure_resultant_storage(g);
  const Bt4Constants k = bt4_constants(g.props, mat, cyc.dt1);
  double capture[kGroupSize];
  const std::int64_t any_small = bt4_small_strain_capture(g, capture);

  Bt4Block bk;
  SectionBlock<kBlock>& sec = bk.sec;
  sec.dt1 = k.s.dt1;  // law 27's rate term
  sec.rfac_lower = k.r_lower;
  for (int i0 = 0; i0 < g.count; i0 += kBlock) {
    const int len = std::min(kBlock, g.count - i0);
    // Gather [docs/architecture.md 3], frame [1.2] and thickness (thick = 0 is t0 on first use, live only).
    open_quad_block(g, nodes, i0, len, bk.nb, bk.fr);
    for (int j = 0; j < len; ++j) bk.nondeg[j] = bk.nb.node[2][j] != bk.nb.node[3][j] ? 1.0 : 0.0;
    open_thickness_block(FirstUseThickness::LiveElements, k.s.update_thick, g, i0, len, sec);
    bt4_local_coordinates(bk, g, i0, len, any_small, capture);
    bt4_geometry_and_increments(bk, k, g, i0, len);
    sqrt_in_place(bk.root[0], 3 * kBlock);
    bt4_filtered_rate(bk, k, mat, g, i0, len);
    // Section [1.4, 1.8, 6] and the element factor after it [6.4] (a loop of its own: its branches would
    // keep the next one from being vectorised).
    section_update_block(g, i0, len, mat, k.s.rule, k.s.gs, sec);
    for (int j = 0; j < len; ++j)
      bk.off[j] = next_off(k.s.fail_limit, sec.off[j], sec.eps_p_max[j], sec.fail_now[j]);
    const std::int64_t any_gone = bt4_energy_forces_hourglass(bk, k, g, i0, len);
    // Rotate to global axes and store minus the internal force (a loop of its own: fewer live values);
    // element step [4.1] and nodal stiffness [4.5].
    double* dts = g.dt.data();
    double* k_nodal = g.k_nodal.data();
    store_quad_block(bk.fr, bk.fl, g, i0, len, [&](int j, std::size_t ii) {
      const double area = bk.area[j], t = sec.t[j], l2 = bk.l2[j], l = bk.root[1][j];
      dts[ii] = l * k.s.phi / k.s.c;
      k_nodal[ii] = 0.81 * 0.5 * area * t * k.s.young / l2;
    });
    clear_deleted_block(g, i0, len, bk.flag, any_gone);
  }
}

[[gnu::flatten]] void bt4_baseline(ShellGroup& g, const NodeState& nodes, const MaterialParams& mat,
                                   const CycleInfo& cyc) {
  bt4_body(g, nodes, mat, cyc);
}

#if RADX_HAVE_ISA_V3
RADX_TARGET_V3 void bt4_v3(ShellGroup& g, const NodeState& nodes, const MaterialParams& mat,
                           const CycleInfo& cyc) {
  bt4_body(g, nodes, mat, cyc);
}
#endif

}  // namespace

void shell_bt4_forces(ShellGroup& g, const NodeState& nodes, const MaterialParams& mat, const CycleInfo& cyc,
                      KernelIsa isa) {
#if RADX_HAVE_ISA_V3
  if (isa == KernelIsa::V3 && kernel_isa_supported(KernelIsa::V3)) return bt4_v3(g, nodes, mat, cyc);
#endif
  (void)isa;
  bt4_baseline(g, nodes, mat, cyc);
}

void shell_bt4_forces(ShellGroup& g, const NodeState& nodes, const MaterialParams& mat,
                      const CycleInfo& cyc) {
  shell_bt4_forces(g, nodes, mat, cyc, best_kernel_isa());
}

}  // namespace radx::solver
