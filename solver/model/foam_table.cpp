// Law 70's tables and moduli: the formulas are at the top of foam_table.hpp.
#include "solver/model/foam_table.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace radx::model {

namespace {

// The positive part of one curve, forced through the origin (foam_table.hpp, first rule).
void positive_part(const FoamCurveInput& c, std::vector<double>& xs, std::vector<double>& ys) {
  xs.clear();
  ys.clear();
  if (c.n < 2) {  // a one-point curve: the origin and that point, if it lies at x > 0
    xs.push_back(0.0);
    ys.push_back(0.0);
    if (c.n == 1 && c.x[0] > 0) {
      xs.push_back(c.x[0]);
      ys.push_back(c.y[0] * c.scale);
    }
    return;
  }
  double s2 = 0, t2 = 0;
  for (std::size_t j = 0; j + 1 < c.n; ++j) {
    double s1 = c.x[j], t1 = c.y[j] * c.scale;
    s2 = c.x[j + 1];
    t2 = c.y[j + 1] * c.scale;
    if (s1 < 0 && s2 < 0) continue;
    if (j == 0 && s1 > 0) {
      s1 = 0;
      t1 = 0;
    } else if (s1 <= 0 && s2 > 0 && t1 != 0) {
      s1 = 0;
      t1 = 0;
    }
    xs.push_back(s1);
    ys.push_back(t1);
  }
  xs.push_back(s2);
  ys.push_back(t2);
  for (std::size_t k = 0; k < xs.size(); ++k)
    if (xs[k] == 0) ys[k] = 0;
}

// Thinning of a curve to `target` points (foam_table.hpp): Visvalingam-Whyatt as vw_smooth.F does it.
void thin(std::vector<double>& x, std::vector<double>& y, std::size_t target) {
  const std::size_t n = x.size();
  if (n <= target) return;
  constexpr double kRemoved = std::numeric_limits<double>::max();
  constexpr double kKept = kRemoved / 10;  // the end points and the origin
  constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> prev(n), next(n);
  std::vector<double> area(n, kKept);
  for (std::size_t i = 0; i < n; ++i) {
    prev[i] = i == 0 ? kNone : i - 1;
    next[i] = i + 1 < n ? i + 1 : kNone;
  }
  for (std::size_t i = 1; i + 1 < n; ++i) {
    if (x[i] == 0 && y[i] == 0) continue;
    area[i] = std::abs(x[i - 1] * y[i] + x[i] * y[i + 1] + x[i + 1] * y[i - 1] - x[i - 1] * y[i + 1] -
                       x[i] * y[i - 1] - x[i + 1] * y[i]);
  }
  // Each removed point's neighbours get the estimate |(x0 - x2)(y0 - y1)| (x0 the neighbour, x2 its new
  // next point, y1 the point before it), the previous one only when it is not the first point, the next one
  // only when its own next is before the last point.
  auto estimate = [&](std::size_t i0, std::size_t i1, std::size_t i2) {
    area[i0] = std::abs((x[i0] - x[i2]) * (y[i0] - y[i1]));
  };
  for (std::size_t iter = 0; iter < n - target; ++iter) {
    std::size_t imin = 0;
    double amin = kRemoved;
    for (std::size_t i = 0; i < n; ++i)
      if (area[i] < amin) {
        amin = area[i];
        imin = i;
      }
    const std::size_t ip = prev[imin], in = next[imin];
    if (ip != kNone) next[ip] = in;
    if (in != kNone) prev[in] = ip;
    area[imin] = kRemoved;
    if (ip != kNone && prev[ip] != kNone && in != kNone) estimate(ip, prev[ip], in);
    if (in != kNone && next[in] != kNone && next[in] < n - 1 && ip != kNone) estimate(in, ip, next[in]);
  }
  std::vector<double> kx, ky;
  for (std::size_t i = 0; i < n; ++i)
    if (area[i] < kRemoved) {
      kx.push_back(x[i]);
      ky.push_back(y[i]);
    }
  // Points on the wrong side of the axes go to the origin (a point of negative strain and negative stress
  // stays, unless the next point is in the positive quadrant).
  for (std::size_t i = 0; i < kx.size(); ++i) {
    const double sx = kx[i], ty = ky[i];
    const bool wrong = (sx < 0 && ty > 0) || (sx > 0 && ty < 0) || (sx == 0 && ty != 0);
    const bool before_positive = sx < 0 && ty < 0 && i + 1 < kx.size() && kx[i + 1] > 0 && ky[i + 1] > 0;
    if (wrong || before_positive) kx[i] = ky[i] = 0.0;
  }
  x = std::move(kx);
  y = std::move(ky);
}

// Linear interpolation of (xs, ys) at x with the end segments extrapolated.
double interp(const std::vector<double>& xs, const std::vector<double>& ys, double x) {
  const std::size_t n = xs.size();
  if (n == 1) return ys[0];
  const auto it = std::upper_bound(xs.begin() + 1, xs.end() - 1, x);
  const auto i = static_cast<std::size_t>(it - (xs.begin() + 1));
  const double dx = xs[i + 1] - xs[i];
  const double slope = dx != 0 ? (ys[i + 1] - ys[i]) / dx : 0.0;
  return ys[i] + slope * (x - xs[i]);
}

}  // namespace

