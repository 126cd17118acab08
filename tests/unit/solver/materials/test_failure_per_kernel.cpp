// Failure wiring of the kernels QEPH (Ishell 24), QBAT (Ishell 12), HEPH (Isolid 24), the fully integrated
// brick (Isolid 14), the tetrahedron and the 20-node brick with law 36 Eps_p_max and LAW2 + /FAIL/JOHNSON,
// each driven in tension by imposed nodal velocities on fixed nodes (a constant strain increment per cycle),
// against the rules written at the top of solver/materials/fail_johnson.cpp and
// solver/elements/shell/shell_section.hpp:
//  * shells: deleted at once (off 0) in the cycle the section says so (next_off with fail_now);
//  * solids: off 0.8 in the failure cycle, 0.8 x off per cycle after it, 0 in the first cycle starting below
//    0.1 (brick_next_off): 0.8^10 = 0.107 >= 0.1 > 0.8^11 = 0.086, so deleted 11 cycles after the trigger;
//  * /FAIL/JOHNSON with D2 = D3 = D4 = D5 = 0: eps_f = D1 at any triaxiality, D = eps_p / D1.
// Units: MPa, mm, s.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

#include "solver/elements/element_groups.hpp"
#include "solver/engine/node_state.hpp"
#include "solver/materials/material_point.hpp"
#include "solver/model/geometry.hpp"
#include "solver/model/hex20_shape.hpp"

using radx::model::Function;
using radx::model::Material;
using radx::model::MaterialLaw;
using namespace radx::solver;

