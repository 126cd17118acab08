// radx regress: deck discovery, the child runs, the status of each deck and the report (apps/regress.hpp).
#include "apps/regress.hpp"

#include <fnmatch.h>
#include <sched.h>
#include <stdlib.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <mutex>
#include <ostream>
#include <set>
#include <sstream>
#include <thread>

#include "apps/cli_common.hpp"
#include "apps/starter_pipeline.hpp"
#include "io/listing/summary_json.hpp"
#include "io/spawn_process.hpp"
#include "io/xml_text.hpp"
#include "parser/building/build_run_controls.hpp"
#include "parser/reading/deck.hpp"

namespace radx::app {

namespace fs = std::filesystem;

namespace {

// Marks a work folder as radx regress's own, so a second run may clear the deck folders inside it; a folder
// without it that is not empty is refused (it could be anything, a deck folder included).
constexpr const char* kWorkMarker = ".radx-regress";
constexpr const char* kRunLog = "run.log";
// Widths of the refusal text: on the line printed per deck, and in the table.
constexpr std::size_t kLineRefusalChars = 160;
constexpr std::size_t kTableRefusalChars = 72;
constexpr std::size_t kMostFrequentShown = 10;

bool all_digits(std::string_view s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// NAME_NNNN.rad: the run number NNNN (four digits), or -1.
int run_number_of(std::string_view file_name) {
  if (!file_name.ends_with(".rad") || file_name.size() < 10) return -1;
  const std::string_view digits = file_name.substr(file_name.size() - 8, 4);
  if (file_name[file_name.size() - 9] != '_' || !all_digits(digits)) return -1;
  return std::stoi(std::string(digits));
}

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

// A line number: digits that fit, else false (a number too long for any deck is no line of it).
bool parse_line_number(std::string_view digits, std::int64_t& out) {
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), out);
  return ec == std::errc() && end == digits.data() + digits.size() && all_digits(digits);
}

std::string read_text(const fs::path& path) {
  std::ifstream f(path, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

// A percentage for the report: two decimals, or three significant digits when large.
std::string percent(double fraction) {
  if (std::isnan(fraction)) return "nan";
  if (std::isinf(fraction)) return "inf";
  char buf[32];
  const double p = 100.0 * fraction;
  std::snprintf(buf, sizeof buf, p < 1000 ? "%.2f" : "%.3g", p);
  return buf;
}

// The tolerance as the user gave it: "5", "2.5".
std::string tolerance_text(double fraction) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", 100.0 * fraction);
  return buf;
}

std::string seconds_text(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f s", s);
  return buf;
}

// The name of a folder as given ("a/b/" and "a/b/." are "b"; "." is the current folder's name).
std::string folder_name(const fs::path& dir) {
  std::error_code ec;
  fs::path p = fs::absolute(dir, ec).lexically_normal();
  if (p.filename().empty()) p = p.parent_path();
  return p.filename().empty() ? std::string("root") : p.filename().string();
}

std::string signal_text(int sig) {
  const char* name = sigabbrev_np(sig);
  return "signal " + std::to_string(sig) + (name ? std::string(" (SIG") + name + ")" : std::string());
}

}  // namespace

// ---------------------------------------------------------------------------------------------------
// Finding the decks.

std::string ExpectedError::text() const {
  std::string t = code;
  if (line > 0) t += " line " + std::to_string(line);
  if (!file.empty()) t += " in " + file.filename().string();
  return warning ? t + " (warning)" : t;
}

std::vector<ExpectedError> read_expected_errors(const fs::path& deck, std::vector<std::string>& problems) {
  std::vector<ExpectedError> out;
  std::ifstream f(deck, std::ios::binary);
  std::string line;
  for (std::size_t no = 1; std::getline(f, line); ++no) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] != '#') break;  // the opening comment block only
    const std::string_view tag = "# expect:";
    if (line.compare(0, tag.size(), tag) != 0) continue;
    std::istringstream in(line.substr(tag.size()));
    std::vector<std::string> w;
    for (std::string t; in >> t;) w.push_back(t);
    ExpectedError e;
    bool ok = !w.empty() && w[0].size() > 2 && w[0].compare(0, 2, "RX") == 0 &&
              all_digits(std::string_view(w[0]).substr(2));
    if (ok) e.code = w[0];
    if (ok && w.back() == "warning") {
      e.warning = true;
      w.pop_back();
    }
    for (std::size_t k = 1; ok && k < w.size(); k += 2) {
      if (k + 1 >= w.size())
        ok = false;
      else if (w[k] == "line")
        ok = parse_line_number(w[k + 1], e.line) && e.line > 0;
      else if (w[k] == "file")
        e.file = (deck.parent_path() / w[k + 1]).lexically_normal();
      else
        ok = false;
    }
    if (!ok) {
      problems.push_back(deck.string() + ":" + std::to_string(no) +
                         ": an expectation is \"# expect: RXnnn [line L] [file PATH] [warning]\", L a line "
                         "number from 1");
      continue;
    }
    if (e.file.empty()) e.file = deck.lexically_normal();
    out.push_back(std::move(e));
  }
  return out;
}

