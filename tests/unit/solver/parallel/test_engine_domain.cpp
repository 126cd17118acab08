// The engine split over ranks (solver/parallel/engine_domain.hpp) against one rank: after N cycles on 2 and
// 3 loopback ranks, every rank's coordinates, velocities, angular velocities and energy balance must be
// the one-rank engine's to the bit (the determinism rule of docs/parallel.md: no tolerance is right here).
#include <catch2/catch.hpp>
#include <cstring>
#include <string>
#include <vector>

#include "contact/type7_prepare.hpp"
#include "loopback_comm.hpp"
#include "solver/engine/explicit_engine.hpp"
#include "solver/parallel/engine_domain.hpp"
#include "test_util.hpp"

namespace {

namespace par = radx::solver::parallel;

// What a run leaves that the comparison reads: the node kinematics and the last report's energies.
struct RunEnd {
  std::vector<double> nodes;     // every node's state: rank 0's, the writer's (the others hold their own)
  std::vector<double> energies;  // the last report: every rank's
  std::int64_t cycles = 0;
  std::int64_t groups = 0;
};

RunEnd run_cycles(const radx::model::Model& model, int cycles, par::Comm* comm) {
  radx::model::RunControls rc;
  rc.t_stop = 1.0;  // stopped after `cycles` cycles
  radx::solver::EngineOptions options(1, 1);
  options.comm = comm;
  radx::solver::ExplicitEngine engine(model, rc, options);
  int n = 0;
  const auto res = engine.run([&](const radx::solver::CycleReport&) { return ++n < cycles; });
  RunEnd end;
  end.cycles = res.cycles;
  end.groups = engine.groups().count();
  const auto& s = engine.nodes();
  for (const auto* a : {&s.x, &s.y, &s.z, &s.vx, &s.vy, &s.vz, &s.wx, &s.wy, &s.wz, &s.ax, &s.ay, &s.az})
    end.nodes.insert(end.nodes.end(), a->begin(), a->end());
  const auto& e = res.last.energy;
  end.energies = {e.kinetic_t,
                  e.kinetic_r,
                  e.internal,
                  e.hourglass,
                  e.external_work,
                  e.plastic_work,
                  e.spring,
                  e.error_percent,
                  res.last.dt,
                  res.time,
                  res.last.momentum[0],
                  res.last.momentum[1],
                  res.last.momentum[2]};
  return end;
}

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

// The model's run on one rank and on P loopback ranks: every rank ends with one rank's bits.
void check_ranks(const radx::model::Model& model, int cycles, const std::string& what) {
  REQUIRE(par::features_not_distributed(model, radx::model::RunControls{}).empty());
  const RunEnd serial = run_cycles(model, cycles, nullptr);
  REQUIRE(serial.cycles == cycles - 1);
  for (const int P : {2, 3}) {
    std::vector<RunEnd> ends(static_cast<std::size_t>(P));
    radx::test::run_ranks(P, [&](par::Comm& comm) {
      ends[static_cast<std::size_t>(comm.rank())] = run_cycles(model, cycles, &comm);
    });
    for (int r = 0; r < P; ++r) {
      INFO(what << ": rank " << r << " of " << P << ", " << serial.groups << " groups");
      CHECK(ends[static_cast<std::size_t>(r)].cycles == serial.cycles);
      CHECK(same_bits(ends[static_cast<std::size_t>(r)].energies, serial.energies));
      if (r == 0) CHECK(same_bits(ends[0].nodes, serial.nodes));
    }
  }
}

}  // namespace

TEST_CASE("the engine on 2 and 3 ranks gives one rank's coordinates, velocities and energies to the bit",
          "[parallel][engine]") {
  // The impact benchmark's plate (shells) and block (bricks) with their TYPE7 contact (run on every rank):
  // many groups of 128 elements in rows, so most group boundaries put nodes on two ranks' groups.
  radx::test::TempDir dir;
  auto impact = radx::test::impact_benchmark_model(dir, 24);
  radx::contact::prepare_type7_interfaces(impact);  // the starter's gaps and search boxes
  const RunEnd probe = run_cycles(impact, 2, nullptr);
  REQUIRE(probe.groups >= 6);  // enough groups for every rank to have several
  check_ranks(impact, 60, "impact plate and block, N = 24");

  // Without contact no node is kept whole on every rank: each is integrated by its owner alone, and rank 0
  // gathers them for the outputs.
  impact.interfaces.clear();
  REQUIRE(par::replicated_nodes(impact) == std::vector<std::uint8_t>(impact.nodes.id.size(), 0));
  check_ranks(impact, 60, "impact plate and block without contact, N = 24");
}

TEST_CASE("a run with a feature not yet split over ranks is refused by the engine on more than one rank",
          "[parallel][engine]") {
  // A section's force sums every element's nodal forces at every cycle: not gathered yet.
  radx::test::TempDir dir;
  auto impact = radx::test::impact_benchmark_model(dir, 8);
  radx::contact::prepare_type7_interfaces(impact);
  impact.sections.emplace_back();
  const auto refused = par::features_not_distributed(impact, radx::model::RunControls{});
  REQUIRE(refused.size() == 1);
  CHECK(refused[0].find("/SECT") != std::string::npos);
  std::vector<std::string> said(2);
  radx::test::run_ranks(2, [&](par::Comm& comm) {
    try {
      run_cycles(impact, 2, &comm);
    } catch (const std::exception& e) {
      said[static_cast<std::size_t>(comm.rank())] = e.what();
    }
  });
  for (const auto& s : said) CHECK(s.find("/SECT") != std::string::npos);
}

