// /ACCEL accelerometers: a node's acceleration on the axes of a skew (global axes for skew 0), read every
// cycle after the kinematic conditions (a = a^n final), with dt12 = (dt1 + dt2)/2 and dt2 the next step:
//
//   a_s = R a                    (R: rows x', y', z' of the skew)
//   w_s += dt12 a_s              (WX WY WZ: the velocity change integrated from the unfiltered a_s)
//   AX AY AZ = R y, y = the global acceleration through a 4-pole Butterworth low-pass of cut-off
//   f = min(Fcut, 0.4 / dt2) (dt1 on the last cycle, where dt2 = 0; Fcut 0: no filter, AX AY AZ = a_s). The
//   filter is two cascaded biquads from the bilinear transform with pre-warping, d = tan(pi f dt2), for the
//   pole angles theta = pi/8 and 3 pi/8:
//       g = 1 / (1 + 2 sin(theta) d + d^2),   b0 = d^2 g, b1 = 2 b0, b2 = b0,
//       a1 = 2 (1 - d^2) g,   a2 = -(1 - 2 sin(theta) d + d^2) g,
//       y_n = b0 x_n + b1 x_{n-1} + b2 x_{n-2} + a1 y_{n-1} + a2 y_{n-2}
//   (unit gain at zero frequency: a constant acceleration is read exactly once the start transient is gone).
// Its state starts at zero, as OpenRadioss's (accel1.F). R is the skew's frame of the cycle (SkewFrames: a
// /SKEW/MOV turns with its nodes); the filter runs on the global components, so turning axes do not disturb
// it.
#pragma once

#include <array>
#include <vector>

#include "solver/conditions/skew_frames.hpp"
#include "solver/engine/node_state.hpp"
#include "solver/model/model.hpp"

namespace radx::solver {

class Accelerometers {
 public:
  // `skews` must outlive this object.
  Accelerometers(const model::Model& m, const SkewFrames& skews);
  // dt12: the step centred on this cycle (W); dt_filter: the step the filter samples at, dt2, or dt1 on
  // the last cycle where dt2 = 0 (the filter must not fall back to the raw signal there).
  void update(const NodeState& s, double dt12, double dt_filter);
  struct Reading {
    std::array<double, 3> acceleration{};  // AX AY AZ on the skew axes (filtered when Fcut > 0)
    std::array<double, 3> velocity{};      // WX WY WZ
  };
  [[nodiscard]] const std::vector<Reading>& readings() const { return readings_; }
  [[nodiscard]] bool empty() const { return sensors_.empty(); }

 private:
  struct Sensor {
    std::size_t node = 0;
    std::int32_t skew = model::kNone;  // dense skew index
    double fcut = 0;
    // Per global component: input x, first-stage output y, second-stage output z, each at n-1 and n-2.
    std::array<std::array<double, 2>, 3> x{}, y{}, z{};
  };
  const SkewFrames* skews_;
  std::vector<Sensor> sensors_;
  std::vector<Reading> readings_;
};

}  // namespace radx::solver
