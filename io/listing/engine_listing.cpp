#include "io/listing/engine_listing.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <sstream>

namespace radx::io {

namespace {

const char* rule =
    "---------------------------------------------------------------------------------------------------\n";

void heading(std::ostream& os, const char* title) {
  os << '\n' << rule << "  " << title << '\n' << rule;
}

// Column widths of a listing line (titles use the same ones).
constexpr int kCycleW = 10;
constexpr int kRealW = 14;  // %14.5E: at most 13 characters ("-1.23456E+100"), so always a blank before
constexpr int kKindW = 5;   // BRICK, SHELL, SH3N, NODE, INTER
constexpr int kIdW = 10;
constexpr int kErrorW = 7;  // "-99.9" plus '%' after it

std::string sci(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.5E", v);
  return buf;
}

// One decimal, fixed (a mean count).
std::string fixed1(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", v);
  return buf;
}

std::string gnum(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

std::string never_or(double v, double never, const std::string& unit) {
  return v >= never ? std::string("never") : gnum(v) + unit;
}

std::string action_text(model::DtAction a) {
  switch (a) {
    case model::DtAction::None: return "no action";
    case model::DtAction::Stop: return "stop the run";
    case model::DtAction::Delete: return "remove the secondary node from its interface";
    case model::DtAction::Constant: return "switch to small strain, step kept constant";
    case model::DtAction::AddMass: return "add mass to keep the step";
    case model::DtAction::Lagrange: return "switch pairs to Lagrange multipliers (LAGDT)";
  }
  return "?";
}

void dt_row(std::ostream& os, const char* what, const model::DtControl& c, const std::string& tu) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "  %-34s", what);
  os << buf << "scale " << gnum(c.scale) << ", minimum " << gnum(c.t_min) << tu;
  if (c.t_min > 0) os << " (then: " << action_text(c.action) << ")";
  os << (c.given ? "" : "  [default]") << '\n';
}

std::string join(const std::vector<std::string>& v) {
  std::string out;
  for (const auto& s : v) out += (out.empty() ? "" : " ") + s;
  return out.empty() ? "-" : out;
}

void row(std::ostream& os, const char* label, const std::string& value) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "  %-34s", label);
  os << buf << value << '\n';
}

}  // namespace

double energy_error_percent(double e_total, double e_total0, double w_ext) {
  const double ref = e_total0 + w_ext;
  if (std::abs(ref) <= 1e-20) return 0.0;
  const double e = 100.0 * (e_total / ref - 1.0);
  if (std::isnan(e)) return e;
  return std::clamp(e, -99.9, 99.9);
}

std::vector<std::string> EnergyErrorWarnings::check(double error_percent) {
  std::vector<std::string> due;
  for (std::size_t k = 0; k < kLevels.size(); ++k) {
    if (said_[k] || !(std::abs(error_percent) >= kLevels[k])) continue;
    said_[k] = true;
    char text[320];
    std::snprintf(text, sizeof text,
                  "the energy error is %.3g %%, past %g %%: the run %s energy it cannot account for (a sound "
                  "run stays within a few per cent); it goes on (/STOP Emax stops it)",
                  error_percent, kLevels[k], error_percent < 0 ? "loses" : "creates");
    due.emplace_back(text);
  }
  return due;
}

std::string_view termination_label(RunStatus s) {
  switch (s) {
    case RunStatus::Normal: return "NORMAL TERMINATION";
    case RunStatus::Error: return "ERROR TERMINATION";
    case RunStatus::Interrupted: return "INTERRUPTED TERMINATION";
    case RunStatus::Running: return "RUNNING";
  }
  return "";
}

std::string_view step_source_label(StepSource s) {
  switch (s) {
    case StepSource::None: return "-";
    case StepSource::Brick: return "BRICK";
    case StepSource::Shell: return "SHELL";
    case StepSource::Shell3: return "SH3N";
    case StepSource::Node: return "NODE";
    case StepSource::Interface: return "INTER";
    case StepSource::Imposed: return "DTIX";
    case StepSource::Spring: return "SPRING";
    case StepSource::Truss: return "TRUSS";
    case StepSource::Beam: return "BEAM";
  }
  return "-";
}