std::vector<RegressDeck> find_regress_decks(const std::vector<fs::path>& dirs, const fs::path& skip) {
  std::vector<RegressDeck> out;
  std::set<fs::path> seen;  // the same deck reached through overlapping DIRs runs once
  std::error_code ec;
  const fs::path skip_canonical = skip.empty() ? fs::path() : fs::weakly_canonical(skip, ec);
  for (std::size_t k = 0; k < dirs.size(); ++k) {
    const fs::path& dir = dirs[k];
    const std::string dir_name = folder_name(dir);

    std::map<fs::path, std::vector<std::string>> rad_files;  // folder -> the names of its .rad files
    const auto add_folder_files = [&](const fs::path& folder) {
      std::error_code e1;
      for (const auto& e :
           fs::directory_iterator(folder, fs::directory_options::skip_permission_denied, e1)) {
        std::error_code e2;
        const std::string name = e.path().filename().string();
        if (name.ends_with(".rad") && e.is_regular_file(e2)) rad_files[folder].push_back(name);
      }
    };
    add_folder_files(dir);
    std::error_code walk;
    for (auto it = fs::recursive_directory_iterator(dir, fs::directory_options::skip_permission_denied, walk);
         !walk && it != fs::recursive_directory_iterator(); it.increment(walk)) {
      std::error_code e1;
      if (it->is_symlink(e1) || !it->is_directory(e1)) continue;  // symbolic links are not followed
      const std::string name = it->path().filename().string();
      const bool hidden = !name.empty() && name[0] == '.';
      if (hidden || (!skip_canonical.empty() && fs::weakly_canonical(it->path(), e1) == skip_canonical)) {
        it.disable_recursion_pending();
        continue;
      }
      add_folder_files(it->path());
    }

    for (auto& [folder, names] : rad_files) {
      std::sort(names.begin(), names.end());
      std::vector<std::string> decks;
      for (const auto& n : names)
        if (run_number_of(n) == 0) decks.push_back(n);
      // Without a NAME_0000.rad: one-file decks, and starter decks that declare their diagnostics.
      if (decks.empty())
        for (const auto& n : names) {
          std::vector<std::string> ignored;
          if (run_number_of(n) < 0 &&
              (is_one_file_deck((folder / n).string()) || !read_expected_errors(folder / n, ignored).empty()))
            decks.push_back(n);
        }
      fs::path rel = folder.lexically_relative(dir);
      if (rel.empty() || rel == ".") rel = dir_name;
      const bool has_reference = fs::is_regular_file(folder / "ref.extract", ec);
      for (const auto& deck : decks) {
        const fs::path starter = fs::absolute(folder / deck, ec).lexically_normal();
        if (!seen.insert(fs::weakly_canonical(starter, ec)).second) continue;
        RegressDeck d;
        d.starter_deck = starter;
        // Several DIRs: the label starts with DIR as given, the work folder with DIR's rank and name.
        d.label = dirs.size() > 1 ? (dir / folder.lexically_relative(dir)).lexically_normal().generic_string()
                                  : rel.generic_string();
        while (d.label.size() > 1 && d.label.back() == '/') d.label.pop_back();
        d.work_subdir = dirs.size() > 1 ? fs::path(std::to_string(k + 1) + "_" + dir_name) / rel : rel;
        if (decks.size() > 1) {
          d.label += "/" + deck;
          d.work_subdir /= fs::path(deck).stem();
        }
        d.expected = read_expected_errors(starter, d.expect_problems);
        const std::string root = run_output_root(starter.string());
        d.own_reference = starter.parent_path() / (root + ".ref");
        d.has_own_reference = fs::is_regular_file(d.own_reference, ec);
        d.starter_only =
            !fs::exists(folder / (root + "_0001.rad"), ec) && !is_one_file_deck(starter.string());
        std::vector<std::string> notes;
        if (has_reference) {
          if (d.has_own_reference)
            notes.push_back("ref.extract not used: the deck has its own " +
                            d.own_reference.filename().string());
          else if (decks.size() == 1)
            d.reference = folder / "ref.extract";
          else
            notes.push_back("ref.extract not used: the folder holds " + std::to_string(decks.size()) +
                            " decks");
        }
        // Later engine decks of the same run (NAME_0002.rad, ...): OpenRadioss restarts, which radx lacks.
        if (run_number_of(deck) == 0) {
          const std::string prefix = deck.substr(0, deck.size() - 8);  // "NAME_"
          std::string later;
          for (const auto& n : names)
            if (run_number_of(n) >= 2 && n.size() == deck.size() && n.compare(0, prefix.size(), prefix) == 0)
              later += (later.empty() ? "" : ", ") + n;
          if (!later.empty())
            notes.push_back(later + " not run (radx runs " + prefix + "0001.rad only: it has no restart)");
        }
        for (const auto& n : notes) d.note += (d.note.empty() ? "" : "; ") + n;
        out.push_back(std::move(d));
      }
    }
  }
  // One flat folder per deck: a deck's run folder must never hold another's, since each is cleared before
  // its run and removed when it passes (deck A/ and deck A/B/ would otherwise share WORK/A).
  std::set<std::string> used;
  for (auto& d : out) {
    std::string flat = d.work_subdir.generic_string();
    std::replace(flat.begin(), flat.end(), '/', '~');
    std::string name = flat;
    for (int k = 2; !used.insert(name).second; ++k) name = flat + "_" + std::to_string(k);
    d.work_subdir = name;
  }
  return out;
}

// ---------------------------------------------------------------------------------------------------
// The child run.

