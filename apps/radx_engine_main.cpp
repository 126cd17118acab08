// radx-engine: runs the explicit engine on NAME_0001.rad and the starter's model file NAME_0000.hdf, on one
// rank (radx-engine-mpi is the same engine over MPI).
#include "apps/engine_cli.hpp"
#include "solver/parallel/serial_comm.hpp"

int main(int argc, char** argv) {
  radx::solver::parallel::SerialComm comm;
  return radx::app::engine_main(argc, argv, "radx-engine", comm);
}
