#include "solver/conditions/rigid_body.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "solver/conditions/sensors.hpp"

namespace radx::solver {

namespace {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using RowMat3 = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;

Vec3 position(const NodeState& s, std::size_t n) {
  return {s.x[n], s.y[n], s.z[n]};
}
Vec3 velocity(const NodeState& s, std::size_t n) {
  return {s.vx[n], s.vy[n], s.vz[n]};
}
Vec3 spin(const NodeState& s, std::size_t n) {
  return {s.wx[n], s.wy[n], s.wz[n]};
}
Vec3 acceleration(const NodeState& s, std::size_t n) {
  return {s.ax[n], s.ay[n], s.az[n]};
}
Vec3 spin_rate(const NodeState& s, std::size_t n) {
  return {s.awx[n], s.awy[n], s.awz[n]};
}

// Rotation matrix of the rotation vector theta (Rodrigues).
Mat3 rotation(const Vec3& theta) {
  const double phi = theta.norm();
  if (phi == 0) return Mat3::Identity();
  return Eigen::AngleAxisd(phi, theta / phi).toRotationMatrix();
}

// (R(theta) - 1) r / dt = c1 (w x r) + c2 dt w x (w x r), theta = w dt, phi = |theta|.
void rotation_series(double phi, double& c1, double& c2) {
  if (phi < 1e-4) {
    const double p2 = phi * phi;
    c1 = 1.0 - p2 / 6.0;
    c2 = 0.5 - p2 / 24.0;
  } else {
    c1 = std::sin(phi) / phi;
    const double h = std::sin(0.5 * phi);
    c2 = 2.0 * h * h / (phi * phi);
  }
}

// Rows orthonormal and right-handed again after many incremental rotations.
void orthonormalize(RowMat3& r) {
  Vec3 e0 = r.row(0).transpose(), e1 = r.row(1).transpose();
  e0.normalize();
  e1 -= e1.dot(e0) * e0;
  e1.normalize();
  const Vec3 e2 = e0.cross(e1);
  r.row(0) = e0.transpose();
  r.row(1) = e1.transpose();
  r.row(2) = e2.transpose();
}

}  // namespace

RigidBodies::RigidBodies(const model::Model& m, std::span<const std::int64_t> inactive)
    : secondary_flag_(m.nodes.size(), 0) {
  for (const auto& rb : m.rigid_bodies) {
    // /RBODY/OFF in the engine deck: the body is not formed in this run; its nodes move freely.
    if (std::find(inactive.begin(), inactive.end(), rb.id) != inactive.end()) continue;
    const std::string what = rb.rigid_material != 0
                                 ? "the rigid body of /MAT/RIGID/" + std::to_string(rb.rigid_material)
                                 : "/RBODY/" + std::to_string(rb.id);
    if (rb.main_node == model::kNone || static_cast<std::size_t>(rb.main_node) >= m.nodes.size())
      throw std::runtime_error(what + ": no main node");
    if (rb.icog < 1 || rb.icog > 4) throw std::runtime_error(what + ": ICoG must be 1, 2, 3 or 4");
    RigidBodyInfo b;
    b.id = rb.id;
    b.name = what;
    b.main = rb.main_node;
    b.secondary = rb.secondary;
    b.sensor = m.sensor_index(rb.sensor);
    // With a sensor, or built from /MAT/RIGID elements: formed from the secondaries alone.
    b.from_secondaries = b.sensor != model::kNone || rb.rigid_material != 0;
    b.ispher = rb.ispher == 1 ? 1 : 2;
    b.icog = b.from_secondaries ? 2 : rb.icog;
    for (const auto n : b.secondary) secondary_flag_[static_cast<std::size_t>(n)] = 1;
    deck_mass_.push_back(b.from_secondaries ? 0.0 : rb.mass);
    deck_inertia_.push_back(b.from_secondaries ? std::array<double, 6>{} : rb.inertia);
    bodies_.push_back(std::move(b));
  }
}

std::vector<std::string> RigidBodies::take_messages() {
  std::vector<std::string> out;
  out.swap(messages_);
  return out;
}

void RigidBodies::release(RigidBodyInfo& b, NodeState& s) {
  b.active = false;
  b.release_in = 0;
  const auto mn = static_cast<std::size_t>(b.main);
  s.mass[mn] = 0;  // the main node of a body with a sensor has no mass of its own (INIRBYS)
  s.inertia[mn] = 0;
  for (const auto n : b.secondary) secondary_flag_[static_cast<std::size_t>(n)] = 0;
  b.force = b.moment = b.secondary_force = b.secondary_moment = {};
  messages_.push_back("RIGID BODY " + std::to_string(b.id) + " SET OFF");
}

void RigidBodies::initialize(NodeState& s, std::span<const double> sensor_starts) {
  for (std::size_t bi = 0; bi < bodies_.size(); ++bi) {
    auto& b = bodies_[bi];
    const std::string& what = b.name;
    const auto mn = static_cast<std::size_t>(b.main);
    const bool sensor = b.sensor != model::kNone;
    if (b.from_secondaries) {
      s.mass[mn] = 0;
      s.inertia[mn] = 0;
    }
    if (sensor) {
      if (time_origin(b.sensor, sensor_starts) <= 0) {  // the sensor is on at t = 0: never formed
        release(b, s);
        continue;
      }
    }
    double m0 = s.mass[mn] + deck_mass_[bi];
    if (m0 == 0) m0 = 1e-20;
    const auto& j = deck_inertia_[bi];  // Jxx Jyy Jzz Jxy Jyz Jxz
    Mat3 inertia;
    inertia << j[0], j[3], j[5], j[3], j[1], j[4], j[5], j[4], j[2];
    inertia += s.inertia[mn] * Mat3::Identity();

    const Vec3 x_old = position(s, mn);
    double ms = 0;
    Vec3 mx = Vec3::Zero();
    for (const auto n : b.secondary) {
      const auto k = static_cast<std::size_t>(n);
      ms += s.mass[k];
      mx += s.mass[k] * position(s, k);
    }
    Vec3 x_new = x_old, x_g = x_old;
    double mass = m0 + ms;
    switch (b.icog) {
      case 1:
        if (mass <= 1e-30) throw std::runtime_error(what + ": the rigid body has no mass (ICoG 1)");
        x_new = (m0 * x_old + mx) / mass;
        break;
      case 2:
        if (ms <= 1e-30) throw std::runtime_error(what + ": the secondary nodes have no mass (ICoG 2)");
        x_new = mx / ms;
        x_g = x_new;
        break;
      case 3: break;
      default: mass = m0; break;
    }
    if (b.icog <= 3) {
      const Vec3 d = x_g - x_new;
      inertia += m0 * (d.squaredNorm() * Mat3::Identity() - d * d.transpose());
      if (b.secondary.size() == 1) inertia += 1e-20 * Mat3::Identity();
      for (const auto n : b.secondary) {
        const auto k = static_cast<std::size_t>(n);
        const Vec3 r = position(s, k) - x_new;
        inertia += s.inertia[k] * Mat3::Identity() +
                   s.mass[k] * (r.squaredNorm() * Mat3::Identity() - r * r.transpose());
      }
    }
    b.tensor = {inertia(0, 0), inertia(1, 1), inertia(2, 2), inertia(0, 1), inertia(1, 2), inertia(0, 2)};

    // Principal values and axes (columns of V), right-handed.
    Eigen::SelfAdjointEigenSolver<Mat3> eig(inertia);
    Vec3 lam = eig.eigenvalues();
    Mat3 v = eig.eigenvectors();
    if (v.determinant() < 0) v.col(2) = -v.col(2);
    const double imax = lam.maxCoeff();
    if (b.ispher == 1) {
      lam.setConstant(lam.mean());
    } else if (lam.minCoeff() <= 1e-3 * imax) {
      for (int i = 0; i < 3; ++i)
        if (lam(i) / imax < 1e-3) lam(i) += 0.1 * imax;
    }
    if (!(lam.minCoeff() > 0))
      throw std::runtime_error(what +
                               ": the rigid body has no rotational inertia (all its mass at the main "
                               "node and no inertia given)");
    b.principal = {lam(0), lam(1), lam(2)};
    RowMat3 r = v.transpose();
    std::copy(r.data(), r.data() + 9, b.axes.begin());
    b.mass = mass;

    // The main node: position, mass, inertia; the secondaries follow its motion.
    s.x[mn] = s.x0[mn] = x_new(0);
    s.y[mn] = s.y0[mn] = x_new(1);
    s.z[mn] = s.z0[mn] = x_new(2);
    s.mass[mn] = mass;
    s.inertia[mn] = lam.minCoeff();
    Vec3 vm = velocity(s, mn), wm = spin(s, mn);
    if (b.from_secondaries) {  // the velocities that keep the secondaries' momentum and angular momentum
                               // (rbypid.F)
      Vec3 p = Vec3::Zero(), l = Vec3::Zero();
      for (const auto n : b.secondary) {
        const auto k = static_cast<std::size_t>(n);
        p += s.mass[k] * velocity(s, k);
        l += (position(s, k) - x_new).cross(s.mass[k] * velocity(s, k)) + s.inertia[k] * spin(s, k);
      }
      vm = p / mass;
      wm = r.transpose() * ((r * l).array() / lam.array()).matrix();
      s.vx[mn] = vm(0);
      s.vy[mn] = vm(1);
      s.vz[mn] = vm(2);
      s.wx[mn] = wm(0);
      s.wy[mn] = wm(1);
      s.wz[mn] = wm(2);
    }
    for (const auto n : b.secondary) {
      const auto k = static_cast<std::size_t>(n);
      const Vec3 vs = vm + wm.cross(position(s, k) - x_new);
      s.vx[k] = vs(0);
      s.vy[k] = vs(1);
      s.vz[k] = vs(2);
      s.wx[k] = wm(0);
      s.wy[k] = wm(1);
      s.wz[k] = wm(2);
    }
  }
}

void RigidBodies::gather_and_accelerate(NodeState& s, double t, double dt1,
                                        std::span<const double> sensor_starts) {
  for (auto& b : bodies_) {
    if (!b.active) continue;
    if (b.sensor != model::kNone) {  // rbyonf.F RBYSENS: released 2 cycles after the sensor is seen on
      if (b.release_in > 0 && --b.release_in == 0) {
        release(b, s);
        continue;
      }
      if (b.release_in == 0 && t > time_origin(b.sensor, sensor_starts)) {
        b.release_in = 2;
        messages_.push_back("RIGID BODY " + std::to_string(b.id) + " WILL BE SET OFF WITHIN 2 CYCLES");
      }
    }
    const auto mn = static_cast<std::size_t>(b.main);
    const Vec3 xm = position(s, mn);
    Vec3 f(s.fx[mn], s.fy[mn], s.fz[mn]);
    Vec3 mom(s.mx[mn], s.my[mn], s.mz[mn]);
    double k_main = s.stiffness[mn];
    Vec3 f_sec = Vec3::Zero(), mom_sec = Vec3::Zero();
    for (const auto n : b.secondary) {
      const auto k = static_cast<std::size_t>(n);
      const Vec3 fs(s.fx[k], s.fy[k], s.fz[k]);
      f_sec += fs;
      mom_sec += Vec3(s.mx[k], s.my[k], s.mz[k]) + (position(s, k) - xm).cross(fs);
      k_main += s.stiffness[k];
      s.stiffness[k] = 1e-20;
    }
    f += f_sec;
    mom += mom_sec;
    b.secondary_force = {f_sec(0), f_sec(1), f_sec(2)};
    b.secondary_moment = {mom_sec(0), mom_sec(1), mom_sec(2)};
    s.stiffness[mn] = k_main;
    s.fx[mn] = f(0);
    s.fy[mn] = f(1);
    s.fz[mn] = f(2);
    s.mx[mn] = mom(0);
    s.my[mn] = mom(1);
    s.mz[mn] = mom(2);
    b.force = {f(0), f(1), f(2)};
    b.moment = {mom(0), mom(1), mom(2)};

    // Translation: a = F / M.
    const double mass = s.mass[mn];
    if (mass > 0) {
      s.ax[mn] = f(0) / mass;
      s.ay[mn] = f(1) / mass;
      s.az[mn] = f(2) / mass;
    }

    // Rotation: advance the principal frame to t_n, then Euler's equations.
    Eigen::Map<RowMat3> r(b.axes.data());
    const Vec3 w = spin(s, mn);
    for (int d = 0; d < 3; ++d) b.rotation[static_cast<std::size_t>(d)] += w(d) * dt1;
    if (dt1 > 0 && w.squaredNorm() > 0) {
      RowMat3 rn = r * rotation(w * dt1).transpose();
      orthonormalize(rn);
      r = rn;
    }
    const Vec3 ip(b.principal[0], b.principal[1], b.principal[2]);
    Vec3 alpha;
    const unsigned fixed_rot = (s.fixed[mn] >> 3) & 7u;
    if (fixed_rot == 0) {
      const Vec3 wp = r * w;
      const Vec3 mp = r * mom;
      Vec3 ap;
      ap(0) = (mp(0) + (ip(1) - ip(2)) * wp(1) * wp(2)) / ip(0);
      ap(1) = (mp(1) + (ip(2) - ip(0)) * wp(2) * wp(0)) / ip(1);
      ap(2) = (mp(2) + (ip(0) - ip(1)) * wp(0) * wp(1)) / ip(2);
      alpha = r.transpose() * ap;
    } else {
      // Global system I alpha = Mom - w x (I w) restricted to the free rotations.
      const Mat3 ig = r.transpose() * ip.asDiagonal() * r;
      const Vec3 rhs = mom - w.cross(ig * w);
      int free_idx[3];
      int nf = 0;
      for (int i = 0; i < 3; ++i)
        if (!(fixed_rot & (1u << i))) free_idx[nf++] = i;
      alpha.setZero();
      if (nf == 1) {
        const int i = free_idx[0];
        alpha(i) = rhs(i) / ig(i, i);
      } else if (nf == 2) {
        const int i = free_idx[0], k = free_idx[1];
        const double det = ig(i, i) * ig(k, k) - ig(i, k) * ig(k, i);
        alpha(i) = (ig(k, k) * rhs(i) - ig(i, k) * rhs(k)) / det;
        alpha(k) = (-ig(k, i) * rhs(i) + ig(i, i) * rhs(k)) / det;
      }
    }
    s.awx[mn] = alpha(0);
    s.awy[mn] = alpha(1);
    s.awz[mn] = alpha(2);
  }
}

void RigidBodies::secondary_kinematics(NodeState& s, double dt1, double dt2) const {
  const double dt12 = 0.5 * (dt1 + dt2);
  const double inv = 1.0 / dt12;
  for (const auto& b : bodies_) {
    if (!b.active) continue;
    const auto mn = static_cast<std::size_t>(b.main);
    const Vec3 xm = position(s, mn);
    const Vec3 w = spin(s, mn) + dt12 * spin_rate(s, mn);          // omega^{n+1/2}
    const Vec3 vm = velocity(s, mn) + dt12 * acceleration(s, mn);  // v_N^{n+1/2}
    double c1, c2;
    rotation_series(w.norm() * dt2, c1, c2);
    for (const auto n : b.secondary) {
      const auto k = static_cast<std::size_t>(n);
      const Vec3 r = position(s, k) - xm;
      const Vec3 wr = w.cross(r);
      const Vec3 target = vm + c1 * wr + (c2 * dt2) * w.cross(wr);
      s.ax[k] = (target(0) - s.vx[k]) * inv;
      s.ay[k] = (target(1) - s.vy[k]) * inv;
      s.az[k] = (target(2) - s.vz[k]) * inv;
      s.awx[k] = (w(0) - s.wx[k]) * inv;
      s.awy[k] = (w(1) - s.wy[k]) * inv;
      s.awz[k] = (w(2) - s.wz[k]) * inv;
    }
  }
}

void RigidBodies::kinetic_correction(const NodeState& s, double dt1, KineticSums& c) const {
  const double h = 0.5 * dt1;
  for (const auto& b : bodies_) {
    if (!b.active) continue;
    const auto mn = static_cast<std::size_t>(b.main);
    const Eigen::Map<const RowMat3> r(b.axes.data());
    const Vec3 w = spin(s, mn) + h * spin_rate(s, mn);
    const Vec3 wp = r * w;
    c.rotational.add(0.5 * (b.principal[0] * wp(0) * wp(0) + b.principal[1] * wp(1) * wp(1) +
                            b.principal[2] * wp(2) * wp(2)));
    c.rotational.add(-(0.5 * s.inertia[mn] * w.squaredNorm()));
    // Each secondary's terms exactly as the node sums add them (kinematics_driver.cpp), negated: they cancel.
    for (const auto n : b.secondary) {
      const auto k = static_cast<std::size_t>(n);
      const double vx = s.vx[k] + h * s.ax[k], vy = s.vy[k] + h * s.ay[k], vz = s.vz[k] + h * s.az[k];
      const double wx = s.wx[k] + h * s.awx[k], wy = s.wy[k] + h * s.awy[k], wz = s.wz[k] + h * s.awz[k];
      c.translational.add(-(0.5 * s.mass[k] * (vx * vx + vy * vy + vz * vz)));
      c.rotational.add(-(0.5 * s.inertia[k] * (wx * wx + wy * wy + wz * wz)));
      c.mass.add(-s.mass[k]);
      c.momentum[0].add(-(s.mass[k] * vx));
      c.momentum[1].add(-(s.mass[k] * vy));
      c.momentum[2].add(-(s.mass[k] * vz));
    }
  }
}

std::array<double, 6> current_inertia(const RigidBodyInfo& b) {
  const Eigen::Map<const RowMat3> r(b.axes.data());
  const Vec3 ip(b.principal[0], b.principal[1], b.principal[2]);
  const Mat3 ig = r.transpose() * ip.asDiagonal() * r;
  return {ig(0, 0), ig(1, 1), ig(2, 2), ig(0, 1), ig(1, 2), ig(0, 2)};
}

double RigidBodies::kinetic_energy(std::size_t bi, const NodeState& s, double dt1) const {
  const auto& b = bodies_.at(bi);
  const auto mn = static_cast<std::size_t>(b.main);
  const double h = 0.5 * dt1;
  const Eigen::Map<const RowMat3> r(b.axes.data());
  const Vec3 v = velocity(s, mn) + h * acceleration(s, mn);
  const Vec3 wp = r * (spin(s, mn) + h * spin_rate(s, mn));
  return 0.5 * s.mass[mn] * v.squaredNorm() +
         0.5 * (b.principal[0] * wp(0) * wp(0) + b.principal[1] * wp(1) * wp(1) +
                b.principal[2] * wp(2) * wp(2));
}

}  // namespace radx::solver