std::string listing_column_titles(bool lagrange_column) {
  char buf[320];
  std::snprintf(buf, sizeof buf, "%*s%*s%*s  %-*s%*s%*s%*s%*s%*s%*s%*s%*s", kCycleW, "CYCLE", kRealW, "TIME",
                kRealW, "TIME-STEP", kKindW + 1 + kIdW, "ELEMENT", kErrorW + 2, "ERROR %", kRealW, "I-ENERGY",
                kRealW, "K-ENERGY T", kRealW, "K-ENERGY R", kRealW, "EXT-WORK", kRealW, "MAS.ERR", kRealW,
                "TOTAL MASS", kRealW, "MASS ADDED");
  std::string out = buf;
  if (lagrange_column) {
    std::snprintf(buf, sizeof buf, "%*s", kRealW, "LAG-PAIRS");
    out += buf;
  }
  return out;
}

std::string format_listing_line(const ListingLine& l) {
  std::string id = l.source == StepSource::None || l.source == StepSource::Imposed
                       ? std::string("-")
                       : std::to_string(l.source_id);
  if (l.source == StepSource::Interface && l.source_node != 0) id += ":" + std::to_string(l.source_node);
  const std::string kind(step_source_label(l.source));
  // "+ 0.0" turns -0.0 into 0.0, so a zero never prints as "-0.0%".
  char buf[320];
  std::snprintf(buf, sizeof buf, "%*lld%*.5E%*.5E  %-*s %*s %*.1f%%%*.5E%*.5E%*.5E%*.5E%*.5E%*.5E%*.5E",
                kCycleW, static_cast<long long>(l.cycle), kRealW, l.time + 0.0, kRealW, l.dt + 0.0, kKindW,
                kind.c_str(), kIdW, id.c_str(), kErrorW, l.error_percent + 0.0, kRealW,
                l.internal_energy + 0.0, kRealW, l.kinetic_t + 0.0, kRealW, l.kinetic_r + 0.0, kRealW,
                l.external_work + 0.0, kRealW, l.mass_error + 0.0, kRealW, l.total_mass + 0.0, kRealW,
                l.added_mass + 0.0);
  std::string out = buf;
  if (l.switched_pairs >= 0) {
    std::snprintf(buf, sizeof buf, "%*lld", kRealW, static_cast<long long>(l.switched_pairs));
    out += buf;
  }
  return out;
}

double us_per_element_cycle(const RunSummary& s, double seconds) {
  if (s.elements == 0 || s.cycles <= 0) return 0.0;
  return 1e6 * seconds / (static_cast<double>(s.elements) * static_cast<double>(s.cycles));
}

double us_per_element_cycle(const RunSummary& s) {
  return us_per_element_cycle(s, s.wall_seconds);
}

