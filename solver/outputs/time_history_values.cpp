// Time-history values; the definition of every variable is in time_history_values.hpp.
#include "solver/outputs/time_history_values.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <type_traits>

#include "solver/conditions/kinematics_driver.hpp"
#include "solver/conditions/rigid_body.hpp"
#include "solver/elements/shell/shell_section.hpp"
#include "solver/model/exact_sum.hpp"
#include "solver/model/masses.hpp"

namespace radx::solver {

namespace {

constexpr Dim kEnergy{1, 2, -2}, kMomentum{1, 1, -1}, kMass{1, 0, 0}, kTime{0, 0, 1}, kLength{0, 1, 0},
    kVelocity{0, 1, -1}, kAcceleration{0, 1, -2}, kForce{1, 1, -2}, kMoment{1, 2, -2}, kNone{0, 0, 0},
    kAngularVelocity{0, 0, -1}, kAngularAcceleration{0, 0, -2}, kForcePerLength{1, 0, -2},
    kMomentPerLength{1, 1, -2}, kStress{1, -1, -2}, kDensity{1, -3, 0}, kVolume{0, 3, 0}, kRate{0, 0, -1},
    kInertia{1, 2, 0};

std::size_t index_of(const std::vector<std::string>& names, const std::string& v) {
  return static_cast<std::size_t>(std::find(names.begin(), names.end(), v) - names.begin());
}

// What 8-node and 20-node bricks write alike under /TH/BRIC: their state scalars and the centre velocity v.
template <class Put, class Group>
void put_solid_state(const Put& put, std::size_t o, const Group& g, std::size_t k, const double (&v)[3]) {
  put(o, "OFF", g.off[k]);
  put(o, "IE", g.vol0[k] > 0 ? g.e_int[k] / g.vol0[k] : 0.0);
  put(o, "DENS", g.rho[k]);
  put(o, "BULK", g.q[k]);
  put(o, "VOL", g.vol[k]);
  put(o, "PLAS", g.eps_p[k]);
  put(o, "PLSR", g.rate[k]);
  put(o, "VX", v[0]);
  put(o, "VY", v[1]);
  put(o, "VZ", v[2]);
}

}  // namespace

const std::vector<ThVariableInfo>& global_th_variables() {
  static const std::vector<ThVariableInfo> v = {
      {"IE", kEnergy}, {"KE", kEnergy}, {"XMOM", kMomentum},   {"YMOM", kMomentum},  {"ZMOM", kMomentum},
      {"MASS", kMass}, {"DT", kTime},   {"RKE", kEnergy},      {"EXTW", kEnergy},    {"SE", kEnergy},
      {"CE", kEnergy}, {"HE", kEnergy}, {"CE_ELAST", kEnergy}, {"CE_FRIC", kEnergy}, {"CE_DAMP", kEnergy},
      {"PW", kEnergy}, {"DMAS", kMass}, {"DMAS_PCT", kNone},
  };
  return v;
}

Dim th_variable_dim(model::ThKind kind, const std::string& n) {
  using K = model::ThKind;
  switch (kind) {
    case K::Node:
      if (n[0] == 'D' && n.size() == 2) return kLength;
      if (n == "X" || n == "Y" || n == "Z") return kLength;
      if (n[0] == 'V' && n.size() == 2) return kVelocity;
      if (n[0] == 'A' && n.size() == 2) return kAcceleration;
      if (n.rfind("VR", 0) == 0) return kAngularVelocity;
      if (n.rfind("AR", 0) == 0) return kAngularAcceleration;
      if (n.rfind("DR", 0) == 0) return kNone;
      if (n.size() == 6) return kMoment;  // REACXX..
      return kForce;                      // REACX..
    case K::Part:
    case K::Subset:
      if (n == "MASS" || n == "ERODED") return kMass;
      if (n.find("MOM") != std::string::npos) return kMomentum;
      return kEnergy;
    case K::Inter:
      if (n.rfind("CE_", 0) == 0) return kEnergy;
      return kForce;
    case K::Rwall: return kForce;
    case K::Shell:
    case K::Shell3:
      if (n == "F1" || n == "F2" || n == "F12") return kForcePerLength;
      if (n == "M1" || n == "M2" || n == "M12") return kMomentPerLength;
      if (n == "IEM" || n == "IEB") return kEnergy;
      if (n == "EPSD") return kRate;
      if (n == "THIC") return kLength;
      return kNone;
    case K::Brick:
      if (n[0] == 'S' || n == "IE" || n == "BULK") return kStress;
      if (n == "DENS") return kDensity;
      if (n == "VOL") return kVolume;
      if (n == "PLSR") return kRate;
      if (n[0] == 'V') return kVelocity;
      return kNone;  // OFF, PLAS, TEMP
    case K::Rbody:
      if (n[0] == 'F') return kForce;  // FX.., FXI..
      if (n[0] == 'M' && n != "MASS") return kMoment;
      if (n == "MASS") return kMass;
      if (n[0] == 'I') return kInertia;
      if (n[0] == 'D' || n == "X" || n == "Y" || n == "Z") return kLength;
      if (n.rfind("VR", 0) == 0) return kAngularVelocity;
      if (n.rfind("AR", 0) == 0) return kAngularAcceleration;
      if (n[0] == 'V') return kVelocity;
      if (n[0] == 'A') return kAcceleration;
      return kNone;  // RX.. (radians), STATUS
    case K::Section:
      if (n[0] == 'C') return kLength;
      if (n[0] == 'M') return kMoment;
      return kForce;
    case K::Accel: return n[0] == 'A' ? kAcceleration : kVelocity;
    case K::Spring:
      if (n[0] == 'F') return kForce;
      if (n[0] == 'M') return kMoment;
      if (n[0] == 'L') return kLength;
      if (n == "IE") return kEnergy;
      return kNone;  // OFF, RX RY RZ (radians)
    case K::Truss:
      if (n == "F") return kForce;
      if (n == "IE") return kEnergy;
      if (n == "A") return Dim{0, 2, 0};
      if (n == "L") return kLength;
      return kNone;  // OFF, PLAS
    case K::Beam:
      if (n[0] == 'F') return kForce;
      if (n[0] == 'M') return Dim{1, 2, -2};
      if (n == "IE") return kEnergy;
      return kNone;  // OFF, EPSP
  }
  return kNone;
}

void global_th_values(const ExplicitEngine& e, const CycleReport& r, std::span<double> out) {
  const auto& en = r.energy;
  const double contact = en.contact_elastic + en.contact_friction + en.contact_damping + en.contact_lagrange;
  (void)e;
  const double v[] = {en.internal,
                      en.kinetic_t,
                      r.momentum[0],
                      r.momentum[1],
                      r.momentum[2],
                      r.mass,
                      r.dt,
                      en.kinetic_r,
                      en.external_work,
                      0.0,
                      contact,
                      en.hourglass,
                      en.contact_elastic,
                      en.contact_friction,
                      en.contact_damping,
                      en.plastic_work,
                      r.added_mass,
                      r.mass0 > 0 ? 100.0 * r.added_mass / r.mass0 : 0.0};
  std::copy(std::begin(v), std::end(v), out.begin());
}

ThGroupSampler::ThGroupSampler(const ExplicitEngine& e, const model::TimeHistoryGroup& g)
    : kind_(g.kind), objects_(g.objects), variables_(g.variables) {
  const auto& m = e.model();
  using K = model::ThKind;
  // Interval means (time_history_values.hpp): an interface's forces (not its energies), a section's forces
  // and moments (not its centre), each with its instantaneous value as <VAR>_INST after the deck's variables.
  if (kind_ == K::Inter || kind_ == K::Section) {
    const std::size_t deck_variables = variables_.size();
    for (std::size_t v = 0; v < deck_variables; ++v) {
      const std::string& name = variables_[v];
      const bool mean = kind_ == K::Inter ? !name.starts_with("CE_") : name[0] != 'C';
      if (!mean) continue;
      averaged_.emplace_back(v, variables_.size());
      variables_.push_back(name + "_INST");
    }
    last_.assign(size(), 0.0);
    integral_.assign(size(), 0.0);
  }
  if (kind_ == K::Shell || kind_ == K::Shell3 || kind_ == K::Brick || kind_ == K::Spring ||
      kind_ == K::Truss || kind_ == K::Beam) {
    // Where each object sits in the element groups, found once: the groups do not change during a run.
    slots_.assign(objects_.size(), {-1, -1});
    std::vector<std::pair<int, int>> where;
    auto index = [&](const auto& groups, auto in_kind) {
      for (std::size_t gi = 0; gi < groups.size(); ++gi) {
        const auto& grp = groups[gi];
        if (!in_kind(grp)) continue;
        for (int i = 0; i < grp.count; ++i) {
          const auto el = static_cast<std::size_t>(grp.element[static_cast<std::size_t>(i)]);
          if (where.size() <= el) where.resize(el + 1, {-1, -1});
          where[el] = {static_cast<int>(gi), i};
        }
      }
    };
    if (kind_ == K::Brick) {
      index(e.groups().bricks, [](const BrickGroup&) { return true; });
      // 20-node bricks are objects bricks.size() + e: their slots after the 8-node bricks' ones
      const auto nb = m.bricks.size();
      std::vector<std::pair<int, int>> eight;
      eight.swap(where);
      index(e.groups().bricks20, [](const Hex20Group&) { return true; });
      quadratic_.assign(objects_.size(), 0);
      for (std::size_t o = 0; o < objects_.size(); ++o) {
        const auto el = static_cast<std::size_t>(objects_[o]);
        if (el < nb) {
          if (el < eight.size()) slots_[o] = eight[el];
        } else {
          quadratic_[o] = 1;
          if (el - nb < where.size()) slots_[o] = where[el - nb];
        }
      }
      return;
    } else if (kind_ == K::Spring)
      index(e.groups().springs, [](const SpringGroup&) { return true; });
    else if (kind_ == K::Truss)
      index(e.groups().trusses, [](const TrussGroup&) { return true; });
    else if (kind_ == K::Beam)
      index(e.groups().beams, [](const BeamGroup&) { return true; });
    else
      index(e.groups().shells, [&](const ShellGroup& grp) { return grp.triangle == (kind_ == K::Shell3); });
    for (std::size_t o = 0; o < objects_.size(); ++o) {
      const auto el = static_cast<std::size_t>(objects_[o]);
      if (el < where.size()) slots_[o] = where[el];
    }
    return;
  }
  if (kind_ == K::Section) {
    for (const auto o : objects_) sections_.emplace_back(m.sections[static_cast<std::size_t>(o)], e.groups());
    return;
  }
  if (kind_ == K::Node) {
    for (std::size_t o = 0; o < objects_.size(); ++o)
      skews_.push_back(o < g.skews.size() ? e.skews().index(g.skews[o]) : model::kNone);
    return;
  }
  if (kind_ == K::Rbody) {
    const auto& formed = e.kinematics().rigid_bodies().bodies();
    for (const auto o : objects_) {
      const auto id = m.rigid_bodies[static_cast<std::size_t>(o)].id;
      const auto b =
          std::find_if(formed.begin(), formed.end(), [id](const RigidBodyInfo& x) { return x.id == id; });
      bodies_.push_back(b == formed.end() ? -1 : static_cast<int>(b - formed.begin()));
    }
    return;
  }
  if (kind_ != K::Part && kind_ != K::Subset) return;
  // Node shares of each part: the part's lumped-mass contribution over the node's total mass.
  std::vector<std::map<std::int32_t, double>> shares(m.parts.size());
  model::for_each_nodal_mass(m, [&](std::int32_t node, std::int32_t part, std::size_t, double mass) {
    shares[static_cast<std::size_t>(part)][node] += mass;
  });
  part_nodes_.resize(m.parts.size());
  for (std::size_t p = 0; p < m.parts.size(); ++p)
    for (const auto& [node, mass] : shares[p]) {
      const double total = m.node_mass[static_cast<std::size_t>(node)];
      if (total > 0) part_nodes_[p].emplace_back(node, mass / total);
    }
  for (const auto o : objects_) {
    std::vector<std::int32_t> parts;
    if (kind_ == model::ThKind::Part) {
      parts.push_back(o);
    } else {  // a subset: its parts and those of its child subsets, recursively
      std::vector<std::int32_t> todo{o}, seen;
      while (!todo.empty()) {
        const auto s = todo.back();
        todo.pop_back();
        if (std::find(seen.begin(), seen.end(), s) != seen.end()) continue;
        seen.push_back(s);
        const auto& sub = m.subsets[static_cast<std::size_t>(s)];
        parts.insert(parts.end(), sub.parts.begin(), sub.parts.end());
        todo.insert(todo.end(), sub.children.begin(), sub.children.end());
      }
      std::sort(parts.begin(), parts.end());
      parts.erase(std::unique(parts.begin(), parts.end()), parts.end());
    }
    object_parts_.push_back(std::move(parts));
  }
}

void ThGroupSampler::sample_nodes(const ExplicitEngine& e, const CycleReport& r, const ThPut& put) const {
  const auto& s = e.nodes();
  const double h = 0.5 * r.dt1;
  for (std::size_t o = 0; o < objects_.size(); ++o) {
    const auto n = static_cast<std::size_t>(objects_[o]);
    // Every vector on the axes of the object's skew of this cycle (the global axes for none); X Y Z are
    // the position's components on those axes, not measured from a skew's origin, but measured from a
    // frame's (OpenRadioss thnod.F and relfram.F; a /FRAME/FIX here, the starter refuses a /FRAME/MOV).
    const auto sk = skews_[o];
    const auto on = [&](std::array<double, 3> u) { return e.skews().on_axes(sk, u); };
    const std::array<double, 3> o0 = e.skews().is_frame(sk) ? e.skews().origin(sk) : std::array<double, 3>{};
    const auto v = on({s.vx[n] + h * s.ax[n], s.vy[n] + h * s.ay[n], s.vz[n] + h * s.az[n]});
    const auto reac =
        on({s.mass[n] * s.ax[n] - s.fx[n], s.mass[n] * s.ay[n] - s.fy[n], s.mass[n] * s.az[n] - s.fz[n]});
    const auto mreac = on({s.inertia[n] * s.awx[n] - s.mx[n], s.inertia[n] * s.awy[n] - s.my[n],
                           s.inertia[n] * s.awz[n] - s.mz[n]});
    const auto x = on({s.x[n] - o0[0], s.y[n] - o0[1], s.z[n] - o0[2]});
    const auto disp = on({s.x[n] - s.x0[n], s.y[n] - s.y0[n], s.z[n] - s.z0[n]});
    const auto a = on({s.ax[n], s.ay[n], s.az[n]});
    const auto vr = on({s.wx[n] + h * s.awx[n], s.wy[n] + h * s.awy[n], s.wz[n] + h * s.awz[n]});
    const auto aw = on({s.awx[n], s.awy[n], s.awz[n]});
    const char* axes[3] = {"X", "Y", "Z"};
    for (std::size_t d = 0; d < 3; ++d) {
      const std::string ax = axes[d];
      put(o, "D" + ax, disp[d]);
      put(o, "V" + ax, v[d]);
      put(o, "A" + ax, a[d]);
      put(o, "VR" + ax, vr[d]);
      put(o, "AR" + ax, aw[d]);
      put(o, ax, x[d]);
      put(o, "REAC" + ax, reac[d]);
      put(o, "REAC" + ax + ax, mreac[d]);
    }
  }
}

void ThGroupSampler::sample_parts(const ExplicitEngine& e, const CycleReport& r, const ThPut& put) const {
  const auto& s = e.nodes();
  const auto& m = e.model();
  const double h = 0.5 * r.dt1;
  // Element energies and eroded mass per part: each group's partial, added to its part in flat group order
  // (as the engine's totals, sum_energies). Then the node sums per part, exact (model::ExactSum).
  std::vector<double> ie(m.parts.size(), 0.0), he(m.parts.size(), 0.0), eroded(m.parts.size(), 0.0);
  const auto& mats = e.materials();
  e.groups().for_each([&](const auto& g) {
    if constexpr (kHasMaterial<std::decay_t<decltype(g)>>) {
      const auto p = static_cast<std::size_t>(g.part);
      const double rho0 = mats[static_cast<std::size_t>(g.material)].rho0;
      double g_ie = 0, g_he = 0, g_eroded = 0;
      for (int i = 0; i < g.count; ++i) {
        const auto k = static_cast<std::size_t>(i);
        g_ie += g.e_int[k];
        g_he += g.e_hg[k];
        if (g.off[k] <= 0) g_eroded += initial_mass(g, k, rho0);
      }
      ie[p] += g_ie;
      he[p] += g_he;
      eroded[p] += g_eroded;
    }
  });
  for (std::size_t o = 0; o < objects_.size(); ++o) {
    double v_ie = 0, v_he = 0, v_er = 0;
    model::ExactSum ke, mass, mom[3];
    for (const auto p : object_parts_[o]) {
      const auto pp = static_cast<std::size_t>(p);
      v_ie += ie[pp];
      v_he += he[pp];
      v_er += eroded[pp];
      for (const auto& [node, share] : part_nodes_[pp]) {
        const auto n = static_cast<std::size_t>(node);
        const double mn = share * s.mass[n];
        const double v[3] = {s.vx[n] + h * s.ax[n], s.vy[n] + h * s.ay[n], s.vz[n] + h * s.az[n]};
        ke.add(0.5 * mn * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
        mass.add(mn);
        for (int d = 0; d < 3; ++d) mom[d].add(mn * v[d]);
      }
    }
    put(o, "IE", v_ie);
    put(o, "KE", ke.value());
    put(o, "XMOM", mom[0].value());
    put(o, "YMOM", mom[1].value());
    put(o, "ZMOM", mom[2].value());
    put(o, "MASS", mass.value());
    put(o, "HE", v_he);
    put(o, "ERODED", v_er);
  }
}

void ThGroupSampler::sample_rigid_walls(const ExplicitEngine& e, const CycleReport& /*r*/,
                                        const ThPut& put) const {
  const auto& walls = e.kinematics().wall_outputs();
  for (std::size_t o = 0; o < objects_.size(); ++o) {
    const auto& w = walls[static_cast<std::size_t>(objects_[o])];
    const char* axes[3] = {"X", "Y", "Z"};
    for (std::size_t d = 0; d < 3; ++d) {
      put(o, std::string("FN") + axes[d], w.normal_force[d]);
      put(o, std::string("FT") + axes[d], w.tangential_force[d]);
    }
  }
}

void ThGroupSampler::sample_interfaces(const ExplicitEngine& e, const CycleReport& /*r*/,
                                       const ThPut& put) const {
  const auto& m = e.model();
  if (e.contact() == nullptr) return;
  const auto results = e.contact()->results();
  for (std::size_t o = 0; o < objects_.size(); ++o) {
    const auto id = m.interfaces[static_cast<std::size_t>(objects_[o])].id;
    for (const auto& res : results) {
      if (res.id != id) continue;
      const char* axes[3] = {"X", "Y", "Z"};
      for (std::size_t d = 0; d < 3; ++d) {
        put(o, std::string("FN") + axes[d], res.normal_force[d]);
        put(o, std::string("FT") + axes[d], res.tangential_force[d]);
      }
      put(o, "CE_ELAST", res.e_elastic);
      put(o, "CE_FRIC", res.e_friction);
      put(o, "CE_DAMP", res.e_damping);
    }
  }
}

void ThGroupSampler::sample_shells(const ExplicitEngine& e, const CycleReport& /*r*/,
                                   const ThPut& put) const {
  for (std::size_t o = 0; o < objects_.size(); ++o) {
    const auto [gi, i] = slots_[o];
    if (gi < 0) continue;
    const auto& g = e.groups().shells[static_cast<std::size_t>(gi)];
    const auto k = static_cast<std::size_t>(i);
    const int np = g.props.n_points;
    const double t = g.thick[k] > 0 ? g.thick[k] : g.t0[k];
    double f[3] = {0, 0, 0}, mm[3] = {0, 0, 0};
    // QBAT keeps one state per in-plane Gauss point ([gauss][...]): its resultants are their mean, as the
    // result fields take it (result_fields.cpp).
    const std::size_t rows = static_cast<std::size_t>(np <= 0 ? 8 : 5 * np) * kGroupSize;
    const double per_point = 1.0 / g.gauss;
    for (int gp = 0; gp < g.gauss; ++gp) {
      const double* sig = g.sig.data() + static_cast<std::size_t>(gp) * rows;
      if (np <= 0) {
        for (std::size_t q = 0; q < 3; ++q) {
          f[q] += per_point * sig[q * kGroupSize + k];
          mm[q] += per_point * sig[(5 + q) * kGroupSize + k];
        }
      } else {
        const auto rule = shell_detail::thickness_rule(np);
        for (int p = 0; p < np; ++p)
          for (int q = 0; q < 3; ++q) {
            const double sg = sig[shell_detail::sig_index(p, q, i)];
            f[q] += per_point * rule.w[p] * sg;
            mm[q] += per_point * rule.m[p] * sg;
          }
      }
    }
    put(o, "F1", f[0] * t);
    put(o, "F2", f[1] * t);
    put(o, "F12", f[2] * t);
    put(o, "M1", mm[0] * t * t);
    put(o, "M2", mm[1] * t * t);
    put(o, "M12", mm[2] * t * t);
    put(o, "IEM", g.e_int[k]);
    put(o, "OFF", g.off[k]);
    // the filtered equivalent strain rate of the rate laws (docs/theory/elements.md 6.1)
    put(o, "EPSD", g.rate[k]);
    put(o, "THIC", t);
  }
}

void ThGroupSampler::sample_bricks(const ExplicitEngine& e, const CycleReport& r, const ThPut& put) const {
  const auto& s = e.nodes();
  const double h = 0.5 * r.dt1;
  for (std::size_t o = 0; o < objects_.size(); ++o) {
    const auto [gi, i] = slots_[o];
    if (gi < 0) continue;
    if (quadratic_[o]) {
      sample_brick20(e, r, put, o);
      continue;
    }
    const auto& g = e.groups().bricks[static_cast<std::size_t>(gi)];
    const auto k = static_cast<std::size_t>(i);
    const char* names[6] = {"SX", "SY", "SZ", "SXY", "SYZ", "SXZ"};
    double sg[6];
    brick_global_stress(g, k, sg);  // global axes also for co-rotational bricks
    for (std::size_t c = 0; c < 6; ++c) put(o, names[c], sg[c]);
    double v[3] = {0, 0, 0};
    for (std::size_t c = 0; c < 8; ++c) {
      const auto n = static_cast<std::size_t>(g.conn[c * kGroupSize + k]);
      v[0] += (s.vx[n] + h * s.ax[n]) / 8;
      v[1] += (s.vy[n] + h * s.ay[n]) / 8;
      v[2] += (s.vz[n] + h * s.az[n]) / 8;
    }
    put_solid_state(put, o, g, k, v);
  }
}

// A 20-node brick under /TH/BRIC: the volume-weighted mean stress of its points, the mean plastic strain, and
// the velocity at its centre, sum_a N_a(0) v_a = (sum of the mid-side nodes' - sum of the corners') / 4.
void ThGroupSampler::sample_brick20(const ExplicitEngine& e, const CycleReport& r, const ThPut& put,
                                    std::size_t o) const {
  const auto& s = e.nodes();
  const double h = 0.5 * r.dt1;
  const auto [gi, i] = slots_[o];
  const auto& g = e.groups().bricks20[static_cast<std::size_t>(gi)];
  const auto k = static_cast<std::size_t>(i);
  const char* names[6] = {"SX", "SY", "SZ", "SXY", "SYZ", "SXZ"};
  for (std::size_t c = 0; c < 6; ++c) put(o, names[c], g.sig[c * kGroupSize + k]);
  double v[3] = {0, 0, 0};
  for (std::size_t c = 0; c < 20; ++c) {
    const auto n = static_cast<std::size_t>(g.conn[c * kGroupSize + k]);
    const double w = c < 8 ? -0.25 : 0.25;
    v[0] += w * (s.vx[n] + h * s.ax[n]);
    v[1] += w * (s.vy[n] + h * s.ay[n]);
    v[2] += w * (s.vz[n] + h * s.az[n]);
  }
  put_solid_state(put, o, g, k, v);
}

void ThGroupSampler::sample_rigid_bodies(const ExplicitEngine& e, const CycleReport& r,
                                         const ThPut& put) const {
  const auto& s = e.nodes();
  const auto& m = e.model();
  const double h = 0.5 * r.dt1;
  const auto& formed = e.kinematics().rigid_bodies().bodies();
  for (std::size_t o = 0; o < objects_.size(); ++o) {
    const RigidBodyInfo* b = bodies_[o] < 0 ? nullptr : &formed[static_cast<std::size_t>(bodies_[o])];
    if (b && !b->active) b = nullptr;  // released by its sensor: a free main node, STATUS 0
    const auto main = b ? b->main : m.rigid_bodies[static_cast<std::size_t>(objects_[o])].main_node;
    if (main == model::kNone) continue;
    const auto n = static_cast<std::size_t>(main);
    const char* axes[3] = {"X", "Y", "Z"};
    const double x[3] = {s.x[n], s.y[n], s.z[n]}, x0[3] = {s.x0[n], s.y0[n], s.z0[n]};
    const double v[3] = {s.vx[n] + h * s.ax[n], s.vy[n] + h * s.ay[n], s.vz[n] + h * s.az[n]};
    const double a[3] = {s.ax[n], s.ay[n], s.az[n]};
    const double w[3] = {s.wx[n] + h * s.awx[n], s.wy[n] + h * s.awy[n], s.wz[n] + h * s.awz[n]};
    const double aw[3] = {s.awx[n], s.awy[n], s.awz[n]};
    for (std::size_t d = 0; d < 3; ++d) {
      const std::string ax = axes[d];
      put(o, ax, x[d]);
      put(o, "D" + ax, x[d] - x0[d]);
      put(o, "V" + ax, v[d]);
      put(o, "A" + ax, a[d]);
      put(o, "VR" + ax, w[d]);
      put(o, "AR" + ax, aw[d]);
      if (b) {
        put(o, "F" + ax, b->secondary_force[d]);
        put(o, "M" + ax, b->secondary_moment[d]);
        put(o, "R" + ax, b->rotation[d]);
      }
    }
    put(o, "MASS", s.mass[n]);
    put(o, "STATUS", b ? 1.0 : 0.0);
    if (b) {
      const auto inertia = current_inertia(*b);
      const char* names[6] = {"IXX", "IYY", "IZZ", "IXY", "IYZ", "IZX"};
      for (std::size_t c = 0; c < 6; ++c) put(o, names[c], inertia[c]);
    }
  }
}

void ThGroupSampler::sample_sections(const ExplicitEngine& e, const CycleReport& /*r*/,
                                     const ThPut& put) const {
  const auto& s = e.nodes();
  for (std::size_t o = 0; o < objects_.size(); ++o) {
    const SectionCut c = sections_[o].evaluate(s, e.groups());
    const char* axes[3] = {"X", "Y", "Z"};
    for (std::size_t d = 0; d < 3; ++d) {
      const std::string ax = axes[d], k = std::to_string(d + 1);
      put(o, "FN" + ax, c.normal_force[d]);
      put(o, "FT" + ax, c.tangential_force[d]);
      put(o, "M" + ax, c.moment[d]);
      put(o, "C" + ax, c.centre[d]);
      put(o, "F" + k, c.local_force[d]);
      put(o, "M" + k, c.local_moment[d]);
    }
  }
}

void ThGroupSampler::sample_springs(const ExplicitEngine& e, const CycleReport& /*r*/,
                                    const ThPut& put) const {
  for (std::size_t o = 0; o < objects_.size(); ++o) {
    const auto [gi, i] = slots_[o];
    if (gi < 0) continue;
    const auto& g = e.groups().springs[static_cast<std::size_t>(gi)];
    const auto k = static_cast<std::size_t>(i);
    put(o, "OFF", g.off[k]);
    put(o, "IE", g.e_int[k]);
    // TYPE4: FX and LX along the spring; TYPE8: the six laws' forces, moments, elongations, rotations.
    const char* names[4][3] = {
        {"FX", "FY", "FZ"}, {"MX", "MY", "MZ"}, {"LX", "LY", "LZ"}, {"RX", "RY", "RZ"}};
    for (std::size_t d = 0; d < (g.props.type == 4 ? 1u : 3u); ++d) {
      put(o, names[0][d], g.force[d * kGroupSize + k]);
      put(o, names[2][d], g.dx[d * kGroupSize + k]);
      if (g.props.type == 4) continue;
      put(o, names[1][d], g.force[(3 + d) * kGroupSize + k]);
      put(o, names[3][d], g.dx[(3 + d) * kGroupSize + k]);
    }
  }
}

void ThGroupSampler::sample_trusses(const ExplicitEngine& e, const CycleReport& /*r*/,
                                    const ThPut& put) const {
  for (std::size_t o = 0; o < objects_.size(); ++o) {
    const auto [gi, i] = slots_[o];
    if (gi < 0) continue;
    const auto& g = e.groups().trusses[static_cast<std::size_t>(gi)];
    const auto k = static_cast<std::size_t>(i);
    put(o, "OFF", g.off[k]);
    put(o, "F", g.force[k]);
    put(o, "IE", g.e_int[k]);
    put(o, "A", g.area[k]);
    put(o, "L", g.l0[k]);
    put(o, "PLAS", g.eps_p[k]);
  }
}

void ThGroupSampler::sample_beams(const ExplicitEngine& e, const CycleReport& /*r*/, const ThPut& put) const {
  static const char* names[6] = {"F1", "F2", "F3", "M1", "M2", "M3"};
  for (std::size_t o = 0; o < objects_.size(); ++o) {
    const auto [gi, i] = slots_[o];
    if (gi < 0) continue;
    const auto& g = e.groups().beams[static_cast<std::size_t>(gi)];
    const auto k = static_cast<std::size_t>(i);
    put(o, "OFF", g.off[k]);
    for (std::size_t d = 0; d < 6; ++d) put(o, names[d], g.resultant[d * kGroupSize + k]);
    put(o, "IE", g.e_int[k]);
    put(o, "EPSP", g.eps_p[k]);
  }
}

void ThGroupSampler::sample_accelerometers(const ExplicitEngine& e, const CycleReport& /*r*/,
                                           const ThPut& put) const {
  for (std::size_t o = 0; o < objects_.size(); ++o) {
    const auto& a = e.accelerometers().readings()[static_cast<std::size_t>(objects_[o])];
    const char* axes[3] = {"X", "Y", "Z"};
    for (std::size_t d = 0; d < 3; ++d) {
      put(o, std::string("A") + axes[d], a.acceleration[d]);
      put(o, std::string("W") + axes[d], a.velocity[d]);
    }
  }
}

void ThGroupSampler::ThPut::operator()(std::size_t obj, const std::string& name, double value) const {
  const std::size_t k = index_of(variables, name);
  if (k < variables.size()) out[obj * variables.size() + k] = value;
}

void ThGroupSampler::accumulate(const ExplicitEngine& e, const CycleReport& r) {
  if (averaged_.empty()) return;
  std::vector<double>& now = cycle_;
  now.resize(size());
  sample_cycle(e, r, now);
  const std::size_t nv = variables_.size();
  if (accumulated_) {
    const double half_step = 0.5 * (r.time - last_time_);
    for (std::size_t o = 0; o < objects_.size(); ++o)
      for (const auto& [v, inst] : averaged_) {
        const std::size_t k = o * nv + v;
        integral_[k] += half_step * (last_[k] + now[k]);
      }
  }
  std::copy(now.begin(), now.end(), last_.begin());
  last_time_ = r.time;
  accumulated_ = true;
}

void ThGroupSampler::sample(const ExplicitEngine& e, const CycleReport& r, std::span<double> out) {
  if (averaged_.empty()) {
    sample_cycle(e, r, out);
    return;
  }
  // A caller that did not accumulate this cycle (the engine's outputs accumulate every cycle) gets the
  // trapezoid from the last cycle it accumulated.
  if (!accumulated_ || last_time_ != r.time) accumulate(e, r);
  std::copy(last_.begin(), last_.end(), out.begin());
  const std::size_t nv = variables_.size();
  const double interval = r.time - row_time_;
  // The first row has no interval: it keeps the cycle's value, as does a row at the time of the previous one.
  const bool mean = sampled_ && interval > 0;
  for (std::size_t o = 0; o < objects_.size(); ++o)
    for (const auto& [v, inst] : averaged_) {
      const std::size_t k = o * nv + v;
      out[o * nv + inst] = out[k];
      if (mean) out[k] = integral_[k] / interval;
      integral_[k] = 0;
    }
  row_time_ = r.time;
  sampled_ = true;
}

// One row per object, each variable the group asks for at its column; the kind's sampler fills them.
void ThGroupSampler::sample_cycle(const ExplicitEngine& e, const CycleReport& r,
                                  std::span<double> out) const {
  std::fill(out.begin(), out.end(), 0.0);
  const ThPut put{out, variables_};
  using K = model::ThKind;
  switch (kind_) {
    case K::Node: sample_nodes(e, r, put); break;
    case K::Part:
    case K::Subset: sample_parts(e, r, put); break;
    case K::Rwall: sample_rigid_walls(e, r, put); break;
    case K::Inter: sample_interfaces(e, r, put); break;
    case K::Shell:
    case K::Shell3: sample_shells(e, r, put); break;
    case K::Brick: sample_bricks(e, r, put); break;
    case K::Rbody: sample_rigid_bodies(e, r, put); break;
    case K::Section: sample_sections(e, r, put); break;
    case K::Spring: sample_springs(e, r, put); break;
    case K::Truss: sample_trusses(e, r, put); break;
    case K::Beam: sample_beams(e, r, put); break;
    case K::Accel: sample_accelerometers(e, r, put); break;
  }
}

}  // namespace radx::solver
