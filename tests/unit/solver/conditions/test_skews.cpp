// /SKEW/FIX and the conditions and loads that name a skew (parser/building/build_skews.cpp,
// solver/conditions/boundary_conditions.cpp, solver/conditions/external_loads.cpp). Expected values from the
// frame's definition and Newton's law on a free node.
#include <catch2/catch.hpp>
#include <cmath>

#include "solver/conditions/boundary_conditions.hpp"
#include "solver/conditions/external_loads.hpp"
#include "test_util.hpp"

using radx::test::Line;
namespace m = radx::model;
namespace sv = radx::solver;

namespace {

bool close(double a, double b, double tol) {
  return std::abs(a - b) <= tol;
}

// The frame of the tests: Y' = (1, 1, 0), Z' = (0, 0, 1) give x' = (1, -1, 0)/sqrt2, y' = (1, 1, 0)/sqrt2,
// z' = (0, 0, 1).
m::Skew diagonal_skew() {
  const double r = 1.0 / std::sqrt(2.0);
  m::Skew s;
  s.id = 5;
  s.axes = {r, -r, 0, r, r, 0, 0, 0, 1};
  return s;
}

// One free node of mass 2 at the origin, the skew above, a node group {0}.
m::Model one_node() {
  m::Model md;
  md.nodes.id = {1};
  md.nodes.x = {0.0};
  md.nodes.y = {0.0};
  md.nodes.z = {0.0};
  md.skews.push_back(diagonal_skew());
  m::NodeGroup g;
  g.id = 1;
  g.nodes = {0};
  md.node_groups.push_back(g);
  m::Function f;
  f.id = 1;
  f.x = {0.0, 1.0};
  f.y = {1.0, 1.0};
  md.functions.push_back(f);
  return md;
}

sv::NodeState state(const m::Model& md) {
  sv::NodeState s;
  s.resize(md.nodes.size());
  s.mass[0] = 2.0;
  return s;
}

void cycle(sv::NodeState& s, double dt) {  // a = f/m, v += dt a, x += dt v (constant step)
  s.ax[0] = s.fx[0] / s.mass[0];
  s.ay[0] = s.fy[0] / s.mass[0];
  s.az[0] = s.fz[0] / s.mass[0];
  (void)dt;
}

void update(sv::NodeState& s, double dt) {
  s.vx[0] += dt * s.ax[0];
  s.vy[0] += dt * s.ay[0];
  s.vz[0] += dt * s.az[0];
  s.x[0] += dt * s.vx[0];
  s.y[0] += dt * s.vy[0];
  s.z[0] += dt * s.vz[0];
}

void zero_forces(sv::NodeState& s) {
  for (auto* v : {&s.fx, &s.fy, &s.fz, &s.fx_ext, &s.fy_ext, &s.fz_ext, &s.mx, &s.my, &s.mz})
    std::fill(v->begin(), v->end(), 0.0);
}

}  // namespace

TEST_CASE("/SKEW/FIX: x' = Y' x Z', y' = Z' x x', z' = Z', normalised", "[skew]") {
  std::string s = radx::test::begin_block(2026, "Mg mm s");
  s += "/NODE\n" + Line().put(1, 1, 10).put(0.0, 11, 30).str() + "\n";
  s += "/SKEW/FIX/5\ndiagonal\n" + Line().put(1.0, 1, 20).put(2.0, 21, 40).put(3.0, 41, 60).str() + "\n" +
       Line().put(2.0, 1, 20).put(2.0, 21, 40).put(0.0, 41, 60).str() + "\n" +
       Line().put(0.0, 1, 20).put(0.0, 21, 40).put(3.0, 41, 60).str() + "\n/END\n";
  radx::Diagnostics diags;
  const auto md = radx::test::model_of_deck(s);
  REQUIRE(md.skews.size() == 1);
  const auto want = diagonal_skew().axes;
  for (std::size_t k = 0; k < 9; ++k) CHECK(close(md.skews[0].axes[k], want[k], 1e-15));
  CHECK(md.skews[0].origin == std::array<double, 3>{1.0, 2.0, 3.0});
  CHECK(!md.skews[0].moving());
  CHECK(md.skew_index(5) == 0);
  CHECK(md.skew_index(0) == m::kNone);
  CHECK_THROWS(md.skew_index(7));
  const sv::SkewFrames frames(md);
  CHECK(frames.axis(0, 0)[1] == md.skews[0].axes[1]);
  CHECK(frames.axis(m::kNone, 2) == std::array<double, 3>{0.0, 0.0, 1.0});
}

