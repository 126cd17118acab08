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

// The nodes of the law-13 elements joined into connected sets (a union-find forest over every node).
struct RigidSets {
  std::vector<std::int32_t> parent;
  std::vector<std::uint8_t> in_rigid;  // 1 for a node of a law-13 element
  // The first law-13 material met at each set's root, for the body's listing and model file.
  std::vector<std::int64_t> material_of;
  std::int64_t material_of_set(std::int32_t n) {
    return material_of[static_cast<std::size_t>(find_root(parent, n))];
  }
};

bool rigid_part(const model::Model& m, std::int32_t part) {
  const auto mat = m.parts[static_cast<std::size_t>(part)].material;
  return mat != kNone && m.materials[static_cast<std::size_t>(mat)].law == model::MaterialLaw::Rigid;
}

// The connected sets of the nodes of the elements whose part has a law-13 material.
RigidSets join_rigid_material_nodes(const model::Model& m) {
  const std::size_t nn = m.nodes.size();
  RigidSets sets{std::vector<std::int32_t>(nn), std::vector<std::uint8_t>(nn, 0),
                 std::vector<std::int64_t>(nn, 0)};
  std::iota(sets.parent.begin(), sets.parent.end(), 0);
  for (const auto* b : {&m.shells, &m.shells3, &m.bricks, &m.tetras, &m.bricks20}) {
    const auto npe = static_cast<std::size_t>(b->npe());
    for (std::size_t e = 0; e < b->size(); ++e) {
      if (b->part[e] == kNone || !rigid_part(m, b->part[e])) continue;
      const auto* c = &b->conn[e * npe];
      // A node that does not exist is reported with the element already (its slot holds kNone).
      if (std::any_of(c, c + npe, [](std::int32_t n) { return n < 0; })) continue;
      const auto mat = m.parts[static_cast<std::size_t>(b->part[e])].material;
      for (std::size_t q = 0; q < npe; ++q) {
        const auto n = static_cast<std::size_t>(c[q]);
        sets.in_rigid[n] = 1;
        if (sets.material_of[n] == 0) sets.material_of[n] = m.materials[static_cast<std::size_t>(mat)].id;
        const auto a = find_root(sets.parent, c[0]);
        const auto r = find_root(sets.parent, c[q]);
        if (a != r) sets.parent[static_cast<std::size_t>(r)] = a;
      }
    }
  }
  return sets;
}

// A node both in a law-13 set and in a /RBODY: the two bodies would fight over it. The error for the first
// such node; false when there is none.
bool rbody_shares_rigid_node(ModelBuilder& b, RigidSets& sets) {
  const auto& m = b.m_;
  for (std::size_t k = 0; k < m.rigid_bodies.size(); ++k) {
    const auto& rb = m.rigid_bodies[k];
    std::vector<std::int32_t> nodes = rb.secondary;
    if (rb.main_node != kNone) nodes.push_back(rb.main_node);
    for (const auto n : nodes) {
      if (!sets.in_rigid[static_cast<std::size_t>(n)]) continue;
      const auto rec =
          std::find_if(b.deck_.records.begin(), b.deck_.records.end(),
                       [&](const KeywordRecord& r) { return r.decl->path == "/RBODY" && r.id == rb.id; });
      const std::string msg =
          "node " + std::to_string(m.nodes.id[static_cast<std::size_t>(n)]) + " of /RBODY " +
          std::to_string(rb.id) + " is also a node of an element of /MAT/RIGID " +
          std::to_string(sets.material_of_set(n)) +
          ", whose connected elements form a rigid body of their own; radx does not merge rigid bodies "
          "(Radioss builds a hierarchy): put those elements in the /RBODY's node group with a deformable "
          "material, or leave the node out of the /RBODY";
      if (rec != b.deck_.records.end())
        b.error_at(*rec, "grnd_ID", Diag::PhysicsNotImplemented, msg);
      else
        b.diags_.error(Diag::PhysicsNotImplemented, Where{}, About{"/RBODY", rb.id}, msg);
      return true;
    }
  }
  return false;
}

