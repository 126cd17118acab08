// Eight-node fully integrated bricks: Isolid 14 (HA8), 17 (H8C), 18 (H8D, run as 17 with automatic flags) and
// 12 (the older S8). One kernel: the four differ only in the flags the engine gives the group (frame,
// pressure treatment, strain operator, time-step length), see BrickGroup and resolve_full_brick in
// explicit_engine.cpp.
//
// Sources, OpenRadioss (read, not copied): engine/source/elements/forint.F (Isolid 14 -> S8ZFORC3, 17 and
// 18 -> S8EFORC3 in explicit, 12 -> S8FORC3 when the group has 8 points), solide8/s8deri3.F, s8defo3.F,
// s8fint3.F, basisf.F (Gauss points +-1/sqrt(3), per-point derivatives from the inverse Jacobian, per-point
// forces weighted by the point volume), solide8/s8lagr3.F (density per element), solide8z/s8zdefo3.F
// (constant-pressure option, spin set to zero in the co-rotational frame), solide/srepiso3.F and sortho3.F
// (the co-rotational frame from the three centre directions, orthonormalised), starter hm_read_prop14.F and
// sgrtails.F (defaults). Section numbers refer to docs/theory/elements.md.
//
// Nodes and natural coordinates as hex8_fb.cpp: (xi, eta, zeta)_k = (-1,-1,-1), (1,-1,-1), (1,1,-1),
// (-1,1,-1), then the same with zeta = +1. Points p = 0..7 at (xi, eta, zeta)_p = a (xi, eta, zeta)_k,
// a = 1/sqrt(3), weight 1 each. All on x^n with v^{n-1/2}.
//
//   frame (corot): g_xi = dx/dxi(0), g_eta, g_zeta at the centre; Q = [g/|g|] made orthogonal by the
//     iteration Q <- (Q + Q^-T)/2 (the rotation of its polar decomposition, symmetric in the three
//     directions), then e1 = q1, e3 = e1 x q2 / |.|, e2 = e3 x e1; R = rows e1 e2 e3. S8E (17, 18) as its
//     sortho3.F: three passes of q_c <- unit(q_c+1 x q_c+2 + q_c), then Gram-Schmidt led by eta: e_eta = q2,
//     e_xi = e_eta x q3 / |.|, e_zeta = e_xi x e_eta (S8E's local x, y, z are the eta, zeta, xi directions;
//     R keeps the rows in xi, eta, zeta order, which changes no result of an isotropic law). x_loc = R x,
//     v_loc = R v. Without corot (Iframe 1 for 12 and 17) R = I and the stress gets the Jaumann rotation
//     of 3.2 per point.
//   per point: J_p = sum_k x_k (x) dN_k/dxi(p), V_p = det J_p, b_pk = J_p^-T dN_k/dxi(p),
//     L_p = sum_k v_k (x) b_pk, D_p = sym L_p (engineering shears), V = sum_p V_p (exact trilinear volume)
//   strain operator per formulation (in the local frame; see asqbi_operator and select_operator below):
//     12, 17 and 18 with Icpre 1: plain, D_p = sym L_p.
//     14 (S8Z: solide8z/s8zderic3.F, s8zderipr3.F, s8zderim3.F, s8zdefo3.F, s8zfint3.F): the gradient split
//       b_pk = bc_k + sum_m gamma_mk grad h_m(p) (exact for the trilinear brick); shear drops the bending
//       mode of its plane and the warping mode; with Icpre != 1 the normal strains get -nu/(1-nu) and -nu
//       terms of the other components' hourglass parts (ASQBI, Belytschko and Bindeman 1993).
//     18 with Icpre 0 or 2 (S8E: solide8e/s8eselecsh.F, s8ederish2.F, s8ederi_bij.F, s8edefo3.F,
//       solide/srepiso3.F, sortho3.F): the shear of each plane averaged over the four points sharing the
//       natural coordinate normal to that plane (S8E's sets IR, IT, IS for its local xy, xz, yz, whose axes
//       are eta, zeta, xi), so no bending mode locks; Poisson terms from the hourglass parts the shear keeps
//       and drops.
//     Forces are the transpose (work-conjugate): f = -sum_p V_p B~_p^T (sigma_p - q I). The coupling terms'
//     trace updates the point's reference volume V0_p <- V0_p (1 - dt tr) so that mu sees it.
//   volumetric strain for the material (LAW1/LAW2 take the pressure from mu only, the deviator from de):
//     per-point pressure (icpre 0): mu_p = V0_p / V_p - 1;
//     constant pressure (icpre 1, 2 and Isolid 12's per-element density): mu = V0 / V - 1 with V0 = sum V0_p,
//     the same at every point, so the volumetric part is under-integrated and does not lock at nu -> 1/2.
//   material: solid_point_update(de_p = D_p dt1, mu_p) per point, rate from the element-mean D (6.2)
//   bulk viscosity (3.3) per element from the mean tr D: q = rho ec l (qa^2 l ec + qb c), l = V^(1/3)
//   internal energy: dE = sum_p dt1/2 V_p,avg (sigma_old + sigma_new)_p : D_p - dV/2 (q_old + q_new),
//     V_p,avg = V_p (V - dV/2) / V. Isolid 18 with LAW1 adds S8E's viscous hourglass force (s8eforc3.F ->
//     s8evis3.F, see s8e_hourglass_viscosity): its dissipated work goes to e_hg, not to the internal energy
//   forces: f_k = -R^T sum_p V_p B~_p^T (sigma_p - q I), B~_p the operator above
//   element step: 14, 17, 18 (S8Z s8zderim3.F, S8E s8ederi_2.F, /DTSDE off): dx = min_p 8 V_p / A_mid with
//     A_mid = max 4 |g_a x g_b| of the centre directions; 12 (inferred): dx = V / max face area; dt = dx /
//     c_eff, c_eff = qt + sqrt(qt^2 + c^2), qt = qb c + qa^2 l ec; nodal stiffness k = rho V / (4 dt^2) (4.5)
//   output: g.sig = the volume-weighted point mean in global axes, g.eps_p = the point mean, g.rho = rho0
//   V0/V
//
// An element with a point volume V_p <= 0 (inverted, or not a number) gets zero force, dt = 0, k = 0, keeps
// its state and stores the bad volume in `vol`: the engine reports it and stops. Degenerate bricks (repeated
// nodes: the collapsed-edge pentahedra of /BRICK) keep V_p > 0 at the interior Gauss points.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "solver/elements/element_gather.hpp"
#include "solver/elements/element_groups.hpp"
#include "solver/elements/solid/solid_stages.hpp"

