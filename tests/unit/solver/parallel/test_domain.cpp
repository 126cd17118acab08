// The domain plan (solver/parallel/domain.hpp): node owners, ghost lists and the skyline of shared-node sums.
// All ranks are simulated in one process. The element sums assembled on P ranks, each node on its owner,
// must be the serial sums to the bit (docs/parallel-domain.md: the same additions in the same order), for
// P = 2, 3, 4 and two group splits, on sample decks with shells (4- and 3-node), bricks, tetrahedra,
// 20-node bricks, springs, trusses and beams, after a few cycles so the groups hold real forces.
#include <algorithm>
#include <bit>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "contact/type7_prepare.hpp"
#include "loopback_comm.hpp"
#include "solver/engine/explicit_engine.hpp"
#include "solver/parallel/domain.hpp"
#include "test_util.hpp"

namespace {

namespace par = radx::solver::parallel;
using radx::solver::ElementGroups;
using radx::solver::kGroupSize;

constexpr std::size_t kG = static_cast<std::size_t>(kGroupSize);

// The components each entry of a group carries, as the engine adds them: forces and moments for shells,
// beams and TYPE8/13 springs, forces alone for the rest (written here apart from the plan's own rule).
template <class Group>
std::size_t components_of(const Group& g) {
  using T = std::decay_t<Group>;
  if constexpr (std::is_same_v<T, radx::solver::ShellGroup> || std::is_same_v<T, radx::solver::BeamGroup>)
    return 6;
  else if constexpr (std::is_same_v<T, radx::solver::SpringGroup>)
    return static_cast<std::size_t>(g.node_stride());
  else
    return 3;
}

// The serial element sums: every group in flat order, element by element, node by node of the element,
// from zero ([node][fx fy fz mx my mz]).
std::vector<double> serial_sums(const ElementGroups& groups, std::size_t nodes) {
  std::vector<double> sums(6 * nodes, 0.0);
  groups.for_each([&](const auto& g) {
    const std::size_t C = components_of(g);
    for (std::size_t i = 0; i < static_cast<std::size_t>(g.count); ++i)
      for (std::size_t q = 0; q < static_cast<std::size_t>(g.nodes_per_element()); ++q)
        for (std::size_t d = 0; d < C; ++d)
          sums[6 * static_cast<std::size_t>(g.conn[q * kG + i]) + d] += g.nodal_force[(q * C + d) * kG + i];
  });
  return sums;
}

// For every node, how many entries each rank's groups have on it ([node][rank]).
std::vector<int> entries_per_rank(const ElementGroups& groups, const std::vector<std::int32_t>& group_rank,
                                  std::size_t nodes, int P) {
  std::vector<int> count(nodes * static_cast<std::size_t>(P), 0);
  std::size_t flat = 0;
  groups.for_each([&](const auto& g) {
    const auto r = static_cast<std::size_t>(group_rank[flat++]);
    for (std::size_t i = 0; i < static_cast<std::size_t>(g.count); ++i)
      for (std::size_t q = 0; q < static_cast<std::size_t>(g.nodes_per_element()); ++q)
        ++count[static_cast<std::size_t>(g.conn[q * kG + i]) * static_cast<std::size_t>(P) + r];
  });
  return count;
}

// A deck's model and a serial engine run for a few cycles: the groups' nodal_force buffers hold the forces
// of the last cycle.
struct RunSample {
  radx::model::Model model;
  radx::solver::ExplicitEngine engine;
  RunSample(radx::model::Model m, int cycles)
      : model(prepared(std::move(m))), engine(model, controls(), radx::solver::EngineOptions{1, 1}) {
    int n = 0;
    engine.run([&](const radx::solver::CycleReport&) { return ++n < cycles; });
  }
  static radx::model::Model prepared(radx::model::Model m) {
    radx::contact::prepare_type7_interfaces(m);  // the starter's TYPE7 gaps and search boxes
    return m;
  }
  static radx::model::RunControls controls() {
    radx::model::RunControls rc;
    rc.t_stop = 1.0;  // the run is stopped after a few cycles
    return rc;
  }
};

radx::model::Model deck_model(const std::string& deck) {
  std::ifstream in(std::string(RADX_SOURCE_DIR) + "/decks/" + deck);
  REQUIRE(in.good());
  std::stringstream text;
  text << in.rdbuf();
  return radx::test::model_of_deck(text.str());
}

// Two deterministic splits of the groups over P ranks (METIS comes from the partition step).
std::vector<std::int32_t> round_robin(std::int64_t groups, int P) {
  std::vector<std::int32_t> r(static_cast<std::size_t>(groups));
  for (std::int64_t k = 0; k < groups; ++k) r[static_cast<std::size_t>(k)] = static_cast<std::int32_t>(k % P);
  return r;
}
std::vector<std::int32_t> blocks(std::int64_t groups, int P) {
  std::vector<std::int32_t> r(static_cast<std::size_t>(groups));
  for (std::int64_t k = 0; k < groups; ++k)
    r[static_cast<std::size_t>(k)] = static_cast<std::int32_t>(k * P / groups);
  return r;
}

std::vector<par::DomainPlan> all_plans(const ElementGroups& groups,
                                       const std::vector<std::int32_t>& group_rank, std::int64_t nodes,
                                       int P) {
  std::vector<par::DomainPlan> plans;
  for (int r = 0; r < P; ++r) plans.push_back(par::build_domain_plan(groups, group_rank, nodes, P, r));
  return plans;
}

bool same_bits(const double* a, const double* b, std::size_t n) {
  return std::memcmp(a, b, n * sizeof(double)) == 0;
}

// The element stage and the skyline exchange of P simulated ranks: each rank's local sums and slots, its
// messages routed to their owners, the owners' sums. Returns each rank's element sums.
std::vector<std::vector<double>> assemble_on_ranks(const ElementGroups& groups,
                                                   const std::vector<par::DomainPlan>& plans,
                                                   std::size_t nodes) {
  const auto P = plans.size();
  std::vector<std::vector<double>> sums(P, std::vector<double>(6 * nodes, 0.0));
  std::vector<par::SharedSums> shared;
  shared.reserve(P);
  for (const auto& plan : plans) shared.emplace_back(plan);
  std::vector<std::vector<par::Buffer>> sent(P);
  for (std::size_t r = 0; r < P; ++r) {
    for (const std::int64_t flat : plans[r].groups)
      par::add_owned_group_sums(groups, plans[r], flat, sums[r], shared[r]);
    sent[r] = shared[r].pack();
  }
  for (std::size_t o = 0; o < P; ++o) {
    std::vector<par::Buffer> received(P);
    for (std::size_t s = 0; s < P; ++s) received[s] = sent[s][o];
    shared[o].sum_on_owner(received, sums[o]);
  }
  return sums;
}

// A mesh where every kind meets every other on shared nodes: a 16 x 10 x 2 block of bricks (10 mm), quad
// shells on its top face, triangles on part of its bottom face, tetrahedra over the bottom corner of another
// part, beams along a top edge, TYPE4 springs across the block's far side and TYPE13 springs between top
// nodes. Half the top face starts moving down at 10 m/s, so after a few cycles every element carries forces
// and moments.
std::string mixed_mesh_deck() {
  using radx::test::Line;
  constexpr int NX = 16, NY = 10, NZ = 2;
  const auto id = [](int i, int j, int k) { return 1 + i + (NX + 1) * (j + (NY + 1) * k); };
  const auto ints = [](std::initializer_list<int> v) {
    Line l;
    int c = 1;
    for (const int x : v) l.put(x, c, c + 9), c += 10;
    return l.str() + "\n";
  };
  std::string s = radx::test::begin_block(2026) + "/NODE\n";
  for (int k = 0; k <= NZ; ++k)
    for (int j = 0; j <= NY; ++j)
      for (int i = 0; i <= NX; ++i)
        s += Line()
                 .put(id(i, j, k), 1, 10)
                 .put(10.0 * i, 11, 30)
                 .put(10.0 * j, 31, 50)
                 .put(10.0 * k, 51, 70)
                 .str() +
             "\n";
  s += "/BRICK/1\n";
  int e = 1;
  for (int k = 0; k < NZ; ++k)
    for (int j = 0; j < NY; ++j)
      for (int i = 0; i < NX; ++i)
        s += ints({e++, id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1),
                   id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)});
  s += "/SHELL/2\n";
  e = 10001;
  for (int j = 0; j < NY; ++j)
    for (int i = 0; i < NX; ++i)
      s += ints({e++, id(i, j, NZ), id(i + 1, j, NZ), id(i + 1, j + 1, NZ), id(i, j + 1, NZ)});
  s += "/SH3N/2\n";
  e = 20001;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < NX; ++i) {
      s += ints({e++, id(i, j, 0), id(i + 1, j, 0), id(i + 1, j + 1, 0)});
      s += ints({e++, id(i, j, 0), id(i + 1, j + 1, 0), id(i, j + 1, 0)});
    }
  s += "/TETRA4/3\n";  // the orientation of FIELD_FORMS's tetrahedron: a, a + y, a + x, a + z
  e = 30001;
  for (int j = NY - 4; j < NY; ++j)
    for (int i = 0; i < NX; ++i) s += ints({e++, id(i, j, 0), id(i, j + 1, 0), id(i + 1, j, 0), id(i, j, 1)});
  s += "/BEAM/4\n";
  e = 40001;
  for (int i = 0; i < NX; ++i) s += ints({e++, id(i, 0, NZ), id(i + 1, 0, NZ), 0});
  s += "/SPRING/5\n";
  e = 50001;
  for (int i = 0; i <= NX; ++i) s += ints({e++, id(i, NY, 0), id(i, NY, NZ)});
  s += "/SPRING/6\n";
  e = 60001;
  for (int i = 0; i < NX; ++i) s += ints({e++, id(i, NY - 1, NZ), id(i + 1, NY, NZ)});
  s += R"(/PART/1