void write_engine_header(std::ostream& os, const EngineListingHeader& h) {
  const std::string tu = " " + h.time_unit;
  os << "radx engine " << h.program_version << '\n'
     << "engine deck   " << h.engine_deck << '\n'
     << "model file    " << h.model_file << '\n'
     << "outputs       " << h.output_root << "_*" << '\n'
     << "threads       " << h.threads << '\n'
     << "work units    mass " << h.mass_unit << ", length " << h.length_unit << ", time " << h.time_unit
     << '\n';

  heading(os, "MODEL");
  row(os, "nodes", std::to_string(h.nodes));
  row(os, "4-node shells", std::to_string(h.shells));
  row(os, "3-node shells", std::to_string(h.shells3));
  row(os, "8-node bricks", std::to_string(h.bricks));
  if (h.tetras > 0) row(os, "4-node tetrahedra", std::to_string(h.tetras));
  if (h.bricks20 > 0) row(os, "20-node bricks", std::to_string(h.bricks20));
  row(os, "contact interfaces", std::to_string(h.interfaces));
  row(os, "total mass", gnum(h.total_mass) + " " + h.mass_unit);

  if (h.controls) {
    const model::RunControls& c = *h.controls;
    heading(os, "RUN CONTROLS");
    row(os, "run", c.run_name + ", run " + std::to_string(c.run_number));
    row(os, "end time", gnum(c.t_stop) + tu);
    row(os, "listing line every",
        std::to_string(c.print_every) + " cycles" + (c.print_stdout ? " (also on standard output)" : "") +
            (c.print_header_every > 0 ? ", titles every " + std::to_string(c.print_header_every) + " lines"
                                      : ""));
    row(os, "time history every", c.th_dt == 0.0 ? std::string("cycle") : never_or(c.th_dt, 1e30, tu));
    row(os, "animation states",
        c.anim_dt > 0 ? "from " + gnum(c.anim_start) + tu + " every " + gnum(c.anim_dt) + tu + " until " +
                            never_or(c.anim_stop, 1e20, tu)
                      : std::string("first and last only"));
    row(os, "  element fields", join(c.anim_elem));
    row(os, "  nodal vectors", join(c.anim_vect));
    row(os, "  tensors", join(c.anim_tens));
    row(os, "  nodal scalars", join(c.anim_noda));
    os << '\n';
    dt_row(os, "time step, elements (/DT)", c.global, tu);
    dt_row(os, "time step, bricks", c.brick, tu);
    dt_row(os, "time step, 4-node shells", c.shell, tu);
    dt_row(os, "time step, 3-node shells", c.shell3, tu);
    dt_row(os, "time step, nodal", c.nodal, tu);
    if (c.spring.given) dt_row(os, "time step, springs", c.spring, tu);
    if (c.nodal.given && c.nodal_max_added_mass_pct > 0)
      row(os, "  stop when added mass exceeds", gnum(c.nodal_max_added_mass_pct) + " %");
    dt_row(os, "time step, interfaces", c.inter, tu);
    if (c.inter.action == model::DtAction::AddMass && c.inter.t_min > 0)
      row(os, "", "(/INTER/LAGDT/TYPE7: pairs below the minimum switch to Lagrange multipliers)");
    if (c.dt_initial > 0 || c.dt_max < 1e30)
      row(os, "time step bounds (/DTIX)",
          "first step at most " + (c.dt_initial > 0 ? gnum(c.dt_initial) + tu : std::string("-")) +
              ", every step at most " + (c.dt_max < 1e30 ? gnum(c.dt_max) + tu : std::string("(no bound)")));
    os << '\n';
    row(os, "stop: energy error above",
        c.stop_energy_error_pct >= 1e30
            ? std::string("off")
            : gnum(c.stop_energy_error_pct) + " %" + (c.stop_positive_error_only ? " (positive only)" : ""));
    row(os, "stop: mass error above",
        c.stop_mass_error >= 1e30 ? std::string("off") : gnum(c.stop_mass_error));
    row(os, "stop: nodal mass error above",
        c.stop_nodal_mass_error >= 1e30 ? std::string("off") : gnum(c.stop_nodal_mass_error));
    if (!c.rbody_on.empty() || !c.rbody_off.empty()) {
      std::vector<std::string> on, off;
      for (auto id : c.rbody_on) on.push_back(std::to_string(id));
      for (auto id : c.rbody_off) off.push_back(std::to_string(id));
      row(os, "rigid bodies switched on", join(on));
      row(os, "rigid bodies switched off", join(off));
    }
  }
  if (!h.deck_messages.empty()) {
    heading(os, "ENGINE DECK MESSAGES");
    for (const auto& m : h.deck_messages) os << "  " << m << '\n';
  }
  os << '\n';
}

