// radx-engine --decompose P (engine_decompose.hpp).
#include "apps/engine_decompose.hpp"

#include <charconv>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include "io/hdf5/domain_file.hpp"
#include "io/text_file.hpp"
#include "solver/parallel/partition.hpp"

namespace radx::app {

namespace {

namespace fs = std::filesystem;

// The integers of a line up to '#': false when something else is there.
bool line_integers(std::string_view line, std::vector<std::int64_t>& values) {
  values.clear();
  line = line.substr(0, line.find('#'));
  std::size_t k = 0;
  while (k < line.size()) {
    if (line[k] == ' ' || line[k] == '\t' || line[k] == '\r') {
      ++k;
      continue;
    }
    std::int64_t v = 0;
    const auto [end, ec] = std::from_chars(line.data() + k, line.data() + line.size(), v);
    const auto used = static_cast<std::size_t>(end - line.data());
    if (ec != std::errc() ||
        (used < line.size() && line[used] != ' ' && line[used] != '\t' && line[used] != '\r'))
      return false;
    values.push_back(v);
    k = used;
  }
  return true;
}

// The group's part id and its first element's kind and id, for the comment of its line.
std::string group_label(const model::Model& m, const solver::ElementGroups& groups, std::int64_t flat) {
  std::string label;
  groups.visit(flat, [&](const auto& g) {
    const auto& block = solver::element_block(m, g);
    label = "part " + std::to_string(m.parts[static_cast<std::size_t>(g.part)].id) + ", " +
            std::to_string(g.count) + " " + std::string(model::element_type_name(block.type)) + " from id " +
            std::to_string(block.id[static_cast<std::size_t>(g.element[0])]);
  });
  return label;
}

std::string neighbour_list(const std::vector<int>& ranks) {
  if (ranks.empty()) return "-";
  std::string s;
  for (const int r : ranks) s += (s.empty() ? "" : ",") + std::to_string(r);
  return s;
}

void print_table(const solver::parallel::PartitionSummary& s, std::int64_t kept, const std::string& source,
                 const std::string& root, std::ostream& out) {
  std::int64_t groups = 0, elements = 0;
  for (const auto& r : s.per_rank) {
    groups += r.groups;
    elements += r.elements;
  }
  out << "decomposition of " << root << " into " << s.ranks << " ranks: " << groups << " element groups, "
      << elements << " elements; " << source << "\n";
  out << "rank  groups  elements        cost  contact  owned_nodes  ghost_nodes  shared_nodes  neighbours\n";
  for (std::size_t r = 0; r < s.per_rank.size(); ++r) {
    const auto& p = s.per_rank[r];
    out << std::setw(4) << r << std::setw(8) << p.groups << std::setw(10) << p.elements << std::setw(12)
        << p.cost << std::setw(9) << p.contact << std::setw(13) << p.owned_nodes << std::setw(13)
        << p.ghost_nodes << std::setw(14) << p.shared_nodes << "  " << neighbour_list(p.neighbours) << '\n';
  }
  std::ostringstream imbalance;
  imbalance << std::fixed << std::setprecision(4) << "imbalance (heaviest rank / mean): cost "
            << s.cost_imbalance << " (METIS tolerance " << std::setprecision(2)
            << solver::parallel::kCostTolerance << "), contact work " << std::setprecision(4)
            << s.contact_imbalance << " (tolerance " << std::setprecision(2)
            << solver::parallel::kContactTolerance << ")";
  out << imbalance.str() << '\n';
  out << "shared nodes: " << s.shared_nodes << " (touched by the elements of more than one rank)\n";
  out << "rigid bodies cut: " << s.rigid_bodies_cut << "; kept on one rank by the partition: " << kept
      << "; TYPE2 ties cut: " << s.ties_cut << '\n';
}

// A file for P ranks names each of them: one that leaves a rank without a group was written for fewer ranks
// (or edited by mistake), and would leave that rank idle.
void check_every_rank_named(const std::string& path, const std::vector<int>& rank, int ranks,
                            Diagnostics& diags) {
  std::vector<char> named(static_cast<std::size_t>(ranks), 0);
  for (const int r : rank) named[static_cast<std::size_t>(r)] = 1;
  std::string idle;
  int highest = -1;
  for (int r = 0; r < ranks; ++r) {
    if (named[static_cast<std::size_t>(r)] == 0)
      idle += (idle.empty() ? "" : ", ") + std::to_string(r);
    else
      highest = r;
  }
  if (idle.empty()) return;
  diags.error(Diag::BadGroupRankFile, Where{path}, About{},
              "rank(s) " + idle + " of the " + std::to_string(ranks) +
                  " ranks have no group (the file names ranks up to " + std::to_string(highest) +
                  "): a group-rank file for P ranks gives each rank 0 .. P-1 at least one group");
}

}  // namespace

std::vector<int> read_group_ranks(const std::string& path, std::int64_t groups, int ranks,
                                  Diagnostics& diags) {
  std::vector<int> rank(static_cast<std::size_t>(groups), -1);
  std::vector<int> line_of(static_cast<std::size_t>(groups), 0);
  std::ifstream in(path);
  if (!in) {
    diags.error(Diag::BadGroupRankFile, Where{path}, About{}, "cannot open the group-rank file");
    return rank;
  }
  const std::string accepted = "a line \"GROUP RANK\" per element group, GROUP in 0 .. " +
                               std::to_string(groups - 1) + " and RANK in 0 .. " + std::to_string(ranks - 1);
  std::string line;
  std::vector<std::int64_t> v;
  for (int number = 1; std::getline(in, line); ++number) {
    if (!line_integers(line, v) || (!v.empty() && v.size() != 2)) {
      diags.error(Diag::BadGroupRankFile, Where{path, number}, About{},
                  "cannot read \"" + line + "\": give " + accepted);
      continue;
    }
    if (v.empty()) continue;
    if (v[0] < 0 || v[0] >= groups || v[1] < 0 || v[1] >= ranks) {
      diags.error(Diag::BadGroupRankFile, Where{path, number}, About{},
                  "group " + std::to_string(v[0]) + " rank " + std::to_string(v[1]) +
                      " is out of range: give " + accepted);
      // A group given a rank out of range is given, wrongly: not reported again as missing.
      if (v[0] >= 0 && v[0] < groups && line_of[static_cast<std::size_t>(v[0])] == 0)
        line_of[static_cast<std::size_t>(v[0])] = number;
      continue;
    }
    const auto g = static_cast<std::size_t>(v[0]);
    if (line_of[g] != 0) {
      diags.error(Diag::BadGroupRankFile, Where{path, number}, About{},
                  "group " + std::to_string(g) + " is given a rank again (first on line " +
                      std::to_string(line_of[g]) + "): give each group once");
      continue;
    }
    line_of[g] = number;
    rank[g] = static_cast<int>(v[1]);
  }
  std::string missing;
  std::int64_t count = 0;
  for (std::size_t g = 0; g < rank.size(); ++g)
    if (line_of[g] == 0 && count++ < 10) missing += (missing.empty() ? "" : ", ") + std::to_string(g);
  if (count > 0)
    diags.error(Diag::BadGroupRankFile, Where{path}, About{},
                std::to_string(count) + (count == 1 ? " element group has" : " element groups have") +
                    " no rank (" + missing + (count > 10 ? ", ..." : "") + "): give " + accepted);
  else if (!diags.has_errors())
    check_every_rank_named(path, rank, ranks, diags);
  return rank;
}

std::string group_ranks_text(const model::Model& m, const solver::ElementGroups& groups,
                             const std::vector<int>& group_rank, int ranks, const std::string& root) {
  std::string text =
      "# radx group ranks of " + root + ": " + std::to_string(ranks) + " ranks, " +
      std::to_string(groups.count()) +
      " element groups in the engine's flat order (shells, bricks, tetrahedra, 20-node bricks, "
      "springs, trusses, beams)\n# GROUP RANK  (radx-engine --decompose P --partition FILE reads "
      "this)\n";
  for (std::size_t g = 0; g < group_rank.size(); ++g)
    text += std::to_string(g) + " " + std::to_string(group_rank[g]) + "  # " +
            group_label(m, groups, static_cast<std::int64_t>(g)) + "\n";
  return text;
}

int decompose_model(const model::Model& m, const solver::ElementGroups& groups, int ranks,
                    const std::string& partition_file, const std::string& out_dir, const std::string& root,
                    std::ostream& out, std::ostream& err) {
  namespace par = solver::parallel;
  par::PartitionSummary summary;
  std::vector<int> group_rank;
  std::int64_t kept = 0;
  std::string source;
  if (!partition_file.empty()) {
    Diagnostics diags;
    group_rank = read_group_ranks(partition_file, groups.count(), ranks, diags);
    diags.print(err);
    if (diags.has_errors()) {
      err << "radx-engine: " << diags.error_count() << " error(s) in the group-rank file " << partition_file
          << "; nothing was written\n";
      return 1;
    }
    summary = par::summarize_partition(m, groups, group_rank, ranks);
    source = "group ranks from " + partition_file;
  } else {
    try {
      par::Partition p = par::partition_groups(m, groups, ranks);
      group_rank = std::move(p.group_rank);
      summary = std::move(p.summary);
      kept = p.rigid_bodies_kept;
    } catch (const std::invalid_argument& e) {
      // An option, not a line of a file: the message names the program instead of a file.
      err << "radx-engine: error: " << diag_code(Diag::DecompositionRanks) << ": " << e.what() << '\n';
      return 1;
    } catch (const std::exception& e) {  // METIS failing, or memory
      err << "radx-engine: error: the partition over " << ranks << " ranks failed: " << e.what() << '\n';
      return 1;
    }
    source = ranks == 1 ? "one rank: every group on rank 0"
                        : "METIS k-way, seed " + std::to_string(par::kPartitionSeed);
  }
  print_table(summary, kept, source, root, out);

  std::vector<std::int32_t> cell_domain = par::cell_groups(m, groups);
  const std::vector<std::int32_t> cell_group = cell_domain;
  for (auto& c : cell_domain)
    if (c >= 0) c = group_rank[static_cast<std::size_t>(c)];
  std::error_code ec;
  fs::create_directories(out_dir, ec);
  const std::string domain_path = (fs::path(out_dir) / (root + "_domain.hdf")).string();
  const std::string ranks_path = (fs::path(out_dir) / (root + "_partition.txt")).string();
  try {
    io::write_domain_file(domain_path, m, cell_domain, cell_group, summary.node_owner);
  } catch (const std::exception& e) {
    err << "radx-engine: error: cannot write the decomposition: " << e.what() << '\n';
    return 1;
  }
  if (std::string error;
      !io::write_text_atomically(ranks_path, group_ranks_text(m, groups, group_rank, ranks, root), error)) {
    err << "radx-engine: error: " << error << '\n';
    return 1;
  }
  out << "wrote " << domain_path
      << " (cell arrays domain and group, point array node_owner: open it in ParaView)\n"
      << "wrote " << ranks_path << " (the group ranks; --partition reads them)\n";
  return 0;
}

}  // namespace radx::app
