// Items finished in any order by any thread, committed in item order, region by region.
//
// The element stage computes its groups on the team's threads, in an order that changes from run to run;
// the groups' nodal forces must still be added to each node in one fixed order (group 0, then 1, ...) for
// the sums to be bit-identical for any thread count. OrderedCommit lets each group be added as soon as every
// group before it is, by whichever thread is there at that moment, instead of in a separate pass after the
// stage: the sums are made while the forces are still in cache, and on two threads beside the other's work.
//
// The order only matters node by node, so the nodes are cut into regions (the engine's node chunks) and each
// region has its own stream: the items that write into it, in item order. An item is committed into a
// region once every earlier item writing into that region is. Items far apart in the order that write into
// different regions are so committed independently: a thread running the first half of the groups and one
// running the second half each commit their own nodes as they go, and only the regions both halves write
// into wait for both. With a single region every item waits for all the items before it.
//
// Protocol, per stream: finished(k, commit) marks item k done, then, for each region item k writes into, the
// thread tries to become that stream's committer (one at a time, by an exchange on its `busy`); the
// committer commits the stream's items from `next` on while they are done. A thread that finds `busy` taken
// leaves: the committer will reach its item, unless the committer had already stopped at that item and was
// leaving, which is why a committer checks the next item again after letting go of `busy` (the two sides are
// a store then a load on two atomics, so both are sequentially consistent: at least one of them sees the
// other's store). drain() after the stage commits whatever is left on the calling thread; it never finds
// anything in flight, since the team returns only when every chunk body (and so every commit started inside
// one) has returned.
#pragma once
#include <atomic>
#include <cassert>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace radx::solver {

class OrderedCommit {
 public:
  // For a stage of `items` items that all write into one region (before any stage runs).
  void assign(std::int64_t items) {
    std::vector<std::vector<std::int32_t>> one(static_cast<std::size_t>(items), std::vector<std::int32_t>{0});
    assign(one, items > 0 ? 1 : 0);
  }

  // For a stage whose item k writes into the regions item_regions[k] (ascending, each below `regions`).
  void assign(const std::vector<std::vector<std::int32_t>>& item_regions, std::int32_t regions) {
    const auto items = item_regions.size();
    item_begin_.assign(items + 1, 0);
    item_region_.clear();
    std::vector<std::int64_t> per_region(static_cast<std::size_t>(regions) + 1, 0);
    for (std::size_t k = 0; k < items; ++k) {
      for (std::size_t s = 0; s < item_regions[k].size(); ++s) {
        const std::int32_t r = item_regions[k][s];
        assert(r >= 0 && r < regions && (s == 0 || r > item_regions[k][s - 1]));
        item_region_.push_back(r);
        ++per_region[static_cast<std::size_t>(r) + 1];
      }
      item_begin_[k + 1] = static_cast<std::int64_t>(item_region_.size());
    }
    for (std::size_t r = 0; r < static_cast<std::size_t>(regions); ++r) per_region[r + 1] += per_region[r];
    region_begin_ = per_region;
    stream_item_.assign(item_region_.size(), 0);
    stream_slot_.assign(item_region_.size(), 0);
    std::vector<std::int64_t> fill(per_region.begin(), per_region.end() - 1);
    for (std::size_t k = 0; k < items; ++k)  // items ascending: each stream lists its items in item order
      for (std::int64_t s = item_begin_[k]; s < item_begin_[k + 1]; ++s) {
        const auto at = static_cast<std::size_t>(
            fill[static_cast<std::size_t>(item_region_[static_cast<std::size_t>(s)])]++);
        stream_item_[at] = static_cast<std::int64_t>(k);
        stream_slot_[at] = static_cast<std::int32_t>(s - item_begin_[k]);
      }
    items_ = static_cast<std::int64_t>(items);
    regions_ = regions;
    done_ = std::make_unique<std::atomic<std::uint8_t>[]>(items);
    streams_ = std::make_unique<Stream[]>(static_cast<std::size_t>(regions));
    reset();
  }

