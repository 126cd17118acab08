// radx-engine-mpi: the engine of radx-engine, with the same options and outputs, on the ranks of
// `mpirun -np P` (docs/parallel.md). Rank 0 alone prints and writes files. The only executable that links
// MPI: radx-engine, radx-starter and radx stay free of it.
#include "apps/engine_cli.hpp"
#include "apps/mpi/mpi_comm.hpp"

int main(int argc, char** argv) {
  radx::app::MpiComm comm(&argc, &argv);
  return radx::app::engine_main(argc, argv, "radx-engine-mpi", comm);
}
