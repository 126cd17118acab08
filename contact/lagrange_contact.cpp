// Lagrange multipliers of switched LAGDT pairs (docs/theory/type7-lagdt.md section 6), one call per cycle
// after a0 = f / m.
//
// Row r of a pair (secondary node s, contact point sum h_j x_j, unit normal n from the surface to s): the
// normal gap rate  gdot_r = J_r v = n . (v_s - sum_j h_j v_j), i.e. J_r holds +n on s and -h_j n on each main
// node: the 15 coefficients of a node-to-quadrangle row (12 for a triangle).
// Velocities at the end of the step: v^{n+1/2} = v^{n-1/2} + dt12 a, a = a0 + M^-1 J^T lambda (lumped M; a
// translation held by a boundary condition has zero inverse mass and a0 = 0 there).
// Target, at the velocity level with the closing allowed by the position:
//     gdot_r(v^{n+1/2}) >= -c_r / dt2,   c_r = max(0, d_r - g_r),
// so that the predicted distance at the end of the step d + dt2 gdot stays >= min(d, g): a pair inside its
// gap (where LAGDT pairs switch, before they reach the surface) may not close any further, and a pair still
// outside may close only down to the gap. Why not push the node back out to the gap (the position-level
// form): the penetration already present is what the penalty held before the switch; removing it in one
// step would turn it into a rebound velocity the model never had (energy from nothing). The target never
// asks for separation, so the multipliers only ever dissipate energy, as a perfectly inelastic impact.
// Active rows satisfy the target with equality:
//     S lambda = (t - J v_pred) / dt12,   S = J M^-1 J^T = A A^T,   A = J M^-1/2,   v_pred = v^{n-1/2} + dt12
//     a0,
// factorised by CHOLMOD (cholmod_gram.hpp). Active set: rows whose target is violated by v_pred start
// active; rows with lambda < 0 (they would pull) are released and the system solved again; released rows
// that the correction makes violate their target come back; at most kMaxPasses passes, then lambda is
// clamped to >= 0. A released row keeps its place in A with zero coefficients and a unit entry in its own
// extra column (S_rr = 1, lambda_r = 0), so the pattern of A, hence the symbolic analysis, does not change
// with the active set.
// Rows with no free degree of freedom are dropped; a row identical to another (two interfaces holding the
// same node against the same segment) is merged into it.
// Friction after the switch (this project's addition; Radioss has none): Coulomb, |F_t| <= mu lambda with mu
// by the interface's Ifric law at pressure lambda / area, applied row by row in order (a deterministic
// Gauss-Seidel sweep): the force that stops the tangential relative velocity at the end of the step,
//     F_stick,d = -v_t,d / (dt12 w_d),  w_d = w_s,d + sum_j h_j^2 w_j,d  (w the inverse masses),
// projected on the tangent plane and scaled down to mu lambda when longer (sliding). A /CTCLAW friction law
// bounds it instead by its own force at the slip speed v_t and the pressure lambda / A_s
// (docs/theory/contact-laws.md section 5): exact Coulomb mu lambda, the regularised laws their smaller force
// at low slip; the one-directional laws keep only the component along the segment's first tangent.
#include "contact/lagrange_contact.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

#include "contact/cholmod_gram.hpp"
#include "contact/type7_laws.hpp"

