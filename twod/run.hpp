// A run of the 2D solver (run.cpp): advance a Solver to t_end, sampling the surface h(x, t) and
// the depth-averaged velocity into a SurfaceSeries, the 2D counterpart of depthavg::Solver::run.
//
// Schedule. Samples are taken at t = min(k dt_out, t_end), k = 1, 2, ..., on the uniform grid
// counted from t = 0, whatever time the solver starts at: a run restarted from a checkpoint at
// time t_c continues with the first k dt_out after t_c, so its series is the uninterrupted run's
// (the measurement needs that uniform grid, analysis/spectral/surface_measurement.hpp). Snapshots,
// when asked for, are taken at the start and at j dt_snapshot on the same kind of grid. The start
// counts only for a new run (an empty series): a restart adds neither sample nor snapshot there.
// The solver is advanced with Solver::advance_to to each next event time, so the step sequence
// depends only on the event times: a run with the same events repeats another to the bit (the
// solver halves the last two steps before an event instead of taking a sliver, so every event
// time counts).
//
// A run that stops early (interrupted, diverged, failed) ends with a snapshot of its last state.
// When the run completes and t_end is not on the snapshot grid, a last snapshot is taken at
// t_end, so that the output always ends with the final state.
//
// Checkpoints. With dt_checkpoint > 0 the checkpoint hook is called at the first sample at or
// after each j dt_checkpoint (again on the grid from t = 0), after that sample's snapshot. They
// are not events of the schedule: a run gives the same steps with or without them, and a run
// restarted from any of them repeats the uninterrupted one.
//
// Control. The stop flag (Ctrl-C) is read after each sample: a raised flag ends the run there,
// with the series so far, and the checkpoint hook is called. A DivergenceError ends the run with
// its time, place and quantity; any other std::exception from the time loop (a linear solve that
// does not converge, a full disk in a hook) ends it as Failed with the time, the step and the
// exception's message (which names the part of the step that failed). In every case the samples
// taken so far are returned. A checkpoint that cannot be written at a stop does not lose the run:
// the status stays Interrupted and the message says why there is no checkpoint.
#pragma once

#include <atomic>
#include <functional>
#include <optional>
#include <string>

#include "common/run_status.hpp"
#include "common/surface_series.hpp"
#include "twod/diagnostics.hpp"
#include "twod/solver.hpp"

namespace granbench::twod {

struct RunSchedule {
  double t_end = 1.0;          // [s]
  double dt_out = 0.01;        // samples at k dt_out [s]
  double dt_snapshot = 0.0;    // snapshots at j dt_snapshot [s]; 0: only the one at the start
  double dt_checkpoint = 0.0;  // checkpoint hook every dt_checkpoint [s] of simulated time; 0: none
};

// What the caller does at the run's events; every hook may be empty.
struct RunHooks {
  // After each sample (the start's included): progress, the caller's own per-sample records.
  std::function<void(const Solver&, const SurfaceSeries&)> sample;
  // At the start and at each snapshot time (2D fields to a file). Empty: no snapshot times
  // enter the schedule.
  std::function<void(const Solver&)> snapshot;
  // When the run stops at the stop flag, and on the dt_checkpoint schedule: the state and series
  // to continue from.
  std::function<void(const Solver&, const SurfaceSeries&)> checkpoint;
  const std::atomic<bool>* stop = nullptr;  // read after each sample
};

using granbench::RunStatus;  // common/run_status.hpp

struct RunResult {
  RunStatus status = RunStatus::Completed;
  std::string message;                        // why it stopped early; empty if completed
  std::optional<DivergenceError> divergence;  // when, where: set if Diverged
  SurfaceSeries series;
  // Rheology over the samples taken after the start (docs/design.md §9): the range of I visited,
  // the ill-posed fraction at the last such sample and its largest value.
  double I_min = 0.0, I_max = 0.0;  // NaN if no sample had a granular cell with p > 0
  RheologyStats last;
  double illposed_fraction_max = 0.0;
  double wall_seconds = 0.0;
  bool completed() const { return status == RunStatus::Completed; }
};

// The speed above which a run of a base flow with surface speed u_surface is reported as
// diverging (SolverParams::velocity_limit): ten times the surface speed, never below the former
// fixed 50 m/s. A fixed limit called valid steep flows (60 degrees: 47.7 m/s at the surface)
// diverged at their first step, while slow flows keep the limit they had.
double divergence_speed_limit(double u_surface);

// Runs `solver` from its current time to schedule.t_end. `series` holds the samples so far (a
// restart's); when it is empty the current state is sampled first.
RunResult run(Solver& solver, SurfaceSeries series, const RunSchedule& schedule,
              const RunHooks& hooks = {});

}  // namespace granbench::twod
