#include "solver/conditions/skew_frames.hpp"

#include "solver/model/geometry.hpp"

namespace radx::solver {

SkewFrames::SkewFrames(const model::Model& m) : model_(m) {
  axes_.reserve(m.skews.size());
  origins_.reserve(m.skews.size());
  for (std::size_t k = 0; k < m.skews.size(); ++k) {
    axes_.push_back(m.skews[k].axes);
    origins_.push_back(m.skews[k].origin);
    if (m.skews[k].moving()) moving_.push_back(static_cast<std::int32_t>(k));
  }
}

void SkewFrames::update(const NodeState& s) {
  auto at = [&](std::int32_t n) {
    const auto k = static_cast<std::size_t>(n);
    return model::Vec3{s.x[k], s.y[k], s.z[k]};
  };
  for (const auto i : moving_) {
    const auto& sk = model_.skews[static_cast<std::size_t>(i)];
    axes_[static_cast<std::size_t>(i)] = model::node_skew_axes(at(sk.n1), at(sk.n2), at(sk.n3), sk.dir);
    origins_[static_cast<std::size_t>(i)] = at(sk.n1);
  }
}

}  // namespace radx::solver
