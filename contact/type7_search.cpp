// Candidate search of a TYPE7 interface (docs/theory/type7-lagdt.md 4.8; section 5, step 2).
//
// Candidate. A secondary node s and a main segment m (nodes n1..n4, n4 == n3 for a triangle) form a
// candidate when s lies in the axis-aligned box of m's nodes enlarged on every side by e = gap_max + margin,
//     min_k x_k(a) - e <= x_s(a) <= max_k x_k(a) + e   for each axis a,
// and s is not one of m's nodes (a node never contacts a segment it belongs to). gap_max bounds every pair
// gap, so a node outside the box enlarged by gap_max alone is farther than its gap from the segment.
//
// Margin. margin = Bumult * (mean main segment edge length), the mean over every edge of every active
// segment (4 per quadrangle, 3 per triangle), taken at the first sort (coordinates are not known before)
// and fixed afterwards.
//
// When a new sort is due. Let d = max over the tracked nodes (active secondary nodes and nodes of active
// segments) of |x - x_sort|. Every node of a segment moved by at most d, so the segment's box now lies
// within its box at the sort enlarged by d, and the secondary node moved by at most d as well. A pair within
// gap_max of the box at the current coordinates was thus within gap_max + 2 d of it at the sort: it is still
// a kept candidate while 2 d < margin. A new sort is due when 2 d >= margin.
//
// Sort (bucket / voxel sort), O(N + M) for N secondary nodes and M segments:
//  1. box of the active secondary nodes; cell side h = mean over the active segments of the largest side of
//     the enlarged box, grown until the grid has at most 2 (N + M) cells, so memory and cell loops stay
//     linear however the boxes are shaped;
//  2. counting sort of the nodes into the cells (CSR offsets, nodes in increasing order inside a cell, their
//     coordinates copied in that order so that the box tests read contiguous memory);
//  3. for each active segment, the cells its enlarged box overlaps and the box test of each node in them;
//  4. a stable counting sort of the pairs (found segment by segment) by node gives (node, segment) order.
// The cell of a coordinate is clamp(trunc((x - x0) / h)) with x0 the low corner of the node box. Rounded
// subtraction and multiplication by a positive constant are monotonic, and so are clamping and truncation,
// so a node inside a box always falls in a cell between those of the box corners: the voxel sort finds
// exactly the pairs of the brute-force test below, which uses the same expressions.
#include "contact/type7_search.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace radx::contact {

namespace {

using Segment = std::array<std::int32_t, 4>;

struct Box {
  double lo[3], hi[3];
};

// The segment's box enlarged by `e` on every side. The sort and the brute-force reference both use this
// function so that the two agree to the last bit.
Box enlarged_box(const Coordinates& c, const Segment& q, double e) {
  Box b{};
  const std::span<const double>* axes[3] = {&c.x, &c.y, &c.z};
  for (int a = 0; a < 3; ++a) {
    const std::span<const double>& v = *axes[a];
    double lo = v[static_cast<std::size_t>(q[0])], hi = lo;
    for (int k = 1; k < 4; ++k) {
      const double t = v[static_cast<std::size_t>(q[k])];
      lo = std::min(lo, t);
      hi = std::max(hi, t);
    }
    b.lo[a] = lo - e;
    b.hi[a] = hi + e;
  }
  return b;
}

bool inside(const Box& b, double x, double y, double z) {
  return b.lo[0] <= x && x <= b.hi[0] && b.lo[1] <= y && y <= b.hi[1] && b.lo[2] <= z && z <= b.hi[2];
}

bool contains_node(const Segment& q, std::int32_t node) {
  return q[0] == node || q[1] == node || q[2] == node || q[3] == node;
}

// Number of distinct nodes of a segment written to `out` (3 for a triangle n4 == n3).
int distinct_nodes(const Segment& q, std::int32_t out[4]) {
  int n = 0;
  for (int k = 0; k < 4; ++k)
    if (std::find(out, out + n, q[k]) == out + n) out[n++] = q[k];
  return n;
}

// Cell of coordinate `x` along one axis; a NaN lands in cell 0 rather than in undefined behaviour.
std::int32_t cell_of(double x, double x0, double inv_h, double last) {
  const double t = (x - x0) * inv_h;
  return static_cast<std::int32_t>(t > 0 ? (t < last ? t : last) : 0.0);
}

}  // namespace

