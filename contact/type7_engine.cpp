// TYPE7 penalty contact, one cycle per call (docs/theory/type7-lagdt.md sections 4 and 5).
//
// For each interface active at t (Tstart <= t < Tstop, and t >= the activation time of its sensor while the
// sensor is on: OpenRadioss inttri.F, intfop2.F), after a new candidate sort when due (4.8):
//   for each secondary node s (in order), over its candidate segments m (not containing s, not removed,
//   not made inactive by Inacti 2): the closest point c of m (four triangles around the centroid for a
//   quadrangle), d = |x_s - c|, weights h_1..h_4 of c; the pair is the candidate of smallest d.
//   Gap g = pair_gap(gs, gm) (4.1), reduced by r_s for Inacti 5, 6, where r_s = min(r_s, max(0, g - d))
//   (Inacti 6: g - 0.95 d, the 5 % margin) so that it shrinks back to 0 as the pair opens; penetration
//   p = g - r_s - d; active while p > 0.
//   n = (x_s - c)/d (two-sided gap; the segment normal when d = 0).
//   K = pair_stiffness(Km, Ks) (4.2). Normal force on s: F_n = K p g/(g - p) (4.3).
//   Relative velocity v_r = v_s - sum h_j v_j, v_n = v_r . n; damping force on s: -c v_n n with
//   c = VISs sqrt(2 k m_s / r) + 0.32 m_s max(0, -v_n)/(g - p) (4.3).
//   Friction (4.5): v_t = v_r - v_n n, pressure F_n / A_m, mu by Ifric, F_t by Iform 1 (viscous) or 2
//   (incremental, the previous force of the node rotated into the current tangent plane), then the filter.
//   Force on s: F = (F_n - c v_n) n + F_t; on main node j: -h_j F.
//   Time step (4.4): k_t = K (g/(g - p))^2; the damping ratio xi = c / (2 sqrt(k_t m)) lowers the stable step
//   of the spring by (sqrt(1 + xi^2) - xi), taken as k_eff = k_t / (sqrt(1 + xi^2) - xi)^2. Each free node
//   sums, over all pairs of all interfaces (two-pass contact puts two springs on the same nodes), the
//   Gershgorin row sum of M^-1 K: G_s = k_eff (1 + sum of the free main nodes' h), G_j = h_j k_eff ([s free]
//   + sum of the free h); it votes dt = scale sqrt(2 m / G). Against a fixed segment this is the
//   specification's scale sqrt(2 m / k_eff); when both sides move it keeps the same margin to the critical
//   step of the relative motion, which the per-node formula alone does not (a deliberate difference).
//   A pair about to close (gap closed within two steps at its approach speed) adds K already. Every pair
//   votes with the stiffness it can reach within the step at its approach speed w (reach_factor: k_t at p
//   times (1 + tau0 w / g)^2, tau0 the step at p = 0), so that a fast pair cannot close into a stiffer part
//   of the hyperbola than its vote allowed (without it a pair crossing most of a small gap in one step,
//   voted with k_t at the start of the step, met a stiffness up to 20 times larger and the run gained
//   energy). dt_k = 0.5 (g - p) / max(-v_n, tiny); the dashpots (damping c, Iform 1 viscous friction C) add
//   dt <= scale m/(c + C); a /CTCLAW regularised friction law is bounded by what stops the slip within the
//   step (ctclaw_laws.cpp) and adds nothing. /DT/INTER/CST (plain TYPE7): below Tmin the node's mass grows to
//   m = k_eff (Tmin / scale)^2 / 2 (main nodes with h_j k_eff), and the pair's own vote leaves the spring
//   step to the nodal step so that it does not undercut Tmin; /DT/INTER/DEL: a pair whose step (spring,
//   kinematic, dashpot) is below Tmin leaves the interface before it acts (no force, IBC release or stiffness
//   in that cycle), and a pair about to close whose step at p = 0 is already below Tmin does not vote (it
//   will leave as it closes). A node whose remaining gap (g - p)/g falls below 1e-6 cannot be held by the
//   penalty: it is deactivated with a warning naming the node and the interface. IBC: at the node's first
//   impact, its fixed X/Y/Z translations selected by IBCX/Y/Z are released.
// Initial penetrations at Tstart > 0, or under a sensor (4.6): on the interface's first active cycle the
// nodes closer than the gap get the Inacti treatment from the current coordinates (1: the node, 2: the
// segment leave; 3: the node is moved out to the gap; 5, 6: reduced gap), reported once; otherwise the
// starter did it at t = 0. Energies: the work of each force kind over each step, W += 1/2 (F^{n-1} + F^n) .
// v_r^{n-1/2} dt1 (the trapezoidal rule the engine uses for element and load work, consistent with its
// full-step kinetic energy): elastic = -W_elastic (stored, returned as the pair opens), damping and friction
// = -W (dissipated). So the energy balance of the engine closes with contact. Forces are scattered node by
// node in a fixed order (secondary nodes in order, then their segments' nodes), so the result does not depend
// on the thread count.
#include "contact/type7_engine.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "contact/ctclaw_laws.hpp"
#include "contact/type7_laws.hpp"
#include "contact/type7_prepare.hpp"
#include "contact/type7_search.hpp"
#include "solver/model/exact_sum.hpp"
#include "solver/model/geometry.hpp"

