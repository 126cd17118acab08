// STREAM-like memory bandwidth of this machine: the four kernels of McCalpin's STREAM on three
// double arrays a, b, c of `n` elements each (default 50,000,000: 400 MB per array, 1.2 GB in all), best of
// `reps` repetitions (the first one a warm-up, left out), on 1 and 2 threads (OpenMP, static schedule, each
// thread touching its own share of the arrays first, so pages sit where they are used). Why so large: this
// machine reports a 508 MB last-level cache (getconf LEVEL3_CACHE_SIZE; an EPYC with stacked cache), and
// 3 x 80 MB arrays ran at 25 GB/s triad against 16 to 28 GB/s with 1.2 to 2.4 GB: part of the smaller set
// stayed in cache. The kernels:
//   copy   c = a            16 bytes per element (read a, write c)
//   scale  b = s c          16 bytes
//   add    c = a + b        24 bytes
//   triad  a = b + s c      24 bytes
// Bytes are counted as STREAM counts them: each array read or written once per element; the write-allocate
// read of the destination (a store miss first reads the line, unless the compiler emits non-temporal stores)
// is NOT counted. The traffic the memory bus actually carries is then up to 3/2 (copy, scale) or 4/3 (add,
// triad) of the figure printed; the "with write-allocate" column prints that upper figure too.
//
// Usage: radx_bench_stream [N] [REPS] [MAX_THREADS]   (defaults 50000000 10 2)
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <memory>
#include <string>

namespace {

struct Kernel {
  const char* name;
  double bytes_per_elem;     // STREAM's count
  double allocate_per_elem;  // extra write-allocate read of the destination
};

constexpr Kernel kKernels[4] = {{"copy", 16, 8}, {"scale", 16, 8}, {"add", 24, 8}, {"triad", 24, 8}};

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// One timed pass of kernel k over the arrays.
void run_kernel(int k, double* a, double* b, double* c, std::int64_t n, double s) {
  switch (k) {
    case 0:
#pragma omp parallel for schedule(static)
      for (std::int64_t i = 0; i < n; ++i) c[i] = a[i];
      break;
    case 1:
#pragma omp parallel for schedule(static)
      for (std::int64_t i = 0; i < n; ++i) b[i] = s * c[i];
      break;
    case 2:
#pragma omp parallel for schedule(static)
      for (std::int64_t i = 0; i < n; ++i) c[i] = a[i] + b[i];
      break;
    default:
#pragma omp parallel for schedule(static)
      for (std::int64_t i = 0; i < n; ++i) a[i] = b[i] + s * c[i];
      break;
  }
}

}  // namespace

int main(int argc, char** argv) {
  const std::int64_t n = argc > 1 ? std::atoll(argv[1]) : 50'000'000;
  const int reps = argc > 2 ? std::atoi(argv[2]) : 10;
  const int max_threads = argc > 3 ? std::atoi(argv[3]) : 2;
  if (n < 1000 || reps < 2 || max_threads < 1) {
    std::fprintf(stderr, "usage: radx_bench_stream [N >= 1000] [REPS >= 2] [MAX_THREADS >= 1]\n");
    return 2;
  }
  const auto un = static_cast<std::size_t>(n);
  std::unique_ptr<double[]> a(new double[un]), b(new double[un]), c(new double[un]);
  std::printf("arrays: 3 x %lld doubles (%.0f MB each, %.0f MB in all); best of %d repetitions\n",
              static_cast<long long>(n), 8e-6 * static_cast<double>(n), 24e-6 * static_cast<double>(n), reps);
  std::printf(
      "bytes counted as STREAM does (copy, scale 16 per element; add, triad 24), write-allocate not "
      "counted;\nthe last column adds the write-allocate read of the destination (8 per element)\n\n");
  std::printf("| threads | kernel | best GB/s | mean GB/s | with write-allocate GB/s | best time ms |\n");
  std::printf("|--------:|--------|----------:|----------:|-------------------------:|-------------:|\n");
  const double s = 3.0;
  for (int threads = 1; threads <= max_threads; ++threads) {
    omp_set_num_threads(threads);
    // First touch by the threads that will use each share.
#pragma omp parallel for schedule(static)
    for (std::int64_t i = 0; i < n; ++i) {
      a[static_cast<std::size_t>(i)] = 1.0;
      b[static_cast<std::size_t>(i)] = 2.0;
      c[static_cast<std::size_t>(i)] = 0.0;
    }
    double best[4], total[4];
    std::fill(best, best + 4, std::numeric_limits<double>::infinity());
    std::fill(total, total + 4, 0.0);
    for (int r = 0; r < reps; ++r)
      for (int k = 0; k < 4; ++k) {
        const double t0 = now();
        run_kernel(k, a.get(), b.get(), c.get(), n, s);
        const double t = now() - t0;
        if (r == 0) continue;  // the first repetition warms up (STREAM skips it too)
        total[k] += t;
        best[k] = std::min(best[k], t);
      }
    for (int k = 0; k < 4; ++k) {
      const double elems = static_cast<double>(n);
      const double gb = kKernels[k].bytes_per_elem * elems * 1e-9;
      const double gb_wa = (kKernels[k].bytes_per_elem + kKernels[k].allocate_per_elem) * elems * 1e-9;
      const double mean = total[k] / (reps - 1);
      std::printf("| %7d | %-6s | %9.2f | %9.2f | %24.2f | %12.2f |\n", threads, kKernels[k].name,
                  gb / best[k], gb / mean, gb_wa / best[k], 1e3 * best[k]);
    }
  }
  // A check that the loops ran (and were not optimised away): STREAM's own validation, on the last values.
  double sum = 0;
  for (std::int64_t i = 0; i < n; i += n / 1000) sum += a[static_cast<std::size_t>(i)];
  if (!(sum > 0)) {
    std::fprintf(stderr, "stream: unexpected array contents\n");
    return 1;
  }
  return 0;
}
