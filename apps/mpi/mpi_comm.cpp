#include "apps/mpi/mpi_comm.hpp"

#include <mpi.h>

#include <chrono>
#include <climits>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <type_traits>
#include <vector>

#include "solver/parallel/vote_order.hpp"

namespace radx::app {

using solver::parallel::Buffer;
using solver::parallel::Vote;

namespace {

// Point-to-point tags of the exchange: one collective at a time is under way on a rank, and MPI keeps the
// order of messages between two ranks with one tag, so one tag is enough.
constexpr int kExchangeTag = 7301;

[[noreturn]] void abort_all(int rank, const std::string& message, int exit_code = 1) {
  std::fprintf(stderr, "radx: MPI rank %d: %s\n", rank, message.c_str());
  std::fflush(stderr);
  MPI_Abort(MPI_COMM_WORLD, exit_code);
  std::_Exit(exit_code);  // MPI_Abort does not return; this says so to the compiler
}

// A failed MPI call ends every rank with the call's name and MPI's reason.
void check(int rc, int rank, const char* call) {
  if (rc == MPI_SUCCESS) return;
  char reason[MPI_MAX_ERROR_STRING] = {};
  int length = 0;
  MPI_Error_string(rc, reason, &length);
  abort_all(rank, std::string(call) + " failed: " + std::string(reason, static_cast<std::size_t>(length)));
}

// MPI counts in an int: a message (or a gathered whole) beyond INT_MAX bytes, or a reduction beyond INT_MAX
// entries, is refused by name.
int mpi_count(std::int64_t n, int rank, const char* what, const char* unit = "bytes") {
  if (n < 0 || n > INT_MAX)
    abort_all(rank, std::string(what) + " of " + std::to_string(n) + " " + unit + " exceeds MPI's count of " +
                        std::to_string(INT_MAX) + " " + unit + "; radx does not split messages");
  return static_cast<int>(n);
}

int byte_count(std::int64_t bytes, int rank, const char* what) {
  return mpi_count(bytes, rank, what);
}

int entry_count(std::size_t entries, int rank, const char* what) {
  return mpi_count(static_cast<std::int64_t>(entries), rank, what, "entries");
}

// The reduction of votes: an MPI user operation, in = in (op) inout, element by element.
void reduce_votes(void* in, void* inout, int* len, MPI_Datatype* /*type*/) {
  const auto* a = static_cast<const Vote*>(in);
  auto* b = static_cast<Vote*>(inout);
  for (int i = 0; i < *len; ++i) b[i] = solver::parallel::combine_votes(a[i], b[i]);
}

void* data_or_null(Buffer& b) {
  return b.empty() ? nullptr : b.data();
}

const void* data_or_null(const Buffer& b) {
  return b.empty() ? nullptr : b.data();
}

// One collective call counted: the call on construction, the seconds until destruction (the transfer and the
// wait for the other ranks; the copies around the MPI calls are microseconds against them).
class Counted {
 public:
  explicit Counted(CommCounts& c) : counts_(c), start_(std::chrono::steady_clock::now()) { ++counts_.calls; }
  ~Counted() {
    counts_.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }
  Counted(const Counted&) = delete;
  Counted& operator=(const Counted&) = delete;

