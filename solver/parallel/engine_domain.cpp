// The engine's domain on one rank: group blocks, shared-node slots, the gathered node sums
// (engine_domain.hpp gives the sums and the order they keep).
#include "solver/parallel/engine_domain.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <utility>

#include "solver/parallel/partition.hpp"

namespace radx::solver::parallel {

std::vector<std::int32_t> block_group_ranks(std::int64_t groups, int ranks) {
  std::vector<std::int32_t> rank(static_cast<std::size_t>(groups));
  for (std::int64_t g = 0; g < groups; ++g)
    rank[static_cast<std::size_t>(g)] =
        static_cast<std::int32_t>(g * ranks / std::max<std::int64_t>(groups, 1));
  return rank;
}

std::vector<std::string> features_not_distributed(const model::Model& m, const model::RunControls&) {
  std::vector<std::string> found;
  const auto refuse = [&](bool present, const char* what) {
    if (present) found.emplace_back(what);
  };
  refuse(!m.sections.empty(), "/SECT sections");
  return found;
}

namespace {

// Node `node` (above every node in `runs`) onto ascending runs: the last run grows, or a new one starts.
void append_node(std::vector<NodeRun>& runs, std::int64_t node) {
  if (!runs.empty() && runs.back().last == node)
    ++runs.back().last;
  else
    runs.push_back({node, node + 1});
}

// Every rank's owned nodes that `keep(node)` selects, as ascending runs.
template <class Keep>
std::vector<std::vector<NodeRun>> runs_of_every_rank(const std::vector<std::int32_t>& owner, int ranks,
                                                     Keep&& keep) {
  std::vector<std::vector<NodeRun>> runs(static_cast<std::size_t>(ranks));
  for (std::size_t n = 0; n < owner.size(); ++n)
    if (keep(n)) append_node(runs[static_cast<std::size_t>(owner[n])], static_cast<std::int64_t>(n));
  return runs;
}

// The nodes `rank` owns or every rank keeps whole, as ascending runs.
std::vector<NodeRun> pass_runs_of(const std::vector<std::int32_t>& owner,
                                  std::span<const std::uint8_t> replicated, int rank) {
  std::vector<NodeRun> runs;
  for (std::size_t n = 0; n < owner.size(); ++n)
    if (owner[n] == rank || replicated[n] != 0) append_node(runs, static_cast<std::int64_t>(n));
  return runs;
}

void mark_group(const model::Model& m, std::int32_t group, std::vector<std::uint8_t>& mark) {
  if (group == model::kNone) return;
  for (const auto n : m.node_groups[static_cast<std::size_t>(group)].nodes)
    mark[static_cast<std::size_t>(n)] = 1;
}

void mark_surface(const model::Model& m, std::int32_t surface, std::vector<std::uint8_t>& mark) {
  if (surface == model::kNone) return;
  for (const auto& seg : m.surfaces[static_cast<std::size_t>(surface)].segments)
    for (const auto n : seg) mark[static_cast<std::size_t>(n)] = 1;
}

void mark_nodes(std::span<const std::int32_t> nodes, std::vector<std::uint8_t>& mark) {
  for (const auto n : nodes)
    if (n != model::kNone) mark[static_cast<std::size_t>(n)] = 1;
}

// Each rank's groups ascending, as a CSR list (begin [ranks + 1], groups).
std::vector<std::int64_t> rank_begins(const std::vector<std::int32_t>& group_rank, int ranks) {
  std::vector<std::int64_t> begin(static_cast<std::size_t>(ranks) + 1, 0);
  for (const auto r : group_rank) ++begin[static_cast<std::size_t>(r) + 1];
  for (std::size_t r = 0; r < static_cast<std::size_t>(ranks); ++r) begin[r + 1] += begin[r];
  return begin;
}
std::vector<std::int64_t> rank_group_lists(const std::vector<std::int32_t>& group_rank, int ranks) {
  auto next = rank_begins(group_rank, ranks);
  std::vector<std::int64_t> list(group_rank.size());
  for (std::size_t g = 0; g < group_rank.size(); ++g)
    list[static_cast<std::size_t>(next[static_cast<std::size_t>(group_rank[g])]++)] =
        static_cast<std::int64_t>(g);
  return list;
}

}  // namespace

std::vector<std::uint8_t> replicated_nodes(const model::Model& m) {
  std::vector<std::uint8_t> mark(m.nodes.id.size(), 0);
  for (const auto& v : m.imposed_velocities) mark_group(m, v.group, mark);
  for (const auto& g : m.imposed_final_geometries) mark_nodes(g.nodes, mark);
  for (const auto& v : m.initial_velocities)  // at t = 0 every rank sets every node alike
    if (v.sensor != 0 || v.t_start > 0) mark_group(m, v.group, mark);
  for (const auto& l : m.concentrated_loads) mark_group(m, l.group, mark);
  for (const auto& p : m.pressure_loads) mark_surface(m, p.surface, mark);
  for (const auto& g : m.gravities) {
    if (g.group == model::kNone)
      std::fill(mark.begin(), mark.end(), 1);
    else
      mark_group(m, g.group, mark);
  }
  for (const auto& w : m.rigid_walls) {
    mark_nodes(w.secondary, mark);
    mark_nodes(std::span(&w.node, 1), mark);
  }
  for (const auto& b : m.rigid_bodies) {
    mark_nodes(b.secondary, mark);
    mark_nodes(std::span(&b.main_node, 1), mark);
  }
  for (const auto& t : m.tied_interfaces) {
    mark_nodes(t.tie_node, mark);
    for (const auto& seg : t.tie_segment) mark_nodes(seg, mark);
  }
  for (const auto& i : m.interfaces) {
    mark_nodes(i.secondary_nodes, mark);
    mark_surface(m, i.main_surface, mark);
  }
  for (const auto& k : m.skews)
    if (k.moving()) mark_nodes(std::array{k.n1, k.n2, k.n3}, mark);
  for (const auto& a : m.accelerometers) mark_nodes(std::span(&a.node, 1), mark);
  return mark;
}

std::vector<std::int32_t> engine_group_ranks(const model::Model& model, const ElementGroups& groups,
                                             Comm& comm, std::span<const std::int32_t> given) {
  const int ranks = comm.size();
  std::vector<std::int32_t> rank(static_cast<std::size_t>(groups.count()));
  const std::size_t bytes = rank.size() * sizeof(std::int32_t);
  // The message: a first byte 0 and the group ranks, or 1 and rank 0's error, which every rank then throws
  // (a rank left waiting in the broadcast would hang the run).
  Buffer message;
  if (comm.rank() == 0) {
    std::string failure;
    try {
      if (!given.empty()) {
        // Checked by the caller against the file it came from; a mismatch here is a caller's bug, said
        // by every rank rather than run on a partition that does not fit.
        if (const std::string why = check_group_ranks(groups.count(), given, ranks); !why.empty())
          throw std::runtime_error("the given group ranks do not fit: " + why);
        std::copy(given.begin(), given.end(), rank.begin());
      } else {
        const auto p = partition_groups(model, groups, ranks);
        std::copy(p.group_rank.begin(), p.group_rank.end(), rank.begin());
      }
    } catch (const std::invalid_argument&) {  // fewer groups than ranks: blocks, some ranks without groups
      rank = block_group_ranks(groups.count(), ranks);
    } catch (const std::exception& e) {
      failure = e.what();
    }
    message.assign(1, std::byte{failure.empty() ? std::uint8_t{0} : std::uint8_t{1}});
    if (!failure.empty()) {
      const auto* text = reinterpret_cast<const std::byte*>(failure.data());
      message.insert(message.end(), text, text + failure.size());
    } else if (bytes > 0) {
      const auto* data = reinterpret_cast<const std::byte*>(rank.data());
      message.insert(message.end(), data, data + bytes);
    }
  }
  comm.broadcast(message, 0);
  if (!message.empty() && message[0] == std::byte{1})
    throw std::runtime_error(
        "the partition over " + std::to_string(ranks) + " ranks failed on rank 0: " +
        std::string(reinterpret_cast<const char*>(message.data()) + 1, message.size() - 1));
  if (message.size() != bytes + 1)
    throw std::runtime_error("rank 0's group ranks do not cover this rank's groups");
  if (bytes > 0) std::memcpy(rank.data(), message.data() + 1, bytes);
  return rank;
}

EngineDomain::EngineDomain(const ElementGroups& groups, std::vector<std::int32_t> group_rank,
                           std::span<const std::uint8_t> replicated, std::span<const std::int32_t> watched,
                           Comm& comm)
    : comm_(comm),
      group_rank_(std::move(group_rank)),
      rank_groups_begin_(rank_begins(group_rank_, comm.size())),
      rank_groups_(rank_group_lists(group_rank_, comm.size())),
      plan_(build_domain_plan(groups, group_rank_, static_cast<std::int64_t>(replicated.size()), comm.size(),
                              comm.rank())),
      shared_(plan_) {
  const auto& owner = plan_.node_owner;
  replicated_runs_ =
      runs_of_every_rank(owner, comm.size(), [&](std::size_t n) { return replicated[n] != 0; });
  unreplicated_runs_ =
      runs_of_every_rank(owner, comm.size(), [&](std::size_t n) { return replicated[n] == 0; });
  pass_runs_ = pass_runs_of(owner, replicated, comm.rank());
  for (const auto n : plan_.ghost_nodes)
    if (replicated[static_cast<std::size_t>(n)] == 0) partial_ghosts_.push_back(n);
  // The watched nodes but the replicated ones, which every rank holds whole already.
  std::vector<std::uint8_t> watch(owner.size(), 0);
  for (const auto n : watched)
    watch[static_cast<std::size_t>(n)] = replicated[static_cast<std::size_t>(n)] == 0;
  watched_runs_ = runs_of_every_rank(owner, comm.size(), [&](std::size_t n) { return watch[n] != 0; });
  any_watched_ =
      std::any_of(watched_runs_.begin(), watched_runs_.end(), [](const auto& r) { return !r.empty(); });
}

void EngineDomain::write_shared_slots(const ElementGroups& groups, std::int64_t flat) {
  const std::int32_t local = plan_.local_group[static_cast<std::size_t>(flat)];
  assert(local >= 0);
  const auto codes = plan_.shared_codes(static_cast<std::size_t>(local));
  if (codes.empty()) return;
  const auto offsets = plan_.shared_offsets(static_cast<std::size_t>(local));
  constexpr std::size_t G = kGroupSize;
  visit_group_entries(groups, flat, [&](const auto& g, int, auto components) {
    constexpr std::size_t C = decltype(components)::value;
    for (std::size_t k = 0; k < codes.size(); ++k) {
      const std::size_t i = codes[k] >> 5, q = codes[k] & 31u;
      const double* f = g.nodal_force.data() + q * C * G + i;
      double* slot = shared_.slot(offsets[k]);
      for (std::size_t d = 0; d < C; ++d) slot[d] = f[d * G];
    }
  });
}

std::vector<Buffer> EngineDomain::complete_element_sums(std::span<double> element_sums,
                                                        const Buffer& record) {
  exchange_shared_sums(shared_, comm_, element_sums);
  // A ghost's sum here holds this rank's entries only (its owner has the whole sum); cleared, as the
  // assembly pass that would clear it does not walk the ghost.
  for (const auto n : partial_ghosts_)
    std::fill_n(element_sums.data() + 6 * static_cast<std::size_t>(n), 6, 0.0);
  const NodeField sums{element_sums.data(), 6};
  return all_gather_runs(replicated_runs_, std::span(&sums, 1), record);
}

void EngineDomain::update_ghosts(NodeState& nodes) {
  exchange_ghosts(plan_, comm_, nodes);
}

void EngineDomain::gather_node_motion(NodeState& s, int root) {
  const std::array<NodeField, 6> motion{{{s.vx.data(), 1},
                                         {s.vy.data(), 1},
                                         {s.vz.data(), 1},
                                         {s.ax.data(), 1},
                                         {s.ay.data(), 1},
                                         {s.az.data(), 1}}};
  all_gather_runs(unreplicated_runs_, motion, {}, root);
  if (any_watched_) gather_runs_of_state(watched_runs_, s, root);
}

void EngineDomain::gather_node_state(NodeState& s, int root) {
  gather_runs_of_state(unreplicated_runs_, s, root);
}

void EngineDomain::gather_runs_of_state(const std::vector<std::vector<NodeRun>>& runs, NodeState& s,
                                        int root) {
  const std::array<NodeField, 24> fields{
      {{s.x.data(), 1},   {s.y.data(), 1},      {s.z.data(), 1},      {s.vx.data(), 1},    {s.vy.data(), 1},
       {s.vz.data(), 1},  {s.ax.data(), 1},     {s.ay.data(), 1},     {s.az.data(), 1},    {s.fx.data(), 1},
       {s.fy.data(), 1},  {s.fz.data(), 1},     {s.wx.data(), 1},     {s.wy.data(), 1},    {s.wz.data(), 1},
       {s.mx.data(), 1},  {s.my.data(), 1},     {s.mz.data(), 1},     {s.awx.data(), 1},   {s.awy.data(), 1},
       {s.awz.data(), 1}, {s.fx_ext.data(), 1}, {s.fy_ext.data(), 1}, {s.fz_ext.data(), 1}}};
  all_gather_runs(runs, fields, {}, root);
}

std::vector<Buffer> EngineDomain::all_gather_runs(const std::vector<std::vector<NodeRun>>& runs,
                                                  std::span<const NodeField> fields, const Buffer& header,
                                                  int root) {
  // A message: the header's size (8 bytes), the header, then each run's fields.
  const auto doubles_of = [&](const std::vector<NodeRun>& rs) {
    std::size_t d = 0;
    for (const auto& run : rs)
      for (const auto& f : fields) d += f.width * static_cast<std::size_t>(run.last - run.first);
    return d;
  };
  const auto& mine = runs[static_cast<std::size_t>(plan_.rank)];
  const std::uint64_t header_bytes = header.size();
  Buffer out(sizeof header_bytes + header.size() + doubles_of(mine) * sizeof(double));
  std::byte* p = out.data();
  std::memcpy(p, &header_bytes, sizeof header_bytes);
  p += sizeof header_bytes;
  if (!header.empty()) std::memcpy(p, header.data(), header.size());
  p += header.size();
  for (const auto& run : mine)
    for (const auto& f : fields) {
      const std::size_t bytes = f.width * static_cast<std::size_t>(run.last - run.first) * sizeof(double);
      std::memcpy(p, f.data + f.width * static_cast<std::size_t>(run.first), bytes);
      p += bytes;
    }
  const auto all = root < 0 ? comm_.all_gather(out) : comm_.gather(out, root);
  std::vector<Buffer> headers(all.size());
  for (std::size_t r = 0; r < all.size(); ++r) {
    std::uint64_t theirs = 0;
    if (all[r].size() >= sizeof theirs) std::memcpy(&theirs, all[r].data(), sizeof theirs);
    if (theirs > all[r].size() - std::min(all[r].size(), sizeof theirs) ||
        all[r].size() != sizeof theirs + theirs + doubles_of(runs[r]) * sizeof(double))
      throw std::runtime_error("rank " + std::to_string(r) +
                               "'s node message does not have the size its nodes need");
    const std::byte* q = all[r].data() + sizeof theirs;
    headers[r].assign(q, q + theirs);
    q += theirs;
    if (static_cast<int>(r) == plan_.rank) continue;
    for (const auto& run : runs[r])
      for (const auto& f : fields) {
        const std::size_t bytes = f.width * static_cast<std::size_t>(run.last - run.first) * sizeof(double);
        std::memcpy(f.data + f.width * static_cast<std::size_t>(run.first), q, bytes);
        q += bytes;
      }
  }
  return headers;
}

}  // namespace radx::solver::parallel
