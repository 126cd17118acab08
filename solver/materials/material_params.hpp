// The parameters of a material as the points and the kernels use them (work units), derived once per
// material by make_material_params (material_params.cpp): the constants every law has, then each law's own
// in a struct of that law, declared in the law's header.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "solver/materials/failure.hpp"
#include "solver/materials/law27_plas_brit.hpp"
#include "solver/materials/law2_plas_johns.hpp"
#include "solver/materials/law36_plas_tab.hpp"
#include "solver/materials/law42_ogden.hpp"
#include "solver/materials/law70_foam_tab.hpp"
#include "solver/model/model.hpp"

namespace radx::solver {

struct MaterialParams {
  model::MaterialLaw law = model::MaterialLaw::Elastic;
  double rho0 = 0;  // initial density rho_I
  double young = 0, nu = 0;
  double shear = 0, bulk = 0;  // G = E / 2(1 + nu), K = E / 3(1 - 2 nu)
  double a11 = 0, a12 = 0;     // plane stress: A11 = E / (1 - nu^2), A12 = nu A11
  double c_shell = 0;          // sqrt(E / rho0): shell sound speed (docs/theory/elements.md 4.1)
  double c_solid = 0;          // sqrt((K + 4G/3) / rho0): solid sound speed (3.3)
  double f_cut = 0;            // strain-rate filter (laws 2, 27, 36, 70)
  FailParams fail;
  // Each law's own constants; only the law's struct is filled.
  JohnsonCookParams jc;  // law 2, and law 27's flow stress
  TabPlasParams tab;     // law 36
  BritParams brit;       // law 27
  OgdenParams ogden;     // law 42
  FoamParams foam;       // law 70
};

// Factor of the strain-rate filter (docs/theory/elements.md 6.1 shells, 6.2 solids): rate <- alpha
// e + (1 - alpha) rate, alpha = min(1, 2 pi Fcut dt1), 1 when Fcut = 0 (no
// filter). Shared by the shell and solid kernels.
inline double rate_filter_alpha(const MaterialParams& mat, double dt1) {
  if (mat.f_cut <= 0) return 1.0;
  return std::min(1.0, 2.0 * std::numbers::pi * mat.f_cut * dt1);
}

// Parameters of the laws without curves (1, 2, 27, 42) and of a /FAIL/JOHNSON on them. A law-36 or law-70
// material, or a /FAIL/TAB, needs the overload below.
MaterialParams make_material_params(const model::Material& m);

// Any law: law 36 gets its curves from `functions` (the model's) through `curves`, which receives them and
// must outlive the parameters and not be resized afterwards (the parameters point into it). The curves'
// points stay in `functions`, which must outlive them too.
MaterialParams make_material_params(const model::Material& m, const std::vector<model::Function>& functions,
                                    std::vector<TabCurve>& curves);

}  // namespace radx::solver