namespace radx::solver {

namespace {

constexpr int kNat[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                            {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};

// Points sharing a natural coordinate, for the assumed shear: kSet[c][p] = 0 or 1 is the side of point p
// along natural direction c (0 xi, 1 eta, 2 zeta).
constexpr int side(int p, int c) {
  return kNat[p][c] > 0 ? 1 : 0;
}

// dN_k/dxi_c at point p (a = 1/sqrt(3)).
struct ShapeDerivs {
  double d[8][8][3];
};

ShapeDerivs make_derivs() {
  ShapeDerivs s{};
  const double a = 1.0 / std::sqrt(3.0);
  for (int p = 0; p < 8; ++p) {
    const double xi = a * kNat[p][0], eta = a * kNat[p][1], zeta = a * kNat[p][2];
    for (int k = 0; k < 8; ++k) {
      const double xk = kNat[k][0], ek = kNat[k][1], zk = kNat[k][2];
      s.d[p][k][0] = 0.125 * xk * (1 + ek * eta) * (1 + zk * zeta);
      s.d[p][k][1] = 0.125 * ek * (1 + xk * xi) * (1 + zk * zeta);
      s.d[p][k][2] = 0.125 * zk * (1 + xk * xi) * (1 + ek * eta);
    }
  }
  return s;
}

const ShapeDerivs& derivs() {
  static const ShapeDerivs s = make_derivs();  // constant table, built once
  return s;
}

// Inverse of a 3x3 matrix m with determinant det (not zero).
inline void inverse3(const double m[3][3], double det, double inv[3][3]) {
  const double id = 1.0 / det;
  inv[0][0] = (m[1][1] * m[2][2] - m[1][2] * m[2][1]) * id;
  inv[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) * id;
  inv[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) * id;
  inv[1][0] = (m[1][2] * m[2][0] - m[1][0] * m[2][2]) * id;
  inv[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) * id;
  inv[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) * id;
  inv[2][0] = (m[1][0] * m[2][1] - m[1][1] * m[2][0]) * id;
  inv[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) * id;
  inv[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) * id;
}

inline double det3(const double m[3][3]) {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
         m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

// Co-rotational frame R (rows e1 e2 e3) from the centre directions of the element.
void corot_frame(const double x[8][3], double R[3][3], bool s8e) {
  double q[3][3];  // columns: unit centre directions along xi, eta, zeta
  for (int c = 0; c < 3; ++c) {
    double g[3] = {0, 0, 0};
    for (int k = 0; k < 8; ++k)
      for (int d = 0; d < 3; ++d) g[d] += 0.125 * kNat[k][c] * x[k][d];
    const double n = std::sqrt(dot3(g, g));
    for (int d = 0; d < 3; ++d) q[d][c] = n > 0 ? g[d] / n : (d == c ? 1.0 : 0.0);
  }
  if (s8e) {
    // S8E (sortho3.F): three passes of e_c <- unit(e_c+1 x e_c+2 + e_c), cyclic, then Gram-Schmidt led by eta
    // (then zeta): e_eta, e_xi = unit(e_eta x e_zeta), e_zeta = e_xi x e_eta.
    for (int it = 0; it < 3; ++it) {
      double nq[3][3];
      for (int c = 0; c < 3; ++c) {
        const double a[3] = {q[0][(c + 1) % 3], q[1][(c + 1) % 3], q[2][(c + 1) % 3]};
        const double b[3] = {q[0][(c + 2) % 3], q[1][(c + 2) % 3], q[2][(c + 2) % 3]};
        double e[3];
        cross3(a, b, e);
        for (int d = 0; d < 3; ++d) e[d] += q[d][c];
        const double n = std::sqrt(dot3(e, e));
        for (int d = 0; d < 3; ++d) nq[d][c] = n > 0 ? e[d] / n : q[d][c];
      }
      for (int d = 0; d < 3; ++d)
        for (int c = 0; c < 3; ++c) q[d][c] = nq[d][c];
    }
    double ee[3] = {q[0][1], q[1][1], q[2][1]}, qz[3] = {q[0][2], q[1][2], q[2][2]}, ex[3], ez[3];
    cross3(ee, qz, ex);
    const double n = std::sqrt(dot3(ex, ex));
    for (double& v : ex) v /= n;
    cross3(ex, ee, ez);
    for (int d = 0; d < 3; ++d) {
      R[0][d] = ex[d];
      R[1][d] = ee[d];
      R[2][d] = ez[d];
    }
    return;
  }
  // Polar rotation by the averaging iteration: converges quadratically from a nearly orthogonal start.
  for (int it = 0; it < 4; ++it) {
    const double det = det3(q);
    if (!(std::abs(det) > 1e-12)) break;
    double inv[3][3];
    inverse3(q, det, inv);
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) q[a][b] = 0.5 * (q[a][b] + inv[b][a]);
  }
  double e1[3] = {q[0][0], q[1][0], q[2][0]}, q2[3] = {q[0][1], q[1][1], q[2][1]}, e2[3], e3[3];
  double n = std::sqrt(dot3(e1, e1));
  for (double& v : e1) v /= n;
  cross3(e1, q2, e3);
  n = std::sqrt(dot3(e3, e3));
  for (double& v : e3) v /= n;
  cross3(e3, e1, e2);
  for (int d = 0; d < 3; ++d) {
    R[0][d] = e1[d];
    R[1][d] = e2[d];
    R[2][d] = e3[d];
  }
}

// Point volumes V_p = det J_p, gradients b_pk and inverse Jacobians ji_p[c][a] = dxi_c / dx_a of the geometry
// x. Returns false when a V_p <= 0 (or NaN); vp then holds the point volumes computed so far.
bool point_gradients(const double x[8][3], double vp[8], double b[8][8][3], double ji[8][3][3]) {
  const auto& s = derivs();
  for (int p = 0; p < 8; ++p) {
    double J[3][3] = {};  // J[a][c] = dx_a / dxi_c
    for (int k = 0; k < 8; ++k)
      for (int a = 0; a < 3; ++a)
        for (int c = 0; c < 3; ++c) J[a][c] += x[k][a] * s.d[p][k][c];
    const double det = det3(J);
    vp[p] = det;
    if (!(det > 0.0)) return false;
    inverse3(J, det, ji[p]);
    for (int k = 0; k < 8; ++k)
      for (int a = 0; a < 3; ++a)
        b[p][k][a] = s.d[p][k][0] * ji[p][0][a] + s.d[p][k][1] * ji[p][1][a] + s.d[p][k][2] * ji[p][2][a];
  }
  return true;
}

// The points' strain operator: normal strain eps_aa = sum_k b_pk,a v_k,a + sum_{s != a} sum_k cp[p][s][a][k]
// v_k,s, shear dv_a/dx_c (a != c) = sum_k bs[p][a][c][k] v_k,a. Plain: bs = b, cp = 0.
constexpr std::size_t kPoints = 8;  // the 2 x 2 x 2 Gauss points

struct PointOperator {
  double bs[8][3][3][8];
  double cp[8][3][3][8];
};

// Hourglass decomposition (Flanagan-Belytschko, exact for the trilinear brick): N_k = 1/8 + b_k.(x - x_c) +
// sum_a gamma_ak h_a, h = (eta zeta, zeta xi, xi eta, xi eta zeta), b_k = J_c^-T s_k / 8 (J_c the centre
// Jacobian, s_k the node's natural coordinates), gamma_ak = (h_ak - b_k.H_a) / 8, H_a = sum_k h_ak x_k.
// hg[p][m][k][a] = gamma_mk dh_m/dx_a at point p (grad h_m through the point's inverse Jacobian), and bc the
// centre gradients; b_pk = bc_k + sum_m hg[p][m][k].
void hourglass_parts(const double x[8][3], const double ji[8][3][3], double bc[8][3], double hg[8][4][8][3]) {
  double Jc[3][3] = {};
  for (int k = 0; k < 8; ++k)
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 3; ++c) Jc[a][c] += 0.125 * x[k][a] * kNat[k][c];
  double ic[3][3];
  inverse3(Jc, det3(Jc), ic);
  double hk[4][8];
  for (int k = 0; k < 8; ++k) {
    const double xi = kNat[k][0], et = kNat[k][1], ze = kNat[k][2];
    hk[0][k] = et * ze;
    hk[1][k] = ze * xi;
    hk[2][k] = xi * et;
    hk[3][k] = xi * et * ze;
    for (int a = 0; a < 3; ++a)
      bc[k][a] = 0.125 * (ic[0][a] * kNat[k][0] + ic[1][a] * kNat[k][1] + ic[2][a] * kNat[k][2]);
  }
  double gam[4][8];
  for (int m = 0; m < 4; ++m) {
    double H[3] = {0, 0, 0};
    for (int k = 0; k < 8; ++k)
      for (int a = 0; a < 3; ++a) H[a] += hk[m][k] * x[k][a];
    for (int k = 0; k < 8; ++k) gam[m][k] = 0.125 * (hk[m][k] - dot3(bc[k], H));
  }
  const double q = 1.0 / std::sqrt(3.0);
  for (int p = 0; p < 8; ++p) {
    const double xi = q * kNat[p][0], et = q * kNat[p][1], ze = q * kNat[p][2];
    const double dh[4][3] = {{0, ze, et}, {ze, 0, xi}, {et, xi, 0}, {et * ze, xi * ze, xi * et}};
    for (int m = 0; m < 4; ++m) {
      double g[3];
      for (int a = 0; a < 3; ++a)
        g[a] = ji[p][0][a] * dh[m][0] + ji[p][1][a] * dh[m][1] + ji[p][2][a] * dh[m][2];
      for (int k = 0; k < 8; ++k)
        for (int a = 0; a < 3; ++a) hg[p][m][k][a] = gam[m][k] * g[a];
    }
  }
}

// Isolid 14 (S8Z, assumed strain after Belytschko and Bindeman's ASQBI), in the co-rotational frame:
//   shear dv_a/dx_c keeps, of the four hourglass modes, only those whose gradient along c does not vary in
//   the a-c plane of a bent element: {h1, h2} for xy, {h1, h3} for xz, {h2, h3} for yz (bending modes h3, h2,
//   h1 and the warping h4 give no parasitic shear); normal strains (coupled, Icpre != 1): eps_bb += -nub
//   gamma_m.v_a dh_m/dx_a - nu sum_{n in {a, 4}} gamma_n.v_a dh_n/dx_a for a != b, m the bending mode of the
//   a-b plane (h3 xy, h2 xz, h1 yz), n = the mode free of a's natural coordinate (h1 for x, h2 for y, h3 for
//   z) and h4, nub = nu / (1 - nu): a bending mode then carries the plane-strain Poisson contraction instead
//   of locking.
void asqbi_operator(const double b[8][8][3], const double hg[8][4][8][3], const double bc[8][3], double nu,
                    bool coupled, PointOperator& op) {
  constexpr int kPlaneMode[3][3] = {{-1, 2, 1}, {2, -1, 0}, {1, 0, -1}};  // bending mode of plane (a, c)
  const double nub = nu / (1.0 - nu);
  for (int p = 0; p < 8; ++p)
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 3; ++c) {
        if (a == c) continue;
        const int drop = kPlaneMode[a][c];  // the two kept modes are the other two of h1..h3
        for (int k = 0; k < 8; ++k) {
          double g = bc[k][c];
          for (int m = 0; m < 3; ++m)
            if (m != drop) g += hg[p][m][k][c];
          op.bs[p][a][c][k] = g;
          // coupling: source component a (velocity), target normal strain c
          op.cp[p][a][c][k] =
              coupled ? -nub * hg[p][drop][k][a] - nu * (hg[p][a][k][a] + hg[p][3][k][a]) : 0.0;
        }
      }
  (void)b;
}

// Isolid 18 (S8E with its shear selection, Icpre 0 or 2), in the co-rotational frame:
//   shear dv_a/dx_c at point p = the plain mean of the full gradient over the four points sharing p's natural
//   coordinate normal to the plane (a, c): zeta for xy, eta for xz, xi for yz in this frame (x along xi). The
//   shear is then constant over its own plane and both bending modes of the plane are free of it. (S8E's
//   local axes are eta, zeta, xi and it averages xy over xi, xz over zeta, yz over eta: the same rule.)
//   normal strains: with S_ac,k = that mean minus the centre gradient bc_k,a (the hourglass part kept by the
//   pair (a, c)) and R_a,k = b_pk,a - bc_k,a - sum_{c != a} S_ac,k (the rest), eps_bb += sum_k (-nub S_at,k -
//   nu R_a,k) v_k,a for a != b, t the third axis.
constexpr int kPairDir[3][3] = {{-1, 2, 1}, {2, -1, 0}, {1, 0, -1}};  // natural direction normal to the pair
void select_operator(const double b[8][8][3], const double bc[8][3], double nu, PointOperator& op) {
  const double nub = nu / (1.0 - nu);
  for (int p = 0; p < 8; ++p)
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 3; ++c) {
        if (a == c) continue;
        const int dir = kPairDir[a][c];
        for (int k = 0; k < 8; ++k) {
          double g = 0;
          for (int q = 0; q < 8; ++q)
            if (side(q, dir) == side(p, dir)) g += 0.25 * b[q][k][c];
          op.bs[p][a][c][k] = g;
        }
      }
  for (int p = 0; p < 8; ++p)
    for (int a = 0; a < 3; ++a)
      for (int k = 0; k < 8; ++k) {
        // S_ac for the two c != a is bs[p][c][a] (the x-gradient of the pair is the same for v_c)
        const int c1 = (a + 1) % 3, c2 = (a + 2) % 3;
        const double s1 = op.bs[p][c1][a][k] - bc[k][a], s2 = op.bs[p][c2][a][k] - bc[k][a];
        const double rest = nu * (b[p][k][a] - bc[k][a] - s1 - s2);
        op.cp[p][a][c1][k] = -nub * s2 - rest;  // target c1: third axis c2
        op.cp[p][a][c2][k] = -nub * s1 - rest;
        op.cp[p][a][a][k] = 0.0;
      }
}

