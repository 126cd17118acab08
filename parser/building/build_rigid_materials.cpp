// Deck -> Model: the rigid bodies of /MAT/RIGID (law 13), as the OpenRadioss starter builds them
// (initia.F, inirig_mat.F, ininode_rm.F, rigid_mat.F):
// * the nodes of every element whose part has a law-13 material are joined through the elements into
//   connected sets, whatever their part or material; each set is one rigid body;
// * its mass is the sum of its nodes' masses (the elements of every law, rho_I V as for any element) and its
//   inertia tensor sum_s [I_s 1 + m_s (|r_s|^2 1 - r_s r_s^T)] about their centre of mass: the body is formed
//   from its nodes alone, with no main node of the deck. radx runs it as a /RBODY
//   (solver/conditions/rigid_body.cpp) whose main node is a node the starter adds (id above every node id, no
//   element, no mass of its own) and which is formed as a body with a sensor is (ICoG 2; v and omega keep the
//   nodes' momentum and angular momentum), a form that gives the same motion;
// * the elements themselves compute no force (OpenRadioss forint.F skips laws 0 and 13).
// A node of a law-13 set may not be a node of a /RBODY too (OpenRadioss merges such bodies into a hierarchy,
// radx does not), nor carry a /BCS, /IMPVEL or /IMPDISP (OpenRadioss constrains the body through it, radx's
// body would override it): both refused by name (RX510).
#include <algorithm>
#include <numeric>
#include <string>

#include "parser/building/model_builder.hpp"

