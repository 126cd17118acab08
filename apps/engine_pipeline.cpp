#include "apps/engine_pipeline.hpp"

#include "apps/build_info.hpp"
#include "apps/engine_decompose.hpp"
#include "apps/engine_outputs.hpp"
#include "apps/runaway_watch.hpp"
#include "apps/stop_deadline.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <memory>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include "io/hdf5/model_file.hpp"
#include "io/hdf5/results_writer.hpp"
#include "io/listing/engine_listing.hpp"
#include "io/listing/summary_json.hpp"
#include "io/text_file.hpp"
#include "parser/building/build_run_controls.hpp"
#include "parser/building/plausibility.hpp"
#include "parser/reading/deck.hpp"
#include "parser/reading/diagnostics.hpp"
#include "solver/engine/explicit_engine.hpp"
#include "solver/model/run_files.hpp"
#include "solver/model/stable_step.hpp"
#include "solver/parallel/engine_domain.hpp"

namespace radx::app {

namespace fs = std::filesystem;

namespace {

io::StepSource source_of(solver::StepControl::Kind k) {
  switch (k) {
    case solver::StepControl::Kind::Shell: return io::StepSource::Shell;
    case solver::StepControl::Kind::Shell3: return io::StepSource::Shell3;
    case solver::StepControl::Kind::Brick: return io::StepSource::Brick;
    // Radioss lists a tetrahedron's step as a solid's, BRICK with the element id.
    case solver::StepControl::Kind::Tetra: return io::StepSource::Brick;
    case solver::StepControl::Kind::Node: return io::StepSource::Node;
    case solver::StepControl::Kind::Interface: return io::StepSource::Interface;
    case solver::StepControl::Kind::Imposed: return io::StepSource::Imposed;
    case solver::StepControl::Kind::Spring: return io::StepSource::Spring;
    case solver::StepControl::Kind::Truss: return io::StepSource::Truss;
    case solver::StepControl::Kind::Beam: return io::StepSource::Beam;
    case solver::StepControl::Kind::None: break;
  }
  return io::StepSource::None;
}

// SIGTERM (what batch schedulers send at the wall-time limit) and SIGINT (Ctrl-C) ask the run to stop after
// the cycle under way, with its last state, summary and termination lines. A handler may only set a lock-free
// atomic, and it is given nothing but the signal number, so this flag is a global: the one the project
// allows, because the handler cannot reach anything else.
std::atomic<int> g_stop_signal{0};
static_assert(std::atomic<int>::is_always_lock_free, "a signal handler may only touch lock-free atomics");

// The first signal asks for the stop; a second one of the other kind, or of the same kind at least half a
// second later, ends the engine at once (for a user who will not wait for the last state): its default action
// is restored and the signal raised again, delivered as the handler returns. The same signal again sooner is
// the same request sent twice: `timeout` signals the engine and then its process group, and a script may
// signal both the process and its group, microseconds apart; ending at once then would lose the last state
// the first one asked for.
// (SA_RESETHAND would reset only the signal caught, so SIGTERM then SIGINT would still wait.) signal(),
// raise() and clock_gettime() are async-signal-safe.
std::atomic<std::int64_t> g_first_signal_ns{0};
static_assert(std::atomic<std::int64_t>::is_always_lock_free,
              "a signal handler may only touch lock-free atomics");
constexpr std::int64_t kRepeatedSignalNs = 500'000'000;

std::int64_t monotonic_ns() {
  timespec t{};
  ::clock_gettime(CLOCK_MONOTONIC, &t);
  return static_cast<std::int64_t>(t.tv_sec) * 1'000'000'000 + t.tv_nsec;
}

void on_stop_signal(int signo) {
  int none = 0;
  if (g_stop_signal.compare_exchange_strong(none, signo, std::memory_order_relaxed)) {
    g_first_signal_ns.store(monotonic_ns(), std::memory_order_relaxed);
    return;
  }
  if (signo == g_stop_signal.load(std::memory_order_relaxed) &&
      monotonic_ns() - g_first_signal_ns.load(std::memory_order_relaxed) < kRepeatedSignalNs)
    return;
  ::signal(signo, SIG_DFL);
  ::raise(signo);
}

// The handlers for the time of one run; the previous ones come back after it. SA_RESTART: a write to the
// output files carries on through the signal. A signal the engine was started with ignored (nohup, a
// background job) stays ignored.
class StopSignals {
 public:
  StopSignals() {
    g_stop_signal.store(0);
    struct sigaction sa {};
    sa.sa_handler = on_stop_signal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESTART;
    for (std::size_t k = 0; k < kSignals.size(); ++k) {
      sigaction(kSignals[k], &sa, &previous_[k]);
      if (previous_[k].sa_handler == SIG_IGN) sigaction(kSignals[k], &previous_[k], nullptr);
    }
  }
  ~StopSignals() {
    for (std::size_t k = 0; k < kSignals.size(); ++k) sigaction(kSignals[k], &previous_[k], nullptr);
  }
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

  // The signal received since the run began, 0 when none.
  [[nodiscard]] static int received() { return g_stop_signal.load(std::memory_order_relaxed); }

