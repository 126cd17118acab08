// The engine's thread team (solver/engine/thread_team.hpp): every chunk runs exactly once whatever the team
// size, chunk boundaries do not depend on the thread count, and a run of the impact benchmark's model
// (shells, bricks, two TYPE7 interfaces; large enough that every stage runs in parallel) is bit-identical on
// 1, 2 and 3 threads (docs/architecture.md section 3: a deterministic scatter, results independent of the
// thread count).
#include <array>
#include <atomic>
#include <catch2/catch.hpp>
#include <chrono>
#include <set>
#include <thread>
#include <utility>
#include <vector>

#include "contact/type7_prepare.hpp"
#include "parser/building/build_run_controls.hpp"
#include "solver/engine/explicit_engine.hpp"
#include "solver/engine/ordered_commit.hpp"
#include "solver/engine/thread_team.hpp"
#include "test_util.hpp"

using radx::solver::Chunks;
using radx::solver::OrderedCommit;
using radx::solver::ThreadTeam;

TEST_CASE("chunks cover the items once, with boundaries that depend only on the item count", "[threads]") {
  for (const std::int64_t n : {0, 1, 5, 2047, 2048, 2049, 10000}) {
    const auto c = Chunks::of(n, 2048);
    std::int64_t covered = 0, expect_begin = 0;
    for (std::int64_t k = 0; k < c.count(); ++k) {
      CHECK(c.begin(k) == expect_begin);
      CHECK(c.end(k) > c.begin(k));
      CHECK(c.end(k) - c.begin(k) <= 2048);
      covered += c.end(k) - c.begin(k);
      expect_begin = c.end(k);
    }
    CHECK(covered == n);
  }
}

TEST_CASE("the threads' lanes partition a stage into equal blocks in order", "[threads]") {
  // Each thread takes its lane first, so a lane must hold each chunk once, and the lane a chunk lands in
  // must depend only on the chunk, the chunk count and the thread count (a chunk then runs on the same thread
  // every time the stage is posted, where its data already is). That a thread does start with its own lane
  // is a matter of speed, not of results, and is not asserted here (it would depend on timing).
  for (const std::int64_t lanes : {1, 2, 3, 5})
    for (const std::int64_t chunks : {0, 1, 2, 3, 4, 7, 64, 339}) {
      std::int64_t next = 0;
      for (std::int64_t k = 0; k < lanes; ++k) {
        const auto s = ThreadTeam::share(chunks, lanes, k);
        CHECK(s.first == next);  // lane k's block follows lane k - 1's: together they cover [0, chunks) once
        // Shares differ by at most one chunk: an equal split.
        CHECK(s.count >= chunks / lanes);
        CHECK(s.count <= chunks / lanes + 1);
        next = s.first + s.count;
      }
      CHECK(next == chunks);
    }
}

TEST_CASE("a team runs every chunk of every stage exactly once", "[threads]") {
  // Many short stages back to back exercise the hand-over between stages (a worker that misses a stage or
  // runs a chunk twice would show as a count other than 1).
  for (const int threads : {1, 2, 3, 8}) {
    ThreadTeam team(threads);
    CHECK(team.size() == threads);
    for (const std::int64_t chunks : {1, 2, 7, 64, 1000}) {
      std::vector<std::atomic<int>> runs(static_cast<std::size_t>(chunks));
      for (int stage = 0; stage < 200; ++stage)
        team.run(chunks, [&](std::int64_t c) { ++runs[static_cast<std::size_t>(c)]; });
      for (const auto& r : runs) REQUIRE(r.load() == 200);
    }
    // Sequential fallback: in chunk order on the calling thread.
    std::vector<std::int64_t> order;
    team.run(
        5, [&](std::int64_t c) { order.push_back(c); }, false);
    CHECK(order == std::vector<std::int64_t>{0, 1, 2, 3, 4});
  }
}

TEST_CASE("a stage's writes are all visible to the caller when run() returns, from every thread",
          "[threads]") {
  // Chunks that sleep for a millisecond keep every thread of the team busy at once: run() returning before
  // the last chunk finishes would leave old values behind, and only one thread id would mean no parallelism.
  ThreadTeam team(2);
  std::vector<double> out(16 * 1000, 0.0);
  const auto chunks = Chunks::of(static_cast<std::int64_t>(out.size()), 1000);
  std::vector<std::thread::id> who(static_cast<std::size_t>(chunks.count()));
  std::set<std::thread::id> threads_seen;
  for (int stage = 1; stage <= 10; ++stage) {
    team.run(chunks.count(), [&](std::int64_t c) {
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
      for (auto i = chunks.begin(c); i < chunks.end(c); ++i) out[static_cast<std::size_t>(i)] = stage;
      who[static_cast<std::size_t>(c)] = std::this_thread::get_id();
    });
    for (const double v : out) REQUIRE(v == stage);
    threads_seen.insert(who.begin(), who.end());
  }
  CHECK(threads_seen.size() == 2);
}

