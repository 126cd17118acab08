// The decomposition of the element groups over ranks (solver/parallel/partition.hpp), on the impact
// benchmark's model (shells, a block of bricks, TYPE7 contact): every group on one rank, the same partition
// on a second call, METIS's balance tolerances met, a small rigid body's groups on one rank, P = 1 without
// METIS, too many ranks refused, and the statistics recounted here from the groups' connectivity.
#include <algorithm>
#include <catch2/catch.hpp>
#include <map>
#include <set>
#include <stdexcept>
#include <vector>

#include "contact/type7_prepare.hpp"
#include "solver/engine/explicit_engine.hpp"
#include "solver/parallel/partition.hpp"
#include "test_util.hpp"

namespace par = radx::solver::parallel;
using radx::solver::ElementGroups;
using radx::solver::kGroupSize;

namespace {

struct Built {
  radx::model::Model model;
  std::unique_ptr<radx::solver::ExplicitEngine> engine;
  [[nodiscard]] const ElementGroups& groups() const { return engine->groups(); }
};

// The impact model of an n x n plate and a block of block x block x 4 bricks (0: 10), its engine's groups
// built (the engine is not run).
std::unique_ptr<Built> impact(int n, int block = 0) {
  radx::test::TempDir dir;
  auto b = std::make_unique<Built>();
  b->model = radx::test::impact_benchmark_model(dir, n, block);
  radx::contact::prepare_type7_interfaces(b->model);
  radx::model::RunControls rc;
  rc.t_stop = 1e-4;
  b->engine = std::make_unique<radx::solver::ExplicitEngine>(b->model, rc, radx::solver::EngineOptions(1));
  return b;
}

// Each group's distinct nodes with its entries on them, read from the groups directly.
std::vector<std::map<std::int32_t, int>> entries_per_group(const ElementGroups& groups) {
  std::vector<std::map<std::int32_t, int>> out;
  groups.for_each([&](const auto& g) {
    auto& e = out.emplace_back();
    for (int q = 0; q < g.nodes_per_element(); ++q)
      for (int i = 0; i < g.count; ++i) ++e[g.conn[static_cast<std::size_t>(q * kGroupSize + i)]];
  });
  return out;
}

}  // namespace

TEST_CASE("a few hundred groups over 4 ranks: whole groups, the same twice, balanced", "[partition]") {
  const auto b = impact(200, 20);  // 40,000 shells (313 groups) and 1,600 bricks (13 groups)
  const ElementGroups& groups = b->groups();
  REQUIRE(groups.count() > 300);
  const int P = 4;
  const par::Partition p = par::partition_groups(b->model, groups, P);
  REQUIRE(static_cast<std::int64_t>(p.group_rank.size()) == groups.count());
  for (const int r : p.group_rank) REQUIRE((r >= 0 && r < P));
  // The same input, the same partition (a fixed seed; nothing depends on the time or the run).
  CHECK(par::partition_groups(b->model, groups, P).group_rank == p.group_rank);

  // Groups are never split: every cell of a group is in that group alone, so it has the group's rank.
  const auto cell_group = par::cell_groups(b->model, groups);
  std::vector<std::int64_t> cells_of(static_cast<std::size_t>(groups.count()), 0);
  for (const auto g : cell_group) {
    REQUIRE(g >= 0);  // every element of this model has forces, so is in a group
    ++cells_of[static_cast<std::size_t>(g)];
  }
  std::int64_t flat = 0;
  groups.for_each([&](const auto& g) { CHECK(cells_of[static_cast<std::size_t>(flat++)] == g.count); });

  // Element counts per rank, recounted from the groups.
  std::vector<std::int64_t> elements(P, 0);
  flat = 0;
  groups.for_each([&](const auto& g) {
    elements[static_cast<std::size_t>(p.group_rank[static_cast<std::size_t>(flat++)])] += g.count;
  });
  for (int r = 0; r < P; ++r)
    CHECK(p.summary.per_rank[static_cast<std::size_t>(r)].elements == elements[static_cast<std::size_t>(r)]);

  // METIS's tolerances: the heaviest rank within 3 % of the mean kernel cost and 10 % of the mean contact
  // work (the weights it balanced, before its integer scaling: 1e-3 covers that rounding).
  CHECK(p.summary.cost_imbalance <= par::kCostTolerance + 1e-3);
  CHECK(p.summary.contact_imbalance <= par::kContactTolerance + 1e-3);
  // The plate's strips are cut into P blocks: far fewer shared nodes than a random assignment would give
  // (a random one shares nearly every node); 4 ranks cutting a 201 x 201 node plate share a few rows of
  // 201 nodes.
  CHECK(p.summary.shared_nodes > 0);
  CHECK(p.summary.shared_nodes < 6 * 201 + 4 * 41);
}