Type7Search::Type7Search(std::vector<std::int32_t> secondary, std::vector<Segment> segments, double gap_max,
                         double bumult)
    : secondary_(std::move(secondary)),
      segments_(std::move(segments)),
      node_removed_(secondary_.size(), 0),
      segment_removed_(segments_.size(), 0),
      gap_max_(gap_max),
      bumult_(bumult) {
  assert(gap_max >= 0 && bumult >= 0);
  // Tracked nodes, sorted so that a removal finds its node by bisection; each counts its users so that a
  // node stops being tracked (and cannot trigger sorts) once nothing active refers to it.
  tracked_ = secondary_;
  for (const Segment& q : segments_) tracked_.insert(tracked_.end(), q.begin(), q.end());
  std::sort(tracked_.begin(), tracked_.end());
  tracked_.erase(std::unique(tracked_.begin(), tracked_.end()), tracked_.end());
  users_.assign(tracked_.size(), 0);
  auto add_user = [&](std::int32_t node) {
    ++users_[static_cast<std::size_t>(std::lower_bound(tracked_.begin(), tracked_.end(), node) -
                                      tracked_.begin())];
  };
  for (std::int32_t n : secondary_) add_user(n);
  for (const Segment& q : segments_) {
    std::int32_t d[4];
    const int nd = distinct_nodes(q, d);
    for (int k = 0; k < nd; ++k) add_user(d[k]);
  }
}

void Type7Search::release_tracked(std::int32_t node) {
  const auto it = std::lower_bound(tracked_.begin(), tracked_.end(), node);
  assert(it != tracked_.end() && *it == node);
  auto& u = users_[static_cast<std::size_t>(it - tracked_.begin())];
  if (--u == 0) tracked_stale_ = true;
}

// Removes the tracked nodes nobody uses any more, keeping the order (and x_sort_ in step with it).
void Type7Search::drop_unused_tracked() {
  const bool with_x = x_sort_.size() == 3 * tracked_.size();
  std::size_t n = 0;
  for (std::size_t k = 0; k < tracked_.size(); ++k) {
    if (users_[k] == 0) continue;
    tracked_[n] = tracked_[k];
    users_[n] = users_[k];
    if (with_x)
      for (std::size_t a = 0; a < 3; ++a) x_sort_[3 * n + a] = x_sort_[3 * k + a];
    ++n;
  }
  tracked_.resize(n);
  users_.resize(n);
  if (with_x) x_sort_.resize(3 * n);
  tracked_stale_ = false;
}

bool Type7Search::update(const Coordinates& c, bool force, const ParallelFor* parallel) {
  if (force || sorts_ == 0) {
    sort(c);
    return true;
  }
  if (tracked_stale_) drop_unused_tracked();
  // Largest squared displacement since the last sort: a flat loop over the tracked nodes, every cycle, in
  // chunks of kTrackedChunk nodes (each its own maximum, then the maximum of those). A maximum is exact and
  // does not depend on the order it is taken in (a NaN is skipped by every std::max(d2, NaN) alike), so the
  // result is that of one loop for any division and any thread.
  const auto n = static_cast<std::int64_t>(tracked_.size());
  const std::int64_t chunks = (n + kTrackedChunk - 1) / kTrackedChunk;
  chunk_d2_.assign(static_cast<std::size_t>(chunks), 0.0);
  const std::int32_t* t = tracked_.data();
  const double* xs = x_sort_.data();
  const double *x = c.x.data(), *y = c.y.data(), *z = c.z.data();
  double* out = chunk_d2_.data();
  const auto body = [=](std::int64_t ch) {
    const auto first = static_cast<std::size_t>(ch * kTrackedChunk);
    const auto last = static_cast<std::size_t>(std::min(n, (ch + 1) * kTrackedChunk));
    // Four running maxima: one would make every node wait for the previous node's comparison.
    double m[4] = {0, 0, 0, 0};
    std::size_t k = first;
    for (; k + 4 <= last; k += 4)
      for (std::size_t u = 0; u < 4; ++u) {
        const std::int32_t i = t[k + u];
        const double* s = xs + 3 * (k + u);
        const double dx = x[i] - s[0], dy = y[i] - s[1], dz = z[i] - s[2];
        m[u] = std::max(m[u], dx * dx + dy * dy + dz * dz);
      }
    for (; k < last; ++k) {
      const std::int32_t i = t[k];
      const double dx = x[i] - xs[3 * k], dy = y[i] - xs[3 * k + 1], dz = z[i] - xs[3 * k + 2];
      m[0] = std::max(m[0], dx * dx + dy * dy + dz * dz);
    }
    out[ch] = std::max(std::max(m[0], m[1]), std::max(m[2], m[3]));
  };
  run_chunks(parallel, chunks, body);
  double d2 = 0;
  for (const double v : chunk_d2_) d2 = std::max(d2, v);
  // 2 d >= margin, squared (both sides are non-negative).
  if (4 * d2 >= margin_ * margin_) {
    sort(c);
    return true;
  }
  return false;
}