TEST_CASE("items finished in any order are committed once each, in item order", "[threads]") {
  // On one thread, finished in reverse: nothing can be committed before item 0, then everything at once.
  OrderedCommit order;
  order.assign(6);
  std::vector<std::int64_t> committed;
  const auto commit = [&](std::int64_t k, std::int32_t) { committed.push_back(k); };
  for (std::int64_t k = 5; k >= 1; --k) {
    order.finished(k, commit);
    CHECK(committed.empty());
  }
  order.finished(0, commit);
  CHECK(committed == std::vector<std::int64_t>{0, 1, 2, 3, 4, 5});
  // Out of order: 1, 0 (commits 0 and 1), 3 (waits for 2), 2 (commits 2 and 3).
  order.reset();
  committed.clear();
  order.finished(1, commit);
  order.finished(0, commit);
  CHECK(committed == std::vector<std::int64_t>{0, 1});
  order.finished(3, commit);
  CHECK(order.committed() == 2);
  order.finished(2, commit);
  order.drain(commit);
  CHECK(committed == std::vector<std::int64_t>{0, 1, 2, 3});
}

TEST_CASE("items writing into different regions are committed independently, each region in item order",
          "[threads]") {
  // Items 0 and 1 write into region 0, item 2 into regions 0 and 1, item 3 into region 1 alone.
  OrderedCommit order;
  order.assign({{0}, {0}, {0, 1}, {1}}, 2);
  CHECK(order.parts() == 5);
  CHECK(order.regions_of(2).size() == 2);
  std::vector<std::pair<std::int64_t, std::int32_t>> committed;  // (item, region)
  const auto commit = [&](std::int64_t k, std::int32_t slot) {
    committed.emplace_back(k, order.regions_of(k)[static_cast<std::size_t>(slot)]);
  };
  // Item 3 waits for item 2, the only earlier item in region 1.
  order.finished(3, commit);
  CHECK(committed.empty());
  // Item 2 commits into region 1 at once (then item 3 follows), but not into region 0 before items 0, 1.
  order.finished(2, commit);
  using P = std::pair<std::int64_t, std::int32_t>;
  CHECK(committed == std::vector<P>{{2, 1}, {3, 1}});
  order.finished(1, commit);
  CHECK(committed.size() == 2);
  order.finished(0, commit);
  CHECK(committed == std::vector<P>{{2, 1}, {3, 1}, {0, 0}, {1, 0}, {2, 0}});
  CHECK(order.committed() == order.parts());
}

TEST_CASE("a team's threads commit every item in item order, one committer at a time", "[threads]") {
  // Items of uneven length (some sleep) make the threads finish out of order and race for the commit; the
  // commit itself checks that no other commit runs beside it. drain() after the stage must find the rest.
  for (const int threads : {2, 3}) {
    ThreadTeam team(threads);
    constexpr std::int64_t kItems = 400;
    OrderedCommit order;
    order.assign(kItems);
    std::vector<std::int64_t> committed;
    std::atomic<int> inside{0};
    std::atomic<bool> overlapped{false};
    const auto commit = [&](std::int64_t k, std::int32_t) {
      if (inside.fetch_add(1) != 0) overlapped = true;
      committed.push_back(k);
      inside.fetch_sub(1);
    };
    for (int stage = 0; stage < 20; ++stage) {
      order.reset();
      committed.clear();
      team.run(kItems, [&](std::int64_t k) {
        if ((k * 7 + stage) % 13 == 0) std::this_thread::sleep_for(std::chrono::microseconds(200));
        order.finished(k, commit);
      });
      // Every item was committed inside the stage: a finished item is never left behind (drain() would
      // hide a lost commit, so it is checked before it).
      REQUIRE(order.committed() == kItems);
      order.drain(commit);
      REQUIRE(committed.size() == static_cast<std::size_t>(kItems));
      for (std::int64_t k = 0; k < kItems; ++k) REQUIRE(committed[static_cast<std::size_t>(k)] == k);
    }
    CHECK_FALSE(overlapped.load());
  }
}

