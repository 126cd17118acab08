// Element groups: up to kGroupSize elements of one type, material and property, structure of arrays
// with the element index innermost (array[k * kGroupSize + i]). The unit of vectorisation and of
// threading. Kernels gather nodal values through `conn`, compute, and write their nodal forces into
// the group's own `nodal_force` buffer; the assembly then sums those buffers node by node in a fixed
// order, so results do not depend on the number of threads.
#pragma once

#include <cstdint>
#include <vector>

#include "solver/material_point.hpp"
#include "solver/node_state.hpp"

namespace radx::solver {

inline constexpr int kGroupSize = 128;

// Values of the cycle the kernels need.
struct CycleInfo {
  double dt1 = 0;  // previous step t^n - t^{n-1}: the step of the strain increments
  double dt2 = 0;  // current estimate of the next step (for predictions; kernels mostly use dt1)
  double time = 0;
};

struct ShellProps {
  int ishell = 1, ismstr = 2, ithick = 0, iplas = 0;  // internal meaning: ithick 1 = update, iplas 1 = Newton
  int ish3n = 2;     // 3-node shells: 2 with the in-plane large-rotation terms T11, T22; 1 without
  int n_points = 3;  // through-thickness points, >= 1; 0 = resultant elasticity (LAW1 only)
  double hm = 0.01, hf = 0.01, hr = 0.01, dm = 0, ashear = 5.0 / 6.0;
  double p_thick_fail = 0.999999;  // /FAIL Ifail_sh 2: failed thickness fraction that deletes the element
};

struct ShellGroup {
  int count = 0;                      // elements in this group
  bool triangle = false;              // 3-node C0 shells (conn rows 0..2)
  std::vector<std::int32_t> element;  // [G] index of each slot's element in its model block
  std::int32_t part = -1;             // dense part index (all elements of a group share it)
  std::int32_t material = -1;         // index into the engine's MaterialParams
  ShellProps props;
  std::vector<std::int32_t> conn;  // [4][G] dense node indices (triangles: row 3 unused)
  std::vector<double> t0;          // [G] thickness used by the mechanics
  std::vector<double> thick;       // [G] current thickness (output; mechanics when ithick = 1)
  std::vector<double> area0;       // [G] initial area
  std::vector<double> off;         // [G] 1 alive, decaying by 0.8 after failure, 0 deleted
  std::vector<double> sig;         // [n_points][5][G]  sxx syy sxy syz szx, local frame
  std::vector<double> eps_p;       // [n_points][G]
  std::vector<double> dmg;         // [n_points][G] /FAIL/JOHNSON damage (0 .. 1; 1: the point has failed)
  std::vector<double> hg;          // [3][G] elastic hourglass resultants Sx Sy Sz (Ishell 1)
  std::vector<double> e_int;       // [G] accumulated internal energy (membrane + bending)
  std::vector<double> e_hg;        // [G] accumulated hourglass energy
  std::vector<double> w_plastic;   // [G] accumulated plastic work
  std::vector<double> rate;        // [G] filtered equivalent strain rate (Johnson-Cook)
  std::vector<double> dt;          // [G] stable step of the cycle, before the /DT scale
  std::vector<double> dt_fixed;    // [G] engine: constant step after a /DT/SHELL|SH_3N/CST switch (0: none)
  // Small strain after that switch: 1.0 once the element's local geometry is frozen in ref_local
  // (quads: x2 x3 x4 y2 y3 y4; triangles: x2 x3 y3 and 0), so its B matrix, area and step stay constant.
  std::vector<double> small;        // [G] 0 or 1
  std::vector<double> ref_local;    // [6][G]
  std::vector<double> k_nodal;      // [G] nodal stiffness contribution of each node (for nodal steps)
  std::vector<double> nodal_force;  // [4][6][G] force (fx fy fz) and moment (mx my mz) ADDED to each node,
                                    // global axes (internal forces enter with their minus sign)
  void allocate(int n, int points);
};

struct BrickGroup {
  int count = 0;
  std::vector<std::int32_t> element;  // [G] index of each slot's element in the model's brick block
  std::int32_t part = -1;
  std::int32_t material = -1;
  int isolid = 1;
  int ismstr = 4;  // /DT/BRICK/CST switches a brick to small strain only with Ismstr 2 (deck-format.md)
  double qa = 1.1, qb = 0.05, h = 0.1;
  std::vector<std::int32_t> conn;  // [8][G]
  std::vector<double> vol0;        // [G] initial (one-point) volume
  std::vector<double> vol;         // [G] current volume
  std::vector<double> rho;         // [G] current density rho0 V0 / V
  std::vector<double> off;         // [G]
  std::vector<double> sig;         // [6][G] xx yy zz xy yz zx, global axes
  std::vector<double> eps_p;       // [G]
  std::vector<double> dmg;         // [G] /FAIL/JOHNSON damage (0 .. 1)
  std::vector<double> q;           // [G] bulk viscosity pressure of the last cycle
  std::vector<double> e_int;       // [G] accumulated internal energy (includes bulk viscosity work)
  std::vector<double> e_hg;        // [G]
  std::vector<double> hg_force;    // [4][3][G] hourglass forces H_j of the last cycle (energy trapezoid)
  std::vector<double> w_plastic;   // [G]
  std::vector<double> rate;        // [G] strain rate measure (Johnson-Cook)
  std::vector<double> dt;          // [G]
  std::vector<double> dt_fixed;    // [G] engine: constant step after a /DT/BRICK/CST switch (0: none)
  // Small strain after that switch: 1 once the node coordinates are frozen in x_ref; the gradients, volume
  // and step then come from x_ref (Radioss's small-strain switch), the velocities stay current.
  std::vector<std::uint8_t> small;  // [G]
  std::vector<double> x_ref;        // [8][3][G]
  std::vector<double> k_nodal;      // [G] nodal stiffness contribution (1/4 rho V / dt_e^2)
  std::vector<double> nodal_force;  // [8][3][G] force ADDED to each node, global axes
  void allocate(int n);
};

// Kernels (one file each). Each reads node coordinates and velocities from `nodes`, updates the
// group's state, energies and element steps, and fills `nodal_force`. Elements with off == 0 give no
// force and a step of +infinity.
void shell_bt4_forces(ShellGroup& g, const NodeState& nodes, const MaterialParams& mat, const CycleInfo& cyc);
void shell_c0_tri3_forces(ShellGroup& g, const NodeState& nodes, const MaterialParams& mat,
                          const CycleInfo& cyc);
void hex8_forces(BrickGroup& g, const NodeState& nodes, const MaterialParams& mat, const CycleInfo& cyc);

}  // namespace radx::solver
