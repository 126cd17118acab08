// /MAT/PLAS_BRIT (law 27): Johnson-Cook plasticity of shells with a smeared tension crack, its parameters and
// the layout of its point state (law27_plas_brit.cpp).
#pragma once

#include "solver/model/model.hpp"

namespace radx::solver {

struct MaterialParams;

// The crack's constants: direction 1 only (OpenRadioss m27crak.F opens no other). The flow stress is law 2's
// (MaterialParams::jc).
struct BritParams {
  double eps_t = 1e20, eps_m = 1.1e20, d_max = 0.999, eps_f = 1.2e22;
  bool point_rate = true;  // Fsmooth 0: the rate term takes the point's largest strain increment, else the
                           // element's filtered rate
};

// Law 27's state at one shell point, kBritVars rows of the group's `brit` buffer: the total in-plane strain
// exx eyy gxy (element frame, engineering shear), the crack frame's direction 1 (cos, sin in the element
// frame; (1, 0) until the crack opens), the damage of direction 1 and its crack strain.
inline constexpr int kBritVars = 7;
enum BritVar : int { kBritExx = 0, kBritEyy, kBritGxy, kBritCos, kBritSin, kBritDamage, kBritCrack };

// Fills p.jc (law 27's flow stress, with hm_read_mat27.F's defaults: a 0 means 1e20, elastic-brittle), p.brit
// and the rate filter.
void plas_brit_params(const model::Material& m, MaterialParams& p);

}  // namespace radx::solver
