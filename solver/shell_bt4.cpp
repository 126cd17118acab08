// Four-node Belytschko-Tsay shell (Ishell 1; every other Ishell is run as 1), one point in the plane, as
// OpenRadioss runs it by default. Source of every formula: shared/spec/elements.md (sections in brackets),
// itself read from OpenRadioss cforc3.F, ccoor3.F, cnvec3.F, cderi3.F, cdefo3.F, ccurv3.F, cstra3.F,
// mulawc.F90, cfint3.F, chvis3.F, cdlen3.F, cdt3.F.
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
//
// Conventions: nodal_force ([4][6][G], fx fy fz mx my mz) is the force ADDED to each node (minus the
// internal force), global axes; dt is in the model's time unit, before the /DT scale; at cycle 0
// (dt1 = 0) every increment is zero and the forces come from the stored state (plus the viscous hourglass
// forces, which depend on the velocity only); an element whose OFF is 0 at entry gives no force, no energy
// and dt = +inf; thick = 0 is taken as t0 on first use. N = 0 keeps FOR and MOM in sig as [8][G]
// (shell_section.hpp; the buffer is grown once if allocate() made it [5][G]).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "solver/element_groups.hpp"
#include "solver/shell_section.hpp"

namespace radx::solver {

namespace {

inline double signed_floor(double v, double eps) {
  return v >= 0 ? std::max(v, eps) : std::min(v, -eps);
}

}  // namespace

void shell_bt4_forces(ShellGroup& g, const NodeState& nodes, const MaterialParams& mat,
                      const CycleInfo& cyc) {
  using namespace shell_detail;
  constexpr std::size_t G = kGroupSize;
  const ShellProps& pr = g.props;
  const double dt1 = cyc.dt1;
  const ThicknessRule rule = thickness_rule(std::max(pr.n_points, 0));
  ensure_resultant_storage(g);

  const double young = mat.young, nu = mat.nu, rho = mat.rho0;
  const double c = mat.c_shell > 0 ? mat.c_shell : std::sqrt(young / rho);
  const double shf = pr.n_points == 1 ? 0.0 : pr.ashear;
  const double gs = shf * mat.shear;
  const double dm = pr.dm;
  const double phi = std::sqrt(1.0 + dm * dm) - dm;
  const double visc0 = (dm > 0 && dt1 > 0) ? 1.414 * dm * rho * c / dt1 : 0.0;
  const double alpha = rate_filter_alpha(mat, dt1);
  const double hmax = std::max(pr.hm, pr.hf);
  // Hourglass coefficients without their geometric factors.
  const double cm0 = 12.5 * rho * pr.hm;
  const double cf0 = 12.5 * rho * pr.hf * std::sqrt(shf / (3.0 * (1.0 + nu)));
  const double cr0 = 0.90211 * rho * pr.hr;
  const double km0 = young * pr.hm / 8.0 * dt1;
  const double kf0 = young * pr.hf * shf / (24.0 * (1.0 + nu)) * dt1;
  constexpr double kInf = std::numeric_limits<double>::infinity();

  const double* X = nodes.x.data();
  const double* Y = nodes.y.data();
  const double* Z = nodes.z.data();
  const double* VX = nodes.vx.data();
  const double* VY = nodes.vy.data();
  const double* VZ = nodes.vz.data();
  const double* WX = nodes.wx.data();
  const double* WY = nodes.wy.data();
  const double* WZ = nodes.wz.data();
  double* nf = g.nodal_force.data();

  for (int i = 0; i < g.count; ++i) {
    const std::size_t ii = static_cast<std::size_t>(i);
    const double off_start = g.off[ii];
    if (off_start <= 0.0) {
      for (int r = 0; r < 24; ++r) nf[r * G + ii] = 0.0;
      g.dt[ii] = kInf;
      g.k_nodal[ii] = 0.0;
      continue;
    }
    // Gather.
    std::int32_t n[4];
    double px[4], py[4], pz[4];
    for (int k = 0; k < 4; ++k) {
      n[k] = g.conn[k * G + ii];
      px[k] = X[n[k]];
      py[k] = Y[n[k]];
      pz[k] = Z[n[k]];
    }
    const bool degenerate = n[2] == n[3];
    if (g.thick[ii] <= 0.0) g.thick[ii] = g.t0[ii];
    const double t = pr.ithick == 1 ? g.thick[ii] : g.t0[ii];

    // Convected frame [1.2].
    const double g1x = (px[1] - px[0]) + (px[2] - px[3]), g1y = (py[1] - py[0]) + (py[2] - py[3]),
                 g1z = (pz[1] - pz[0]) + (pz[2] - pz[3]);
    const double g2x = (px[2] - px[1]) + (px[3] - px[0]), g2y = (py[2] - py[1]) + (py[3] - py[0]),
                 g2z = (pz[2] - pz[1]) + (pz[3] - pz[0]);
    double e3x = g1y * g2z - g1z * g2y, e3y = g1z * g2x - g1x * g2z, e3z = g1x * g2y - g1y * g2x;
    double inv = 1.0 / std::max(std::sqrt(e3x * e3x + e3y * e3y + e3z * e3z), 1e-30);
    e3x *= inv, e3y *= inv, e3z *= inv;
    const double ng1 = std::sqrt(g1x * g1x + g1y * g1y + g1z * g1z);
    const double ng2 = std::sqrt(g2x * g2x + g2y * g2y + g2z * g2z);
    const double f12 = ng1 / std::max(ng2, 1e-30);
    double e1x = g1x + f12 * (g2y * e3z - g2z * e3y), e1y = g1y + f12 * (g2z * e3x - g2x * e3z),
           e1z = g1z + f12 * (g2x * e3y - g2y * e3x);
    inv = 1.0 / std::max(std::sqrt(e1x * e1x + e1y * e1y + e1z * e1z), 1e-30);
    e1x *= inv, e1y *= inv, e1z *= inv;
    const double e2x = e3y * e1z - e3z * e1y, e2y = e3z * e1x - e3x * e1z, e2z = e3x * e1y - e3y * e1x;

    double lx[4], ly[4];
    lx[0] = ly[0] = 0.0;
    for (int k = 1; k < 4; ++k) {
      const double dx = px[k] - px[0], dy = py[k] - py[0], dz = pz[k] - pz[0];
      lx[k] = e1x * dx + e1y * dy + e1z * dz;
      ly[k] = e2x * dx + e2y * dy + e2z * dz;
    }
    const double PX1 = 0.5 * (ly[1] - ly[3]), PY1 = 0.5 * (lx[3] - lx[1]);
    const double PX2 = 0.5 * ly[2], PY2 = -0.5 * lx[2];
    const double PX[4] = {PX1, PX2, -PX1, -PX2};
    const double PY[4] = {PY1, PY2, -PY1, -PY2};
    const double area = std::max(2.0 * (PY2 * PX1 - PY1 * PX2), 1e-20);
    const double ainv = 1.0 / area;

    // Local velocities and rotations.
    double vx[4], vy[4], vz[4], rx[4], ry[4];
    for (int k = 0; k < 4; ++k) {
      const double ux = VX[n[k]], uy = VY[n[k]], uz = VZ[n[k]];
      const double wx = WX[n[k]], wy = WY[n[k]], wz = WZ[n[k]];
      vx[k] = e1x * ux + e1y * uy + e1z * uz;
      vy[k] = e2x * ux + e2y * uy + e2z * uz;
      vz[k] = e3x * ux + e3y * uy + e3z * uz;
      rx[k] = e1x * wx + e1y * wy + e1z * wz;
      ry[k] = e2x * wx + e2y * wy + e2z * wz;
    }

    // Rates times A [1.3].
    const double w13 = vz[0] - vz[2], w24 = vz[1] - vz[3];
    const double ta = signed_floor(PY1 + PY2, 1e-20), tb = signed_floor(PX2 - PX1, 1e-20);
    const double t1 = 0.25 * dt1 * (w13 - w24) * (w13 - w24) / ta;
    const double t2 = 0.25 * dt1 * (w13 + w24) * (w13 + w24) / tb;
    const double u13 = vx[0] - vx[2] - t1, u24 = vx[1] - vx[3] + t1;
    const double v13 = vy[0] - vy[2] + t2, v24 = vy[1] - vy[3] + t2;
    const double rx13 = rx[0] - rx[2], rx24 = rx[1] - rx[3], ry13 = ry[0] - ry[2], ry24 = ry[1] - ry[3];
    const double rxs = rx[0] + rx[1] + rx[2] + rx[3], rys = ry[0] + ry[1] + ry[2] + ry[3];
    const double f = dt1 * ainv;  // rate * A -> increment
    double dem[5], dk[3];
    dem[0] = f * (PX1 * u13 + PX2 * u24);
    dem[1] = f * (PY1 * v13 + PY2 * v24);
    dem[2] = f * (PY1 * u13 + PY2 * u24 + PX1 * v13 + PX2 * v24);
    dem[3] = f * (PY1 * w13 + PY2 * w24 - 0.25 * area * rxs);  // gyz
    dem[4] = f * (PX1 * w13 + PX2 * w24 + 0.25 * area * rys);  // gzx
    dk[0] = f * (PX1 * ry13 + PX2 * ry24);
    dk[1] = -f * (PY1 * rx13 + PY2 * rx24);
    dk[2] = f * (PY1 * ry13 + PY2 * ry24 - PX1 * rx13 - PX2 * rx24);

    // Strain rate (one per element) and the section.
    const double rate = alpha * equivalent_rate(dem, dk, g.thick[ii], dt1) + (1.0 - alpha) * g.rate[ii];
    g.rate[ii] = rate;
    SectionUpdate su;
    section_update(g, i, mat, rule, gs, t, area, rate, off_start, dem, dk, su);
    const double off = next_off(mat, off_start, su.eps_p_max);
    g.off[ii] = off;
    g.w_plastic[ii] += su.w_plastic;
    g.thick[ii] += su.dthick * off;

    // Membrane damping (Dm > 0 only).
    double fv[3] = {0.0, 0.0, 0.0};
    if (visc0 > 0) {
      const double visc = visc0 * std::sqrt(area);
      fv[0] = visc * (dem[0] + 0.5 * dem[1]);
      fv[1] = visc * (dem[1] + 0.5 * dem[0]);
      fv[2] = visc * dem[2] / 3.0;
    }

    // Internal energy [1.5].
    double de_mem = 0, de_bend = 0;
    for (int k = 0; k < 5; ++k) de_mem += (off_start * su.for_old[k] + off * su.for_new[k]) * dem[k];
    for (int k = 0; k < 3; ++k) de_bend += (off_start * su.mom_old[k] + off * su.mom_new[k]) * dk[k];
    g.e_int[ii] += 0.5 * area * t * (de_mem + t * de_bend) +
                   area * t * off * (fv[0] * dem[0] + fv[1] * dem[1] + fv[2] * dem[2]);

    if (off <= 0.0) {  // deleted in this cycle
      for (int r = 0; r < 24; ++r) nf[r * G + ii] = 0.0;
      g.dt[ii] = kInf;
      g.k_nodal[ii] = 0.0;
      continue;
    }

    // Internal nodal forces [1.6], local axes.
    const double ot = off * t, ot2 = off * t * t;
    const double Nxx = ot * (su.for_new[0] + fv[0]), Nyy = ot * (su.for_new[1] + fv[1]),
                 Nxy = ot * (su.for_new[2] + fv[2]);
    const double Qy = ot * su.for_new[3], Qx = ot * su.for_new[4];
    const double Mxx = ot2 * su.mom_new[0], Myy = ot2 * su.mom_new[1], Mxy = ot2 * su.mom_new[2];
    double fx[4], fy[4], fz[4], mx[4], my[4];
    for (int k = 0; k < 4; ++k) {
      fx[k] = Nxx * PX[k] + Nxy * PY[k];
      fy[k] = Nxy * PX[k] + Nyy * PY[k];
      fz[k] = Qx * PX[k] + Qy * PY[k];
      mx[k] = -(Myy * PY[k] + Mxy * PX[k]) - 0.25 * area * Qy;
      my[k] = Mxx * PX[k] + Mxy * PY[k] + 0.25 * area * Qx;
    }

    // Hourglass [1.7].
    if (!degenerate) {
      const double hx = (-lx[1] + lx[2] - lx[3]) * ainv, hy = (-ly[1] + ly[2] - ly[3]) * ainv;
      const double c1 = PX1 * hx + PY1 * hy, c2 = PX2 * hx + PY2 * hy;
      const double gam[4] = {off * (1.0 - c1), off * (-1.0 - c2), off * (1.0 + c1), off * (-1.0 + c2)};
      double qx = 0, qy = 0, qz = 0;
      for (int k = 0; k < 4; ++k) {
        qx += gam[k] * vx[k];
        qy += gam[k] * vy[k];
        qz += gam[k] * vz[k];
      }
      const double rxh = rx[0] - rx[1] + rx[2] - rx[3], ryh = ry[0] - ry[1] + ry[2] - ry[3];
      const double b12 = PX1 * PX1 + PY1 * PY1 + PX2 * PX2 + PY2 * PY2;
      const double cm = cm0 * t * std::sqrt(area), cf = cf0 * t * t, cr = cr0 * t * t * area;
      const double km = km0 * t, kf = kf0 * t * t * t / std::max(b12, 1e-30);
      double* S = g.hg.data();
      S[ii] += km * qx;
      S[G + ii] += km * qy;
      S[2 * G + ii] += kf * qz;
      const double hxf = S[ii] + cm * std::abs(qx) * qx, hyf = S[G + ii] + cm * std::abs(qy) * qy,
                   hzf = S[2 * G + ii] + cf * std::abs(qz) * qz;
      const double mxh = cr * std::abs(rxh) * rxh, myh = cr * std::abs(ryh) * ryh;
      constexpr double h[4] = {1.0, -1.0, 1.0, -1.0};
      for (int k = 0; k < 4; ++k) {
        fx[k] += hxf * gam[k];
        fy[k] += hyf * gam[k];
        fz[k] += hzf * gam[k];
        mx[k] += mxh * h[k];
        my[k] += myh * h[k];
      }
      g.e_hg[ii] += dt1 * off * (hxf * qx + hyf * qy + hzf * qz + mxh * rxh + myh * ryh);
    }

    // Rotate to global axes and store minus the internal force.
    for (int k = 0; k < 4; ++k) {
      double* o = nf + static_cast<std::size_t>(k) * 6 * G + ii;
      o[0] = -(fx[k] * e1x + fy[k] * e2x + fz[k] * e3x);
      o[G] = -(fx[k] * e1y + fy[k] * e2y + fz[k] * e3y);
      o[2 * G] = -(fx[k] * e1z + fy[k] * e2z + fz[k] * e3z);
      o[3 * G] = -(mx[k] * e1x + my[k] * e2x);
      o[4 * G] = -(mx[k] * e1y + my[k] * e2y);
      o[5 * G] = -(mx[k] * e1z + my[k] * e2z);
    }

    // Element step [4.1] and nodal stiffness [4.5].
    const double l12 = lx[1] * lx[1] + ly[1] * ly[1];
    const double l23 = (lx[2] - lx[1]) * (lx[2] - lx[1]) + (ly[2] - ly[1]) * (ly[2] - ly[1]);
    const double l34 = (lx[3] - lx[2]) * (lx[3] - lx[2]) + (ly[3] - ly[2]) * (ly[3] - ly[2]);
    const double l41 = lx[3] * lx[3] + ly[3] * ly[3];
    const double d13 = lx[2] * lx[2] + ly[2] * ly[2];
    const double d24 = (lx[3] - lx[1]) * (lx[3] - lx[1]) + (ly[3] - ly[1]) * (ly[3] - ly[1]);
    double lmin2 = std::min({l12, l23, l41});
    if (l34 != 0.0) lmin2 = std::min({lmin2, l34, d13, d24});
    double l2 = std::max(area * area / std::max({d13, d24, 1e-20}), lmin2);
    if (hmax > 0) l2 = std::min(l2, 0.5 * (lmin2 + l2) / hmax);
    g.dt[ii] = std::sqrt(l2) * phi / c;
    g.k_nodal[ii] = 0.81 * 0.5 * area * t * young / l2;
  }
}

}  // namespace radx::solver