namespace radx::contact {

namespace {

using model::Vec3;
using Clock = std::chrono::steady_clock;
constexpr int kMaxPasses = 20;
constexpr double kSameRow = 1e-9;  // coefficients equal to this (relative to 1) make a duplicate row

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// A row in canonical form: its nodes ascending (a node met twice has its coefficients summed).
struct Row {
  std::int32_t pair = -1;
  int count = 0;
  std::array<std::int32_t, 5> node{};
  std::array<double, 5> coef{};  // gdot = sum_k coef_k n . v_node_k
  Vec3 n{};
  double allowed = 0;  // c_r: closing allowed within the step
};

Row make_row(const SwitchedPair& p, std::int32_t index) {
  Row r;
  r.pair = index;
  r.n = p.n;
  r.allowed = std::max(0.0, p.distance - p.gap);
  auto put = [&](std::int32_t node, double c) {
    for (int k = 0; k < r.count; ++k)
      if (r.node[static_cast<std::size_t>(k)] == node) {
        r.coef[static_cast<std::size_t>(k)] += c;
        return;
      }
    r.node[static_cast<std::size_t>(r.count)] = node;
    r.coef[static_cast<std::size_t>(r.count)] = c;
    ++r.count;
  };
  put(p.node, 1.0);
  const bool triangle = p.seg[3] == p.seg[2];
  for (std::size_t j = 0; j < (triangle ? 3u : 4u); ++j)
    if (p.h[j] != 0) put(p.seg[j], -p.h[j]);
  // Ascending nodes (insertion sort of at most five).
  for (int a = 1; a < r.count; ++a)
    for (int b = a; b > 0 && r.node[static_cast<std::size_t>(b - 1)] > r.node[static_cast<std::size_t>(b)];
         --b) {
      std::swap(r.node[static_cast<std::size_t>(b - 1)], r.node[static_cast<std::size_t>(b)]);
      std::swap(r.coef[static_cast<std::size_t>(b - 1)], r.coef[static_cast<std::size_t>(b)]);
    }
  return r;
}

bool same_nodes(const Row& a, const Row& b) {
  if (a.count != b.count) return false;
  for (std::size_t k = 0; k < static_cast<std::size_t>(a.count); ++k)
    if (a.node[k] != b.node[k]) return false;
  return true;
}

bool same_row(const Row& a, const Row& b) {
  if (!same_nodes(a, b)) return false;
  for (std::size_t k = 0; k < static_cast<std::size_t>(a.count); ++k)
    if (std::abs(a.coef[k] - b.coef[k]) > kSameRow) return false;
  for (std::size_t d = 0; d < 3; ++d)
    if (std::abs(a.n[d] - b.n[d]) > kSameRow) return false;
  return true;
}

bool row_less(const Row& a, const Row& b) {
  const auto na = static_cast<std::size_t>(a.count), nb = static_cast<std::size_t>(b.count);
  for (std::size_t k = 0; k < std::min(na, nb); ++k)
    if (a.node[k] != b.node[k]) return a.node[k] < b.node[k];
  if (na != nb) return na < nb;
  return a.pair < b.pair;
}

}  // namespace

struct LagrangeSolver::Impl {
  GramFactor factor;
  LagrangeStats stats;
  // Work arrays, kept between cycles so that a steady contact allocates nothing.
  std::vector<Row> rows;
  std::vector<std::int32_t> local;        // per model node: index among the row nodes, -1
  std::vector<std::int32_t> local_nodes;  // model node of each local index
  std::vector<std::array<int, 3>> cols;   // per local node: column of each dof, -1 when held
  std::vector<std::int32_t> col_node;     // per dof column: local node
  std::vector<std::uint8_t> col_dof;      // per dof column: 0, 1, 2
  std::vector<double> col_winv_sqrt;      // per dof column: 1 / sqrt(m)
  SparseColumns a;
  std::vector<double> a_base;  // values of A with every row active
  std::vector<double> rate0, target, rhs, lambda, delta;
  std::vector<std::uint8_t> active;

  void number_columns(const LagrangeNodes& nodes) {
    local_nodes.clear();
    cols.clear();
    col_node.clear();
    col_dof.clear();
    col_winv_sqrt.clear();
    for (const auto& r : rows)
      for (std::size_t k = 0; k < static_cast<std::size_t>(r.count); ++k) {
        const auto n = static_cast<std::size_t>(r.node[k]);
        if (local[n] >= 0) continue;
        local[n] = static_cast<std::int32_t>(local_nodes.size());
        local_nodes.push_back(r.node[k]);
        std::array<int, 3> c{-1, -1, -1};
        const double m = nodes.mass[n];
        for (unsigned d = 0; d < 3; ++d)
          if (m > 0 && !(nodes.fixed[n] & (1u << d))) {
            c[d] = static_cast<int>(col_node.size());
            col_node.push_back(local[n]);
            col_dof.push_back(static_cast<std::uint8_t>(d));
            col_winv_sqrt.push_back(1.0 / std::sqrt(m));
          }
        cols.push_back(c);
      }
  }

