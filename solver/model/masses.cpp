#include "solver/model/masses.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "solver/model/geometry.hpp"
#include "solver/model/hex20_shape.hpp"

namespace radx::model {

double shell_thickness(const Model& m, const ElementBlock& b, std::size_t e) {
  if (b.thickness[e] > 0) return b.thickness[e];
  const auto part = b.part[e];
  if (part == kNone || m.parts[part].property == kNone) return 0.0;
  return m.properties[m.parts[part].property].shell.thickness;
}

void for_each_nodal_mass(const Model& m,
                         const std::function<void(std::int32_t, std::int32_t, std::size_t, double)>& fn) {
  auto X = [&](std::int32_t n) { return Vec3{m.nodes.x[n], m.nodes.y[n], m.nodes.z[n]}; };
  auto rho_of = [&](std::int32_t part) -> double {
    if (part == kNone) return 0.0;
    const auto mat = m.parts[part].material;
    return mat == kNone ? 0.0 : m.materials[mat].rho;
  };
  auto valid = [](const ElementBlock& b, std::size_t e) {
    for (int k = 0; k < b.npe(); ++k)
      if (b.conn[e * static_cast<std::size_t>(b.npe()) + static_cast<std::size_t>(k)] < 0) return false;
    return b.part[e] != kNone;
  };
  std::size_t cell = 0;
  for (std::size_t e = 0; e < m.shells.size(); ++e, ++cell) {
    if (!valid(m.shells, e)) continue;
    const auto* c = &m.shells.conn[4 * e];
    const auto part = m.shells.part[e];
    const double me =
        rho_of(part) * shell_thickness(m, m.shells, e) * quad_area(X(c[0]), X(c[1]), X(c[2]), X(c[3]));
    for (int k = 0; k < 4; ++k) fn(c[k], part, cell, 0.25 * me);
  }
  for (std::size_t e = 0; e < m.shells3.size(); ++e, ++cell) {
    if (!valid(m.shells3, e)) continue;
    const auto* c = &m.shells3.conn[3 * e];
    const auto part = m.shells3.part[e];
    const Vec3 x[3] = {X(c[0]), X(c[1]), X(c[2])};
    const double me = rho_of(part) * shell_thickness(m, m.shells3, e) * triangle_area(x[0], x[1], x[2]);
    for (int k = 0; k < 3; ++k) {
      const auto a = sub(x[(k + 1) % 3], x[k]);
      const auto b = sub(x[(k + 2) % 3], x[k]);
      const double na = norm(a), nb = norm(b);
      const double cosang = (na > 0 && nb > 0) ? std::clamp(dot(a, b) / (na * nb), -1.0, 1.0) : 1.0;
      fn(c[k], part, cell, me * std::acos(cosang) / std::numbers::pi);
    }
  }
  for (std::size_t e = 0; e < m.bricks.size(); ++e, ++cell) {
    if (!valid(m.bricks, e)) continue;
    const auto* c = &m.bricks.conn[8 * e];
    std::array<Vec3, 8> x{};
    for (int k = 0; k < 8; ++k) x[k] = X(c[k]);
    const double me = rho_of(m.bricks.part[e]) * std::max(0.0, brick_volume(x));
    for (int k = 0; k < 8; ++k) fn(c[k], m.bricks.part[e], cell, 0.125 * me);
  }
  // Tetrahedra: m_e = rho V0, a quarter to each node (OpenRadioss starter s4mass3.F).
  for (std::size_t e = 0; e < m.tetras.size(); ++e, ++cell) {
    if (!valid(m.tetras, e)) continue;
    const auto* c = &m.tetras.conn[4 * e];
    const double me =
        rho_of(m.tetras.part[e]) * std::max(0.0, tetra_volume(X(c[0]), X(c[1]), X(c[2]), X(c[3])));
    for (int k = 0; k < 4; ++k) fn(c[k], m.tetras.part[e], cell, 0.25 * me);
  }
  // 20-node bricks: m_e = rho V0 (V0 by the 3 x 3 x 3 rule), 1/64 to each corner and 7/96 to each mid-side
  // node (OpenRadioss starter s20mass3.F; hex20_shape.hpp).
  for (std::size_t e = 0; e < m.bricks20.size(); ++e, ++cell) {
    if (!valid(m.bricks20, e)) continue;
    const auto* c = &m.bricks20.conn[20 * e];
    double x[20][3];
    for (int k = 0; k < 20; ++k) {
      const Vec3 p = X(c[k]);
      for (int d = 0; d < 3; ++d) x[k][d] = p[d];
    }
    const double me = rho_of(m.bricks20.part[e]) * std::max(0.0, hex20_volume(x, hex20_starter_rule()));
    for (int k = 0; k < 20; ++k) fn(c[k], m.bricks20.part[e], cell, hex20_mass_share(k) * me);
  }
  // Springs: their property's M (M L0 with Ileng 1), half on each of n1 and n2 (OpenRadioss starter
  // rmass.F); numbered after the mesh cells.
  for (std::size_t e = 0; e < m.springs.size(); ++e, ++cell) {
    const auto* c = &m.springs.conn[3 * e];
    const auto part = m.springs.part[e];
    if (c[0] < 0 || c[1] < 0 || part == kNone) continue;
    const auto prop = m.parts[static_cast<std::size_t>(part)].property;
    if (prop == kNone || m.properties[static_cast<std::size_t>(prop)].kind != PropertyKind::Spring) continue;
    const auto& sp = m.properties[static_cast<std::size_t>(prop)].spring;
    const double l0 = sp.ileng == 1 ? norm(sub(X(c[1]), X(c[0]))) : 1.0;
    for (int k = 0; k < 2; ++k) fn(c[k], part, cell, 0.5 * sp.mass * l0);
  }
  // Trusses: m_e = rho A0 L0, half on each node (OpenRadioss starter tmass.F); numbered after the springs.
  for (std::size_t e = 0; e < m.trusses.size(); ++e, ++cell) {
    if (!valid(m.trusses, e)) continue;
    const auto* c = &m.trusses.conn[2 * e];
    const auto part = m.trusses.part[e];
    const auto prop = m.parts[static_cast<std::size_t>(part)].property;
    if (prop == kNone || m.properties[static_cast<std::size_t>(prop)].kind != PropertyKind::Truss) continue;
    const double me =
        rho_of(part) * m.properties[static_cast<std::size_t>(prop)].truss.area * norm(sub(X(c[1]), X(c[0])));
    for (int k = 0; k < 2; ++k) fn(c[k], part, cell, 0.5 * me);
  }
  // Beams: m_e = rho A l0, half on each of n1 and n2 (OpenRadioss starter pmass.F); the orientation node
  // carries nothing. Numbered after the trusses.
  for (std::size_t e = 0; e < m.beams.size(); ++e, ++cell) {
    const auto* c = &m.beams.conn[3 * e];
    const auto part = m.beams.part[e];
    if (c[0] < 0 || c[1] < 0 || part == kNone) continue;
    const auto prop = m.parts[static_cast<std::size_t>(part)].property;
    if (prop == kNone || m.properties[static_cast<std::size_t>(prop)].kind != PropertyKind::Beam) continue;
    const double me =
        rho_of(part) * m.properties[static_cast<std::size_t>(prop)].beam.area * norm(sub(X(c[1]), X(c[0])));
    for (int k = 0; k < 2; ++k) fn(c[k], part, cell, 0.5 * me);
  }
}

void compute_lumped_masses(Model& m) {
  m.node_mass.assign(m.nodes.size(), 0.0);
  for (auto& p : m.parts) p.mass = 0;
  for_each_nodal_mass(m, [&](std::int32_t node, std::int32_t part, std::size_t, double mass) {
    m.node_mass[static_cast<std::size_t>(node)] += mass;
    m.parts[static_cast<std::size_t>(part)].mass += mass;
  });
  m.total_mass = 0;
  for (const auto& p : m.parts) m.total_mass += p.mass;
  // /ADMAS: on the nodes, in the total, in no part.
  for (const auto& a : m.added_masses) {
    if (a.group < 0 || static_cast<std::size_t>(a.group) >= m.node_groups.size()) continue;
    const auto& nodes = m.node_groups[static_cast<std::size_t>(a.group)].nodes;
    if (nodes.empty()) continue;
    const double each = a.type == 1 ? a.mass / static_cast<double>(nodes.size()) : a.mass;
    for (const auto n : nodes) m.node_mass[static_cast<std::size_t>(n)] += each;
    m.total_mass += each * static_cast<double>(nodes.size());
  }
}

}  // namespace radx::model
