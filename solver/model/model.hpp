// The validated model: what the starter produces and the engine runs. Immutable once the starter has
// finished. User ids live only at the edges (ids arrays and IdMap); everything else refers to other
// objects by dense 0-based index. All values are in work units. Depends on nothing of ours.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "solver/model/id_map.hpp"

namespace radx::model {

inline constexpr std::int32_t kNone = -1;  // "no object" for an optional index
inline constexpr double kNever = 1e30;     // time that never comes (Tstop of an interface, ...)

struct Units {
  // SI factor of one work unit, and its name as written in /BEGIN.
  double mass = 1.0, length = 1.0, time = 1.0;
  std::string mass_name = "kg", length_name = "m", time_name = "s";
};

struct Nodes {
  std::vector<std::int64_t> id;
  std::vector<double> x, y, z;  // initial coordinates
  IdMap index;
  [[nodiscard]] std::size_t size() const { return id.size(); }
};

// Stored as its integer in the model file: new types go at the end.
enum class ElementType : std::uint8_t {
  Shell4 = 0,
  Shell3 = 1,
  Brick8 = 2,
  Tetra4 = 3,
  Spring2 = 4,
  Truss2 = 5,
  Beam2 = 6,
  Brick20 = 7
};
[[nodiscard]] constexpr int nodes_per_element(ElementType t) {
  switch (t) {
    case ElementType::Shell4: return 4;
    case ElementType::Shell3: return 3;
    case ElementType::Brick8: return 8;
    case ElementType::Tetra4: return 4;
    case ElementType::Spring2: return 3;  // n1 n2 and the optional orientation node
    case ElementType::Truss2: return 2;
    case ElementType::Beam2: return 3;  // n1 n2 and the orientation node (kNone when blank)
    case ElementType::Brick20: return 20;
  }
  return 0;
}

// The element type as messages and listings name it ("brick", "3-node shell").
[[nodiscard]] constexpr std::string_view element_type_name(ElementType t) {
  switch (t) {
    case ElementType::Shell4: return "shell";
    case ElementType::Shell3: return "3-node shell";
    case ElementType::Brick8: return "brick";
    case ElementType::Tetra4: return "tetrahedron";
    case ElementType::Spring2: return "spring";
    case ElementType::Truss2: return "truss";
    case ElementType::Beam2: return "beam";
    case ElementType::Brick20: return "20-node brick";
  }
  return "element";
}

// All elements of one type, element-major connectivity (conn[e * npe + k], dense node indices).
struct ElementBlock {
  ElementType type = ElementType::Shell4;
  std::vector<std::int64_t> id;
  std::vector<std::int32_t> part;  // dense part index
  std::vector<std::int32_t> conn;
  std::vector<double> thickness;  // shells: element-card thickness, 0 = property thickness
  std::vector<double> phi;        // shells: material angle (degrees)
  IdMap index;
  [[nodiscard]] std::size_t size() const { return id.size(); }
  [[nodiscard]] int npe() const { return nodes_per_element(type); }
};

enum class MaterialLaw : std::uint8_t {
  Elastic = 1,
  JohnsonCook = 2,
  PlasTab = 36,
  PlasBrit = 27,  // /MAT/PLAS_BRIT (shells only)
  // Elements of these laws compute no internal force (OpenRadioss forint.F skips laws 0 and 13).
  // A void element only carries its mass (rho_I V, 0 when no density is given) and its contact stiffness
  // (E, nu); a rigid one is part of the rigid body the starter builds from the connected law-13 elements.
  Void = 0,
  Rigid = 13,
  Ogden = 42,    // /MAT/OGDEN: hyperelastic, stress from the total deformation gradient (one-point bricks)
  FoamTab = 70,  // /MAT/FOAM_TAB: tabulated visco-elastic foam, total strain (one-point bricks)
};

// /MAT/PLAS_TAB (law 36): yield curves sigma_y(eps_p) per strain rate, as given in the deck (the engine adds
// the rate-0 curve OpenRadioss inserts when the first rate is not 0). Parallel vectors, one entry a curve.
struct PlasTab {
  std::vector<std::int64_t> function_id;  // user ids (listing)
  std::vector<std::int32_t> function;     // dense indices into Model::functions
  std::vector<double> scale;              // Fscale_i (0 -> 1 done by the starter)
  std::vector<double> rate;               // Eps_dot_i, strictly increasing
  int fsmooth = 0;                        // rate interpolation: 0 or 1 linear, 2 logarithmic
  int vp = 0;                             // 0: total strain rate (1, plastic rate, is refused)
};

// /FAIL/JOHNSON on a material: damage D += d_eps_p / eps_f at each point,
// eps_f = max(EPSF_MIN, (D1 + D2 exp(D3 sigma_m / svm)) (1 + D4 ln(max(1, rate / rate0))) (1 + D5 T*)).
struct FailJohnson {
  bool on = false;
  std::int64_t fail_id = 0;
  double d1 = 0, d2 = 0, d3 = 0, d4 = 0, d5 = 0;
  double eps_dot_0 = 1e-20;  // 0 -> 1e-20
  double eps_f_min = 0;
  double dadv = 1;
  int ifail_sh = 1;  // 1: one failed point deletes the shell; 2: every point must fail
  int ifail_so = 1;  // 1: brick deleted; 2: deviator zero; 3: deviator zero, no tension; 4: stress zero
};

// /FAIL/TAB on a material (OpenRadioss hm_read_fail_tab_old.F, run as /FAIL/TAB1 by the starter's
// conversion): failure plastic strain from tables of the triaxiality, one per strain rate, times an
// element-size factor and a temperature factor; damage D += n D^(1 - 1/n) d_eps_p / eps_f, the point fails at
// Dcrit. Defaults resolved by the starter. Parallel vectors, one entry a strain rate.
struct FailTab {
  bool on = false;
  std::int64_t fail_id = 0;
  int ifail_sh = 1;        // 1: one failed point deletes the shell; 2 and 3: P_thickfail of the thickness
  int ifail_so = 1;        // 1: brick deleted; 2: normal stresses set to the mean; 3: the stress is kept
  double p_thickfail = 0;  // failed thickness fraction (Ifail_sh 2, 3); 0 = the property's
  double dcrit = 1, d = 0.999, n = 1;
  std::vector<std::int64_t> function_id;  // eps_f(triaxiality) per rate, user ids (listing)
  std::vector<std::int32_t> function;     // dense indices into Model::functions
  std::vector<double> scale;              // Fscale of each (0 -> 1)
  std::vector<double> rate;               // Epsdot of each
  std::int64_t size_function_id = 0;      // factor of the element size / El_ref; 0 = none
  std::int32_t size_function = -1;
  double size_scale = 1, el_ref = 1;
  std::int64_t temp_function_id = 0;  // a constant temperature function only (radx has no temperature)
  double temp_factor = 1;             // Fscale_T times that constant
};

// /FAIL/BIQUAD on a material (OpenRadioss hm_read_fail_biquad.F): the plastic strain at failure of the
// triaxiality from two parabolas through C1..C5 at -1/3, 0, 1/3, 1/sqrt(3), 2/3; damage D += d_eps_p / eps_f,
// the point fails at D = 1. Values as the starter resolves them (M_Flag's multiples of C3, S_Flag, the
// clamped P_thickfail).
struct FailBiquad {
  bool on = false;
  std::int64_t fail_id = 0;
  double c1 = 0, c2 = 0, c3 = 0, c4 = 0, c5 = 0;  // after M_Flag
  int m_flag = 0;
  int s_flag = 2;  // 1: the second parabola above 1/3; 2: plane strain the minimum; 3: 2 and the necking
  double inst_start = 0;              // S_Flag 3: the instability strain at plane strain, in (0, C4)
  double p_thickfail = 1e-6;          // in [1e-6, 1]; min with the property's at run time
  std::int64_t size_function_id = 0;  // factor of eps_f by the element size / EI_ref; 0 = none
  std::int32_t size_function = -1;
  double el_ref = 1;
};

// /MAT/PLAS_BRIT (law 27): the tension crack of each shell point, by direction 1 and 2 of the crack frame.
// Defaults as OpenRadioss hm_read_mat27.F sets them for a blank or 0 field. The Johnson-Cook part (a, b, n,
// sig_max0, c, eps_dot_0, icc, fsmooth, f_cut) is kept in Material's law-2 fields.
struct PlasBrit {
  double eps_t1 = 1e20, eps_m1 = 1.1e20, d_max1 = 0.999, eps_f1 = 1.2e22;  // crack starts, full, cap, delete
  double eps_t2 = 1e20, eps_m2 = 1.1e20, d_max2 = 0.999, eps_f2 = 1.2e22;
};

// /MAT/OGDEN (law 42) as OpenRadioss hm_read_mat42.F keeps it: the terms with mu_p != 0, in the deck's
// order (up to 10), the bulk modulus K = G (1 + nu) / (3 (1 - 2 nu)) with G = sum mu_p alpha_p (twice the
// initial shear modulus), the tension cut-off (Biot stress; 0 -> 1e20) and the volumetric form Iform
// (1: U = K/2 (J - 1)^2, 2: U = K (J - 1 - ln J)). The shear modulus and nu are in Material::shear, poisson.
struct Ogden {
  std::vector<double> mu, alpha;
  double sig_cut = 1e20;
  int iform = 1;
};

// /MAT/FOAM_TAB (law 70) as the deck gives it (OpenRadioss hm_read_mat70.F's defaults applied): the loading
// curves sigma(eps) per strain rate and the unloading curves (parallel vectors, one entry a curve, in the
// deck's order), the tension factor curve of Itens 1, and the scalars. E0, nu are in Material::young,
// poisson. The curve processing of the engine (solver/model/foam_table.hpp) derives the table, E0, Emax and
// the strain limit the law runs with.
struct FoamTab {
  std::vector<std::int64_t> load_function_id;  // user ids (listing)
  std::vector<std::int32_t> load_function;     // dense indices into Model::functions
  std::vector<double> load_scale;              // 0 -> 1
  std::vector<double> load_rate;
  std::vector<std::int64_t> unload_function_id;
  std::vector<std::int32_t> unload_function;
  std::vector<double> unload_scale;
  std::vector<double> unload_rate;
  double e_max = 0;    // Emax: 0 -> the largest slope of the loading table
  double eps_max = 1;  // strain beyond which the stiffness Emax continues the curves (0 -> 1)
  int itens = 0;       // 1: stress times fct(1 - rho / rho0) in expansion
  std::int64_t tens_function_id = 0;
  std::int32_t tens_function = -1;
  double tens_scale = 1;
  int israte = 0;  // strain-rate filter flag (Fcut > 0 sets it); the cut-off is Material::f_cut
  int iflag = 0;   // unloading formulation 0..4 (0 after the starter when no unloading curve and Iflag <= 2)
  double shape = 1;  // Shape exponent of Iflag 3, 4 (0 -> 1)
  double hys = 1;    // Hys factor of Iflag 3, 4 (0 -> 1)
};

struct Material {
  std::int64_t id = 0;
  std::string title;
  MaterialLaw law = MaterialLaw::Elastic;
  std::string keyword;  // as written, e.g. /MAT/PLAS_JOHNS
  double rho = 0, rho_ref = 0, young = 0, poisson = 0;
  double shear = 0, bulk = 0;  // derived: G = E/2(1+nu), K = E/3(1-2nu)
  // Johnson-Cook (law 2). sigma_y = (a + b eps_p^n)(1 + c ln(epsdot/epsdot0))(1 - T*^m), capped.
  int iflag = 0, flag_vp = 2, icc = 1, fsmooth = 0;
  double a = 0, b = 0, n = 1, eps_p_max = 1e20, sig_max0 = 1e20;
  double sig_y_input = 0, uts = 0, e_uts = 0;  // Iflag = 1 input, kept for the listing
  double c = 0, eps_dot_0 = 0, f_cut = 0, chard = 0, p_min = -1e20;
  double m_temp = 1, t_melt = 1e20, rho_cp = 0, t_ref = 300, t_max = 1e20;
  // Tabulated plasticity (law 36); eps_p_max and f_cut above are shared with law 2.
  PlasTab tab;
  FailJohnson fail_jc;
  FailTab fail_tab;
  FailBiquad fail_bq;
  PlasBrit brit;  // law 27's crack model
  Ogden ogden;    // law 42
  FoamTab foam;   // law 70
};

enum class PropertyKind : std::uint8_t { Shell = 1, Truss = 2, Beam = 3, Solid = 14, Spring = 4 };

struct ShellProperty {
  int ishell = 1, ismstr = 2, ish3n = 2, idrill = 0, ipinch = 0, n_ip = 0, ithick = 2, iplas = 2, ipos = 0;
  double p_thick_fail = 0.999999, hm = 0.01, hf = 0.01, hr = 0.01, dm = 0, dn = 0;
  double thickness = 0, ashear = 5.0 / 6.0;
};

struct SolidProperty {
  int isolid = 1, ismstr = 4, icpre = 0, iframe = 1, inpts = 0, itetra4 = 1000, itetra10 = 1000, iale = 0;
  double qa = 1.1, qb = 0.05, h = 0.1, lambda_v = 0, mu_v = 0, dn = 0, dt_min = 0;
  // qa and qb both 0 (blank) in the deck: OpenRadioss then runs law 70 without bulk viscosity (its defaults
  // 1.1 and 0.05 apply to the other laws).
  bool q_default = false;
};

// One spring law, as OpenRadioss's starter reads it (hm_read_prop04.F, hm_read_prop08.F), defaults
// resolved: the force along one degree of freedom, with x its elongation (divided by the initial length when
// Ileng = 1) and v = dx/dt:  F = (A + B ln(max(1, |v| / D)) + E g2(v / F)) f(x) + C v + Hscale g4(v / F),
// with f(x) = K x without fct_ID1 (A = 1, B = E = 0 then), f1(x / Ascale) with it. For a rotational degree
// of freedom x is an angle and F a moment.
struct SpringLaw {
  double stiffness = 0;  // K: the linear stiffness, and the stiffness of the time step
  double damping = 0;    // C
  double a = 1, b = 0, d = 1, e = 0;
  int hardening = 0;  // H: 0 1 2 4 5 6 7 8 (spring_law.hpp; check_formulations.cpp refuses 8 on TYPE8)
  std::int32_t f_load = kNone;    // fct_ID1: force of the elongation (dense index into Model::functions)
  std::int32_t f_damp = kNone;    // fct_ID2: the amplification g2 of the velocity
  std::int32_t f_unload = kNone;  // fct_ID3: H 4 lower yield, H 5 residual, H 6 and 7 unloading
  std::int32_t f_damp4 = kNone;   // fct_ID4: the additional force g4 of the velocity
  double fscale = 1;              // F: velocity scale of g2 and g4
  double ascale = 1;              // Ascale: abscissa scale of fct_ID1
  double hscale = 1;              // Hscale4: ordinate scale of g4
  double delta_min = -1e30, delta_max = 1e30;  // failure elongations (0 in the deck: none)
};

// /PROP/SPRING (TYPE4): one law along the spring (`x`). /PROP/SPR_GENE (TYPE8): six uncoupled laws
// x y z rx ry rz along the axes of a fixed frame (global, or a /SKEW/FIX), with the rotational inertia
// `inertia` and the failure criterion `ifail`. /PROP/SPR_BEAM (TYPE13): the same six laws in a frame that
// follows the spring, the shear forces balanced by end moments (spring_type13.cpp).
struct SpringProperty {
  int type = 4;        // Radioss property type: 4 (/PROP/SPRING), 8 (/PROP/SPR_GENE), 13 (/PROP/SPR_BEAM)
  double mass = 0;     // M (per unit length when Ileng = 1), half to each node
  double inertia = 0;  // TYPE8, TYPE13: rotational inertia, half to each node
  int ileng = 0;       // TYPE4: 1: M, K, C and the curves per unit length
  std::int64_t sensor = 0;    // sens_ID (refused when not 0)
  std::int32_t skew = kNone;  // TYPE8: frame of the six laws; TYPE13: orients the initial frame without n3
                              // (dense index into Model::skews); kNone global
  int ifail = 0;  // TYPE8, TYPE13: 0 a degree of freedom breaks the spring alone, 1 sum of squares
  SpringLaw x, y, z, rx, ry, rz;  // TYPE4 uses x only
  [[nodiscard]] const SpringLaw& law(int dof) const {
    const SpringLaw* l[6] = {&x, &y, &z, &rx, &ry, &rz};
    return *l[dof];
  }
  [[nodiscard]] SpringLaw& law(int dof) {
    SpringLaw* l[6] = {&x, &y, &z, &rx, &ry, &rz};
    return *l[dof];
  }
};

// /PROP/TRUSS (TYPE2): the initial cross-section area. The truss carries an axial force only; its area
// follows the axial strain through the material's Poisson ratio (docs/theory/elements.md, trusses).
struct TrussProperty {
  double area = 0;
};

// /PROP/BEAM (TYPE3): the Radioss beam, integrated over its section (resultants): the section's area and
// second moments, the membrane and flexural damping, the shear flag and the released rotations
// (docs/elements-openradioss.md 12.2).
struct BeamProperty {
  double area = 0, iyy = 0, izz = 0, ixx = 0;  // Ixx: torsion
  double dm = 0, df = 0.01;                    // Df 0 -> 0.01 (hm_read_prop03.F)
  int ishear = 0;                              // 0: Timoshenko shear; 1: shear neglected (Euler-Bernoulli)
  int ismstr = 0;
  // Released rotations (Wdof): x at either end (torsion), y and z at node 1 and node 2; 1 = released.
  int release_x = 0, release_y1 = 0, release_z1 = 0, release_y2 = 0, release_z2 = 0;
};

struct Property {
  std::int64_t id = 0;
  std::string title;
  PropertyKind kind = PropertyKind::Shell;
  ShellProperty shell;
  SolidProperty solid;
  SpringProperty spring;
  TrussProperty truss;
  BeamProperty beam;
};

struct Part {
  std::int64_t id = 0;
  std::string title;
  std::int32_t property = kNone;
  std::int32_t material = kNone;
  std::int32_t subset = kNone;
  double contact_thickness = 0;  // /PART Thick: used only for contact gaps
  // Computed by the starter.
  double mass = 0;
  std::int64_t element_count = 0;
};

struct Subset {
  std::int64_t id = 0;
  std::string title;
  std::vector<std::int32_t> children;  // dense subset indices
  std::vector<std::int32_t> parts;     // parts directly in this subset
};

struct NodeGroup {
  std::int64_t id = 0;
  std::string title;
  std::string kind;                 // NODE, PART, GRNOD, BOX, GENE, ...
  std::vector<std::int32_t> nodes;  // sorted, unique dense node indices
};

// /BOX/RECTA (axis-aligned), /BOX/CYLIN (finite cylinder) and /BOX/SPHER: one id space. A point on the
// boundary is inside (OpenRadioss starter model/box/rdbox.F).
enum class BoxShape : std::uint8_t { Recta = 0, Cylinder = 1, Sphere = 2 };
struct Box {
  std::int64_t id = 0;
  std::string title;
  BoxShape shape = BoxShape::Recta;
  // Recta: the lowest and highest corners. Cylinder: the centres of its two end faces (the axis runs from p1
  // to p2). Sphere: p1 is the centre.
  std::array<double, 3> p1{}, p2{};
  double diameter = 0;  // cylinder and sphere
};

// A main-surface segment. Triangles repeat their third node (n4 == n3): 3-node shells and tetrahedron faces.
enum class SegmentOwner : std::uint8_t { None = 0, Shell4 = 1, Shell3 = 2, Brick8 = 3, Tetra4 = 4 };
struct Surface {
  std::int64_t id = 0;
  std::string title;
  std::string kind;  // PART, PART/EXT, SEG
  std::vector<std::array<std::int32_t, 4>> segments;
  std::vector<SegmentOwner> owner_type;  // element type behind each segment
  std::vector<std::int32_t> owner;       // element index in its block (kNone for /SURF/SEG without one)
};

struct Function {
  std::int64_t id = 0;
  std::string title;
  std::vector<double> x, y;
};

// A skew: a frame that loads, conditions and outputs may be given in. axes holds the unit vectors x', y',
// z' (rows, global components).
// /SKEW/FIX: fixed; z' is the deck's Z' direction, x' = Y' x Z', y' = z' x x' (Radioss's order), each
// normalised.
// /SKEW/MOV: carried by the nodes n1 n2 n3 (dense indices), origin n1, axis `dir` (0 x', 1 y', 2 z')
// along n1 -> n2, n3 in the plane of that axis and the next one (node_skew_axes, geometry.hpp). origin
// and axes hold the frame at t = 0; the engine rebuilds it from the current positions every cycle.
struct Skew {
  std::int64_t id = 0;
  std::string title;
  std::array<double, 3> origin{};
  std::array<double, 9> axes{1, 0, 0, 0, 1, 0, 0, 0, 1};
  std::int32_t n1 = kNone, n2 = kNone, n3 = kNone;  // /SKEW/MOV nodes; kNone for /SKEW/FIX
  int dir = 0;                                      // /SKEW/MOV Dir: 0 X, 1 Y, 2 Z
  // A /FRAME/FIX or /FRAME/MOV: built as the skew of the same card, but a /TH/NODE in it measures positions
  // from its origin, and only the fields that Radioss reads as "skew or frame" accept it.
  bool frame = false;
  [[nodiscard]] bool moving() const { return n1 != kNone; }
};

struct BoundaryCondition {
  std::int64_t id = 0;
  std::string title;
  std::array<std::uint8_t, 6> fixed{};  // Tx Ty Tz Rx Ry Rz
  std::int64_t skew = 0;
  std::int32_t group = kNone;
};

// Direction codes: 0..2 translations X Y Z, 3..5 rotations XX YY ZZ.
struct ImposedVelocity {
  std::int64_t id = 0;
  std::string title;
  std::int32_t function = kNone;
  int dir = 0;
  std::int64_t skew = 0, sensor = 0, frame = 0;
  int icoor = 0;
  std::int32_t group = kNone;
  double ascale_x = 1, fscale_y = 1, t_start = 0, t_stop = kNever;
  // /IMPDISP: the function gives the displacement from the initial position, not the velocity.
  bool displacement = false;
};

// /IMPDISP/FGEO, "prescribed final geometry" (OpenRadioss read_impdisp_fgeo.F, fixfingeo.F): each node
// moves along the straight line from its initial position X0 to its target XF; the displacement along
// u = (XF - X0)/|XF - X0| is |XF - X0| f(t * ascale_x) (Radioss multiplies the time by Ascale here, where
// /IMPDISP divides by it), and the whole acceleration of the node is replaced by the one along u.
struct ImposedFinalGeometry {
  std::int64_t id = 0;
  std::string title;
  std::int32_t function = kNone;
  std::int64_t sensor = 0;
  double ascale_x = 1, t_start = 0, t_stop = kNever;
  std::vector<std::int32_t> nodes;             // dense node indices, in the deck's order
  std::vector<std::array<double, 3>> targets;  // XF of each node
};

// /ADMAS/0 (Mass added to each node of the group) and /ADMAS/1 (Mass shared equally by its nodes).
struct AddedMass {
  std::int64_t id = 0;
  std::string title;
  int type = 0;  // 0 per node, 1 total shared by the nodes
  double mass = 0;
  std::int32_t group = kNone;
};

struct InitialVelocity {
  std::int64_t id = 0;
  std::string title;
  std::array<double, 3> v{};
  std::int32_t group = kNone;
  std::int64_t skew = 0, sensor = 0;
  double t_start = 0;
  bool rotational = false;  // /INIVEL/ROT: v is the angular velocity of the nodes' rotational dofs
};

struct ConcentratedLoad {
  std::int64_t id = 0;
  std::string title;
  std::int32_t function = kNone;
  int dir = 0;
  std::int64_t skew = 0, sensor = 0;
  std::int32_t group = kNone;
  int itypfun = 1;
  double ascale_x = 1, fscale_y = 1;
};

struct PressureLoad {
  std::int64_t id = 0;
  std::string title;
  std::int32_t surface = kNone;
  std::int32_t function = kNone;
  std::int64_t sensor = 0;
  int ipinch = 0, idel = 1, itypfun = 1;
  double ascale_x = 1, fscale_y = 1;
};

struct Gravity {
  std::int64_t id = 0;
  std::string title;
  std::int32_t function = kNone;  // kNone: constant
  int dir = 0;
  std::int64_t skew = 0, sensor = 0;
  std::int32_t group = kNone;  // kNone: all nodes
  double ascale_x = 1, fscale_y = 1;
};

struct RigidWall {
  std::int64_t id = 0;
  std::string title;
  std::int32_t node = kNone;  // moving wall node, kNone for a fixed wall
  int slide = 0, iform = 0, ifq = 0;
  std::int32_t group1 = kNone, group2 = kNone;
  double distance = 0, friction = 0, diameter = 0, ffac = 0, mass = 0;
  std::array<double, 3> m{}, m1{}, v0{}, normal{};
  std::vector<std::int32_t> secondary;  // resolved secondary nodes (group1 + distance - group2)
  // 0 /RWALL/PLANE (normal), 1 /RWALL/CYL (axis M -> M1 in `normal`), 2 /RWALL/SPHER (centre M),
  // 3 /RWALL/PARAL (the parallelogram of corner M and edges M1 - M, M2 - M; `normal` (M1 - M) x (M2 - M),
  // unit). For a moving wall M is the wall node's initial position.
  int shape = 0;
  std::array<double, 3> m2{};  // /RWALL/PARAL: the third corner
};

struct RigidBody {
  std::int64_t id = 0;
  std::string title;
  std::int32_t main_node = kNone;
  std::int64_t sensor = 0, skew = 0;
  int ispher = 2, ikrem = 0, icog = 1, ioptoff = 0, iexpams = 0, ifail = 0;
  double mass = 0;
  std::array<double, 6>
      inertia{};  // Jxx Jyy Jzz Jxy Jyz Jxz (added), global axes (the starter turns a skew's)
  double fn = 1e20, ft = 1e20, exp_n = 2, exp_t = 2;
  std::int32_t group = kNone;
  std::int32_t surface = kNone;
  std::vector<std::int32_t> secondary;  // main node removed
  // /MAT/RIGID (law 13): user id of the material whose connected elements form this body, 0 for a /RBODY.
  // Such a body is built by the starter (id 0, not named by /RBODY/OFF or /TH/RBODY) on an internal main
  // node of its own and, as a body with a sensor, from its secondary nodes alone (ICoG 2, no deck mass or
  // inertia, the velocities that keep their momentum and angular momentum): OpenRadioss rigid_mat.F.
  std::int64_t rigid_material = 0;
};

// /SECT: a cut through the model (OpenRadioss hm_read_sect.F, section.F). The engine sums the forces (and
// shell moments) that the listed elements apply to the section's nodes: the force one side of the cut
// exerts on the other. Frame from the current positions of N1 N2 N3: Iframe < 10 local axes e1 = N1->N2,
// e3 = e1 x (N3 - N1) (the section normal), e2 = e3 x e1; Iframe >= 10 global axes, normal along
// (N2 - N1) x (N3 - N1), or Z when N1 is 0. Moment reference point by Iframe % 10: 0 the projection of N3 on
// the line N1 N2, 1 the mean of the section nodes, 2 their mass centre, 3 the origin.
struct Section {
  std::int64_t id = 0;
  std::string title;
  std::int32_t n1 = kNone, n2 = kNone, n3 = kNone;  // dense node indices (kNone only with Iframe >= 10)
  std::int32_t node_group = kNone;
  int iframe = 0;
  std::vector<std::int32_t> nodes;    // sorted dense indices: where the forces are summed
  std::vector<std::int32_t> shells;   // 4-node shells of grshel_ID with a node in `nodes`
  std::vector<std::int32_t> shells3;  // 3-node shells of grtria_ID with a node in `nodes`
  std::vector<std::int32_t> bricks;   // bricks of grbric_ID with a node in `nodes`
  std::vector<std::int32_t> trusses;  // trusses of grtrus_ID with a node in `nodes`
  std::vector<std::int32_t> beams;    // beams of grbeam_ID with a node in `nodes`
};

// /ACCEL: an accelerometer on a node, its axes a skew's (0: global), its signal filtered by a 4-pole
// Butterworth low-pass of cut-off Fcut (0: none).
struct Accelerometer {
  std::int64_t id = 0;
  std::string title;
  std::int32_t node = kNone;
  std::int64_t skew = 0;
  double fcut = 0;
};

// /SENSOR/TIME (OpenRadioss read_sensor_time.F, sensor_time.F): on from Tdelay, off again from Tstop. The
// loads, conditions and interfaces that name a sensor keep its user id (their `sensor` or `sens_id`); the
// engine keeps each sensor's state (solver/conditions/sensors.hpp). Stored as its integer in the model file:
// new types go at the end.
enum class SensorType : std::uint8_t { Time = 0 };
struct Sensor {
  std::int64_t id = 0;
  std::string title;
  SensorType type = SensorType::Time;
  double t_delay = 0;      // Tdelay: the sensor switches on when the run reaches it
  double t_stop = kNever;  // Tstop (deck format 2023 and newer): it switches off; kNever = never
};

// Stored as its integer in the model file (docs/model-file.md): new kinds go at the end.
enum class ThKind : std::uint8_t {
  Node,
  Part,
  Inter,
  Rwall,
  Shell,
  Subset,
  Brick,
  Shell3,
  Rbody,
  Section,
  Accel,
  Spring,
  Truss,
  Beam
};
struct TimeHistoryGroup {
  std::int64_t id = 0;
  std::string title;
  ThKind kind = ThKind::Node;
  std::vector<std::string> variables;  // expanded (DEF replaced)
  // dense indices of the objects of `kind`; /TH/BRIC: a 20-node brick e is bricks.size() + e (Radioss keeps
  // them in one solid table)
  std::vector<std::int32_t> objects;
  // /TH/NODE: the skew (user id, 0 global axes) each object's vectors are written in, one per object;
  // empty for the other kinds.
  std::vector<std::int64_t> skews;
};

// /CTCLAW (docs/theory/contact-laws.md): the normal and friction law of the SDT family that replaces an
// interface's own, as the starter read the law string. The kinds are stored as their integers in the model
// file: new kinds go at the end.
enum class NormalLaw : std::uint8_t {
  Interface = 0,    // no n part: the interface's own TYPE7 penalty stays the normal law
  Linear = 1,       // P = Kc u
  Exponential = 2,  // P = pz exp(lambda u), linear beyond the KcMax knee
  Tabulated = 3,    // P(gap) from a /FUNCT curve
  Power = 4         // P = sum kp_m u^m
};
enum class FrictionLaw : std::uint8_t {
  Interface = 0,     // no s part and no n part: the interface's own friction
  None = 1,          // no s part after an n part: frictionless
  Coulomb = 2,       // s1 / s11: exact Coulomb with a sticking stiffness
  Linear = 3,        // s2 / s12: min(ct s, mu p)
  Arctangent = 4,    // s3 / s13: mu p (2/pi) atan(ct s)
  ScaledLinear = 5,  // s4 / s14: p min(ct s, mu)
};
struct ContactLaw {
  NormalLaw normal = NormalLaw::Interface;
  FrictionLaw friction = FrictionLaw::Interface;
  bool bidirectional = false;  // s11..s14: the whole tangent plane; s1..s4: the segment's first tangent only
  // Linear: Kc (Pa/m), or -1: automatic, K / A_s with K the pair's penalty stiffness.
  double kc = 0;
  // Exponential: pz (Pa); lambda (1/m), or 0 with pe > 0: lambda = (K / A_s) / pe per pair; KcMax (Pa/m), 0:
  // unbounded.
  double pz = 0, lambda = 0, pe = 0, kc_max = 0;
  // Tabulated: dense index into Model::functions of the gap -> pressure curve; monotone cubic interpolation.
  std::int32_t curve = kNone;
  bool cubic = false;
  // Power: P = sum over k of power_k[k] u^power_m[k].
  std::vector<double> power_m, power_k;
  // Friction: Mu; CtLin (Pa s/m for s2; s/m for s3, whose atan takes ct s, and s4); kappa (Pa/m), the
  // sticking stiffness per unit area (0: K / A_s, the interface's penalty stiffness).
  double mu = 0, ct = 0, kappa = 0;
};

// /INTER/TYPE7 and /INTER/LAGDT/TYPE7 as one definition (docs/theory/type7-lagdt.md section 3), plus what the
// starter computes for it (sections 4.1, 4.2, 4.6).
struct Interface {
  std::int64_t id = 0;
  std::string title;
  bool lagdt = false;
  std::int32_t secondary_group = kNone;
  std::int32_t main_surface = kNone;
  int istf = 0, igap = 0, ibag = 0, idel = 0, ithe = 0, icurv = 0, iadm = 0, itied = 0, ists = 0;
  double fscale_gap = 1.0, gap_max = 0, fpenmax = 0;
  double stmin = 0, stmax = 1e30, mesh_size_pct = 0, dt_min = 0;
  int irem_gap = 0, irem_i2 = 0;
  double stfac = 1.0, fric = 0, gapmin_input = 0, t_start = 0, t_stop = kNever;
  std::array<std::uint8_t, 3> ibc{};
  int inacti = 0;
  double vis_s = 0.05, vis_f = 1.0, bumult = 0.2;
  int ifric = 0, ifiltr = 0, iform = 1;
  double xfreq = 0;
  std::array<double, 6> c{};  // C1..C6
  std::int64_t sens_id = 0, fct_id_f = 0, fric_id = 0;
  double ascale_f = 0;
  std::int64_t contact_law_id = 0;  // /CTCLAW that replaces the normal and friction laws (0: none)
  std::string contact_law;          // its law string, e.g. n2s13{pz1e5,lambda2e3,Mu0.3,CtLin10}
  ContactLaw law;                   // that string as understood (contact_law_id != 0)

