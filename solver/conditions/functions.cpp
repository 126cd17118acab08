#include "solver/conditions/functions.hpp"

#include <algorithm>
#include <iterator>

namespace radx::solver {

double function_value(const model::Function& f, double x) {
  const std::size_t n = std::min(f.x.size(), f.y.size());
  if (n == 0) return 0.0;
  if (n == 1) return f.y[0];
  // Segment [i, i+1] containing x; clamped to the first and last segments for the extrapolation.
  const auto end = f.x.begin() + static_cast<std::ptrdiff_t>(n);
  const auto it = std::upper_bound(f.x.begin(), end, x);
  std::size_t i = it == f.x.begin() ? 0 : static_cast<std::size_t>(std::distance(f.x.begin(), it)) - 1;
  i = std::min(i, n - 2);
  const double x0 = f.x[i], x1 = f.x[i + 1];
  const double y0 = f.y[i], y1 = f.y[i + 1];
  return y0 + (y1 - y0) * (x - x0) / (x1 - x0);
}

}  // namespace radx::solver
