// Four-node shell QEPH (Ishell 24): one integration point in the plane, with physical hourglass
// stabilisation instead of Ishell 1's viscous and elastic hourglass. Sources: docs/theory/elements.md 1.10,
// 4.3, 4.5 and 5, read from OpenRadioss czforc3.F (call sequence), czcorc.F (frame, local coordinates),
// czdef.F (centre rates and the hourglass rates), czstrah3.F (the stabilisation strains at the four Gauss
// points: only xx and yy of the membrane and bending fields, the in-plane shears stay constant),
// czfintn.F (stabilisation resultants: the material's A11 times the tangent factor ZCFAC, and Dn), cndt3.F
// and cncoef3.F (step and nodal stiffness), cinmas.F (inertia). Written from the formulas, in our own words
// and structure; what is our interpretation is marked [inferred].
//
// Frame and local coordinates: shell_frame.hpp (1.2, the bisector frame of Ishell 1), rebuilt every cycle;
// stresses stay in that convected frame. Warping terms are not taken (flat element) [inferred: czdef.F adds
// them with the warp z1, which Ishell 1 also drops].
// Rows: shell_quad_mindlin.hpp (bilinear membrane and curvature, assumed transverse shear tied at the edge
// midpoints). The centre point (xi = eta = 0) gives the constant part:
//   de = rows(0) v dt1 with the second-order membrane correction of 1.3 (exx -= dt1 w,x^2, eyy -= dt1 w,y^2,
//   quad_second_order), dkappa likewise; the section (shell_section.hpp: 1.4, 1.8, 6.3, 6.4, 6.5) updates
//   FOR, MOM at the N points; f_k = A rows(0)^T (N, M, Q), A = 4 det J(0) (the area of Ishell 1), N = FOR t,
//   M = MOM t^2, Q = FOR_shear t, all times OFF. Energy as Ishell 1 (1.5).
// Membrane damping (1.4, Dm default 0.015 for QEPH): visc = 1.414 Dm rho c sqrt(A)/dt1 on the centre
//   membrane increments, its work booked in the internal energy.
// Stabilisation, at the four Gauss points g (xi, eta = +-1/sqrt(3), weight det J(g)):
//   hourglass rates  dh(g) = rows(g) v - rows(0) v, kept for exx, eyy, kxx, kyy, gyz, gzx only;
//   stored resultants S(g) += C_h dh(g) dt1, with C_h = (A11 t fm, A11 t fm, A11 t^3/12 fb, A11 t^3/12 fb,
//   GS t fm, GS t fm) (bending terms 0 for N = 1), A11 = E/(1 - nu^2), GS = Ashear G;
//   damping  S_v(g) = Dn (L/c) C_h dh(g) (stiffness-proportional, damping ratio Dn at the element's highest
//   frequency 2c/L: the reason the step carries sqrt(1 + Dn^2) - Dn) [inferred form; the default Dn 0.015
//   and its step factor are read];
//   f_k += sum_g det J(g) (rows(g) - rows(0))^T (S(g) + S_v(g)) times OFF;
//   E_hg += sum_g det J(g) OFF [1/2 (S_old + S_new) + S_v] . dh dt1 (hourglass energy, not internal).
//   fm, fb: tangent factors of the points (ZCFAC): each point that yielded in this cycle gives
//   f_p = (dsigma . de)/(de . C de), clamped to [0, 1] (the elasto-plastic stiffness along its strain
//   increment over the elastic one), an elastic point gives 1; fm = sum w_p f_p, fb = sum w_p zeta_p^2 f_p /
//   sum w_p zeta_p^2 [inferred: ZCFAC is returned by the material law; this is the same ratio measured
//   through the generic material point functions, so every law gets it]. Hm, Hf, Hr are not used.
//   Since sum_g det J(g) (rows(g) - rows(0)) = 0 and rows(g) - rows(0) vanishes on every linear velocity
//   field, a constant strain or curvature field gives no stabilisation force: the patch tests hold.
// Step (4.3, 1.10; stored before the /DT scale): dt = L (sqrt(1 + Dn^2) - Dn)/c, c = sqrt(E/rho), L of
//   qeph_step_length (shell_quad_mindlin.hpp). Nodal stiffness (4.5, cndt3.F): k = 1/2 A t A11 / L^2.
// Inertia (5): I = m/4 (A0/12 + t0^2/12), set by the engine.
// Small strain (Ismstr 1 or after /DT/SHELL/CST): the local coordinates are frozen at the first cycle and
//   used from then on, as Ishell 1 does.
//
// Evaluation [our own algebra of the same rows; the equations above are unchanged]. Per-node rows at five
// points per element cost more than the rest of the kernel, so the rows are never formed. With the
// projections of the node values u_k of a field, u_xi = sum xi_k u_k / 4, u_eta = sum eta_k u_k / 4,
// u_h = sum h_k u_k / 4 (h_k = xi_k eta_k), and the same of the node coordinates (x_xi ... y_h), the
// bilinear map has x,xi = x_xi + eta x_h, x,eta = x_eta + xi x_h (y alike), u,xi = u_xi + eta u_h,
// u,eta = u_eta + xi u_h, and
//   rows(g) u = ((y,eta u,xi - y,xi u,eta), (x,xi u,eta - x,eta u,xi)) / det J(g)
// are the x and y derivatives; the assumed shear is J(g)^-1 of the four tied edge values. det J(g) and the
// numerators are linear in xi and eta (the shear's with a xi eta term), so the hourglass rates
// dh(g) = rows(g) v - rows(0) v cost a few products per field and point. The forces are the
// transpose: det J(g) rows(g)^T is the adjugate (no division), whose node values are
//   f_k = (xi_k S_xi + eta_k S_eta + h_k S_h) / 4,
//   S_xi = F_x y,eta - F_y x,eta,  S_eta = F_y x,xi - F_x y,xi,  S_h = eta S_xi + xi S_eta,
// summed over the points, F the flux of the field ((Nxx, Nxy) for fx, (Nxy, Nyy) for fy, (Mxx, Mxy) for my,
// -(Mxy, Myy) for mx), the sums over the four points taken through the moments of the point values (their
// sum and xi-, eta-, xi eta-weighted sums); the shear forces are those of the four edge values. The
// centre takes
//   R = 4 n0 - sum_g det J(g) / det J(0) s(g),   s(g) = OFF (S(g) + S_v(g)),
// which is A rows(0)^T n0 - sum_g det J(g) rows(0)^T s(g) with rows(0) = adj(0) / det J(0), A = 4 det J(0).
// The sums are those of the point-by-point form, in another order: the results agree to round-off.
//
// Layout: the group runs in blocks of kBlock elements; the gather and frame are the shared block passes
// (element_gather.hpp, shell_frame.hpp), the section is the shared vectorised through-thickness update; the
// local state, rates and hourglass rates, and then the energy, stabilisation and forces are two loops over
// the block's elements in structure-of-arrays form, which GCC vectorises (the square roots in passes of
// their own, sqrt_in_place; state updates written x + m dx with a mask m, as in shell_bt4.cpp). Only the
// tangent factor of the points that yielded in this cycle runs element by element.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
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
constexpr int kHgRows = 6;  // stabilisation resultants per Gauss point: nxx nyy mxx myy qyz qzx

