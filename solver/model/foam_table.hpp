// /MAT/FOAM_TAB (law 70): the tables of stress against strain that the law interpolates, built from the
// deck's curves as OpenRadioss's starter builds them (read from law70_upd.F, law70_table.F, table_slope.F,
// func2d_deintersect.F, table_values_2d.F; see docs/elements-openradioss.md 6.8). Shared by the starter (its
// checks and listing) and the engine (the law), so both see the same numbers.
//
//   curve i (points x_k, y_k scaled by its Fscale):
//     segments with both ends at x < 0 are dropped; a first point with x > 0 is replaced by the origin, and
//     so is the lower end of the segment that crosses x = 0 when its ordinate is not 0 (the curve is forced
//     through (0, 0), only its positive part is kept: the law uses the norm of the strain);
//   several curves: the abscissas of all of them merged (sorted, repeated values once), each curve
//     evaluated there (linear, the end segments extrapolated); then for each curve j >= 2 in rate order, at
//     each abscissa k >= 2, when y_j - y_{j-1} changes sign between k-1 and k, y_j(k) <- 1.1 y_{j-1}(k)
//     (the curves are made not to cross);
//   every curve is made non-decreasing: y(k) <- max(y(k), y(k-1));
//   a curve of more than 100 points, and then a table of more than 100 abscissas (its first curve, the others
//   taking their values at the abscissas kept), is thinned to 100 (vw_smooth.F): the interior point of least
//   triangle area |x1 y + x y2 + x2 y1 - x1 y2 - x y1 - x2 y| (the origin and the end points never) is
//   removed, its two neighbours get the estimate |(x0 - x2)(y0 - y1)| (neighbour x0, its new next x2, the
//   point before it y1; the first point and a point whose next is the last keep theirs), until 100 remain;
//   then points in the second or fourth quadrant, or on x = 0 with y != 0, go to the origin.
//   value at (eps, rate): linear in eps on the common abscissas and linear in the rate between the two
//   curves around it, both extrapolated with the end intervals (one curve: eps only).
//
// Moduli (law70_upd.F): S_ini = the largest slope of a segment touching x = 0, S_max the largest slope of the
// table (with several curves, each curve's slope is taken from the previous point of the last curve, as
// table_slope.F does); Emax 0 -> S_max; E0 < S_ini -> E0 = S_ini (then Emax >= E0); a segment of slope
// >= Emax starting at x1 > 0 moves the strain limit to the smallest such x1 (eps0) and the stiffening
// strain to |eps0 - y1 / Emax|; a = (Emax - E0) / (that strain); sigma(eps_max) of the first curve at the
// deck's eps_max continues the curves beyond the limit with the slope Emax.
#pragma once

#include <cstddef>
#include <vector>

namespace radx::model {

inline constexpr std::size_t kFoamTablePoints = 100;  // law70_table.F: NPTMAX

// One deck curve: its points (not scaled), its ordinate scale and its strain rate.
struct FoamCurveInput {
  const double* x = nullptr;
  const double* y = nullptr;
  std::size_t n = 0;
  double scale = 1;
  double rate = 0;
};

// A table: the common abscissas x, the rates of the curves (increasing) and y[curve * x.size() + k].
struct FoamTable {
  std::vector<double> x;
  std::vector<double> rate;
  std::vector<double> y;
  [[nodiscard]] std::size_t n_curves() const { return rate.size(); }
  // Value at strain eps and strain rate r (the rate is ignored with one curve).
  [[nodiscard]] double at(double eps, double r) const;
  // Value of curve c at eps.
  [[nodiscard]] double curve_at(std::size_t c, double eps) const;
};

// The table of curves already sorted by increasing rate.
FoamTable build_foam_table(const std::vector<FoamCurveInput>& curves);

// The moduli and strain limit the law runs with (hm_read_mat70.F and law70_upd.F).
struct FoamModuli {
  double e0 = 0;        // lower bound of the modulus
  double e_max = 0;     // upper bound of the modulus
  double aa = 0;        // growth of the modulus with the strain past the curve: (Emax - E0) / strain
  double eps_max = 1;   // strain beyond which the curves continue with slope Emax
  double yld_emax = 0;  // first curve at the deck's eps_max
  double stiff_ini = 0, stiff_max = 0;
  bool e0_raised = false;    // E0 < S_ini: E0 taken as S_ini (OpenRadioss warns)
  bool limit_moved = false;  // a segment as steep as Emax moved the strain limit (OpenRadioss informs)
};
FoamModuli foam_moduli(const FoamTable& load, double e0, double e_max, double eps_max);

}  // namespace radx::model