Block
         1         2         0                 0.0
/PART/2
Skin
         2         1         0                 0.0
/PART/3
Tetrahedra
         1         2         0                 0.0
/PART/4
Beams
         4         2         0                 0.0
/PART/5
TYPE4 springs
         5         0         0                 0.0
/PART/6
TYPE13 springs
         6         0         0                 0.0
/PROP/SOLID/1
Solid
         1         4         0         0         0         0         0         1                 0.0
                 0.0                 0.0                 0.0                 0.0                 0.0
                 0.0                 0.0                 0.0                 0.0                 0.0
/PROP/SHELL/2
Shell 1 mm
         1         2         2         0         0                           0.0
                 0.0                 0.0                 0.0                 0.0                 0.0
         5                           1.0                 0.0                   1         1         0
/PROP/BEAM/4
Square 10 mm
                   0
                 0.0                 0.0
               100.0   833.3333333333334   833.3333333333334              1406.0
   000 000         0
/PROP/SPRING/5
Spring by curve, slope 1000 N/mm
                1e-6
                 0.0                 0.0
         9         0
                 0.0
/FUNCT/9
Spring force of the elongation
              -100.0             -1.0e5
               100.0              1.0e5
/PROP/SPR_GENE/6
General spring K1 1000 N per mm; K2 250 N per mm; K4 2000 N mm per rad
                1e-6                2e-6         0         0         0         0         0         0
              1000.0
         0         0
                 0.0
               250.0
         0         0
                 0.0
                 0.0
         0         0
                 0.0
              2000.0
         0         0
                 0.0
                 0.0
         0         0
                 0.0
                 0.0
         0         0
                 0.0
         0
