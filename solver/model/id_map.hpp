// User id -> dense index. User ids are any positive 64-bit integers; a direct table is used when the
// ids are dense enough (the usual case for meshes), a sorted table otherwise.
#pragma once

#include <cstdint>
#include <vector>

namespace radx::model {

class IdMap {
 public:
  // Builds the map from ids in dense order. Returns false and sets `duplicate` to the first repeated
  // id when the ids are not unique.
  bool build(const std::vector<std::int64_t>& ids, std::int64_t& duplicate);
  // Dense index of a user id, -1 when unknown.
  [[nodiscard]] std::int32_t find(std::int64_t user_id) const;
  [[nodiscard]] bool empty() const { return direct_.empty() && sorted_ids_.empty(); }

 private:
  std::int64_t base_ = 0;
  std::vector<std::int32_t> direct_;      // direct_[id - base_]
  std::vector<std::int64_t> sorted_ids_;  // sparse case
  std::vector<std::int32_t> sorted_index_;
};

}  // namespace radx::model
