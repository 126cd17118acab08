// TYPE7 in the engine, the paths a deck cannot reach reliably: a secondary node whose remaining gap
// (g - p)/g is below 1e-6 cannot be held by the hyperbolic penalty (type7-lagdt.md 4.3) and is deactivated
// with a warning naming the node and the interface.
#include <algorithm>
#include <catch2/catch.hpp>
#include <string>

#include "contact/type7_prepare.hpp"
#include "parser/build_run_controls.hpp"
#include "solver/explicit_engine.hpp"
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
