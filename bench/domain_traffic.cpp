// Bytes per cycle each rank sends and receives for the domain exchange (solver/parallel/domain.hpp): the
// shared-node sums shipped to their owners (one slot of 3 or 6 doubles per entry on a shared node) and the
// ghost update after integration (x, v: 48 B a node, 72 B with omega), for P ranks and two simple splits of
// the element groups (contiguous blocks of the flat order, and round robin; METIS is the partition step's).
// Prints, per P and split, the shared nodes, the busiest rank's ghosts, and the busiest rank's bytes sent
// plus received per cycle.
//
// Usage: radx_bench_domain MODEL_FILE [P ...]   (default P: 2 3 4 8 16)
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include "io/hdf5/model_file.hpp"
#include "solver/engine/explicit_engine.hpp"
#include "solver/parallel/domain.hpp"

namespace {

namespace par = radx::solver::parallel;

std::vector<std::int32_t> split(std::int64_t groups, int P, bool round_robin) {
  std::vector<std::int32_t> r(static_cast<std::size_t>(groups));
  for (std::int64_t k = 0; k < groups; ++k)
    r[static_cast<std::size_t>(k)] = static_cast<std::int32_t>(round_robin ? k % P : k * P / groups);
  return r;
}

void report(const radx::solver::ExplicitEngine& engine, int P, bool round_robin) {
  const auto& groups = engine.groups();
  const auto nodes = static_cast<std::int64_t>(engine.nodes().n);
  const auto group_rank = split(groups.count(), P, round_robin);
  std::int64_t shared = 0, most_ghosts = 0, most_sums = 0, most_ghost_bytes = 0, most_total = 0;
  int most_messages = 0;
  for (int r = 0; r < P; ++r) {
    const auto plan = par::build_domain_plan(groups, group_rank, nodes, P, r);
    const auto t = par::domain_traffic(plan);
    shared += static_cast<std::int64_t>(plan.shared_nodes.size());
    most_ghosts = std::max(most_ghosts, static_cast<std::int64_t>(plan.ghost_nodes.size()));
    most_sums = std::max(most_sums, t.shared_sum_sent + t.shared_sum_received);
    most_ghost_bytes = std::max(most_ghost_bytes, t.ghost_sent + t.ghost_received);
    most_total =
        std::max(most_total, t.shared_sum_sent + t.shared_sum_received + t.ghost_sent + t.ghost_received);
    most_messages = std::max(most_messages, t.shared_sum_messages + t.ghost_messages);
  }
  std::printf("| %3d | %-11s | %8lld | %8lld | %10.1f | %10.1f | %10.1f | %4d |\n", P,
              round_robin ? "round robin" : "blocks", static_cast<long long>(shared),
              static_cast<long long>(most_ghosts), most_sums / 1e3, most_ghost_bytes / 1e3, most_total / 1e3,
              most_messages);
}

}  // namespace

int main(int argc, char** argv) {
  using namespace radx;
  if (argc < 2) {
    std::fprintf(stderr, "usage: radx_bench_domain MODEL_FILE [P ...]\n");
    return 2;
  }
  std::vector<int> ranks;
  for (int a = 2; a < argc; ++a) ranks.push_back(std::atoi(argv[a]));
  if (ranks.empty()) ranks = {2, 3, 4, 8, 16};
  model::Model model;
  std::string error;
  if (!io::read_model_file(argv[1], model, error)) {
    std::cerr << argv[1] << ": " << error << '\n';
    return 1;
  }
  const solver::ExplicitEngine engine(model, model::RunControls{}, solver::EngineOptions(1));
  std::printf("%s: %zu nodes, %zu elements, %lld groups\n", argv[1], engine.nodes().n, engine.element_count(),
              static_cast<long long>(engine.groups().count()));
  std::printf(
      "|   P | split       |   shared |  ghosts* | sums kB/cy* | ghost kB/cy* | total kB/cy* | msgs* |\n");
  std::printf("(* the busiest rank; kB sent plus received per cycle)\n");
  for (const int P : ranks) {
    if (P < 2) continue;
    report(engine, P, false);
    report(engine, P, true);
  }
  return 0;
}
