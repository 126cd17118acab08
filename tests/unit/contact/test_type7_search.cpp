// TYPE7 candidate search (docs/theory/type7-lagdt.md 4.8): the voxel sort against the brute-force reference
// on random meshes, self-contact exclusion, the margin, the re-sort criterion 2 d >= margin and the guarantee
// that makes it safe, removals. The scaling benchmark at the end is hidden (run by bench/contact_search.sh).
#include <algorithm>
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <set>

#include "contact/type7_search.hpp"

using radx::contact::brute_force_candidates;
using radx::contact::Candidate;
using radx::contact::Coordinates;
using radx::contact::Type7Search;

namespace {

struct Mesh {
  std::vector<double> x, y, z;
  std::vector<std::int32_t> secondary;
  std::vector<std::array<std::int32_t, 4>> segments;
  [[nodiscard]] Coordinates coords() const { return {x, y, z}; }
  std::int32_t add(double px, double py, double pz) {
    x.push_back(px);
    y.push_back(py);
    z.push_back(pz);
    return static_cast<std::int32_t>(x.size() - 1);
  }
};

// An n x n grid of cells of side h, nodes moved at random by up to 0.2 h in plane and 0.3 h out of it;
// about one cell in five is split into two triangles (n4 == n3). `free_nodes` random secondary nodes in a
// slab around the grid, plus every third grid node (nodes of their own segments: self-contact), in a
// shuffled order so that secondary indices and node indices differ.
Mesh random_mesh(int n, int free_nodes, unsigned seed, double h = 1.0) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0), unit(0.0, 1.0);
  Mesh m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.add(h * (i + 0.2 * u(rng)), h * (j + 0.2 * u(rng)), 0.3 * h * u(rng));
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const std::int32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
      if (unit(rng) < 0.2) {
        m.segments.push_back({a, b, c, c});
        m.segments.push_back({a, c, d, d});
      } else {
        m.segments.push_back({a, b, c, d});
      }
    }
  for (std::int32_t k = 0; k < static_cast<std::int32_t>(m.x.size()); k += 3) m.secondary.push_back(k);
  for (int k = 0; k < free_nodes; ++k)
    m.secondary.push_back(
        m.add(h * (-1 + (n + 2) * unit(rng)), h * (-1 + (n + 2) * unit(rng)), 1.5 * h * u(rng)));
  std::shuffle(m.secondary.begin(), m.secondary.end(), rng);
  return m;
}

// Mean length over every edge of every segment, computed independently of the search.
double mean_edge(const Mesh& m) {
  double sum = 0;
  int edges = 0;
  for (const auto& q : m.segments) {
    const int ne = q[3] == q[2] ? 3 : 4;
    for (int k = 0; k < ne; ++k) {
      const auto i = static_cast<std::size_t>(q[k]), j = static_cast<std::size_t>(q[(k + 1) % ne]);
      sum += std::hypot(m.x[j] - m.x[i], m.y[j] - m.y[i], m.z[j] - m.z[i]);
      ++edges;
    }
  }
  return sum / edges;
}

bool is_subset(const std::vector<Candidate>& a, const std::vector<Candidate>& b) {
  const auto less = [](const Candidate& p, const Candidate& q) {
    return p.node != q.node ? p.node < q.node : p.segment < q.segment;
  };
  return std::includes(b.begin(), b.end(), a.begin(), a.end(), less);
}

// Moves every node by a random vector of length at most `d`.
void move_all(Mesh& m, std::mt19937& rng, double d) {
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (std::size_t i = 0; i < m.x.size(); ++i) {
    const double a = g(rng), b = g(rng), c = g(rng), r = std::max(std::hypot(a, b, c), 1e-12);
    const double len = d * unit(rng);
    m.x[i] += len * a / r;
    m.y[i] += len * b / r;
    m.z[i] += len * c / r;
  }
}

}  // namespace