namespace radx::contact {

namespace {

using model::Vec3;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kTiny = 1e-300;
// A LAGDT node within this fraction of the gap outside the gap's edge counts as resting on it (see on_edge).
constexpr double kEdgeBand = 1e-3;

// The forces of one active pair in the last cycle, kept to book their work over the step.
struct PairRecord {
  std::int32_t node;                      // dense node index
  std::array<std::int32_t, 4> seg;        // dense node indices of the segment
  std::array<double, 4> h;                // weights
  Vec3 f_elastic, f_damping, f_friction;  // forces on the secondary node
};

struct InterfaceState {
  const model::Interface* in = nullptr;
  std::vector<std::array<std::int32_t, 4>> segments;
  std::vector<double> segment_area0;
  std::vector<double> tributary_area;  // A_s per secondary index (the starter's; updated as elements die)
  // LAGDT: 1 where the secondary node's row pushed (lambda > 0) in the last cycle: it keeps its row (hold).
  std::vector<std::uint8_t> row_pushed;
  std::unique_ptr<Type7Search> search;
  std::vector<std::uint8_t> node_off, segment_off;  // per secondary index / segment index
  std::vector<double> reduction;                    // Inacti 5, 6: r per secondary index
  std::vector<Vec3> f_t;                            // previous tangential force per secondary index
  std::vector<std::uint8_t> hit;                    // IBC: first impact seen
  std::vector<std::int32_t> owner_cell;             // model cell behind each segment (Idel), -1 unknown
  std::vector<PairRecord> pairs;
  InterfaceResult result;  // its energies and forces are filled from the exact sums below by results()
  // Works of the contact forces since the start, and the forces of the last cycle: reported sums, exact and
  // order-free (model::ExactSum), so any split of the pairs between threads or ranks gives the same bits.
  model::ExactSum w_elastic, w_damping, w_friction, w_lagrange;
  std::array<model::ExactSum, 3> normal_force, tangential_force;
  bool started = false;    // the first cycle inside [Tstart, Tstop) has been seen
  bool from_start = true;  // the starter's initial-penetration treatment holds (Tstart 0, no sensor)
  std::int32_t sensor = model::kNone;  // dense index into model.sensors
  bool warned_held = false;  // a LAGDT pair kept on the penalty path by a kinematic condition was reported
  std::int32_t index = 0;    // position among the engine's interfaces (the friction law of its rows)
};

// A penalty pair of this cycle, computed but not applied yet: the LAGDT switch looks at the summed nodal
// stiffness of all pairs before the forces are scattered.
struct PendingPair {
  InterfaceState* st = nullptr;
  std::size_t ks = 0;  // secondary index in the interface
  SwitchedPair row;    // what the pair becomes if it switches
  Vec3 f_el{}, f_dp{}, f_fr{}, vr{};
  double keff = 0, dt_vote = kInf, p = 0;
  bool switchable = false;
};

// The work of a switched pair's forces over the half step after t^n, booked at the next cycle.
struct LagrangeRecord {
  std::int32_t iface;
  std::int32_t node;
  std::array<std::int32_t, 4> seg;
  std::array<double, 4> h;
  Vec3 f_normal, f_friction, vr_full;  // forces on the secondary node; v_r at t^n
  double dt2;
};

Vec3 node_x(const ContactNodes& n, std::int32_t i) {
  const auto k = static_cast<std::size_t>(i);
  return {n.x[k], n.y[k], n.z[k]};
}
Vec3 node_v(const ContactNodes& n, std::int32_t i) {
  const auto k = static_cast<std::size_t>(i);
  return {n.vx[k], n.vy[k], n.vz[k]};
}
auto velocity(const ContactNodes& n) {
  return [&n](std::int32_t i) { return node_v(n, i); };
}

// v_r = v_s - sum_j h_j v_j for the per-node velocity v(n) (a triangle's repeated node has h = 0).
template <class Velocity>
Vec3 relative_velocity(const Velocity& v, std::int32_t s, const std::array<std::int32_t, 4>& seg,
                       const std::array<double, 4>& h) {
  Vec3 vr = v(s);
  for (std::size_t j = 0; j < 4; ++j)
    if (h[j] != 0) vr = model::sub(vr, model::scale(v(seg[j]), h[j]));
  return vr;
}

// The candidates are sorted by node: node k = cand[c].node owns cand[c .. end). Calls visit(k, c, end) for
// each node whose candidates start in [c, stop), in order.
template <class Visit>
void for_each_node(const std::vector<Candidate>& cand, std::size_t c, std::size_t stop, Visit&& visit) {
  while (c < stop) {
    const std::int32_t k = cand[c].node;
    std::size_t end = c;
    while (end < cand.size() && cand[end].node == k) ++end;
    visit(static_cast<std::size_t>(k), c, end);
    c = end;
  }
}

double segment_area(const std::array<Vec3, 4>& x, bool triangle) {
  return triangle ? model::triangle_area(x[0], x[1], x[2]) : model::quad_area(x[0], x[1], x[2], x[3]);
}

// The stiffness a pair can reach within the step, as a factor on its stiffness at the current penetration.
// With remaining gap r = g - p and approach speed w = max(0, -v_n), a step dt takes the pair to
// k_t(p + w dt) = K g^2 / (r - w dt)^2; with tau0 = scale sqrt(2 m / K) the stable step at p = 0,
// dt <= tau0 (r - w dt) / g holds for dt <= tau0 r / (g + tau0 w), which is the step of the stiffness
// k_t(p) (1 + tau0 w / g)^2.
double reach_factor(double tau0, double g, double w) {
  const double f = 1.0 + tau0 * std::max(w, 0.0) / g;
  return f * f;
}

// The same for a /CTCLAW normal law, whose stiffness has no pole: the larger of Kc A_s at the overclosure u
// and at the overclosure two steps of the last length ahead at the approach speed w (the laws stiffen as u
// grows, the exponential one without bound until its KcMax knee).
double law_reach_stiffness(const PairLaw& law, double area, double u, double w, double dt) {
  const double ahead = u + 2.0 * std::max(w, 0.0) * dt;
  return area * std::max(normal_pressure(law, u).kc, normal_pressure(law, ahead).kc);
}

// The segment's first tangent x2 - x1 in the tangent plane of n, unit (one-directional /CTCLAW friction).
Vec3 first_tangent(const std::array<Vec3, 4>& x, const Vec3& n) {
  Vec3 t = model::sub(x[1], x[0]);
  t = model::sub(t, model::scale(n, model::dot(t, n)));
  const double len = model::norm(t);
  return len > 0 ? model::scale(t, 1.0 / len) : Vec3{};
}

// The previous tangential force rotated into the current tangent plane of n, its length kept.
Vec3 rotated_into_plane(const Vec3& f_old, const Vec3& n) {
  const double len_old = model::norm(f_old);
  const Vec3 in_plane = model::sub(f_old, model::scale(n, model::dot(f_old, n)));
  const double len_new = model::norm(in_plane);
  return len_new > 0 ? model::scale(in_plane, len_old / len_new) : in_plane;
}

// Which parts of a pair's response a /CTCLAW law replaces (docs/theory/contact-laws.md section 5). The
// interface's law decides it for all of its pairs, so the pair loop is compiled once per variant and chosen
// once per interface (interface_cycle): no per-pair branch on the law's kind remains.
struct LawVariant {
  bool law = false;       // a /CTCLAW law: forces on the tributary area A_s, the segment's first tangent
  bool normal = false;    // its normal law replaces the interface's penalty
  bool friction = false;  // its friction law (None included) replaces the interface's Ifric friction
};
constexpr LawVariant kPenaltyOnly{}, kLawAreas{true, false, false}, kLawNormal{true, true, false},
    kLawFriction{true, false, true}, kLawBoth{true, true, true};

// What the controls and the interface fix for all of its pairs in this cycle.
struct CycleFlags {
  double dt1 = 0, scale = 0, alpha = 1;  // the step, the step scale factor, the friction filter factor
  double t_min = 0;                      // Tmin of /DT/INTER
  bool lagdt = false;                    // LAGDT pairs switch to rows (in.lagdt under lagrange_on())
  bool mass_scaled = false;              // /DT/INTER/CST on a plain TYPE7: Tmin is kept by added mass
  bool deletes = false;                  // /DT/INTER/DEL: a pair below Tmin leaves the interface
};

// The closest pair of a secondary node: its segment (stage A), gap and penetration, contact normal.
struct PairGeometry {
  std::size_t ks = 0, sb = 0;  // secondary index, segment index
  std::int32_t node = 0;
  std::array<double, 4> h{};
  std::array<Vec3, 4> x{};  // the segment's corners
  double d = 0, g = 0, p = 0;
  Vec3 n{};
};

// What the pair's response starts from: penalty stiffness, mass, relative velocity, and the pair's law.
struct PairContact {
  double K = 0, ms = 0, vn = 0;
  Vec3 vr{};
  double area_s = 0;  // A_s of a /CTCLAW law, 0 without one
  PairLaw law;
  Pressure pr;
  double onset = 0;
  Vec3 t1{};
  double row_area = 0, row_gap = 0;  // what the pair's row (LAGDT) takes
  bool held = false;                 // its row pushed in the last cycle
};

// What a pair does in this cycle. classify_contact decides before the response (Open, Approaching,
// Deactivate, or Penalty for a pair in contact); a pair in contact may then still Leave (classify_step) or
// switch to a row, Lagrange (lagrange_class), once its step is known.
enum class PairClass {
  Open,         // not in contact, not about to be: nothing acts, its friction history ends
  Approaching,  // not in contact yet, but closing within two steps, resting on the gap's edge or held
  Penalty,      // in contact: the penalty (or its /CTCLAW law) acts
  Lagrange,     // LAGDT: a row of the multiplier solve instead (section 6)
  Leave,        // /DT/INTER/DEL: its step fell below Tmin
  Deactivate,   // the penalty cannot hold it any more
};
struct ContactClass {
  PairClass cls = PairClass::Penalty;
  bool approaching = false;  // closing within two steps at its approach speed
  bool on_edge = false;      // a LAGDT node resting on the gap's edge
};

struct NormalResponse {
  double fn = 0, kt = 0, cdamp = 0;  // normal force, tangent stiffness, damping coefficient
  Vec3 f_el{}, f_dp{};               // elastic and damping forces on the secondary node
};
struct FrictionResponse {
  Vec3 f{};      // on the secondary node
  double c = 0;  // the viscous slope, a dashpot for the step
};
struct PairStep {
  double keff = 0;                          // the stiffness the pair votes with
  double dt_spring = kInf, dt_pair = kInf;  // the spring's step; the kinematic and dashpot limits
  double dt_vote = kInf;                    // the pair's own vote
};

// The row of the pair, if it switches.
SwitchedPair pair_row(const InterfaceState& st, const PairGeometry& pg, const PairContact& pc) {
  return SwitchedPair{pg.node,    st.segments[pg.sb], pg.h,     pg.n, pg.d,
                      pc.row_gap, pc.row_area,        st.index, pc.t1};
}

// The pair's class before its response: in contact when its law (or the penalty) pushes; otherwise open,
// or approaching when it is about to close, rests on the gap's edge or is held by its row.
template <LawVariant V>
[[gnu::always_inline]] inline ContactClass classify_contact(const PairGeometry& pg, const PairContact& pc,
                                                            const CycleFlags& f) {
  const double p = pg.p, g = pg.g, vn = pc.vn, ms = pc.ms, onset = pc.onset;
  if (V.normal ? !(pc.pr.p > 0) : !(p > 0)) {
    // A pair about to close (within two steps at its approach speed) already votes with its stiffness at
    // p = 0: the step must be small before the force appears, because the velocity update of the first
    // contact cycle uses (dt1 + dt2)/2, half of it from the step before.
    // Not under /DT/INTER/DEL when the pair's step at p = 0 is already below Tmin: it will leave the
    // interface as soon as it closes (k_eff >= K), so it must not pull the step below Tmin before.
    const double k_close = V.normal ? law_reach_stiffness(pc.law, pc.area_s, onset, -vn, f.dt1) : pc.K;
    const bool leaves =
        f.deletes && ms > 0 && k_close > 0 && f.scale * std::sqrt(2.0 * ms / k_close) < f.t_min;
    // A LAGDT node resting on the gap's edge (a row of the last cycle stopped it there, p = 0 to
    // round-off) keeps its row: without it the forces behind it would push it one step into the gap
    // before it switches again. The row costs nothing when it does not bind: the active set releases it.
    // (From the law's onset for a law that acts beyond the gap.)
    const double edge = std::isfinite(onset) ? onset : 0.0;
    const bool on_edge = f.lagdt && edge - p <= kEdgeBand * g;
    const bool approaching = vn < 0 && onset - p < -2.0 * vn * f.dt1;
    const bool closing = (approaching || on_edge || pc.held) && !leaves;
    return {closing ? PairClass::Approaching : PairClass::Open, approaching, on_edge};
  }
  // A node whose remaining gap is below 1e-6 of the gap cannot be held by the penalty.
  if ((g - p) / g < 1e-6) return {PairClass::Deactivate};
  return {PairClass::Penalty};
}

// Normal response: force, tangent stiffness and the VISs damping: the law's P A_s and Kc A_s with the
// plain critical-damping fraction (the hyperbola's 1/sqrt(r) and quadratic terms belong to its pole), or
// the interface's penalty.
template <LawVariant V>
[[gnu::always_inline]] inline NormalResponse normal_response(const model::Interface& in,
                                                             const PairGeometry& pg, const PairContact& pc) {
  NormalResponse r;
  r.fn = V.normal ? pc.pr.p * pc.area_s : penalty_force(pc.K, pg.g, pg.p);
  r.kt = V.normal ? pc.pr.kc * pc.area_s : penalty_tangent_stiffness(pc.K, pg.g, pg.p);
  r.cdamp = V.normal ? in.vis_s * std::sqrt(2.0 * r.kt * pc.ms)
                     : damping_coefficient(in.vis_s, pc.K, pg.g, pg.p, pc.ms, pc.vn);
  r.f_el = model::scale(pg.n, r.fn);
  // A law's damping never pulls: on the exponential tail P is tiny while c = VISs sqrt(2 Kc A_s m) is
  // not, and a separating node would be held back by a force its law does not have.
  const double f_damp = V.normal ? std::max(-r.cdamp * pc.vn, -r.fn) : -r.cdamp * pc.vn;
  r.f_dp = model::scale(pg.n, f_damp);
  return r;
}

// Friction by the pair's /CTCLAW law, at its pressure on A_s.
// A regularised law's force is bounded by what stops the slip within the step (mobility: 1 / m_slip), so it
// is no dashpot for the step.
template <LawVariant V>
[[gnu::always_inline]] inline FrictionResponse law_friction(const InterfaceState& st, const PairGeometry& pg,
                                                            const PairContact& pc, const NormalResponse& nr,
                                                            const Vec3& vt, double dt1, double mobility) {
  FrictionResponse r;
  const auto& law = pc.law;
  if (law.friction != model::FrictionLaw::None) {
    const double pressure = V.normal ? pc.pr.p : (pc.area_s > 0 ? nr.fn / pc.area_s : 0.0);
    const LawFrictionInput li{vt,       pg.n,      pc.t1, rotated_into_plane(st.f_t[pg.ks], pg.n),
                              pressure, pc.area_s, dt1,   mobility};
    r.f = law_friction_force(law, li);
  }
  return r;
}

// Friction by the interface's Ifric law and Iform.
[[gnu::always_inline]] inline FrictionResponse interface_friction(const InterfaceState& st,
                                                                  const PairGeometry& pg,
                                                                  const PairContact& pc,
                                                                  const NormalResponse& nr, const Vec3& vt,
                                                                  const CycleFlags& f) {
  FrictionResponse r;
  const auto& in = *st.in;
  const double area = st.segment_area0[pg.sb];
  const double speed = model::norm(vt);
  const double mu = friction_coefficient(in.ifric, in.fric, in.c, area > 0 ? nr.fn / area : 0.0, speed);
  const Vec3 old = rotated_into_plane(st.f_t[pg.ks], pg.n);
  r.c = in.iform == 2 ? 0.0 : in.vis_f * std::sqrt(2.0 * pc.K * pc.ms);
  FrictionInput fi;
  fi.iform = in.iform == 2 ? 2 : 1;
  fi.mu = mu;
  fi.normal_force = std::abs(nr.fn - nr.cdamp * pc.vn);
  fi.K = pc.K;
  fi.mass = pc.ms;
  fi.vis_f = in.vis_f;
  fi.dt = f.dt1;
  fi.alpha = f.alpha;
  fi.v_t = vt;
  fi.f_old = old;
  const auto ft = tangential_force(fi);
  r.f = {ft[0], ft[1], ft[2]};
  return r;
}

// Friction, and its viscous slope (Iform 1: a dashpot for the step); the node's friction history takes the
// force. mobility: 1 / m_slip of the pair (slip_mobility), for a /CTCLAW friction law.
template <LawVariant V>
[[gnu::always_inline]] inline FrictionResponse friction(InterfaceState& st, const PairGeometry& pg,
                                                        const PairContact& pc, const NormalResponse& nr,
                                                        const CycleFlags& f, double mobility) {
  const auto& in = *st.in;
  FrictionResponse r;
  Vec3 vt = model::sub(pc.vr, model::scale(pg.n, pc.vn));
  if (V.friction)
    r = law_friction<V>(st, pg, pc, nr, vt, f.dt1, mobility);
  else if (in.fric > 0 || in.ifric > 0)
    r = interface_friction(st, pg, pc, nr, vt, f);
  st.f_t[pg.ks] = r.f;
  return r;
}

// Time step of the pair (4.4), before anything is applied: under /DT/INTER/DEL a pair below Tmin leaves
// the interface without acting in this cycle (no force, no IBC release, no stiffness).
template <LawVariant V>
[[gnu::always_inline]] inline PairStep pair_step(const PairGeometry& pg, const PairContact& pc,
                                                 const NormalResponse& nr, const FrictionResponse& fr,
                                                 const CycleFlags& f) {
  const double g = pg.g, p = pg.p, ms = pc.ms, K = pc.K, vn = pc.vn, kt = nr.kt, cdamp = nr.cdamp;
  const double scale = f.scale;
  const double xi = ms > 0 && kt > 0 ? cdamp / (2.0 * std::sqrt(kt * ms)) : 0.0;
  const double shrink = std::sqrt(1.0 + xi * xi) - xi;
  // Voted with the stiffness the pair can reach within the step (reach_factor): tau0 = the step at p = 0.
  // Not under /DT/INTER/CST on a plain TYPE7: there the step is held at Tmin by added mass, computed from
  // k_eff as docs/theory/type7-lagdt.md section 6 writes it.
  // A /CTCLAW law votes with law_reach_stiffness, and exact Coulomb's sticking spring kappa A_s when
  // stiffer (a spring across the normal one: their directions are orthogonal, so the larger one sets the
  // step).
  const double reach = ms > 0 && !f.mass_scaled ? reach_factor(scale * std::sqrt(2.0 * ms / K), g, -vn) : 1.0;
  double k_vote = V.normal ? law_reach_stiffness(pc.law, pc.area_s, p, -vn, f.dt1) : kt * reach;
  if (V.law && pc.law.friction == model::FrictionLaw::Coulomb)
    k_vote = std::max(k_vote, pc.law.kappa * pc.area_s);
  PairStep s;
  s.keff = k_vote / (shrink * shrink);
  s.dt_spring = ms > 0 ? scale * std::sqrt(2.0 * ms / s.keff) : kInf;
  double dt_pair = 0.5 * (g - p) / std::max(-vn, kTiny);  // kinematic
  // Dashpots computed with v^{n-1/2} overshoot when c dt / m > 1 (the velocity they damp changes sign
  // every cycle): the normal damping c and the viscous friction (C = VISF sqrt(2 K m) for Iform 1) keep
  // dt <= m / c. (A /CTCLAW law's friction is bounded by the slip it can stop instead: fr.c = 0.)
  const double c_total = cdamp + fr.c;
  if (c_total > 0) {
    double dt_dash = scale * ms / c_total;
    // Under /DT/INTER/CST (plain TYPE7) the step must stay at Tmin: this limit keeps a margin of more
    // than two to the dashpot's stability bound 2 m / c, so it is not allowed below Tmin there.
    if (f.mass_scaled) dt_dash = std::max(dt_dash, f.t_min);
    dt_pair = std::min(dt_pair, dt_dash);
  }
  s.dt_pair = dt_pair;
  // The pair's own vote: kinematic and dashpot limits, and the spring's step (never below the nodal step
  // of a free node, so redundant there) except under /DT/INTER/CST on a plain TYPE7, where the nodal step
  // adds mass to stay at Tmin and the pair's step, taken with the mass before that, must not undercut it.
  if (!f.mass_scaled) dt_pair = std::min(dt_pair, s.dt_spring);
  s.dt_vote = dt_pair;
  return s;
}

// A pair in contact once its step is known: under /DT/INTER/DEL it leaves when the step is below Tmin.
[[gnu::always_inline]] inline PairClass classify_step(const PairStep& s, const CycleFlags& f) {
  return f.deletes && std::min(s.dt_spring, s.dt_pair) < f.t_min ? PairClass::Leave : PairClass::Penalty;
}

}  // namespace

struct Type7Contact::Impl {
  const model::Model& model;
  ContactControls controls;
  std::vector<InterfaceState> interfaces;
  std::vector<double> force;          // [3 nodes]
  std::vector<std::int32_t> touched;  // nodes with a force this cycle, ascending
  std::vector<std::uint8_t> is_touched;
  std::vector<std::string> messages;
  std::vector<std::int32_t> elements_around0;  // elements at each node at the start (Idel node removal)
  // Contact stiffness summed per node this cycle, for the nodal stability steps.
  std::vector<double> k_sum;
  std::vector<std::int32_t> k_nodes;
  std::vector<std::int64_t> k_interface;     // an interface that touched the node (for the listing)
  std::vector<std::uint8_t> k_mass_scaling;  // a plain TYPE7 pair touched it (/DT/INTER/CST adds mass)
  // LAGDT.
  std::vector<PendingPair> pending;
  std::vector<SwitchedPair> switched;     // this cycle's rows, in interface then node order
  std::vector<double> switched_p;         // their penetrations (results)
  std::vector<std::int32_t> switched_ks;  // their secondary indices
  std::vector<std::pair<std::int32_t, std::int32_t>>
      pushed;                     // (interface, secondary index) with row_pushed set
  std::vector<FrictionLaw> laws;  // per interface
  std::vector<PairForce> lagrange_out;
  std::vector<LagrangeRecord> lagrange_records;
  std::vector<NodeForce> lagrange_forces;
  std::vector<double> lagrange_buf;  // [3 nodes], zero outside a call
  std::vector<std::int32_t> lagrange_touched;
  LagrangeSolver lagrange;
  // The engine's threads (set_parallel_for); empty: in order on the calling thread.
  ParallelFor parallel;