// The error for the first node of node group `group` (of the condition `path` `id`) in a law-13 set; false
// when none is.
bool refuse_held_rigid_node(ModelBuilder& b, RigidSets& sets, std::string_view path, std::int64_t id,
                            std::int32_t group, std::string_view what) {
  if (group == kNone) return false;
  const auto& m = b.m_;
  for (const auto n : m.node_groups[static_cast<std::size_t>(group)].nodes) {
    if (!sets.in_rigid[static_cast<std::size_t>(n)]) continue;
    const auto rec = std::find_if(b.deck_.records.begin(), b.deck_.records.end(),
                                  [&](const KeywordRecord& r) { return r.decl->path == path && r.id == id; });
    const std::string msg =
        std::string(what) + " on node " + std::to_string(m.nodes.id[static_cast<std::size_t>(n)]) +
        ", a node of an element of /MAT/RIGID " + std::to_string(sets.material_of_set(n)) +
        ": radx does not constrain a rigid material's body through its nodes (Radioss does); hold the "
        "deformable nodes next to it, or model the body as a /RBODY with the condition on its main node";
    if (rec != b.deck_.records.end())
      b.error_at(*rec, "grnod_ID", Diag::PhysicsNotImplemented, msg);
    else
      b.diags_.error(Diag::PhysicsNotImplemented, Where{}, About{path, id}, msg);
    return true;
  }
  return false;
}

// A /BCS or imposed motion on a node of a set: OpenRadioss constrains the whole body through it
// (rmatpon.F); radx's rigid body would overwrite the node's motion with the body's, so the condition would
// be lost. One error per condition that holds such a node; false when none does.
bool conditions_hold_rigid_nodes(ModelBuilder& b, RigidSets& sets) {
  bool held = false;
  for (const auto& bc : b.m_.bcs)
    held = refuse_held_rigid_node(b, sets, "/BCS", bc.id, bc.group, "/BCS") || held;
  for (const auto& iv : b.m_.imposed_velocities)
    held = refuse_held_rigid_node(b, sets, iv.displacement ? "/IMPDISP" : "/IMPVEL", iv.id, iv.group,
                                  iv.displacement ? "/IMPDISP" : "/IMPVEL") ||
           held;
  return held;
}

// One body per set, in the order of the sets' first nodes; its secondary nodes in node order.
std::vector<model::RigidBody> bodies_of_sets(RigidSets& sets) {
  const std::size_t nn = sets.in_rigid.size();
  std::vector<std::int32_t> body_of(nn, kNone);
  std::vector<model::RigidBody> bodies;
  for (std::size_t n = 0; n < nn; ++n) {
    if (!sets.in_rigid[n]) continue;
    const auto root = static_cast<std::size_t>(find_root(sets.parent, static_cast<std::int32_t>(n)));
    if (body_of[root] == kNone) {
      body_of[root] = static_cast<std::int32_t>(bodies.size());
      model::RigidBody rb;
      rb.rigid_material = sets.material_of[root];
      rb.title = "/MAT/RIGID " + std::to_string(rb.rigid_material) + " body";
      rb.icog = 2;
      bodies.push_back(std::move(rb));
    }
    bodies[static_cast<std::size_t>(body_of[root])].secondary.push_back(static_cast<std::int32_t>(n));
  }
  return bodies;
}

// The bodies into the model, each with its added main node: ids above every node id, at the mean of their
// body's nodes (the engine moves them to the centre of mass, as for any ICoG 2 body); then the node index
// again, with the duplicates already reported made unreachable as build_nodes does.
void add_bodies_with_main_nodes(ModelBuilder& b, std::vector<model::RigidBody> bodies) {
  auto& nodes = b.m_.nodes;
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
    b.node_used_.push_back(1);
    b.node_pos_.push_back(b.node_pos_.empty() ? SourcePos{} : b.node_pos_.back());
    b.node_submodel_.push_back(-1);
    b.node_bad_.push_back(0);
    b.m_.rigid_bodies.push_back(std::move(rb));
  }
  std::vector<std::int64_t> ids = nodes.id;
  std::unordered_map<std::int64_t, int> seen;
  for (auto& id : ids)
    if (seen[id]++ > 0) id = -id - 1;
  std::int64_t dup = 0;
  nodes.index.build(ids, dup);
}

}  // namespace

void ModelBuilder::build_rigid_material_bodies() {
  auto sets = join_rigid_material_nodes(m_);
  if (std::none_of(sets.in_rigid.begin(), sets.in_rigid.end(), [](std::uint8_t f) { return f != 0; })) return;
  if (rbody_shares_rigid_node(*this, sets)) return;
  if (conditions_hold_rigid_nodes(*this, sets)) return;
  add_bodies_with_main_nodes(*this, bodies_of_sets(sets));
}

}  // namespace radx::detail
