// What every communicator must do, as checks one rank runs (the same on the loopback threads of the unit
// tests and on the MPI processes of tests/mpi/test_comm_mpi.cpp). Each returns what this rank saw wrong
// (empty: nothing), so the caller can report it from the main thread or from rank 0. Expected values come
// from loops over all ranks' inputs, which every rank can form itself; comparisons are exact (==): a
// communicator moves and combines values, it never rounds them.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

#include "solver/parallel/comm.hpp"

namespace radx::test::comm_checks {

using solver::parallel::Buffer;
using solver::parallel::Comm;
using solver::parallel::Vote;

using Failures = std::vector<std::string>;

inline void expect(Failures& f, const Comm& comm, bool ok, const std::string& what) {
  if (!ok) f.push_back("rank " + std::to_string(comm.rank()) + ": " + what);
}

// --- keyed sums --------------------------------------------------------------------------------------------
// Node j (owned by rank j % P) sums terms k = 0..K-1 in key order, as the serial loop does. Term (j, k) is
// made by rank (3j + 5k) % P and shipped to the owner with its key, in reverse key order (the sender's own
// order). The terms alternate +-1e16 with small values: added in another order they round to other sums.
struct KeyedTerm {
  std::int64_t node;
  std::int64_t key;
  double value;
};
inline constexpr int kKeyedNodes = 7;
inline constexpr int kKeyedTerms = 12;

inline double keyed_term(int node, int key) {
  switch (key % 4) {
    case 0: return 1e16;
    case 1: return 1.0 + 0.25 * node + 1e-3 * key;
    case 2: return -1e16;
    default: return 3.0 - 0.5 * node;
  }
}

inline double serial_keyed_sum(int node) {
  double s = 0;
  for (int k = 0; k < kKeyedTerms; ++k) s += keyed_term(node, k);
  return s;
}

inline Failures check_keyed_sums(Comm& comm) {
  Failures f;
  const int P = comm.size();
  const int me = comm.rank();
  std::vector<std::vector<KeyedTerm>> outgoing(static_cast<std::size_t>(P));
  for (int k = kKeyedTerms - 1; k >= 0; --k)
    for (int j = 0; j < kKeyedNodes; ++j)
      if ((3 * j + 5 * k) % P == me)
        outgoing[static_cast<std::size_t>(j % P)].push_back({j, k, keyed_term(j, k)});
  std::vector<Buffer> to_rank(static_cast<std::size_t>(P));
  for (std::size_t r = 0; r < to_rank.size(); ++r) {
    to_rank[r].resize(outgoing[r].size() * sizeof(KeyedTerm));
    if (!outgoing[r].empty()) std::memcpy(to_rank[r].data(), outgoing[r].data(), to_rank[r].size());
  }
  const std::vector<Buffer> received = comm.exchange(to_rank);
  expect(f, comm, received.size() == static_cast<std::size_t>(P), "exchange returned a message count not P");
  std::vector<KeyedTerm> mine;
  for (const auto& b : received) {
    const std::size_t n = b.size() / sizeof(KeyedTerm);
    const std::size_t at = mine.size();
    mine.resize(at + n);
    if (n > 0) std::memcpy(mine.data() + at, b.data(), n * sizeof(KeyedTerm));
  }
  // The owner restores the serial order from the keys, whatever order the terms arrived in.
  std::sort(mine.begin(), mine.end(), [](const KeyedTerm& a, const KeyedTerm& b) {
    return std::tie(a.node, a.key) < std::tie(b.node, b.key);
  });
  std::vector<double> sums(kKeyedNodes, 0.0);
  std::vector<int> counts(kKeyedNodes, 0);
  for (const auto& t : mine) {
    sums[static_cast<std::size_t>(t.node)] += t.value;
    ++counts[static_cast<std::size_t>(t.node)];
  }
  bool order_matters = false;
  for (int j = 0; j < kKeyedNodes; ++j) {
    double reversed = 0;
    for (int k = kKeyedTerms - 1; k >= 0; --k) reversed += keyed_term(j, k);
    order_matters = order_matters || reversed != serial_keyed_sum(j);
    if (j % P != me) {
      expect(f, comm, counts[static_cast<std::size_t>(j)] == 0, "received terms of a node it does not own");
      continue;
    }
    expect(f, comm, counts[static_cast<std::size_t>(j)] == kKeyedTerms,
           "node " + std::to_string(j) + ": " + std::to_string(counts[static_cast<std::size_t>(j)]) +
               " terms of " + std::to_string(kKeyedTerms));
    expect(f, comm, sums[static_cast<std::size_t>(j)] == serial_keyed_sum(j),
           "node " + std::to_string(j) + ": keyed sum " + std::to_string(sums[static_cast<std::size_t>(j)]) +
               " differs from the serial loop's " + std::to_string(serial_keyed_sum(j)));
  }
  expect(f, comm, order_matters,
         "the keyed terms add to the same sum in any order: the check proves nothing");
  return f;
}

// --- votes -------------------------------------------------------------------------------------------------
// The winner by the rule of comm.hpp, found by brute force over every rank's vote.
inline Vote expected_vote(const std::vector<Vote>& by_rank) {
  Vote best{};
  bool first = true;
  std::uint32_t flags = 0;
  int flag_rank = -1;
  for (int r = 0; r < static_cast<int>(by_rank.size()); ++r) {
    const Vote& v = by_rank[static_cast<std::size_t>(r)];
    flags |= v.flags;
    if (v.flags != 0 && flag_rank < 0) flag_rank = r;
    if (first || std::make_tuple(v.value, v.key, r) < std::make_tuple(best.value, best.key, best.rank)) {
      best = v;
      best.rank = r;
      first = false;
    }
  }
  best.flags = flags;
  best.flag_rank = flag_rank;
  return best;
}

inline bool same_vote(const Vote& a, const Vote& b) {
  const bool same_value = a.value == b.value || (std::isnan(a.value) && std::isnan(b.value));
  return same_value && a.key == b.key && a.flags == b.flags && a.rank == b.rank && a.flag_rank == b.flag_rank;
}

inline std::string describe(const Vote& v) {
  return "{value " + std::to_string(v.value) + ", key " + std::to_string(v.key) + ", flags " +
         std::to_string(v.flags) + ", rank " + std::to_string(v.rank) + ", flag_rank " +
         std::to_string(v.flag_rank) + "}";
}

inline Failures check_votes(Comm& comm) {
  Failures f;
  const int P = comm.size();
  using Case = Vote (*)(int rank, int ranks);
  struct Named {
    const char* name;
    Case make;
  };
  const Named cases[] = {
      // Distinct values: the smallest wins, here the last rank's.
      {"distinct values",
       [](int r, int) {
         return Vote{10.0 - r, 7, 0};
       }},
      // Equal values: the smallest key wins, again the last rank's.
      {"equal values",
       [](int r, int) {
         return Vote{1.5, 100 - r, 0};
       }},
      // Equal values and keys: the lowest rank wins.
      {"equal values and keys",
       [](int, int) {
         return Vote{1.5, 42, 0};
       }},
      // Flags: OR-ed; flag_rank is the lowest rank with any (rank 0 has none).
      {"flags",
       [](int r, int) {
         return Vote{2.0, r, r == 0 ? 0u : (1u << (r % 3))};
       }},
      // A step that is not a number wins over every number, so no rank can miss it.
      {"NaN value",
       [](int r, int n) {
         return Vote{r == n - 1 ? std::numeric_limits<double>::quiet_NaN() : 1.0, r, 0};
       }},
  };
  for (const auto& c : cases) {
    std::vector<Vote> all;
    for (int r = 0; r < P; ++r) all.push_back(c.make(r, P));
    Vote mine = all[static_cast<std::size_t>(comm.rank())];
    mine.rank = 12345;  // filled by the reduction: what the caller leaves there does not count
    mine.flag_rank = 777;
    const Vote got = comm.vote(mine);
    Vote want = expected_vote(all);
    if (std::isnan(all.back().value)) {
      // The brute-force tuple order knows no NaN: the NaN voter, the last rank, wins.
      want = all.back();
      want.rank = P - 1;
      want.flag_rank = -1;
    }
    const bool ok = same_vote(got, want);
    expect(f, comm, ok,
           std::string("vote, ") + c.name + ": got " + describe(got) + ", want " + describe(want));
  }
  return f;
}

// --- max, exact sums, OR -----------------------------------------------------------------------------------
inline std::vector<double> max_input(int r, int P) {
  return {-(r + 1.0), 1.5 * r, r == P / 2 ? 1e300 : -1e300, r == 0 ? -0.0 : -1.0};
}

inline Failures check_max(Comm& comm) {
  Failures f;
  const int P = comm.size();
  std::vector<double> values = max_input(comm.rank(), P);
  std::vector<double> want = max_input(0, P);
  for (int r = 1; r < P; ++r) {
    const auto v = max_input(r, P);
    for (std::size_t i = 0; i < want.size(); ++i) want[i] = std::max(want[i], v[i]);
  }
  comm.max(values);
  for (std::size_t i = 0; i < want.size(); ++i)
    expect(f, comm, values[i] == want[i],
           "max entry " + std::to_string(i) + ": " + std::to_string(values[i]) + ", want " +
               std::to_string(want[i]));
  return f;
}

// Bins that cancel over the ranks (c * (2r - (P - 1)) sums to 0), and one near 2^60 per rank whose total
// needs all 63 bits for P = 5: an integer sum is exact whatever the order.
inline Failures check_sum_exact(Comm& comm) {
  Failures f;
  const std::int64_t P = comm.size();
  const std::int64_t r = comm.rank();
  const std::int64_t big = std::int64_t{1} << 60;
  std::vector<std::int64_t> bins = {(2 * r - (P - 1)) * 123456789,
                                    (2 * r - (P - 1)) * (std::int64_t{1} << 58), big + r, -r * r};
  comm.sum_exact(bins);
  std::int64_t squares = 0;
  for (std::int64_t k = 0; k < P; ++k) squares += k * k;
  const std::vector<std::int64_t> want = {0, 0, P * big + P * (P - 1) / 2, -squares};
  for (std::size_t i = 0; i < want.size(); ++i)
    expect(f, comm, bins[i] == want[i],
           "sum_exact bin " + std::to_string(i) + ": " + std::to_string(bins[i]) + ", want " +
               std::to_string(want[i]));
  return f;
}

inline Failures check_bit_or(Comm& comm) {
  Failures f;
  const int P = comm.size();
  std::vector<std::uint64_t> words = {std::uint64_t{1} << (comm.rank() % 64),
                                      comm.rank() == P - 1 ? ~0ull : 0ull};
  comm.bit_or(words);
  std::uint64_t want0 = 0;
  for (int r = 0; r < P; ++r) want0 |= std::uint64_t{1} << (r % 64);
  expect(f, comm, words[0] == want0 && words[1] == ~0ull, "bit_or: wrong words");
  return f;
}

// --- messages ----------------------------------------------------------------------------------------------
// Rank `from`'s message to rank `to`: 0, 4 or 8 bytes (some empty for P >= 2), each naming both ranks.
inline Buffer message(int from, int to) {
  Buffer b(static_cast<std::size_t>(((from + 2 * to) % 3) * 4));
  for (std::size_t i = 0; i < b.size(); ++i)
    b[i] = static_cast<std::byte>(from * 16 + to + static_cast<int>(i));
  return b;
}

// Rank `r`'s message to a gather or broadcast: rank 1's is empty, the others r + 2 bytes.
inline Buffer own_message(int r) {
  Buffer b(r == 1 ? 0 : static_cast<std::size_t>(r + 2));
  for (std::size_t i = 0; i < b.size(); ++i) b[i] = static_cast<std::byte>(r * 7 + static_cast<int>(i));
  return b;
}

inline Failures check_messages(Comm& comm) {
  Failures f;
  const int P = comm.size();
  const int me = comm.rank();
  std::vector<Buffer> to_rank;
  for (int d = 0; d < P; ++d) to_rank.push_back(message(me, d));
  const auto got = comm.exchange(to_rank);
  expect(f, comm, got.size() == static_cast<std::size_t>(P), "exchange: not one message per rank");
  for (int s = 0; s < P && s < static_cast<int>(got.size()); ++s)
    expect(f, comm, got[static_cast<std::size_t>(s)] == message(s, me),
           "exchange: wrong message from rank " + std::to_string(s));

  const int root = P - 1;  // a root other than 0 when P > 1
  const auto gathered = comm.gather(own_message(me), root);
  if (me == root) {
    expect(f, comm, gathered.size() == static_cast<std::size_t>(P),
           "gather: not one message per rank at the root");
    for (int s = 0; s < P && s < static_cast<int>(gathered.size()); ++s)
      expect(f, comm, gathered[static_cast<std::size_t>(s)] == own_message(s),
             "gather: wrong message from rank " + std::to_string(s));
  } else {
    expect(f, comm, gathered.empty(), "gather: a rank other than the root got messages");
  }

  const auto everyone = comm.all_gather(own_message(me));
  expect(f, comm, everyone.size() == static_cast<std::size_t>(P), "all_gather: not one message per rank");
  for (int s = 0; s < P && s < static_cast<int>(everyone.size()); ++s)
    expect(f, comm, everyone[static_cast<std::size_t>(s)] == own_message(s),
           "all_gather: wrong message from rank " + std::to_string(s));

  const int bcast_root = P / 2;
  Buffer data(static_cast<std::size_t>(1000 + 17 * me), std::byte{0x5a});  // other lengths before
  const Buffer want = [&] {
    Buffer b(4096);
    for (std::size_t i = 0; i < b.size(); ++i) b[i] = static_cast<std::byte>((i * 31 + 7) & 0xff);
    return b;
  }();
  if (me == bcast_root) data = want;
  comm.broadcast(data, bcast_root);
  expect(f, comm, data == want, "broadcast: data differs from the root's");
  comm.barrier();
  return f;
}

// Every check above, in one order every rank follows.
inline Failures check_all(Comm& comm) {
  Failures f;
  for (auto* check :
       {check_keyed_sums, check_votes, check_max, check_sum_exact, check_bit_or, check_messages}) {
    auto more = check(comm);
    f.insert(f.end(), more.begin(), more.end());
  }
  return f;
}

}  // namespace radx::test::comm_checks
