// The domain plan: which rank owns each node, what it sends and receives, and the bit-identical assembly of
// the element sums of nodes shared between ranks (docs/parallel-domain.md).
//
// The serial engine adds the element groups' nodal forces to each node in one order, the entries
// (flat group g, element i, node q of the element) ascending, from zero:
//   S_n[d] = ((0 + c_1[d]) + c_2[d]) + ... + c_m[d],   d < C of each entry (C = 3 forces, or 6 with moments),
// and floating-point addition is not associative, so on P ranks the same bits come only from the same
// additions in the same order. A node whose entries all come from one rank's groups is summed there as today
// (a rank's groups are a subsequence of the flat order, so its entries keep their order). A node touched by
// several ranks is summed by its owner alone: every rank ships each of its entries on the node as itself (a
// skyline slot), never a partial sum, and the owner adds them from zero in the serial order above. This is
// OpenRadioss's /PARITH/ON skyline (FSKY), summed in a fixed order as its asspar4 does.
//
// After integration the owner sends x, v (and omega for nodes with rotations) to the ranks whose elements
// read the node (its ghosts there).
//
// Every rank builds its plan from the replicated model and the same group ranks, so all ranks agree on every
// owner, slot and message size without talking.
#pragma once

#include <cstdint>
#include <span>
#include <type_traits>
#include <vector>

#include "solver/elements/element_groups.hpp"
#include "solver/engine/node_state.hpp"
#include "solver/parallel/comm.hpp"

namespace radx::solver::parallel {

// Calls f(group, nodes per element, components) for the group of flat index `flat`, components an
// integral_constant: 6 for a buffer of forces and moments (shells, beams, TYPE8 and TYPE13 springs), 3 for
// forces alone. The engine's own sums use it too (ExplicitEngine::visit_group_sums).
template <class Groups, class F>
void visit_group_entries(Groups& groups, std::int64_t flat, F&& f) {
  using Forces = std::integral_constant<std::size_t, 3>;
  using ForcesAndMoments = std::integral_constant<std::size_t, 6>;
  groups.visit(flat, [&](auto& g) {
    using Group = std::decay_t<decltype(g)>;
    if constexpr (std::is_same_v<Group, ShellGroup> || std::is_same_v<Group, BeamGroup>) {
      f(g, g.nodes_per_element(), ForcesAndMoments{});
    } else if constexpr (std::is_same_v<Group, SpringGroup>) {
      if (g.node_stride() == 6)
        f(g, g.nodes_per_element(), ForcesAndMoments{});
      else
        f(g, g.nodes_per_element(), Forces{});
    } else {
      f(g, g.nodes_per_element(), Forces{});
    }
  });
}

// The owning rank of every node: the rank whose groups have the most entries (element-node incidences) on
// it, ties to the lowest rank. A node no element touches (a rigid body's main node, a free node) goes to
// rank 0 for now. group_rank[flat] is the rank of each group, in [0, ranks).
[[nodiscard]] std::vector<std::int32_t> node_owner_ranks(const ElementGroups& groups,
                                                         std::span<const std::int32_t> group_rank,
                                                         std::int64_t node_count, int ranks);

// A run of consecutive owned nodes [first, last).
struct NodeRun {
  std::int64_t first = 0, last = 0;
};

// One term of a shared node's sum on its owner: `components` doubles at `offset` (in doubles) in the
// message from rank `source`.
struct Contribution {
  std::int32_t source = 0;
  std::int32_t offset = 0;
  std::int32_t components = 0;
};

// One rank's part of the decomposition. Lists are CSR arrays (a begin array and one flat list), indexed by
// rank where they say "per rank": no per-node containers.
struct DomainPlan {
  int ranks = 1;
  int rank = 0;
  std::int64_t node_count = 0;

  // Owned groups, ascending flat index; local_group[flat] is a group's position there, or -1.
  std::vector<std::int64_t> groups;
  std::vector<std::int32_t> local_group;

  // Owned nodes as runs, ascending (what the node passes walk instead of node chunks), and their count.
  std::vector<NodeRun> owned_runs;
  std::int64_t owned_nodes = 0;
  // Every node's owning rank (node_owner_ranks), the same on every rank.
  std::vector<std::int32_t> node_owner;

  // Ghost update, per rank r: the nodes this rank receives from their owner r (nodes its groups touch that
  // r owns) and the nodes it sends to r (nodes it owns that r's groups touch), ascending. *_rotation says,
  // entry by entry, whether the node has rotations (an entry of a 6-component group): omega rides along.
  std::vector<std::int64_t> ghost_begin;  // [ranks + 1]
  std::vector<std::int32_t> ghost_nodes;
  std::vector<std::uint8_t> ghost_rotation;
  std::vector<std::int64_t> send_begin;  // [ranks + 1]
  std::vector<std::int32_t> send_nodes;
  std::vector<std::uint8_t> send_rotation;