 private:
  static constexpr std::array<int, 2> kSignals{SIGTERM, SIGINT};
  std::array<struct sigaction, 2> previous_{};
};

// The watchdog's end of a run whose cycle did not end after a stop signal: the default action of the
// signal, as a second signal would give. The summary keeps saying "running": it was not written, and the
// run did not end normally.
void end_stuck_run(double waited_s) {
  const int signo = StopSignals::received();
  char line[160];
  std::snprintf(line, sizeof line,
                "radx-engine: the cycle under way did not end %.1f s after the stop signal; ending the run "
                "now, without a last state\n",
                waited_s);
  std::fputs(line, stderr);
  ::signal(signo, SIG_DFL);
  ::raise(signo);
}

std::string signal_name(int signo) {
  if (signo == SIGTERM) return "SIGTERM";
  if (signo == SIGINT) return "SIGINT";
  return "signal " + std::to_string(signo);
}

io::EnergyBalance to_io(const solver::EnergyBalance& e) {
  io::EnergyBalance b;
  b.kinetic_t = e.kinetic_t;
  b.kinetic_r = e.kinetic_r;
  b.internal = e.internal;
  b.spring = e.spring;
  b.hourglass = e.hourglass;
  b.contact_elastic = e.contact_elastic;
  b.contact_damping = e.contact_damping;
  b.contact_friction = e.contact_friction;
  b.contact_lagrange = e.contact_lagrange;
  b.external_work = e.external_work;
  b.initial_total = e.initial_total;
  return b;
}

// What to do about a model file that cannot be read. The starter leaves its listing NAME_0000.out beside
// the model file even when deck errors kept it from writing one: then the starter did run, and telling the
// user to run it "first" would send them in a circle.
std::string starter_hint(const std::string& model_path, const std::string& root) {
  std::error_code ec;
  if (fs::exists(model_path, ec) && !fs::is_regular_file(model_path, ec)) {
    // Most often --model given a folder: running the starter again would not help.
    return "  " + model_path + " is " +
           (fs::is_directory(model_path, ec) ? "a directory" : "not a regular file") +
           ": give the starter's model file itself, e.g. --model " + root + "_0000.hdf\n";
  }
  const fs::path listing = fs::path(model_path).replace_extension(".out");
  if (fs::exists(model_path, ec) || !fs::is_regular_file(listing, ec)) {
    return "  run the starter first (radx-starter " + root + "_0000.rad), or give it with --model FILE\n";
  }
  std::ifstream in(listing);
  std::string line;
  while (std::getline(in, line)) {
    if (line.find("no model file written") != std::string::npos) {
      return "  the starter ran but found errors in the deck, so it wrote no model file: fix the errors its "
             "listing " +
             listing.string() + " names (the starter also printed them), then run the starter again\n";
    }
  }
  return "  the starter's listing " + listing.string() +
         " is there but its model file is missing: run the starter again (radx-starter " + root +
         "_0000.rad), or give the model file with --model FILE\n";
}

// A problem of the model file as a diagnostic of that file: the codes are the same numbers (9xx).
Diag model_file_diag(io::ModelFileCode code) {
  static_assert(static_cast<int>(Diag::ModelFileBadReference) ==
                static_cast<int>(io::ModelFileCode::BadReference));
  static_assert(static_cast<int>(Diag::ModelFileBadValue) == static_cast<int>(io::ModelFileCode::BadValue));
  static_assert(static_cast<int>(Diag::ModelFileOtherFormat) ==
                static_cast<int>(io::ModelFileCode::OtherFormat));
  static_assert(static_cast<int>(Diag::ModelFileChanged) == static_cast<int>(io::ModelFileCode::Changed));
  static_assert(static_cast<int>(Diag::ModelFileOtherRun) == static_cast<int>(io::ModelFileCode::OtherRun));
  return static_cast<Diag>(static_cast<std::uint16_t>(code));
}

// The engine deck runs the model of its own run: the run the starter wrote the model for (NAME of its
// NAME_0000.rad) is the engine deck's (NAME of NAME_0001.rad, run_files.hpp), as radx names every file of a
// run. Another deck's model, given with --model or copied under this run's name, is refused.
void check_model_of_this_run(const io::ModelFileFingerprint& f, const std::string& model_path,
                             const std::string& engine_deck, const std::string& root,
                             const model::RunControls& controls, Diagnostics& diags) {
  if (f.run == root) return;
  const std::string made_from =
      f.deck_files.empty() ? std::string() : " (made from " + f.deck_files.front() + ")";
  diags.error(Diag::ModelFileOtherRun, Where{model_path}, About{},
              (f.run.empty() ? std::string("the model file does not say which run it is the model of")
                             : "the model file is the model of run " + f.run + made_from) +
                  ", but the engine deck " + engine_deck + " is run " + root + " (/RUN/" + controls.run_name +
                  "): give the model of " + root + " (run radx-starter " + root +
                  "_0000.rad, or give its model file with --model)");
}

// The model file read, checked entry by entry, and found to be the model of this run. False, with every
// problem printed against the model file, when the engine must not run it.
bool read_checked_model(const std::string& model_path, const std::string& engine_deck,
                        const std::string& root, const model::RunControls& controls, model::Model& model,
                        std::ostream& err) {
  const io::ModelFileReading r = io::read_model_file(model_path, model);
  if (!r.error.empty()) {
    err << model_path << ": error: cannot read the model file: " << r.error << '\n';
    err << (r.error.find("the file is damaged") != std::string::npos
                ? "  run the starter again to write the model file anew\n"
                : starter_hint(model_path, root));
    return false;
  }
  Diagnostics diags;
  for (const auto& p : r.problems.items)
    diags.error(model_file_diag(p.code), Where{model_path}, About{}, p.where + ": " + p.message);
  check_model_of_this_run(r.fingerprint, model_path, engine_deck, root, controls, diags);
  if (!diags.has_errors()) return true;
  diags.print(err);
  const std::size_t count = r.problems.count + diags.error_count() - r.problems.items.size();
  if (r.problems.count > r.problems.items.size())
    err << "radx-engine: the first " << r.problems.items.size() << " problems of the model file are listed\n";
  err << "radx-engine: " << count << " error(s) in the model file " << model_path
      << "; nothing was run. The engine runs only a model file its starter wrote, unchanged, for this run: "
         "run the starter on the deck again (radx-starter "
      << root << "_0000.rad)\n";
  return false;
}

// The run starts: nothing of an earlier run of this name may stay beside its outputs, where a script would
// take it for this run's, even if this run is refused or killed before its first cycle. False (with the
// reason on err) when the folder cannot be locked or cleared.
bool claim_output_folder(const std::string& out_dir, const std::string& root, RunLock& lock,
                         std::ostream& err) {
  std::error_code ec;
  fs::create_directories(out_dir, ec);
  try {
    lock = RunLock(out_dir, root);
    remove_earlier_engine_outputs(out_dir, root);
  } catch (const std::exception& e) {
    err << "radx-engine: error: " << e.what() << '\n';
    return false;
  }
  return true;
}

// NAME_0002.rad and later beside NAME_0001.rad are the restart decks OpenRadioss runs one after another; radx
// runs NAME_0001.rad only, and says so once rather than skip them without a word.
void note_restart_decks(const std::string& path, Diagnostics& diags) {
  const auto found = model::later_engine_decks(path);
  if (found.empty()) return;
  const std::string name = fs::path(path).filename().string();
  std::string list;
  for (const auto& f : found) list += (list.empty() ? "" : ", ") + f;
  diags.note(Diag::EngineRestartDecks, Where{path}, About{},
             list +
                 (found.size() == 1 ? " is an OpenRadioss restart deck" : " are OpenRadioss restart decks") +
                 " (run after " + name +
                 " from its restart file); radx does not run restart decks: it runs " + name + " only");
}

// The engine deck read into controls, its diagnostics printed; false when it has errors.
bool read_engine_deck_checked(const std::string& path, Diagnostics& diags, EngineDeck& deck,
                              model::RunControls& controls, std::ostream& err) {
  controls = read_run_controls(path, diags, &deck);
  note_restart_decks(path, diags);
  diags.sort();
  diags.print(err);
  if (!diags.has_errors()) return true;
  err << "radx-engine: " << diags.error_count() << " error(s) in " << path << "; nothing was run\n";
  return false;
}

// What the engine said during the cycle: warnings to the listing, standard error and the summary; events to
// the listing, with their cycle and time.
void report_cycle_messages(solver::ExplicitEngine& engine, const solver::CycleReport& r,
                           std::ostream& listing_file, io::EngineListing& listing, std::ostream& err,
                           io::RunSummary& s) {
  for (const auto& m : engine.take_messages()) {
    listing_file << "  WARNING (cycle " << r.cycle << "): " << m << '\n';
    err << "radx-engine: warning: cycle " << r.cycle << ", time " << r.time << ": " << m << '\n';
    s.add_warning("cycle " + std::to_string(r.cycle) + ": " + m);
  }
  for (const auto& m : engine.take_events()) {
    char at[64];
    std::snprintf(at, sizeof at, " (cycle %lld, t = %.5E)", static_cast<long long>(r.cycle), r.time);
    listing.message(" " + m + at);
  }
}

// What the model uses that the engine does not run on more than one rank yet (solver/parallel/
// engine_domain.hpp), read before the output folder is claimed, so a refused run leaves nothing written.
// Every rank reads the same deck and model and finds the same list; rank 0 alone says it. A deck or model
// that does not read is left to the run itself, which reports it.
bool refuse_distributed_run(const EngineOptions& opt, const solver::parallel::Comm& comm, std::ostream& err) {
  std::ostringstream quiet;
  Diagnostics diags;
  EngineDeck deck;
  model::RunControls controls;
  if (!read_engine_deck_checked(opt.engine_deck, diags, deck, controls, quiet)) return false;
  const std::string root = model::run_output_root(opt.engine_deck);
  const std::string model_path =
      opt.model_file.empty() ? (fs::path(opt.out_dir) / (root + "_0000.hdf")).string() : opt.model_file;
  model::Model model;
  if (!read_checked_model(model_path, opt.engine_deck, root, controls, model, quiet)) return false;
  const auto refused = solver::parallel::features_not_distributed(model, controls);
  if (refused.empty()) return false;
  if (comm.rank() == 0) {
    err << "radx-engine-mpi: error: " << opt.engine_deck << ": the run cannot be split over " << comm.size()
        << " ranks yet: it uses";
    for (std::size_t k = 0; k < refused.size(); ++k) err << (k == 0 ? " " : ", ") << refused[k];
    err << ", which the engine runs on one rank only; run it with mpirun -np 1, or radx-engine\n";
  }
  return true;
}

// How the run ended: normally, interrupted by a signal, or in error; and the reason.
void set_final_status(io::RunSummary& s, const solver::RunResult& result, int stopped_by,
                      const std::string& stop_message) {
  s.status = result.status == solver::RunStatus::Normal ? io::RunStatus::Normal
             : stopped_by != 0                          ? io::RunStatus::Interrupted
                                                        : io::RunStatus::Error;
  s.message = !stop_message.empty()    ? stop_message
              : result.message.empty() ? std::string("end time reached")
                                       : result.message;
}

// The summary's model figures and the decks' warnings, before the run starts.
void start_summary(io::RunSummary& s, const model::Model& model, const solver::ExplicitEngine& engine,
                   std::initializer_list<const Diagnostics*> lists) {
  s.nodes = model.nodes.size();
  s.elements = engine.element_count();
  for (const auto* list : lists)
    for (const auto& d : list->items())
      if (d.severity == Severity::Warning) s.add_warning(Diagnostics::format(d));
}

// The last state and time-history row, also after an error stop, and the energy plot. A failure to write them
// makes the run an error termination (no longer an interruption), with that reason unless /STOP gave one.
void finish_outputs(EngineOutputs& outputs, bool plot, std::ostream& err, solver::RunResult& result,
                    std::string& stop_message, int& stopped_by) {
  try {
    outputs.finish(result, plot, err);
  } catch (const std::exception& e) {
    err << "radx-engine: error: cannot write the results: " << e.what() << '\n';
    if (stop_message.empty() || stopped_by != 0)
      stop_message = std::string("cannot write the results: ") + e.what();
    stopped_by = 0;
    result.status = solver::RunStatus::Error;
  }
}

// A listing or summary that cannot be written makes the run an error termination, with that reason unless
// the run already ended in error; the error goes to standard error at once.
void fail_run(io::RunSummary& s, const std::string& why, std::ostream& err) {
  err << "radx-engine: error: " << why << '\n';
  if (s.status == io::RunStatus::Error) return;
  s.status = io::RunStatus::Error;
  s.message = why;
}

// The summary and the listing's termination lines written, the reason also on standard error (where a batch
// system or a script looks for it), and the exit code: 0 normal, 1 error, 128 + the signal for an
// interruption (as a shell reports it). The summary first, then the listing file, and standard output last:
// it says NORMAL TERMINATION only when both were written. A summary that cannot be written leaves none.
int end_of_run(io::RunSummary& s, io::EngineListing& listing, io::CheckedOutputFile& listing_file,
               const std::string& summary_path, int stopped_by, std::ostream& err) {
  const std::string listing_error = listing_file.error();
  if (!listing_error.empty() && s.message.find(listing_error) == std::string::npos)
    fail_run(s, "cannot write the listing: " + listing_error, err);
  std::string error;
  if (!io::write_summary_json(summary_path, s, error)) fail_run(s, "cannot write the summary: " + error, err);
  listing.summary_to_file(s);
  if (listing_error.empty() && !listing_file.error().empty()) {
    fail_run(s, "cannot write the listing: " + listing_file.error(), err);
    io::write_summary_json(summary_path, s, error);
  }
  listing.summary_to_terminal(s);
  if (s.status == io::RunStatus::Error) err << "radx-engine: error termination: " << s.message << '\n';
  if (s.status == io::RunStatus::Interrupted)
    err << "radx-engine: " << s.message << "; the last state, the summary and the listing are written\n";
  if (s.status == io::RunStatus::Interrupted) return 128 + stopped_by;
  return s.status == io::RunStatus::Normal ? 0 : 1;
}

// The listing's header: what runs, on what, in which units, with the deck's messages.
io::EngineListingHeader listing_header(const EngineOptions& opt, const model::Model& model,
                                       const std::string& model_path, const std::string& root,
                                       const model::RunControls& controls,
                                       std::initializer_list<const Diagnostics*> messages) {
  io::EngineListingHeader h;
  h.program_version = RADX_VERSION " (" RADX_ARCH ")";
  h.engine_deck = opt.engine_deck;
  h.model_file = model_path;
  h.output_root = root;
  h.nodes = model.nodes.size();
  h.shells = model.shells.size();
  h.shells3 = model.shells3.size();
  h.bricks = model.bricks.size();
  h.tetras = model.tetras.size();
  h.bricks20 = model.bricks20.size();
  h.interfaces = model.interfaces.size();
  h.total_mass = model.total_mass;
  h.mass_unit = model.units.mass_name;
  h.length_unit = model.units.length_name;
  h.time_unit = model.units.time_name;
  h.controls = &controls;
  for (const auto* list : messages)
    for (auto& l : list->lines()) h.deck_messages.push_back(std::move(l));
  return h;
}

// One line of the listing for a report cycle; the switched LAGDT pairs only when an interface can switch.
io::ListingLine listing_line(const solver::CycleReport& r, bool lagrange_column) {
  io::ListingLine l;
  l.cycle = r.cycle;
  l.time = r.time;
  l.dt = r.dt;
  l.source = source_of(r.control.kind);
  l.source_id = r.control.user_id;
  l.source_node = r.control.node_id;
  l.error_percent = r.energy.error_percent;
  l.internal_energy = r.energy.internal;
  l.kinetic_t = r.energy.kinetic_t;
  l.kinetic_r = r.energy.kinetic_r;
  l.external_work = r.energy.external_work;
  l.mass_error = r.mass0 > 0 ? (r.mass - r.mass0) / r.mass0 : 0.0;
  l.total_mass = r.mass;
  l.added_mass = r.added_mass;
  if (lagrange_column) l.switched_pairs = r.switched_pairs;
  return l;
}

// Why /STOP stops the run at this report (energy error, mass error), or nothing.
std::string stop_criterion(const model::RunControls& controls, const solver::CycleReport& r) {
  const double err_pct = r.energy.error_percent;
  const bool err_hit = controls.stop_positive_error_only ? err_pct > controls.stop_energy_error_pct
                                                         : std::abs(err_pct) > controls.stop_energy_error_pct;
  if (err_hit)
    return "/STOP: energy error " + std::to_string(err_pct) + " % beyond " +
           std::to_string(controls.stop_energy_error_pct) + " %";
  if (r.mass0 > 0 && (r.mass - r.mass0) / r.mass0 > controls.stop_mass_error)
    return "/STOP: mass error beyond " + std::to_string(controls.stop_mass_error);
  return {};
}

// /RBODY/ON and /RBODY/OFF name rigid bodies of the model. Every body is active at the start of a run (one
// with a sensor until the sensor releases it), so ON keeps it and OFF leaves it out of this run; an id the
// model lacks switches nothing (a warning, as Radioss goes on too). And the cycle count the run would need:
// the starter warns too, but only when it found this engine deck beside its own; and the animation states
// it would write.
Diagnostics check_deck_against_model(const EngineDeck& deck, model::RunControls& controls,
                                     const model::Model& model, const model::StepEstimate& step) {
  std::vector<std::int64_t> body_ids;
  for (const auto& b : model.rigid_bodies) body_ids.push_back(b.id);
  Diagnostics model_diags;
  check_rigid_body_switches(deck, body_ids, controls, model_diags);
  check_cycle_count(deck, controls, model, step, model_diags);
  check_output_count(deck, controls, model, step, model_diags);
  model_diags.sort();
  return model_diags;
}

// The LAGDT solver's figures of the run.
void fill_lagrange_summary(const contact::LagrangeStats& st, decltype(io::RunSummary::lagrange)& L) {
  L.present = true;
  L.cycles = st.cycles;
  L.rows_max = st.rows_max;
  L.rows_total = st.rows_total;
  L.nonzeros_max = st.nonzeros_max;
  L.dropped_rows = st.dropped_rows;
  L.merged_rows = st.merged_rows;
  L.factorizations = st.factorizations;
  L.analyses = st.analyses;
  L.symbolic_reuses = st.symbolic_reuses;
  L.regularisations = st.regularisations;
  L.active_set_passes = st.active_set_passes;
  L.passes_max = st.passes_max;
  L.unconverged = st.unconverged;
  L.beta_max = st.beta_max;
  L.seconds_assembly = st.seconds_assembly;
  L.seconds_factorization = st.seconds_factorization;
  L.seconds_solve = st.seconds_solve;
}

// The run's figures into its summary: cycles, time, cost, masses, momentum, energies, interfaces, the LAGDT
// solver, the outputs written.
void fill_run_summary(io::RunSummary& s, const solver::RunResult& result, const model::Model& model,
                      const model::RunControls& controls, const solver::ExplicitEngine& engine,
                      const EngineOutputs& outputs, const std::string& th_path) {
  s.cycles = result.cycles;
  s.time = result.time;
  s.dt = result.dt;
  s.threads = result.threads;
  s.wall_seconds = result.wall_seconds;
  s.contact_seconds = result.contact_seconds;
  s.element_loop_seconds = result.element_seconds;
  s.initial_mass = result.last.mass0;
  s.mass = result.last.mass;
  s.added_mass = result.last.added_mass;
  s.momentum = result.last.momentum;
  s.energy = to_io(result.last.energy);
  if (const auto w = io::hourglass_warning(s.energy); !w.empty()) s.add_warning(w);
  s.substitutions = model.substitutions;
  if (const auto* c = engine.contact())
    for (const auto& r : c->results())
      s.interfaces.push_back(io::InterfaceSummary{r.id, r.active_pairs, r.max_penetration,
                                                  r.switched_pairs_max, r.switched_pairs_total, r.added_mass,
                                                  r.deactivated_nodes, r.mean_candidates(), r.search_sorts});
  if (const auto* c = engine.contact(); c != nullptr && c->has_lagrange())
    fill_lagrange_summary(c->lagrange_stats(), s.lagrange);
  const auto& by_part = engine.deleted_by_part();
  for (std::size_t p = 0; p < by_part.size(); ++p)
    if (by_part[p] > 0) s.deleted_by_part.push_back({model.parts[p].id, model.parts[p].title, by_part[p]});
  for (const auto& d : engine.first_deleted())
    s.first_deleted.push_back({d.kind, d.element_id, d.part_id, d.cycle, d.time});
  s.states = outputs.states_written();
  s.series = outputs.series_path();
  if (!model.time_histories.empty() || controls.th_dt < 1e29) s.time_history = th_path;
  s.output_seconds = outputs.seconds_writing();
}

// What the pipeline does after each cycle the engine reports: the cycle's messages and progress, the time
// history's interval means, and on full reports the energy warnings, the outputs, the listing line, the /STOP
// criteria and the stop signals. after_cycle returns false to end the run, with the reason in stop_message
// (and the signal in stopped_by).
struct CycleWatch {
  solver::ExplicitEngine& engine;
  const model::RunControls& controls;
  EngineOutputs& outputs;
  io::EngineListing& listing;
  io::CheckedOutputFile& listing_file;
  std::ostream& err;
  io::RunSummary& s;
  std::chrono::steady_clock::time_point wall0 = std::chrono::steady_clock::now();
  bool lagrange_column = engine.contact() != nullptr && engine.contact()->has_lagrange();
  io::EnergyErrorWarnings energy_warnings{};
  RunawayWatch runaway{};
  bool stop_if_runaway = false;
  std::string stop_message{};
  int stopped_by = 0;

