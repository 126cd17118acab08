// The domain plan and the skyline assembly of shared nodes: see domain.hpp for the sums it reproduces.
#include "solver/parallel/domain.hpp"

#include <algorithm>
#include <cassert>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

namespace radx::solver::parallel {

namespace {

constexpr std::size_t kG = kGroupSize;
// Entry codes 32 i + q: q < 32 holds the 20 nodes of a quadratic brick, and 32 * 128 codes fit in 16 bits.
static_assert(32 * kGroupSize <= 65536, "entry codes 32 i + q must fit in 16 bits");

void check_group_ranks(const ElementGroups& groups, std::span<const std::int32_t> group_rank, int ranks) {
  if (ranks < 1) throw std::invalid_argument("domain plan: " + std::to_string(ranks) + " ranks (at least 1)");
  if (static_cast<std::int64_t>(group_rank.size()) != groups.count())
    throw std::invalid_argument("domain plan: " + std::to_string(group_rank.size()) + " group ranks for " +
                                std::to_string(groups.count()) + " element groups");
  for (std::size_t k = 0; k < group_rank.size(); ++k)
    if (group_rank[k] < 0 || group_rank[k] >= ranks)
      throw std::invalid_argument("domain plan: group " + std::to_string(k) + " has rank " +
                                  std::to_string(group_rank[k]) + ", outside [0, " + std::to_string(ranks) +
                                  ")");
}

// Calls f(node, components, i, q) for every entry of group `flat`, element by element, node by node of the
// element: the serial order of the sums.
template <class F>
void for_each_entry(const ElementGroups& groups, std::int64_t flat, F&& f) {
  visit_group_entries(groups, flat, [&](const auto& g, int nodes_per_element, auto components) {
    constexpr int C = static_cast<int>(decltype(components)::value);
    for (int i = 0; i < g.count; ++i)
      for (int q = 0; q < nodes_per_element; ++q)
        f(g.conn[static_cast<std::size_t>(q) * kG + static_cast<std::size_t>(i)], C, i, q);
  });
}

// For every node, the ranks of the entries on it (CSR over nodes, each node's ranks sorted ascending), and
// whether any entry on it has moments (the node has rotations). Transient: 4 bytes per entry.
struct NodeIncidence {
  std::vector<std::int64_t> begin;  // [nodes + 1]
  std::vector<std::int32_t> rank;
  std::vector<std::uint8_t> rotation;