namespace {

constexpr std::size_t G = kGroupSize;
using P3 = std::array<double, 3>;

constexpr double kEpsMax = 0.01;  // law 36 Eps_p_max
constexpr double kD1 = 0.02;      // /FAIL/JOHNSON D1: the failure strain
// D and eps_p / D1 are sums of the same few hundred plastic increments (one divided by D1 term by term):
// their relative difference is round-off of those sums, far below 1e-11.
constexpr double kSumRound = 1e-11;
// "Crossing" bounds: eps_p before the failure cycle is at most D1 and after it at least D1, up to the same
// round-off of a sum (1e-9 relative is generous and still 1e5 times below one cycle's increment of ~1e-4).
constexpr double kCross = 1e-9;

Function curve(std::vector<double> x, std::vector<double> y) {
  Function f;
  f.x = std::move(x);
  f.y = std::move(y);
  return f;
}

Material steel() {
  Material m;
  m.rho = 7.85e-9;
  m.young = 210000.0;
  m.poisson = 0.3;
  return m;
}

// Law 36 on one hardening curve (200 MPa at eps_p 0 .. 400 at 1) with Eps_p_max 0.01.
const MaterialParams& law36() {
  static const std::vector<Function> fns = {
      curve({0.0, 0.05, 0.1, 0.3, 1.0}, {200.0, 260.0, 300.0, 350.0, 400.0})};
  static std::vector<TabCurve> curves;
  static const MaterialParams p = [] {
    Material m = steel();
    m.law = MaterialLaw::PlasTab;
    m.tab.function_id = {1};
    m.tab.function = {0};
    m.tab.scale = {1.0};
    m.tab.rate = {0.0};
    m.eps_p_max = kEpsMax;
    return make_material_params(m, fns, curves);
  }();
  return p;
}

// LAW2 (a 200, b 1000, n 1, no rate effect, no Eps_p_max) with /FAIL/JOHNSON D1 = 0.02, D2..D5 = 0 (Ifail_sh
// and Ifail_so default to 1: delete). d4 > 0 only for the test of the shells' rate term.
MaterialParams law2_johnson(double d4 = 0.0) {
  Material m = steel();
  m.law = MaterialLaw::JohnsonCook;
  m.a = 200.0;
  m.b = 1000.0;
  m.n = 1.0;
  m.fail_jc.on = true;
  m.fail_jc.d1 = kD1;
  m.fail_jc.d4 = d4;
  m.fail_jc.eps_dot_0 = 1.0;
  return make_material_params(m);
}

// ---- shells -------------------------------------------------------------------------------------------

const char* name(ShellKernel k) {
  return k == ShellKernel::Qbat ? "QBAT" : "QEPH";
}

// One 10 x 10 square, thickness 1, three points; x velocity 500 x: a membrane strain of 5e-4 per cycle
// (dt 1e-6) at every Gauss point and every point through the thickness.
struct ShellCase {
  NodeState s;
  ShellGroup g;
};

ShellCase shell_case(ShellKernel kernel) {
  ShellCase c;
  const double a = 10.0;
  const std::vector<P3> xyz = {{0, 0, 0}, {a, 0, 0}, {a, a, 0}, {0, a, 0}};
  c.s.resize(4);
  for (std::size_t k = 0; k < 4; ++k) {
    c.s.x[k] = c.s.x0[k] = xyz[k][0];
    c.s.y[k] = c.s.y0[k] = xyz[k][1];
    c.s.z[k] = c.s.z0[k] = xyz[k][2];
    c.s.vx[k] = 500.0 * xyz[k][0];
  }
  c.g.allocate(1, 3, kernel == ShellKernel::Qbat ? 4 : 1, kernel == ShellKernel::Qeph ? 24 : 3);
  c.g.kernel = kernel;
  c.g.props.ishell = kernel == ShellKernel::Qbat ? 12 : 24;
  if (kernel == ShellKernel::Qeph) c.g.props.dn = c.g.props.dm = 0.015;
  for (std::size_t k = 0; k < 4; ++k) c.g.conn[k * G] = static_cast<std::int32_t>(k);
  c.g.t0[0] = c.g.thick[0] = 1.0;
  return c;
}

void run_shell(ShellCase& c, const MaterialParams& mat) {
  CycleInfo cyc;
  cyc.dt1 = cyc.dt2 = 1e-6;
  if (c.g.kernel == ShellKernel::Qbat)
    shell_qbat_forces(c.g, c.s, mat, cyc);
  else
    shell_qeph_forces(c.g, c.s, mat, cyc);
}

// Rows of element 0 in the point arrays (eps_p, dmg): [gauss][point] for QBAT, [point] for QEPH.
std::size_t shell_rows(const ShellGroup& g) {
  return g.eps_p.size() / G;
}

double shell_max_eps_p(const ShellGroup& g) {
  double m = 0;
  for (std::size_t r = 0; r < shell_rows(g); ++r) m = std::max(m, g.eps_p[r * G]);
  return m;
}

double max_abs(std::span<const double> v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

// ---- solids -------------------------------------------------------------------------------------------

enum class Solid { OnePoint, Heph, Full14, Tetra, Hex20 };
const char* name(Solid k) {
  switch (k) {
    case Solid::OnePoint: return "one-point brick (Isolid 1)";
    case Solid::Heph: return "HEPH (Isolid 24)";
    case Solid::Full14: return "fully integrated (Isolid 14)";
    case Solid::Tetra: return "tetra4";
    case Solid::Hex20: return "20-node brick (Isolid 16)";
  }
  return "";
}

// One cycle of a solid: the element factor, the largest point plastic strain and damage, and the largest
// relative gap |D - eps_p / D1| / max(D, 1e-300) over the points.
struct SolidRec {
  double off = 1, eps_p = 0, dmg = 0, dmg_gap = 0, dmg_elem = 0;
  double f_max = 0;  // largest nodal force component of the cycle
};

// Isochoric stretch v = (10 x, -5 y, -5 z) on fixed nodes, dt1 1e-5: a strain increment of 1e-4 along x per
// cycle, the same at every integration point (linear field).
std::vector<SolidRec> drive_solid(Solid kind, const MaterialParams& mat, int cycles) {
  CycleInfo cyc;
  cyc.dt1 = 1e-5;
  auto velocities = [](NodeState& ns) {
    for (std::size_t k = 0; k < ns.x.size(); ++k) {
      ns.vx[k] = 10.0 * ns.x[k];
      ns.vy[k] = -5.0 * ns.y[k];
      ns.vz[k] = -5.0 * ns.z[k];
    }
  };
  auto nodes = [&](const std::vector<P3>& pts) {
    NodeState ns;
    ns.resize(pts.size());
    for (std::size_t k = 0; k < pts.size(); ++k) {
      ns.x[k] = ns.x0[k] = pts[k][0];
      ns.y[k] = ns.y0[k] = pts[k][1];
      ns.z[k] = ns.z0[k] = pts[k][2];
    }
    velocities(ns);
    return ns;
  };
  auto gap = [](double d, double e) { return std::abs(d - e / kD1) / std::max(d, 1e-300); };
  auto f_max = [](std::span<const double> f) {
    double m = 0;
    for (std::size_t r = 0; r < f.size() / G; ++r) m = std::max(m, std::abs(f[r * G]));
    return m;
  };
  std::vector<SolidRec> out;
  if (kind == Solid::Tetra) {
    const NodeState ns = nodes({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
    TetraGroup g;
    g.allocate(1);
    // Nodes 1 and 3 swapped, as the starter orders them, for a positive volume.
    const std::array<std::int32_t, 4> conn = {0, 3, 2, 1};
    for (std::size_t k = 0; k < 4; ++k) g.conn[k * G] = conn[k];
    g.vol0[0] = g.vol[0] = radx::model::tetra_volume({0, 0, 0}, {0, 0, 1}, {0, 1, 0}, {1, 0, 0});
    REQUIRE(g.vol0[0] > 0);
    g.rho[0] = mat.rho0;
    for (int n = 0; n < cycles && g.off[0] > 0; ++n) {
      tetra4_forces(g, ns, mat, cyc);
      out.push_back(
          {g.off[0], g.eps_p[0], g.dmg[0], gap(g.dmg[0], g.eps_p[0]), g.dmg[0], f_max(g.nodal_force)});
    }
    return out;
  }
  if (kind == Solid::Hex20) {
    // The unit cube's 20 nodes (corners, then the mid-side nodes in /BRIC20's order), 2 x 2 x 2 points.
    std::vector<P3> pts;
    double x0[20][3];
    for (std::size_t k = 0; k < 20; ++k) {
      for (std::size_t d = 0; d < 3; ++d) x0[k][d] = 0.5 * (1 + radx::model::kHex20Nat[k][d]);
      pts.push_back({x0[k][0], x0[k][1], x0[k][2]});
    }
    const NodeState ns = nodes(pts);
    Hex20Group g;
    g.allocate(1);
    for (std::size_t k = 0; k < 20; ++k) g.conn[k * G] = static_cast<std::int32_t>(k);
    hex20_init_geometry(g, 0, x0);
    g.rho[0] = mat.rho0;
    for (int n = 0; n < cycles && g.off[0] > 0; ++n) {
      hex20_forces(g, ns, mat, cyc);
      SolidRec r;
      r.off = g.off[0];
      r.dmg_elem = g.dmg[0];
      for (std::size_t p = 0; p < 8; ++p) {
        const double e = g.eps_p_p[p * G], d = g.dmg_p[p * G];
        r.eps_p = std::max(r.eps_p, e);
        r.dmg = std::max(r.dmg, d);
        r.dmg_gap = std::max(r.dmg_gap, gap(d, e));
      }
      r.f_max = f_max(g.nodal_force);
      out.push_back(r);
    }
    return out;
  }
  const std::vector<P3> pts = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                               {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const NodeState ns = nodes(pts);
  BrickGroup g;
  g.allocate(1);
  for (std::size_t k = 0; k < 8; ++k) g.conn[k * G] = static_cast<std::int32_t>(k);
  if (kind == Solid::Heph || kind == Solid::OnePoint) {
    if (kind == Solid::Heph) {
      g.isolid = 24;
      g.iframe = 2;
    }
    std::array<radx::model::Vec3, 8> xe;
    for (std::size_t k = 0; k < 8; ++k) xe[k] = {pts[k][0], pts[k][1], pts[k][2]};
    g.vol0[0] = g.vol[0] = radx::model::brick_volume(xe);
  } else {
    radx::model::SolidProperty prop;
    prop.isolid = 14;
    prop.iframe = 2;
    resolve_full_brick(prop, mat, g);
    REQUIRE(g.n_points == 8);
    double x[8][3], vp[8];
    for (std::size_t k = 0; k < 8; ++k)
      for (std::size_t d = 0; d < 3; ++d) x[k][d] = pts[k][d];
    hex8_full_point_volumes(x, vp);
    double v = 0;
    for (std::size_t p = 0; p < 8; ++p) {
      g.vol0_p[p * G] = vp[p];
      v += vp[p];
    }
    g.vol0[0] = g.vol[0] = v;
  }
  g.rho[0] = mat.rho0;
  for (int n = 0; n < cycles && g.off[0] > 0; ++n) {
    SolidRec r;
    if (kind == Solid::Heph || kind == Solid::OnePoint) {
      if (kind == Solid::Heph)
        hex8_heph_forces(g, ns, mat, cyc);
      else
        hex8_forces(g, ns, mat, cyc);
      r = {g.off[0], g.eps_p[0], g.dmg[0], gap(g.dmg[0], g.eps_p[0]), g.dmg[0], 0.0};
    } else {
      hex8_full_forces(g, ns, mat, cyc);
      r.off = g.off[0];
      r.dmg_elem = g.dmg[0];
      for (std::size_t p = 0; p < 8; ++p) {
        const double e = g.eps_p_p[p * G], d = g.dmg_p[p * G];
        r.eps_p = std::max(r.eps_p, e);
        r.dmg = std::max(r.dmg, d);
        r.dmg_gap = std::max(r.dmg_gap, gap(d, e));
      }
    }
    r.f_max = f_max(g.nodal_force);
    out.push_back(r);
  }
  return out;
}

// The factors after the trigger cycle t: off(t + k) = 0.8^(k + 1) for k = 0 .. 10, off(t + 11) = 0. The
// kernel multiplies by 0.8 eleven times; std::pow rounds once: 1e-14 relative covers those roundings.
void check_decay(const std::vector<SolidRec>& rec, std::size_t trigger) {
  REQUIRE(rec.size() == trigger + 12);  // the drive stops at off 0
  for (std::size_t k = 0; k <= 10; ++k) {
    INFO("cycle " << k << " after the trigger");
    CHECK(std::abs(rec[trigger + k].off - std::pow(0.8, static_cast<double>(k + 1))) <= 1e-14);
  }
  CHECK(rec[trigger + 11].off == 0.0);
}

std::size_t first_below_one(const std::vector<SolidRec>& rec) {
  for (std::size_t n = 0; n < rec.size(); ++n)
    if (rec[n].off < 1.0) return n;
  return rec.size();
}

}  // namespace

TEST_CASE("failwire: QEPH and QBAT with law 36 Eps_p_max are deleted in the cycle a point exceeds it",
          "[failwire][shell]") {
  const MaterialParams& mat = law36();
  // One section per kernel: a failed REQUIRE ends only that kernel's run.
  for (ShellKernel kernel : {ShellKernel::Qeph, ShellKernel::Qbat}) DYNAMIC_SECTION(name(kernel)) {
      ShellCase c = shell_case(kernel);
      int trigger = -1;
      double ep_before = 0;
      for (int cycle = 0; cycle < 200 && trigger < 0; ++cycle) {
        ep_before = shell_max_eps_p(c.g);
        run_shell(c, mat);
        if (c.g.off[0] < 1.0) trigger = cycle;
      }
      INFO("trigger cycle " << trigger << ", eps_p " << ep_before << " -> " << shell_max_eps_p(c.g));
      REQUIRE(trigger > 0);
      // Straight from 1 to 0 (no 0.8 decay): the section's verdict, an exact 0.
      CHECK(c.g.off[0] == 0.0);
      // The trigger is the cycle in which the largest point eps_p passes 0.01 (strictly above, sigeps36.F).
      CHECK(ep_before <= kEpsMax);
      CHECK(shell_max_eps_p(c.g) > kEpsMax);
      // Deleted in that very cycle: it gives no force (off 0 scales the forces), nor in the next one, whose
      // step is infinite.
      CHECK(max_abs(c.g.nodal_force) == 0.0);
      run_shell(c, mat);
      CHECK(max_abs(c.g.nodal_force) == 0.0);
      CHECK(std::isinf(c.g.dt[0]));
    }
}

TEST_CASE("failwire: QEPH and QBAT with LAW2 + FAIL/JOHNSON: D = eps_p / D1, deleted when eps_p crosses D1",
          "[failwire][shell]") {
  const MaterialParams mat = law2_johnson();
  // One section per kernel: a failed REQUIRE ends only that kernel's run.
  for (ShellKernel kernel : {ShellKernel::Qeph, ShellKernel::Qbat}) DYNAMIC_SECTION(name(kernel)) {
      ShellCase c = shell_case(kernel);
      const std::size_t rows = shell_rows(c.g);
      REQUIRE(rows == (kernel == ShellKernel::Qbat ? 12u : 3u));
      int trigger = -1, plastic = 0;
      double ep_before = 0, worst_gap = 0;
      for (int cycle = 0; cycle < 400 && trigger < 0; ++cycle) {
        ep_before = shell_max_eps_p(c.g);
        run_shell(c, mat);
        if (c.g.off[0] < 1.0) {
          trigger = cycle;
          break;
        }
        bool failed_point = false;
        for (std::size_t r = 0; r < rows; ++r) {
          const double e = c.g.eps_p[r * G], d = c.g.dmg[r * G];
          failed_point = failed_point || d >= 1.0;
          if (e == 0) {
            CHECK(d == 0.0);
            continue;
          }
          ++plastic;
          worst_gap = std::max(worst_gap, std::abs(d - e / kD1) / d);
        }
        if (failed_point) {
          FAIL_CHECK("a point has D = 1 and the element is still alive (cycle " << cycle << ")");
          break;
        }
      }
      INFO("trigger cycle " << trigger << ", eps_p " << ep_before << " -> " << shell_max_eps_p(c.g)
                            << ", worst |D - eps_p/D1| / D " << worst_gap);
      REQUIRE(trigger > 0);
      CHECK(plastic > 0);
      CHECK(worst_gap <= kSumRound);
      // Ifail_sh 1: deleted at once (off exactly 0) when a point's D reaches 1, i.e. when eps_p crosses D1.
      CHECK(c.g.off[0] == 0.0);
      double dmax = 0;
      for (std::size_t r = 0; r < rows; ++r) dmax = std::max(dmax, c.g.dmg[r * G]);
      CHECK(dmax == 1.0);                      // capped at 1 exactly
      CHECK(max_abs(c.g.nodal_force) == 0.0);  // deleted in this cycle: no force
      CHECK(ep_before < kD1 * (1 + kCross));
      CHECK(shell_max_eps_p(c.g) >= kD1 * (1 - kCross));
    }
}

TEST_CASE("failwire: QEPH and QBAT pass the element strain rate to FAIL/JOHNSON's D4 term",
          "[failwire][shell]") {
  // D4 = 0.05, rate0 = 1: eps_f = D1 (1 + D4 ln(rate)), the rate being the element's (Fcut 0: unfiltered),
  // 500 sqrt(4/3) = 577 1/s for this stretch (up to the half-step geometry, a few 1e-4): eps_f = 1.32 D1.
  // D = eps_p / eps_f with the rate the kernel stored (round-off of the sums); with the rate left out it
  // would be eps_p / D1, 32 % larger.
  const MaterialParams mat = law2_johnson(0.05);
  // One section per kernel: a failed REQUIRE ends only that kernel's run.
  for (ShellKernel kernel : {ShellKernel::Qeph, ShellKernel::Qbat}) DYNAMIC_SECTION(name(kernel)) {
      ShellCase c = shell_case(kernel);
      double worst_gap = 0;
      int plastic = 0;
      for (int cycle = 0; cycle < 30; ++cycle) {
        run_shell(c, mat);
        const double rate = c.g.rate[0];
        CHECK(std::abs(rate - 500.0 * std::sqrt(4.0 / 3.0)) <= 1e-3 * rate);
        const double eps_f = kD1 * (1.0 + 0.05 * std::log(rate));
        for (std::size_t r = 0; r < shell_rows(c.g); ++r) {
          const double e = c.g.eps_p[r * G], d = c.g.dmg[r * G];
          if (e == 0) continue;
          ++plastic;
          worst_gap = std::max(worst_gap, std::abs(d - e / eps_f) / d);
        }
      }
      INFO("worst |D - eps_p/eps_f| / D " << worst_gap);
      CHECK(plastic > 0);
      CHECK(worst_gap <= kSumRound);
    }
}

TEST_CASE(
    "failwire: HEPH, Isolid 14, tetra4 and the 20-node brick with law 36 Eps_p_max: 0.8 at the trigger, "
    "0.8^k, deleted",
    "[failwire][brick][tetra][hex20]") {
  const MaterialParams& mat = law36();
  // One section per kernel: a failed REQUIRE ends only that kernel's run.
  for (Solid kind : {Solid::Heph, Solid::Full14, Solid::Tetra, Solid::Hex20}) DYNAMIC_SECTION(name(kind)) {
      const auto rec = drive_solid(kind, mat, 400);
      const std::size_t t = first_below_one(rec);
      REQUIRE(t > 0);
      REQUIRE(t < rec.size());
      INFO("trigger cycle " << t << ", eps_p " << rec[t - 1].eps_p << " -> " << rec[t].eps_p);
      // The cycle in which the largest point eps_p passes Eps_p_max (strictly above) sets 0.8 exactly.
      CHECK(rec[t - 1].eps_p <= kEpsMax);
      CHECK(rec[t].eps_p > kEpsMax);
      CHECK(rec[t].off == 0.8);
      check_decay(rec, t);
    }
}

TEST_CASE(
    "failwire: HEPH, Isolid 14, tetra4 and the 20-node brick with LAW2 + FAIL/JOHNSON: D = eps_p / D1, "
    "then the decay",
    "[failwire][brick][tetra][hex20]") {
  const MaterialParams mat = law2_johnson();
  // One section per kernel: a failed REQUIRE ends only that kernel's run.
  for (Solid kind : {Solid::Heph, Solid::Full14, Solid::Tetra, Solid::Hex20}) DYNAMIC_SECTION(name(kind)) {
      const auto rec = drive_solid(kind, mat, 600);
      const std::size_t t = first_below_one(rec);
      REQUIRE(t > 0);
      REQUIRE(t < rec.size());
      double worst_gap = 0;
      int plastic = 0;
      for (std::size_t n = 0; n < t; ++n) {
        CHECK(rec[n].dmg < 1.0);
        CHECK(rec[n].dmg_elem == rec[n].dmg);  // the element's damage is its largest point damage
        if (rec[n].eps_p == 0) continue;
        ++plastic;
        worst_gap = std::max(worst_gap, rec[n].dmg_gap);
      }
      INFO("trigger cycle " << t << ", eps_p " << rec[t - 1].eps_p << " -> " << rec[t].eps_p
                            << ", worst |D - eps_p/D1| / D " << worst_gap);
      CHECK(plastic > 100);
      CHECK(worst_gap <= kSumRound);
      // Ifail_so 1: D reaches 1 (capped exactly) in the cycle eps_p crosses D1; the element takes 0.8.
      CHECK(rec[t].dmg == 1.0);
      CHECK(rec[t - 1].eps_p < kD1 * (1 + kCross));
      CHECK(rec[t].eps_p >= kD1 * (1 - kCross));
      CHECK(rec[t].off == 0.8);
      check_decay(rec, t);
    }
}

TEST_CASE("failwire: HEPH limits its hourglass stresses by law 36's tabulated flow stress",
          "[failwire][heph]") {
  // solid_yield_stress of law 36 is the table's flow stress: on the curve at eps_p 0.075 halfway between
  // (0.05, 260) and (0.1, 300): 280, and 300 at the point 0.1 (round-off of one interpolation).
  const MaterialParams& p36 = law36();
  CHECK(std::abs(solid_yield_stress(p36, 0.075, 0.0) - 280.0) <= 1e-12 * 280.0);
  CHECK(std::abs(solid_yield_stress(p36, 0.1, 0.0) - 300.0) <= 1e-12 * 300.0);
  CHECK(solid_yield_stress(p36, 0.075, 0.0) == tab_flow_stress(p36, 0.075, 0.0));

  // In the kernel: the warping mode of a unit cube (test_hex8_heph.cpp) driven for 50 steps, LAW1, LAW2 with
  // a flat flow stress of 10 (a 10, b 0) and law 36 on the flat curve 10. The mode has no strain at the
  // centre, so both plastic laws carry no stress and limit the hourglass stresses by the same 10: the same
  // forces to round-off, and (limited) under half the elastic force after 50 steps.
  const double young = 1e6, nu = 0.3;
  Material base;
  base.rho = 1.0;
  base.young = young;
  base.poisson = nu;
  Material el = base;
  el.law = MaterialLaw::Elastic;
  Material jc = base;
  jc.law = MaterialLaw::JohnsonCook;
  jc.a = 10.0;
  jc.b = 0.0;
  jc.n = 1.0;
  Material tab = base;
  tab.law = MaterialLaw::PlasTab;
  tab.tab.function_id = {1};
  tab.tab.function = {0};
  tab.tab.scale = {1.0};
  tab.tab.rate = {0.0};
  const std::vector<Function> flat = {curve({0.0, 1.0}, {10.0, 10.0})};
  std::vector<TabCurve> curves;
  const MaterialParams m36 = make_material_params(tab, flat, curves);
  CHECK(solid_yield_stress(m36, 0.0, 0.0) == 10.0);

  constexpr double m1[8] = {1, 1, -1, -1, -1, -1, 1, 1};
  const double u0 = 2.6e-6, dt1 = 1e-4;
  auto drive = [&](const MaterialParams& mat) {
    std::vector<double> fx;
    const std::vector<P3> pts = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                 {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    NodeState ns;
    ns.resize(8);
    BrickGroup g;
    g.allocate(1);
    g.isolid = 24;
    g.iframe = 2;
    std::array<radx::model::Vec3, 8> xe;
    for (std::size_t k = 0; k < 8; ++k) {
      ns.x[k] = ns.x0[k] = pts[k][0];
      ns.y[k] = ns.y0[k] = pts[k][1];
      ns.z[k] = ns.z0[k] = pts[k][2];
      g.conn[k * G] = static_cast<std::int32_t>(k);
      xe[k] = {pts[k][0], pts[k][1], pts[k][2]};
    }
    g.vol0[0] = g.vol[0] = radx::model::brick_volume(xe);
    g.rho[0] = mat.rho0;
    g.dn = 0.0;  // no viscous part: the force is the stored hourglass stress only
    CycleInfo cyc;
    cyc.dt1 = dt1;
    for (int step = 0; step < 50; ++step) {
      for (std::size_t k = 0; k < 8; ++k) {
        ns.vx[k] = u0 / dt1 * m1[k];
        if (step > 0) ns.x[k] += u0 * m1[k];
      }
      hex8_heph_forces(g, ns, mat, cyc);
      fx.push_back(-g.nodal_force[(0 * 3 + 0) * G]);  // node 1 (m1 = +1): the force opposes the mode
    }
    return fx;
  };
  const auto f_el = drive(make_material_params(el));
  const auto f_jc = drive(make_material_params(jc));
  const auto f_36 = drive(m36);
  for (std::size_t s = 0; s < f_el.size(); ++s) {
    INFO("step " << s << ": LAW1 " << f_el[s] << ", LAW2 " << f_jc[s] << ", law 36 " << f_36[s]);
    // Same flow stress, same stresses: the same hourglass force up to round-off (1e-12 relative).
    CHECK(std::abs(f_36[s] - f_jc[s]) <= 1e-12 * std::abs(f_jc[s]));
  }
  INFO("after 50 steps: LAW1 " << f_el.back() << ", law 36 " << f_36.back());
  CHECK(f_36.back() < 0.5 * f_el.back());
}

TEST_CASE("failwire: a failing solid's forces take the new factor in the same cycle, as the one-point brick",
          "[failwire][brick][tetra]") {
  // The one-point brick (hex8_fb.cpp) scales the forces and energies of a cycle by the factor that cycle
  // sets: 0.8 in the failure cycle, 0.8^(k+1) k cycles later, and no force at all in the cycle that deletes
  // it (the element reported deleted pushes on no node). The new kernels must do the same. The stress of
  // consecutive cycles differs by one cycle's hardening (H d_eps_p ~ 0.1 MPa on ~220 MPa, 5e-4 relative), so
  // the force ratio of two cycles is the ratio of their factors within 2e-3.
  const MaterialParams mat = law2_johnson();
  for (Solid kind : {Solid::OnePoint, Solid::Heph, Solid::Full14, Solid::Tetra, Solid::Hex20})
    DYNAMIC_SECTION(name(kind)) {
      const auto rec = drive_solid(kind, mat, 600);
      const std::size_t t = first_below_one(rec);
      REQUIRE(t > 0);
      REQUIRE(rec.size() == t + 12);
      REQUIRE(rec[t - 1].f_max > 0);
      INFO("forces: before " << rec[t - 1].f_max << ", trigger " << rec[t].f_max << ", next "
                             << rec[t + 1].f_max << ", deletion cycle " << rec[t + 11].f_max);
      CHECK(std::abs(rec[t].f_max / rec[t - 1].f_max - 0.8) <= 2e-3);
      CHECK(std::abs(rec[t + 1].f_max / rec[t].f_max - 0.8) <= 2e-3);
      CHECK(rec[t + 11].f_max == 0.0);
    }
}