struct QephBlock {
  NodeBlock<4, kBlock> nb;
  shell_detail::FrameBlock<kBlock> fr;
  double lx[4][kBlock], ly[4][kBlock];  // local coordinates (node 1 at the origin)
  double frozen[kBlock], capture[kBlock];
  // The bilinear map: x,xi = xa + eta xh, x,eta = xb + xi xh, y,xi = ya + eta yh, y,eta = yb + xi yh.
  double xa[kBlock], xb[kBlock], xh[kBlock], ya[kBlock], yb[kBlock], yh[kBlock];
  double inv0[kBlock];            // 1 / det J(0)
  double detg[4][kBlock];         // det J at the Gauss points: their weights
  double dh[4][kHgRows][kBlock];  // hourglass rates rows(g) v - rows(0) v
  double root[4][kBlock];         // square roots: equivalent rate, |g1|, |g2|, sqrt(A)
  double step_root[kBlock];       // the step's last root: L = A / step_root
  double rate[kBlock], off[kBlock], fm[kBlock], fb[kBlock];
  std::int64_t flag[kBlock];
  double sig_before[shell_detail::kMaxPoints][3][kBlock];  // in-plane stress of the points before the update
  double eps_before[shell_detail::kMaxPoints][kBlock];
  double fl[5][4][kBlock];  // local nodal forces fx fy fz and moments mx my
  shell_detail::SectionBlock<kBlock> sec;
};

// The group's constants of the kernel: the shared ones (shell_stages.hpp) and QEPH's own.
struct QephConstants {
  shell_detail::ShellConstants s;
  double a12, bend, dn, rate_one;
  // Tangent factors of an element none of whose points yielded in this cycle, and the bending weights.
  double fm_elastic, fb_elastic, bend_weight_sum;
  double tiny30, one, zero;  // opaque floor of divisors, and the masks of the state updates
  StepConstants step_k;
};

QephConstants qeph_constants(const ShellProps& pr, const MaterialParams& mat, double dt1) {
  QephConstants k;
  k.s = shell_detail::shell_constants(pr, mat, dt1, pr.dn);
  k.a12 = k.s.nu * k.s.a11;
  k.bend = pr.n_points == 1 ? 0.0 : 1.0 / 12.0;  // no bending stiffness with one point
  k.dn = pr.dn;
  // Strain rate above which the element's rate term differs from 1 (jc_rate_factor).
  k.rate_one = shell_rate_threshold(mat);
  // Tangent factors of an element none of whose points yielded in this cycle: the sums of the loop of
  // qeph_tangent_factors with f_p = 1 at every point, in its order (the same values to the bit); and the
  // bending weights sum w_p zeta_p^2 (0 for N <= 1).
  const shell_detail::ThicknessRule& rule = k.s.rule;
  k.fm_elastic = 1.0, k.fb_elastic = 1.0, k.bend_weight_sum = 0;
  if (rule.n > 0) {
    double sum_m = 0, sum_b = 0;
    for (int p = 0; p < rule.n; ++p) {
      sum_m += rule.w[p] * 1.0;
      sum_b += rule.w[p] * rule.zeta[p] * rule.zeta[p] * 1.0;
      k.bend_weight_sum += rule.w[p] * rule.zeta[p] * rule.zeta[p];
    }
    k.fm_elastic = sum_m;
    k.fb_elastic = k.bend_weight_sum > 0 ? sum_b / k.bend_weight_sum : k.fm_elastic;
  }
  // Floors of divisors, and the masks of the state updates (see shell_bt4.cpp: a select of a computed value
  // would be moved into a branch and keep the loop scalar).
  k.tiny30 = opaque(1e-30);
  k.step_k = StepConstants{k.tiny30, opaque(1e-60), opaque(0.5), opaque(0.0)};
  k.one = opaque(1.0), k.zero = opaque(0.0);
  return k;
}