  bool after_cycle(const solver::CycleReport& r) {
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    report_cycle_messages(engine, r, listing_file, listing, err, s);
    listing.progress(r.cycle, r.time, controls.t_stop, wall);
    outputs.accumulate(r);  // every cycle: the interval means of the time history
    if (!r.full) return true;
    // To the listing and standard output (the run's own record), and to standard error as other warnings.
    for (const auto& m : energy_warnings.check(r.energy.error_percent)) {
      listing.message("  WARNING (cycle " + std::to_string(r.cycle) + "): " + m);
      err << "radx-engine: warning: cycle " << r.cycle << ", time " << r.time << ": " << m << '\n';
      s.add_warning("cycle " + std::to_string(r.cycle) + ": " + m);
    }
    if (!check_runaway(r, wall)) return false;
    try {
      outputs.on_report(r);
    } catch (const std::exception& e) {
      stop_message = std::string("cannot write the results: ") + e.what();
      return false;
    }
    if (const std::string& e = listing_file.error(); !e.empty()) {
      stop_message = "cannot write the listing: " + e;
      return false;
    }
    // Read once per cycle, on full reports only: a signal that lands after a partial report stops the next
    // cycle, which output_due makes full. On the last cycle the run ends normally anyway.
    const int signo = r.time < controls.t_stop ? StopSignals::received() : 0;
    if (signo == 0 && r.cycle % std::max(1, controls.print_every) != 0 && r.time < controls.t_stop)
      return true;
    listing.line(listing_line(r, lagrange_column));
    if (std::string why = stop_criterion(controls, r); !why.empty()) {
      stop_message = why;
      return false;
    }
    if (signo != 0) {
      stopped_by = signo;
      char at[96];
      std::snprintf(at, sizeof at, " at cycle %lld, time %.5E", static_cast<long long>(r.cycle), r.time);
      stop_message = "interrupted by " + signal_name(signo) + at;
      return false;
    }
    return true;
  }

