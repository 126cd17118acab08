// /MAT/OGDEN (law 42): Ogden's hyperelastic rubber, its parameters and its point (law42_ogden.cpp).
#pragma once

#include "solver/model/model.hpp"

namespace radx::solver {

struct MaterialParams;

// The terms with mu_p != 0, G = sum mu_p alpha_p, the tension cut-off on the principal Biot stress, the
// volumetric form (1: U = K/2 (J-1)^2, 2: U = K (J - 1 - ln J)) and the bulk stiffening of OpenRadioss's
// sigeps42.F for K > 24 G (below a stretch of 0.2 the bulk modulus is multiplied by max(1, nu1 /
// lambda_min), nu1 = 40 (1/2 - nu_G), nu_G = (3K - G) / (6K + G)).
struct OgdenParams {
  static constexpr int kMaxTerms = 10;
  int n = 0;
  double mu[kMaxTerms] = {}, alpha[kMaxTerms] = {};
  double g = 0;  // sum mu_p alpha_p = 2 mu0
  double sig_cut = 1e20;
  int iform = 1;
  bool stiffen = false;  // K > 24 G
  double nu1 = 0;
};

// Fills p.ogden and the moduli the starter derived (G0, K and the solid sound speed).
void ogden_params(const model::Material& m, MaterialParams& p);

// Law 42 at one point: the Cauchy stress sig (xx yy zz xy yz zx, in the axes F maps into) from the total
// deformation gradient F[a][c] = dx_a / dX_c. Returns the modulus M = K' + 4/3 G_t of the point's wave speed
// c = sqrt(M / rho) (K' the bulk modulus with its stiffening, G_t the tangent shear estimate), J = det F, and
// `cut` when a principal Biot stress passed sigma_cut (sig is then 0).
struct OgdenPointResult {
  double modulus = 0;
  double j = 1;
  bool cut = false;
};
OgdenPointResult ogden_point(const MaterialParams& p, const double F[3][3], double sig[6]);

// Strain energy per unit reference volume W(F) of law 42 (without the bulk stiffening), for tests and
// checks: W = sum_p mu_p / alpha_p (lb1^alpha_p + lb2^alpha_p + lb3^alpha_p - 3) + U(J).
double ogden_energy_density(const MaterialParams& p, const double F[3][3]);

// Principal stretches lambda_i and directions n_i (column i of n) of a deformation gradient F: the
// eigen-decomposition of B = F F^T (shared by laws 42 and 70).
void principal_stretches(const double F[3][3], double lam[3], double n[3][3]);

}  // namespace radx::solver