// Small strain (Ismstr 1 or after /DT/SHELL/CST): the local coordinates are frozen at the first cycle; the
// elements that have none yet capture them now.
[[gnu::always_inline]] inline void qeph_small_strain_flags(QephBlock& bk, ShellGroup& g, int i0, int len) {
  double* small = g.small.data();
  for (int j = 0; j < len; ++j) {
    const std::size_t ii = static_cast<std::size_t>(i0 + j);
    const bool frozen = g.dt_fixed[ii] > 0.0 || g.props.ismstr == 1;
    const bool cap = frozen && small[ii] == 0.0;
    if (cap) small[ii] = 1.0;
    bk.frozen[j] = frozen ? 1.0 : 0.0;
    bk.capture[j] = cap ? 1.0 : 0.0;
  }
}

// Projections (xi, eta, h) of node values: of the coordinates, and of the velocity fields.
[[gnu::always_inline]] inline double pxi(const double u[4]) {
  return 0.25 * (((-u[0] + u[1]) + u[2]) - u[3]);
}
[[gnu::always_inline]] inline double peta(const double u[4]) {
  return 0.25 * (((-u[0] - u[1]) + u[2]) + u[3]);
}
[[gnu::always_inline]] inline double ph(const double u[4]) {
  return 0.25 * (((u[0] - u[1]) + u[2]) - u[3]);
}

// Numerators of the x and y derivatives of a field, rows(g) u det J(g) = p0 + xi p1 + eta p2 (+ xi eta p3 for
// the shear; its xi eta terms of the derivatives cancel): p0 / det J(0) is the centre's rate.
struct Lin {
  double p0, p1, p2, p3;
};

// The bilinear map of one element: x,xi = xa + eta xh, x,eta = xb + xi xh, y,xi = ya + eta yh, y,eta = yb +
// xi yh.
struct QuadMap {
  double xa, xb, xh, ya, yb, yh;
  [[gnu::always_inline]] Lin d_x(const double u[4]) const {
    const double ua = pxi(u), ub = peta(u), uh = ph(u);
    return Lin{yb * ua - ya * ub, yh * ua - ya * uh, yb * uh - yh * ub, 0.0};
  }
  [[gnu::always_inline]] Lin d_y(const double u[4]) const {
    const double ua = pxi(u), ub = peta(u), uh = ph(u);
    return Lin{xa * ub - xb * ua, xa * uh - xh * ua, xh * ub - xb * uh, 0.0};
  }
};

// Element j's local coordinates (through the small-strain switch, shell_frame.hpp), velocities and rotation
// rates: the steps of quad_local_state in a form that vectorises (its selects are arithmetic: frozen, capture
// are 0 or 1; with 0 they return the other value exactly).
[[gnu::always_inline]] inline void qeph_local_state(QephBlock& bk, ShellGroup& g, int i0, int j, double lx[4],
                                                    double ly[4], double vx[4], double vy[4], double vz[4],
                                                    double rx[4], double ry[4]) {
  using shell_detail::to_local;
  constexpr std::size_t G = kGroupSize;
  const std::size_t ii = static_cast<std::size_t>(i0 + j);
  double* ref = g.ref_local.data();
  const double e1x = bk.fr.e1[0][j], e1y = bk.fr.e1[1][j], e1z = bk.fr.e1[2][j];
  const double e2x = bk.fr.e2[0][j], e2y = bk.fr.e2[1][j], e2z = bk.fr.e2[2][j];
  const double e3x = bk.fr.e3[0][j], e3y = bk.fr.e3[1][j], e3z = bk.fr.e3[2][j];
  const double fz = bk.frozen[j], cap = bk.capture[j];
  lx[0] = ly[0] = 0.0;
  bk.lx[0][j] = bk.ly[0][j] = 0.0;
#pragma GCC unroll 4
  for (int k = 1; k < 4; ++k) {
    double cx = 0, cy = 0, lz_unused = 0;
    to_local(e1x, e1y, e1z, e2x, e2y, e2z, e3x, e3y, e3z, bk.nb.x[k][j] - bk.nb.x[0][j],
             bk.nb.y[k][j] - bk.nb.y[0][j], bk.nb.z[k][j] - bk.nb.z[0][j], cx, cy, lz_unused);
    shell_detail::small_strain_coordinates(cx, cy, cap, fz, ref[static_cast<std::size_t>(k - 1) * G + ii],
                                           ref[static_cast<std::size_t>(k + 2) * G + ii], lx[k], ly[k]);
    bk.lx[k][j] = lx[k];
    bk.ly[k][j] = ly[k];
  }
#pragma GCC unroll 4
  for (int k = 0; k < 4; ++k) {
    double rz_unused = 0;
    to_local(e1x, e1y, e1z, e2x, e2y, e2z, e3x, e3y, e3z, bk.nb.vx[k][j], bk.nb.vy[k][j], bk.nb.vz[k][j],
             vx[k], vy[k], vz[k]);
    to_local(e1x, e1y, e1z, e2x, e2y, e2z, e3x, e3y, e3z, bk.nb.rx[k][j], bk.nb.ry[k][j], bk.nb.rz[k][j],
             rx[k], ry[k], rz_unused);
  }
}

