// radx: the driver. `radx check DECK` runs every starter check (and the engine deck's, when one is
// beside it or in the same one-file deck) without writing anything; `radx keywords` prints the
// keyword reference generated from the declarations; `radx th FILE` lists or exports a time history;
// `radx regress DIR...` runs every deck under the folders given and compares them with their references
// (apps/regress_command.hpp); `radx diff RUN_A RUN_B` compares two runs (io/compare/run_compare.hpp).
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iostream>
#include <string>
#include <string_view>
#include <vector>

#include <filesystem>

#include "apps/build_info.hpp"
#include "apps/cli_common.hpp"
#include "apps/engine_pipeline.hpp"
#include "apps/regress_command.hpp"
#include "apps/starter_pipeline.hpp"
#include "io/compare/run_compare.hpp"
#include "io/hdf5/time_history.hpp"
#include "io/hdf5/time_history_export.hpp"
#include "io/signal/cfc_filter.hpp"
#include "parser/reading/deck.hpp"
#include "parser/reading/deck_echo.hpp"
#include "solver/model/run_files.hpp"

namespace {

// Each command's synopsis and help, the one text both `radx --help` and `radx COMMAND --help` print.
struct CommandHelp {
  std::string_view name;
  std::string_view text;
};
constexpr CommandHelp kCommands[] = {
    {"check",
     "  check DECK                  read and check a starter deck (and NAME_0001.rad beside it, or the\n"
     "                              engine part of a one-file deck); writes nothing\n"},
    {"keywords",
     "  keywords [--markdown] [--output FILE]\n"
     "                              the keyword reference (every keyword, card, field and diagnostic "
     "code)\n"},
    {"run",
     "  run [DECK] [--out DIR] [--threads N] [--no-plot] [--allow-substitutions] [--starter-only]\n"
     "      [--stop-if-runaway] [--decompose P]\n"
     "                              the starter then the engine: DECK is NAME_0000.rad (NAME_0001.rad "
     "beside\n"
     "                              it) or a one-file deck; without DECK, the embedded default deck.\n"
     "                              --allow-substitutions: run the nearest formulation radx implements\n"
     "                              where the deck asks for one it lacks (each is listed) instead of\n"
     "                              refusing the deck. --starter-only: stop after the starter (a\n"
     "                              starter deck with no engine deck). --stop-if-runaway: as\n"
     "                              radx-engine's (stop a run whose step has collapsed).\n"
     "                              --decompose P: after the starter, radx-engine --decompose P (print\n"
     "                              and write the decomposition over P ranks; no run)\n"},
    {"th",
     "  th FILE [--csv [-o OUT.csv] [--var SELECTOR]... [--filter CFC]] | th FILE --recover\n"
     "                              a time history P_th.h5: without --csv, list its groups (objects,\n"
     "                              variables, units, rows, time range); with --csv, write the chosen\n"
     "                              columns (all by default) as CSV to OUT.csv or standard output.\n"
     "                              SELECTOR: a group (node/1), a column (global:IE, node/1:12:DX) or an\n"
     "                              object's columns (node/1:12); '*' and '?' are wildcards; repeatable.\n"
     "                              --filter CFC60|CFC180|CFC600|CFC1000: SAE J211 channel frequency\n"
     "                              class filter of each chosen column (phaseless 2-pole Butterworth,\n"
     "                              forward then backward; -3 dB at 5/3 CFC Hz); rows not evenly spaced\n"
     "                              are resampled on a uniform step for it (a note says so).\n"
     "                              --recover: rewrite a file whose run was killed inside a flush (HDF5\n"
     "                              readers refuse it) with the rows of the flushes that completed\n"},
    {"diff",
     "  diff RUN_A RUN_B [--rel R] [--abs A] [--top N]\n"
     "                              compare two runs: the figures of their NAME_summary.json and their\n"
     "                              NAME_th.h5 channels (matched by group, object id and variable, read\n"
     "                              at the common times by linear interpolation). RUN: a\n"
     "                              NAME_summary.json, its folder, or DIR/NAME. B passes where |B - A| <=\n"
     "                              max(R |A|, floor): R the relative tolerance (default 1e-3), floor R x\n"
     "                              the largest magnitude in either run of the channels of the same /TH\n"
     "                              group and unit (of a figure's family: every energy, the momentum),\n"
     "                              or A with --abs (in each channel's unit). Prints the N largest\n"
     "                              deviations (default 10) with their time and both values.\n"
     "                              Exit code 0 within the tolerance, 1 past it, 2 on bad input (a\n"
     "                              missing file, runs that cannot be compared, a bad option)\n"},
    {"regress",
     "  regress [DIR...] [-j N] [--filter PATTERN]... [--update] [--keep] [--junit FILE]\n"
     "          [--summary FILE] [--tol PCT] [--timeout SECONDS] [--threads N] [--work DIR]\n"
     "                              run every deck under the folders (default ./decks: NAME_0000.rad, a\n"
     "                              one-file deck, or a deck whose # expect: lines say it must be\n"
     "                              refused), N at a time (default: the cores), each as its own `radx\n"
     "                              run` (--threads, default 1) with a time limit (--timeout, default\n"
     "                              600 s), and compare it with its reference: its NAME.ref, or the\n"
     "                              folder's OpenRadioss ref.extract (energies within --tol, default\n"
     "                              5 %); one line per deck as it finishes, then a table. --filter keeps\n"
     "                              the decks whose name matches (glob, or substring); --update rewrites\n"
     "                              (or writes) each NAME.ref from the run, saying what changed; --junit\n"
     "                              writes a JUnit XML report, --summary a JSON one. Runs happen in a\n"
     "                              scratch folder; a passing deck's is removed unless --keep (--work\n"
     "                              DIR keeps them there). Exit code 1 when a deck fails\n"
     "                              (docs/regress.md)\n"},
};

constexpr std::string_view kExitCodes =
    "Exit code: 0 success, 1 input errors or an error termination, 2 usage errors, 143 or 130 when\n"
    "SIGTERM or SIGINT stopped the engine (after a cycle, with a last state and the summary).\n";

void usage(std::ostream& os) {
  os << "usage: radx <command> [options]\n\ncommands:\n";
  for (const auto& c : kCommands) os << c.text;
  os << "\n  --help, --version; radx COMMAND --help (or radx help COMMAND) for one command\n\n" << kExitCodes;
}

// The help of one command, or nullptr when `name` is none.
const CommandHelp* command_help(std::string_view name) {
  for (const auto& c : kCommands)
    if (c.name == name) return &c;
  return nullptr;
}

void command_usage(const CommandHelp& c, std::ostream& os) {
  os << "usage: radx " << c.name << " [options]\n\n" << c.text << '\n' << kExitCodes;
}

int check(const std::vector<std::string>& args) {
  if (args.size() != 1) {
    std::cerr << "radx check: give exactly one deck\n";
    return radx::app::kExitUsage;
  }
  radx::app::StarterOptions opt;
  opt.deck = args[0];
  opt.write_outputs = false;
  opt.check_engine_deck = true;
  return radx::app::run_starter(opt, std::cout, std::cerr).exit_code;
}

int run(const std::vector<std::string>& args) {
  radx::app::StarterOptions sopt;
  radx::app::EngineOptions eopt;
  bool starter_only = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if ((a == "--out" || a == "--threads" || a == "--decompose") && i + 1 >= args.size()) {
      std::cerr << "radx run: " << a << " needs a value\n";
      return radx::app::kExitUsage;
    }
    if (a == "--out") {
      sopt.out_dir = eopt.out_dir = args[++i];
    } else if (a == "--threads") {
      try {
        eopt.threads = std::stoi(args[++i]);
      } catch (...) {
        eopt.threads = -1;
      }
      if (eopt.threads < 1) {
        std::cerr << "radx run: --threads needs a positive integer\n";
        return radx::app::kExitUsage;
      }
    } else if (a == "--decompose") {
      try {
        eopt.decompose_ranks = std::stoi(args[++i]);
      } catch (...) {
        eopt.decompose_ranks = -1;
      }
      if (eopt.decompose_ranks < 1) {
        std::cerr << "radx run: --decompose needs a positive integer (the rank count)\n";
        return radx::app::kExitUsage;
      }
    } else if (a == "--no-plot") {
      eopt.plot = false;
    } else if (a == "--stop-if-runaway") {
      eopt.stop_if_runaway = true;
    } else if (a == "--allow-substitutions") {
      sopt.allow_substitutions = true;
    } else if (a == "--starter-only") {
      starter_only = true;
    } else if (!a.empty() && a[0] == '-') {
      std::cerr << radx::app::unknown_option("radx run", a,
                                             {"--out", "--threads", "--no-plot", "--allow-substitutions",
                                              "--starter-only", "--stop-if-runaway", "--decompose", "--help"})
                << '\n';
      return radx::app::kExitUsage;
    } else if (sopt.deck.empty()) {
      sopt.deck = a;
    } else {
      std::cerr << "radx run: one deck at a time\n";
      return radx::app::kExitUsage;
    }
  }
  if (sopt.deck.empty()) {
    sopt.deck = radx::app::write_default_starter_deck(sopt.out_dir);
    eopt.engine_deck = radx::app::write_default_engine_deck(sopt.out_dir);
    std::cout << "radx run: no deck given, running the embedded default deck " << sopt.deck << '\n';
  }
  if (eopt.engine_deck.empty()) {
    if (radx::model::is_one_file_deck(sopt.deck)) {
      eopt.engine_deck = sopt.deck;
    } else {
      const std::filesystem::path p(sopt.deck);
      const std::string stem = p.stem().string();
      const std::string base = stem.size() > 5 && stem.compare(stem.size() - 5, 5, "_0000") == 0
                                   ? stem.substr(0, stem.size() - 5)
                                   : stem;
      eopt.engine_deck = (p.parent_path() / (base + "_0001" + p.extension().string())).string();
    }
  }
  const auto s = radx::app::run_starter(sopt, std::cout, std::cerr);
  if (s.exit_code != 0 || starter_only) return s.exit_code;
  eopt.model_file = s.model_path;
  return radx::app::run_engine(eopt, std::cout, std::cerr);
}