// Isolid 18 with LAW1 (S8E, s8evis3.F): a viscous force on the hourglass rates, with the structure of
// HEPH's hourglass (hex8_heph.cpp, szhour3.F) and no stiffness. In the frame x along xi:
//   gamma_jk = m_jk / 8 - bc_k . (m_j . x), q(d, j) = sum_k gamma_jk v_k[d] (modes m1 eta-zeta, m2 zeta-xi,
//   m3 xi-eta, m4 xi-eta-zeta), J_d = 8 |g_d|_d (4 x the edge), T = cv q with cv = 0.0025 rho c V^(1/3),
//   N = H T (HEPH's H with nu1 = 2/(1-nu), nu2 = nu nu1, nu3 = 2/3 (1+nu)), f_k[d] -= sum_j gamma_jk N(d, j).
// The projection term has no 1/8, unlike Flanagan-Belytschko's gamma = (m - bc . (m . x)) / 8 that HEPH uses:
// OpenRadioss's S8E builds m . x without the 1/8 (s8ederic3.F) where HEPH's szderi3.F has it. So on a brick
// that is not a parallelepiped (m . x != 0) a linear velocity field L x gets the rate q = -7/8 L (m . x) and
// is damped, which is what the QA beam HSEPH measures (its trapezoidal two-brick beam; radx with the 1/8 was
// 34 % off its internal energy, 0.3 % with OpenRadioss's form). radx reproduces it on purpose, so that decks
// run as in Radioss; on parallelepipeds both forms agree (m . x = 0).
// Returns the dissipated power sum N q. OpenRadioss books it nowhere (HSEPH's listing shows the loss as a
// -1.2 % to -2.3 % energy error through the run, -18 % at its last line where the external work is small);
// radx books it as hourglass energy, outside the internal energy, so its balance closes.
constexpr int kHgMode[4][8] = {{1, 1, -1, -1, -1, -1, 1, 1},
                               {1, -1, -1, 1, -1, 1, 1, -1},
                               {1, -1, 1, -1, 1, -1, 1, -1},
                               {-1, 1, -1, 1, 1, -1, 1, -1}};