  // LAGDT pairs switch under /DT/INTER/CST or /DT/INTER/LAG with a Tmin.
  [[nodiscard]] bool lagrange_on() const {
    return controls.t_min > 0 && (controls.action == ContactControls::Action::AddMass ||
                                  controls.action == ContactControls::Action::Lagrange);
  }

  // The pair's own stable step: min over its free nodes of scale sqrt(2 m_i / G_i), G the pair's
  // Gershgorin row sums (add_pair_stiffness) for the spring k.
  double pair_spring_step(std::int32_t s_node, const std::array<std::int32_t, 4>& seg,
                          const std::array<double, 4>& h, double k, const ContactNodes& nodes) const {
    auto is_free = [&](std::int32_t n) { return (nodes.fixed[static_cast<std::size_t>(n)] & 7u) != 7u; };
    auto mass = [&](std::int32_t n) { return nodes.mass[static_cast<std::size_t>(n)]; };
    const bool triangle = seg[3] == seg[2];
    double h_free = 0;
    for (std::size_t j = 0; j < 4; ++j)
      if (h[j] > 0 && !(j == 3 && triangle) && is_free(seg[j])) h_free += h[j];
    const bool s_free = is_free(s_node);
    double dt = kInf;
    const double scale = controls.dt_scale;
    if (s_free && mass(s_node) > 0)
      dt = std::min(dt, scale * std::sqrt(2.0 * mass(s_node) / (k * (1.0 + h_free))));
    for (std::size_t j = 0; j < 4; ++j)
      if (h[j] > 0 && !(j == 3 && triangle) && is_free(seg[j]) && mass(seg[j]) > 0)
        dt = std::min(dt,
                      scale * std::sqrt(2.0 * mass(seg[j]) / (h[j] * k * ((s_free ? 1.0 : 0.0) + h_free))));
    return dt;
  }