int keywords(const std::vector<std::string>& args) {
  std::string output;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--markdown") continue;
    if (args[i] == "--output" && i + 1 < args.size()) {
      output = args[++i];
      continue;
    }
    std::cerr << "radx keywords: unknown argument " << args[i] << '\n';
    return radx::app::kExitUsage;
  }
  if (output.empty()) {
    radx::write_keyword_reference(std::cout);
    return radx::app::kExitOk;
  }
  std::ofstream f(output, std::ios::trunc);
  if (!f) {
    std::cerr << "radx keywords: cannot write " << output << '\n';
    return radx::app::kExitInputError;
  }
  radx::write_keyword_reference(f);
  return radx::app::kExitOk;
}

// Parsing only: reading, selecting and writing are io's (io/hdf5/time_history_export.hpp).
int th(const std::vector<std::string>& args) {
  std::string file, output, filter;
  bool csv = false, have_output = false, recover = false;
  std::vector<std::string> selectors;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if ((a == "-o" || a == "--output" || a == "--var" || a == "--filter") && i + 1 >= args.size()) {
      std::cerr << "radx th: " << a << " needs a value\n";
      return radx::app::kExitUsage;
    }
    if (a == "--csv") {
      csv = true;
    } else if (a == "--recover") {
      recover = true;
    } else if (a == "-o" || a == "--output") {
      output = args[++i];
      have_output = true;
    } else if (a == "--var") {
      selectors.push_back(args[++i]);
    } else if (a == "--filter") {
      filter = args[++i];
    } else if (!a.empty() && a[0] == '-') {
      std::cerr << radx::app::unknown_option(
                       "radx th", a, {"--csv", "--recover", "--output", "-o", "--var", "--filter", "--help"})
                << '\n';
      return radx::app::kExitUsage;
    } else if (file.empty()) {
      file = a;
    } else {
      std::cerr << "radx th: one file at a time\n";
      return radx::app::kExitUsage;
    }
  }
  if (file.empty()) {
    std::cerr << "radx th: give a time-history file (P_th.h5)\n";
    return radx::app::kExitUsage;
  }
  if (!csv && (have_output || !selectors.empty() || !filter.empty())) {
    std::cerr << "radx th: -o, --var and --filter go with --csv\n";
    return radx::app::kExitUsage;
  }
  const auto cfc = radx::io::parse_cfc_class(filter);
  if (!filter.empty() && !cfc) {
    std::cerr << "radx th: --filter " << filter
              << ": not a class; accepted: CFC60, CFC180, CFC600, CFC1000\n";
    return radx::app::kExitUsage;
  }
  // --recover rewrites the file: never under a run that is still writing it (its next flush would append at
  // the old offsets). The run holds NAME.lock beside NAME_th.h5; holding it here keeps a run from starting
  // until the rewrite is done.
  radx::app::RunLock lock;
  if (recover) {
    const std::filesystem::path p(file);
    const std::string name = p.filename().string();
    const std::string suffix = "_th.h5";
    if (name.size() > suffix.size() && name.ends_with(suffix)) {
      try {
        const std::string dir = p.has_parent_path() ? p.parent_path().string() : std::string(".");
        lock = radx::app::RunLock(dir, name.substr(0, name.size() - suffix.size()));
      } catch (const std::exception& e) {
        std::cerr << "radx th: cannot recover " << file << " now: " << e.what() << '\n';
        return radx::app::kExitInputError;
      }
    }
  }
  std::vector<radx::io::ThGroupData> groups;
  std::string error;
  bool interrupted = false;
  if (!radx::io::read_time_history(file, groups, error, &interrupted)) {
    std::cerr << "radx th: " << error << '\n';
    return radx::app::kExitInputError;
  }
  if (recover) {
    if (!interrupted) {
      std::cerr << "radx th: " << file << " is complete: nothing to recover\n";
      return radx::app::kExitOk;
    }
    if (!radx::io::rewrite_time_history(file, groups, error)) {
      std::cerr << "radx th: cannot recover " << error << '\n';
      return radx::app::kExitInputError;
    }
    std::cerr << "radx th: " << file << " rewritten with the rows of the flushes that completed\n";
    return radx::app::kExitOk;
  }
  // Other HDF5 readers refuse such a file ("already open for write"); h5clear alone would let them read
  // the unfinished flush's rows.
  if (interrupted) {
    std::cerr
        << "radx th: warning: " << file
        << " was being written when its run was killed (or a flush is under way now); read: the rows of "
           "the flushes that completed. Other HDF5 readers refuse the file: `radx th "
        << file
        << " --recover` rewrites it with these rows (do not use h5clear -s, which would let "
           "them read the unfinished flush's rows)\n";
  }
  if (!csv) {
    radx::io::list_time_history(file, groups, std::cout);
    return radx::app::kExitOk;
  }
  std::vector<radx::io::ThColumnRef> chosen;
  if (!radx::io::select_th_columns(groups, selectors, chosen, error)) {
    std::cerr << "radx th: " << file << ": " << error << '\n';
    return radx::app::kExitInputError;
  }
  if (cfc) {
    bool resampled = false, coarse = false;
    if (!radx::io::filter_th_columns(groups, chosen, *cfc, error, &resampled, &coarse)) {
      std::cerr << "radx th: " << file << ": --filter " << filter << ": " << error << '\n';
      return radx::app::kExitInputError;
    }
    if (resampled)
      std::cerr << "radx th: note: " << file << ": the rows are not evenly spaced; each column was resampled "
                << "on a uniform step (the span over the rows) for the " << filter
                << " filter and read back at the rows' times\n";
    if (coarse)
      std::cerr << "radx th: note: " << file << ": the rows are sampled below the 10 F_H = " << 50 * *cfc / 3
                << " Hz that SAE J211 asks for the " << filter
                << " class; the filter ran, but a finer /TFILE interval gives a truer pulse\n";
  }
  bool written = have_output ? radx::io::write_th_csv_file(groups, chosen, output, error, filter)
                             : radx::io::write_th_csv(groups, chosen, std::cout, error, filter);
  // Standard output redirected to a file: a full disk shows only as the stream's state after the flush.
  if (written && !have_output && !std::cout.flush()) {
    error = std::string("cannot write the CSV to standard output: ") + std::strerror(errno);
    written = false;
  }
  if (!written) {
    std::cerr << "radx th: " << file << ": " << error << '\n';
    return radx::app::kExitInputError;
  }
  return radx::app::kExitOk;
}

