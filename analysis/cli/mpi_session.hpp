// The processes of one `granbench sweep` started by mpirun: this is the only file that knows MPI.
// Built with MPI when CMake found it (GRANBENCH_HAVE_MPI); without it, or when the command was not
// started by mpirun, the session is one process, rank 0 of 1, and the collectives return their
// input. Only the main thread calls MPI (MPI_THREAD_FUNNELED): the sweep's worker threads never do.
//
//   mpirun -np 4 granbench sweep --model depthavg --Lx 0.02:0.4:32 --jobs 1 --out sweep.h5
#pragma once

#include <vector>

namespace granbench::cli {

class MpiSession {
 public:
  MpiSession();   // MPI_Init_thread when started by mpirun
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
  bool active_ = false;
  int exceptions_ = 0;  // in flight when constructed
};

}  // namespace granbench::cli