  // The pair's slip mobility 1 / m_slip = [s free] / m_s + sum_j [j free] h_j^2 / m_j (1/kg): the change of
  // the relative velocity per unit force on the secondary node (and -h_j of it on main node j); 0 when
  // nothing can move. The same measure as a LAGDT row's (lagrange_contact.cpp). A node whose motion a
  // kinematic condition sets (imposed velocity, rigid body, rigid wall: `held`) does not yield to the pair's
  // force with its own nodal mass: it counts as fixed, so a rigid impactor's pairs are not capped below
  // the law's force.
  double slip_mobility(std::int32_t s_node, const std::array<std::int32_t, 4>& seg,
                       const std::array<double, 4>& h, const ContactNodes& nodes) const {
    auto is_free = [&](std::int32_t n) {
      const auto k = static_cast<std::size_t>(n);
      return (nodes.fixed[k] & 7u) != 7u && (nodes.held.empty() || !nodes.held[k]);
    };
    auto inverse_mass = [&](std::int32_t n) {
      const double m = nodes.mass[static_cast<std::size_t>(n)];
      return is_free(n) && m > 0 ? 1.0 / m : 0.0;
    };
    const bool triangle = seg[3] == seg[2];
    double w = inverse_mass(s_node);
    for (std::size_t j = 0; j < 4; ++j)
      if (h[j] > 0 && !(j == 3 && triangle)) w += h[j] * h[j] * inverse_mass(seg[j]);
    return w;
  }

  // Whether a LAGDT pair that would switch may: not when a kinematic condition other than /BCS moves one of
  // its nodes after step 6 (it would undo the correction); reported once per interface.
  bool may_switch(InterfaceState& st, const SwitchedPair& row, const ContactNodes& nodes) {
    if (nodes.held.empty()) return true;
    std::int32_t held = -1;
    if (nodes.held[static_cast<std::size_t>(row.node)]) held = row.node;
    for (std::size_t j = 0; j < 4 && held < 0; ++j)
      if (row.h[j] > 0 && nodes.held[static_cast<std::size_t>(row.seg[j])]) held = row.seg[j];
    if (held < 0) return true;
    if (!st.warned_held) {
      st.warned_held = true;
      messages.push_back("interface " + std::to_string(st.in->id) + ": node " +
                         std::to_string(model.nodes.id[static_cast<std::size_t>(held)]) +
                         " has an imposed velocity, a rigid body or a rigid wall: LAGDT pairs on such nodes "
                         "stay on the penalty path (reported once per interface)");
    }
    return false;
  }

  void switch_pair(InterfaceState& st, const SwitchedPair& row, std::size_t ks, double p) {
    switched.push_back(row);
    switched_p.push_back(p);
    switched_ks.push_back(static_cast<std::int32_t>(ks));
    st.f_t[ks] = Vec3{};
    ++st.result.switched_pairs;
  }

  void release_ibc(InterfaceState& st, std::size_t ks, std::int32_t node, const ContactNodes& nodes) {
    if (st.hit[ks]) return;
    st.hit[ks] = 1;
    std::uint8_t mask = 0;
    for (unsigned d = 0; d < 3; ++d)
      if (st.in->ibc[d]) mask = static_cast<std::uint8_t>(mask | (1u << d));
    if (mask) nodes.fixed[static_cast<std::size_t>(node)] &= static_cast<std::uint8_t>(~mask);
  }

  // After every interface's pairs are computed: their stiffness summed per node, then a LAGDT pair on a node
  // whose summed step falls below Tmin switches too (several pairs at one node add up), so that the
  // step never falls below Tmin for LAGDT pairs.
  void settle_switches(const ContactNodes& nodes) {
    for (const auto& q : pending) add_pair_stiffness(q.row.node, q.row.seg, q.row.h, q.keff, nodes, *q.st);
    if (!lagrange_on()) return;
    const double scale = controls.dt_scale;
    auto below = [&](std::int32_t n) {
      const auto i = static_cast<std::size_t>(n);
      const double k = k_sum[i];
      return (nodes.fixed[i] & 7u) != 7u && k > 0 && nodes.mass[i] > 0 &&
             scale * std::sqrt(2.0 * nodes.mass[i] / k) < controls.t_min;
    };
    for (auto& q : pending) {
      if (!q.switchable) continue;
      bool low = below(q.row.node);
      for (std::size_t j = 0; j < 4 && !low; ++j) low = q.row.h[j] > 0 && below(q.row.seg[j]);
      if (!low) continue;
      add_pair_stiffness(q.row.node, q.row.seg, q.row.h, -q.keff, nodes, *q.st);
      switch_pair(*q.st, q.row, q.ks, q.p);
      q.st = nullptr;  // applied as a row, not as a penalty pair
    }
  }

  // Scatters a penalty pair's forces, books the current half of its work and records its vote.
  void apply_pair(const PendingPair& q, ContactStep& vote) {
    auto& st = *q.st;
    const auto& seg = q.row.seg;
    Vec3 f_total{};
    for (std::size_t d = 0; d < 3; ++d) f_total[d] = q.f_el[d] + q.f_dp[d] + q.f_fr[d];
    add_force(q.row.node, f_total);
    for (std::size_t j = 0; j < 4; ++j) {
      if (q.row.h[j] == 0) continue;
      if (j == 3 && seg[3] == seg[2]) continue;
      add_force(seg[j], model::scale(f_total, -q.row.h[j]));
    }
    st.pairs.push_back(PairRecord{q.row.node, seg, q.row.h, q.f_el, q.f_dp, q.f_fr});
    // The other half of the step's work (see book_work): this cycle's force with v^{n-1/2}.
    st.w_elastic.add(0.5 * model::dot(q.f_el, q.vr) * dt1_);
    st.w_damping.add(0.5 * model::dot(q.f_dp, q.vr) * dt1_);
    st.w_friction.add(0.5 * model::dot(q.f_fr, q.vr) * dt1_);
    ++st.result.active_pairs;
    st.result.max_penetration = std::max(st.result.max_penetration, q.p);
    for (std::size_t d = 0; d < 3; ++d) {
      st.normal_force[d].add(q.f_el[d] + q.f_dp[d]);
      st.tangential_force[d].add(q.f_fr[d]);
    }
    if (q.dt_vote < vote.dt) {
      vote.dt = q.dt_vote;
      vote.interface_id = st.in->id;
      vote.node_id = model.nodes.id[static_cast<std::size_t>(q.row.node)];
    }
  }
  double dt1_ = 0;  // the step of the cycle being computed

  void add_stiffness(std::int32_t n, double k, const InterfaceState& st) {
    const auto i = static_cast<std::size_t>(n);
    if (k_sum[i] == 0) {
      k_nodes.push_back(n);
      k_interface[i] = st.in->id;
      k_mass_scaling[i] = 0;
    }
    k_sum[i] += k;
    if (!st.in->lagdt) k_mass_scaling[i] = 1;
  }

  // The pair's spring k between the node s and the point sum h_j x_j adds to each free node's row of
  // M^-1 K the sum of its absolute entries (Gershgorin): G_s = k (1 + sum_free h_j),
  // G_j = h_j k ([s free] + sum_free h_l). A node fixed in X, Y and Z does not move and takes nothing.
  void add_pair_stiffness(std::int32_t s_node, const std::array<std::int32_t, 4>& seg,
                          const std::array<double, 4>& h, double k, const ContactNodes& nodes,
                          const InterfaceState& st) {
    auto is_free = [&](std::int32_t n) { return (nodes.fixed[static_cast<std::size_t>(n)] & 7u) != 7u; };
    const bool triangle = seg[3] == seg[2];
    double h_free = 0;
    for (std::size_t j = 0; j < 4; ++j)
      if (h[j] > 0 && !(j == 3 && triangle) && is_free(seg[j])) h_free += h[j];
    const bool s_free = is_free(s_node);
    if (s_free) add_stiffness(s_node, k * (1.0 + h_free), st);
    for (std::size_t j = 0; j < 4; ++j)
      if (h[j] > 0 && !(j == 3 && triangle) && is_free(seg[j]))
        add_stiffness(seg[j], h[j] * k * ((s_free ? 1.0 : 0.0) + h_free), st);
  }

  // Nodal steps dt = scale sqrt(2 m / G) (G the Gershgorin row sums above: for a node against a fixed
  // segment G = k_eff and this is docs/theory/type7-lagdt.md 4.4's sqrt(2 m / k_eff); when both sides move
  // the relative motion is stiffer and the step shrinks with it); /DT/INTER/CST on plain TYPE7 adds mass
  // below Tmin.
  ContactStep nodal_steps(const ContactNodes& nodes) {
    ContactStep vote;
    std::sort(k_nodes.begin(), k_nodes.end());
    const double scale = controls.dt_scale;
    for (const auto n : k_nodes) {
      const auto i = static_cast<std::size_t>(n);
      const double k = k_sum[i];
      k_sum[i] = 0;
      auto& m = nodes.mass[i];
      if (!(k > 0) || m <= 0) continue;
      double dt = scale * std::sqrt(2.0 * m / k);
      if (controls.t_min > 0 && dt < controls.t_min && controls.action == ContactControls::Action::AddMass &&
          k_mass_scaling[i]) {
        const double m_new = 0.5 * k * (controls.t_min / scale) * (controls.t_min / scale);
        nodes.added_mass[i] += m_new - m;
        for (auto& st : interfaces)
          if (st.in->id == k_interface[i]) st.result.added_mass += m_new - m;
        m = m_new;
        dt = controls.t_min;
      }
      if (dt < vote.dt) {
        vote.dt = dt;
        vote.interface_id = k_interface[i];
        vote.node_id = model.nodes.id[i];
      }
    }
    k_nodes.clear();
    return vote;
  }

