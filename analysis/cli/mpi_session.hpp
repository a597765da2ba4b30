// The processes of one `granbench sweep` started by mpirun. The MPI calls are in a module of their
// own (mpi_module.cpp, libgranbench_mpi.so, built when CMake found MPI; its path is
// GRANBENCH_MPI_MODULE), which the session loads only when mpirun started the process; otherwise
// the session is one process, rank 0 of 1, and the collectives return their input. Only the main
// thread calls MPI (MPI_THREAD_FUNNELED): the sweep's worker threads never do.
//
//   mpirun -np 4 granbench sweep --model depthavg --Lx 0.02:0.4:32 --jobs 1 --out sweep.h5
#pragma once

#include <vector>

struct granbench_mpi_api;  // the MPI module's functions (mpi_module.hpp)

namespace granbench::cli {

class MpiSession {
 public:
  // When started by mpirun: loads the MPI module (std::runtime_error naming it when it cannot)
  // and starts MPI.
  MpiSession();
  ~MpiSession();  // MPI_Finalize; MPI_Abort instead when left by an exception, since the other
                  // ranks may be waiting in a collective call that this one will never make
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool root() const { return rank_ == 0; }

  // The root's values, on every rank.
  std::vector<double> broadcast(std::vector<double> values) const;
  // Every rank's values, concatenated in rank order, on the root; empty on the other ranks.
  std::vector<double> gather(const std::vector<double>& values) const;
  void barrier() const;

 private:
  int rank_ = 0, size_ = 1;
  const granbench_mpi_api* mpi_ = nullptr;  // the module's functions; null: one process
  int exceptions_ = 0;                      // in flight when constructed
};

}  // namespace granbench::cli
