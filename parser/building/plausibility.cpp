// Plausibility of a valid model's run (RX513): the estimated initial step in seconds (step times the
// deck's time unit) against 1e-12 s, and the cycles to the end time, t_stop / min(scale * dt, dt_max),
// against 1e9. Warnings only: a scaled or academic model can mean it, a unit slip usually does not.
// A deck that names no units reads as seconds: of the usual time units (s, ms, us) the most lenient for a
// step that is too small, and the cycle count does not depend on the unit.
#include "parser/building/plausibility.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

namespace radx {

namespace {

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

const char* keyword_of(model::ElementType t) {
  switch (t) {
    case model::ElementType::Shell4: return "/SHELL";
    case model::ElementType::Shell3: return "/SH3N";
    case model::ElementType::Brick8: return "/BRICK";
    case model::ElementType::Tetra4: return "/TETRA4";
    case model::ElementType::Spring2: return "/SPRING";
    case model::ElementType::Truss2: return "/TRUSS";
    case model::ElementType::Beam2: return "/BEAM";
    case model::ElementType::Brick20: return "/BRIC20";
  }
  return "/SHELL";
}

// The line of an element's card; the deck's first file when it cannot be found.
Where element_where(const Deck& deck, model::ElementType t, std::int64_t id) {
  const char* id_field = t == model::ElementType::Brick8    ? "brick_ID"
                         : t == model::ElementType::Tetra4  ? "tetra_ID"
                         : t == model::ElementType::Shell3  ? "tria_ID"
                         : t == model::ElementType::Spring2 ? "spring_ID"
                         : t == model::ElementType::Truss2  ? "truss_ID"
                         : t == model::ElementType::Beam2   ? "beam_ID"
                         : t == model::ElementType::Brick20 ? "brick20_ID"
                                                            : "shell_ID";
  for (const auto* r : deck.of(keyword_of(t))) {
    const int c = r->records.column(id_field);
    if (c < 0) continue;
    const auto& ids = r->records.ints[static_cast<std::size_t>(c)];
    for (std::size_t e = 0; e < ids.size(); ++e)
      if (ids[e] == id) return deck.where(r->records.pos[e], 1);
  }
  return deck.files.empty() ? Where{} : Where{deck.files.front()};
}

std::string element_name(const model::StepEstimate& step) {
  return std::string(model::element_type_name(step.type)) + " " + std::to_string(step.element_id);
}

}  // namespace

void check_initial_step(const Deck& deck, const model::Model& m, const model::StepEstimate& step,
                        Diagnostics& diags) {
  if (!(step.dt > 0)) return;
  const double seconds = step.dt * m.units.time;
  if (seconds >= kImplausibleStepSeconds) return;
  const bool spring = step.type == model::ElementType::Spring2;
  diags.warning(Diag::ImplausibleTimeStep, element_where(deck, step.type, step.element_id),
                About{keyword_of(step.type), step.element_id},
                "the initial stable time step is about " + num(seconds) + " s (" +
                    (m.units.time == 1.0 ? std::string() : num(step.dt) + " " + m.units.time_name + ", ") +
                    (spring ? "mass, stiffness and damping of " : "element size over wave speed of ") +
                    element_name(step) +
                    "), below 1e-12 s: a millisecond would take more than 1e9 cycles; crash models step at "
                    "1e-8 to 1e-5 s: " +
                    (spring ? "check the spring property's mass and stiffness and their units"
                            : "check the element size and the units of the material's E and RHO_I"));
}

namespace {

inline constexpr double kContactStepRatio = 100;

// The largest stiffness per unit area (Pa/m) a /CTCLAW normal law can reach, 0 when it has no bound
// (exponential without KcMax, power law) or no normal part; -1 for Kc = -1 (the interface's K / A_s).
double law_stiffness_bound(const model::ContactLaw& law, const model::Model& m) {
  switch (law.normal) {
    case model::NormalLaw::Linear: return law.kc;
    case model::NormalLaw::Exponential: return law.kc_max;
    case model::NormalLaw::Tabulated: {
      if (law.curve == model::kNone) return 0;
      const auto& f = m.functions[static_cast<std::size_t>(law.curve)];
      double slope = 0;
      for (std::size_t k = 0; k + 1 < f.x.size(); ++k)
        if (f.x[k + 1] > f.x[k])
          slope = std::max(slope, std::abs((f.y[k + 1] - f.y[k]) / (f.x[k + 1] - f.x[k])));
      return slope;
    }
    default: return 0;
  }
}

// The interface's record, for the warning's location.
Where interface_where(const Deck& deck, std::int64_t id) {
  for (const auto& rec : deck.records)
    if (rec.id == id && (rec.decl->path == "/INTER/TYPE7" || rec.decl->path == "/INTER/LAGDT/TYPE7"))
      return deck.where(rec.pos, 1);
  return deck.files.empty() ? Where{} : Where{deck.files.front()};
}

}  // namespace

void check_contact_step(const Deck& deck, const model::Model& m, const model::StepEstimate& step,
                        Diagnostics& diags) {
  if (!(step.dt > 0)) return;
  for (const auto& in : m.interfaces) {
    if (in.lagdt) continue;
    const bool by_law = in.contact_law_id != 0 && in.law.normal != model::NormalLaw::Interface;
    const double bound = by_law ? law_stiffness_bound(in.law, m) : -1.0;
    if (bound == 0) continue;
    double dt_min = std::numeric_limits<double>::infinity(), k_at = 0, m_at = 0;
    std::int32_t node_at = model::kNone;
    for (std::size_t k = 0; k < in.secondary_nodes.size(); ++k) {
      const auto n = static_cast<std::size_t>(in.secondary_nodes[k]);
      const double area = k < in.tributary_area.size() ? in.tributary_area[k] : 0.0;
      const double stiffness = bound < 0 ? in.stiff_hi : bound * area;
      const double mass = n < m.node_mass.size() ? m.node_mass[n] : 0.0;
      if (!(stiffness > 0) || !(mass > 0)) continue;
      const double dt = std::sqrt(2.0 * mass / stiffness);
      if (dt < dt_min) dt_min = dt, k_at = stiffness, m_at = mass, node_at = in.secondary_nodes[k];
    }
    if (!(dt_min * kContactStepRatio < step.dt)) continue;
    const std::string tu = " " + m.units.time_name;
    const std::string what =
        !by_law ? "its penalty stiffness K = " + num(k_at)
                : "the /CTCLAW/" + std::to_string(in.contact_law_id) + " law's largest stiffness " +
                      (in.law.normal == model::NormalLaw::Linear && in.law.kc > 0 ? "Kc A_s"
                       : in.law.normal == model::NormalLaw::Exponential           ? "KcMax A_s"
                       : in.law.normal == model::NormalLaw::Tabulated             ? "(steepest segment) A_s"
                                                                                  : "K") +
                      " = " + num(k_at);
    diags.warning(
        Diag::ImplausibleTimeStep, interface_where(deck, in.id), About{"/INTER/TYPE7", in.id, in.title},
        "once in contact a pair of this interface votes a step of about " + num(dt_min) + tu + ": " + what +
            " on secondary node " + std::to_string(m.nodes.id[static_cast<std::size_t>(node_at)]) +
            " of mass " + num(m_at) + ", sqrt(2 m / k); that is 1/" + num(step.dt / dt_min) +
            " of the elements' estimated step " + num(step.dt) + tu + " (set by " + element_name(step) +
            "), so the run takes that many times the cycles while the pairs are closed: check the "
            "stiffness and its units (/DT/INTER/STOP stops a run whose step falls below a minimum)");
  }
}

RunCycles estimate_run_cycles(const model::RunControls& controls, const model::StepEstimate& step) {
  if (!(step.dt > 0) || !(controls.t_stop > 0)) return {};
  // /DT/NODA replaces the element step by the nodal one, with its own scale; /DT/NODA/CST adds mass so
  // that it stays at Tmin at least: a mass-scaled run is not warned of for the step it would have without.
  const auto& noda = controls.nodal;
  const bool nodal = noda.given;
  const auto& dt_control = nodal ? noda : controls.global;
  const double scale = dt_control.scale > 0 ? dt_control.scale : 0.9;
  double dt = scale * step.dt;
  if (nodal && noda.action == model::DtAction::AddMass && noda.t_min > 0) dt = std::max(dt, noda.t_min);
  dt = std::min(dt, controls.dt_max);
  if (!(dt > 0)) return {};
  return {dt, controls.t_stop / dt};
}

void check_cycle_count(const EngineDeck& engine, const model::RunControls& controls, const model::Model& m,
                       const model::StepEstimate& step, Diagnostics& diags) {
  const auto [dt, cycles] = estimate_run_cycles(controls, step);
  if (cycles <= kImplausibleCycles) return;
  const auto runs = engine.of("/RUN");
  const Where where = !runs.empty()           ? engine.where(runs.front()->pos, 1)
                      : !engine.files.empty() ? Where{engine.files.front()}
                                              : Where{};
  diags.warning(Diag::ImplausibleTimeStep, where, About{"/RUN"},
                "the end time " + num(controls.t_stop) + " " + m.units.time_name + " needs about " +
                    num(cycles) + " cycles of the initial step " + num(dt) + " " + m.units.time_name +
                    " (set by " + element_name(step) +
                    "), more than 1e9, more than a run can take: crash runs take 1e4 to 1e7 "
                    "cycles: check the end time and its unit (" +
                    m.units.time_name + ")");
}

void check_output_count(const EngineDeck& engine, const model::RunControls& controls, const model::Model& m,
                        const model::StepEstimate& step, Diagnostics& diags) {
  const auto anim = engine.of("/ANIM/DT");
  if (anim.empty() || !(controls.anim_dt > 0)) return;
  const double last = std::min(controls.anim_stop, controls.t_stop);
  if (!(last > controls.anim_start)) return;
  const double asked = (last - controls.anim_start) / controls.anim_dt;
  // At most one state a cycle is written, whatever the interval.
  const double cycles = estimate_run_cycles(controls, step).cycles;
  const double written = cycles > 0 ? std::min(asked, cycles) : asked;
  if (written <= kManyAnimStates) return;
  diags.warning(Diag::ValueOutOfRange, engine.where(anim.front()->pos, 1), About{"/ANIM/DT"},
                "dT = " + num(controls.anim_dt) + " " + m.units.time_name + " writes about " + num(written) +
                    " animation states (" +
                    (written < asked ? "one every cycle of the estimated " + num(cycles)
                                     : "from " + num(controls.anim_start) + " to " + num(last)) +
                    "), each a full copy of the /ANIM fields: more than any study reads; check the interval "
                    "and its unit (" +
                    m.units.time_name + ")");
}

}  // namespace radx