// The grid of one sort (step 1): the box of the active secondary nodes, the enlargement of the segments'
// boxes and the cells.
struct Type7Search::Grid {
  double nlo[3], nhi[3];  // box of the active secondary nodes
  double e;               // gap_max + margin
  double inv_h;           // 1 / cell side
  double last[3];         // last cell along each axis
  std::int32_t nx, ny;    // cells along x and y
  std::size_t n_cells, n_nodes;
};

void Type7Search::sort(const Coordinates& c) {
  if (tracked_stale_) drop_unused_tracked();
  if (sorts_ == 0) set_margin(c);
  ++sorts_;
  keep_sort_coordinates(c);
  candidates_.clear();
  candidates_stale_ = false;
  Grid grid;
  if (!make_grid(c, grid)) return;
  bin_nodes(c, grid);
  find_pairs(c, grid);
  order_by_node();
}

// The margin, from the mean edge length of the active segments at the first sort.
void Type7Search::set_margin(const Coordinates& c) {
  const double *x = c.x.data(), *y = c.y.data(), *z = c.z.data();
  const std::size_t n_seg = segments_.size();
  double sum = 0;
  std::int64_t edges = 0;
  for (std::size_t s = 0; s < n_seg; ++s) {
    if (segment_removed_[s]) continue;
    const Segment& q = segments_[s];
    const int ne = q[3] == q[2] ? 3 : 4;
    for (int k = 0; k < ne; ++k) {
      const auto i = static_cast<std::size_t>(q[k]), j = static_cast<std::size_t>(q[(k + 1) % ne]);
      sum += std::sqrt((x[j] - x[i]) * (x[j] - x[i]) + (y[j] - y[i]) * (y[j] - y[i]) +
                       (z[j] - z[i]) * (z[j] - z[i]));
    }
    edges += ne;
  }
  margin_ = edges > 0 ? bumult_ * sum / static_cast<double>(edges) : 0.0;
}

void Type7Search::keep_sort_coordinates(const Coordinates& c) {
  const double *x = c.x.data(), *y = c.y.data(), *z = c.z.data();
  x_sort_.resize(3 * tracked_.size());
  for (std::size_t k = 0; k < tracked_.size(); ++k) {
    const auto i = static_cast<std::size_t>(tracked_[k]);
    x_sort_[3 * k] = x[i];
    x_sort_[3 * k + 1] = y[i];
    x_sort_[3 * k + 2] = z[i];
  }
}

