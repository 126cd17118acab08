// radx: the driver. `radx check DECK` runs every starter check (and the engine deck's, when one is
// beside it or in the same one-file deck) without writing anything; `radx keywords` prints the
// keyword reference generated from the declarations.
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "apps/cli_common.hpp"
#include "apps/starter_pipeline.hpp"
#include "parser/deck_echo.hpp"

namespace {

void usage(std::ostream& os) {
  os << "usage: radx <command> [options]\n"
        "\n"
        "commands:\n"
        "  check DECK                  read and check a starter deck (and NAME_0001.rad beside it, or the\n"
        "                              engine part of a one-file deck); writes nothing\n"
        "  keywords [--markdown] [--output FILE]\n"
        "                              the keyword reference (every keyword, card, field and diagnostic "
        "code)\n"
        "  run, regress                not available yet: they come with the engine\n"
        "\n"
        "  --help, --version\n"
        "\n"
        "Exit code: 0 success, 1 input errors, 2 usage errors.\n";
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

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    usage(std::cerr);
    return radx::app::kExitUsage;
  }
  const std::string cmd = argv[1];
  const std::vector<std::string> args(argv + 2, argv + argc);
  if (cmd == "--help" || cmd == "-h" || cmd == "help") {
    usage(std::cout);
    return radx::app::kExitOk;
  }
  if (cmd == "--version") {
    std::cout << "radx " << RADX_VERSION << '\n';
    return radx::app::kExitOk;
  }
  if (cmd == "check") return check(args);
  if (cmd == "keywords") return keywords(args);
  if (cmd == "run" || cmd == "regress") {
    std::cerr << "radx " << cmd
              << ": not available in this version: the engine is not built yet; run radx-starter "
                 "to check a deck and write its model file\n";
    return radx::app::kExitUsage;
  }
  std::cerr << "radx: unknown command '" << cmd << "'\n";
  usage(std::cerr);
  return radx::app::kExitUsage;
}
