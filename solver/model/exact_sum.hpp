// ExactSum: a sum of doubles with no rounding until it is read, so that it gives the same bits in any order
// of its terms and over any split of them between threads or ranks (docs/theory/elements.md 8.1, "Order-free
// sums").
//
// Every finite double is an integer multiple of 2^-1074 (the smallest subnormal): x = (-1)^s m 2^(e - 1075)
// with the 53-bit significand m = 2^52 + f for a biased exponent e >= 1 and m = f, e = 1 for subnormals. So
// x = (-1)^s m 2^p 2^-1074, p = max(e, 1) - 1 in [0, 2045], and the sum of any finite doubles is the integer
//   N = sum_i (-1)^s_i m_i 2^p_i
// times 2^-1074. N is held in 32-bit digits, digit b of weight 2^(32 b) (a fixed-point accumulator over the
// whole exponent range, as in Kulisch's long accumulator and the "superaccumulator" of Collange, Defour,
// Graillat and Iakymchuk, ExBLAS). A term m 2^p, p = 32 b + r, is m 2^r (at most 84 bits) split into three
// digits added to bins b, b+1, b+2 as signed 64-bit integers: exact. Each bin takes less than 2^32 per
// term, so 2^30 terms fit in an int64 bin before carries are propagated (normalise: each bin but the last
// brought to [0, 2^32), its carry added to the next, the last bin signed); add() normalises on its own every
// 2^30 terms. Top: a finite double is below 2^1024 = 2^2098 units; 2^31 terms of it and 2^20 ranks' sums
// stay below 2^2149, inside the 68 bins (2^2176) with the top bin as a signed overflow digit.
//
// value() normalises a copy, takes the sign from the top bin (the lower digits are non-negative), turns the
// digits into |N| and rounds |N| 2^-1074 to the nearest double once, ties to even: correctly rounded. N = 0
// gives +0.0. A sum too large for a double gives +-inf, as IEEE rounding of the exact sum would.
//
// Non-finite terms are counted apart (+inf, -inf, NaN); value() returns what IEEE addition of the terms in
// any order gives: NaN when any NaN or both infinities were added, else the infinity added.
//
// state(): the bins and the three counters as int64 values; after normalise() every bin but the top lies in
// [0, 2^32) and the counters stay below 2^32 when each holder added fewer than 2^31 terms, so the
// element-wise integer sum of the states of up to 2^20 holders (threads, ranks: Comm::sum_exact) is exact and
// from_state() of that sum is the accumulator of all their terms.
#pragma once

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <stdexcept>

namespace radx::model {

class ExactSum {
 public:
  static constexpr int kDigitBits = 32;
  static constexpr std::size_t kBins = 68;
  static constexpr std::size_t kStateSize = kBins + 3;  // bins, then +inf, -inf and NaN counts
  // Terms between two carry propagations: each adds less than 2^32 to a bin, so a bin stays below 2^62 + the
  // normalised digit.
  static constexpr std::int64_t kTermsPerNormalise = std::int64_t{1} << 30;

  ExactSum() { state_.fill(0); }
  explicit ExactSum(double x) : ExactSum() { add(x); }

  // Adds x exactly. Branches only on a non-finite x and on the rare carry propagation.
  void add(double x) {
    const auto bits = std::bit_cast<std::uint64_t>(x);
    const auto biased = static_cast<std::uint32_t>((bits >> 52) & 0x7ffu);
    if (biased == 0x7ffu) [[unlikely]] {
      add_non_finite(x);
      return;
    }
    const std::uint64_t normal = biased != 0 ? 1u : 0u;
    const std::uint64_t m = (bits & ((std::uint64_t{1} << 52) - 1)) | (normal << 52);
    const std::uint32_t p = biased - static_cast<std::uint32_t>(normal);
    const std::size_t b = p / kDigitBits;
    const std::uint32_t r = p % kDigitBits;
    const std::uint64_t shifted_low = m << r;          // the low 64 bits of m 2^r
    const std::uint64_t high = m >> (kDigitBits - r);  // m 2^r / 2^32, r < 32 so the shift is 1..32
    // Two's-complement negation by the sign bit: (d ^ -s) + s is d for s = 0 and -d for s = 1.
    const auto s = static_cast<std::int64_t>(bits >> 63);
    const auto signed_digit = [s](std::uint64_t d) { return (static_cast<std::int64_t>(d) ^ -s) + s; };
    state_[b] += signed_digit(shifted_low & kDigitMask);
    state_[b + 1] += signed_digit(high & kDigitMask);
    state_[b + 2] += signed_digit(high >> kDigitBits);
    if (++pending_ == kTermsPerNormalise) [[unlikely]]
      normalise();
  }

  ExactSum& operator+=(double x) {
    add(x);
    return *this;
  }

  // Adds every term of `other`, exactly.
  void merge(const ExactSum& other) {
    ExactSum o = other;
    o.normalise();
    normalise();
    for (std::size_t i = 0; i < kStateSize; ++i) state_[i] += o.state_[i];
    normalise();
  }

  // Propagates the carries: bins 0..kBins-2 to [0, 2^32), the top bin signed. The value is unchanged.
  void normalise() {
    for (std::size_t i = 0; i + 1 < kBins; ++i) {
      const std::int64_t carry = state_[i] >> kDigitBits;  // floor division by 2^32
      state_[i] -= carry * (std::int64_t{1} << kDigitBits);
      state_[i + 1] += carry;
    }
    pending_ = 0;
  }

