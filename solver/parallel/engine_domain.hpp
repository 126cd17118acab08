// The explicit engine's side of the domain decomposition: what one rank computes of a cycle and what it
// exchanges so that P ranks reproduce one rank's results to the bit (docs/parallel.md).
//
// Groups are placed on ranks by the METIS partition (partition.hpp), computed on rank 0 and broadcast; a
// model with fewer groups than ranks takes contiguous blocks of the flat group order instead,
// rank(g) = floor(g P / G), leaving some ranks without groups. A rank's groups, in flat order, are a
// subsequence of the serial order. Each node has one owner (node_owner_ranks). Per cycle:
//   - each rank computes its own groups only; their entries on nodes no other rank touches are summed as the
//     serial engine sums them (the same order: the group order restricted to the groups reaching the node);
//     entries on shared nodes also go to their skyline slots, and each shared node's owner sums them from
//     zero in the serial order (DomainPlan, SharedSums):   S_n[d] = ((0 + c_1[d]) + c_2[d]) + ... + c_m[d];
//   - the replicated nodes (replicated_nodes: those a stage that runs whole on every rank reads or writes:
//     loads, imposed motion, rigid walls and bodies, ties, contact, moving skews, accelerometers) get their
//     sums S_n from their owners on every rank, and every rank runs their node passes and those stages on
//     the same values as one rank;
//   - every other node is assembled, accelerated, conditioned and integrated by its owner alone (node passes
//     over pass_runs: owned or replicated nodes); after integration the owners send x, v (and omega) to the
//     ranks whose groups read the node (its ghosts there);
//   - each rank's groups' time-step votes, combined in group order into one record a rank, ride with the
//     replicated nodes' sums to every rank (complete_element_sums), which merges them as one rank's scan;
//   - before the outputs read the nodes or groups, the owners send what those read to rank 0, the writer
//     (gather_node_state, gather_node_motion, share_group_arrays with a root); the listing of deleted
//     elements and a bad element's message gather life factors and steps on every rank. Boundary conditions
//     are applied by every rank to every node they hold (harmless where a rank does not integrate the node).
#pragma once

#include <cstdint>
#include <cstring>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "solver/elements/element_groups.hpp"
#include "solver/model/model.hpp"
#include "solver/model/run_controls.hpp"
#include "solver/parallel/comm.hpp"
#include "solver/parallel/domain.hpp"

namespace radx::solver::parallel {

// The rank of each group for `ranks` ranks: contiguous blocks of the flat order, floor(g P / G).
[[nodiscard]] std::vector<std::int32_t> block_group_ranks(std::int64_t groups, int ranks);

// The rank of each group for the engine on comm's ranks: `given` when not empty (one rank in 0 .. P-1 per
// group, as radx-engine-mpi --partition FILE reads them; rank 0's are used), else the METIS partition, or
// blocks when the model has fewer groups than ranks; decided on rank 0 and broadcast, so every rank holds the
// same. Called by every rank; throws on every rank when rank 0's `given` does not fit the groups and ranks.
[[nodiscard]] std::vector<std::int32_t> engine_group_ranks(const model::Model& model,
                                                           const ElementGroups& groups, Comm& comm,
                                                           std::span<const std::int32_t> given = {});

// The nodes that a stage run whole on every rank reads or writes, 1 each: nodes of loads (concentrated,
// pressure, gravity), imposed velocities and displacements, delayed initial velocities, rigid walls (their
// secondary and wall nodes), rigid bodies, TYPE2 ties (secondary nodes and main segments), contact interfaces
// (secondary nodes and main segments), moving skews and accelerometers. Boundary conditions are not among
// them: they act on each node alone, on whichever rank integrates it.
[[nodiscard]] std::vector<std::uint8_t> replicated_nodes(const model::Model& model);

// What a model uses that the engine does not yet run on more than one rank, by keyword (empty: all of it
// runs): /SECT, whose force reads every element's nodal forces at every cycle (not gathered). The same list
// on every rank: it reads the replicated model and controls only.
[[nodiscard]] std::vector<std::string> features_not_distributed(const model::Model& model,
                                                                const model::RunControls& controls);

class EngineDomain {
 public:
  // Every rank builds its domain from the same groups and the same group ranks (engine_group_ranks).
  // `replicated` (replicated_nodes, one entry a node) and `watched` (the time history's nodes, whose whole
  // state gather_node_motion sends) are the same on every rank.
  EngineDomain(const ElementGroups& groups, std::vector<std::int32_t> group_rank,
               std::span<const std::uint8_t> replicated, std::span<const std::int32_t> watched, Comm& comm);
  EngineDomain(const EngineDomain&) = delete;
  EngineDomain& operator=(const EngineDomain&) = delete;

  [[nodiscard]] bool owns(std::int64_t flat) const {
    return plan_.local_group[static_cast<std::size_t>(flat)] >= 0;
  }
  [[nodiscard]] const DomainPlan& plan() const { return plan_; }
  [[nodiscard]] Comm& comm() const { return comm_; }

  // The entries of owned group `flat` on shared nodes into their skyline slots (any thread; slots are
  // distinct).
  void write_shared_slots(const ElementGroups& groups, std::int64_t flat);

  // The nodes this rank's node passes walk: those it owns and the replicated ones, as ascending runs.
  [[nodiscard]] const std::vector<NodeRun>& pass_runs() const { return pass_runs_; }

