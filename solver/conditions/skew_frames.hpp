// The current axes of the model's skews, the one place the engine reads a skew from (OpenRadioss resol.F
// calls newskw.F at the start of every cycle, before the loads):
//   /SKEW/FIX  the axes the starter built, for the whole run;
//   /SKEW/MOV  rebuilt by update() from the current positions x^n of its nodes N1 N2 N3
//              (model::node_skew_axes), so every use in the cycle (loads at t_n, /BCS, /IMPVEL, /IMPDISP,
//              /INIVEL applied at t_n, /ACCEL, /TH/NODE) sees the frame of x^n. Before the first update() the
//              axes are the starter's, those of t = 0.
//   /FRAME/FIX and /FRAME/MOV are skews of the same construction with an origin that matters: origin()
//              is the starter's for a fixed one and the current position of N1 for a moving one.
// Users keep the skew's dense index (index(), kNone for the global frame) and read the axes when they act.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "solver/engine/node_state.hpp"
#include "solver/model/model.hpp"

namespace radx::solver {

class SkewFrames {
 public:
  explicit SkewFrames(const model::Model& m);
  // Rebuilds the moving skews (axes and origin) from s.x, s.y, s.z. Cheap when there is none.
  void update(const NodeState& s);
  // Dense index of the skew with user id `id`; kNone for 0. Throws std::out_of_range for an unknown id.
  [[nodiscard]] std::int32_t index(std::int64_t id) const { return model_.skew_index(id); }
  // Rows x', y', z' (global components) of skew `i`; the identity for kNone.
  [[nodiscard]] const std::array<double, 9>& axes(std::int32_t i) const {
    return i == model::kNone ? kGlobal : axes_[static_cast<std::size_t>(i)];
  }
  // Unit vector of axis k (0 x', 1 y', 2 z') of skew `i`, global components.
  [[nodiscard]] std::array<double, 3> axis(std::int32_t i, int k) const {
    const auto& r = axes(i);
    const auto o = 3 * static_cast<std::size_t>(k);
    return {r[o], r[o + 1], r[o + 2]};
  }
  // Origin of skew `i` (global coordinates; for a moving one that of x^n), (0, 0, 0) for kNone.
  [[nodiscard]] const std::array<double, 3>& origin(std::int32_t i) const {
    return i == model::kNone ? kZero : origins_[static_cast<std::size_t>(i)];
  }
  // True for a /FRAME/FIX or /FRAME/MOV: a position in it is measured from its origin.
  [[nodiscard]] bool is_frame(std::int32_t i) const {
    return i != model::kNone && model_.skews[static_cast<std::size_t>(i)].frame;
  }
  // (v.x', v.y', v.z') for skew `i`.
  [[nodiscard]] std::array<double, 3> on_axes(std::int32_t i, const std::array<double, 3>& v) const {
    const auto& r = axes(i);
    return {r[0] * v[0] + r[1] * v[1] + r[2] * v[2], r[3] * v[0] + r[4] * v[1] + r[5] * v[2],
            r[6] * v[0] + r[7] * v[1] + r[8] * v[2]};
  }

 private:
  static constexpr std::array<double, 9> kGlobal{1, 0, 0, 0, 1, 0, 0, 0, 1};
  static constexpr std::array<double, 3> kZero{0, 0, 0};
  const model::Model& model_;
  std::vector<std::array<double, 9>> axes_;     // one per model skew
  std::vector<std::array<double, 3>> origins_;  // one per model skew
  std::vector<std::int32_t> moving_;            // indices of the /SKEW/MOV skews
};

}  // namespace radx::solver
