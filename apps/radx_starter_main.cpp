// radx-starter: reads a starter deck, checks it, and writes the listing NAME_0000.out and the model
// file NAME_0000.hdf for the engine.
#include <iostream>
#include <string>

#include "apps/build_info.hpp"
#include "apps/cli_common.hpp"
#include "apps/starter_pipeline.hpp"

namespace {

void usage(std::ostream& os) {
  os << "usage: radx-starter [NAME_0000.rad] [--out DIR] [--allow-substitutions]\n"
        "       radx-starter -i NAME_0000.rad [--out DIR]\n"
        "\n"
        "Reads a Radioss-format starter deck (or a one-file deck), checks it, and writes\n"
        "NAME_0000.out (listing) and NAME_0000.hdf (model file for radx-engine; it also opens in\n"
        "ParaView as the undeformed model) in the current folder or in DIR.\n"
        "Without a deck, runs the embedded default deck (block on plate), written to DIR first.\n"
        "\n"
        "  -i DECK       the starter deck (as Radioss users type it)\n"
        "  -nt N, -np N  Radioss's thread and domain counts: accepted and without effect (the starter runs "
        "on\n"
        "                one thread and writes the same model file for any count)\n"
        "  --out DIR     output folder (default: the current folder)\n"
        "  --allow-substitutions\n"
        "                where the deck asks for a formulation or option radx does not implement, run\n"
        "                the nearest one radx implements instead of refusing the deck; every substitution\n"
        "                is listed (listing, model file, and the engine's NAME_summary.json)\n"
        "  --help        this text\n"
        "  --version     the version\n"
        "\n"
        "Exit code: 0 success, 1 input errors (listed on stderr as file:line:col: error: ...), 2 usage "
        "errors.\n";
}

}  // namespace

int main(int argc, char** argv) {
  radx::app::StarterOptions opt;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--help" || a == "-h") {
      usage(std::cout);
      return radx::app::kExitOk;
    }
    if (a == "--version" || a == "-version") {
      std::cout << "radx-starter " << radx::app::version_text() << '\n';
      return radx::app::kExitOk;
    }
    if ((a == "-i" || a == "--out" || a == "-nt" || a == "-np") && i + 1 >= argc) {
      std::cerr << "radx-starter: " << a << " needs a value\n";
      usage(std::cerr);
      return radx::app::kExitUsage;
    }
    if (a == "-i") {
      opt.deck = argv[++i];
    } else if (a == "--out") {
      opt.out_dir = argv[++i];
    } else if (a == "--allow-substitutions") {
      opt.allow_substitutions = true;
    } else if (a == "-nt") {
      // Radioss's starter thread count (starter_linux64 -i DECK -np 1 -nt 1): the starter runs on one thread.
      ++i;
    } else if (a == "-np") {
      // Radioss's domain count: radx writes one model file for every process count.
      ++i;
    } else if (!a.empty() && a[0] == '-') {
      std::cerr << radx::app::unknown_option("radx-starter", a,
                                             {"-i", "--out", "--allow-substitutions", "-nt", "-np",
                                              "--version", "-version", "--help"})
                << '\n';
      usage(std::cerr);
      return radx::app::kExitUsage;
    } else if (opt.deck.empty()) {
      opt.deck = a;
    } else {
      std::cerr << "radx-starter: one deck at a time (got " << opt.deck << " and " << a << ")\n";
      return radx::app::kExitUsage;
    }
  }
  if (opt.deck.empty()) {
    opt.deck = radx::app::write_default_starter_deck(opt.out_dir);
    radx::app::write_default_engine_deck(opt.out_dir);
    std::cout << "radx-starter: no deck given, running the embedded default deck " << opt.deck << '\n';
  }
  return radx::app::run_starter(opt, std::cout, std::cerr).exit_code;
}