  // A run that will not end: warned once (listing, standard output and error, summary), or with
  // --stop-if-runaway stopped here (false), on a full report so that its last state and summary agree.
  bool check_runaway(const solver::CycleReport& r, double wall) {
    const std::string m = runaway.check(r, wall, stop_if_runaway);
    if (m.empty()) return true;
    if (stop_if_runaway) {
      stop_message = "stopped by --stop-if-runaway at cycle " + std::to_string(r.cycle) + ": " + m;
      return false;
    }
    listing.message("  WARNING (cycle " + std::to_string(r.cycle) + "): " + m);
    err << "radx-engine: warning: cycle " << r.cycle << ", time " << r.time << ": " << m << '\n';
    s.add_warning("cycle " + std::to_string(r.cycle) + ": " + m);
    return true;
  }
};

}  // namespace

// The file is removed as the lock is released, so a folder keeps no lock file after a run that ended. A
// process that opened the file just before that holds a lock on a removed file: it checks, after locking,
// that the path still names the file it locked, and starts again if not.
RunLock::RunLock(const std::string& out_dir, const std::string& root)
    : path_((fs::path(out_dir) / (root + ".lock")).string()) {
  for (int attempt = 0; attempt < 100; ++attempt) {
    fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0) throw std::runtime_error("cannot open the lock file " + path_ + ": " + std::strerror(errno));
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      const int e = errno;
      std::string holder;
      char buf[32] = {};
      if (::pread(fd_, buf, sizeof buf - 1, 0) > 0) holder = std::to_string(std::atoll(buf));
      ::close(fd_);
      fd_ = -1;
      if (e != EWOULDBLOCK) throw std::runtime_error("cannot lock " + path_ + ": " + std::strerror(e));
      throw std::runtime_error("another radx process" +
                               (holder.empty() || holder == "0" ? "" : " (pid " + holder + ")") +
                               " is running " + root + " in " + out_dir + " (it holds " + path_ +
                               "); wait for it to end, stop it, or give this run another output folder");
    }
    struct stat locked {};
    struct stat named {};
    if (::fstat(fd_, &locked) == 0 && ::stat(path_.c_str(), &named) == 0 && locked.st_ino == named.st_ino &&
        locked.st_dev == named.st_dev)
      break;
    ::close(fd_);
    fd_ = -1;
  }
  if (fd_ < 0) throw std::runtime_error("cannot lock " + path_ + ": it keeps being replaced");
  // The pid, for the message of a second run; written after the lock, so a reader sees the holder's.
  const std::string pid = std::to_string(::getpid()) + '\n';
  if (::ftruncate(fd_, 0) != 0 ||
      ::pwrite(fd_, pid.data(), pid.size(), 0) != static_cast<ssize_t>(pid.size())) {
    // The lock holds without the pid; a second run's message then names no process.
  }
}

