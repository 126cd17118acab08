// The engine listing (standard output and NAME_0001.out), Radioss style: a header block with the model and
// the resolved run controls, then every /PRINT cycles one line (docs/theory/elements.md section 8):
//   CYCLE TIME TIME-STEP ELEMENT(type id) ERROR% I-ENERGY K-ENERGY-T K-ENERGY-R EXT-WORK MAS.ERR TOTAL-MASS
//   MASS-ADDED
// with the column titles repeated every nh lines when /PRINT/n/nh asks; a progress line on interactive
// terminals only (rewritten in place with '\r'); and the end-of-run block: energy balance by kind, cycles,
// wall time, cost in microseconds per element per cycle, mass added, status and message.
//
// The engine fills the plain structs below; nothing here knows solver internals. Energies, masses and times
// are in work units.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <iosfwd>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "solver/model/run_controls.hpp"

namespace radx::io {

// ERROR % of docs/theory/elements.md 8: 100 (E_tot / (E_tot0 + W_ext) - 1), clipped to [-99.9, 99.9]; 0 when
// |E_tot0 + W_ext| <= 1e-20. E_tot = KE_T + KE_R + IE; E_tot0 = E_tot at cycle 0 minus the work booked at
// cycle 0; W_ext the external work so far. NaN inputs give NaN (shown, never hidden).
double energy_error_percent(double e_total, double e_total0, double w_ext);

// The energy error levels worth a warning during a run, 10 % and 50 % in absolute value, each said once:
// a run that ends quietly with most of its energy made up or lost is worse than one that stops. The run
// goes on (only /STOP Emax stops it).
class EnergyErrorWarnings {
 public:
  static constexpr std::array<double, 2> kLevels = {10.0, 50.0};
  // The warnings due at this error: one per level passed for the first time (none for NaN).
  std::vector<std::string> check(double error_percent);