// Hourglass rates of field q at the Gauss points: the point's rate minus the centre's, from the numerator n
// of the field's derivative (the points (xi, eta) = (-g, -g), (g, -g), (g, g), (-g, g), xi eta = g^2
// (-1)^gp).
[[gnu::always_inline]] inline void qeph_hourglass_rate(QephBlock& bk, int j, int q, const Lin& n, double sign,
                                                       double centre, const double inv[4]) {
  const double gp1 = kGauss * n.p1, gp2 = kGauss * n.p2, h3 = (kGauss * kGauss) * n.p3;
  const double a = n.p0 - gp2, b = n.p0 + gp2;
  const double v[4] = {(a - gp1) + h3, (a + gp1) - h3, (b + gp1) + h3, (b - gp1) - h3};
#pragma GCC unroll 4
  for (int gp = 0; gp < 4; ++gp) bk.dh[gp][q][j] = sign * (v[gp] * inv[gp]) - centre;
}

// Local geometry and velocities, centre increments, hourglass rates and the square roots' arguments.
[[gnu::always_inline]] inline void qeph_geometry_and_increments(QephBlock& bk, const QephConstants& k,
                                                                ShellGroup& g, int i0, int len) {
  shell_detail::SectionBlock<kBlock>& sec = bk.sec;
  const double dt1 = k.s.dt1, tiny30 = k.tiny30;
  const double* thick = g.thick.data();
  RADX_IVDEP
  for (int j = 0; j < len; ++j) {
    double lx[4], ly[4], vx[4], vy[4], vz[4], rx[4], ry[4];
    qeph_local_state(bk, g, i0, j, lx, ly, vx, vy, vz, rx, ry);

    const QuadMap m{pxi(lx), peta(lx), ph(lx), pxi(ly), peta(ly), ph(ly)};
    const double xa = m.xa, xb = m.xb, xh = m.xh, ya = m.ya, yb = m.yb, yh = m.yh;
    bk.xa[j] = xa, bk.xb[j] = xb, bk.xh[j] = xh, bk.ya[j] = ya, bk.yb[j] = yb, bk.yh[j] = yh;
    // det J(g) = j0 + xi j1 + eta j2; A = 4 det J(0).
    const double j0 = xa * yb - ya * xb, j1 = xa * yh - ya * xh, j2 = xh * yb - yh * xb;
    const double det0 = std::max(j0, tiny30);
    const double inv0 = 1.0 / det0;
    bk.inv0[j] = inv0;
    const double area = 4.0 * det0;
    sec.area[j] = area;
    const Lin vx_x = m.d_x(vx), vy_y = m.d_y(vy), vx_y = m.d_y(vx), vy_x = m.d_x(vy);
    const Lin ry_x = m.d_x(ry), rx_y = m.d_y(rx), ry_y = m.d_y(ry), rx_x = m.d_x(rx);
    const Lin vz_x = m.d_x(vz), vz_y = m.d_y(vz);
    // Covariant shear at the edge midpoints A (1 -> 2), C (4 -> 3), B (1 -> 4), D (2 -> 3), beta = (ry,
    // -rx); g_xi = gxi0 + eta dgx, g_eta = geta0 + xi dge.
    const auto edge = [&](int a, int b) {
      const double dx = 0.25 * (lx[b] - lx[a]), dy = 0.25 * (ly[b] - ly[a]);
      return 0.5 * (vz[b] - vz[a]) + dx * (ry[a] + ry[b]) - dy * (rx[a] + rx[b]);
    };
    const double ga = edge(0, 1), gc = edge(3, 2), gb = edge(0, 3), gd = edge(1, 2);
    const double gxi0 = 0.5 * ga + 0.5 * gc, geta0 = 0.5 * gb + 0.5 * gd;
    const double dgx = 0.5 * (gc - ga), dge = 0.5 * (gd - gb);
    const Lin gzx{yb * gxi0 - ya * geta0, yh * gxi0 - ya * dge, yb * dgx - yh * geta0, yh * (dgx - dge)};
    const Lin gyz{xa * geta0 - xb * gxi0, xa * dge - xh * gxi0, xh * geta0 - xb * dgx, xh * (dge - dgx)};

    // Centre rates and increments, with the second-order membrane correction of 1.3 (quad_second_order).
    const double exx0 = vx_x.p0 * inv0, eyy0 = vy_y.p0 * inv0, kxx0 = ry_x.p0 * inv0,
                 kyy0 = -(rx_y.p0 * inv0);
    const double gyz0 = gyz.p0 * inv0, gzx0 = gzx.p0 * inv0;
    const double wx = vz_x.p0 * inv0, wy = vz_y.p0 * inv0;
    const double dem0 = (exx0 - dt1 * wx * wx) * dt1, dem1 = (eyy0 - dt1 * wy * wy) * dt1;
    const double dem2 = (vx_y.p0 * inv0 + vy_x.p0 * inv0) * dt1;
    sec.dem[0][j] = dem0, sec.dem[1][j] = dem1, sec.dem[2][j] = dem2;
    sec.dem[3][j] = gyz0 * dt1, sec.dem[4][j] = gzx0 * dt1;
    const double dk0 = kxx0 * dt1, dk1 = kyy0 * dt1, dk2 = (ry_y.p0 * inv0 - rx_x.p0 * inv0) * dt1;
    sec.dk[0][j] = dk0, sec.dk[1][j] = dk1, sec.dk[2][j] = dk2;

    // Hourglass rates at the Gauss points: the point's rates minus the centre's (without the second-order
    // term), for exx eyy kxx kyy gyz gzx.
    double inv[4];
#pragma GCC unroll 4
    for (int gp = 0; gp < 4; ++gp) {
      const double det = std::max(j0 + kXiGauss[gp] * j1 + kEtaGauss[gp] * j2, tiny30);
      bk.detg[gp][j] = det;
      inv[gp] = 1.0 / det;
    }
    qeph_hourglass_rate(bk, j, 0, vx_x, 1.0, exx0, inv);
    qeph_hourglass_rate(bk, j, 1, vy_y, 1.0, eyy0, inv);
    qeph_hourglass_rate(bk, j, 2, ry_x, 1.0, kxx0, inv);
    qeph_hourglass_rate(bk, j, 3, rx_y, -1.0, kyy0, inv);
    qeph_hourglass_rate(bk, j, 4, gyz, 1.0, gyz0, inv);
    qeph_hourglass_rate(bk, j, 5, gzx, 1.0, gzx0, inv);

    // Square-root arguments: equivalent strain rate (1.3, with the current thickness), the step's |g1|,
    // |g2| (qeph_step_axes_sq), sqrt(A) of the membrane damping.
    bk.root[0][j] = shell_detail::equivalent_rate_arg(dem0, dem1, dem2, dk0, dk1, dk2, thick[i0 + j]);
    qeph_step_axes_sq(lx, ly, bk.root[1][j], bk.root[2][j]);
    bk.root[3][j] = area;
  }
}

