#include "solver/conditions/external_loads.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "solver/conditions/functions.hpp"
#include "solver/conditions/sensors.hpp"

namespace radx::solver {

namespace {

const model::Function& function_of(const model::Model& m, std::int32_t index, const std::string& what) {
  if (index < 0 || static_cast<std::size_t>(index) >= m.functions.size())
    throw std::runtime_error(what + ": no function (funct_IDT is required)");
  return m.functions[static_cast<std::size_t>(index)];
}

const std::vector<std::int32_t>& group_of(const model::Model& m, std::int32_t index,
                                          const std::string& what) {
  if (index < 0 || static_cast<std::size_t>(index) >= m.node_groups.size())
    throw std::runtime_error(what + ": no node group");
  return m.node_groups[static_cast<std::size_t>(index)].nodes;
}

bool owner_less(std::uint8_t ta, std::int32_t ea, std::uint8_t tb, std::int32_t eb) {
  return ta != tb ? ta < tb : ea < eb;
}

}  // namespace

double ExternalLoads::Curve::at(double t) const {
  return constant ? fscale : scaled_function_value(f, t, ascale, fscale);
}

std::optional<std::pair<double, double>> ExternalLoads::Switch::ends(const Curve& c, std::int32_t sensor,
                                                                     double t, double dt1,
                                                                     std::span<const double> sensor_starts) {
  if (sensor == model::kNone) return std::pair{c.at(t - dt1), c.at(t)};
  const double tau = t - time_origin(sensor, sensor_starts);
  const bool on_now = tau >= 0;
  if (!on_now && !on) return std::nullopt;
  const double now = on_now ? c.at(tau) : 0.0;
  const double before = on ? last : dt1 > 0 ? 0.0 : now;
  on = on_now;
  last = now;
  return std::pair{before, now};
}

ExternalLoads::ExternalLoads(const model::Model& m, const SkewFrames& skews,
                             std::span<const std::uint8_t> rigid_secondary)
    : skews_(&skews), rigid_secondary_(rigid_secondary) {
  const std::size_t nn = m.nodes.size();
  if (!rigid_secondary.empty() && rigid_secondary.size() != nn)
    throw std::runtime_error("ExternalLoads: the rigid-secondary flags must have one entry per node");

  for (const auto& g : m.gravities) {
    const std::string what = "/GRAV/" + std::to_string(g.id);
    Gravity out;
    out.sensor = m.sensor_index(g.sensor);
    out.g.constant = g.function == model::kNone;
    if (!out.g.constant) out.g.f = function_of(m, g.function, what);
    out.g.ascale = g.ascale_x;
    out.g.fscale = g.fscale_y;
    out.dir = g.dir;
    if (g.dir < 0 || g.dir > 2) throw std::runtime_error(what + ": DIR must be X, Y or Z");
    out.skew = skews.index(g.skew);
    if (g.group == model::kNone) {
      for (std::size_t n = 0; n < nn; ++n) out.nodes.push_back(static_cast<std::int32_t>(n));
    } else {
      out.nodes = group_of(m, g.group, what);
    }
    gravity_.push_back(std::move(out));
  }

  for (const auto& c : m.concentrated_loads) {
    const std::string what = "/CLOAD/" + std::to_string(c.id);
    if (c.itypfun != 1)
      throw std::runtime_error(what + ": Itypfun = " + std::to_string(c.itypfun) +
                               " (function of displacement or velocity) is not supported by the radx "
                               "engine; use Itypfun = 1 (function of time)");
    if (c.dir < 0 || c.dir > 5) throw std::runtime_error(what + ": Dir must be X, Y, Z, XX, YY or ZZ");
    Concentrated out;
    out.sensor = m.sensor_index(c.sensor);
    out.f.f = function_of(m, c.function, what);
    out.f.ascale = c.ascale_x;
    out.f.fscale = c.fscale_y;
    out.dir = c.dir;
    out.skew = skews.index(c.skew);
    out.nodes = group_of(m, c.group, what);
    cloads_.push_back(std::move(out));
  }

  for (const auto& p : m.pressure_loads) {
    const std::string what = "/PLOAD/" + std::to_string(p.id);
    if (p.itypfun != 1)
      throw std::runtime_error(what + ": Itypfun = " + std::to_string(p.itypfun) +
                               " (function of displacement or velocity) is not supported by the radx "
                               "engine; use Itypfun = 1 (function of time)");
    if (p.ipinch != 0)
      throw std::runtime_error(what + ": Ipinch = " + std::to_string(p.ipinch) +
                               " (load on pinching dofs) is not supported by the radx engine; use 0");
    if (p.surface < 0 || static_cast<std::size_t>(p.surface) >= m.surfaces.size())
      throw std::runtime_error(what + ": no surface");
    const auto& surf = m.surfaces[static_cast<std::size_t>(p.surface)];
    Pressure out;
    out.sensor = m.sensor_index(p.sensor);
    out.p.f = function_of(m, p.function, what);
    out.p.ascale = p.ascale_x;
    out.p.fscale = p.fscale_y;
    out.segments = surf.segments;
    out.active.assign(surf.segments.size(), 1);
    if (p.idel == 1) {
      const auto load = static_cast<std::uint32_t>(ploads_.size());
      for (std::size_t k = 0; k < surf.segments.size(); ++k) {
        if (k >= surf.owner.size() || k >= surf.owner_type.size()) break;
        if (surf.owner[k] == model::kNone || surf.owner_type[k] == model::SegmentOwner::None) continue;
        owners_.push_back(Owner{static_cast<std::uint8_t>(surf.owner_type[k]), surf.owner[k], load,
                                static_cast<std::uint32_t>(k)});
      }
    }
    ploads_.push_back(std::move(out));
  }
  std::sort(owners_.begin(), owners_.end(),
            [](const Owner& a, const Owner& b) { return owner_less(a.type, a.element, b.type, b.element); });
}

void ExternalLoads::remove_element(model::SegmentOwner type, std::int32_t element) {
  const auto t = static_cast<std::uint8_t>(type);
  auto it = std::lower_bound(
      owners_.begin(), owners_.end(), Owner{t, element, 0, 0},
      [](const Owner& a, const Owner& b) { return owner_less(a.type, a.element, b.type, b.element); });
  for (; it != owners_.end() && it->type == t && it->element == element; ++it)
    ploads_[it->load].active[it->segment] = 0;
}

double ExternalLoads::apply(NodeState& s, double t, double dt1, std::span<const double> sensor_starts) {
  double work = 0;
  apply_gravity(s, t, dt1, sensor_starts, work);
  apply_concentrated_loads(s, t, dt1, sensor_starts);
  apply_pressures(s, t, dt1, sensor_starts, work);
  return work;
}

// Gravity: force m g, work 1/2 (g_old + g_new) m v dt1; a rigid body's secondary nodes are skipped.
void ExternalLoads::apply_gravity(NodeState& s, double t, double dt1, std::span<const double> sensor_starts,
                                  double& work) {
  const auto& rigid = rigid_secondary_;
  std::array<HugeVector<double>*, 3> f = {&s.fx, &s.fy, &s.fz};
  std::array<HugeVector<double>*, 3> fext = {&s.fx_ext, &s.fy_ext, &s.fz_ext};
  std::array<const HugeVector<double>*, 3> v = {&s.vx, &s.vy, &s.vz};
  for (auto& g : gravity_) {
    const auto ends = g.sw.ends(g.g, g.sensor, t, dt1, sensor_starts);
    if (!ends) continue;
    const auto [g_old, g_new] = *ends;
    if (g.skew != model::kNone) {  // m g u on each node, work 1/2 (g_old + g_new) m (v.u) dt1
      const auto u = skews_->axis(g.skew, g.dir);
      double mv = 0;
      for (const auto n32 : g.nodes) {
        const auto n = static_cast<std::size_t>(n32);
        if (!rigid.empty() && rigid[n]) continue;
        const double force = s.mass[n] * g_new;
        for (std::size_t d = 0; d < 3; ++d) {
          (*f[d])[n] += force * u[d];
          (*fext[d])[n] += force * u[d];
        }
        mv += s.mass[n] * (s.vx[n] * u[0] + s.vy[n] * u[1] + s.vz[n] * u[2]);
      }
      work += 0.5 * (g_old + g_new) * mv * dt1;
      continue;
    }
    const auto d = static_cast<std::size_t>(g.dir);
    auto& fd = *f[d];
    auto& fe = *fext[d];
    const auto& vd = *v[d];
    double mv = 0;
    for (const auto n32 : g.nodes) {
      const auto n = static_cast<std::size_t>(n32);
      if (!rigid.empty() && rigid[n]) continue;
      const double force = s.mass[n] * g_new;
      fd[n] += force;
      fe[n] += force;
      mv += s.mass[n] * vd[n];
    }
    work += 0.5 * (g_old + g_new) * mv * dt1;
  }
}

// Concentrated loads: the full value on every node; power 1/2 (F_old + F_new) v, booked with dt2.
void ExternalLoads::apply_concentrated_loads(NodeState& s, double t, double dt1,
                                             std::span<const double> sensor_starts) {
  std::array<HugeVector<double>*, 3> f = {&s.fx, &s.fy, &s.fz};
  std::array<HugeVector<double>*, 3> fext = {&s.fx_ext, &s.fy_ext, &s.fz_ext};
  std::array<HugeVector<double>*, 3> mom = {&s.mx, &s.my, &s.mz};
  std::array<const HugeVector<double>*, 3> v = {&s.vx, &s.vy, &s.vz};
  std::array<const HugeVector<double>*, 3> w = {&s.wx, &s.wy, &s.wz};
  cload_power_ = 0;
  for (auto& c : cloads_) {
    const auto ends = c.sw.ends(c.f, c.sensor, t, dt1, sensor_starts);
    if (!ends) continue;
    const auto [f_old, f_new] = *ends;
    const bool moment = c.dir >= 3;
    if (c.skew != model::kNone) {  // F u on each node (a moment about u for XX YY ZZ), power
                                   // 1/2 (F_old + F_new) (v.u)
      const auto u = skews_->axis(c.skew, c.dir % 3);
      double vsum = 0;
      for (const auto n32 : c.nodes) {
        const auto n = static_cast<std::size_t>(n32);
        for (std::size_t d = 0; d < 3; ++d) {
          if (moment) {
            (*mom[d])[n] += f_new * u[d];
          } else {
            (*f[d])[n] += f_new * u[d];
            (*fext[d])[n] += f_new * u[d];
          }
        }
        vsum += moment ? s.wx[n] * u[0] + s.wy[n] * u[1] + s.wz[n] * u[2]
                       : s.vx[n] * u[0] + s.vy[n] * u[1] + s.vz[n] * u[2];
      }
      cload_power_ += 0.5 * (f_old + f_new) * vsum;
      continue;
    }
    const auto d = static_cast<std::size_t>(moment ? c.dir - 3 : c.dir);
    const auto& vd = moment ? *w[d] : *v[d];
    double vsum = 0;
    for (const auto n32 : c.nodes) {
      const auto n = static_cast<std::size_t>(n32);
      if (moment) {
        (*mom[d])[n] += f_new;
      } else {
        (*f[d])[n] += f_new;
        (*fext[d])[n] += f_new;
      }
      vsum += vd[n];
    }
    cload_power_ += 0.5 * (f_old + f_new) * vsum;
  }
}

// Pressure: p A n split equally over the nodes of each segment, current geometry.
void ExternalLoads::apply_pressures(NodeState& s, double t, double dt1, std::span<const double> sensor_starts,
                                    double& work) {
  for (const auto& p : ploads_) {
    const double tau = t - time_origin(p.sensor, sensor_starts);
    if (tau < 0) continue;
    const double pr = p.p.at(tau);
    if (pr == 0) continue;
    for (std::size_t k = 0; k < p.segments.size(); ++k) {
      if (!p.active[k]) continue;
      const auto& sg = p.segments[k];
      const auto n1 = static_cast<std::size_t>(sg[0]), n2 = static_cast<std::size_t>(sg[1]);
      const auto n3 = static_cast<std::size_t>(sg[2]), n4 = static_cast<std::size_t>(sg[3]);
      const bool tri = n4 == n3;
      double nx, ny, nz, c;
      int count;
      if (tri) {
        const double ax = s.x[n2] - s.x[n1], ay = s.y[n2] - s.y[n1], az = s.z[n2] - s.z[n1];
        const double bx = s.x[n3] - s.x[n1], by = s.y[n3] - s.y[n1], bz = s.z[n3] - s.z[n1];
        nx = ay * bz - az * by;
        ny = az * bx - ax * bz;
        nz = ax * by - ay * bx;
        c = pr / 6.0;
        count = 3;
      } else {
        const double ax = s.x[n3] - s.x[n1], ay = s.y[n3] - s.y[n1], az = s.z[n3] - s.z[n1];
        const double bx = s.x[n4] - s.x[n2], by = s.y[n4] - s.y[n2], bz = s.z[n4] - s.z[n2];
        nx = ay * bz - az * by;
        ny = az * bx - ax * bz;
        nz = ax * by - ay * bx;
        c = pr / 8.0;
        count = 4;
      }
      const double fxn = c * nx, fyn = c * ny, fzn = c * nz;
      for (int q = 0; q < count; ++q) {
        const auto n = static_cast<std::size_t>(sg[static_cast<std::size_t>(q)]);
        s.fx[n] += fxn;
        s.fy[n] += fyn;
        s.fz[n] += fzn;
        s.fx_ext[n] += fxn;
        s.fy_ext[n] += fyn;
        s.fz_ext[n] += fzn;
        work += dt1 * (fxn * s.vx[n] + fyn * s.vy[n] + fzn * s.vz[n]);
      }
    }
  }
}

}  // namespace radx::solver