double s8e_hourglass_viscosity(const double x[8][3], const double v[8][3], double vol, double cv, double nu,
                               double fl[8][3]) {
  double Jc[3][3] = {};
  for (int k = 0; k < 8; ++k)
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 3; ++c) Jc[a][c] += 0.125 * x[k][a] * kNat[k][c];
  const double det = det3(Jc);
  if (!(det > 0.0)) return 0.0;
  double ic[3][3];
  inverse3(Jc, det, ic);
  double bc[8][3];
  for (int k = 0; k < 8; ++k)
    for (int a = 0; a < 3; ++a)
      bc[k][a] = 0.125 * (ic[0][a] * kNat[k][0] + ic[1][a] * kNat[k][1] + ic[2][a] * kNat[k][2]);
  const double J[3] = {8.0 * Jc[0][0], 8.0 * Jc[1][1], 8.0 * Jc[2][2]};
  if (!(J[0] > 0.0) || !(J[1] > 0.0) || !(J[2] > 0.0)) return 0.0;
  double gam[4][8], q[3][4] = {};
  for (int j = 0; j < 4; ++j) {
    double hx[3] = {0, 0, 0};
    for (int k = 0; k < 8; ++k)
      for (int d = 0; d < 3; ++d) hx[d] += kHgMode[j][k] * x[k][d];
    for (int k = 0; k < 8; ++k) {
      gam[j][k] = 0.125 * kHgMode[j][k] - dot3(bc[k], hx);
      for (int d = 0; d < 3; ++d) q[d][j] += gam[j][k] * v[k][d];
    }
  }
  double T[3][4];
  for (int d = 0; d < 3; ++d)
    for (int j = 0; j < 4; ++j) T[d][j] = cv * q[d][j];
  const double h11 = J[1] * J[2] / J[0], h22 = J[0] * J[2] / J[1], h33 = J[0] * J[1] / J[2];
  const double h12 = J[2], h13 = J[1], h23 = J[0];
  const double nu1 = 2.0 / (1.0 - nu), nu2 = nu * nu1, nu3 = 2.0 / 3.0 * (1.0 + nu);
  double N[3][4];
  N[0][0] = (h22 + h33) * T[0][0] + h12 * T[1][1] + h13 * T[2][2];
  N[1][1] = (h11 + h33) * T[1][1] + h23 * T[2][2] + h12 * T[0][0];
  N[2][2] = (h11 + h22) * T[2][2] + h13 * T[0][0] + h23 * T[1][1];
  N[0][1] = nu1 * h11 * T[0][1] + nu2 * h12 * T[1][0];
  N[0][2] = nu1 * h11 * T[0][2] + nu2 * h13 * T[2][0];
  N[1][0] = nu1 * h22 * T[1][0] + nu2 * h12 * T[0][1];
  N[2][0] = nu1 * h33 * T[2][0] + nu2 * h13 * T[0][2];
  N[1][2] = nu1 * h22 * T[1][2] + nu2 * h23 * T[2][1];
  N[2][1] = nu1 * h33 * T[2][1] + nu2 * h23 * T[1][2];
  N[0][3] = nu3 * h11 * T[0][3];
  N[1][3] = nu3 * h22 * T[1][3];
  N[2][3] = nu3 * h33 * T[2][3];
  double power = 0;
  for (int d = 0; d < 3; ++d)
    for (int j = 0; j < 4; ++j) {
      power += N[d][j] * q[d][j];
      for (int k = 0; k < 8; ++k) fl[k][d] -= gam[j][k] * N[d][j];
    }
  (void)vol;
  return power;
}