 private:
  CommCounts& counts_;
  std::chrono::steady_clock::time_point start_;
};

// An all-reduce of `bytes` a rank: its contribution out, the result in.
void count_reduction(CommCounts& c, std::size_t bytes) {
  c.bytes_sent += static_cast<std::int64_t>(bytes);
  c.bytes_received += static_cast<std::int64_t>(bytes);
}

// The size every rank's message is announced with (an int64) in exchange, gather, all-gather and broadcast.
constexpr std::int64_t kSizeBytes = sizeof(std::int64_t);

// Splits a gathered whole into messages of the given sizes.
std::vector<Buffer> split(const Buffer& whole, const std::vector<int>& counts,
                          const std::vector<int>& displs) {
  std::vector<Buffer> parts(counts.size());
  for (std::size_t r = 0; r < counts.size(); ++r)
    parts[r].assign(whole.begin() + displs[r], whole.begin() + displs[r] + counts[r]);
  return parts;
}

}  // namespace

// The vote as an MPI struct (its fields by offset, padded to sizeof(Vote)) and its reduction.
struct MpiComm::Types {
  MPI_Datatype vote = MPI_DATATYPE_NULL;
  MPI_Op vote_op = MPI_OP_NULL;
};

MpiComm::MpiComm(int* argc, char*** argv) {
  int provided = 0;
  if (MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) {
    std::fprintf(stderr, "radx: cannot initialise MPI\n");
    std::exit(1);
  }
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  if (provided < MPI_THREAD_FUNNELED)
    abort_all(rank_,
              "the MPI library gives thread level " + std::to_string(provided) +
                  ", below MPI_THREAD_FUNNELED, which radx needs (its thread team runs inside each rank)");
  types_ = std::make_unique<Types>();
  const int lengths[] = {1, 1, 1, 1, 1};
  const MPI_Aint offsets[] = {offsetof(Vote, value), offsetof(Vote, key), offsetof(Vote, flags),
                              offsetof(Vote, rank), offsetof(Vote, flag_rank)};
  const MPI_Datatype fields[] = {MPI_DOUBLE, MPI_INT64_T, MPI_UINT32_T, MPI_INT, MPI_INT};
  MPI_Datatype packed = MPI_DATATYPE_NULL;
  check(MPI_Type_create_struct(5, lengths, offsets, fields, &packed), rank_, "MPI_Type_create_struct");
  check(MPI_Type_create_resized(packed, 0, sizeof(Vote), &types_->vote), rank_, "MPI_Type_create_resized");
  check(MPI_Type_free(&packed), rank_, "MPI_Type_free");
  check(MPI_Type_commit(&types_->vote), rank_, "MPI_Type_commit");
  // Commutative: the order (value, key, rank) is total, so any grouping of the ranks picks one winner.
  check(MPI_Op_create(reduce_votes, 1, &types_->vote_op), rank_, "MPI_Op_create");
}

MpiComm::~MpiComm() {
  if (types_) {
    MPI_Op_free(&types_->vote_op);
    MPI_Type_free(&types_->vote);
  }
  MPI_Finalize();
}

Vote MpiComm::vote(const Vote& mine) {
  auto& tally = stats_[CommKind::kVote];
  const Counted counted(tally);
  count_reduction(tally, sizeof(Vote));
  const Vote entry = solver::parallel::vote_of_rank(mine, rank_);
  Vote result;
  check(MPI_Allreduce(&entry, &result, 1, types_->vote, types_->vote_op, MPI_COMM_WORLD), rank_,
        "MPI_Allreduce (vote)");
  return result;
}

void MpiComm::max(std::span<double> values) {
  auto& tally = stats_[CommKind::kMax];
  const Counted counted(tally);
  count_reduction(tally, values.size_bytes());
  check(MPI_Allreduce(MPI_IN_PLACE, values.data(), entry_count(values.size(), rank_, "a max"), MPI_DOUBLE,
                      MPI_MAX, MPI_COMM_WORLD),
        rank_, "MPI_Allreduce (max)");
}

void MpiComm::sum_exact(std::span<std::int64_t> bins) {
  auto& tally = stats_[CommKind::kSumExact];
  const Counted counted(tally);
  count_reduction(tally, bins.size_bytes());
  check(MPI_Allreduce(MPI_IN_PLACE, bins.data(), entry_count(bins.size(), rank_, "an exact sum"), MPI_INT64_T,
                      MPI_SUM, MPI_COMM_WORLD),
        rank_, "MPI_Allreduce (exact sum)");
}

void MpiComm::bit_or(std::span<std::uint64_t> words) {
  auto& tally = stats_[CommKind::kBitOr];
  const Counted counted(tally);
  count_reduction(tally, words.size_bytes());
  check(MPI_Allreduce(MPI_IN_PLACE, words.data(), entry_count(words.size(), rank_, "an OR"), MPI_UINT64_T,
                      MPI_BOR, MPI_COMM_WORLD),
        rank_, "MPI_Allreduce (bit or)");
}

std::vector<Buffer> MpiComm::exchange(const std::vector<Buffer>& to_rank) {
  auto& tally = stats_[CommKind::kExchange];
  const Counted counted(tally);
  if (to_rank.size() != static_cast<std::size_t>(size_))
    abort_all(rank_, "exchange given " + std::to_string(to_rank.size()) + " messages for " +
                         std::to_string(size_) + " ranks");
  const auto P = static_cast<std::size_t>(size_);
  std::vector<std::int64_t> send_sizes(P);
  std::vector<std::int64_t> recv_sizes(P);
  for (std::size_t r = 0; r < P; ++r) send_sizes[r] = static_cast<std::int64_t>(to_rank[r].size());
  check(MPI_Alltoall(send_sizes.data(), 1, MPI_INT64_T, recv_sizes.data(), 1, MPI_INT64_T, MPI_COMM_WORLD),
        rank_, "MPI_Alltoall (message sizes)");
  tally.bytes_sent += kSizeBytes * (size_ - 1);
  tally.bytes_received += kSizeBytes * (size_ - 1);
  std::vector<Buffer> received(P);
  std::vector<MPI_Request> requests;
  requests.reserve(2 * P);
  const auto me = static_cast<std::size_t>(rank_);
  // Only non-empty messages travel; its own comes back by copy.
  for (std::size_t r = 0; r < P; ++r) {
    if (r == me || recv_sizes[r] == 0) continue;
    received[r].resize(static_cast<std::size_t>(byte_count(recv_sizes[r], rank_, "a message received")));
    tally.bytes_received += recv_sizes[r];
    check(MPI_Irecv(received[r].data(), static_cast<int>(recv_sizes[r]), MPI_BYTE, static_cast<int>(r),
                    kExchangeTag, MPI_COMM_WORLD, &requests.emplace_back()),
          rank_, "MPI_Irecv (exchange)");
  }
  for (std::size_t r = 0; r < P; ++r) {
    if (r == me || send_sizes[r] == 0) continue;
    tally.bytes_sent += send_sizes[r];
    ++tally.messages;
    check(MPI_Isend(to_rank[r].data(), byte_count(send_sizes[r], rank_, "a message sent"), MPI_BYTE,
                    static_cast<int>(r), kExchangeTag, MPI_COMM_WORLD, &requests.emplace_back()),
          rank_, "MPI_Isend (exchange)");
  }
  received[me] = to_rank[me];
  check(MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE), rank_,
        "MPI_Waitall (exchange)");
  return received;
}