void RunLock::release() {
  if (fd_ < 0) return;
  ::unlink(path_.c_str());
  ::close(fd_);
  fd_ = -1;
}

RunLock::RunLock(RunLock&& o) noexcept : fd_(std::exchange(o.fd_, -1)), path_(std::move(o.path_)) {}

RunLock& RunLock::operator=(RunLock&& o) noexcept {
  if (this != &o) {
    release();
    fd_ = std::exchange(o.fd_, -1);
    path_ = std::move(o.path_);
  }
  return *this;
}

RunLock::~RunLock() {
  release();
}

void remove_earlier_engine_outputs(const std::string& out_dir, const std::string& root) {
  remove_earlier_outputs(out_dir, root);
  io::remove_result_set(out_dir, root);
}

namespace {

// The model of a run and the engine's element groups, read and checked as for a run, without running: the
// engine has one thread, and its groups are the ones a run builds. The model outlives the engine, which
// refers to it.
struct GroupedModel {
  model::Model model;
  std::unique_ptr<solver::ExplicitEngine> engine;
};

// False, with the problems printed on `err`, when the deck, the model or the engine's set-up fails.
bool read_grouped_model(const EngineOptions& opt, GroupedModel& g, std::ostream& err) {
  const std::string root = model::run_output_root(opt.engine_deck);
  Diagnostics diags;
  EngineDeck deck;
  model::RunControls controls;
  if (!read_engine_deck_checked(opt.engine_deck, diags, deck, controls, err)) return false;
  const std::string model_path =
      opt.model_file.empty() ? (fs::path(opt.out_dir) / (root + "_0000.hdf")).string() : opt.model_file;
  if (!read_checked_model(model_path, opt.engine_deck, root, controls, g.model, err)) return false;
  try {
    g.engine = std::make_unique<solver::ExplicitEngine>(g.model, controls, solver::EngineOptions(1));
  } catch (const std::exception& e) {
    err << opt.engine_deck << ": error: " << e.what() << '\n';
    return false;
  }
  return true;
}

// radx-engine --decompose P: the engine's element groups built, and the decomposition printed and written
// (apps/engine_decompose.hpp). Nothing runs, and nothing an earlier run left in the output folder is touched
// (no lock either: only NAME_domain.hdf and NAME_partition.txt are written, each whole or not at all).
int decompose_engine(const EngineOptions& opt, std::ostream& out, std::ostream& err) {
  GroupedModel g;
  if (!read_grouped_model(opt, g, err)) return 1;
  return decompose_model(g.model, g.engine->groups(), opt.decompose_ranks, opt.partition_file, opt.out_dir,
                         model::run_output_root(opt.engine_deck), out, err);
}

// A run with --partition FILE: the group ranks from FILE (apps/engine_decompose.hpp) instead of METIS, for
// the comm's P ranks. Rank 0 reads and checks the file before the output folder is claimed, then broadcasts
// its verdict and the ranks, so that a bad file ends every rank with exit 1, said once (by rank 0) and with
// nothing written. A deck or model that does not read is left to the run, which reports it. False when the
// run must not start; else `group_ranks` holds the file's ranks on every rank (empty when left to the run).
bool read_given_group_ranks(const EngineOptions& opt, std::ostream& err,
                            std::vector<std::int32_t>& group_ranks) {
  const int rank = opt.comm != nullptr ? opt.comm->rank() : 0;
  const int ranks = opt.comm != nullptr ? opt.comm->size() : 1;
  solver::parallel::Buffer message(1, std::byte{0});  // 0 and the ranks, or 1: the file is refused
  if (rank == 0) {
    std::ostringstream quiet;
    GroupedModel g;
    if (read_grouped_model(opt, g, quiet)) {
      Diagnostics diags;
      const auto file_ranks = read_group_ranks(opt.partition_file, g.engine->groups().count(), ranks, diags);
      if (diags.has_errors()) {
        diags.print(err);
        err << (ranks > 1 ? "radx-engine-mpi: " : "radx-engine: ") << diags.error_count()
            << " error(s) in the group-rank file " << opt.partition_file << " (--partition, for " << ranks
            << (ranks > 1 ? " ranks: mpirun -np " + std::to_string(ranks) : " rank")
            << "); nothing was run\n";
        message[0] = std::byte{1};
      } else {
        const std::vector<std::int32_t> given(file_ranks.begin(), file_ranks.end());
        const auto* bytes = reinterpret_cast<const std::byte*>(given.data());
        message.insert(message.end(), bytes, bytes + given.size() * sizeof(std::int32_t));
      }
    }
  }
  if (opt.comm != nullptr) opt.comm->broadcast(message, 0);
  if (message[0] != std::byte{0}) return false;
  group_ranks.resize((message.size() - 1) / sizeof(std::int32_t));
  if (!group_ranks.empty()) std::memcpy(group_ranks.data(), message.data() + 1, message.size() - 1);
  return true;
}

// `loop_ended`, when given, is set once the engine's cycle loop has ended: on more than one rank every rank
// leaves it on the same cycle, so an end before that point is this rank's alone.
int run_engine_on_this_rank(const EngineOptions& opt, std::ostream& out, std::ostream& err,
                            bool* loop_ended = nullptr);

// A stream that drops what it is given: the printing of ranks other than 0.
class NullStream : public std::ostream {
 public:
  NullStream() : std::ostream(nullptr) {}
};

// Ranks other than 0 run the same pipeline, so they take every collective step rank 0 takes (the outputs'
// gathers, the stop decisions), into a private folder that is removed at the end: rank 0 alone writes the
// run's files and prints.
int run_engine_on_other_rank(const EngineOptions& opt, bool* loop_ended) {
  const std::string root = model::run_output_root(opt.engine_deck);
  std::string scratch = (fs::temp_directory_path() / "radx-rank-XXXXXX").string();
  if (::mkdtemp(scratch.data()) == nullptr) {
    opt.comm->abort(1, "radx-engine-mpi: error: rank " + std::to_string(opt.comm->rank()) +
                           " cannot make its scratch folder: " + std::strerror(errno));
  }
  EngineOptions mine = opt;
  mine.out_dir = scratch;
  mine.model_file =
      opt.model_file.empty() ? (fs::path(opt.out_dir) / (root + "_0000.hdf")).string() : opt.model_file;
  mine.plot = false;
  NullStream quiet;
  std::ostringstream errors;  // said only if this rank ends the run alone (below), else rank 0 says it
  const int code = run_engine_on_this_rank(mine, quiet, errors, loop_ended);
  std::error_code ignored;
  fs::remove_all(scratch, ignored);
  if (code != 0 && !*loop_ended) {
    std::string text = errors.str();
    while (!text.empty() && text.back() == '\n') text.pop_back();
    opt.comm->abort(code, text.empty() ? "failed before the run's end; ending every rank"
                                       : text + " (ending every rank)");
  }
  return code;
}

}  // namespace