  bool has_free_dof(const Row& r, const LagrangeNodes& nodes) const {
    for (std::size_t k = 0; k < static_cast<std::size_t>(r.count); ++k) {
      const auto n = static_cast<std::size_t>(r.node[k]);
      if (nodes.mass[n] > 0 && (nodes.fixed[n] & 7u) != 7u && r.coef[k] != 0) return true;
    }
    return false;
  }

  // The pattern and values of A = J M^-1/2 (dof columns) followed by one release column per row.
  void assemble_a() {
    const int ndof = static_cast<int>(col_node.size());
    const int nrows = static_cast<int>(rows.size());
    a.nrows = nrows;
    a.ncols = ndof + nrows;
    a.col_ptr.assign(static_cast<std::size_t>(a.ncols) + 1, 0);
    for (const auto& r : rows)
      for (std::size_t k = 0; k < static_cast<std::size_t>(r.count); ++k)
        for (const int c : cols[static_cast<std::size_t>(local[static_cast<std::size_t>(r.node[k])])])
          if (c >= 0) ++a.col_ptr[static_cast<std::size_t>(c) + 1];
    for (int r = 0; r < nrows; ++r) a.col_ptr[static_cast<std::size_t>(ndof + r) + 1] = 1;
    for (std::size_t c = 0; c < static_cast<std::size_t>(a.ncols); ++c) a.col_ptr[c + 1] += a.col_ptr[c];
    const auto nnz = static_cast<std::size_t>(a.col_ptr.back());
    a.row_index.resize(nnz);
    a_base.resize(nnz);
    std::vector<int> next(a.col_ptr.begin(), a.col_ptr.end() - 1);
    for (std::size_t ri = 0; ri < rows.size(); ++ri) {
      const auto& r = rows[ri];
      for (std::size_t k = 0; k < static_cast<std::size_t>(r.count); ++k) {
        const auto& c3 = cols[static_cast<std::size_t>(local[static_cast<std::size_t>(r.node[k])])];
        for (std::size_t d = 0; d < 3; ++d) {
          const int c = c3[d];
          if (c < 0) continue;
          const auto slot = static_cast<std::size_t>(next[static_cast<std::size_t>(c)]++);
          a.row_index[slot] = static_cast<int>(ri);
          a_base[slot] = r.coef[k] * r.n[d] * col_winv_sqrt[static_cast<std::size_t>(c)];
        }
      }
      const auto slot = static_cast<std::size_t>(next[static_cast<std::size_t>(ndof) + ri]++);
      a.row_index[slot] = static_cast<int>(ri);
      a_base[slot] = 0.0;
    }
    a.value.resize(nnz);
  }

  // Values of A for the current active set: a released row has zero coefficients and 1 in its column.
  void set_active_values() {
    const int ndof = static_cast<int>(col_node.size());
    for (int c = 0; c < a.ncols; ++c)
      for (int q = a.col_ptr[static_cast<std::size_t>(c)]; q < a.col_ptr[static_cast<std::size_t>(c) + 1];
           ++q) {
        const auto k = static_cast<std::size_t>(q);
        const bool on = active[static_cast<std::size_t>(a.row_index[k])] != 0;
        a.value[k] = c < ndof ? (on ? a_base[k] : 0.0) : (on ? 0.0 : 1.0);
      }
  }