/MAT/PLAS_JOHNS/1
Steel (Johnson-Cook)
            7.85e-09
            210000.0                 0.3         0         0                 0.0
               250.0               450.0                 0.3                 0.0                 0.0
                 0.0                 0.0         0         0                 0.0                 0.0
                 0.0                 0.0                 0.0                 0.0                 0.0
/MAT/LAW1/2
Aluminium (elastic)
             2.7e-09
             70000.0                0.33
/GRNOD/NODE/1
Half the top face
)";
  std::vector<int> moving;
  for (int j = 0; j <= NY; ++j)
    for (int i = NX / 2; i <= NX; ++i) moving.push_back(id(i, j, NZ));
  for (std::size_t k = 0; k < moving.size(); k += 8) {
    Line l;
    for (std::size_t m = k; m < std::min(moving.size(), k + 8); ++m)
      l.put(moving[m], 1 + 10 * static_cast<int>(m - k), 10 + 10 * static_cast<int>(m - k));
    s += l.str() + "\n";
  }
  s += "/INIVEL/TRA/1\nmoving down\n" +
       Line().put(0.0, 1, 20).put(0.0, 21, 40).put(-1e4, 41, 60).put(1, 61, 70).str() + "\n/END\n";
  return s;
}

// Sample decks: each group kind alone (20-node bricks, trusses, beams, both springs) and several at once.
// Their parts mostly do not share nodes, so they check the local sums; the mixed mesh, the Taylor bar and the
// impact model share. Contact plays no part in the element sums (its forces have their own buffer).
const char* const kDecks[] = {
    "imposed_loads/IMPOSED_LOADS_0000.rad",          // bricks and shells, two parts each
    "field_forms/FIELD_FORMS_0000.rad",              // bricks, shells, 3-node shells, springs, tetrahedra
    "bric20_cantilever/BRIC20_CANTILEVER_0000.rad",  // 20-node bricks
    "spring_general/SPRING_GEN_0000.rad",            // TYPE13 springs on one node
    "truss_bar/TRUSS_BAR_0000.rad",                  // trusses
    "beam_cantilever/BEAM_CANTILEVER_0000.rad",      // beams
};

}  // namespace

