#include "solver/elements/element_groups.hpp"
#include "solver/elements/solid/solid_stages.hpp"

#include <algorithm>

namespace radx::solver {

void ShellGroup::allocate(int n, int points, int gauss_points, int hg_rows) {
  count = n;
  props.n_points = points;
  gauss = gauss_points;
  const auto ng = static_cast<std::size_t>(gauss_points);
  const auto G = static_cast<std::size_t>(kGroupSize);
  const auto np = static_cast<std::size_t>(points > 0 ? points : 1);
  conn.assign(4 * G, 0);
  element.assign(G, -1);
  for (auto* v : {&t0, &thick, &area0, &e_int, &e_hg, &w_plastic, &rate, &dt, &dt_fixed, &k_nodal})
    v->assign(G, 0.0);
  off.assign(G, 1.0);
  small.assign(G, 0.0);
  ref_local.assign(6 * G, 0.0);
  // N = 0 (resultant elasticity) keeps 5 force and 3 moment resultants.
  sig.assign(ng * (points > 0 ? np * 5 : 8) * G, 0.0);
  eps_p.assign(ng * np * G, 0.0);
  res.assign(ng * 8 * G, 0.0);
  dmg.assign(ng * np * G, 0.0);
  dmg_inst.assign(ng * np * G, 0.0);
  fail_scale.assign(G, 1.0);
  hg.assign(static_cast<std::size_t>(hg_rows) * G, 0.0);
  nodal_force.assign(4 * 6 * G, 0.0);
}

void ShellGroup::allocate_brit() {
  const auto G = static_cast<std::size_t>(kGroupSize);
  const auto rows = static_cast<std::size_t>(gauss) * static_cast<std::size_t>(std::max(props.n_points, 1));
  brit.assign(rows * kBritVars * G, 0.0);
  for (std::size_t r = 0; r < rows; ++r)
    std::fill_n(brit.begin() + static_cast<std::ptrdiff_t>((r * kBritVars + kBritCos) * G), G, 1.0);
}

void BrickGroup::allocate(int n) {
  count = n;
  const auto G = static_cast<std::size_t>(kGroupSize);
  conn.assign(8 * G, 0);
  element.assign(G, -1);
  for (auto* v :
       {&vol0, &vol, &rho, &eps_p, &dmg, &q, &e_int, &e_hg, &w_plastic, &rate, &dt, &dt_fixed, &k_nodal})
    v->assign(G, 0.0);
  off.assign(G, 1.0);
  sig.assign(6 * G, 0.0);
  hg_force.assign(4 * 3 * G, 0.0);
  nodal_force.assign(8 * 3 * G, 0.0);
  small.assign(G, 0);
  x_ref.assign(8 * 3 * G, 0.0);
  frame.assign(9 * G, 0.0);
  for (std::size_t d = 0; d < 3; ++d)
    for (std::size_t i = 0; i < G; ++i) frame[(4 * d) * G + i] = 1.0;
  hg_stress.assign(12 * G, 0.0);
  w_hg.assign(G, 0.0);
}

void BrickGroup::set_reference(std::size_t i, const double x0[8][3]) {
  const auto G = static_cast<std::size_t>(kGroupSize);
  if (b_ref.empty()) b_ref.assign(12 * G, 0.0);
  double j1[3], j2[3], j3[3], c12[3], c23[3], c31[3], b[8][3];
  const double v0 = brick_centre_jacobian(x0, j1, j2, j3, c12, c23, c31);
  brick_centre_gradients(c12, c23, c31, v0, b);
  for (std::size_t k = 0; k < 4; ++k)
    for (std::size_t d = 0; d < 3; ++d) b_ref[(3 * k + d) * G + i] = b[k][d];
}

void TetraGroup::allocate(int n) {
  count = n;
  const auto G = static_cast<std::size_t>(kGroupSize);
  conn.assign(4 * G, 0);
  element.assign(G, -1);
  for (auto* v : {&vol0, &vol, &rho, &eps_p, &dmg, &q, &e_int, &e_hg, &w_plastic, &rate, &dt, &k_nodal})
    v->assign(G, 0.0);
  off.assign(G, 1.0);
  sig.assign(6 * G, 0.0);
  nodal_force.assign(4 * 3 * G, 0.0);
}

void Hex20Group::allocate(int n) {
  count = n;
  const auto G = static_cast<std::size_t>(kGroupSize);
  const auto np = static_cast<std::size_t>(n_points());
  conn.assign(20 * G, 0);
  element.assign(G, -1);
  for (auto* v : {&vol0, &vol, &rho, &eps_p, &dmg, &q, &e_int, &e_hg, &w_plastic, &rate, &dt, &k_nodal})
    v->assign(G, 0.0);
  off.assign(G, 1.0);
  sig.assign(6 * G, 0.0);
  sig_p.assign(np * 6 * G, 0.0);
  eps_p_p.assign(np * G, 0.0);
  dmg_p.assign(np * G, 0.0);
  vol0_p.assign(np * G, 0.0);
  nodal_force.assign(20 * 3 * G, 0.0);
}

void SpringGroup::allocate(int n) {
  count = n;
  const auto G = static_cast<std::size_t>(kGroupSize);
  conn.assign(2 * G, 0);
  element.assign(G, -1);
  for (auto* v : {&l0, &e_int, &dt, &k_nodal}) v->assign(G, 0.0);
  for (auto* v : {&dx, &force, &f_static, &plastic, &plastic_c, &yield, &travel}) v->assign(6 * G, 0.0);
  x0.assign(3 * G, 0.0);
  ey.assign(3 * G, 0.0);
  off.assign(G, 1.0);
  nodal_force.assign(2 * 6 * G, 0.0);
}

void TrussGroup::allocate(int n) {
  count = n;
  const auto G = static_cast<std::size_t>(kGroupSize);
  conn.assign(2 * G, 0);
  element.assign(G, -1);
  for (auto* v : {&area0, &area, &l0, &force, &strain, &sig, &eps_p, &dmg, &e_int, &e_hg, &w_plastic, &rate,
                  &dt, &k_nodal})
    v->assign(G, 0.0);
  off.assign(G, 1.0);
  nodal_force.assign(2 * 3 * G, 0.0);
}

void BeamGroup::allocate(int n) {
  count = n;
  const auto G = static_cast<std::size_t>(kGroupSize);
  conn.assign(2 * G, 0);
  element.assign(G, -1);
  for (auto* v : {&l0, &sig, &eps_p, &dmg, &e_int, &e_hg, &w_plastic, &rate, &dt, &k_nodal})
    v->assign(G, 0.0);
  ey.assign(3 * G, 0.0);
  resultant.assign(6 * G, 0.0);
  off.assign(G, 1.0);
  nodal_force.assign(2 * 6 * G, 0.0);
}

void BrickGroup::allocate_points() {
  const auto G = static_cast<std::size_t>(kGroupSize);
  sig_p.assign(8 * 6 * G, 0.0);
  eps_p_p.assign(8 * G, 0.0);
  dmg_p.assign(8 * G, 0.0);
  vol0_p.assign(8 * G, 0.0);
}

}  // namespace radx::solver
