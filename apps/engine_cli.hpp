// The command line of the engine executables: radx-engine (one rank, a SerialComm) and radx-engine-mpi (the
// same options on every MPI rank). Only rank 0 prints: the other ranks parse the same arguments to the same
// exit code, with their standard output and error going nowhere.
#pragma once

#include <span>
#include <string>

namespace radx::solver::parallel {
class Comm;
}

namespace radx::app {

// An option without value that one executable adds to the engine's (radx-engine-mpi's --comm-stats): named
// in the usage text with its help, and `given` set when the command line has it.
struct ExtraFlag {
  std::string name;
  std::string help;  // lines of the usage text, each indented by the caller
  bool given = false;
};

// Parses the options, runs the engine on `comm` and returns the exit code (apps/engine_pipeline.hpp).
// `program` names the executable in the usage text and in the messages of the command line.
int engine_main(int argc, char** argv, const char* program, solver::parallel::Comm& comm,
                std::span<ExtraFlag> extra_flags = {});

}  // namespace radx::app
