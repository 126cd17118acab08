// A first stop signal (SIGTERM, SIGINT) is acted on at the end of the cycle under way, so that the run ends
// on a state, a time-history row and a summary that agree. Should that cycle never end, whatever the engine
// is doing, the run must end all the same: StopDeadline watches from its own thread, and once a stop is asked
// it allows the cycle under way
//
//   grace = max(min_grace, 4 x the longest time between two cycle ends so far)
//
// from the request to end (the longest gap includes the outputs written at a cycle's end, so a large final
// state is not cut short), and then calls on_expired (the engine: say why on standard error and end with the
// signal's default action, as a second signal would). It is disarmed by its destructor, before the last
// outputs are written.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <stop_token>
#include <thread>

namespace radx::app {

class StopDeadline {
 public:
  // stop_asked: whether a stop was asked (polled; must be cheap and thread-safe). on_expired: called once,
  // from the watchdog's thread, when the grace has passed without a cycle end; it may end the process.
  StopDeadline(std::function<bool()> stop_asked, std::function<void(double waited_s)> on_expired,
               std::chrono::milliseconds min_grace = std::chrono::seconds(10));
  ~StopDeadline();
  StopDeadline(const StopDeadline&) = delete;
  StopDeadline& operator=(const StopDeadline&) = delete;

  // From the engine's thread, at the end of each cycle.
  void cycle_ended();

  // The grace a stop asked now would get, in seconds.
  [[nodiscard]] double grace_seconds() const;

 private:
  void watch(const std::stop_token& stop);

  std::function<bool()> stop_asked_;
  std::function<void(double)> on_expired_;
  std::int64_t min_grace_ns_;
  std::atomic<std::int64_t> last_end_ns_;
  std::atomic<std::int64_t> longest_gap_ns_{0};
  std::mutex mutex_;
  std::condition_variable_any wake_;
  std::jthread thread_;  // last: started once everything it reads is set
};

}  // namespace radx::app
