// TYPE7 in the engine, the paths a deck cannot reach reliably: a secondary node whose remaining gap
// (g - p)/g is below 1e-6 cannot be held by the hyperbolic penalty (docs/theory/type7-lagdt.md 4.3) and is
// deactivated with a warning naming the node and the interface. The search's workload the results report:
// candidate pairs per active cycle and sorts, against a brute-force search on the same coordinates.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "contact/type7_engine.hpp"
#include "contact/type7_prepare.hpp"
#include "contact/type7_search.hpp"
#include "parser/building/build_run_controls.hpp"
#include "solver/engine/explicit_engine.hpp"
#include "test_util.hpp"

TEST_CASE("a node at the surface (remaining gap below 1e-6 of the gap) is deactivated with a warning",
          "[type7-engine]") {
  // decks/verification/node_on_segment: a cube whose four lower-face nodes (101..104) are the secondary
  // nodes of /INTER/TYPE7/1 against a fixed plate, gap 1 mm. The cube is moved down so that its lower face
  // is 1e-10 m above the plate: remaining gap 1e-7 of the gap.
  const std::string dir = std::string(RADX_SOURCE_DIR) + "/decks/verification/node_on_segment/";
  radx::Diagnostics d;
  const auto deck = radx::read_starter_deck(dir + "NODE_ON_SEGMENT_0000.rad", d);
  auto m = radx::build_model(deck, d);
  REQUIRE_FALSE(d.has_errors());
  REQUIRE(m.interfaces.size() == 1);
  const auto& in = m.interfaces[0];
  const auto lowest = [&](bool secondary) {
    double z = 1e300;
    for (std::size_t n = 0; n < m.nodes.size(); ++n) {
      const bool is_sec =
          std::binary_search(m.node_groups[static_cast<std::size_t>(in.secondary_group)].nodes.begin(),
                             m.node_groups[static_cast<std::size_t>(in.secondary_group)].nodes.end(),
                             static_cast<std::int32_t>(n));
      if (is_sec == secondary) z = std::min(z, m.nodes.z[n]);
    }
    return z;
  };
  const double plate_z = lowest(false), face_z = lowest(true);
  const double shift = face_z - plate_z - 1e-10;
  for (std::size_t n = 0; n < m.nodes.size(); ++n)
    if (m.nodes.z[n] > plate_z + 0.5 * (face_z - plate_z)) m.nodes.z[n] -= shift;
  radx::contact::prepare_type7_interfaces(m);
  auto rc = radx::read_run_controls(dir + "NODE_ON_SEGMENT_0001.rad", d);
  REQUIRE_FALSE(d.has_errors());
  radx::solver::ExplicitEngine engine(m, rc, radx::solver::EngineOptions(1, 1));
  std::vector<std::string> messages;
  engine.run([&](const radx::solver::CycleReport& r) {
    for (auto& s : engine.take_messages()) messages.push_back(s);
    return r.cycle < 3;
  });
  REQUIRE(messages.size() == 4);  // the four lower-face nodes, once each
  for (const std::int64_t id : {101, 102, 103, 104}) {
    const bool named = std::any_of(messages.begin(), messages.end(), [&](const std::string& s) {
      return s.find("interface 1: secondary node " + std::to_string(id) + " reached the main surface") !=
             std::string::npos;
    });
    CHECK(named);
  }
  // Deactivated nodes get no contact force afterwards.
  CHECK(engine.contact()->touched().empty());
}