TEST_CASE("shared-node sums assembled on their owners are the serial sums to the bit", "[parallel][domain]") {
  const auto check = [](const RunSample& run, const std::string& name) {
    const auto& groups = run.engine.groups();
    const std::size_t nodes = run.engine.nodes().n;
    const std::vector<double> ref = serial_sums(groups, nodes);
    std::int64_t shared_checked = 0;
    for (const int P : {2, 3, 4})
      for (const bool rr : {true, false}) {
        {
          INFO(name << " on " << P << " ranks, " << (rr ? "round robin" : "blocks"));
          const auto group_rank = rr ? round_robin(groups.count(), P) : blocks(groups.count(), P);
          const auto plans = all_plans(groups, group_rank, static_cast<std::int64_t>(nodes), P);
          const auto sums = assemble_on_ranks(groups, plans, nodes);
          std::int64_t wrong = 0, owned = 0;
          for (std::size_t r = 0; r < plans.size(); ++r)
            for (const auto& run_of : plans[r].owned_runs)
              for (auto n = static_cast<std::size_t>(run_of.first); n < static_cast<std::size_t>(run_of.last);
                   ++n) {
                ++owned;
                if (!same_bits(&sums[r][6 * n], &ref[6 * n], 6)) ++wrong;
              }
          CHECK(owned == static_cast<std::int64_t>(nodes));
          CHECK(wrong == 0);
          // The skyline carries real forces: shared nodes with a nonzero sum exist whenever groups are
          // split (otherwise a sum could match by being zero on both sides).
          for (const auto& plan : plans)
            for (const std::int32_t n : plan.shared_nodes)
              if (std::any_of(&ref[6 * static_cast<std::size_t>(n)],
                              &ref[6 * static_cast<std::size_t>(n) + 6], [](double v) { return v != 0.0; }))
                ++shared_checked;
        }
      }
    return shared_checked;
  };
  for (const char* deck : kDecks) check(RunSample(deck_model(deck), 4), deck);
  const RunSample mixed(radx::test::model_of_deck(mixed_mesh_deck()), 4);
  const auto& kinds = mixed.engine.groups();
  const auto has_spring = [&](int stride) {
    return std::any_of(kinds.springs.begin(), kinds.springs.end(),
                       [&](const auto& g) { return g.node_stride() == stride; });
  };
  REQUIRE(std::any_of(kinds.shells.begin(), kinds.shells.end(), [](const auto& g) { return g.triangle; }));
  REQUIRE(std::any_of(kinds.shells.begin(), kinds.shells.end(), [](const auto& g) { return !g.triangle; }));
  REQUIRE((!kinds.bricks.empty() && !kinds.tetras.empty() && !kinds.beams.empty()));
  REQUIRE((has_spring(3) && has_spring(6)));
  CHECK(check(mixed, "mixed mesh") > 0);
  CHECK(check(RunSample(deck_model("taylor_bar/TAYLOR_BAR_0000.rad"), 4), "taylor bar") > 0);
  // The impact benchmark's plate and block: many groups, 128 x 1 strips, so most nodes are shared.
  radx::test::TempDir dir;
  const RunSample impact(radx::test::impact_benchmark_model(dir, 24), 3);
  CHECK(check(impact, "impact N = 24") > 0);
}