// Filtered strain rate (6.1) and its rate term; the step's last root argument.
[[gnu::always_inline]] inline void qeph_filtered_rate(QephBlock& bk, const QephConstants& k,
                                                      const MaterialParams& mat, ShellGroup& g, int i0,
                                                      int len) {
  shell_detail::SectionBlock<kBlock>& sec = bk.sec;
  const double dt1 = k.s.dt1, alpha = k.s.alpha;
  double* rates = g.rate.data();
  std::int64_t any_rate = 0;
  RADX_IVDEP
  for (int j = 0; j < len; ++j) {
    const std::size_t ii = static_cast<std::size_t>(i0 + j);
    const double old = rates[ii];
    const double eq = dt1 > 0 ? bk.root[0][j] / dt1 : 0.0;
    const double rate = alpha * eq + (1.0 - alpha) * old;
    rates[ii] = sec.off[j] > 0.0 ? rate : old;
    bk.rate[j] = rate;
    sec.rate[j] = rate;  // the /FAIL/JOHNSON D4 term
    sec.rfac[j] = 1.0;
    const std::int64_t r = rate <= k.rate_one ? 0 : 1;  // R = 1 at or below rate0 (and for c = 0)
    bk.flag[j] = r;
    any_rate |= r;
  }
  RADX_IVDEP
  for (int j = 0; j < len; ++j) {
    const double lx[4] = {bk.lx[0][j], bk.lx[1][j], bk.lx[2][j], bk.lx[3][j]};
    const double ly[4] = {bk.ly[0][j], bk.ly[1][j], bk.ly[2][j], bk.ly[3][j]};
    bk.step_root[j] = qeph_step_arg(lx, ly, sec.area[j], bk.root[1][j], bk.root[2][j], k.step_k);
  }
  sqrt_in_place(bk.step_root, kBlock);
  if (any_rate != 0)
    for (int j = 0; j < len; ++j)
      if (bk.flag[j] != 0) sec.rfac[j] = jc_rate_factor(mat, bk.rate[j]);
}

// The points' in-plane stress and plastic strain before the update (for the tangent factor).
[[gnu::always_inline]] inline void qeph_points_before(QephBlock& bk, const shell_detail::ThicknessRule& rule,
                                                      const ShellGroup& g, int i0, int len) {
  constexpr std::size_t G = kGroupSize;
  for (int p = 0; p < rule.n; ++p) {
    for (int q = 0; q < 3; ++q) {
      const double* sp = g.sig.data() + shell_detail::sig_index(p, q, i0);
      for (int j = 0; j < len; ++j) bk.sig_before[p][q][j] = sp[j];
    }
    const double* ep = g.eps_p.data() + static_cast<std::size_t>(p) * G + static_cast<std::size_t>(i0);
    for (int j = 0; j < len; ++j) bk.eps_before[p][j] = ep[j];
  }
}