  // Skyline, sender side. A shared node is touched by the groups of more than one rank. Each entry of an
  // owned group on a shared node has a slot in the message to the node's owner: its components (3 or 6
  // doubles) at an offset in the slot storage, where the message to rank r is
  // [message_begin[r], message_begin[r + 1]) and its slots follow (flat, i, q). Per owned group (local
  // index), the shared entries as codes 32 i + q ascending and each one's offset.
  std::vector<std::int64_t> message_begin;       // [ranks + 1], in doubles
  std::vector<std::int64_t> shared_entry_begin;  // [groups.size() + 1]
  std::vector<std::uint16_t> shared_entry_code;
  std::vector<std::int64_t> shared_entry_offset;

  // Skyline, owner side: the owned shared nodes, ascending, each with its contributions in the serial order
  // (flat, i, q), and the size in doubles of the message expected from each rank.
  std::vector<std::int32_t> shared_nodes;
  std::vector<std::int64_t> contribution_begin;  // [shared_nodes.size() + 1]
  std::vector<Contribution> contributions;
  std::vector<std::int64_t> expected_from;  // [ranks], in doubles

  // The offset of entry (element i, node q) of group `flat` in the slot storage, or -1 when the entry's
  // node is not shared (or the group not owned): a binary search in the group's shared entries.
  [[nodiscard]] std::int64_t entry_slot(std::int64_t flat, int i, int q) const;
  // The shared entries of owned group `local` (codes 32 i + q ascending, and their offsets).
  [[nodiscard]] std::span<const std::uint16_t> shared_codes(std::size_t local) const {
    const auto b = static_cast<std::size_t>(shared_entry_begin[local]);
    return {shared_entry_code.data() + b, static_cast<std::size_t>(shared_entry_begin[local + 1]) - b};
  }
  [[nodiscard]] std::span<const std::int64_t> shared_offsets(std::size_t local) const {
    const auto b = static_cast<std::size_t>(shared_entry_begin[local]);
    return {shared_entry_offset.data() + b, static_cast<std::size_t>(shared_entry_begin[local + 1]) - b};
  }
};

// The plan of rank `rank` of `ranks` for groups placed by group_rank[flat] (every rank computes the same
// global facts from the replicated model, then keeps its own part). Throws std::invalid_argument when
// group_rank does not give every group a rank in [0, ranks).
[[nodiscard]] DomainPlan build_domain_plan(const ElementGroups& groups,
                                           std::span<const std::int32_t> group_rank, std::int64_t node_count,
                                           int ranks, int rank);

// Bytes one rank sends and receives per cycle (messages to itself not counted), and the messages.
struct DomainTraffic {
  std::int64_t shared_sum_sent = 0, shared_sum_received = 0;
  std::int64_t ghost_sent = 0, ghost_received = 0;
  int shared_sum_messages = 0, ghost_messages = 0;  // messages sent to other ranks
};
[[nodiscard]] DomainTraffic domain_traffic(const DomainPlan& plan);

// The skyline's slot storage of one rank and its exchange. Keeps a reference to the plan, which must outlive
// it.
class SharedSums {
 public:
  explicit SharedSums(const DomainPlan& plan);

  // The slot at `offset` (DomainPlan::entry_slot): its entry's components, written by the element stage.
  // Slots are distinct, so any thread may write any of them.
  [[nodiscard]] double* slot(std::int64_t offset) { return storage_.data() + offset; }
  [[nodiscard]] std::span<const double> storage() const { return storage_; }

  // One message per rank (indexed by rank; empty where this rank owns none of the shared nodes it touches):
  // the slots of the nodes that rank owns, as they lie in the storage.
  [[nodiscard]] std::vector<Buffer> pack() const;

  // The owner's side: received[s] is rank s's message. Each owned shared node's sum is made from zero in
  // the serial order of its contributions and stored into element_sums[6 node + d] (d < 6), where the
  // serial engine has it; components no contribution has stay 0. Throws std::runtime_error when a message
  // does not have the size the plan expects (plans built from different inputs).
  void sum_on_owner(const std::vector<Buffer>& received, std::span<double> element_sums) const;

 private:
  const DomainPlan& plan_;
  std::vector<double> storage_;
};

// The element stage of owned group `flat` on this rank: entries on nodes the rank alone touches are added to
// element_sums[6 node + d] (element by element, node by node, as the serial engine adds them), entries on
// shared nodes are written into their slots. The reference for the engine's own region-ordered commits.
void add_owned_group_sums(const ElementGroups& groups, const DomainPlan& plan, std::int64_t flat,
                          std::span<double> element_sums, SharedSums& shared);

// Ships every rank's slots to the owners and sums them there (pack, comm.exchange, sum_on_owner). Called by
// every rank.
void exchange_shared_sums(const SharedSums& shared, Comm& comm, std::span<double> element_sums);

// Ghost update after integration: x, y, z, vx, vy, vz, then wx, wy, wz where the node has rotations, for
// each node sent to (ghost_pack) or received from (ghost_unpack) each rank. ghost_unpack throws
// std::runtime_error when a message does not have the size the plan expects.
[[nodiscard]] std::vector<Buffer> ghost_pack(const DomainPlan& plan, const NodeState& nodes);
void ghost_unpack(const DomainPlan& plan, const std::vector<Buffer>& received, NodeState& nodes);
void exchange_ghosts(const DomainPlan& plan, Comm& comm, NodeState& nodes);

}  // namespace radx::solver::parallel
