// /MAT/FOAM_TAB (law 70): tabulated visco-elastic foam, its parameters, the layout of its point state and
// its point (law70_foam_tab.cpp).
#pragma once

#include <memory>
#include <vector>

#include "solver/model/foam_table.hpp"
#include "solver/model/model.hpp"

namespace radx::solver {

struct MaterialParams;

// The loading and unloading tables (model/foam_table.hpp; shared, built once per material), the moduli the
// law runs with and its flags. `unload` is null when the unloading formulation needs no curve (Iflag 3, 4
// without unloading curves).
struct FoamParams {
  std::shared_ptr<const model::FoamTable> load, unload;
  std::shared_ptr<const model::FoamTable> tension;  // Itens 1: the factor against 1 - rho / rho0 (one curve)
  double e0 = 0, e_max = 0, aa = 0, eps_max = 1, yld_emax = 0;
  double static_rate = 0;  // rate of the first loading curve (0)
  int iflag = 0;
  double shape = 1, hys = 1;
};

// Law 70's state at one point, kFoamVars rows of the brick group's `foam` buffer (the names of sigeps70.F's
// user variables in brackets): the strain past the curve (eps_s), the largest dissipation measure reached,
// the current modulus E, the strain norm of the last cycle, its loading direction (+1, -1), the stress norm
// of the last cycle, the dissipation measure W, the static curve's value of the last cycle and the tension
// factor of the last cycle.
inline constexpr int kFoamVars = 9;
enum FoamVar : int {
  kFoamEpsS = 0,
  kFoamWMax,
  kFoamE,
  kFoamEpstOld,
  kFoamLoad,
  kFoamYldOld,
  kFoamW,
  kFoamYldElasOld,
  kFoamTensOld
};

// Fills p.foam's tables and moduli from the model's curves, and the moduli of E0 and the rate filter the
// law runs with.
void foam_params(const model::Material& m, const std::vector<model::Function>& functions, MaterialParams& p);

// Law 70's strain eps = V - I (engineering shears) from the total deformation gradient F:
// sum_i (lambda_i - 1) n_i (x) n_i.
void foam_strain(const double F[3][3], double eps[6]);

// Law 70 at one point. In: eps, the total strain of the point (xx yy zz, then the engineering shears, in the
// axes of the stress), de the strain increment of the step (same layout), rate the filtered strain rate,
// rho_ratio = rho / rho0, sig the stress of the last cycle (in the same axes; the law divides out the last
// tension factor itself). Out: sig the new stress, st[kFoamVars] updated. Returns the wave speed
// c = sqrt(A11 / rho0), A11 = E (1 - nu) / ((1 + nu)(1 - 2 nu)) with the current modulus E.
double foam_point(const MaterialParams& p, const double eps[6], const double de[6], double rate,
                  double rho_ratio, double sig[6], double st[kFoamVars]);

// A law-70 point's state before its first cycle (OpenRadioss m70init.F): modulus E0, tension factor 1.
void foam_initial_state(const MaterialParams& p, double st[kFoamVars]);

}  // namespace radx::solver
