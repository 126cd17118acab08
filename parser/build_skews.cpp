// Deck -> Model: /SKEW/FIX, the fixed frames that /BCS, /IMPVEL, /IMPDISP, /INIVEL, /CLOAD and /GRAV may
// name.
//
//   Y' = (X1, Y1, Z1), Z' = (X2, Y2, Z2) as given (a direction with only a Y (resp. Z) component is taken as
//   its sign, as Radioss does), x' = Y' x Z', y' = Z' x x', z' = Z'; each normalised. x' = 0 (Y' and Z'
//   parallel, or one of them zero) leaves no frame: an error naming the skew.
#include <cmath>
#include <string>

#include "parser/field_parse.hpp"
#include "parser/model_builder.hpp"
#include "solver/model/geometry.hpp"

namespace radx::detail {

namespace {

using V3 = model::Vec3;
using model::cross;
using model::norm;

std::string direction_text(const V3& a) {
  return "(" + number_text(a[0]) + ", " + number_text(a[1]) + ", " + number_text(a[2]) + ")";
}

}  // namespace

void ModelBuilder::build_skews() {
  std::unordered_map<std::int64_t, SourcePos> first;
  for (const auto* r : deck_.of("/SKEW/FIX")) {
    model::Skew s;
    s.id = r->id;
    s.title = r->title;
    s.origin = submodel_point(*r, {r->get_real("Ox"), r->get_real("Oy"), r->get_real("Oz")});
    // Registered before the frame is checked: a degenerate frame is one error, not one more per use.
    if (!register_id(skew_ids_, s.id, static_cast<std::int32_t>(m_.skews.size()), *r, "skew", first))
      continue;
    V3 y = {r->get_real("X1"), r->get_real("Y1"), r->get_real("Z1")};
    V3 z = {r->get_real("X2"), r->get_real("Y2"), r->get_real("Z2")};
    if (y[0] == 0 && y[2] == 0) y[1] = y[1] < 0 ? -1.0 : 1.0;
    if (z[0] == 0 && z[1] == 0) z[2] = z[2] < 0 ? -1.0 : 1.0;
    // Directions written inside a submodel turn with it.
    y = submodel_vector(*r, y);
    z = submodel_vector(*r, z);
    const V3 x = cross(y, z);
    const double lx = norm(x), lz = norm(z);
    if (!(lx > 1e-12 * norm(y) * lz) || !(lz > 0)) {
      error_at(*r, "X2", Diag::InconsistentValues,
               "the Y' direction " + direction_text(y) + " and the Z' direction " + direction_text(z) +
                   " are parallel or zero: they define no frame; give two independent directions");
      continue;
    }
    const V3 yy = cross(z, x);
    const double ly = norm(yy);
    for (int k = 0; k < 3; ++k) {
      s.axes[static_cast<std::size_t>(k)] = x[static_cast<std::size_t>(k)] / lx;
      s.axes[static_cast<std::size_t>(3 + k)] = yy[static_cast<std::size_t>(k)] / ly;
      s.axes[static_cast<std::size_t>(6 + k)] = z[static_cast<std::size_t>(k)] / lz;
    }
    m_.skews.push_back(std::move(s));
  }
}

}  // namespace radx::detail