TEST_CASE("a team's threads commit every region's items in item order, one committer per region at a time",
          "[threads]") {
  // 400 items over 7 regions, like element groups over node chunks: item k writes into region k / 60 and,
  // every fifth item, into the next one too. Each region's commits must come in item order, none
  // overlapping another of the same region; the threads run blocks of items, as in the element stage, so
  // whole regions are committed by the thread whose block they lie in.
  constexpr std::int64_t kItems = 400;
  constexpr std::int32_t kRegions = 7;
  std::vector<std::vector<std::int32_t>> regions(kItems);
  for (std::int64_t k = 0; k < kItems; ++k) {
    const auto r = static_cast<std::int32_t>(k / 60);
    regions[static_cast<std::size_t>(k)].push_back(r);
    if (k % 5 == 0 && r + 1 < kRegions) regions[static_cast<std::size_t>(k)].push_back(r + 1);
  }
  for (const int threads : {2, 3}) {
    ThreadTeam team(threads);
    OrderedCommit order;
    order.assign(regions, kRegions);
    std::vector<std::vector<std::int64_t>> committed(kRegions);
    std::vector<std::atomic<int>> inside(kRegions);
    std::atomic<bool> overlapped{false};
    const auto commit = [&](std::int64_t k, std::int32_t slot) {
      const auto r = static_cast<std::size_t>(order.regions_of(k)[static_cast<std::size_t>(slot)]);
      if (inside[r].fetch_add(1) != 0) overlapped = true;
      committed[r].push_back(k);
      inside[r].fetch_sub(1);
    };
    for (int stage = 0; stage < 20; ++stage) {
      order.reset();
      for (auto& c : committed) c.clear();
      team.run(kItems, [&](std::int64_t k) {
        if ((k * 7 + stage) % 13 == 0) std::this_thread::sleep_for(std::chrono::microseconds(200));
        order.finished(k, commit);
      });
      REQUIRE(order.committed() == order.parts());  // inside the stage, before drain() could make up for it
      order.drain(commit);
      for (std::int32_t r = 0; r < kRegions; ++r) {
        std::vector<std::int64_t> expect;
        for (std::int64_t k = 0; k < kItems; ++k)
          for (const auto rr : regions[static_cast<std::size_t>(k)])
            if (rr == r) expect.push_back(k);
        REQUIRE(committed[static_cast<std::size_t>(r)] == expect);
      }
    }
    CHECK_FALSE(overlapped.load());
  }
}

namespace {

struct RunOutcome {
  radx::solver::HugeVector<double> x, y, z, vx, vy, vz;
  radx::solver::EnergyBalance energy;
  std::int64_t cycles = 0;
};

// The impact benchmark at N = 70 (4,900 Johnson-Cook shells, 5,041 plate nodes; a 10 x 10 x 4 brick block;
// two TYPE7), run to 2e-4 s on `threads` threads with the benchmark's engine controls.
RunOutcome run_impact(const radx::model::Model& m, radx::model::RunControls rc, int threads) {
  rc.t_stop = 2e-4;  // about 80 cycles of the 14.3 mm shells' step; contact starts at 1e-4 s (1 mm at 10 m/s)
  radx::solver::ExplicitEngine engine(m, rc, radx::solver::EngineOptions{threads, 1});
  const auto res = engine.run([](const radx::solver::CycleReport&) { return true; });
  REQUIRE(res.status == radx::solver::RunStatus::Normal);
  REQUIRE(res.threads == threads);
  const auto& s = engine.nodes();
  return RunOutcome{s.x, s.y, s.z, s.vx, s.vy, s.vz, res.last.energy, res.cycles};
}

// The impact benchmark's deck at N = 70 (gen_shell_plate.py --impact), read as the starter would (TYPE7
// gaps and search boxes prepared), with its engine controls.
struct ImpactDeck {
  radx::model::Model model;
  radx::model::RunControls controls;
};
ImpactDeck impact_deck() {
  radx::test::TempDir dir;
  ImpactDeck deck{radx::test::impact_benchmark_model(dir, 70), {}};
  radx::contact::prepare_type7_interfaces(deck.model);  // the starter's gaps and search boxes
  radx::Diagnostics d;
  deck.controls = radx::read_run_controls(dir.file("PLATE70I_0001.rad"), d);
  REQUIRE_FALSE(d.has_errors());
  return deck;
}

}  // namespace

