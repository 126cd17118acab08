// The MPI communicator under mpirun, two modes:
//   test_comm_mpi                   every rank runs the communicator checks (tests/unit/comm_checks.hpp, the
//                                   ones the loopback threads pass); rank 0 prints every rank's failures and
//                                   all ranks exit 1 if there is any, else 0.
//   test_comm_mpi --lose-rank R N   every rank loops votes; rank R kills itself (SIGKILL) at iteration N, as
//   a
//                                   crashed or OOM-killed rank would. The others must not hang: mpirun ends
//                                   the job (tests/mpi/check_mpi_failures.py).
//   test_comm_mpi --bad-root        every rank gathers to a root that does not exist: the MPI call fails, and
//                                   the communicator names it and ends every rank.
//   test_comm_mpi --stats           every rank makes a known sequence of calls with rank-dependent message
//                                   sizes; the communication statistics (apps/mpi/comm_stats.hpp) must count
//                                   the calls, messages and bytes the sizes give, and rank 0's gathered
//                                   statistics must be every rank's, with bytes sent over all ranks equal to
//                                   bytes received where every byte sent is received once.
#include <signal.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "apps/mpi/mpi_comm.hpp"
#include "comm_checks.hpp"

namespace {

using radx::solver::parallel::Buffer;

// Rank 0 prints every rank's failures and the count; every rank returns 1 when there is any.
int report_failures(radx::app::MpiComm& comm, const std::vector<std::string>& failures) {
  std::string text;
  for (const auto& f : failures) text += f + '\n';
  const auto all = comm.gather(Buffer(reinterpret_cast<const std::byte*>(text.data()),
                                      reinterpret_cast<const std::byte*>(text.data() + text.size())),
                               0);
  std::vector<std::int64_t> count{static_cast<std::int64_t>(failures.size())};
  comm.sum_exact(count);
  if (comm.rank() == 0) {
    for (const auto& b : all) std::fwrite(b.data(), 1, b.size(), stdout);
    std::printf("%s: %lld failure(s) on %d ranks\n", count[0] == 0 ? "PASS" : "FAIL",
                static_cast<long long>(count[0]), comm.size());
  }
  return count[0] == 0 ? 0 : 1;
}

int run_checks(radx::app::MpiComm& comm) {
  // Twice: the second round must not see the first round's messages.
  std::vector<std::string> failures = radx::test::comm_checks::check_all(comm);
  const auto again = radx::test::comm_checks::check_all(comm);
  failures.insert(failures.end(), again.begin(), again.end());
  return report_failures(comm, failures);
}

// The statistics check. Message sizes in bytes: exchange from rank r to rank q, to_size(r, q) (empty when
// r + q is a multiple of 3); gather to rank 1 (rank 0 when alone), gather_size(r); all-gather,
// all_gather_size(r); broadcast from rank 0, 7 bytes. Expected counts follow the rules of comm_stats.hpp.
std::int64_t to_size(int r, int q) {
  return (r + q) % 3 == 0 ? 0 : 10 * r + q + 1;
}
std::int64_t gather_size(int r) {
  return 3 * r + 2;
}
std::int64_t all_gather_size(int r) {
  return 5 * r + 1;
}

void expect_counts(std::vector<std::string>& failures, int rank, radx::app::CommKind kind,
                   const radx::app::CommCounts& got, const radx::app::CommCounts& want) {
  const auto same = got.calls == want.calls && got.messages == want.messages &&
                    got.bytes_sent == want.bytes_sent && got.bytes_received == want.bytes_received &&
                    got.seconds >= 0;
  if (!same)
    failures.push_back("rank " + std::to_string(rank) + " " + std::string(radx::app::comm_kind_name(kind)) +
                       ": calls/messages/sent/received " + std::to_string(got.calls) + "/" +
                       std::to_string(got.messages) + "/" + std::to_string(got.bytes_sent) + "/" +
                       std::to_string(got.bytes_received) + ", expected " + std::to_string(want.calls) + "/" +
                       std::to_string(want.messages) + "/" + std::to_string(want.bytes_sent) + "/" +
                       std::to_string(want.bytes_received) + " (seconds " + std::to_string(got.seconds) +
                       ")");
}

int check_stats(radx::app::MpiComm& comm) {
  using radx::app::CommKind;
  const int P = comm.size();
  const int me = comm.rank();
  std::vector<std::string> failures;
  if (comm.stats().total().calls != 0) failures.push_back("statistics not zero before any call");

  (void)comm.vote(radx::solver::parallel::Vote{1.0 + me, me, 0});
  std::vector<double> maxima(3, 1.0 * me);
  comm.max(maxima);
  std::vector<std::int64_t> bins(5, me);
  comm.sum_exact(bins);
  std::vector<std::uint64_t> words(2, 1u << me);
  comm.bit_or(words);
  for (int round = 0; round < 2; ++round) {  // twice: the counts add up
    std::vector<Buffer> to_rank(static_cast<std::size_t>(P));
    for (int q = 0; q < P; ++q) to_rank[static_cast<std::size_t>(q)].resize(to_size(me, q));
    (void)comm.exchange(to_rank);
  }
  const int root = P > 1 ? 1 : 0;
  (void)comm.gather(Buffer(static_cast<std::size_t>(gather_size(me))), root);
  (void)comm.all_gather(Buffer(static_cast<std::size_t>(all_gather_size(me))));
  Buffer broadcast(me == 0 ? 7 : 3);
  comm.broadcast(broadcast, 0);
  comm.barrier();

  // Expected, from the sizes: 8 bytes for each announced size (an int64).
  const std::int64_t S = 8;
  radx::app::CommStats want;
  want[CommKind::kVote] = {1, 0, sizeof(radx::solver::parallel::Vote), sizeof(radx::solver::parallel::Vote),
                           0};
  want[CommKind::kMax] = {1, 0, 3 * 8, 3 * 8, 0};
  want[CommKind::kSumExact] = {1, 0, 5 * 8, 5 * 8, 0};
  want[CommKind::kBitOr] = {1, 0, 2 * 8, 2 * 8, 0};
  auto& x = want[CommKind::kExchange];
  auto& g = want[CommKind::kGather];
  auto& a = want[CommKind::kAllGather];
  x.calls = 2;
  g.calls = a.calls = 1;
  for (int q = 0; q < P; ++q) {
    if (q == me) continue;
    x.messages += 2 * (to_size(me, q) > 0 ? 1 : 0);
    x.bytes_sent += 2 * (S + to_size(me, q));
    x.bytes_received += 2 * (S + to_size(q, me));
    if (me == root) g.bytes_received += S + gather_size(q);
    a.bytes_received += S + all_gather_size(q);
  }
  if (me != root) g.bytes_sent = S + gather_size(me);
  a.bytes_sent = S + all_gather_size(me);
  want[CommKind::kBroadcast] = {1, 0, me == 0 ? S + 7 : 0, me == 0 ? 0 : S + 7, 0};
  want[CommKind::kBarrier] = {1, 0, 0, 0, 0};
  for (int k = 0; k < radx::app::kCommKinds; ++k) {
    const auto kind = static_cast<CommKind>(k);
    expect_counts(failures, me, kind, comm.stats()[kind], want[kind]);
  }

  // Rank 0's gathered statistics: every rank's own, in rank order, with the wall time given. Bytes of the
  // exchange and the all-gather conserve: what all ranks send to others is what all ranks receive.
  const auto all = comm.gather_stats(10.0 + me);
  if (me == 0) {
    std::int64_t x_sent = 0, x_received = 0;
    for (int r = 0; r < static_cast<int>(all.size()); ++r) {
      const auto& s = all[static_cast<std::size_t>(r)];
      if (s.rank != r || s.wall_seconds != 10.0 + r)
        failures.push_back("gathered statistics " + std::to_string(r) + " are rank " +
                           std::to_string(s.rank) + "'s, wall " + std::to_string(s.wall_seconds));
      x_sent += s.stats[CommKind::kExchange].bytes_sent;
      x_received += s.stats[CommKind::kExchange].bytes_received;
    }
    if (static_cast<int>(all.size()) != P)
      failures.push_back("gathered statistics of " + std::to_string(all.size()) + " ranks");
    if (x_sent != x_received)
      failures.push_back("exchange bytes sent over all ranks " + std::to_string(x_sent) + " != received " +
                         std::to_string(x_received));
    if (!all.empty() && all[0].stats[CommKind::kExchange].bytes_sent != want[CommKind::kExchange].bytes_sent)
      failures.push_back("rank 0's gathered statistics are not its own");
    std::ostringstream text;
    radx::app::print_comm_stats(text, all);
    const std::string share = "rank 0: wall 10.000 s, inside MPI";
    if (text.str().find(share) == std::string::npos)
      failures.push_back("the printed table has no line \"" + share + "\":\n" + text.str());
  } else if (!all.empty()) {
    failures.push_back("rank " + std::to_string(me) + " received the gathered statistics");
  }
  return report_failures(comm, failures);
}

int lose_rank(radx::app::MpiComm& comm, int lost, int at_iteration) {
  for (int i = 0; i < 1'000'000; ++i) {
    if (comm.rank() == lost && i == at_iteration) {
      std::fprintf(stderr, "test_comm_mpi: rank %d kills itself at iteration %d\n", lost, i);
      std::fflush(stderr);
      ::kill(::getpid(), SIGKILL);
    }
    (void)comm.vote(radx::solver::parallel::Vote{1.0 + comm.rank(), i, 0});
    ::usleep(1000);
  }
  std::fprintf(stderr, "test_comm_mpi: rank %d ran every iteration: rank %d was never lost\n", comm.rank(),
               lost);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  radx::app::MpiComm comm(&argc, &argv);
  if (argc == 4 && std::strcmp(argv[1], "--lose-rank") == 0)
    return lose_rank(comm, std::atoi(argv[2]), std::atoi(argv[3]));
  if (argc == 2 && std::strcmp(argv[1], "--bad-root") == 0) {
    (void)comm.gather(Buffer(8), comm.size());
    return 0;  // not reached: the failed call ends every rank
  }
  if (argc == 2 && std::strcmp(argv[1], "--stats") == 0) return check_stats(comm);
  if (argc != 1) {
    if (comm.rank() == 0)
      std::fprintf(stderr, "usage: test_comm_mpi [--lose-rank RANK ITERATION | --bad-root | --stats]\n");
    return 2;
  }
  return run_checks(comm);
}
