// TYPE7 starter computations (docs/theory/type7-lagdt.md):
//
// Gap, 4.1. Igap 0: g = Gapmin, with Gapmin = min(t, l/10, lmin/2) when the input is 0 (t the mean
//   thickness of the main shells, l the mean side of the main bricks, lmin the shortest side of all
//   main segments; a term with no element behind it is left out).
//   Igap 1: g = max(Gapmin, gs + gm); Igap 2: g = max(Gapmin, min(Fscalegap (gs + gm), Gapmax)),
//   Gapmax = 0 meaning no cap. gm = t/2 of the main shell (0 for a brick face); gs = t/2 of the
//   thickest shell at the secondary node, sqrt(A)/2 for a truss or beam of cross-section A (the largest of
//   these; 0 for bricks only or no element).
// Stiffness, 4.2. Main segment on a shell: Km = Stfac 0.5 E t; on a brick: Km = Stfac B S^2 / V.
//   Secondary node on a shell: Ks = Stfac 0.5 E t; on a brick: Ks = Stfac B V^(1/3).
//   A tetrahedron counts as a solid as a brick does (Radioss keeps it as a degenerate brick): its face gives
//   Km = Stfac B S^2 / V with its own volume, its nodes Ks = Stfac B V^(1/3), and its 6 edges join the mean
//   side l of the main solids.
//   [inferred: the formulas are the brick's applied to the tetrahedron's volume and face]
//   Istf 0: K = Km; 1: K = Stfac; 2..5: K = clamp(Kn, Stmin, Stmax) with Kn = (Km + Ks)/2,
//   max(Km, Ks), min(Km, Ks), Km Ks / (Km + Ks).
// Initial penetrations, 4.6: a secondary node closer than g to a main segment (p = g - d > 0) is
//   treated by Inacti: 0 nothing, 1 node without stiffness, 2 segment without stiffness, 3 node moved
//   out to the gap surface, 5 gap reduced to g - P0, 6 gap reduced to (g - P0) - 0.05 (g - P0).
//
// The search for pairs is a uniform bucket grid: segments are binned by their box enlarged by the
// largest gap, nodes look up their own cell, so the cost is linear in nodes plus segments.
#include "contact/type7_prepare.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "solver/model/geometry.hpp"
#include "solver/model/hex20_shape.hpp"
#include "solver/model/masses.hpp"

namespace radx::contact {

using model::kNone;
using model::Vec3;

double closest_point_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, Vec3& w) {
  // Voronoi-region walk over vertices, edges and the face (Ericson, Real-Time Collision Detection 5.1.5).
  const Vec3 ab = model::sub(b, a), ac = model::sub(c, a), ap = model::sub(p, a);
  const double d1 = model::dot(ab, ap), d2 = model::dot(ac, ap);
  auto finish = [&](double wa, double wb, double wc) {
    w = {wa, wb, wc};
    const Vec3 q{wa * a[0] + wb * b[0] + wc * c[0], wa * a[1] + wb * b[1] + wc * c[1],
                 wa * a[2] + wb * b[2] + wc * c[2]};
    const Vec3 d = model::sub(p, q);
    return model::dot(d, d);
  };
  if (d1 <= 0 && d2 <= 0) return finish(1, 0, 0);
  const Vec3 bp = model::sub(p, b);
  const double d3 = model::dot(ab, bp), d4 = model::dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return finish(0, 1, 0);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double v = d1 / (d1 - d3);
    return finish(1 - v, v, 0);
  }
  const Vec3 cp = model::sub(p, c);
  const double d5 = model::dot(ab, cp), d6 = model::dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return finish(0, 0, 1);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double t = d2 / (d2 - d6);
    return finish(1 - t, 0, t);
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return finish(0, 1 - t, t);
  }
  const double denom = va + vb + vc;
  if (denom == 0) return finish(1, 0, 0);  // degenerate triangle: fall back to a vertex
  const double v = vb / denom, t = vc / denom;
  return finish(1 - v - t, v, t);
}

