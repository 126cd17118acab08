// What the builders of groups, surfaces and sets share (defined in build_groups.cpp): whether a point is in a
// box, and the segments an element gives a surface.
#pragma once

#include <array>
#include <cstdint>
#include <set>
#include <vector>

#include "solver/model/model.hpp"

namespace radx::detail {

// The sorted nodes of a face: two faces with the same key are one face seen from its two sides.
using FaceKey = std::array<std::int32_t, 4>;

// Inside the box or on its boundary (OpenRadioss rdbox.F).
bool inside_box(const model::Box& b, double x, double y, double z);

// Shell e (a 4-node shell; push_shell3: a 3-node shell) as a segment of s, as the element is numbered or
// flipped.
void push_shell(const model::Model& m, model::Surface& s, std::int32_t e, bool flip);
void push_shell3(const model::Model& m, model::Surface& s, std::int32_t e, bool flip);

// The faces of `bricks`, then of `tetras`, each pointing out of its element. With `neighbours` (bricks) and
// `tetra_neighbours`, a face that another marked solid also has is an inner face and is left out; a face
// whose key is in `covered` is left out too.
void push_solid_faces(const model::Model& m, model::Surface& s, const std::vector<std::int32_t>& bricks,
                      const std::vector<std::int32_t>& tetras, const std::vector<std::uint8_t>* neighbours,
                      const std::vector<std::uint8_t>* tetra_neighbours, const std::set<FaceKey>& covered);

}  // namespace radx::detail
