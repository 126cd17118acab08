#include "apps/stop_deadline.hpp"

#include <algorithm>
#include <utility>

namespace radx::app {

namespace {

std::int64_t now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

// How often the watchdog looks at the stop request: fine enough not to add to the grace, coarse enough to
// cost nothing beside a cycle.
constexpr auto kPoll = std::chrono::milliseconds(50);

}  // namespace

StopDeadline::StopDeadline(std::function<bool()> stop_asked, std::function<void(double)> on_expired,
                           std::chrono::milliseconds min_grace)
    : stop_asked_(std::move(stop_asked)),
      on_expired_(std::move(on_expired)),
      min_grace_ns_(std::chrono::duration_cast<std::chrono::nanoseconds>(min_grace).count()),
      last_end_ns_(now_ns()),
      thread_([this](const std::stop_token& stop) { watch(stop); }) {}

StopDeadline::~StopDeadline() {
  thread_.request_stop();  // wakes the wait at once (condition_variable_any with the stop token)
}

void StopDeadline::cycle_ended() {
  const std::int64_t now = now_ns();
  const std::int64_t gap = now - last_end_ns_.exchange(now, std::memory_order_relaxed);
  if (gap > longest_gap_ns_.load(std::memory_order_relaxed))
    longest_gap_ns_.store(gap, std::memory_order_relaxed);
}

double StopDeadline::grace_seconds() const {
  return 1e-9 *
         static_cast<double>(std::max(min_grace_ns_, 4 * longest_gap_ns_.load(std::memory_order_relaxed)));
}

void StopDeadline::watch(const std::stop_token& stop) {
  std::unique_lock lock(mutex_);
  std::int64_t asked_ns = 0;
  while (!stop.stop_requested()) {
    wake_.wait_for(lock, stop, kPoll, [] { return false; });
    if (stop.stop_requested()) return;
    if (asked_ns == 0) {
      if (stop_asked_()) asked_ns = now_ns();
      continue;
    }
    // Counted from the request: the engine acts on it at the end of the cycle under way or the next one.
    const double waited = 1e-9 * static_cast<double>(now_ns() - asked_ns);
    const double grace = grace_seconds();
    if (waited > grace) {
      on_expired_(waited);
      return;
    }
  }
}

}  // namespace radx::app
