// The engine's watchdog for a stop signal whose cycle does not end (apps/stop_deadline.hpp).
#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <thread>

#include "apps/stop_deadline.hpp"

using namespace std::chrono_literals;
using radx::app::StopDeadline;

TEST_CASE("stop deadline: a stop asked while no cycle ends expires after the grace, once") {
  std::atomic<bool> asked{false};
  std::atomic<int> expired{0};
  std::atomic<double> waited{0};
  const auto t0 = std::chrono::steady_clock::now();
  {
    StopDeadline deadline([&] { return asked.load(); },
                          [&](double w) {
                            waited = w;
                            ++expired;
                          },
                          200ms);
    std::this_thread::sleep_for(100ms);
    CHECK(expired == 0);  // nothing asked: nothing happens however long the cycle
    asked = true;
    for (int k = 0; k < 100 && expired == 0; ++k) std::this_thread::sleep_for(20ms);
  }
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  CHECK(expired == 1);
  // The grace is the minimum here (no cycle ended); the watchdog polls every 50 ms, so it acts between
  // 0.2 s and 0.2 s + a poll (and scheduling slack on a loaded machine) after the request.
  CHECK(waited >= 0.2);
  CHECK(waited < 1.5);
  CHECK(elapsed < 2.5);
}

TEST_CASE("stop deadline: a run that acts on the stop within its grace is never ended") {
  std::atomic<bool> asked{false};
  std::atomic<int> expired{0};
  {
    StopDeadline deadline([&] { return asked.load(); }, [&](double) { ++expired; }, 300ms);
    deadline.cycle_ended();
    asked = true;
    std::this_thread::sleep_for(100ms);  // the engine ends its cycle and the run within the grace
    deadline.cycle_ended();
  }  // disarmed here, before the last outputs
  std::this_thread::sleep_for(400ms);
  CHECK(expired == 0);
}

TEST_CASE("stop deadline: the grace grows with the longest cycle seen, so slow cycles are waited for") {
  StopDeadline deadline([] { return false; }, [](double) {}, 10ms);
  CHECK(deadline.grace_seconds() == Approx(0.01).epsilon(1e-9));
  std::this_thread::sleep_for(60ms);
  deadline.cycle_ended();  // a first gap of at least 60 ms: the grace is four of them
  CHECK(deadline.grace_seconds() >= 4 * 0.06);
}
