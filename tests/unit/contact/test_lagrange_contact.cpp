// The Lagrange-multiplier system of switched LAGDT pairs (contact/lagrange_contact.hpp) and its CHOLMOD
// wrapper (contact/cholmod_gram.hpp), against closed forms: a perfectly inelastic impact (common speed and
// kinetic-energy loss), momentum, the active set (no row pulls), redundant rows, Coulomb friction after the
// switch; and the wrapper against a dense solve, with a singular system and a failed allocation.
#include <SuiteSparse_config.h>

#include <Eigen/Dense>
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "contact/cholmod_gram.hpp"
#include "contact/lagrange_contact.hpp"

using radx::contact::FrictionLaw;
using radx::contact::LagrangeNodes;
using radx::contact::LagrangeSolver;
using radx::contact::PairForce;
using radx::contact::SwitchedPair;

namespace {

// A small node state: node 0 the secondary node, nodes 1..4 a square main segment (unit normal +z).
struct Nodes {
  std::vector<double> m, vx, vy, vz, ax, ay, az;
  std::vector<std::uint8_t> fixed;
  explicit Nodes(std::size_t n)
      : m(n, 1.0), vx(n, 0.0), vy(n, 0.0), vz(n, 0.0), ax(n, 0.0), ay(n, 0.0), az(n, 0.0), fixed(n, 0) {}
  LagrangeNodes view() { return LagrangeNodes{m, vx, vy, vz, ax, ay, az, fixed}; }
  // v^{n+1/2} = v^{n-1/2} + dt12 a
  double vz_end(std::size_t k, double dt12) const { return vz[k] + dt12 * az[k]; }
  double vx_end(std::size_t k, double dt12) const { return vx[k] + dt12 * ax[k]; }
};

SwitchedPair pair_on_square(std::int32_t node, std::array<double, 4> h, double distance = 0.5,
                            double gap = 1.0) {
  SwitchedPair p;
  p.node = node;
  p.seg = {1, 2, 3, 4};
  p.h = h;
  p.n = {0, 0, 1};
  p.distance = distance;
  p.gap = gap;
  p.area = 1.0;
  p.law = 0;
  return p;
}

const std::array<double, 4> kCentre{0.25, 0.25, 0.25, 0.25};

}  // namespace

TEST_CASE(
    "two masses meeting through a switched pair: common speed and kinetic-energy loss of a perfectly "
    "inelastic impact",
    "[lagrange]") {
  // Secondary node (m1) at -V against the centre of a square segment (four nodes of m2/4) at +U.
  const double m1 = 2.5, m2 = 7.0, V = 30.0, U = 4.0, dt = 1e-6;
  Nodes s(5);
  s.m[0] = m1;
  s.vz[0] = -V;
  for (std::size_t k = 1; k <= 4; ++k) {
    s.m[k] = m2 / 4;
    s.vz[k] = U;
  }
  const std::vector<SwitchedPair> pairs{pair_on_square(0, kCentre)};
  const std::vector<FrictionLaw> laws(1);
  std::vector<PairForce> out(1);
  LagrangeSolver solver;
  solver.solve(pairs, laws, s.view(), dt, dt, out);
  const double vc = (m1 * -V + m2 * U) / (m1 + m2);  // momentum conservation
  for (std::size_t k = 0; k <= 4; ++k) CHECK(s.vz_end(k, dt) == Approx(vc).epsilon(1e-10));
  double ke0 = 0.5 * m1 * V * V + 0.5 * m2 * U * U, ke1 = 0;
  for (std::size_t k = 0; k <= 4; ++k) ke1 += 0.5 * s.m[k] * std::pow(s.vz_end(k, dt), 2);
  const double mu = m1 * m2 / (m1 + m2);
  CHECK(ke0 - ke1 == Approx(0.5 * mu * (V + U) * (V + U)).epsilon(1e-10));
  // The multiplier is the impulse over the step: lambda dt12 = m1 (vc + V).
  CHECK(out[0].lambda * dt == Approx(m1 * (vc + V)).epsilon(1e-10));
}