TEST_CASE("node owners, owned runs, ghost lists and skyline slots are consistent over all ranks",
          "[parallel][domain]") {
  for (const std::string deck :
       {"mixed mesh", "field_forms/FIELD_FORMS_0000.rad", "taylor_bar/TAYLOR_BAR_0000.rad"}) {
    const RunSample run(
        deck == "mixed mesh" ? radx::test::model_of_deck(mixed_mesh_deck()) : deck_model(deck), 1);
    const auto& groups = run.engine.groups();
    const std::size_t nodes = run.engine.nodes().n;
    for (const int P : {2, 3, 4}) {
      {
        INFO(deck << " on " << P << " ranks");
        const auto group_rank = round_robin(groups.count(), P);
        const auto plans = all_plans(groups, group_rank, static_cast<std::int64_t>(nodes), P);
        const auto owner = par::node_owner_ranks(groups, group_rank, static_cast<std::int64_t>(nodes), P);
        const auto count = entries_per_rank(groups, group_rank, nodes, P);
        const auto touches = [&](std::size_t n, int r) {
          return count[n * static_cast<std::size_t>(P) + r] > 0;
        };

        // Owners: the rank with the most entries, the lowest on ties; rank 0 for untouched nodes. The owned
        // runs of all ranks cover every node exactly once, each on its owner.
        std::vector<int> owned_by(nodes, 0);
        for (int r = 0; r < P; ++r) {
          std::int64_t in_runs = 0;
          for (const auto& run_of : plans[static_cast<std::size_t>(r)].owned_runs)
            for (auto n = run_of.first; n < run_of.last; ++n) {
              ++owned_by[static_cast<std::size_t>(n)];
              ++in_runs;
              CHECK(owner[static_cast<std::size_t>(n)] == r);
            }
          CHECK(in_runs == plans[static_cast<std::size_t>(r)].owned_nodes);
        }
        CHECK(std::all_of(owned_by.begin(), owned_by.end(), [](int k) { return k == 1; }));
        for (std::size_t n = 0; n < nodes; ++n) {
          int best = 0;
          for (int r = 1; r < P; ++r)
            if (count[n * static_cast<std::size_t>(P) + r] > count[n * static_cast<std::size_t>(P) + best])
              best = r;
          CHECK(owner[n] == best);
          const bool touched = std::any_of(count.begin() + static_cast<std::ptrdiff_t>(n * P),
                                           count.begin() + static_cast<std::ptrdiff_t>((n + 1) * P),
                                           [](int k) { return k > 0; });
          if (touched) CHECK(touches(n, owner[n]));
        }

        // Ghosts: what A sends B is what B receives from A, node for node and rotation for rotation; a
        // rank's ghosts are exactly the nodes its groups touch and another rank owns.
        for (int a = 0; a < P; ++a) {
          const auto& pa = plans[static_cast<std::size_t>(a)];
          std::set<std::int32_t> ghosts;
          for (int b = 0; b < P; ++b) {
            const auto& pb = plans[static_cast<std::size_t>(b)];
            const auto sa = static_cast<std::size_t>(pa.send_begin[static_cast<std::size_t>(b)]);
            const auto ea = static_cast<std::size_t>(pa.send_begin[static_cast<std::size_t>(b) + 1]);
            const auto sb = static_cast<std::size_t>(pb.ghost_begin[static_cast<std::size_t>(a)]);
            const auto eb = static_cast<std::size_t>(pb.ghost_begin[static_cast<std::size_t>(a) + 1]);
            REQUIRE(ea - sa == eb - sb);
            CHECK(std::equal(pa.send_nodes.begin() + static_cast<std::ptrdiff_t>(sa),
                             pa.send_nodes.begin() + static_cast<std::ptrdiff_t>(ea),
                             pb.ghost_nodes.begin() + static_cast<std::ptrdiff_t>(sb)));
            CHECK(std::equal(pa.send_rotation.begin() + static_cast<std::ptrdiff_t>(sa),
                             pa.send_rotation.begin() + static_cast<std::ptrdiff_t>(ea),
                             pb.ghost_rotation.begin() + static_cast<std::ptrdiff_t>(sb)));
            CHECK(std::is_sorted(pa.send_nodes.begin() + static_cast<std::ptrdiff_t>(sa),
                                 pa.send_nodes.begin() + static_cast<std::ptrdiff_t>(ea)));
            for (auto k = static_cast<std::size_t>(pa.ghost_begin[static_cast<std::size_t>(b)]);
                 k < static_cast<std::size_t>(pa.ghost_begin[static_cast<std::size_t>(b) + 1]); ++k) {
              CHECK(owner[static_cast<std::size_t>(pa.ghost_nodes[k])] == b);
              ghosts.insert(pa.ghost_nodes[k]);
            }
          }
          std::set<std::int32_t> expected;
          for (std::size_t n = 0; n < nodes; ++n)
            if (touches(n, a) && owner[n] != a) expected.insert(static_cast<std::int32_t>(n));
          CHECK(ghosts == expected);
        }

        // Groups and entries: the ranks' groups partition the groups; every entry on a shared node has one
        // slot, and the slots an owner expects from each sender tile that sender's message to it exactly.
        std::vector<int> group_seen(static_cast<std::size_t>(groups.count()), 0);
        for (const auto& p : plans)
          for (const auto flat : p.groups) ++group_seen[static_cast<std::size_t>(flat)];
        CHECK(std::all_of(group_seen.begin(), group_seen.end(), [](int k) { return k == 1; }));
        std::int64_t shared_entries = 0, contributions = 0;
        for (std::size_t n = 0; n < nodes; ++n) {
          int ranks_on = 0, entries = 0;
          for (int r = 0; r < P; ++r) {
            ranks_on += touches(n, r) ? 1 : 0;
            entries += count[n * static_cast<std::size_t>(P) + static_cast<std::size_t>(r)];
          }
          if (ranks_on > 1) shared_entries += entries;
        }
        for (std::size_t o = 0; o < plans.size(); ++o) {
          contributions += static_cast<std::int64_t>(plans[o].contributions.size());
          for (std::size_t s = 0; s < plans.size(); ++s) {
            const std::int64_t size = plans[s].message_begin[o + 1] - plans[s].message_begin[o];
            CHECK(plans[o].expected_from[s] == size);
            std::vector<int> cover(static_cast<std::size_t>(size), 0);
            for (const auto& c : plans[o].contributions)
              if (c.source == static_cast<std::int32_t>(s))
                for (int d = 0; d < c.components; ++d) ++cover[static_cast<std::size_t>(c.offset + d)];
            CHECK(std::all_of(cover.begin(), cover.end(), [](int k) { return k == 1; }));
          }
        }
        std::int64_t slots = 0;
        for (const auto& p : plans) slots += static_cast<std::int64_t>(p.shared_entry_code.size());
        CHECK(contributions == shared_entries);
        CHECK(slots == shared_entries);
      }
    }
  }
}

