// Candidate search of a TYPE7 interface (docs/theory/type7-lagdt.md 4.8): a voxel (bucket) sort of the
// secondary nodes against the main segments' boxes enlarged by the largest pair gap and a margin
// Bumult * (mean main segment edge length). Candidates are kept between sorts; a new sort is due when the
// nodes have moved, since the last sort, by more than the margin can absorb (two nodes approaching each
// other each use half of it). Cost O(N + M) per sort in the number of nodes and segments.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "contact/parallel_for.hpp"

namespace radx::contact {

// One candidate pair: a secondary node (index into the interface's secondary list, not a node index) and
// a main segment (index into the interface's segment list). Candidates are sorted by (node, segment).
struct Candidate {
  std::int32_t node;
  std::int32_t segment;
  friend bool operator==(const Candidate&, const Candidate&) = default;
};

// Coordinates of all nodes of the model (dense node indices), read during the call only.
struct Coordinates {
  std::span<const double> x, y, z;
};

class Type7Search {
 public:
  // `secondary`: dense node indices of the secondary nodes. `segments`: dense node indices n1..n4 of each
  // main segment (n4 == n3 for a triangle). `gap_max`: the largest pair gap of the interface (a node
  // farther than this from every segment cannot be in contact). `bumult`: the margin factor.
  Type7Search(std::vector<std::int32_t> secondary, std::vector<std::array<std::int32_t, 4>> segments,
              double gap_max, double bumult);

  // Sorts again when due (or when `force` is set) and returns true when it did. `x0` coordinates at the
  // previous call are tracked internally; the first call always sorts. `parallel` (may be null) runs the
  // displacement test of the tracked nodes in chunks of kTrackedChunk nodes.
  bool update(const Coordinates& c, bool force = false, const ParallelFor* parallel = nullptr);

  // Tracked nodes per chunk of the displacement test (a few microseconds of work each).
  static constexpr std::int64_t kTrackedChunk = 4096;

  // Candidates of the last sort: every (node, segment) whose node lies inside the segment's box enlarged
  // by gap_max + margin, except a node and a segment that contains it (self-contact), sorted. Pairs of
  // nodes and segments removed since are dropped here, in one pass on the first call after the removals
  // (so a burst of removals costs one pass, not one per removal; not to be called concurrently).
  [[nodiscard]] const std::vector<Candidate>& candidates() const;
  [[nodiscard]] double margin() const { return margin_; }
  [[nodiscard]] std::int64_t sorts() const { return sorts_; }

  // Removes a segment or a node from all later sorts and from the current candidates (Idel, /DT/INTER/DEL).
  void remove_segment(std::int32_t segment);
  void remove_node(std::int32_t node);

 private:
  // The sort and its stages (type7_search.cpp).
  struct Grid;
  void sort(const Coordinates& c);
  void set_margin(const Coordinates& c);
  void keep_sort_coordinates(const Coordinates& c);
  bool make_grid(const Coordinates& c, Grid& grid) const;
  void bin_nodes(const Coordinates& c, const Grid& grid);
  void find_pairs(const Coordinates& c, const Grid& grid);
  void order_by_node();
  void drop_unused_tracked();
  void release_tracked(std::int32_t node);

  std::vector<std::int32_t> secondary_;
  std::vector<std::array<std::int32_t, 4>> segments_;
  std::vector<std::uint8_t> node_removed_, segment_removed_;
  double gap_max_ = 0, bumult_ = 0.2, margin_ = 0;
  std::vector<std::int32_t> tracked_;  // every node whose motion can use up the margin (secondary and main)
  std::vector<std::int32_t> users_;    // [tracked] active secondary entries and segments using the node
  bool tracked_stale_ = false;         // a node of tracked_ has lost its last user since the last pruning
  std::vector<double> x_sort_;         // [3 * tracked] coordinates at the last sort
  mutable std::vector<Candidate> candidates_;
  mutable bool candidates_stale_ = false;  // candidates_ may still hold pairs of removed nodes or segments
  std::int64_t sorts_ = 0;

  // Work arrays of the sort, kept so that later sorts reuse their capacity instead of allocating.
  std::vector<std::int32_t> node_cell_;   // [secondary] cell of each active node, -1 when removed
  std::vector<std::int32_t> cell_first_;  // [cells + 1] CSR offsets of the cells into cell_node_
  std::vector<std::int32_t> cell_node_;   // [active nodes] secondary index, grouped by cell
  std::vector<double> cell_xyz_;          // [3 * active nodes] coordinates in the order of cell_node_
  std::vector<Candidate> found_;          // pairs in the order found (segment by segment)
  std::vector<std::int32_t> node_first_;  // [secondary + 1] CSR offsets used to order pairs by node
  std::vector<double> chunk_d2_;          // [chunks] largest squared displacement per chunk (update)
};

// Reference search for tests: every (node, segment) pair within the enlarged boxes, by brute force.
std::vector<Candidate> brute_force_candidates(const Coordinates& c, std::span<const std::int32_t> secondary,
                                              std::span<const std::array<std::int32_t, 4>> segments,
                                              double enlarge);

}  // namespace radx::contact
