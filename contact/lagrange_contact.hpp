// Lagrange multipliers for switched LAGDT contact pairs (docs/theory/type7-lagdt.md section 6;
// docs/architecture.md section 3, step 6). Contact does not know the time loop: the engine hands over views
// of the node state after a0 = f / m and the steps, and gets back corrected accelerations and each pair's
// multiplier and friction force. The equations are in lagrange_contact.cpp.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <span>

#include "contact/ctclaw_laws.hpp"
#include "solver/model/geometry.hpp"

namespace radx::contact {

// One switched pair: the secondary node against the contact point sum h_j x_j of a main segment.
struct SwitchedPair {
  std::int32_t node = -1;             // dense index of the secondary node
  std::array<std::int32_t, 4> seg{};  // main nodes (a triangle repeats seg[2] in seg[3], h[3] = 0)
  std::array<double, 4> h{};          // weights of the contact point
  model::Vec3 n{};                    // unit normal from the contact point to the node
  double distance = 0;                // d = |x_s - sum h_j x_j|
  double gap = 0;                     // g: the pair may still close down to min(d, g)
  double area = 0;                    // friction pressure lambda / area: the main segment's area, or the
                                      // secondary node's tributary area A_s under a /CTCLAW law
  std::int32_t law = 0;               // index into the friction laws (the interface)
  model::Vec3 t1{};                   // the segment's first tangent (one-directional /CTCLAW friction)
};

// Friction of a switched pair: Coulomb, |F_t| <= mu lambda, mu by the interface's Ifric law (4.5); or, when
// the interface has a /CTCLAW friction law (ctclaw.friction other than Interface), that law with lambda as
// the normal force: |F_t| <= friction_traction(|v_t|, lambda / area) area.
struct FrictionLaw {
  int ifric = 0;
  double fric = 0;
  std::array<double, 6> c{};
  PairLaw ctclaw{};
};

struct LagrangeNodes {
  std::span<const double> mass;
  std::span<const double> vx, vy, vz;   // v^{n-1/2}
  std::span<double> ax, ay, az;         // in: a0 = f / m; out: corrected
  std::span<const std::uint8_t> fixed;  // bits 0..2: translation held by a boundary condition
};

// What acted on one pair (zero for a dropped, merged-away or released row).
struct PairForce {
  double lambda = 0;       // normal contact force on the secondary node along n (>= 0)
  model::Vec3 friction{};  // friction force on the secondary node (the main nodes get -h_j of both)
};

struct LagrangeStats {
  std::int64_t cycles = 0;  // cycles with at least one row
  std::int64_t rows_last = 0, rows_max = 0, rows_total = 0;
  std::int64_t nonzeros_last = 0, nonzeros_max = 0;  // entries of A = L M^-1/2
  std::int64_t dropped_rows = 0;                     // rows with no free degree of freedom
  std::int64_t merged_rows = 0;                      // duplicates of another row (two interfaces, same pair)
  std::int64_t analyses = 0, symbolic_reuses = 0, factorizations = 0, regularisations = 0;
  double beta_max = 0;
  std::int64_t active_set_passes = 0;  // summed over cycles
  int passes_max = 0;                  // most passes in one cycle
  std::int64_t unconverged = 0;        // cycles that reached the pass limit
  double seconds_assembly = 0, seconds_factorization = 0, seconds_solve = 0;
};

class LagrangeSolver {
 public:
  LagrangeSolver();
  ~LagrangeSolver();
  LagrangeSolver(const LagrangeSolver&) = delete;
  LagrangeSolver& operator=(const LagrangeSolver&) = delete;

  // Corrects nodes.a* in place so that no pair closes below min(d, g) at the end of the step, with
  // dt12 = (dt1 + dt2) / 2 the velocity step and dt2 the position step; out[k] receives pair k's forces.
  // Throws CholmodError when CHOLMOD fails (out of memory, ...).
  void solve(std::span<const SwitchedPair> pairs, std::span<const FrictionLaw> laws,
             const LagrangeNodes& nodes, double dt12, double dt2, std::span<PairForce> out);

  [[nodiscard]] const LagrangeStats& stats() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace radx::contact
