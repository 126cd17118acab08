// radx-engine: runs the explicit engine on NAME_0001.rad and the starter's model file NAME_0000.hdf.
#include <iostream>
#include <string>

#include "apps/build_info.hpp"
#include "apps/cli_common.hpp"
#include "apps/engine_pipeline.hpp"

namespace {

void usage(std::ostream& os) {
  os << "usage: radx-engine [NAME_0001.rad] [--out DIR] [--model FILE] [--threads N] [--no-plot]\n"
        "                   [--stop-if-runaway]\n"
        "       radx-engine -i NAME_0001.rad ...\n"
        "       radx-engine --decompose P [--partition FILE] NAME_0001.rad [--out DIR] [--model FILE]\n"
        "\n"
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
        "                 with --decompose: the group ranks from FILE (lines \"GROUP RANK\", the format of\n"
        "                 NAME_partition.txt) instead of METIS, to cut a rigid body or a tie on purpose\n"
        "  --help, --version (or -version)\n"
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

int main(int argc, char** argv) {
  radx::app::EngineOptions opt;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--help" || a == "-h") {
      usage(std::cout);
      return radx::app::kExitOk;
    }
    // -version and -nt N are Radioss's own spellings (engine_linux64 -i DECK -nt N): scripts written for it
    // run unchanged.
    if (a == "--version" || a == "-version") {
      std::cout << "radx-engine " << radx::app::version_text() << '\n';
      return radx::app::kExitOk;
    }
    const bool takes_value = a == "-i" || a == "--out" || a == "--model" || a == "--threads" || a == "-nt" ||
                             a == "--decompose" || a == "--partition";
    if (takes_value && i + 1 >= argc) {
      std::cerr << "radx-engine: " << a << " needs a value\n";
      return radx::app::kExitUsage;
    }
    if (a == "-i") {
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
        std::cerr << "radx-engine: " << a << " needs a positive integer\n";
        return radx::app::kExitUsage;
      }
    } else if (a == "--decompose") {
      try {
        opt.decompose_ranks = std::stoi(argv[++i]);
      } catch (...) {
        opt.decompose_ranks = -1;
      }
      if (opt.decompose_ranks < 1) {
        std::cerr << "radx-engine: --decompose needs a positive integer (the rank count)\n";
        return radx::app::kExitUsage;
      }
    } else if (a == "--partition") {
      opt.partition_file = argv[++i];
    } else if (a == "--no-plot") {
      opt.plot = false;
    } else if (a == "--stop-if-runaway") {
      opt.stop_if_runaway = true;
    } else if (!a.empty() && a[0] == '-') {
      std::cerr << radx::app::unknown_option(
                       "radx-engine", a,
                       {"-i", "--out", "--model", "--threads", "-nt", "--no-plot", "--stop-if-runaway",
                        "--decompose", "--partition", "--version", "-version", "--help"})
                << '\n';
      usage(std::cerr);
      return radx::app::kExitUsage;
    } else if (opt.engine_deck.empty()) {
      opt.engine_deck = a;
    } else {
      std::cerr << "radx-engine: one deck at a time\n";
      return radx::app::kExitUsage;
    }
  }
  if (opt.engine_deck.empty()) {
    std::cerr << "radx-engine: give the engine deck (NAME_0001.rad)\n";
    usage(std::cerr);
    return radx::app::kExitUsage;
  }
  if (!opt.partition_file.empty() && opt.decompose_ranks == 0) {
    std::cerr << "radx-engine: --partition goes with --decompose P\n";
    return radx::app::kExitUsage;
  }
  return radx::app::run_engine(opt, std::cout, std::cerr);
}
