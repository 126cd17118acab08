// /FRAME/FIX and /FRAME/MOV: frames built as the skews of the same cards (parser/building/build_skews.cpp)
// and a /TH/NODE written in a /FRAME/FIX (solver/outputs/time_history_values.cpp): positions measured from
// the frame's origin, vectors on its axes (docs/theory/frames.md). Expected values by hand: the axes from
// their definitions, the node's straight-line motion x(t) = x0 + v t turned onto the axes.
#include <catch2/catch.hpp>
#include <cmath>

#include "solver/engine/explicit_engine.hpp"
#include "solver/outputs/time_history_values.hpp"
#include "test_util.hpp"

using radx::test::Line;
namespace m = radx::model;
namespace sv = radx::solver;

namespace {

using V3 = m::Vec3;

void check_axes(const std::array<double, 9>& got, const V3& x, const V3& y, const V3& z, double tol) {
  for (std::size_t d = 0; d < 3; ++d) {
    CHECK(std::abs(got[d] - x[d]) <= tol);
    CHECK(std::abs(got[3 + d] - y[d]) <= tol);
    CHECK(std::abs(got[6 + d] - z[d]) <= tol);
  }
}

std::string node_line(int id, double x, double y, double z) {
  return Line().put(id, 1, 10).put(x, 11, 30).put(y, 31, 50).put(z, 51, 70).str() + "\n";
}

std::string three_reals(double a, double b, double c) {
  return Line().put(a, 1, 20).put(b, 21, 40).put(c, 41, 60).str() + "\n";
}

// A /SKEW/FIX or /FRAME/FIX: origin o, Y' = y, Z' = z.
std::string fixed(const std::string& path, int id, const V3& o, const V3& y, const V3& z) {
  return path + "/" + std::to_string(id) + "\nfixed " + std::to_string(id) + "\n" +
         three_reals(o[0], o[1], o[2]) + three_reals(y[0], y[1], y[2]) + three_reals(z[0], z[1], z[2]);
}

}  // namespace

TEST_CASE("/FRAME/MOV and /FRAME/FIX: the skews' axes with their origin, in the skews' id space", "[frame]") {
  // N1 (1, 1, 1), N2 = N1 + (2, 0, 0), N3 = N1 + (1, 3, 0). /FRAME/MOV Dir Y: y' = N1N2 = X, x' = y' x N1N3 =
  // Z, z' = x' x y' = Y; origin N1. /FRAME/FIX: Y' = (1, 1, 0), Z' = (0, 0, 2): x' = Y' x Z' = (2, -2, 0) ->
  // (1, -1, 0)/sqrt2, y' = Z' x x' = (4, 4, 0) -> (1, 1, 0)/sqrt2, z' = (0, 0, 1); origin as given.
  std::string s = radx::test::begin_block(2026, "Mg mm s") + "/NODE\n" + node_line(1, 1, 1, 1) +
                  node_line(2, 3, 1, 1) + node_line(3, 2, 4, 1);
  s += fixed("/SKEW/FIX", 5, {0, 0, 0}, {0, 1, 0}, {0, 0, 1});
  s += "/FRAME/MOV/6\nmoving frame\n" +
       Line().put(1, 1, 10).put(2, 11, 20).put(3, 21, 30).put("Y", 31, 40).str() + "\n";
  s += fixed("/FRAME/FIX", 7, {1, 2, 3}, {1, 1, 0}, {0, 0, 2});
  s += "/END\n";
  const auto md = radx::test::model_of_deck(s);
  REQUIRE(md.skews.size() == 3);
  const V3 X{1, 0, 0}, Y{0, 1, 0}, Z{0, 0, 1};
  const auto& skew = md.skews[md.skew_index(5)];
  const auto& mov = md.skews[md.skew_index(6)];
  const auto& fix = md.skews[md.skew_index(7)];
  CHECK_FALSE(skew.frame);
  CHECK(mov.frame);
  CHECK(fix.frame);
  CHECK(mov.moving());
  CHECK_FALSE(fix.moving());
  CHECK(mov.dir == 1);
  CHECK(mov.n1 == 0);
  CHECK(mov.n2 == 1);
  CHECK(mov.n3 == 2);
  CHECK(mov.origin == std::array<double, 3>{1.0, 1.0, 1.0});
  check_axes(mov.axes, Z, X, Y, 1e-15);
  const double r = 1.0 / std::sqrt(2.0);
  check_axes(fix.axes, {r, -r, 0}, {r, r, 0}, Z, 1e-15);
  CHECK(fix.origin == std::array<double, 3>{1.0, 2.0, 3.0});
}