namespace radx::detail {

using model::kNone;

namespace {

std::int32_t find_root(std::vector<std::int32_t>& parent, std::int32_t n) {
  while (parent[static_cast<std::size_t>(n)] != n) {
    auto& p = parent[static_cast<std::size_t>(n)];
    p = parent[static_cast<std::size_t>(p)];  // path halving
    n = p;
  }
  return n;
}

}  // namespace

void ModelBuilder::build_rigid_material_bodies() {
  auto rigid_part = [&](std::int32_t part) {
    const auto mat = m_.parts[static_cast<std::size_t>(part)].material;
    return mat != kNone && m_.materials[static_cast<std::size_t>(mat)].law == model::MaterialLaw::Rigid;
  };
  const std::size_t nn = m_.nodes.size();
  std::vector<std::int32_t> parent(nn);
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<std::uint8_t> in_rigid(nn, 0);
  // The first law-13 material met at each set's root, for the body's listing and model file.
  std::vector<std::int64_t> material_of(nn, 0);
  for (const auto* b : {&m_.shells, &m_.shells3, &m_.bricks, &m_.tetras}) {
    const auto npe = static_cast<std::size_t>(b->npe());
    for (std::size_t e = 0; e < b->size(); ++e) {
      if (b->part[e] == kNone || !rigid_part(b->part[e])) continue;
      const auto* c = &b->conn[e * npe];
      // A node that does not exist is reported with the element already (its slot holds kNone).
      if (std::any_of(c, c + npe, [](std::int32_t n) { return n < 0; })) continue;
      const auto mat = m_.parts[static_cast<std::size_t>(b->part[e])].material;
      for (std::size_t q = 0; q < npe; ++q) {
        const auto n = static_cast<std::size_t>(c[q]);
        in_rigid[n] = 1;
        if (material_of[n] == 0) material_of[n] = m_.materials[static_cast<std::size_t>(mat)].id;
        const auto a = find_root(parent, c[0]);
        const auto r = find_root(parent, c[q]);
        if (a != r) parent[static_cast<std::size_t>(r)] = a;
      }
    }
  }
  if (std::none_of(in_rigid.begin(), in_rigid.end(), [](std::uint8_t f) { return f != 0; })) return;

  // A node both in a law-13 set and in a /RBODY: the two bodies would fight over it.
  for (std::size_t k = 0; k < m_.rigid_bodies.size(); ++k) {
    const auto& rb = m_.rigid_bodies[k];
    std::vector<std::int32_t> nodes = rb.secondary;
    if (rb.main_node != kNone) nodes.push_back(rb.main_node);
    for (const auto n : nodes) {
      if (!in_rigid[static_cast<std::size_t>(n)]) continue;
      const auto rec = std::find_if(deck_.records.begin(), deck_.records.end(), [&](const KeywordRecord& r) {
        return r.decl->path == "/RBODY" && r.id == rb.id;
      });
      const std::string msg =
          "node " + std::to_string(m_.nodes.id[static_cast<std::size_t>(n)]) + " of /RBODY " +
          std::to_string(rb.id) + " is also a node of an element of /MAT/RIGID " +
          std::to_string(material_of[static_cast<std::size_t>(find_root(parent, n))]) +
          ", whose connected elements form a rigid body of their own; radx does not merge rigid bodies "
          "(Radioss builds a hierarchy): put those elements in the /RBODY's node group with a deformable "
          "material, or leave the node out of the /RBODY";
      if (rec != deck_.records.end())
        error_at(*rec, "grnd_ID", Diag::PhysicsNotImplemented, msg);
      else
        diags_.error(Diag::PhysicsNotImplemented, Where{}, About{"/RBODY", rb.id}, msg);
      return;
    }
  }

  // A /BCS or imposed motion on a node of a set: OpenRadioss constrains the whole body through it
  // (rmatpon.F); radx's rigid body would overwrite the node's motion with the body's, so the condition would
  // be lost.
  auto refuse_held = [&](std::string_view path, std::int64_t id, std::int32_t group, std::string_view what) {
    if (group == kNone) return false;
    for (const auto n : m_.node_groups[static_cast<std::size_t>(group)].nodes) {
      if (!in_rigid[static_cast<std::size_t>(n)]) continue;
      const auto rec = std::find_if(deck_.records.begin(), deck_.records.end(), [&](const KeywordRecord& r) {
        return r.decl->path == path && r.id == id;
      });
      const std::string msg =
          std::string(what) + " on node " + std::to_string(m_.nodes.id[static_cast<std::size_t>(n)]) +
          ", a node of an element of /MAT/RIGID " +
          std::to_string(material_of[static_cast<std::size_t>(find_root(parent, n))]) +
          ": radx does not constrain a rigid material's body through its nodes (Radioss does); hold the "
          "deformable nodes next to it, or model the body as a /RBODY with the condition on its main node";
      if (rec != deck_.records.end())
        error_at(*rec, "grnod_ID", Diag::PhysicsNotImplemented, msg);
      else
        diags_.error(Diag::PhysicsNotImplemented, Where{}, About{path, id}, msg);
      return true;
    }
    return false;
  };
  bool held = false;
  for (const auto& bc : m_.bcs) held = refuse_held("/BCS", bc.id, bc.group, "/BCS") || held;
  for (const auto& iv : m_.imposed_velocities)
    held = refuse_held(iv.displacement ? "/IMPDISP" : "/IMPVEL", iv.id, iv.group,
                       iv.displacement ? "/IMPDISP" : "/IMPVEL") ||
           held;
  if (held) return;

  // One body per set, in the order of the sets' first nodes; its secondary nodes in node order.
  std::vector<std::int32_t> body_of(nn, kNone);
  std::vector<model::RigidBody> bodies;
  for (std::size_t n = 0; n < nn; ++n) {
    if (!in_rigid[n]) continue;
    const auto root = static_cast<std::size_t>(find_root(parent, static_cast<std::int32_t>(n)));
    if (body_of[root] == kNone) {
      body_of[root] = static_cast<std::int32_t>(bodies.size());
      model::RigidBody rb;
      rb.rigid_material = material_of[root];
      rb.title = "/MAT/RIGID " + std::to_string(rb.rigid_material) + " body";
      rb.icog = 2;
      bodies.push_back(std::move(rb));
    }
    bodies[static_cast<std::size_t>(body_of[root])].secondary.push_back(static_cast<std::int32_t>(n));
  }

  // The added main nodes: ids above every node id, at the mean of their body's nodes (the engine moves them
  // to the centre of mass, as for any ICoG 2 body).
  auto& nodes = m_.nodes;
  std::int64_t next_id = nodes.id.empty() ? 1 : *std::max_element(nodes.id.begin(), nodes.id.end()) + 1;
  for (auto& rb : bodies) {
    double x = 0, y = 0, z = 0;
    for (const auto s : rb.secondary) {
      x += nodes.x[static_cast<std::size_t>(s)];
      y += nodes.y[static_cast<std::size_t>(s)];
      z += nodes.z[static_cast<std::size_t>(s)];
    }
    const auto ns = static_cast<double>(rb.secondary.size());
    rb.main_node = static_cast<std::int32_t>(nodes.id.size());
    nodes.id.push_back(next_id++);
    nodes.x.push_back(x / ns);
    nodes.y.push_back(y / ns);
    nodes.z.push_back(z / ns);
    node_used_.push_back(1);
    node_pos_.push_back(node_pos_.empty() ? SourcePos{} : node_pos_.back());
    node_submodel_.push_back(-1);
    node_bad_.push_back(0);
    m_.rigid_bodies.push_back(std::move(rb));
  }
  // The ids again, with the duplicates already reported made unreachable as build_nodes does.
  std::vector<std::int64_t> ids = nodes.id;
  std::unordered_map<std::int64_t, int> seen;
  for (auto& id : ids)
    if (seen[id]++ > 0) id = -id - 1;
  std::int64_t dup = 0;
  nodes.index.build(ids, dup);
}

}  // namespace radx::detail
