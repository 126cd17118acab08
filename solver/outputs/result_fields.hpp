// Result fields of the running model, gathered from the element groups and the node state into flat
// arrays in model order, for animation states and time histories (docs/theory/results-format.md sections 3
// and 7). Cells are numbered as the model file numbers them: 4-node shells, then 3-node shells, then bricks,
// then tetrahedra (the same fields as bricks),
// each block in its model order. Nothing here changes the engine's state.
//
// Definitions (work units):
//   shells: the stress of a cell is the through-thickness mean (the force resultant divided by the
//     thickness, i.e. the membrane stress), rotated from the element frame to global axes; its plastic
//     strain is the largest over the thickness points (the point that fails first); the plane-stress
//     szz is 0. Volume = A0 t0 (initial).
//   shell layers (z along the element normal e3 = the frame's, -t/2 <= z <= t/2, top = +t/2):
//     N points at zeta_i = -1/2 + i/(N-1) (shell_section.hpp): bottom = point 1, top = point N (both on
//     the surfaces), middle = the point at zeta = 0 (N odd) or the mean of the two points around it (N
//     even, linear interpolation); N = 1: the one point for all three.
//     N = 0 (resultant elasticity, FOR = N/t, MOM = M/t^2): sxx syy sxy at z = zeta t are
//     FOR + 12 zeta MOM, i.e. N/t -+ 6 M/t^2 at the bottom and top and N/t in the middle; syz szx are the
//     mean transverse shear FOR at every layer (the resultants keep no through-thickness profile).
//     QBAT's in-plane Gauss points: their mean, as for the mean stress. Solids, trusses and beams have no
//     layers: their three layer values are their stress.
//   bricks: the one-point stress; volume the current one-point volume.
//   von Mises = sqrt(1/2 [(sxx-syy)^2 + (syy-szz)^2 + (szz-sxx)^2] + 3 (sxy^2 + syz^2 + szx^2));
//   pressure = -(sxx + syy + szz)/3; energy densities = accumulated energy / initial volume;
//   density: bricks rho0 V0/V, shells rho0.
//   velocity at the full step v^n = v^{n-1/2} + dt1/2 a^n (as the kinetic energy, docs/theory/elements.md 8);
//   internal force f_int = f_ext - f (m a = f_ext - f_int before kinematic conditions);
//   reaction force = m a - f (a after the kinematic conditions): what boundary conditions, imposed
//   velocities, rigid walls and rigid bodies add to the node; contact force: the TYPE7 forces of the cycle.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "solver/engine/explicit_engine.hpp"
#include "solver/outputs/time_history_values.hpp"

namespace radx::solver {

enum class CellField : std::uint8_t {
  VonMises,
  PlasticStrain,
  Thickness,
  InternalEnergyDensity,
  Pressure,
  Density,
  HourglassEnergyDensity,
  Stress,  // 6 components XX YY ZZ XY YZ XZ
  // Shell layers (see above); other elements: their stress.
  VonMisesBottom,
  VonMisesMiddle,
  VonMisesTop,
  StressBottom,  // 6 components, as Stress
  StressMiddle,
  StressTop,
};

// Through-thickness position of a shell output.
enum class ShellLayer : std::uint8_t { Bottom, Middle, Top };

enum class NodeField : std::uint8_t {
  Displacement,
  Velocity,
  Acceleration,
  ContactForce,
  InternalForce,
  ExternalForce,
  ReactionForce,
  AddedMass,      // scalar
  NodalTimeStep,  // scalar: sqrt(2 m / k) from the element stiffness estimates (0 where k = 0)
};

// The output array name of a field (docs/theory/results-format.md: no '/' or '.'), and back.
std::string_view field_name(CellField f);
std::string_view field_name(NodeField f);
std::optional<CellField> cell_field_named(std::string_view name);
std::optional<NodeField> node_field_named(std::string_view name);
int components(CellField f);
int components(NodeField f);
// The physical dimension of a field's values (stress, length, ...), for its unit label.
Dim field_dim(CellField f);
Dim field_dim(NodeField f);

// Local stress (sxx syy sxy syz szx in the element frame) of shell i of group g: at a layer, or at
// through-thickness point `point` (0-based, point < g.props.n_points); the mean over QBAT's in-plane Gauss
// points.
std::array<double, 5> shell_layer_stress(const ShellGroup& g, int i, ShellLayer layer);
std::array<double, 5> shell_point_stress(const ShellGroup& g, int i, int point);
// The largest number of through-thickness points of the model's shells (0: none, or only resultant ones).
int shell_points_max(const ExplicitEngine& e);

// Fill `out` ([cells * components] or [nodes * components]). `dt1` is the step t^n - t^{n-1}.
void gather_cell_field(const ExplicitEngine& e, CellField f, std::span<float> out);
void gather_node_field(const ExplicitEngine& e, NodeField f, double dt1, std::span<float> out);
// Stress (6 components, global axes, as CellField::Stress) at through-thickness point `point` (0-based) of
// every shell that has it; 0 for every other cell.
void gather_shell_point_stress(const ExplicitEngine& e, int point, std::span<float> out);
void gather_element_status(const ExplicitEngine& e, std::span<std::uint8_t> out);  // 1 active, 0 deleted
void gather_points(const ExplicitEngine& e, std::span<double> out);                // [3 nodes]

}  // namespace radx::solver