TEST_CASE("the voxel sort finds exactly the brute-force candidates, in (node, segment) order",
          "[type7-search]") {
  struct Case {
    int n, free_nodes;
    unsigned seed;
    double gap_max, bumult;
  };
  // Small and large gaps (a box over many cells), no gap nor margin at all, a coarse and a fine mesh.
  const Case cases[] = {
      {12, 300, 1, 0.25, 0.2}, {30, 2000, 2, 0.1, 0.3}, {20, 800, 3, 3.0, 0.2}, {16, 500, 4, 0.0, 0.0}};
  for (const Case& k : cases) {
    CAPTURE(k.n, k.seed, k.gap_max, k.bumult);
    const Mesh m = random_mesh(k.n, k.free_nodes, k.seed);
    Type7Search search(m.secondary, m.segments, k.gap_max, k.bumult);
    CHECK(search.update(m.coords()));
    CHECK(search.sorts() == 1);
    CHECK(search.margin() == Approx(k.bumult * mean_edge(m)).epsilon(1e-12));
    const auto ref = brute_force_candidates(m.coords(), m.secondary, m.segments, k.gap_max + search.margin());
    CHECK(!ref.empty());
    CHECK(search.candidates() == ref);
  }
}

TEST_CASE("the voxel sort handles flat node sets and a single node", "[type7-search]") {
  // Every secondary node in the plane z = 0: the grid is one cell thick.
  Mesh m;
  for (int j = 0; j <= 6; ++j)
    for (int i = 0; i <= 6; ++i) m.add(i, j, 0.0);
  for (std::int32_t j = 0; j < 6; ++j)
    for (std::int32_t i = 0; i < 6; ++i) {
      const std::int32_t a = j * 7 + i;
      m.segments.push_back({a, a + 1, a + 8, a + 7});
    }
  for (int k = 0; k < 40; ++k) m.secondary.push_back(m.add(0.15 * k, 0.1 * k, 0.0));
  Type7Search flat(m.secondary, m.segments, 0.05, 0.1);
  flat.update(m.coords());
  CHECK(flat.margin() == Approx(0.1));
  CHECK(flat.candidates() ==
        brute_force_candidates(m.coords(), m.secondary, m.segments, 0.05 + flat.margin()));

  const std::vector<std::int32_t> one{m.secondary[7]};
  Type7Search single(one, m.segments, 0.05, 0.1);
  single.update(m.coords());
  CHECK(!single.candidates().empty());
  CHECK(single.candidates() == brute_force_candidates(m.coords(), one, m.segments, 0.05 + single.margin()));
}

TEST_CASE("a secondary node is never paired with a segment that contains it", "[type7-search]") {
  // A gap larger than the cells, so that every grid node lies inside the boxes of its own segments and
  // of their neighbours: the exclusion must remove exactly the segments that contain the node.
  const Mesh m = random_mesh(10, 0, 5);
  const double gap_max = 1.5;
  Type7Search search(m.secondary, m.segments, gap_max, 0.2);
  search.update(m.coords());
  const auto& cand = search.candidates();
  std::set<std::pair<std::int32_t, std::int32_t>> found;
  for (const auto& p : cand) found.insert({p.node, p.segment});
  int own = 0, neighbours = 0;
  for (std::size_t i = 0; i < m.secondary.size(); ++i)
    for (std::size_t s = 0; s < m.segments.size(); ++s) {
      const auto& q = m.segments[s];
      const bool contains = std::find(q.begin(), q.end(), m.secondary[i]) != q.end();
      const bool listed = found.count({static_cast<std::int32_t>(i), static_cast<std::int32_t>(s)}) > 0;
      if (contains) {
        ++own;
        CHECK_FALSE(listed);
      } else if (listed) {
        ++neighbours;
      }
    }
  CHECK(own > 0);
  CHECK(neighbours > 0);
  CHECK(cand == brute_force_candidates(m.coords(), m.secondary, m.segments, gap_max + search.margin()));
}

