// The command line of the engine executables: radx-engine (one rank, a SerialComm) and radx-engine-mpi (the
// same options on every MPI rank). Only rank 0 prints: the other ranks parse the same arguments to the same
// exit code, with their standard output and error going nowhere.
#pragma once

namespace radx::solver::parallel {
class Comm;
}

namespace radx::app {

// Parses the options, runs the engine on `comm` and returns the exit code (apps/engine_pipeline.hpp).
// `program` names the executable in the usage text and in the messages of the command line.
int engine_main(int argc, char** argv, const char* program, solver::parallel::Comm& comm);

}  // namespace radx::app