  // Computed by the starter.
  std::vector<std::int32_t> secondary_nodes;  // sorted dense node indices
  double gapmin = 0;                          // the Gapmin in use (input or automatic)
  bool gapmin_automatic = false;
  std::vector<double> gap_node;       // gs per secondary node (Igap 1, 2)
  std::vector<double> gap_segment;    // gm per main segment (Igap 1, 2)
  std::vector<double> stiff_node;     // Ks per secondary node
  std::vector<double> stiff_segment;  // Km per main segment
  double gap_lo = 0, gap_hi = 0;      // range of the pair gaps g
  double stiff_lo = 0, stiff_hi = 0;  // range of the pair stiffnesses K
  // Initial penetrations (section 4.6).
  std::int64_t initial_penetrations = 0;
  double max_initial_penetration = 0;
  std::int64_t max_penetration_node = 0;        // user id
  std::vector<std::int32_t> inactive_nodes;     // Inacti 1: nodes without stiffness
  std::vector<std::int32_t> inactive_segments;  // Inacti 2: segments without stiffness
  std::vector<std::int32_t> penetrating_nodes;  // Inacti 5, 6: nodes with a reduced initial gap
  std::vector<double> initial_gap_reduction;    // P0 (+5 % margin for 6) per penetrating node
  // Tributary area A_s per secondary node (a /CTCLAW law's F_n = P A_s): a quarter of each 4-node shell or
  // open brick face around the node, a third of each 3-node shell; 0 for a node without any (it takes the
  // area of the segment it hits).
  std::vector<double> tributary_area;

