#include "solver/outputs/accelerometer.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace radx::solver {

Accelerometers::Accelerometers(const model::Model& m, const SkewFrames& skews) : skews_(&skews) {
  for (const auto& a : m.accelerometers) {
    if (a.node < 0 || static_cast<std::size_t>(a.node) >= m.nodes.id.size())
      throw std::runtime_error("accelerometer " + std::to_string(a.id) + ": node index " +
                               std::to_string(a.node) + " is outside the model (a corrupt model file)");
    Sensor s;
    s.node = static_cast<std::size_t>(a.node);
    s.skew = skews.index(a.skew);
    s.fcut = a.fcut;
    sensors_.push_back(s);
  }
  readings_.resize(sensors_.size());
}

namespace {

// One biquad of the Butterworth cascade (see the header), for pole angle theta.
struct Biquad {
  double b0, b1, b2, a1, a2;
  Biquad(double d, double theta) {
    const double q = 2.0 * std::sin(theta), dd = d * d;
    const double g = 1.0 / (1.0 + q * d + dd);
    b0 = dd * g;
    b1 = 2.0 * b0;
    b2 = b0;
    a1 = 2.0 * (1.0 - dd) * g;
    a2 = -(1.0 - q * d + dd) * g;
  }
  // y_n from x_n and the two past inputs and outputs; shifts the histories.
  double step(double xn, std::array<double, 2>& xh, std::array<double, 2>& yh) const {
    const double yn = b0 * xn + b1 * xh[0] + b2 * xh[1] + a1 * yh[0] + a2 * yh[1];
    xh = {xn, xh[0]};
    yh = {yn, yh[0]};
    return yn;
  }
};

}  // namespace

void Accelerometers::update(const NodeState& st, double dt12, double dt_filter) {
  for (std::size_t k = 0; k < sensors_.size(); ++k) {
    auto& s = sensors_[k];
    auto& out = readings_[k];
    const std::array<double, 3> a = {st.ax[s.node], st.ay[s.node], st.az[s.node]};
    const auto as = skews_->on_axes(s.skew, a);
    for (std::size_t d = 0; d < 3; ++d) out.velocity[d] += as[d] * dt12;
    if (!(s.fcut > 0) || !(dt_filter > 0)) {
      out.acceleration = as;
      continue;
    }
    const double f = std::min(s.fcut, 0.4 / dt_filter);
    const double dfac = std::tan(std::numbers::pi * f * dt_filter);
    const Biquad first(dfac, std::numbers::pi / 8), second(dfac, 3 * std::numbers::pi / 8);
    std::array<double, 3> filtered{};
    for (std::size_t d = 0; d < 3; ++d) {
      // The first stage's output history is the second stage's input history.
      std::array<double, 2> y_as_input = s.y[d];
      const double y = first.step(a[d], s.x[d], s.y[d]);
      filtered[d] = second.step(y, y_as_input, s.z[d]);
    }
    out.acceleration = skews_->on_axes(s.skew, filtered);
  }
}

}  // namespace radx::solver
