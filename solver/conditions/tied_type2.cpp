// /INTER/TYPE2 kinematic and rigid ties: the equations are written at the top of tied_type2.hpp (map:
// solver/model/tied_map.hpp; OpenRadioss engine i2for3.F, i2vit3.F; starter i2tid3.F).
#include "solver/conditions/tied_type2.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

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

// 3 x 3 matrices, row-major.
using M3 = std::array<double, 9>;

constexpr M3 kIdentity{1, 0, 0, 0, 1, 0, 0, 0, 1};

V3 mul(const M3& a, const V3& v) {
  return {a[0] * v[0] + a[1] * v[1] + a[2] * v[2], a[3] * v[0] + a[4] * v[1] + a[5] * v[2],
          a[6] * v[0] + a[7] * v[1] + a[8] * v[2]};
}
M3 mul(const M3& a, const M3& b) {
  M3 c{};
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j)
      c[3 * i + j] = a[3 * i] * b[j] + a[3 * i + 1] * b[3 + j] + a[3 * i + 2] * b[6 + j];
  return c;
}
M3 transpose(const M3& a) {
  return {a[0], a[3], a[6], a[1], a[4], a[7], a[2], a[5], a[8]};
}
// tr(S) I - S for the symmetric part S of a.
M3 trace_minus_sym(const M3& a) {
  const double t = a[0] + a[4] + a[8];
  const double s01 = 0.5 * (a[1] + a[3]), s02 = 0.5 * (a[2] + a[6]), s12 = 0.5 * (a[5] + a[7]);
  return {t - a[0], -s01, -s02, -s01, t - a[4], -s12, -s02, -s12, t - a[8]};
}
// x with a x = b (a symmetric positive definite here), by the adjugate.
V3 solve(const M3& a, const V3& b) {
  const V3 c0{a[0], a[3], a[6]}, c1{a[1], a[4], a[7]}, c2{a[2], a[5], a[8]};
  const double det = model::dot(c0, model::cross(c1, c2));
  return {model::dot(b, model::cross(c1, c2)) / det, model::dot(c0, model::cross(b, c2)) / det,
          model::dot(c0, model::cross(c1, b)) / det};
}
// Smallest eigenvalue of a symmetric matrix, by cyclic Jacobi rotations (accurate to round-off also for the
// repeated eigenvalues of a square or regular segment, where the trigonometric closed form loses half the
// digits).
double smallest_eigenvalue(M3 a) {
  for (int sweep = 0; sweep < 30; ++sweep) {
    const double off = a[1] * a[1] + a[2] * a[2] + a[5] * a[5];
    const double diag = a[0] * a[0] + a[4] * a[4] + a[8] * a[8];
    if (!(off > 1e-32 * diag)) break;
    for (const auto& [p, q] : {std::pair<std::size_t, std::size_t>{0, 1}, {0, 2}, {1, 2}}) {
      const double apq = a[3 * p + q];
      if (apq == 0) continue;
      const double theta = (a[3 * q + q] - a[3 * p + p]) / (2.0 * apq);
      const double t = (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
      const double c = 1.0 / std::sqrt(t * t + 1.0), sn = t * c;
      // a <- G^T a G with the rotation G in the (p, q) plane.
      for (std::size_t k = 0; k < 3; ++k) {
        const double akp = a[3 * k + p], akq = a[3 * k + q];
        a[3 * k + p] = c * akp - sn * akq;
        a[3 * k + q] = sn * akp + c * akq;
      }
      for (std::size_t k = 0; k < 3; ++k) {
        const double apk = a[3 * p + k], aqk = a[3 * q + k];
        a[3 * p + k] = c * apk - sn * aqk;
        a[3 * q + k] = sn * apk + c * aqk;
      }
    }
  }
  return std::min({a[0], a[4], a[8]});
}
// exp([d]x) by Rodrigues' formula.
M3 rotation_of(const V3& d) {
  const double t2 = model::dot(d, d), t = std::sqrt(t2);
  const double sa = t > 1e-4 ? std::sin(t) / t : 1.0 - t2 / 6.0;
  const double sb = t > 1e-4 ? (1.0 - std::cos(t)) / t2 : 0.5 - t2 / 24.0;
  const M3 w{0, -d[2], d[1], d[2], 0, -d[0], -d[1], d[0], 0};
  const M3 w2 = mul(w, w);
  M3 r = kIdentity;
  for (std::size_t i = 0; i < 9; ++i) r[i] += sa * w[i] + sb * w2[i];
  return r;
}
// The rotation vector of a rotation matrix (angle below pi).
V3 log_of(const M3& r) {
  const V3 v{0.5 * (r[7] - r[5]), 0.5 * (r[2] - r[6]), 0.5 * (r[3] - r[1])};
  const double sn = model::norm(v), cs = 0.5 * (r[0] + r[4] + r[8] - 1.0);
  const double t = std::atan2(sn, cs);
  return model::scale(v, sn > 1e-12 ? t / sn : 1.0 + sn * sn / 6.0);
}
// Rows made orthonormal again (Gram-Schmidt), so round-off does not accumulate over the cycles.
void orthonormalize(M3& r) {
  V3 a{r[0], r[1], r[2]}, b{r[3], r[4], r[5]};
  a = model::scale(a, 1.0 / model::norm(a));
  b = model::sub(b, model::scale(a, model::dot(a, b)));
  b = model::scale(b, 1.0 / model::norm(b));
  const V3 c = model::cross(a, b);
  r = {a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2]};
}