// Tangent factors of the membrane and bending stabilisation (ZCFAC) [inferred measure, see above]: the
// elastic ones, unless a point of the element yielded in this cycle.
[[gnu::always_inline]] inline void qeph_tangent_factors(QephBlock& bk, const QephConstants& k,
                                                        const MaterialParams& mat, const ShellGroup& g,
                                                        int i0, int len) {
  using shell_detail::sig_index;
  constexpr std::size_t G = kGroupSize;
  const shell_detail::SectionBlock<kBlock>& sec = bk.sec;
  const shell_detail::ThicknessRule& rule = k.s.rule;
  const double a11 = k.s.a11, a12 = k.a12;
  std::int64_t any_yield = 0;
  for (int j = 0; j < len; ++j) {
    bk.fm[j] = k.fm_elastic, bk.fb[j] = k.fb_elastic;
    bk.flag[j] = 0;
  }
  for (int p = 0; p < rule.n; ++p) {
    const double* ep = g.eps_p.data() + static_cast<std::size_t>(p) * G + static_cast<std::size_t>(i0);
    RADX_IVDEP
    for (int j = 0; j < len; ++j) {
      const std::int64_t y = ep[j] - bk.eps_before[p][j] > 0 ? 1 : 0;
      bk.flag[j] |= y;
      any_yield |= y;
    }
  }
  if (any_yield == 0) return;
  for (int j = 0; j < len; ++j) {
    if (bk.flag[j] == 0 || sec.off[j] <= 0.0) continue;
    const double t = sec.t[j];
    double sum_m = 0, sum_b = 0;
    for (int p = 0; p < rule.n; ++p) {
      const double z = rule.zeta[p] * t;
      const double d0 = sec.dem[0][j] + z * sec.dk[0][j], d1 = sec.dem[1][j] + z * sec.dk[1][j],
                   d2 = sec.dem[2][j] + z * sec.dk[2][j];
      double fp = 1.0;
      const double deps =
          g.eps_p[static_cast<std::size_t>(p) * G + static_cast<std::size_t>(i0 + j)] - bk.eps_before[p][j];
      if (deps > 0) {
        const double ds0 = g.sig[sig_index(p, 0, i0 + j)] - bk.sig_before[p][0][j];
        const double ds1 = g.sig[sig_index(p, 1, i0 + j)] - bk.sig_before[p][1][j];
        const double ds2 = g.sig[sig_index(p, 2, i0 + j)] - bk.sig_before[p][2][j];
        const double elastic = a11 * (d0 * d0 + d1 * d1) + 2.0 * a12 * d0 * d1 + mat.shear * d2 * d2;
        fp = elastic > 0 ? std::clamp((ds0 * d0 + ds1 * d1 + ds2 * d2) / elastic, 0.0, 1.0) : 1.0;
      }
      sum_m += rule.w[p] * fp;
      sum_b += rule.w[p] * rule.zeta[p] * rule.zeta[p] * fp;
    }
    bk.fm[j] = sum_m;
    bk.fb[j] = k.bend_weight_sum > 0 ? sum_b / k.bend_weight_sum : sum_m;
  }
}

// What the forces need of the stabilisation resultants at the four Gauss points, per component q: their
// moments over the points mo[q] (sum, xi-, eta- and xi eta-weighted sums) and the centre's share
// sum_g det J(g) / det J(0) s(g). Per component: inc = C_h dh dt1, S_v = Dn (L/c) C_h dh, the energy term
// (S_old + inc/2 + S_v) dh, the point's resultant OFF (S_old + inc + S_v), with the factors of dh taken once
// per element. Updates the stored resultants and returns the hourglass energy increment.
[[gnu::always_inline]] inline double qeph_stabilisation(const QephBlock& bk, const QephConstants& k,
                                                        double* hg, std::size_t ii, int j, double off,
                                                        double malive, double mo[kHgRows][4],
                                                        double share[kHgRows]) {
  constexpr std::size_t G = kGroupSize;
  const double dt1 = k.s.dt1, a11 = k.s.a11, gs = k.s.gs, bend = k.bend;
  const double t = bk.sec.t[j], area = bk.sec.area[j];
  const double fm = bk.fm[j], fb = bk.fb[j];
  const double ch[kHgRows] = {
      a11 * t * fm, a11 * t * fm, a11 * bend * t * t * t * fb, a11 * bend * t * t * t * fb,
      gs * t * fm,  gs * t * fm};
  const double l = area / bk.step_root[j];
  const double damp = k.dn * l / k.s.c;  // Dn times the element's time scale L/c
  const double inv0 = bk.inv0[j];
  double w[4], wr[4];
#pragma GCC unroll 4
  for (int gp = 0; gp < 4; ++gp) w[gp] = bk.detg[gp][j], wr[gp] = w[gp] * inv0;
  double k_half[kHgRows], k_full[kHgRows], k_store[kHgRows];
#pragma GCC unroll 6
  for (int q = 0; q < kHgRows; ++q) {
    const double cd = ch[q] * dt1, cv = damp * ch[q];
    k_half[q] = 0.5 * cd + cv, k_full[q] = cd + cv, k_store[q] = malive * cd;
  }
  double e_point[4] = {0.0, 0.0, 0.0, 0.0};
#pragma GCC unroll 6
  for (int q = 0; q < kHgRows; ++q) {
    double sq[4];
#pragma GCC unroll 4
    for (int gp = 0; gp < 4; ++gp) {
      double& stored = hg[static_cast<std::size_t>(gp * kHgRows + q) * G + ii];
      const double h = bk.dh[gp][q][j];
      const double s0 = stored;
      e_point[gp] += (s0 + k_half[q] * h) * h;
      stored = s0 + k_store[q] * h;
      sq[gp] = off * (s0 + k_full[q] * h);
    }
    mo[q][0] = (sq[0] + sq[1]) + (sq[2] + sq[3]);
    mo[q][1] = kGauss * ((sq[1] - sq[0]) + (sq[2] - sq[3]));
    mo[q][2] = kGauss * ((sq[2] - sq[1]) + (sq[3] - sq[0]));
    mo[q][3] = (kGauss * kGauss) * ((sq[0] - sq[1]) + (sq[2] - sq[3]));
    share[q] = (wr[0] * sq[0] + wr[1] * sq[1]) + (wr[2] * sq[2] + wr[3] * sq[3]);
  }
  return off * dt1 * ((w[0] * e_point[0] + w[1] * e_point[1]) + (w[2] * e_point[2] + w[3] * e_point[3]));
}