  // delta = M^-1 J^T lambda per dof column.
  void corrections() {
    const int ndof = static_cast<int>(col_node.size());
    delta.assign(static_cast<std::size_t>(ndof), 0.0);
    for (int c = 0; c < ndof; ++c) {
      double s = 0;
      for (int q = a.col_ptr[static_cast<std::size_t>(c)]; q < a.col_ptr[static_cast<std::size_t>(c) + 1];
           ++q)
        s += a_base[static_cast<std::size_t>(q)] *
             lambda[static_cast<std::size_t>(a.row_index[static_cast<std::size_t>(q)])];
      delta[static_cast<std::size_t>(c)] = s * col_winv_sqrt[static_cast<std::size_t>(c)];
    }
  }

  // Gap rate of row r at the end of the step with a0 (+ delta when given).
  double rate(const Row& r, const LagrangeNodes& nodes, double dt12, bool with_delta) const {
    double g = 0;
    for (std::size_t k = 0; k < static_cast<std::size_t>(r.count); ++k) {
      const auto n = static_cast<std::size_t>(r.node[k]);
      const auto& c3 = cols[static_cast<std::size_t>(local[n])];
      const double v[3] = {nodes.vx[n], nodes.vy[n], nodes.vz[n]};
      const double acc[3] = {nodes.ax[n], nodes.ay[n], nodes.az[n]};
      double vn = 0;
      for (std::size_t d = 0; d < 3; ++d) {
        const int c = c3[d];
        double ad = c >= 0 ? acc[d] : 0.0;
        if (with_delta && c >= 0) ad += delta[static_cast<std::size_t>(c)];
        vn += r.n[d] * (v[d] + dt12 * ad);
      }
      g += r.coef[k] * vn;
    }
    return g;
  }

  void friction(std::span<const FrictionLaw> laws, std::span<const SwitchedPair> pairs,
                const LagrangeNodes& nodes, double dt12, std::span<PairForce> out) {
    for (std::size_t ri = 0; ri < rows.size(); ++ri) {
      const double lam = lambda[ri];
      if (!(lam > 0)) continue;
      const auto& r = rows[ri];
      const auto& p = pairs[static_cast<std::size_t>(r.pair)];
      const auto& law = laws[static_cast<std::size_t>(p.law)];
      const auto kind = law.ctclaw.friction;
      if (kind == model::FrictionLaw::Interface ? !(law.fric > 0 || law.ifric > 0)
                                                : kind == model::FrictionLaw::None)
        continue;
      Vec3 vr{}, w{};
      for (std::size_t k = 0; k < static_cast<std::size_t>(r.count); ++k) {
        const auto n = static_cast<std::size_t>(r.node[k]);
        const auto& c3 = cols[static_cast<std::size_t>(local[n])];
        const double v[3] = {nodes.vx[n] + dt12 * nodes.ax[n], nodes.vy[n] + dt12 * nodes.ay[n],
                             nodes.vz[n] + dt12 * nodes.az[n]};
        for (std::size_t d = 0; d < 3; ++d) {
          vr[d] += r.coef[k] * v[d];
          if (c3[d] >= 0) w[d] += r.coef[k] * r.coef[k] / nodes.mass[n];
        }
      }
      const Vec3 vt = model::sub(vr, model::scale(r.n, model::dot(vr, r.n)));
      Vec3 f{};
      for (std::size_t d = 0; d < 3; ++d) f[d] = w[d] > 0 ? -vt[d] / (dt12 * w[d]) : 0.0;
      f = model::sub(f, model::scale(r.n, model::dot(f, r.n)));
      // One-directional /CTCLAW friction acts along the first tangent only, and is judged at that slip speed.
      const bool along_t1 = kind != model::FrictionLaw::Interface && !law.ctclaw.bidirectional;
      if (along_t1) f = model::scale(p.t1, model::dot(f, p.t1));
      const double len = model::norm(f);
      if (!(len > 0)) continue;
      const double pressure = p.area > 0 ? lam / p.area : 0.0;
      const double slip = along_t1 ? std::abs(model::dot(vt, p.t1)) : model::norm(vt);
      const double cap =
          kind == model::FrictionLaw::Interface
              ? std::max(0.0, friction_coefficient(law.ifric, law.fric, law.c, pressure, model::norm(vt))) *
                    lam
              : friction_traction(law.ctclaw, slip, pressure) * p.area;
      if (len > cap) f = model::scale(f, cap / len);
      for (std::size_t k = 0; k < static_cast<std::size_t>(r.count); ++k) {
        const auto n = static_cast<std::size_t>(r.node[k]);
        const auto& c3 = cols[static_cast<std::size_t>(local[n])];
        const double s = r.coef[k] / nodes.mass[n];
        if (c3[0] >= 0) nodes.ax[n] += s * f[0];
        if (c3[1] >= 0) nodes.ay[n] += s * f[1];
        if (c3[2] >= 0) nodes.az[n] += s * f[2];
      }
      out[static_cast<std::size_t>(r.pair)].friction = f;
    }
  }

