// Bytes per cycle each rank sends and receives for the domain exchange (solver/parallel/domain.hpp): the
// shared-node sums shipped to their owners (one slot of 3 or 6 doubles per entry on a shared node) and the
// ghost update after integration (x, v: 48 B a node, 72 B with omega), for P ranks and three splits of the
// element groups: contiguous blocks of the flat order, round robin, and the METIS partition radx-engine-mpi
// uses (solver/parallel/partition.hpp). Prints, per P and split, the shared nodes, the busiest rank's ghosts,
// its bytes sent plus received per cycle and its messages sent per cycle (bench/mpi_weak_scaling.py reads
// the METIS rows).
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
#include "solver/parallel/partition.hpp"

namespace {

namespace par = radx::solver::parallel;

enum class Split { kBlocks, kRoundRobin, kMetis };

std::vector<std::int32_t> split(const radx::model::Model& model, const radx::solver::ElementGroups& groups,
                                int P, Split how) {
  const std::int64_t count = groups.count();
  std::vector<std::int32_t> r(static_cast<std::size_t>(count));
  if (how == Split::kMetis) {
    const auto p = par::partition_groups(model, groups, P);
    std::copy(p.group_rank.begin(), p.group_rank.end(), r.begin());
    return r;
  }
  for (std::int64_t k = 0; k < count; ++k)
    r[static_cast<std::size_t>(k)] =
        static_cast<std::int32_t>(how == Split::kRoundRobin ? k % P : k * P / count);
  return r;
}

void report(const radx::model::Model& model, const radx::solver::ExplicitEngine& engine, int P, Split how) {
  const auto& groups = engine.groups();
  const auto nodes = static_cast<std::int64_t>(engine.nodes().n);
  const auto group_rank = split(model, groups, P, how);
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
              how == Split::kMetis        ? "metis"
              : how == Split::kRoundRobin ? "round robin"
                                          : "blocks",
              static_cast<long long>(shared), static_cast<long long>(most_ghosts), most_sums / 1e3,
              most_ghost_bytes / 1e3, most_total / 1e3, most_messages);
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
    report(model, engine, P, Split::kBlocks);
    report(model, engine, P, Split::kRoundRobin);
    report(model, engine, P, Split::kMetis);
  }
  return 0;
}
