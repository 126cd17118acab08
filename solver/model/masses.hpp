// Lumped nodal masses and part masses (docs/theory/elements.md section 5): the element mass is
// rho_I t0 A0 for shells and rho_I V0 for bricks (one-point volume); 4-node shells give m/4 to each
// connectivity slot (so a degenerate quad's repeated node gets 2/4), bricks m/8 per node, 3-node
// shells m alpha_k / pi to node k (alpha_k the interior angle), springs their property's M, trusses
// and beams rho A0 L0 / 2 per node.
#pragma once

#include <functional>

#include "solver/model/model.hpp"

namespace radx::model {

// Thickness a shell element uses for its mechanics and mass (docs/theory/deck-format.md 5.4): the element
// card's value if > 0, else its property's; 0 when neither is known.
double shell_thickness(const Model& m, const ElementBlock& b, std::size_t e);

// Calls fn(node, part, element_index_in_block_order, mass) for every lumped-mass contribution of every
// valid element, in model cell order (4-node shells, 3-node shells, bricks, tetrahedra, 20-node bricks, then
// springs, trusses and beams); `cell` numbers the elements that way. Elements with a missing node or part are
// skipped.
void for_each_nodal_mass(
    const Model& m,
    const std::function<void(std::int32_t node, std::int32_t part, std::size_t cell, double mass)>& fn);

// Fills m.node_mass, every part's mass and m.total_mass from the current coordinates. Elements with a
// missing node or part are skipped (the starter has reported them).
void compute_lumped_masses(Model& m);

}  // namespace radx::model
