// Lagrange-multiplier contact benchmark (contact/lagrange_contact.hpp). Requirement: assemble, factorise and
// solve 10,000 switched rows in under 20 ms on one thread with the symbolic analysis reused.
// Synthetic contact: a main surface of N x N unit quadrangles on (N+1)^2 free main nodes (mass 1e-3) at rest,
// and N*N free secondary nodes (mass 2e-3), one above each segment at the local point (0.3, -0.2), normal
// (0,0,1), distance 0.5 inside a gap of 1, area 1, law 0 with Fric 0.1. The secondary nodes close at
// v_z = -10 (and slide at v_x = 1 so that friction acts), a0 = 0, dt12 = dt2 = 1e-6: every row is active.
// Scenario 1 calls solve() R times on the same solver and pattern (the first call analyses, the others reuse
// the analysis); scenario 2 drops a different row each time, so every call analyses again.
// The solver is single-threaded (CHOLMOD simplicial, no BLAS); OMP_NUM_THREADS does not matter.
// Usage: radx_bench_lagrange [N=100] [R=50]   (bench/lagrange_solve.sh builds and runs it)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "contact/lagrange_contact.hpp"

using namespace radx::contact;
using Clock = std::chrono::steady_clock;

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

struct State {
  std::vector<double> mass, vx, vy, vz, ax, ay, az;
  std::vector<std::uint8_t> fixed;
  void reset(std::size_t nmain) {
    const std::size_t n = mass.size();
    vx.assign(n, 0.0), vy.assign(n, 0.0), vz.assign(n, 0.0);
    ax.assign(n, 0.0), ay.assign(n, 0.0), az.assign(n, 0.0);
    for (std::size_t i = nmain; i < n; ++i) vx[i] = 1.0, vz[i] = -10.0;
  }
  LagrangeNodes view() { return {mass, vx, vy, vz, ax, ay, az, fixed}; }
};

}  // namespace

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 100;
  const int reps = argc > 2 ? std::atoi(argv[2]) : 50;
  if (n < 1 || reps < 2) {
    std::fprintf(stderr, "usage: %s [N >= 1] [R >= 2]\n", argv[0]);
    return 2;
  }
  const double dt = 1e-6, xi = 0.3, eta = -0.2;
  const auto nmain = static_cast<std::size_t>((n + 1) * (n + 1));
  const auto nrows = static_cast<std::size_t>(n * n);
  State s;
  s.mass.assign(nmain, 1e-3);
  s.mass.resize(nmain + nrows, 2e-3);
  s.fixed.assign(nmain + nrows, 0);
  std::vector<SwitchedPair> pairs(nrows);
  const std::array<double, 4> h{0.25 * (1 - xi) * (1 - eta), 0.25 * (1 + xi) * (1 - eta),
                                0.25 * (1 + xi) * (1 + eta), 0.25 * (1 - xi) * (1 + eta)};
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      auto& p = pairs[static_cast<std::size_t>(j * n + i)];
      const int c = j * (n + 1) + i;
      p.node = static_cast<std::int32_t>(nmain) + j * n + i;
      p.seg = {c, c + 1, c + n + 2, c + n + 1};
      p.h = h;
      p.n = {0.0, 0.0, 1.0};
      p.distance = 0.5, p.gap = 1.0, p.area = 1.0, p.law = 0;
    }
  const std::vector<FrictionLaw> laws{{0, 0.1, {}}};
  std::vector<PairForce> out(nrows);

  // Scenario 1: same pattern every call.
  LagrangeSolver solver;
  std::vector<double> ms;
  LagrangeStats before{};
  for (int r = 0; r < reps; ++r) {
    s.reset(nmain);
    if (r == 1) before = solver.stats();
    const auto t0 = Clock::now();
    solver.solve(pairs, laws, s.view(), dt, dt, out);
    ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
  }
  const LagrangeStats& st = solver.stats();
  const std::vector<double> later(ms.begin() + 1, ms.end());
  const double per = 1e3 / static_cast<double>(reps - 1);
  // Sanity: gap rate at the end of the step (target 0, from -10) and every lambda > 0.
  double rate_max = 0;
  bool all_positive = true;
  for (std::size_t k = 0; k < nrows; ++k) {
    const auto& p = pairs[k];
    const auto sn = static_cast<std::size_t>(p.node);
    double g = s.vz[sn] + dt * s.az[sn];
    for (std::size_t j = 0; j < 4; ++j) {
      const auto m = static_cast<std::size_t>(p.seg[j]);
      g -= p.h[j] * (s.vz[m] + dt * s.az[m]);
    }
    rate_max = std::max(rate_max, std::abs(g));
    all_positive = all_positive && out[k].lambda > 0;
  }
  std::printf("rows %lld, nonzeros %lld (N = %d, %d calls)\n", static_cast<long long>(st.rows_last),
              static_cast<long long>(st.nonzeros_last), n, reps);
  std::printf("first call (symbolic analysis): %.3f ms\n", ms[0]);
  std::printf("reuse: median %.3f ms, min %.3f ms\n", median(later),
              *std::min_element(later.begin(), later.end()));
  std::printf("  per call: assembly %.3f ms, factorisation %.3f ms, solve %.3f ms\n",
              per * (st.seconds_assembly - before.seconds_assembly),
              per * (st.seconds_factorization - before.seconds_factorization),
              per * (st.seconds_solve - before.seconds_solve));
  std::printf("  analyses %lld, symbolic reuses %lld, factorisations %lld, passes max %d\n",
              static_cast<long long>(st.analyses), static_cast<long long>(st.symbolic_reuses),
              static_cast<long long>(st.factorizations), st.passes_max);
  std::printf("  sanity: max |gap rate| / 10 = %.3e, all lambda > 0: %s\n", rate_max / 10.0,
              all_positive ? "yes" : "NO");

  // Scenario 2: a different row dropped each call, so the pattern changes and nothing is reused.
  LagrangeSolver fresh;
  std::vector<double> ms2;
  std::vector<SwitchedPair> fewer(nrows - 1);
  std::vector<PairForce> out2(nrows - 1);
  for (int r = 0; r < reps; ++r) {
    const auto drop = static_cast<std::size_t>(r) % nrows;
    std::copy(pairs.begin(), pairs.begin() + static_cast<std::ptrdiff_t>(drop), fewer.begin());
    std::copy(pairs.begin() + static_cast<std::ptrdiff_t>(drop) + 1, pairs.end(),
              fewer.begin() + static_cast<std::ptrdiff_t>(drop));
    s.reset(nmain);
    const auto t0 = Clock::now();
    fresh.solve(fewer, laws, s.view(), dt, dt, out2);
    ms2.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
  }
  std::printf("no reuse (pattern changes every call): median %.3f ms, analyses %lld, reuses %lld\n",
              median(ms2), static_cast<long long>(fresh.stats().analyses),
              static_cast<long long>(fresh.stats().symbolic_reuses));
  return 0;
}
