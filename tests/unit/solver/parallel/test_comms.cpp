// The one-rank communicator and the loopback one (P threads) against the checks every communicator must
// pass (comm_checks.hpp); the MPI communicator runs the same checks under mpirun (tests/mpi).
#include <catch2/catch.hpp>

#include <atomic>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "comm_checks.hpp"
#include "loopback_comm.hpp"
#include "solver/parallel/serial_comm.hpp"

namespace {

using radx::solver::parallel::Buffer;
using radx::solver::parallel::Comm;
using radx::solver::parallel::Vote;

std::string joined(const std::vector<std::string>& lines) {
  std::string s;
  for (const auto& l : lines) s += l + '\n';
  return s;
}

}  // namespace

TEST_CASE("SerialComm: every collective is the identity", "[parallel][comm]") {
  radx::solver::parallel::SerialComm comm;
  CHECK(comm.rank() == 0);
  CHECK(comm.size() == 1);
  const auto failures = radx::test::comm_checks::check_all(comm);
  INFO(joined(failures));
  CHECK(failures.empty());
  const Vote v = comm.vote(Vote{0.25, 9, radx::solver::parallel::kVoteSignal, 5, 5});
  CHECK(v.value == 0.25);
  CHECK(v.key == 9);
  CHECK(v.rank == 0);
  CHECK(v.flag_rank == 0);
  CHECK_THROWS_AS(comm.gather(Buffer{}, 1), std::invalid_argument);
}

TEST_CASE("LoopbackComm: the communicator checks on 1, 2, 3 and 5 ranks", "[parallel][comm]") {
  for (const int ranks : {1, 2, 3, 5}) {
    std::mutex m;
    std::vector<std::string> failures;
    // Twice in a row: the second round must not read the first round's messages.
    radx::test::run_ranks(ranks, [&](Comm& comm) {
      for (int round = 0; round < 2; ++round) {
        const auto mine = radx::test::comm_checks::check_all(comm);
        const std::lock_guard lock(m);
        failures.insert(failures.end(), mine.begin(), mine.end());
      }
    });
    INFO(ranks << " ranks:\n" << joined(failures));
    CHECK(failures.empty());
  }
}

TEST_CASE("LoopbackComm: a failing rank releases the others instead of hanging", "[parallel][comm]") {
  std::atomic<int> released{0};
  const auto body = [&](Comm& comm) {
    if (comm.rank() == 1) throw std::runtime_error("rank 1 broke");
    try {
      comm.barrier();
    } catch (...) {
      ++released;
      throw;
    }
  };
  CHECK_THROWS_WITH(radx::test::run_ranks(3, body), "rank 1 broke");
  CHECK(released == 2);
}

TEST_CASE("LoopbackComm: abort ends every rank with the aborting rank's message", "[parallel][comm]") {
  try {
    radx::test::run_ranks(3, [](Comm& comm) {
      if (comm.rank() == 2) comm.abort(3, "cannot write the results");
      comm.barrier();
    });
    FAIL("run_ranks returned after an abort");
  } catch (const radx::test::LoopbackAbort& e) {
    CHECK(e.exit_code == 3);
    CHECK(std::string(e.what()) == "cannot write the results");
  }
}

TEST_CASE("LoopbackComm: ranks calling different collectives are told so", "[parallel][comm]") {
  const auto body = [](Comm& comm) {
    if (comm.rank() == 0) {
      comm.barrier();
    } else {
      std::vector<double> v{1.0};
      comm.max(v);
    }
  };
  CHECK_THROWS_WITH(radx::test::run_ranks(2, body),
                    "loopback collectives out of step: rank 0 called barrier, rank 1 called max");
}
