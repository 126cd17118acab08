#include "solver/conditions/rigid_wall_plane.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "solver/model/exact_sum.hpp"

namespace radx::solver {

RigidWalls::RigidWalls(const model::Model& m) {
  for (const auto& w : m.rigid_walls) {
    const std::string what = std::string(w.shape == 1   ? "/RWALL/CYL/"
                                         : w.shape == 2 ? "/RWALL/SPHER/"
                                         : w.shape == 3 ? "/RWALL/PARAL/"
                                                        : "/RWALL/PLANE/") +
                             std::to_string(w.id);
    if (w.iform != 0)
      throw std::runtime_error(what + ": Iform = " + std::to_string(w.iform) +
                               " (penalty formulation) is not supported by the radx engine; use Iform = 0 "
                               "(kinematic)");
    if (w.slide < 0 || w.slide > 2)
      throw std::runtime_error(what + ": Slide = " + std::to_string(w.slide) + " is not 0, 1 or 2");
    if (w.slide == 2 && w.ifq != 0 && w.shape != 3)
      throw std::runtime_error(what + ": friction filtering ifq = " + std::to_string(w.ifq) +
                               " is not supported by the radx engine; use ifq = 0 (no filter)");
    double nn = std::sqrt(w.normal[0] * w.normal[0] + w.normal[1] * w.normal[1] + w.normal[2] * w.normal[2]);
    if (w.shape == 2) nn = 1.0;  // a sphere has no axis
    if (!(nn > 0)) throw std::runtime_error(what + ": the wall normal is undefined (M1 = M)");
    Wall out;
    out.shape = w.shape;
    out.radius = 0.5 * w.diameter;
    if ((w.shape == 1 || w.shape == 2) && !(out.radius > 0))
      throw std::runtime_error(what + ": the diameter must be > 0");
    out.node = w.node;
    out.slide = w.slide;
    out.friction = w.slide == 2 ? w.friction : 0.0;
    out.added_mass = w.mass;
    out.point = w.m;
    out.normal = {w.normal[0] / nn, w.normal[1] / nn, w.normal[2] / nn};
    out.v0 = w.v0;
    if (w.shape == 3) {
      for (std::size_t d = 0; d < 3; ++d) {
        out.edge1[d] = w.m1[d] - w.m[d];
        out.edge2[d] = w.m2[d] - w.m[d];
      }
      const auto& a = out.edge1;
      const auto& b = out.edge2;
      out.edge12 = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
      out.edge12_sq =
          out.edge12[0] * out.edge12[0] + out.edge12[1] * out.edge12[1] + out.edge12[2] * out.edge12[2];
      if (!(out.edge12_sq > 0)) throw std::runtime_error(what + ": the parallelogram has no area");
      out.vn_prev = w.node != model::kNone
                        ? w.v0[0] * out.normal[0] + w.v0[1] * out.normal[1] + w.v0[2] * out.normal[2]
                        : 0.0;
    }
    out.secondary = w.secondary;
    walls_.push_back(std::move(out));
    RigidWallOutput o;
    o.id = w.id;
    out_.push_back(o);
  }
}

void RigidWalls::initialize(NodeState& s) const {
  for (std::size_t k = 0; k < walls_.size(); ++k) {
    const auto& w = walls_[k];
    if (w.node == model::kNone) continue;
    const auto n = static_cast<std::size_t>(w.node);
    s.mass[n] += w.added_mass;
    // A massless wall node runs as in Radioss: in the directions /IMPVEL or /BCS impose, it follows them;
    // in the free ones it takes the lagged contact force over the contact mass alone
    // (apply_wall_node_forces), and keeps its velocity while nothing touches it.
    s.vx[n] = w.v0[0];
    s.vy[n] = w.v0[1];
    s.vz[n] = w.v0[2];
  }
}

void RigidWalls::apply_wall_node_forces(NodeState& s) const {
  for (const auto& w : walls_) {
    if (w.node == model::kNone) continue;
    const auto n = static_cast<std::size_t>(w.node);
    const double m = s.mass[n];
    const double denom = m + w.contact_mass_prev;
    if (!(denom > 0)) continue;
    s.ax[n] = (m * s.ax[n] + w.force_prev[0]) / denom;
    s.ay[n] = (m * s.ay[n] + w.force_prev[1]) / denom;
    s.az[n] = (m * s.az[n] + w.force_prev[2]) / denom;
  }
}

// Cylinder (axis a through the wall point) and sphere (centre at the wall point): in contact when the
// predicted position x* is inside, |x* - x_w|_perp <= R (cylinder) or |x* - x_w| <= R (sphere), with no test
// on the approach speed (Radioss rgwalc.F, rgwals.F); the normal is the outward radial direction at the
// node's current position. A node on the axis or at the centre has no normal and is left free.
bool RigidWalls::curved_contact(const Wall& w, const NodeState& s, std::size_t n, double vsx, double vsy,
                                double vsz, double dt2, double xwx, double xwy, double xwz, double xw0x,
                                double xw0y, double xw0z, double& nx, double& ny, double& nz) {
  const bool cyl = w.shape == 1;
  auto radial = [&](double dx, double dy, double dz, double& rx, double& ry, double& rz) {
    const double along = cyl ? dx * w.normal[0] + dy * w.normal[1] + dz * w.normal[2] : 0.0;
    rx = dx - along * w.normal[0];
    ry = dy - along * w.normal[1];
    rz = dz - along * w.normal[2];
    return rx * rx + ry * ry + rz * rz;
  };
  double rx, ry, rz;
  const double r2_pred =
      radial(s.x[n] + vsx * dt2 - xwx, s.y[n] + vsy * dt2 - xwy, s.z[n] + vsz * dt2 - xwz, rx, ry, rz);
  if (r2_pred > w.radius * w.radius) return false;
  const double r2 = radial(s.x[n] - xw0x, s.y[n] - xw0y, s.z[n] - xw0z, rx, ry, rz);
  if (!(r2 > 0)) return false;
  const double inv = 1.0 / std::sqrt(r2);
  nx = rx * inv;
  ny = ry * inv;
  nz = rz * inv;
  return true;
}

bool RigidWalls::parallelogram_contact(const Wall& w, const NodeState& s, std::size_t n, double vsx,
                                       double vsy, double vsz, double dt1, double dt2, double xw0x,
                                       double xw0y, double xw0z, double vwx, double vwy, double vwz,
                                       double tol_wall, double& v_push) {
  const auto& e1 = w.edge1;
  const auto& e2 = w.edge2;
  const auto& s12 = w.edge12;
  const double nx = w.normal[0], ny = w.normal[1], nz = w.normal[2];
  const double dx0 = s.x[n] - xw0x, dy0 = s.y[n] - xw0y, dz0 = s.z[n] - xw0z;
  const double rvx = vsx - vwx, rvy = vsy - vwy, rvz = vsz - vwz;
  const double rvn = rvx * nx + rvy * ny + rvz * nz;
  const double dp0 = dx0 * nx + dy0 * ny + dz0 * nz;
  const double dp = dp0 + rvn * dt2;
  const double tol = 2.0 * dt1 * std::max(std::abs(rvn), tol_wall);
  if (dp > 0 || dp0 <= -tol) return false;
  // The predicted point projected on the plane, c = a e1 + b e2: e1 x c = b s12 and c x e2 = a s12.
  const double cx = dx0 + rvx * dt2 - dp * nx, cy = dy0 + rvy * dt2 - dp * ny, cz = dz0 + rvz * dt2 - dp * nz;
  const double b1 = e1[1] * cz - e1[2] * cy, b2 = e1[2] * cx - e1[0] * cz, b3 = e1[0] * cy - e1[1] * cx;
  if (s12[0] * b1 + s12[1] * b2 + s12[2] * b3 < 0 || b1 * b1 + b2 * b2 + b3 * b3 > w.edge12_sq) return false;
  const double a1 = cy * e2[2] - cz * e2[1], a2 = cz * e2[0] - cx * e2[2], a3 = cx * e2[1] - cy * e2[0];
  if (s12[0] * a1 + s12[1] * a2 + s12[2] * a3 < 0 || a1 * a1 + a2 * a2 + a3 * a3 > w.edge12_sq) return false;
  if (rvn > 0 && dp0 > 0) return false;  // separating, above the wall
  v_push = dt2 > 0 ? -std::min(dp0, 0.0) / dt2 : 0.0;
  return true;
}

double RigidWalls::apply(NodeState& s, double dt1, double dt2) {
  const double dt12 = 0.5 * (dt1 + dt2);
  const double fact = dt12 != 0 ? 1.0 / dt12 : 0.0;
  double work = 0;
  for (std::size_t k = 0; k < walls_.size(); ++k) {
    auto& w = walls_[k];
    auto& o = out_[k];
    const double ax_ = w.normal[0], ay_ = w.normal[1], az_ = w.normal[2];  // plane normal or cylinder axis
    double vwx = 0, vwy = 0, vwz = 0;
    double xwx = w.point[0], xwy = w.point[1], xwz = w.point[2];
    double xw0x = xwx, xw0y = xwy, xw0z = xwz;  // the wall point now (the normal of a curved wall)
    if (w.node != model::kNone) {
      xw0x = s.x[static_cast<std::size_t>(w.node)];
      xw0y = s.y[static_cast<std::size_t>(w.node)];
      xw0z = s.z[static_cast<std::size_t>(w.node)];
      const auto m = static_cast<std::size_t>(w.node);
      vwx = s.vx[m] + s.ax[m] * dt12;
      vwy = s.vy[m] + s.ay[m] * dt12;
      vwz = s.vz[m] + s.az[m] * dt12;
      xwx = s.x[m] + vwx * dt2;
      xwy = s.y[m] + vwy * dt2;
      xwz = s.z[m] + vwz * dt2;
    }
    // Parallelogram: the change of the wall's normal velocity since the last cycle widens the tolerance.
    const double vn = vwx * ax_ + vwy * ay_ + vwz * az_;
    const double tol_wall = std::abs(vn - w.vn_prev);
    if (w.shape == 3) w.vn_prev = vn;
    const double mu2 = w.friction * w.friction;
    // fnx.. and contact_mass feed a moving wall's motion (force_prev): serial sums in secondary order. What
    // is only reported (forces, impulses, work) is summed exactly, order-free (model::ExactSum).
    double fnx = 0, fny = 0, fnz = 0, ftx = 0, fty = 0, ftz = 0;
    double contact_mass = 0;
    std::array<model::ExactSum, 3> reported_fn, reported_ft;
    model::ExactSum w_normal, w_tangential;
    int contacts = 0;
    for (const auto n32 : w.secondary) {
      const auto n = static_cast<std::size_t>(n32);
      // Prediction.
      const double vsx = s.vx[n] + s.ax[n] * dt12, vsy = s.vy[n] + s.ay[n] * dt12,
                   vsz = s.vz[n] + s.az[n] * dt12;
      double nx = ax_, ny = ay_, nz = az_;
      double vp = 0;  // normal velocity relative to the wall after the contact (parallelogram push-back)
      if (w.shape == 3) {
        if (!parallelogram_contact(w, s, n, vsx, vsy, vsz, dt1, dt2, xw0x, xw0y, xw0z, vwx, vwy, vwz,
                                   tol_wall, vp))
          continue;
      } else if (w.shape == 0) {
        const double gap = (s.x[n] + vsx * dt2 - xwx) * nx + (s.y[n] + vsy * dt2 - xwy) * ny +
                           (s.z[n] + vsz * dt2 - xwz) * nz;
        if (gap > 0) continue;
        if ((vsx - vwx) * nx + (vsy - vwy) * ny + (vsz - vwz) * nz > 0) continue;
      } else if (!curved_contact(w, s, n, vsx, vsy, vsz, dt2, xwx, xwy, xwz, xw0x, xw0y, xw0z, nx, ny, nz)) {
        continue;
      }
      ++contacts;
      const double m = s.mass[n];
      // Normal impulse and work.
      const double rvx = s.vx[n] - vwx, rvy = s.vy[n] - vwy, rvz = s.vz[n] - vwz;
      const double u = rvx * nx + rvy * ny + rvz * nz;
      const double p = s.ax[n] * nx + s.ay[n] * ny + s.az[n] * nz;
      const double fn = m * (u + p * dt12 - vp);
      const double fx = fn * nx, fy = fn * ny, fz = fn * nz;
      w_normal.add(-(fact * u * fn));
      fnx += fx;
      fny += fy;
      fnz += fz;
      reported_fn[0].add(fx);
      reported_fn[1].add(fy);
      reported_fn[2].add(fz);
      contact_mass += m;
      const double du = u - vp;  // normal velocity removed
      if (w.slide == 0) {
        s.ax[n] -= p * nx;
        s.ay[n] -= p * ny;
        s.az[n] -= p * nz;
        s.vx[n] -= du * nx;
        s.vy[n] -= du * ny;
        s.vz[n] -= du * nz;
        continue;
      }
      // Tangential impulse that would stop the node relative to the wall.
      double tx = (rvx + s.ax[n] * dt12 - vp * nx) * m - fx;
      double ty = (rvy + s.ay[n] * dt12 - vp * ny) * m - fy;
      double tz = (rvz + s.az[n] * dt12 - vp * nz) * m - fz;
      const double ft2 = tx * tx + ty * ty + tz * tz;
      const double fn2 = fx * fx + fy * fy + fz * fz;
      if (w.slide == 1 || ft2 <= mu2 * fn2 || !(m > 0)) {
        // Tied, or sticking.
        s.ax[n] = s.ay[n] = s.az[n] = 0;
        s.vx[n] = vwx + vp * nx;
        s.vy[n] = vwy + vp * ny;
        s.vz[n] = vwz + vp * nz;
      } else {
        // Slip: the tangential impulse is limited to mu |Fn|.
        const double c = w.friction * std::sqrt(fn2 / ft2);
        tx *= c;
        ty *= c;
        tz *= c;
        const double inv = 1.0 / (dt12 * m);
        s.ax[n] -= p * nx + tx * inv;
        s.ay[n] -= p * ny + ty * inv;
        s.az[n] -= p * nz + tz * inv;
        s.vx[n] -= du * nx;
        s.vy[n] -= du * ny;
        s.vz[n] -= du * nz;
        w_tangential.add(-((s.vx[n] - vwx) * tx + (s.vy[n] - vwy) * ty + (s.vz[n] - vwz) * tz));
      }
      ftx += tx;
      fty += ty;
      ftz += tz;
      reported_ft[0].add(tx);
      reported_ft[1].add(ty);
      reported_ft[2].add(tz);
    }
    work += w_tangential.value() + 0.5 * dt1 * w_normal.value();
    o.contacts = contacts;
    for (std::size_t d = 0; d < 3; ++d) {
      const double impulse_n = reported_fn[d].value(), impulse_t = reported_ft[d].value();
      o.normal_force[d] = impulse_n * fact;
      o.tangential_force[d] = impulse_t * fact;
      o.normal_impulse[d] += impulse_n;
      o.tangential_impulse[d] += impulse_t;
    }
    w.force_prev = {(fnx + ftx) * fact, (fny + fty) * fact, (fnz + ftz) * fact};
    w.contact_mass_prev = contact_mass;
  }
  return work;
}

}  // namespace radx::solver