  // After the element stage: the owners sum the shared nodes, every rank receives the replicated nodes' sums
  // into element_sums [node][6], and the partial sums of ghosts (nodes owned elsewhere) are cleared. Each
  // rank's `record` (its step vote) rides in the same message: every rank's is returned, indexed by rank.
  // Called by every rank.
  [[nodiscard]] std::vector<Buffer> complete_element_sums(std::span<double> element_sums,
                                                          const Buffer& record);

  // After integration: x, v (and omega) of each ghost from its owner. Called by every rank.
  void update_ghosts(NodeState& nodes);

  // The state of every node rank `root` does not integrate (x, v, a, f, omega, moments, angular a, external
  // forces), from its owner, so that the root holds every node as one rank does: before its outputs read
  // them. Called by every rank.
  void gather_node_state(NodeState& nodes, int root);
  // Less of it, for a time-history or listing cycle: every node's v and a (the parts' kinetic energy and
  // momentum) and the whole state of the watched nodes.
  void gather_node_motion(NodeState& nodes, int root);

  // This rank's owned nodes, as runs (each node is counted by one rank in order-free sums).
  [[nodiscard]] const std::vector<NodeRun>& owned_runs() const { return plan_.owned_runs; }

  // One trivially copyable record per group (indexed by flat group): each owner's records reach every rank.
  template <class T>
  void share_group_records(std::span<T> per_group) {
    static_assert(std::is_trivially_copyable_v<T>);
    Buffer mine(plan_.groups.size() * sizeof(T));
    std::byte* p = mine.data();
    for (const std::int64_t flat : plan_.groups) {
      std::memcpy(p, &per_group[static_cast<std::size_t>(flat)], sizeof(T));
      p += sizeof(T);
    }
    const auto all = comm_.all_gather(mine);
    for_each_remote_group(all, [&](std::int64_t flat, const std::byte*& q) {
      std::memcpy(&per_group[static_cast<std::size_t>(flat)], q, sizeof(T));
      q += sizeof(T);
    });
  }

  // Arrays of the groups, chosen by select(group, visit) calling visit(array) for each array to share: each
  // owner's arrays reach every rank's copies of its groups (root -1), or rank root's alone. Array sizes are
  // the same on every rank (groups are built from the replicated model).
  template <class Select>
  void share_group_arrays(ElementGroups& groups, Select&& select, int root = -1) {
    Buffer mine;
    for (const std::int64_t flat : plan_.groups)
      groups.visit(flat, [&](auto& g) {
        select(g, [&](const auto& array) {
          const std::size_t bytes = array.size() * sizeof(array[0]);
          const std::size_t at = mine.size();
          mine.resize(at + bytes);
          if (bytes != 0) std::memcpy(mine.data() + at, array.data(), bytes);
        });
      });
    const auto all = root < 0 ? comm_.all_gather(mine) : comm_.gather(mine, root);
    if (all.empty()) return;  // not the root
    for_each_remote_group(all, [&](std::int64_t flat, const std::byte*& q) {
      groups.visit(flat, [&](auto& g) {
        select(g, [&](auto& array) {
          const std::size_t bytes = array.size() * sizeof(array[0]);
          if (bytes != 0) std::memcpy(array.data(), q, bytes);
          q += bytes;
        });
      });
    });
  }

 private:
  // f(flat, cursor) for each group of every other rank, in that rank's order, the cursor walking its message.
  template <class F>
  void for_each_remote_group(const std::vector<Buffer>& all, F&& f) const {
    for (std::size_t r = 0; r < all.size(); ++r) {
      if (static_cast<int>(r) == plan_.rank) continue;
      const std::byte* q = all[r].data();
      for (std::size_t k = static_cast<std::size_t>(rank_groups_begin_[r]);
           k < static_cast<std::size_t>(rank_groups_begin_[r + 1]); ++k)
        f(rank_groups_[k], q);
      if (q != all[r].data() + all[r].size())
        throw std::runtime_error("a rank's group message does not have the size its groups need");
    }
  }

  Comm& comm_;
  std::vector<std::int32_t> group_rank_;
  // Every rank's groups, ascending: rank r's are rank_groups_[rank_groups_begin_[r] .. [r + 1]).
  std::vector<std::int64_t> rank_groups_begin_;
  std::vector<std::int64_t> rank_groups_;
  DomainPlan plan_;
  SharedSums shared_;  // refers to plan_
  // A field of the nodes: `width` doubles a node from `data` (node n at data + width n).
  struct NodeField {
    double* data;
    std::size_t width;
  };
  // Each rank sends `header` and its runs[rank] of every field; the others' runs arrive into this rank's
  // fields, and every rank's header is returned, indexed by rank: on every rank (root -1) or on rank root
  // alone (the others return no header and receive nothing).
  void gather_runs_of_state(const std::vector<std::vector<NodeRun>>& runs, NodeState& nodes, int root);
  std::vector<Buffer> all_gather_runs(const std::vector<std::vector<NodeRun>>& runs,
                                      std::span<const NodeField> fields, const Buffer& header = {},
                                      int root = -1);

  // Every rank's owned nodes, replicated ones (their sums go to every rank) and the rest (gathered for
  // outputs only), as runs.
  std::vector<std::vector<NodeRun>> replicated_runs_;
  std::vector<std::vector<NodeRun>> unreplicated_runs_;
  std::vector<std::vector<NodeRun>> watched_runs_;  // unreplicated nodes of the time history, per owner
  bool any_watched_ = false;                        // some rank owns one (the same on every rank)
  std::vector<NodeRun> pass_runs_;
  std::vector<std::int32_t> partial_ghosts_;  // ghosts not replicated: their local sums are partial
};

}  // namespace radx::solver::parallel
