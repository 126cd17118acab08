// Cost of ExactSum::add (solver/model/exact_sum.hpp) against a plain double sum, in ns per term, over an
// array of N doubles (resident in cache for the default N: the kinetic-energy pass reads its terms from the
// node arrays and adds them at once), best of REPS passes. Also sums 2^31 + 7 copies of one full-significand
// value whose lowest digit is full, through the periodic carry propagation, and checks that the
// result is the product rounded once: the term count the accumulator promises.
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "solver/model/exact_sum.hpp"

namespace {

template <class F>
double best_ns_per_term(std::size_t n, int reps, F&& pass) {
  double best = 1e300;
  for (int r = 0; r < reps; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    pass();
    const std::chrono::duration<double, std::nano> dt = std::chrono::steady_clock::now() - t0;
    best = std::min(best, dt.count() / static_cast<double>(n));
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t n = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 100000;
  const int reps = argc > 2 ? std::atoi(argv[2]) : 200;
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  // Kinetic-energy-like terms: positive, spread over a few decades.
  std::vector<double> terms(n);
  for (auto& x : terms) x = std::ldexp(u(rng), -static_cast<int>(rng() % 40));

  volatile double sink = 0;
  const double plain = best_ns_per_term(n, reps, [&] {
    double s = 0;
    for (const double x : terms) s += x;
    sink = s;
  });
  const double exact = best_ns_per_term(n, reps, [&] {
    radx::model::ExactSum s;
    for (const double x : terms) s.add(x);
    sink = s.value();
  });
  const double value = best_ns_per_term(1, reps * 100, [&] {
    radx::model::ExactSum s;
    s.add(terms[0]);
    sink = s.value();
  });
  std::printf(
      "terms %zu, best of %d: plain sum %.2f ns/term, ExactSum::add %.2f ns/term, "
      "one add + value() %.0f ns\n",
      n, reps, plain, exact, value);

  // (2^53 - 1) 2^-50: its lowest digit is 2^32 - 1 (biased exponent 1025 = 1 + 32 x 32), so 2^31 + 7 terms
  // overflow an int64 bin unless the carries are propagated on the way.
  const double x = std::ldexp(9007199254740991.0, -50);
  const std::int64_t many = (std::int64_t{1} << 31) + 7;
  radx::model::ExactSum s;
  const auto t0 = std::chrono::steady_clock::now();
  for (std::int64_t i = 0; i < many; ++i) s.add(x);
  const std::chrono::duration<double> dt = std::chrono::steady_clock::now() - t0;
  const bool ok = s.value() == static_cast<double>(many) * x;
  std::printf("2^31 + 7 terms of %.17g: %s (%.2f s)\n", x, ok ? "exact" : "WRONG", dt.count());
  (void)sink;
  return ok ? 0 : 1;
}