  // The smallest and largest nonzero tributary area ({0, 0} when no secondary node has one): with stiff_lo
  // and stiff_hi they bound the automatic stiffness density K / A_s of a /CTCLAW law.
  [[nodiscard]] std::pair<double, double> tributary_area_range() const {
    double lo = 0, hi = 0;
    for (const double a : tributary_area) {
      if (!(a > 0)) continue;
      lo = lo == 0 ? a : std::min(lo, a);
      hi = std::max(hi, a);
    }
    return {lo, hi};
  }
};

// /INTER/TYPE2, kinematic tied interface (solver/conditions/tied_type2.hpp holds the equations). Each
// secondary node that found a main segment within the search distance is a tie k, stored as columns: the
// node, the segment's nodes (n4 == n3 for a triangle), its coordinates on the segment and its signed distance
// along the segment's unit normal at t = 0 (the offset the engine carries in the segment's rotating frame).
struct TiedInterface {
  std::int64_t id = 0;
  std::string title;
  std::int32_t secondary_group = kNone;
  std::int32_t main_surface = kNone;
  int ignore = 0;  // 0: a node without a segment is an error; 1..3: it leaves the interface (warning)
  int spotflag =
      0;  // 0 (or 5): the standard kinematic tie; 1: the rigid tie (solver/conditions/tied_type2.hpp)
  int level = 0, isearch = 2, idel2 = 0;
  double dsearch = 0;  // as given; 0 = automatic
  // Computed by the starter.
  double search_distance = 0;                            // the distance in use
  std::vector<std::int32_t> tie_node;                    // dense index of each tied secondary node, ascending
  std::vector<std::array<std::int32_t, 4>> tie_segment;  // dense indices of its main segment's nodes
  std::vector<double> tie_r, tie_s;  // quad: natural coordinates (r, s); triangle: area coordinates of n2, n3
  std::vector<double> tie_offset;    // signed normal distance at t = 0
  std::vector<std::int64_t> not_found;  // user ids of the secondary nodes left untied
};

struct Model {
  std::string title;
  std::string run_name;
  int deck_version = 0;
  Units units;
  Nodes nodes;
  ElementBlock shells{ElementType::Shell4, {}, {}, {}, {}, {}, {}};
  ElementBlock shells3{ElementType::Shell3, {}, {}, {}, {}, {}, {}};
  ElementBlock bricks{ElementType::Brick8, {}, {}, {}, {}, {}, {}};
  // 4-node tetrahedra (/TETRA4), nodes as the deck gives them unless the starter renumbered an inverted one
  // (n2 and n4 swapped, as Radioss does) so that tetra_volume (geometry.hpp) is positive.
  ElementBlock tetras{ElementType::Tetra4, {}, {}, {}, {}, {}, {}};
  // 20-node quadratic bricks (/BRIC20): the 8 corners then the 12 mid-side nodes, in Radioss's order
  // (hex20_shape.hpp). Cells of the mesh after the tetrahedra.
  ElementBlock bricks20{ElementType::Brick20, {}, {}, {}, {}, {}, {}};
  // /SPRING: 2-node springs (their parts have a /PROP/SPRING); conn[3 e + 2] is the optional third node
  // (orientation, kNone when blank). Not cells of the solid and shell mesh: element_count() leaves them out.
  ElementBlock springs{ElementType::Spring2, {}, {}, {}, {}, {}, {}};
  // /TRUSS: 2-node trusses (their parts have a /PROP/TRUSS and a law 1 or 2 material). Cells of the results
  // after the springs; not cells of the solid and shell mesh either.
  ElementBlock trusses{ElementType::Truss2, {}, {}, {}, {}, {}, {}};
  // /BEAM: 2-node beams (their parts have a /PROP/BEAM and a law 1 or 2 material); conn[3 e + 2] is the
  // orientation node (kNone when blank). Cells of the results after the trusses.
  ElementBlock beams{ElementType::Beam2, {}, {}, {}, {}, {}, {}};
  std::vector<Material> materials;
  std::vector<Property> properties;
  std::vector<Part> parts;
  std::vector<Subset> subsets;
  std::vector<NodeGroup> node_groups;
  std::vector<Box> boxes;
  std::vector<Surface> surfaces;
  std::vector<Function> functions;
  std::vector<BoundaryCondition> bcs;
  std::vector<ImposedVelocity> imposed_velocities;
  std::vector<ImposedFinalGeometry> imposed_final_geometries;
  std::vector<InitialVelocity> initial_velocities;
  std::vector<ConcentratedLoad> concentrated_loads;
  std::vector<PressureLoad> pressure_loads;
  std::vector<Gravity> gravities;
  std::vector<RigidWall> rigid_walls;
  std::vector<RigidBody> rigid_bodies;
  std::vector<AddedMass> added_masses;
  std::vector<Skew> skews;
  std::vector<Section> sections;
  std::vector<Accelerometer> accelerometers;
  std::vector<Sensor> sensors;
  std::vector<TimeHistoryGroup> time_histories;
  std::vector<Interface> interfaces;
  std::vector<TiedInterface> tied_interfaces;  // /INTER/TYPE2
  std::vector<std::string> ignored_keywords;   // control cards accepted as ignored, as written
  // --allow-substitutions: what runs instead of what the deck asks, one sentence each (empty otherwise).
  std::vector<std::string> substitutions;

