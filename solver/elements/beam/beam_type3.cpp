// Radioss type-3 beam (/BEAM with /PROP/BEAM): a 2-node Timoshenko beam integrated over its section, its
// state the section's resultants (axial force N, shear forces Qy Qz, torque Mx, bending moments My Mz) in a
// frame that follows the beam; elastic (law 1) or with a global plasticity criterion on the resultants (law
// 2).
//
// Sources, read for the behaviour (OpenRadioss): engine/source/elements/beam/pevec3.F (frame), pdefo3.F and
// pcurv3.F (strain and curvature rates), main_beam3.F, materials/mat/mat001/m1lawp.F and mat002/m2lawp.F
// (laws), pdamp3.F (damping), pfint3.F (nodal forces), pdlen3.F (step); starter pmass.F (mass, inertia),
// peveci.F (initial frame), hm_read_prop03.F (defaults). docs/elements-openradioss.md 12.2.
//
// Frame (x^n): e1 = (x2 - x1) / l; the y axis of the last cycle e2' gives e3 = e1 x e2', e2 = e3 x e1, turned
//   about e1 by theta = dt1 (w1 + w2) . e1 / 2 (the beam's mean twist rate), normalised; e3 = e1 x e2.
// Rates (v at n-1/2, w the nodal angular velocities): exx, exy, exz = e1, e2, e3 . (v2 - v1) / l; the local
//   rotation rates r_k = (e1, e2, e3) . w_k; then, with h = dt1 / 2 and the rates before the update (0):
//     exx -= h (exy0^2 + exz0^2), exy += h exz0 exx0, exz += h exy0 exx0
//     rx_k -= h (exy0 ry_k0 + exz0 rz_k0), ry_k -= (h/2)(rx1 + rx2) (rz_k0 - exy), rz_k += (h/2)(rx1 +
//     rx2)(ry_k0 + exz)
//   released rotations (Wdof) replace r by the value that makes the end moment vanish (pcurv3.F);
//   kxx, kyy, kzz = (r_2 - r_1) / l;  exz += (ry1 + ry2) / 2,  exy -= (rz1 + rz2) / 2.
// Law 1 (increments d = rate dt1): N += E A dexx; Qy += S2 dexy; Qz += S1 dexz; Mx += G Ixx dkxx;
//   My += E Iyy dkyy; Mz += E Izz dkzz, with the shear stiffnesses S1 = S0 B1 / (S + B1) + f B1,
//   S2 = S0 B2 / (S + B2) + f B2, S = 5/6 G A, B1 = 12 E Iyy / l^2, B2 = 12 E Izz / l^2, S0 = (1 - f) S,
//   f = 1 with Ishear 1 (shear neglected: the shear stiffness of the bending alone), 0 otherwise.
// Law 2: the elastic trial, then the equivalent stress s = sqrt(N^2 + 3 A (Mx^2/Ixx + My^2/Iyy + Mz^2/Izz)) /
// A
//   against sigma_y = min((a + b eps_p^n) R, SIG_max0 (R if ICC 1)), R = 1 + c ln(max(rate, eps_dot0 dt1) /
//   (eps_dot0 dt1)) with rate = |dW| / (s A) the section's work increment; N and the moments are scaled by
//   min(1, sigma_y / s) (the shear forces are not); eps_p += max(0, R dW_p / (2 sigma_y A)) with dW_p the
//   increment's work less its elastic part; rupture at EPS_p_max as the truss (off *= 0.8 each cycle).
// Failure model on law 2 (/FAIL/JOHNSON, /FAIL/BIQUAD; fail_beam3.F with fail_johnson_b.F, fail_biquad_b.F):
//   while the beam is intact (off = 1, EPS_max not reached) and yields (d_eps_p > 0), with the new resultants
//   s = the equivalent stress above and sigma_m = N / (3 A):
//     D += d_eps_p / eps_f(sigma_m, s, rate) (failure.hpp: Johnson-Cook, or the biquadratic curve of
//     eta = sigma_m / s kept in [-2/3, 2/3], times the size factor of l0, floored at 1e-6);
//     D = 1: the beam fades as at EPS_max (off 0.8, then 0.8 per cycle).
//   rate (Johnson-Cook's D4 only): r = l sqrt(3 (exx^2 / 2 + (exy / 2)^2 + (exz / 2)^2)) / 1.5 from the
//   rates, filtered as the material's strain rate (Fcut) when the law has a rate term. OpenRadioss multiplies
//   by the length l, so r is a velocity rather than a strain rate; kept as it runs, to fail where Radioss
//   fails.
// Work: E += l/2 [(N + N') dexx + (Q + Q') . (dexy, dexz) + (M + M') . dk] (old and new resultants).
// Damping (forces to the nodes, not to the state): N += Dm exx A l sqrt(2 E rho); Q += Df (exy, exz) A l
//   sqrt(2 E rho); Mx += Df kxx l Ixx sqrt(2 G rho); My, Mz += Df (kyy Iyy, kzz Izz) l sqrt(2 E rho).
// Nodal forces (added; node 1 then node 2): N e1 + Qy e2 + Qz e3 and its opposite; moments
//   node 1: Mx e1 + (My - l Qz / 2) e2 + (Mz + l Qy / 2) e3, node 2: -Mx e1 - (My + l Qz / 2) e2 - (Mz - l Qy
//   / 2) e3 (a released end's moment goes to the other end, pfint3.F).
// Step (pdlen3.F): dt = k l / c / sqrt(F), c = sqrt(E / rho0), k = sqrt(1 + d^2) - d with d = sqrt(2) max(Dm,
// Df),
//   F = max(1, l / (A l^2 / (12 max(Iyy, Izz)) + 6 E / (5 G))) as OpenRadioss writes it (l in the work
//   units); nodal stiffness F A E / (l k^2).
#include <algorithm>
#include <cmath>
#include <limits>