namespace {

// The energies at the end and the balance error.
void write_energy_balance(std::ostream& os, const EnergyBalance& e) {
  heading(os, "ENERGY BALANCE");
  auto erow = [&](const char* label, double v) { row(os, label, sci(v)); };
  erow("kinetic, translational", e.kinetic_t);
  erow("kinetic, rotational", e.kinetic_r);
  erow("internal", e.internal);
  if (e.spring != 0) erow("  of which springs", e.spring);
  erow("hourglass", e.hourglass);
  erow("contact, elastic", e.contact_elastic);
  erow("contact, damping", e.contact_damping);
  erow("contact, friction", e.contact_friction);
  erow("contact, Lagrange", e.contact_lagrange);
  erow("external work", e.external_work);
  erow("initial total E0", e.initial_total);
  erow("total E (all but external work)", e.total());
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.1f %%", e.error_percent());
  row(os, "error 100 (E / (E0 + W) - 1)", buf);
  if (e.internal > 0) {
    std::snprintf(buf, sizeof buf, "%.1f %%", 100.0 * e.hourglass / e.internal);
    row(os, "hourglass / internal", buf);
  }
  if (const auto w = hourglass_warning(e); !w.empty()) os << "  WARNING: " << w << '\n';
}

// Cycles, time, cost, masses and momentum.
void write_run_figures(std::ostream& os, const RunSummary& s) {
  char buf[64];
  heading(os, "RUN");
  row(os, "cycles", std::to_string(s.cycles));
  row(os, "final time", sci(s.time));
  row(os, "last time step", sci(s.dt));
  row(os, "wall time", format_duration(s.wall_seconds));
  std::snprintf(buf, sizeof buf, "%.4g", us_per_element_cycle(s));
  row(os, "cost",
      std::string(buf) + " us per element per cycle (" + std::to_string(s.elements) + " elements, " +
          std::to_string(s.threads) + " thread(s))");
  if (s.contact_seconds > 0) {
    std::snprintf(buf, sizeof buf, "%.1f %% of the wall time (%s)",
                  s.wall_seconds > 0 ? 100.0 * s.contact_seconds / s.wall_seconds : 0.0,
                  format_duration(s.contact_seconds).c_str());
    row(os, "contact (search and forces)", buf);
  }
  if (s.element_loop_seconds > 0) {
    std::snprintf(buf, sizeof buf, "%.4g us per element per cycle, %.1f %% of the wall time",
                  us_per_element_cycle(s, s.element_loop_seconds),
                  s.wall_seconds > 0 ? 100.0 * s.element_loop_seconds / s.wall_seconds : 0.0);
    row(os, "element loop", std::string(buf) + " (forces, assembly, integration)");
  }
  row(os, "initial mass", sci(s.initial_mass));
  row(os, "final mass", sci(s.mass));
  std::string added = sci(s.added_mass);
  if (s.initial_mass > 0) {
    std::snprintf(buf, sizeof buf, " (%.3g %% of the initial mass)", 100.0 * s.added_mass / s.initial_mass);
    added += buf;
  }
  row(os, "added mass", added);
  row(os, "momentum", sci(s.momentum[0]) + " " + sci(s.momentum[1]) + " " + sci(s.momentum[2]));
}

// Each contact interface's counts and the Lagrange-multiplier solve's.
void write_contact_figures(std::ostream& os, const RunSummary& s) {
  if (!s.interfaces.empty()) {
    heading(os, "CONTACT INTERFACES");
    for (const auto& in : s.interfaces) {
      os << "  interface " << in.id << ": active pairs " << in.active_pairs << ", max penetration "
         << sci(in.max_penetration) << ", switched pairs max " << in.switched_pairs_max << " total "
         << in.switched_pairs_total << ", added mass " << sci(in.added_mass) << ", nodes removed "
         << in.removed_nodes << ", candidate pairs per cycle " << fixed1(in.candidates_mean)
         << " (mean), search sorts " << in.search_sorts << '\n';
    }
  }
  if (s.lagrange.present) {
    const auto& L = s.lagrange;
    heading(os, "LAGRANGE MULTIPLIERS (switched LAGDT pairs, CHOLMOD)");
    row(os, "cycles with rows", std::to_string(L.cycles));
    row(os, "rows",
        "max " + std::to_string(L.rows_max) + " in one cycle, " + std::to_string(L.rows_total) +
            " row-cycles; dropped (no free dof) " + std::to_string(L.dropped_rows) + ", merged " +
            std::to_string(L.merged_rows));
    row(os, "nonzeros of A = L M^-1/2", "max " + std::to_string(L.nonzeros_max));
    row(os, "factorisations",
        std::to_string(L.factorizations) + " (symbolic analyses " + std::to_string(L.analyses) + ", reuses " +
            std::to_string(L.symbolic_reuses) + ")");
    row(os, "active-set passes",
        std::to_string(L.active_set_passes) + " (max " + std::to_string(L.passes_max) + " in one cycle, " +
            std::to_string(L.unconverged) + " cycle(s) at the limit)");
    row(os, "regularisations", std::to_string(L.regularisations) + " (largest beta " + sci(L.beta_max) + ")");
    // Milliseconds and the share of the run: the multiplier solve is meant to stay a small part of the cycle.
    auto share = [&](double seconds) {
      char buf[96];
      std::snprintf(buf, sizeof buf, "%.1f ms (%.2f %% of the wall time)", 1e3 * seconds,
                    s.wall_seconds > 0 ? 100.0 * seconds / s.wall_seconds : 0.0);
      return std::string(buf);
    };
    row(os, "time: assembly", share(L.seconds_assembly));
    row(os, "time: factorisation", share(L.seconds_factorization));
    row(os, "time: solve", share(L.seconds_solve));
    row(os, "time: all three", share(L.seconds_assembly + L.seconds_factorization + L.seconds_solve));
  }
}

// How many elements each part lost, and the first ones.
void write_deleted_elements(std::ostream& os, const RunSummary& s) {
  if (s.deleted_by_part.empty()) return;
  heading(os, "DELETED ELEMENTS");
  row(os, "total", std::to_string(s.deleted_total()));
  for (const auto& p : s.deleted_by_part)
    row(os, ("part " + std::to_string(p.part_id) + (p.title.empty() ? "" : " \"" + p.title + "\"")).c_str(),
        std::to_string(p.count));
  os << "  the first " << s.first_deleted.size() << ":\n";
  for (const auto& d : s.first_deleted) {
    char at[64];
    std::snprintf(at, sizeof at, " (cycle %lld, t = %.5E)", static_cast<long long>(d.cycle), d.time);
    os << "    " << d.kind << " " << d.element_id << " of part " << d.part_id << at << '\n';
  }
}

// What was written and how long writing took.
void write_results_figures(std::ostream& os, const RunSummary& s) {
  if (s.states == 0 && s.time_history.empty()) return;
  char buf[64];
  heading(os, "RESULTS");
  if (s.states > 0) row(os, "animation states", std::to_string(s.states) + " in " + s.series);
  if (!s.time_history.empty()) row(os, "time history", s.time_history);
  std::snprintf(buf, sizeof buf, " (%.1f %% of the wall time)",
                s.wall_seconds > 0 ? 100.0 * s.output_seconds / s.wall_seconds : 0.0);
  row(os, "writing time", format_duration(s.output_seconds) + buf);
}

}  // namespace

