// /INTER/TYPE2 kinematic tie: the equations are written at the top of tied_type2.hpp (map:
// solver/model/tied_map.hpp; OpenRadioss engine i2for3.F, i2vit3.F; starter i2tid3.F).
#include "solver/tied_type2.hpp"

#include <algorithm>
#include <cmath>

#include "solver/model/tied_map.hpp"

namespace radx::solver {

namespace {

using V3 = model::Vec3;

V3 at(const NodeState& s, std::size_t n) {
  return {s.x[n], s.y[n], s.z[n]};
}

// Clamped coordinates: onto [-1, 1]^2, or onto the triangle.
void clamp_coordinates(double& r, double& s, bool triangle) {
  if (triangle) {
    r = std::max(r, 0.0);
    s = std::max(s, 0.0);
    if (r + s > 1) {
      const double t = r + s;
      r /= t;
      s /= t;
    }
  } else {
    r = std::clamp(r, -1.0, 1.0);
    s = std::clamp(s, -1.0, 1.0);
  }
}

// x_s on the map for segment nodes x (d: the offset).
V3 place(const std::array<V3, 4>& x, const double* h, double d, bool triangle) {
  const V3 nn = model::tie_normal(x, triangle);
  const double len = model::norm(nn);
  V3 p = len > 0 ? model::scale(nn, d / len) : V3{0, 0, 0};
  for (std::size_t j = 0; j < 4; ++j) p = model::add(p, model::scale(x[j], h[j]));
  return p;
}

}  // namespace

TiedInterfaces::TiedInterfaces(const model::Model& m) {
  for (const auto& in : m.tied_interfaces) {
    for (std::size_t k = 0; k < in.tie_node.size(); ++k) {
      const auto& sg = in.tie_segment[k];
      const bool tri = model::is_triangle(sg);
      node_.push_back(in.tie_node[k]);
      for (const auto n : sg) seg_.push_back(n);
      const auto h = model::tie_shape(in.tie_r[k], in.tie_s[k], tri);
      double rc = in.tie_r[k], sc = in.tie_s[k];
      clamp_coordinates(rc, sc, tri);
      const auto hc = model::tie_shape(rc, sc, tri);
      h_.insert(h_.end(), h.begin(), h.end());
      hc_.insert(hc_.end(), hc.begin(), hc.end());
      offset_.push_back(in.tie_offset[k]);
      triangle_.push_back(tri ? 1 : 0);
    }
  }
}

void TiedInterfaces::mark_nodes(std::vector<std::uint8_t>& held) const {
  for (const auto n : node_) held[static_cast<std::size_t>(n)] = 1;
}

void TiedInterfaces::initialize(NodeState& s) {
  for (std::size_t k = 0; k < node_.size(); ++k) {
    const auto n = static_cast<std::size_t>(node_[k]);
    const int nj = triangle_[k] ? 3 : 4;
    // Main nodes that carry rotations receive the secondary's inertia and, each cycle, its moment.
    for (int j = 0; j < nj; ++j) {
      const auto q = 4 * k + static_cast<std::size_t>(j);
      const auto mn = static_cast<std::size_t>(seg_[q]);
      s.mass[mn] += hc_[q] * s.mass[n];
      if (s.inertia[mn] > 0) s.inertia[mn] += hc_[q] * s.inertia[n];
    }
    s.mass[n] = 0;
    s.inertia[n] = 0;
    // The secondary starts with the velocity of its place on the map (its own /INIVEL is replaced):
    // v_s = sum h_j v_j + d dn/dt, dn/dt = (1 - n n^T) dN/dt / |N|.
    std::array<V3, 4> x{}, v{};
    for (std::size_t j = 0; j < 4; ++j) {
      const auto mn = static_cast<std::size_t>(seg_[4 * k + j]);
      x[j] = at(s, mn);
      v[j] = {s.vx[mn], s.vy[mn], s.vz[mn]};
    }
    const bool tri = triangle_[k] != 0;
    V3 vs = model::scale(v[0], h_[4 * k]);
    for (std::size_t j = 1; j < 4; ++j) vs = model::add(vs, model::scale(v[j], h_[4 * k + j]));
    const V3 nn = model::tie_normal(x, tri);
    const double len = model::norm(nn);
    if (len > 0 && offset_[k] != 0) {
      const V3 dn = tri ? model::add(model::cross(model::sub(v[1], v[0]), model::sub(x[2], x[0])),
                                     model::cross(model::sub(x[1], x[0]), model::sub(v[2], v[0])))
                        : model::add(model::cross(model::sub(v[2], v[0]), model::sub(x[3], x[1])),
                                     model::cross(model::sub(x[2], x[0]), model::sub(v[3], v[1])));
      const V3 u = model::scale(nn, 1.0 / len);
      const V3 dnt = model::sub(dn, model::scale(u, model::dot(u, dn)));
      vs = model::add(vs, model::scale(dnt, offset_[k] / len));
    }
    s.vx[n] = vs[0];
    s.vy[n] = vs[1];
    s.vz[n] = vs[2];
  }
}

void TiedInterfaces::transfer_forces(NodeState& s) const {
  for (std::size_t k = 0; k < node_.size(); ++k) {
    const auto n = static_cast<std::size_t>(node_[k]);
    const bool tri = triangle_[k] != 0;
    const int nj = tri ? 3 : 4;
    std::array<std::size_t, 4> mn{};
    std::array<V3, 4> x{};
    for (std::size_t j = 0; j < 4; ++j) {
      mn[j] = static_cast<std::size_t>(seg_[4 * k + j]);
      x[j] = at(s, mn[j]);
    }
    const V3 f{s.fx[n], s.fy[n], s.fz[n]};
    std::array<V3, 4> fj{};
    for (std::size_t j = 0; j < 4; ++j) fj[j] = model::scale(f, h_[4 * k + j]);
    const double d = offset_[k];
    if (d != 0) {
      const V3 nn = model::tie_normal(x, tri);
      const double len = model::norm(nn);
      if (len > 0) {
        const V3 u = model::scale(nn, 1.0 / len);
        const V3 g = model::scale(model::sub(f, model::scale(u, model::dot(u, f))), d / len);
        if (tri) {
          const V3 a = model::sub(x[1], x[0]), b = model::sub(x[2], x[0]);
          const V3 bg = model::cross(b, g), ga = model::cross(g, a);
          fj[1] = model::add(fj[1], bg);
          fj[2] = model::add(fj[2], ga);
          fj[0] = model::sub(fj[0], model::add(bg, ga));
        } else {
          const V3 a = model::sub(x[2], x[0]), b = model::sub(x[3], x[1]);
          const V3 bg = model::cross(b, g), ga = model::cross(g, a);
          fj[2] = model::add(fj[2], bg);
          fj[0] = model::sub(fj[0], bg);
          fj[3] = model::add(fj[3], ga);
          fj[1] = model::sub(fj[1], ga);
        }
      }
    }
    for (int jj = 0; jj < nj; ++jj) {
      const auto j = static_cast<std::size_t>(jj);
      const auto m = mn[j];
      s.fx[m] += fj[j][0];
      s.fy[m] += fj[j][1];
      s.fz[m] += fj[j][2];
      if (s.inertia[m] > 0) {
        const double w = hc_[4 * k + j];
        s.mx[m] += w * s.mx[n];
        s.my[m] += w * s.my[n];
        s.mz[m] += w * s.mz[n];
      }
    }
    s.fx[n] = s.fy[n] = s.fz[n] = 0;
    s.mx[n] = s.my[n] = s.mz[n] = 0;
  }
}

void TiedInterfaces::transfer_stiffness(NodeState& s) const {
  for (std::size_t k = 0; k < node_.size(); ++k) {
    const auto n = static_cast<std::size_t>(node_[k]);
    const int nj = triangle_[k] ? 3 : 4;
    for (int j = 0; j < nj; ++j) {
      const auto q = 4 * k + static_cast<std::size_t>(j);
      s.stiffness[static_cast<std::size_t>(seg_[q])] += std::abs(h_[q]) * s.stiffness[n];
    }
    s.stiffness[n] = 1e-20;
  }
}

void TiedInterfaces::secondary_kinematics(NodeState& s, double dt1, double dt2) const {
  if (!(dt2 > 0)) return;
  const double dt12 = 0.5 * (dt1 + dt2);
  const double inv12 = 1.0 / dt12, inv2 = 1.0 / dt2;
  for (std::size_t k = 0; k < node_.size(); ++k) {
    const auto n = static_cast<std::size_t>(node_[k]);
    const bool tri = triangle_[k] != 0;
    std::array<V3, 4> x1{};
    double w[3] = {0, 0, 0};
    for (std::size_t j = 0; j < 4; ++j) {
      const auto m = static_cast<std::size_t>(seg_[4 * k + j]);
      x1[j] = {s.x[m] + dt2 * (s.vx[m] + dt12 * s.ax[m]), s.y[m] + dt2 * (s.vy[m] + dt12 * s.ay[m]),
               s.z[m] + dt2 * (s.vz[m] + dt12 * s.az[m])};
      if (s.inertia[m] > 0 && (!tri || j < 3)) {
        const double c = hc_[4 * k + j];
        w[0] += c * (s.wx[m] + dt12 * s.awx[m]);
        w[1] += c * (s.wy[m] + dt12 * s.awy[m]);
        w[2] += c * (s.wz[m] + dt12 * s.awz[m]);
      }
    }
    const V3 target = place(x1, &h_[4 * k], offset_[k], tri);
    s.ax[n] = ((target[0] - s.x[n]) * inv2 - s.vx[n]) * inv12;
    s.ay[n] = ((target[1] - s.y[n]) * inv2 - s.vy[n]) * inv12;
    s.az[n] = ((target[2] - s.z[n]) * inv2 - s.vz[n]) * inv12;
    s.awx[n] = (w[0] - s.wx[n]) * inv12;
    s.awy[n] = (w[1] - s.wy[n]) * inv12;
    s.awz[n] = (w[2] - s.wz[n]) * inv12;
  }
}

}  // namespace radx::solver