int run_engine(const EngineOptions& options, std::ostream& out, std::ostream& err) {
  EngineOptions opt = options;
  if (!opt.partition_file.empty() && opt.decompose_ranks == 0 &&
      !read_given_group_ranks(opt, err, opt.group_ranks))
    return 1;
  if (!opt.group_ranks.empty() && opt.comm != nullptr && opt.comm->size() > 1)
    out << "radx-engine-mpi: the element groups go to the ranks " << opt.partition_file
        << " gives (--partition), not to METIS's\n";
  if (opt.comm == nullptr || opt.comm->size() == 1) return run_engine_on_this_rank(opt, out, err);
  if (refuse_distributed_run(opt, *opt.comm, err)) return 1;
  bool loop_ended = false;
  const int code = opt.comm->rank() == 0 ? run_engine_on_this_rank(opt, out, err, &loop_ended)
                                         : run_engine_on_other_rank(opt, &loop_ended);
  // A rank that fails before the cycle loop has ended on every rank (its output folder locked, a file it
  // cannot write, an exception of its own) would leave the others waiting in a collective: end them all.
  // Rank 0 has printed its message; the others say theirs as they end (run_engine_on_other_rank).
  if (code != 0 && !loop_ended) opt.comm->abort(code, "the error above ends the run on every rank");
  return code;
}