void plain_operator(const double b[8][8][3], PointOperator& op) {
  for (int p = 0; p < 8; ++p)
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 8; ++k) {
          op.bs[p][a][c][k] = b[p][k][c];
          op.cp[p][a][c][k] = 0.0;
        }
}

// The group's constants of the kernel.
struct FullConstants {
  double dt1, c, rho0, qa2, qb, alpha;
  bool const_p;  // Icpre: every point takes the element's volumetric strain
  double nu;     // the material's Poisson ratio in the coupling terms, as S8Z/S8E
};

FullConstants full_constants(const BrickGroup& g, const MaterialParams& mat, double dt1) {
  FullConstants k;
  k.dt1 = dt1;
  k.c = mat.c_solid;
  k.rho0 = mat.rho0;
  k.qa2 = g.qa * g.qa;
  k.qb = g.qb;
  k.const_p = g.icpre != 0;
  k.alpha = mat.f_cut > 0 ? std::min(1.0, 2.0 * std::numbers::pi * mat.f_cut * dt1) : 1.0;
  k.nu = std::min(0.5, mat.nu);
  return k;
}

// Frame R (the identity without the co-rotational option) and the element's local coordinates and velocities.
void full_local_state(const BrickGroup& g, const double xg[8][3], const double vg[8][3], double R[3][3],
                      double x[8][3], double v[8][3]) {
  if (g.corot) corot_frame(xg, R, g.dt_points && g.strain != BrickGroup::FullStrain::Asqbi);
  for (int n = 0; n < 8; ++n)
    for (int a = 0; a < 3; ++a) {
      x[n][a] = R[a][0] * xg[n][0] + R[a][1] * xg[n][1] + R[a][2] * xg[n][2];
      v[n][a] = R[a][0] * vg[n][0] + R[a][1] * vg[n][1] + R[a][2] * vg[n][2];
    }
}