  // Before a stage: nothing done, nothing committed.
  void reset() {
    for (std::int64_t k = 0; k < items_; ++k)
      done_[static_cast<std::size_t>(k)].store(0, std::memory_order_relaxed);
    for (std::int32_t r = 0; r < regions_; ++r) {
      auto& st = streams_[static_cast<std::size_t>(r)];
      assert(!st.busy.load());  // a commit left unfinished (it threw) would drop the next stages' items
      st.next.store(region_begin_[static_cast<std::size_t>(r)], std::memory_order_relaxed);
    }
  }

  // The regions item k writes into, ascending; commit(k, slot) is called for regions_of(k)[slot].
  [[nodiscard]] std::span<const std::int32_t> regions_of(std::int64_t k) const {
    const auto b = static_cast<std::size_t>(item_begin_[static_cast<std::size_t>(k)]);
    const auto e = static_cast<std::size_t>(item_begin_[static_cast<std::size_t>(k) + 1]);
    return {item_region_.data() + b, e - b};
  }

  // Item k is finished (its outputs written by this thread); commit what is now next in line in each of its
  // regions: commit(item, slot) adds item's part in its region regions_of(item)[slot].
  template <class Commit>
  void finished(std::int64_t k, Commit&& commit) {
    done_[static_cast<std::size_t>(k)].store(1);
    for (const std::int32_t r : regions_of(k)) commit_ready(r, commit);
  }

  // After the stage (every item finished): commit the rest, in order, on this thread.
  template <class Commit>
  void drain(Commit&& commit) {
    for (std::int32_t r = 0; r < regions_; ++r) commit_ready(r, commit);
  }

  // (item, region) parts committed so far, of parts() in all.
  [[nodiscard]] std::int64_t committed() const {
    std::int64_t n = 0;
    for (std::int32_t r = 0; r < regions_; ++r)
      n += streams_[static_cast<std::size_t>(r)].next.load(std::memory_order_relaxed) -
           region_begin_[static_cast<std::size_t>(r)];
    return n;
  }
  [[nodiscard]] std::int64_t parts() const { return static_cast<std::int64_t>(item_region_.size()); }

 private:
  struct alignas(64) Stream {
    std::atomic<std::int64_t> next{0};  // position in stream_item_ of the first item not committed
    std::atomic<bool> busy{false};
  };

  [[nodiscard]] bool ready(std::int32_t r, std::int64_t at) const {
    return at < region_begin_[static_cast<std::size_t>(r) + 1] &&
           done_[static_cast<std::size_t>(stream_item_[static_cast<std::size_t>(at)])].load() != 0;
  }

  template <class Commit>
  void commit_ready(std::int32_t r, Commit& commit) {
    auto& st = streams_[static_cast<std::size_t>(r)];
    for (;;) {
      if (st.busy.exchange(true)) return;  // another thread commits; see the protocol above
      std::int64_t at = st.next.load(std::memory_order_relaxed);
      for (; ready(r, at); ++at)
        commit(stream_item_[static_cast<std::size_t>(at)], stream_slot_[static_cast<std::size_t>(at)]);
      st.next.store(at, std::memory_order_relaxed);
      st.busy.store(false);
      if (!ready(r, at)) return;
    }
  }

  std::int64_t items_ = 0;
  std::int32_t regions_ = 0;
  std::vector<std::int64_t>
      item_begin_;  // [items + 1]: item k's regions are item_region_[begin[k], begin[k+1])
  std::vector<std::int32_t> item_region_;   // the regions of every item, item by item
  std::vector<std::int64_t> region_begin_;  // [regions + 1]: region r's stream is [begin[r], begin[r+1])
  std::vector<std::int64_t> stream_item_;   // every stream's items, stream by stream, in item order
  std::vector<std::int32_t> stream_slot_;   // the region's position in that item's regions_of
  std::unique_ptr<std::atomic<std::uint8_t>[]> done_;
  std::unique_ptr<Stream[]> streams_;
};

}  // namespace radx::solver