std::vector<Buffer> MpiComm::gather(const Buffer& mine, int root) {
  auto& tally = stats_[CommKind::kGather];
  const Counted counted(tally);
  const std::int64_t my_size = static_cast<std::int64_t>(mine.size());
  const auto P = static_cast<std::size_t>(size_);
  std::vector<std::int64_t> sizes(rank_ == root ? P : 0);
  check(MPI_Gather(&my_size, 1, MPI_INT64_T, sizes.data(), 1, MPI_INT64_T, root, MPI_COMM_WORLD), rank_,
        "MPI_Gather (message sizes)");
  std::vector<int> counts(sizes.size());
  std::vector<int> displs(sizes.size());
  std::int64_t total = 0;
  for (std::size_t r = 0; r < sizes.size(); ++r) {
    counts[r] = byte_count(sizes[r], rank_, "a gathered message");
    displs[r] = byte_count(total, rank_, "the gathered messages");
    total += sizes[r];
  }
  Buffer whole(static_cast<std::size_t>(byte_count(total, rank_, "the gathered messages")));
  check(MPI_Gatherv(data_or_null(mine), byte_count(my_size, rank_, "a message to gather"), MPI_BYTE,
                    data_or_null(whole), counts.data(), displs.data(), MPI_BYTE, root, MPI_COMM_WORLD),
        rank_, "MPI_Gatherv");
  if (rank_ != root) {
    tally.bytes_sent += kSizeBytes + my_size;
    return {};
  }
  tally.bytes_received += (size_ - 1) * kSizeBytes + total - my_size;
  return split(whole, counts, displs);
}

