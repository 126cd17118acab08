// Result fields: see result_fields.hpp for the definition of every field. Shell frames are rebuilt from
// the current coordinates with the element's own construction (shell_bt4.cpp [1.2] for quads,
// shell_c0_tri3.cpp [2] for triangles) so the rotated stress is the one the kernel holds.
#include "solver/outputs/result_fields.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <type_traits>

#include "solver/elements/shell/shell_section.hpp"
#include "solver/model/geometry.hpp"

namespace radx::solver {

namespace {

using model::Vec3;

struct CellFieldInfo {
  CellField field;
  std::string_view name;
  int components;
  Dim dim;
};
struct NodeFieldInfo {
  NodeField field;
  std::string_view name;
  int components;
  Dim dim;
};

constexpr Dim kStress{1, -1, -2};  // also energy per volume
constexpr Dim kNone{0, 0, 0};
constexpr Dim kLength{0, 1, 0};
constexpr Dim kForce{1, 1, -2};

// Names match parser's anim_field_names() output names (a test keeps the two in step).
// The shell layer fields are not /ANIM names: the engine adds them beside von_mises and stress.
constexpr std::array<CellFieldInfo, 14> kCellFields = {{
    {CellField::VonMises, "von_mises", 1, kStress},
    {CellField::PlasticStrain, "plastic_strain", 1, kNone},
    {CellField::Thickness, "thickness", 1, kLength},
    {CellField::InternalEnergyDensity, "internal_energy_density", 1, kStress},
    {CellField::Pressure, "pressure", 1, kStress},
    {CellField::Density, "density", 1, {1, -3, 0}},
    {CellField::HourglassEnergyDensity, "hourglass_energy_density", 1, kStress},
    {CellField::Stress, "stress", 6, kStress},
    {CellField::VonMisesBottom, "von_mises_bottom", 1, kStress},
    {CellField::VonMisesMiddle, "von_mises_middle", 1, kStress},
    {CellField::VonMisesTop, "von_mises_top", 1, kStress},
    {CellField::StressBottom, "stress_bottom", 6, kStress},
    {CellField::StressMiddle, "stress_middle", 6, kStress},
    {CellField::StressTop, "stress_top", 6, kStress},
}};
constexpr std::array<NodeFieldInfo, 9> kNodeFields = {{
    {NodeField::Displacement, "displacement", 3, kLength},
    {NodeField::Velocity, "velocity", 3, {0, 1, -1}},
    {NodeField::Acceleration, "acceleration", 3, {0, 1, -2}},
    {NodeField::ContactForce, "contact_force", 3, kForce},
    {NodeField::InternalForce, "internal_force", 3, kForce},
    {NodeField::ExternalForce, "external_force", 3, kForce},
    {NodeField::ReactionForce, "reaction_force", 3, kForce},
    {NodeField::AddedMass, "added_mass", 1, {1, 0, 0}},
    {NodeField::NodalTimeStep, "nodal_time_step", 1, {0, 0, 1}},
}};

// The stress state of one cell in global axes, with what the scalar fields need.
struct CellValues {
  std::array<double, 6> sig{};                   // xx yy zz xy yz zx
  std::array<std::array<double, 6>, 3> layer{};  // the same at the bottom, middle, top (ShellLayer order)
  double eps_p = 0, thickness = 0, volume0 = 0, e_int = 0, e_hg = 0, density = 0;
};

double von_mises(const std::array<double, 6>& s) {
  const double a = s[0] - s[1], b = s[1] - s[2], c = s[2] - s[0];
  return std::sqrt(0.5 * (a * a + b * b + c * c) + 3.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
}

// Local plane stress (sxx syy sxy syz szx in frame e1 e2 e3) to global: sigma = R s R^T with R = [e1 e2 e3].
std::array<double, 6> to_global(const double loc[5], const Vec3& e1, const Vec3& e2, const Vec3& e3) {
  const double s[3][3] = {{loc[0], loc[2], loc[4]}, {loc[2], loc[1], loc[3]}, {loc[4], loc[3], 0.0}};
  const Vec3 R[3] = {e1, e2, e3};  // R[k] is local axis k
  auto comp = [&](int i, int j) {
    double v = 0;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        v += R[a][static_cast<std::size_t>(i)] * s[a][b] * R[b][static_cast<std::size_t>(j)];
    return v;
  };
  return {comp(0, 0), comp(1, 1), comp(2, 2), comp(0, 1), comp(1, 2), comp(2, 0)};
}

Vec3 unit(const Vec3& v) {
  const double n = model::norm(v);
  return n > 0 ? model::scale(v, 1.0 / n) : v;
}

// Element frame of a shell from its current nodes.
void shell_frame(const ShellGroup& g, int i, const NodeState& s, Vec3& e1, Vec3& e2, Vec3& e3) {
  auto X = [&](int k) {
    const auto n = static_cast<std::size_t>(g.conn[static_cast<std::size_t>(k * kGroupSize + i)]);
    return Vec3{s.x[n], s.y[n], s.z[n]};
  };
  if (g.triangle) {
    const Vec3 x1 = X(0), x2 = X(1), x3 = X(2);
    e1 = unit(model::sub(x2, x1));
    e3 = unit(model::cross(model::sub(x3, x1), model::sub(x3, x2)));
    e2 = model::cross(e3, e1);
    return;
  }
  const Vec3 x1 = X(0), x2 = X(1), x3 = X(2), x4 = X(3);
  const Vec3 g1 = model::add(model::sub(x2, x1), model::sub(x3, x4));
  const Vec3 g2 = model::add(model::sub(x3, x2), model::sub(x4, x1));
  e3 = unit(model::cross(g1, g2));
  const double n1 = model::norm(g1), n2 = model::norm(g2);
  e1 = unit(model::add(g1, model::scale(model::cross(g2, e3), n2 > 0 ? n1 / n2 : 0.0)));
  e2 = model::cross(e3, e1);
}

// Calls body(gi) for every group index gi < n, 16 groups to a chunk, on the engine's threads (idle while a
// state is written).
template <class Body>
void each_group_parallel(const ExplicitEngine& e, std::int64_t n, Body&& body) {
  const auto chunks = Chunks::of(n, 16);
  e.team().run(chunks.count(), [&](std::int64_t c) {
    for (std::int64_t gi = chunks.begin(c); gi < chunks.end(c); ++gi) body(gi);
  });
}

// The rows of one in-plane Gauss point of a shell group's sig: [5 n_points][G], or [8][G] for N = 0.
std::size_t shell_sig_rows(const ShellGroup& g) {
  const int np = g.props.n_points;
  return static_cast<std::size_t>(np <= 0 ? 8 : 5 * np) * kGroupSize;
}

// Element i of a shell group: the through-thickness mean stress in global axes, the largest eps_p of its
// points, its thickness. QBAT keeps one state per in-plane Gauss point ([gauss][...]): the element's value is
// their mean (the Gauss points have nearly equal weights), and its eps_p the largest.
CellValues cell_values(const ShellGroup& g, int i, const NodeState& s,
                       const std::vector<MaterialParams>& mats) {
  const int np = g.props.n_points;
  const auto rule = shell_detail::thickness_rule(np > 0 ? np : 0);
  const auto k = static_cast<std::size_t>(i);
  CellValues c;
  double loc[5] = {0, 0, 0, 0, 0};
  const std::size_t rows = static_cast<std::size_t>(np <= 0 ? 8 : 5 * np) * kGroupSize;
  const std::size_t eps_rows = static_cast<std::size_t>(np <= 0 ? 1 : np) * kGroupSize;
  const double per_point = 1.0 / g.gauss;
  for (int gp = 0; gp < g.gauss; ++gp) {
    const double* sig = g.sig.data() + static_cast<std::size_t>(gp) * rows;
    const double* eps = g.eps_p.data() + static_cast<std::size_t>(gp) * eps_rows;
    if (np <= 0) {  // resultant elasticity: the first 5 rows are the mean stresses
      for (int q = 0; q < 5; ++q) loc[q] += per_point * sig[static_cast<std::size_t>(q) * kGroupSize + k];
    } else {
      for (int p = 0; p < np; ++p) {
        for (int q = 0; q < 5; ++q) loc[q] += per_point * rule.w[p] * sig[shell_detail::sig_index(p, q, i)];
        c.eps_p = std::max(c.eps_p, eps[static_cast<std::size_t>(p) * kGroupSize + k]);
      }
    }
  }
  Vec3 e1, e2, e3;
  shell_frame(g, i, s, e1, e2, e3);
  c.sig = to_global(loc, e1, e2, e3);
  for (const ShellLayer l : {ShellLayer::Bottom, ShellLayer::Middle, ShellLayer::Top})
    c.layer[static_cast<std::size_t>(l)] = to_global(shell_layer_stress(g, i, l).data(), e1, e2, e3);
  c.thickness = g.thick[k] > 0 ? g.thick[k] : g.t0[k];
  c.volume0 = g.area0[k] * g.t0[k];
  c.e_int = g.e_int[k];
  c.e_hg = g.e_hg[k];
  c.density = mats[static_cast<std::size_t>(g.material)].rho0;
  return c;
}

// Element i of a brick, tetrahedron or 20-node brick group (e_hg stays 0 but for the 8-node bricks).
template <class Solid>
CellValues cell_values(const Solid& g, int i, const NodeState&, const std::vector<MaterialParams>&) {
  const auto k = static_cast<std::size_t>(i);
  CellValues c;
  if constexpr (std::is_same_v<Solid, BrickGroup>) {
    brick_global_stress(g, k, c.sig.data());
  } else {
    for (int q = 0; q < 6; ++q)
      c.sig[static_cast<std::size_t>(q)] = g.sig[static_cast<std::size_t>(q) * kGroupSize + k];
  }
  c.layer = {c.sig, c.sig, c.sig};
  c.eps_p = g.eps_p[k];
  c.volume0 = g.vol0[k];
  c.e_int = g.e_int[k];
  c.e_hg = g.e_hg[k];
  c.density = g.rho[k];
  return c;
}

// Element i of a truss or beam group: the uniaxial stress sigma e (x) e along its current line in global
// axes (a truss's stress, a beam's mean axial stress N / A: the section's forces and moments are in
// /TH/BEAM), so that von Mises is |sigma| and the pressure -sigma/3; the volume A0 L0 for the energy
// density.
template <class LineGroup>
requires(std::is_same_v<LineGroup, TrussGroup> || std::is_same_v<LineGroup, BeamGroup>) CellValues
    cell_values(const LineGroup& g, int i, const NodeState& s, const std::vector<MaterialParams>& mats) {
  const auto k = static_cast<std::size_t>(i);
  const auto n1 = static_cast<std::size_t>(g.conn[k]), n2 = static_cast<std::size_t>(g.conn[kGroupSize + k]);
  const Vec3 e = unit(Vec3{s.x[n2] - s.x[n1], s.y[n2] - s.y[n1], s.z[n2] - s.z[n1]});
  CellValues c;
  const double sigma = g.sig[k];
  c.sig = {sigma * e[0] * e[0], sigma * e[1] * e[1], sigma * e[2] * e[2],
           sigma * e[0] * e[1], sigma * e[1] * e[2], sigma * e[2] * e[0]};
  c.layer = {c.sig, c.sig, c.sig};
  c.eps_p = g.eps_p[k];
  if constexpr (std::is_same_v<LineGroup, TrussGroup>)
    c.volume0 = g.area0[k] * g.l0[k];
  else
    c.volume0 = g.section.area * g.l0[k];
  c.e_int = g.e_int[k];
  c.density = mats[static_cast<std::size_t>(g.material)].rho0;
  return c;
}

// Calls fn(cell index, CellValues) for every element of the model with a material (springs have none of
// these fields). Groups write disjoint cells: the engine's threads, idle while a state is written, share the
// groups.
template <class Fn>
void for_each_cell(const ExplicitEngine& e, Fn&& fn) {
  const auto& m = e.model();
  each_group_parallel(e, e.groups().count(), [&](std::int64_t gi) {
    e.groups().visit(gi, [&](const auto& g) {
      if constexpr (kHasMaterial<std::decay_t<decltype(g)>>) {
        for (int i = 0; i < g.count; ++i)
          fn(first_cell(m, g) + static_cast<std::size_t>(g.element[static_cast<std::size_t>(i)]),
             cell_values(g, i, e.nodes(), e.materials()));
      }
    });
  });
}

}  // namespace

std::string_view field_name(CellField f) {
  for (const auto& i : kCellFields)
    if (i.field == f) return i.name;
  return {};
}
std::string_view field_name(NodeField f) {
  for (const auto& i : kNodeFields)
    if (i.field == f) return i.name;
  return {};
}
std::optional<CellField> cell_field_named(std::string_view name) {
  for (const auto& i : kCellFields)
    if (i.name == name) return i.field;
  return std::nullopt;
}
std::optional<NodeField> node_field_named(std::string_view name) {
  for (const auto& i : kNodeFields)
    if (i.name == name) return i.field;
  return std::nullopt;
}
int components(CellField f) {
  for (const auto& i : kCellFields)
    if (i.field == f) return i.components;
  return 1;
}
int components(NodeField f) {
  for (const auto& i : kNodeFields)
    if (i.field == f) return i.components;
  return 1;
}
Dim field_dim(CellField f) {
  for (const auto& i : kCellFields)
    if (i.field == f) return i.dim;
  return {};
}
Dim field_dim(NodeField f) {
  for (const auto& i : kNodeFields)
    if (i.field == f) return i.dim;
  return {};
}

std::array<double, 5> shell_point_stress(const ShellGroup& g, int i, int point) {
  std::array<double, 5> loc{};
  const std::size_t rows = shell_sig_rows(g);
  const double per_point = 1.0 / g.gauss;
  for (int gp = 0; gp < g.gauss; ++gp) {
    const double* sig = g.sig.data() + static_cast<std::size_t>(gp) * rows;
    for (int q = 0; q < 5; ++q)
      loc[static_cast<std::size_t>(q)] += per_point * sig[shell_detail::sig_index(point, q, i)];
  }
  return loc;
}

std::array<double, 5> shell_layer_stress(const ShellGroup& g, int i, ShellLayer layer) {
  const int np = g.props.n_points;
  if (np <= 0) {  // resultants: FOR + 12 zeta MOM for the in-plane rows, FOR for the transverse shear
    const double zeta = layer == ShellLayer::Bottom ? -0.5 : layer == ShellLayer::Top ? 0.5 : 0.0;
    const std::size_t rows = shell_sig_rows(g);
    const auto k = static_cast<std::size_t>(i);
    std::array<double, 5> loc{};
    const double per_point = 1.0 / g.gauss;
    for (int gp = 0; gp < g.gauss; ++gp) {
      const double* sig = g.sig.data() + static_cast<std::size_t>(gp) * rows;
      const auto row = [&](int r) { return sig[static_cast<std::size_t>(r) * kGroupSize + k]; };
      for (int q = 0; q < 5; ++q) loc[static_cast<std::size_t>(q)] += per_point * row(q);
      for (int q = 0; q < 3; ++q) loc[static_cast<std::size_t>(q)] += per_point * 12.0 * zeta * row(5 + q);
    }
    return loc;
  }
  if (layer == ShellLayer::Bottom) return shell_point_stress(g, i, 0);
  if (layer == ShellLayer::Top) return shell_point_stress(g, i, np - 1);
  if (np % 2 == 1) return shell_point_stress(g, i, np / 2);
  const auto below = shell_point_stress(g, i, np / 2 - 1), above = shell_point_stress(g, i, np / 2);
  std::array<double, 5> mid{};
  for (std::size_t q = 0; q < 5; ++q) mid[q] = 0.5 * (below[q] + above[q]);
  return mid;
}

int shell_points_max(const ExplicitEngine& e) {
  int n = 0;
  for (const auto& g : e.groups().shells) n = std::max(n, g.props.n_points);
  return n;
}

void gather_shell_point_stress(const ExplicitEngine& e, int point, std::span<float> out) {
  std::fill(out.begin(), out.end(), 0.0f);
  const auto& m = e.model();
  const auto& shells = e.groups().shells;
  each_group_parallel(e, static_cast<std::int64_t>(shells.size()), [&](std::int64_t gi) {
    const ShellGroup& g = shells[static_cast<std::size_t>(gi)];
    if (point >= g.props.n_points) return;
    for (int i = 0; i < g.count; ++i) {
      Vec3 e1, e2, e3;
      shell_frame(g, i, e.nodes(), e1, e2, e3);
      const auto sig = to_global(shell_point_stress(g, i, point).data(), e1, e2, e3);
      float* o = out.data() +
                 6 * (first_cell(m, g) + static_cast<std::size_t>(g.element[static_cast<std::size_t>(i)]));
      for (std::size_t q = 0; q < 6; ++q) o[q] = static_cast<float>(sig[q]);
    }
  });
}

void gather_cell_field(const ExplicitEngine& e, CellField f, std::span<float> out) {
  std::fill(out.begin(), out.end(), 0.0f);
  const auto k = static_cast<std::size_t>(components(f));
  for_each_cell(e, [&](std::size_t cell, const CellValues& c) {
    float* o = out.data() + cell * k;
    const double per_volume = c.volume0 > 0 ? 1.0 / c.volume0 : 0.0;
    switch (f) {
      case CellField::VonMises: o[0] = static_cast<float>(von_mises(c.sig)); break;
      case CellField::PlasticStrain: o[0] = static_cast<float>(c.eps_p); break;
      case CellField::Thickness: o[0] = static_cast<float>(c.thickness); break;
      case CellField::InternalEnergyDensity: o[0] = static_cast<float>(c.e_int * per_volume); break;
      case CellField::Pressure: o[0] = static_cast<float>(-(c.sig[0] + c.sig[1] + c.sig[2]) / 3.0); break;
      case CellField::Density: o[0] = static_cast<float>(c.density); break;
      case CellField::HourglassEnergyDensity: o[0] = static_cast<float>(c.e_hg * per_volume); break;
      case CellField::Stress:
        for (std::size_t q = 0; q < 6; ++q) o[q] = static_cast<float>(c.sig[q]);
        break;
      case CellField::VonMisesBottom: o[0] = static_cast<float>(von_mises(c.layer[0])); break;
      case CellField::VonMisesMiddle: o[0] = static_cast<float>(von_mises(c.layer[1])); break;
      case CellField::VonMisesTop: o[0] = static_cast<float>(von_mises(c.layer[2])); break;
      case CellField::StressBottom:
      case CellField::StressMiddle:
      case CellField::StressTop: {
        const auto l = static_cast<std::size_t>(f) - static_cast<std::size_t>(CellField::StressBottom);
        for (std::size_t q = 0; q < 6; ++q) o[q] = static_cast<float>(c.layer[l][q]);
        break;
      }
    }
  });
}

void gather_node_field(const ExplicitEngine& e, NodeField f, double dt1, std::span<float> out) {
  const auto& s = e.nodes();
  std::fill(out.begin(), out.end(), 0.0f);
  auto put3 = [&](std::size_t n, double x, double y, double z) {
    out[3 * n] = static_cast<float>(x);
    out[3 * n + 1] = static_cast<float>(y);
    out[3 * n + 2] = static_cast<float>(z);
  };
  if (f == NodeField::NodalTimeStep) {
    // The elements' stiffness without the springs' (the engine's nodal step adds theirs).
    std::vector<double> k(s.n, 0.0);
    e.groups().for_each([&](const auto& g) {
      if constexpr (kHasMaterial<std::decay_t<decltype(g)>>) add_nodal_stiffness(g, k);
    });
    for (std::size_t n = 0; n < s.n; ++n)
      out[n] = k[n] > 0 ? static_cast<float>(std::sqrt(2.0 * s.mass[n] / k[n])) : 0.0f;
    return;
  }
  for (std::size_t n = 0; n < s.n; ++n) {
    switch (f) {
      case NodeField::Displacement: put3(n, s.x[n] - s.x0[n], s.y[n] - s.y0[n], s.z[n] - s.z0[n]); break;
      case NodeField::Velocity:
        put3(n, s.vx[n] + 0.5 * dt1 * s.ax[n], s.vy[n] + 0.5 * dt1 * s.ay[n], s.vz[n] + 0.5 * dt1 * s.az[n]);
        break;
      case NodeField::Acceleration: put3(n, s.ax[n], s.ay[n], s.az[n]); break;
      case NodeField::ContactForce: break;  // filled below from the contact buffer
      case NodeField::InternalForce:
        put3(n, s.fx_ext[n] - s.fx[n], s.fy_ext[n] - s.fy[n], s.fz_ext[n] - s.fz[n]);
        break;
      case NodeField::ExternalForce: put3(n, s.fx_ext[n], s.fy_ext[n], s.fz_ext[n]); break;
      case NodeField::ReactionForce:
        put3(n, s.mass[n] * s.ax[n] - s.fx[n], s.mass[n] * s.ay[n] - s.fy[n], s.mass[n] * s.az[n] - s.fz[n]);
        break;
      case NodeField::AddedMass: out[n] = static_cast<float>(s.added_mass[n]); break;
      case NodeField::NodalTimeStep: break;
    }
  }
  if (e.contact() != nullptr && (f == NodeField::ContactForce || f == NodeField::InternalForce)) {
    // f holds the contact forces too: the contact field is the contact buffer, and the internal force
    // f_ext - f gets them back.
    const auto& fc = e.contact()->force();
    for (const auto n : e.contact()->touched()) {
      const auto k = static_cast<std::size_t>(n);
      if (f == NodeField::ContactForce) {
        put3(k, fc[3 * k], fc[3 * k + 1], fc[3 * k + 2]);
      } else {
        put3(k, s.fx_ext[k] - s.fx[k] + fc[3 * k], s.fy_ext[k] - s.fy[k] + fc[3 * k + 1],
             s.fz_ext[k] - s.fz[k] + fc[3 * k + 2]);
      }
    }
  }
}

void gather_element_status(const ExplicitEngine& e, std::span<std::uint8_t> out) {
  const auto& m = e.model();
  std::fill(out.begin(), out.end(), std::uint8_t{1});
  e.groups().for_each([&](const auto& g) {
    for (int i = 0; i < g.count; ++i)
      if (g.off[static_cast<std::size_t>(i)] <= 0)
        out[first_cell(m, g) + static_cast<std::size_t>(g.element[static_cast<std::size_t>(i)])] = 0;
  });
}

void gather_points(const ExplicitEngine& e, std::span<double> out) {
  const auto& s = e.nodes();
  for (std::size_t n = 0; n < s.n; ++n) {
    out[3 * n] = s.x[n];
    out[3 * n + 1] = s.y[n];
    out[3 * n + 2] = s.z[n];
  }
}

}  // namespace radx::solver