 private:
  std::array<bool, kLevels.size()> said_{};
};

// What controls the time step printed on a listing line.
enum class StepSource : std::uint8_t {
  None,
  Brick,
  Shell,
  Shell3,
  Node,
  Interface,
  Imposed,
  Spring,
  Truss,
  Beam
};
// "BRICK", "SHELL", "SH3N", "NODE", "INTER", "SPRING", "TRUSS", "BEAM", "DTIX" (/DTIX set the step), or "-"
// for None.
std::string_view step_source_label(StepSource s);

// One listing line.
struct ListingLine {
  std::int64_t cycle = 0;
  double time = 0;
  double dt = 0;  // the time step of this cycle
  StepSource source = StepSource::None;
  std::int64_t source_id = 0;    // user id of the element, node or interface controlling dt
  std::int64_t source_node = 0;  // Interface: the secondary node of the controlling pair (printed id:node)
  double error_percent = 0;      // energy_error_percent(...)
  double internal_energy = 0;    // I-ENERGY (no hourglass, no contact)
  double kinetic_t = 0;          // K-ENERGY T
  double kinetic_r = 0;          // K-ENERGY R
  double external_work = 0;      // EXT-WORK
  double mass_error = 0;         // MAS.ERR = (M - M0) / M0
  double total_mass = 0;         // TOTAL MASS
  double added_mass = 0;         // MASS ADDED by /DT/.../CST
  std::int64_t switched_pairs = -1;  // LAG-PAIRS: LAGDT pairs solved with multipliers (-1: no such column)
};

// The column titles, aligned with format_listing_line (one line, no line end).
std::string listing_column_titles(bool lagrange_column = false);
// One listing line (no line end). Columns are blank separated; reals are printed with 6 significant
// digits (%.5E), the error with one decimal and a '%'; an element is "TYPE id" ("- -" when none).
std::string format_listing_line(const ListingLine& l);

// Energies at the end of the run (or at any cycle), by kind.
struct EnergyBalance {
  double kinetic_t = 0;
  double kinetic_r = 0;
  double internal = 0;
  double spring = 0;  // the springs' part of `internal` (listed apart, as OpenRadioss books it)
  double hourglass = 0;
  double contact_elastic = 0;
  double contact_damping = 0;
  double contact_friction = 0;
  double contact_lagrange = 0;
  double external_work = 0;
  double initial_total = 0;  // E_tot0 of docs/theory/elements.md 8
  // E_tot = KE_T + KE_R + IE + hourglass + contact. Radioss leaves hourglass and contact energies out of
  // its ERROR % (they show as a negative error); radx books them, so its balance closes
  // (docs/theory/verification.md C). This is a deliberate difference.
  [[nodiscard]] double total() const {
    return kinetic_t + kinetic_r + internal + hourglass + contact_elastic + contact_damping +
           contact_friction + contact_lagrange;
  }
  [[nodiscard]] double error_percent() const {
    return energy_error_percent(total(), initial_total, external_work);
  }
};

struct InterfaceSummary {
  std::int64_t id = 0;
  std::int64_t active_pairs = 0;          // pairs in contact at the end of the run
  double max_penetration = 0;             // largest penetration seen during the run
  std::int64_t switched_pairs_max = 0;    // LAGDT: most pairs switched to Lagrange in one cycle
  std::int64_t switched_pairs_total = 0;  // LAGDT: pair-cycles handled by Lagrange multipliers
  double added_mass = 0;                  // by /DT/INTER/CST on this interface's nodes
  std::int64_t removed_nodes = 0;         // deactivated (surface reached), Idel or /DT/INTER/DEL
  double candidates_mean = 0;             // candidate pairs of the search per cycle the interface was active
  std::int64_t search_sorts = 0;          // sorts of the candidate search
};

// Interrupted: SIGTERM or SIGINT stopped the run after a cycle, its last state written. Running: the summary
// a run writes when it starts, replaced at its end (a killed run leaves it behind).
enum class RunStatus : std::uint8_t { Normal, Error, Interrupted, Running };
// "NORMAL TERMINATION", "ERROR TERMINATION", "INTERRUPTED TERMINATION", "RUNNING".
std::string_view termination_label(RunStatus s);

// What the engine knows at the end of a run.
struct RunSummary {
  RunStatus status = RunStatus::Normal;
  std::string message;  // why the run ended ("end time reached", "/STOP: energy error ...", "interrupted by
                        // SIGTERM ...")
  std::string run_name;
  int run_number = 1;
  // The build that ran (apps/build_info.hpp): "0.1.0", "abc1234" (or "abc1234-dirty", "unknown"),
  // "x86-64-v2". Empty: not said (the summary then leaves the key out).
  std::string version, commit, arch;
  // The model's work units as /BEGIN names them and the listing states them ("kg", "m", "s"); empty before
  // the model is read.
  std::string mass_unit, length_unit, time_unit;
  std::int64_t cycles = 0;
  double time = 0;  // final time
  double dt = 0;    // last time step
  std::size_t nodes = 0;
  std::size_t elements = 0;
  int threads = 1;
  double wall_seconds = 0;
  double contact_seconds = 0;  // wall time in the contact step (search, forces), part of wall_seconds
  // Wall time in the element loop (element forces, their sums, the assembly, the integration), part of
  // wall_seconds; 0: not measured.
  double element_loop_seconds = 0;
  double initial_mass = 0;
  double mass = 0;        // total mass at the end (with added mass)
  double added_mass = 0;  // by /DT/NODA/CST and /DT/INTER/CST
  std::array<double, 3> momentum{0, 0, 0};
  EnergyBalance energy;
  std::vector<InterfaceSummary> interfaces;
  // Deleted elements (failed material, broken spring, truss or beam): the count of each part that lost any,
  // and the first ones with when they went (the listing names up to a thousand as they go).
  struct DeletedPart {
    std::int64_t part_id = 0;
    std::string title;
    std::int64_t count = 0;
  };
  struct DeletedElement {
    std::string kind;
    std::int64_t element_id = 0, part_id = 0, cycle = 0;
    double time = 0;
  };
  std::vector<DeletedPart> deleted_by_part;
  std::vector<DeletedElement> first_deleted;
  [[nodiscard]] std::int64_t deleted_total() const {
    std::int64_t n = 0;
    for (const auto& p : deleted_by_part) n += p.count;
    return n;
  }
  // --allow-substitutions: what ran instead of what the deck asks (from the model file).
  std::vector<std::string> substitutions;
  // The run's warnings, in the order said: those of the engine deck and its checks against the model, then
  // those during the run ("cycle N: ..."), at most kMaxSummaryWarnings (the listing has them all).
  std::vector<std::string> warnings;
  std::size_t warnings_left_out = 0;
  static constexpr std::size_t kMaxSummaryWarnings = 100;
  void add_warning(std::string text) {
    if (warnings.size() < kMaxSummaryWarnings)
      warnings.push_back(std::move(text));
    else
      ++warnings_left_out;
  }
  // The Lagrange-multiplier solver of switched LAGDT pairs (present: a LAGDT interface could switch).
  struct Lagrange {
    bool present = false;
    std::int64_t cycles = 0, rows_max = 0, rows_total = 0, nonzeros_max = 0, dropped_rows = 0,
                 merged_rows = 0;
    std::int64_t factorizations = 0, analyses = 0, symbolic_reuses = 0, regularisations = 0;
    std::int64_t active_set_passes = 0, passes_max = 0, unconverged = 0;
    double beta_max = 0, seconds_assembly = 0, seconds_factorization = 0, seconds_solve = 0;
  } lagrange;
  // Result files (empty when none were written) and the wall time spent writing them.
  int states = 0;
  std::string series;        // the ParaView index P.hdf.series
  std::string time_history;  // P_th.h5, or empty
  double output_seconds = 0;
};

// The warning a run whose hourglass energy passes 10 % of its internal energy gets (the ratio Radioss users
// check: above it the one-point elements' zero-energy modes carry a share of the work that the mesh's real
// deformation should), or "" below it.
std::string hourglass_warning(const EnergyBalance& e);

// Wall microseconds per element per cycle: 1e6 wall / (elements cycles); 0 when either count is 0. The
// second form takes another wall time of the run (the element loop's).
double us_per_element_cycle(const RunSummary& s);
double us_per_element_cycle(const RunSummary& s, double seconds);

// What the header block shows.
struct EngineListingHeader {
  std::string program_version;
  std::string engine_deck;
  std::string model_file;
  std::string output_root;  // NAME: outputs NAME_0001.out, NAME_summary.json, ...
  int threads = 1;
  std::size_t nodes = 0;
  std::size_t shells = 0;
  std::size_t shells3 = 0;
  std::size_t bricks = 0;
  std::size_t tetras = 0;
  std::size_t bricks20 = 0;
  std::size_t interfaces = 0;
  double total_mass = 0;
  std::string mass_unit = "kg", length_unit = "m", time_unit = "s";
  const model::RunControls* controls = nullptr;  // echoed when set
  // The notes and warnings of the engine deck and of its checks against the model, formatted, one per
  // line (a run with errors never starts); echoed under ENGINE DECK MESSAGES when there are any.
  std::vector<std::string> deck_messages;
};

void write_engine_header(std::ostream& os, const EngineListingHeader& h);
// The end-of-run block.
void write_run_summary(std::ostream& os, const RunSummary& s);

// "2 h 05 min", "3 min 07 s", "12.4 s".
std::string format_duration(double seconds);
// The progress text (no '\r', no line end): percentage of Tstop done, cycle, elapsed and estimated time
// left (linear in simulated time).
std::string format_progress(std::int64_t cycle, double time, double t_stop, double wall_seconds);
// isatty(STDOUT_FILENO).
bool stdout_is_terminal();

// Where listing output goes, and how.
struct ListingSinks {
  std::ostream* file = nullptr;      // NAME_0001.out (may be null)
  std::ostream* terminal = nullptr;  // standard output (may be null)
  bool lines_to_terminal = true;     // /PRINT with negative n
  bool terminal_is_tty = false;      // progress lines only on an interactive terminal
  int header_every = 0;              // /PRINT nh: column titles again every nh lines (0: once)
};

// The listing of one run: header block, lines (with their column titles), progress and end-of-run block,
// each to the right sinks. The progress line is cleared before any other output reaches the terminal.
class EngineListing {
 public:
  explicit EngineListing(ListingSinks sinks) : s_(sinks) {}
  void header(const EngineListingHeader& h);
  void line(const ListingLine& l);
  // Written at most every `min_interval` wall seconds; nothing when the terminal is not a tty.
  void progress(std::int64_t cycle, double time, double t_stop, double wall_seconds,
                double min_interval = 0.5);
  // A free message line (a warning during the run) to the file and the terminal.
  void message(std::string_view text);
  // The end-of-run block to both sinks; or to each alone, so a caller can learn whether the file took it
  // before the terminal says how the run ended.
  void summary(const RunSummary& s);
  void summary_to_file(const RunSummary& s);
  void summary_to_terminal(const RunSummary& s);
  [[nodiscard]] std::size_t lines_written() const { return lines_; }

 private:
  void clear_progress();
  ListingSinks s_;
  std::size_t lines_ = 0;
  std::size_t progress_len_ = 0;
  double last_progress_ = -1e300;
};

}  // namespace radx::io