ChildOutcome run_child(const std::vector<std::string>& args, const fs::path& log_path,
                       std::chrono::duration<double> timeout) {
  io::ProcessRequest request;
  request.argv = args;
  request.output_file = log_path;
  // Any file a run writes outside --out lands in its work folder, not in the caller's.
  request.working_dir = log_path.parent_path();
  request.timeout = timeout;
  const io::ProcessResult p = io::run_process(request);
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

const io::QuantityCheck* worst_check(const RegressResult& r) {
  const io::QuantityCheck* worst = nullptr;
  for (const auto& c : r.checks)
    if (!worst || c.score > worst->score) worst = &c;
  return worst;
}

std::size_t failed_checks(const RegressResult& r) {
  return static_cast<std::size_t>(std::count_if(r.checks.begin(), r.checks.end(),
                                                [](const io::QuantityCheck& c) { return !c.passed(); }));
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
  io::RegressReference ref;
  std::vector<std::string> errors;
  if (!io::read_regress_reference(r.deck.own_reference.string(), ref, errors)) {
    r.status = RegressStatus::RefError;
    for (const auto& e : errors) r.detail += (r.detail.empty() ? "" : "; ") + e;
    return;
  }
  const std::vector<io::ThGroupData>* th = files.th ? &*files.th : nullptr;
  r.checks = io::check_reference(ref, *files.summary, th);
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
      p.energy[static_cast<std::size_t>(io::ExtractEnergy::Internal)] = std::stod(f[pct + 1]);
      p.energy[static_cast<std::size_t>(io::ExtractEnergy::KineticTranslational)] = std::stod(f[pct + 2]);
      p.energy[static_cast<std::size_t>(io::ExtractEnergy::KineticRotational)] = std::stod(f[pct + 3]);
      p.energy[static_cast<std::size_t>(io::ExtractEnergy::ExternalWork)] = std::stod(f[pct + 4]);
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
  if (files.model_written && files.summary && files.summary->status == io::RunStatus::Error)
    details.push_back("error termination: " + files.summary->message);
  // Neither is a finished run, whatever the exit code says: the summary's figures are not the deck's.
  if (files.model_written && files.summary && files.summary->status == io::RunStatus::Interrupted)
    details.push_back("the engine was " + files.summary->message);
  if (files.model_written && files.summary && files.summary->status == io::RunStatus::Running)
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
  if (failed || !files.summary || files.summary->status != io::RunStatus::Normal) {
    r.status = RegressStatus::RunError;
    return r;
  }
  const io::RunSummary& s = *files.summary;
  io::RunFigures fig;
  fig.cycles = s.cycles;
  fig.time = s.time;
  fig.energy[static_cast<std::size_t>(io::ExtractEnergy::Internal)] = s.energy.internal;
  fig.energy[static_cast<std::size_t>(io::ExtractEnergy::KineticTranslational)] = s.energy.kinetic_t;
  fig.energy[static_cast<std::size_t>(io::ExtractEnergy::KineticRotational)] = s.energy.kinetic_r;
  fig.energy[static_cast<std::size_t>(io::ExtractEnergy::ExternalWork)] = s.energy.external_work;
  r.radx = fig;
  if (deck.has_own_reference) {
    evaluate_own_reference(r, files);
    return r;
  }
  if (deck.reference.empty()) {
    r.status = RegressStatus::Ran;
    return r;
  }
  io::RegressionExtract ref;
  std::string error;
  if (!io::read_regression_extract(deck.reference.string(), ref, error)) {
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
  r.comparison = io::compare_to_extract(fig, ref);
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
  files.model_written = fs::exists(dir / (starter_output_root(deck_path) + ".hdf"), ec);
  const std::string root = run_output_root(deck_path);
  const fs::path summary = dir / (root + "_summary.json");
  io::RunSummary s;
  if (!fs::exists(summary, ec))
    files.summary_error = "no " + summary.filename().string() + " written";
  else if (io::read_summary_json(summary.string(), s, files.summary_error))
    files.summary = s;
  files.output = read_text(dir / kRunLog);
  files.listing = listing_points(read_text(dir / (root + "_0001.out")));
  const fs::path th = dir / (root + "_th.h5");
  if (fs::exists(th, ec)) {
    std::vector<io::ThGroupData> groups;
    if (io::read_time_history(th.string(), groups, files.th_error)) files.th = std::move(groups);
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
    text = io::new_reference_text(r.deck.starter_deck.filename().string(), *files.summary);
    r.update_report = "  new reference " + path.filename().string() + "\n";
  } else {
    io::RegressReference ref;
    std::vector<std::string> errors;
    if (!io::read_regress_reference(path.string(), ref, errors)) {
      r.status = RegressStatus::RefError;
      r.detail.clear();
      for (const auto& e : errors) r.detail += (r.detail.empty() ? "" : "; ") + e;
      return;
    }
    const std::vector<io::ThGroupData>* th = files.th ? &*files.th : nullptr;
    std::vector<double> values;
    std::vector<std::string> lacking;
    for (const auto& q : ref.quantities) {
      std::string why;
      const auto v = io::run_quantity(q.name, *files.summary, th, why);
      if (!v) lacking.push_back(q.name + ": " + why);
      values.push_back(v.value_or(std::numeric_limits<double>::quiet_NaN()));
      if (!v) continue;
      const std::string was = q.value ? io::reference_number(*q.value) : std::string("-");
      const std::string now = io::reference_number(*v);
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
    text = io::updated_reference_text(ref, values);
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

// ---------------------------------------------------------------------------------------------------
// The report.

namespace {

std::string refusal_text(const RegressResult& r, std::size_t max_chars, bool with_location) {
  if (r.refusal.message.empty()) return shorten(r.detail, max_chars);
  std::string t = with_location && !r.refusal.location.empty() ? r.refusal.location + ": " : "";
  return shorten(t + r.refusal.message, max_chars);
}

std::string cycles_text(const RegressResult& r) {
  if (!r.radx) return "-";
  return std::to_string(r.radx->cycles) + "/" + (r.reference ? std::to_string(r.reference->cycles) : "-");
}

std::string energy_text(const RegressResult& r, io::ExtractEnergy e) {
  return r.comparison ? percent(r.comparison->energy[static_cast<std::size_t>(e)]) : "-";
}

std::string number_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

// One quantity's check: "energy.internal x1.53 (radx 510, ref 494.9, +3.1 %, allowed 9.9)", the score being
// the deviation over its allowance ("missing" when there is no value to compare).
std::string check_text(const io::QuantityCheck& c, bool with_values) {
  char score[32];
  if (!c.reference || !c.radx)
    std::snprintf(score, sizeof score, "missing");
  else if (std::isinf(c.score))
    std::snprintf(score, sizeof score, "xinf");  // a difference where the tolerance is zero
  else
    std::snprintf(score, sizeof score, "x%.2f", c.score);
  std::string t = c.name + " " + score;
  if (!with_values) return t;
  if (!c.reference || !c.radx) return t + " (" + c.why + ")";
  t += " (radx " + number_text(*c.radx) + ", ref " + number_text(*c.reference);
  if (*c.reference != 0) {
    char rel[32];
    std::snprintf(rel, sizeof rel, ", %+.3g %%", 100 * (*c.radx - *c.reference) / std::abs(*c.reference));
    t += rel;
  }
  return t + ", allowed " + number_text(c.allowed) + ")";
}

std::string worst_text(const RegressResult& r, bool with_values) {
  const io::QuantityCheck* w = worst_check(r);
  return w ? check_text(*w, with_values) : std::string();
}

}  // namespace

std::string format_regress_line(const RegressResult& r) {
  std::string s = r.deck.label + "  " + std::string(status_name(r.status));
  if (r.comparison) {
    const auto& c = *r.comparison;
    char ratio[32];
    std::snprintf(ratio, sizeof ratio, "%.2f", c.cycle_ratio);
    s += "  cycles " + cycles_text(r) + " (x" + ratio + ")  TIME " + percent(c.time) + " %" +
         (r.at_reference_time ? " (at the reference's last line)" : "");
    for (const auto e : io::kExtractEnergies)
      s += "  " + std::string(io::extract_label(e)) + " " + energy_text(r, e) + " %";
  } else if (r.radx) {
    char t[32];
    std::snprintf(t, sizeof t, "%.5g", r.radx->time);
    s += "  cycles " + std::to_string(r.radx->cycles) + "  time " + t;
  }
  if (!r.checks.empty()) {
    const std::size_t failed = failed_checks(r);
    s += "  worst " + worst_text(r, true);
    s += failed
             ? "  " + std::to_string(failed) + " of " + std::to_string(r.checks.size()) + " beyond tolerance"
             : "  " + std::to_string(r.checks.size()) + " quantities within tolerance";
  }
  if (r.status == RegressStatus::ReadError || r.status == RegressStatus::RunError ||
      r.status == RegressStatus::RefError) {
    s += "  " + refusal_text(r, kLineRefusalChars, true);
    if (!r.refusal.message.empty() && !r.detail.empty()) s += " (" + r.detail + ")";
  }
  if (r.status == RegressStatus::Diagnosed || r.status == RegressStatus::Unexpected) s += "  " + r.detail;
  if (!r.deck.note.empty()) s += "  [" + r.deck.note + "]";
  s += "  (" + seconds_text(r.seconds) + ")";
  // Every quantity beyond its tolerance, and what --update changed, on the lines below.
  for (const auto& c : r.checks)
    if (!c.passed()) s += "\n      " + check_text(c, true);
  if (!r.update_report.empty()) {
    s += "\n" + r.update_report;
    while (!s.empty() && s.back() == '\n') s.pop_back();
  }
  return s;
}

namespace {

// Counts of a batch for the totals line and the JSON summary.
struct RegressTotals {
  std::map<RegressStatus, std::size_t> count;
  std::size_t found = 0, must_fail = 0, read = 0, ran = 0, with_reference = 0, compared = 0;
};

RegressTotals regress_totals(const std::vector<RegressResult>& results) {
  RegressTotals t;
  t.found = results.size();
  for (const auto& r : results) {
    ++t.count[r.status];
    if (!r.deck.expected.empty()) {
      ++t.must_fail;
      continue;
    }
    if (r.status != RegressStatus::ReadError) ++t.read;
    if (r.radx) ++t.ran;
    if (!r.deck.reference.empty() || r.deck.has_own_reference) ++t.with_reference;
    if (r.status == RegressStatus::Compared) ++t.compared;
  }
  return t;
}

}  // namespace

void write_regress_table(std::ostream& os, const std::vector<RegressResult>& results, double tolerance) {
  const std::vector<std::string> titles{
      "deck",     "status",    "cycles radx/ref", "IE dev %",
      "KE dev %", "KER dev %", "EXT dev %",       "worst quantity, or first refusal"};
  std::vector<std::vector<std::string>> rows;
  for (const auto& r : results) {
    std::vector<std::string> row{r.deck.label, std::string(status_name(r.status)), cycles_text(r)};
    for (const auto e : io::kExtractEnergies) row.push_back(energy_text(r, e));
    const bool refused = r.status == RegressStatus::ReadError || r.status == RegressStatus::RunError ||
                         r.status == RegressStatus::RefError;
    if (refused)
      row.push_back(refusal_text(r, kTableRefusalChars, false));
    else if (!r.checks.empty())
      row.push_back(worst_text(r, false));
    else if (r.status == RegressStatus::Unexpected)
      row.push_back(shorten(r.detail, kTableRefusalChars));
    else
      row.push_back("");
    rows.push_back(std::move(row));
  }
  std::vector<std::size_t> width(titles.size());
  for (std::size_t c = 0; c < titles.size(); ++c) {
    width[c] = titles[c].size();
    for (const auto& row : rows) width[c] = std::max(width[c], row[c].size());
  }
  const auto put_row = [&](const std::vector<std::string>& row) {
    std::string line;
    for (std::size_t c = 0; c < row.size(); ++c) {
      const bool number = c >= 2 && c <= 6;  // right-aligned
      const std::string pad(width[c] - std::min(width[c], row[c].size()), ' ');
      if (c > 0) line += "  ";
      line += number ? pad + row[c] : (c + 1 == row.size() ? row[c] : row[c] + pad);
    }
    while (!line.empty() && line.back() == ' ') line.pop_back();
    os << line << '\n';
  };
  put_row(titles);
  std::size_t total = 0;
  for (const auto w : width) total += w + 2;
  os << std::string(std::min<std::size_t>(total, 160), '-') << '\n';
  for (const auto& row : rows) put_row(row);

  std::map<std::string, std::size_t> groups;
  for (const auto& r : results)
    if (!r.refusal.message.empty() && r.deck.expected.empty() &&
        (r.status == RegressStatus::ReadError || r.status == RegressStatus::RunError))
      ++groups[std::string(status_name(r.status)) + "  " + refusal_group(r.refusal.message)];
  RegressTotals t = regress_totals(results);
  os << "\ndecks found " << t.found << ", read " << t.read << ", ran " << t.ran << ", compared " << t.compared
     << " of " << t.with_reference << " with a reference (NAME.ref; ref.extract within "
     << tolerance_text(tolerance) << " %)";
  if (t.must_fail)
    os << ", diagnosed as expected " << t.count[RegressStatus::Diagnosed] << " of " << t.must_fail;
  os << "\n";
  os << "  read-error " << t.count[RegressStatus::ReadError] << ", run-error "
     << t.count[RegressStatus::RunError] << ", ref-error " << t.count[RegressStatus::RefError]
     << ", deviates " << t.count[RegressStatus::Deviates] << ", unexpected "
     << t.count[RegressStatus::Unexpected] << "; ran (no reference) " << t.count[RegressStatus::Ran]
     << ", compared " << t.count[RegressStatus::Compared] << ", read (starter only) "
     << t.count[RegressStatus::Read] << ", diagnosed " << t.count[RegressStatus::Diagnosed] << ", updated "
     << t.count[RegressStatus::Updated] << '\n';
  if (!groups.empty()) {
    std::vector<std::pair<std::string, std::size_t>> sorted(groups.begin(), groups.end());
    std::stable_sort(sorted.begin(), sorted.end(),
                     [](const auto& a, const auto& b) { return a.second > b.second; });
    os << "\nmost frequent first refusals:\n";
    for (std::size_t k = 0; k < std::min(sorted.size(), kMostFrequentShown); ++k) {
      char n[16];
      std::snprintf(n, sizeof n, "%5zu", sorted[k].second);
      os << n << "  " << sorted[k].first << '\n';
    }
  }
}

std::string regress_summary_json(const std::vector<RegressResult>& results, const RegressSettings& settings,
                                 bool work_dir_kept) {
  using io::json_number;
  using io::json_string;
  RegressTotals t = regress_totals(results);
  std::string j = "{\n";
  j += "  \"tolerance_percent\": " + json_number(100 * settings.tolerance) + ",\n";
  j += "  \"timeout_seconds\": " + json_number(settings.timeout_seconds) + ",\n";
  j += "  \"threads\": " + std::to_string(settings.threads) + ",\n";
  j += "  \"work_dir\": " + json_string(settings.work_dir.string()) + ",\n";
  j += "  \"work_dir_kept\": " + std::string(work_dir_kept ? "true" : "false") + ",\n";
  j += "  \"totals\": {\"found\": " + std::to_string(t.found) + ", \"read\": " + std::to_string(t.read) +
       ", \"ran\": " + std::to_string(t.ran) + ", \"with_reference\": " + std::to_string(t.with_reference) +
       ", \"compared\": " + std::to_string(t.compared) +
       ", \"with_expected_diagnostics\": " + std::to_string(t.must_fail);
  for (const auto s : {RegressStatus::ReadError, RegressStatus::RunError, RegressStatus::RefError,
                       RegressStatus::Ran, RegressStatus::Deviates, RegressStatus::Read,
                       RegressStatus::Diagnosed, RegressStatus::Unexpected, RegressStatus::Updated}) {
    std::string key(status_name(s));
    std::replace(key.begin(), key.end(), '-', '_');
    if (s == RegressStatus::Ran) key = "ran_without_reference";
    if (s == RegressStatus::Read) key = "read_starter_only";
    j += ", \"" + key + "\": " + std::to_string(t.count[s]);
  }
  j += "},\n  \"decks\": [";
  for (std::size_t k = 0; k < results.size(); ++k) {
    const RegressResult& r = results[k];
    j += k ? ",\n    {" : "\n    {";
    j += "\"deck\": " + json_string(r.deck.label);
    j += ", \"status\": " + json_string(status_name(r.status));
    j += ", \"starter_deck\": " + json_string(r.deck.starter_deck.string());
    j += ", \"reference\": " + (r.deck.reference.empty() ? "null" : json_string(r.deck.reference.string()));
    j += ", \"work_dir\": " + json_string((settings.work_dir / r.deck.work_subdir).string());
    j += ", \"seconds\": " + json_number(r.seconds);
    j += ", \"first_refusal\": " + (r.refusal.message.empty()
                                        ? "null"
                                        : "{\"location\": " + json_string(r.refusal.location) +
                                              ", \"message\": " + json_string(r.refusal.message) + "}");
    j += ", \"detail\": " + json_string(r.detail);
    j += ", \"note\": " + json_string(r.deck.note);
    if (r.radx) {
      j += ",\n     \"radx\": {\"cycles\": " + std::to_string(r.radx->cycles) +
           ", \"TIME\": " + json_number(r.radx->time);
      for (const auto e : io::kExtractEnergies)
        j += ", \"" + std::string(io::extract_key(e)) +
             "\": " + json_number(r.radx->energy[static_cast<std::size_t>(e)]);
      j += "}";
    } else {
      j += ", \"radx\": null";
    }
    if (r.reference) {
      j += ",\n     \"ref\": {\"cycles\": " + std::to_string(r.reference->cycles) +
           ", \"TIME\": " + json_number(r.reference->time);
      for (const auto e : io::kExtractEnergies) {
        const auto& v = (*r.reference)[e];
        j += ", \"" + std::string(io::extract_key(e)) + "\": {\"value\": " + json_number(v.value) +
             ", \"magnitude\": " + json_number(v.magnitude) + "}";
      }
      j += "}";
    } else {
      j += ", \"ref\": null";
    }
    if (r.comparison) {
      const auto& c = *r.comparison;
      j += ",\n     \"cycle_ratio\": " + json_number(c.cycle_ratio) +
           ", \"deviation_percent\": {\"TIME\": " + json_number(100 * c.time);
      for (const auto e : io::kExtractEnergies)
        j += ", \"" + std::string(io::extract_key(e)) +
             "\": " + json_number(100 * c.energy[static_cast<std::size_t>(e)]);
      j += "}";
    } else {
      j += ", \"cycle_ratio\": null, \"deviation_percent\": null";
    }
    j += ",\n     \"own_reference\": " +
         (r.deck.has_own_reference ? json_string(r.deck.own_reference.string()) : std::string("null"));
    j += ", \"checks\": [";
    for (std::size_t c = 0; c < r.checks.size(); ++c) {
      const auto& q = r.checks[c];
      const auto opt = [](const std::optional<double>& v) {
        return v ? json_number(*v) : std::string("null");
      };
      j += (c ? ", " : "") + std::string("{\"quantity\": ") + json_string(q.name) +
           ", \"radx\": " + opt(q.radx) + ", \"ref\": " + opt(q.reference) +
           ", \"allowed\": " + json_number(q.allowed) + ", \"score\": " + json_number(q.score) +
           ", \"passed\": " + (q.passed() ? "true" : "false") + "}";
    }
    j += "]}";
  }
  j += results.empty() ? "]\n}\n" : "\n  ]\n}\n";
  return j;
}

std::string regress_junit_xml(const std::vector<RegressResult>& results, double total_seconds) {
  std::size_t failures = 0, errors = 0;
  for (const auto& r : results) {
    if (r.status == RegressStatus::Deviates || r.status == RegressStatus::Unexpected) ++failures;
    if (r.status == RegressStatus::ReadError || r.status == RegressStatus::RunError ||
        r.status == RegressStatus::RefError)
      ++errors;
  }
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, "%.3f", total_seconds);
  std::string x = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  const std::string counts = " tests=\"" + std::to_string(results.size()) + "\" failures=\"" +
                             std::to_string(failures) + "\" errors=\"" + std::to_string(errors) +
                             "\" skipped=\"0\" time=\"" + seconds + "\"";
  x += "<testsuites name=\"radx regress\"" + counts + ">\n";
  x += "  <testsuite name=\"radx regress\"" + counts + ">\n";
  for (const auto& r : results) {
    std::snprintf(seconds, sizeof seconds, "%.3f", r.seconds);
    x += "    <testcase classname=\"radx.regress\" name=\"" + io::xml_escape(r.deck.label) + "\" time=\"" +
         seconds + "\">\n";
    const std::string line = format_regress_line(r);
    const std::string first_line = line.substr(0, line.find('\n'));
    if (is_failure(r.status)) {
      const bool failure = r.status == RegressStatus::Deviates || r.status == RegressStatus::Unexpected;
      const std::string tag = failure ? "failure" : "error";
      x += "      <" + tag + " type=\"" + std::string(status_name(r.status)) + "\" message=\"" +
           io::xml_escape(shorten(first_line, 300)) + "\">" + io::xml_escape(line) + "</" + tag + ">\n";
    }
    x += "      <system-out>" + io::xml_escape(line) + "</system-out>\n";
    x += "    </testcase>\n";
  }
  x += "  </testsuite>\n</testsuites>\n";
  return x;
}

bool label_matches(const std::string& label, const std::string& pattern) {
  if (pattern.find_first_of("*?[") == std::string::npos) return label.find(pattern) != std::string::npos;
  return fnmatch(pattern.c_str(), label.c_str(), 0) == 0;
}

// ---------------------------------------------------------------------------------------------------
// The command.

namespace {

// The cores this process may run on (its CPU affinity: a batch started under taskset or in a container
// limited to 2 cores of 64 runs 2 decks at a time), at least 1.
int usable_cores() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) == 0 && CPU_COUNT(&set) > 0) return CPU_COUNT(&set);
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

bool positive_number(const std::string& s, double& v) {
  try {
    std::size_t used = 0;
    v = std::stod(s, &used);
    return used == s.size() && std::isfinite(v) && v > 0;
  } catch (...) {
    return false;
  }
}

// The command line of `radx regress`, parsed.
struct RegressOptions {
  RegressSettings settings;
  std::vector<fs::path> dirs;
  std::vector<std::string> filters;
  std::string work, summary_file, junit_file;
};

// Parses `args` into `o`; the exit code of a usage error (its message on `err`), or nothing.
std::optional<int> parse_regress_options(const std::vector<std::string>& args, RegressOptions& o,
                                         std::ostream& err) {
  RegressSettings& settings = o.settings;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    const bool takes_value = a == "--tol" || a == "--work" || a == "--timeout" || a == "--threads" ||
                             a == "--summary" || a == "--junit" || a == "--filter" || a == "-j" ||
                             a == "--jobs";
    if (takes_value && i + 1 >= args.size()) {
      err << "radx regress: " << a << " needs a value\n";
      return kExitUsage;
    }
    double v = 0;
    if (a == "--tol") {
      if (!positive_number(args[++i], v)) {
        err << "radx regress: --tol needs a positive percentage\n";
        return kExitUsage;
      }
      settings.tolerance = v / 100;
    } else if (a == "--timeout") {
      if (!positive_number(args[++i], v)) {
        err << "radx regress: --timeout needs a positive number of seconds\n";
        return kExitUsage;
      }
      settings.timeout_seconds = v;
    } else if (a == "--threads" || a == "-j" || a == "--jobs") {
      if (!positive_number(args[++i], v) || v != std::floor(v) || v > 1024) {
        err << "radx regress: " << a << " needs a positive integer\n";
        return kExitUsage;
      }
      (a == "--threads" ? settings.threads : settings.jobs) = static_cast<int>(v);
    } else if (a == "--work") {
      o.work = args[++i];
    } else if (a == "--summary") {
      o.summary_file = args[++i];
    } else if (a == "--junit") {
      o.junit_file = args[++i];
    } else if (a == "--filter") {
      o.filters.push_back(args[++i]);
    } else if (a == "--keep") {
      settings.keep = true;
    } else if (a == "--update") {
      settings.update = true;
    } else if (!a.empty() && a[0] == '-') {
      err << "radx regress: unknown option " << a << '\n';
      return kExitUsage;
    } else {
      o.dirs.emplace_back(a);
    }
  }
  std::error_code ec;
  if (o.dirs.empty()) {
    if (!fs::is_directory("decks", ec)) {
      err << "radx regress: give one or more folders to search for decks (radx regress DIR...); without one, "
             "radx regress runs ./decks, and there is no decks folder here\n";
      return kExitUsage;
    }
    o.dirs.emplace_back("decks");
  }
  for (const auto& d : o.dirs)
    if (!fs::is_directory(d, ec)) {
      err << "radx regress: " << d.string() << ": no such folder\n";
      return kExitUsage;
    }
  return std::nullopt;
}

// Sets o.settings.work_dir: a new temporary folder, or --work. The folder is ours when we create it or it
// carries our marker; anything else that is not empty is refused, since each deck's folder in it is cleared
// before its run. The exit code of a failure (its message on `err`), or nothing.
std::optional<int> open_work_folder(RegressOptions& o, std::ostream& err) {
  RegressSettings& settings = o.settings;
  std::error_code ec;
  if (o.work.empty()) {
    std::string tmpl = (fs::temp_directory_path(ec) / "radx-regress-XXXXXX").string();
    if (!mkdtemp(tmpl.data())) {
      err << "radx regress: cannot create a work folder " << tmpl << ": " << std::strerror(errno) << '\n';
      return kExitInputError;
    }
    settings.work_dir = fs::absolute(tmpl, ec);  // TMPDIR may be relative; the children run elsewhere
  } else {
    settings.work_dir = fs::absolute(o.work, ec);
    if (fs::exists(settings.work_dir, ec) &&
        (!fs::is_directory(settings.work_dir, ec) ||
         (!fs::is_empty(settings.work_dir, ec) && !fs::exists(settings.work_dir / kWorkMarker, ec)))) {
      err << "radx regress: --work " << o.work
          << ": exists and is not a radx regress work folder; give a new or empty folder\n";
      return kExitUsage;
    }
    settings.keep = true;  // a folder the user named is theirs to remove
  }
  fs::create_directories(settings.work_dir, ec);
  std::ofstream(settings.work_dir / kWorkMarker) << "radx regress work folder: deck folders in it are "
                                                    "cleared and rewritten by each run\n";
  if (!fs::is_directory(settings.work_dir, ec)) {
    err << "radx regress: cannot create the work folder " << settings.work_dir.string() << '\n';
    return kExitInputError;
  }
  return std::nullopt;
}

// Runs the decks `settings.jobs` at a time, each in its own child process. A line is printed as each
// finishes, in the order they finish; the results are in deck order whatever the order of finishing.
std::vector<RegressResult> run_decks(const std::vector<RegressDeck>& decks, const RegressSettings& settings,
                                     std::ostream& out) {
  std::vector<RegressResult> results(decks.size());
  std::atomic<std::size_t> next{0};
  std::size_t finished = 0;
  std::mutex print;
  const int digits = static_cast<int>(std::to_string(decks.size()).size());
  const auto worker = [&] {
    for (std::size_t k = next++; k < decks.size(); k = next++) {
      RegressResult r;
      try {
        r = run_regress_deck(decks[k], settings);
      } catch (const std::exception& e) {  // one deck's trouble (a full disk, memory) ends its run only
        r.deck = decks[k];
        r.status = RegressStatus::RunError;
        r.detail = std::string("radx regress could not run it: ") + e.what();
      }
      const std::string line = format_regress_line(r);
      std::lock_guard<std::mutex> lock(print);
      char counter[48];
      std::snprintf(counter, sizeof counter, "[%*zu/%zu] ", digits, ++finished, decks.size());
      out << counter << line << std::endl;
      results[k] = std::move(r);
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < settings.jobs; ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  return results;
}

}  // namespace

int regress_command(const std::vector<std::string>& args, const fs::path& executable, std::ostream& out,
                    std::ostream& err) {
  RegressOptions o;
  o.settings.executable = executable;
  o.settings.jobs = usable_cores();
  if (const auto code = parse_regress_options(args, o, err)) return *code;
  if (const auto code = open_work_folder(o, err)) return *code;
  RegressSettings& settings = o.settings;
  std::error_code ec;

  std::vector<RegressDeck> decks = find_regress_decks(o.dirs, settings.work_dir);
  if (!o.filters.empty())
    std::erase_if(decks, [&](const RegressDeck& d) {
      return std::none_of(o.filters.begin(), o.filters.end(),
                          [&](const std::string& p) { return label_matches(d.label, p); });
    });
  if (decks.empty()) {
    err << "radx regress: no deck (NAME_0000.rad, a one-file deck, or a deck with # expect: lines) under the "
           "folders given"
        << (o.filters.empty() ? "" : " that matches --filter") << '\n';
    if (o.work.empty()) fs::remove_all(settings.work_dir, ec);
    return kExitInputError;
  }
  settings.jobs = std::min<int>(settings.jobs, static_cast<int>(decks.size()));
  out << "radx regress: " << decks.size() << " deck(s), " << settings.jobs << " at a time, "
      << settings.threads << " engine thread(s) each, time limit " << settings.timeout_seconds
      << " s each, ref.extract tolerance " << tolerance_text(settings.tolerance) << " %, work folder "
      << settings.work_dir.string() << (settings.update ? ", updating references" : "") << "\n\n";

  const auto start = std::chrono::steady_clock::now();
  const std::vector<RegressResult> results = run_decks(decks, settings, out);
  const double total_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out << '\n';
  write_regress_table(out, results, settings.tolerance);

  const auto failing = static_cast<std::size_t>(std::count_if(
      results.begin(), results.end(), [](const RegressResult& r) { return is_failure(r.status); }));
  int code = failing ? kExitInputError : kExitOk;
  // The run folders of passing decks are already gone (unless kept): what is left is the failures'.
  if (!settings.keep && failing == 0) fs::remove_all(settings.work_dir, ec);
  out << "\nwall time " << seconds_text(total_seconds) << "; work folder " << settings.work_dir.string();
  if (settings.keep)
    out << " (outputs and each deck's run.log)\n";
  else if (failing == 0)
    out << " removed (--keep keeps it)\n";
  else
    out << " keeps the " << failing << " failing deck(s)' outputs and run.log\n";
  const auto write_report = [&](const std::string& path, const std::string& text, const char* what) {
    if (const fs::path parent = fs::path(path).parent_path(); !parent.empty())
      fs::create_directories(parent, ec);
    std::string error;
    if (!write_text_atomically(path, text, error)) {
      err << "radx regress: " << error << '\n';
      code = kExitInputError;
      return;
    }
    out << what << ' ' << path << '\n';
  };
  if (!o.summary_file.empty())
    write_report(o.summary_file, regress_summary_json(results, settings, settings.keep), "summary");
  if (!o.junit_file.empty())
    write_report(o.junit_file, regress_junit_xml(results, total_seconds), "JUnit report");
  return code;
}

}  // namespace radx::app
