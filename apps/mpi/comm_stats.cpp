#include "apps/mpi/comm_stats.hpp"

#include <cstdio>
#include <string>

namespace radx::app {

std::string_view comm_kind_name(CommKind kind) {
  switch (kind) {
    case CommKind::kVote: return "vote";
    case CommKind::kMax: return "max";
    case CommKind::kSumExact: return "sum_exact";
    case CommKind::kBitOr: return "bit_or";
    case CommKind::kExchange: return "exchange";
    case CommKind::kGather: return "gather";
    case CommKind::kAllGather: return "all_gather";
    case CommKind::kBroadcast: return "broadcast";
    case CommKind::kBarrier: return "barrier";
  }
  return "?";
}

CommCounts CommStats::total() const {
  CommCounts t;
  for (const auto& k : kinds) {
    t.calls += k.calls;
    t.messages += k.messages;
    t.bytes_sent += k.bytes_sent;
    t.bytes_received += k.bytes_received;
    t.seconds += k.seconds;
  }
  return t;
}

namespace {

void print_row(std::ostream& os, int rank, std::string_view kind, const CommCounts& c) {
  char line[200];
  std::snprintf(line, sizeof line, "| %4d | %-10.*s | %10lld | %10lld | %14lld | %14lld | %10.4f |\n", rank,
                static_cast<int>(kind.size()), kind.data(), static_cast<long long>(c.calls),
                static_cast<long long>(c.messages), static_cast<long long>(c.bytes_sent),
                static_cast<long long>(c.bytes_received), c.seconds);
  os << line;
}

}  // namespace

void print_comm_stats(std::ostream& os, const std::vector<RankCommStats>& ranks) {
  os << "\nMPI communication per rank (--comm-stats; seconds inside MPI: transfer and wait)\n\n"
        "| rank | collective |      calls |   messages |     bytes sent | bytes received |    seconds |\n"
        "|-----:|------------|-----------:|-----------:|---------------:|---------------:|-----------:|\n";
  for (const auto& r : ranks) {
    for (int k = 0; k < kCommKinds; ++k) {
      const auto kind = static_cast<CommKind>(k);
      if (r.stats[kind].calls > 0) print_row(os, r.rank, comm_kind_name(kind), r.stats[kind]);
    }
    print_row(os, r.rank, "total", r.stats.total());
  }
  os << '\n';
  for (const auto& r : ranks) {
    const double mpi = r.stats.total().seconds;
    char line[160];
    std::snprintf(line, sizeof line, "rank %d: wall %.3f s, inside MPI %.3f s (%.2f %% of wall)\n", r.rank,
                  r.wall_seconds, mpi, r.wall_seconds > 0 ? 100.0 * mpi / r.wall_seconds : 0.0);
    os << line;
  }
}

}  // namespace radx::app
