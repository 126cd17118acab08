#include "solver/engine/thread_team.hpp"

#include <sched.h>

#include <algorithm>
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
  const auto workers = static_cast<std::size_t>(threads > 1 ? threads - 1 : 0);
  state_ = std::make_unique<WorkerState[]>(workers);
  lanes_ = std::make_unique<Lane[]>(workers + 1);
  workers_.reserve(workers);
  for (std::size_t i = 0; i < workers; ++i) workers_.emplace_back([this, i] { worker_loop(i); });
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

ThreadTeam::Share ThreadTeam::share(std::int64_t chunks, std::int64_t lanes, std::int64_t lane) {
  const std::int64_t first = chunks * lane / lanes;
  return Share{first, chunks * (lane + 1) / lanes - first};
}

std::int64_t ThreadTeam::take_chunks(std::size_t lane) {
  const std::size_t lanes = workers_.size() + 1;
  std::int64_t ran = 0;
  for (std::size_t k = 0; k < lanes; ++k) {
    Lane& l = lanes_[(lane + k) % lanes];
    while (true) {
      const std::int64_t i = l.next.fetch_add(1, std::memory_order_relaxed);
      if (i >= l.share.count) break;
      fn_(ctx_, l.share.first + i);
      ++ran;
    }
  }
  return ran;
}

void ThreadTeam::post(std::int64_t chunks, ChunkFn fn, void* ctx) {
  fn_ = fn;
  ctx_ = ctx;
  const std::size_t workers = workers_.size();
  const auto lanes = static_cast<std::int64_t>(workers + 1);
  for (std::int64_t k = 0; k < lanes; ++k) {
    Lane& l = lanes_[static_cast<std::size_t>(k)];
    l.share = share(chunks, lanes, k);
    l.next.store(0, std::memory_order_relaxed);
  }
  for (std::size_t i = 0; i < workers; ++i) state_[i].v.store(kPosted, std::memory_order_release);
  generation_.fetch_add(1, std::memory_order_release);
  generation_.notify_all();
  using clock = std::chrono::steady_clock;
  const auto t0 = clock::now();
  const std::int64_t mine = take_chunks(0);
  const auto t1 = clock::now();
  // Every chunk is taken. A worker still at kPosted has not read the stage: withdraw it. The others hold
  // or held a chunk: wait for their kDone, which releases their chunks' writes to this thread.
  for (std::size_t i = 0; i < workers; ++i) {
    int seen = kPosted;
    if (state_[i].v.compare_exchange_strong(seen, kWithdrawn, std::memory_order_acq_rel)) continue;
    while (seen != kDone) seen = wait_while_equal(state_[i].v, seen);
  }
  // Did sharing pay? Alone, the caller would have taken about its time per chunk times every chunk.
  const double worked = std::chrono::duration<double>(t1 - t0).count();
  const double took = std::chrono::duration<double>(clock::now() - t0).count();
  if (mine > 0 && took > worked * static_cast<double>(chunks) / static_cast<double>(mine)) {
    solo_left_ = solo_next_;
    solo_next_ = std::min(2 * solo_next_, kMaxSoloStages);
  } else {
    solo_next_ = 2;
  }
}

void ThreadTeam::worker_loop(std::size_t index) {
  auto& state = state_[index].v;
  // The generation the team started with: a stage posted before this thread first runs is still seen.
  std::uint32_t seen = 0;
  while (true) {
    seen = wait_while_equal(generation_, seen);
    if (stop_.load(std::memory_order_relaxed)) return;
    // The stage to join is the one whose kPosted this reads (a late wake-up may find a newer stage than the
    // generation it woke for, or none: withdrawn).
    int posted = kPosted;
    if (!state.compare_exchange_strong(posted, kRunning, std::memory_order_acq_rel)) continue;
    take_chunks(index + 1);
    state.store(kDone, std::memory_order_release);
    state.notify_one();
  }
}

}  // namespace radx::solver