TEST_CASE("a /BCS in a skew holds along its fixed skew axes and frees the rest", "[skew]") {
  // x' fixed; gravity g along global X: the free acceleration is g (e_X - (e_X.x') x') = g (1/2, 1/2, 0).
  auto md = one_node();
  m::BoundaryCondition c;
  c.id = 1;
  c.fixed = {1, 0, 0, 0, 0, 0};
  c.skew = 5;
  c.group = 0;
  md.bcs.push_back(c);
  m::Gravity gr;
  gr.id = 1;
  gr.dir = 0;
  gr.fscale_y = 9.81;
  md.gravities.push_back(gr);
  auto s = state(md);
  const sv::SkewFrames frames(md);
  sv::BoundaryConditions bcs(md, frames);
  sv::ExternalLoads loads(md, frames);
  bcs.set_fixed_bits(s);
  CHECK(s.fixed[0] == 0);  // no global bit: the skew carries it
  std::vector<std::uint8_t> held(1, 0);
  bcs.mark_skewed(held);
  CHECK(held[0] == 1);
  const double dt = 1e-3;
  for (int k = 0; k < 100; ++k) {
    zero_forces(s);
    (void)loads.apply(s, k * dt, dt);
    cycle(s, dt);
    bcs.apply(s);
    update(s, dt);
  }
  const double t = 100 * dt;
  // v = a t exactly up to round-off; nothing along x'.
  CHECK(close(s.vx[0], 0.5 * 9.81 * t, 1e-12));
  CHECK(close(s.vy[0], 0.5 * 9.81 * t, 1e-12));
  CHECK(s.vz[0] == 0.0);
  CHECK(close((s.vx[0] - s.vy[0]) / std::sqrt(2.0), 0.0, 1e-14));
  CHECK(close((s.x[0] - s.y[0]) / std::sqrt(2.0), 0.0, 1e-15));
}

TEST_CASE("/IMPVEL, /INIVEL and /CLOAD along skew axes", "[skew]") {
  const double r = 1.0 / std::sqrt(2.0), dt = 1e-3;
  SECTION("/IMPVEL along y': v.y' = V, the other components keep their free motion") {
    auto md = one_node();
    m::ImposedVelocity iv;
    iv.id = 1;
    iv.function = 0;
    iv.dir = 1;
    iv.skew = 5;
    iv.group = 0;
    iv.fscale_y = 3.0;
    md.imposed_velocities.push_back(iv);
    auto s = state(md);
    s.vz[0] = 0.25;  // free, along z'
    const sv::SkewFrames frames(md);
    sv::ImposedVelocities impvel(md, frames);
    double t = 0;
    for (int k = 0; k < 10; ++k) {
      zero_forces(s);
      cycle(s, dt);
      (void)impvel.apply(s, t, dt, dt);  // a constant step: dt12 = dt as the update below
      update(s, dt);
      t += dt;
      CHECK(close(r * s.vx[0] + r * s.vy[0], 3.0, 1e-14));  // along y'
      CHECK(close(r * s.vx[0] - r * s.vy[0], 0.0, 1e-14));  // along x': no force, no motion
      CHECK(s.vz[0] == 0.25);
    }
  }
  SECTION("/INIVEL/TRA in a skew: v = sum of V_k along x', y', z'") {
    auto md = one_node();
    m::InitialVelocity iv;
    iv.id = 1;
    iv.v = {1.0, 2.0, 3.0};
    iv.skew = 5;
    iv.group = 0;
    md.initial_velocities.push_back(iv);
    auto s = state(md);
    const sv::SkewFrames frames(md);
    sv::InitialVelocities inivel(md, frames);
    (void)inivel.apply(s, 0.0);
    CHECK(close(s.vx[0], r * 1.0 + r * 2.0, 1e-15));
    CHECK(close(s.vy[0], -r * 1.0 + r * 2.0, 1e-15));
    CHECK(close(s.vz[0], 3.0, 1e-15));
  }
  SECTION("/CLOAD along x': F x' on the node, power F (v.x')") {
    auto md = one_node();
    m::ConcentratedLoad c;
    c.id = 1;
    c.function = 0;
    c.dir = 0;
    c.skew = 5;
    c.group = 0;
    c.fscale_y = 4.0;
    md.concentrated_loads.push_back(c);
    auto s = state(md);
    s.vx[0] = 1.0;  // v.x' = 1/sqrt2
    const sv::SkewFrames frames(md);
    sv::ExternalLoads loads(md, frames);
    zero_forces(s);
    (void)loads.apply(s, 0.0, dt);
    CHECK(close(s.fx[0], 4.0 * r, 1e-15));
    CHECK(close(s.fy[0], -4.0 * r, 1e-15));
    CHECK(s.fz[0] == 0.0);
    CHECK(close(loads.concentrated_load_work(dt), 4.0 * r * dt, 1e-15));
  }
}

