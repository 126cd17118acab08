// The engine's team of threads: deterministic division of work, each thread's own share first and the
// others' leftovers after, bounded waiting.
//
// A stage of n items is cut into chunks of a fixed size (Chunks::of), so chunk c always covers the same
// items [c * size, min((c + 1) * size, n)) whatever the thread count. Each chunk writes only its own outputs
// and reductions are combined in chunk order after the stage, so results are bit-identical for any number of
// threads and whichever thread runs a chunk.
//
// Which thread runs a chunk: every thread has a lane, its share of the stage's chunks (thread k of T: the
// k-th T-th of them, a contiguous run), and takes its own lane's chunks first, from a counter of the lane,
// then the other lanes' leftovers from the same counters. So on an idle machine a stage posted again runs
// each chunk on the same thread as last time, and the data it touches (a node range, an element group's
// state) stays in that core's cache: read on the other core, data written here moves at half the speed
// (measured on this machine's two cores: 26-35 GB/s against 51-58 GB/s). Stages over the same range in the
// same chunks (the node passes) so meet their data where the last one left it. A thread whose core another
// program is using takes fewer chunks: the others empty its lane instead of waiting for it.
//
// Waiting is bounded: a thread with nothing to do spins for at most kSpinMicroseconds (pausing), then
// sleeps on a futex (std::atomic::wait) until the next stage is posted or the last chunk is done. The
// caller never waits for a worker that has not started the stage: when the caller has run out of chunks it
// withdraws the stage from every worker still asleep (their share was done without them) and waits only
// for those holding a chunk, so a worker whose core is busy elsewhere costs the stage nothing. OpenMP's
// default (libgomp spins about 300 000 times before sleeping) makes a waiting thread hold a core that
// another job on the machine needs, and a team of 2 then ran 1.3x slower than 1 thread beside one busy core.
// The bound is long enough to bridge the short serial gaps between a cycle's stages (tens of microseconds)
// and short against a stage (milliseconds on a model worth threading).
//
// Stages too small to pay for waking a thread (fewer than two chunks, or one thread) run inline on the
// calling thread: no thread is woken.
//
// A worker can still be preempted while it holds a chunk (its core taken by another program for a time
// slice, milliseconds), and the stage then waits for it. So the team checks each shared stage: when the
// caller's wait for the workers' last chunks made the stage longer than the caller would have taken alone
// (its own time per chunk times all the chunks), the next stages run on the caller alone, 2, 4, ... up to
// kMaxSoloStages at a time while sharing keeps losing, and sharing is tried again after each such run. On a
// machine whose other cores are busy the team so falls back to one thread instead of being slower than it;
// which thread runs a chunk never changes the results.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <thread>
#include <type_traits>
#include <vector>

namespace radx::solver {

// A stage's division into chunks of `size` items (the last may be shorter).
struct Chunks {
  std::int64_t items = 0, size = 1;
  [[nodiscard]] std::int64_t count() const { return items <= 0 ? 0 : (items + size - 1) / size; }
  [[nodiscard]] std::int64_t begin(std::int64_t c) const { return c * size; }
  [[nodiscard]] std::int64_t end(std::int64_t c) const {
    return c * size + size < items ? c * size + size : items;
  }
  static Chunks of(std::int64_t items, std::int64_t size) { return Chunks{items, size > 0 ? size : 1}; }
};

class ThreadTeam {
 public:
  static constexpr int kSpinMicroseconds = 50;
  static constexpr int kMaxSoloStages = 1024;

  // threads >= 1: the calling thread plus threads - 1 workers started now and joined by the destructor.
  explicit ThreadTeam(int threads);
  ~ThreadTeam();
  ThreadTeam(const ThreadTeam&) = delete;
  ThreadTeam& operator=(const ThreadTeam&) = delete;

  [[nodiscard]] int size() const { return static_cast<int>(workers_.size()) + 1; }

  // Lane `lane`'s share of a stage of `chunks` chunks dealt to `lanes` lanes: chunks [first, first + count).
  // The shares of lanes 0 .. lanes - 1 partition [0, chunks) in order.
  struct Share {
    std::int64_t first = 0, count = 0;
  };
  static Share share(std::int64_t chunks, std::int64_t lanes, std::int64_t lane);

  // Calls body(c) exactly once for every chunk c in [0, chunks), on the team's threads, and returns when all
  // are done; in order on the calling thread when `parallel` is false (work too small to share). The body
  // must not throw and must not call run() itself.
  template <class Body>
  void run(std::int64_t chunks, Body&& body, bool parallel = true) {
    if (chunks <= 0) return;
    if (!parallel || chunks == 1 || workers_.empty() || solo_left_ > 0) {
      if (parallel && solo_left_ > 0) --solo_left_;
      for (std::int64_t c = 0; c < chunks; ++c) body(c);
      return;
    }
    using B = std::remove_reference_t<Body>;
    void* ctx = const_cast<void*>(static_cast<const void*>(&body));
    post(
        chunks, [](void* p, std::int64_t c) { (*static_cast<B*>(p))(c); }, ctx);
  }

  // The number of threads the engine uses when none is asked for: OMP_NUM_THREADS when it is set (Radioss
  // users set it), else the cores this process may run on.
  static int default_threads();

 private:
  using ChunkFn = void (*)(void*, std::int64_t);
  void post(std::int64_t chunks, ChunkFn fn, void* ctx);
  // Runs lane `lane`'s chunks, then the others'; returns how many it ran.
  std::int64_t take_chunks(std::size_t lane);
  void worker_loop(std::size_t index);

  // A thread's share of the posted stage, handed out by `next`.
  struct alignas(64) Lane {
    std::atomic<std::int64_t> next{0};
    Share share;
  };

  // The posted stage; written by the caller before it bumps `generation_`, read by the workers after.
  ChunkFn fn_ = nullptr;
  void* ctx_ = nullptr;
  std::unique_ptr<Lane[]> lanes_;                         // lane 0 the caller's, lane i + 1 worker i's
  alignas(64) std::atomic<std::uint32_t> generation_{0};  // bumped per stage; workers wait on it
  // Each worker's part in the posted stage: kPosted (not started), then kRunning and kDone, or kWithdrawn
  // when the caller finished the stage first. A worker reads the stage only after moving it to kRunning.
  enum : int { kIdle, kPosted, kRunning, kDone, kWithdrawn };
  struct alignas(64) WorkerState {
    std::atomic<int> v{kIdle};
  };
  std::unique_ptr<WorkerState[]> state_;
  std::atomic<bool> stop_{false};
  std::vector<std::thread> workers_;
  // The caller's fallback to running stages alone (caller's thread only).
  int solo_left_ = 0;  // shared-looking stages still to run alone
  int solo_next_ = 2;  // the length of the next solo run if sharing loses again
};

}  // namespace radx::solver