// The segment's nodes about their centroid c (rigid tie k): returns c, fills r.
struct RigidFrame {
  V3 c{};
  std::array<V3, 4> r{};
};

// Least-squares rotation R (R^T K symmetric, K = sum r_j r0_j^T) by Newton's method from R's value.
void fit_rotation(const std::array<V3, 4>& r, const double* r0, int nj, M3& R) {
  M3 k{};
  for (int j = 0; j < nj; ++j) {
    const auto q = static_cast<std::size_t>(j);
    for (std::size_t a = 0; a < 3; ++a)
      for (std::size_t b = 0; b < 3; ++b) k[3 * a + b] += r[q][a] * r0[3 * q + b];
  }
  double scale = 0, size = 0;
  for (const double v : k) scale = std::max(scale, std::abs(v));
  for (int j = 0; j < nj; ++j) {
    const auto q = static_cast<std::size_t>(j);
    size += model::norm(r[q]) * model::norm(V3{r0[3 * q], r0[3 * q + 1], r0[3 * q + 2]});
  }
  for (int it = 0; it < 40; ++it) {
    const M3 g = mul(transpose(R), k);
    const V3 gv{g[7] - g[5], g[2] - g[6], g[3] - g[1]};
    if (model::norm(gv) <= 1e-15 * scale) break;
    // Far from the fit (the segment turned by a large angle since R, or folded) the Newton matrix need not be
    // positive definite and Newton's method could settle on a saddle of tr(R^T K): there a gradient step
    // (an ascent, the objective's curvature being at most sum |r_j| |r0_j|), and never more than half a
    // radian at once.
    const M3 a = trace_minus_sym(g);
    const bool definite =
        a[0] > 0 && a[0] * a[4] - a[1] * a[3] > 0 &&
        model::dot(V3{a[0], a[3], a[6]}, model::cross(V3{a[1], a[4], a[7]}, V3{a[2], a[5], a[8]})) > 0;
    V3 d = definite ? solve(a, gv) : model::scale(gv, 1.0 / size);
    const double nd = model::norm(d);
    if (nd > 0.5) d = model::scale(d, 0.5 / nd);
    R = mul(R, rotation_of(d));
    if (nd < 1e-15) break;
  }
  orthonormalize(R);
}

}  // namespace

