// A communicator for tests: P "ranks" as P threads of this process, meeting at each collective, so that
// multi-rank code runs under Catch2 without mpirun. Each collective is one rendezvous: every rank posts one
// message per destination, waits under a mutex until all P have posted, copies what was posted to it, and
// waits again until all P have copied (so a fast rank cannot post the next collective over messages not yet
// read). Reductions are then formed locally on each rank, over ranks 0..P-1 in order, with the same rules
// as the MPI communicator (solver/parallel/vote_order.hpp). Speed does not matter; correctness does.
//
// Ranks must call the same collectives in the same order (as with MPI); a rank that calls another one
// (or another root) makes every rank throw, naming both. A rank whose function throws, or that calls
// abort(), releases the others (they throw too), so a failing test never hangs. Catch2 2 assertions are not
// thread-safe: rank functions record what they see, and the test checks it after run_ranks returns.
#pragma once

#include <functional>
#include <stdexcept>
#include <string>

#include "solver/parallel/comm.hpp"

namespace radx::test {

// What abort() throws on a loopback rank (std::runtime_error with the exit code).
struct LoopbackAbort : std::runtime_error {
  LoopbackAbort(int code, const std::string& message) : std::runtime_error(message), exit_code(code) {}
  int exit_code;
};

// Runs `body` on `ranks` threads, each given its own communicator (rank 0..ranks-1 of `ranks`), and
// returns when all have ended. Rethrows the exception of the lowest rank that failed on its own (not of the
// ranks its failure released).
void run_ranks(int ranks, const std::function<void(solver::parallel::Comm&)>& body);

}  // namespace radx::test