  // Rows: canonical, ordered, duplicates merged, rows without a free degree of freedom dropped.
  void build_rows(std::span<const SwitchedPair> pairs, const LagrangeNodes& nodes) {
    rows.clear();
    for (std::size_t k = 0; k < pairs.size(); ++k) {
      Row r = make_row(pairs[k], static_cast<std::int32_t>(k));
      if (!has_free_dof(r, nodes)) {
        ++stats.dropped_rows;
        continue;
      }
      rows.push_back(r);
    }
    std::sort(rows.begin(), rows.end(), row_less);
    std::size_t kept = 0;
    for (std::size_t k = 0; k < rows.size(); ++k) {
      if (kept > 0 && same_row(rows[kept - 1], rows[k])) {
        rows[kept - 1].allowed = std::min(rows[kept - 1].allowed, rows[k].allowed);
        ++stats.merged_rows;
        continue;
      }
      rows[kept++] = rows[k];
    }
    rows.resize(kept);
  }

  // The gap rates with a0 alone, the targets, and the first active set: the rows whose target a0 violates.
  // Sets the tolerance of the comparisons with the targets; true when a row starts active.
  bool start_active_set(const LagrangeNodes& nodes, double dt12, double dt2, double& tol) {
    const std::size_t nr = rows.size();
    rate0.resize(nr);
    target.resize(nr);
    active.assign(nr, 0);
    double scale = 0;
    for (std::size_t r = 0; r < nr; ++r) {
      rate0[r] = rate(rows[r], nodes, dt12, false);
      target[r] = -rows[r].allowed / dt2;
      scale = std::max({scale, std::abs(rate0[r]), std::abs(target[r])});
    }
    tol = 1e-12 * scale + 1e-300;
    bool any = false;
    for (std::size_t r = 0; r < nr; ++r) {
      active[r] = rate0[r] < target[r] - tol ? 1 : 0;
      any = any || active[r];
    }
    return any;
  }

  void count_rows() {
    const std::size_t nr = rows.size();
    ++stats.cycles;
    stats.rows_last = static_cast<std::int64_t>(nr);
    stats.rows_max = std::max(stats.rows_max, stats.rows_last);
    stats.rows_total += stats.rows_last;
    stats.nonzeros_last = static_cast<std::int64_t>(a.col_ptr.back()) - static_cast<std::int64_t>(nr);
    stats.nonzeros_max = std::max(stats.nonzeros_max, stats.nonzeros_last);
  }