TEST_CASE("TYPE7 results count the search's candidate pairs per active cycle and its sorts",
          "[type7-engine]") {
  // The impact benchmark's model at N = 20 with a 4 x 4 x 4 block of 10 mm bricks over 50 mm plate shells.
  // Prescribed motion (no solver): the block slides 0.37 mm in x per cycle for 40 cycles, the plate stays.
  // Expected values come from the rule of type7_search.cpp, not from the search: the margin is Bumult times
  // the mean main segment edge at the first sort; a sort is due when 2 d >= margin, d the block's travel
  // since the last sort (every tracked node of both interfaces moves with the block or not at all); between
  // sorts the candidates are those of brute_force_candidates at the coordinates of the last sort.
  radx::test::TempDir dir;
  auto m = radx::test::impact_benchmark_model(dir, 20, 4);
  radx::contact::prepare_type7_interfaces(m);
  REQUIRE(m.interfaces.size() == 2);
  const std::size_t nn = m.nodes.size();
  std::vector<std::uint8_t> is_block(nn, 0);
  for (const auto n : m.interfaces[0].secondary_nodes) is_block[static_cast<std::size_t>(n)] = 1;

  std::vector<double> x = m.nodes.x, y = m.nodes.y, z = m.nodes.z, vx(nn, 0.0), vy(nn, 0.0), vz(nn, 0.0);
  std::vector<double> mass(nn, 1e-6), added(nn, 0.0);
  std::vector<std::uint8_t> fixed(nn, 0);
  const double step = 0.37;  // mm per cycle
  const int cycles = 40;

  // Independent count per interface.
  std::vector<double> expected_mean;
  std::vector<std::int64_t> expected_sorts;
  for (const auto& in : m.interfaces) {
    REQUIRE(in.igap == 0);
    REQUIRE(in.contact_law_id == 0);
    const auto& segs = m.surfaces[static_cast<std::size_t>(in.main_surface)].segments;
    double edges = 0;
    std::size_t count = 0;
    const auto len = [&](std::int32_t a, std::int32_t b) {
      const auto i = static_cast<std::size_t>(a), j = static_cast<std::size_t>(b);
      return std::hypot(x[i] - x[j], y[i] - y[j], z[i] - z[j]);
    };
    for (const auto& sg : segs) {
      const bool tri = sg[2] == sg[3];
      edges += len(sg[0], sg[1]) + len(sg[1], sg[2]) +
               (tri ? len(sg[2], sg[0]) : len(sg[2], sg[3]) + len(sg[3], sg[0]));
      count += tri ? 3 : 4;
    }
    const double margin = in.bumult * edges / static_cast<double>(count);
    std::int64_t sum = 0, sorts = 0;
    std::size_t held = 0;
    int last_sort = 0;
    for (int k = 0; k < cycles; ++k) {
      if (k == 0 || 2 * step * (k - last_sort) >= margin) {
        std::vector<double> xs = x;
        for (std::size_t n = 0; n < nn; ++n)
          if (is_block[n]) xs[n] += step * k;
        held = radx::contact::brute_force_candidates({xs, y, z}, in.secondary_nodes, segs, in.gapmin + margin)
                   .size();
        ++sorts;
        last_sort = k;
      }
      sum += static_cast<std::int64_t>(held);
    }
    expected_mean.push_back(static_cast<double>(sum) / cycles);
    expected_sorts.push_back(sorts);
  }
  // Margins 0.2 x 50 mm = 10 mm and 0.2 x 10 mm = 2 mm: a sort every 14 and every 3 cycles.
  CHECK(expected_sorts == std::vector<std::int64_t>{3, 14});

  radx::contact::Type7Contact contact(m, radx::contact::ContactControls{});
  const double dt = 1e-6;
  for (int k = 0; k < cycles; ++k) {
    for (std::size_t n = 0; n < nn; ++n)
      if (is_block[n]) x[n] = m.nodes.x[n] + step * k;
    contact.compute(k * dt, k == 0 ? 0.0 : dt, {x, y, z, vx, vy, vz, mass, added, fixed, {}});
  }
  const auto results = contact.results();
  REQUIRE(results.size() == 2);
  for (std::size_t i = 0; i < 2; ++i) {
    INFO("interface " << results[i].id);
    CHECK(results[i].active_cycles == cycles);
    CHECK(results[i].search_sorts == expected_sorts[i]);
    CHECK(results[i].mean_candidates() == Approx(expected_mean[i]).epsilon(1e-15));
    CHECK(results[i].mean_candidates() > 0);
  }
}