TEST_CASE("an off-centre switched pair stops the approach and conserves momentum", "[lagrange]") {
  const double dt = 2e-6;
  Nodes s(5);
  s.m = {1.3, 0.4, 0.7, 0.5, 0.9};
  s.vz = {-12.0, 1.0, 0.5, -0.25, 2.0};
  s.vx = {3.0, 0.0, 0.0, 0.0, 0.0};
  s.az = {-9.81, 100.0, 0.0, -50.0, 0.0};
  const std::array<double, 4> h{0.1, 0.2, 0.3, 0.4};
  const std::vector<SwitchedPair> pairs{pair_on_square(0, h)};
  const std::vector<FrictionLaw> laws(1);
  std::vector<PairForce> out(1);
  double p0 = 0;
  for (std::size_t k = 0; k < 5; ++k) p0 += s.m[k] * s.vz_end(k, dt);  // momentum with a0: the external part
  LagrangeSolver solver;
  solver.solve(pairs, laws, s.view(), dt, dt, out);
  double rate = s.vz_end(0, dt), p1 = 0;
  for (std::size_t j = 0; j < 4; ++j) rate -= h[j] * s.vz_end(j + 1, dt);
  for (std::size_t k = 0; k < 5; ++k) p1 += s.m[k] * s.vz_end(k, dt);
  CHECK(std::abs(rate) <= 1e-12 * 12.0);   // the gap rate at the end of the step is zero
  CHECK(p1 == Approx(p0).epsilon(1e-12));  // the multiplier is an internal force
  CHECK(out[0].lambda > 0);
  CHECK(s.vx_end(0, dt) == 3.0);  // no friction law: the tangential motion is untouched
}

TEST_CASE("a pair outside its gap may close down to the gap within the step, no further", "[lagrange]") {
  const double dt = 1e-3, g = 1.0, d = 1.004;
  Nodes s(5);
  s.vz[0] = -10.0;  // would close 10 mm in the step, 4 um are allowed
  for (std::size_t k = 1; k <= 4; ++k) s.fixed[k] = 7;
  const std::vector<SwitchedPair> pairs{pair_on_square(0, kCentre, d, g)};
  std::vector<PairForce> out(1);
  LagrangeSolver solver;
  solver.solve(pairs, std::vector<FrictionLaw>(1), s.view(), dt, dt, out);
  CHECK(d + dt * s.vz_end(0, dt) == Approx(g).epsilon(1e-12));
}

TEST_CASE("the active set releases a row that would pull and keeps every multiplier non-negative",
          "[lagrange]") {
  // A light segment between a heavy fast node and a light slow one, both approaching: holding both would
  // make the slow node's multiplier pull it down; it is released and stays approachable but not violated.
  const double dt = 1e-6;
  Nodes s(6);
  for (std::size_t k = 1; k <= 4; ++k) s.m[k] = 0.25;
  s.m[0] = 100.0;
  s.vz[0] = -10.0;
  s.m[5] = 1.0;
  s.vz[5] = -1.0;
  const std::vector<SwitchedPair> pairs{pair_on_square(0, kCentre), pair_on_square(5, kCentre)};
  std::vector<PairForce> out(2);
  LagrangeSolver solver;
  solver.solve(pairs, std::vector<FrictionLaw>(1), s.view(), dt, dt, out);
  CHECK(out[0].lambda > 0);
  CHECK(out[1].lambda == 0.0);
  const double v_seg = s.vz_end(1, dt);
  CHECK(s.vz_end(0, dt) == Approx(v_seg).epsilon(1e-12));
  CHECK(s.vz_end(5, dt) - v_seg > 0);  // the released row is not violated
  CHECK(v_seg == Approx((100.0 * -10.0) / 101.0).epsilon(1e-12));
  CHECK(solver.stats().passes_max >= 2);

  SECTION("a separating pair gets no force at all") {
    Nodes t(5);
    t.vz[0] = 2.0;
    std::vector<PairForce> o(1);
    LagrangeSolver sv;
    sv.solve(std::vector<SwitchedPair>{pair_on_square(0, kCentre)}, std::vector<FrictionLaw>(1), t.view(), dt,
             dt, o);
    CHECK(o[0].lambda == 0.0);
    CHECK(t.az[0] == 0.0);
  }
}

