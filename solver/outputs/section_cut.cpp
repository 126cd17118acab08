// Section cut forces, as OpenRadioss computes them (engine section.F, section_c.F, section_skew.F):
//
//   F = sum_{e in groups} sum_{q in e, node(q) in cut} f_eq        (f_eq: force element e adds to q;
//                                                                   bricks, shells, trusses and beams)
//   M = sum_{e, q} (x_node(q) - C) x f_eq + m_eq                   (m_eq: shell or beam nodal moment;
//                                                                   section_p.F for beams, section_t.F)
//   frame, from the current positions, Iframe < 10:
//     e1 = (x2 - x1)/|x2 - x1|,  e3 = e1 x (x3 - x1)/|.|,  e2 = e3 x e1,  n = e3
//   Iframe >= 10: e_k = global axes, n = (x2 - x1) x (x3 - x1)/|.| (n = Z when N1 is 0)
//   centre C by Iframe % 10: 0 x1 + ((x3 - x1) . u) u with u = (x2 - x1)/|x2 - x1| (N3 projected on the
//     axis N1 N2), 1 the mean of the cut's nodes, 2 their mass centre (lumped masses), 3 the origin
//   FN = (F . n) n,  FT = F - FN,  F_k = F . e_k,  M_k = M . e_k.
//
// f_eq is the force the element applies to the node, so F is the force that the groups' side of the cut
// exerts on the cut's nodes: for a bar held at one end and pulled at the other by P, the half on the held
// side gives F = -P, the half on the loaded side F = +P (quasi-statically). Radioss accumulates these sums
// every cycle into impulses (its time history holds integrals over time); radx evaluates them every cycle and
// writes their means over each output interval (solver/outputs/time_history_values.hpp).
// The sums (F, M, the centre of modes 1 and 2) are reported only: they are exact and order-free
// (model::ExactSum), so any split of the cut's terms between threads or ranks gives the same bits.
#include "solver/outputs/section_cut.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "solver/model/exact_sum.hpp"