  // Per-node lumped mass from the elements (computed by the starter).
  std::vector<double> node_mass;
  double total_mass = 0;

  // Cells are numbered 4-node shells, 3-node shells, bricks, tetrahedra, 20-node bricks (model file,
  // results, contact).
  [[nodiscard]] std::size_t element_count() const {
    return shells.size() + shells3.size() + bricks.size() + tetras.size() + bricks20.size();
  }

  // Cells of the results files: the mesh cells above, then the springs, trusses and beams (VTK lines n1 n2).
  [[nodiscard]] std::size_t cell_count() const {
    return element_count() + springs.size() + trusses.size() + beams.size();
  }

  // Dense index of the skew with user id `skew`; kNone for 0 (the global frame). Throws std::out_of_range
  // for an id the model lacks (the starter refuses those).
  [[nodiscard]] std::int32_t skew_index(std::int64_t skew) const {
    if (skew == 0) return kNone;
    for (std::size_t k = 0; k < skews.size(); ++k)
      if (skews[k].id == skew) return static_cast<std::int32_t>(k);
    throw std::out_of_range("no /SKEW/FIX, /SKEW/MOV, /FRAME/FIX or /FRAME/MOV " + std::to_string(skew) +
                            " in the model");
  }

  // Dense index in `sensors` of the sensor with user id `sensor`; kNone for 0 (no sensor). Throws
  // std::out_of_range for an id the model lacks (the starter refuses those).
  [[nodiscard]] std::int32_t sensor_index(std::int64_t sensor) const {
    if (sensor == 0) return kNone;
    for (std::size_t k = 0; k < sensors.size(); ++k)
      if (sensors[k].id == sensor) return static_cast<std::int32_t>(k);
    throw std::out_of_range("no /SENSOR/" + std::to_string(sensor) + " in the model");
  }
};

}  // namespace radx::model
