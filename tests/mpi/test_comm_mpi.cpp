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
#include <signal.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "apps/mpi/mpi_comm.hpp"
#include "comm_checks.hpp"

namespace {

using radx::solver::parallel::Buffer;

int run_checks(radx::app::MpiComm& comm) {
  // Twice: the second round must not see the first round's messages.
  std::vector<std::string> failures = radx::test::comm_checks::check_all(comm);
  const auto again = radx::test::comm_checks::check_all(comm);
  failures.insert(failures.end(), again.begin(), again.end());
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
  if (argc != 1) {
    if (comm.rank() == 0)
      std::fprintf(stderr, "usage: test_comm_mpi [--lose-rank RANK ITERATION | --bad-root]\n");
    return 2;
  }
  return run_checks(comm);
}