// Local nodal forces of element j into bk.fl: S_xi, S_eta, S_h of fx, fy, mx, my and the four edge values of
// the shear, from the points (their sums over the points through the moments: x,xi = xa + eta xh ...), then
// from the centre with R = 4 n0 - share.
[[gnu::always_inline]] inline void qeph_local_forces(QephBlock& bk, int j, double off, const double fv[3],
                                                     const double mo[kHgRows][4],
                                                     const double share[kHgRows]) {
  const shell_detail::SectionBlock<kBlock>& sec = bk.sec;
  const double t = sec.t[j];
  const double xa = bk.xa[j], xb = bk.xb[j], xh = bk.xh[j], ya = bk.ya[j], yb = bk.yb[j], yh = bk.yh[j];
  const auto flux_x = [&](const double m[4], double sv[3]) {  // flux (s, 0)
    sv[0] = yb * m[0] + yh * m[1], sv[1] = -(ya * m[0] + yh * m[2]), sv[2] = yb * m[2] - ya * m[1];
  };
  const auto flux_y = [&](const double m[4], double sv[3]) {  // flux (0, s)
    sv[0] = -(xb * m[0] + xh * m[1]), sv[1] = xa * m[0] + xh * m[2], sv[2] = xa * m[1] - xb * m[2];
  };
  double sfx[3], sfy[3], smx[3], smy[3];  // xi, eta, h
  flux_x(mo[0], sfx);
  flux_y(mo[1], sfy);
  flux_x(mo[2], smy);
  flux_y(mo[3], smx);
  for (double& v : smx) v = -v;  // flux (0, -Myy)
  const double* mqy = mo[4];
  const double* mqx = mo[5];
  const double txs = (yb * mqx[0] + yh * mqx[1]) - (xb * mqy[0] + xh * mqy[1]);  // sum_g T_xi
  const double txe = (yb * mqx[2] + yh * mqx[3]) - (xb * mqy[2] + xh * mqy[3]);  // sum_g eta T_xi
  const double tes = (xa * mqy[0] + xh * mqy[2]) - (ya * mqx[0] + yh * mqx[2]);  // sum_g T_eta
  const double tex = (xa * mqy[1] + xh * mqy[3]) - (ya * mqx[1] + yh * mqx[3]);  // sum_g xi T_eta
  double ea = 0.5 * (txs - txe), ec = 0.5 * (txs + txe), eb = 0.5 * (tes - tex), ed = 0.5 * (tes + tex);
  // The centre (xi = eta = 0: no h part).
  const double ot = off * t, ot2 = off * t * t;
  const double rnxx = 4.0 * (ot * (sec.for_new[0][j] + fv[0])) - share[0];
  const double rnyy = 4.0 * (ot * (sec.for_new[1][j] + fv[1])) - share[1];
  const double rnxy = 4.0 * (ot * (sec.for_new[2][j] + fv[2]));
  const double rqy = 4.0 * (ot * sec.for_new[3][j]) - share[4],
               rqx = 4.0 * (ot * sec.for_new[4][j]) - share[5];
  const double rmxx = 4.0 * (ot2 * sec.mom_new[0][j]) - share[2];
  const double rmyy = 4.0 * (ot2 * sec.mom_new[1][j]) - share[3];
  const double rmxy = 4.0 * (ot2 * sec.mom_new[2][j]);
  sfx[0] += rnxx * yb - rnxy * xb, sfx[1] += rnxy * xa - rnxx * ya;
  sfy[0] += rnxy * yb - rnyy * xb, sfy[1] += rnyy * xa - rnxy * ya;
  smy[0] += rmxx * yb - rmxy * xb, smy[1] += rmxy * xa - rmxx * ya;
  smx[0] += rmyy * xb - rmxy * yb, smx[1] += rmxy * ya - rmyy * xa;
  const double txi0 = rqx * yb - rqy * xb, teta0 = rqy * xa - rqx * ya;
  ea += 0.5 * txi0, ec += 0.5 * txi0, eb += 0.5 * teta0, ed += 0.5 * teta0;

  const auto node = [](const double sv[3], double xi_k, double eta_k, double h_k) {
    return 0.25 * (xi_k * sv[0] + eta_k * sv[1] + h_k * sv[2]);
  };
  const auto edx = [&](int a, int b) { return 0.25 * (bk.lx[b][j] - bk.lx[a][j]); };
  const auto edy = [&](int a, int b) { return 0.25 * (bk.ly[b][j] - bk.ly[a][j]); };
  const double dxa = edx(0, 1), dya = edy(0, 1), dxc = edx(3, 2), dyc = edy(3, 2);
  const double dxb = edx(0, 3), dyb = edy(0, 3), dxd = edx(1, 2), dyd = edy(1, 2);
  // Each edge (a -> b) gives -e/2 and e/2 to w_a, w_b, and (dx, dy) e to beta_a and beta_b.
  const double fz[4] = {-0.5 * ea - 0.5 * eb, 0.5 * ea - 0.5 * ed, 0.5 * ec + 0.5 * ed, 0.5 * eb - 0.5 * ec};
  const double bx[4] = {dxa * ea + dxb * eb, dxa * ea + dxd * ed, dxc * ec + dxd * ed, dxc * ec + dxb * eb};
  const double by[4] = {dya * ea + dyb * eb, dya * ea + dyd * ed, dyc * ec + dyd * ed, dyc * ec + dyb * eb};
#pragma GCC unroll 4
  for (int n = 0; n < 4; ++n) {
    const double hk = kXiNode[n] * kEtaNode[n];
    bk.fl[0][n][j] = node(sfx, kXiNode[n], kEtaNode[n], hk);
    bk.fl[1][n][j] = node(sfy, kXiNode[n], kEtaNode[n], hk);
    bk.fl[2][n][j] = fz[n];
    bk.fl[3][n][j] = node(smx, kXiNode[n], kEtaNode[n], hk) - by[n];  // beta_y = -rx
    bk.fl[4][n][j] = node(smy, kXiNode[n], kEtaNode[n], hk) + bx[n];  // beta_x = ry
  }
}

