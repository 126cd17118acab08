#include "solver/thread_team.hpp"

#include <sched.h>

#include <chrono>
#include <cstdlib>
#include <string>

namespace radx::solver {

namespace {

inline void cpu_pause() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#endif
}

// Spins while `value` still reads `old`, for at most kSpinMicroseconds, then sleeps until it changes.
// Returns the new value.
template <class T>
T wait_while_equal(const std::atomic<T>& value, T old) {
  using clock = std::chrono::steady_clock;
  const auto give_up = clock::now() + std::chrono::microseconds(ThreadTeam::kSpinMicroseconds);
  for (int spin = 0;; ++spin) {
    const T now = value.load(std::memory_order_acquire);
    if (now != old) return now;
    cpu_pause();
    if ((spin & 63) == 63 && clock::now() > give_up) break;
  }
  while (true) {
    value.wait(old, std::memory_order_acquire);
    const T now = value.load(std::memory_order_acquire);
    if (now != old) return now;
  }
}

}  // namespace

ThreadTeam::ThreadTeam(int threads) {
  const int workers = threads > 1 ? threads - 1 : 0;
  workers_.reserve(static_cast<std::size_t>(workers));
  for (int i = 0; i < workers; ++i) workers_.emplace_back([this] { worker_loop(); });
}

ThreadTeam::~ThreadTeam() {
  stop_.store(true, std::memory_order_relaxed);
  generation_.fetch_add(1, std::memory_order_release);
  generation_.notify_all();
  for (auto& t : workers_) t.join();
}

int ThreadTeam::default_threads() {
  if (const char* env = std::getenv("OMP_NUM_THREADS")) {
    // OMP_NUM_THREADS may list one count per nesting level ("4,2"): the first is the team's.
    char* end = nullptr;
    const long n = std::strtol(env, &end, 10);
    if (end != env && n >= 1 && n <= 1024) return static_cast<int>(n);
  }
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof(set), &set) == 0) {
    const int n = CPU_COUNT(&set);
    if (n >= 1) return n;
  }
  const unsigned hw = std::thread::hardware_concurrency();
  return hw >= 1 ? static_cast<int>(hw) : 1;
}

void ThreadTeam::take_chunks() {
  while (true) {
    const std::int64_t c = next_chunk_.fetch_add(1, std::memory_order_relaxed);
    if (c >= chunks_) return;
    fn_(ctx_, c);
  }
}

void ThreadTeam::post(std::int64_t chunks, ChunkFn fn, void* ctx) {
  fn_ = fn;
  ctx_ = ctx;
  chunks_ = chunks;
  next_chunk_.store(0, std::memory_order_relaxed);
  busy_.store(static_cast<int>(workers_.size()), std::memory_order_relaxed);
  generation_.fetch_add(1, std::memory_order_release);  // publishes the stage above
  generation_.notify_all();
  take_chunks();
  // The workers' last decrement releases their chunks' writes to this thread.
  for (int left = busy_.load(std::memory_order_acquire); left != 0;) left = wait_while_equal(busy_, left);
}

void ThreadTeam::worker_loop() {
  // The generation the team started with: a stage posted before this thread first runs is still seen.
  std::uint32_t seen = 0;
  while (true) {
    seen = wait_while_equal(generation_, seen);
    if (stop_.load(std::memory_order_relaxed)) return;
    take_chunks();
    if (busy_.fetch_sub(1, std::memory_order_acq_rel) == 1) busy_.notify_one();
  }
}

}  // namespace radx::solver
