// /MAT/PLAS_TAB (law 36): isotropic plasticity with tabulated yield curves, its parameters and its flow
// stress (law36_plas_tab.cpp).
#pragma once

#include <algorithm>
#include <vector>

#include "solver/model/model.hpp"

namespace radx::solver {

struct MaterialParams;

// One yield curve of law 36: a non-owning view of a /FUNCT's points (the engine's model owns them), its
// ordinate scale and its strain rate. sigma_y(eps_p) = scale f(eps_p), f linear between the points and
// extrapolated with the end segments (as every /FUNCT, functions.hpp).
struct TabCurve {
  const double* x = nullptr;
  const double* y = nullptr;
  int n = 0;
  double scale = 1;
  double rate = 0;
};

// Value and slope of a TabCurve's function (not scaled) at x: linear between the points, extrapolated with
// the end segments (as every /FUNCT, functions.hpp); a one-point function is constant.
inline void curve_at(const TabCurve& c, double x, double& y, double& dy) {
  if (c.n <= 1) {
    y = c.n == 1 ? c.y[0] : 0.0;
    dy = 0.0;
    return;
  }
  // Segment i: the number of interior abscissas x_1 .. x_{n-2} at or below x (0 before x_1, n-2 after).
  const auto i = static_cast<int>(std::upper_bound(c.x + 1, c.x + c.n - 1, x) - (c.x + 1));
  dy = (c.y[i + 1] - c.y[i]) / (c.x[i + 1] - c.x[i]);
  y = c.y[i] + dy * (x - c.x[i]);
}

// Law 36's constants: curves[0 .. n_curves) by increasing rate, the rate-0 curve first when there are
// several (non-owning: see make_material_params), and what the shells' elastic fast path needs to skip the
// curves (shell_yield_bound, material_point.hpp).
struct TabPlasParams {
  const TabCurve* curves = nullptr;
  int n_curves = 0;
  bool log_rate = false;  // Fsmooth 2: interpolation in ln(rate) between two curves, else linear in rate
  double lower = 0;       // lower bound of sigma_y over eps_p >= 0 and rates <= rate_max (fast path)
  double rate_max = 0;
  bool bound = false;       // `lower` is a valid bound (every curve's last segment rises or is flat)
  double eps_p_max = 1e20;  // Eps_p_max: a point past it deletes its element
};

// Law 36 flow stress (law36_plas_tab.cpp) at plastic strain eps_p and strain rate `rate`:
// sigma_y = max(Y1 + f (Y2 - Y1), 1e-20), Y_k = scale_k f_k(eps_p) of the two curves around the rate,
// f = (rate - r1)/(r2 - r1) (or the same in ln(rate)). `slope` receives H = d sigma_y / d eps_p.
double tab_flow_stress(const MaterialParams& p, double eps_p, double rate, double* slope = nullptr);

// Fills p.tab's curves from the material: they are built from the model's `functions` into `curves`, which
// p points into (see make_material_params).
void tab_curves_params(const model::Material& m, const std::vector<model::Function>& functions,
                       std::vector<TabCurve>& curves, MaterialParams& p);

}  // namespace radx::solver