namespace {

int run_engine_on_this_rank(const EngineOptions& opt, std::ostream& out, std::ostream& err,
                            bool* loop_ended) {
  if (opt.decompose_ranks > 0) return decompose_engine(opt, out, err);
  // Before anything that takes time (reading the deck and the model, setting up): a signal during it stops
  // the run before its first cycle, and the default action (an end without a summary) never meets it.
  const StopSignals stop_signals;
  const std::string root = model::run_output_root(opt.engine_deck);
  // The deck first: a restart run (refused until radx can resume one) must not touch run 1's outputs, which
  // claiming the folder removes. Other deck errors still clear them, so no earlier run's results stay beside
  // a run that did not happen.
  Diagnostics diags;
  EngineDeck deck;
  model::RunControls controls;
  const bool deck_read = read_engine_deck_checked(opt.engine_deck, diags, deck, controls, err);
  if (!deck_read && controls.run_number >= 2) return 1;
  RunLock lock;
  if (!claim_output_folder(opt.out_dir, root, lock, err)) return 1;
  const std::string summary_path = io::summary_json_path(opt.out_dir, root);
  io::RunSummary s;
  s.version = kVersion;
  s.commit = build_commit();
  s.arch = kArch;
  // A stop signal before the engine runs: the summary says so, and the exit code is the signal's.
  auto interrupted_early = [&]() {
    const int signo = StopSignals::received();
    s.status = io::RunStatus::Interrupted;
    s.message = "interrupted by " + signal_name(signo) + " before the first cycle";
    std::string ignored;
    io::write_summary_json(summary_path, s, ignored);
    err << "radx-engine: " << s.message << '\n';
    return 128 + signo;
  };
  if (!deck_read) return 1;
  s.run_name = controls.run_name;
  s.run_number = controls.run_number;
  const std::string model_path =
      opt.model_file.empty() ? (fs::path(opt.out_dir) / (root + "_0000.hdf")).string() : opt.model_file;
  model::Model model;
  if (!read_checked_model(model_path, opt.engine_deck, root, controls, model, err)) return 1;
  s.mass_unit = model.units.mass_name;
  s.length_unit = model.units.length_name;
  s.time_unit = model.units.time_name;
  if (StopSignals::received() != 0) return interrupted_early();
  const model::StepEstimate step_estimate = model::estimate_stable_step(model);
  Diagnostics model_diags = check_deck_against_model(deck, controls, model, step_estimate);
  model_diags.print(err);
  // Kinematic conditions check what the starter could not (a moving wall without mass, a rigid body
  // without inertia) and throw with a message; report it as an input error.
  std::unique_ptr<solver::ExplicitEngine> engine_ptr;
  std::unique_ptr<EngineOutputs> outputs;
  solver::EngineOptions engine_options(opt.threads, std::max(1, controls.print_every));
  engine_options.comm = opt.comm;
  engine_options.group_ranks = opt.group_ranks;
  // A stop signal makes the next cycle a full report (energies summed), so the run ends on a cycle whose
  // state, time-history row and summary agree.
  engine_options.output_due = [&outputs](double t) {
    return StopSignals::received() != 0 || (outputs && outputs->due(t));
  };
  engine_options.state_due = [&outputs](double t) {
    return StopSignals::received() != 0 || (outputs && outputs->state_due(t));
  };
  try {
    engine_ptr = std::make_unique<solver::ExplicitEngine>(model, controls, engine_options);
  } catch (const std::exception& e) {
    err << opt.engine_deck << ": error: " << e.what() << '\n';
    return 1;
  }
  auto& engine = *engine_ptr;

  // A "running" summary replaces none (the earlier run's went first), so a run killed outright leaves either
  // no summary or one that says it did not finish.
  start_summary(s, model, engine, {&diags, &model_diags});
  const std::string listing_path = (fs::path(opt.out_dir) / (root + "_0001.out")).string();
  io::CheckedOutputFile listing_file(listing_path);
  if (!listing_file.is_open()) {
    err << "radx-engine: error: " << listing_file.error() << '\n';
    return 1;
  }
  // An error before the first cycle still leaves a summary that says so.
  auto early_error = [&](const std::string& message) {
    err << "radx-engine: error: " << message << '\n';
    listing_file << message << '\n';
    s.status = io::RunStatus::Error;
    s.message = message;
    std::string ignored;
    io::write_summary_json(summary_path, s, ignored);
    return 1;
  };
  try {
    outputs = std::make_unique<EngineOutputs>(model, controls, engine, opt.out_dir, root);
  } catch (const std::exception& e) {
    return early_error(std::string("cannot write the results: ") + e.what());
  }
  s.status = io::RunStatus::Running;
  s.message = "the run has started; this summary is replaced when it ends";
  if (std::string error; !io::write_summary_json(summary_path, s, error)) return early_error(error);
  io::EngineListing listing(io::ListingSinks{&listing_file, &out, controls.print_stdout,
                                             io::stdout_is_terminal(), controls.print_header_every});
  io::EngineListingHeader h = listing_header(opt, model, model_path, root, controls, {&diags, &model_diags});
  h.threads = engine.team().size();  // the threads the run uses, as the footer and the summary say
  listing.header(h);

  CycleWatch watch{engine, controls, *outputs, listing, listing_file, err, s};
  watch.runaway = RunawayWatch(estimate_run_cycles(controls, step_estimate).cycles, controls.t_stop,
                               model.units.time_name);
  watch.stop_if_runaway = opt.stop_if_runaway;
  solver::RunResult result;
  try {
    StopDeadline deadline([] { return StopSignals::received() != 0; }, end_stuck_run);
    result = engine.run([&](const solver::CycleReport& r) {
      deadline.cycle_ended();
      return watch.after_cycle(r);
    });
    if (loop_ended != nullptr) *loop_ended = true;
  } catch (const std::exception& e) {
    err << opt.engine_deck << ": error: " << e.what() << '\n';
    s.status = io::RunStatus::Error;
    s.message = e.what();
    listing.summary(s);
    std::string ignored;
    io::write_summary_json(summary_path, s, ignored);
    return 1;
  }

  finish_outputs(*outputs, opt.plot, err, result, watch.stop_message, watch.stopped_by);

  set_final_status(s, result, watch.stopped_by, watch.stop_message);
  fill_run_summary(s, result, model, controls, engine, *outputs,
                   (fs::path(opt.out_dir) / (root + "_th.h5")).string());
  return end_of_run(s, listing, listing_file, summary_path, watch.stopped_by, err);
}

}  // namespace

}  // namespace radx::app
