// How contact runs its pure per-chunk work on the engine's threads without knowing them (contact may not
// include solver headers): the engine gives a ParallelFor, once, that calls body(c) exactly once for every
// chunk c in [0, chunks) on whatever threads it has and returns when all are done, in any order (its own
// team may run every chunk on the calling thread). Contact cuts its work into chunks whose boundaries depend
// only on the model and the candidate list, never on the thread count, and each chunk writes only its own
// outputs; whatever crosses chunks is combined in chunk order afterwards. So the results are bit-identical
// for any ParallelFor, including one that runs the chunks in reverse
// (tests/unit/contact/test_type7_parallel.cpp).
#pragma once

#include <concepts>
#include <cstdint>
#include <functional>
#include <type_traits>

namespace radx::contact {

// A non-owning reference to a chunk body body(c): passed by value per stage without allocating. The
// referenced callable must outlive the call it is passed to.
class ChunkBody {
 public:
  template <class F>
  requires(!std::same_as<std::remove_cvref_t<F>, ChunkBody>)
      ChunkBody(F& f)  // NOLINT(google-explicit-constructor): a view, built where the body is passed
      : ctx_(const_cast<void*>(static_cast<const void*>(&f))),
        fn_([](void* p, std::int64_t c) { (*static_cast<F*>(p))(c); }) {}
  // A const temporary would bind to F& (F = const X) and leave a view that outlives it.
  template <class F>
  ChunkBody(const F&&) = delete;
  void operator()(std::int64_t c) const { fn_(ctx_, c); }

 private:
  void* ctx_;
  void (*fn_)(void*, std::int64_t);
};

// Runs body(c) for every c in [0, chunks) and returns when all are done. Empty: in order on the caller.
using ParallelFor = std::function<void(std::int64_t chunks, ChunkBody body)>;

// body(c) for every chunk: on `parallel` when given and there are at least two chunks, else in order here.
inline void run_chunks(const ParallelFor* parallel, std::int64_t chunks, ChunkBody body) {
  if (parallel != nullptr && *parallel && chunks >= 2) {
    (*parallel)(chunks, body);
    return;
  }
  for (std::int64_t c = 0; c < chunks; ++c) body(c);
}

}  // namespace radx::contact
