// /RANDOM and /RANDOM/GRNOD (parser/building/build_random.cpp): the node coordinates after the starter,
// against the 16-bit linear congruential sequence written out here independently: I <- (25173 I + 13849) mod
// 65536, r = (I - 32768) / 32768, each node's x, y, z in node order, I_0 = trunc(32768 SEED + 32768).
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>

#include "parser/reading/deck.hpp"
#include "test_util.hpp"

using radx::test::Line;

namespace {

// Eight nodes of a 10 mm cube and its brick; `extra` goes before /END.
std::string cube_deck(const std::string& extra) {
  std::string s = radx::test::begin_block(2026) + "/NODE\n";
  for (int k = 0; k < 8; ++k) {
    const double x = (k == 1 || k == 2 || k == 5 || k == 6) ? 10.0 : 0.0;
    const double y = (k == 2 || k == 3 || k == 6 || k == 7) ? 10.0 : 0.0;
    s += Line().put(k + 1, 1, 10).put(x, 11, 30).put(y, 31, 50).put(k >= 4 ? 10.0 : 0.0, 51, 70).str() + "\n";
  }
  Line b;
  b.put(1, 1, 10);
  for (int k = 0; k < 8; ++k) b.put(k + 1, 11 + 10 * k, 20 + 10 * k);
  s += "/BRICK/1\n" + b.str() + "\n/PART/1\ncube\n" + Line().put(1, 1, 10).put(1, 11, 20).str() + "\n";
  s += "/PROP/SOLID/1\nsolid\n\n\n/MAT/LAW1/1\nsteel\n" + Line().put(7.85e-9, 1, 20).str() + "\n" +
       Line().put(210000.0, 1, 20).put(0.3, 21, 40).str() + "\n";
  s +=
      "/GRNOD/NODE/7\ntop\n" + Line().put(8, 1, 10).put(6, 11, 20).put(5, 21, 30).put(7, 31, 40).str() + "\n";
  return s + extra + "/END\n";
}

struct Sequence {
  std::int64_t i;
  explicit Sequence(double seed) : i(seed == 0 ? 0 : static_cast<std::int64_t>(seed * 32768 + 32768)) {}
  double next() {
    i = (25173 * i + 13849) % 65536;
    return (static_cast<double>(i) - 32768.0) / 32768.0;
  }
};

std::string random_card(double xalea, double seed) {
  return Line().put(xalea, 1, 20).put(seed, 21, 40).str() + "\n";
}

}  // namespace

TEST_CASE("/RANDOM moves every node by Radioss's sequence, within XALEA", "[random]") {
  const double xalea = 0.01, seed = 0.37;
  const auto plain = radx::test::model_of_deck(cube_deck(""));
  const auto m = radx::test::model_of_deck(cube_deck("/RANDOM\n" + random_card(xalea, seed)));
  Sequence s(seed);
  double largest = 0;
  for (std::size_t n = 0; n < 8; ++n) {
    // Exact to round-off: one addition of a product of two doubles.
    CHECK(m.nodes.x[n] == Approx(plain.nodes.x[n] + xalea * s.next()).margin(1e-15));
    CHECK(m.nodes.y[n] == Approx(plain.nodes.y[n] + xalea * s.next()).margin(1e-15));
    CHECK(m.nodes.z[n] == Approx(plain.nodes.z[n] + xalea * s.next()).margin(1e-15));
    largest =
        std::max({largest, std::abs(m.nodes.x[n] - plain.nodes.x[n]),
                  std::abs(m.nodes.y[n] - plain.nodes.y[n]), std::abs(m.nodes.z[n] - plain.nodes.z[n])});
  }
  CHECK(largest <= xalea);
  CHECK(largest > 0.1 * xalea);  // 24 draws: the sequence is not stuck near 0
}

TEST_CASE("/RANDOM/GRNOD moves only the group's nodes, in node order, from the default sequence",
          "[random]") {
  const double xalea = 0.02;
  const auto plain = radx::test::model_of_deck(cube_deck(""));
  const auto m = radx::test::model_of_deck(cube_deck("/RANDOM/GRNOD/7\n" + random_card(xalea, 0.0)));
  Sequence s(0.0);
  for (std::size_t n = 0; n < 8; ++n) {
    INFO("node " << n + 1);
    if (n < 4) {
      CHECK(m.nodes.x[n] == plain.nodes.x[n]);
      CHECK(m.nodes.z[n] == plain.nodes.z[n]);
      continue;
    }
    // The group lists 8 6 5 7: the nodes are perturbed in node order 5 6 7 8.
    CHECK(m.nodes.x[n] == Approx(plain.nodes.x[n] + xalea * s.next()).margin(1e-15));
    CHECK(m.nodes.y[n] == Approx(plain.nodes.y[n] + xalea * s.next()).margin(1e-15));
    CHECK(m.nodes.z[n] == Approx(plain.nodes.z[n] + xalea * s.next()).margin(1e-15));
  }
}

TEST_CASE("/RANDOM with /RANDOM/GRNOD is refused, a missing group and a negative XALEA are errors",
          "[random]") {
  radx::test::TempDir dir;
  const std::string deck =
      cube_deck("/RANDOM\n" + random_card(0.01, 0) + "/RANDOM/GRNOD/7\n" + random_card(0.01, 0) +
                "/RANDOM/GRNOD/9\n" + random_card(0.01, 0) + "/RANDOM/0\n" + random_card(-0.01, 0));
  radx::Diagnostics d;
  const auto parsed = radx::read_starter_deck(dir.write("r_0000.rad", deck), d);
  (void)radx::build_model(parsed, d);
  std::string all;
  for (const auto& i : d.items()) all += radx::Diagnostics::format(i) + "\n";
  INFO(all);
  CHECK(all.find("RX507: [/RANDOM/GRNOD id 7]") != std::string::npos);
  CHECK(all.find("Radioss then perturbs no node at all") != std::string::npos);
  CHECK(all.find("RX501: [/RANDOM]") != std::string::npos);
  radx::Diagnostics d2;
  const auto parsed2 = radx::read_starter_deck(
      dir.write("g_0000.rad", cube_deck("/RANDOM/GRNOD/9\n" + random_card(0.01, 0))), d2);
  (void)radx::build_model(parsed2, d2);
  std::string all2;
  for (const auto& i : d2.items()) all2 += radx::Diagnostics::format(i) + "\n";
  INFO(all2);
  CHECK(all2.find("RX402: [/RANDOM/GRNOD id 9]") != std::string::npos);
}

TEST_CASE(
    "/RANDOM with a SEED beyond 32 bits starts from Radioss's integer indefinite, without undefined "
    "behaviour",
    "[random]") {
  // trunc(32768 SEED + 32768) does not fit 32 bits for SEED = 1e10: Radioss's INT on x86 gives INT32_MIN.
  // The first draw by hand, in 32-bit arithmetic: 25173 (-2^31) + 13849 wraps to -2^31 + 13849 =
  // -2147469799, whose Fortran MOD 65536 is -51687: r = (-51687 - 32768) / 32768.
  const double xalea = 0.01;
  const auto plain = radx::test::model_of_deck(cube_deck(""));
  const auto m = radx::test::model_of_deck(cube_deck("/RANDOM\n" + random_card(xalea, 1e10)));
  CHECK(m.nodes.x[0] == Approx(plain.nodes.x[0] + xalea * (-51687.0 - 32768.0) / 32768.0).margin(1e-15));
}