TEST_CASE("redundant rows: duplicates merged, rows without a free degree of freedom dropped, fixed segments",
          "[lagrange]") {
  const double dt = 1e-6;
  SECTION("the same pair from two interfaces is one row") {
    Nodes s(5);
    s.vz[0] = -5.0;
    const auto p = pair_on_square(0, kCentre);
    std::vector<PairForce> out(2);
    LagrangeSolver solver;
    solver.solve(std::vector<SwitchedPair>{p, p}, std::vector<FrictionLaw>(1), s.view(), dt, dt, out);
    CHECK(solver.stats().merged_rows == 1);
    CHECK(solver.stats().regularisations == 0);
    CHECK(out[0].lambda + out[1].lambda == Approx(1.0 * 4.0 / 5.0 * 5.0 / dt).epsilon(1e-10));  // mu V / dt
    CHECK(s.vz_end(0, dt) == Approx(s.vz_end(1, dt)).epsilon(1e-12));
  }
  SECTION("a node against a fully fixed segment stops; a pair with every node fixed is dropped") {
    Nodes s(6);
    s.vz[0] = -5.0;
    s.vz[5] = -1.0;
    s.fixed = {0, 7, 7, 7, 7, 7};
    std::vector<PairForce> out(2);
    LagrangeSolver solver;
    solver.solve(std::vector<SwitchedPair>{pair_on_square(0, kCentre), pair_on_square(5, kCentre)},
                 std::vector<FrictionLaw>(1), s.view(), dt, dt, out);
    CHECK(std::abs(s.vz_end(0, dt)) <= 1e-12 * 5.0);
    CHECK(out[0].lambda == Approx(5.0 / dt).epsilon(1e-12));
    CHECK(out[1].lambda == 0.0);
    CHECK(solver.stats().dropped_rows == 1);
    for (std::size_t k = 1; k <= 4; ++k) CHECK(s.az[k] == 0.0);
  }
  SECTION("a node on the edge shared by two coplanar segments: the two rows are one") {
    // Node 0 above the edge 2-3 shared by segments 1-2-3-4 and 2-5-6-3: h = 1/2 on the edge nodes of both,
    // so both rows hold +n on node 0 and -n/2 on nodes 2 and 3; kept apart they would make S singular.
    Nodes s(7);
    s.vz[0] = -5.0;
    SwitchedPair a = pair_on_square(0, {0.0, 0.5, 0.5, 0.0});
    SwitchedPair b = a;
    b.seg = {2, 5, 6, 3};
    b.h = {0.5, 0.0, 0.0, 0.5};
    std::vector<PairForce> out(2);
    LagrangeSolver solver;
    solver.solve(std::vector<SwitchedPair>{a, b}, std::vector<FrictionLaw>(1), s.view(), dt, dt, out);
    CHECK(solver.stats().merged_rows == 1);
    CHECK(solver.stats().regularisations == 0);
    CHECK(std::abs(s.vz_end(0, dt) - 0.5 * (s.vz_end(2, dt) + s.vz_end(3, dt))) <= 1e-12 * 5.0);
    double p = 0;
    for (std::size_t k = 0; k < 7; ++k) p += s.m[k] * s.vz_end(k, dt);
    CHECK(p == Approx(-5.0).epsilon(1e-12));
  }
}

TEST_CASE("friction after the switch: sliding decelerates at mu g, a slow slide sticks", "[lagrange]") {
  // A node of mass m pressed on a fixed segment by gravity (a0 = -g), sliding along x.
  const double m = 3.0, g = 9.81, mu = 0.3, dt = 1e-5;
  std::vector<FrictionLaw> laws(1);
  laws[0].fric = mu;
  auto run = [&](double v0) {
    Nodes s(5);
    s.m[0] = m;
    s.vx[0] = v0;
    s.az[0] = -g;
    for (std::size_t k = 1; k <= 4; ++k) s.fixed[k] = 7;
    std::vector<PairForce> out(1);
    LagrangeSolver solver;
    solver.solve(std::vector<SwitchedPair>{pair_on_square(0, kCentre)}, laws, s.view(), dt, dt, out);
    CHECK(out[0].lambda == Approx(m * g).epsilon(1e-12));
    return std::pair{s, out[0]};
  };
  const auto [sliding, f] = run(2.0);
  CHECK(sliding.ax[0] == Approx(-mu * g).epsilon(1e-12));
  CHECK(f.friction[0] == Approx(-mu * m * g).epsilon(1e-12));
  const auto [sticking, f2] = run(1e-6);  // stopping it needs m v / dt = 0.3 N < mu m g
  CHECK(std::abs(sticking.vx_end(0, dt)) <= 1e-15);
  CHECK(std::abs(f2.friction[0]) < mu * m * g);
}

