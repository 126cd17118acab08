// Items finished in any order by any thread, committed strictly in item order.
//
// The element stage computes its groups on whichever thread is free, in an order that changes from run to
// run; the groups' nodal forces must still be added to the nodes in one fixed order (group 0, then 1, ...)
// for the sums to be bit-identical for any thread count. OrderedCommit lets each group be added as soon as
// every group before it is, by whichever thread is there at that moment, instead of in a separate pass after
// the stage: the sums are made while the forces are still in cache, and on two threads one thread adds
// while the other computes.
//
// Protocol: finished(k, commit) marks item k done, then the thread tries to become the committer (one at a
// time, by an exchange on `busy_`); the committer commits items next_, next_ + 1, ... while they are done.
// A thread that finds `busy_` taken leaves: the committer will reach its item, unless the committer had
// already stopped at that item and was leaving, which is why a committer checks the next item again after
// letting go of `busy_` (the two sides are a store then a load on two atomics, so both are sequentially
// consistent: at least one of them sees the other's store). drain() after the stage commits whatever is
// left on the calling thread; it never finds anything in flight, since the team returns only when every
// chunk body (and so every commit started inside one) has returned.
#pragma once
#include <atomic>
#include <cassert>
#include <cstdint>
#include <memory>

namespace radx::solver {

class OrderedCommit {
 public:
  // For a stage of `items` items (before any stage runs).
  void assign(std::int64_t items) {
    items_ = items;
    done_ = std::make_unique<std::atomic<std::uint8_t>[]>(static_cast<std::size_t>(items));
    reset();
  }

  // Before a stage: nothing done, nothing committed.
  void reset() {
    assert(!busy_.load());  // a commit left unfinished (it threw) would drop the next stages' items
    for (std::int64_t k = 0; k < items_; ++k)
      done_[static_cast<std::size_t>(k)].store(0, std::memory_order_relaxed);
    next_.store(0, std::memory_order_relaxed);
  }

  // Item k is finished (its outputs written by this thread); commit what is now next in line.
  template <class Commit>
  void finished(std::int64_t k, Commit&& commit) {
    done_[static_cast<std::size_t>(k)].store(1);
    commit_ready(commit);
  }

  // After the stage (every item finished): commit the rest, in order, on this thread.
  template <class Commit>
  void drain(Commit&& commit) {
    commit_ready(commit);
  }

  [[nodiscard]] std::int64_t committed() const { return next_.load(std::memory_order_relaxed); }

 private:
  [[nodiscard]] bool next_is_done(std::int64_t c) const {
    return c < items_ && done_[static_cast<std::size_t>(c)].load() != 0;
  }

  template <class Commit>
  void commit_ready(Commit& commit) {
    for (;;) {
      if (busy_.exchange(true)) return;  // another thread commits; see the protocol above
      std::int64_t c = next_.load(std::memory_order_relaxed);
      while (next_is_done(c)) commit(c++);
      next_.store(c, std::memory_order_relaxed);
      busy_.store(false);
      if (!next_is_done(c)) return;
    }
  }

  std::int64_t items_ = 0;
  std::unique_ptr<std::atomic<std::uint8_t>[]> done_;
  alignas(64) std::atomic<std::int64_t> next_{0};
  alignas(64) std::atomic<bool> busy_{false};
};

}  // namespace radx::solver