TEST_CASE("through a communicator, owners get the serial sums and ghosts the owners' x, v and omega",
          "[parallel][domain]") {
  const RunSample run(radx::test::model_of_deck(mixed_mesh_deck()), 4);
  const auto& groups = run.engine.groups();
  const auto& serial_nodes = run.engine.nodes();
  const std::size_t nodes = serial_nodes.n;
  const std::vector<double> ref = serial_sums(groups, nodes);
  constexpr int P = 3;
  const auto group_rank = blocks(groups.count(), P);
  const auto plans = all_plans(groups, group_rank, static_cast<std::int64_t>(nodes), P);
  REQUIRE(groups.count() >= P);

  // Each rank's node state: its owned nodes hold the serial values, every other entry NaN, so a ghost the
  // update misses (or fills from the wrong place) shows.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<radx::solver::NodeState> state(P);
  std::vector<std::vector<double>> sums(P, std::vector<double>(6 * nodes, 0.0));
  for (int r = 0; r < P; ++r) {
    auto& s = state[static_cast<std::size_t>(r)];
    s.resize(nodes);
    for (auto* a : {&s.x, &s.y, &s.z, &s.vx, &s.vy, &s.vz, &s.wx, &s.wy, &s.wz})
      std::fill(a->begin(), a->end(), nan);
    for (const auto& run_of : plans[static_cast<std::size_t>(r)].owned_runs)
      for (auto n = static_cast<std::size_t>(run_of.first); n < static_cast<std::size_t>(run_of.last); ++n) {
        s.x[n] = serial_nodes.x[n], s.y[n] = serial_nodes.y[n], s.z[n] = serial_nodes.z[n];
        s.vx[n] = serial_nodes.vx[n], s.vy[n] = serial_nodes.vy[n], s.vz[n] = serial_nodes.vz[n];
        s.wx[n] = serial_nodes.wx[n], s.wy[n] = serial_nodes.wy[n], s.wz[n] = serial_nodes.wz[n];
      }
  }
  radx::test::run_ranks(P, [&](par::Comm& comm) {
    const auto k = static_cast<std::size_t>(comm.rank());
    par::SharedSums shared(plans[k]);
    for (const std::int64_t flat : plans[k].groups)
      par::add_owned_group_sums(groups, plans[k], flat, sums[k], shared);
    par::exchange_shared_sums(shared, comm, sums[k]);
    par::exchange_ghosts(plans[k], comm, state[k]);
  });

  std::int64_t wrong_sums = 0, wrong_ghosts = 0, ghosts = 0, rotations = 0;
  for (std::size_t r = 0; r < static_cast<std::size_t>(P); ++r) {
    for (const auto& run_of : plans[r].owned_runs)
      for (auto n = static_cast<std::size_t>(run_of.first); n < static_cast<std::size_t>(run_of.last); ++n)
        if (!same_bits(&sums[r][6 * n], &ref[6 * n], 6)) ++wrong_sums;
    const auto& s = state[r];
    for (std::size_t k = 0; k < plans[r].ghost_nodes.size(); ++k) {
      const auto n = static_cast<std::size_t>(plans[r].ghost_nodes[k]);
      ++ghosts;
      const double got[] = {s.x[n], s.y[n], s.z[n], s.vx[n], s.vy[n], s.vz[n]};
      const double want[] = {serial_nodes.x[n],  serial_nodes.y[n],  serial_nodes.z[n],
                             serial_nodes.vx[n], serial_nodes.vy[n], serial_nodes.vz[n]};
      if (!same_bits(got, want, 6)) ++wrong_ghosts;
      if (plans[r].ghost_rotation[k] != 0) {
        ++rotations;
        const double w[] = {s.wx[n], s.wy[n], s.wz[n]};
        const double w_want[] = {serial_nodes.wx[n], serial_nodes.wy[n], serial_nodes.wz[n]};
        if (!same_bits(w, w_want, 3)) ++wrong_ghosts;
      } else if (!std::isnan(s.wx[n])) {
        ++wrong_ghosts;  // a node without rotations ships no omega
      }
    }
    // Nodes neither owned nor ghost are left alone.
    std::vector<std::uint8_t> live(nodes, 0);
    for (const auto& run_of : plans[r].owned_runs)
      for (auto n = run_of.first; n < run_of.last; ++n) live[static_cast<std::size_t>(n)] = 1;
    for (const std::int32_t n : plans[r].ghost_nodes) live[static_cast<std::size_t>(n)] = 1;
    for (std::size_t n = 0; n < nodes; ++n)
      if (live[n] == 0) CHECK(std::isnan(s.x[n]));
  }
  CHECK(wrong_sums == 0);
  CHECK(wrong_ghosts == 0);
  CHECK(ghosts > 0);
  CHECK(rotations > 0);
}