  [[nodiscard]] std::span<const std::int32_t> ranks_of(std::int64_t n) const {
    const auto b = static_cast<std::size_t>(begin[static_cast<std::size_t>(n)]);
    return {rank.data() + b, static_cast<std::size_t>(begin[static_cast<std::size_t>(n) + 1]) - b};
  }
};

NodeIncidence node_incidence(const ElementGroups& groups, std::span<const std::int32_t> group_rank,
                             std::int64_t node_count) {
  NodeIncidence inc;
  const auto nodes = static_cast<std::size_t>(node_count);
  inc.begin.assign(nodes + 1, 0);
  inc.rotation.assign(nodes, 0);
  const std::int64_t group_count = groups.count();
  for (std::int64_t flat = 0; flat < group_count; ++flat)
    for_each_entry(groups, flat, [&](std::int32_t n, int components, int, int) {
      assert(n >= 0 && n < node_count);
      ++inc.begin[static_cast<std::size_t>(n) + 1];
      if (components == 6) inc.rotation[static_cast<std::size_t>(n)] = 1;
    });
  for (std::size_t n = 0; n < nodes; ++n) inc.begin[n + 1] += inc.begin[n];
  inc.rank.resize(static_cast<std::size_t>(inc.begin[nodes]));
  std::vector<std::int64_t> fill(inc.begin.begin(), inc.begin.end() - 1);
  for (std::int64_t flat = 0; flat < group_count; ++flat) {
    const std::int32_t r = group_rank[static_cast<std::size_t>(flat)];
    for_each_entry(groups, flat, [&](std::int32_t n, int, int, int) {
      inc.rank[static_cast<std::size_t>(fill[static_cast<std::size_t>(n)]++)] = r;
    });
  }
  for (std::size_t n = 0; n < nodes; ++n)
    std::sort(inc.rank.begin() + inc.begin[n], inc.rank.begin() + inc.begin[n + 1]);
  return inc;
}

// The rank with the most entries in a sorted list, the lowest on ties; rank 0 for a node no entry touches.
std::int32_t most_entries(std::span<const std::int32_t> sorted) {
  std::int32_t best = 0;
  std::size_t best_count = 0;
  for (std::size_t k = 0; k < sorted.size();) {
    std::size_t e = k;
    while (e < sorted.size() && sorted[e] == sorted[k]) ++e;
    if (e - k > best_count) {  // strictly more: a later (higher) rank never wins a tie
      best = sorted[k];
      best_count = e - k;
    }
    k = e;
  }
  return best;
}

bool touched_by_several(std::span<const std::int32_t> sorted) {
  return !sorted.empty() && sorted.front() != sorted.back();
}

std::vector<std::int32_t> owners_of(const NodeIncidence& inc, std::int64_t node_count) {
  std::vector<std::int32_t> owner(static_cast<std::size_t>(node_count));
  for (std::int64_t n = 0; n < node_count; ++n)
    owner[static_cast<std::size_t>(n)] = most_entries(inc.ranks_of(n));
  return owner;
}

std::vector<NodeRun> owned_runs_of(const std::vector<std::int32_t>& owner, int rank) {
  std::vector<NodeRun> runs;
  const auto nodes = static_cast<std::int64_t>(owner.size());
  for (std::int64_t n = 0; n < nodes;) {
    if (owner[static_cast<std::size_t>(n)] != rank) {
      ++n;
      continue;
    }
    NodeRun run{n, n};
    while (run.last < nodes && owner[static_cast<std::size_t>(run.last)] == rank) ++run.last;
    runs.push_back(run);
    n = run.last;
  }
  return runs;
}

// A CSR list per rank filled in node order: count(r) first, then add(r, node, rotation).
struct PerRankLists {
  std::vector<std::int64_t>& begin;
  std::vector<std::int32_t>& nodes;
  std::vector<std::uint8_t>& rotation;
};

// The ghost lists: nodes this rank receives from each owner, and nodes it sends to each rank that touches a
// node it owns. Both in node order, so what A sends B is what B receives from A, entry by entry.
void build_ghost_lists(DomainPlan& plan, const NodeIncidence& inc, const std::vector<std::int32_t>& owner) {
  const auto P = static_cast<std::size_t>(plan.ranks);
  // visit(node, from, to) for every ghost copy this rank takes part in.
  const auto each_copy = [&](auto&& visit) {
    for (std::int64_t n = 0; n < plan.node_count; ++n) {
      const auto rs = inc.ranks_of(n);
      if (!touched_by_several(rs)) continue;
      const std::int32_t o = owner[static_cast<std::size_t>(n)];
      for (std::size_t k = 0; k < rs.size(); ++k) {
        if (k > 0 && rs[k] == rs[k - 1]) continue;  // each reader once
        if (rs[k] == o) continue;
        if (o == plan.rank || rs[k] == plan.rank) visit(n, o, rs[k]);
      }
    }
  };
  const auto fill = [&](PerRankLists lists, bool sending) {
    lists.begin.assign(P + 1, 0);
    each_copy([&](std::int64_t, std::int32_t from, std::int32_t to) {
      if ((from == plan.rank) == sending) ++lists.begin[static_cast<std::size_t>(sending ? to : from) + 1];
    });
    for (std::size_t r = 0; r < P; ++r) lists.begin[r + 1] += lists.begin[r];
    lists.nodes.resize(static_cast<std::size_t>(lists.begin[P]));
    lists.rotation.resize(lists.nodes.size());
    std::vector<std::int64_t> at(lists.begin.begin(), lists.begin.end() - 1);
    each_copy([&](std::int64_t n, std::int32_t from, std::int32_t to) {
      if ((from == plan.rank) != sending) return;
      const auto k = static_cast<std::size_t>(at[static_cast<std::size_t>(sending ? to : from)]++);
      lists.nodes[k] = static_cast<std::int32_t>(n);
      lists.rotation[k] = inc.rotation[static_cast<std::size_t>(n)];
    });
  };
  fill(PerRankLists{plan.send_begin, plan.send_nodes, plan.send_rotation}, true);
  fill(PerRankLists{plan.ghost_begin, plan.ghost_nodes, plan.ghost_rotation}, false);
}

// The skyline. Every entry on a shared node, in the serial order, takes the next free place in the message
// from its group's rank s to the node's owner o (offsets counted per pair (s, o)). This rank keeps the
// places of its own entries (sender side) and, for the nodes it owns, every entry's source and place in the
// serial order (owner side).
void build_skyline(DomainPlan& plan, const ElementGroups& groups, std::span<const std::int32_t> group_rank,
                   const NodeIncidence& inc, const std::vector<std::int32_t>& owner) {
  const auto P = static_cast<std::size_t>(plan.ranks);
  const auto me = static_cast<std::size_t>(plan.rank);
  // The owned shared nodes and room for their contributions (one per entry on the node).
  std::vector<std::int32_t> shared_index(static_cast<std::size_t>(plan.node_count), -1);
  plan.contribution_begin.assign(1, 0);
  for (std::int64_t n = 0; n < plan.node_count; ++n) {
    const auto rs = inc.ranks_of(n);
    if (owner[static_cast<std::size_t>(n)] != plan.rank || !touched_by_several(rs)) continue;
    shared_index[static_cast<std::size_t>(n)] = static_cast<std::int32_t>(plan.shared_nodes.size());
    plan.shared_nodes.push_back(static_cast<std::int32_t>(n));
    plan.contribution_begin.push_back(plan.contribution_begin.back() + static_cast<std::int64_t>(rs.size()));
  }
  plan.contributions.resize(static_cast<std::size_t>(plan.contribution_begin.back()));
  std::vector<std::int64_t> next_contribution(plan.contribution_begin.begin(),
                                              plan.contribution_begin.end() - 1);

  std::vector<std::int64_t> used(P * P, 0);  // [s][o]: doubles placed so far in the message from s to o
  std::vector<std::int32_t>
      entry_owner;  // per own shared entry, its node's owner (offsets made global below)
  plan.shared_entry_begin.assign(1, 0);
  const std::int64_t group_count = groups.count();
  for (std::int64_t flat = 0; flat < group_count; ++flat) {
    const auto s = static_cast<std::size_t>(group_rank[static_cast<std::size_t>(flat)]);
    for_each_entry(groups, flat, [&](std::int32_t n, int components, int i, int q) {
      if (!touched_by_several(inc.ranks_of(n))) return;
      const auto o = static_cast<std::size_t>(owner[static_cast<std::size_t>(n)]);
      const std::int64_t offset = used[s * P + o];
      used[s * P + o] += components;
      if (s == me) {
        plan.shared_entry_code.push_back(static_cast<std::uint16_t>(32 * i + q));
        plan.shared_entry_offset.push_back(offset);
        entry_owner.push_back(static_cast<std::int32_t>(o));
      }
      if (o == me) {
        if (offset > std::numeric_limits<std::int32_t>::max())
          throw std::length_error("domain plan: a shared-sum message over 2^31 doubles");
        const auto at =
            next_contribution[static_cast<std::size_t>(shared_index[static_cast<std::size_t>(n)])]++;
        plan.contributions[static_cast<std::size_t>(at)] =
            Contribution{static_cast<std::int32_t>(s), static_cast<std::int32_t>(offset), components};
      }
    });
    if (s == me) plan.shared_entry_begin.push_back(static_cast<std::int64_t>(plan.shared_entry_code.size()));
  }
  plan.message_begin.assign(P + 1, 0);
  plan.expected_from.assign(P, 0);
  for (std::size_t r = 0; r < P; ++r) {
    plan.message_begin[r + 1] = plan.message_begin[r] + used[me * P + r];
    plan.expected_from[r] = used[r * P + me];
  }
  for (std::size_t k = 0; k < plan.shared_entry_offset.size(); ++k)
    plan.shared_entry_offset[k] += plan.message_begin[static_cast<std::size_t>(entry_owner[k])];
}

// Doubles of the ghost record of each node in a list: x, v, and omega with rotations.
std::int64_t ghost_doubles(std::span<const std::uint8_t> rotation) {
  std::int64_t d = 0;
  for (const std::uint8_t r : rotation) d += r != 0 ? 9 : 6;
  return d;
}

void check_message(const Buffer& b, std::int64_t doubles, int from, const char* what) {
  if (b.size() != static_cast<std::size_t>(doubles) * sizeof(double))
    throw std::runtime_error(std::string("domain exchange: the ") + what + " message from rank " +
                             std::to_string(from) + " has " + std::to_string(b.size()) + " bytes, the plan " +
                             std::to_string(doubles * static_cast<std::int64_t>(sizeof(double))) +
                             " (ranks built different plans)");
}

void check_message_count(const std::vector<Buffer>& received, int ranks, const char* what) {
  if (static_cast<int>(received.size()) != ranks)
    throw std::runtime_error(std::string("domain exchange: ") + std::to_string(received.size()) + " " + what +
                             " messages for " + std::to_string(ranks) + " ranks");
}

}  // namespace

std::vector<std::int32_t> node_owner_ranks(const ElementGroups& groups,
                                           std::span<const std::int32_t> group_rank, std::int64_t node_count,
                                           int ranks) {
  check_group_ranks(groups, group_rank, ranks);
  return owners_of(node_incidence(groups, group_rank, node_count), node_count);
}

DomainPlan build_domain_plan(const ElementGroups& groups, std::span<const std::int32_t> group_rank,
                             std::int64_t node_count, int ranks, int rank) {
  check_group_ranks(groups, group_rank, ranks);
  if (rank < 0 || rank >= ranks)
    throw std::invalid_argument("domain plan: rank " + std::to_string(rank) + " outside [0, " +
                                std::to_string(ranks) + ")");
  DomainPlan plan;
  plan.ranks = ranks;
  plan.rank = rank;
  plan.node_count = node_count;
  const NodeIncidence inc = node_incidence(groups, group_rank, node_count);
  plan.node_owner = owners_of(inc, node_count);
  const std::vector<std::int32_t>& owner = plan.node_owner;

  plan.local_group.assign(group_rank.size(), -1);
  for (std::size_t flat = 0; flat < group_rank.size(); ++flat)
    if (group_rank[flat] == rank) {
      plan.local_group[flat] = static_cast<std::int32_t>(plan.groups.size());
      plan.groups.push_back(static_cast<std::int64_t>(flat));
    }
  plan.owned_runs = owned_runs_of(owner, rank);
  for (const NodeRun& r : plan.owned_runs) plan.owned_nodes += r.last - r.first;
  build_ghost_lists(plan, inc, owner);
  build_skyline(plan, groups, group_rank, inc, owner);
  return plan;
}

std::int64_t DomainPlan::entry_slot(std::int64_t flat, int i, int q) const {
  const std::int32_t local = local_group[static_cast<std::size_t>(flat)];
  if (local < 0) return -1;
  const auto codes = shared_codes(static_cast<std::size_t>(local));
  const auto code = static_cast<std::uint16_t>(32 * i + q);
  const auto it = std::lower_bound(codes.begin(), codes.end(), code);
  if (it == codes.end() || *it != code) return -1;
  return shared_offsets(static_cast<std::size_t>(local))[static_cast<std::size_t>(it - codes.begin())];
}

DomainTraffic domain_traffic(const DomainPlan& plan) {
  DomainTraffic t;
  constexpr auto kBytes = static_cast<std::int64_t>(sizeof(double));
  for (int r = 0; r < plan.ranks; ++r) {
    if (r == plan.rank) continue;
    const auto k = static_cast<std::size_t>(r);
    const std::int64_t sums = plan.message_begin[k + 1] - plan.message_begin[k];
    t.shared_sum_sent += kBytes * sums;
    t.shared_sum_received += kBytes * plan.expected_from[k];
    t.shared_sum_messages += sums > 0 ? 1 : 0;
    const auto sent = std::span(plan.send_rotation)
                          .subspan(static_cast<std::size_t>(plan.send_begin[k]),
                                   static_cast<std::size_t>(plan.send_begin[k + 1] - plan.send_begin[k]));
    const auto got = std::span(plan.ghost_rotation)
                         .subspan(static_cast<std::size_t>(plan.ghost_begin[k]),
                                  static_cast<std::size_t>(plan.ghost_begin[k + 1] - plan.ghost_begin[k]));
    t.ghost_sent += kBytes * ghost_doubles(sent);
    t.ghost_received += kBytes * ghost_doubles(got);
    t.ghost_messages += sent.empty() ? 0 : 1;
  }
  return t;
}

SharedSums::SharedSums(const DomainPlan& plan)
    : plan_(plan), storage_(static_cast<std::size_t>(plan.message_begin.back()), 0.0) {}

std::vector<Buffer> SharedSums::pack() const {
  std::vector<Buffer> out(static_cast<std::size_t>(plan_.ranks));
  for (std::size_t r = 0; r < out.size(); ++r) {
    const auto b = static_cast<std::size_t>(plan_.message_begin[r]);
    const auto e = static_cast<std::size_t>(plan_.message_begin[r + 1]);
    out[r].resize((e - b) * sizeof(double));
    if (e > b) std::memcpy(out[r].data(), storage_.data() + b, (e - b) * sizeof(double));
  }
  return out;
}

void SharedSums::sum_on_owner(const std::vector<Buffer>& received, std::span<double> element_sums) const {
  check_message_count(received, plan_.ranks, "shared-sum");
  for (int s = 0; s < plan_.ranks; ++s)
    check_message(received[static_cast<std::size_t>(s)], plan_.expected_from[static_cast<std::size_t>(s)], s,
                  "shared-sum");
  for (std::size_t k = 0; k < plan_.shared_nodes.size(); ++k) {
    // From zero, term by term in the serial order: ((0 + c1) + c2) + ...
    double sum[6] = {0, 0, 0, 0, 0, 0};
    for (auto c = plan_.contribution_begin[k]; c < plan_.contribution_begin[k + 1]; ++c) {
      const Contribution& t = plan_.contributions[static_cast<std::size_t>(c)];
      const std::byte* p = received[static_cast<std::size_t>(t.source)].data() +
                           static_cast<std::size_t>(t.offset) * sizeof(double);
      for (int d = 0; d < t.components; ++d) {
        double v = 0;
        std::memcpy(&v, p + static_cast<std::size_t>(d) * sizeof(double), sizeof(double));
        sum[d] += v;
      }
    }
    double* out = element_sums.data() + 6 * static_cast<std::size_t>(plan_.shared_nodes[k]);
    std::copy(sum, sum + 6, out);
  }
}

void add_owned_group_sums(const ElementGroups& groups, const DomainPlan& plan, std::int64_t flat,
                          std::span<double> element_sums, SharedSums& shared) {
  const std::int32_t local = plan.local_group[static_cast<std::size_t>(flat)];
  assert(local >= 0);  // a group of this rank
  const auto codes = plan.shared_codes(static_cast<std::size_t>(local));
  const auto offsets = plan.shared_offsets(static_cast<std::size_t>(local));
  visit_group_entries(groups, flat, [&](const auto& g, int nodes_per_element, auto components) {
    constexpr std::size_t C = decltype(components)::value;
    std::size_t next_shared = 0;  // the group's shared entries come in the order of the loop below
    for (std::size_t i = 0; i < static_cast<std::size_t>(g.count); ++i)
      for (std::size_t q = 0; q < static_cast<std::size_t>(nodes_per_element); ++q) {
        const double* f = g.nodal_force.data() + q * C * kG + i;
        if (next_shared < codes.size() && codes[next_shared] == 32 * i + q) {
          double* slot = shared.slot(offsets[next_shared++]);
          for (std::size_t d = 0; d < C; ++d) slot[d] = f[d * kG];
        } else {
          double* sum = element_sums.data() + 6 * static_cast<std::size_t>(g.conn[q * kG + i]);
          for (std::size_t d = 0; d < C; ++d) sum[d] += f[d * kG];
        }
      }
  });
}

void exchange_shared_sums(const SharedSums& shared, Comm& comm, std::span<double> element_sums) {
  shared.sum_on_owner(comm.exchange(shared.pack()), element_sums);
}

std::vector<Buffer> ghost_pack(const DomainPlan& plan, const NodeState& nodes) {
  std::vector<Buffer> out(static_cast<std::size_t>(plan.ranks));
  for (std::size_t r = 0; r < out.size(); ++r) {
    const auto b = static_cast<std::size_t>(plan.send_begin[r]);
    const auto e = static_cast<std::size_t>(plan.send_begin[r + 1]);
    out[r].resize(static_cast<std::size_t>(ghost_doubles(std::span(plan.send_rotation).subspan(b, e - b))) *
                  sizeof(double));
    std::byte* p = out[r].data();
    const auto put = [&p](double v) {
      std::memcpy(p, &v, sizeof v);
      p += sizeof v;
    };
    for (std::size_t k = b; k < e; ++k) {
      const auto n = static_cast<std::size_t>(plan.send_nodes[k]);
      for (const double v : {nodes.x[n], nodes.y[n], nodes.z[n], nodes.vx[n], nodes.vy[n], nodes.vz[n]})
        put(v);
      if (plan.send_rotation[k] != 0)
        for (const double v : {nodes.wx[n], nodes.wy[n], nodes.wz[n]}) put(v);
    }
  }
  return out;
}

void ghost_unpack(const DomainPlan& plan, const std::vector<Buffer>& received, NodeState& nodes) {
  check_message_count(received, plan.ranks, "ghost");
  for (std::size_t r = 0; r < received.size(); ++r) {
    const auto b = static_cast<std::size_t>(plan.ghost_begin[r]);
    const auto e = static_cast<std::size_t>(plan.ghost_begin[r + 1]);
    check_message(received[r], ghost_doubles(std::span(plan.ghost_rotation).subspan(b, e - b)),
                  static_cast<int>(r), "ghost");
    const std::byte* p = received[r].data();
    const auto take = [&p](double& v) {
      std::memcpy(&v, p, sizeof v);
      p += sizeof v;
    };
    for (std::size_t k = b; k < e; ++k) {
      const auto n = static_cast<std::size_t>(plan.ghost_nodes[k]);
      for (auto* a : {&nodes.x, &nodes.y, &nodes.z, &nodes.vx, &nodes.vy, &nodes.vz}) take((*a)[n]);
      if (plan.ghost_rotation[k] != 0)
        for (auto* a : {&nodes.wx, &nodes.wy, &nodes.wz}) take((*a)[n]);
    }
  }
}

void exchange_ghosts(const DomainPlan& plan, Comm& comm, NodeState& nodes) {
  ghost_unpack(plan, comm.exchange(ghost_pack(plan, nodes)), nodes);
}

}  // namespace radx::solver::parallel