namespace radx::solver {

namespace {

Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec3& a, const Vec3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
Vec3 unit(const Vec3& a) {
  const double l = std::max(std::sqrt(dot(a, a)), 1e-20);
  return {a[0] / l, a[1] / l, a[2] / l};
}
Vec3 minus(const Vec3& a, const Vec3& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

// Element index in its model block -> (group, slot), for the groups of one kind that `keep` accepts.
template <class Group, class Keep>
std::vector<std::pair<int, int>> slots_of(const std::vector<Group>& groups, Keep keep) {
  std::vector<std::pair<int, int>> where;
  for (std::size_t gi = 0; gi < groups.size(); ++gi) {
    if (!keep(groups[gi])) continue;
    for (int i = 0; i < groups[gi].count; ++i) {
      const auto el = static_cast<std::size_t>(groups[gi].element[static_cast<std::size_t>(i)]);
      if (where.size() <= el) where.resize(el + 1, {-1, -1});
      where[el] = {static_cast<int>(gi), i};
    }
  }
  return where;
}

}  // namespace

SectionSum::SectionSum(const model::Section& s, const ElementGroups& groups)
    : nodes_(s.nodes), n1_(s.n1), n2_(s.n2), n3_(s.n3), iframe_(s.iframe) {
  auto on_cut = [&](std::int32_t n) { return std::binary_search(nodes_.begin(), nodes_.end(), n); };
  auto add = [&](const auto& kind_groups, const auto& where, const std::vector<std::int32_t>& elements,
                 int npe, Kind kind) {
    for (const auto el : elements) {
      const auto e = static_cast<std::size_t>(el);
      if (e >= where.size() || where[e].first < 0) continue;  // not run (e.g. inside a rigid body)
      const auto [gi, i] = where[e];
      const auto& g = kind_groups[static_cast<std::size_t>(gi)];
      Term t{kind, gi, i, 0};
      for (int q = 0; q < npe; ++q)
        if (on_cut(g.conn[static_cast<std::size_t>(q * kGroupSize + i)])) t.corners |= std::uint8_t(1u << q);
      if (t.corners != 0) terms_.push_back(t);
    }
  };
  const auto all = [](const auto&) { return true; };
  const auto& shells = groups.shells;
  // A degenerate quad (n3 == n4) keeps four corners, each with its share of the force: both count.
  add(shells, slots_of(shells, [](const ShellGroup& g) { return !g.triangle; }), s.shells, 4, Kind::Shell);
  add(shells, slots_of(shells, [](const ShellGroup& g) { return g.triangle; }), s.shells3, 3, Kind::Shell);
  add(groups.bricks, slots_of(groups.bricks, all), s.bricks, 8, Kind::Brick);
  add(groups.trusses, slots_of(groups.trusses, all), s.trusses, 2, Kind::Truss);
  add(groups.beams, slots_of(groups.beams, all), s.beams, 2, Kind::Beam);
}

SectionCut SectionSum::evaluate(const NodeState& nodes, const ElementGroups& groups) const {
  SectionCut c;
  auto x = [&](std::int32_t n) {
    const auto k = static_cast<std::size_t>(n);
    return Vec3{nodes.x[k], nodes.y[k], nodes.z[k]};
  };
  c.axes = {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};
  c.normal = {0, 0, 1};
  const bool has_nodes = n1_ != model::kNone;
  if (has_nodes) {
    const Vec3 x1 = x(n1_), a = minus(x(n2_), x1), b = minus(x(n3_), x1);
    if (iframe_ < 10) {
      const Vec3 e1 = unit(a), e3 = unit(cross(e1, b));
      c.axes = {e1, unit(cross(e3, e1)), e3};
      c.normal = e3;
    } else {
      c.normal = unit(cross(a, b));
    }
  }
  switch (iframe_ % 10) {
    case 0:
      if (has_nodes) {
        const Vec3 x1 = x(n1_), u = unit(minus(x(n2_), x1));
        const double d = dot(minus(x(n3_), x1), u);
        c.centre = {x1[0] + d * u[0], x1[1] + d * u[1], x1[2] + d * u[2]};
      }
      break;
    case 1:
    case 2: {
      model::ExactSum w_sum;
      std::array<model::ExactSum, 3> weighted_position;
      for (const auto n : nodes_) {
        const double w = iframe_ % 10 == 1 ? 1.0 : nodes.mass[static_cast<std::size_t>(n)];
        const Vec3 p = x(n);
        for (std::size_t d = 0; d < 3; ++d) weighted_position[d].add(w * p[d]);
        w_sum.add(w);
      }
      const double w_total = w_sum.value();
      if (w_total > 0)
        for (std::size_t d = 0; d < 3; ++d) c.centre[d] = weighted_position[d].value() / w_total;
      break;
    }
    default: break;  // 3: the origin
  }
  std::array<model::ExactSum, 3> force, moment;
  auto add = [&](std::int32_t node, const double* f, std::size_t stride, bool with_moment) {
    const Vec3 fq{f[0], f[stride], f[2 * stride]};
    const Vec3 m = cross(minus(x(node), c.centre), fq);
    for (std::size_t d = 0; d < 3; ++d) {
      force[d].add(fq[d]);
      moment[d].add(m[d]);
      if (with_moment) moment[d].add(f[(3 + d) * stride]);
    }
  };
  constexpr auto G = static_cast<std::size_t>(kGroupSize);
  // The corners of one term whose node is on the cut: C components per node (3 forces, or 6 with moments).
  const auto add_corners = [&](const auto& g, const Term& t, std::size_t corners, std::size_t C) {
    const auto i = static_cast<std::size_t>(t.slot);
    for (std::size_t q = 0; q < corners; ++q)
      if (t.corners & (1u << q)) add(g.conn[q * G + i], &g.nodal_force[q * C * G + i], G, C == 6);
  };
  for (const auto& t : terms_) {
    const auto k = static_cast<std::size_t>(t.group);
    switch (t.kind) {
      case Kind::Shell: add_corners(groups.shells[k], t, 4, 6); break;
      case Kind::Brick: add_corners(groups.bricks[k], t, 8, 3); break;
      case Kind::Truss: add_corners(groups.trusses[k], t, 2, 3); break;
      case Kind::Beam: add_corners(groups.beams[k], t, 2, 6); break;
    }
  }
  for (std::size_t d = 0; d < 3; ++d) {
    c.force[d] = force[d].value();
    c.moment[d] = moment[d].value();
  }
  const double fn = dot(c.force, c.normal);
  for (std::size_t d = 0; d < 3; ++d) {
    c.normal_force[d] = fn * c.normal[d];
    c.tangential_force[d] = c.force[d] - c.normal_force[d];
    c.local_force[d] = dot(c.force, c.axes[d]);
    c.local_moment[d] = dot(c.moment, c.axes[d]);
  }
  return c;
}

}  // namespace radx::solver