TEST_CASE("a bad group rank or a message of the wrong size is refused", "[parallel][domain]") {
  const RunSample run(deck_model("taylor_bar/TAYLOR_BAR_0000.rad"), 1);
  const auto& groups = run.engine.groups();
  const auto nodes = static_cast<std::int64_t>(run.engine.nodes().n);
  auto group_rank = round_robin(groups.count(), 2);
  group_rank[1] = 2;
  CHECK_THROWS_WITH(par::build_domain_plan(groups, group_rank, nodes, 2, 0),
                    Catch::Contains("group 1 has rank 2, outside [0, 2)"));
  CHECK_THROWS_AS(par::build_domain_plan(groups, round_robin(groups.count(), 2), nodes, 2, 2),
                  std::invalid_argument);
  const auto plan = par::build_domain_plan(groups, round_robin(groups.count(), 2), nodes, 2, 0);
  REQUIRE(plan.expected_from[1] > 0);
  par::SharedSums shared(plan);
  std::vector<double> sums(6 * static_cast<std::size_t>(nodes), 0.0);
  std::vector<par::Buffer> received(2);
  received[0] = shared.pack()[0];
  received[1].resize(8);
  CHECK_THROWS_WITH(shared.sum_on_owner(received, sums),
                    Catch::Contains("shared-sum message from rank 1 has 8 bytes"));
}