// Failure, thickness, energy (1.5), centre forces (1.6), stabilisation: the local nodal forces. Returns
// whether an element of the block is deleted (at entry or in this cycle: bk.flag).
[[gnu::always_inline]] inline std::int64_t qeph_energy_and_forces(QephBlock& bk, const QephConstants& k,
                                                                  ShellGroup& g, int i0, int len) {
  const shell_detail::SectionBlock<kBlock>& sec = bk.sec;
  const double one = k.one, zero = k.zero;
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
    const double off = bk.off[j];
    const double t = sec.t[j], area = sec.area[j];
    const double dem[5] = {sec.dem[0][j], sec.dem[1][j], sec.dem[2][j], sec.dem[3][j], sec.dem[4][j]};
    const double dk[3] = {sec.dk[0][j], sec.dk[1][j], sec.dk[2][j]};
    offs[ii] = live ? off : off_start;
    const double mlive = live ? one : zero;
    const double wp0 = w_plastic[ii], th0 = thick[ii];
    w_plastic[ii] = wp0 + mlive * sec.w_plastic[j];
    thick[ii] = th0 + mlive * (sec.dthick[j] * off);

    // Membrane damping (1.4; membrane_damping with its sqrt(A) taken above; fv = 0 when visc0 = 0).
    const double visc = k.s.visc0 * bk.root[3][j];
    const double fv[3] = {visc * (dem[0] + 0.5 * dem[1]), visc * (dem[1] + 0.5 * dem[0]),
                          visc * dem[2] / 3.0};
    // Internal energy (1.5).
    const double de_int = shell_energy_increment(area, t, off_start, off, sec.for_old, sec.for_new,
                                                 sec.mom_old, sec.mom_new, j, dem, dk, fv);
    const double ei = e_int[ii];
    e_int[ii] = ei + mlive * de_int;

    const bool alive = live & (off > 0.0);  // not deleted at entry nor in this cycle
    const std::int64_t gone = alive ? 0 : 1;
    bk.flag[j] = gone;
    any_gone |= gone;
    const double malive = alive ? one : zero;

    double mo[kHgRows][4], share[kHgRows];
    const double de_hg = qeph_stabilisation(bk, k, hg, ii, j, off, malive, mo, share);
    const double eh = e_hg[ii];
    e_hg[ii] = eh + malive * de_hg;
    qeph_local_forces(bk, j, off, fv, mo, share);
  }
  return any_gone;
}

}  // namespace

// The kernel: the list of its stages over each block of the group.
void shell_qeph_forces(ShellGroup& g, const NodeState& nodes, const MaterialParams& mat,
                       const CycleInfo& cyc) {
  using namespace shell_detail;
  ensure_resultant_storage(g);
  const QephConstants k = qeph_constants(g.props, mat, cyc.dt1);

  QephBlock bk;
  SectionBlock<kBlock>& sec = bk.sec;
  sec.dt1 = k.s.dt1;  // law 27's rate term
  for (int i0 = 0; i0 < g.count; i0 += kBlock) {
    const int len = std::min(kBlock, g.count - i0);
    open_quad_block(g, nodes, i0, len, bk.nb, bk.fr);
    qeph_small_strain_flags(bk, g, i0, len);
    open_thickness_block(FirstUseThickness::EveryElement, k.s.update_thick, g, i0, len, sec);
    qeph_geometry_and_increments(bk, k, g, i0, len);
    sqrt_in_place(bk.root[0], 4 * kBlock);
    qeph_filtered_rate(bk, k, mat, g, i0, len);
    qeph_points_before(bk, k.s.rule, g, i0, len);
    section_update_block(g, i0, len, mat, k.s.rule, k.s.gs, sec);
    for (int j = 0; j < len; ++j)
      bk.off[j] = next_off(k.s.fail_limit, sec.off[j], sec.eps_p_max[j], sec.fail_now[j]);
    qeph_tangent_factors(bk, k, mat, g, i0, len);
    const std::int64_t any_gone = qeph_energy_and_forces(bk, k, g, i0, len);
    // Rotate to global axes and store minus the internal force; step (1.10) and nodal stiffness (4.5).
    double* dts = g.dt.data();
    double* k_nodal = g.k_nodal.data();
    store_quad_block(bk.fr, bk.fl, g, i0, len, [&](int j, std::size_t ii) {
      const double area = sec.area[j], t = sec.t[j];
      const double l = area / bk.step_root[j];
      dts[ii] = l * k.s.phi / k.s.c;
      k_nodal[ii] = 0.5 * area * t * k.s.a11 / (l * l);
    });
    clear_deleted_block(g, i0, len, bk.flag, any_gone);
  }
}

}  // namespace radx::solver