double FoamTable::curve_at(std::size_t c, double eps) const {
  const std::size_t n = x.size();
  if (n == 0) return 0.0;
  const double* yc = y.data() + c * n;
  if (n == 1) return yc[0];
  const auto it = std::upper_bound(x.begin() + 1, x.end() - 1, eps);
  const auto i = static_cast<std::size_t>(it - (x.begin() + 1));
  const double dx = x[i + 1] - x[i];
  const double slope = dx != 0 ? (yc[i + 1] - yc[i]) / dx : 0.0;
  return yc[i] + slope * (eps - x[i]);
}

double FoamTable::at(double eps, double r) const {
  const std::size_t m = rate.size();
  if (m <= 1) return curve_at(0, eps);
  // Rate interval j: the last curve with rate <= r among 0 .. m-2 (the first below, the last above).
  const auto it = std::upper_bound(rate.begin() + 1, rate.end() - 1, r);
  const auto j = static_cast<std::size_t>(it - (rate.begin() + 1));
  const double y1 = curve_at(j, eps), y2 = curve_at(j + 1, eps);
  const double dr = rate[j + 1] - rate[j];
  const double w = dr != 0 ? (r - rate[j]) / dr : 0.0;
  return y1 + w * (y2 - y1);
}

FoamTable build_foam_table(const std::vector<FoamCurveInput>& curves) {
  FoamTable t;
  const std::size_t m = curves.size();
  if (m == 0) return t;
  std::vector<std::vector<double>> xs(m), ys(m);
  for (std::size_t i = 0; i < m; ++i) {
    positive_part(curves[i], xs[i], ys[i]);
    thin(xs[i], ys[i], kFoamTablePoints);
    t.rate.push_back(curves[i].rate);
  }
  if (m == 1) {
    t.x = xs[0];
    t.y = ys[0];
  } else {
    for (const auto& v : xs) t.x.insert(t.x.end(), v.begin(), v.end());
    std::sort(t.x.begin(), t.x.end());
    t.x.erase(std::unique(t.x.begin(), t.x.end()), t.x.end());
    const std::size_t n = t.x.size();
    t.y.assign(m * n, 0.0);
    for (std::size_t i = 0; i < m; ++i)
      for (std::size_t k = 0; k < n; ++k) t.y[i * n + k] = interp(xs[i], ys[i], t.x[k]);
    // Curves made not to cross, each against the one below it (already corrected).
    for (std::size_t j = 1; j < m; ++j) {
      double* lo = t.y.data() + (j - 1) * n;
      double* hi = t.y.data() + j * n;
      for (std::size_t k = 1; k < n; ++k) {
        const double d1 = hi[k - 1] - lo[k - 1];
        const double d2 = hi[k] - lo[k];
        if (d1 * d2 < 0) hi[k] = lo[k] * 1.1;
      }
    }
  }
  std::size_t n = t.x.size();
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t k = 1; k < n; ++k) t.y[i * n + k] = std::max(t.y[i * n + k], t.y[i * n + k - 1]);
  if (n > kFoamTablePoints) {
    // The first curve is thinned; the others take their values at the abscissas it keeps.
    const std::vector<double> x_all = t.x;
    std::vector<double> y0(t.y.begin(), t.y.begin() + static_cast<std::ptrdiff_t>(n));
    std::vector<double> x0 = x_all;
    thin(x0, y0, kFoamTablePoints);
    const std::size_t nn = x0.size();
    std::vector<double> y(m * nn);
    for (std::size_t k = 0; k < nn; ++k) y[k] = y0[k];
    for (std::size_t i = 1; i < m; ++i) {
      const std::vector<double> yi(t.y.begin() + static_cast<std::ptrdiff_t>(i * n),
                                   t.y.begin() + static_cast<std::ptrdiff_t>((i + 1) * n));
      for (std::size_t k = 0; k < nn; ++k) y[i * nn + k] = interp(x_all, yi, x0[k]);
    }
    t.x = std::move(x0);
    t.y = std::move(y);
    n = nn;
  }
  return t;
}

