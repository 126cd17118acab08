// Element groups: up to kGroupSize elements of one type, material and property, structure of arrays
// with the element index innermost (array[k * kGroupSize + i]). The unit of vectorisation and of
// threading. Kernels gather nodal values through `conn`, compute, and write their nodal forces into
// the group's own `nodal_force` buffer; the engine then adds each buffer to the nodes' sums group by group in
// a fixed order (solver/engine/ordered_commit.hpp), so results do not depend on the number of threads.
#pragma once

#include <array>
#include <cstdint>
#include <memory_resource>
#include <optional>
#include <span>
#include <type_traits>
#include <vector>

#include "solver/elements/spring/spring_law.hpp"
#include "solver/engine/node_state.hpp"
#include "solver/materials/material_point.hpp"
#include "solver/model/geometry.hpp"

namespace radx::solver {

inline constexpr int kGroupSize = 128;

// A group's per-element array. Groups are small (128 elements, some 200 KB) and many (20,800 at 2.66 M
// elements): each array on its own from the heap would sit on 4 KB pages, so the engine carves them out of
// one arena on huge pages (HugePageResource under a monotonic buffer), which also keeps a group's arrays
// together in memory. A group built without an arena (tests, tools) uses the heap.
template <class T>
using GroupArray = std::pmr::vector<T>;

// Values of the cycle the kernels need.
struct CycleInfo {
  double dt1 = 0;  // previous step t^n - t^{n-1}: the step of the strain increments
  double dt2 = 0;  // current estimate of the next step (for predictions; kernels mostly use dt1)
  double time = 0;
};

// The fields every group kind has: what the engine's stages (the sums, the step votes, deleted elements,
// energies) and the outputs read without knowing the kind. Each kind adds its own state and says the layout
// of `conn` and `nodal_force`.
struct GroupCore {
  // Where the arrays below live: the engine's arena (ExplicitEngine::group_arena_), or the heap by default.
  std::pmr::memory_resource* arena = std::pmr::get_default_resource();
  GroupCore() = default;
  explicit GroupCore(std::pmr::memory_resource* r) : arena(r) {}
  int count = 0;                            // elements in this group
  GroupArray<std::int32_t> element{arena};  // [G] index of each slot's element in its model block
  std::int32_t part = -1;                   // dense part index (all elements of a group share it)
  GroupArray<std::int32_t> conn{arena};     // [nodes per element][G] dense node indices
  GroupArray<double> off{arena};            // [G] 1 alive, decaying after failure, 0 deleted
  GroupArray<double> e_int{arena};          // [G] accumulated internal energy (work of the element forces)
  GroupArray<double> dt{arena};             // [G] stable step of the cycle, before the /DT scale
  GroupArray<double> k_nodal{arena};        // [G] nodal stiffness contribution of each node (nodal steps)
  // [nodes per element][components][G] force (and moment) ADDED to each node, global axes (internal forces
  // enter with their minus sign)
  GroupArray<double> nodal_force{arena};
};

// The fields of the groups whose elements have a material at their integration points (shells, bricks,
// tetrahedra): the stress and plastic state (laid out per kind), the energies the material dissipates and the
// filtered strain rate.
struct MaterialGroupCore : GroupCore {
  using GroupCore::GroupCore;
  std::int32_t material = -1;           // index into the engine's MaterialParams
  GroupArray<double> sig{arena};        // stresses, layout per kind
  GroupArray<double> eps_p{arena};      // plastic strain per point
  GroupArray<double> dmg{arena};        // failure damage D / Dcrit per point (0 .. 1; 1: the point failed)
  GroupArray<double> e_hg{arena};       // [G] accumulated hourglass energy
  GroupArray<double> w_plastic{arena};  // [G] accumulated plastic work
  GroupArray<double> rate{arena};       // [G] filtered equivalent strain rate (Johnson-Cook, law 36)
};

struct ShellProps {
  int ishell = 1, ismstr = 2, ithick = 0, iplas = 0;  // internal meaning: ithick 1 = update, iplas 1 = Newton
  int ish3n = 2;     // 3-node shells: 2 with the in-plane large-rotation terms T11, T22; 1 without
  int n_points = 3;  // through-thickness points, >= 1; 0 = resultant elasticity (LAW1 only)
  double hm = 0.01, hf = 0.01, hr = 0.01, dm = 0, ashear = 5.0 / 6.0;
  // QEPH numerical damping of the stabilisation (docs/theory/elements.md 1.10; 0.015 by default)
  double dn = 0;
  double p_thick_fail = 0.999999;  // /FAIL Ifail_sh 2: failed thickness fraction that deletes the element
};

// The shell kernel a group runs: one enum value per formulation, one switch in the engine.
enum class ShellKernel : std::uint8_t {
  Bt4,   // Ishell 1 (shell_bt4.cpp)
  Tri3,  // 3-node C0 (shell_c0_tri3.cpp)
  Qeph,  // Ishell 24 (shell_qeph.cpp)
  Qbat,  // Ishell 12 (shell_qbat.cpp)
};

// Shells: conn [4][G] (triangles: row 3 unused), nodal_force [4][6][G] forces and moments.
struct ShellGroup : MaterialGroupCore {
  using MaterialGroupCore::MaterialGroupCore;
  bool triangle = false;  // 3-node C0 shells (conn rows 0..2)
  ShellKernel kernel = ShellKernel::Bt4;
  int gauss = 1;  // in-plane integration points: 4 for QBAT (each with n_points)
  ShellProps props;
  GroupArray<double> t0{arena};     // [G] thickness used by the mechanics
  GroupArray<double> thick{arena};  // [G] current thickness (output; mechanics when ithick = 1)
  GroupArray<double> area0{arena};  // [G] initial area
  // sig [gauss][n_points][5][G] sxx syy sxy syz szx, local frame; eps_p and dmg [gauss][n_points][G]
  // [gauss][8][G] FOR xx yy xy yz zx and MOM xx yy xy of `sig` (N >= 1: sums over the points, raw, as
  // shell_section.hpp takes them), kept from the last cycle as the next cycle's old resultants. Zero with a
  // zero sig; whatever writes sig outside the section update must write them too.
  GroupArray<double> res{arena};
  // /FAIL/BIQUAD S_Flag 3: the points' instability damage, the rows of dmg ([gauss][n_points][G]).
  GroupArray<double> dmg_inst{arena};
  GroupArray<double> fail_scale{
      arena};                      // [G] /FAIL/TAB element-size factor of eps_f (1 otherwise; set at t = 0)
  GroupArray<double> brit{arena};  // law 27 only: [gauss][n_points][kBritVars][G] crack state (allocate_brit)
  GroupArray<double> hg{arena};    // [3][G] elastic hourglass resultants Sx Sy Sz (Ishell 1);
                                   // QEPH: [4][6][G] stabilisation resultants at the 4 Gauss points
                                   // (shell_qeph.cpp)
  GroupArray<double> dt_fixed{
      arena};  // [G] engine: constant step after a /DT/SHELL|SH_3N/CST switch (0: none)
  // Small strain after that switch: 1.0 once the element's local geometry is frozen in ref_local
  // (quads: x2 x3 x4 y2 y3 y4; triangles: x2 x3 y3 and 0), so its B matrix, area and step stay constant.
  GroupArray<double> small{arena};      // [G] 0 or 1
  GroupArray<double> ref_local{arena};  // [6][G]
  [[nodiscard]] int nodes_per_element() const { return triangle ? 3 : 4; }
  // n elements, `points` through the thickness (0: resultants), `gauss_points` in the plane, `hg_rows` rows
  // of hourglass state.
  void allocate(int n, int points, int gauss_points = 1, int hg_rows = 3);
  void allocate_brit();  // law 27's crack state, after allocate: no strain, crack frame (1, 0), no damage
};

// Bricks: conn [8][G], nodal_force [8][3][G]; sig [6][G] xx yy zz xy yz zx (global axes, or the element
// frame of a co-rotational group), eps_p and dmg (/FAIL/JOHNSON) [G]; e_int includes the bulk viscosity work.
struct BrickGroup : MaterialGroupCore {
  using MaterialGroupCore::MaterialGroupCore;
  int isolid = 1;
  // /DT/BRICK/CST switches a brick to small strain only with Ismstr 2 (docs/theory/deck-format.md)
  int ismstr = 4;
  int iframe = 1;  // 1 Jaumann rate, global stress; 2 co-rotational element frame, stress in that frame
  // Icpre: Isolid 24: 0 compressible hourglass modes, 1 incompressible; fully integrated bricks (resolved by
  // resolve_full_brick): 0 pressure per point, 1 and 2 constant pressure over the element.
  int icpre = 0;
  double qa = 1.1, qb = 0.05, h = 0.1;
  double dn = 0.1;  // Isolid 24: viscous part of the physical hourglass
  // Fully integrated bricks (Isolid 12, 14, 17, 18: hex8_full.cpp), set by the engine from the property.
  int n_points = 1;    // 1: one-point kernel (hex8_fb.cpp); 8: 2x2x2 Gauss points (hex8_full.cpp)
  bool corot = false;  // co-rotational frame (stress kept in it) instead of the Jaumann rate
  // Strain operator of the points (hex8_full.cpp): Plain, the assumed-strain element of Isolid 14 (Asqbi), or
  // the averaged shear and Poisson terms of Isolid 18 (SelectShear); `coupled` adds the normal-strain terms.
  enum class FullStrain : std::uint8_t { Plain, Asqbi, SelectShear };
  FullStrain strain = FullStrain::Plain;
  bool coupled = false;
  bool dt_points = false;  // element length min_p 8 V_p / A_mid (S8Z, S8E) instead of V / max face area
  bool s8e_visc = false;   // Isolid 18 with LAW1: S8E's viscous hourglass damping (s8evis3.F), work in e_hg
  GroupArray<double> sig_p{
      arena};  // [8][6][G] point stresses (co-rotational frame when corot), 8 points only
  GroupArray<double> eps_p_p{arena};   // [8][G] point plastic strains
  GroupArray<double> dmg_p{arena};     // [8][G] point /FAIL/JOHNSON damage
  GroupArray<double> vol0_p{arena};    // [8][G] initial point volumes det J_p
  GroupArray<double> vol0{arena};      // [G] initial (one-point) volume
  GroupArray<double> vol{arena};       // [G] current volume
  GroupArray<double> rho{arena};       // [G] current density rho0 V0 / V
  GroupArray<double> q{arena};         // [G] bulk viscosity pressure of the last cycle
  GroupArray<double> hg_force{arena};  // [4][3][G] hourglass forces H_j of the last cycle (energy trapezoid)
  GroupArray<double> dt_fixed{arena};  // [G] engine: constant step after a /DT/BRICK/CST switch (0: none)
  // Small strain after that switch: 1 once the node coordinates are frozen in x_ref; the gradients, volume
  // and step then come from x_ref (Radioss's small-strain switch), the velocities stay current.
  GroupArray<std::uint8_t> small{arena};  // [G]
  GroupArray<double> x_ref{arena};        // [8][3][G]
  // Co-rotational frame (Iframe 2, Isolid 24): columns e_x e_y e_z of the element frame of the last cycle,
  // [3 * column + row][G]; `sig` is then in that frame (global = R sig R^T). Identity until the first cycle.
  GroupArray<double> frame{arena};  // [9][G]
  GroupArray<double> hg_stress{
      arena};                      // [3][4][G] Isolid 24: hourglass stresses per direction and mode (local)
  GroupArray<double> w_hg{arena};  // [G] Isolid 24: hourglass work, a part of e_int (diagnostic only)
  // Laws of total strain (law 42, hex8_fb.cpp): the centre gradients B_k = dN_k/dX(0) of the initial geometry
  // (global axes), k = 1..4 (B_{5..8} = -B_{3,4,1,2}), [3 * k + d][G], from which the kernel forms the total
  // deformation gradient F = sum_k x_k (x) B_k. Empty for the other laws.
  GroupArray<double> b_ref{arena};
  // Law 70 (law70_foam_tab.cpp): the point state, kFoamVars rows [v][G]. Empty for the other laws.
  GroupArray<double> foam{arena};
  [[nodiscard]] static constexpr int nodes_per_element() { return 8; }
  void allocate(int n);
  void allocate_points();  // the point arrays of a fully integrated group (n_points = 8)
  // b_ref of element i from its initial node coordinates x0[8][3].
  void set_reference(std::size_t i, const double x0[8][3]);
};

// True when the group's stress lives in the co-rotational element frame (Iframe 2; Isolid 24 forces it).
// Fully integrated groups keep their own frames per point and store the mean stress in global axes.
inline bool brick_corotational(const BrickGroup& g) {
  return g.n_points == 1 && (g.iframe == 2 || g.isolid == 24);
}

// Element i's stress in global axes (xx yy zz xy yz zx): `sig` itself, or R sig R^T for a co-rotational
// group.
inline void brick_global_stress(const BrickGroup& g, std::size_t i, double out[6]) {
  constexpr std::size_t G = kGroupSize;
  const double s[6] = {g.sig[0 * G + i], g.sig[1 * G + i], g.sig[2 * G + i],
                       g.sig[3 * G + i], g.sig[4 * G + i], g.sig[5 * G + i]};
  if (!brick_corotational(g)) {
    for (int m = 0; m < 6; ++m) out[m] = s[m];
    return;
  }
  const double S[3][3] = {{s[0], s[3], s[5]}, {s[3], s[1], s[4]}, {s[5], s[4], s[2]}};
  double R[3][3];
  for (std::size_t c = 0; c < 3; ++c)
    for (std::size_t r = 0; r < 3; ++r) R[r][c] = g.frame[(3 * c + r) * G + i];
  auto at = [&](int a, int b) {
    double v = 0.0;
    for (int p = 0; p < 3; ++p)
      for (int q = 0; q < 3; ++q) v += R[a][p] * S[p][q] * R[b][q];
    return v;
  };
  out[0] = at(0, 0);
  out[1] = at(1, 1);
  out[2] = at(2, 2);
  out[3] = at(0, 1);
  out[4] = at(1, 2);
  out[5] = at(2, 0);
}

// 4-node tetrahedra (/TETRA4, Itetra4 1000): one point, constant strain, no hourglass (e_hg stays 0). The
// same state as a brick less what only hourglass control and the small-strain switch need: conn [4][G],
// nodal_force [4][3][G], sig [6][G] in global axes.
struct TetraGroup : MaterialGroupCore {
  using MaterialGroupCore::MaterialGroupCore;
  double qa = 1.1, qb = 0.05;
  GroupArray<double> vol0{arena};  // [G] initial volume
  GroupArray<double> vol{arena};   // [G] current volume
  GroupArray<double> rho{arena};   // [G] current density rho0 V0 / V
  GroupArray<double> q{arena};     // [G] bulk viscosity pressure of the last cycle
  [[nodiscard]] static constexpr int nodes_per_element() { return 4; }
  void allocate(int n);
};

// 20-node quadratic bricks (/BRIC20, hex20_quadratic.cpp): a product Gauss rule of n[0] x n[1] x n[2]
// points (2 or 3 along each natural direction), per-point state, no hourglass (e_hg stays 0). conn [20][G],
// nodal_force [20][3][G]; sig [6][G] the volume-weighted mean point stress (global axes), eps_p [G] the
// points' mean plastic strain, dmg [G] their largest damage.
struct Hex20Group : MaterialGroupCore {
  using MaterialGroupCore::MaterialGroupCore;
  double qa = 1.1, qb = 0.05;
  std::array<int, 3> rule{2, 2, 2};  // Gauss points along xi, eta, zeta (model::Hex20Rule::n)
  [[nodiscard]] int n_points() const { return rule[0] * rule[1] * rule[2]; }
  GroupArray<double> sig_p{arena};    // [np][6][G] point stresses, global axes (Jaumann rate)
  GroupArray<double> eps_p_p{arena};  // [np][G] point plastic strains
  GroupArray<double> dmg_p{arena};    // [np][G] point failure damage
  GroupArray<double> vol0_p{arena};   // [np][G] initial point volumes w_p det J_p
  GroupArray<double> vol0{arena};     // [G] initial volume sum_p vol0_p
  GroupArray<double> vol{arena};      // [G] current volume
  GroupArray<double> rho{arena};      // [G] current density rho0 V0 / V
  GroupArray<double> q{arena};        // [G] bulk viscosity pressure of the last cycle
  [[nodiscard]] static constexpr int nodes_per_element() { return 20; }
  void allocate(int n);  // after `rule` is set
};

// Springs (/SPRING): one part, so one property, per group. TYPE4 (/PROP/SPRING, spring_type4.cpp): one axial
// law, state in the first G slots of dx, force, the law state and forces [2][3][G]. TYPE8 (/PROP/SPR_GENE,
// spring_type8.cpp) and TYPE13 (/PROP/SPR_BEAM, spring_type13.cpp): six laws X Y Z RX RY RZ, state [6][G]
// and forces and moments [2][6][G]; TYPE13 also carries its moving frame's Y axis. The curves point into the
// model's functions (the engine keeps the model alive). conn [2][G] n1 n2; e_int is the work of the spring
// forces (elastic and damping); off 0 once broken (delta_min, delta_max).
struct SpringGroup : GroupCore {
  using GroupCore::GroupCore;
  model::SpringProperty props;
  std::array<SpringLawCurves, 6> curves{};                 // each law's curves (TYPE4: [0])
  std::array<double, 9> frame{1, 0, 0, 0, 1, 0, 0, 0, 1};  // TYPE8: rows = the axes X Y Z, global components
  GroupArray<double> l0{arena};                            // [G] initial length
  GroupArray<double> x0{arena};                            // [3][G] TYPE8: initial x2 - x1 in the frame
  GroupArray<double> ey{arena};     // [3][G] TYPE13: the frame's Y axis of the last cycle (global components)
  GroupArray<double> dx{arena};     // [6][G] elongation (rotation) of the last cycle (> 0 in tension)
  GroupArray<double> force{arena};  // [6][G] force (moment) of the last cycle (> 0 in tension)
  // [6][G] each law's SpringLawState (spring_law.hpp): the static force before amplification, the plastic
  // elongations (or extremes of the elongation), the yield force and the plastic travel.
  GroupArray<double> f_static{arena}, plastic{arena}, plastic_c{arena}, yield{arena}, travel{arena};
  // nodal_force: [2][3][G] (TYPE4) or [2][6][G] (TYPE8, 13), forces and moments
  [[nodiscard]] int node_stride() const { return props.type == 4 ? 3 : 6; }
  [[nodiscard]] static constexpr int nodes_per_element() { return 2; }
  // The law state of slot j = dof * G + i, gathered from and scattered to the arrays above.
  [[nodiscard]] SpringLawState law_state(std::size_t j) const {
    return {f_static[j], plastic[j], plastic_c[j], yield[j], travel[j]};
  }
  void store(std::size_t j, const SpringLawState& s) {
    f_static[j] = s.f_static;
    plastic[j] = s.plastic;
    plastic_c[j] = s.plastic_c;
    yield[j] = s.yield;
    travel[j] = s.travel;
  }
  void allocate(int n);
};

// Trusses (/TRUSS, truss_axial.cpp): one part per group, laws 1 and 2. conn [2][G] n1 n2, nodal_force
// [2][3][G]; sig [G] the axial stress N / A, eps_p [G] the plastic strain (law 2); dmg, e_hg and rate stay 0.
struct TrussGroup : MaterialGroupCore {
  using MaterialGroupCore::MaterialGroupCore;
  GroupArray<double> area0{arena};   // [G] initial cross-section (the property's)
  GroupArray<double> area{arena};    // [G] current cross-section (follows the strain through nu)
  GroupArray<double> l0{arena};      // [G] initial length
  GroupArray<double> force{arena};   // [G] axial force N of the last cycle (> 0 in tension)
  GroupArray<double> strain{arena};  // [G] accumulated axial strain (the integral of the strain rate)
  [[nodiscard]] static constexpr int nodes_per_element() { return 2; }
  void allocate(int n);
};

// The section of a type-3 beam as its kernel uses it (beam_type3.cpp).
struct BeamSection {
  double area = 0, iyy = 0, izz = 0, ixx = 0;
  double dm = 0, df = 0.01;
  bool shear_neglected = false;  // Ishear 1
};
// Which end rotations a beam transmits: 1 transmitted, 0 released (Wdof 1); x is the torsion at either end.
struct BeamReleases {
  double x = 1, y1 = 1, z1 = 1, y2 = 1, z2 = 1;
};
struct BeamStep {
  double dt = 0, k_nodal = 0;
};

// Type-3 beams (/BEAM, beam_type3.cpp): one part per group, laws 1 and 2. conn [2][G] n1 n2 (the orientation
// node only sets ey at the start), nodal_force [2][6][G] forces and moments; the section's resultants
// [6][G] N Qy Qz Mx My Mz in the beam's frame, ey [3][G] its y axis of the last cycle (global components);
// sig [G] the mean axial stress N / A, eps_p [G] the plastic strain of law 2.
struct BeamGroup : MaterialGroupCore {
  using MaterialGroupCore::MaterialGroupCore;
  BeamSection section;
  BeamReleases releases;
  GroupArray<double> l0{arena};         // [G] initial length
  GroupArray<double> ey{arena};         // [3][G]
  GroupArray<double> resultant{arena};  // [6][G]
  [[nodiscard]] static constexpr int nodes_per_element() { return 2; }
  void allocate(int n);
};

// Every element group of a model, kind by kind, in the one order all the engine's stages use: shells,
// bricks, tetrahedra, 20-node bricks, springs, trusses, beams. A flat group index counts through the kinds in
// that order (the element stage's chunks, its votes and the order of the nodal sums), and sums over groups
// are taken in it.
struct ElementGroups {
  std::vector<ShellGroup> shells;
  std::vector<BrickGroup> bricks;
  std::vector<TetraGroup> tetras;
  std::vector<Hex20Group> bricks20;
  std::vector<SpringGroup> springs;
  std::vector<TrussGroup> trusses;
  std::vector<BeamGroup> beams;