  Impl(const model::Model& m, ContactControls c) : model(m), controls(c) {
    for (const auto& in : m.interfaces) {
      if (in.main_surface == model::kNone || in.secondary_nodes.empty()) continue;
      InterfaceState st;
      st.in = &in;
      const auto& surf = m.surfaces[static_cast<std::size_t>(in.main_surface)];
      st.segments = surf.segments;
      const std::size_t ns = in.secondary_nodes.size(), nm = st.segments.size();
      st.node_off.assign(ns, 0);
      st.segment_off.assign(nm, 0);
      st.reduction.assign(ns, 0.0);
      st.f_t.assign(ns, Vec3{});
      st.hit.assign(ns, 0);
      // The starter's initial-penetration treatment holds for an interface active from t = 0; with Tstart > 0
      // or a sensor the engine treats the penetrations it finds when the interface starts
      // (start_penetrations).
      st.sensor = m.sensor_index(in.sens_id);
      const bool from_start = !(in.t_start > 0) && st.sensor == model::kNone;
      st.from_start = from_start;
      for (const auto s : in.inactive_segments)
        if (from_start) st.segment_off[static_cast<std::size_t>(s)] = 1;
      for (const auto node : from_start ? in.inactive_nodes : std::vector<std::int32_t>{}) {
        const auto it = std::lower_bound(in.secondary_nodes.begin(), in.secondary_nodes.end(), node);
        if (it != in.secondary_nodes.end() && *it == node)
          st.node_off[static_cast<std::size_t>(it - in.secondary_nodes.begin())] = 1;
      }
      for (std::size_t k = 0; from_start && k < in.penetrating_nodes.size(); ++k) {
        const auto it =
            std::lower_bound(in.secondary_nodes.begin(), in.secondary_nodes.end(), in.penetrating_nodes[k]);
        if (it != in.secondary_nodes.end() && *it == in.penetrating_nodes[k])
          st.reduction[static_cast<std::size_t>(it - in.secondary_nodes.begin())] =
              in.initial_gap_reduction[k];
      }
      st.tributary_area = in.tributary_area;
      st.row_pushed.assign(ns, 0);
      st.segment_area0.resize(nm);
      for (std::size_t s = 0; s < nm; ++s) {
        std::array<Vec3, 4> x{};
        for (int j = 0; j < 4; ++j) {
          const auto n = static_cast<std::size_t>(st.segments[s][static_cast<std::size_t>(j)]);
          x[static_cast<std::size_t>(j)] = {m.nodes.x[n], m.nodes.y[n], m.nodes.z[n]};
        }
        st.segment_area0[s] = segment_area(x, st.segments[s][2] == st.segments[s][3]);
      }
      // Model cell of each segment's owner element (cells: 4-node shells, 3-node shells, bricks, tetrahedra).
      st.owner_cell.assign(nm, -1);
      for (std::size_t s = 0; s < nm && s < surf.owner.size(); ++s) {
        const auto o = surf.owner[s];
        if (o == model::kNone) continue;
        std::size_t base = 0;
        switch (surf.owner_type[s]) {
          case model::SegmentOwner::Shell4: base = 0; break;
          case model::SegmentOwner::Shell3: base = m.shells.size(); break;
          case model::SegmentOwner::Brick8: base = m.shells.size() + m.shells3.size(); break;
          case model::SegmentOwner::Tetra4:
            base = m.shells.size() + m.shells3.size() + m.bricks.size();
            break;
          default: continue;
        }
        st.owner_cell[s] = static_cast<std::int32_t>(base + static_cast<std::size_t>(o));
      }
      // A /CTCLAW law that acts at open gaps (exponential, a table still pushing at gap 0) reaches beyond the
      // gap by its onset: the search looks that much further so that the law ends where it says, not where
      // the last sort happened to stop (the smallest lambda: stiff_lo over the largest area).
      double law_reach = 0;
      if (in.contact_law_id != 0) {
        double area_hi = in.tributary_area_range().second;
        for (const double a : st.segment_area0) area_hi = std::max(area_hi, a);
        if (area_hi > 0)
          law_reach = std::max(0.0, -contact_onset(resolve_pair_law(in.law, m, in.stiff_lo, area_hi)));
      }
      const double gap_max = (in.igap == 0 ? in.gapmin : std::max(in.gap_hi, in.gapmin)) + law_reach;
      st.search = std::make_unique<Type7Search>(in.secondary_nodes, st.segments, gap_max, in.bumult);
      st.result.id = in.id;
      st.index = static_cast<std::int32_t>(interfaces.size());
      FrictionLaw law{std::max(0, in.ifric), in.fric, in.c, {}};
      if (in.contact_law_id != 0) {
        law.ctclaw.friction = in.law.friction;
        law.ctclaw.bidirectional = in.law.bidirectional;
        law.ctclaw.mu = in.law.mu;
        law.ctclaw.ct = in.law.ct;
      }
      laws.push_back(law);
      interfaces.push_back(std::move(st));
    }
    force.assign(3 * m.nodes.size(), 0.0);
    is_touched.assign(m.nodes.size(), 0);
    elements_around0.assign(m.nodes.size(), 0);
    for (const auto* b : {&m.shells, &m.shells3, &m.bricks, &m.tetras, &m.bricks20}) {
      const auto npe = static_cast<std::size_t>(b->npe());
      for (std::size_t e = 0; e < b->size(); ++e)
        for (std::size_t k = 0; k < npe; ++k)
          if (b->conn[e * npe + k] >= 0) ++elements_around0[static_cast<std::size_t>(b->conn[e * npe + k])];
    }
    k_sum.assign(m.nodes.size(), 0.0);
    k_interface.assign(m.nodes.size(), 0);
    k_mass_scaling.assign(m.nodes.size(), 0);
    lagrange_buf.assign(3 * m.nodes.size(), 0.0);
  }

  void touch(std::int32_t n) {
    const auto k = static_cast<std::size_t>(n);
    if (!is_touched[k]) {
      is_touched[k] = 1;
      touched.push_back(n);
    }
  }

  void add_force(std::int32_t n, const Vec3& f) {
    touch(n);
    const auto k = 3 * static_cast<std::size_t>(n);
    force[k] += f[0];
    force[k + 1] += f[1];
    force[k + 2] += f[2];
  }

  // Work over the step just taken, trapezoidal in the force as the engine books element and load work:
  // 1/2 (F^{n-1} + F^n) . v_r^{n-1/2} dt1, v_r = v_s - sum h_j v_j with each pair's own weights. The first
  // half (last cycle's forces) is booked here, the second when this cycle's forces are computed.
  void book_work(InterfaceState& st, const ContactNodes& nodes, double dt1) {
    for (const auto& p : st.pairs) {
      const Vec3 vr = relative_velocity(velocity(nodes), p.node, p.seg, p.h);
      st.w_elastic.add(0.5 * model::dot(p.f_elastic, vr) * dt1);
      st.w_damping.add(0.5 * model::dot(p.f_damping, vr) * dt1);
      st.w_friction.add(0.5 * model::dot(p.f_friction, vr) * dt1);
    }
  }

  // The second half of the last cycle's multiplier work, over [t^n, t^{n+1/2}] with the mean velocity
  // (v_r^n + v_r^{n+1/2}) / 2, now that v^{n+1/2} is known (the velocities of this call).
  void book_lagrange_work(const ContactNodes& nodes) {
    for (const auto& r : lagrange_records) {
      const Vec3 vr = relative_velocity(velocity(nodes), r.node, r.seg, r.h);
      const Vec3 vmean = model::scale(model::add(vr, r.vr_full), 0.5);
      auto& st = interfaces[static_cast<std::size_t>(r.iface)];
      st.w_lagrange.add(model::dot(r.f_normal, vmean) * 0.5 * r.dt2);
      st.w_friction.add(model::dot(r.f_friction, vmean) * 0.5 * r.dt2);
    }
    lagrange_records.clear();
  }

  void deactivate(InterfaceState& st, std::size_t k, const std::string& why) {
    st.node_off[k] = 1;
    st.search->remove_node(static_cast<std::int32_t>(k));
    ++st.result.deactivated_nodes;
    messages.push_back("interface " + std::to_string(st.in->id) + ": secondary node " +
                       std::to_string(model.nodes.id[static_cast<std::size_t>(st.in->secondary_nodes[k])]) +
                       " " + why);
  }

  // A_s of secondary node ks (its tributary area from the starter), or the area of segment sb it hits when it
  // has none (a free node).
  double law_area(const InterfaceState& st, std::size_t ks, std::size_t sb) const {
    const auto& a = st.tributary_area;
    return ks < a.size() && a[ks] > 0 ? a[ks] : st.segment_area0[sb];
  }

  struct Closest {
    std::int32_t segment = -1;
    double d = kInf;
    std::array<double, 4> h{};
    std::array<Vec3, 4> x{};
  };
  // The closest of the candidate segments cand[c .. end) of one node at xs (removed segments skipped).
  // Reads only the coordinates and the interface's segments: the candidate stage runs it on any thread.
  static Closest closest_segment(const InterfaceState& st, const std::vector<Candidate>& cand, std::size_t c,
                                 std::size_t end, const Vec3& xs, const ContactNodes& nodes) {
    Closest best;
    for (std::size_t q = c; q < end; ++q) {
      const auto s = static_cast<std::size_t>(cand[q].segment);
      if (st.segment_off[s]) continue;
      std::array<Vec3, 4> x{};
      for (std::size_t j = 0; j < 4; ++j) x[j] = node_x(nodes, st.segments[s][j]);
      std::array<double, 4> h{};
      const double d = closest_point_segment(xs, x, st.segments[s][2] == st.segments[s][3], h);
      if (d < best.d) best = Closest{cand[q].segment, d, h, x};
    }
    return best;
  }