// The points' strain operator (the formulation's assumed strain).
void full_strain_operator(const BrickGroup& g, const FullConstants& k, const double x[8][3],
                          const double b[kPoints][8][3], const double ji[kPoints][3][3], PointOperator& op) {
  double bc[8][3], hg[8][4][8][3];
  switch (g.strain) {
    case BrickGroup::FullStrain::Plain: plain_operator(b, op); break;
    case BrickGroup::FullStrain::Asqbi:
      hourglass_parts(x, ji, bc, hg);
      asqbi_operator(b, hg, bc, k.nu, g.coupled, op);
      break;
    case BrickGroup::FullStrain::SelectShear:
      hourglass_parts(x, ji, bc, hg);
      select_operator(b, bc, k.nu, op);
      break;
  }
}

// The points' strain rates D (engineering shears) and spin increments W through the operator; with the
// coupling terms, each point's reference volume takes its share of the volumetric strain.
void full_strain_rates(BrickGroup& g, std::size_t i, double dt1, const PointOperator& op,
                       const double v[8][3], const double b[kPoints][8][3], double D[kPoints][6],
                       double W[kPoints][3]) {
  constexpr std::size_t G = kGroupSize;
  for (std::size_t p = 0; p < kPoints; ++p) {
    double L[3][3] = {};  // plain velocity gradient, for the normal strains and the spin
    for (int n = 0; n < 8; ++n)
      for (int a = 0; a < 3; ++a)
        for (int e = 0; e < 3; ++e) L[a][e] += v[n][a] * b[p][n][e];
    double sh[3][3] = {};  // assumed dv_a/dx_c (a != c) and the coupling's normal strains (a == c)
    for (int n = 0; n < 8; ++n)
      for (int a = 0; a < 3; ++a)
        for (int c = 0; c < 3; ++c) {
          if (a == c) continue;
          sh[a][c] += op.bs[p][a][c][n] * v[n][a];
          if (g.coupled) sh[c][c] += op.cp[p][a][c][n] * v[n][a];
        }
    D[p][0] = L[0][0] + sh[0][0];
    D[p][1] = L[1][1] + sh[1][1];
    D[p][2] = L[2][2] + sh[2][2];
    D[p][3] = sh[0][1] + sh[1][0];
    D[p][4] = sh[1][2] + sh[2][1];
    D[p][5] = sh[2][0] + sh[0][2];
    W[p][0] = 0.5 * dt1 * (L[2][1] - L[1][2]);  // wx
    W[p][1] = 0.5 * dt1 * (L[0][2] - L[2][0]);  // wy
    W[p][2] = 0.5 * dt1 * (L[1][0] - L[0][1]);  // wz
    // The coupling terms change the volume the strain sees, not the geometric one: the point's reference
    // volume takes that part of the volumetric strain (V0_p <- V0_p (1 - dt1 tr), as S8Z and S8E do), so
    // the pressure from mu = V0_p / V_p - 1 stays consistent with the strain.
    if (g.coupled) g.vol0_p[p * G + i] *= 1.0 - dt1 * (sh[0][0] + sh[1][1] + sh[2][2]);
  }
}

// What the material stage gives the element.
struct FullMaterialResult {
  double work = 0, w_pl = 0, eps_mean = 0, dmg_max = 0;
  bool fails = false;  // a point starts the brick's deletion (law 36 Eps_p_max, /FAIL/JOHNSON Ifail_so 1)
};

// Material per point: the stress sn[p], the stress work with the mean volume over the step, the plastic
// work, the mean plastic strain and the largest damage.
FullMaterialResult full_material(BrickGroup& g, std::size_t i, const FullConstants& k,
                                 const MaterialParams& mat, double off, double rate, double mu_el,
                                 double vavg_ratio, const double vp[kPoints], const double D[kPoints][6],
                                 const double W[kPoints][3], double sn[kPoints][6]) {
  constexpr std::size_t G = kGroupSize;
  const double dt1 = k.dt1;
  FullMaterialResult r;
  for (std::size_t p = 0; p < kPoints; ++p) {
    double so[6];
    for (std::size_t m = 0; m < 6; ++m) so[m] = g.sig_p[(p * 6 + m) * G + i];
    if (!g.corot) {  // Jaumann rotation of the point's stress (3.2), old values on the right
      const double wx = W[p][0], wy = W[p][1], wz = W[p][2];
      const double s0[6] = {so[0], so[1], so[2], so[3], so[4], so[5]};
      jaumann_rotate(s0, wx, wy, wz, so);
    }
    const double mu = k.const_p ? mu_el : g.vol0_p[p * G + i] / vp[p] - 1.0;
    const double de[6] = {D[p][0] * dt1, D[p][1] * dt1, D[p][2] * dt1,
                          D[p][3] * dt1, D[p][4] * dt1, D[p][5] * dt1};
    for (std::size_t m = 0; m < 6; ++m) sn[p][m] = so[m];
    double& ep = g.eps_p_p[p * G + i];
    const SolidPointResult pr = solid_point_update(mat, rate, de, mu, sn[p], ep, g.dmg_p[p * G + i], off);
    const double deps_p = pr.deps_p;
    r.fails = r.fails || pr.element_fails;
    r.dmg_max = std::max(r.dmg_max, g.dmg_p[p * G + i]);
    r.eps_mean += ep / 8.0;
    double wp = 0;
    for (std::size_t m = 0; m < 6; ++m) wp += (so[m] + sn[p][m]) * D[p][m];
    r.work += 0.5 * dt1 * vp[p] * vavg_ratio * wp;
    const double svm = std::sqrt(von_mises2(sn[p]));
    r.w_pl += svm * deps_p * vp[p];
  }
  return r;
}

