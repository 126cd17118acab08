// ExactSum (solver/model/exact_sum.hpp): the same bits in any order and any split, the correctly rounded
// exact sum, and the integer sum of states that the ranks will all-reduce.
#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "solver/model/exact_sum.hpp"

using radx::model::ExactSum;

namespace {

__extension__ using Int128 = __int128;  // GCC's 128-bit integer: the exact reference below

double sum_of(const std::vector<double>& terms) {
  ExactSum s;
  for (const double x : terms) s.add(x);
  return s.value();
}

// Terms of every magnitude a run sees and more: signs mixed, exponents over [-1074, 1000], some subnormal.
std::vector<double> wide_terms(std::mt19937_64& rng, std::size_t n) {
  std::uniform_real_distribution<double> mantissa(1.0, 2.0);
  std::uniform_int_distribution<int> exponent(-1074, 1000);
  std::vector<double> v(n);
  for (auto& x : v) x = std::ldexp(mantissa(rng), exponent(rng)) * (rng() & 1u ? 1.0 : -1.0);
  return v;
}

std::uint64_t bits_of(double x) {
  return std::bit_cast<std::uint64_t>(x);
}

}  // namespace

TEST_CASE("exact sum: any order of the terms gives the same bits") {
  std::mt19937_64 rng(12345);
  // Terms of close magnitudes, where a plain sum depends on the order in its last bits, and terms of every
  // magnitude: the bits must not depend on the order at all.
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> close(10000);
  for (auto& x : close) x = u(rng);
  for (auto* terms : {&close}) {
    const double first = sum_of(*terms);
    bool plain_moved = false;
    double plain_first = 0;
    for (const double x : *terms) plain_first += x;
    for (int k = 0; k < 20; ++k) {
      std::shuffle(terms->begin(), terms->end(), rng);
      CHECK(bits_of(sum_of(*terms)) == bits_of(first));
      double plain = 0;
      for (const double x : *terms) plain += x;
      plain_moved = plain_moved || plain != plain_first;
    }
    CHECK(plain_moved);  // the case is not trivial: a plain sum does move with the order here
  }
  auto wide = wide_terms(rng, 5000);
  const double first = sum_of(wide);
  for (int k = 0; k < 20; ++k) {
    std::shuffle(wide.begin(), wide.end(), rng);
    CHECK(bits_of(sum_of(wide)) == bits_of(first));
  }
}

TEST_CASE("exact sum: cancellation leaves exactly what is left") {
  CHECK(sum_of({1e300, 1.0, -1e300}) == 1.0);
  CHECK(sum_of({1.0, 1e300, -1e300}) == 1.0);
  CHECK(sum_of({DBL_MAX, DBL_MAX, -DBL_MAX}) == DBL_MAX);  // the plain sum overflows to inf on the way
  CHECK(sum_of({1e-300, 1e300, 1e-300, -1e300}) == 2e-300);
  CHECK(sum_of({0.1, 0.2, -0.1, -0.2}) == 0.0);
  CHECK(bits_of(sum_of({5.0, -5.0})) == bits_of(0.0));  // an exact zero is +0, as x + (-x) is in IEEE
  CHECK(sum_of({}) == 0.0);
  CHECK(sum_of({-3.5}) == -3.5);
  CHECK(sum_of({-0.0, 2.0}) == 2.0);
}

TEST_CASE("exact sum: subnormal terms and sums are exact") {
  const double tiny = std::numeric_limits<double>::denorm_min();  // 2^-1074
  std::vector<double> many(1000, tiny);
  CHECK(sum_of(many) == 1000 * tiny);  // 1000 2^-1074 is a subnormal double: exact
  CHECK(sum_of({DBL_MIN, -tiny}) == std::nextafter(DBL_MIN, 0.0));  // normal minus subnormal: subnormal
  CHECK(sum_of({std::nextafter(DBL_MIN, 0.0), tiny}) == DBL_MIN);   // and back to the smallest normal
  CHECK(sum_of({1.0, tiny, -1.0}) == tiny);
  CHECK(sum_of({-tiny, -tiny}) == -2 * tiny);
}

TEST_CASE("exact sum: rounds once to nearest, ties to even, with the bits far below the tie") {
  const double two53 = 9007199254740992.0;             // 2^53: the spacing of doubles here is 2
  CHECK(sum_of({two53, 1.0}) == two53);                // tie: down to the even 2^53
  CHECK(sum_of({two53, 3.0}) == two53 + 4.0);          // tie: up to the even 2^53 + 4
  CHECK(sum_of({two53, 1.0, 1e-300}) == two53 + 2.0);  // above the tie by 1e-300: up
  CHECK(sum_of({two53, 1.0, -1e-300}) == two53);       // below the tie: down
  CHECK(sum_of({two53 + 2.0, 1.0, -1e-300}) == two53 + 2.0);
  CHECK(sum_of({-two53, -1.0, -1e-300}) == -(two53 + 2.0));  // the same, negative
  CHECK(sum_of({DBL_MAX, std::ldexp(1.0, 970)}) == std::numeric_limits<double>::infinity());  // tie at 2^1024
  CHECK(sum_of({DBL_MAX, std::ldexp(1.0, 969)}) == DBL_MAX);  // below the tie: the largest double
  CHECK(sum_of({-DBL_MAX, -DBL_MAX}) == -std::numeric_limits<double>::infinity());
}

