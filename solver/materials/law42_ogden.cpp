// /MAT/OGDEN (law 42): Ogden's hyperelastic rubber at one point, from the total deformation gradient.
//
// Source: the Ogden model as OpenRadioss's manual and sigeps42.F state it (decoupled isochoric and volumetric
// parts, the volumetric form Iform, the tension cut-off, the wave-speed estimate); hm_read_mat42.F for the
// moduli. Written from the equations; no Prony series, no tabulated bulk (both refused by the starter).
//
//   B = F F^T = sum_i lambda_i^2 n_i (x) n_i          (left Cauchy-Green tensor, principal stretches lambda_i
//                                                     and directions n_i; F is the total gradient, so the
//                                                     stress is objective and path-independent)
//   J = lambda_1 lambda_2 lambda_3,  lb_i = J^(-1/3) lambda_i   (isochoric stretches)
//   W = sum_p mu_p / alpha_p (lb_1^alpha_p + lb_2^alpha_p + lb_3^alpha_p - 3) + U(J)
//   U(J) = K/2 (J - 1)^2 (Iform 1),  U(J) = K (J - 1 - ln J) (Iform 2)
//   principal Cauchy stresses (the isochoric part is deviatoric by construction):
//     t_i = sum_p mu_p lb_i^alpha_p,  sigma_i = (t_i - (t_1 + t_2 + t_3) / 3) / J + U'(J)
//     U'(J) = K' (J - 1) (Iform 1), K' (1 - 1/J) (Iform 2)
//   sigma = sum_i sigma_i n_i (x) n_i
//   K' = K, stiffened as OpenRadioss does to keep a nearly incompressible brick from collapsing: when
//     K > 24 G (G = sum mu_p alpha_p) and the smallest stretch is below 0.2, K' = K max(1, nu1 / lambda_min),
//     nu1 = 40 (1/2 - (3K - G) / (6K + G)).
//   tension cut-off: the principal Biot (nominal) stresses T_i = J sigma_i / lambda_i; when one exceeds
//     sigma_cut the point's stress is zero and the element is deleted.
//   wave speed (time step, bulk viscosity, hourglass): c^2 = (K' + 4/3 G_t) / rho with the tangent shear
//     estimate G_t = G0 max(1, 0.405 max_i C_i / G), C_i = sum_p mu_p alpha_p (lb_i^alpha_p + m_p),
//     m_p = (lb_1^alpha_p + lb_2^alpha_p + lb_3^alpha_p) / 3, G0 = G / 2: at rest C_i = 2 G and G_t = G0,
//     in tension or compression the stiffening terms lb^alpha_p with alpha_p > 1 (or < 0) raise it.
//   Incompressible uniaxial check (K >> G): sigma = sum_p mu_p (lambda^alpha_p - lambda^(-alpha_p / 2)).
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "solver/materials/material_params.hpp"