TEST_CASE("the nodes kept whole on every rank are those of the stages every rank runs whole, and no others",
          "[parallel][engine]") {
  // One feature a node (or a few), each on nodes of its own, so a feature left out shows as its nodes
  // unmarked; nodes under a boundary condition only, or under none, must stay the owner's alone.
  namespace model = radx::model;
  model::Model m;
  for (std::int64_t id = 1; id <= 24; ++id) m.nodes.id.push_back(id);
  const auto group = [&](std::vector<std::int32_t> nodes) {
    m.node_groups.push_back({});
    m.node_groups.back().nodes = std::move(nodes);
    return static_cast<std::int32_t>(m.node_groups.size() - 1);
  };
  const auto surface = [&](std::array<std::int32_t, 4> segment) {
    m.surfaces.push_back({});
    m.surfaces.back().segments.push_back(segment);
    return static_cast<std::int32_t>(m.surfaces.size() - 1);
  };
  std::vector<std::int32_t> expected;
  const auto expect = [&](std::initializer_list<std::int32_t> nodes) {
    expected.insert(expected.end(), nodes);
  };
  m.imposed_velocities.push_back({});
  m.imposed_velocities.back().group = group({0, 1});
  expect({0, 1});
  m.imposed_final_geometries.push_back({});
  m.imposed_final_geometries.back().nodes = {2};
  expect({2});
  m.initial_velocities.push_back({});  // applied at t = 0 alike on every rank: not kept whole
  m.initial_velocities.back().group = group({3});
  m.initial_velocities.push_back({});  // delayed: applied mid-run, with its work
  m.initial_velocities.back().group = group({4});
  m.initial_velocities.back().t_start = 1e-3;
  expect({4});
  m.concentrated_loads.push_back({});
  m.concentrated_loads.back().group = group({5});
  expect({5});
  m.pressure_loads.push_back({});
  m.pressure_loads.back().surface = surface({6, 7, 8, 8});
  expect({6, 7, 8});
  m.rigid_walls.push_back({});
  m.rigid_walls.back().secondary = {9};
  m.rigid_walls.back().node = 10;
  expect({9, 10});
  m.rigid_bodies.push_back({});
  m.rigid_bodies.back().secondary = {11};
  m.rigid_bodies.back().main_node = 12;
  expect({11, 12});
  m.tied_interfaces.push_back({});
  m.tied_interfaces.back().tie_node = {13};
  m.tied_interfaces.back().tie_segment = {{14, 15, 16, 16}};
  expect({13, 14, 15, 16});
  m.interfaces.push_back({});
  m.interfaces.back().secondary_nodes = {17};
  m.interfaces.back().main_surface = surface({18, 19, 20, 20});
  expect({17, 18, 19, 20});
  m.skews.push_back({});  // a fixed skew reads no node
  m.skews.push_back({});
  m.skews.back().n1 = 21;
  m.skews.back().n2 = 0;
  m.skews.back().n3 = 1;
  expect({21});
  m.accelerometers.push_back({});
  m.accelerometers.back().node = 22;
  expect({22});
  m.bcs.push_back({});
  m.bcs.back().group = group({23});
  m.gravities.push_back({});
  m.gravities.back().group = group({3});
  expect({3});

  std::vector<std::uint8_t> want(m.nodes.id.size(), 0);
  for (const auto n : expected) want[static_cast<std::size_t>(n)] = 1;
  CHECK(par::replicated_nodes(m) == want);

  m.gravities.back().group = model::kNone;  // gravity on every node: every node kept whole
  CHECK(par::replicated_nodes(m) == std::vector<std::uint8_t>(m.nodes.id.size(), 1));
}

TEST_CASE(
    "given group ranks replace the partition on every rank, and ranks that do not fit are refused by all",
    "[parallel][engine]") {
  radx::test::TempDir dir;
  auto impact = radx::test::impact_benchmark_model(dir, 8);
  radx::contact::prepare_type7_interfaces(impact);
  const radx::solver::ExplicitEngine engine(impact, radx::model::RunControls{},
                                            radx::solver::EngineOptions(1));
  const auto& groups = engine.groups();
  const std::int64_t G = groups.count();
  REQUIRE(G >= 3);
  // Not what METIS or the blocks would give: every group on rank 2 but the first two, on ranks 1 and 0.
  std::vector<std::int32_t> given(static_cast<std::size_t>(G), 2);
  given[0] = 1;
  given[1] = 0;
  constexpr int P = 3;
  std::vector<std::vector<std::int32_t>> got(P);
  radx::test::run_ranks(P, [&](par::Comm& comm) {
    // Only rank 0's are read: the others pass none and still end with rank 0's.
    const std::vector<std::int32_t> mine = comm.rank() == 0 ? given : std::vector<std::int32_t>{};
    got[static_cast<std::size_t>(comm.rank())] = par::engine_group_ranks(impact, groups, comm, mine);
  });
  for (int r = 0; r < P; ++r) CHECK(got[static_cast<std::size_t>(r)] == given);

  // One rank too many for P = 2, or one group short: every rank throws rank 0's reason instead of running.
  for (const auto& bad : {given, std::vector<std::int32_t>(given.begin(), given.end() - 1)}) {
    std::vector<std::string> said(2);
    radx::test::run_ranks(2, [&](par::Comm& comm) {
      try {
        (void)par::engine_group_ranks(impact, groups, comm, bad);
      } catch (const std::exception& e) {
        said[static_cast<std::size_t>(comm.rank())] = e.what();
      }
    });
    for (const auto& s : said) CHECK(s.find("the given group ranks do not fit") != std::string::npos);
  }
}
