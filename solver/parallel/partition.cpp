// The decomposition of a model's element groups over P ranks (partition.hpp).
//
// Graph: vertex v = a group (or the groups of a small rigid body, contracted); edge (u, v) with weight
//   w_uv = |nodes(u) ∩ nodes(v)| + |TYPE2 ties between u and v| + |TYPE7 t = 0 candidates between u and v|;
// METIS_PartGraphKway minimises the cut sum of w_uv over the edges between ranks subject to, for each
// constraint c (kernel cost, contact work), max_rank W_c(rank) <= ubvec_c * W_c(total) / P.
// Node owner: argmax_rank (element entries of the rank on the node), ties to the lowest rank.
#include "solver/parallel/partition.hpp"

#include <metis.h>

#include "contact/type7_search.hpp"
#include "solver/parallel/domain.hpp"

#include <algorithm>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

namespace radx::solver::parallel {

namespace {

// Instructions per element-cycle of each kernel: the balance weight of an element. Measured (callgrind,
// docs/performance.md section 2, the impact model): a BT4 shell 616, a one-point brick 1,980. The others are
// estimates from their work relative to those two (not measured): they only need to be right in proportion.
constexpr std::int64_t kBt4Shell = 616;        // measured
constexpr std::int64_t kTri3Shell = 460;       // 3 nodes and no hourglass: ~3/4 of BT4
constexpr std::int64_t kQephShell = 800;       // BT4 plus the stabilisation resultants of 4 points
constexpr std::int64_t kQbatShell = 2464;      // 4 in-plane points, each a BT4 section update
constexpr std::int64_t kOnePointBrick = 1980;  // measured
constexpr std::int64_t kHephBrick = 2400;      // one point plus the physical hourglass stresses
constexpr std::int64_t kBrickPoint = 1980;     // a fully integrated brick: 8 one-point updates
constexpr std::int64_t kTetra = 1000;          // 4 nodes, no hourglass: ~half a one-point brick
constexpr std::int64_t kHex20Point = 2500;     // per Gauss point: 20-node gradients and a material update
constexpr std::int64_t kLineElement = 150;     // springs and trusses: one axial update
constexpr std::int64_t kBeam = 400;            // type-3 beam: six resultants

std::int64_t element_cost(const ShellGroup& g) {
  switch (g.kernel) {
    case ShellKernel::Bt4: return kBt4Shell;
    case ShellKernel::Tri3: return kTri3Shell;
    case ShellKernel::Qeph: return kQephShell;
    case ShellKernel::Qbat: return kQbatShell;
  }
  return kBt4Shell;
}
std::int64_t element_cost(const BrickGroup& g) {
  switch (brick_kernel(g)) {
    case BrickKernel::OnePoint: return kOnePointBrick;
    case BrickKernel::Heph: return kHephBrick;
    case BrickKernel::FullyIntegrated: return 8 * kBrickPoint;
  }
  return kOnePointBrick;
}
std::int64_t element_cost(const TetraGroup&) {
  return kTetra;
}
std::int64_t element_cost(const Hex20Group& g) {
  return g.n_points() * kHex20Point;
}
std::int64_t element_cost(const SpringGroup&) {
  return kLineElement;
}
std::int64_t element_cost(const TrussGroup&) {
  return kLineElement;
}
std::int64_t element_cost(const BeamGroup&) {
  return kBeam;
}

// Compressed rows: row r holds item[begin[r] .. begin[r + 1]) with their counts.
struct Rows {
  std::vector<std::int64_t> begin{0};
  std::vector<std::int32_t> item;
  std::vector<std::int32_t> count;
  [[nodiscard]] std::size_t rows() const { return begin.size() - 1; }
};

// Each group's distinct nodes, ascending, with the group's element entries on each.
Rows group_nodes(const ElementGroups& groups) {
  Rows r;
  std::vector<std::int32_t> entries;
  groups.for_each([&](const auto& g) {
    entries.clear();
    const auto nodes = static_cast<std::size_t>(g.nodes_per_element());
    for (std::size_t q = 0; q < nodes; ++q)
      for (std::size_t i = 0; i < static_cast<std::size_t>(g.count); ++i)
        entries.push_back(g.conn[q * kGroupSize + i]);
    std::sort(entries.begin(), entries.end());
    for (std::size_t k = 0; k < entries.size();) {
      std::size_t e = k;
      while (e < entries.size() && entries[e] == entries[k]) ++e;
      r.item.push_back(entries[k]);
      r.count.push_back(static_cast<std::int32_t>(e - k));
      k = e;
    }
    r.begin.push_back(static_cast<std::int64_t>(r.item.size()));
  });
  return r;
}

// The transpose: each node's groups, ascending, with the group's entries on the node.
Rows transpose(const Rows& by_group, std::size_t nodes) {
  Rows r;
  r.begin.assign(nodes + 1, 0);
  for (const std::int32_t n : by_group.item) ++r.begin[static_cast<std::size_t>(n) + 1];
  std::partial_sum(r.begin.begin(), r.begin.end(), r.begin.begin());
  r.item.resize(by_group.item.size());
  r.count.resize(by_group.item.size());
  std::vector<std::int64_t> at(r.begin.begin(), r.begin.end() - 1);
  for (std::size_t g = 0; g < by_group.rows(); ++g)
    for (auto k = by_group.begin[g]; k < by_group.begin[g + 1]; ++k) {
      const auto n = static_cast<std::size_t>(by_group.item[static_cast<std::size_t>(k)]);
      const auto to = static_cast<std::size_t>(at[n]++);
      r.item[to] = static_cast<std::int32_t>(g);
      r.count[to] = by_group.count[static_cast<std::size_t>(k)];
    }
  return r;
}

// The model's groups as both row sets.
struct Incidence {
  Rows group_nodes, node_groups;
  Incidence(const model::Model& m, const ElementGroups& groups)
      : group_nodes(parallel::group_nodes(groups)), node_groups(transpose(group_nodes, m.nodes.size())) {}
  // The first (lowest flat) group touching node n, -1 when none does.
  [[nodiscard]] std::int32_t first_group(std::int32_t n) const {
    const auto k = static_cast<std::size_t>(n);
    return node_groups.begin[k] == node_groups.begin[k + 1]
               ? -1
               : node_groups.item[static_cast<std::size_t>(node_groups.begin[k])];
  }
};

// The group of main segment k of surface s: its element's, else the first group touching its first node.
std::int32_t segment_group(const model::Model& m, const model::Surface& s, std::size_t k,
                           std::span<const std::int32_t> cell_group, const Incidence& inc) {
  const std::int32_t e = k < s.owner.size() ? s.owner[k] : model::kNone;
  const auto type = k < s.owner_type.size() ? s.owner_type[k] : model::SegmentOwner::None;
  if (e != model::kNone) {
    std::size_t first = 0;
    switch (type) {
      case model::SegmentOwner::Shell4: first = 0; break;
      case model::SegmentOwner::Shell3: first = m.shells.size(); break;
      case model::SegmentOwner::Brick8: first = m.shells.size() + m.shells3.size(); break;
      case model::SegmentOwner::Tetra4: first = m.shells.size() + m.shells3.size() + m.bricks.size(); break;
      case model::SegmentOwner::None: first = cell_group.size(); break;
    }
    const std::size_t cell = first + static_cast<std::size_t>(e);
    if (cell < cell_group.size() && cell_group[cell] >= 0) return cell_group[cell];
  }
  return inc.first_group(s.segments[k][0]);
}

// What TYPE7 contact puts on the groups: work (each secondary node and main segment once, each on one group;
// each pair candidate on its node's group, whose rank computes the pair) and links (the groups of a
// candidate's node and segment). The candidates are those of a search at the initial coordinates, with the
// largest gap of the interface (Type7Search, as the engine's first cycle sorts; a /CTCLAW law's reach beyond
// the gap left out).
struct ContactLoad {
  std::vector<std::int64_t> work;                            // per group
  std::vector<std::pair<std::int32_t, std::int32_t>> links;  // (node group, segment group)
};

ContactLoad contact_load(const model::Model& m, const ElementGroups& groups, const Incidence& inc) {
  ContactLoad load;
  load.work.assign(static_cast<std::size_t>(groups.count()), 0);
  const std::vector<std::int32_t> cell_group = cell_groups(m, groups);
  const auto add = [&](std::int32_t g) {
    if (g >= 0) ++load.work[static_cast<std::size_t>(g)];
  };
  const contact::Coordinates x0{m.nodes.x, m.nodes.y, m.nodes.z};
  for (const model::Interface& in : m.interfaces) {
    for (const std::int32_t n : in.secondary_nodes) add(inc.first_group(n));
    if (in.main_surface == model::kNone) continue;
    const model::Surface& s = m.surfaces[static_cast<std::size_t>(in.main_surface)];
    std::vector<std::int32_t> seg_group(s.segments.size());
    for (std::size_t k = 0; k < s.segments.size(); ++k)
      add(seg_group[k] = segment_group(m, s, k, cell_group, inc));
    if (in.secondary_nodes.empty() || s.segments.empty()) continue;
    const double gap = in.igap == 0 ? in.gapmin : std::max(in.gap_hi, in.gapmin);
    contact::Type7Search search(in.secondary_nodes, s.segments, gap, in.bumult);
    search.update(x0, true);
    for (const contact::Candidate& c : search.candidates()) {
      const std::int32_t node_group = inc.first_group(in.secondary_nodes[static_cast<std::size_t>(c.node)]);
      add(node_group);
      const std::int32_t other = seg_group[static_cast<std::size_t>(c.segment)];
      if (node_group >= 0 && other >= 0) load.links.emplace_back(node_group, other);
    }
  }
  return load;
}

GroupWeights weights_of(const ElementGroups& groups, const ContactLoad& contact) {
  GroupWeights w;
  groups.for_each([&](const auto& g) {
    w.elements.push_back(g.count);
    w.cost.push_back(element_cost(g) * g.count);
  });
  w.contact = contact.work;
  return w;
}

// A union-find over the groups, each set's representative its lowest group.
struct GroupSets {
  std::vector<std::int32_t> parent;
  explicit GroupSets(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  std::int32_t find(std::int32_t g) {
    while (parent[static_cast<std::size_t>(g)] != g) {
      auto& p = parent[static_cast<std::size_t>(g)];
      p = parent[static_cast<std::size_t>(p)];
      g = p;
    }
    return g;
  }
  void join(std::int32_t a, std::int32_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
  }
};

// The nodes of a rigid body: its main node and its secondary nodes.
std::vector<std::int32_t> body_nodes(const model::RigidBody& b) {
  std::vector<std::int32_t> nodes = b.secondary;
  if (b.main_node != model::kNone) nodes.push_back(b.main_node);
  return nodes;
}

// Joins the groups touching each rigid body whose elements (those with a node in the body) are under
// kSmallRigidBody of the model's; returns how many bodies it kept together.
std::int64_t join_small_rigid_bodies(const model::Model& m, const ElementGroups& groups, const Incidence& inc,
                                     std::int64_t elements, GroupSets& sets) {
  std::int64_t kept = 0;
  std::vector<std::uint8_t> in_body(m.nodes.size(), 0);
  for (const model::RigidBody& b : m.rigid_bodies) {
    const std::vector<std::int32_t> nodes = body_nodes(b);
    std::vector<std::int32_t> touching;
    for (const std::int32_t n : nodes) {
      in_body[static_cast<std::size_t>(n)] = 1;
      const auto k = static_cast<std::size_t>(n);
      for (auto j = inc.node_groups.begin[k]; j < inc.node_groups.begin[k + 1]; ++j)
        touching.push_back(inc.node_groups.item[static_cast<std::size_t>(j)]);
    }
    std::sort(touching.begin(), touching.end());
    touching.erase(std::unique(touching.begin(), touching.end()), touching.end());
    std::int64_t body_elements = 0;
    for (const std::int32_t flat : touching)
      groups.visit(flat, [&](const auto& g) {
        const auto per = static_cast<std::size_t>(g.nodes_per_element());
        for (std::size_t i = 0; i < static_cast<std::size_t>(g.count); ++i) {
          bool touches = false;
          for (std::size_t q = 0; q < per && !touches; ++q)
            touches = in_body[static_cast<std::size_t>(g.conn[q * kGroupSize + i])] != 0;
          body_elements += touches ? 1 : 0;
        }
      });
    for (const std::int32_t n : nodes) in_body[static_cast<std::size_t>(n)] = 0;
    if (touching.empty() ||
        static_cast<double>(body_elements) >= kSmallRigidBody * static_cast<double>(elements))
      continue;
    for (const std::int32_t g : touching) sets.join(touching.front(), g);
    ++kept;
  }
  return kept;
}

// The graph METIS partitions, in its compressed form (xadj, adjncy, adjwgt) with ncon weights per vertex.
struct MetisGraph {
  std::vector<idx_t> xadj{0}, adjncy, adjwgt, vwgt;
  idx_t ncon = 1;
};

// Edges between groups: one per shared node and one per TYPE2 tie, mapped onto the vertices (self edges of
// contracted groups dropped) and summed per vertex pair.
std::vector<std::pair<std::int32_t, std::int32_t>> vertex_pairs(const model::Model& m, const Incidence& inc,
                                                                const ContactLoad& contact,
                                                                std::span<const std::int32_t> vertex) {
  std::vector<std::pair<std::int32_t, std::int32_t>> pairs;
  const auto add = [&](std::int32_t a, std::int32_t b) {
    const std::int32_t u = vertex[static_cast<std::size_t>(a)], v = vertex[static_cast<std::size_t>(b)];
    if (u != v) pairs.emplace_back(std::min(u, v), std::max(u, v));
  };
  const auto& ng = inc.node_groups;
  for (std::size_t n = 0; n + 1 < ng.begin.size(); ++n)
    for (auto i = ng.begin[n]; i < ng.begin[n + 1]; ++i)
      for (auto j = i + 1; j < ng.begin[n + 1]; ++j)
        add(ng.item[static_cast<std::size_t>(i)], ng.item[static_cast<std::size_t>(j)]);
  for (const model::TiedInterface& t : m.tied_interfaces)
    for (std::size_t k = 0; k < t.tie_node.size(); ++k) {
      const auto s = static_cast<std::size_t>(t.tie_node[k]);
      const auto& seg = t.tie_segment[k];
      std::vector<std::int32_t> main_groups;
      for (const std::int32_t n : seg)
        for (auto j = ng.begin[static_cast<std::size_t>(n)]; j < ng.begin[static_cast<std::size_t>(n) + 1];
             ++j)
          main_groups.push_back(ng.item[static_cast<std::size_t>(j)]);
      std::sort(main_groups.begin(), main_groups.end());
      main_groups.erase(std::unique(main_groups.begin(), main_groups.end()), main_groups.end());
      for (auto i = ng.begin[s]; i < ng.begin[s + 1]; ++i)
        for (const std::int32_t g : main_groups) add(ng.item[static_cast<std::size_t>(i)], g);
    }
  for (const auto& [a, b] : contact.links) add(a, b);
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

// Scales a weight column so that its total fits METIS's 32-bit sums with room to spare; every nonzero
// weight stays at least 1.
std::vector<idx_t> scaled(std::span<const std::int64_t> w) {
  constexpr std::int64_t kMaxTotal = std::int64_t{1} << 28;
  const std::int64_t total = std::accumulate(w.begin(), w.end(), std::int64_t{0});
  const std::int64_t divisor = std::max<std::int64_t>(1, (total + kMaxTotal - 1) / kMaxTotal);
  std::vector<idx_t> out(w.size());
  for (std::size_t k = 0; k < w.size(); ++k)
    out[k] = static_cast<idx_t>(w[k] == 0 ? 0 : std::max<std::int64_t>(1, w[k] / divisor));
  return out;
}

MetisGraph metis_graph(const model::Model& m, const Incidence& inc, const ContactLoad& contact,
                       const GroupWeights& w, std::span<const std::int32_t> vertex, std::size_t vertices) {
  MetisGraph G;
  std::vector<std::int64_t> cost(vertices, 0), work(vertices, 0);
  for (std::size_t g = 0; g < vertex.size(); ++g) {
    cost[static_cast<std::size_t>(vertex[g])] += w.cost[g];
    work[static_cast<std::size_t>(vertex[g])] += w.contact[g];
  }
  const bool has_contact = std::any_of(work.begin(), work.end(), [](auto c) { return c > 0; });
  G.ncon = has_contact ? 2 : 1;
  const std::vector<idx_t> c0 = scaled(cost), c1 = scaled(work);
  for (std::size_t v = 0; v < vertices; ++v) {
    G.vwgt.push_back(c0[v]);
    if (has_contact) G.vwgt.push_back(c1[v]);
  }
  // Summed pairs, then both directions, grouped by vertex in ascending neighbour order.
  const auto pairs = vertex_pairs(m, inc, contact, vertex);
  std::vector<std::tuple<std::int32_t, std::int32_t, std::int64_t>> edges;
  for (std::size_t k = 0; k < pairs.size();) {
    std::size_t e = k;
    while (e < pairs.size() && pairs[e] == pairs[k]) ++e;
    edges.emplace_back(pairs[k].first, pairs[k].second, static_cast<std::int64_t>(e - k));
    edges.emplace_back(pairs[k].second, pairs[k].first, static_cast<std::int64_t>(e - k));
    k = e;
  }
  std::sort(edges.begin(), edges.end());
  std::vector<idx_t> degree(vertices, 0);
  for (const auto& [u, v, wt] : edges) {
    ++degree[static_cast<std::size_t>(u)];
    G.adjncy.push_back(v);
    G.adjwgt.push_back(static_cast<idx_t>(std::min<std::int64_t>(wt, std::numeric_limits<idx_t>::max())));
  }
  for (std::size_t v = 0; v < vertices; ++v) G.xadj.push_back(G.xadj.back() + degree[v]);
  return G;
}

std::vector<idx_t> run_metis(MetisGraph& G, int ranks) {
  auto nvtxs = static_cast<idx_t>(G.xadj.size() - 1);
  idx_t nparts = ranks, objval = 0;
  std::vector<idx_t> part(static_cast<std::size_t>(nvtxs), 0);
  real_t ubvec[2] = {static_cast<real_t>(kCostTolerance), static_cast<real_t>(kContactTolerance)};
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_SEED] = kPartitionSeed;
  options[METIS_OPTION_NUMBERING] = 0;
  // METIS reads adjncy and adjwgt even for a graph without edges: give it one valid element.
  if (G.adjncy.empty()) {
    G.adjncy.push_back(0);
    G.adjwgt.push_back(1);
  }
  const int status =
      METIS_PartGraphKway(&nvtxs, &G.ncon, G.xadj.data(), G.adjncy.data(), G.vwgt.data(), nullptr,
                          G.adjwgt.data(), &nparts, nullptr, ubvec, options, &objval, part.data());
  if (status != METIS_OK)
    throw std::runtime_error("METIS_PartGraphKway failed (status " + std::to_string(status) + ") on " +
                             std::to_string(nvtxs) + " vertices and " + std::to_string(nparts) + " parts");
  return part;
}

// Each node's owner by the domain's rule (node_owner_ranks: most entries, ties to the lowest rank), -1 for a
// node no group's element touches: the statistics count such nodes on no rank.
std::vector<std::int32_t> node_owners_of(const ElementGroups& groups, const Incidence& inc,
                                         std::span<const int> group_rank, int ranks) {
  const auto& ng = inc.node_groups;
  std::vector<std::int32_t> owner =
      node_owner_ranks(groups, group_rank, static_cast<std::int64_t>(ng.rows()), ranks);
  for (std::size_t n = 0; n < ng.rows(); ++n)
    if (ng.begin[n] == ng.begin[n + 1]) owner[n] = -1;
  return owner;
}

double imbalance(const std::vector<RankShare>& per_rank, std::int64_t RankShare::*field) {
  std::int64_t total = 0, most = 0;
  for (const RankShare& r : per_rank) {
    total += r.*field;
    most = std::max(most, r.*field);
  }
  if (total == 0) return 1.0;
  return static_cast<double>(most) * static_cast<double>(per_rank.size()) / static_cast<double>(total);
}

// Per rank: nodes owned, ghost and shared, and the neighbour ranks; and the nodes shared by any ranks.
void count_nodes(const Incidence& inc, std::span<const int> group_rank, PartitionSummary& s) {
  const auto ranks = static_cast<std::size_t>(s.ranks);
  std::vector<std::uint8_t> neighbour(ranks * ranks, 0);
  std::vector<int> touching;
  const auto& ng = inc.node_groups;
  for (std::size_t n = 0; n < ng.rows(); ++n) {
    touching.clear();
    for (auto j = ng.begin[n]; j < ng.begin[n + 1]; ++j)
      touching.push_back(group_rank[static_cast<std::size_t>(ng.item[static_cast<std::size_t>(j)])]);
    std::sort(touching.begin(), touching.end());
    touching.erase(std::unique(touching.begin(), touching.end()), touching.end());
    if (touching.empty()) continue;
    ++s.per_rank[static_cast<std::size_t>(s.node_owner[n])].owned_nodes;
    if (touching.size() == 1) continue;
    ++s.shared_nodes;
    for (const int r : touching) {
      auto& share = s.per_rank[static_cast<std::size_t>(r)];
      ++share.shared_nodes;
      if (r != s.node_owner[n]) ++share.ghost_nodes;
      for (const int q : touching)
        if (q != r) neighbour[static_cast<std::size_t>(r) * ranks + static_cast<std::size_t>(q)] = 1;
    }
  }
  for (std::size_t r = 0; r < ranks; ++r)
    for (std::size_t q = 0; q < ranks; ++q)
      if (neighbour[r * ranks + q] != 0) s.per_rank[r].neighbours.push_back(static_cast<int>(q));
}

// Bodies and ties whose nodes have owners on more than one rank.
void count_cut_conditions(const model::Model& m, PartitionSummary& s) {
  const auto owner = [&](std::int32_t n) { return s.node_owner[static_cast<std::size_t>(n)]; };
  for (const model::RigidBody& b : m.rigid_bodies) {
    int first = -1;
    bool cut = false;
    for (const std::int32_t n : body_nodes(b)) {
      const int r = owner(n);
      if (r < 0) continue;
      cut = cut || (first >= 0 && r != first);
      if (first < 0) first = r;
    }
    s.rigid_bodies_cut += cut ? 1 : 0;
  }
  for (const model::TiedInterface& t : m.tied_interfaces)
    for (std::size_t k = 0; k < t.tie_node.size(); ++k) {
      const int r = owner(t.tie_node[k]);
      bool cut = false;
      for (const std::int32_t n : t.tie_segment[k]) cut = cut || (owner(n) >= 0 && r >= 0 && owner(n) != r);
      s.ties_cut += cut ? 1 : 0;
    }
}

PartitionSummary summarize(const model::Model& m, const ElementGroups& groups, const Incidence& inc,
                           const GroupWeights& w, std::span<const int> group_rank, int ranks) {
  PartitionSummary s;
  s.ranks = ranks;
  s.per_rank.resize(static_cast<std::size_t>(ranks));
  for (std::size_t g = 0; g < group_rank.size(); ++g) {
    RankShare& r = s.per_rank[static_cast<std::size_t>(group_rank[g])];
    ++r.groups;
    r.elements += w.elements[g];
    r.cost += w.cost[g];
    r.contact += w.contact[g];
  }
  s.node_owner = node_owners_of(groups, inc, group_rank, ranks);
  count_nodes(inc, group_rank, s);
  s.cost_imbalance = imbalance(s.per_rank, &RankShare::cost);
  s.contact_imbalance = imbalance(s.per_rank, &RankShare::contact);
  count_cut_conditions(m, s);
  return s;
}

void require_valid(std::int64_t groups, std::span<const int> group_rank, int ranks) {
  const std::string why = check_group_ranks(groups, group_rank, ranks);
  if (!why.empty()) throw std::invalid_argument(why);
}

}  // namespace

std::vector<std::int32_t> cell_groups(const model::Model& m, const ElementGroups& groups) {
  std::vector<std::int32_t> cell(m.cell_count(), -1);
  std::int32_t flat = 0;
  groups.for_each([&](const auto& g) {
    const std::size_t first = first_cell(m, g);
    for (std::size_t i = 0; i < static_cast<std::size_t>(g.count); ++i)
      cell[first + static_cast<std::size_t>(g.element[i])] = flat;
    ++flat;
  });
  return cell;
}

GroupWeights group_weights(const model::Model& m, const ElementGroups& groups) {
  const Incidence inc(m, groups);
  return weights_of(groups, contact_load(m, groups, inc));
}

std::string check_group_ranks(std::int64_t groups, std::span<const int> group_rank, int ranks) {
  if (ranks < 1) return "the rank count must be at least 1, not " + std::to_string(ranks);
  if (static_cast<std::int64_t>(group_rank.size()) != groups)
    return std::to_string(group_rank.size()) + " group ranks for " + std::to_string(groups) +
           " element groups: give one rank per group";
  for (std::size_t g = 0; g < group_rank.size(); ++g)
    if (group_rank[g] < 0 || group_rank[g] >= ranks)
      return "group " + std::to_string(g) + " has rank " + std::to_string(group_rank[g]) + ", outside 0 .. " +
             std::to_string(ranks - 1);
  return {};
}

PartitionSummary summarize_partition(const model::Model& m, const ElementGroups& groups,
                                     std::span<const int> group_rank, int ranks) {
  require_valid(groups.count(), group_rank, ranks);
  const Incidence inc(m, groups);
  return summarize(m, groups, inc, weights_of(groups, contact_load(m, groups, inc)), group_rank, ranks);
}

Partition partition_groups(const model::Model& m, const ElementGroups& groups, int ranks) {
  if (ranks < 1)
    throw std::invalid_argument("the rank count must be at least 1, not " + std::to_string(ranks));
  const Incidence inc(m, groups);
  const ContactLoad contact = contact_load(m, groups, inc);
  const GroupWeights w = weights_of(groups, contact);
  const auto count = static_cast<std::size_t>(groups.count());
  Partition p;
  p.group_rank.assign(count, 0);
  if (ranks > 1) {
    GroupSets sets(count);
    const std::int64_t elements = std::accumulate(w.elements.begin(), w.elements.end(), std::int64_t{0});
    p.rigid_bodies_kept = join_small_rigid_bodies(m, groups, inc, elements, sets);
    // Vertices numbered in the order of their lowest group.
    std::vector<std::int32_t> vertex(count, -1);
    std::int32_t vertices = 0;
    for (std::size_t g = 0; g < count; ++g) {
      const auto root = static_cast<std::size_t>(sets.find(static_cast<std::int32_t>(g)));
      vertex[g] = root == g ? vertices++ : vertex[root];
    }
    if (vertices < ranks)
      throw std::invalid_argument(
          "cannot decompose the model into " + std::to_string(ranks) + " ranks: it has " +
          std::to_string(count) + " element groups of up to " + std::to_string(kGroupSize) + " elements" +
          (static_cast<std::size_t>(vertices) < count
               ? " (" + std::to_string(vertices) + " once each of its " +
                     std::to_string(p.rigid_bodies_kept) + " small rigid bodies keeps its groups together)"
               : std::string()) +
          " and each rank takes whole groups: give at most " + std::to_string(vertices) + " ranks");
    MetisGraph G = metis_graph(m, inc, contact, w, vertex, static_cast<std::size_t>(vertices));
    const std::vector<idx_t> part = run_metis(G, ranks);
    for (std::size_t g = 0; g < count; ++g)
      p.group_rank[g] = static_cast<int>(part[static_cast<std::size_t>(vertex[g])]);
  }
  p.summary = summarize(m, groups, inc, w, p.group_rank, ranks);
  return p;
}

}  // namespace radx::solver::parallel