TEST_CASE("/TH/NODE in a /FRAME/FIX: the position from the origin, the vectors on the axes",
          "[frame][engine]") {
  // Node 1, a free point mass at x0 = (5, 6, 7) with v = (3, 4, 0) mm/s, is listed in /FRAME/FIX 7 (origin
  // O = (1, 2, 3), axes x' = (1, -1, 0)/sqrt2, y' = (1, 1, 0)/sqrt2, z' = Z), in /SKEW/FIX 5 (the same
  // origin and axes) and in the global axes. In the frame X' = R (x - O) = (-t, 8 + 7t, 4 sqrt2)/sqrt2; in
  // the skew X = R x = (-1 - t, 11 + 7t, 7 sqrt2)/sqrt2, not from the origin; V = R v = (-1, 7, 0)/sqrt2 in
  // both.
  const double dt = 1e-3;
  std::string s = radx::test::begin_block(2026, "Mg mm s") + "/NODE\n" + node_line(1, 5, 6, 7);
  s += "/GRNOD/NODE/1\nfree\n" + Line().put(1, 1, 10).str() + "\n";
  s += "/ADMAS/0/1\nfree mass\n" + Line().put(1e-3, 1, 20).put(1, 21, 30).str() + "\n";
  s += "/INIVEL/TRA/1\nmoving\n" +
       Line().put(3.0, 1, 20).put(4.0, 21, 40).put(0.0, 41, 60).put(1, 61, 70).str() + "\n";
  s += fixed("/SKEW/FIX", 5, {1, 2, 3}, {1, 1, 0}, {0, 0, 1});
  s += fixed("/FRAME/FIX", 7, {1, 2, 3}, {1, 1, 0}, {0, 0, 1});
  s += "/TH/NODE/1\nin a frame\n" + Line().put("XYZ", 1, 10).put("V", 11, 20).str() + "\n" +
       Line().put(1, 1, 10).put(7, 11, 20).str() + "\n" + Line().put(1, 1, 10).put(5, 11, 20).str() + "\n" +
       Line().put(1, 1, 10).str() + "\n/END\n";
  const auto md = radx::test::model_of_deck(s);
  REQUIRE(md.time_histories.size() == 1);
  const auto& th = md.time_histories[0];
  REQUIRE(th.skews == std::vector<std::int64_t>{7, 5, 0});
  m::RunControls rc;
  rc.t_stop = 0.1;
  rc.dt_initial = rc.dt_max = dt;
  sv::ExplicitEngine engine(md, rc, sv::EngineOptions{1, 1});
  sv::ThGroupSampler sampler(engine, th);
  std::vector<double> v(sampler.size());
  REQUIRE(v.size() == 3u * 6u);
  const double r = 1.0 / std::sqrt(2.0);
  double worst = 0;
  int rows = 0;
  engine.run([&](const sv::CycleReport& c) {
    sampler.sample(engine, c, v);
    const double t = c.time;
    const double want[18] = {-t * r,       (8 + 7 * t) * r,  4, -r, 7 * r, 0,   // frame 7
                             (-1 - t) * r, (11 + 7 * t) * r, 7, -r, 7 * r, 0,   // skew 5
                             5 + 3 * t,    6 + 4 * t,        7, 3,  4,     0};  // global
    for (std::size_t k = 0; k < 18; ++k) worst = std::max(worst, std::abs(v[k] - want[k]));
    ++rows;
    return true;
  });
  CHECK(rows > 90);
  // No force acts: x = x0 + v t to round-off over 100 steps.
  CHECK(worst <= 1e-12 * 20);
}