TEST_CASE("CHOLMOD wrapper: A A^T solves as the dense system, the symbolic analysis is reused",
          "[lagrange][cholmod]") {
  // A: 3 rows x 4 columns, compressed columns.
  radx::contact::SparseColumns a;
  a.nrows = 3;
  a.ncols = 4;
  a.col_ptr = {0, 2, 4, 5, 7};
  a.row_index = {0, 1, 0, 2, 1, 1, 2};
  a.value = {1.0, 2.0, -1.0, 0.5, 3.0, 1.5, -2.0};
  auto dense = [](const radx::contact::SparseColumns& s) {
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(s.nrows, s.ncols);
    for (int c = 0; c < s.ncols; ++c)
      for (int q = s.col_ptr[static_cast<std::size_t>(c)]; q < s.col_ptr[static_cast<std::size_t>(c) + 1];
           ++q)
        A(s.row_index[static_cast<std::size_t>(q)], c) = s.value[static_cast<std::size_t>(q)];
    return Eigen::MatrixXd(A * A.transpose());
  };
  const std::vector<double> b{1.0, -2.0, 0.5};
  std::vector<double> x(3);
  radx::contact::GramFactor f;
  CHECK_FALSE(f.factorize(a));
  f.solve(b, x);
  const Eigen::Vector3d ref = dense(a).ldlt().solve(Eigen::Vector3d(b[0], b[1], b[2]));
  for (int k = 0; k < 3; ++k) CHECK(x[static_cast<std::size_t>(k)] == Approx(ref(k)).epsilon(1e-12));
  CHECK(f.beta() == 0.0);
  a.value = {2.0, 1.0, -3.0, 0.25, 1.0, 0.5, -1.0};
  CHECK(f.factorize(a));  // same pattern: reused
  f.solve(b, x);
  const Eigen::Vector3d ref2 = dense(a).ldlt().solve(Eigen::Vector3d(b[0], b[1], b[2]));
  for (int k = 0; k < 3; ++k) CHECK(x[static_cast<std::size_t>(k)] == Approx(ref2(k)).epsilon(1e-12));
  CHECK(f.counters().analyses == 1);
  CHECK(f.counters().reuses == 1);
}

TEST_CASE("CHOLMOD wrapper: a singular system gets a reported regularisation and a finite answer",
          "[lagrange][cholmod]") {
  // Rows 0 and 1 are the same: S = A A^T has rank 1.
  radx::contact::SparseColumns a;
  a.nrows = 2;
  a.ncols = 2;
  a.col_ptr = {0, 2, 4};
  a.row_index = {0, 1, 0, 1};
  a.value = {1.0, 1.0, 2.0, 2.0};
  radx::contact::GramFactor f;
  f.factorize(a);
  CHECK(f.beta() > 0);
  CHECK(f.beta() <= 1e-8 * 5.0);  // a small fraction of the diagonal S_rr = 5
  CHECK(f.counters().regularisations == 1);
  std::vector<double> x(2);
  f.solve(std::vector<double>{5.0, 5.0}, x);
  CHECK(std::isfinite(x[0]));
  CHECK(std::isfinite(x[1]));
  // The regularised system (S + beta I) x = b holds: 5 (x0 + x1) + beta x_k = 5.
  for (std::size_t k = 0; k < 2; ++k)
    CHECK(5.0 * (x[0] + x[1]) + f.beta() * x[k] == Approx(5.0).epsilon(1e-6));
}

namespace {
void* failing_malloc(std::size_t) {
  return nullptr;
}
void* failing_calloc(std::size_t, std::size_t) {
  return nullptr;
}
}  // namespace

TEST_CASE("CHOLMOD wrapper: a failed allocation becomes an error message", "[lagrange][cholmod]") {
  radx::contact::SparseColumns a;
  a.nrows = 1;
  a.ncols = 1;
  a.col_ptr = {0, 1};
  a.row_index = {0};
  a.value = {2.0};
  radx::contact::GramFactor f;
  auto* saved_malloc = SuiteSparse_config.malloc_func;
  auto* saved_calloc = SuiteSparse_config.calloc_func;
  SuiteSparse_config.malloc_func = failing_malloc;
  SuiteSparse_config.calloc_func = failing_calloc;
  std::string message;
  try {
    f.factorize(a);
  } catch (const radx::contact::CholmodError& e) {
    message = e.what();
  }
  SuiteSparse_config.malloc_func = saved_malloc;
  SuiteSparse_config.calloc_func = saved_calloc;
  CHECK(message.find("out of memory") != std::string::npos);
  CHECK(message.find("CHOLMOD") != std::string::npos);
}
