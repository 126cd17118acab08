// The communicator of a run on one rank: every collective is the identity (a vote wins itself, a max or a
// sum over one rank is the value itself, a message to oneself comes back unchanged). radx-engine and
// `radx run` use it; radx-engine-mpi at np = 1 computes the same through MPI.
#pragma once

#include "solver/parallel/comm.hpp"

namespace radx::solver::parallel {

class SerialComm final : public Comm {
 public:
  [[nodiscard]] int rank() const override { return 0; }
  [[nodiscard]] int size() const override { return 1; }

  [[nodiscard]] Vote vote(const Vote& mine) override;
  void max(std::span<double> values) override;
  void sum_exact(std::span<std::int64_t> bins) override;
  void bit_or(std::span<std::uint64_t> words) override;
  [[nodiscard]] std::vector<Buffer> exchange(const std::vector<Buffer>& to_rank) override;
  [[nodiscard]] std::vector<Buffer> gather(const Buffer& mine, int root) override;
  [[nodiscard]] std::vector<Buffer> all_gather(const Buffer& mine) override;
  void broadcast(Buffer& data, int root) override;
  void barrier() override;
  [[noreturn]] void abort(int exit_code, const std::string& message) override;
};

}  // namespace radx::solver::parallel
