// The explicit time loop; see explicit_engine.hpp for the cycle order and the energy definitions.
// Masses and rotational inertias (docs/theory/elements.md section 5): shells m_e = rho t0 A0, m_e/4 per slot,
// I = (m_e/4)(A0/9 + t0^2/12); 3-node shells m_e alpha_k/pi with I_e = m_e (A0/4.5 + t0^2/12);
// bricks m_e/8 per node, tetrahedra m_e/4 per node, 20-node bricks m_e/64 per corner and 7 m_e/96 per
// mid-side node, no inertia for these; TYPE8 springs I/2 per node;
// type-3 beams as add_beam_inertias says (trusses carry none).
#include "solver/engine/explicit_engine.hpp"
#include "solver/engine/step_control_names.hpp"

#include <algorithm>
#include <cassert>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include "solver/conditions/kinematics_driver.hpp"
#include "solver/model/exact_sum.hpp"
#include "solver/model/geometry.hpp"
#include "solver/model/hex20_shape.hpp"
#include "solver/model/masses.hpp"
#include "solver/model/stable_step.hpp"
#include "solver/parallel/engine_domain.hpp"

namespace radx::solver {

namespace {

// Wall seconds from t0 to now (the stages' timers of the listing).
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

constexpr double kInf = std::numeric_limits<double>::infinity();
// Node stages run in chunks of this many nodes (about 0.1 ms of work each): chunk boundaries never depend
// on the thread count, and a model of fewer than two chunks' nodes runs them on one thread.
constexpr std::int64_t kNodeChunk = 2048;
// The element sums are committed in regions of whole node chunks (build_sum_regions), at most this many: one
// chunk each on a small model, more on a large one. A group whose nodes reach into two regions adds its
// entries from a list, slower than its plain loop; on a plate meshed row by row a group's nodes span a row
// of nodes, which on a large model is as long as a chunk (1,601 nodes at 2.66 M elements), and most groups
// would cross. 64 regions still give every thread many of its own.
constexpr std::int64_t kMaxSumRegions = 64;
// Below this many groups (of kGroupSize elements) the element stage runs on one thread: waking another
// costs about what a few groups' forces do.
constexpr std::int64_t kMinParallelGroups = 8;

// a = f / m, angular a = moment / scalar inertia; a massless node gets none.
inline void accelerate_node(NodeState& s, std::size_t n) {
  const double m = s.mass[n];
  const double inv = m > 0 ? 1.0 / m : 0.0;
  s.ax[n] = s.fx[n] * inv;
  s.ay[n] = s.fy[n] * inv;
  s.az[n] = s.fz[n] * inv;
  const double I = s.inertia[n];
  const double invI = I > 0 ? 1.0 / I : 0.0;
  s.awx[n] = s.mx[n] * invI;
  s.awy[n] = s.my[n] * invI;
  s.awz[n] = s.mz[n] * invI;
}

// The node passes' loops over [first, last). The arrays never overlap, which GCC cannot see (it would have to
// compare every pair of the twenty arrays before the loop, and gives up; it ignores __restrict on local
// pointers): `ivdep` (RADX_IVDEP) tells it, and the integration is so vectorised. The assembly is written two
// nodes at a time by hand: its sums are [node][6], a stride GCC does not vectorise, and its guarded divisions
// keep GCC's loop scalar.
using Pair = double __attribute__((vector_size(16)));
using PairMask = long long __attribute__((vector_size(16)));
inline Pair load_pair(const double* p) {
  Pair v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
inline void store_pair(double* p, Pair v) {
  std::memcpy(p, &v, sizeof v);
}
// 1 / m where m > 0, else 0 (a massless node), for both lanes: the division runs on every lane (a zero or
// NaN lane's inf or NaN is then masked away), the same division as the scalar 1.0 / m.
inline Pair inverse_or_zero(Pair m) {
  const PairMask positive = m > Pair{0.0, 0.0};
  return reinterpret_cast<Pair>(reinterpret_cast<PairMask>(Pair{1.0, 1.0} / m) & positive);
}

// Assembly [4-5]: f = f_ext + the element sums, moments += their sums, the sums cleared for the next cycle;
// with Accelerate, a = f / m and the angular a = moment / inertia (a massless node gets none).
template <bool Accelerate>
void assemble_nodes(NodeState& s, double* sums, std::size_t first, std::size_t last) {
  const double* fx_ext = s.fx_ext.data();
  const double* fy_ext = s.fy_ext.data();
  const double* fz_ext = s.fz_ext.data();
  const double* mass = s.mass.data();
  const double* inertia = s.inertia.data();
  double* fx = s.fx.data();
  double* fy = s.fy.data();
  double* fz = s.fz.data();
  double* mx = s.mx.data();
  double* my = s.my.data();
  double* mz = s.mz.data();
  double* ax = s.ax.data();
  double* ay = s.ay.data();
  double* az = s.az.data();
  double* awx = s.awx.data();
  double* awy = s.awy.data();
  double* awz = s.awz.data();
  std::size_t n = first;
  for (; n + 1 < last; n += 2) {
    // Nodes n and n + 1: their sums [6] side by side, turned into one pair per component.
    double* f = sums + 6 * n;
    const Pair a01 = load_pair(f), a23 = load_pair(f + 2), a45 = load_pair(f + 4);
    const Pair b01 = load_pair(f + 6), b23 = load_pair(f + 8), b45 = load_pair(f + 10);
    // External loads were put in f*_ext by the loads; the total is their sum with the element forces.
    const Pair fxn = load_pair(fx_ext + n) + __builtin_shufflevector(a01, b01, 0, 2);
    const Pair fyn = load_pair(fy_ext + n) + __builtin_shufflevector(a01, b01, 1, 3);
    const Pair fzn = load_pair(fz_ext + n) + __builtin_shufflevector(a23, b23, 0, 2);
    const Pair mxn = load_pair(mx + n) + __builtin_shufflevector(a23, b23, 1, 3);
    const Pair myn = load_pair(my + n) + __builtin_shufflevector(a45, b45, 0, 2);
    const Pair mzn = load_pair(mz + n) + __builtin_shufflevector(a45, b45, 1, 3);
    store_pair(fx + n, fxn);
    store_pair(fy + n, fyn);
    store_pair(fz + n, fzn);
    store_pair(mx + n, mxn);
    store_pair(my + n, myn);
    store_pair(mz + n, mzn);
    for (int d = 0; d < 12; d += 2)
      store_pair(f + d, Pair{0.0, 0.0});  // the next cycle's sums start from zero
    if constexpr (Accelerate) {
      const Pair inv = inverse_or_zero(load_pair(mass + n));
      store_pair(ax + n, fxn * inv);
      store_pair(ay + n, fyn * inv);
      store_pair(az + n, fzn * inv);
      const Pair inv_i = inverse_or_zero(load_pair(inertia + n));
      store_pair(awx + n, mxn * inv_i);
      store_pair(awy + n, myn * inv_i);
      store_pair(awz + n, mzn * inv_i);
    }
  }
  for (; n < last; ++n) {  // an odd last node
    double* f = sums + 6 * n;
    fx[n] = fx_ext[n] + f[0];
    fy[n] = fy_ext[n] + f[1];
    fz[n] = fz_ext[n] + f[2];
    mx[n] += f[3];
    my[n] += f[4];
    mz[n] += f[5];
    for (int d = 0; d < 6; ++d) f[d] = 0.0;
    if constexpr (Accelerate) accelerate_node(s, n);
  }
}

// Integration [8]: v += dt12 a, omega += dt12 alpha, x += dt2 v; the external forces and moments are zeroed
// for the next cycle's loads. Returns false when a coordinate is not finite.
bool integrate_nodes(NodeState& s, double dt12, double dt2, std::size_t first, std::size_t last) {
  const double* ax = s.ax.data();
  const double* ay = s.ay.data();
  const double* az = s.az.data();
  const double* awx = s.awx.data();
  const double* awy = s.awy.data();
  const double* awz = s.awz.data();
  double* vx = s.vx.data();
  double* vy = s.vy.data();
  double* vz = s.vz.data();
  double* wx = s.wx.data();
  double* wy = s.wy.data();
  double* wz = s.wz.data();
  double* x = s.x.data();
  double* y = s.y.data();
  double* z = s.z.data();
  double* fx_ext = s.fx_ext.data();
  double* fy_ext = s.fy_ext.data();
  double* fz_ext = s.fz_ext.data();
  double* mx = s.mx.data();
  double* my = s.my.data();
  double* mz = s.mz.data();
  // t - t is 0 for a finite t, NaN otherwise: an integer or over the pass instead of a branch per node.
  int bad = 0;
  RADX_IVDEP
  for (std::size_t n = first; n < last; ++n) {
    const double vxn = vx[n] + dt12 * ax[n], vyn = vy[n] + dt12 * ay[n], vzn = vz[n] + dt12 * az[n];
    vx[n] = vxn;
    vy[n] = vyn;
    vz[n] = vzn;
    wx[n] += dt12 * awx[n];
    wy[n] += dt12 * awy[n];
    wz[n] += dt12 * awz[n];
    const double xn = x[n] + dt2 * vxn, yn = y[n] + dt2 * vyn, zn = z[n] + dt2 * vzn;
    x[n] = xn;
    y[n] = yn;
    z[n] = zn;
    const double t = xn + yn + zn;
    bad |= static_cast<int>(!(t - t == 0.0));
    fx_ext[n] = fy_ext[n] = fz_ext[n] = 0.0;
    mx[n] = my[n] = mz[n] = 0.0;
  }
  return bad == 0;
}

}  // namespace

ExplicitEngine::ExplicitEngine(const model::Model& model, const model::RunControls& controls,
                               EngineOptions options)
    : model_(model), controls_(controls), options_(options), sensors_(model), skews_(model) {
  materials_.reserve(model_.materials.size());
  // Law 36's curves: one list per material, filled before any pointer to it is taken (never resized after).
  material_curves_.resize(model_.materials.size());
  for (std::size_t i = 0; i < model_.materials.size(); ++i)
    materials_.push_back(make_material_params(model_.materials[i], model_.functions, material_curves_[i]));
  build_nodes();
  build_groups();
  element_sums_.assign(6 * nodes_.n, 0.0);
  build_sum_regions();
  if (options_.comm != nullptr && options_.comm->size() > 1) {
    if (const auto refused = parallel::features_not_distributed(model_, controls_); !refused.empty()) {
      std::string names;
      for (const auto& f : refused) names += (names.empty() ? "" : ", ") + f;
      throw std::runtime_error("the engine does not run these on more than one rank yet: " + names);
    }
    auto& comm = *options_.comm;
    std::vector<std::int32_t> watched;  // the time history's nodes: rank 0 reads them on its cycles
    for (const auto& th : model_.time_histories)
      if (th.kind == model::ThKind::Node) watched.insert(watched.end(), th.objects.begin(), th.objects.end());
    domain_ = std::make_unique<parallel::EngineDomain>(
        groups_, parallel::engine_group_ranks(model_, groups_, comm, options_.group_ranks),
        parallel::replicated_nodes(model_), watched, comm);
  }
  build_node_pass_chunks();
  for (const auto& th : model_.time_histories)
    th_reads_elements_ =
        th_reads_elements_ || (th.kind != model::ThKind::Node && th.kind != model::ThKind::Part &&
                               th.kind != model::ThKind::Subset && th.kind != model::ThKind::Inter &&
                               th.kind != model::ThKind::Rwall && th.kind != model::ThKind::Rbody &&
                               th.kind != model::ThKind::Accel);
  group_votes_.resize(static_cast<std::size_t>(group_count()));
  team_ =
      std::make_unique<ThreadTeam>(options_.threads > 0 ? options_.threads : ThreadTeam::default_threads());
  kinematics_ = std::make_unique<KinematicsDriver>(model_, controls_, nodes_, skews_, sensors_.starts());
  accelerometers_ = std::make_unique<Accelerometers>(model_, skews_);
  if (!model_.interfaces.empty()) {
    contact::ContactControls cc;
    const auto& inter = controls_.inter;
    cc.dt_scale = inter.given ? inter.scale : controls_.global.scale;
    cc.t_min = inter.given ? inter.t_min : 0.0;
    cc.action = inter.action == model::DtAction::AddMass    ? contact::ContactControls::Action::AddMass
                : inter.action == model::DtAction::Delete   ? contact::ContactControls::Action::Delete
                : inter.action == model::DtAction::Lagrange ? contact::ContactControls::Action::Lagrange
                                                            : contact::ContactControls::Action::None;
    contact_ = std::make_unique<contact::Type7Contact>(model_, cc);
    if (contact_->empty()) contact_.reset();
    // Contact's pure stages (search displacement test, closest segments) in its own fixed chunks on the
    // team; contact runs fewer than two chunks on the calling thread without calling this.
    if (contact_)
      contact_->set_parallel_for(
          [team = team_.get()](std::int64_t chunks, contact::ChunkBody body) { team->run(chunks, body); });
  }
  fuse_accelerations_ = !kinematics_->has_ties() && !controls_.nodal.given &&
                        !(contact_ && controls_.inter.action == model::DtAction::AddMass);
}

std::int64_t ExplicitEngine::count_deleted() const {
  // The element stage counted each group's deleted elements (springs count none: their failure does not
  // concern contact).
  return step_vote_.deleted;
}

ExplicitEngine::~ExplicitEngine() = default;

std::vector<std::string> ExplicitEngine::take_events() {
  auto out = sensors_.take_messages();
  for (auto& m : kinematics_->take_messages()) out.push_back(std::move(m));
  for (auto& m : deletion_events_) out.push_back(std::move(m));
  deletion_events_.clear();
  return out;
}

namespace {

// The listing names at most this many deleted elements one by one (Radioss names every one; a crash model
// that erodes thousands would bury the rest of the listing), then says how many more there are.
constexpr std::int64_t kDeletionLines = 1000;

}  // namespace

// Once an element's life factor reaches 0 (its material failed, a spring or truss broke), the listing says
// which, once, as Radioss's "DELETE OF ... ELEMENT" and "RUPTURE OF ..." lines do. Scans the groups only in a
// cycle whose count of such elements changed.
void ExplicitEngine::list_deleted_elements(std::int64_t cycle, double time) {
  const std::int64_t ended = step_vote_.ended;
  if (ended == ended_elements_) return;
  // The counts are every rank's (gathered votes); the elements' life factors come from their owners.
  if (domain_) domain_->share_group_arrays(groups_, [](auto& g, auto&& visit) { visit(g.off); });
  const std::int64_t before = ended_elements_;
  ended_elements_ = ended;
  if (deletion_listed_.empty()) deletion_listed_.assign(model_.cell_count(), 0);
  if (deleted_by_part_.empty()) deleted_by_part_.assign(model_.parts.size(), 0);
  std::int64_t listed = before;
  groups_.for_each([&](const auto& g) {
    const auto& block = element_block(model_, g);
    const std::string_view kind = model::element_type_name(block.type);
    for (int i = 0; i < g.count; ++i) {
      const auto k = static_cast<std::size_t>(i);
      if (g.off[k] > 0) continue;
      const auto e = static_cast<std::size_t>(g.element[k]);
      auto& seen = deletion_listed_[first_cell(model_, g) + e];
      if (seen) continue;
      seen = 1;
      ++listed;
      ++deleted_by_part_[static_cast<std::size_t>(g.part)];
      const std::int64_t part_id = model_.parts[static_cast<std::size_t>(g.part)].id;
      if (first_deleted_.size() < kFirstDeleted)
        first_deleted_.push_back({std::string(kind), block.id[e], part_id, cycle, time});
      if (listed <= kDeletionLines)
        deletion_events_.push_back(std::string(kind) + " " + std::to_string(block.id[e]) + " of part " +
                                   std::to_string(part_id) +
                                   " deleted: it failed and carries no force from now on");
      else if (listed == kDeletionLines + 1)
        deletion_events_.push_back("more elements are deleted from here on; the listing names the first " +
                                   std::to_string(kDeletionLines) + " only (element_status in the results)");
    }
  });
}

namespace {

// Type-3 beams: each node's rotational inertia (OpenRadioss starter pmass.F), with m = rho A l / 2 per node,
// lambda = A l^2 / (12 max(Iyy, Izz)) and phi = 6 E / (5 G) / lambda min(Iyy, Izz) / max(Iyy, Izz):
// I = 1.2 m (1.2 l)^2 / 12 + rho l / 2 max(Iyy, Izz), times max(1, (4 + phi) / (1 + phi) / (1 + lambda)) for
// a short beam (lambda < 1), and at least rho l / 2 Ixx.
void add_beam_inertias(const model::Model& m, NodeState& nodes) {
  for (std::size_t e = 0; e < m.beams.size(); ++e) {
    const auto* c = &m.beams.conn[3 * e];
    const auto part = m.beams.part[e];
    if (c[0] < 0 || c[1] < 0 || part == model::kNone) continue;
    const auto& p = m.parts[static_cast<std::size_t>(part)];
    if (p.property == model::kNone || p.material == model::kNone ||
        m.properties[static_cast<std::size_t>(p.property)].kind != model::PropertyKind::Beam)
      continue;
    const auto& b = m.properties[static_cast<std::size_t>(p.property)].beam;
    const auto& mat = m.materials[static_cast<std::size_t>(p.material)];
    const double l = model::norm(model::sub(model::Vec3{m.nodes.x[c[1]], m.nodes.y[c[1]], m.nodes.z[c[1]]},
                                            model::Vec3{m.nodes.x[c[0]], m.nodes.y[c[0]], m.nodes.z[c[0]]}));
    const double bb = std::max({b.iyy, b.izz, 1e-30});
    const double lambda = b.area * l * l / bb / 12.0;
    const double phi = 1.2 * mat.young / std::max(mat.shear, 1e-30) / lambda * std::min(b.iyy, b.izz) / bb;
    const double amplification = std::max(1.0, (4.0 + phi) / (1.0 + phi) / (1.0 + lambda));
    const double half_mass = 0.5 * mat.rho * l * b.area;
    double inertia = 1.2 * half_mass * (1.2 * l) * (1.2 * l) / 12.0 + mat.rho * 0.5 * l * bb;
    if (lambda < 1.0) inertia *= amplification;
    inertia = std::max(inertia, mat.rho * 0.5 * l * b.ixx);
    for (int k = 0; k < 2; ++k) nodes.inertia[static_cast<std::size_t>(c[k])] += inertia;
  }
}

}  // namespace

void ExplicitEngine::build_nodes() {
  const auto& m = model_;
  nodes_.resize(m.nodes.size());
  for (std::size_t n = 0; n < m.nodes.size(); ++n) {
    nodes_.x[n] = nodes_.x0[n] = m.nodes.x[n];
    nodes_.y[n] = nodes_.y0[n] = m.nodes.y[n];
    nodes_.z[n] = nodes_.z0[n] = m.nodes.z[n];
  }
  // Masses are the starter's lumped masses (solver/model/masses.cpp); the engine adds the scalar
  // rotational inertias, which shells and TYPE8 springs carry.
  nodes_.mass.assign(m.node_mass.begin(), m.node_mass.end());
  auto X = [&](std::int32_t n) { return model::Vec3{m.nodes.x[n], m.nodes.y[n], m.nodes.z[n]}; };
  auto rho_of = [&](std::int32_t part) { return m.materials[m.parts[part].material].rho; };
  for (std::size_t e = 0; e < m.shells.size(); ++e) {
    const auto* c = &m.shells.conn[4 * e];
    const double t0 = model::shell_thickness(m, m.shells, e);
    const double a0 = model::quad_area(X(c[0]), X(c[1]), X(c[2]), X(c[3]));
    const double me = rho_of(m.shells.part[e]) * t0 * a0;
    // Divisor of the in-plane term: 9, or 12 for QBAT and QEPH (docs/theory/elements.md 5, cinmas.F: internal
    // IHBE >= 11).
    const auto part = m.shells.part[e];
    const int ishell = m.properties[m.parts[part].property].shell.ishell;
    const double in_plane = (ishell == 12 || ishell == 24) ? 12.0 : 9.0;
    const double inertia = 0.25 * me * (a0 / in_plane + t0 * t0 / 12.0);
    for (int k = 0; k < 4; ++k) nodes_.inertia[c[k]] += inertia;
  }
  for (std::size_t e = 0; e < m.shells3.size(); ++e) {
    const auto* c = &m.shells3.conn[3 * e];
    const double t0 = model::shell_thickness(m, m.shells3, e);
    const model::Vec3 x[3] = {X(c[0]), X(c[1]), X(c[2])};
    const double a0 = model::triangle_area(x[0], x[1], x[2]);
    const double ie = rho_of(m.shells3.part[e]) * t0 * a0 * (a0 / 4.5 + t0 * t0 / 12.0);
    for (int k = 0; k < 3; ++k) {
      const auto u = model::sub(x[(k + 1) % 3], x[k]);
      const auto v = model::sub(x[(k + 2) % 3], x[k]);
      const double cosang = std::clamp(model::dot(u, v) / (model::norm(u) * model::norm(v)), -1.0, 1.0);
      nodes_.inertia[c[k]] += ie * std::acos(cosang) / std::numbers::pi;
    }
  }
  add_beam_inertias(m, nodes_);
  // TYPE8 springs: the property's inertia, half on each node (OpenRadioss starter rmass.F).
  for (std::size_t e = 0; e < m.springs.size(); ++e) {
    const auto* c = &m.springs.conn[3 * e];
    const auto part = m.springs.part[e];
    if (c[0] < 0 || c[1] < 0 || part == model::kNone) continue;
    const auto prop = m.parts[static_cast<std::size_t>(part)].property;
    if (prop == model::kNone ||
        m.properties[static_cast<std::size_t>(prop)].kind != model::PropertyKind::Spring)
      continue;
    const auto& sp = m.properties[static_cast<std::size_t>(prop)].spring;
    for (int k = 0; k < 2; ++k) nodes_.inertia[c[k]] += 0.5 * sp.inertia;
  }
}

namespace {

// Void and rigid elements compute no force (OpenRadioss forint.F skips laws 0 and 13): they get no group,
// hence no stable step either. Their mass is in the nodal masses, a rigid one's motion in its rigid body.
// A spring's part has no material (-1): its force comes from its property.
bool part_has_forces(const model::Model& m, std::int32_t part) {
  const auto mat = m.parts[static_cast<std::size_t>(part)].material;
  if (mat < 0) return true;
  const auto law = m.materials[static_cast<std::size_t>(mat)].law;
  return law != model::MaterialLaw::Void && law != model::MaterialLaw::Rigid;
}

// The elements of a block that have forces, sorted by part (stable).
std::vector<std::int32_t> order_by_part(const model::Model& m, const model::ElementBlock& b) {
  std::vector<std::int32_t> order;
  order.reserve(b.size());
  for (std::size_t e = 0; e < b.size(); ++e)
    if (part_has_forces(m, b.part[e])) order.push_back(static_cast<std::int32_t>(e));
  std::stable_sort(order.begin(), order.end(),
                   [&](std::int32_t a, std::int32_t c) { return b.part[a] < b.part[c]; });
  return order;
}

// The block's elements with forces cut into groups: runs of one part of at most kGroupSize elements, in part
// order; group(part, run) makes each.
template <class MakeGroup>
void for_each_group_run(const model::Model& m, const model::ElementBlock& b, MakeGroup&& group) {
  const auto order = order_by_part(m, b);
  std::size_t k = 0;
  while (k < order.size()) {
    const auto part = b.part[order[k]];
    std::size_t end = k;
    while (end < order.size() && b.part[order[end]] == part && end - k < static_cast<std::size_t>(kGroupSize))
      ++end;
    group(part, std::span<const std::int32_t>(order).subspan(k, end - k));
    k = end;
  }
}

// A shell group of the elements `run` of one part: the kernel of the property's formulation
// (check_formulations.cpp accepts only these), the property's figures, connectivity, thickness, initial area
// and the /FAIL/TAB element-size factor.
ShellGroup make_shell_group(const model::Model& m, const std::vector<MaterialParams>& materials,
                            std::pmr::memory_resource* arena, const model::ElementBlock& b, bool triangle,
                            std::int32_t part, std::span<const std::int32_t> run) {
  const auto& prop = m.properties[m.parts[part].property].shell;
  const auto mat = m.parts[part].material;
  const int npe = b.npe();
  int points = prop.n_ip;
  if (m.materials[mat].law != model::MaterialLaw::Elastic && points == 0) points = 3;  // LAW2 with N = 0
  if (m.materials[mat].law == model::MaterialLaw::Elastic && points > 1) points = 0;   // LAW1: resultant
  ShellGroup g(arena);
  const ShellKernel kernel = triangle            ? ShellKernel::Tri3
                             : prop.ishell == 24 ? ShellKernel::Qeph
                             : prop.ishell == 12 ? ShellKernel::Qbat
                                                 : ShellKernel::Bt4;
  const int gauss = kernel == ShellKernel::Qbat ? 4 : 1;
  const int hg_rows = kernel == ShellKernel::Qeph ? 24 : 3;
  g.allocate(static_cast<int>(run.size()), points, gauss, hg_rows);
  if (m.materials[mat].law == model::MaterialLaw::PlasBrit) g.allocate_brit();
  g.kernel = kernel;
  g.triangle = triangle;
  g.part = part;
  g.material = mat;
  g.props.ishell = prop.ishell;
  g.props.ismstr = prop.ismstr;
  g.props.ish3n = prop.ish3n;
  g.props.ithick = prop.ithick == 1 ? 1 : 0;
  g.props.iplas = prop.iplas == 1 ? 1 : 0;
  g.props.hm = prop.hm;
  g.props.hf = prop.hf;
  g.props.hr = prop.hr;
  g.props.dm = prop.dm;
  g.props.dn = prop.dn;
  g.props.ashear = points == 1 ? 0.0 : prop.ashear;
  g.props.p_thick_fail = prop.p_thick_fail;
  for (int i = 0; i < g.count; ++i) {
    const auto e = static_cast<std::size_t>(run[static_cast<std::size_t>(i)]);
    g.element[static_cast<std::size_t>(i)] = static_cast<std::int32_t>(e);
    for (int q = 0; q < npe; ++q)
      g.conn[static_cast<std::size_t>(q * kGroupSize + i)] = b.conn[e * static_cast<std::size_t>(npe) + q];
    if (triangle) g.conn[static_cast<std::size_t>(3 * kGroupSize + i)] = b.conn[e * 3 + 2];
    const double t0 = model::shell_thickness(m, b, e);
    g.t0[static_cast<std::size_t>(i)] = g.thick[static_cast<std::size_t>(i)] = t0;
    auto X = [&](int q) {
      const auto n = b.conn[e * static_cast<std::size_t>(npe) + static_cast<std::size_t>(q)];
      return model::Vec3{m.nodes.x[n], m.nodes.y[n], m.nodes.z[n]};
    };
    g.area0[static_cast<std::size_t>(i)] =
        triangle ? model::triangle_area(X(0), X(1), X(2)) : model::quad_area(X(0), X(1), X(2), X(3));
    // /FAIL/TAB's element-size factor from the length at t = 0 (OpenRadioss keeps the starter's ALDT,
    // cfailini.F): docs/theory/elements.md 4.1 L = max(A / longest diagonal, shortest side or diagonal) for
    // quads, 4.2 2A / longest side for triangles.
    const auto& fp = materials[static_cast<std::size_t>(mat)].fail;
    if (fp.on && fp.has_size) {
      const double len =
          triangle ? model::triangle_length(X(0), X(1), X(2)) : model::quad_length(X(0), X(1), X(2), X(3));
      g.fail_scale[static_cast<std::size_t>(i)] = fail_size_factor(fp, len);
    }
  }
  return g;
}

// Law 70's state (m70init.F), and no bulk viscosity when the property leaves qa and qb blank; OpenRadioss
// runs law 70 with Ismstr 11 (sgrtails.F): never the small-strain switch.
void init_foam_group(BrickGroup& g, const MaterialParams& gmat, const model::SolidProperty& prop) {
  g.foam.assign(static_cast<std::size_t>(kFoamVars) * kGroupSize, 0.0);
  double st[kFoamVars];
  foam_initial_state(gmat, st);
  for (std::size_t v = 0; v < static_cast<std::size_t>(kFoamVars); ++v)
    for (std::size_t i = 0; i < kGroupSize; ++i) g.foam[v * kGroupSize + i] = st[v];
  if (prop.q_default) g.qa = g.qb = 0.0;
  g.ismstr = 11;
}

// Brick i's reference geometry: its volume; with eight points their volumes, and the current volume as the
// kernel measures it (their sum); for a total-strain law (42, 70) the reference gradients of the total
// deformation gradient.
void init_brick_geometry(BrickGroup& g, int i, const std::array<model::Vec3, 8>& x, bool total_strain) {
  const double v0 = model::brick_volume(x);
  g.vol0[static_cast<std::size_t>(i)] = g.vol[static_cast<std::size_t>(i)] = v0;
  double xa[8][3];
  for (std::size_t q = 0; q < 8; ++q)
    for (std::size_t d = 0; d < 3; ++d) xa[q][d] = x[q][d];
  if (g.n_points == 8) {
    double vp[8];
    hex8_full_point_volumes(xa, vp);
    double sum = 0;
    for (std::size_t q = 0; q < 8; ++q) {
      g.vol0_p[q * kGroupSize + static_cast<std::size_t>(i)] = vp[q];
      sum += vp[q];
    }
    g.vol[static_cast<std::size_t>(i)] = sum;
  }
  if (total_strain) g.set_reference(static_cast<std::size_t>(i), xa);
}

// What every solid group takes alike from its part and elements: the part and material, the property's bulk
// viscosity, and per element its index, its nodes' slots and the initial density. `geometry(i, x)` then sets
// element i's reference geometry from its nodes' coordinates x at t = 0.
template <std::size_t kNodes, class Group, class Geometry>
void fill_solid_group(Group& g, const model::Model& m, const std::vector<MaterialParams>& materials,
                      const model::ElementBlock& b, std::int32_t part, std::span<const std::int32_t> run,
                      Geometry&& geometry) {
  const auto& prop = m.properties[m.parts[part].property].solid;
  g.part = part;
  g.material = m.parts[part].material;
  g.qa = prop.qa;
  g.qb = prop.qb;
  const double rho0 = materials[static_cast<std::size_t>(g.material)].rho0;
  for (int i = 0; i < g.count; ++i) {
    const auto e = static_cast<std::size_t>(run[static_cast<std::size_t>(i)]);
    g.element[static_cast<std::size_t>(i)] = static_cast<std::int32_t>(e);
    std::array<model::Vec3, kNodes> x{};
    for (std::size_t q = 0; q < kNodes; ++q) {
      const auto n = b.conn[kNodes * e + q];
      g.conn[q * kGroupSize + static_cast<std::size_t>(i)] = n;
      x[q] = {m.nodes.x[n], m.nodes.y[n], m.nodes.z[n]};
    }
    geometry(i, x);
    g.rho[static_cast<std::size_t>(i)] = rho0;
  }
}

// A brick group of the elements `run` of one part: the property's formulation and figures, the material's
// state, connectivity and reference geometry.
BrickGroup make_brick_group(const model::Model& m, const std::vector<MaterialParams>& materials,
                            std::pmr::memory_resource* arena, std::int32_t part,
                            std::span<const std::int32_t> run) {
  const auto& prop = m.properties[m.parts[part].property].solid;
  BrickGroup g(arena);
  g.allocate(static_cast<int>(run.size()));
  g.isolid = prop.isolid;
  g.ismstr = prop.ismstr;
  g.iframe = prop.iframe;
  g.icpre = prop.icpre;
  g.dn = prop.dn > 0 ? prop.dn : 0.1;  // Isolid 24: dn 0 means the default 0.1 (hm_read_prop14.F)
  g.h = prop.h;
  const auto& gmat = materials[static_cast<std::size_t>(m.parts[part].material)];
  const bool total_strain = gmat.law == model::MaterialLaw::Ogden || gmat.law == model::MaterialLaw::FoamTab;
  resolve_full_brick(prop, gmat, g);  // before the geometry: it sets the number of points
  fill_solid_group<8>(g, m, materials, m.bricks, part, run, [&](int i, const std::array<model::Vec3, 8>& x) {
    init_brick_geometry(g, i, x, total_strain);
  });
  // After the common set-up, whose bulk viscosity law 70 may clear.
  if (gmat.law == model::MaterialLaw::FoamTab) init_foam_group(g, gmat, prop);
  return g;
}

// A tetrahedron group of the elements `run` of one part; the property gives the bulk viscosity only (no
// hourglass).
TetraGroup make_tetra_group(const model::Model& m, const std::vector<MaterialParams>& materials,
                            std::pmr::memory_resource* arena, std::int32_t part,
                            std::span<const std::int32_t> run) {
  TetraGroup g(arena);
  g.allocate(static_cast<int>(run.size()));
  fill_solid_group<4>(g, m, materials, m.tetras, part, run, [&](int i, const std::array<model::Vec3, 4>& x) {
    const double v0 = model::tetra_volume(x[0], x[1], x[2], x[3]);
    g.vol0[static_cast<std::size_t>(i)] = g.vol[static_cast<std::size_t>(i)] = v0;
  });
  return g;
}

// A 20-node brick group of the elements `run` of one part: the Gauss rule from the property's Isolid and
// Inpts (the starter accepts 16 and 14 with 2 or 3 points per direction, and 17 as 2 x 2 x 2), the bulk
// viscosity, the initial point volumes.
Hex20Group make_hex20_group(const model::Model& m, const std::vector<MaterialParams>& materials,
                            std::pmr::memory_resource* arena, std::int32_t part,
                            std::span<const std::int32_t> run) {
  const auto& prop = m.properties[m.parts[part].property].solid;
  Hex20Group g(arena);
  g.rule =
      prop.isolid == 17 ? std::array<int, 3>{2, 2, 2} : model::hex20_rule_of_inpts(prop.inpts, prop.isolid).n;
  g.allocate(static_cast<int>(run.size()));
  fill_solid_group<20>(g, m, materials, m.bricks20, part, run,
                       [&](int i, const std::array<model::Vec3, 20>& x) {
                         double xa[20][3];
                         for (std::size_t q = 0; q < 20; ++q)
                           for (std::size_t d = 0; d < 3; ++d) xa[q][d] = x[q][d];
                         hex20_init_geometry(g, static_cast<std::size_t>(i), xa);
                       });
  return g;
}

// A spring group of the elements `run` of one part: its property and the curves it names, the frame of
// TYPE8's six laws (a fixed skew's axes: moving skews are refused by the starter), the initial lengths and,
// for TYPE13, the initial y axis.
SpringGroup make_spring_group(const model::Model& m, std::pmr::memory_resource* arena, std::int32_t part,
                              std::span<const std::int32_t> run) {
  const auto& prop = m.properties[static_cast<std::size_t>(m.parts[part].property)].spring;
  SpringGroup g(arena);
  g.allocate(static_cast<int>(run.size()));
  g.part = part;
  g.props = prop;
  auto curve = [&](std::int32_t f) {
    return f == model::kNone ? nullptr : &m.functions[static_cast<std::size_t>(f)];
  };
  for (int d = 0; d < (prop.type == 4 ? 1 : 6); ++d) {
    const auto& law = prop.law(d);
    g.curves[static_cast<std::size_t>(d)] =
        SpringLawCurves{curve(law.f_load), curve(law.f_damp), curve(law.f_unload), curve(law.f_damp4)};
  }
  if (prop.type == 8 && prop.skew != model::kNone)
    g.frame = m.skews[static_cast<std::size_t>(prop.skew)].axes;
  for (int i = 0; i < g.count; ++i) {
    const auto e = static_cast<std::size_t>(run[static_cast<std::size_t>(i)]);
    g.element[static_cast<std::size_t>(i)] = static_cast<std::int32_t>(e);
    const auto n1 = m.springs.conn[3 * e], n2 = m.springs.conn[3 * e + 1];
    g.conn[static_cast<std::size_t>(i)] = n1;
    g.conn[static_cast<std::size_t>(kGroupSize + i)] = n2;
    const auto x21 = model::sub(model::Vec3{m.nodes.x[n2], m.nodes.y[n2], m.nodes.z[n2]},
                                model::Vec3{m.nodes.x[n1], m.nodes.y[n1], m.nodes.z[n1]});
    g.l0[static_cast<std::size_t>(i)] = model::norm(x21);
    for (std::size_t d = 0; d < 3; ++d)
      g.x0[d * kGroupSize + static_cast<std::size_t>(i)] =
          x21[0] * g.frame[3 * d] + x21[1] * g.frame[3 * d + 1] + x21[2] * g.frame[3 * d + 2];
    if (prop.type == 13) {
      const auto n3 = m.springs.conn[3 * e + 2];
      const auto y = spring_type13_initial_y(
          x21,
          n3 == model::kNone ? std::optional<model::Vec3>{}
                             : model::sub(model::Vec3{m.nodes.x[n3], m.nodes.y[n3], m.nodes.z[n3]},
                                          model::Vec3{m.nodes.x[n1], m.nodes.y[n1], m.nodes.z[n1]}),
          prop.skew == model::kNone ? model::Skew{}.axes : m.skews[static_cast<std::size_t>(prop.skew)].axes);
      for (std::size_t d = 0; d < 3; ++d) g.ey[d * kGroupSize + static_cast<std::size_t>(i)] = y[d];
    }
  }
  return g;
}

// The slots of a truss or beam group (`npe` slots an element in `block`): the element, its two nodes and its
// initial length; then f(slot, element) for what the kind adds.
template <class LineGroup, class F>
void fill_line_group(const model::Model& m, const model::ElementBlock& block,
                     std::span<const std::int32_t> run, LineGroup& g, F&& f) {
  const auto npe = static_cast<std::size_t>(block.npe());
  for (int i = 0; i < g.count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const auto e = static_cast<std::size_t>(run[k]);
    g.element[k] = static_cast<std::int32_t>(e);
    const auto n1 = block.conn[npe * e], n2 = block.conn[npe * e + 1];
    g.conn[k] = n1;
    g.conn[kGroupSize + k] = n2;
    g.l0[k] = model::norm(model::sub(model::Vec3{m.nodes.x[n2], m.nodes.y[n2], m.nodes.z[n2]},
                                     model::Vec3{m.nodes.x[n1], m.nodes.y[n1], m.nodes.z[n1]}));
    f(k, e);
  }
}

// A truss group of the elements `run` of one part: the property's area, the initial lengths.
TrussGroup make_truss_group(const model::Model& m, std::pmr::memory_resource* arena, std::int32_t part,
                            std::span<const std::int32_t> run) {
  const auto& prop = m.properties[static_cast<std::size_t>(m.parts[part].property)].truss;
  TrussGroup g(arena);
  g.allocate(static_cast<int>(run.size()));
  g.part = part;
  g.material = m.parts[part].material;
  fill_line_group(m, m.trusses, run, g,
                  [&](std::size_t k, std::size_t) { g.area0[k] = g.area[k] = prop.area; });
  return g;
}

// A beam's initial y axis (peveci.F): towards its orientation node n3, else the global Y axis, or Z for a
// beam along Y. The kernel makes it normal to the beam each cycle.
model::Vec3 beam_initial_y(const model::Model& m, std::size_t e) {
  const auto* c = &m.beams.conn[3 * e];
  auto X = [&](std::int32_t n) { return model::Vec3{m.nodes.x[n], m.nodes.y[n], m.nodes.z[n]}; };
  if (c[2] != model::kNone) {
    const auto y = model::sub(X(c[2]), X(c[0]));
    return model::scale(y, 1.0 / model::norm(y));
  }
  const auto e1 = model::sub(X(c[1]), X(c[0]));
  return e1[0] * e1[0] + e1[2] * e1[2] < 1e-20 ? model::Vec3{0, 0, 1} : model::Vec3{0, 1, 0};
}

// A beam group of the elements `run` of one part: the property's section and released rotations, the initial
// lengths and y axes.
BeamGroup make_beam_group(const model::Model& m, std::pmr::memory_resource* arena, std::int32_t part,
                          std::span<const std::int32_t> run) {
  const auto& prop = m.properties[static_cast<std::size_t>(m.parts[part].property)].beam;
  BeamGroup g(arena);
  g.allocate(static_cast<int>(run.size()));
  g.part = part;
  g.material = m.parts[part].material;
  g.section = {prop.area, prop.iyy, prop.izz, prop.ixx, prop.dm, prop.df, prop.ishear != 0};
  g.releases = {1.0 - prop.release_x, 1.0 - prop.release_y1, 1.0 - prop.release_z1, 1.0 - prop.release_y2,
                1.0 - prop.release_z2};
  fill_line_group(m, m.beams, run, g, [&](std::size_t k, std::size_t e) {
    const auto y = beam_initial_y(m, e);
    for (std::size_t d = 0; d < 3; ++d) g.ey[d * kGroupSize + k] = y[d];
  });
  return g;
}

}  // namespace

// The element groups of every kind: the elements with forces of each block cut by part into runs of at most
// kGroupSize.
void ExplicitEngine::build_groups() {
  const auto& m = model_;
  std::pmr::memory_resource* arena = &group_arena_;
  for_each_group_run(m, m.shells, [&](std::int32_t part, std::span<const std::int32_t> run) {
    groups_.shells.push_back(make_shell_group(m, materials_, arena, m.shells, false, part, run));
  });
  for_each_group_run(m, m.shells3, [&](std::int32_t part, std::span<const std::int32_t> run) {
    groups_.shells.push_back(make_shell_group(m, materials_, arena, m.shells3, true, part, run));
  });
  for_each_group_run(m, m.bricks, [&](std::int32_t part, std::span<const std::int32_t> run) {
    groups_.bricks.push_back(make_brick_group(m, materials_, arena, part, run));
  });
  for_each_group_run(m, m.tetras, [&](std::int32_t part, std::span<const std::int32_t> run) {
    groups_.tetras.push_back(make_tetra_group(m, materials_, arena, part, run));
  });
  for_each_group_run(m, m.bricks20, [&](std::int32_t part, std::span<const std::int32_t> run) {
    groups_.bricks20.push_back(make_hex20_group(m, materials_, arena, part, run));
  });
  for_each_group_run(m, m.springs, [&](std::int32_t part, std::span<const std::int32_t> run) {
    groups_.springs.push_back(make_spring_group(m, arena, part, run));
  });
  for_each_group_run(m, m.trusses, [&](std::int32_t part, std::span<const std::int32_t> run) {
    groups_.trusses.push_back(make_truss_group(m, arena, part, run));
  });
  for_each_group_run(m, m.beams, [&](std::int32_t part, std::span<const std::int32_t> run) {
    groups_.beams.push_back(make_beam_group(m, arena, part, run));
  });
  element_count_ = m.element_count() + m.springs.size() + m.trusses.size() + m.beams.size();
}

// sum[d] += f[d * G] for d < C, two components at a time: the same additions as one at a time (each lane is
// its own sum), in half the instructions; GCC does not pair them itself (the f values are G apart).
template <std::size_t C, std::size_t G>
inline void add_entry(double* sum, const double* f) {
  for (std::size_t d = 0; d + 1 < C; d += 2)
    store_pair(sum + d, load_pair(sum + d) + Pair{f[d * G], f[(d + 1) * G]});
  if constexpr (C % 2 == 1) sum[C - 1] += f[(C - 1) * G];
}

// Calls f(group, nodes per element, components) for the group of flat index `flat`: the rule the domain's
// shared-node slots follow too (parallel::visit_group_entries), so the two cannot disagree on a group's
// components.
template <class F>
void ExplicitEngine::visit_group_sums(std::int64_t flat, F&& f) const {
  parallel::visit_group_entries(groups_, flat, std::forward<F>(f));
}

// The regions (runs of node chunks, kMaxSumRegions) each group writes into, and for a group writing into
// several its entries region by region, each region's in the group's own order (element, node of the
// element): one pass over the entries, then a stable sort by region, so a badly numbered mesh (a group over
// many chunks) costs no more.
void ExplicitEngine::build_sum_regions() {
  // q < 32: up to the 20 nodes of a quadratic brick
  static_assert(32 * kGroupSize <= 65536, "entry codes 32 i + q must fit in 16 bits");
  const std::int64_t groups = group_count();
  const std::int64_t chunks = node_chunks().count();
  const std::int64_t region_nodes =
      kNodeChunk * std::max<std::int64_t>(1, (chunks + kMaxSumRegions - 1) / kMaxSumRegions);
  const auto regions =
      static_cast<std::int32_t>((static_cast<std::int64_t>(nodes_.n) + region_nodes - 1) / region_nodes);
  std::vector<std::vector<std::int32_t>> group_regions(static_cast<std::size_t>(groups));
  sum_part_begin_.assign(static_cast<std::size_t>(groups) + 1, 0);
  sum_entries_begin_.assign(1, 0);
  sum_entries_.clear();
  std::vector<std::pair<std::int32_t, std::uint16_t>> entries;  // (region, code), then sorted by region
  for (std::int64_t flat = 0; flat < groups; ++flat)
    visit_group_sums(flat, [&](const auto& g, int nodes_per_element, auto) {
      entries.clear();
      for (std::size_t i = 0; i < static_cast<std::size_t>(g.count); ++i)
        for (std::size_t q = 0; q < static_cast<std::size_t>(nodes_per_element); ++q)
          entries.emplace_back(static_cast<std::int32_t>(g.conn[q * kGroupSize + i] / region_nodes),
                               static_cast<std::uint16_t>(32 * i + q));
      std::stable_sort(entries.begin(), entries.end(),
                       [](const auto& a, const auto& b) { return a.first < b.first; });
      auto& rs = group_regions[static_cast<std::size_t>(flat)];
      for (std::size_t k = 0; k < entries.size(); ++k)
        if (k == 0 || entries[k].first != entries[k - 1].first) rs.push_back(entries[k].first);
      // One part per region; a part's codes are listed only when the group has more than one.
      std::size_t k = 0;
      for (const std::int32_t r : rs) {
        for (; k < entries.size() && entries[k].first == r; ++k)
          if (rs.size() > 1) sum_entries_.push_back(entries[k].second);
        sum_entries_begin_.push_back(static_cast<std::int64_t>(sum_entries_.size()));
      }
      sum_part_begin_[static_cast<std::size_t>(flat) + 1] =
          sum_part_begin_[static_cast<std::size_t>(flat)] + static_cast<std::int64_t>(rs.size());
    });
  element_sums_order_.assign(group_regions, regions);
}

// Adds group `flat`'s nodal-force buffer to the nodes' element sums of its region regions_of(flat)[slot],
// element by element and node by node of the element: called for each region's groups in group order
// (shells, bricks, tetras, 20-node bricks, springs, ...), so each node's sum is made in one fixed order. A
// degenerate quad (n3 == n4) still has four slots; each carries its share.
void ExplicitEngine::add_group_forces(std::int64_t flat, std::int32_t slot) {
  double* sums = element_sums_.data();
  const auto part = static_cast<std::size_t>(sum_part_begin_[static_cast<std::size_t>(flat)] + slot);
  const std::uint16_t* code = sum_entries_.data() + sum_entries_begin_[part];
  const std::uint16_t* code_end = sum_entries_.data() + sum_entries_begin_[part + 1];
  visit_group_sums(flat, [&](const auto& g, int nodes_per_element, auto components) {
    constexpr std::size_t C = decltype(components)::value;
    constexpr std::size_t G = kGroupSize;
    const double* nf = g.nodal_force.data();
    const auto add = [&](std::size_t i, std::size_t q) {
      add_entry<C, G>(sums + 6 * static_cast<std::size_t>(g.conn[q * G + i]), nf + q * C * G + i);
    };
    if (code == code_end) {  // the group writes into this region only: every entry
      // The nodes per element as a constant for the usual counts, so the element's entries are unrolled.
      const auto all = [&](auto nodes) {  // an integral_constant, or the run-time count
        for (std::size_t i = 0; i < static_cast<std::size_t>(g.count); ++i)
          for (std::size_t q = 0; q < static_cast<std::size_t>(nodes); ++q) add(i, q);
      };
      switch (nodes_per_element) {
        case 2: all(std::integral_constant<std::size_t, 2>{}); break;
        case 3: all(std::integral_constant<std::size_t, 3>{}); break;
        case 4: all(std::integral_constant<std::size_t, 4>{}); break;
        case 8: all(std::integral_constant<std::size_t, 8>{}); break;
        default: all(static_cast<std::size_t>(nodes_per_element));
      }
    } else {
      for (; code != code_end; ++code) add(*code >> 5, *code & 31u);
    }
  });
}

// 3. The element stage: each group's forces, then, while its state is in cache, its time-step vote and
// its deleted elements. One chunk is one group. Each thread runs its own block of groups first (thread k of
// T: the k-th T-th of them), so a group runs on the same core every cycle and so do, mostly, the nodes it
// writes, which the node passes deal out in blocks too: its state and its nodes stay in that core's cache.
// Each group's forces are added to the nodes' sums as soon as every earlier group writing into the same
// region of node chunks is (OrderedCommit; kMaxSumRegions), by whichever thread is there: while they are
// still in cache, and each thread for its own block of nodes, beside the other's work; only the regions two
// blocks share wait for both.
void ExplicitEngine::compute_element_forces(const CycleInfo& cyc) {
  const std::int64_t groups = group_count();
  // On more than one rank another rank's group adds nothing here; it still passes its turn in the order.
  const auto owned = [this](std::int64_t flat) { return domain_ == nullptr || domain_->owns(flat); };
  const auto add = [&](std::int64_t flat, std::int32_t slot) {
    if (owned(flat)) add_group_forces(flat, slot);
  };
  element_sums_order_.reset();
  team_->run(
      groups,
      [&](std::int64_t flat) {
        if (owned(flat)) {
          group_forces_and_vote(flat, cyc);
          if (domain_) domain_->write_shared_slots(groups_, flat);
        }
        element_sums_order_.finished(flat, add);
      },
      groups >= kMinParallelGroups);
  element_sums_order_.drain(add);
  // every group's forces are in the sums
  assert(element_sums_order_.committed() == element_sums_order_.parts());
  combine_step_votes(cyc.time);
}

namespace {

// The kernel of a group: one switch per kind, no virtual call.
void run_kernel(ShellGroup& g, const NodeState& nodes, const std::vector<MaterialParams>& materials,
                const CycleInfo& cyc) {
  const auto& mat = materials[static_cast<std::size_t>(g.material)];
  switch (g.kernel) {
    case ShellKernel::Bt4: shell_bt4_forces(g, nodes, mat, cyc); break;
    case ShellKernel::Tri3: shell_c0_tri3_forces(g, nodes, mat, cyc); break;
    case ShellKernel::Qeph: shell_qeph_forces(g, nodes, mat, cyc); break;
    case ShellKernel::Qbat: shell_qbat_forces(g, nodes, mat, cyc); break;
  }
}
void run_kernel(BrickGroup& g, const NodeState& nodes, const std::vector<MaterialParams>& materials,
                const CycleInfo& cyc) {
  const auto& mat = materials[static_cast<std::size_t>(g.material)];
  switch (brick_kernel(g)) {
    case BrickKernel::OnePoint: hex8_forces(g, nodes, mat, cyc); break;  // Isolid 1 and 2
    case BrickKernel::Heph: hex8_heph_forces(g, nodes, mat, cyc); break;
    case BrickKernel::FullyIntegrated: hex8_full_forces(g, nodes, mat, cyc); break;
  }
}
void run_kernel(TetraGroup& g, const NodeState& nodes, const std::vector<MaterialParams>& materials,
                const CycleInfo& cyc) {
  tetra4_forces(g, nodes, materials[static_cast<std::size_t>(g.material)], cyc);
}
void run_kernel(Hex20Group& g, const NodeState& nodes, const std::vector<MaterialParams>& materials,
                const CycleInfo& cyc) {
  hex20_forces(g, nodes, materials[static_cast<std::size_t>(g.material)], cyc);
}
void run_kernel(SpringGroup& g, const NodeState& nodes, const std::vector<MaterialParams>&,
                const CycleInfo& cyc) {
  if (g.props.type == 8)
    spring_type8_forces(g, nodes, cyc);
  else if (g.props.type == 13)
    spring_type13_forces(g, nodes, cyc);
  else
    spring_type4_forces(g, nodes, cyc);
}
void run_kernel(TrussGroup& g, const NodeState& nodes, const std::vector<MaterialParams>& materials,
                const CycleInfo& cyc) {
  truss_axial_forces(g, nodes, materials[static_cast<std::size_t>(g.material)], cyc);
}
void run_kernel(BeamGroup& g, const NodeState& nodes, const std::vector<MaterialParams>& materials,
                const CycleInfo& cyc) {
  beam_type3_forces(g, nodes, materials[static_cast<std::size_t>(g.material)], cyc);
}

// How a group's elements vote for the step: the /DT scale of their family, the family's /DT/<family>/CST
// control, the kind the report names, and the frozen steps of the elements that family may switch to a
// constant step (null when none can be).
struct StepRule {
  double scale = 1;
  const model::DtControl* family = nullptr;
  StepControl::Kind kind = StepControl::Kind::None;
  double* frozen_steps = nullptr;
  bool switchable = false;
};
double family_scale(const model::DtControl& family, const model::RunControls& c) {
  return family.given ? family.scale : c.global.scale;
}
StepRule step_rule(ShellGroup& g, const model::RunControls& c) {
  const auto& fam = g.triangle ? c.shell3 : c.shell;
  return {family_scale(fam, c), &fam, g.triangle ? StepControl::Kind::Shell3 : StepControl::Kind::Shell,
          g.dt_fixed.data(), g.props.ismstr == 2};
}
StepRule step_rule(BrickGroup& g, const model::RunControls& c) {
  return {family_scale(c.brick, c), &c.brick, StepControl::Kind::Brick, g.dt_fixed.data(), g.ismstr == 2};
}
// Tetrahedra vote with the brick family's /DT/BRICK scale (Radioss counts them as solids); they are not
// switched by /DT/BRICK/CST (no small-strain form here).
StepRule step_rule(TetraGroup&, const model::RunControls& c) {
  return {family_scale(c.brick, c), &c.brick, StepControl::Kind::Tetra, nullptr, false};
}
// 20-node bricks vote as bricks (/DT/BRICK scale); no /DT/BRICK/CST switch (no small-strain form here).
StepRule step_rule(Hex20Group&, const model::RunControls& c) {
  return {family_scale(c.brick, c), &c.brick, StepControl::Kind::Brick, nullptr, false};
}
// Springs vote with the /DT/SPRING/STOP scale when given, else the global /DT scale (Radioss's DTFAC1(6));
// no /DT/<family>/CST switch applies.
StepRule step_rule(SpringGroup&, const model::RunControls& c) {
  return {family_scale(c.spring, c), &c.spring, StepControl::Kind::Spring, nullptr, false};
}
// Trusses vote with the global /DT scale too (Radioss's DTFAC1(4), which only /DT/TRUSS sets; radx does not
// read /DT/TRUSS).
StepRule step_rule(TrussGroup&, const model::RunControls& c) {
  return {c.global.scale, &c.global, StepControl::Kind::Truss, nullptr, false};
}
// Beams likewise (DTFAC1(5), set by /DT/BEAM, which radx does not read).
StepRule step_rule(BeamGroup&, const model::RunControls& c) {
  return {c.global.scale, &c.global, StepControl::Kind::Beam, nullptr, false};
}

// /DT/<family>/CST: an element whose scaled step reaches Tmin is switched to a constant step (the
// small-strain switch of Radioss); radx freezes the step at Tmin and keeps the element's large-strain
// kinematics (a documented difference). Without /DT/<family>/CST the step is the element's.
// Radioss switches only the elements whose Ismstr allows it (2; 12 for bricks): the others keep their own
// step under /DT/<family>/CST.
// A group's vote: the first element with the smallest scaled step. Under /DT/<family>/CST with a switchable
// element (frozen: the group's dt_fixed) each element is visited for the switch; otherwise only the
// smallest step is looked for, and the element's user id (ids[element]) is read for it alone (a read per
// element would be a second stream through the model beside the group's own arrays).
void vote_for_step(GroupVote& vote, const GroupCore& g, const StepRule& rule,
                   const std::vector<std::int64_t>& ids) {
  const double scale = rule.scale;
  const model::DtControl& fam = *rule.family;
  const StepControl::Kind kind = rule.kind;
  double* frozen_steps = rule.frozen_steps;
  const auto id_of = [&](std::size_t k) {
    return static_cast<std::int64_t>(ids[static_cast<std::size_t>(g.element[k])]);
  };
  const std::size_t n = static_cast<std::size_t>(g.count);
  if (!(rule.switchable && frozen_steps != nullptr && fam.action == model::DtAction::Constant &&
        fam.t_min > 0)) {
    double best = vote.dt;
    std::size_t at = n;
    for (std::size_t k = 0; k < n; ++k) {
      const double dt = scale * g.dt[k];
      if (dt < best) best = dt, at = k;
    }
    if (at < n) {
      vote.dt = best;
      vote.kind = kind;
      vote.user_id = id_of(at);
    }
    return;
  }
  for (std::size_t k = 0; k < n; ++k) {
    const double raw = g.dt[k];
    double& frozen = frozen_steps[k];
    double dt = scale * raw;
    if (frozen > 0) {
      // Without the small-strain kinematics the element's own stable step keeps falling; below half the
      // frozen step the run would go unstable, so it stops and says which element.
      if (dt < 0.5 * frozen && vote.violation_id == 0) {
        vote.violation_id = id_of(k);
        vote.violation_frozen = frozen;
        vote.violation_dt = dt;
      }
      dt = frozen;
    } else if (dt < fam.t_min && raw > 0) {
      frozen = fam.t_min;
      dt = frozen;
      ++vote.switched;
    }
    if (dt < vote.dt) {
      vote.dt = dt;
      vote.kind = kind;
      vote.user_id = id_of(k);
    }
  }
}

std::int64_t count_deleted_in(const GroupCore& g) {
  std::int64_t n = 0;
  for (int i = 0; i < g.count; ++i) n += g.off[static_cast<std::size_t>(i)] <= 0 ? 1 : 0;
  return n;
}

}  // namespace

// Each group's kernel, then, while its state is in cache, its vote for the step and its deleted elements
// (springs count none: their failure does not concern contact).
void ExplicitEngine::group_forces_and_vote(std::int64_t flat, const CycleInfo& cyc) {
  auto& vote = group_votes_[static_cast<std::size_t>(flat)];
  vote = GroupVote{kInf};
  groups_.visit(flat, [&](auto& g) {
    run_kernel(g, nodes_, materials_, cyc);
    vote_for_step(vote, g, step_rule(g, controls_), element_block(model_, g).id);
    const std::int64_t ended = count_deleted_in(g);
    vote.ended += ended;
    if constexpr (kHasMaterial<std::decay_t<decltype(g)>>) vote.deleted += ended;
  });
}

Chunks ExplicitEngine::node_chunks() const {
  return Chunks::of(static_cast<std::int64_t>(nodes_.n), kNodeChunk);
}

void ExplicitEngine::build_node_pass_chunks() {
  pass_chunks_.clear();
  pass_nodes_ = 0;
  const auto add_run = [this](std::size_t first, std::size_t last) {
    for (std::size_t b = first; b < last; b += static_cast<std::size_t>(kNodeChunk))
      pass_chunks_.push_back({b, std::min(last, b + static_cast<std::size_t>(kNodeChunk))});
    pass_nodes_ += last - first;
  };
  if (!domain_) {
    add_run(0, nodes_.n);
    return;
  }
  for (const auto& run : domain_->pass_runs())
    add_run(static_cast<std::size_t>(run.first), static_cast<std::size_t>(run.last));
}

// Calls body(c, first, last) for every node pass chunk c, nodes [first, last), on the team; fewer than two
// chunks' nodes on the calling thread alone.
template <class Body>
void ExplicitEngine::node_pass(Body&& body) {
  team_->run(
      static_cast<std::int64_t>(pass_chunks_.size()),
      [&](std::int64_t c) {
        const auto& span = pass_chunks_[static_cast<std::size_t>(c)];
        body(c, span.first, span.last);
      },
      pass_nodes_ >= 2 * static_cast<std::size_t>(kNodeChunk));
}

// 4-5. f = f_ext + the element sums (made in group order by the element stage), node by node; with
// `accelerate`, a = f / m and the angular a = moment / scalar inertia in the same pass (a massless node gets
// none).
void ExplicitEngine::assemble_and_accelerate(bool accelerate) {
  double* sums = element_sums_.data();
  node_pass([&](std::int64_t, std::size_t first, std::size_t last) {
    if (accelerate)
      assemble_nodes<true>(nodes_, sums, first, last);
    else
      assemble_nodes<false>(nodes_, sums, first, last);
  });
}

// The element stage's votes combined in group order, so the controlling element is the one a serial scan
// would name: the first group with the smallest step (ties go to the earlier group).
namespace {

// The /DT/<family>/STOP control of the elements a vote comes from (null for families without one).
const model::DtControl* stop_family(StepControl::Kind kind, const model::RunControls& c) {
  switch (kind) {
    case StepControl::Kind::Brick:
    case StepControl::Kind::Tetra: return &c.brick;
    case StepControl::Kind::Shell: return &c.shell;
    case StepControl::Kind::Shell3: return &c.shell3;
    case StepControl::Kind::Spring: return &c.spring;
    default: return nullptr;
  }
}
std::string short_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

// One group's vote into a rank's, in group order (flat ascending).
void add_group_vote(StepVote& into, const GroupVote& v, std::int64_t flat, const model::RunControls& c) {
  // /DT/<family>/STOP: an element of the family below its Tmin ends the run (OpenRadioss IDTMIN = 1).
  if (const auto* fam = stop_family(v.kind, c); into.stop_flat == StepVote::kNoGroup && fam != nullptr &&
                                                fam->given && fam->action == model::DtAction::Stop &&
                                                v.dt < fam->t_min) {
    into.stop = v;
    into.stop_flat = flat;
  }
  into.switched += v.switched;
  into.deleted += v.deleted;
  into.ended += v.ended;
  if (v.violation_id != 0 && into.violation_flat == StepVote::kNoGroup) {
    into.violation = v;
    into.violation_flat = flat;
  }
  if (v.dt < into.best.dt) {
    into.best = v;
    into.best_flat = flat;
  }
}

// Another rank's vote into this one: each first by its flat group (an infinite or NaN step never wins, as
// in the serial scan), counts summed, flags OR-ed.
void merge_step_votes(StepVote& into, const StepVote& v) {
  if (v.best.dt < into.best.dt ||
      (v.best.dt == into.best.dt && v.best.dt < kInf && v.best_flat < into.best_flat)) {
    into.best = v.best;
    into.best_flat = v.best_flat;
  }
  if (v.stop_flat < into.stop_flat) {
    into.stop = v.stop;
    into.stop_flat = v.stop_flat;
  }
  if (v.violation_flat < into.violation_flat) {
    into.violation = v.violation;
    into.violation_flat = v.violation_flat;
  }
  into.switched += v.switched;
  into.deleted += v.deleted;
  into.ended += v.ended;
  into.flags |= v.flags;
}

}  // namespace

// After the element stage: this rank's groups' votes in group order; on more than one rank, with the shared
// and replicated nodes' sums, every rank's vote (one small record a rank, whatever the model's size), merged.
void ExplicitEngine::combine_step_votes(double time) {
  step_vote_ = StepVote{};
  if (!domain_) {
    for (std::int64_t flat = 0; flat < group_count(); ++flat)
      add_group_vote(step_vote_, group_votes_[static_cast<std::size_t>(flat)], flat, controls_);
    return;
  }
  for (const std::int64_t flat : domain_->plan().groups)
    add_group_vote(step_vote_, group_votes_[static_cast<std::size_t>(flat)], flat, controls_);
  if (options_.output_due && options_.output_due(time)) step_vote_.flags |= StepVote::kOutputDue;
  if (!options_.state_due || options_.state_due(time)) step_vote_.flags |= StepVote::kStateDue;
  static_assert(std::is_trivially_copyable_v<StepVote>);
  parallel::Buffer mine(sizeof(StepVote));
  std::memcpy(mine.data(), &step_vote_, sizeof(StepVote));  // padding included: the merge reads fields only
  const auto all = domain_->complete_element_sums(element_sums_, mine);
  step_vote_ = StepVote{};
  for (const auto& theirs : all) {
    if (theirs.size() != sizeof(StepVote)) throw std::runtime_error("a rank's step vote has the wrong size");
    StepVote v;
    std::memcpy(&v, theirs.data(), sizeof(StepVote));
    merge_step_votes(step_vote_, v);
  }
}

// The combined vote's step and what controls it; its /DT/.../STOP and /CST findings, for choose_time_step.
double ExplicitEngine::element_time_step(StepControl& control) {
  const StepVote& v = step_vote_;
  if (v.stop_flat != StepVote::kNoGroup && step_stop_.empty())
    step_stop_ = step_control_name(StepControl{v.stop.kind, v.stop.user_id}) + " has the step " +
                 short_number(v.stop.dt) + ", below the " + step_stop_keyword(v.stop.kind) + " minimum " +
                 short_number(stop_family(v.stop.kind, controls_)->t_min);
  switched_elements_ += v.switched;
  if (v.violation_flat != StepVote::kNoGroup && cst_violation_.empty())
    cst_violation_ = "element " + std::to_string(v.violation.violation_id) +
                     " was held at the /DT/.../CST step " + std::to_string(v.violation.violation_frozen) +
                     " but its own stable step fell to " + std::to_string(v.violation.violation_dt) +
                     " (radx keeps large-strain kinematics after the switch); the run stops before it "
                     "goes unstable: refine the mesh or use /DT/NODA/CST";
  if (v.best_flat != StepVote::kNoGroup) {
    control.kind = v.best.kind;
    control.user_id = v.best.user_id;
  }
  return v.best.dt;
}

double ExplicitEngine::nodal_time_step(StepControl& control) {
  // /DT/NODA/CST: dt_n = Tscale sqrt(2 m / K) with K the sum of the element stiffness estimates at the
  // node (docs/theory/elements.md 4.5); below Tmin, mass is added so that
  // dt_n = Tmin: m = K (Tmin / Tscale)^2 / 2.
  auto& s = nodes_;
  std::fill(s.stiffness.begin(), s.stiffness.end(), 0.0);
  groups_.for_each([&](const auto& g) { add_nodal_stiffness(g, s.stiffness); });
  kinematics_->transfer_tied_stiffness();
  const auto& noda = controls_.nodal;
  double best = kInf;
  for (std::size_t n = 0; n < s.n; ++n) {
    const double k = s.stiffness[n];
    if (k <= 0 || s.mass[n] <= 0) continue;
    double dt = noda.scale * std::sqrt(2.0 * s.mass[n] / k);
    if (noda.action == model::DtAction::AddMass && noda.t_min > 0 && dt < noda.t_min) {
      const double m_needed = 0.5 * k * (noda.t_min / noda.scale) * (noda.t_min / noda.scale);
      s.added_mass[n] += m_needed - s.mass[n];
      s.mass[n] = m_needed;
      dt = noda.t_min;
    }
    if (dt < best) {
      best = dt;
      control.kind = StepControl::Kind::Node;
      control.user_id = model_.nodes.id[n];
    }
  }
  return best;
}

namespace {

template <class Group>
std::string solid_name() {
  return std::is_same_v<Group, BrickGroup>   ? "brick "
         : std::is_same_v<Group, Hex20Group> ? "20-node brick "
                                             : "tetrahedron ";
}

// A value as %g writes it: a step of 1e-300 must not read 0.000000.
std::string short_text(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", v);
  return text;
}

// Why a run stops on an energy that is not finite: the energies that are not, and the first node whose
// kinetic energy 1/2 m v^2 or external force is not (a rigid material of density 1e300 still moves and keeps
// finite coordinates, but its kinetic energy overflows), else, for the external work, the imposed motions and
// loads.
std::string nonfinite_energy_message(const EnergyBalance& e, const NodeState& s, const model::Model& m) {
  const std::pair<const char*, double> terms[] = {
      {"kinetic", e.kinetic_t + e.kinetic_r},
      {"internal", e.internal},
      {"hourglass", e.hourglass},
      {"external work", e.external_work},
      {"contact", e.contact_elastic + e.contact_damping + e.contact_friction + e.contact_lagrange}};
  std::string which;
  for (const auto& [name, value] : terms)
    if (!std::isfinite(value)) which += std::string(which.empty() ? "" : ", ") + name;
  std::string message = "the " + which + " energy is not finite";
  for (std::size_t n = 0; n < s.n; ++n) {
    const double v2 = s.vx[n] * s.vx[n] + s.vy[n] * s.vy[n] + s.vz[n] * s.vz[n];
    const double f = s.fx_ext[n] + s.fy_ext[n] + s.fz_ext[n];
    if (std::isfinite(s.mass[n] * v2) && std::isfinite(f)) continue;
    message += " (node " + std::to_string(m.nodes.id[n]) + ": mass " + short_text(s.mass[n]) + ", speed " +
               short_text(std::sqrt(v2)) + ", external force " + short_text(f) + ")";
    return message +
           ": a density, mass, stiffness, velocity or load of the deck is beyond the range of doubles";
  }
  if (!std::isfinite(e.external_work))  // no node's own values: the work of an imposed motion's reaction
    return message +
           ": an imposed motion or a load (/IMPVEL, /IMPDISP, /IMPACC, /CLOAD, /PLOAD, /GRAV) or its "
           "/FUNCT curve is beyond the range of doubles";
  return message +
         ": a density, mass, stiffness, velocity or load of the deck is beyond the range of doubles";
}

}  // namespace

// The first element, in group order, without a valid step: a solid's volume went to zero or below, a
// shell collapsed or its values are no longer finite.
std::string ExplicitEngine::bad_element(double time, std::int64_t cycle) const {
  const std::string when = " at cycle " + std::to_string(cycle) + ", time " + std::to_string(time);
  std::string found;
  groups_.for_each([&](const auto& g) {
    using Group = std::decay_t<decltype(g)>;
    if constexpr (kHasMaterial<Group>) {
      for (int i = 0; i < g.count && found.empty(); ++i) {
        const auto k = static_cast<std::size_t>(i);
        if (g.dt[k] > 0) continue;
        const auto id = std::to_string(element_block(model_, g).id[static_cast<std::size_t>(g.element[k])]);
        if constexpr (std::is_same_v<Group, ShellGroup>)
          found = std::string(g.triangle ? "3-node shell " : "shell ") + id +
                  " has no valid time step (collapsed or non-finite)" + when + "; the run stops";
        else if constexpr (std::is_same_v<Group, TrussGroup> || std::is_same_v<Group, BeamGroup>)
          found = std::string(std::is_same_v<Group, BeamGroup> ? "beam " : "truss ") + id +
                  " has no valid time step (its nodes met or its values are not finite)" + when +
                  "; the run stops";
        else if (!(g.vol[k] > 0))
          found = solid_name<Group>() + id + " has a zero or negative volume (" + std::to_string(g.vol[k]) +
                  ")" + when + ": the mesh is inverted; the run stops";
        else  // a sound volume with a step of 0 or NaN: the sound speed or the bulk viscosity is at fault
          found =
              solid_name<Group>() + id + " has no valid time step (" + short_text(g.dt[k]) +
              ") though its volume is positive (" + short_text(g.vol[k]) + ")" + when +
              ": its material's sound speed or its property's bulk viscosity (qa, qb) is not finite or too "
              "large; the run stops";
      }
    }
  });
  return found.empty() ? "an element has no valid time step at cycle " + std::to_string(cycle) : found;
}

CycleReport ExplicitEngine::report(std::int64_t cycle, double time, double dt,
                                   const StepControl& control) const {
  CycleReport r;
  r.cycle = cycle;
  r.time = time;
  r.dt = dt;
  r.control = control;
  r.energy = energy_;
  r.mass0 = mass0_;
  r.mass = total_mass();
  model::ExactSum added;
  for (std::size_t n = 0; n < nodes_.n; ++n) added.add(nodes_.added_mass[n]);
  r.added_mass = added.value();
  return r;
}

// The nodal masses with each rigid body counted once, exact and order-free (docs/theory/elements.md 8.1).
double ExplicitEngine::total_mass() const {
  model::ExactSum mass = kinematics_->mass_correction();
  for (std::size_t n = 0; n < nodes_.n; ++n) mass.add(nodes_.mass[n]);
  return mass.value();
}

// The time loop. Each cycle is the list of its stages, in the order of explicit_engine.hpp:
//   0. skews_.update (moving skews of x^n), and the TYPE8 springs' frames that follow them
//   1. external_loads        2. contact_forces (penalty, votes, LAGDT switches)
//   3-4. element_forces (groups, then the deterministic assembly with the contact forces)
//   9. choose_time_step (early: the step of this cycle comes from the votes just computed), then the sensors
//   4b. transfer_tied_forces (/INTER/TYPE2 secondary forces and moments onto the main segments)
//   5. accelerations         6. lagrange_correction (switched LAGDT pairs)
//   7. kinematic_conditions  10. outputs (energies on report cycles, the caller's on_cycle)
//   8. integrate             11. advance
// A stage that ends the run returns false with res.status and res.message set.
RunResult ExplicitEngine::run(const std::function<bool(const CycleReport&)>& on_cycle) {
  RunResult res;
  res.threads = team_->size();
  const auto t_wall0 = std::chrono::steady_clock::now();
  sensors_.update(0.0, 0.0);  // a sensor due at t = 0 is on from the start
  kinematics_->initial_conditions();
  if (contact_) held_ = kinematics_->held_nodes();
  // Reference mass after the set-up (rigid bodies and moving walls may add mass).
  mass0_ = total_mass();

  LoopState L;
  while (true) {
    skews_.update(nodes_);  // 0.
    follow_moving_skews();
    external_loads(L);
    element_forces(L);
    contact_forces(L);
    if (!choose_time_step(L, res)) break;
    sensors_.update(L.time, L.dt2);
    kinematics_->transfer_tied_forces();  // 4b. TYPE2: before the accelerations, as in OpenRadioss
    if (!fuse_accelerations_) accelerations(L);
    if (!lagrange_correction(L, res)) break;
    kinematics_->kinematic_conditions(L.time, L.dt1, L.dt2);
    if (!accelerometers_->empty()) accelerometers_->update(nodes_, L.dt12(), L.dt2 > 0 ? L.dt2 : L.dt1);
    const bool last = L.time >= controls_.t_stop || L.dt2 <= 0;
    if (!outputs(L, last, on_cycle, res)) break;
    if (last) break;
    if (!integrate(L, res)) break;
    L.time = L.reaches_end ? controls_.t_stop : L.time + L.dt2;  // 11.
    L.dt1 = L.dt2;
    ++L.cycle;
    L.first = false;
  }
  // An error ends the loop on every rank at once (every stop is decided on shared values); the state the
  // caller writes then must be every node's.
  if (domain_ && res.status != RunStatus::Normal) share_output_state(true);
  res.cycles = L.cycle;
  res.time = L.time;
  res.dt1 = L.dt1;
  res.dt = L.dt2 > 0 ? L.dt2 : L.dt1;  // the last step taken (the final cycle only reaches Tstop)
  res.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_wall0).count();
  res.element_seconds = L.element_seconds;
  res.contact_seconds = L.contact_seconds;
  return res;
}

// 1. External loads at t_n into f*_ext; moments start from zero (integrate() zeroed them after the last
// cycle's update, in its pass over the nodes).
void ExplicitEngine::external_loads(LoopState& L) {
  auto& s = nodes_;
  if (!loads_zeroed_)
    for (auto* v : {&s.fx_ext, &s.fy_ext, &s.fz_ext, &s.mx, &s.my, &s.mz})
      std::fill(v->begin(), v->end(), 0.0);
  loads_zeroed_ = false;
  kinematics_->external_loads(L.time, L.dt1, L.dt2);
}

// 3-4. Element groups, then the assembly f = f_ext + f_elements node by node (and a = f / m when fused).
void ExplicitEngine::element_forces(LoopState& L) {
  const auto t0 = std::chrono::steady_clock::now();
  compute_element_forces(CycleInfo{L.dt1, L.dt2, L.time});
  list_deleted_elements(L.cycle, L.time);
  assemble_and_accelerate(fuse_accelerations_);
  L.element_seconds += seconds_since(t0);
}

// 2. Contact at x^n with v^{n-1/2}: Idel first (contact learns which elements were deleted), then the penalty
// forces added node by node in ascending order, the contact time-step vote and this cycle's switched pairs.
void ExplicitEngine::contact_forces(LoopState& L) {
  L.dt_contact = kInf;
  if (!contact_) return;
  const auto t0 = std::chrono::steady_clock::now();
  tell_contact_deleted_elements();
  auto& s = nodes_;
  contact::ContactNodes v{s.x, s.y, s.z, s.vx, s.vy, s.vz, s.mass, s.added_mass, s.fixed, held_};
  const contact::ContactStep step = contact_->compute(L.time, L.dt1, v, sensors_.starts());
  const auto& f = contact_->force();
  for (const auto n : contact_->touched()) {
    const auto k = static_cast<std::size_t>(n);
    s.fx[k] += f[3 * k];
    s.fy[k] += f[3 * k + 1];
    s.fz[k] += f[3 * k + 2];
    if (fuse_accelerations_) accelerate_node(s, k);
  }
  if (step.dt < kInf) {
    L.dt_contact = step.dt;
    L.contact_control.kind = StepControl::Kind::Interface;
    L.contact_control.user_id = step.interface_id;
    L.contact_control.node_id = step.node_id;
  }
  L.contact_seconds += seconds_since(t0);
}

// 0. A TYPE8 spring in a /SKEW/MOV works in the skew's current axes (OpenRadioss r2def3.F): its group's
// frame follows the skew; its offsets x0 stay those of t = 0 in the initial axes.
void ExplicitEngine::follow_moving_skews() {
  for (auto& g : groups_.springs) {
    const auto skew = g.props.skew;
    if (g.props.type != 8 || skew == model::kNone || !model_.skews[static_cast<std::size_t>(skew)].moving())
      continue;
    g.frame = skews_.axes(skew);
  }
}

void ExplicitEngine::tell_contact_deleted_elements() {
  const std::int64_t deleted = count_deleted();
  if (deleted == deleted_elements_) return;
  deleted_elements_ = deleted;
  // The count is every rank's (gathered votes); the elements' life factors come from their owners.
  if (domain_) domain_->share_group_arrays(groups_, [](auto& g, auto&& visit) { visit(g.off); });
  std::vector<std::uint8_t> alive(model_.element_count(), 1);
  groups_.for_each([&](const auto& g) {
    if constexpr (kMeshCell<std::decay_t<decltype(g)>>) {
      for (int i = 0; i < g.count; ++i)
        if (g.off[static_cast<std::size_t>(i)] <= 0)
          alive[first_cell(model_, g) + static_cast<std::size_t>(g.element[static_cast<std::size_t>(i)])] = 0;
    }
  });
  contact_->elements_deleted(alive);
}

// 9 (early). dt2 = min(element or nodal step, contact vote, 1.1 dt1), cut at Tstop; stops on a bad element,
// a /DT/.../CST violation, a non-finite step or a step below the /DT minimum.
bool ExplicitEngine::choose_time_step(LoopState& L, RunResult& res) {
  StepControl ctl;
  double dt_elem = element_time_step(ctl);
  if (!(dt_elem > 0)) {
    if (domain_)  // the bad element's step and volume from its owner (every rank sees the same votes)
      domain_->share_group_arrays(groups_, [](auto& g, auto&& visit) {
        visit(g.dt);
        if constexpr (requires { g.vol; }) visit(g.vol);
      });
    res.status = RunStatus::Error;
    res.message = bad_element(L.time, L.cycle);
    return false;
  }
  if (!cst_violation_.empty()) {
    res.status = RunStatus::Error;
    res.message =
        cst_violation_ + " (cycle " + std::to_string(L.cycle) + ", time " + std::to_string(L.time) + ")";
    return false;
  }
  // /DT/INTER/STOP: the contact vote (its own scale applied) below Tmin ends the run.
  const auto& inter = controls_.inter;
  if (step_stop_.empty() && inter.given && inter.action == model::DtAction::Stop &&
      L.dt_contact < inter.t_min)
    step_stop_ = "interface " + std::to_string(L.contact_control.user_id) + " (secondary node " +
                 std::to_string(L.contact_control.node_id) + ") has the step " + short_number(L.dt_contact) +
                 ", below the /DT/INTER/STOP minimum " + short_number(inter.t_min);
  if (!step_stop_.empty()) {
    res.status = RunStatus::Error;
    res.message = "the run stops: " + step_stop_ + " (cycle " + std::to_string(L.cycle) + ", time " +
                  short_number(L.time) + ")";
    return false;
  }
  if (controls_.nodal.given) {  // /DT/NODA and /DT/NODA/CST: the nodal step replaces the element step
    StepControl nctl;
    // Every group's stiffness at its nodes, from the group's owner (the nodal pass runs on every rank).
    if (domain_) domain_->share_group_arrays(groups_, [](auto& g, auto&& visit) { visit(g.k_nodal); });
    dt_elem = nodal_time_step(nctl);  // /DT/NODA replaces the element step by the nodal one
    ctl = nctl;
  }
  if (L.dt_contact < dt_elem) {  // contact votes on the step (its own scale is already applied)
    dt_elem = L.dt_contact;
    ctl = L.contact_control;
  }
  if (L.first) {
    L.dt2 = dt_elem;
    if (controls_.dt_initial > 0 && controls_.dt_initial < L.dt2) {  // /DTIX DT_ini
      L.dt2 = controls_.dt_initial;
      ctl = StepControl{StepControl::Kind::Imposed, 0, 0};
    }
  } else {
    L.dt2 = std::min(dt_elem, 1.1 * L.dt1);
    if (L.dt2 != dt_elem) ctl = L.control;
  }
  if (L.dt2 > controls_.dt_max) {  // /DTIX DT_max
    L.dt2 = controls_.dt_max;
    ctl = StepControl{StepControl::Kind::Imposed, 0, 0};
  }
  if (!std::isfinite(L.dt2)) {
    res.status = RunStatus::Error;
    res.message = "no finite time step: the model has no element with a stable step";
    return false;
  }
  // The step that reaches the end time ends on it. A step that would leave less than a millionth of
  // itself is stretched to the end (stable: the step carries its /DT scale): without that, time summed in
  // floating point leaves a last cycle of round-off size (3000 steps of 1e-3 s end 2.2e-13 s short of 3 s)
  // that evaluates loads and imposed velocities at the end time once more, as OpenRadioss does not.
  const double remaining = controls_.t_stop - L.time;
  L.reaches_end = L.dt2 >= remaining - 1e-6 * L.dt2;
  if (L.reaches_end) L.dt2 = std::max(remaining, 0.0);
  L.control = ctl;
  if (controls_.global.t_min > 0 && dt_elem < controls_.global.t_min) {
    res.status = RunStatus::Error;
    res.message = "the time step " + std::to_string(dt_elem) + " fell below the /DT minimum " +
                  std::to_string(controls_.global.t_min);
    return false;
  }
  return true;
}

// 5. a = f / m for every node: after the TYPE2 ties moved forces (otherwise the assembly pass did it).
void ExplicitEngine::accelerations(LoopState& L) {
  const auto t0 = std::chrono::steady_clock::now();
  auto& s = nodes_;
  node_pass([&](std::int64_t, std::size_t first, std::size_t last) {
    for (std::size_t n = first; n < last; ++n) accelerate_node(s, n);
  });
  L.element_seconds += seconds_since(t0);
}

// 6. The switched LAGDT pairs' multipliers correct a; their forces join f (outputs: reactions, internal
// forces). A CHOLMOD failure stops the run with its message.
bool ExplicitEngine::lagrange_correction(LoopState& L, RunResult& res) {
  if (!contact_ || contact_->switched_pairs() == 0) return true;
  auto& s = nodes_;
  const auto t0 = std::chrono::steady_clock::now();
  try {
    const auto& forces = contact_->lagrange_correction(
        contact::LagrangeNodesView{s.mass, s.vx, s.vy, s.vz, s.ax, s.ay, s.az, s.fixed}, L.dt1, L.dt2);
    for (const auto& nf : forces) {
      const auto k = static_cast<std::size_t>(nf.node);
      s.fx[k] += nf.f[0];
      s.fy[k] += nf.f[1];
      s.fz[k] += nf.f[2];
    }
  } catch (const std::exception& e) {
    res.status = RunStatus::Error;
    res.message = std::string("the Lagrange-multiplier contact solve failed at cycle ") +
                  std::to_string(L.cycle) + ", time " + std::to_string(L.time) + ": " + e.what();
    return false;
  }
  L.contact_seconds += seconds_since(t0);
  return true;
}

// 10. Energies at t_n (docs/theory/elements.md section 8; summed only on report cycles, they cost a pass over
// every element and node), then the caller's on_cycle (listing, states, /STOP), which may stop the run.
bool ExplicitEngine::outputs(LoopState& L, bool last, const std::function<bool(const CycleReport&)>& on_cycle,
                             RunResult& res) {
  // On more than one rank, a stop signal seen by one rank makes the cycle full on all: each rank's
  // output_due, read at the element stage, rode in the step vote.
  const bool due = domain_ ? (step_vote_.flags & StepVote::kOutputDue) != 0
                           : options_.output_due && options_.output_due(L.time);
  const bool full = L.first || last || L.cycle % std::max<std::int64_t>(1, options_.report_every) == 0 || due;
  CycleReport rep;
  if (full) {
    share_output_state(L.first || last || th_reads_elements_ ||
                       (step_vote_.flags & StepVote::kStateDue) != 0);
    sum_energies(L);
    rep = report(L.cycle, L.time, L.dt2, L.control);
    rep.momentum = momentum_;
    rep.dt1 = L.dt1;
  } else {
    rep.cycle = L.cycle;
    rep.time = L.time;
    rep.dt = L.dt2;
    rep.dt1 = L.dt1;
    rep.control = L.control;
  }
  rep.switched_pairs = contact_ ? contact_->switched_pairs() : 0;
  rep.full = full;
  if (full) res.last = rep;
  // A normal end must not report energies that are not numbers.
  if (full && !std::isfinite(energy_.total() + energy_.external_work + energy_.initial_total)) {
    res.status = RunStatus::Error;
    res.message = nonfinite_energy_message(energy_, nodes_, model_) + " (cycle " + std::to_string(L.cycle) +
                  ", time " + short_text(L.time) + "); the run stops";
    return false;
  }
  // Every rank stops when one does (a write failure or a signal may be one rank's alone): decided on full
  // cycles, where the ranks agree to meet; a rank's wish to stop on a partial cycle waits for the next one.
  stop_wanted_ = (on_cycle && !on_cycle(rep)) || stop_wanted_;
  const bool stop = domain_ == nullptr ? stop_wanted_ : full && any_rank(stop_wanted_);
  if (stop) {
    res.status = RunStatus::Error;
    if (res.message.empty()) res.message = "stopped by a /STOP criterion";
    return false;
  }
  return true;
}

// On more than one rank: whether any rank says `mine` (every rank gets the same answer); else `mine`.
bool ExplicitEngine::any_rank(bool mine) const {
  if (!domain_) return mine;
  std::uint64_t word = mine ? 1 : 0;
  domain_->comm().bit_or(std::span(&word, 1));
  return word != 0;
}

// On more than one rank: the node and group state the result fields and the time history read, from each
// node's and group's owner into rank 0's copy (the writer), so it reads what one rank has. The other ranks
// need none of it: the energies come from each owner's sums (kinetic_sums, sum_energies).
void ExplicitEngine::share_output_state(bool whole) {
  if (!domain_) return;
  if (!whole) {  // the time history's nodes, and its parts: motion, energies and eroded mass
    domain_->gather_node_motion(nodes_, 0);
    domain_->share_group_arrays(
        groups_,
        [](auto& g, auto&& visit) {
          visit(g.off);
          visit(g.e_int);
          if constexpr (requires { g.e_hg; }) visit(g.e_hg);
        },
        0);
    return;
  }
  domain_->gather_node_state(nodes_, 0);
  domain_->share_group_arrays(
      groups_,
      [](auto& g, auto&& visit) {
        visit(g.off);
        visit(g.e_int);
        visit(g.dt);
        visit(g.k_nodal);  // the nodal_time_step field, with or without /DT/NODA
        if constexpr (requires { g.sig; }) {
          visit(g.sig);
          visit(g.eps_p);
          visit(g.dmg);
          visit(g.e_hg);
          visit(g.w_plastic);
          visit(g.rate);
        }
        if constexpr (requires { g.thick; }) {
          visit(g.thick);
          visit(g.dmg_inst);
        }
        if constexpr (requires { g.sig_p; }) {
          visit(g.sig_p);
          visit(g.eps_p_p);
          visit(g.dmg_p);
        }
        if constexpr (requires { g.vol; }) {
          visit(g.vol);
          visit(g.rho);
          visit(g.q);
        }
        if constexpr (requires { g.force; }) visit(g.force);
        if constexpr (requires { g.dx; }) visit(g.dx);
        if constexpr (std::is_same_v<std::decay_t<decltype(g)>, TrussGroup>) {
          visit(g.strain);
          visit(g.area);
        }
        if constexpr (requires { g.resultant; }) visit(g.resultant);
        // A co-rotational brick's stress is kept in its element frame (brick_global_stress rotates it back).
        if constexpr (std::is_same_v<std::decay_t<decltype(g)>, BrickGroup>) visit(g.frame);
      },
      0);
}

// Kinetic energy and momentum at t_n (energy_, momentum_): exact sums over every node, the rigid bodies
// counted once; on more than one rank each rank sums the nodes it owns (rank 0 the bodies' correction), and
// the sums' bins are added over the ranks, which gives one rank's bits.
void ExplicitEngine::kinetic_sums(double dt1) {
  std::vector<std::array<std::size_t, 2>> runs;
  if (!domain_) {
    runs.push_back({0, nodes_.n});
  } else {
    for (const auto& r : domain_->owned_runs())
      runs.push_back({static_cast<std::size_t>(r.first), static_cast<std::size_t>(r.last)});
  }
  KineticSums sums = kinematics_->kinetic_sums(dt1, runs, !domain_ || domain_->comm().rank() == 0);
  std::array<model::ExactSum*, 5> parts{&sums.translational, &sums.rotational, &sums.momentum[0],
                                        &sums.momentum[1], &sums.momentum[2]};
  if (domain_) {
    constexpr std::size_t n = model::ExactSum::kStateSize;
    std::vector<std::int64_t> bins(parts.size() * n);
    for (std::size_t k = 0; k < parts.size(); ++k) {
      parts[k]->normalise();
      std::copy_n(parts[k]->state().begin(), n, bins.begin() + static_cast<std::ptrdiff_t>(k * n));
    }
    domain_->comm().sum_exact(bins);
    for (std::size_t k = 0; k < parts.size(); ++k)
      *parts[k] = model::ExactSum::from_state(std::span(bins).subspan(k * n, n));
  }
  energy_.kinetic_t = sums.translational.value();
  energy_.kinetic_r = sums.rotational.value();
  momentum_ = {sums.momentum[0].value(), sums.momentum[1].value(), sums.momentum[2].value()};
}

// The element energies: each group's partial sums (from 0, in element order), then the partials added in
// flat group order. A group is never split between ranks, so its partial is the same on any rank count; on
// more than one rank each owner sends its groups' partials to every rank, which adds them in this order.
void ExplicitEngine::sum_energies(const LoopState& L) {
  auto& kin = *kinematics_;
  struct GroupEnergy {
    double internal = 0, hourglass = 0, plastic_work = 0;
    bool spring = false;  // a spring group: its internal energy is the spring energy
  };
  std::vector<GroupEnergy> partials(static_cast<std::size_t>(groups_.count()));
  std::int64_t flat = -1;
  groups_.for_each([&](const auto& g) {
    ++flat;
    if (domain_ && !domain_->owns(flat)) return;  // its owner's partial arrives below
    GroupEnergy e;
    for (int i = 0; i < g.count; ++i) {
      const auto k = static_cast<std::size_t>(i);
      e.internal += g.e_int[k];
      if constexpr (kHasMaterial<std::decay_t<decltype(g)>>) {
        e.hourglass += g.e_hg[k];
        e.plastic_work += g.w_plastic[k];
      }
    }
    e.spring = !kHasMaterial<std::decay_t<decltype(g)>>;
    partials[static_cast<std::size_t>(flat)] = e;
  });
  if (domain_) domain_->share_group_records(std::span(partials));
  energy_.internal = energy_.hourglass = energy_.plastic_work = energy_.spring = 0;
  for (const auto& e : partials) {
    if (e.spring) {
      energy_.spring += e.internal;
    } else {
      energy_.internal += e.internal;
      energy_.hourglass += e.hourglass;
      energy_.plastic_work += e.plastic_work;
    }
  }
  energy_.internal += energy_.spring;
  if (contact_) {
    energy_.contact_elastic = contact_->energy_elastic();
    energy_.contact_damping = contact_->energy_damping();
    energy_.contact_friction = contact_->energy_friction();
    energy_.contact_lagrange = contact_->energy_lagrange();
  }
  kinetic_sums(L.dt1);
  energy_.external_work = kin.external_work();
  if (L.first) energy_.initial_total = energy_.total() - energy_.external_work;
  const double denom = energy_.initial_total + energy_.external_work;
  const double e_tot = energy_.total();
  energy_.error_percent =
      std::abs(denom) <= 1e-20 ? 0.0 : std::clamp(100.0 * (e_tot / denom - 1.0), -99.9, 99.9);
}

// 8. v^{n+1/2} = v^{n-1/2} + dt12 a^n, x^{n+1} = x^n + dt2 v^{n+1/2}; a non-finite coordinate stops the run.
// The same pass zeroes the external forces and moments for the next cycle's loads (step 1).
bool ExplicitEngine::integrate(LoopState& L, RunResult& res) {
  const auto t0 = std::chrono::steady_clock::now();
  auto& s = nodes_;
  const double dt12 = L.dt12();
  const double dt2 = L.dt2;
  std::vector<std::uint8_t> chunk_finite(pass_chunks_.size(), 1);
  node_pass([&](std::int64_t c, std::size_t first, std::size_t last) {
    chunk_finite[static_cast<std::size_t>(c)] = integrate_nodes(s, dt12, dt2, first, last) ? 1 : 0;
  });
  loads_zeroed_ = true;
  const bool finite =
      !any_rank(std::any_of(chunk_finite.begin(), chunk_finite.end(), [](std::uint8_t f) { return f == 0; }));
  if (finite && domain_) domain_->update_ghosts(s);
  L.element_seconds += seconds_since(t0);
  kinematics_->after_update(dt2);
  if (finite) return true;
  res.status = RunStatus::Error;
  res.message = "node " + std::to_string(first_nonfinite_node()) + " has non-finite coordinates at cycle " +
                std::to_string(L.cycle) + ", time " + std::to_string(L.time) +
                ": the run is unstable (check the time step and the mesh)";
  return false;
}

// The user id of the first node (in node order) with a non-finite coordinate among those the ranks integrate,
// or 0: each rank's first, the smallest of them.
std::int64_t ExplicitEngine::first_nonfinite_node() const {
  const auto& s = nodes_;
  std::int64_t first = std::numeric_limits<std::int64_t>::max();
  for (const auto& span : pass_chunks_)
    for (std::size_t n = span.first; n < span.last && first == std::numeric_limits<std::int64_t>::max(); ++n)
      if (!std::isfinite(s.x[n] + s.y[n] + s.z[n])) first = static_cast<std::int64_t>(n);
  if (domain_) {
    const parallel::Vote v = domain_->comm().vote(parallel::Vote{static_cast<double>(first), first});
    first = v.key;
  }
  return first == std::numeric_limits<std::int64_t>::max() ? 0
                                                           : model_.nodes.id[static_cast<std::size_t>(first)];
}

}  // namespace radx::solver
