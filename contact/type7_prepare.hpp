// What the starter computes for each TYPE7 / LAGDT interface before the engine runs:
// the gap (docs/theory/type7-lagdt.md 4.1), the stiffness per pair family (4.2) and the initial penetrations
// with their Inacti treatment (4.6). Inputs and outputs are the model's interface records.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "solver/model/model.hpp"

namespace radx::contact {

// Closest point of triangle (a, b, c) to p; returns the squared distance and the barycentric
// weights (wa, wb, wc) of the closest point.
double closest_point_triangle(const std::array<double, 3>& p, const std::array<double, 3>& a,
                              const std::array<double, 3>& b, const std::array<double, 3>& c,
                              std::array<double, 3>& weights);

// Closest point of a segment (quadrangle split into four triangles around its centroid, or a
// triangle when n4 == n3) to p. Returns the distance; `weights` receives the shape-function weights
// h1..h4 of the closest point (they sum to 1).
double closest_point_segment(const std::array<double, 3>& p, const std::array<std::array<double, 3>, 4>& x,
                             bool triangle, std::array<double, 4>& weights);

// Thickness a shell element uses for its mechanics: element card value if > 0, else the property's.
double shell_element_thickness(const model::Model& m, model::ElementType type, std::int32_t e);
// Thickness a shell element uses for contact gaps: /PART Thick > element Thick > /PROP Thick.
double shell_contact_thickness(const model::Model& m, model::ElementType type, std::int32_t e);

// Pair stiffness from the segment and node stiffnesses for Istf 0..5 (4.2).
double pair_stiffness(const model::Interface& in, double k_main, double k_secondary);
// Pair gap from the node and segment half-thicknesses for Igap 0..2 (4.1).
double pair_gap(const model::Interface& in, double g_secondary, double g_main);

// Tributary area A_s of each of `nodes` (sorted dense indices: an interface's secondary nodes), in their
// order, from the initial coordinates. The patches around a node: a quarter of each 4-node shell, a third of
// each 3-node shell, a quarter of each outer brick face (a face no other brick has); a degenerate element or
// face shares its area among its distinct nodes. Only the patches whose nodes are all among `nodes` count
// (the contact surface: a brick corner of a block's contacting face takes that face, not the block's sides);
// a node with no such patch takes every patch around it, and a node with none has 0. `alive`: per model cell
// (4-node shells, 3-node shells, bricks), 1 alive; empty: all alive.
std::vector<double> tributary_areas(const model::Model& m, std::span<const std::int32_t> nodes,
                                    std::span<const std::uint8_t> alive = {});

// The largest initial stiffness density lambda pz (Pa/m) of an exponential /CTCLAW law given by pe over the
// interface's secondary nodes, lambda = (K / A_s) / pe: K = stiff_hi and A_s the smallest nonzero
// tributary area. All 0 when the interface has no such law or no node with an area.
struct PeLawStiffness {
  double stiffness = 0;  // lambda pz
  double k = 0;          // K (N/m)
  double area = 0;       // A_s (m^2)
};
PeLawStiffness pe_law_initial_stiffness_max(const model::Interface& in);

// Fills gapmin, gap_node, gap_segment, stiff_node, stiff_segment, the gap and stiffness ranges, the
// initial-penetration fields and the tributary areas (before any node moves) of every interface. Inacti = 3
// moves the penetrating nodes in `m.nodes` (the engine then starts from the corrected coordinates).
void prepare_type7_interfaces(model::Model& m);

}  // namespace radx::contact