TEST_CASE("node owners, ghosts and shared nodes follow the most-entries rule", "[partition]") {
  const auto b = impact(40);
  const ElementGroups& groups = b->groups();
  const int P = 3;
  const par::Partition p = par::partition_groups(b->model, groups, P);
  const auto per_group = entries_per_group(groups);
  // Independent recount: per node, the entries of each rank.
  std::map<std::int32_t, std::map<int, int>> per_node;
  for (std::size_t g = 0; g < per_group.size(); ++g)
    for (const auto& [node, count] : per_group[g]) per_node[node][p.group_rank[g]] += count;
  std::vector<std::int64_t> owned(P, 0), ghosts(P, 0), shared(P, 0);
  std::int64_t shared_total = 0;
  std::vector<std::set<int>> neighbours(P);
  for (const auto& [node, ranks] : per_node) {
    int owner = -1, most = 0;
    for (const auto& [r, c] : ranks)  // ascending rank: a tie keeps the lower
      if (c > most) {
        most = c;
        owner = r;
      }
    CHECK(p.summary.node_owner[static_cast<std::size_t>(node)] == owner);
    ++owned[static_cast<std::size_t>(owner)];
    if (ranks.size() < 2) continue;
    ++shared_total;
    for (const auto& [r, c] : ranks) {
      ++shared[static_cast<std::size_t>(r)];
      if (r != owner) ++ghosts[static_cast<std::size_t>(r)];
      for (const auto& [q, d] : ranks)
        if (q != r) neighbours[static_cast<std::size_t>(r)].insert(q);
    }
  }
  CHECK(p.summary.shared_nodes == shared_total);
  for (int r = 0; r < P; ++r) {
    const auto& s = p.summary.per_rank[static_cast<std::size_t>(r)];
    CHECK(s.owned_nodes == owned[static_cast<std::size_t>(r)]);
    CHECK(s.ghost_nodes == ghosts[static_cast<std::size_t>(r)]);
    CHECK(s.shared_nodes == shared[static_cast<std::size_t>(r)]);
    CHECK(std::vector<int>(neighbours[static_cast<std::size_t>(r)].begin(),
                           neighbours[static_cast<std::size_t>(r)].end()) == s.neighbours);
  }
  // Every node an element touches has one owner: the owned counts add up to those nodes.
  std::int64_t total = 0;
  for (const auto o : owned) total += o;
  CHECK(total == static_cast<std::int64_t>(per_node.size()));
}

TEST_CASE("a small rigid body's groups go to one rank, a large one's are left to METIS", "[partition]") {
  const auto b = impact(200, 20);
  const ElementGroups& groups = b->groups();
  const int P = 4;
  // Nodes of the plate's first column at five rows far apart (201 nodes a row): their strips of shells lie in
  // different corners of the plate, so METIS alone puts them on different ranks.
  std::vector<std::int32_t> column;
  for (const int row : {0, 50, 100, 150, 200}) column.push_back(row * 201);
  const auto groups_touching = [&](const std::vector<std::int32_t>& nodes) {
    std::set<std::int64_t> out;
    const auto per_group = entries_per_group(groups);
    for (std::size_t g = 0; g < per_group.size(); ++g)
      for (const auto n : nodes)
        if (per_group[g].count(n)) out.insert(static_cast<std::int64_t>(g));
    return out;
  };
  const auto touched = groups_touching(column);
  REQUIRE(touched.size() >= 5);
  const auto ranks_of = [&](const par::Partition& p) {
    std::set<int> r;
    for (const auto g : touched) r.insert(p.group_rank[static_cast<std::size_t>(g)]);
    return r;
  };
  const par::Partition free = par::partition_groups(b->model, groups, P);
  REQUIRE(ranks_of(free).size() > 1);         // the test means something: without the body they are cut
  CHECK(free.summary.rigid_bodies_cut == 0);  // no body yet

  radx::model::Model with_body = b->model;
  radx::model::RigidBody body;
  body.main_node = column.front();
  body.secondary.assign(column.begin() + 1, column.end());
  with_body.rigid_bodies.push_back(body);
  const par::Partition kept = par::partition_groups(with_body, groups, P);
  CHECK(kept.rigid_bodies_kept == 1);
  CHECK(ranks_of(kept).size() == 1);
  CHECK(kept.summary.rigid_bodies_cut == 0);
  // The same body cut by the unconstrained partition is counted as cut.
  CHECK(par::summarize_partition(with_body, groups, free.group_rank, P).rigid_bodies_cut == 1);

  // A body over the whole block's nodes: its 1,600 bricks are 3.8 % of the 41,600 elements, over 1 %, so no
  // groups are joined for it.
  radx::model::Model big = b->model;
  radx::model::RigidBody block;
  const auto nodes = b->model.nodes.size();
  for (std::size_t n = 201 * 201; n < nodes; ++n) block.secondary.push_back(static_cast<std::int32_t>(n));
  block.main_node = block.secondary.back();
  block.secondary.pop_back();
  big.rigid_bodies.push_back(block);
  CHECK(par::partition_groups(big, groups, P).rigid_bodies_kept == 0);
}

