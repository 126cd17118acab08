// LAW27 (/MAT/PLAS_BRIT): Johnson-Cook plasticity of shells with a smeared tension crack at each integration
// point. The shell section (shell_section.hpp) calls it for every point of a law-27 group; the point keeps
// its crack state in the group's `brit` rows (BritVar, material_point.hpp).
//
// Sources (read, not translated): OpenRadioss starter/source/materials/mat/mat027/hm_read_mat27.F (cards,
// defaults), cm27in3.F (initial crack frame), engine/source/materials/mat/mat027/sigeps27c.F, m27elas.F,
// m27plas.F, m27crak.F, and mulawc.F90 (the strain increments rotated into the crack frame).
//
// Frames. The stress is stored in the element frame. The point's crack frame has direction 1 along
// n = (c, s) (element frame; (1, 0) until the crack opens). Stress and strain increments are turned into it,
//   x1 = c^2 x + s^2 y + 2cs xy,  x2 = s^2 x + c^2 y - 2cs xy,  x12 = cs (y - x) + (c^2 - s^2) xy,
//   x23 = c yz - s zx,  x31 = s yz + c zx          (tensor shears for the strains)
// and the updated stress turned back with the transpose.
//
// Damaged elasticity (m27elas.F), in the crack frame, d the damage of direction 1 (direction 2 never
// opens: m27crak.F opens only direction 1, so its damage stays 0):
//   D1 = 1 - d when s1 >= 0 (open crack), 1 when s1 < 0 (closed crack carries compression), D2 = 1
//   k  = 1 when D1 = 1 (undamaged), else 0: the Poisson coupling is lost across an open crack
//   elastic strain of the old stress: e1 = (s1/D1 - nu k s2)/E, e2 = (s2 - nu k s1)/E, g12 = s12/(D1 G),
//                                     g23 = s23/(G_s), g31 = s31/(D1 G_s)       (G_s = Ashear G)
//   e += de (crack frame);  if d > 0: crack strain k_c += de1, d = min(max(d, k_c/(EPS_m1 - EPS_t1)), d_max1)
//   D1 again with the new d (same sign test on the old s1), q = 1 - nu^2 k,
//   s1 = E D1/q e1 + nu k E D1/q e2,  s2 = nu k E D1/q e1 + E/q e2,  s12 = D1 G g12,
//   s23 = G_s g23,  s31 = D1 G_s g31
//   (undamaged this is the plane-stress update of LAW2: s += A de.)
//
// Plasticity (m27plas.F): LAW2's shell return (law2_plas_johns.cpp, radial or Iplas 1 Newton) on the
// in-plane stress of the crack frame, with the flow stress
//   sigma_y = min((a + b eps_p^n) Q, SIG_max0 (Q if ICC = 1 else 1)),  Q = 1 + c ln(e_p / e_r),
//   e_r = max(1e-20, EPS_DOT_0 dt),  e_p = max(e_r, max(|de1|, |de2|, |dg12|/2))   (Fsmooth 0, Fcut 0)
//                                    e_p = max(e_r, rate dt)  (Fsmooth 1 or Fcut > 0: the element's rate,
//                                                              filtered with Fcut by the kernels)
//   Defaults: a 0 = 1e20 (elastic-brittle), n 0 = 1, SIG_max0 0 = 1e20.
//
// Crack (m27crak.F), after the update, on the total strain of the point (element frame, e = e_m + z kappa,
// accumulated here from the increments):
//   eps_1 = (exx + eyy)/2 + sqrt(((exx - eyy)/2)^2 + (gxy/2)^2)      (largest principal strain)
//   opens, once (d = 0, element not deleted), when eps_1 >= EPS_t1: n = (gxy/2, eps_1 - exx)/|.| (the
//     principal direction; (1, 0) when |.| < 1e-8), d = min((eps_1 - EPS_t1)/(EPS_m1 - EPS_t1), d_max1);
//     it acts from the next cycle on.
//   the element is deleted at once (OFF 0) when eps_1 > EPS_f1 at one of its points while OFF = 1.
// Thickness strain (1.8) as LAW2, with the plastic trace of the crack frame (the trace is frame-free).
// Differences from OpenRadioss: the total strain uses the current thickness for z (sigeps27c.F the initial
// one); within the cycle a deletion does not stop the later points' update (m27crak.F's OFF = 0 does).
#include <algorithm>
#include <cmath>