TEST_CASE("the impact model runs bit-identically on 1, 2 and 3 threads", "[threads][engine]") {
  const auto deck = impact_deck();
  const auto& m = deck.model;
  const auto& rc = deck.controls;
  // Every stage must be parallel for the test to mean anything: more than 8 groups, two node chunks.
  REQUIRE(m.nodes.size() >= 4096);
  const auto one = run_impact(m, rc, 1);
  // Contact has started: the block (10 m/s, 1 mm above the plate) has moved twice the gap by 2e-4 s.
  // More than 1 % of the block's energy is in the plate's strain (about 6 % at 2e-4 s), so the contact and
  // plasticity paths ran under test.
  const double total = one.energy.kinetic_t + one.energy.internal + one.energy.contact_elastic;
  REQUIRE(one.energy.internal > 0.01 * total);
  for (const int threads : {2, 3}) {
    const auto other = run_impact(m, rc, threads);
    CHECK(other.cycles == one.cycles);
    // Bit-identical: == on doubles, no tolerance.
    CHECK(other.x == one.x);
    CHECK(other.y == one.y);
    CHECK(other.z == one.z);
    CHECK(other.vx == one.vx);
    CHECK(other.vy == one.vy);
    CHECK(other.vz == one.vz);
    CHECK(other.energy.internal == one.energy.internal);
    CHECK(other.energy.kinetic_t == one.energy.kinetic_t);
    CHECK(other.energy.contact_elastic == one.energy.contact_elastic);
  }
}

TEST_CASE("each node's element sum is made in group, element, node-of-element order across node chunks",
          "[threads][engine]") {
  // The sums are committed node chunk by node chunk (2,048 nodes each), a group reaching into several chunks
  // by its entries listed per chunk. Whatever the split, each node's sum must be the plain loop's: start from
  // +0, add every group's entries in group order (shells, then bricks), element by element, node by node of
  // the element. The impact model (5,041 plate nodes, then the block's: three chunks, shell groups across
  // their boundaries, bricks in the last), run until the block has hit the plate: after the last cycle
  // (which does not integrate) f = (f_ext + that sum) + the contact force for every node (contact adds its
  // forces after the assembly; zero where it has none), compared with ==.
  auto deck = impact_deck();
  const auto& m = deck.model;
  auto& rc = deck.controls;
  rc.t_stop = 2e-4;  // contact starts at 1e-4 s (1 mm at 10 m/s)
  REQUIRE(m.nodes.size() > 2 * 2048);
  for (const int threads : {1, 2}) {
    radx::solver::ExplicitEngine engine(m, rc, radx::solver::EngineOptions{threads, 1});
    const auto res = engine.run([](const radx::solver::CycleReport&) { return true; });
    REQUIRE(res.status == radx::solver::RunStatus::Normal);
    const auto& s = engine.nodes();
    std::vector<std::array<double, 6>> sum(s.n, std::array<double, 6>{});
    constexpr std::size_t G = radx::solver::kGroupSize;
    const auto add = [&](const auto& g, std::size_t nodes_per_element, std::size_t components) {
      for (std::size_t i = 0; i < static_cast<std::size_t>(g.count); ++i)
        for (std::size_t q = 0; q < nodes_per_element; ++q)
          for (std::size_t c = 0; c < components; ++c)
            sum[static_cast<std::size_t>(g.conn[q * G + i])][c] +=
                g.nodal_force[(q * components + c) * G + i];
    };
    for (const auto& g : engine.groups().shells) add(g, g.triangle ? 3 : 4, 6);
    for (const auto& g : engine.groups().bricks) add(g, 8, 3);
    REQUIRE(engine.groups().tetras.empty());
    REQUIRE(engine.groups().springs.empty());
    std::size_t crossing = 0;  // shell groups reaching into two node chunks: the listed entries' path
    for (const auto& g : engine.groups().shells) {
      std::set<int> chunks;
      for (std::size_t i = 0; i < static_cast<std::size_t>(g.count); ++i)
        for (std::size_t q = 0; q < 4; ++q) chunks.insert(g.conn[q * G + i] / 2048);
      crossing += chunks.size() > 1 ? 1 : 0;
    }
    REQUIRE(crossing > 0);
    REQUIRE(engine.contact() != nullptr);
    const auto& contact_force = engine.contact()->force();
    std::size_t loaded = 0;
    for (std::size_t n = 0; n < s.n; ++n) {
      REQUIRE(s.fx[n] == (s.fx_ext[n] + sum[n][0]) + contact_force[3 * n]);
      REQUIRE(s.fy[n] == (s.fy_ext[n] + sum[n][1]) + contact_force[3 * n + 1]);
      REQUIRE(s.fz[n] == (s.fz_ext[n] + sum[n][2]) + contact_force[3 * n + 2]);
      REQUIRE(s.mx[n] == sum[n][3]);  // no external moments in this model
      REQUIRE(s.my[n] == sum[n][4]);
      REQUIRE(s.mz[n] == sum[n][5]);
      loaded += sum[n][3] != 0.0 ? 1 : 0;
    }
    CHECK(loaded > s.n / 2);  // not a comparison of zeros: most nodes carry element moments
  }
}
