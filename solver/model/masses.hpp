// Lumped nodal masses and part masses (shared/spec/elements.md section 5): the element mass is
// rho_I t0 A0 for shells and rho_I V0 for bricks (one-point volume); 4-node shells give m/4 to each
// connectivity slot (so a degenerate quad's repeated node gets 2/4), bricks m/8 per node, 3-node
// shells m alpha_k / pi to node k (alpha_k the interior angle).
#pragma once

#include "solver/model/model.hpp"

namespace radx::model {

// Fills m.node_mass, every part's mass and m.total_mass from the current coordinates. Elements with a
// missing node or part are skipped (the starter has reported them).
void compute_lumped_masses(Model& m);

}  // namespace radx::model
