// The files of one 2D run (run_output.cpp): the HDF5 output with its snapshots and XDMF index,
// and the checkpoints. Attached to twod::run as its snapshot and checkpoint hooks.
//
// Durability. At each checkpoint the output so far is written under its final name first
// (status "running"), then the checkpoint; both are written to a temporary name and renamed
// into place. A process killed at any moment (SIGKILL, the OOM killer) therefore leaves
// a complete output and a checkpoint of the same time, or of an earlier one. A restart from the
// checkpoint into the same output takes over the snapshots written before it (their times are
// in the checkpoint), so that the restarted run's file is the uninterrupted run's.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "common/hdf5_file.hpp"
#include "twod/output.hpp"
#include "twod/run.hpp"

namespace granbench::twod {

struct RunFiles {
  std::string out;         // HDF5 output, with <out minus extension>.xdmf beside it; empty: none
  std::string checkpoint;  // checkpoint file, written on the schedule and at a stop
  // The snapshots of the part of this run before a restart (Checkpoint::snapshot_times): taken
  // over from `out` when that file exists.
  std::vector<double> earlier_snapshots;
};

class RunOutput {
 public:
  // The caller's own root attributes, added at every write of the output (inputs, model name).
  using Attributes = std::function<void(H5Writer&)>;
  // Opens the output (when there is one). Throws std::runtime_error when `out` exists but does
  // not hold the earlier snapshots, so that a restart into another run's file fails before the run.
  RunOutput(RunFiles files, const Grid& grid, const SolverParams& params, Attributes attributes);
  ~RunOutput();
  RunOutput(const RunOutput&) = delete;
  RunOutput& operator=(const RunOutput&) = delete;

  // Sets hooks.snapshot and hooks.checkpoint (other hooks are left as they are).
  void attach(RunHooks& hooks);
  // The final write of the output: the series, the parameters, status, message and the caller's
  // results (JSON text, stored as the root attribute results_json).
  void finish(const SurfaceSeries& series, const std::string& status, const std::string& message,
              const std::string& results_json);
  const std::string& checkpoint_path() const { return files_.checkpoint; }
  int checkpoints_written() const { return checkpoints_; }

 private:
  void open(const std::vector<double>& carried);
  void write(const SurfaceSeries& series, const std::string& status, const std::string& message,
             const std::string& results_json);

  RunFiles files_;
  Grid grid_;
  SolverParams params_;
  Attributes attributes_;
  std::unique_ptr<H5Writer> h5_;
  std::unique_ptr<SnapshotWriter> snaps_;
  std::vector<double> times_;  // every snapshot of the run, the carried-over ones included
  int checkpoints_ = 0;
};

}  // namespace granbench::twod