// Parsing only: the comparison is io's (io/compare/run_compare.hpp). Exit 0 within, 1 past, 2 bad input.
int diff(const std::vector<std::string>& args) {
  constexpr int kWithin = 0, kPast = 1, kBadInput = 2;
  radx::io::CompareOptions options;
  std::vector<std::string> runs;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--rel" || a == "--abs" || a == "--top") {
      if (i + 1 >= args.size()) {
        std::cerr << "radx diff: " << a << " needs a value\n";
        return kBadInput;
      }
      const std::string& v = args[++i];
      double x = -1;
      try {
        std::size_t used = 0;
        x = std::stod(v, &used);
        if (used != v.size()) x = -1;
      } catch (...) {
        x = -1;
      }
      if (!(x >= 0) || (a == "--top" && x != static_cast<double>(static_cast<std::size_t>(x)))) {
        std::cerr << "radx diff: " << a << " " << v << ": give a number >= 0"
                  << (a == "--top" ? " (a whole number)" : "") << '\n';
        return kBadInput;
      }
      if (a == "--rel") options.rel = x;
      if (a == "--abs") options.abs = x;
      if (a == "--top") options.top = static_cast<std::size_t>(x);
    } else if (!a.empty() && a[0] == '-') {
      std::cerr << radx::app::unknown_option("radx diff", a, {"--rel", "--abs", "--top", "--help"}) << '\n';
      return kBadInput;
    } else {
      runs.push_back(a);
    }
  }
  if (runs.size() != 2) {
    std::cerr
        << "radx diff: give two runs, RUN_A RUN_B (each a NAME_summary.json, its folder, or DIR/NAME)\n";
    return kBadInput;
  }
  radx::io::RunFiles a, b;
  std::string error;
  if (!radx::io::find_run_files(runs[0], a, error) || !radx::io::find_run_files(runs[1], b, error)) {
    std::cerr << "radx diff: " << error << '\n';
    return kBadInput;
  }
  radx::io::RunComparison c;
  if (!radx::io::compare_runs(a, b, options, c, error)) {
    std::cerr << "radx diff: " << error << '\n';
    return kBadInput;
  }
  radx::io::write_comparison(a, b, options, c, std::cout);
  return c.past() == 0 ? kWithin : kPast;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    usage(std::cerr);
    return radx::app::kExitUsage;
  }
  const std::string cmd = argv[1];
  const std::vector<std::string> args(argv + 2, argv + argc);
  if (cmd == "--help" || cmd == "-h" || cmd == "help") {
    // `radx help COMMAND`: that command's help.
    if (!args.empty()) {
      const auto* c = command_help(args[0]);
      if (c == nullptr) {
        std::cerr << "radx help: unknown command '" << args[0] << "'\n";
        usage(std::cerr);
        return radx::app::kExitUsage;
      }
      command_usage(*c, std::cout);
      return radx::app::kExitOk;
    }
    usage(std::cout);
    return radx::app::kExitOk;
  }
  // `radx COMMAND --help` (or -h) anywhere among its arguments: that command's help, nothing run.
  if (const auto* c = command_help(cmd)) {
    for (const auto& a : args)
      if (a == "--help" || a == "-h") {
        command_usage(*c, std::cout);
        return radx::app::kExitOk;
      }
  }
  if (cmd == "--version") {
    std::cout << "radx " << radx::app::version_text() << '\n';
    return radx::app::kExitOk;
  }
  if (cmd == "check") return check(args);
  if (cmd == "keywords") return keywords(args);
  if (cmd == "run") return run(args);
  if (cmd == "th") return th(args);
  if (cmd == "diff") return diff(args);
  if (cmd == "regress") {
    // The decks run in child processes of this same executable (`radx run`).
    std::error_code ec;
    const auto self = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec) {
      std::cerr << "radx regress: cannot find this executable (/proc/self/exe): " << ec.message() << '\n';
      return radx::app::kExitInputError;
    }
    return radx::app::regress_command(args, self, std::cout, std::cerr);
  }
  const std::string hint =
      radx::did_you_mean(cmd, {"check", "keywords", "run", "th", "diff", "regress", "help"});
  std::cerr << "radx: unknown command '" << cmd << "'" << (hint.empty() ? "" : " (" + hint + ")") << '\n';
  usage(std::cerr);
  return radx::app::kExitUsage;
}