TEST_CASE("a new sort is due when a node has moved by half the margin since the last sort",
          "[type7-search]") {
  // A regular grid of unit quadrangles: margin = bumult * 1.
  Mesh m;
  for (int j = 0; j <= 4; ++j)
    for (int i = 0; i <= 4; ++i) m.add(i, j, 0.0);
  for (std::int32_t j = 0; j < 4; ++j)
    for (std::int32_t i = 0; i < 4; ++i) {
      const std::int32_t a = j * 5 + i;
      m.segments.push_back({a, a + 1, a + 6, a + 5});
    }
  const std::int32_t free_node = m.add(2.3, 1.7, 0.4);
  m.secondary = {free_node, 12};
  Type7Search search(m.secondary, m.segments, 0.1, 0.2);
  CHECK(search.update(m.coords()));
  REQUIRE(search.margin() == Approx(0.2));
  const double half = 0.5 * search.margin();

  // A secondary node: just below half the margin, nothing; just beyond it, a sort.
  m.z[free_node] = 0.4 + 0.98 * half;
  CHECK_FALSE(search.update(m.coords()));
  CHECK(search.sorts() == 1);
  m.z[free_node] = 0.4 + 1.02 * half;
  CHECK(search.update(m.coords()));
  CHECK(search.sorts() == 2);

  // Motion counts from the last sort, not from the previous call: two steps of 0.6 * half add up.
  const auto main_node = static_cast<std::size_t>(6);  // a segment node that is not secondary
  m.x[main_node] += 0.6 * half;
  CHECK_FALSE(search.update(m.coords()));
  m.x[main_node] += 0.6 * half;
  CHECK(search.update(m.coords()));
  CHECK(search.sorts() == 3);

  // No motion: no sort, unless forced.
  CHECK_FALSE(search.update(m.coords()));
  CHECK(search.update(m.coords(), true));
  CHECK(search.sorts() == 4);
  // The margin is the one of the first sort, whatever the motion since.
  CHECK(search.margin() == Approx(0.2));
}

TEST_CASE("after motions below half the margin the kept candidates hold every pair within gap_max",
          "[type7-search]") {
  for (unsigned seed : {11u, 12u, 13u}) {
    CAPTURE(seed);
    Mesh m = random_mesh(14, 600, seed);
    const double gap_max = 0.2;
    Type7Search search(m.secondary, m.segments, gap_max, 0.25);
    search.update(m.coords());
    std::mt19937 rng(seed);
    int kept = 0, resorted = 0;
    // A random walk: each step moves every node by up to 0.2 * margin, so a few steps stay without a
    // sort and then one is due. Without a sort, the guarantee; after one, the exact candidate set.
    for (int step = 0; step < 24; ++step) {
      move_all(m, rng, 0.2 * search.margin());
      const auto within_gap = brute_force_candidates(m.coords(), m.secondary, m.segments, gap_max);
      if (search.update(m.coords())) {
        ++resorted;
        CHECK(search.candidates() ==
              brute_force_candidates(m.coords(), m.secondary, m.segments, gap_max + search.margin()));
      } else {
        ++kept;
      }
      CHECK(!within_gap.empty());
      CHECK(is_subset(within_gap, search.candidates()));
    }
    CHECK(kept > 0);
    CHECK(resorted > 0);
    // One motion of every node by just under half the margin: no sort, and still every pair is held.
    search.update(m.coords(), true);
    move_all(m, rng, 0.499 * search.margin());
    CHECK_FALSE(search.update(m.coords()));
    CHECK(
        is_subset(brute_force_candidates(m.coords(), m.secondary, m.segments, gap_max), search.candidates()));
  }
}

