// MPI for the sweep's processes; see mpi_session.hpp. Collectives move plain arrays of doubles:
// sizes first (MPI_Bcast, MPI_Gather), then the values (MPI_Bcast, MPI_Gatherv).
#include "analysis/cli/mpi_session.hpp"

#include <cstdlib>
#include <exception>
#include <stdexcept>

#ifdef GRANBENCH_HAVE_MPI
#define OMPI_SKIP_MPICXX 1  // the C API only
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>
#endif

namespace granbench::cli {

namespace {
// mpirun (OpenMPI, or a PMI/PMIx launcher such as MPICH's) tells its processes so in their
// environment; a command started otherwise stays a single process and does not start MPI.
bool started_by_mpirun() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE"})
    if (std::getenv(v)) return true;
  return false;
}
}  // namespace

#ifdef GRANBENCH_HAVE_MPI

MpiSession::MpiSession() : exceptions_(std::uncaught_exceptions()) {
  if (!started_by_mpirun()) return;
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  active_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiSession::~MpiSession() {
  if (!active_) return;
  if (std::uncaught_exceptions() > exceptions_) MPI_Abort(MPI_COMM_WORLD, 1);
  MPI_Finalize();
}

std::vector<double> MpiSession::broadcast(std::vector<double> values) const {
  if (!active_) return values;
  long n = static_cast<long>(values.size());
  MPI_Bcast(&n, 1, MPI_LONG, 0, MPI_COMM_WORLD);
  values.resize(static_cast<std::size_t>(n));
  MPI_Bcast(values.data(), static_cast<int>(n), MPI_DOUBLE, 0, MPI_COMM_WORLD);
  return values;
}

std::vector<double> MpiSession::gather(const std::vector<double>& values) const {
  if (!active_) return values;
  int n = static_cast<int>(values.size());
  std::vector<int> counts(root() ? size_ : 0), offsets(counts.size());
  MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::vector<double> all;
  if (root()) {
    for (int r = 1; r < size_; ++r) offsets[r] = offsets[r - 1] + counts[r - 1];
    all.resize(static_cast<std::size_t>(offsets.back() + counts.back()));
  }
  MPI_Gatherv(values.data(), n, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE,
              0, MPI_COMM_WORLD);
  return all;
}

void MpiSession::barrier() const {
  if (active_) MPI_Barrier(MPI_COMM_WORLD);
}

#else  // built without MPI: one process

MpiSession::MpiSession() : exceptions_(std::uncaught_exceptions()) {
  (void)active_;
  (void)exceptions_;
  // Every process would run every point and write the same file.
  if (started_by_mpirun())
    throw std::runtime_error(
        "started by mpirun, but this granbench was built without MPI (install libopenmpi-dev, "
        "then configure and build again)");
}
MpiSession::~MpiSession() = default;
std::vector<double> MpiSession::broadcast(std::vector<double> values) const {
  return values;
}
std::vector<double> MpiSession::gather(const std::vector<double>& values) const {
  return values;
}
void MpiSession::barrier() const {}

#endif

}  // namespace granbench::cli