std::string hourglass_warning(const EnergyBalance& e) {
  if (!(e.internal > 0) || !(e.hourglass > 0.1 * e.internal)) return {};
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.1f %%", 100.0 * e.hourglass / e.internal);
  return std::string("hourglass energy is ") + buf +
         " of the internal energy, above 10 %: the one-point elements' zero-energy modes carry work the "
         "mesh should; use physically stabilised or fully integrated formulations (QEPH shells Ishell 24, "
         "HEPH "
         "bricks Isolid 24, or Isolid 14 and 17) or a finer mesh";
}

void write_run_summary(std::ostream& os, const RunSummary& s) {
  heading(os, termination_label(s.status).data());
  if (!s.message.empty()) os << "  " << s.message << '\n';
  write_energy_balance(os, s.energy);
  if (!s.substitutions.empty()) {
    heading(os, "SUBSTITUTIONS (--allow-substitutions: these ran instead of what the deck asks)");
    for (const auto& text : s.substitutions) os << "  " << text << '\n';
  }

  write_run_figures(os, s);
  write_deleted_elements(os, s);
  write_contact_figures(os, s);
  write_results_figures(os, s);
  os << rule;
  os << "  " << termination_label(s.status) << '\n';
}

std::string format_duration(double seconds) {
  char buf[64];
  if (!(seconds >= 0) || !std::isfinite(seconds)) return "?";
  if (seconds < 60) {
    std::snprintf(buf, sizeof buf, "%.1f s", seconds);
  } else if (seconds < 3600) {
    const auto t = static_cast<long long>(std::lround(seconds));
    std::snprintf(buf, sizeof buf, "%lld min %02lld s", t / 60, t % 60);
  } else {
    const auto t = static_cast<long long>(std::lround(seconds / 60));
    std::snprintf(buf, sizeof buf, "%lld h %02lld min", t / 60, t % 60);
  }
  return buf;
}

