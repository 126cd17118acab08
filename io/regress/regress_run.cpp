// radx regress: one deck's child run, its status and --update (io/regress/regress_run.hpp).
#include "io/regress/regress_run.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>

#include "io/listing/summary_json.hpp"
#include "io/regress/regress_text.hpp"
#include "io/spawn_process.hpp"
#include "io/text_file.hpp"
#include "solver/model/run_files.hpp"

namespace radx::io {

namespace fs = std::filesystem;

namespace {

constexpr const char* kRunLog = "run.log";

// A diagnostic's place "FILE:LINE:COL" or "FILE:LINE": FILE and LINE (LINE empty when the text ends in no
// number, e.g. a program name "radx-engine").
struct Place {
  std::string_view file, line;
};
Place split_place(std::string_view where) {
  Place p{where, {}};
  for (int part = 0; part < 2; ++part) {
    const std::size_t colon = p.file.rfind(':');
    if (colon == std::string_view::npos || !all_digits(p.file.substr(colon + 1))) break;
    p.line = p.file.substr(colon + 1);
    p.file = p.file.substr(0, colon);
  }
  return p;
}

std::string read_text(const fs::path& path) {
  std::ifstream f(path, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

std::string signal_text(int sig) {
  const char* name = sigabbrev_np(sig);
  return "signal " + std::to_string(sig) + (name ? std::string(" (SIG") + name + ")" : std::string());
}

}  // namespace

// ---------------------------------------------------------------------------------------------------
// The child run.

ChildOutcome run_child(const std::vector<std::string>& args, const fs::path& log_path,
                       std::chrono::duration<double> timeout) {
  ProcessRequest request;
  request.argv = args;
  request.output_file = log_path;
  // Any file a run writes outside --out lands in its work folder, not in the caller's.
  request.working_dir = log_path.parent_path();
  request.timeout = timeout;
  const ProcessResult p = run_process(request);
  ChildOutcome r;
  r.start_error = p.error;
  if (!p.error.empty()) return r;
  r.timed_out = p.timed_out;
  r.exit_code = p.exit_code;
  r.signal = p.signal;
  r.seconds = p.seconds;
  return r;
}

// ---------------------------------------------------------------------------------------------------
// Reading the output.

FirstError first_error(std::string_view output) {
  FirstError first;
  std::size_t pos = 0;
  while (pos < output.size()) {
    const std::size_t end = std::min(output.find('\n', pos), output.size());
    const std::string_view line = output.substr(pos, end - pos);
    pos = end + 1;
    const std::size_t at = line.find("error: ");
    if (at == std::string_view::npos) continue;
    std::string_view prefix = line.substr(0, at);
    const bool at_start = prefix.find_first_not_of(" \t") == std::string_view::npos;
    if (!at_start && !prefix.ends_with(": ")) continue;
    FirstError e;
    e.message = std::string(line.substr(at + 7));
    while (!e.message.empty() && (e.message.back() == '\r' || e.message.back() == ' ')) e.message.pop_back();
    if (!at_start) {
      prefix.remove_suffix(2);
      // FILE:LINE:COL or FILE:LINE -> FILE_NAME:LINE; a program name stays as it is.
      const Place p = split_place(prefix);
      e.location = p.line.empty() ? std::string(prefix)
                                  : fs::path(p.file).filename().string() + ":" + std::string(p.line);
    }
    // A reference to an object that does not exist is most often the echo of a keyword refused further
    // down (a /PART naming the unsupported /MAT): the refusal is the first other error, when there is one.
    const bool dangling_reference = e.message.rfind("RX402:", 0) == 0;
    if (!dangling_reference) return e;
    if (first.message.empty()) first = e;
  }
  return first;
}

std::string refusal_group(std::string_view message) {
  const std::size_t colon = message.find(':');
  const std::string_view head = message.substr(0, colon);
  if (head.size() > 2 && head.substr(0, 2) == "RX" && all_digits(head.substr(2)) &&
      colon != std::string_view::npos) {
    std::string_view rest = message.substr(colon + 1);
    rest.remove_prefix(std::min(rest.find_first_not_of(' '), rest.size()));
    if (!rest.empty() && rest[0] == '[') {
      const std::size_t stop = rest.find_first_of(" ]");
      return std::string(head) + " " +
             std::string(rest.substr(1, stop == std::string_view::npos ? 0 : stop - 1));
    }
    return std::string(head);
  }
  return shorten(head, 60);
}

std::string shorten(std::string_view text, std::size_t max_chars) {
  if (text.size() <= max_chars) return std::string(text);
  std::size_t cut = max_chars > 3 ? max_chars - 3 : 0;
  const std::size_t space = text.rfind(' ', cut);
  if (space != std::string_view::npos && space > cut / 2) {
    cut = space;
  } else {
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;  // not inside UTF-8
  }
  std::string s(text.substr(0, cut));
  while (!s.empty() && (s.back() == ' ' || s.back() == ',' || s.back() == ';' || s.back() == ':'))
    s.pop_back();
  return s + "...";
}

// ---------------------------------------------------------------------------------------------------
// Status.

std::string_view status_name(RegressStatus s) {
  switch (s) {
    case RegressStatus::ReadError: return "read-error";
    case RegressStatus::RunError: return "run-error";
    case RegressStatus::RefError: return "ref-error";
    case RegressStatus::Ran: return "ran";
    case RegressStatus::Compared: return "compared";
    case RegressStatus::Deviates: return "deviates";
    case RegressStatus::Read: return "read";
    case RegressStatus::Diagnosed: return "diagnosed";
    case RegressStatus::Unexpected: return "unexpected";
    case RegressStatus::Updated: return "updated";
  }
  return "?";
}

bool is_failure(RegressStatus s) {
  return s == RegressStatus::ReadError || s == RegressStatus::RunError || s == RegressStatus::RefError ||
         s == RegressStatus::Deviates || s == RegressStatus::Unexpected;
}

const QuantityCheck* worst_check(const RegressResult& r) {
  const QuantityCheck* worst = nullptr;
  for (const auto& c : r.checks)
    if (!worst || c.score > worst->score) worst = &c;
  return worst;
}

std::size_t failed_checks(const RegressResult& r) {
  return static_cast<std::size_t>(
      std::count_if(r.checks.begin(), r.checks.end(), [](const QuantityCheck& c) { return !c.passed(); }));
}

namespace {

// A diagnostic the run reported: "PATH:LINE:COL: error: RXnnn: ..." (or PATH:LINE, or a warning).
struct ReportedError {
  fs::path file;
  std::int64_t line = 0;
  std::string code;
  bool error = true;  // false: a warning
  auto operator<=>(const ReportedError&) const = default;
};

// Each diagnostic once: two checks that find the same fault at the same place are one expectation.
std::vector<ReportedError> reported_errors(std::string_view output) {
  std::vector<ReportedError> out;
  std::size_t pos = 0;
  while (pos < output.size()) {
    const std::size_t end = std::min(output.find('\n', pos), output.size());
    const std::string_view line = output.substr(pos, end - pos);
    pos = end + 1;
    std::size_t at = line.find(": error: RX");
    const bool error = at != std::string_view::npos;
    if (!error) at = line.find(": warning: RX");
    if (at == std::string_view::npos) continue;
    ReportedError e;
    e.error = error;
    const std::string_view tail = line.substr(at + (error ? 9 : 11));
    e.code = std::string(tail.substr(0, std::min(tail.find(':'), tail.size())));
    const Place p = split_place(line.substr(0, at));
    if (!p.line.empty() && !parse_line_number(p.line, e.line)) e.line = 0;
    e.file = fs::path(p.file).lexically_normal();
    if (std::find(out.begin(), out.end(), e) == out.end()) out.push_back(std::move(e));
  }
  return out;
}

bool same_file(const fs::path& a, const fs::path& b) {
  std::error_code ec;
  return fs::weakly_canonical(a, ec) == fs::weakly_canonical(b, ec);
}

// A deck that declares its diagnostics: every one reported (an error or a warning), and no other error.
void evaluate_expected_refusal(RegressResult& r, const ChildOutcome& child, const RegressRunFiles& files) {
  const RegressDeck& deck = r.deck;
  if (!deck.expect_problems.empty()) {
    r.status = RegressStatus::RefError;
    r.detail = deck.expect_problems.front();
    return;
  }
  if (child.timed_out || child.signal != 0) {
    r.status = RegressStatus::Unexpected;
    r.detail = child.timed_out ? "ran out of time instead of being diagnosed"
                               : "ended by " + signal_text(child.signal) + " instead of being diagnosed";
    return;
  }
  std::vector<ReportedError> got = reported_errors(files.output);
  // Expectations at a given line take their diagnostic first, so that one at any line cannot use it up.
  std::vector<const ExpectedError*> order;
  for (const auto& e : deck.expected) order.push_back(&e);
  std::stable_partition(order.begin(), order.end(), [](const ExpectedError* e) { return e->line > 0; });
  std::vector<std::string> missing;
  bool error_expected = false;
  for (const ExpectedError* e : order) {
    error_expected = error_expected || !e->warning;
    const auto it = std::find_if(got.begin(), got.end(), [&](const ReportedError& g) {
      return g.code == e->code && g.error == !e->warning && (e->line == 0 || g.line == e->line) &&
             same_file(g.file, e->file);
    });
    if (it == got.end())
      missing.push_back(e->text());
    else
      got.erase(it);
  }
  std::vector<std::string> extra;  // other errors (other warnings are no fault of the deck's expectation)
  for (const auto& g : got)
    if (g.error)
      extra.push_back(g.code + " line " + std::to_string(g.line) + " in " + g.file.filename().string());
  const bool refused = child.exit_code != 0;
  if (missing.empty() && extra.empty() && refused == error_expected) {
    r.status = RegressStatus::Diagnosed;
    r.detail =
        std::to_string(deck.expected.size()) + " expected diagnostic(s)" + (refused ? ", refused" : ", read");
    return;
  }
  r.status = RegressStatus::Unexpected;
  const auto join = [](const std::vector<std::string>& v) {
    std::string t;
    for (const auto& x : v) t += (t.empty() ? "" : ", ") + x;
    return t;
  };
  if (error_expected && !refused) r.detail = "the deck must be refused but was read";
  if (!error_expected && refused) r.detail = "the deck was refused, though it expects warnings only";
  if (!missing.empty()) r.detail += (r.detail.empty() ? "" : "; ") + ("missing " + join(missing));
  if (!extra.empty()) r.detail += (r.detail.empty() ? "" : "; ") + ("not expected " + join(extra));
}

// Compares a finished run with the deck's own reference.
void evaluate_own_reference(RegressResult& r, const RegressRunFiles& files) {
  RegressReference ref;
  std::vector<std::string> errors;
  if (!read_regress_reference(r.deck.own_reference.string(), ref, errors)) {
    r.status = RegressStatus::RefError;
    for (const auto& e : errors) r.detail += (r.detail.empty() ? "" : "; ") + e;
    return;
  }
  const std::vector<ThGroupData>* th = files.th ? &*files.th : nullptr;
  r.checks = check_reference(ref, *files.summary, th);
  r.status = failed_checks(r) == 0 ? RegressStatus::Compared : RegressStatus::Deviates;
}

}  // namespace

std::vector<ListingPoint> listing_points(const std::string& listing_text) {
  // CYCLE TIME TIME-STEP KIND ID ERROR% I-ENERGY K-ENERGY-T K-ENERGY-R EXT-WORK ...
  // (io/listing/engine_listing.cpp)
  std::vector<ListingPoint> out;
  std::istringstream in(listing_text);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::vector<std::string> f;
    for (std::string w; ls >> w;) f.push_back(w);
    if (f.size() < 10 || f[0].find_first_not_of("0123456789") != std::string::npos) continue;
    std::size_t pct = 0;
    while (pct < f.size() && (f[pct].empty() || f[pct].back() != '%')) ++pct;
    if (pct + 4 >= f.size()) continue;
    try {
      ListingPoint p;
      p.cycle = std::stoll(f[0]);
      p.time = std::stod(f[1]);
      p.energy[static_cast<std::size_t>(ExtractEnergy::Internal)] = std::stod(f[pct + 1]);
      p.energy[static_cast<std::size_t>(ExtractEnergy::KineticTranslational)] = std::stod(f[pct + 2]);
      p.energy[static_cast<std::size_t>(ExtractEnergy::KineticRotational)] = std::stod(f[pct + 3]);
      p.energy[static_cast<std::size_t>(ExtractEnergy::ExternalWork)] = std::stod(f[pct + 4]);
      if (out.empty() || p.time >= out.back().time) out.push_back(p);
    } catch (const std::exception&) {
    }
  }
  return out;
}

RegressResult evaluate_deck(const RegressDeck& deck, const ChildOutcome& child, const RegressRunFiles& files,
                            double tolerance) {
  RegressResult r;
  r.deck = deck;
  r.seconds = child.seconds;
  r.refusal = first_error(files.output);
  if (!child.start_error.empty()) {
    r.status = RegressStatus::RunError;
    r.detail = child.start_error;
    return r;
  }
  if (!deck.expected.empty() || !deck.expect_problems.empty()) {
    evaluate_expected_refusal(r, child, files);
    return r;
  }
  // The detail says what the status and the first error line do not: a time limit, a signal, the message of
  // an error termination, a failure that printed no error line.
  const std::string stage = files.model_written ? "engine" : "starter";
  const bool failed = child.timed_out || child.signal != 0 || child.exit_code != 0;
  std::vector<std::string> details;
  if (child.timed_out)
    details.push_back("the " + stage + " ran out of time (" + seconds_text(child.seconds) + ")");
  else if (child.signal != 0)
    details.push_back("the " + stage + " was ended by " + signal_text(child.signal));
  if (files.model_written && files.summary && files.summary->status == RunStatus::Error)
    details.push_back("error termination: " + files.summary->message);
  // Neither is a finished run, whatever the exit code says: the summary's figures are not the deck's.
  if (files.model_written && files.summary && files.summary->status == RunStatus::Interrupted)
    details.push_back("the engine was " + files.summary->message);
  if (files.model_written && files.summary && files.summary->status == RunStatus::Running)
    details.push_back("the engine did not finish (its summary still says \"running\")");
  if (details.empty() && failed && r.refusal.message.empty())
    details.push_back("the " + stage + " failed (exit code " + std::to_string(child.exit_code) +
                      ") without an error line; see its run.log");
  if (details.empty() && !failed && !files.model_written)
    details.push_back("the starter wrote no model file");
  if (details.empty() && !failed && files.model_written && !files.summary)
    details.push_back(files.summary_error);
  for (const auto& d : details) r.detail += (r.detail.empty() ? "" : "; ") + d;
  if (!files.model_written) {
    r.status = RegressStatus::ReadError;
    return r;
  }
  if (deck.starter_only) {
    r.status = failed ? RegressStatus::ReadError : RegressStatus::Read;
    if (!failed) r.detail.clear();
    return r;
  }
  if (failed || !files.summary || files.summary->status != RunStatus::Normal) {
    r.status = RegressStatus::RunError;
    return r;
  }
  // A time history the run wrote that cannot be read (damaged: a checksum says so) is an output lost.
  if (!files.th_error.empty()) {
    r.status = RegressStatus::RunError;
    r.detail = "cannot read the time history: " + files.th_error;
    return r;
  }
  const RunSummary& s = *files.summary;
  RunFigures fig;
  fig.cycles = s.cycles;
  fig.time = s.time;
  fig.energy[static_cast<std::size_t>(ExtractEnergy::Internal)] = s.energy.internal;
  fig.energy[static_cast<std::size_t>(ExtractEnergy::KineticTranslational)] = s.energy.kinetic_t;
  fig.energy[static_cast<std::size_t>(ExtractEnergy::KineticRotational)] = s.energy.kinetic_r;
  fig.energy[static_cast<std::size_t>(ExtractEnergy::ExternalWork)] = s.energy.external_work;
  r.radx = fig;
  if (deck.has_own_reference) {
    evaluate_own_reference(r, files);
    return r;
  }
  if (deck.reference.empty()) {
    r.status = RegressStatus::Ran;
    return r;
  }
  RegressionExtract ref;
  std::string error;
  if (!read_regression_extract(deck.reference.string(), ref, error)) {
    r.status = RegressStatus::RefError;
    r.detail = error;
    return r;
  }
  r.reference = ref;
  // A Radioss ref.extract holds the last printed listing line, which may come before the end time (the
  // line of the last multiple of the /PRINT interval): compare radx at that time, interpolated between its
  // own listing lines, when the reference stops earlier than the run.
  if (ref.time < fig.time * (1 - 1e-9) && files.listing.size() >= 2) {
    const auto& L = files.listing;
    std::size_t k = 1;
    while (k + 1 < L.size() && L[k].time < ref.time) ++k;
    const double t0 = L[k - 1].time, t1 = L[k].time;
    const double w = t1 > t0 ? std::clamp((ref.time - t0) / (t1 - t0), 0.0, 1.0) : 1.0;
    for (std::size_t e = 0; e < fig.energy.size(); ++e)
      fig.energy[e] = (1 - w) * L[k - 1].energy[e] + w * L[k].energy[e];
    fig.time = (1 - w) * t0 + w * t1;
    fig.cycles = w < 0.5 ? L[k - 1].cycle : L[k].cycle;
    r.radx = fig;
    r.at_reference_time = true;
  }
  r.comparison = compare_to_extract(fig, ref);
  r.status = r.comparison->within(tolerance) ? RegressStatus::Compared : RegressStatus::Deviates;
  return r;
}

RegressResult run_regress_deck(const RegressDeck& deck, const RegressSettings& settings) {
  const fs::path dir = settings.work_dir / deck.work_subdir;
  std::error_code ec;
  fs::remove_all(dir, ec);
  fs::create_directories(dir, ec);
  const std::string deck_path = deck.starter_deck.string();
  std::vector<std::string> argv{
      settings.executable.string(),     "run",      deck_path, "--out", dir.string(), "--threads",
      std::to_string(settings.threads), "--no-plot"};
  if (deck.starter_only) argv.emplace_back("--starter-only");
  const ChildOutcome child =
      run_child(argv, dir / kRunLog, std::chrono::duration<double>(settings.timeout_seconds));
  RegressRunFiles files;
  files.model_written = fs::exists(dir / (model::starter_output_root(deck_path) + ".hdf"), ec);
  const std::string root = model::run_output_root(deck_path);
  const fs::path summary = dir / (root + "_summary.json");
  RunSummary s;
  if (!fs::exists(summary, ec))
    files.summary_error = "no " + summary.filename().string() + " written";
  else if (read_summary_json(summary.string(), s, files.summary_error))
    files.summary = s;
  files.output = read_text(dir / kRunLog);
  files.listing = listing_points(read_text(dir / (root + "_0001.out")));
  const fs::path th = dir / (root + "_th.h5");
  if (fs::exists(th, ec)) {
    std::vector<ThGroupData> groups;
    if (read_time_history(th.string(), groups, files.th_error)) files.th = std::move(groups);
  }
  RegressResult r = evaluate_deck(deck, child, files, settings.tolerance);
  if (settings.update) update_reference(r, files);
  if (!settings.keep && !is_failure(r.status)) fs::remove_all(dir, ec);
  return r;
}

void update_reference(RegressResult& r, const RegressRunFiles& files) {
  const bool finished = r.status == RegressStatus::Ran || r.status == RegressStatus::Compared ||
                        r.status == RegressStatus::Deviates;
  if (!finished || !files.summary) return;
  // An OpenRadioss ref.extract is the reference solver's result, not radx's to rewrite.
  if (!r.deck.has_own_reference && !r.deck.reference.empty()) return;
  const fs::path path = r.deck.own_reference;
  std::string text;
  if (!r.deck.has_own_reference) {
    text = new_reference_text(r.deck.starter_deck.filename().string(), *files.summary);
    r.update_report = "  new reference " + path.filename().string() + "\n";
  } else {
    RegressReference ref;
    std::vector<std::string> errors;
    if (!read_regress_reference(path.string(), ref, errors)) {
      r.status = RegressStatus::RefError;
      r.detail.clear();
      for (const auto& e : errors) r.detail += (r.detail.empty() ? "" : "; ") + e;
      return;
    }
    const std::vector<ThGroupData>* th = files.th ? &*files.th : nullptr;
    std::vector<double> values;
    std::vector<std::string> lacking;
    for (const auto& q : ref.quantities) {
      std::string why;
      const auto v = run_quantity(q.name, *files.summary, th, why);
      if (!v) lacking.push_back(q.name + ": " + why);
      values.push_back(v.value_or(std::numeric_limits<double>::quiet_NaN()));
      if (!v) continue;
      const std::string was = q.value ? reference_number(*q.value) : std::string("-");
      const std::string now = reference_number(*v);
      if (was == now) continue;
      std::string change;
      if (q.value && *q.value != 0) {
        char buf[48];
        std::snprintf(buf, sizeof buf, " (%+.3g %%)", 100 * (*v - *q.value) / std::abs(*q.value));
        change = buf;
      }
      r.update_report += "  " + q.name + ": " + was + " -> " + now + change + "\n";
    }
    if (!lacking.empty()) {
      r.status = RegressStatus::RefError;
      r.detail = "not updated: the run has no value for ";
      for (std::size_t k = 0; k < lacking.size(); ++k) r.detail += (k ? "; " : "") + lacking[k];
      r.update_report.clear();
      return;
    }
    if (r.update_report.empty()) r.update_report = "  " + path.filename().string() + " unchanged\n";
    text = updated_reference_text(ref, values);
  }
  // Through a temporary file and a rename: an interrupted update leaves the old reference whole.
  std::string error;
  if (!write_text_atomically(path.string(), text, error)) {
    r.status = RegressStatus::RefError;
    r.detail = error;
    r.update_report.clear();
    return;
  }
  r.status = RegressStatus::Updated;
  r.detail.clear();
  r.checks.clear();  // they judged the old values; the report says what changed
}

}  // namespace radx::io
