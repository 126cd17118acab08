// `radx regress DIR...`: the batch runner (docs/regress.md). It finds every deck under the folders given,
// runs each in its own child process (`radx run`, the same executable) with a time limit, reads the
// engine's NAME_summary.json, compares it with the folder's OpenRadioss `ref.extract` when there is one
// (io/regress/regression_extract.hpp), prints one line per deck as it finishes, then a table and totals, and
// optionally writes the table as JSON.
//
// Child processes, not threads: a deck that crashes, hangs or exhausts memory ends only its own run, and
// the time limit can always be enforced (SIGKILL).
#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/hdf5/time_history.hpp"
#include "io/listing/engine_listing.hpp"
#include "io/regress/regress_reference.hpp"
#include "io/regress/regression_extract.hpp"

namespace radx::app {

// A diagnostic a deck must get: a "# expect: RXnnn [line L] [file F] [warning]" line at the top of its
// starter deck (decks/invalid/README.md). Without "warning" it is an error, and the deck must be refused.
struct ExpectedError {
  std::string code;                        // "RX402"
  std::int64_t line = 0;                   // 0: any line
  std::filesystem::path file;              // absolute; the deck itself when the line names no file
  bool warning = false;                    // "... warning": a warning, not an error that refuses the deck
  [[nodiscard]] std::string text() const;  // "RX402 line 97 in x.rad", "RX512 line 84 in x.rad (warning)"
};

// The "# expect:" lines of the comment block that opens `deck` (paths relative to its folder). Lines that
// do not parse are returned in `problems` ("FILE:LINE: ...").
std::vector<ExpectedError> read_expected_errors(const std::filesystem::path& deck,
                                                std::vector<std::string>& problems);

// One deck found under a DIR.
struct RegressDeck {
  std::string label;                   // the folder relative to DIR (see find_regress_decks)
  std::filesystem::path starter_deck;  // NAME_0000.rad, or a one-file deck
  std::filesystem::path reference;     // ref.extract beside it; empty when none (or not this deck's)
  // NAME.ref beside the starter deck (io/regress/regress_reference.hpp): where the deck's own reference is,
  // or where --update writes it. It takes precedence over ref.extract when it exists.
  std::filesystem::path own_reference;
  bool has_own_reference = false;
  bool starter_only = false;  // no engine deck beside it (NAME_0001.rad) and not a one-file deck: only the
                              // starter runs
  std::vector<ExpectedError> expected;  // not empty: the deck must get these diagnostics and no other error
  std::vector<std::string> expect_problems;  // "# expect:" lines that do not parse
  std::filesystem::path work_subdir;         // where its outputs go, relative to the work folder
  std::string note;  // what the run leaves out (a restart deck), or why ref.extract is not used
};

// Every deck under `dirs`, recursively (hidden folders, symbolic links to folders and `skip` excepted),
// sorted by path within each DIR. A deck is a starter deck NAME_0000.rad, or, in a folder without one, a
// one-file deck NAME.rad. Its label is its folder relative to DIR ("LOIS/LOI14/data"; DIR's own name for
// a deck directly in DIR), prefixed by DIR as given when there are several DIRs, and followed by
// "/NAME_0000.rad" when the folder holds several decks; a folder's ref.extract belongs to its deck only
// when the folder holds one deck. Engine decks NAME_0002.rad and later are noted: radx runs NAME_0001.rad
// only (they are OpenRadioss restarts).
std::vector<RegressDeck> find_regress_decks(const std::vector<std::filesystem::path>& dirs,
                                            const std::filesystem::path& skip = {});

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
  std::optional<io::RunFigures> radx;              // when the engine ran to the end
  std::optional<io::RegressionExtract> reference;  // when ref.extract was read
  std::optional<io::ExtractComparison> comparison;
  // The reference stops before the run's end: radx was compared at the reference time, interpolated
  // between its listing lines (radx holds those figures then, not the run's end).
  bool at_reference_time = false;
  std::vector<io::QuantityCheck> checks;  // against the deck's own reference (NAME.ref)
  std::string update_report;              // --update: what changed, one line each
};

// The check with the largest score (the worst deviation), or null when there is none.
const io::QuantityCheck* worst_check(const RegressResult& r);
// How many checks fail.
std::size_t failed_checks(const RegressResult& r);

// One cycle line of the engine listing NAME_0001.out: what a Radioss ref.extract records.
struct ListingPoint {
  std::int64_t cycle = 0;
  double time = 0;
  std::array<double, 4> energy{};  // indexed by io::ExtractEnergy
};
// The cycle lines of an engine listing's text (lines that do not parse are skipped).
std::vector<ListingPoint> listing_points(const std::string& listing_text);

// What the child run left behind, as evaluate_deck needs it.
struct RegressRunFiles {
  bool model_written = false;                      // the starter's NAME_0000.hdf exists: the starter passed
  std::optional<io::RunSummary> summary;           // NAME_summary.json, when it could be read
  std::string summary_error;                       // why it could not
  std::string output;                              // the child's standard output and error
  std::vector<ListingPoint> listing;               // the engine listing's cycle lines
  std::optional<std::vector<io::ThGroupData>> th;  // NAME_th.h5, when it could be read
  std::string th_error;                            // why it could not (or "" when there is none)
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

// The JUnit XML report: one testsuite, one testcase per deck (a failure for deviates and unexpected, an
// error for read-error, run-error and ref-error).
std::string regress_junit_xml(const std::vector<RegressResult>& results, double total_seconds);

// Whether a deck's label matches a --filter pattern: a glob ('*', '?', '[...]') against the whole label, or
// a substring when the pattern has no wildcard.
bool label_matches(const std::string& label, const std::string& pattern);

// The line printed when a deck finishes (no line end): status, first refusal or deviations, seconds.
std::string format_regress_line(const RegressResult& r);
// The table (one row per deck), the totals and the most frequent first refusals.
void write_regress_table(std::ostream& os, const std::vector<RegressResult>& results, double tolerance);
// The same as a JSON document (docs/regress.md lists its keys).
std::string regress_summary_json(const std::vector<RegressResult>& results, const RegressSettings& settings,
                                 bool work_dir_kept);

// The command: parses `args` (DIR... and the options), runs, reports. 0 when every deck passes, 1 when one
// fails (or none was found), 2 for usage errors. `executable` is the radx driver to run the decks with.
int regress_command(const std::vector<std::string>& args, const std::filesystem::path& executable,
                    std::ostream& out, std::ostream& err);

}  // namespace radx::app