#include "solver/materials/material_point.hpp"

namespace radx::solver {

void plas_brit_params(const model::Material& m, MaterialParams& p) {
  // hm_read_mat27.F's defaults, applied again for a Material built by hand.
  p.jc.a = m.a == 0 ? 1e20 : m.a;
  p.jc.b = m.b;
  p.jc.n = m.n == 0 ? 1.0 : m.n;
  p.jc.c = m.c;
  p.jc.eps_dot0 = (m.c == 0 || m.eps_dot_0 <= 0) ? 1.0 : m.eps_dot_0;
  p.jc.sig_max0 = m.sig_max0 == 0 ? 1e20 : m.sig_max0;
  p.jc.icc = m.icc == 0 ? 1 : m.icc;
  p.f_cut = m.f_cut;
  const auto& b = m.brit;
  p.brit.eps_t = b.eps_t1 == 0 ? 1e20 : b.eps_t1;
  p.brit.eps_m = b.eps_m1 == 0 ? 1.1e20 : b.eps_m1;
  p.brit.d_max = b.d_max1 == 0 ? 0.999 : b.d_max1;
  p.brit.eps_f = b.eps_f1 == 0 ? 1.2e22 : b.eps_f1;
  p.brit.point_rate = m.fsmooth == 0 && m.f_cut == 0;
}

namespace detail {

namespace {

constexpr double kTinyShear = 1e-30;  // m27elas.F EM30: floor of a transverse shear stiffness as a divisor
constexpr double kTinyRate = 1e-20;   // m27plas.F EM20: floor of the reference strain increment
constexpr double kTinyNorm = 1e-8;    // m27crak.F EM8: below it the principal direction is undefined

// Plane (xx, yy, xy) with tensor shear and transverse (yz, zx) components turned into the frame (c, s).
void to_frame(double c, double s, double v[5]) {
  const double x = v[0], y = v[1], t = v[2], yz = v[3], zx = v[4];
  v[0] = c * c * x + s * s * y + 2.0 * c * s * t;
  v[1] = s * s * x + c * c * y - 2.0 * c * s * t;
  v[2] = c * s * (y - x) + (c * c - s * s) * t;
  v[3] = c * yz - s * zx;
  v[4] = s * yz + c * zx;
}

void from_frame(double c, double s, double v[5]) {
  const double x = v[0], y = v[1], t = v[2], r4 = v[3], r5 = v[4];
  v[0] = c * c * x + s * s * y - 2.0 * c * s * t;
  v[1] = s * s * x + c * c * y + 2.0 * c * s * t;
  v[2] = c * s * (x - y) + (c * c - s * s) * t;
  v[3] = c * r4 + s * r5;
  v[4] = -s * r4 + c * r5;
}

}  // namespace

ShellPointResult law27_shell_point(const MaterialParams& p, int iplas, double rate, double dt1, double off,
                                   const double de[5], double gs, double sig[5], double& eps_p, double* st,
                                   std::size_t stride) {
  const auto at = [&](int k) -> double& { return st[static_cast<std::size_t>(k) * stride]; };
  const double c = at(kBritCos), s = at(kBritSin);
  double d = at(kBritDamage);

  double so[5] = {sig[0], sig[1], sig[2], sig[3], sig[4]};
  to_frame(c, s, so);
  double e[5] = {de[0], de[1], 0.5 * de[2], 0.5 * de[3], 0.5 * de[4]};
  to_frame(c, s, e);
  e[2] *= 2.0, e[3] *= 2.0, e[4] *= 2.0;

  // Damaged elasticity: back to the elastic strain with the old stiffness, then forward with the new.
  const double e_mod = p.young, nu = p.nu, g = p.shear;
  const bool open = so[0] >= 0.0;
  double d1 = open ? 1.0 - d : 1.0;
  double k = d1 >= 1.0 ? 1.0 : 0.0;
  const double ee[5] = {(so[0] / d1 - nu * so[1] * k) / e_mod + e[0], (so[1] - nu * so[0] * k) / e_mod + e[1],
                        so[2] / d1 / g + e[2], so[3] / std::max(gs, kTinyShear) + e[3],
                        so[4] / std::max(d1 * gs, kTinyShear) + e[4]};
  if (d != 0.0) {
    at(kBritCrack) += e[0];
    d = std::min(std::max(d, at(kBritCrack) / (p.brit.eps_m - p.brit.eps_t)), p.brit.d_max);
    at(kBritDamage) = d;
  }
  d1 = open ? 1.0 - d : 1.0;
  k = d1 >= 1.0 ? 1.0 : 0.0;
  const double q = 1.0 - nu * nu * k;
  const double a11 = e_mod * d1 / q, a22 = e_mod / q, a12 = nu * a11 * k;
  double sn[5] = {a11 * ee[0] + a12 * ee[1], a12 * ee[0] + a22 * ee[1], d1 * g * ee[2], gs * ee[3],
                  d1 * gs * ee[4]};

  // Plasticity with the rate term of the point (or of the element).
  const double e_ref = std::max(kTinyRate, p.jc.eps_dot0 * dt1);
  const double inc =
      p.brit.point_rate ? std::max({std::abs(e[0]), std::abs(e[1]), 0.5 * std::abs(e[2])}) : rate * dt1;
  const double rfac = 1.0 + p.jc.c * std::log(std::max(inc, e_ref) / e_ref);
  ShellPointResult out;
  double dezz_p = 0;
  out.deps_p = jc_shell_return(p, iplas, rfac, off, sn[0], sn[1], sn[2], eps_p, dezz_p);
  if (out.deps_p > 0) {
    const double vm_old = std::sqrt(std::max(0.0, shell_vm2_radial(sig[0], sig[1], sig[2])));
    const double vm_new = std::sqrt(std::max(0.0, shell_vm2_radial(sn[0], sn[1], sn[2])));
    out.w_plastic = 0.5 * (vm_old + vm_new) * out.deps_p;
  }
  from_frame(c, s, sn);
  for (int m = 0; m < 5; ++m) sig[m] = sn[m];
  out.dezz = shell_dezz(p, de[0], de[1], dezz_p);

  // Crack on the total strain of the point.
  const double exx = (at(kBritExx) += de[0]);
  const double eyy = (at(kBritEyy) += de[1]);
  const double gxy = (at(kBritGxy) += de[2]);
  const double half_xy = 0.5 * gxy;
  const double eps1 = 0.5 * (exx + eyy) + std::sqrt(0.25 * (exx - eyy) * (exx - eyy) + half_xy * half_xy);
  if (eps1 >= p.brit.eps_t && !(d > 0.0) && off != 0.0) {
    double nx = half_xy, ny = eps1 - exx;
    const double norm = std::sqrt(nx * nx + ny * ny);
    if (norm < kTinyNorm) {
      nx = 1.0;
      ny = 0.0;
    } else {
      nx /= norm;
      ny /= norm;
    }
    at(kBritCos) = nx;
    at(kBritSin) = ny;
    at(kBritDamage) = std::min((eps1 - p.brit.eps_t) / (p.brit.eps_m - p.brit.eps_t), p.brit.d_max);
  }
  out.fails = p.brit.eps_f > 0 && eps1 > p.brit.eps_f && off == 1.0;
  return out;
}

}  // namespace detail

}  // namespace radx::solver