  [[nodiscard]] std::int64_t count() const {
    return static_cast<std::int64_t>(shells.size() + bricks.size() + tetras.size() + bricks20.size() +
                                     springs.size() + trusses.size() + beams.size());
  }
  // Calls f(group) for every group, in the flat order.
  template <class F>
  void for_each(F&& f) const {
    each(*this, f);
  }
  template <class F>
  void for_each(F&& f) {
    each(*this, f);
  }
  // Calls f(group) for the group of flat index `flat`.
  template <class F>
  void visit(std::int64_t flat, F&& f) const {
    at(*this, flat, f);
  }
  template <class F>
  void visit(std::int64_t flat, F&& f) {
    at(*this, flat, f);
  }

 private:
  template <class Self, class F>
  static void each(Self& self, F& f) {
    for (auto& g : self.shells) f(g);
    for (auto& g : self.bricks) f(g);
    for (auto& g : self.tetras) f(g);
    for (auto& g : self.bricks20) f(g);
    for (auto& g : self.springs) f(g);
    for (auto& g : self.trusses) f(g);
    for (auto& g : self.beams) f(g);
  }
  template <class Self, class F>
  static void at(Self& self, std::int64_t flat, F& f) {
    auto k = static_cast<std::size_t>(flat);
    if (k < self.shells.size()) return f(self.shells[k]);
    k -= self.shells.size();
    if (k < self.bricks.size()) return f(self.bricks[k]);
    k -= self.bricks.size();
    if (k < self.tetras.size()) return f(self.tetras[k]);
    k -= self.tetras.size();
    if (k < self.bricks20.size()) return f(self.bricks20[k]);
    k -= self.bricks20.size();
    if (k < self.springs.size()) return f(self.springs[k]);
    k -= self.springs.size();
    if (k < self.trusses.size()) return f(self.trusses[k]);
    f(self.beams[k - self.trusses.size()]);
  }
};

// True for the group kinds with a material at their points (shells, bricks, tetrahedra, trusses), for the
// visitors that skip springs.
template <class Group>
inline constexpr bool kHasMaterial = std::is_base_of_v<MaterialGroupCore, Group>;

// The model block a group's elements come from (their user ids, parts and connectivity).
inline const model::ElementBlock& element_block(const model::Model& m, const ShellGroup& g) {
  return g.triangle ? m.shells3 : m.shells;
}
inline const model::ElementBlock& element_block(const model::Model& m, const BrickGroup&) {
  return m.bricks;
}
inline const model::ElementBlock& element_block(const model::Model& m, const TetraGroup&) {
  return m.tetras;
}
inline const model::ElementBlock& element_block(const model::Model& m, const Hex20Group&) {
  return m.bricks20;
}
inline const model::ElementBlock& element_block(const model::Model& m, const SpringGroup&) {
  return m.springs;
}
inline const model::ElementBlock& element_block(const model::Model& m, const TrussGroup&) {
  return m.trusses;
}
inline const model::ElementBlock& element_block(const model::Model& m, const BeamGroup&) {
  return m.beams;
}

// Where a group's elements sit among the model's cells (4-node shells, 3-node shells, bricks, tetrahedra,
// then springs and trusses: the order of the model file, the results and contact's element flags): slot i of
// g is cell first_cell(m, g) + g.element[i].
inline std::size_t first_cell(const model::Model& m, const ShellGroup& g) {
  return g.triangle ? m.shells.size() : 0;
}
inline std::size_t first_cell(const model::Model& m, const BrickGroup&) {
  return m.shells.size() + m.shells3.size();
}
inline std::size_t first_cell(const model::Model& m, const TetraGroup&) {
  return m.shells.size() + m.shells3.size() + m.bricks.size();
}
inline std::size_t first_cell(const model::Model& m, const Hex20Group&) {
  return m.shells.size() + m.shells3.size() + m.bricks.size() + m.tetras.size();
}
inline std::size_t first_cell(const model::Model& m, const SpringGroup&) {
  return m.element_count();
}
inline std::size_t first_cell(const model::Model& m, const TrussGroup&) {
  return m.element_count() + m.springs.size();
}
inline std::size_t first_cell(const model::Model& m, const BeamGroup&) {
  return m.element_count() + m.springs.size() + m.trusses.size();
}

// True for the kinds whose elements are cells of the solid and shell mesh (contact's surfaces and element
// flags number those cells only); springs and trusses are cells of the results after them.
template <class Group>
inline constexpr bool kMeshCell =
    kHasMaterial<Group> && !std::is_same_v<Group, TrussGroup> && !std::is_same_v<Group, BeamGroup>;

// Adds each element's nodal stiffness contribution k_nodal to its nodes' sums k[node] (the nodal time step),
// element by element and node by node of the element.
template <class Group>
void add_nodal_stiffness(const Group& g, std::span<double> k) {
  const int nodes = g.nodes_per_element();
  for (int i = 0; i < g.count; ++i)
    for (int q = 0; q < nodes; ++q)
      k[static_cast<std::size_t>(g.conn[static_cast<std::size_t>(q * kGroupSize + i)])] +=
          g.k_nodal[static_cast<std::size_t>(i)];
}

// The initial mass of element i of a group with a material of initial density rho0.
inline double initial_mass(const ShellGroup& g, std::size_t i, double rho0) {
  return rho0 * g.area0[i] * g.t0[i];
}
inline double initial_mass(const TrussGroup& g, std::size_t i, double rho0) {
  return rho0 * g.area0[i] * g.l0[i];
}
inline double initial_mass(const BeamGroup& g, std::size_t i, double rho0) {
  return rho0 * g.section.area * g.l0[i];
}
template <class Solid>
requires(std::is_same_v<Solid, BrickGroup> || std::is_same_v<Solid, TetraGroup> ||
         std::is_same_v<Solid, Hex20Group>) inline double initial_mass(const Solid& g, std::size_t i,
                                                                       double rho0) {
  return rho0 * g.vol0[i];
}

// Kernels (one file each). Each reads node coordinates and velocities from `nodes`, updates the
// group's state, energies and element steps, and fills `nodal_force`. Elements with off == 0 give no
// force and a step of +infinity.
void shell_bt4_forces(ShellGroup& g, const NodeState& nodes, const MaterialParams& mat, const CycleInfo& cyc);
void shell_c0_tri3_forces(ShellGroup& g, const NodeState& nodes, const MaterialParams& mat,
                          const CycleInfo& cyc);
void shell_qeph_forces(ShellGroup& g, const NodeState& nodes, const MaterialParams& mat,
                       const CycleInfo& cyc);
void shell_qbat_forces(ShellGroup& g, const NodeState& nodes, const MaterialParams& mat,
                       const CycleInfo& cyc);
void spring_type4_forces(SpringGroup& g, const NodeState& nodes, const CycleInfo& cyc);
void spring_type8_forces(SpringGroup& g, const NodeState& nodes, const CycleInfo& cyc);
void spring_type13_forces(SpringGroup& g, const NodeState& nodes, const CycleInfo& cyc);
void truss_axial_forces(TrussGroup& g, const NodeState& nodes, const MaterialParams& mat,
                        const CycleInfo& cyc);
void beam_type3_forces(BeamGroup& g, const NodeState& nodes, const MaterialParams& mat, const CycleInfo& cyc);
// The step and the nodal stiffness of a type-3 beam of length l (beam_type3.cpp).
[[nodiscard]] BeamStep beam_step(const BeamSection& s, const MaterialParams& mat, double l);
// TYPE13's initial Y axis (unit, normal to l = x2 - x1): from r3 = x3 - x1 when given and off the axis, else
// from the skew's Y axis (rows of `skew_axes`: X Y Z), else its X axis (spring_type13.cpp).
[[nodiscard]] model::Vec3 spring_type13_initial_y(const model::Vec3& l, const std::optional<model::Vec3>& r3,
                                                  const std::array<double, 9>& skew_axes);
void hex8_forces(BrickGroup& g, const NodeState& nodes, const MaterialParams& mat, const CycleInfo& cyc);
void hex8_heph_forces(BrickGroup& g, const NodeState& nodes, const MaterialParams& mat, const CycleInfo& cyc);

// Co-rotational frame of a one-point brick from its node coordinates x[8][3] (docs/theory/elements.md 3.6):
// the three centre directions r (eta), s (zeta), t (xi), made orthonormal symmetrically. `heph_order`: the
// frame's x axis along t, y along r, z along s (Isolid 24); otherwise x along r, y along s, z along t
// (Isolid 1, 2). R[row][column], columns the unit axes in global coordinates.
void brick_corotational_frame(const double x[8][3], bool heph_order, double R[3][3]);
void tetra4_forces(TetraGroup& g, const NodeState& nodes, const MaterialParams& mat, const CycleInfo& cyc);
void hex20_forces(Hex20Group& g, const NodeState& nodes, const MaterialParams& mat, const CycleInfo& cyc);
// Element i's initial point volumes vol0_p, volume vol0 and vol from its node coordinates x0[20][3]
// (hex20_quadratic.cpp).
void hex20_init_geometry(Hex20Group& g, std::size_t i, const double x0[20][3]);
void hex8_full_forces(BrickGroup& g, const NodeState& nodes, const MaterialParams& mat, const CycleInfo& cyc);
// The flags of a brick group from its property and material (OpenRadioss's defaults per Isolid, see
// hex8_full.cpp): n_points, icpre, corot, strain, coupled, dt_points. One-point formulations keep n_points
// = 1.
void resolve_full_brick(const model::SolidProperty& prop, const MaterialParams& mat, BrickGroup& g);

// Which kernel runs a brick group: one switch in the engine, no virtual call.
enum class BrickKernel : std::uint8_t { OnePoint, Heph, FullyIntegrated };
inline BrickKernel brick_kernel(const BrickGroup& g) {
  if (g.n_points == 8) return BrickKernel::FullyIntegrated;
  return g.isolid == 24 ? BrickKernel::Heph : BrickKernel::OnePoint;
}

// Point volumes det J_p of the 2x2x2 Gauss points of the fully integrated brick at coordinates x (values <= 0
// for an inverted point).
void hex8_full_point_volumes(const double x[8][3], double vp[8]);

}  // namespace radx::solver
