// /MAT/FOAM_TAB (law 70): tabulated visco-elastic foam at one point, from the total strain.
//
// Source: OpenRadioss sigeps70.F (engine), hm_read_mat70.F, law70_upd.F, m70init.F (starter), read for the
// behaviour and written here from the equations below (docs/elements-openradioss.md 6.8). Tables and moduli:
// solver/model/foam_table.hpp.
//
// Strain: eps = V - I = sum_i (lambda_i - 1) n_i (x) n_i, the principal stretches lambda_i and directions n_i
//   of B = F F^T (hex8_fb.cpp gives F, the total deformation gradient); shears engineering (2 eps_ab).
//   [radx] OpenRadioss runs law 70 on bricks with the total small strain sym(F - I) (Ismstr 11); V - I is the
//   same to first order and free of rigid rotations.
// Norm of the strain: e = sqrt(exx^2 + eyy^2 + ezz^2 + (gxy^2 + gyz^2 + gzx^2) / 2).
// Curves (tables by strain rate r, the filtered rate of the brick; L loading, U unloading, L0 the first
//   loading curve), continued with the slope Emax past the strain limit e_lim:
//   Y_e = L0(e)                       (e < e_lim),   Y_e = L0(e_lim_deck) + Emax (e - e_lim)   (static)
//   Y_max = L(min(e, e_lim), r) [+ Emax (e - e_lim) when e >= e_lim]
//   Y_min = U(min(e, e_lim), r), or U(e) with a single unloading curve [+ the same Emax term]
//   no unloading curve and Iflag <= 2: U = L0 and Iflag 0 (the starter's rule); Iflag 3, 4 need none.
// Direction: loading when e >= e_old (the norm of the last cycle), else unloading.
// Modulus E (state, E0 <= E <= Emax): with Y = Y_max (loading, or any Iflag != 0) else Y_min,
//   eps_s = max(0, e - Y / E),  dE = a (eps_s - eps_s_old):
//   loading E += max(dE, 0), eps_s_old <- max(eps_s_old, eps_s); unloading E += min(dE, 0), eps_s_old <-
//   min(...); at a change of direction E keeps its value.
// Hooke with E and nu: A11 = E (1 - nu)/((1 + nu)(1 - 2 nu)), A12 = A11 nu / (1 - nu), G = E / (2 (1 + nu)).
// Target stress norm Y:
//   Iflag 0: trial s_t = sig_old + C de, |.| the tensor norm sqrt(sum s_ii^2 + 2 sum s_ij^2);
//     loading Y = min(Y_max, |s_t|); unloading Y = min(max(Y_min, |s_t|), Y_old), except Y = Y_min when
//     |C de| exceeds both Y_min and |s_t| (a jump across the loop). While the stress is held between the
//     curves (Y from |s_t|) a change of direction is not recorded (direction and eps_s kept).
//   Iflag 1..4: Y = Y_max, and the dissipation measure W += (Y_e + Y_e_old)/2 (e - e_old), W >= 0,
//     W_max = max(W_max, W).
// Stress ("spherical projection"): sig = C eps scaled to the norm Y: sig = Y C eps / |C eps|.
// Unloading (e < e_old) then scales it:
//   Iflag 1: deviator times Y_min / Y_e;  Iflag 2: all of sig times Y_min / Y_e;
//   Iflag 3: deviator times 1 - (1 - Hys)(1 - (W / W_max)^Shape);  Iflag 4: all of sig times the same
//   (Iflag 3, 4: only once W_max > 0).
// Tension (Itens 1): in expansion (mu = 1 - rho / rho0 > 0) sig is multiplied by f = max(0, Fscale T(mu)),
//   f kept to divide the next cycle's old stress by.
// Wave speed (step, bulk viscosity, hourglass): c = sqrt(A11 / rho0) with the current E.
#include <algorithm>
#include <cmath>

#include "solver/materials/material_params.hpp"

namespace radx::solver {

namespace {

double tensor_norm(const double s[6]) {
  return std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2] + 2.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
}

// C e with engineering shears in e: the shear stresses are G gamma.
void hooke(double a1, double a2, double g, const double e[6], double s[6]) {
  s[0] = a1 * e[0] + a2 * (e[1] + e[2]);
  s[1] = a1 * e[1] + a2 * (e[0] + e[2]);
  s[2] = a1 * e[2] + a2 * (e[0] + e[1]);
  s[3] = g * e[3];
  s[4] = g * e[4];
  s[5] = g * e[5];
}

}  // namespace