double closest_point_segment(const Vec3& p, const std::array<Vec3, 4>& x, bool triangle,
                             std::array<double, 4>& h) {
  Vec3 w{};
  if (triangle) {
    const double d2 = closest_point_triangle(p, x[0], x[1], x[2], w);
    h = {w[0], w[1], w[2], 0.0};
    return std::sqrt(d2);
  }
  const Vec3 c = model::scale(model::add(model::add(x[0], x[1]), model::add(x[2], x[3])), 0.25);
  double best = std::numeric_limits<double>::max();
  for (int k = 0; k < 4; ++k) {
    const int k1 = (k + 1) % 4;
    const double d2 = closest_point_triangle(p, x[k], x[k1], c, w);
    if (d2 < best) {
      best = d2;
      h = {0.25 * w[2], 0.25 * w[2], 0.25 * w[2], 0.25 * w[2]};
      h[k] += w[0];
      h[k1] += w[1];
    }
  }
  return std::sqrt(best);
}

double shell_element_thickness(const model::Model& m, model::ElementType type, std::int32_t e) {
  return model::shell_thickness(m, type == model::ElementType::Shell3 ? m.shells3 : m.shells,
                                static_cast<std::size_t>(e));
}

double shell_contact_thickness(const model::Model& m, model::ElementType type, std::int32_t e) {
  const auto& b = type == model::ElementType::Shell3 ? m.shells3 : m.shells;
  const auto part = b.part[e];
  if (part != kNone && m.parts[part].contact_thickness > 0) return m.parts[part].contact_thickness;
  return shell_element_thickness(m, type, e);
}

double pair_stiffness(const model::Interface& in, double km, double ks) {
  double kn = km;
  switch (in.istf) {
    case 0: return km;
    case 1: return in.stfac;
    case 2: kn = 0.5 * (km + ks); break;
    case 3: kn = std::max(km, ks); break;
    case 4: kn = std::min(km, ks); break;
    case 5: kn = (km + ks) > 0 ? km * ks / (km + ks) : 0.0; break;
    default: break;
  }
  return std::clamp(kn, in.stmin, in.stmax);
}

double pair_gap(const model::Interface& in, double gs, double gm) {
  switch (in.igap) {
    case 1: return std::max(in.gapmin, gs + gm);
    case 2: {
      double g = in.fscale_gap * (gs + gm);
      if (in.gap_max > 0) g = std::min(g, in.gap_max);
      return std::max(in.gapmin, g);
    }
    default: return in.gapmin;
  }
}

