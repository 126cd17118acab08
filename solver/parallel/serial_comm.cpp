#include "solver/parallel/serial_comm.hpp"

#include "solver/parallel/vote_order.hpp"

#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace radx::solver::parallel {

namespace {

// A caller that names a rank other than 0, or ships a message list not of one entry, has a bug: say which.
void require_rank_zero(int root, const char* what) {
  if (root != 0)
    throw std::invalid_argument(std::string("SerialComm::") + what + ": root " + std::to_string(root) +
                                " on a run of one rank");
}

}  // namespace

Vote SerialComm::vote(const Vote& mine) {
  return vote_of_rank(mine, 0);
}

void SerialComm::max(std::span<double> /*values*/) {}

void SerialComm::sum_exact(std::span<std::int64_t> /*bins*/) {}

void SerialComm::bit_or(std::span<std::uint64_t> /*words*/) {}

std::vector<Buffer> SerialComm::exchange(const std::vector<Buffer>& to_rank) {
  if (to_rank.size() != 1)
    throw std::invalid_argument("SerialComm::exchange: " + std::to_string(to_rank.size()) +
                                " messages on a run of one rank");
  return to_rank;
}

std::vector<Buffer> SerialComm::gather(const Buffer& mine, int root) {
  require_rank_zero(root, "gather");
  return {mine};
}

std::vector<Buffer> SerialComm::all_gather(const Buffer& mine) {
  return {mine};
}

void SerialComm::broadcast(Buffer& /*data*/, int root) {
  require_rank_zero(root, "broadcast");
}

void SerialComm::barrier() {}

void SerialComm::abort(int exit_code, const std::string& message) {
  std::fprintf(stderr, "%s\n", message.c_str());
  std::fflush(stderr);
  std::_Exit(exit_code);
}

}  // namespace radx::solver::parallel
