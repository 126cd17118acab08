// Four-node shell QEPH (Ishell 24): one integration point in the plane, with physical hourglass
// stabilisation instead of Ishell 1's viscous and elastic hourglass. Sources: shared/spec/elements.md 1.10,
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
// Layout: the group runs in blocks of kBlock elements; the gather and frame are the shared block passes
// (element_gather.hpp, shell_frame.hpp), the section is the shared vectorised through-thickness update, the
// rows, stabilisation and forces run element by element on the block's scratch (no allocation).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "solver/element_gather.hpp"
#include "solver/element_groups.hpp"
#include "solver/shell_frame.hpp"
#include "solver/shell_quad_mindlin.hpp"
#include "solver/shell_section.hpp"

namespace radx::solver {

namespace {

constexpr int kBlock = 64;  // elements per block (see shell_bt4.cpp)
constexpr int kHgRows = 6;  // stabilisation resultants per Gauss point: nxx nyy mxx myy qyz qzx

struct QephBlock {
  NodeBlock<4, kBlock> nb;
  shell_detail::FrameBlock<kBlock> fr;
  double vx[4][kBlock], vy[4][kBlock], vz[4][kBlock], rx[4][kBlock], ry[4][kBlock];  // local
  double lx[4][kBlock], ly[4][kBlock];                                               // local coordinates
  double sig_before[shell_detail::kMaxPoints][3][kBlock];  // in-plane stress of the points before the update
  double eps_before[shell_detail::kMaxPoints][kBlock];
  shell_detail::SectionBlock<kBlock> sec;
};

}  // namespace

void shell_qeph_forces(ShellGroup& g, const NodeState& nodes, const MaterialParams& mat,
                       const CycleInfo& cyc) {
  using namespace shell_detail;
  constexpr std::size_t G = kGroupSize;
  const ShellProps& pr = g.props;
  const double dt1 = cyc.dt1;
  const ThicknessRule rule = thickness_rule(std::max(pr.n_points, 0));
  ensure_resultant_storage(g);

  const double young = mat.young, nu = mat.nu, rho = mat.rho0;
  const double c = mat.c_shell > 0 ? mat.c_shell : std::sqrt(young / rho);
  const double a11 = mat.a11 > 0 ? mat.a11 : young / (1.0 - nu * nu);
  const double a12 = nu * a11;
  const double shf = pr.n_points == 1 ? 0.0 : pr.ashear;
  const double gs = shf * mat.shear;
  const double bend = pr.n_points == 1 ? 0.0 : 1.0 / 12.0;  // no bending stiffness with one point
  const double dn = pr.dn;
  const double phi = std::sqrt(1.0 + dn * dn) - dn;
  const double visc0 = (pr.dm > 0 && dt1 > 0) ? 1.414 * pr.dm * rho * c / dt1 : 0.0;
  const double alpha = rate_filter_alpha(mat, dt1);
  const double fail_limit = failure_limit(mat);
  const bool update_thick = pr.ithick == 1;
  // Bending weights of the tangent factor: sum w_p zeta_p^2 (0 for N <= 1).
  double bend_weight_sum = 0;
  for (int p = 0; p < rule.n; ++p) bend_weight_sum += rule.w[p] * rule.zeta[p] * rule.zeta[p];

  double* nf = g.nodal_force.data();
  double* hg = g.hg.data();

  QephBlock bk;
  SectionBlock<kBlock>& sec = bk.sec;
  sec.dt1 = dt1;  // law 27's rate term
  for (int i0 = 0; i0 < g.count; i0 += kBlock) {
    const int len = std::min(kBlock, g.count - i0);
    gather_block<true>(g.conn.data(), G, static_cast<std::size_t>(i0), static_cast<std::size_t>(len), nodes,
                       bk.nb);
    quad_frame_block(bk.nb, len, bk.fr);

    // Local geometry and velocities, centre rows, increments and the element rate.
    for (int j = 0; j < len; ++j) {
      const std::size_t ii = static_cast<std::size_t>(i0 + j);
      const double off_start = g.off[ii];
      sec.off[j] = off_start;
      if (g.thick[ii] <= 0.0) g.thick[ii] = g.t0[ii];
      sec.t[j] = update_thick ? g.thick[ii] : g.t0[ii];
      // Local geometry (small strain: the first cycle's), velocities and rotation rates (shell_frame.hpp).
      double lx[4], ly[4], vx[4], vy[4], vz[4], rx[4], ry[4];
      quad_local_state(bk, j, g, ii, g.dt_fixed[ii] > 0.0 || pr.ismstr == 1, lx, ly, vx, vy, vz, rx, ry);
      const QuadRows r0 = quad_rows(lx, ly, 0.0, 0.0);
      sec.area[j] = 4.0 * r0.detj;
      double e[5], kap[3];
      quad_rates(r0, vx, vy, vz, rx, ry, e, kap);
      quad_second_order(r0, vz, dt1, e);
      for (int q = 0; q < 5; ++q) sec.dem[q][j] = e[q] * dt1;
      for (int q = 0; q < 3; ++q) sec.dk[q][j] = kap[q] * dt1;
      const double eq =
          dt1 > 0 ? std::sqrt(equivalent_rate_arg(sec.dem[0][j], sec.dem[1][j], sec.dem[2][j], sec.dk[0][j],
                                                  sec.dk[1][j], sec.dk[2][j], g.thick[ii])) /
                        dt1
                  : 0.0;
      const double rate = alpha * eq + (1.0 - alpha) * g.rate[ii];
      if (off_start > 0.0) g.rate[ii] = rate;
      sec.rfac[j] = jc_rate_factor(mat, rate);
      sec.rate[j] = rate;  // the /FAIL/JOHNSON D4 term
    }

    // The points' in-plane stress and plastic strain before the update (for the tangent factor).
    for (int p = 0; p < rule.n; ++p)
      for (int j = 0; j < len; ++j) {
        for (int q = 0; q < 3; ++q) bk.sig_before[p][q][j] = g.sig[sig_index(p, q, i0 + j)];
        bk.eps_before[p][j] = g.eps_p[static_cast<std::size_t>(p) * G + static_cast<std::size_t>(i0 + j)];
      }
    section_update_block(g, i0, len, mat, rule, gs, sec);

    // Failure, energy, centre forces, stabilisation, step.
    for (int j = 0; j < len; ++j) {
      const std::size_t ii = static_cast<std::size_t>(i0 + j);
      const double off_start = sec.off[j];
      if (off_start <= 0.0) {
        clear_shell_element(g, nf, ii, 24);
        continue;
      }
      const double t = sec.t[j], area = sec.area[j];
      const double dem[5] = {sec.dem[0][j], sec.dem[1][j], sec.dem[2][j], sec.dem[3][j], sec.dem[4][j]};
      const double dk[3] = {sec.dk[0][j], sec.dk[1][j], sec.dk[2][j]};
      const double off = next_off(fail_limit, off_start, sec.eps_p_max[j], sec.fail_now[j]);
      g.off[ii] = off;
      g.w_plastic[ii] += sec.w_plastic[j];
      g.thick[ii] += sec.dthick[j] * off;

      // Membrane damping (1.4).
      double fv[3];
      membrane_damping(visc0, area, dem, fv);
      // Internal energy (1.5).
      g.e_int[ii] += shell_energy_increment(area, t, off_start, off, sec.for_old, sec.for_new, sec.mom_old,
                                            sec.mom_new, j, dem, dk, fv);
      if (off <= 0.0) {
        clear_shell_element(g, nf, ii, 24);
        continue;
      }

      // Tangent factors of the membrane and bending stabilisation (ZCFAC) [inferred measure, see above].
      double fm = 1.0, fb = 1.0;
      if (rule.n > 0) {
        double sum_m = 0, sum_b = 0;
        for (int p = 0; p < rule.n; ++p) {
          const double z = rule.zeta[p] * t;
          const double d0 = dem[0] + z * dk[0], d1 = dem[1] + z * dk[1], d2 = dem[2] + z * dk[2];
          double fp = 1.0;
          const double deps = g.eps_p[static_cast<std::size_t>(p) * G + ii] - bk.eps_before[p][j];
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
        fm = sum_m;
        fb = bend_weight_sum > 0 ? sum_b / bend_weight_sum : fm;
      }

      double lx[4], ly[4], vx[4], vy[4], vz[4], rx[4], ry[4];
      for (int k = 0; k < 4; ++k) {
        lx[k] = bk.lx[k][j], ly[k] = bk.ly[k][j];
        vx[k] = bk.vx[k][j], vy[k] = bk.vy[k][j], vz[k] = bk.vz[k][j], rx[k] = bk.rx[k][j],
        ry[k] = bk.ry[k][j];
      }
      const QuadRows r0 = quad_rows(lx, ly, 0.0, 0.0);
      const double l = qeph_step_length(lx, ly, area);

      // Centre forces (1.6 with the rows of shell_quad_mindlin.hpp).
      double fx[4] = {}, fy[4] = {}, fz[4] = {}, mx[4] = {}, my[4] = {};
      const double ot = off * t, ot2 = off * t * t;
      const double n0[5] = {ot * (sec.for_new[0][j] + fv[0]), ot * (sec.for_new[1][j] + fv[1]),
                            ot * (sec.for_new[2][j] + fv[2]), ot * sec.for_new[3][j], ot * sec.for_new[4][j]};
      const double m0[3] = {ot2 * sec.mom_new[0][j], ot2 * sec.mom_new[1][j], ot2 * sec.mom_new[2][j]};
      quad_add_forces(r0, area, n0, m0, fx, fy, fz, mx, my);

      // Stabilisation at the four Gauss points.
      const double ch[kHgRows] = {
          a11 * t * fm, a11 * t * fm, a11 * bend * t * t * t * fb, a11 * bend * t * t * t * fb,
          gs * t * fm,  gs * t * fm};
      const double damp = dn * l / c;  // Dn times the element's time scale L/c
      double de_hg = 0;
      for (int gp = 0; gp < 4; ++gp) {
        QuadRows d = quad_rows(lx, ly, kXiGauss[gp], kEtaGauss[gp]);
        const double w = d.detj;
        for (int k = 0; k < 4; ++k) {
          d.nx[k] -= r0.nx[k], d.ny[k] -= r0.ny[k];
          d.sxw[k] -= r0.sxw[k], d.sxr[k] -= r0.sxr[k], d.sxs[k] -= r0.sxs[k];
          d.syw[k] -= r0.syw[k], d.syr[k] -= r0.syr[k], d.sys[k] -= r0.sys[k];
        }
        double eh[5], kh[3];
        quad_rates(d, vx, vy, vz, rx, ry, eh, kh);
        const double hrate[kHgRows] = {eh[0], eh[1], kh[0], kh[1], eh[3], eh[4]};
        double s[kHgRows];
        for (int q = 0; q < kHgRows; ++q) {
          double& stored = hg[static_cast<std::size_t>(gp * kHgRows + q) * G + ii];
          const double inc = ch[q] * hrate[q] * dt1;
          const double sv = damp * ch[q] * hrate[q];
          de_hg += w * off * (stored + 0.5 * inc + sv) * hrate[q] * dt1;
          stored += inc;
          s[q] = off * (stored + sv);
        }
        const double nh[5] = {s[0], s[1], 0.0, s[4], s[5]};
        const double mh[3] = {s[2], s[3], 0.0};
        quad_add_forces(d, w, nh, mh, fx, fy, fz, mx, my);
      }
      g.e_hg[ii] += de_hg;

      const double e1x = bk.fr.e1[0][j], e1y = bk.fr.e1[1][j], e1z = bk.fr.e1[2][j];
      const double e2x = bk.fr.e2[0][j], e2y = bk.fr.e2[1][j], e2z = bk.fr.e2[2][j];
      const double e3x = bk.fr.e3[0][j], e3y = bk.fr.e3[1][j], e3z = bk.fr.e3[2][j];
      for (int k = 0; k < 4; ++k)
        store_local_forces(nf, G, static_cast<std::size_t>(k), ii, e1x, e1y, e1z, e2x, e2y, e2z, e3x, e3y,
                           e3z, fx[k], fy[k], fz[k], mx[k], my[k]);

      // Step (1.10) and nodal stiffness (4.5).
      g.dt[ii] = l * phi / c;
      g.k_nodal[ii] = 0.5 * area * t * a11 / (l * l);
    }
  }
}

}  // namespace radx::solver