namespace {

struct ElementProps {
  double young = 0, bulk = 0;
};

ElementProps material_of(const model::Model& m, std::int32_t part) {
  if (part == kNone || m.parts[part].material == kNone) return {};
  const auto& mat = m.materials[m.parts[part].material];
  return {mat.young, mat.bulk};
}

Vec3 node_x(const model::Model& m, std::int32_t n) {
  return {m.nodes.x[n], m.nodes.y[n], m.nodes.z[n]};
}

std::array<Vec3, 8> brick_x(const model::Model& m, std::int32_t e) {
  std::array<Vec3, 8> x{};
  for (int k = 0; k < 8; ++k) x[k] = node_x(m, m.bricks.conn[8 * static_cast<std::size_t>(e) + k]);
  return x;
}

// Mean edge length of a brick (12 edges).
double brick_mean_side(const std::array<Vec3, 8>& x) {
  static constexpr int edges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                       {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  double s = 0;
  for (const auto& e : edges) s += model::norm(model::sub(x[e[1]], x[e[0]]));
  return s / 12.0;
}

std::array<Vec3, 4> tetra_x(const model::Model& m, std::int32_t e) {
  std::array<Vec3, 4> x{};
  for (int k = 0; k < 4; ++k) x[k] = node_x(m, m.tetras.conn[4 * static_cast<std::size_t>(e) + k]);
  return x;
}

// Mean edge length of a tetrahedron (6 edges).
double tetra_mean_side(const std::array<Vec3, 4>& x) {
  double s = 0;
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b) s += model::norm(model::sub(x[b], x[a]));
  return s / 6.0;
}

// Per-node properties of the elements around each node: thickest shell or truss (contact thickness), and the
// largest shell (or truss) and brick stiffness terms.
struct NodeSupport {
  std::vector<double> half_thickness;  // gs
  std::vector<double> k_shell;         // 0.5 E t (max over shells), E A / L (trusses)
  std::vector<double> k_brick;         // B V^(1/3) (max over bricks)
};

// A truss's or beam's nodes (`stride` slots an element): the largest half section size and axial stiffness.
void support_of_line_elements(const model::Model& m, const model::ElementBlock& b, std::size_t stride,
                              NodeSupport& s) {
  for (std::size_t e = 0; e < b.size(); ++e) {
    const auto part = b.part[e];
    if (part < 0) continue;
    const auto& p = m.parts[static_cast<std::size_t>(part)];
    if (p.property < 0 || p.material < 0) continue;
    const auto& prop = m.properties[static_cast<std::size_t>(p.property)];
    const double area = prop.kind == model::PropertyKind::Beam ? prop.beam.area : prop.truss.area;
    const double half = p.contact_thickness > 0 ? 0.5 * p.contact_thickness : 0.5 * std::sqrt(area);
    const auto n1 = b.conn[stride * e], n2 = b.conn[stride * e + 1];
    if (n1 < 0 || n2 < 0) continue;
    const double l = model::norm(model::sub(node_x(m, n2), node_x(m, n1)));
    const double k = l > 0 ? material_of(m, part).young * area / l : 0.0;
    for (const auto node : {n1, n2}) {
      s.half_thickness[node] = std::max(s.half_thickness[node], half);
      s.k_shell[node] = std::max(s.k_shell[node], k);
    }
  }
}

NodeSupport node_support(const model::Model& m) {
  NodeSupport s;
  const auto n = m.nodes.size();
  s.half_thickness.assign(n, 0.0);
  s.k_shell.assign(n, 0.0);
  s.k_brick.assign(n, 0.0);
  for (auto type : {model::ElementType::Shell4, model::ElementType::Shell3}) {
    const auto& b = type == model::ElementType::Shell3 ? m.shells3 : m.shells;
    const auto npe = static_cast<std::size_t>(b.npe());
    for (std::size_t e = 0; e < b.size(); ++e) {
      const auto ei = static_cast<std::int32_t>(e);
      const double tc = shell_contact_thickness(m, type, ei);
      const double k = 0.5 * material_of(m, b.part[e]).young * shell_element_thickness(m, type, ei);
      for (std::size_t j = 0; j < npe; ++j) {
        const auto node = b.conn[e * npe + j];
        if (node < 0) continue;
        s.half_thickness[node] = std::max(s.half_thickness[node], 0.5 * tc);
        s.k_shell[node] = std::max(s.k_shell[node], k);
      }
    }
  }
  for (std::size_t e = 0; e < m.bricks.size(); ++e) {
    const auto x = brick_x(m, static_cast<std::int32_t>(e));
    const double v = std::max(0.0, model::brick_volume(x));
    const double k = material_of(m, m.bricks.part[e]).bulk * std::cbrt(v);
    for (int j = 0; j < 8; ++j) {
      const auto node = m.bricks.conn[8 * e + j];
      if (node >= 0) s.k_brick[node] = std::max(s.k_brick[node], k);
    }
  }
  // Trusses and beams: gs = sqrt(A)/2 for the cross-section A (or half the /PART contact thickness when
  // given), and the axial stiffness E A / L as the node's stiffness term.
  // [inferred: Ks = E A / L, the nodal stiffness Radioss's starter gives a truss node (tmass.F)]
  support_of_line_elements(m, m.trusses, 2, s);
  support_of_line_elements(m, m.beams, 3, s);
  for (std::size_t e = 0; e < m.tetras.size(); ++e) {
    const auto x = tetra_x(m, static_cast<std::int32_t>(e));
    const double v = std::max(0.0, model::tetra_volume(x[0], x[1], x[2], x[3]));
    const double k = material_of(m, m.tetras.part[e]).bulk * std::cbrt(v);
    for (int j = 0; j < 4; ++j) {
      const auto node = m.tetras.conn[4 * e + j];
      if (node >= 0) s.k_brick[node] = std::max(s.k_brick[node], k);
    }
  }
  // 20-node bricks give their nodes (secondary nodes of a contact; they have no main faces) the same solid
  // term, K V^(1/3) with V by the starter's 3 x 3 x 3 rule.
  for (std::size_t e = 0; e < m.bricks20.size(); ++e) {
    double x[20][3];
    for (int j = 0; j < 20; ++j) {
      const auto p = node_x(m, m.bricks20.conn[20 * e + static_cast<std::size_t>(j)]);
      for (int d = 0; d < 3; ++d) x[j][d] = p[static_cast<std::size_t>(d)];
    }
    const double v = std::max(0.0, model::hex20_volume(x, model::hex20_starter_rule()));
    const double k = material_of(m, m.bricks20.part[e]).bulk * std::cbrt(v);
    for (int j = 0; j < 20; ++j) {
      const auto node = m.bricks20.conn[20 * e + static_cast<std::size_t>(j)];
      if (node >= 0) s.k_brick[node] = std::max(s.k_brick[node], k);
    }
  }
  return s;
}

std::array<Vec3, 4> segment_x(const model::Model& m, const std::array<std::int32_t, 4>& seg) {
  return {node_x(m, seg[0]), node_x(m, seg[1]), node_x(m, seg[2]), node_x(m, seg[3])};
}

// Gap and stiffness of one interface.
void gap_and_stiffness(model::Model& m, model::Interface& in, const NodeSupport& support) {
  const auto& surf = m.surfaces[in.main_surface];
  const auto ns = surf.segments.size();
  in.gap_segment.assign(ns, 0.0);
  in.stiff_segment.assign(ns, 0.0);
  double t_sum = 0, l_sum = 0, lmin = std::numeric_limits<double>::max();
  int t_count = 0, l_count = 0;
  for (std::size_t s = 0; s < ns; ++s) {
    const auto& seg = surf.segments[s];
    const auto x = segment_x(m, seg);
    const bool tri = seg[2] == seg[3];
    const int sides = tri ? 3 : 4;
    for (int k = 0; k < sides; ++k) lmin = std::min(lmin, model::norm(model::sub(x[(k + 1) % sides], x[k])));
    const double area =
        tri ? model::triangle_area(x[0], x[1], x[2]) : model::quad_area(x[0], x[1], x[2], x[3]);
    const auto owner = surf.owner[s];
    switch (surf.owner_type[s]) {
      case model::SegmentOwner::Shell4:
      case model::SegmentOwner::Shell3: {
        const auto type = surf.owner_type[s] == model::SegmentOwner::Shell3 ? model::ElementType::Shell3
                                                                            : model::ElementType::Shell4;
        const auto& b = type == model::ElementType::Shell3 ? m.shells3 : m.shells;
        const double t = shell_element_thickness(m, type, owner);
        t_sum += t;
        ++t_count;
        in.gap_segment[s] = 0.5 * shell_contact_thickness(m, type, owner);
        in.stiff_segment[s] = in.stfac * 0.5 * material_of(m, b.part[owner]).young * t;
        break;
      }
      case model::SegmentOwner::Brick8: {
        const auto bx = brick_x(m, owner);
        l_sum += brick_mean_side(bx);
        ++l_count;
        const double v = model::brick_volume(bx);
        in.stiff_segment[s] =
            v > 0 ? in.stfac * material_of(m, m.bricks.part[owner]).bulk * area * area / v : 0.0;
        break;
      }
      case model::SegmentOwner::Tetra4: {
        const auto tx = tetra_x(m, owner);
        l_sum += tetra_mean_side(tx);
        ++l_count;
        const double v = model::tetra_volume(tx[0], tx[1], tx[2], tx[3]);
        in.stiff_segment[s] =
            v > 0 ? in.stfac * material_of(m, m.tetras.part[owner]).bulk * area * area / v : 0.0;
        break;
      }
      case model::SegmentOwner::None: break;
    }
  }
  in.gapmin_automatic = in.gapmin_input == 0;
  if (in.gapmin_automatic) {
    double g = ns > 0 ? 0.5 * lmin : 0.0;
    if (t_count > 0) g = std::min(g, t_sum / t_count);
    if (l_count > 0) g = std::min(g, 0.1 * l_sum / l_count);
    in.gapmin = g;
  } else {
    in.gapmin = in.gapmin_input;
  }
  const auto nn = in.secondary_nodes.size();
  in.gap_node.assign(nn, 0.0);
  in.stiff_node.assign(nn, 0.0);
  for (std::size_t k = 0; k < nn; ++k) {
    const auto node = in.secondary_nodes[k];
    in.gap_node[k] = support.half_thickness[node];
    in.stiff_node[k] = in.stfac * std::max(support.k_shell[node], support.k_brick[node]);
  }
  // Ranges: every combination rule is monotone in both arguments, so the extremes of the pair values
  // are reached at the extremes of the node and segment values.
  auto range = [](const std::vector<double>& v) {
    if (v.empty()) return std::pair{0.0, 0.0};
    const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
    return std::pair{*lo, *hi};
  };
  const auto [gs_lo, gs_hi] = range(in.gap_node);
  const auto [gm_lo, gm_hi] = range(in.gap_segment);
  in.gap_lo = pair_gap(in, gs_lo, gm_lo);
  in.gap_hi = pair_gap(in, gs_hi, gm_hi);
  const auto [ks_lo, ks_hi] = range(in.stiff_node);
  const auto [km_lo, km_hi] = range(in.stiff_segment);
  in.stiff_lo = pair_stiffness(in, km_lo, ks_lo);
  in.stiff_hi = pair_stiffness(in, km_hi, ks_hi);
}

// Uniform bucket grid over segment boxes enlarged by `reach`.
class SegmentGrid {
 public:
  SegmentGrid(const model::Model& m, const model::Surface& surf, double reach) {
    const auto ns = surf.segments.size();
    if (ns == 0) return;
    lo_ = {1e300, 1e300, 1e300};
    Vec3 hi{-1e300, -1e300, -1e300};
    double size_sum = 0;
    std::vector<std::array<Vec3, 2>> boxes(ns);
    for (std::size_t s = 0; s < ns; ++s) {
      const auto x = segment_x(m, surf.segments[s]);
      Vec3 a = x[0], b = x[0];
      for (const auto& p : x)
        for (int d = 0; d < 3; ++d) {
          a[d] = std::min(a[d], p[d]);
          b[d] = std::max(b[d], p[d]);
        }
      size_sum += std::max({b[0] - a[0], b[1] - a[1], b[2] - a[2]});
      for (int d = 0; d < 3; ++d) {
        a[d] -= reach;
        b[d] += reach;
        lo_[d] = std::min(lo_[d], a[d]);
        hi[d] = std::max(hi[d], b[d]);
      }
      boxes[s] = {a, b};
    }
    cell_ = std::max(size_sum / static_cast<double>(ns) + 2 * reach, 1e-30);
    for (int d = 0; d < 3; ++d)
      dims_[d] =
          std::clamp<std::int64_t>(static_cast<std::int64_t>((hi[d] - lo_[d]) / cell_) + 1, 1, 1 << 20);
    for (std::size_t s = 0; s < ns; ++s) {
      const auto i0 = cell_of(boxes[s][0]), i1 = cell_of(boxes[s][1]);
      for (auto i = i0[0]; i <= i1[0]; ++i)
        for (auto j = i0[1]; j <= i1[1]; ++j)
          for (auto k = i0[2]; k <= i1[2]; ++k)
            entries_.push_back({key(i, j, k), static_cast<std::int32_t>(s)});
    }
    std::sort(entries_.begin(), entries_.end());
  }

