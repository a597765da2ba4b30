// The MPI calls of a sweep started by mpirun, built as a module of its own (libgranbench_mpi.so)
// that mpi_session.cpp loads only in a process that mpirun started. Linked into the program,
// OpenMPI's libraries (libmpi, libopen-rte, libopen-pal, hwloc, libevent, udev) were mapped and
// relocated at the start of every command: 4.4 ms of each process on this machine, 2 % of the
// Gerris-sized 2D run (docs/performance.md, forty-fifth session), for the one use that needs them.
//
// The interface is the table of plain C functions of mpi_module.hpp, so that neither side's C++
// runtime crosses the boundary; the collectives move arrays of doubles with their sizes first.
#include "analysis/cli/mpi_module.hpp"

#define OMPI_SKIP_MPICXX 1  // the C API only
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>

namespace {

void init(int* rank, int* size) {
  int provided = 0;
  // Only the main thread calls MPI: the sweep's worker threads never do.
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  MPI_Comm_rank(MPI_COMM_WORLD, rank);
  MPI_Comm_size(MPI_COMM_WORLD, size);
}

void finalize(int abort) {
  // Abort when the session ends by an exception: the other ranks may be waiting in a collective
  // call that this one will never make.
  if (abort) MPI_Abort(MPI_COMM_WORLD, 1);
  MPI_Finalize();
}

long broadcast_size(long n) {
  MPI_Bcast(&n, 1, MPI_LONG, 0, MPI_COMM_WORLD);
  return n;
}

void broadcast_values(double* values, long n) {
  MPI_Bcast(values, static_cast<int>(n), MPI_DOUBLE, 0, MPI_COMM_WORLD);
}

void gather_sizes(int n, int* counts) {
  MPI_Gather(&n, 1, MPI_INT, counts, 1, MPI_INT, 0, MPI_COMM_WORLD);
}

void gather_values(const double* values, int n, double* all, const int* counts,
                   const int* offsets) {
  MPI_Gatherv(values, n, MPI_DOUBLE, all, counts, offsets, MPI_DOUBLE, 0, MPI_COMM_WORLD);
}

void barrier() {
  MPI_Barrier(MPI_COMM_WORLD);
}

}  // namespace

extern "C" const granbench_mpi_api* granbench_mpi_module() {
  static const granbench_mpi_api api = {
      init, finalize, broadcast_size, broadcast_values, gather_sizes, gather_values, barrier};
  return &api;
}