// 1. Box of the active secondary nodes and the cell side. False when there is no active node or segment.
bool Type7Search::make_grid(const Coordinates& c, Grid& grid) const {
  const double *x = c.x.data(), *y = c.y.data(), *z = c.z.data();
  const std::size_t n_sec = secondary_.size(), n_seg = segments_.size();
  double* nlo = grid.nlo;
  double* nhi = grid.nhi;
  for (int a = 0; a < 3; ++a) {
    nlo[a] = std::numeric_limits<double>::infinity();
    nhi[a] = -nlo[a];
  }
  std::size_t n_nodes = 0;
  for (std::size_t i = 0; i < n_sec; ++i) {
    if (node_removed_[i]) continue;
    const auto g = static_cast<std::size_t>(secondary_[i]);
    const double p[3] = {x[g], y[g], z[g]};
    for (int a = 0; a < 3; ++a) {
      nlo[a] = std::min(nlo[a], p[a]);
      nhi[a] = std::max(nhi[a], p[a]);
    }
    ++n_nodes;
  }
  const double e = gap_max_ + margin_;
  double side_sum = 0;
  std::size_t n_segs = 0;
  for (std::size_t s = 0; s < n_seg; ++s) {
    if (segment_removed_[s]) continue;
    const Box b = enlarged_box(c, segments_[s], e);
    side_sum += std::max({b.hi[0] - b.lo[0], b.hi[1] - b.lo[1], b.hi[2] - b.lo[2]});
    ++n_segs;
  }
  if (n_nodes == 0 || n_segs == 0) return false;

  const double extent[3] = {nhi[0] - nlo[0], nhi[1] - nlo[1], nhi[2] - nlo[2]};
  double h = side_sum / static_cast<double>(n_segs);
  if (!(h > 0) || !std::isfinite(h)) h = std::max({extent[0], extent[1], extent[2]});
  if (!(h > 0) || !std::isfinite(h)) h = 1;
  // At most 2 (N + M) cells (and within the 32-bit cell numbering): grow h until the grid fits.
  const double max_cells =
      std::min(2.0 * static_cast<double>(n_nodes + n_segs), static_cast<double>(1 << 30));
  double dims[3];
  for (;;) {
    for (int a = 0; a < 3; ++a) dims[a] = std::floor(extent[a] / h) + 1;
    const double cells = dims[0] * dims[1] * dims[2];
    if (cells <= max_cells) break;
    h *= std::max(1.05, std::cbrt(cells / max_cells));
  }
  grid.e = e;
  grid.inv_h = 1 / h;
  for (int a = 0; a < 3; ++a) grid.last[a] = dims[a] - 1;
  grid.nx = static_cast<std::int32_t>(dims[0]);
  grid.ny = static_cast<std::int32_t>(dims[1]);
  grid.n_cells = static_cast<std::size_t>(dims[0] * dims[1] * dims[2]);
  grid.n_nodes = n_nodes;
  return true;
}

// 2. Counting sort of the nodes into cells: counts at cell_first_[cell + 1], prefix sums, then a fill
// that advances cell_first_[cell] as its cursor and a shift that restores the offsets.
void Type7Search::bin_nodes(const Coordinates& c, const Grid& grid) {
  const double *x = c.x.data(), *y = c.y.data(), *z = c.z.data();
  const std::size_t n_sec = secondary_.size(), n_cells = grid.n_cells;
  const double* nlo = grid.nlo;
  const double* last = grid.last;
  const double inv_h = grid.inv_h;
  node_cell_.resize(n_sec);
  cell_first_.assign(n_cells + 1, 0);
  for (std::size_t i = 0; i < n_sec; ++i) {
    if (node_removed_[i]) {
      node_cell_[i] = -1;
      continue;
    }
    const auto g = static_cast<std::size_t>(secondary_[i]);
    const std::int32_t cell =
        cell_of(x[g], nlo[0], inv_h, last[0]) +
        grid.nx * (cell_of(y[g], nlo[1], inv_h, last[1]) + grid.ny * cell_of(z[g], nlo[2], inv_h, last[2]));
    node_cell_[i] = cell;
    ++cell_first_[static_cast<std::size_t>(cell) + 1];
  }
  for (std::size_t k = 0; k < n_cells; ++k) cell_first_[k + 1] += cell_first_[k];
  cell_node_.resize(grid.n_nodes);
  cell_xyz_.resize(3 * grid.n_nodes);
  for (std::size_t i = 0; i < n_sec; ++i) {
    if (node_cell_[i] < 0) continue;
    const auto slot = static_cast<std::size_t>(cell_first_[static_cast<std::size_t>(node_cell_[i])]++);
    const auto g = static_cast<std::size_t>(secondary_[i]);
    cell_node_[slot] = static_cast<std::int32_t>(i);
    cell_xyz_[3 * slot] = x[g];
    cell_xyz_[3 * slot + 1] = y[g];
    cell_xyz_[3 * slot + 2] = z[g];
  }
  for (std::size_t k = n_cells; k > 0; --k) cell_first_[k] = cell_first_[k - 1];
  cell_first_[0] = 0;
}

