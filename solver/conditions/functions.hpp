// Evaluation of a /FUNCT curve (docs/keywords.md /FUNCT; OpenRadioss engine/source/tools/curve/finter.F):
//   * between two abscissas x_i <= x <= x_{i+1}: linear interpolation
//       f(x) = y_i + (y_{i+1} - y_i) (x - x_i) / (x_{i+1} - x_i);
//   * before the first point and after the last one: LINEAR EXTRAPOLATION with the first (resp. last)
//     segment, the same formula with i = 0 (resp. i = n - 2);
//   * a single point is a constant y_0; an empty function is 0.
// Loads and imposed velocities use the scaled value (docs/theory/deck-format.md section 5.5)
//   value(t) = Fscale_y f(t / Ascale_x)            (both scales already 0 -> 1 in the model).
// The abscissas are strictly increasing (checked by the starter). No allocation; O(log n) per call.
#pragma once

#include "solver/model/model.hpp"

namespace radx::solver {

// f(x) of the function, as above.
[[nodiscard]] double function_value(const model::Function& f, double x);

// Fscale_y f(t / Ascale_x). Precondition: ascale_x != 0.
[[nodiscard]] inline double scaled_function_value(const model::Function& f, double t, double ascale_x,
                                                  double fscale_y) {
  return fscale_y * function_value(f, t / ascale_x);
}

}  // namespace radx::solver