FoamModuli foam_moduli(const FoamTable& load, double e0, double e_max, double eps_max) {
  FoamModuli o;
  const std::size_t n = load.x.size();
  const std::size_t m = load.n_curves();
  if (eps_max == 0) eps_max = 1;
  // Slopes of the table (table_slope.F).
  double s_ini = 0, s_max = 0;
  if (n >= 2 && m >= 1) {
    if (m == 1) {
      if (load.x[0] >= 0) s_ini = (load.y[1] - load.y[0]) / (load.x[1] - load.x[0]);
      for (std::size_t k = 1; k < n; ++k) {
        const double x1 = load.x[k - 1], x2 = load.x[k];
        const double d = (load.y[k] - load.y[k - 1]) / (x2 - x1);
        s_max = std::max(s_max, d);
        if (x1 == 0 || x2 == 0) s_ini = std::max(s_ini, d);
      }
    } else {
      double y1 = load.y[0];  // the first curve's first point, then the last curve's previous point
      for (std::size_t k = 1; k < n; ++k) {
        const double dx = load.x[k] - load.x[k - 1];
        double y2 = y1;
        for (std::size_t c = 0; c < m; ++c) {
          y2 = load.y[c * n + k];
          const double d = (y2 - y1) / dx;
          s_max = std::max(s_max, d);
          if (load.x[k - 1] == 0 || load.x[k] == 0) s_ini = std::max(s_ini, d);
        }
        y1 = y2;
      }
    }
  }
  o.stiff_ini = s_ini;
  o.stiff_max = s_max;
  if (e_max < e0) e_max = 0;  // hm_read_mat70.F: Emax below E0 is dropped (warning)
  if (e_max == 0) e_max = s_max;
  double aa = (e_max - e0) / eps_max;
  double e0_run = e0;
  double e0_loc = e0, emax_loc = e_max;
  if (e0_loc < s_ini) {
    e0_loc = s_ini;
    if (emax_loc < e0_loc) emax_loc = e0_loc;
    o.e0_raised = true;
  }
  // A segment as steep as Emax: the strain limit moves to its start (the same running x1 over all curves).
  double eps0 = 1, epst = 1;
  bool moved = false;
  if (n >= 2) {
    double x1 = load.x[0];
    for (std::size_t c = 0; c < m; ++c)
      for (std::size_t k = 0; k + 1 < n; ++k) {
        const double x2 = load.x[k + 1];
        const double ya = load.y[c * n + k], yb = load.y[c * n + k + 1];
        const double d = (yb - ya) / (x2 - x1);
        if (d >= emax_loc && x1 > 0) {
          eps0 = std::min(eps0, x1);
          moved = true;
          if (x1 == eps0) epst = std::min(epst, std::abs(eps0 - ya / emax_loc));
        }
        x1 = x2;
      }
  }
  double eps_lim = eps_max;
  if (moved) {
    e0_loc = std::min(e0_loc, emax_loc);
    aa = (emax_loc - e0_loc) / epst;
    eps_lim = eps0;
  }
  if (o.e0_raised) {
    e0_loc = std::min(e0_loc, emax_loc);
    e0_run = e0_loc;
    aa = (emax_loc - e0_loc) / epst;
  }
  o.limit_moved = moved;
  o.e0 = e0_run;
  o.e_max = e_max;
  o.aa = aa;
  o.eps_max = eps_lim;
  // The first curve at the deck's strain limit (the segment found from the start, at least the first).
  if (n >= 2) {
    std::size_t k = 1;
    while (load.x[k] < eps_max && k < n - 1) ++k;
    const double xa = load.x[k - 1], xb = load.x[k];
    const double ya = load.y[k - 1], yb = load.y[k];
    o.yld_emax = ya + (yb - ya) / (xb - xa) * (eps_max - xa);
  } else if (n == 1) {
    o.yld_emax = load.y[0];
  }
  return o;
}

}  // namespace radx::model
