// radx regress: the command's options, its work folder, the decks run N at a time, and its exit code
// (apps/regress_command.hpp).
#include "apps/regress_command.hpp"

#include <sched.h>
#include <stdlib.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <mutex>
#include <optional>
#include <ostream>
#include <thread>

#include "apps/cli_common.hpp"
#include "io/regress/regress_decks.hpp"
#include "io/regress/regress_report.hpp"
#include "io/regress/regress_run.hpp"
#include "io/regress/regress_text.hpp"
#include "io/text_file.hpp"

namespace radx::app {

namespace fs = std::filesystem;
using io::RegressDeck;
using io::RegressResult;
using io::RegressSettings;
using io::RegressStatus;

namespace {

// Marks a work folder as radx regress's own, so a second run may clear the deck folders inside it; a folder
// without it that is not empty is refused (it could be anything, a deck folder included).
constexpr const char* kWorkMarker = ".radx-regress";

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
      err << unknown_option("radx regress", a,
                            {"--tol", "--work", "--timeout", "--threads", "--summary", "--junit", "--filter",
                             "-j", "--jobs", "--keep", "--update", "--help"})
          << '\n';
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
        r = io::run_regress_deck(decks[k], settings);
      } catch (const std::exception& e) {  // one deck's trouble (a full disk, memory) ends its run only
        r.deck = decks[k];
        r.status = RegressStatus::RunError;
        r.detail = std::string("radx regress could not run it: ") + e.what();
      }
      const std::string line = io::format_regress_line(r);
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

  std::vector<RegressDeck> decks = io::find_regress_decks(o.dirs, settings.work_dir);
  if (!o.filters.empty())
    std::erase_if(decks, [&](const RegressDeck& d) {
      return std::none_of(o.filters.begin(), o.filters.end(),
                          [&](const std::string& p) { return io::label_matches(d.label, p); });
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
      << " s each, ref.extract tolerance " << io::tolerance_text(settings.tolerance) << " %, work folder "
      << settings.work_dir.string() << (settings.update ? ", updating references" : "") << "\n\n";

  const auto start = std::chrono::steady_clock::now();
  const std::vector<RegressResult> results = run_decks(decks, settings, out);
  const double total_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out << '\n';
  io::write_regress_table(out, results, settings.tolerance);

  const auto failing = static_cast<std::size_t>(std::count_if(
      results.begin(), results.end(), [](const RegressResult& r) { return io::is_failure(r.status); }));
  int code = failing ? kExitInputError : kExitOk;
  // The run folders of passing decks are already gone (unless kept): what is left is the failures'.
  if (!settings.keep && failing == 0) fs::remove_all(settings.work_dir, ec);
  out << "\nwall time " << io::seconds_text(total_seconds) << "; work folder " << settings.work_dir.string();
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
    if (!io::write_text_atomically(path, text, error)) {
      err << "radx regress: " << error << '\n';
      code = kExitInputError;
      return;
    }
    out << what << ' ' << path << '\n';
  };
  if (!o.summary_file.empty())
    write_report(o.summary_file, io::regress_summary_json(results, settings, settings.keep), "summary");
  if (!o.junit_file.empty())
    write_report(o.junit_file, io::regress_junit_xml(results, total_seconds), "JUnit report");
  return code;
}

}  // namespace radx::app
