// The functions of the MPI module (mpi_module.cpp, built as libgranbench_mpi.so) as mpi_session.cpp
// finds them: the module exports one C function, granbench_mpi_module(), which returns this table.
// Plain C types only, so that the program and the module share no C++ runtime state.
#pragma once

extern "C" {

struct granbench_mpi_api {
  void (*init)(int* rank, int* size);  // MPI_Init_thread (funneled), rank and size of the world
  void (*finalize)(int abort);         // MPI_Finalize; MPI_Abort first when abort != 0
  long (*broadcast_size)(long n);      // the root's n, on every rank
  void (*broadcast_values)(double* values, long n);  // the root's n values, on every rank
  void (*gather_sizes)(int n, int* counts);          // every rank's n, into counts on the root
  // every rank's values, concatenated in rank order (counts, offsets) into `all` on the root
  void (*gather_values)(const double* values, int n, double* all, const int* counts,
                        const int* offsets);
  void (*barrier)();
};

// The symbol mpi_session.cpp looks up in the module.
const granbench_mpi_api* granbench_mpi_module();
using granbench_mpi_module_fn = const granbench_mpi_api* (*)();
}