// Characteristic length. S8Z and S8E: min over the points of 8 V_p / A_mid, A_mid the largest of the three
// mid-sections of the centre Jacobian (4 |g_a x g_b|); equal to V / max face area on a box, and shorter on a
// degenerate brick where a point's V_p shrinks. Otherwise the one-point V / max face area.
double full_step_length(const BrickGroup& g, const double x[8][3], const double vp[kPoints], double vol) {
  if (!g.dt_points) return brick_face_length(x, vol);
  double gc[3][3] = {};  // gc[c] = dx/dxi_c at the centre
  for (int n = 0; n < 8; ++n)
    for (int c = 0; c < 3; ++c)
      for (int d = 0; d < 3; ++d) gc[c][d] += 0.125 * kNat[n][c] * x[n][d];
  double amid = 0.0;
  for (int c = 0; c < 3; ++c) {
    double nc[3];
    cross3(gc[(c + 1) % 3], gc[(c + 2) % 3], nc);
    amid = std::max(amid, 4.0 * std::sqrt(dot3(nc, nc)));
  }
  double vmin = vp[0];
  for (std::size_t p = 1; p < kPoints; ++p) vmin = std::min(vmin, vp[p]);
  return 8.0 * vmin / amid;
}

// Forces in the local frame: the transpose of the strain operator, f_k,a = -sum_p V_p [(s_aa - q) b_pk,a
//   + sum_{c != a} ((s_cc - q) cp[p][a][c][k] + s_ac bs[p][a][c][k])]; and the volume-weighted mean stress.
void full_local_forces(const BrickGroup& g, const PointOperator& op, const double b[kPoints][8][3],
                       const double vp[kPoints], double vol, const double sn[kPoints][6], double q_new,
                       double fl[8][3], double smean[6]) {
  for (std::size_t p = 0; p < kPoints; ++p) {
    const double s[3][3] = {{sn[p][0] - q_new, sn[p][3], sn[p][5]},
                            {sn[p][3], sn[p][1] - q_new, sn[p][4]},
                            {sn[p][5], sn[p][4], sn[p][2] - q_new}};
    for (int n = 0; n < 8; ++n)
      for (int a = 0; a < 3; ++a) {
        double t = s[a][a] * b[p][n][a];
        for (int c = 0; c < 3; ++c) {
          if (c == a) continue;
          t += s[a][c] * op.bs[p][a][c][n];
          if (g.coupled) t += s[c][c] * op.cp[p][a][c][n];
        }
        fl[n][a] -= vp[p] * t;
      }
    for (int m = 0; m < 6; ++m) smean[m] += vp[p] * sn[p][m] / vol;
  }
}

// The element's output stress: the mean stress in global axes, sigma_g = R^T sigma_loc R.
void full_output_stress(const double R[3][3], const double smean[6], double out[6]) {
  const double S[3][3] = {
      {smean[0], smean[3], smean[5]}, {smean[3], smean[1], smean[4]}, {smean[5], smean[4], smean[2]}};
  double T[3][3] = {};
  for (int a = 0; a < 3; ++a)
    for (int e = 0; e < 3; ++e)
      for (int r = 0; r < 3; ++r)
        for (int t = 0; t < 3; ++t) T[a][e] += R[r][a] * S[r][t] * R[t][e];
  out[0] = T[0][0], out[1] = T[1][1], out[2] = T[2][2], out[3] = T[0][1], out[4] = T[1][2], out[5] = T[2][0];
}

// An element that does not run this cycle: deleted (dt = +inf), or with a point of non-positive volume (its
// volume stored as the worst one, not-a-number kept, dt = 0: reported and stopped by the engine).
void full_element_off(BrickGroup& g, std::size_t i, bool deleted, const double vp[kPoints]) {
  clear_nodal_forces<8, 3>(g.nodal_force.data(), kGroupSize, i);
  if (deleted) {
    g.dt[i] = std::numeric_limits<double>::infinity();
  } else {
    double bad = 0;
    for (std::size_t p = 0; p < kPoints; ++p) bad = std::min(bad, vp[p]);
    g.vol[i] = std::isnan(bad) ? bad : std::min(bad, 0.0);
    g.dt[i] = 0.0;
  }
  g.k_nodal[i] = 0.0;
}

}  // namespace

void resolve_full_brick(const model::SolidProperty& prop, const MaterialParams& mat, BrickGroup& g) {
  const int isolid = prop.isolid;
  if (isolid != 12 && isolid != 14 && isolid != 17 && isolid != 18) return;
  g.n_points = 8;
  g.allocate_points();
  const int asked = prop.icpre == 3 ? -3 : prop.icpre;  // 3: explicitly off
  switch (isolid) {
    case 14:  // HA8 (S8Z): co-rotational imposed, Icpre as given (default 0), assumed strain; Poisson
              // coupling unless Icpre = 1; S8Z's time step
      g.corot = true;
      g.icpre = asked > 0 ? asked : 0;
      g.strain = BrickGroup::FullStrain::Asqbi;
      g.coupled = g.icpre != 1;
      g.dt_points = true;
      break;
    case 17:  // H8C (S8E): the deck's frame, Icpre 0 -> 1 (constant pressure), 3 -> 0; plain strain
      g.corot = prop.iframe == 2;
      g.icpre = asked == 0 ? 1 : (asked > 0 ? asked : 0);
      g.dt_points = true;
      break;
    case 18:  // H8D: runs as 17 (S8E), co-rotational, Icpre chosen by the law unless given; with Icpre 0 or 2
              // the shear selection and Poisson coupling of S8E (its two integration layers flag), else plain
      g.corot = true;
      if (asked != 0) {
        g.icpre = asked > 0 ? asked : 0;
      } else if (mat.law == model::MaterialLaw::Elastic) {
        g.icpre = mat.nu >= 0.49 ? 1 : 0;
      } else {
        g.icpre = 2;
      }
      if (g.icpre != 1) {
        g.strain = BrickGroup::FullStrain::SelectShear;
        g.coupled = true;
      }
      g.s8e_visc = mat.law == model::MaterialLaw::Elastic;  // s8eforc3.F: two point layers and LAW1
      g.dt_points = true;
      break;
    default:  // 12: the deck's frame; density per element, so the pressure is constant over the element
      g.corot = prop.iframe == 2;
      g.icpre = 1;
      break;
  }
}