namespace radx::solver {

// Principal stretches and directions of F: eigen-decomposition of B = F F^T (a self-adjoint solver: robust
// for repeated stretches, where the directions are any basis of the eigenspace and the stress does not
// depend on the choice).
void principal_stretches(const double F[3][3], double lam[3], double n[3][3]) {
  Eigen::Matrix3d f;
  for (int a = 0; a < 3; ++a)
    for (int c = 0; c < 3; ++c) f(a, c) = F[a][c];
  const Eigen::Matrix3d b = f * f.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(b);
  for (int i = 0; i < 3; ++i) {
    lam[i] = std::sqrt(std::max(es.eigenvalues()(i), 0.0));
    for (int a = 0; a < 3; ++a) n[a][i] = es.eigenvectors()(a, i);  // column i: direction n_i
  }
}

namespace {

double volumetric_slope(const OgdenParams& o, double k, double j) {
  return o.iform == 2 ? k * (1.0 - 1.0 / j) : k * (j - 1.0);
}

}  // namespace

OgdenPointResult ogden_point(const MaterialParams& p, const double F[3][3], double sig[6]) {
  const auto& o = p.ogden;
  OgdenPointResult out;
  double lam[3], n[3][3];
  principal_stretches(F, lam, n);
  const double j = lam[0] * lam[1] * lam[2];
  out.j = j;
  out.modulus = p.bulk + 4.0 / 3.0 * p.shear;
  for (int m = 0; m < 6; ++m) sig[m] = 0.0;
  if (!(j > 0.0)) return out;  // inverted: the element reports it and the engine stops

  const double jm13 = 1.0 / std::cbrt(j);
  const double lb[3] = {lam[0] * jm13, lam[1] * jm13, lam[2] * jm13};
  double t[3] = {0, 0, 0}, cii[3] = {0, 0, 0};
  for (int k = 0; k < o.n; ++k) {
    const double pw[3] = {std::pow(lb[0], o.alpha[k]), std::pow(lb[1], o.alpha[k]),
                          std::pow(lb[2], o.alpha[k])};
    const double mean = (pw[0] + pw[1] + pw[2]) / 3.0;
    const double ma = o.mu[k] * o.alpha[k];
    for (int i = 0; i < 3; ++i) {
      t[i] += o.mu[k] * pw[i];
      cii[i] += ma * (pw[i] + mean);
    }
  }
  const double tmean = (t[0] + t[1] + t[2]) / 3.0;

  double k_eff = p.bulk;
  const double lam_min = std::min({lam[0], lam[1], lam[2]});
  if (o.stiffen && lam_min < 0.2) k_eff *= std::max(1.0, o.nu1 / std::max(lam_min, 1e-20));
  const double up = volumetric_slope(o, k_eff, j);

  double s[3];
  bool cut = false;
  for (int i = 0; i < 3; ++i) {
    s[i] = (t[i] - tmean) / j + up;
    if (j * s[i] / lam[i] > std::abs(o.sig_cut)) cut = true;
  }
  const double c_max = std::max({cii[0], cii[1], cii[2]});
  const double g_t = p.shear * std::max(1.0, 0.405 * c_max / o.g);
  out.modulus = k_eff + 4.0 / 3.0 * g_t;
  if (cut) {
    out.cut = true;
    return out;
  }
  auto at = [&](int a, int b) {
    return s[0] * n[a][0] * n[b][0] + s[1] * n[a][1] * n[b][1] + s[2] * n[a][2] * n[b][2];
  };
  sig[0] = at(0, 0);
  sig[1] = at(1, 1);
  sig[2] = at(2, 2);
  sig[3] = at(0, 1);
  sig[4] = at(1, 2);
  sig[5] = at(2, 0);
  return out;
}

// LAW42 (Ogden): its terms, cut-off and form, and the starter's moduli.
void ogden_params(const model::Material& m, MaterialParams& p) {
  auto& o = p.ogden;
  o.n = static_cast<int>(std::min<std::size_t>(m.ogden.mu.size(), OgdenParams::kMaxTerms));
  for (int k = 0; k < o.n; ++k) {
    o.mu[k] = m.ogden.mu[static_cast<std::size_t>(k)];
    o.alpha[k] = m.ogden.alpha[static_cast<std::size_t>(k)];
    o.g += o.mu[k] * o.alpha[k];
  }
  o.sig_cut = m.ogden.sig_cut > 0 ? m.ogden.sig_cut : 1e20;
  o.iform = m.ogden.iform == 2 ? 2 : 1;
  // The starter's moduli (build_hyperelastic.cpp): G0 = g / 2, K = g (1 + nu) / 3 (1 - 2 nu).
  p.shear = m.shear;
  p.bulk = m.bulk;
  p.c_solid = p.rho0 > 0 ? std::sqrt((p.bulk + 4.0 * p.shear / 3.0) / p.rho0) : 0.0;
  o.stiffen = p.bulk > 24.0 * o.g;
  o.nu1 = 40.0 * (0.5 - (3.0 * p.bulk - o.g) / (6.0 * p.bulk + o.g));
}

double ogden_energy_density(const MaterialParams& p, const double F[3][3]) {
  const auto& o = p.ogden;
  double lam[3], n[3][3];
  principal_stretches(F, lam, n);
  const double j = lam[0] * lam[1] * lam[2];
  const double jm13 = 1.0 / std::cbrt(j);
  double w = 0.0;
  for (int k = 0; k < o.n; ++k) {
    double sum = -3.0;
    for (double l : lam) sum += std::pow(l * jm13, o.alpha[k]);
    w += o.mu[k] / o.alpha[k] * sum;
  }
  w += o.iform == 2 ? p.bulk * (j - 1.0 - std::log(j)) : 0.5 * p.bulk * (j - 1.0) * (j - 1.0);
  return w;
}

}  // namespace radx::solver
