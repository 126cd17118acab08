#include "apps/engine_cli.hpp"

#include <algorithm>
#include <iostream>
#include <ostream>
#include <streambuf>
#include <string>
#include <vector>

#include "apps/build_info.hpp"
#include "apps/cli_common.hpp"
#include "apps/engine_pipeline.hpp"
#include "solver/parallel/comm.hpp"

namespace radx::app {

namespace {

// Where the output of ranks other than 0 goes: nowhere, with the stream staying good.
class NullStream : public std::ostream {
 public:
  NullStream() : std::ostream(&buffer_) {}

 private:
  struct Discard : std::streambuf {
    int overflow(int c) override { return traits_type::not_eof(c); }
    std::streamsize xsputn(const char* /*s*/, std::streamsize n) override { return n; }
  };
  Discard buffer_;
};

void usage(std::ostream& os, const std::string& program, std::span<const ExtraFlag> extra_flags) {
  const std::string indent(program.size() + 8, ' ');
  os << "usage: " << program << " [NAME_0001.rad] [--out DIR] [--model FILE] [--threads N] [--no-plot]\n"
     << indent << "[--stop-if-runaway] [--partition FILE]\n"
     << "       " << program << " -i NAME_0001.rad ...\n"
     << "       " << program << " --decompose P [--partition FILE] NAME_0001.rad [--out DIR] [--model FILE]\n"
     << "\n"
        "Runs the explicit engine: reads the engine deck and the starter's model file NAME_0000.hdf (in the\n"
        "output folder unless --model is given), and writes the listing NAME_0001.out (also on stdout) and\n"
        "NAME_summary.json, the animation states for ParaView (open NAME.hdf.series; also NAME.xmf), the\n"
        "time history NAME_th.h5 (read it with `radx th`) and the energy balance NAME_energy.csv and\n"
        "NAME_energy.png in the current folder or in DIR.\n"
        "\n"
        "  -i DECK        the engine deck\n"
        "  --out DIR      output folder (default: the current folder)\n"
        "  --model FILE   the model file (default: DIR/NAME_0000.hdf)\n"
        "  --threads N    threads (default: OMP_NUM_THREADS, else the cores this process may use); results "
        "do "
        "not depend on it; -nt N, Radioss's spelling, is the same\n"
        "  --no-plot      do not draw NAME_energy.png (the CSV is still written)\n"
        "  --stop-if-runaway\n"
        "                 stop the run (error termination, its reason in the listing and the summary) when\n"
        "                 its time step falls so far that the cycles left to the end time exceed 100 times\n"
        "                 the starter's estimate of the whole run, or 1e9; without it the run goes on and\n"
        "                 warns once, naming what sets the step and the wall time it would take\n"
        "  --decompose P  do not run: deal the element groups out to P ranks (METIS, as a run on P ranks\n"
        "                 does), print each rank's groups, elements, weights, owned, ghost and shared nodes\n"
        "                 and the imbalance, and write NAME_domain.hdf (cell array domain for ParaView) and\n"
        "                 NAME_partition.txt (the group ranks); an earlier run's outputs stay as they are\n"
        "  --partition FILE\n"
        "                 the group ranks from FILE (lines \"GROUP RANK\", the format of "
        "NAME_partition.txt)\n"
        "                 instead of METIS, to cut a rigid body or a tie on purpose: for a run on P ranks\n"
        "                 (mpirun -np P radx-engine-mpi) or with --decompose P, FILE gives every element\n"
        "                 group once and every rank 0 .. P-1 a group; a bad file is refused before anything\n"
        "                 is written (RX807, naming the file and line)\n";
  for (const auto& f : extra_flags) os << "  " << f.name << '\n' << f.help;
  os << "  --help, --version (or -version)\n"
        "\n"
        "SIGTERM or SIGINT stops the run after the cycle under way, with a last state, the summary (status\n"
        "\"interrupted\") and the listing's termination lines; a second one ends it at once, and so does\n"
        "the first if the cycle under way has not ended after max(10 s, 4 x the longest cycle so far).\n"
        "\n"
        "Exit code: 0 normal termination, 1 input error or error termination, 2 usage errors, 128 + the "
        "signal\n"
        "(143 SIGTERM, 130 SIGINT) when a signal stopped the run.\n";
}

}  // namespace

int engine_main(int argc, char** argv, const char* program_name, solver::parallel::Comm& comm,
                std::span<ExtraFlag> extra_flags) {
  const std::string program = program_name;
  NullStream null_out;
  NullStream null_err;
  // Rank 0 alone speaks; the other ranks reach the same exit code in silence.
  std::ostream& out = comm.rank() == 0 ? std::cout : null_out;
  std::ostream& err = comm.rank() == 0 ? std::cerr : null_err;
  EngineOptions opt;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--help" || a == "-h") {
      usage(out, program, extra_flags);
      return kExitOk;
    }
    // -version and -nt N are Radioss's own spellings (engine_linux64 -i DECK -nt N): scripts written for it
    // run unchanged.
    if (a == "--version" || a == "-version") {
      out << program << " " << version_text() << '\n';
      return kExitOk;
    }
    const bool takes_value = a == "-i" || a == "--out" || a == "--model" || a == "--threads" || a == "-nt" ||
                             a == "--decompose" || a == "--partition";
    if (takes_value && i + 1 >= argc) {
      err << program << ": " << a << " needs a value\n";
      return kExitUsage;
    }
    const auto extra =
        std::find_if(extra_flags.begin(), extra_flags.end(), [&](const ExtraFlag& f) { return f.name == a; });
    if (extra != extra_flags.end()) {
      extra->given = true;
    } else if (a == "-i") {
      opt.engine_deck = argv[++i];
    } else if (a == "--out") {
      opt.out_dir = argv[++i];
    } else if (a == "--model") {
      opt.model_file = argv[++i];
    } else if (a == "--threads" || a == "-nt") {
      try {
        opt.threads = std::stoi(argv[++i]);
      } catch (...) {
        opt.threads = -1;
      }
      if (opt.threads < 1) {
        err << program << ": " << a << " needs a positive integer\n";
        return kExitUsage;
      }
    } else if (a == "--decompose") {
      try {
        opt.decompose_ranks = std::stoi(argv[++i]);
      } catch (...) {
        opt.decompose_ranks = -1;
      }
      if (opt.decompose_ranks < 1) {
        err << program << ": --decompose needs a positive integer (the rank count)\n";
        return kExitUsage;
      }
    } else if (a == "--partition") {
      opt.partition_file = argv[++i];
    } else if (a == "--no-plot") {
      opt.plot = false;
    } else if (a == "--stop-if-runaway") {
      opt.stop_if_runaway = true;
    } else if (!a.empty() && a[0] == '-') {
      std::vector<std::string> known = {"-i",          "--out",     "--model",           "--threads",
                                        "-nt",         "--no-plot", "--stop-if-runaway", "--decompose",
                                        "--partition", "--version", "-version",          "--help"};
      for (const auto& f : extra_flags) known.push_back(f.name);
      err << unknown_option(program, a, known) << '\n';
      usage(err, program, extra_flags);
      return kExitUsage;
    } else if (opt.engine_deck.empty()) {
      opt.engine_deck = a;
    } else {
      err << program << ": one deck at a time\n";
      return kExitUsage;
    }
  }
  if (opt.engine_deck.empty()) {
    err << program << ": give the engine deck (NAME_0001.rad)\n";
    usage(err, program, extra_flags);
    return kExitUsage;
  }
  opt.comm = &comm;
  return run_engine(opt, out, err);
}

}  // namespace radx::app
