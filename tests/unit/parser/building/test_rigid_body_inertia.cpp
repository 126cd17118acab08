// /RBODY's added inertia given in a skew: the starter turns it into global axes, J = R J' R^T with R's
// columns the skew's axes, as Radioss's starter does. Expected values from the rotation by hand.
#include <catch2/catch.hpp>

#include <string>

#include "test_util.hpp"

namespace {

using radx::test::Line;

// Two free nodes, node 1 the main node of /RBODY/1 carrying node 2, with the added inertia diag(10, 20, 30)
// and Jxy 1 in skew `skew` (0: global axes). /SKEW/FIX/5 is the global frame turned 90 degrees about Z: its
// X' is global Y, its Y' global -X.
std::string rbody_deck(int skew) {
  std::string s = radx::test::begin_block(2024);
  s += "/NODE\n" + Line().put(1, 1, 10).put(0.0, 11, 30).put(0.0, 31, 50).put(0.0, 51, 70).str() + "\n" +
       Line().put(2, 1, 10).put(1.0, 11, 30).put(0.0, 31, 50).put(0.0, 51, 70).str() + "\n";
  s += "/SKEW/FIX/5\nturned about Z\n" + Line().put(0.0, 1, 20).put(0.0, 21, 40).put(0.0, 41, 60).str() +
       "\n" + Line().put(-1.0, 1, 20).put(0.0, 21, 40).put(0.0, 41, 60).str() + "\n" +
       Line().put(0.0, 1, 20).put(0.0, 21, 40).put(1.0, 41, 60).str() + "\n";
  s += "/GRNOD/NODE/1\ncarried\n" + Line().put(2, 1, 10).str() + "\n";
  s += "/RBODY/1\nbody\n" +
       Line()
           .put(1, 1, 10)
           .put(0, 11, 20)
           .put(skew, 21, 30)
           .put(0, 31, 40)
           .put(1e-3, 41, 60)
           .put(1, 61, 70)
           .str() +
       "\n" + Line().put(10.0, 1, 20).put(20.0, 21, 40).put(30.0, 41, 60).str() + "\n" +
       Line().put(1.0, 1, 20).put(0.0, 21, 40).put(0.0, 41, 60).str() + "\n";
  s += "/END\n";
  return s;
}

}  // namespace

TEST_CASE("/RBODY added inertia in a skew is turned into global axes", "[rigid_body][starter]") {
  const auto global = radx::test::model_of_deck(rbody_deck(0));
  REQUIRE(global.rigid_bodies.size() == 1);
  CHECK(global.rigid_bodies[0].inertia == std::array<double, 6>{10, 20, 30, 1, 0, 0});
  const auto turned = radx::test::model_of_deck(rbody_deck(5));
  REQUIRE(turned.rigid_bodies.size() == 1);
  const auto& j = turned.rigid_bodies[0].inertia;
  // Global X is the skew's -Y', global Y its X': Jxx = J'yy, Jyy = J'xx, Jxy = -J'xy.
  const std::array<double, 6> expected{20, 10, 30, -1, 0, 0};
  for (std::size_t k = 0; k < 6; ++k) CHECK(j[k] == Approx(expected[k]).margin(1e-12));
}