std::vector<Buffer> MpiComm::all_gather(const Buffer& mine) {
  auto& tally = stats_[CommKind::kAllGather];
  const Counted counted(tally);
  const std::int64_t my_size = static_cast<std::int64_t>(mine.size());
  const auto P = static_cast<std::size_t>(size_);
  std::vector<std::int64_t> sizes(P);
  check(MPI_Allgather(&my_size, 1, MPI_INT64_T, sizes.data(), 1, MPI_INT64_T, MPI_COMM_WORLD), rank_,
        "MPI_Allgather (message sizes)");
  std::vector<int> counts(P);
  std::vector<int> displs(P);
  std::int64_t total = 0;
  for (std::size_t r = 0; r < P; ++r) {
    counts[r] = byte_count(sizes[r], rank_, "a gathered message");
    displs[r] = byte_count(total, rank_, "the gathered messages");
    total += sizes[r];
  }
  Buffer whole(static_cast<std::size_t>(byte_count(total, rank_, "the gathered messages")));
  check(MPI_Allgatherv(data_or_null(mine), counts[static_cast<std::size_t>(rank_)], MPI_BYTE,
                       data_or_null(whole), counts.data(), displs.data(), MPI_BYTE, MPI_COMM_WORLD),
        rank_, "MPI_Allgatherv");
  tally.bytes_sent += kSizeBytes + my_size;
  tally.bytes_received += (size_ - 1) * kSizeBytes + total - my_size;
  return split(whole, counts, displs);
}

void MpiComm::broadcast(Buffer& data, int root) {
  auto& tally = stats_[CommKind::kBroadcast];
  const Counted counted(tally);
  std::int64_t size = static_cast<std::int64_t>(data.size());
  check(MPI_Bcast(&size, 1, MPI_INT64_T, root, MPI_COMM_WORLD), rank_, "MPI_Bcast (message size)");
  (rank_ == root ? tally.bytes_sent : tally.bytes_received) += kSizeBytes + size;
  const int count = byte_count(size, rank_, "a broadcast message");
  if (rank_ != root) data.resize(static_cast<std::size_t>(count));
  if (count == 0) return;
  check(MPI_Bcast(data.data(), count, MPI_BYTE, root, MPI_COMM_WORLD), rank_, "MPI_Bcast");
}

void MpiComm::barrier() {
  const Counted counted(stats_[CommKind::kBarrier]);
  check(MPI_Barrier(MPI_COMM_WORLD), rank_, "MPI_Barrier");
}

void MpiComm::abort(int exit_code, const std::string& message) {
  abort_all(rank_, message, exit_code);
}

std::vector<RankCommStats> MpiComm::gather_stats(double wall_seconds) {
  static_assert(std::is_trivially_copyable_v<RankCommStats>);
  const RankCommStats mine{rank_, wall_seconds, stats_};
  std::vector<RankCommStats> all(rank_ == 0 ? static_cast<std::size_t>(size_) : 0);
  check(MPI_Gather(&mine, sizeof mine, MPI_BYTE, all.data(), sizeof mine, MPI_BYTE, 0, MPI_COMM_WORLD), rank_,
        "MPI_Gather (communication statistics)");
  return all;
}

}  // namespace radx::app