  // Candidates per chunk of the closest-segment stage (some tens of microseconds of work each).
  static constexpr std::int64_t kCandidateChunk = 512;
  // A node's closest segment, kept at the index of its first candidate (the corners are read again from
  // the coordinates when used: the same loads give the same values).
  struct NodeClosest {
    std::int32_t segment;
    double d;
    std::array<double, 4> h;
  };
  std::vector<NodeClosest> closest;  // [candidates]

  // Stage A of interface_cycle: the closest segment of every active secondary node with candidates, into
  // `closest`. Pure (closest_segment writes nothing shared), so it runs in chunks on the engine's threads:
  // chunk c takes the nodes whose first candidate lies in [c kCandidateChunk, (c + 1) kCandidateChunk), a
  // division fixed by the candidate list alone; each node's entry is written by exactly one chunk.
  void closest_stage(const InterfaceState& st, const std::vector<Candidate>& cand,
                     const ContactNodes& nodes) {
    const auto n = static_cast<std::int64_t>(cand.size());
    closest.resize(cand.size());
    const auto& secondary = st.in->secondary_nodes;
    NodeClosest* out = closest.data();
    const auto body = [&, n, out](std::int64_t chunk) {
      const std::int64_t stop = std::min(n, (chunk + 1) * kCandidateChunk);
      std::int64_t c = chunk * kCandidateChunk;
      while (c > 0 && c < n &&
             cand[static_cast<std::size_t>(c)].node == cand[static_cast<std::size_t>(c - 1)].node)
        ++c;  // that node's group belongs to the chunk where it starts
      for_each_node(cand, static_cast<std::size_t>(c), static_cast<std::size_t>(stop),
                    [&](std::size_t ks, std::size_t first, std::size_t end) {
                      if (st.node_off[ks]) return;
                      const Vec3 xs = node_x(nodes, secondary[ks]);
                      const Closest cl = closest_segment(st, cand, first, end, xs, nodes);
                      out[first] = NodeClosest{cl.segment, cl.d, cl.h};
                    });
    };
    run_chunks(&parallel, (n + kCandidateChunk - 1) / kCandidateChunk, body);
  }

  // docs/theory/type7-lagdt.md 4.6 at Tstart > 0 or under a sensor (the starter treated t = 0 otherwise):
  // nodes already closer than the gap when the interface starts get the Inacti treatment then, from the
  // current coordinates.
  void start_penetrations(InterfaceState& st, const ContactNodes& nodes, double t) {
    const auto& in = *st.in;
    st.search->update(Coordinates{nodes.x, nodes.y, nodes.z}, true);
    const auto& cand = st.search->candidates();
    std::int64_t count = 0;
    double worst = 0;
    for_each_node(cand, 0, cand.size(), [&](std::size_t ks, std::size_t c, std::size_t end) {
      const std::int32_t node = in.secondary_nodes[ks];
      const Vec3 xs = node_x(nodes, node);
      const Closest cl = st.node_off[ks] ? Closest{} : closest_segment(st, cand, c, end, xs, nodes);
      if (cl.segment < 0) return;
      const double g = pair_gap(in, in.gap_node[ks], in.gap_segment[static_cast<std::size_t>(cl.segment)]);
      const double p0 = g - cl.d;
      if (!(p0 > 0)) return;
      ++count;
      worst = std::max(worst, p0);
      switch (in.inacti) {
        case 1: st.node_off[ks] = 1; break;
        case 2: st.segment_off[static_cast<std::size_t>(cl.segment)] = 1; break;
        case 3:
          if (cl.d > 0) {  // move the node out to the gap along the line from its closest point
            Vec3 q{};
            for (std::size_t j = 0; j < 4; ++j)
              for (std::size_t d = 0; d < 3; ++d) q[d] += cl.h[j] * cl.x[j][d];
            const auto n = static_cast<std::size_t>(node);
            const double f = g / cl.d;
            nodes.x[n] = q[0] + f * (xs[0] - q[0]);
            nodes.y[n] = q[1] + f * (xs[1] - q[1]);
            nodes.z[n] = q[2] + f * (xs[2] - q[2]);
          }
          break;
        case 5: st.reduction[ks] = p0; break;
        case 6: st.reduction[ks] = p0 + 0.05 * (g - p0); break;
        default: break;
      }
    });
    for (std::size_t g = 0; g < st.segment_off.size(); ++g)
      if (st.segment_off[g]) st.search->remove_segment(static_cast<std::int32_t>(g));
    for (std::size_t k = 0; k < st.node_off.size(); ++k)
      if (st.node_off[k]) st.search->remove_node(static_cast<std::int32_t>(k));
    if (count > 0)
      messages.push_back("interface " + std::to_string(in.id) + " starts at t = " + std::to_string(t) +
                         (st.sensor == model::kNone ? " (Tstart)" : " (its sensor)") + " with " +
                         std::to_string(count) + " secondary node(s) closer than the gap, largest " +
                         "penetration " + std::to_string(worst) + ": Inacti " + std::to_string(in.inacti) +
                         (in.inacti == 0 ? " (no action: the penalty pushes them out)" : " applied"));
  }

  // Closest pair: the gap of the pair with stage A's segment (Inacti 5, 6 reduced), its penetration and its
  // normal. False when there is no pair: no segment left, or no gap left.
  [[gnu::always_inline]] static bool closest_pair(InterfaceState& st, std::size_t ks, const NodeClosest& cl,
                                                  const ContactNodes& nodes, PairGeometry& pg) {
    const auto& in = *st.in;
    const std::int32_t node = in.secondary_nodes[ks];
    const Vec3 xs = node_x(nodes, node);
    const double best_d = cl.d;
    const std::int32_t best = cl.segment;
    const std::array<double, 4>& best_h = cl.h;
    if (best < 0) return false;  // no segment left (removed by Idel)
    const auto sb = static_cast<std::size_t>(best);
    std::array<Vec3, 4> best_x{};
    for (std::size_t j = 0; j < 4; ++j) best_x[j] = node_x(nodes, st.segments[sb][j]);
    const double g_full = pair_gap(in, in.gap_node[ks], in.gap_segment[sb]);
    // Inacti 5, 6: the reduced initial gap returns to the full gap as the pair opens.
    // Inacti 6 keeps 5 % of the open distance as margin: r = g - 0.95 d (= P0 + 0.05 (g - P0) at t = 0).
    if (st.reduction[ks] > 0)
      st.reduction[ks] =
          std::min(st.reduction[ks], std::max(0.0, g_full - (in.inacti == 6 ? 0.95 : 1.0) * best_d));
    const double g = g_full - st.reduction[ks];
    const double p = g - best_d;
    if (g <= 0) return false;
    // Normal from the contact point to the node (two-sided), or the segment normal.
    Vec3 cpt{};
    for (std::size_t j = 0; j < 4; ++j)
      for (std::size_t d = 0; d < 3; ++d) cpt[d] += best_h[j] * best_x[j][d];
    Vec3 n = model::sub(xs, cpt);
    if (best_d > 1e-12 * g) {
      n = model::scale(n, 1.0 / best_d);
    } else {
      n = model::quad_normal(best_x[0], best_x[1], best_x[2], best_x[3]);
      const double ln = model::norm(n);
      n = ln > 0 ? model::scale(n, 1.0 / ln) : Vec3{0, 0, 1};
    }
    pg = PairGeometry{ks, sb, node, best_h, best_x, best_d, g, p, n};
    return true;
  }

  // The pair's stiffness, mass and relative velocity, and its /CTCLAW law: a law (docs/theory/contact-laws.md
  // section 5) replaces the normal law, the friction law or both, with its forces on the tributary area A_s
  // of the node (the hit segment's area for a node without one).
  template <LawVariant V>
  [[gnu::always_inline]] PairContact pair_contact(const InterfaceState& st, const PairGeometry& pg,
                                                  const CycleFlags& f, const ContactNodes& nodes) const {
    const auto& in = *st.in;
    const auto ks = pg.ks, sb = pg.sb;
    const double p = pg.p, g = pg.g;
    PairContact pc;
    pc.K = pair_stiffness(in, in.stiff_segment[sb], in.stiff_node[ks]);
    pc.ms = nodes.mass[static_cast<std::size_t>(pg.node)];
    pc.vr = relative_velocity(velocity(nodes), pg.node, st.segments[sb], pg.h);
    pc.vn = model::dot(pc.vr, pg.n);
    pc.area_s = V.law ? law_area(st, ks, sb) : 0.0;
    pc.law = V.law ? resolve_pair_law(in.law, model, pc.K, pc.area_s) : PairLaw{};
    pc.pr = V.normal ? normal_pressure(pc.law, p) : Pressure{};
    pc.onset = V.normal ? contact_onset(pc.law) : 0.0;  // the exponential law acts at open gaps
    pc.t1 = V.law ? first_tangent(pg.x, pg.n) : Vec3{};
    pc.row_area = V.law ? pc.area_s : st.segment_area0[sb];
    // A law pair's row lets it close down to where its law starts (the gap, or beyond it for the
    // exponential law), no further: one that switches where its law already pushes is held where it is,
    // rather than losing the law's force and falling onto the gap.
    pc.row_gap = V.normal && std::isfinite(pc.onset) ? std::min(g - pc.onset, pg.d) : g;
    // A row that pushed in the last cycle stopped its node: the node keeps it while it needs it (the active
    // set releases a row that would pull). Judged again by its step it could fall back to the penalty path
    // for a cycle once stopped (no approach speed left to vote with) and be driven past where it stopped.
    pc.held = f.lagdt && st.row_pushed[ks] != 0;
    return pc;
  }