TEST_CASE("removed nodes and segments leave the candidates and stop being tracked", "[type7-search]") {
  Mesh m = random_mesh(12, 400, 21);
  const double gap_max = 0.3;
  Type7Search search(m.secondary, m.segments, gap_max, 0.2);
  search.update(m.coords());
  const auto before = search.candidates();
  REQUIRE(before.size() > 10);

  // Remove the node and the segment of two existing pairs, plus a segment and a node picked at random.
  std::set<std::int32_t> gone_nodes{before[3].node, 17}, gone_segments{before[before.size() / 2].segment, 5};
  for (auto i : gone_nodes) search.remove_node(i);
  for (auto s : gone_segments) search.remove_segment(s);
  search.remove_node(17);  // twice: no effect

  std::vector<Candidate> expected;
  for (const auto& p : before)
    if (!gone_nodes.count(p.node) && !gone_segments.count(p.segment)) expected.push_back(p);
  CHECK(expected.size() < before.size());
  CHECK(search.candidates() == expected);
  // And after a new sort as well.
  CHECK(search.update(m.coords(), true));
  CHECK(search.candidates() == expected);

  // A removed free node may fly away without causing sorts (it is no longer tracked).
  const std::int32_t n_grid = 13 * 13;
  std::int32_t free_removed = -1;
  for (std::size_t i = 0; i < m.secondary.size() && free_removed < 0; ++i)
    if (m.secondary[i] >= n_grid) free_removed = static_cast<std::int32_t>(i);
  REQUIRE(free_removed >= 0);
  search.remove_node(free_removed);
  m.z[static_cast<std::size_t>(m.secondary[static_cast<std::size_t>(free_removed)])] += 100 * search.margin();
  CHECK_FALSE(search.update(m.coords()));
  search.update(m.coords(), true);
  for (const auto& p : search.candidates()) {
    CHECK(p.node != free_removed);
    CHECK(!gone_nodes.count(p.node));
    CHECK(!gone_segments.count(p.segment));
  }

  // A burst of removals (every other segment, every fifth node), then the candidates once.
  Type7Search burst(m.secondary, m.segments, gap_max, 0.2);
  burst.update(m.coords());
  const auto all = burst.candidates();
  for (std::int32_t s = 0; s < static_cast<std::int32_t>(m.segments.size()); s += 2) burst.remove_segment(s);
  for (std::int32_t i = 0; i < static_cast<std::int32_t>(m.secondary.size()); i += 5) burst.remove_node(i);
  std::vector<Candidate> left;
  for (const auto& p : all)
    if (p.segment % 2 != 0 && p.node % 5 != 0) left.push_back(p);
  CHECK(!left.empty());
  CHECK(burst.candidates() == left);
  CHECK(burst.update(m.coords(), true));
  CHECK(burst.candidates() == left);
}

// Scaling benchmark (not a unit test: hidden, run by bench/contact_search.sh): sorts of N, 2N and 4N
// segments against as many secondary nodes, two slightly wavy sheets a third of a cell apart. The sort
// is linear when each doubling about doubles the time.
TEST_CASE("type7 search scaling benchmark", "[.][bench-contact-search]") {
  const std::int32_t sizes[] = {500, 707, 1000};  // 250k, 500k, 1M segments (and secondary nodes)
  double previous = 0;
  std::printf("%10s %10s %12s %12s %10s %14s\n", "segments", "nodes", "candidates", "sort [ms]", "ratio",
              "check [ns/node]");
  for (const std::int32_t n : sizes) {
    Mesh m;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (std::int32_t j = 0; j <= n; ++j)
      for (std::int32_t i = 0; i <= n; ++i) m.add(i + 0.2 * u(rng), j + 0.2 * u(rng), 0.1 * u(rng));
    for (std::int32_t j = 0; j < n; ++j)
      for (std::int32_t i = 0; i < n; ++i) {
        const std::int32_t a = j * (n + 1) + i;
        m.segments.push_back({a, a + 1, a + n + 2, a + n + 1});
      }
    for (std::int32_t j = 0; j < n; ++j)
      for (std::int32_t i = 0; i < n; ++i)
        m.secondary.push_back(m.add(i + 0.5 + 0.2 * u(rng), j + 0.5 + 0.2 * u(rng), 0.33 + 0.1 * u(rng)));
    Type7Search search(m.secondary, m.segments, 0.3, 0.2);
    using clock = std::chrono::steady_clock;
    double best = 1e300;
    for (int rep = 0; rep < 5; ++rep) {
      const auto t0 = clock::now();
      search.update(m.coords(), true);
      best = std::min(best, std::chrono::duration<double, std::milli>(clock::now() - t0).count());
    }
    double check = 1e300;
    for (int rep = 0; rep < 5; ++rep) {
      const auto t0 = clock::now();
      const bool sorted = search.update(m.coords());
      check = std::min(check, std::chrono::duration<double, std::nano>(clock::now() - t0).count());
      REQUIRE_FALSE(sorted);
    }
    const double tracked = static_cast<double>(m.x.size());
    char ratio[32] = "-";
    if (previous > 0) std::snprintf(ratio, sizeof ratio, "%.2f", best / previous);
    std::printf("%10zu %10zu %12zu %12.1f %10s %14.2f\n", m.segments.size(), m.secondary.size(),
                search.candidates().size(), best, ratio, check / tracked);
    previous = best;
  }
}