  // The bins and counters (see the file comment). Call normalise() first when the state is to be summed with
  // other holders' states.
  [[nodiscard]] std::span<const std::int64_t, kStateSize> state() const { return state_; }

  // The accumulator whose state is `summed`: the element-wise sum of normalised states (of up to 2^20
  // holders of fewer than 2^31 terms each).
  [[nodiscard]] static ExactSum from_state(std::span<const std::int64_t> summed) {
    if (summed.size() != kStateSize) throw std::invalid_argument("ExactSum::from_state: wrong state size");
    ExactSum e;
    for (std::size_t i = 0; i < kStateSize; ++i) e.state_[i] = summed[i];
    e.normalise();
    return e;
  }

  // The sum rounded once to the nearest double, ties to even.
  [[nodiscard]] double value() const {
    const std::int64_t pos_inf = state_[kBins], neg_inf = state_[kBins + 1], nan = state_[kBins + 2];
    if (nan != 0 || (pos_inf != 0 && neg_inf != 0)) return std::numeric_limits<double>::quiet_NaN();
    if (pos_inf != 0) return std::numeric_limits<double>::infinity();
    if (neg_inf != 0) return -std::numeric_limits<double>::infinity();
    ExactSum n = *this;
    n.normalise();
    auto& d = n.state_;
    const bool negative = d[kBins - 1] < 0;
    if (negative) {  // |N|: negate every digit, then bring them back to [0, 2^32)
      for (std::size_t i = 0; i < kBins; ++i) d[i] = -d[i];
      n.normalise();
    }
    std::size_t top = kBins;
    while (top > 0 && d[top - 1] == 0) --top;
    if (top == 0) return 0.0;
    const double magnitude = round_digits(d, top - 1);
    return negative ? -magnitude : magnitude;
  }

  friend bool operator==(const ExactSum& a, const ExactSum& b) {
    ExactSum x = a, y = b;
    x.normalise();
    y.normalise();
    return x.state_ == y.state_;
  }

 private:
  static constexpr std::uint64_t kDigitMask = (std::uint64_t{1} << kDigitBits) - 1;

  void add_non_finite(double x) {
    if (std::isnan(x))
      ++state_[kBins + 2];
    else
      ++state_[x > 0 ? kBins : kBins + 1];
  }

  // |N| 2^-1074 to nearest, ties to even, from normalised non-negative digits with the top one at `h`.
  // The window of digits h..h-3 (128 bits, the leading one in its top 32) holds the 53 kept bits, the
  // rounding bit and part of the rest; the digits below only say whether the rest is zero (sticky).
  static double round_digits(const std::array<std::int64_t, kStateSize>& d, std::size_t h) {
    const auto digit = [&](std::ptrdiff_t i) {
      return i >= 0 ? static_cast<std::uint64_t>(d[static_cast<std::size_t>(i)]) : std::uint64_t{0};
    };
    const auto hi = static_cast<std::ptrdiff_t>(h);
    const std::uint64_t upper = (digit(hi) << kDigitBits) | digit(hi - 1);      // window bits 64..127
    const std::uint64_t lower = (digit(hi - 2) << kDigitBits) | digit(hi - 3);  // window bits 0..63
    bool sticky = false;
    for (std::ptrdiff_t i = hi - 4; i >= 0 && !sticky; --i) sticky = digit(i) != 0;
    const int window_exponent = kDigitBits * static_cast<int>(hi - 3) - 1074;  // weight of window bit 0
    const int length = 128 - std::countl_zero(upper);  // upper != 0: digit h is not zero
    const int drop = length - 53;  // window bits below the kept 53 (>= 44: digit h-1 is whole)
    // The kept bits, the first dropped bit (round) and whether any later bit is set.
    std::uint64_t kept;
    bool round_bit, rest;
    if (drop >= 64) {
      kept = upper >> (drop - 64);
      round_bit = drop - 65 >= 0 ? ((upper >> (drop - 65)) & 1u) != 0 : (lower >> 63) != 0;
      const std::uint64_t upper_rest = drop - 65 > 0 ? upper & ((std::uint64_t{1} << (drop - 65)) - 1) : 0;
      rest = upper_rest != 0 || (drop - 65 >= 0 ? lower != 0 : (lower << 1) != 0);
    } else {
      kept = (upper << (64 - drop)) | (lower >> drop);
      round_bit = ((lower >> (drop - 1)) & 1u) != 0;
      rest = drop - 1 > 0 && (lower & ((std::uint64_t{1} << (drop - 1)) - 1)) != 0;
    }
    rest = rest || sticky;
    if (round_bit && (rest || (kept & 1u) != 0)) ++kept;  // kept may reach 2^53: still exact in a double
    // kept < 2^54 is exact as a double; ldexp is exact for a normal result and overflows to inf, which is
    // where round-to-nearest puts sums of 2^1024 - 2^970 and above. A subnormal sum has fewer than 53 bits
    // (top digit below digit 2 and no dropped bit): it is the exact kept 2^exponent.
    return std::ldexp(static_cast<double>(kept), window_exponent + drop);
  }

  std::array<std::int64_t, kStateSize> state_;
  std::int64_t pending_ = 0;  // terms since the last normalise()
};

}  // namespace radx::model
