// The decomposition of a model over P ranks: which rank computes each element group.
//
// The unit is the engine's element group (build_groups: up to 128 elements of one part), never split, so
// every element is computed on its rank exactly as on one rank. The groups are the vertices of a graph given
// to METIS (METIS_PartGraphKway, a fixed seed: the same input gives the same partition on every run):
//   - an edge between two groups for each node they share (weight: the shared node count), for each
//     /INTER/TYPE2 tie between the groups of its secondary node and those of its main segment's nodes (1 a
//     tie), and for each TYPE7 candidate pair at t = 0 between its node's group and its segment's, so the
//     cut crosses few nodes, ties and contact pairs;
//   - two balance constraints, ubvec {1.03, 1.10}: the kernel cost (instructions per element-cycle of the
//     group's kernel x its elements) and the contact work (each TYPE7 secondary node, main segment and t = 0
//     candidate pair counted once, on one group: the first touching the node, the segment's element's);
//   - a rigid body whose elements (those touching its nodes) are under 1 % of the model's elements has all
//     the groups touching its nodes contracted into one vertex before METIS, so it lands on one rank.
// The statistics (owned, ghost and shared nodes, neighbours, imbalance) follow from the group ranks alone,
// for a METIS partition or one given by hand.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "solver/elements/element_groups.hpp"
#include "solver/model/model.hpp"

namespace radx::solver::parallel {

// METIS's balance tolerances: the heaviest rank over the mean, for the kernel cost and the contact work.
inline constexpr double kCostTolerance = 1.03;
inline constexpr double kContactTolerance = 1.10;
// METIS_OPTION_SEED: fixed, so a model always gets the same partition.
inline constexpr int kPartitionSeed = 1;
// A rigid body is kept on one rank when its elements are under this fraction of the model's elements.
inline constexpr double kSmallRigidBody = 0.01;

// Each group's balance weights, in flat group order.
struct GroupWeights {
  std::vector<std::int64_t> elements;  // elements of the group
  std::vector<std::int64_t> cost;      // kernel instructions per cycle: cost per element x elements
  std::vector<std::int64_t> contact;   // TYPE7 secondary nodes, main segments and t = 0 candidates it carries
};

// The kernel cost weights and the contact work of every group (see the header comment).
[[nodiscard]] GroupWeights group_weights(const model::Model& m, const ElementGroups& groups);

// One rank's share of a decomposition.
struct RankShare {
  std::int64_t groups = 0, elements = 0, cost = 0, contact = 0;
  std::int64_t owned_nodes = 0;   // nodes it owns (node_owner_ranks, solver/parallel/domain.hpp)
  std::int64_t ghost_nodes = 0;   // nodes its elements touch that another rank owns
  std::int64_t shared_nodes = 0;  // nodes its elements touch that another rank's elements touch too
  std::vector<int> neighbours;    // ranks it shares a node with, ascending
};

struct PartitionSummary {
  int ranks = 1;
  std::vector<RankShare> per_rank;
  std::int64_t shared_nodes = 0;      // nodes touched by the elements of more than one rank
  double cost_imbalance = 1.0;        // heaviest rank's cost over the mean
  double contact_imbalance = 1.0;     // heaviest rank's contact work over the mean (1 without contact)
  std::int64_t rigid_bodies_cut = 0;  // bodies whose nodes' owners are on more than one rank
  std::int64_t ties_cut = 0;          // TYPE2 ties whose secondary node and main nodes have different owners
  // Each node's owner rank (-1: a node no element of a group touches), by node_owner_ranks
  // (solver/parallel/domain.hpp).
  std::vector<std::int32_t> node_owner;
};

struct Partition {
  std::vector<int> group_rank;         // flat group -> rank
  std::int64_t rigid_bodies_kept = 0;  // bodies contracted to one vertex (under kSmallRigidBody)
  PartitionSummary summary;
};

// Each group's rank for `ranks` ranks. ranks == 1: every group on rank 0, without METIS. Throws
// std::invalid_argument when ranks < 1 or when there are fewer groups to deal out (after the small rigid
// bodies are contracted) than ranks, saying how many ranks the model accepts; std::runtime_error when METIS
// fails.
[[nodiscard]] Partition partition_groups(const model::Model& m, const ElementGroups& groups, int ranks);

// The statistics of a given assignment (group_rank: one rank in [0, ranks) per flat group). Throws
// std::invalid_argument when group_rank has another size than the group count or a rank out of range.
[[nodiscard]] PartitionSummary summarize_partition(const model::Model& m, const ElementGroups& groups,
                                                   std::span<const int> group_rank, int ranks);

// The flat group of each cell of the model (cells in the results' order: first_cell), -1 for a cell in no
// group (an element without forces).
[[nodiscard]] std::vector<std::int32_t> cell_groups(const model::Model& m, const ElementGroups& groups);

// What is wrong with `group_rank` for `groups` and `ranks`, or "" when nothing is.
[[nodiscard]] std::string check_group_ranks(std::int64_t groups, std::span<const int> group_rank, int ranks);

}  // namespace radx::solver::parallel
