// radx-engine-mpi: the engine of radx-engine, with the same options and outputs, on the ranks of
// `mpirun -np P` (docs/parallel.md). Rank 0 alone prints and writes files. The only executable that links
// MPI: radx-engine, radx-starter and radx stay free of it.
//
// Its own option, --comm-stats: at the end, rank 0 prints every rank's communication per collective kind and
// its wall time from MPI's start to the engine's end (apps/mpi/comm_stats.hpp), for bench/mpi_scaling.sh.
#include <chrono>
#include <iostream>

#include "apps/engine_cli.hpp"
#include "apps/mpi/comm_stats.hpp"
#include "apps/mpi/mpi_comm.hpp"

int main(int argc, char** argv) {
  const auto start = std::chrono::steady_clock::now();
  radx::app::MpiComm comm(&argc, &argv);
  radx::app::ExtraFlag comm_stats[] = {
      {"--comm-stats",
       "                 at the end, print each rank's MPI communication per collective kind (calls,\n"
       "                 messages, bytes sent and received, seconds inside MPI) and its wall time\n",
       false}};
  const int code = radx::app::engine_main(argc, argv, "radx-engine-mpi", comm, comm_stats);
  if (comm_stats[0].given) {
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const auto all = comm.gather_stats(wall);
    if (comm.rank() == 0) radx::app::print_comm_stats(std::cout, all);
  }
  return code;
}