TEST_CASE("one rank takes every group without METIS, more ranks than groups are refused", "[partition]") {
  const auto b = impact(20);  // 400 shells (4 groups) and 400 bricks (4 groups)
  const ElementGroups& groups = b->groups();
  const par::Partition one = par::partition_groups(b->model, groups, 1);
  CHECK(std::all_of(one.group_rank.begin(), one.group_rank.end(), [](int r) { return r == 0; }));
  CHECK(one.summary.shared_nodes == 0);
  CHECK(one.summary.per_rank[0].ghost_nodes == 0);
  CHECK(one.summary.cost_imbalance == 1.0);
  const auto too_many = static_cast<int>(groups.count()) + 1;
  CHECK_THROWS_AS(par::partition_groups(b->model, groups, too_many), std::invalid_argument);
  try {
    (void)par::partition_groups(b->model, groups, too_many);
  } catch (const std::invalid_argument& e) {
    CHECK_THAT(e.what(), Catch::Contains("give at most " + std::to_string(groups.count()) + " ranks"));
  }
  // Exactly as many ranks as groups is accepted: each rank one group.
  const par::Partition each = par::partition_groups(b->model, groups, static_cast<int>(groups.count()));
  std::set<int> used(each.group_rank.begin(), each.group_rank.end());
  CHECK(static_cast<std::int64_t>(used.size()) <= groups.count());
  // A given assignment is checked: one rank per group, each in range.
  std::vector<int> bad(static_cast<std::size_t>(groups.count()), 0);
  bad.back() = 2;
  CHECK_THROWS_AS(par::summarize_partition(b->model, groups, bad, 2), std::invalid_argument);
  CHECK(par::check_group_ranks(groups.count(), bad, 2).find("outside 0 .. 1") != std::string::npos);
  bad.pop_back();
  CHECK(par::check_group_ranks(groups.count(), bad, 2).find("give one rank per group") != std::string::npos);
}

TEST_CASE("a TYPE2 tie whose secondary node and main nodes have different owners is counted as cut",
          "[partition]") {
  const auto b = impact(20);  // the plate: 21 x 21 nodes, 400 shells in 4 groups of rows
  const ElementGroups& groups = b->groups();
  radx::model::Model m = b->model;
  radx::model::TiedInterface tie;
  tie.tie_node = {0};  // a corner of the plate's first row: the first group's alone
  // Nodes of the plate's last row (21 x 20 = 420 ...), far from the first group.
  tie.tie_segment = {{420, 421, 440, 439}};
  tie.tie_r = tie.tie_s = tie.tie_offset = {0.0};
  m.tied_interfaces.push_back(tie);
  std::vector<int> ranks(static_cast<std::size_t>(groups.count()), 1);
  ranks[0] = 0;  // the first group alone on rank 0
  CHECK(par::summarize_partition(m, groups, ranks, 2).ties_cut == 1);
  std::fill(ranks.begin(), ranks.end(), 0);
  ranks.back() = 1;  // the block's last group on rank 1: the tie stays whole on rank 0
  CHECK(par::summarize_partition(m, groups, ranks, 2).ties_cut == 0);
}