  // The active-set passes from the first active set (`any`: it is not empty): solve, release the rows that
  // would pull, then bring back the released rows the correction makes violate their target, until the set
  // stops changing or kMaxPasses. Returns whether it stopped changing; `passes` receives the passes made.
  bool run_active_set(const LagrangeNodes& nodes, double dt12, double tol, bool any, int& passes) {
    auto& st = stats;
    const std::size_t nr = rows.size();
    lambda.assign(nr, 0.0);
    rhs.resize(nr);
    passes = 0;
    bool converged = !any;
    while (any && passes < kMaxPasses) {
      ++passes;
      auto tf = Clock::now();
      set_active_values();
      factor.factorize(a);
      st.seconds_factorization += seconds_since(tf);
      const auto ts = Clock::now();
      for (std::size_t r = 0; r < nr; ++r) rhs[r] = active[r] ? (target[r] - rate0[r]) / dt12 : 0.0;
      factor.solve(rhs, lambda);
      bool changed = false;
      for (std::size_t r = 0; r < nr; ++r)
        if (active[r] && lambda[r] < 0) {
          active[r] = 0;
          changed = true;
        }
      if (!changed) {
        corrections();
        for (std::size_t r = 0; r < nr; ++r)
          if (!active[r] && rate(rows[r], nodes, dt12, true) < target[r] - tol) {
            active[r] = 1;
            changed = true;
          }
      }
      st.seconds_solve += seconds_since(ts);
      if (!changed) {
        converged = true;
        break;
      }
    }
    return converged;
  }

  // The multipliers of the active rows (clamped to >= 0, which matters when the passes did not converge)
  // into the accelerations and into out.
  void apply_multipliers(const LagrangeNodes& nodes, std::span<PairForce> out) {
    const std::size_t nr = rows.size();
    for (std::size_t r = 0; r < nr; ++r) lambda[r] = active[r] ? std::max(0.0, lambda[r]) : 0.0;
    corrections();
    for (std::size_t c = 0; c < delta.size(); ++c) {
      const auto n = static_cast<std::size_t>(local_nodes[static_cast<std::size_t>(col_node[c])]);
      auto& acc = col_dof[c] == 0 ? nodes.ax : col_dof[c] == 1 ? nodes.ay : nodes.az;
      acc[n] += delta[c];
    }
    for (std::size_t r = 0; r < nr; ++r) out[static_cast<std::size_t>(rows[r].pair)].lambda = lambda[r];
  }

  void count_passes(int passes) {
    auto& st = stats;
    st.active_set_passes += passes;
    st.passes_max = std::max(st.passes_max, passes);
    const auto& fc = factor.counters();
    st.analyses = fc.analyses;
    st.symbolic_reuses = fc.reuses;
    st.factorizations = fc.factorizations;
    st.regularisations = fc.regularisations;
    st.beta_max = fc.beta_max;
  }
};

LagrangeSolver::LagrangeSolver() : impl_(std::make_unique<Impl>()) {}
LagrangeSolver::~LagrangeSolver() = default;

const LagrangeStats& LagrangeSolver::stats() const {
  return impl_->stats;
}

void LagrangeSolver::solve(std::span<const SwitchedPair> pairs, std::span<const FrictionLaw> laws,
                           const LagrangeNodes& nodes, double dt12, double dt2, std::span<PairForce> out) {
  auto& s = *impl_;
  auto& st = s.stats;
  for (auto& o : out) o = PairForce{};
  st.rows_last = st.nonzeros_last = 0;
  if (pairs.empty() || !(dt12 > 0)) return;
  const auto t0 = Clock::now();
  s.build_rows(pairs, nodes);
  if (s.rows.empty()) return;
  if (s.local.size() != nodes.mass.size()) s.local.assign(nodes.mass.size(), -1);
  s.number_columns(nodes);
  s.assemble_a();
  double tol = 0;
  const bool any = s.start_active_set(nodes, dt12, dt2, tol);
  st.seconds_assembly += seconds_since(t0);
  s.count_rows();
  int passes = 0;
  const bool converged = s.run_active_set(nodes, dt12, tol, any, passes);
  const auto ts = Clock::now();
  if (!converged) ++st.unconverged;
  s.apply_multipliers(nodes, out);
  s.friction(laws, pairs, nodes, dt12, out);
  for (const auto n : s.local_nodes) s.local[static_cast<std::size_t>(n)] = -1;
  s.count_passes(passes);
  st.seconds_solve += seconds_since(ts);
}

}  // namespace radx::contact
