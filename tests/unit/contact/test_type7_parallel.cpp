// TYPE7 contact on the engine's threads (contact/parallel_for.hpp): the search's displacement test and
// every secondary node's closest segment run in chunks fixed by the model and the candidate list, so the
// forces, touched nodes, time-step vote, energies, results and messages of a cycle must be == to those of
// the serial code for any order in which the chunks run. Order independence is shown without thread timing:
// a ParallelFor that runs the chunks in reverse; then one that runs them on two real threads.
#include <atomic>
#include <catch2/catch.hpp>
#include <cmath>
#include <thread>
#include <vector>

#include "contact/type7_engine.hpp"
#include "contact/type7_prepare.hpp"
#include "test_util.hpp"

namespace {

using radx::contact::ChunkBody;

// The node state one contact sees; each contact gets its own (compute may release IBC bits or add mass).
struct State {
  std::vector<double> x, y, z, vx, vy, vz, mass, added;
  std::vector<std::uint8_t> fixed;
  radx::contact::ContactNodes view() { return {x, y, z, vx, vy, vz, mass, added, fixed, {}}; }
};

// What one cycle of contact returns, compared with ==.
struct CycleOut {
  radx::contact::ContactStep step;
  std::vector<std::int32_t> touched;
  std::vector<double> force;  // 3 per touched node
  double e_elastic, e_damping, e_friction;
  std::vector<std::int64_t> active_pairs;
  std::vector<double> normal_force;
  std::vector<std::string> messages;
};

CycleOut cycle_out(radx::contact::Type7Contact& c, const radx::contact::ContactStep& step) {
  CycleOut o{step, c.touched(), {}, c.energy_elastic(), c.energy_damping(), c.energy_friction(), {}, {}, {}};
  for (const auto n : c.touched())
    for (std::size_t d = 0; d < 3; ++d) o.force.push_back(c.force()[3 * static_cast<std::size_t>(n) + d]);
  for (const auto& r : c.results()) {
    o.active_pairs.push_back(r.active_pairs);
    o.normal_force.insert(o.normal_force.end(), r.normal_force.begin(), r.normal_force.end());
  }
  o.messages = c.take_messages();
  return o;
}

}  // namespace

TEST_CASE("TYPE7 contact gives == results whatever order or thread its chunks run on", "[type7][threads]") {
  // The impact benchmark's model at N = 90 with a 20 x 20 x 4 block: 11.1 mm plate shells under 10 mm
  // bricks (rows not aligned, so the closest segment of most nodes is not a tie that any order would
  // resolve to the same forces), 8,281 plate nodes: both interfaces have two or more chunks of tracked nodes
  // and of candidates once the block is down.
  radx::test::TempDir dir;
  auto m = radx::test::impact_benchmark_model(dir, 90, 30);
  radx::contact::prepare_type7_interfaces(m);
  REQUIRE(m.interfaces.size() == 2);

  // Prescribed motion (no solver): the block (interface 1's secondary nodes) starts 0.6 mm above the plate's
  // mid-surface, 0.1 mm outside the 0.5 mm gap, and moves down at 10 m/s and sideways at 30 m/s (friction,
  // and a new sort of the candidates as it slides); the plate bulges up under it. 40 steps of 1 us take the
  // block 0.4 mm down (partial penetration) and 1.2 mm sideways.
  const std::size_t nn = m.nodes.size();
  std::vector<std::uint8_t> is_block(nn, 0);
  for (const auto n : m.interfaces[0].secondary_nodes) is_block[static_cast<std::size_t>(n)] = 1;
  State s0;
  s0.x = m.nodes.x;
  s0.y = m.nodes.y;
  s0.z = m.nodes.z;
  s0.vx.assign(nn, 0.0);
  s0.vy.assign(nn, 0.0);
  s0.vz.assign(nn, 0.0);
  s0.mass.assign(nn, 1e-6);
  s0.added.assign(nn, 0.0);
  s0.fixed.assign(nn, 0);
  for (std::size_t n = 0; n < nn; ++n) {
    if (is_block[n]) {
      s0.z[n] -= 0.9;
      s0.vx[n] = 30000.0;
      s0.vz[n] = -10000.0;
    } else {
      const double r2 = (s0.x[n] * s0.x[n] + s0.y[n] * s0.y[n]) / (120.0 * 120.0);
      s0.vz[n] = 3000.0 * std::exp(-r2);
    }
  }

  // Counts the stages given to a ParallelFor with two chunks or more per compute(): the displacement test
  // asks at most once per interface (two), so three or more means a closest-segment stage ran through it.
  int calls = 0, most_calls = 0;
  auto run = [&](const radx::contact::ParallelFor& pf) {
    radx::contact::Type7Contact contact(m, radx::contact::ContactControls{});
    if (pf) contact.set_parallel_for(pf);
    State s = s0;
    const double dt = 1e-6;
    std::vector<CycleOut> out;
    most_calls = 0;
    for (int cyc = 0; cyc < 40; ++cyc) {
      calls = 0;
      const auto step = contact.compute(cyc * dt, cyc == 0 ? 0.0 : dt, s.view());
      most_calls = std::max(most_calls, calls);
      out.push_back(cycle_out(contact, step));
      for (std::size_t n = 0; n < nn; ++n) {
        s.x[n] += dt * s.vx[n];
        s.y[n] += dt * s.vy[n];
        s.z[n] += dt * s.vz[n];
      }
    }
    return out;
  };
  auto check_same = [](const std::vector<CycleOut>& a, const std::vector<CycleOut>& b) {
    REQUIRE(a.size() == b.size());
    for (std::size_t k = 0; k < a.size(); ++k) {
      INFO("cycle " << k);
      CHECK(a[k].step.dt == b[k].step.dt);
      CHECK(a[k].step.node_id == b[k].step.node_id);
      CHECK(a[k].step.interface_id == b[k].step.interface_id);
      CHECK(a[k].touched == b[k].touched);
      CHECK(a[k].force == b[k].force);  // bit-identical: == on doubles, no tolerance
      CHECK(a[k].e_elastic == b[k].e_elastic);
      CHECK(a[k].e_damping == b[k].e_damping);
      CHECK(a[k].e_friction == b[k].e_friction);
      CHECK(a[k].active_pairs == b[k].active_pairs);
      CHECK(a[k].normal_force == b[k].normal_force);
      CHECK(a[k].messages == b[k].messages);
    }
  };

  const auto serial = run({});
  // The contact paths ran: pairs in contact on both interfaces, friction, a time-step vote from contact.
  REQUIRE(serial.back().active_pairs[0] > 100);
  REQUIRE(serial.back().active_pairs[1] > 0);
  REQUIRE(serial.back().e_friction > 0);
  REQUIRE(serial.back().step.dt < 1e30);

  const radx::contact::ParallelFor reverse = [&](std::int64_t chunks, ChunkBody body) {
    if (chunks >= 2) ++calls;
    for (std::int64_t c = chunks - 1; c >= 0; --c) body(c);
  };
  check_same(run(reverse), serial);
  CHECK(most_calls >= 3);

  // Two real threads taking chunks from a shared counter (as the engine's team does).
  const radx::contact::ParallelFor threads = [](std::int64_t chunks, ChunkBody body) {
    std::atomic<std::int64_t> next{0};
    auto work = [&] {
      for (std::int64_t c = next++; c < chunks; c = next++) body(c);
    };
    std::thread other(work);
    work();
    other.join();
  };
  check_same(run(threads), serial);
}
