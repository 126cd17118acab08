#include "solver/conditions/boundary_conditions.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "solver/conditions/functions.hpp"
#include "solver/conditions/sensors.hpp"

namespace radx::solver {

namespace {

const std::vector<std::int32_t>& group_of(const model::Model& m, std::int32_t index,
                                          const std::string& what) {
  if (index < 0 || static_cast<std::size_t>(index) >= m.node_groups.size())
    throw std::runtime_error(what + ": no node group");
  return m.node_groups[static_cast<std::size_t>(index)].nodes;
}

}  // namespace

// ---------------------------------------------------------------------------------------------------------
// /BCS

BoundaryConditions::BoundaryConditions(const model::Model& m, const SkewFrames& skews) : skews_(&skews) {
  std::vector<std::uint8_t> bits(m.nodes.size(), 0);
  for (const auto& c : m.bcs) {
    std::uint8_t b = 0;
    for (std::size_t k = 0; k < 6; ++k)
      if (c.fixed[k]) b = static_cast<std::uint8_t>(b | (1u << k));
    if (b == 0) continue;
    if (c.skew != 0) {
      Skewed sk;
      sk.mask = b;
      sk.skew = skews.index(c.skew);
      for (const auto n : group_of(m, c.group, "/BCS/" + std::to_string(c.id))) {
        sk.node = n;
        skewed_.push_back(sk);
      }
      continue;
    }
    for (const auto n : group_of(m, c.group, "/BCS/" + std::to_string(c.id)))
      bits[static_cast<std::size_t>(n)] = static_cast<std::uint8_t>(bits[static_cast<std::size_t>(n)] | b);
  }
  for (std::size_t n = 0; n < bits.size(); ++n)
    if (bits[n]) {
      node_.push_back(static_cast<std::int32_t>(n));
      mask_.push_back(bits[n]);
    }
}

void BoundaryConditions::set_fixed_bits(NodeState& s) const {
  for (std::size_t k = 0; k < node_.size(); ++k) {
    auto& f = s.fixed[static_cast<std::size_t>(node_[k])];
    f = static_cast<std::uint8_t>(f | mask_[k]);
  }
}

void BoundaryConditions::apply(NodeState& s) const {
  for (std::size_t k = 0; k < node_.size(); ++k) {
    const auto n = static_cast<std::size_t>(node_[k]);
    // s.fixed can lose bits during the run (TYPE7 IBC releases a node's conditions at its first impact).
    const unsigned b = mask_[k] & s.fixed[n];
    if (b & 1u) s.vx[n] = s.ax[n] = 0;
    if (b & 2u) s.vy[n] = s.ay[n] = 0;
    if (b & 4u) s.vz[n] = s.az[n] = 0;
    if (b & 8u) s.wx[n] = s.awx[n] = 0;
    if (b & 16u) s.wy[n] = s.awy[n] = 0;
    if (b & 32u) s.wz[n] = s.awz[n] = 0;
  }
  // Skewed: remove the components along the fixed axes of the cycle, v -= (v.e) e and a -= (a.e) e.
  for (const auto& k : skewed_) {
    const auto n = static_cast<std::size_t>(k.node);
    const auto& axes = skews_->axes(k.skew);
    auto project_out = [&](double& x, double& y, double& z, const double* e) {
      const double c = x * e[0] + y * e[1] + z * e[2];
      x -= c * e[0];
      y -= c * e[1];
      z -= c * e[2];
    };
    for (int axis = 0; axis < 3; ++axis) {
      const double* e = &axes[3 * static_cast<std::size_t>(axis)];
      if (k.mask & (1u << axis)) {
        project_out(s.vx[n], s.vy[n], s.vz[n], e);
        project_out(s.ax[n], s.ay[n], s.az[n], e);
      }
      if (k.mask & (8u << axis)) {
        project_out(s.wx[n], s.wy[n], s.wz[n], e);
        project_out(s.awx[n], s.awy[n], s.awz[n], e);
      }
    }
  }
}

// ---------------------------------------------------------------------------------------------------------
// /IMPVEL

ImposedVelocities::ImposedVelocities(const model::Model& m, const SkewFrames& skews) : skews_(&skews) {
  std::size_t total = 0;
  for (const auto& iv : m.imposed_velocities) {
    const std::string what = (iv.displacement ? "/IMPDISP/" : "/IMPVEL/") + std::to_string(iv.id);
    if (iv.displacement && iv.dir >= 3)
      throw std::runtime_error(what + ": an imposed rotation angle is not implemented");
    if (iv.function < 0 || static_cast<std::size_t>(iv.function) >= m.functions.size())
      throw std::runtime_error(what + ": no function (funct_IDT is required)");
    if (iv.dir < 0 || iv.dir > 5) throw std::runtime_error(what + ": Dir must be X, Y, Z, XX, YY or ZZ");
    Entry e;
    e.f = m.functions[static_cast<std::size_t>(iv.function)];
    e.sensor = m.sensor_index(iv.sensor);
    e.dir = iv.dir;
    e.displacement = iv.displacement;
    e.skew = skews.index(iv.skew);
    e.ascale = iv.ascale_x;
    e.fscale = iv.fscale_y;
    e.t_start = iv.t_start;
    e.t_stop = iv.t_stop;
    e.nodes = group_of(m, iv.group, what);
    e.first = total;
    total += e.nodes.size();
    entries_.push_back(std::move(e));
  }
  for (const auto& g : m.imposed_final_geometries) {
    const std::string what = "/IMPDISP/FGEO/" + std::to_string(g.id);
    if (g.function < 0 || static_cast<std::size_t>(g.function) >= m.functions.size())
      throw std::runtime_error(what + ": no function (fct_ID is required)");
    if (g.nodes.size() != g.targets.size()) throw std::runtime_error(what + ": one final position per node");
    Entry e;
    e.f = m.functions[static_cast<std::size_t>(g.function)];
    e.sensor = m.sensor_index(g.sensor);
    e.displacement = true;
    e.ascale = 1.0 / g.ascale_x;  // f(t * Ascale)
    e.t_start = g.t_start;
    e.t_stop = g.t_stop;
    e.nodes = g.nodes;
    for (std::size_t k = 0; k < g.nodes.size(); ++k) {
      const auto n = static_cast<std::size_t>(g.nodes[k]);
      const std::array<double, 3> d = {g.targets[k][0] - m.nodes.x[n], g.targets[k][1] - m.nodes.y[n],
                                       g.targets[k][2] - m.nodes.z[n]};
      const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      e.node_scale.push_back(len);
      e.node_axis.push_back(len > 0 ? std::array<double, 3>{d[0] / len, d[1] / len, d[2] / len}
                                    : std::array<double, 3>{});
    }
    e.first = total;
    total += e.nodes.size();
    entries_.push_back(std::move(e));
  }
  pending_.assign(total, 0.0);
}

double ImposedVelocities::pending_work() const {
  double w = 0;
  for (const double p : pending_) w += p;
  return w;
}

double ImposedVelocities::apply(NodeState& s, double t, double dt1, double dt2,
                                std::span<const double> sensor_starts) {
  const double dt12 = 0.5 * (dt1 + dt2);
  double work = 0;
  for (const auto& e : entries_) {
    const double tau = t - time_origin(e.sensor, sensor_starts);
    const bool active =
        t >= e.t_start && t <= e.t_stop && tau >= 0 && dt12 > 0 && (!e.displacement || dt2 > 0);
    // /IMPVEL: the velocity of the mid-step. /IMPDISP: the velocity that brings the node to its initial
    // position plus the imposed displacement at the end of the step, u(tau + dt2), whatever it lags now;
    // under a sensor, after its first instant, the function's increment over the step.
    const double f_val = !active          ? 0.0
                         : e.displacement ? scaled_function_value(e.f, tau + dt2, e.ascale, e.fscale)
                                          : scaled_function_value(e.f, tau + 0.5 * dt2, e.ascale, e.fscale);
    // /IMPDISP/FGEO always drives the node to its absolute place on the line (OpenRadioss fixfingeo.F), with
    // or without a sensor; only the plain /IMPDISP follows the increments after its sensor starts.
    const bool increment =
        active && e.displacement && e.sensor != model::kNone && tau > 0 && e.node_axis.empty();
    const double f_now = increment ? scaled_function_value(e.f, tau, e.ascale, e.fscale) : 0.0;
    const bool rot = e.dir >= 3;
    const int d = rot ? e.dir - 3 : e.dir;
    const auto& x = d == 0 ? s.x : d == 1 ? s.y : s.z;
    const auto& x0 = d == 0 ? s.x0 : d == 1 ? s.y0 : s.z0;
    auto& v = rot ? (d == 0 ? s.wx : d == 1 ? s.wy : s.wz) : (d == 0 ? s.vx : d == 1 ? s.vy : s.vz);
    auto& a = rot ? (d == 0 ? s.awx : d == 1 ? s.awy : s.awz) : (d == 0 ? s.ax : d == 1 ? s.ay : s.az);
    const auto& mass = rot ? s.inertia : s.mass;
    const bool line = !e.node_axis.empty();  // /IMPDISP/FGEO: each node along its own line
    const bool skewed = line || e.skew != model::kNone;
    const auto skew_axis = skews_->axis(e.skew, d);  // the skew's axis of this cycle
    for (std::size_t k = 0; k < e.nodes.size(); ++k) {
      double& pend = pending_[e.first + k];
      work += pend;
      pend = 0;
      if (!active) continue;
      const auto n = static_cast<std::size_t>(e.nodes[k]);
      const auto& u = line ? e.node_axis[k] : skew_axis;
      // Components along the imposed direction: a global axis, or a skew axis u (projections).
      double v_along, a_free, disp;
      if (!skewed) {
        v_along = v[n];
        a_free = a[n];
        disp = x[n] - x0[n];
      } else {
        v_along = rot ? s.wx[n] * u[0] + s.wy[n] * u[1] + s.wz[n] * u[2]
                      : s.vx[n] * u[0] + s.vy[n] * u[1] + s.vz[n] * u[2];
        a_free = rot ? s.awx[n] * u[0] + s.awy[n] * u[1] + s.awz[n] * u[2]
                     : s.ax[n] * u[0] + s.ay[n] * u[1] + s.az[n] * u[2];
        disp = (s.x[n] - s.x0[n]) * u[0] + (s.y[n] - s.y0[n]) * u[1] + (s.z[n] - s.z0[n]) * u[2];
      }
      const double scale = line ? e.node_scale[k] : 1.0;  // /IMPDISP/FGEO: f is the share of the way
      const double v_imp = increment        ? scale * (f_val - f_now) / dt2
                           : e.displacement ? (scale * f_val - disp) / dt2
                                            : f_val;
      const double a_imp = (v_imp - v_along) / dt12;
      if (!skewed) {
        a[n] = a_imp;
      } else if (line) {
        s.ax[n] = a_imp * u[0];
        s.ay[n] = a_imp * u[1];
        s.az[n] = a_imp * u[2];
      } else {
        const double da = a_imp - a_free;
        (rot ? s.awx : s.ax)[n] += da * u[0];
        (rot ? s.awy : s.ay)[n] += da * u[1];
        (rot ? s.awz : s.az)[n] += da * u[2];
      }
      const double dw = 0.25 * mass[n] * (a_imp * dt12 + 2.0 * v_along) * (a_imp - a_free);
      work += dt1 * dw;
      pend = dt2 * dw;
    }
  }
  return work;
}

// ---------------------------------------------------------------------------------------------------------
// /INIVEL/TRA

InitialVelocities::InitialVelocities(const model::Model& m, const SkewFrames& skews) : skews_(&skews) {
  for (const auto& iv : m.initial_velocities) {
    Entry e;
    e.v = iv.v;
    e.skew = skews.index(iv.skew);
    e.t_start = iv.t_start;
    e.sensor = m.sensor_index(iv.sensor);
    e.rotational = iv.rotational;
    e.nodes =
        group_of(m, iv.group, (iv.rotational ? "/INIVEL/ROT/" : "/INIVEL/TRA/") + std::to_string(iv.id));
    entries_.push_back(std::move(e));
  }
  remaining_ = entries_.size();
}

double InitialVelocities::apply(NodeState& s, double t, std::span<const double> sensor_starts) {
  if (remaining_ == 0) return 0.0;
  double dke = 0;
  for (auto& e : entries_) {
    if (e.applied) continue;
    // inivel_start.F90: the sensor's time alone when Tstart is 0, else the earlier of the two.
    const double sensor_on = time_origin(e.sensor, sensor_starts);
    const double at = e.sensor == model::kNone ? e.t_start
                      : e.t_start == 0         ? sensor_on
                                               : std::min(e.t_start, sensor_on);
    if (t < at) continue;
    e.applied = true;
    --remaining_;
    auto& vx = e.rotational ? s.wx : s.vx;
    auto& vy = e.rotational ? s.wy : s.vy;
    auto& vz = e.rotational ? s.wz : s.vz;
    const auto& m = e.rotational ? s.inertia : s.mass;
    // Components along the skew axes of now: v = sum_k V_k e_k (the global axes for no skew).
    std::array<double, 3> v{};
    for (int k = 0; k < 3; ++k) {
      const auto u = skews_->axis(e.skew, k);
      for (std::size_t d = 0; d < 3; ++d) v[d] += e.v[static_cast<std::size_t>(k)] * u[d];
    }
    for (const auto n32 : e.nodes) {
      const auto n = static_cast<std::size_t>(n32);
      const double old2 = vx[n] * vx[n] + vy[n] * vy[n] + vz[n] * vz[n];
      vx[n] = v[0];
      vy[n] = v[1];
      vz[n] = v[2];
      const double new2 = vx[n] * vx[n] + vy[n] * vy[n] + vz[n] * vz[n];
      dke += 0.5 * m[n] * (new2 - old2);
    }
  }
  return dke;
}

}  // namespace radx::solver