TiedInterfaces::TiedInterfaces(const model::Model& m) {
  // Rotational degrees of freedom in the model (OpenRadioss's IRODDL: shells, springs, rigid bodies): without
  // them Spotflag 1 is the standard tie, as in OpenRadioss (intti2f.F).
  const bool rotations = m.shells.size() + m.shells3.size() + m.springs.size() + m.rigid_bodies.size() > 0;
  auto at0 = [&](std::int32_t n) {
    const auto q = static_cast<std::size_t>(n);
    return V3{m.nodes.x[q], m.nodes.y[q], m.nodes.z[q]};
  };
  for (const auto& in : m.tied_interfaces) {
    for (std::size_t k = 0; k < in.tie_node.size(); ++k) {
      const auto& sg = in.tie_segment[k];
      const bool tri = model::is_triangle(sg);
      if (in.spotflag == 1 && rotations) {
        const int nj = tri ? 3 : 4;
        rnode_.push_back(in.tie_node[k]);
        for (const auto n : sg) rseg_.push_back(n);
        rnj_.push_back(static_cast<std::uint8_t>(nj));
        V3 c{};
        for (int j = 0; j < nj; ++j) c = model::add(c, at0(sg[static_cast<std::size_t>(j)]));
        c = model::scale(c, 1.0 / nj);
        M3 p0{};
        for (std::size_t j = 0; j < 4; ++j) {
          const V3 r = static_cast<int>(j) < nj ? model::sub(at0(sg[j]), c) : V3{0, 0, 0};
          r0_.insert(r0_.end(), r.begin(), r.end());
          for (std::size_t a = 0; a < 3; ++a)
            for (std::size_t b = 0; b < 3; ++b) p0[3 * a + b] += r[a] * r[b];
        }
        const V3 q = model::sub(at0(in.tie_node[k]), c);
        q0_.insert(q0_.end(), q.begin(), q.end());
        // The starter's projection refuses degenerate segments: J0 is positive definite.
        inv_lmin_.push_back(1.0 / smallest_eigenvalue(trace_minus_sym(p0)));
        rot_.insert(rot_.end(), kIdentity.begin(), kIdentity.end());
        continue;
      }
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
  for (const auto n : rnode_) held[static_cast<std::size_t>(n)] = 1;
}

std::array<double, 9> TiedInterfaces::rigid_rotation(std::size_t k) const {
  M3 r{};
  std::copy_n(rot_.begin() + static_cast<std::ptrdiff_t>(9 * k), 9, r.begin());
  return r;
}

namespace {

// The segment of rigid tie k about its centroid, at positions `pos(node)`.
template <class Pos>
RigidFrame rigid_frame(const std::int32_t* seg, int nj, Pos pos) {
  RigidFrame f;
  for (int j = 0; j < nj; ++j) f.c = model::add(f.c, pos(static_cast<std::size_t>(seg[j])));
  f.c = model::scale(f.c, 1.0 / nj);
  for (int j = 0; j < nj; ++j)
    f.r[static_cast<std::size_t>(j)] = model::sub(pos(static_cast<std::size_t>(seg[j])), f.c);
  return f;
}

}  // namespace

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
  for (std::size_t k = 0; k < rnode_.size(); ++k) {
    const auto n = static_cast<std::size_t>(rnode_[k]);
    const int nj = rnj_[k];
    const double* r0 = &r0_[12 * k];
    const V3 q0{q0_[3 * k], q0_[3 * k + 1], q0_[3 * k + 2]};
    // Mass and rotational inertia about the centroid to the nodes (I2FOMO3, Spotflag 1).
    const double mr = (s.inertia[n] + s.mass[n] * model::dot(q0, q0)) * inv_lmin_[k];
    V3 vbar{}, mom{};
    M3 p0{};
    for (int jj = 0; jj < nj; ++jj) {
      const auto j = static_cast<std::size_t>(jj);
      const auto mn = static_cast<std::size_t>(rseg_[4 * k + j]);
      s.mass[mn] += s.mass[n] / nj + mr;
      s.added_mass[mn] += mr;
      const V3 v{s.vx[mn], s.vy[mn], s.vz[mn]}, r{r0[3 * j], r0[3 * j + 1], r0[3 * j + 2]};
      vbar = model::add(vbar, model::scale(v, 1.0 / nj));
      mom = model::add(mom, model::cross(r, v));
      for (std::size_t a = 0; a < 3; ++a)
        for (std::size_t b = 0; b < 3; ++b) p0[3 * a + b] += r[a] * r[b];
    }
    s.mass[n] = 0;
    s.inertia[n] = 0;
    // The secondary starts with the velocity of its place (its own /INIVEL is replaced) and the segment's
    // rate of rotation: w = J0^-1 sum r0_j x v_j, v_s = vbar + w x q0.
    const V3 w = solve(trace_minus_sym(p0), mom);
    const V3 vs = model::add(vbar, model::cross(w, q0));
    s.vx[n] = vs[0];
    s.vy[n] = vs[1];
    s.vz[n] = vs[2];
    s.wx[n] = w[0];
    s.wy[n] = w[1];
    s.wz[n] = w[2];
  }
}

void TiedInterfaces::transfer_forces(NodeState& s) {
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
  auto xn = [&](std::size_t q) { return at(s, q); };
  for (std::size_t k = 0; k < rnode_.size(); ++k) {
    const auto n = static_cast<std::size_t>(rnode_[k]);
    const int nj = rnj_[k];
    const RigidFrame fr = rigid_frame(&rseg_[4 * k], nj, xn);
    M3 R = rigid_rotation(k);
    fit_rotation(fr.r, &r0_[12 * k], nj, R);
    std::copy(R.begin(), R.end(), rot_.begin() + static_cast<std::ptrdiff_t>(9 * k));
    // A = tr P I - P, P = K R^T = sum_j r_j q_j^T; a = A^-1 (m_s + (x_s - c) x f_s).
    std::array<V3, 4> q{};
    M3 p{};
    for (int jj = 0; jj < nj; ++jj) {
      const auto j = static_cast<std::size_t>(jj);
      q[j] = mul(R, V3{r0_[12 * k + 3 * j], r0_[12 * k + 3 * j + 1], r0_[12 * k + 3 * j + 2]});
      for (std::size_t a = 0; a < 3; ++a)
        for (std::size_t b = 0; b < 3; ++b) p[3 * a + b] += fr.r[j][a] * q[j][b];
    }
    const V3 f{s.fx[n], s.fy[n], s.fz[n]};
    const V3 mom = model::add(V3{s.mx[n], s.my[n], s.mz[n]}, model::cross(model::sub(at(s, n), fr.c), f));
    const V3 a = solve(trace_minus_sym(p), mom);
    for (int jj = 0; jj < nj; ++jj) {
      const auto j = static_cast<std::size_t>(jj);
      const auto m = static_cast<std::size_t>(rseg_[4 * k + j]);
      const V3 fj = model::add(model::scale(f, 1.0 / nj), model::cross(a, q[j]));
      s.fx[m] += fj[0];
      s.fy[m] += fj[1];
      s.fz[m] += fj[2];
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
  for (std::size_t k = 0; k < rnode_.size(); ++k) {
    const auto n = static_cast<std::size_t>(rnode_[k]);
    const int nj = rnj_[k];
    const double q2 =
        q0_[3 * k] * q0_[3 * k] + q0_[3 * k + 1] * q0_[3 * k + 1] + q0_[3 * k + 2] * q0_[3 * k + 2];
    const double kj = s.stiffness[n] * (1.0 / nj + q2 * inv_lmin_[k]);
    for (int j = 0; j < nj; ++j)
      s.stiffness[static_cast<std::size_t>(rseg_[4 * k + static_cast<std::size_t>(j)])] += kj;
    s.stiffness[n] = 1e-20;
  }
}

void TiedInterfaces::secondary_kinematics(NodeState& s, double dt1, double dt2) {
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
  auto x1 = [&](std::size_t m) {
    return V3{s.x[m] + dt2 * (s.vx[m] + dt12 * s.ax[m]), s.y[m] + dt2 * (s.vy[m] + dt12 * s.ay[m]),
              s.z[m] + dt2 * (s.vz[m] + dt12 * s.az[m])};
  };
  for (std::size_t k = 0; k < rnode_.size(); ++k) {
    const auto n = static_cast<std::size_t>(rnode_[k]);
    const int nj = rnj_[k];
    const RigidFrame fr = rigid_frame(&rseg_[4 * k], nj, x1);
    const M3 r_old = rigid_rotation(k);
    M3 R = r_old;
    fit_rotation(fr.r, &r0_[12 * k], nj, R);
    std::copy(R.begin(), R.end(), rot_.begin() + static_cast<std::ptrdiff_t>(9 * k));
    const V3 target = model::add(fr.c, mul(R, V3{q0_[3 * k], q0_[3 * k + 1], q0_[3 * k + 2]}));
    s.ax[n] = ((target[0] - s.x[n]) * inv2 - s.vx[n]) * inv12;
    s.ay[n] = ((target[1] - s.y[n]) * inv2 - s.vy[n]) * inv12;
    s.az[n] = ((target[2] - s.z[n]) * inv2 - s.vz[n]) * inv12;
    const V3 w = model::scale(log_of(mul(R, transpose(r_old))), inv2);
    s.awx[n] = (w[0] - s.wx[n]) * inv12;
    s.awy[n] = (w[1] - s.wy[n]) * inv12;
    s.awz[n] = (w[2] - s.wz[n]) * inv12;
  }
}

}  // namespace radx::solver