#include "solver/elements/element_groups.hpp"
#include "solver/materials/failure.hpp"
#include "solver/model/geometry.hpp"

namespace radx::solver {

namespace {

using V3 = model::Vec3;
using model::cross;
using model::dot;
using model::norm;
using model::scale;

// The beam's frame at x^n from the last cycle's y axis, turned by the mean twist over dt1 (pevec3.F).
void beam_frame(const V3& dx, const V3& ey_old, const V3& w1, const V3& w2, double dt1, V3& e1, V3& e2,
                V3& e3, double& l) {
  l = norm(dx);
  e1 = scale(dx, 1.0 / l);
  e3 = cross(e1, ey_old);
  e2 = cross(e3, e1);
  const double theta = 0.5 * (dot(e1, w1) + dot(e1, w2)) * dt1;
  const double c = std::cos(theta) / norm(e2), s = std::sin(theta) / norm(e3);
  for (std::size_t d = 0; d < 3; ++d) e2[d] = e2[d] * c + e3[d] * s;
  e2 = scale(e2, 1.0 / norm(e2));
  e3 = cross(e1, e2);
  e3 = scale(e3, 1.0 / norm(e3));
}

// The deformation rates of the section in the beam's frame (pdefo3.F, pcurv3.F).
struct BeamRates {
  double exx, exy, exz, kxx, kyy, kzz;
};

BeamRates beam_rates(const BeamReleases& rel, const V3& e1, const V3& e2, const V3& e3, const V3& dv,
                     const V3& w1, const V3& w2, double l, double dt1) {
  BeamRates r{};
  r.exx = dot(e1, dv) / l;
  r.exy = dot(e2, dv) / l;
  r.exz = dot(e3, dv) / l;
  double rx1 = dot(e1, w1), ry1 = dot(e2, w1), rz1 = dot(e3, w1);
  double rx2 = dot(e1, w2), ry2 = dot(e2, w2), rz2 = dot(e3, w2);
  const double h = 0.5 * dt1;
  const double rxav = 0.5 * h * (rx1 + rx2);
  const double exx0 = r.exx, exy0 = r.exy, exz0 = r.exz;
  const double hy = h * r.exy, hz = h * r.exz;
  r.exx -= hy * exy0 + hz * exz0;
  r.exy += hz * exx0;
  r.exz += hy * exx0;
  const double ry10 = ry1, rz10 = rz1, ry20 = ry2, rz20 = rz2;
  rx1 -= hy * ry10 + hz * rz10;
  ry1 -= rxav * (rz10 - r.exy);
  rz1 += rxav * (ry10 + r.exz);
  rx2 -= hy * ry20 + hz * rz20;
  ry2 -= rxav * (rz20 - r.exy);
  rz2 += rxav * (ry20 + r.exz);
  // Released rotations: the rate that leaves the end free of moment replaces the node's own.
  const double irx = rel.x, iry = std::min(1.0, rel.y1 + rel.y2), irz = std::min(1.0, rel.z1 + rel.z2);
  rx1 *= irx, rx2 *= irx, ry1 *= iry, ry2 *= iry, rz1 *= irz, rz2 *= irz;
  r.exz *= iry;
  r.exy *= irz;
  ry1 = rel.y1 * ry1 - (1 - rel.y1) * (1.5 * r.exz + 0.5 * ry2);
  ry2 = rel.y2 * ry2 - (1 - rel.y2) * (1.5 * r.exz + 0.5 * ry1);
  rz1 = rel.z1 * rz1 + (1 - rel.z1) * (1.5 * r.exy - 0.5 * rz2);
  rz2 = rel.z2 * rz2 + (1 - rel.z2) * (1.5 * r.exy - 0.5 * rz1);
  r.kxx = (rx2 - rx1) / l;
  r.kyy = (ry2 - ry1) / l;
  r.kzz = (rz2 - rz1) / l;
  r.exz += 0.5 * (ry1 + ry2);
  r.exy -= 0.5 * (rz1 + rz2);
  return r;
}

// Law 1's increments of the resultants, and the elastic trial of law 2 (m1lawp.F).
void beam_elastic(const BeamSection& s, const MaterialParams& mat, double l, const BeamRates& d,
                  double res[6]) {
  const double E = mat.young, G = mat.shear;
  const double sh = 5.0 / 6.0 * G * s.area;
  const double b = 12.0 * E / (l * l);
  const double b1 = b * s.iyy, b2 = b * s.izz;
  const double f = s.shear_neglected ? 1.0 : 0.0;
  const double sh0 = (1.0 - f) * sh;
  const double s1 = sh0 * b1 / (sh + b1) + f * b1;
  const double s2 = sh0 * b2 / (sh + b2) + f * b2;
  res[0] += d.exx * s.area * E;
  res[1] += d.exy * s2;
  res[2] += d.exz * s1;
  res[3] += d.kxx * G * s.ixx;
  res[4] += d.kyy * E * s.iyy;
  res[5] += d.kzz * E * s.izz;
}

// The equivalent stress of the resultants (main_beam3.F, m2lawp.F).
double beam_equivalent_stress(const BeamSection& s, const double res[6]) {
  const double q = res[0] * res[0] +
                   3.0 * s.area *
                       (res[3] * res[3] / std::max(s.ixx, 1e-20) + res[4] * res[4] / std::max(s.iyy, 1e-20) +
                        res[5] * res[5] / std::max(s.izz, 1e-20));
  return std::sqrt(q) / s.area;
}

// Law 2 on the section (m2lawp.F): the trial `res` (from `old`) scaled back onto the yield surface; returns
// the plastic work increment per unit length (0 when elastic). eps_p grows by the plastic strain.
double beam_plastic_return(const BeamSection& s, const MaterialParams& mat, const BeamRates& d,
                           const double old[6], double res[6], double& eps_p, double dt1) {
  const auto& jc = mat.jc;
  const double E = mat.young, G = mat.shear, A = s.area;
  double work = old[0] * d.exx + old[3] * d.kxx + old[4] * d.kyy + old[5] * d.kzz;  // N and M of the start
  const double seq = beam_equivalent_stress(s, res);
  double rate_factor = 1.0, cap = jc.sig_max0;
  if (jc.c != 0) {
    const double ref = std::max(jc.eps_dot0 * dt1, 1e-20);
    const double increment = std::max(std::abs(work) / (seq + 1e-20) / A, ref);
    rate_factor = 1.0 + jc.c * std::log(increment / ref);
    if (jc.icc == 1) cap *= rate_factor;
  }
  const double hardening = jc.b * std::exp(jc.n * std::log(eps_p + 1e-30));
  const double sigma_y = std::min((jc.a + hardening) * rate_factor, cap);
  const double ratio = std::min(1.0, sigma_y / (seq + 1e-20));
  res[0] *= ratio;
  for (int k = 3; k < 6; ++k) res[k] *= ratio;
  const double elastic = (res[0] + old[0]) * (res[0] - old[0]) / (E * A) +
                         (res[3] + old[3]) * (res[3] - old[3]) / (G * s.ixx) +
                         (res[4] + old[4]) * (res[4] - old[4]) / (E * s.iyy) +
                         (res[5] + old[5]) * (res[5] - old[5]) / (E * s.izz);
  work += res[0] * d.exx + res[3] * d.kxx + res[4] * d.kyy + res[5] * d.kzz;
  const double plastic = work - elastic;
  eps_p += std::max(0.0, 0.5 * rate_factor * plastic / sigma_y / A);
  return std::max(0.0, 0.5 * plastic);
}

// The damping resultants added to the nodal forces (pdamp3.F), from the rates.
void beam_damping(const BeamSection& s, const MaterialParams& mat, double l, const BeamRates& r, double off,
                  double damp[6]) {
  const double rho_e = std::sqrt(2.0 * mat.young * mat.rho0), rho_g = std::sqrt(2.0 * mat.shear * mat.rho0);
  const double dmm = s.area * l * rho_e;
  damp[0] = s.dm * off * r.exx * dmm;
  damp[1] = s.df * off * r.exy * dmm;
  damp[2] = s.df * off * r.exz * dmm;
  damp[3] = s.df * off * r.kxx * l * s.ixx * rho_g;
  damp[4] = s.df * off * r.kyy * l * s.iyy * rho_e;
  damp[5] = s.df * off * r.kzz * l * s.izz * rho_e;
}

// The nodal forces and moments of resultants f (local), added to the nodes in global axes (pfint3.F with the
// minus sign of pfcum3.F and pmcum3.F).
void beam_nodal_forces(const BeamReleases& rel, const double f[6], double l, const V3& e1, const V3& e2,
                       const V3& e3, double out[2][6]) {
  const double force1[3] = {f[0], f[1], f[2]};
  double m11 = -f[3], m21 = -f[4] + 0.5 * l * f[2], m31 = -f[5] - 0.5 * l * f[1];
  double m12 = f[3], m22 = f[4] + 0.5 * l * f[2], m32 = f[5] - 0.5 * l * f[1];
  m21 = rel.y1 * m21 + (1 - rel.y2) * m22;
  m22 = rel.y2 * m22 + (1 - rel.y1) * m21;
  m31 = rel.z1 * m31 + (1 - rel.z2) * m32;
  m32 = rel.z2 * m32 + (1 - rel.z1) * m31;
  const double mom1[3] = {-m11, -m21, -m31}, mom2[3] = {-m12, -m22, -m32};
  for (std::size_t d = 0; d < 3; ++d) {
    const double fd = force1[0] * e1[d] + force1[1] * e2[d] + force1[2] * e3[d];
    out[0][d] = fd;
    out[1][d] = -fd;
    out[0][3 + d] = mom1[0] * e1[d] + mom1[1] * e2[d] + mom1[2] * e3[d];
    out[1][3 + d] = mom2[0] * e1[d] + mom2[1] * e2[d] + mom2[2] * e3[d];
  }
}

// The section's rate for a failure model's strain-rate term, as main_beam3.F forms it (see the header).
double beam_failure_rate(const BeamRates& r, double l) {
  const double q = 0.5 * r.exx * r.exx + 0.25 * r.exy * r.exy + 0.25 * r.exz * r.exz;
  return l * std::sqrt(3.0 * q) / 1.5;
}

// A failure model's damage of an intact, yielding beam; true when it reaches 1.
bool beam_failure(const BeamSection& s, const MaterialParams& mat, const double res[6], double deps_p,
                  double rate, double l0, double& dmg) {
  if (deps_p <= 0) return false;
  const double svm = beam_equivalent_stress(s, res);
  const double sigma_m = res[0] / (3.0 * s.area);
  return fail_accumulate(mat.fail, sigma_m, svm, rate, fail_size_factor(mat.fail, l0), deps_p, dmg);
}

// A failed beam fades over a few cycles (off 1 -> 0.8 -> 0.64 ... -> 0 below 0.1), as Radioss does.
void fade(double& off) {
  if (off < 0.1) off = 0.0;
  if (off < 1.0) off *= 0.8;
}

}  // namespace

BeamStep beam_step(const BeamSection& s, const MaterialParams& mat, double l) {
  const double d = std::sqrt(2.0) * std::max(s.dm, s.df);
  const double k = std::sqrt(1.0 + d * d) - d;
  const double facdt = s.area * l * l / (12.0 * std::max({s.iyy, s.izz, 1e-30}));
  const double fsh = std::max(1.0, l / (facdt + 1.2 * mat.young / mat.shear));
  const double c = std::sqrt(mat.young / mat.rho0);
  return {k * l / c / std::sqrt(fsh), fsh * s.area * mat.young / (l * k * k)};
}

void beam_type3_forces(BeamGroup& g, const NodeState& nodes, const MaterialParams& mat,
                       const CycleInfo& cyc) {
  constexpr std::size_t G = kGroupSize;
  const double dt1 = cyc.dt1;
  const bool plastic = mat.law == model::MaterialLaw::JohnsonCook;
  const auto& s = g.section;
  for (int ii = 0; ii < g.count; ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    for (std::size_t d = 0; d < 12; ++d) g.nodal_force[d * G + i] = 0.0;
    if (g.off[i] <= 0) {
      for (std::size_t k = 0; k < 6; ++k) g.resultant[k * G + i] = 0.0;
      g.dt[i] = std::numeric_limits<double>::infinity();
      g.k_nodal[i] = 0.0;
      continue;
    }
    const auto n1 = static_cast<std::size_t>(g.conn[i]), n2 = static_cast<std::size_t>(g.conn[G + i]);
    const V3 dx = {nodes.x[n2] - nodes.x[n1], nodes.y[n2] - nodes.y[n1], nodes.z[n2] - nodes.z[n1]};
    const V3 dv = {nodes.vx[n2] - nodes.vx[n1], nodes.vy[n2] - nodes.vy[n1], nodes.vz[n2] - nodes.vz[n1]};
    const V3 w1 = {nodes.wx[n1], nodes.wy[n1], nodes.wz[n1]}, w2 = {nodes.wx[n2], nodes.wy[n2], nodes.wz[n2]};
    const V3 ey_old = {g.ey[i], g.ey[G + i], g.ey[2 * G + i]};
    V3 e1, e2, e3;
    double l = 0;
    beam_frame(dx, ey_old, w1, w2, dt1, e1, e2, e3, l);
    for (std::size_t d = 0; d < 3; ++d) g.ey[d * G + i] = e2[d];
    const BeamRates rate = beam_rates(g.releases, e1, e2, e3, dv, w1, w2, l, dt1);
    const BeamRates inc{rate.exx * dt1, rate.exy * dt1, rate.exz * dt1,
                        rate.kxx * dt1, rate.kyy * dt1, rate.kzz * dt1};

    double old[6], res[6];
    for (std::size_t k = 0; k < 6; ++k) old[k] = res[k] = g.resultant[k * G + i];
    beam_elastic(s, mat, l, inc, res);
    double off = g.off[i];
    if (plastic) {
      const double eps_p0 = g.eps_p[i];
      const double w_p = beam_plastic_return(s, mat, inc, old, res, g.eps_p[i], dt1);
      g.w_plastic[i] += w_p * l * off;
      fade(off);
      if (off >= 1.0 && g.eps_p[i] >= mat.jc.eps_p_max) off *= 0.8;
      if (mat.fail.on) {
        // Radioss filters the section's rate only when the law has a rate term (c != 0, its Israte).
        const double alpha = mat.jc.c != 0 ? rate_filter_alpha(mat, dt1) : 1.0;
        g.rate[i] = alpha * beam_failure_rate(rate, l) + (1.0 - alpha) * g.rate[i];
        if (off >= 1.0 && beam_failure(s, mat, res, g.eps_p[i] - eps_p0, g.rate[i], g.l0[i], g.dmg[i]))
          off *= 0.8;
      }
    }
    for (double& r : res) r *= off;
    g.off[i] = off;
    const double strains[6] = {inc.exx, inc.exy, inc.exz, inc.kxx, inc.kyy, inc.kzz};
    double work = 0;
    for (std::size_t k = 0; k < 6; ++k) work += (old[k] + res[k]) * strains[k];
    g.e_int[i] += 0.5 * off * l * work;
    for (std::size_t k = 0; k < 6; ++k) g.resultant[k * G + i] = res[k];
    g.sig[i] = res[0] / s.area;

    double damp[6], total[6];
    beam_damping(s, mat, l, rate, off, damp);
    for (std::size_t k = 0; k < 6; ++k) total[k] = res[k] + damp[k];
    double out[2][6];
    beam_nodal_forces(g.releases, total, l, e1, e2, e3, out);
    for (std::size_t q = 0; q < 2; ++q)
      for (std::size_t d = 0; d < 6; ++d) g.nodal_force[(6 * q + d) * G + i] = out[q][d];

    const auto step = beam_step(s, mat, l);
    g.dt[i] = step.dt;
    g.k_nodal[i] = step.k_nodal * off;
  }
}

}  // namespace radx::solver