// Law 70's tables and moduli (solver/model/foam_table.hpp) from the model's curves. The unloading table is
// the first loading curve when the deck gives none and Iflag <= 2 (hm_read_mat70.F; Iflag is then 0); Iflag 3
// and 4 need no unloading curve.
void foam_params(const model::Material& m, const std::vector<model::Function>& functions, MaterialParams& p) {
  const auto& ft = m.foam;
  auto input = [&](std::int32_t fi, double scale, double rate) {
    model::FoamCurveInput c;
    if (fi >= 0 && static_cast<std::size_t>(fi) < functions.size()) {
      const auto& fn = functions[static_cast<std::size_t>(fi)];
      c.x = fn.x.data();
      c.y = fn.y.data();
      c.n = std::min(fn.x.size(), fn.y.size());
    }
    c.scale = scale == 0 ? 1.0 : scale;
    c.rate = rate;
    return c;
  };
  std::vector<model::FoamCurveInput> load, unload;
  for (std::size_t i = 0; i < ft.load_function.size(); ++i)
    load.push_back(input(ft.load_function[i], ft.load_scale[i], ft.load_rate[i]));
  for (std::size_t i = 0; i < ft.unload_function.size(); ++i)
    unload.push_back(input(ft.unload_function[i], ft.unload_scale[i], ft.unload_rate[i]));
  auto by_rate = [](const model::FoamCurveInput& a, const model::FoamCurveInput& b) {
    return a.rate < b.rate;
  };
  std::stable_sort(load.begin(), load.end(), by_rate);
  std::stable_sort(unload.begin(), unload.end(), by_rate);
  if (load.size() > 1) load[0].rate = 0;  // the static curve's rate is 0 (hm_read_mat70.F)
  if (unload.size() > 1) unload[0].rate = 0;
  auto& f = p.foam;
  f.iflag = ft.iflag;
  if (unload.empty() && ft.iflag <= 2 && !load.empty()) {
    unload.push_back(load[0]);
    f.iflag = 0;
  }
  f.shape = ft.shape == 0 ? 1.0 : ft.shape;
  f.hys = ft.hys == 0 ? 1.0 : ft.hys;
  auto table = std::make_shared<model::FoamTable>(model::build_foam_table(load));
  const auto mod = model::foam_moduli(*table, m.young, ft.e_max, ft.eps_max);
  f.e0 = mod.e0;
  f.e_max = mod.e_max;
  f.aa = mod.aa;
  f.eps_max = mod.eps_max;
  f.yld_emax = mod.yld_emax;
  f.static_rate = table->rate.empty() ? 0.0 : table->rate[0];
  f.load = std::move(table);
  if (!unload.empty()) f.unload = std::make_shared<model::FoamTable>(model::build_foam_table(unload));
  if (ft.itens == 1 && ft.tens_function >= 0 &&
      static_cast<std::size_t>(ft.tens_function) < functions.size()) {
    // The tension factor is the function itself (no processing), times its scale.
    const auto& fn = functions[static_cast<std::size_t>(ft.tens_function)];
    auto t = std::make_shared<model::FoamTable>();
    t->x = fn.x;
    t->rate = {0.0};
    const double sc = ft.tens_scale == 0 ? 1.0 : ft.tens_scale;
    for (double v : fn.y) t->y.push_back(sc * v);
    f.tension = std::move(t);
  }
  // The moduli of E0 (the initial wave speed, the contact stiffness).
  p.young = f.e0;
  p.shear = p.young / (2.0 * (1.0 + p.nu));
  p.bulk = p.young / (3.0 * (1.0 - 2.0 * p.nu));
  p.c_solid = p.rho0 > 0 ? std::sqrt((p.bulk + 4.0 * p.shear / 3.0) / p.rho0) : 0.0;
  p.f_cut = ft.israte > 0 || m.f_cut > 0 ? m.f_cut : 0.0;
}

void foam_strain(const double F[3][3], double eps[6]) {
  double lam[3], nv[3][3];
  principal_stretches(F, lam, nv);
  auto at = [&](int a, int b) {
    return (lam[0] - 1.0) * nv[a][0] * nv[b][0] + (lam[1] - 1.0) * nv[a][1] * nv[b][1] +
           (lam[2] - 1.0) * nv[a][2] * nv[b][2];
  };
  eps[0] = at(0, 0);
  eps[1] = at(1, 1);
  eps[2] = at(2, 2);
  eps[3] = 2.0 * at(0, 1);
  eps[4] = 2.0 * at(1, 2);
  eps[5] = 2.0 * at(2, 0);
}

void foam_initial_state(const MaterialParams& p, double st[kFoamVars]) {
  for (int k = 0; k < kFoamVars; ++k) st[k] = 0.0;
  st[kFoamE] = p.foam.e0;
  st[kFoamYldElasOld] = 1.0;
  st[kFoamTensOld] = 1.0;
}