TEST_CASE("two /BCS with one id are both applied, OR-ed, with a warning (OpenRadioss reads them silently)",
          "[skew][bcs]") {
  // OpenRadioss's QA deck LOIS/LOI13/solide defines /BCS/1 twice on two node groups; its listing applies
  // both.
  std::string s = radx::test::begin_block(2026, "Mg mm s") + "/NODE\n";
  for (int k = 0; k < 4; ++k)
    s += Line().put(k + 1, 1, 10).put(k % 2 == 1 ? 1.0 : 0.0, 11, 30).put(k >= 2 ? 1.0 : 0.0, 31, 50).str() +
         "\n";
  s += "/SHELL/1\n" + Line().put(1, 1, 10).put(1, 11, 20).put(2, 21, 30).put(4, 31, 40).put(3, 41, 50).str();
  s += "\n/PART/1\nplate\n" + Line().put(1, 1, 10).put(1, 11, 20).str() + "\n";
  s += "/PROP/SHELL/1\nshell\n\n\n" + Line().put(1.0, 21, 40).str() + "\n";
  s += "/MAT/LAW1/1\nsteel\n" + Line().put(7.85e-9, 1, 20).str() + "\n" +
       Line().put(210000.0, 1, 20).put(0.3, 21, 40).str() + "\n";
  s += "/GRNOD/NODE/2\na\n" + Line().put(1, 1, 10).put(2, 11, 20).str() + "\n";
  s += "/GRNOD/NODE/3\nb\n" + Line().put(2, 1, 10).put(3, 11, 20).str() + "\n";
  s += "/BCS/1\nfirst\n" + Line().put("100 000", 1, 10).put(0, 11, 20).put(2, 21, 30).str() + "\n";
  s += "/BCS/1\nsecond\n" + Line().put("010 000", 1, 10).put(0, 11, 20).put(3, 21, 30).str() + "\n/END\n";
  radx::test::TempDir dir;
  radx::Diagnostics diags;
  const auto deck = radx::read_starter_deck(dir.write("b_0000.rad", s), diags);
  const auto md = radx::build_model(deck, diags);
  bool warned = false;
  for (const auto& d : diags.items()) {
    INFO(radx::Diagnostics::format(d));
    CHECK(d.severity != radx::Severity::Error);
    warned = warned || (d.code == radx::Diag::DuplicateId && d.severity == radx::Severity::Warning);
  }
  CHECK(warned);
  REQUIRE(md.bcs.size() == 2u);
  // Node 2 is in both groups: X from the first, Y from the second.
  sv::NodeState st;
  st.resize(md.nodes.size());
  const sv::SkewFrames frames(md);
  sv::BoundaryConditions bcs(md, frames);
  bcs.set_fixed_bits(st);
  CHECK(st.fixed[0] == 0b001);
  CHECK(st.fixed[1] == 0b011);
  CHECK(st.fixed[2] == 0b010);
  CHECK(st.fixed[3] == 0);
}