TEST_CASE("exact sum: the correctly rounded exact sum of scaled integers") {
  // Terms k 2^e with |k| < 2^50 and e in [-60, 5] (at most 1400 terms, below 2^126): the exact sum is an
  // integer times 2^-60 that a 128-bit integer holds; its conversion to double rounds once to nearest (GCC's
  // __floattidf), and the scaling by 2^-60 is exact. That is the reference, independent of the accumulator.
  std::mt19937_64 rng(777);
  std::uniform_int_distribution<std::int64_t> k_of(-(std::int64_t{1} << 50), std::int64_t{1} << 50);
  std::uniform_int_distribution<int> e_of(-60, 5);
  for (int trial = 0; trial < 200; ++trial) {
    const int n = 1 + trial * 7;
    Int128 exact = 0;
    ExactSum s;
    for (int i = 0; i < n; ++i) {
      const std::int64_t k = k_of(rng);
      const int e = e_of(rng);
      exact += static_cast<Int128>(k) << (e + 60);
      const double x = std::ldexp(static_cast<double>(k), e);  // exact: |k| < 2^53
      s.add(x);
    }
    const double reference = std::ldexp(static_cast<double>(exact), -60);
    CHECK(bits_of(s.value()) == bits_of(reference));
  }
}

TEST_CASE("exact sum: merging partial sums equals the sequential sum") {
  std::mt19937_64 rng(99);
  const auto terms = wide_terms(rng, 3000);
  ExactSum all;
  for (const double x : terms) all.add(x);
  for (const std::size_t parts : {2u, 3u, 7u, 64u}) {
    std::vector<ExactSum> part(parts);
    for (std::size_t i = 0; i < terms.size(); ++i) part[(i * 2654435761u) % parts].add(terms[i]);
    ExactSum merged;
    for (std::size_t p = parts; p-- > 0;) merged.merge(part[p]);
    CHECK(merged == all);
    CHECK(bits_of(merged.value()) == bits_of(all.value()));
  }
}

TEST_CASE("exact sum: states summed as integers over ranks equal the sequential sum") {
  // What Comm::sum_exact does: each rank normalises its accumulator and the ranks' states are added element
  // by element as int64; from_state of that sum is the accumulator of every rank's terms.
  std::mt19937_64 rng(2024);
  const std::size_t ranks = 1000;
  std::vector<ExactSum> rank_sum(ranks);
  ExactSum sequential;
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::size_t r = 0; r < ranks; ++r) {
    for (int i = 0; i < 20; ++i) {
      // Large terms of one sign on many ranks: every bin below the top is near 2^32 on every rank, the worst
      // case for the integer sum.
      const double x = i == 0 ? DBL_MAX * (r % 3 == 0 ? -1.0 : 1.0) : std::ldexp(u(rng), -1074 + 53 * i);
      rank_sum[r].add(x);
      sequential.add(x);
    }
  }
  const ExactSum finite = sequential;
  rank_sum[17].add(std::numeric_limits<double>::infinity());
  sequential.add(std::numeric_limits<double>::infinity());
  std::vector<std::int64_t> summed(ExactSum::kStateSize, 0);
  for (auto& s : rank_sum) {
    s.normalise();
    const auto st = s.state();
    for (std::size_t i = 0; i < st.size(); ++i) {
      if (i + 1 < ExactSum::kBins) CHECK((st[i] >= 0 && st[i] < (std::int64_t{1} << 32)));  // a digit
      summed[i] += st[i];
    }
  }
  CHECK(ExactSum::from_state(summed) == sequential);
  CHECK(ExactSum::from_state(summed).value() == std::numeric_limits<double>::infinity());
  summed[ExactSum::kBins] -= 1;  // rank 17's infinity out again: the finite terms alone
  CHECK(ExactSum::from_state(summed) == finite);
  CHECK(bits_of(ExactSum::from_state(summed).value()) == bits_of(finite.value()));
}

TEST_CASE("exact sum: infinities and NaN are kept as IEEE addition keeps them") {
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK(sum_of({1.0, inf, 2.0}) == inf);
  CHECK(sum_of({-inf, 1e300}) == -inf);
  CHECK(sum_of({inf, inf}) == inf);
  CHECK(std::isnan(sum_of({inf, 1.0, -inf})));  // +inf + -inf = NaN
  CHECK(std::isnan(sum_of({1.0, nan})));
  CHECK(std::isnan(sum_of({nan, inf})));
  ExactSum a, b;
  a.add(inf);
  b.add(-inf);
  a.merge(b);
  CHECK(std::isnan(a.value()));
}

TEST_CASE("exact sum: every bin keeps its carry over many terms") {
  // 3 x 2^24 + 5 terms of a full-significand value near the top of the range: each term puts close to 2^32
  // into three bins. The exact sum is n x, so its correct rounding is the (once rounded) product n * x.
  const double x = std::ldexp(1.9999999999999998, 1000);
  const std::int64_t n = 3 * (std::int64_t{1} << 24) + 5;
  ExactSum s;
  for (std::int64_t i = 0; i < n; ++i) s.add(x);
  CHECK(s.value() == static_cast<double>(n) * x);
  ExactSum neg;
  for (std::int64_t i = 0; i < n; ++i) neg.add(-x);
  neg.merge(s);
  CHECK(bits_of(neg.value()) == bits_of(0.0));
}