void hex8_full_point_volumes(const double x[8][3], double vp[8]) {
  double b[8][8][3], ji[8][3][3];
  point_gradients(x, vp, b, ji);
}

void hex8_full_forces(BrickGroup& g, const NodeState& nodes, const MaterialParams& mat,
                      const CycleInfo& cyc) {
  constexpr std::size_t G = kGroupSize;
  const FullConstants k = full_constants(g, mat, cyc.dt1);
  const double dt1 = k.dt1, c = k.c;
  PointOperator op;  // per element scratch, on the stack (no allocation in the loop)

  const auto n = static_cast<std::size_t>(g.count);
  for (std::size_t i = 0; i < n; ++i) {
    const double off = g.off[i];
    double vp[kPoints], b[kPoints][8][3], ji[kPoints][3][3];
    if (off == 0.0) {
      full_element_off(g, i, true, vp);
      continue;
    }
    double xg[8][3], vg[8][3];
    gather_element<8>(g.conn.data(), G, i, nodes, xg, vg);
    brick_small_strain_geometry(g, i, xg);  // /DT/BRICK/CST: freeze the geometry once (as hex8_fb.cpp)
    double R[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, x[8][3], v[8][3];
    full_local_state(g, xg, vg, R, x, v);
    if (!point_gradients(x, vp, b, ji)) {
      full_element_off(g, i, false, vp);
      continue;
    }
    double vol = 0;
    for (std::size_t p = 0; p < kPoints; ++p) vol += vp[p];

    full_strain_operator(g, k, x, b, ji, op);
    double D[kPoints][6], W[kPoints][3], Dm[6] = {0, 0, 0, 0, 0, 0};
    full_strain_rates(g, i, dt1, op, v, b, D, W);
    double vol0 = 0;
    for (std::size_t p = 0; p < kPoints; ++p) vol0 += g.vol0_p[p * G + i];
    for (std::size_t p = 0; p < kPoints; ++p)
      for (int m = 0; m < 6; ++m) Dm[m] += vp[p] * D[p][m] / vol;

    // Material per point.
    const double rho = k.rho0 * vol0 / vol;
    const double mu_el = vol0 / vol - 1.0;
    const double rate = filtered_rate(k.alpha, strain_rate_measure(Dm), g.rate[i]);
    const double dvol = vol - g.vol[i];
    const double vavg_ratio = (vol - 0.5 * dvol) / vol;
    double sn[kPoints][6];
    const FullMaterialResult mr = full_material(g, i, k, mat, off, rate, mu_el, vavg_ratio, vp, D, W, sn);

    // Bulk viscosity and step.
    const double l = std::cbrt(vol);
    const double ec = compression_rate(Dm);
    const double q_new = bulk_viscosity(rho, ec, l, k.qa2, k.qb, c);
    const double dt_e = solid_step(full_step_length(g, x, vp, vol), c, k.qa2, k.qb, l, ec);
    const double de_int = mr.work - 0.5 * dvol * (g.q[i] + q_new);

    // Forces, the S8E viscous hourglass, back to global axes.
    double fl[8][3] = {};
    double smean[6] = {0, 0, 0, 0, 0, 0};
    full_local_forces(g, op, b, vp, vol, sn, q_new, fl, smean);
    double w_visc = 0;
    if (g.s8e_visc)
      w_visc = s8e_hourglass_viscosity(x, v, vol, rho * c * 0.0025 * std::cbrt(vol), mat.nu, fl);
    double f[8][3];
    for (int nd = 0; nd < 8; ++nd)
      for (int a = 0; a < 3; ++a) f[nd][a] = R[0][a] * fl[nd][0] + R[1][a] * fl[nd][1] + R[2][a] * fl[nd][2];
    // Deletion as the one-point brick (brick_next_off) once any point fails. As in hex8_fb.cpp, this cycle's
    // forces and energies take the new factor: 0.8 in the failure cycle, none in the cycle that deletes the
    // brick (with the factor at entry a brick reported deleted still pushed on its nodes for one cycle).
    // Which share of failed points OpenRadioss needs for a fully integrated brick is not read: one.
    const double off_new = brick_next_off(off, mr.fails);
    store_nodal_forces<8, 3>(g.nodal_force.data(), G, i, off_new, f);

    // The state.
    double out[6];
    full_output_stress(R, smean, out);
    for (std::size_t p = 0; p < kPoints; ++p)
      for (std::size_t m = 0; m < 6; ++m) g.sig_p[(p * 6 + m) * G + i] = sn[p][m];
    for (std::size_t m = 0; m < 6; ++m) g.sig[m * G + i] = out[m];
    g.eps_p[i] = mr.eps_mean;
    g.dmg[i] = mr.dmg_max;
    g.off[i] = off_new;
    g.vol[i] = vol;
    g.rho[i] = rho;
    g.q[i] = q_new;
    g.rate[i] = rate;
    g.e_int[i] += off_new * de_int;
    g.e_hg[i] += off_new * dt1 * w_visc;
    g.w_plastic[i] += off_new * mr.w_pl;
    g.dt[i] = dt_e;
    g.k_nodal[i] = solid_nodal_stiffness(0.25, rho, vol, dt_e);
  }
}

}  // namespace radx::solver