double foam_point(const MaterialParams& p, const double eps[6], const double de[6], double rate,
                  double rho_ratio, double sig[6], double st[kFoamVars]) {
  const auto& f = p.foam;
  const double nu = p.nu;
  const double e = std::sqrt(eps[0] * eps[0] + eps[1] * eps[1] + eps[2] * eps[2] +
                             0.5 * (eps[3] * eps[3] + eps[4] * eps[4] + eps[5] * eps[5]));
  const bool beyond = e >= f.eps_max;
  const double past = beyond ? f.e_max * (e - f.eps_max) : 0.0;
  const double e_cl = std::min(e, f.eps_max);

  // Curves at this strain and rate.
  const double y_elas = beyond ? f.yld_emax + past : f.load->at(e, f.static_rate);
  const double y_max = f.load->at(e_cl, rate) + past;
  double y_min = y_max;
  if (f.unload) {
    const double x = f.unload->n_curves() > 1 ? e_cl : e;
    y_min = f.unload->at(x, rate) + past;
  }

  // The old stress without the last tension factor.
  double so[6];
  const double t_old = std::max(1e-20, st[kFoamTensOld]);
  for (int m = 0; m < 6; ++m) so[m] = sig[m] / t_old;

  const double eps_s_entry = st[kFoamEpsS];
  const double load_old = st[kFoamLoad];
  const double delta = e - st[kFoamEpstOld];
  const bool loading = delta >= 0;
  double load = loading ? 1.0 : -1.0;

  // Modulus.
  const double e_old = st[kFoamE];
  double y = (loading || f.iflag != 0) ? y_max : y_min;
  const double eps_s = std::max(0.0, e - y / e_old);
  const double d_e = f.aa * (eps_s - st[kFoamEpsS]);
  double em = e_old;
  if (loading) {
    em = load_old == -1.0 ? e_old : e_old + std::max(d_e, 0.0);
    st[kFoamEpsS] = std::max(st[kFoamEpsS], eps_s);
  } else {
    em = load_old == 1.0 ? e_old : e_old + std::min(d_e, 0.0);
    st[kFoamEpsS] = std::min(eps_s, st[kFoamEpsS]);
  }
  em = std::max(std::min(em, f.e_max), f.e0);
  st[kFoamE] = em;
  const double a1 = em * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu));
  const double a2 = a1 * nu / (1.0 - nu);
  const double g = 0.5 * em / (1.0 + nu);

  // Target norm.
  bool held = false;
  if (f.iflag == 0) {
    double ds[6], st_trial[6];
    hooke(a1, a2, g, de, ds);
    for (int m = 0; m < 6; ++m) st_trial[m] = so[m] + ds[m];
    const double dsig = tensor_norm(ds);
    const double svm = tensor_norm(st_trial);
    if (loading) {
      y = std::min(y_max, svm);
    } else {
      y = std::min(std::max(y_min, svm), st[kFoamYldOld]);
      held = true;
      if (dsig > y_min && dsig > svm) {
        y = y_min;
        held = false;
      }
    }
  } else {
    y = y_max;
    st[kFoamW] = std::max(0.0, st[kFoamW] + 0.5 * (y_elas + st[kFoamYldElasOld]) * delta);
    st[kFoamWMax] = std::max(st[kFoamWMax], st[kFoamW]);
  }
  st[kFoamYldElasOld] = y_elas;

  // Stress: C eps scaled to the norm y.
  hooke(a1, a2, g, eps, sig);
  const double r = y / std::max(1e-20, tensor_norm(sig));
  for (int m = 0; m < 6; ++m) sig[m] *= r;

  if (!loading) {
    double scale = 1.0;
    bool dev_only = false;
    switch (f.iflag) {
      case 1:
        scale = y_min / std::max(1e-20, y_elas);
        dev_only = true;
        break;
      case 2: scale = y_min / std::max(1e-20, y_elas); break;
      case 3:
      case 4:
        if (st[kFoamWMax] != 0) {
          scale = 1.0 - (1.0 - f.hys) * (1.0 - std::pow(st[kFoamW] / st[kFoamWMax], f.shape));
          dev_only = f.iflag == 3;
        }
        break;
      default: break;
    }
    if (dev_only) {
      const double pm = (sig[0] + sig[1] + sig[2]) / 3.0;
      for (int m = 0; m < 3; ++m) sig[m] = (sig[m] - pm) * scale + pm;
      for (int m = 3; m < 6; ++m) sig[m] *= scale;
    } else {
      for (int m = 0; m < 6; ++m) sig[m] *= scale;
    }
  }
  if (f.iflag == 0 && held && load_old != load) {
    load = load_old;
    st[kFoamEpsS] = eps_s_entry;
  }
  if (f.iflag == 0) st[kFoamWMax] = y;  // the stress norm of this cycle (sigeps70.F keeps it there)
  st[kFoamEpstOld] = e;
  st[kFoamLoad] = load;
  st[kFoamYldOld] = y;

  // Tension.
  double t = 1.0;
  if (f.tension) {
    const double mu = 1.0 - rho_ratio;
    if (mu > 0) t = std::max(0.0, f.tension->curve_at(0, mu));
  }
  for (int m = 0; m < 6; ++m) sig[m] *= t;
  st[kFoamTensOld] = t;

  return p.rho0 > 0 ? std::sqrt(a1 / p.rho0) : 0.0;
}

}  // namespace radx::solver
