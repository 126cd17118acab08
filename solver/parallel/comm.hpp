// The communicator the solver sees: what ranks exchange, without MPI.
//
// The engine runs on P ranks (processes), each with its own thread team; P = 1 is the serial engine. Every
// collective here is called by every rank, in the same order, from the thread that owns the engine (between
// the team's stages: MPI_THREAD_FUNNELED). The serial implementation (serial_comm.hpp) is what the default
// executables use; the MPI one lives outside solver/ (apps/mpi/), so nothing in solver/ includes mpi.h.
//
// Results identical for any P rest on three rules (docs/parallel.md):
//   - a sum that feeds the solution is formed on one rank, in the serial order, from terms shipped one by one
//     (keyed exchange), never from partial sums;
//   - min and max are reduced with a tie-break key, so every rank picks the same winner as one rank would;
//   - a sum that only reports (energies, momentum, works) goes through integer bins (sum_exact), which add
//     exactly in any order.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace radx::solver::parallel {

// A byte message. Typed helpers (pack/unpack of trivially copyable records) sit beside the callers.
using Buffer = std::vector<std::byte>;

// One rank's vote for the time step and its stop flags. The reduction keeps the smallest `value`; equal
// values go to the smallest `key` (the serial engine's "first" voter: a flat group index, or interface and
// node), then to the lowest rank. `flags` are OR-ed over all ranks, so every rank stops on the same cycle;
// `flag_rank` is the lowest rank with any flag set (-1 when none), whose message the caller then broadcasts.
struct Vote {
  double value = 0;
  std::int64_t key = 0;
  std::uint32_t flags = 0;
  int rank = 0;        // the winner's rank, set by the reduction
  int flag_rank = -1;  // set by the reduction
};

// Stop flags a vote carries (any may be set together).
enum VoteFlag : std::uint32_t {
  kVoteError = 1u << 0,         // an error this cycle (its message on flag_rank)
  kVoteSignal = 1u << 1,        // SIGINT/SIGTERM seen
  kVoteCstViolation = 1u << 2,  // a /DT/.../CST element's own step fell below half its frozen step
  kVoteNonFinite = 1u << 3,     // a coordinate, velocity or energy is not finite
  kVoteStepStop = 1u << 4,      // a step fell below a /DT/.../STOP minimum
};

class Comm {
 public:
  virtual ~Comm() = default;
  [[nodiscard]] virtual int rank() const = 0;
  [[nodiscard]] virtual int size() const = 0;

  // All-reduce of a vote (see Vote): every rank returns the same winning vote.
  [[nodiscard]] virtual Vote vote(const Vote& mine) = 0;
  // All-reduce maximum of each entry, in place. Max is exact and order-free: no key needed.
  virtual void max(std::span<double> values) = 0;
  // All-reduce of integer sums, in place: exact in any order (the exact accumulator's bins).
  virtual void sum_exact(std::span<std::int64_t> bins) = 0;
  // All-reduce bitwise OR / logical flags, in place.
  virtual void bit_or(std::span<std::uint64_t> words) = 0;

  // Every rank sends to_rank[r] to rank r (to_rank.size() == size(); its own entry is delivered to itself)
  // and returns what each rank sent it, indexed by source rank. Empty messages cost no transfer beyond the
  // sizes. The order of records inside a message is the sender's; keys in the records let the receiver
  // restore the serial order.
  [[nodiscard]] virtual std::vector<Buffer> exchange(const std::vector<Buffer>& to_rank) = 0;
  // Rank `root` returns every rank's message, indexed by rank; the others return an empty vector.
  [[nodiscard]] virtual std::vector<Buffer> gather(const Buffer& mine, int root) = 0;
  // Every rank returns every rank's message, indexed by rank.
  [[nodiscard]] virtual std::vector<Buffer> all_gather(const Buffer& mine) = 0;
  // `data` of rank `root` replaces every other rank's `data`.
  virtual void broadcast(Buffer& data, int root) = 0;
  virtual void barrier() = 0;
  // Ends every rank's process with `exit_code` after printing `message` on this one: for an error that only
  // one rank sees outside the collective stop path (a failed write on rank 0, a lost peer).
  [[noreturn]] virtual void abort(int exit_code, const std::string& message) = 0;
};

}  // namespace radx::solver::parallel
