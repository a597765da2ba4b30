// MPI for the sweep's processes, through the MPI module loaded on demand; see mpi_session.hpp.
// Collectives move plain arrays of doubles: sizes first, then the values.
#include "analysis/cli/mpi_session.hpp"

#include <cstdlib>
#include <exception>
#include <stdexcept>
#include <string>

#ifdef GRANBENCH_MPI_MODULE
#include <dlfcn.h>

#include "analysis/cli/mpi_module.hpp"
#include "analysis/cli/shipped_files.hpp"
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

#ifdef GRANBENCH_MPI_MODULE

namespace {
// The module, loaded once per process and kept: MPI cannot be started again after MPI_Finalize,
// and unloading libmpi under its own exit handlers is not safe.
const granbench_mpi_api* load_mpi_module() {
  const std::string path = shipped_mpi_module();
  // RTLD_GLOBAL: OpenMPI loads its components as plugins that look up libmpi's symbols globally.
  void* module = dlopen(path.c_str(), RTLD_NOW | RTLD_GLOBAL);
  if (!module) {
    const char* why = dlerror();
    throw std::runtime_error("started by mpirun, but the MPI module " + path +
                             " could not be loaded: " + (why ? why : "unknown reason") +
                             " (build granbench again with libopenmpi-dev installed)");
  }
  auto entry = reinterpret_cast<granbench_mpi_module_fn>(dlsym(module, "granbench_mpi_module"));
  if (!entry) throw std::runtime_error("the MPI module " + path + " has no granbench_mpi_module");
  return entry();
}
}  // namespace

MpiSession::MpiSession() : exceptions_(std::uncaught_exceptions()) {
  if (!started_by_mpirun()) return;
  static const granbench_mpi_api* const module = load_mpi_module();
  module->init(&rank_, &size_);
  mpi_ = module;
}

MpiSession::~MpiSession() {
  if (mpi_) mpi_->finalize(std::uncaught_exceptions() > exceptions_ ? 1 : 0);
}

std::vector<double> MpiSession::broadcast(std::vector<double> values) const {
  if (!mpi_) return values;
  const long n = mpi_->broadcast_size(static_cast<long>(values.size()));
  values.resize(static_cast<std::size_t>(n));
  mpi_->broadcast_values(values.data(), n);
  return values;
}

std::vector<double> MpiSession::gather(const std::vector<double>& values) const {
  if (!mpi_) return values;
  const int n = static_cast<int>(values.size());
  std::vector<int> counts(root() ? size_ : 0), offsets(counts.size());
  mpi_->gather_sizes(n, counts.data());
  std::vector<double> all;
  if (root()) {
    for (int r = 1; r < size_; ++r) offsets[r] = offsets[r - 1] + counts[r - 1];
    all.resize(static_cast<std::size_t>(offsets.back() + counts.back()));
  }
  mpi_->gather_values(values.data(), n, all.data(), counts.data(), offsets.data());
  return all;
}

void MpiSession::barrier() const {
  if (mpi_) mpi_->barrier();
}

#else  // built without MPI: one process

MpiSession::MpiSession() : exceptions_(std::uncaught_exceptions()) {
  (void)mpi_;
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
