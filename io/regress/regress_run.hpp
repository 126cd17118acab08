// One deck's run in `radx regress` (docs/regress.md): the deck runs in its own child process (`radx run`,
// the same executable) with a time limit; its engine's NAME_summary.json is read and compared with its
// reference, its own NAME.ref (io/regress/regress_reference.hpp) or the folder's OpenRadioss ref.extract
// (io/regress/regression_extract.hpp); that gives its status. --update rewrites its NAME.ref from the run.
//
// Child processes, not threads: a deck that crashes, hangs or exhausts memory ends only its own run, and
// the time limit can always be enforced (SIGKILL).
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/hdf5/time_history.hpp"
#include "io/listing/engine_listing.hpp"
#include "io/regress/regress_decks.hpp"
#include "io/regress/regress_reference.hpp"
#include "io/regress/regression_extract.hpp"

namespace radx::io {

// How a child process ended.
struct ChildOutcome {
  std::string start_error;  // not empty: the process could not be started
  bool timed_out = false;   // killed (SIGKILL) at the time limit
  int exit_code = -1;       // when it exited
  int signal = 0;           // when a signal ended it (the time limit's SIGKILL included)
  double seconds = 0;       // wall time
};

// Runs `argv` (argv[0] an absolute path) in the folder of `log_path`, with standard input from /dev/null and
// standard output and error both into `log_path`; kills it with SIGKILL after `timeout`
// (io/spawn_process.hpp).
ChildOutcome run_child(const std::vector<std::string>& argv, const std::filesystem::path& log_path,
                       std::chrono::duration<double> timeout);

// The first line of `output` with an "error: " message (after a location "FILE:LINE:COL: " or a program
// name "radx-engine: ", or at the start of the line), as its location shortened to "FILE_NAME:LINE" and
// its message; both empty when there is none. A dangling reference (RX402) is taken only when no other
// error follows: it is most often the echo of a keyword refused further down.
struct FirstError {
  std::string location;
  std::string message;
};
FirstError first_error(std::string_view output);

// The group a refusal falls in for the "most frequent" count: its code and keyword ("RX301 /MAT/LAW14",
// from "RX301: [/MAT/LAW14] unknown keyword ..."), else the message up to its first ':'.
std::string refusal_group(std::string_view message);

// `text` cut at a word boundary to at most `max_chars` (then ending with "...").
std::string shorten(std::string_view text, std::size_t max_chars);

enum class RegressStatus : std::uint8_t {
  ReadError,   // the starter refused the deck (or failed)
  RunError,    // the engine refused, stopped on an error, crashed or ran out of time
  RefError,    // the engine ran, but its reference (NAME.ref or ref.extract) cannot be read or used
  Ran,         // the engine ran; no reference
  Compared,    // within the tolerance on every quantity of its reference
  Deviates,    // a quantity beyond its tolerance
  Read,        // a starter deck with no engine deck: the starter read it
  Diagnosed,   // a deck that declares its diagnostics ("# expect:") got exactly those: each at its place and
               // with its severity, no other error, and it was refused when one of them is an error
  Unexpected,  // such a deck lacked one of them, got another error, or ran when it must be refused
  Updated,     // --update: the engine ran and its reference was written
};
// "read-error", "run-error", "ref-error", "ran", "compared", "deviates", "read", "diagnosed", "unexpected",
// "updated".
std::string_view status_name(RegressStatus s);
bool is_failure(RegressStatus s);  // read-error, run-error, ref-error, deviates, unexpected

struct RegressResult {
  RegressDeck deck;
  RegressStatus status = RegressStatus::ReadError;
  FirstError refusal;  // the first error line of the deck's output
  std::string detail;  // what else explains the status (time limit, signal, message of the run's end)
  double seconds = 0;
  std::optional<RunFigures> radx;              // when the engine ran to the end
  std::optional<RegressionExtract> reference;  // when ref.extract was read
  std::optional<ExtractComparison> comparison;
  // The reference stops before the run's end: radx was compared at the reference time, interpolated
  // between its listing lines (radx holds those figures then, not the run's end).
  bool at_reference_time = false;
  std::vector<QuantityCheck> checks;  // against the deck's own reference (NAME.ref)
  std::string update_report;          // --update: what changed, one line each
};

// The check with the largest score (the worst deviation), or null when there is none.
const QuantityCheck* worst_check(const RegressResult& r);
// How many checks fail.
std::size_t failed_checks(const RegressResult& r);

// One cycle line of the engine listing NAME_0001.out: what a Radioss ref.extract records.
struct ListingPoint {
  std::int64_t cycle = 0;
  double time = 0;
  std::array<double, 4> energy{};  // indexed by ExtractEnergy
};
// The cycle lines of an engine listing's text (lines that do not parse are skipped).
std::vector<ListingPoint> listing_points(const std::string& listing_text);

// What the child run left behind, as evaluate_deck needs it.
struct RegressRunFiles {
  bool model_written = false;                  // the starter's NAME_0000.hdf exists: the starter passed
  std::optional<RunSummary> summary;           // NAME_summary.json, when it could be read
  std::string summary_error;                   // why it could not
  std::string output;                          // the child's standard output and error
  std::vector<ListingPoint> listing;           // the engine listing's cycle lines
  std::optional<std::vector<ThGroupData>> th;  // NAME_th.h5, when it could be read
  std::string th_error;                        // why it could not (or "" when there is none)
};

// The status of a deck from its child run, the files it left and its reference (read here from
// deck.reference), compared with `tolerance` (a fraction).
RegressResult evaluate_deck(const RegressDeck& deck, const ChildOutcome& child, const RegressRunFiles& files,
                            double tolerance);

struct RegressSettings {
  std::filesystem::path executable;  // the radx driver the decks run with (`radx run`)
  std::filesystem::path work_dir;
  double tolerance = 0.05;  // fraction, for ref.extract energies
  double timeout_seconds = 600;
  int threads = 1;      // engine threads of each deck
  int jobs = 1;         // decks run at the same time
  bool update = false;  // rewrite (or write) each deck's NAME.ref from its run
  bool keep = false;    // keep the run folders of the decks that pass too
};

// Runs one deck: clears and fills settings.work_dir / deck.work_subdir (run.log holds the child's output)
// and evaluates it; with settings.update, writes its reference (see update_reference). The run folder is
// removed when the deck passes, unless settings.keep.
RegressResult run_regress_deck(const RegressDeck& deck, const RegressSettings& settings);

// --update for a deck whose run `r` finished (status ran, compared, deviates): rewrites NAME.ref with the
// run's values (tolerances, comments and order kept), or writes a new one when the deck has neither NAME.ref
// nor ref.extract (an OpenRadioss ref.extract is never rewritten). Says what changed in r.update_report
// and sets r.status to Updated; a reference that cannot be read or a quantity the run lacks leaves the
// file as it is and sets RefError.
void update_reference(RegressResult& r, const RegressRunFiles& files);

}  // namespace radx::io