  // An approaching pair. LAGDT: a pair whose step at p = 0 is already below Tmin does not drag the step down
  // before it closes: it becomes a row that lets it close down to the gap within the step, no further.
  // It votes with the stiffness it can reach within the step (reach_factor, from the gap's edge where
  // the hyperbola is extended to p < 0), never less than K.
  template <LawVariant V>
  [[gnu::always_inline]] void approach(InterfaceState& st, const PairGeometry& pg, const PairContact& pc,
                                       const ContactClass& cc, const CycleFlags& f,
                                       const ContactNodes& nodes) {
    const double p = pg.p, g = pg.g, K = pc.K, ms = pc.ms, vn = pc.vn;
    const double tau0 = ms > 0 && !f.mass_scaled ? f.scale * std::sqrt(2.0 * ms / K) : 0.0;
    const double ratio = g / (g - p);
    // A law node resting on the edge (not approaching) is judged by its law just inside contact.
    const double k_reach =
        V.normal
            ? law_reach_stiffness(pc.law, pc.area_s, cc.on_edge ? std::max(p, kEdgeBand * g) : p, -vn, f.dt1)
            : std::max(K, K * ratio * ratio * reach_factor(tau0, g, -vn));
    const SwitchedPair row = pair_row(st, pg, pc);
    const auto& seg = st.segments[pg.sb];
    if (f.lagdt && (pc.held || pair_spring_step(pg.node, seg, pg.h, k_reach, nodes) < f.t_min) &&
        may_switch(st, row, nodes))
      switch_pair(st, row, pg.ks, 0.0);
    else if (cc.approaching && k_reach > 0)
      add_pair_stiffness(pg.node, seg, pg.h, k_reach, nodes, st);
  }

  // LAGDT: below Tmin the pair leaves the penalty path for this cycle and becomes a row (section 6), unless
  // a kinematic condition holds one of its nodes (may_switch; the pair then stays a penalty pair that cannot
  // switch later in the cycle either). Judged after release_ibc: a node whose IBC directions were just
  // released counts as free in its spring's step, as it is when the force acts.
  [[gnu::always_inline]] PairClass lagrange_class(PendingPair& q, const PairGeometry& pg,
                                                  const PairContact& pc, const CycleFlags& f,
                                                  const ContactNodes& nodes) {
    if (!f.lagdt) return PairClass::Penalty;
    auto& st = *q.st;
    const bool wants = pc.held || std::min(q.dt_vote, pair_spring_step(pg.node, st.segments[pg.sb], pg.h,
                                                                       q.keff, nodes)) < f.t_min;
    q.switchable = !wants || may_switch(st, q.row, nodes);
    return wants && q.switchable ? PairClass::Lagrange : PairClass::Penalty;
  }

  // One secondary node's pair in the cycle: closest pair, its class, normal response, friction, pair step,
  // then what it becomes (a row, a penalty pair in `pending`, or nothing).
  template <LawVariant V>
  [[gnu::always_inline]] void pair_cycle(InterfaceState& st, std::size_t ks, const NodeClosest& cl,
                                         const CycleFlags& f, const ContactNodes& nodes) {
    PairGeometry pg;
    if (!closest_pair(st, ks, cl, nodes, pg)) {  // the friction history ends with the contact
      st.f_t[ks] = Vec3{};
      return;
    }
    const PairContact pc = pair_contact<V>(st, pg, f, nodes);
    const ContactClass cc = classify_contact<V>(pg, pc, f);
    switch (cc.cls) {
      case PairClass::Open: st.f_t[ks] = Vec3{}; return;
      case PairClass::Approaching:
        st.f_t[ks] = Vec3{};
        approach<V>(st, pg, pc, cc, f, nodes);
        return;
      case PairClass::Deactivate:
        deactivate(st, ks, "reached the main surface (remaining gap below 1e-6 of the gap): deactivated");
        return;
      default: break;
    }
    const NormalResponse nr = normal_response<V>(*st.in, pg, pc);
    const double mobility = V.friction ? slip_mobility(pg.node, st.segments[pg.sb], pg.h, nodes) : 0.0;
    const FrictionResponse fr = friction<V>(st, pg, pc, nr, f, mobility);
    const PairStep ps = pair_step<V>(pg, pc, nr, fr, f);
    if (classify_step(ps, f) == PairClass::Leave) {
      st.f_t[ks] = Vec3{};
      deactivate(st, ks, "left the interface: its contact time step fell below the /DT/INTER/DEL minimum");
      return;
    }
    release_ibc(st, ks, pg.node, nodes);
    PendingPair q;
    q.st = &st;
    q.ks = ks;
    q.row = pair_row(st, pg, pc);
    q.f_el = nr.f_el;
    q.f_dp = nr.f_dp;
    q.f_fr = fr.f;
    q.vr = pc.vr;
    q.keff = ps.keff;
    q.p = pg.p;
    q.dt_vote = ps.dt_vote;
    if (lagrange_class(q, pg, pc, f, nodes) == PairClass::Lagrange)
      switch_pair(st, q.row, ks, pg.p);
    else
      pending.push_back(q);
  }

  // Stage B of interface_cycle, for one law variant: the pairs in node order.
  template <LawVariant V>
  void pair_loop(InterfaceState& st, const std::vector<Candidate>& cand, const CycleFlags& f,
                 const ContactNodes& nodes) {
    for_each_node(cand, 0, cand.size(), [&](std::size_t ks, std::size_t c, std::size_t) {
      if (!st.node_off[ks]) pair_cycle<V>(st, ks, closest[c], f, nodes);
    });
  }

