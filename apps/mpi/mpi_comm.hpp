// The communicator over MPI_COMM_WORLD: radx-engine-mpi's, and the MPI tests'. The only code of radx that
// includes mpi.h (in mpi_comm.cpp), so the solver and the default executables stay free of MPI.
//
// One MpiComm per process: it initialises MPI (MPI_THREAD_FUNNELED: only the thread that created it calls
// collectives, between the thread team's stages) and finalises it when destroyed. Every MPI call returns its
// error (MPI_ERRORS_RETURN); a failed call prints which call failed, on which rank, with MPI's reason, and
// ends every rank (MPI_Abort), so an error never leaves the other ranks waiting.
//
// Every collective is counted (apps/mpi/comm_stats.hpp): calls, messages, bytes and seconds inside MPI, per
// kind, for radx-engine-mpi --comm-stats. The count costs two clock reads a call.
#pragma once

#include <memory>
#include <vector>

#include "apps/mpi/comm_stats.hpp"
#include "solver/parallel/comm.hpp"

namespace radx::app {

class MpiComm final : public solver::parallel::Comm {
 public:
  // Initialises MPI with the program's arguments (either may be null). Exits with a message when the MPI
  // library cannot give MPI_THREAD_FUNNELED.
  MpiComm(int* argc, char*** argv);
  ~MpiComm() override;
  MpiComm(const MpiComm&) = delete;
  MpiComm& operator=(const MpiComm&) = delete;

  [[nodiscard]] int rank() const override { return rank_; }
  [[nodiscard]] int size() const override { return size_; }

  [[nodiscard]] solver::parallel::Vote vote(const solver::parallel::Vote& mine) override;
  void max(std::span<double> values) override;
  void sum_exact(std::span<std::int64_t> bins) override;
  void bit_or(std::span<std::uint64_t> words) override;
  [[nodiscard]] std::vector<solver::parallel::Buffer> exchange(
      const std::vector<solver::parallel::Buffer>& to_rank) override;
  [[nodiscard]] std::vector<solver::parallel::Buffer> gather(const solver::parallel::Buffer& mine,
                                                             int root) override;
  [[nodiscard]] std::vector<solver::parallel::Buffer> all_gather(
      const solver::parallel::Buffer& mine) override;
  void broadcast(solver::parallel::Buffer& data, int root) override;
  void barrier() override;
  [[noreturn]] void abort(int exit_code, const std::string& message) override;

  // What this rank's collectives have done since the communicator was made.
  [[nodiscard]] const CommStats& stats() const { return stats_; }
  // Every rank's statistics (as they stand when called, this call's own traffic not included) and wall time,
  // indexed by rank, on rank 0; the others return an empty vector. Called by every rank.
  [[nodiscard]] std::vector<RankCommStats> gather_stats(double wall_seconds);

 private:
  struct Types;  // the vote's MPI datatype and reduction, created once
  int rank_ = 0;
  int size_ = 1;
  std::unique_ptr<Types> types_;
  CommStats stats_;
};

}  // namespace radx::app