std::string format_progress(std::int64_t cycle, double time, double t_stop, double wall_seconds) {
  const double frac = t_stop > 0 ? std::clamp(time / t_stop, 0.0, 1.0) : 0.0;
  std::string left = "estimating";
  if (time > 0 && t_stop > 0)
    left = "about " + format_duration(wall_seconds * std::max(0.0, t_stop - time) / time);
  char buf[160];
  std::snprintf(buf, sizeof buf, "  %5.1f %%  cycle %lld  t %.4E  elapsed %s  left %s", 100.0 * frac,
                static_cast<long long>(cycle), time, format_duration(wall_seconds).c_str(), left.c_str());
  return buf;
}

bool stdout_is_terminal() {
  return ::isatty(STDOUT_FILENO) != 0;
}

void EngineListing::clear_progress() {
  if (progress_len_ == 0 || !s_.terminal) return;
  *s_.terminal << '\r' << std::string(progress_len_, ' ') << '\r';
  progress_len_ = 0;
}

void EngineListing::header(const EngineListingHeader& h) {
  std::ostringstream os;
  write_engine_header(os, h);
  if (s_.file) *s_.file << os.str();
  if (s_.terminal) {
    clear_progress();
    *s_.terminal << os.str();
  }
}

void EngineListing::line(const ListingLine& l) {
  std::string text;
  if (lines_ == 0 || (s_.header_every > 0 && lines_ % static_cast<std::size_t>(s_.header_every) == 0))
    text = listing_column_titles(l.switched_pairs >= 0) + '\n';
  text += format_listing_line(l) + '\n';
  ++lines_;
  if (s_.file) *s_.file << text;
  if (s_.terminal && s_.lines_to_terminal) {
    clear_progress();
    *s_.terminal << text << std::flush;
  }
}

void EngineListing::progress(std::int64_t cycle, double time, double t_stop, double wall_seconds,
                             double min_interval) {
  if (!s_.terminal || !s_.terminal_is_tty) return;
  if (wall_seconds - last_progress_ < min_interval) return;
  last_progress_ = wall_seconds;
  const std::string text = format_progress(cycle, time, t_stop, wall_seconds);
  *s_.terminal << '\r' << text;
  if (text.size() < progress_len_) *s_.terminal << std::string(progress_len_ - text.size(), ' ');
  *s_.terminal << std::flush;
  progress_len_ = std::max(progress_len_, text.size());
}

void EngineListing::message(std::string_view text) {
  if (s_.file) *s_.file << text << '\n';
  if (s_.terminal) {
    clear_progress();
    *s_.terminal << text << '\n' << std::flush;
  }
}

void EngineListing::summary(const RunSummary& s) {
  summary_to_file(s);
  summary_to_terminal(s);
}

void EngineListing::summary_to_file(const RunSummary& s) {
  if (!s_.file) return;
  std::ostringstream os;
  write_run_summary(os, s);
  *s_.file << os.str() << std::flush;
}

void EngineListing::summary_to_terminal(const RunSummary& s) {
  if (!s_.terminal) return;
  std::ostringstream os;
  write_run_summary(os, s);
  clear_progress();
  *s_.terminal << os.str() << std::flush;
}

}  // namespace radx::io
