// RunOutput (run_output.hpp): the output is rewritten whole at each checkpoint; the snapshots
// come across by HDF5 object copy from the file written at the previous checkpoint, so the
// solver state is needed only once per snapshot.
#include "twod/run_output.hpp"

#include <filesystem>

#include "common/companion_path.hpp"
#include "twod/checkpoint.hpp"

namespace granbench::twod {

namespace {

std::string xdmf_path(const std::string& out) {
  return companion_path(out, ".xdmf");
}

}  // namespace

RunOutput::RunOutput(RunFiles files, const Grid& grid, const SolverParams& params,
                     Attributes attributes)
    : files_(std::move(files)), grid_(grid), params_(params), attributes_(std::move(attributes)) {
  if (files_.out.empty()) return;
  // A restart into another file (or a first run) starts its own snapshot list.
  open(std::filesystem::exists(files_.out) ? files_.earlier_snapshots : std::vector<double>{});
}

RunOutput::~RunOutput() = default;

void RunOutput::open(const std::vector<double>& carried) {
  snaps_.reset();
  h5_ = std::make_unique<H5Writer>(files_.out);
  snaps_ = std::make_unique<SnapshotWriter>(
      *h5_, std::filesystem::path(files_.out).filename().string(), xdmf_path(files_.out), grid_);
  snaps_->carry_over(files_.out, carried);
  times_ = carried;
}

void RunOutput::attach(RunHooks& hooks) {
  // Set also without an output: the snapshot times are events of the step sequence, and a run
  // must not change with whether its fields are written.
  hooks.snapshot = [this](const Solver& s) {
    if (snaps_) snaps_->write(s);
    times_.push_back(s.state().t);
  };
  hooks.checkpoint = [this](const Solver& s, const SurfaceSeries& series) {
    if (h5_) {
      // The output first: a checkpoint never refers to snapshots that no file holds.
      write(series, "running", "checkpoint at t = " + std::to_string(s.state().t) + " s", "");
      open(times_);
    }
    write_checkpoint(files_.checkpoint, s, series, times_);
    ++checkpoints_;
  };
}

void RunOutput::finish(const SurfaceSeries& series, const std::string& status,
                       const std::string& message, const std::string& results_json) {
  if (files_.out.empty()) return;
  if (!h5_) open(times_);  // a failed write at a checkpoint closed it
  write(series, status, message, results_json);
}

void RunOutput::write(const SurfaceSeries& series, const std::string& status,
                      const std::string& message, const std::string& results_json) {
  H5Writer& h5 = *h5_;
  write_surface_series(h5, "/surface", series);
  write_parameters(h5, "/parameters", grid_, params_);
  h5.attribute("/", "model", "twod");
  h5.attribute("/", "status", status);
  h5.attribute("/", "message", message);
  if (!results_json.empty()) h5.attribute("/", "results_json", results_json);
  if (attributes_) attributes_(h5);
  snaps_->finish();
  snaps_.reset();
  std::unique_ptr<H5Writer> done = std::move(h5_);
  done->close();
}

}  // namespace granbench::twod