// 3. Segment by segment, the nodes of the overlapped cells. Cells ix0..ix1 of one row (iy, iz) are
// consecutive, so their nodes form one contiguous range.
void Type7Search::find_pairs(const Coordinates& c, const Grid& grid) {
  const std::size_t n_seg = segments_.size();
  const double *nlo = grid.nlo, *nhi = grid.nhi, *last = grid.last;
  const double inv_h = grid.inv_h;
  const std::int32_t nx = grid.nx, ny = grid.ny;
  found_.clear();
  for (std::size_t s = 0; s < n_seg; ++s) {
    if (segment_removed_[s]) continue;
    const Segment& q = segments_[s];
    const Box b = enlarged_box(c, q, grid.e);
    bool outside = false;
    for (int a = 0; a < 3; ++a) outside = outside || b.hi[a] < nlo[a] || b.lo[a] > nhi[a];
    if (outside) continue;
    std::int32_t lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
      lo[a] = cell_of(b.lo[a], nlo[a], inv_h, last[a]);
      hi[a] = cell_of(b.hi[a], nlo[a], inv_h, last[a]);
    }
    for (std::int32_t iz = lo[2]; iz <= hi[2]; ++iz)
      for (std::int32_t iy = lo[1]; iy <= hi[1]; ++iy) {
        const auto row =
            static_cast<std::size_t>(nx) *
            (static_cast<std::size_t>(iy) + static_cast<std::size_t>(ny) * static_cast<std::size_t>(iz));
        const auto first = static_cast<std::size_t>(cell_first_[row + static_cast<std::size_t>(lo[0])]);
        const auto end = static_cast<std::size_t>(cell_first_[row + static_cast<std::size_t>(hi[0]) + 1]);
        for (std::size_t k = first; k < end; ++k) {
          if (!inside(b, cell_xyz_[3 * k], cell_xyz_[3 * k + 1], cell_xyz_[3 * k + 2])) continue;
          const std::int32_t i = cell_node_[k];
          if (contains_node(q, secondary_[static_cast<std::size_t>(i)])) continue;
          found_.push_back({i, static_cast<std::int32_t>(s)});
        }
      }
  }
}

// 4. Stable counting sort by node: the pairs were found in increasing segment order.
void Type7Search::order_by_node() {
  const std::size_t n_sec = secondary_.size();
  node_first_.assign(n_sec + 1, 0);
  for (const Candidate& p : found_) ++node_first_[static_cast<std::size_t>(p.node) + 1];
  for (std::size_t i = 0; i < n_sec; ++i) node_first_[i + 1] += node_first_[i];
  candidates_.resize(found_.size());
  for (const Candidate& p : found_)
    candidates_[static_cast<std::size_t>(node_first_[static_cast<std::size_t>(p.node)]++)] = p;
}

void Type7Search::remove_segment(std::int32_t segment) {
  const auto s = static_cast<std::size_t>(segment);
  assert(s < segments_.size());
  if (segment_removed_[s]) return;
  segment_removed_[s] = 1;
  std::int32_t d[4];
  const int nd = distinct_nodes(segments_[s], d);
  for (int k = 0; k < nd; ++k) release_tracked(d[k]);
  candidates_stale_ = true;
}

void Type7Search::remove_node(std::int32_t node) {
  const auto i = static_cast<std::size_t>(node);
  assert(i < secondary_.size());
  if (node_removed_[i]) return;
  node_removed_[i] = 1;
  release_tracked(secondary_[i]);
  candidates_stale_ = true;
}

const std::vector<Candidate>& Type7Search::candidates() const {
  if (candidates_stale_) {
    std::erase_if(candidates_, [this](const Candidate& p) {
      return node_removed_[static_cast<std::size_t>(p.node)] ||
             segment_removed_[static_cast<std::size_t>(p.segment)];
    });
    candidates_stale_ = false;
  }
  return candidates_;
}

std::vector<Candidate> brute_force_candidates(const Coordinates& c, std::span<const std::int32_t> secondary,
                                              std::span<const std::array<std::int32_t, 4>> segments,
                                              double enlarge) {
  std::vector<Box> boxes;
  boxes.reserve(segments.size());
  for (const Segment& q : segments) boxes.push_back(enlarged_box(c, q, enlarge));
  std::vector<Candidate> out;
  for (std::size_t i = 0; i < secondary.size(); ++i) {
    const auto g = static_cast<std::size_t>(secondary[i]);
    for (std::size_t s = 0; s < segments.size(); ++s)
      if (inside(boxes[s], c.x[g], c.y[g], c.z[g]) && !contains_node(segments[s], secondary[i]))
        out.push_back({static_cast<std::int32_t>(i), static_cast<std::int32_t>(s)});
  }
  return out;
}

}  // namespace radx::contact