  template <class F>
  void for_candidates(const Vec3& p, F&& f) const {
    if (entries_.empty()) return;
    for (int d = 0; d < 3; ++d)
      if (p[d] < lo_[d] || p[d] > lo_[d] + cell_ * static_cast<double>(dims_[d])) return;
    const auto c = cell_of(p);
    const auto k = key(c[0], c[1], c[2]);
    auto it =
        std::lower_bound(entries_.begin(), entries_.end(), std::pair<std::int64_t, std::int32_t>{k, -1});
    for (; it != entries_.end() && it->first == k; ++it) f(it->second);
  }

 private:
  std::array<std::int64_t, 3> cell_of(const Vec3& p) const {
    std::array<std::int64_t, 3> c{};
    for (int d = 0; d < 3; ++d)
      c[d] = std::clamp<std::int64_t>(static_cast<std::int64_t>((p[d] - lo_[d]) / cell_), 0, dims_[d] - 1);
    return c;
  }
  std::int64_t key(std::int64_t i, std::int64_t j, std::int64_t k) const {
    return (i * dims_[1] + j) * dims_[2] + k;
  }

  Vec3 lo_{};
  double cell_ = 1;
  std::array<std::int64_t, 3> dims_{1, 1, 1};
  std::vector<std::pair<std::int64_t, std::int32_t>> entries_;
};

void initial_penetrations(model::Model& m, model::Interface& in) {
  const auto& surf = m.surfaces[in.main_surface];
  if (surf.segments.empty() || in.secondary_nodes.empty()) return;
  const double reach = std::max(in.gap_hi, in.gapmin);
  const SegmentGrid grid(m, surf, reach);
  std::vector<std::uint8_t> segment_off(surf.segments.size(), 0);
  for (std::size_t k = 0; k < in.secondary_nodes.size(); ++k) {
    const auto node = in.secondary_nodes[k];
    const Vec3 p = node_x(m, node);
    double worst = 0;
    std::int32_t worst_seg = kNone;
    Vec3 worst_dir{};
    double worst_gap = 0;
    grid.for_candidates(p, [&](std::int32_t s) {
      const auto& seg = surf.segments[s];
      if (seg[0] == node || seg[1] == node || seg[2] == node || seg[3] == node) return;  // own segment
      const auto x = segment_x(m, seg);
      std::array<double, 4> h{};
      const double d = closest_point_segment(p, x, seg[2] == seg[3], h);
      const double g = pair_gap(in, in.gap_node[k], in.gap_segment[s]);
      const double pen = g - d;
      if (pen > worst) {
        worst = pen;
        worst_seg = s;
        worst_gap = g;
        Vec3 q{};
        for (int j = 0; j < 4; ++j)
          for (int c = 0; c < 3; ++c) q[c] += h[j] * x[j][c];
        worst_dir = model::sub(p, q);
        if (d < 1e-300) {
          const auto nrm = model::quad_normal(x[0], x[1], x[2], x[3]);
          worst_dir = nrm;
        }
      }
    });
    if (worst_seg == kNone) continue;
    ++in.initial_penetrations;
    if (worst > in.max_initial_penetration) {
      in.max_initial_penetration = worst;
      in.max_penetration_node = m.nodes.id[node];
    }
    switch (in.inacti) {
      case 1: in.inactive_nodes.push_back(node); break;
      case 2: segment_off[worst_seg] = 1; break;
      case 3: {
        const double len = model::norm(worst_dir);
        if (len > 0) {
          const double s = worst / len;
          m.nodes.x[node] += s * worst_dir[0];
          m.nodes.y[node] += s * worst_dir[1];
          m.nodes.z[node] += s * worst_dir[2];
        }
        break;
      }
      case 5:
      case 6: {
        const double open = worst_gap - worst;  // gap - P0
        in.penetrating_nodes.push_back(node);
        in.initial_gap_reduction.push_back(in.inacti == 5 ? worst : worst + 0.05 * open);
        break;
      }
      default: break;
    }
  }
  for (std::size_t s = 0; s < segment_off.size(); ++s)
    if (segment_off[s]) in.inactive_segments.push_back(static_cast<std::int32_t>(s));
}

// Compacts the first `count` nodes of a face or an element to its distinct ones (a degenerate element repeats
// a node), in order, the rest set to -1; returns their count.
int distinct_nodes(std::array<std::int32_t, 4>& n, int count) {
  int d = 0;
  for (int k = 0; k < count; ++k) {
    if (n[k] < 0) continue;
    bool seen = false;
    for (int j = 0; j < d; ++j) seen = seen || n[j] == n[k];
    if (!seen) n[d++] = n[k];
  }
  for (int k = d; k < 4; ++k) n[k] = -1;
  return d;
}

// Area of a polygon of 3 or 4 distinct nodes.
double polygon_area(const model::Model& m, const std::array<std::int32_t, 4>& n, int count) {
  if (count == 3) return model::triangle_area(node_x(m, n[0]), node_x(m, n[1]), node_x(m, n[2]));
  if (count == 4) return model::quad_area(node_x(m, n[0]), node_x(m, n[1]), node_x(m, n[2]), node_x(m, n[3]));
  return 0.0;
}

}  // namespace

