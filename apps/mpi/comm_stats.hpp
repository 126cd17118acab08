// What one rank's communicator did over a run, per collective kind: calls, messages and bytes to and from
// other ranks, and the seconds spent inside MPI (the transfer and the wait for the other ranks, which MPI
// does not tell apart). radx-engine-mpi --comm-stats prints them for every rank at the end, beside the rank's
// wall time, so the share of the run spent communicating is their ratio (bench/mpi_scaling.sh).
//
// Bytes are the caller's data as it leaves or reaches this rank, whatever algorithm MPI uses inside a
// collective (a tree or a ring forwards more): for a payload of n bytes per rank,
//   all-reduce (vote, max, sum_exact, bit_or)  sent n, received n (its contribution and the result);
//   exchange                                   sent 8 (P - 1) + sum of its messages to other ranks,
//                                              received 8 (P - 1) + sum of theirs to it (the sizes first);
//   all-gather                                 sent 8 + n_me (its contribution, once),
//                                              received sum over other ranks of 8 + n_r;
//   gather to root                             a non-root sends 8 + n_me; the root receives as all-gather;
//   broadcast                                  the root sends 8 + n, every other rank receives 8 + n;
//   barrier                                    nothing.
// Messages are the exchange's point-to-point messages this rank sends to other ranks (non-empty ones: empty
// messages do not travel); the collectives' messages are MPI's own and are not counted.
#pragma once

#include <array>
#include <cstdint>
#include <ostream>
#include <string_view>
#include <vector>

namespace radx::app {

enum class CommKind : int {
  kVote,
  kMax,
  kSumExact,
  kBitOr,
  kExchange,
  kGather,
  kAllGather,
  kBroadcast,
  kBarrier,
};
inline constexpr int kCommKinds = 9;

// The kind's name in the --comm-stats table (the method of solver/parallel/comm.hpp).
[[nodiscard]] std::string_view comm_kind_name(CommKind kind);

struct CommCounts {
  std::int64_t calls = 0;
  std::int64_t messages = 0;
  std::int64_t bytes_sent = 0;
  std::int64_t bytes_received = 0;
  double seconds = 0;
};

struct CommStats {
  std::array<CommCounts, kCommKinds> kinds{};

  [[nodiscard]] CommCounts& operator[](CommKind k) { return kinds[static_cast<std::size_t>(k)]; }
  [[nodiscard]] const CommCounts& operator[](CommKind k) const { return kinds[static_cast<std::size_t>(k)]; }
  [[nodiscard]] CommCounts total() const;
};

// One rank's statistics and wall time, as rank 0 receives them to print.
struct RankCommStats {
  int rank = 0;
  double wall_seconds = 0;
  CommStats stats;
};

// Prints, for every rank, a table row per kind with any call and a total row, then each rank's wall time and
// MPI share: the text of radx-engine-mpi --comm-stats (bench/mpi_scaling.sh reads it).
void print_comm_stats(std::ostream& os, const std::vector<RankCommStats>& ranks);

}  // namespace radx::app
