// Truss (/TRUSS with /PROP/TRUSS, TYPE2): a 2-node bar carrying an axial force only, elastic (law 1) or
// elastic-plastic with the static Johnson-Cook curve (law 2). The force is integrated in rate form along the
// current line n1 -> n2, and the cross-section follows the axial strain through Poisson's ratio.
//
// Sources, read for the behaviour (OpenRadioss): engine/source/elements/truss/tdefo3.F (strain rate),
// tdlen3.F (time step), tforc3.F (the cycle), materials/mat/mat001/m1lawt.F and mat002/m2lawt.F (the laws);
// starter tmass.F (mass and nodal stiffness).
//
// Nodes x1, x2 at x^n, velocities v1, v2 at t^{n-1/2}; dt1 = t^n - t^{n-1}.
//   l = |x2 - x1|, e = (x2 - x1) / l
//   eps_dot = e . (v2 - v1) / l + dt1/2 (eps_dot^2 - |v2 - v1|^2 / l^2)   (the geometric mid-step correction)
//   work:    E += N eps_dot l dt1 / 2, before and after the force update (trapezoid)
//   area:    A <- A (1 - 2 nu eps_dot dt1)
//   force:   N <- N + E A eps_dot dt1                                       (elastic trial)
//   law 2:   sigma_y = min(a + b eps_p^n, sig_max0); H = d sigma_y / d eps_p (b for n = 1, 0 at eps_p = 0)
//            f = |N| - sigma_y A;  if f > 0: eps_p += f / ((E + H) A), N = sign(N) sigma_y A
//            plastic work w += sigma_y A d eps_p l
//            rupture: once eps_p >= EPS_max the truss fades, off <- 0.8 off each cycle, 0 below 0.1; its
//            force is N off (Radioss's "RUPTURE OF TRUSS ELEMENT")
//   stress:  sigma = N / A
//   nodal forces: n1 += N e, n2 -= N e        (tension pulls the nodes together)
// Time step (tdlen3.F): dt = l / c with c = sqrt(E / rho0), the bar's wave speed; the nodal stiffness of
// /DT/NODA is E A / l on each node, so that sqrt(2 (m/2) / k) = l / c with the truss's mass m = rho0 A0 l0.
#include <algorithm>
#include <cmath>
#include <limits>

#include "solver/elements/element_groups.hpp"

namespace radx::solver {

namespace {

// Law 2 on the truss: the radial return of the axial force onto the static yield force sigma_y A; returns
// the plastic strain increment.
double truss_plastic_return(const JohnsonCookParams& jc, double young, double area, double& force,
                            double& eps_p, double& sigma_y) {
  sigma_y =
      std::min(jc.a + (eps_p > 0 ? jc.b * std::pow(eps_p, jc.n) : (jc.n == 0 ? jc.b : 0.0)), jc.sig_max0);
  double h = 0;
  if (jc.n == 1)
    h = jc.b;
  else if (eps_p > 0)
    h = jc.b * jc.n * std::pow(eps_p, jc.n - 1);
  const double excess = std::abs(force) - sigma_y * area;
  if (!(excess > 0)) return 0.0;
  const double d_eps_p = excess / ((young + h) * area);
  eps_p += d_eps_p;
  force = std::copysign(sigma_y * area, force);
  return d_eps_p;
}

// A failed truss fades over a few cycles (off 1 -> 0.8 -> 0.64 ... -> 0 below 0.1), as Radioss does.
void fade(double& off) {
  if (off < 0.1) off = 0.0;
  if (off < 1.0) off *= 0.8;
}

}  // namespace

void truss_axial_forces(TrussGroup& g, const NodeState& nodes, const MaterialParams& mat,
                        const CycleInfo& cyc) {
  constexpr std::size_t G = kGroupSize;
  const double dt1 = cyc.dt1;
  const bool plastic = mat.law == model::MaterialLaw::JohnsonCook;
  const double c = std::sqrt(mat.young / mat.rho0);
  for (int ii = 0; ii < g.count; ++ii) {
    const auto i = static_cast<std::size_t>(ii);
    for (std::size_t d = 0; d < 6; ++d) g.nodal_force[d * G + i] = 0.0;
    if (g.off[i] <= 0) {
      g.force[i] = g.sig[i] = 0.0;
      g.dt[i] = std::numeric_limits<double>::infinity();
      g.k_nodal[i] = 0.0;
      continue;
    }
    const auto n1 = static_cast<std::size_t>(g.conn[i]);
    const auto n2 = static_cast<std::size_t>(g.conn[G + i]);
    const double dx[3] = {nodes.x[n2] - nodes.x[n1], nodes.y[n2] - nodes.y[n1], nodes.z[n2] - nodes.z[n1]};
    const double dv[3] = {nodes.vx[n2] - nodes.vx[n1], nodes.vy[n2] - nodes.vy[n1],
                          nodes.vz[n2] - nodes.vz[n1]};
    const double l = std::sqrt(dx[0] * dx[0] + dx[1] * dx[1] + dx[2] * dx[2]);
    const double inv_l = l > 0 ? 1.0 / l : 0.0;
    const double e[3] = {dx[0] * inv_l, dx[1] * inv_l, dx[2] * inv_l};
    double eps_dot = (e[0] * dv[0] + e[1] * dv[1] + e[2] * dv[2]) * inv_l;
    const double ratio = (dv[0] * dv[0] + dv[1] * dv[1] + dv[2] * dv[2]) * inv_l * inv_l;
    eps_dot += 0.5 * dt1 * (eps_dot * eps_dot - ratio);

    double force = g.force[i];
    double off = g.off[i];
    g.e_int[i] += 0.5 * force * eps_dot * l * dt1;
    g.area[i] *= 1.0 - 2.0 * mat.nu * eps_dot * dt1;
    force += mat.young * g.area[i] * eps_dot * dt1;
    if (plastic) {
      double sigma_y = 0;
      const double d_eps_p = truss_plastic_return(mat.jc, mat.young, g.area[i], force, g.eps_p[i], sigma_y);
      g.w_plastic[i] += sigma_y * g.area[i] * d_eps_p * l;
      fade(off);
      if (off >= 1.0 && g.eps_p[i] >= mat.jc.eps_p_max) off *= 0.8;
    }
    force *= off;
    g.off[i] = off;
    g.e_int[i] += 0.5 * force * eps_dot * l * dt1;
    g.force[i] = force;
    g.sig[i] = g.area[i] > 0 ? force / g.area[i] : 0.0;
    g.strain[i] += eps_dot * dt1;

    g.dt[i] = c > 0 ? l / c : std::numeric_limits<double>::infinity();
    g.k_nodal[i] = mat.young * g.area[i] * inv_l * off;
    for (std::size_t d = 0; d < 3; ++d) {
      g.nodal_force[d * G + i] = force * e[d];
      g.nodal_force[(3 + d) * G + i] = -force * e[d];
    }
  }
}

}  // namespace radx::solver