std::vector<double> tributary_areas(const model::Model& m, std::span<const std::int32_t> nodes,
                                    std::span<const std::uint8_t> alive) {
  // The surface patches: each live shell, and each face that exactly one live brick has.
  struct Patch {
    std::array<std::int32_t, 4> n;
    int count;
    double area;
  };
  std::vector<Patch> patches;
  auto is_alive = [&](std::size_t cell) { return alive.empty() || alive[cell] != 0; };
  auto add_patch = [&](std::array<std::int32_t, 4> n, int count) {
    const int d = distinct_nodes(n, count);
    if (d >= 3) patches.push_back({n, d, polygon_area(m, n, d)});
  };
  std::size_t cell = 0;
  for (const auto* b : {&m.shells, &m.shells3}) {
    const int npe = b->npe();
    for (std::size_t e = 0; e < b->size(); ++e, ++cell) {
      if (!is_alive(cell)) continue;
      std::array<std::int32_t, 4> n{-1, -1, -1, -1};
      for (int k = 0; k < npe; ++k) n[k] = b->conn[e * static_cast<std::size_t>(npe) + k];
      add_patch(n, npe);
    }
  }
  std::vector<std::pair<std::array<std::int32_t, 4>, std::array<std::int32_t, 4>>> faces;  // key, nodes
  faces.reserve(6 * m.bricks.size());
  for (std::size_t e = 0; e < m.bricks.size(); ++e, ++cell) {
    if (!is_alive(cell)) continue;
    const auto* c = &m.bricks.conn[8 * e];
    std::vector<std::array<std::int32_t, 4>> own;
    for (const auto& f : model::kBrickFaces) {
      std::array<std::int32_t, 4> n{c[f[0]], c[f[1]], c[f[2]], c[f[3]]};
      const int d = distinct_nodes(n, 4);
      if (d < 3) continue;
      std::array<std::int32_t, 4> key{-1, -1, -1, -1};
      std::copy(n.begin(), n.begin() + d, key.begin());
      for (int a = 1; a < d; ++a)  // insertion sort of 3 or 4 ids
        for (int b = a; b > 0 && key[b - 1] > key[b]; --b) std::swap(key[b - 1], key[b]);
      if (std::find(own.begin(), own.end(), key) != own.end()) continue;  // a brick counts a face once
      own.push_back(key);
      faces.push_back({key, n});
    }
  }
  // Tetrahedron faces join the same pool: a face shared by two solids (brick or tetrahedron) is inner.
  for (std::size_t e = 0; e < m.tetras.size(); ++e, ++cell) {
    if (!is_alive(cell)) continue;
    const auto* c = &m.tetras.conn[4 * e];
    for (const auto& f : model::kTetraFaces) {
      std::array<std::int32_t, 4> n{c[f[0]], c[f[1]], c[f[2]], -1};
      std::array<std::int32_t, 4> key{n[0], n[1], n[2], -1};
      std::sort(key.begin(), key.begin() + 3);
      faces.push_back({key, n});
    }
  }
  std::sort(faces.begin(), faces.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t j = i + 1;
    while (j < faces.size() && faces[j].first == faces[i].first) ++j;
    if (j == i + 1) add_patch(faces[i].second, 4);
    i = j;
  }
  // A patch belongs to the contact surface when all its nodes are among `nodes`; a node that has no such
  // patch takes every patch around it.
  std::vector<std::int32_t> slot(m.nodes.size(), -1);
  for (std::size_t k = 0; k < nodes.size(); ++k)
    slot[static_cast<std::size_t>(nodes[k])] = static_cast<std::int32_t>(k);
  std::vector<double> on_surface(nodes.size(), 0.0), around(nodes.size(), 0.0);
  for (const auto& p : patches) {
    bool inside = true;
    for (int k = 0; k < p.count; ++k) inside = inside && slot[static_cast<std::size_t>(p.n[k])] >= 0;
    for (int k = 0; k < p.count; ++k) {
      const auto s = slot[static_cast<std::size_t>(p.n[k])];
      if (s < 0) continue;
      around[static_cast<std::size_t>(s)] += p.area / p.count;
      if (inside) on_surface[static_cast<std::size_t>(s)] += p.area / p.count;
    }
  }
  for (std::size_t k = 0; k < nodes.size(); ++k)
    if (!(on_surface[k] > 0)) on_surface[k] = around[k];
  return on_surface;
}

PeLawStiffness pe_law_initial_stiffness_max(const model::Interface& in) {
  const auto& law = in.law;
  if (in.contact_law_id == 0 || law.normal != model::NormalLaw::Exponential || !(law.pe > 0)) return {};
  const double a_min = in.tributary_area_range().first;
  if (a_min == 0) return {};
  return {law.pz * (in.stiff_hi / a_min) / law.pe, in.stiff_hi, a_min};
}

void prepare_type7_interfaces(model::Model& m) {
  if (m.interfaces.empty()) return;
  const NodeSupport support = node_support(m);
  for (auto& in : m.interfaces) in.tributary_area = tributary_areas(m, in.secondary_nodes);
  for (auto& in : m.interfaces) {
    if (in.main_surface == kNone) continue;
    gap_and_stiffness(m, in, support);
    initial_penetrations(m, in);
  }
}

}  // namespace radx::contact
