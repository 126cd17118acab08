#include "solver/model/id_map.hpp"

#include <algorithm>
#include <numeric>

namespace radx::model {

bool IdMap::build(const std::vector<std::int64_t>& ids, std::int64_t& duplicate) {
  direct_.clear();
  sorted_ids_.clear();
  sorted_index_.clear();
  if (ids.empty()) return true;
  const auto [lo_it, hi_it] = std::minmax_element(ids.begin(), ids.end());
  const std::int64_t lo = *lo_it;
  const std::int64_t hi = *hi_it;
  // A direct table costs 4 bytes per id in the range; accept up to 4 slots per id.
  if (hi - lo < 4 * static_cast<std::int64_t>(ids.size()) + 1024) {
    base_ = lo;
    direct_.assign(static_cast<std::size_t>(hi - lo + 1), -1);
    for (std::size_t i = 0; i < ids.size(); ++i) {
      auto& slot = direct_[static_cast<std::size_t>(ids[i] - lo)];
      if (slot >= 0) {
        duplicate = ids[i];
        return false;
      }
      slot = static_cast<std::int32_t>(i);
    }
    return true;
  }
  std::vector<std::int32_t> order(ids.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::int32_t a, std::int32_t b) { return ids[a] < ids[b]; });
  sorted_ids_.resize(ids.size());
  sorted_index_.resize(ids.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    sorted_ids_[k] = ids[order[k]];
    sorted_index_[k] = order[k];
    if (k > 0 && sorted_ids_[k] == sorted_ids_[k - 1]) {
      duplicate = sorted_ids_[k];
      return false;
    }
  }
  return true;
}

std::int32_t IdMap::find(std::int64_t user_id) const {
  if (!direct_.empty()) {
    const std::int64_t k = user_id - base_;
    if (k < 0 || k >= static_cast<std::int64_t>(direct_.size())) return -1;
    return direct_[static_cast<std::size_t>(k)];
  }
  const auto it = std::lower_bound(sorted_ids_.begin(), sorted_ids_.end(), user_id);
  if (it == sorted_ids_.end() || *it != user_id) return -1;
  return sorted_index_[static_cast<std::size_t>(it - sorted_ids_.begin())];
}

}  // namespace radx::model