  // One interface's pairs of the cycle: switched pairs into `switched`, penalty pairs into `pending` (applied
  // after settle_switches), pairs about to close add their stiffness.
  void interface_cycle(InterfaceState& st, double t, double dt1, const ContactNodes& nodes,
                       std::span<const double> sensor_starts) {
    const auto& in = *st.in;
    st.pairs.clear();
    st.result.active_pairs = 0;
    st.normal_force = {};
    st.tangential_force = {};
    st.result.switched_pairs = 0;
    if (st.sensor != model::kNone) {
      if (static_cast<std::size_t>(st.sensor) >= sensor_starts.size())
        throw std::logic_error("interface " + std::to_string(in.id) + ": no sensor state given");
      if (t < sensor_starts[static_cast<std::size_t>(st.sensor)]) return;  // kNever while the sensor is off
    }
    if (t < in.t_start || t >= in.t_stop) return;
    if (!st.started) {
      st.started = true;
      if (!st.from_start) start_penetrations(st, nodes, t);
    }
    st.search->update(Coordinates{nodes.x, nodes.y, nodes.z}, false, &parallel);
    const auto& cand = st.search->candidates();
    ++st.result.active_cycles;
    st.result.candidate_pair_cycles += static_cast<std::int64_t>(cand.size());
    CycleFlags f;
    f.dt1 = dt1;
    f.scale = controls.dt_scale;
    f.alpha = friction_filter_alpha(in.ifric >= 0 ? in.ifiltr : 0, in.xfreq, dt1);
    f.t_min = controls.t_min;
    f.lagdt = in.lagdt && lagrange_on();
    f.mass_scaled = controls.action == ContactControls::Action::AddMass && controls.t_min > 0 && !in.lagdt;
    f.deletes = controls.action == ContactControls::Action::Delete && controls.t_min > 0;
    // Stage A (parallel, pure): every node's closest candidate segment. Stage B (pair_loop, in node order
    // as before): everything that writes shared state (forces, stiffness sums, switches, IBC releases,
    // deactivations, messages), so its order and the sums it makes are those of one thread.
    closest_stage(st, cand, nodes);
    const bool by_law = in.contact_law_id != 0;
    const bool normal_law = in.law.normal != model::NormalLaw::Interface;
    const bool friction_law = in.law.friction != model::FrictionLaw::Interface;
    switch (!by_law ? 0 : 1 + (normal_law ? 1 : 0) + (friction_law ? 2 : 0)) {
      case 0: pair_loop<kPenaltyOnly>(st, cand, f, nodes); break;
      case 1: pair_loop<kLawAreas>(st, cand, f, nodes); break;
      case 2: pair_loop<kLawNormal>(st, cand, f, nodes); break;
      case 3: pair_loop<kLawFriction>(st, cand, f, nodes); break;
      default: pair_loop<kLawBoth>(st, cand, f, nodes); break;
    }
  }
};

Type7Contact::Type7Contact(const model::Model& m, ContactControls controls)
    : impl_(std::make_unique<Impl>(m, controls)) {}
Type7Contact::~Type7Contact() = default;

bool Type7Contact::empty() const {
  return impl_->interfaces.empty();
}

void Type7Contact::set_parallel_for(ParallelFor parallel) {
  impl_->parallel = std::move(parallel);
}

ContactStep Type7Contact::compute(double t, double dt1, const ContactNodes& nodes,
                                  std::span<const double> sensor_starts) {
  auto& s = *impl_;
  for (const auto n : s.touched) {
    const auto k = static_cast<std::size_t>(n);
    s.is_touched[k] = 0;
    s.force[3 * k] = s.force[3 * k + 1] = s.force[3 * k + 2] = 0.0;
  }
  s.touched.clear();
  s.dt1_ = dt1;
  s.book_lagrange_work(nodes);
  s.pending.clear();
  s.switched.clear();
  s.switched_p.clear();
  s.switched_ks.clear();
  for (auto& st : s.interfaces) {
    s.book_work(st, nodes, dt1);
    s.interface_cycle(st, t, dt1, nodes, sensor_starts);
  }
  for (const auto& [iface, ks] : s.pushed)  // read by interface_cycle; this cycle's rows set them again
    s.interfaces[static_cast<std::size_t>(iface)].row_pushed[static_cast<std::size_t>(ks)] = 0;
  s.pushed.clear();
  s.settle_switches(nodes);
  ContactStep vote;
  for (const auto& q : s.pending)
    if (q.st != nullptr) s.apply_pair(q, vote);
  for (auto& st : s.interfaces) {
    st.result.switched_pairs_max = std::max(st.result.switched_pairs_max, st.result.switched_pairs);
    st.result.switched_pairs_total += st.result.switched_pairs;
  }
  for (std::size_t k = 0; k < s.switched.size(); ++k) {
    auto& r = s.interfaces[static_cast<std::size_t>(s.switched[k].law)].result;
    r.max_penetration = std::max(r.max_penetration, s.switched_p[k]);
  }
  std::sort(s.touched.begin(), s.touched.end());
  const ContactStep nodal = s.nodal_steps(nodes);
  if (nodal.dt < vote.dt) vote = nodal;
  return vote;
}

const std::vector<NodeForce>& Type7Contact::lagrange_correction(const LagrangeNodesView& nodes, double dt1,
                                                                double dt2) {
  auto& s = *impl_;
  s.lagrange_forces.clear();
  if (s.switched.empty() || !(dt2 > 0)) return s.lagrange_forces;
  s.lagrange_out.resize(s.switched.size());
  const double dt12 = 0.5 * (dt1 + dt2);
  s.lagrange.solve(
      s.switched, s.laws,
      LagrangeNodes{nodes.mass, nodes.vx, nodes.vy, nodes.vz, nodes.ax, nodes.ay, nodes.az, nodes.fixed},
      dt12, dt2, s.lagrange_out);
  // v_r at t^n = v^{n-1/2} + dt1/2 a^n (the full-step velocity of the energy balance; a held translation has
  // a = 0 there, as the boundary conditions will make it).
  auto v_full = [&](std::int32_t n) {
    const auto i = static_cast<std::size_t>(n);
    const double a[3] = {nodes.ax[i], nodes.ay[i], nodes.az[i]};
    const double v[3] = {nodes.vx[i], nodes.vy[i], nodes.vz[i]};
    Vec3 out{};
    for (std::size_t d = 0; d < 3; ++d) out[d] = v[d] + ((nodes.fixed[i] >> d) & 1u ? 0.0 : 0.5 * dt1 * a[d]);
    return out;
  };
  auto v_half = [&](std::int32_t n) {
    const auto i = static_cast<std::size_t>(n);
    return Vec3{nodes.vx[i], nodes.vy[i], nodes.vz[i]};
  };
  auto put = [&](std::int32_t n, const Vec3& f) {
    s.add_force(n, f);
    const auto k = 3 * static_cast<std::size_t>(n);
    if (s.lagrange_buf[k] == 0 && s.lagrange_buf[k + 1] == 0 && s.lagrange_buf[k + 2] == 0)
      s.lagrange_touched.push_back(n);
    for (std::size_t d = 0; d < 3; ++d) s.lagrange_buf[k + d] += f[d];
  };
  for (std::size_t k = 0; k < s.switched.size(); ++k) {
    const auto& row = s.switched[k];
    const auto& out = s.lagrange_out[k];
    if (out.lambda == 0 && model::norm(out.friction) == 0) continue;
    auto& st = s.interfaces[static_cast<std::size_t>(row.law)];
    if (out.lambda > 0) {
      st.row_pushed[static_cast<std::size_t>(s.switched_ks[k])] = 1;
      s.pushed.emplace_back(row.law, s.switched_ks[k]);
    }
    const Vec3 fn = model::scale(row.n, out.lambda);
    const Vec3 f = model::add(fn, out.friction);
    const bool triangle = row.seg[3] == row.seg[2];
    put(row.node, f);
    for (std::size_t j = 0; j < (triangle ? 3u : 4u); ++j)
      if (row.h[j] != 0) put(row.seg[j], model::scale(f, -row.h[j]));
    for (std::size_t d = 0; d < 3; ++d) {
      st.normal_force[d].add(fn[d]);
      st.tangential_force[d].add(out.friction[d]);
    }
    // Work over [t^{n-1/2}, t^n] with the mean velocity of that half step (exact for a force constant over
    // the step, which the multiplier is): F . (v_r^{n-1/2} + v_r^n) / 2 dt1 / 2; the other half at the next
    // cycle (book_lagrange_work).
    const Vec3 vr_half = relative_velocity(v_half, row.node, row.seg, row.h);
    const Vec3 vr_full = relative_velocity(v_full, row.node, row.seg, row.h);
    const Vec3 vmean = model::scale(model::add(vr_half, vr_full), 0.5);
    st.w_lagrange.add(model::dot(fn, vmean) * 0.5 * dt1);
    st.w_friction.add(model::dot(out.friction, vmean) * 0.5 * dt1);
    s.lagrange_records.push_back(
        LagrangeRecord{row.law, row.node, row.seg, row.h, fn, out.friction, vr_full, dt2});
  }
  std::sort(s.lagrange_touched.begin(), s.lagrange_touched.end());
  for (const auto n : s.lagrange_touched) {
    const auto k = 3 * static_cast<std::size_t>(n);
    s.lagrange_forces.push_back(
        NodeForce{n, {s.lagrange_buf[k], s.lagrange_buf[k + 1], s.lagrange_buf[k + 2]}});
    s.lagrange_buf[k] = s.lagrange_buf[k + 1] = s.lagrange_buf[k + 2] = 0.0;
  }
  s.lagrange_touched.clear();
  std::sort(s.touched.begin(), s.touched.end());
  return s.lagrange_forces;
}

std::int64_t Type7Contact::switched_pairs() const {
  return static_cast<std::int64_t>(impl_->switched.size());
}

bool Type7Contact::has_lagrange() const {
  if (!impl_->lagrange_on()) return false;
  for (const auto& st : impl_->interfaces)
    if (st.in->lagdt) return true;
  return false;
}

const LagrangeStats& Type7Contact::lagrange_stats() const {
  return impl_->lagrange.stats();
}

// The booked energies are the negated works (0 - w: +0 when nothing was booked); the sum over the interfaces
// is exact too, rounded once.
double Type7Contact::energy_lagrange() const {
  model::ExactSum w;
  for (const auto& st : impl_->interfaces) w.merge(st.w_lagrange);
  return 0.0 - w.value();
}

const std::vector<double>& Type7Contact::force() const {
  return impl_->force;
}
const std::vector<std::int32_t>& Type7Contact::touched() const {
  return impl_->touched;
}

void Type7Contact::elements_deleted(std::span<const std::uint8_t> alive) {
  auto& s = *impl_;
  const auto& m = s.model;
  // Alive elements around each node, for the removal of secondary nodes left without any (Idel > 0).
  std::vector<std::int32_t> alive_around(m.nodes.size(), 0);
  std::size_t cell = 0;
  for (const auto* b : {&m.shells, &m.shells3, &m.bricks, &m.tetras, &m.bricks20}) {
    const auto npe = static_cast<std::size_t>(b->npe());
    for (std::size_t e = 0; e < b->size(); ++e, ++cell)
      if (alive[cell])
        for (std::size_t k = 0; k < npe; ++k) ++alive_around[static_cast<std::size_t>(b->conn[e * npe + k])];
  }
  for (auto& st : s.interfaces) {
    // A /CTCLAW law's areas follow the faces that are left (type7_prepare.hpp, tributary_areas).
    if (st.in->contact_law_id != 0) st.tributary_area = tributary_areas(m, st.in->secondary_nodes, alive);
    const int idel = st.in->idel;
    if (idel == 0) continue;
    for (std::size_t g = 0; g < st.segments.size(); ++g) {
      const auto oc = st.owner_cell[g];
      if (st.segment_off[g] || oc < 0 || alive[static_cast<std::size_t>(oc)]) continue;
      st.segment_off[g] = 1;
      st.search->remove_segment(static_cast<std::int32_t>(g));
    }
    if (idel < 0) continue;
    // Only nodes that had elements lose them: a node without any (a rigid-body or mass-only node) stays.
    for (std::size_t k = 0; k < st.in->secondary_nodes.size(); ++k) {
      const auto n = static_cast<std::size_t>(st.in->secondary_nodes[k]);
      if (!st.node_off[k] && alive_around[n] == 0 && s.elements_around0[n] > 0)
        s.deactivate(st, k, "is no longer connected to any element (Idel): removed");
    }
  }
}

std::vector<InterfaceResult> Type7Contact::results() const {
  std::vector<InterfaceResult> out;
  for (const auto& st : impl_->interfaces) {
    out.push_back(st.result);
    auto& r = out.back();
    if (st.search) r.search_sorts = st.search->sorts();
    r.e_elastic = 0.0 - st.w_elastic.value();
    r.e_damping = 0.0 - st.w_damping.value();
    r.e_friction = 0.0 - st.w_friction.value();
    r.e_lagrange = 0.0 - st.w_lagrange.value();
    for (std::size_t d = 0; d < 3; ++d) {
      r.normal_force[d] = st.normal_force[d].value();
      r.tangential_force[d] = st.tangential_force[d].value();
    }
  }
  return out;
}

double Type7Contact::energy_elastic() const {
  model::ExactSum w;
  for (const auto& st : impl_->interfaces) w.merge(st.w_elastic);
  return 0.0 - w.value();
}
double Type7Contact::energy_damping() const {
  model::ExactSum w;
  for (const auto& st : impl_->interfaces) w.merge(st.w_damping);
  return 0.0 - w.value();
}
double Type7Contact::energy_friction() const {
  model::ExactSum w;
  for (const auto& st : impl_->interfaces) w.merge(st.w_friction);
  return 0.0 - w.value();
}

std::vector<std::string> Type7Contact::take_messages() {
  std::vector<std::string> out;
  out.swap(impl_->messages);
  return out;
}

}  // namespace radx::contact
