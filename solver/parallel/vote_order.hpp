// The order in which votes (comm.hpp) win, shared by every communicator so that one rank, P threads and
// P processes all pick the same winner:
//   a beats b  <=>  (a.value, a.key, a.rank) < (b.value, b.key, b.rank) lexicographically,
// with a NaN value below every number (a NaN step is never hidden behind a finite one, and the order stays
// total). flags combine by OR; flag_rank is the smallest rank whose own flags are set (-1: none).
// combine_votes is commutative and associative, so an all-reduce may apply it in any order.
#pragma once

#include <algorithm>
#include <cmath>

#include "solver/parallel/comm.hpp"

namespace radx::solver::parallel {

// One rank's vote as it enters the reduction: its rank, and itself as flag_rank when it has flags.
[[nodiscard]] inline Vote vote_of_rank(const Vote& mine, int rank) {
  Vote v = mine;
  v.rank = rank;
  v.flag_rank = mine.flags != 0 ? rank : -1;
  return v;
}

// True when `a` wins over `b` (the order above).
[[nodiscard]] inline bool vote_wins(const Vote& a, const Vote& b) {
  const bool a_nan = std::isnan(a.value);
  const bool b_nan = std::isnan(b.value);
  if (a_nan != b_nan) return a_nan;
  if (!a_nan && a.value != b.value) return a.value < b.value;
  if (a.key != b.key) return a.key < b.key;
  return a.rank < b.rank;
}

// Two (partial) reductions combined.
[[nodiscard]] inline Vote combine_votes(const Vote& a, const Vote& b) {
  Vote v = vote_wins(a, b) ? a : b;
  v.flags = a.flags | b.flags;
  if (a.flag_rank < 0) {
    v.flag_rank = b.flag_rank;
  } else {
    v.flag_rank = b.flag_rank < 0 ? a.flag_rank : std::min(a.flag_rank, b.flag_rank);
  }
  return v;
}

}  // namespace radx::solver::parallel
