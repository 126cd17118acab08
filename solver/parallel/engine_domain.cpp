// The engine's domain on one rank: group blocks, shared-node slots, the gathered node sums
// (engine_domain.hpp gives the sums and the order they keep).
#include "solver/parallel/engine_domain.hpp"

#include <algorithm>
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

std::vector<std::vector<NodeRun>> runs_of_every_rank(const std::vector<std::int32_t>& owner, int ranks) {
  std::vector<std::vector<NodeRun>> runs(static_cast<std::size_t>(ranks));
  for (std::size_t n = 0; n < owner.size(); ++n) {
    auto& r = runs[static_cast<std::size_t>(owner[n])];
    const auto node = static_cast<std::int64_t>(n);
    if (!r.empty() && r.back().last == node)
      ++r.back().last;
    else
      r.push_back({node, node + 1});
  }
  return runs;
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
                           std::int64_t node_count, Comm& comm)
    : comm_(comm),
      group_rank_(std::move(group_rank)),
      rank_groups_begin_(rank_begins(group_rank_, comm.size())),
      rank_groups_(rank_group_lists(group_rank_, comm.size())),
      plan_(build_domain_plan(groups, group_rank_, node_count, comm.size(), comm.rank())),
      shared_(plan_),
      node_runs_(
          runs_of_every_rank(node_owner_ranks(groups, group_rank_, node_count, comm.size()), comm.size())) {}

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

void EngineDomain::complete_element_sums(std::span<double> element_sums) {
  exchange_shared_sums(shared_, comm_, element_sums);
  const auto& mine = node_runs_[static_cast<std::size_t>(plan_.rank)];
  std::size_t doubles = 0;
  for (const auto& run : mine) doubles += 6 * static_cast<std::size_t>(run.last - run.first);
  Buffer out(doubles * sizeof(double));
  std::byte* p = out.data();
  for (const auto& run : mine) {
    const std::size_t bytes = 6 * static_cast<std::size_t>(run.last - run.first) * sizeof(double);
    std::memcpy(p, element_sums.data() + 6 * run.first, bytes);
    p += bytes;
  }
  const auto all = comm_.all_gather(out);
  for (std::size_t r = 0; r < all.size(); ++r) {
    if (static_cast<int>(r) == plan_.rank) continue;
    const std::byte* q = all[r].data();
    for (const auto& run : node_runs_[r]) {
      const std::size_t bytes = 6 * static_cast<std::size_t>(run.last - run.first) * sizeof(double);
      if (q + bytes > all[r].data() + all[r].size())
        throw std::runtime_error("rank " + std::to_string(r) +
                                 "'s node sums are shorter than its nodes need");
      std::memcpy(element_sums.data() + 6 * run.first, q, bytes);
      q += bytes;
    }
  }
}

}  // namespace radx::solver::parallel
