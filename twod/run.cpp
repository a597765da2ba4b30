// A run of the 2D solver: the sampling schedule, the hooks and the stopping rules of run.hpp.
#include "twod/run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "twod/frame.hpp"

namespace granbench::twod {

namespace {

// The first k >= 1 with k dt after t (a time within 1e-9 dt of a grid point counts as on it, so
// a restart at a sample time does not take that sample again, nor a sliver step towards it).
long first_after(double t, double dt) {
  return static_cast<long>(std::floor(t / dt + 1e-9)) + 1;
}

// Reached `target` up to the rounding of the last step, which ends on it.
bool reached(double t, double target) {
  return t >= target * (1.0 - 1e-12);
}

}  // namespace

double divergence_speed_limit(double u_surface) {
  return std::max(50.0, 10.0 * u_surface);
}

RunResult run(Solver& solver, SurfaceSeries series, const RunSchedule& schedule,
              const RunHooks& hooks) {
  if (!(schedule.t_end > 0.0) || !(schedule.dt_out > 0.0) || !(schedule.dt_snapshot >= 0.0) ||
      !(schedule.dt_checkpoint >= 0.0))
    throw std::invalid_argument(
        "twod::run: t_end and dt_out must be positive, dt_snapshot and dt_checkpoint >= 0");
  const auto wall_start = std::chrono::steady_clock::now();
  const Grid& g = solver.grid();
  const MuCurve& curve = solver.viscosity_model().curve();

  RunResult r;
  r.series = std::move(series);
  double I_lo = std::numeric_limits<double>::infinity(), I_hi = 0.0;
  auto take_sample = [&] {
    const Fields& s = solver.state();
    // the series is in the lab frame (frame.hpp), whatever frame the solver runs in
    r.series.append(s.t, columns_in_lab_frame(g, s.t, surface_heights(g, s.f)),
                    columns_in_lab_frame(g, s.t, depth_averaged_velocity(g, s)));
    if (hooks.sample) hooks.sample(solver, r.series);
  };

  const double t_end = schedule.t_end, dt_out = schedule.dt_out, dt_snap = schedule.dt_snapshot;
  // Samples k = 1 .. n_samples at min(k dt_out, t_end): the last one lands on t_end (as in
  // depthavg::Solver::run) also when dt_out does not divide it.
  const auto n_samples = static_cast<long>(std::ceil(t_end / dt_out - 1e-9));
  // Snapshots only on their grid, none past t_end.
  const bool snapshots = hooks.snapshot && dt_snap > 0.0;
  const long n_snaps = snapshots ? static_cast<long>(std::floor(t_end / dt_snap + 1e-9)) : 0;
  long k = first_after(solver.state().t, dt_out);
  long j = snapshots ? first_after(solver.state().t, dt_snap) : 1;
  const double dt_ckpt = hooks.checkpoint ? schedule.dt_checkpoint : 0.0;
  long c = dt_ckpt > 0.0 ? first_after(solver.state().t, dt_ckpt) : 0;
  double last_snapshot = -1.0;
  const auto snapshot = [&] {
    hooks.snapshot(solver);
    last_snapshot = solver.state().t;
  };
  double t_good = solver.state().t;  // the last sample taken, for a failure's message

  try {
    // The start is a snapshot and a sample of a new run only: a restart's start was the
    // interrupted run's checkpoint time, already in its records when it was on their grids.
    if (r.series.nt() == 0) {
      if (hooks.snapshot) snapshot();
      take_sample();
    }
    for (; k <= n_samples; ++k) {
      if (hooks.stop && hooks.stop->load()) {
        r.status = RunStatus::Interrupted;
        r.message = "interrupted at t = " + std::to_string(solver.state().t) + " s";
        break;
      }
      const double t_sample = std::min(static_cast<double>(k) * dt_out, t_end);
      // snapshots before this sample; one at the sample's time follows the sample
      for (; j <= n_snaps && !reached(static_cast<double>(j) * dt_snap, t_sample); ++j) {
        solver.advance_to(static_cast<double>(j) * dt_snap);
        snapshot();
      }
      solver.advance_to(t_sample);
      take_sample();
      t_good = solver.state().t;
      const RheologyStats rs = rheology_stats(g, solver.state().f, solver.properties().I_c, curve);
      if (std::isfinite(rs.I_min)) I_lo = std::min(I_lo, rs.I_min), I_hi = std::max(I_hi, rs.I_max);
      r.illposed_fraction_max = std::max(r.illposed_fraction_max, rs.illposed_fraction);
      r.last = rs;
      if (j <= n_snaps && reached(solver.state().t, static_cast<double>(j) * dt_snap)) {
        snapshot();
        ++j;
      }
      // After the snapshot at this time, so that a restart from here (which takes the next
      // snapshot after its start) misses none; none at t_end, where the run is complete.
      if (c > 0 && k < n_samples && reached(solver.state().t, static_cast<double>(c) * dt_ckpt)) {
        hooks.checkpoint(solver, r.series);
        c = first_after(solver.state().t, dt_ckpt);
      }
    }
    // The output always ends with the final state, also when t_end is off the snapshot grid.
    if (hooks.snapshot && r.status == RunStatus::Completed && !reached(last_snapshot, t_end))
      snapshot();
  } catch (const DivergenceError& e) {
    r.status = RunStatus::Diverged;
    r.message = e.what();
    r.divergence = e;
  } catch (const std::exception& e) {
    // a failed linear solve, a full disk: keep what was computed, say when and where
    r.status = RunStatus::Failed;
    r.message = "failed at t = " + std::to_string(solver.state().t) + " s (step " +
                std::to_string(solver.statistics().steps + 1) +
                ", after the sample at t = " + std::to_string(t_good) + " s): " + e.what();
  }
  if (r.status == RunStatus::Interrupted && hooks.checkpoint) {
    try {
      hooks.checkpoint(solver, r.series);
    } catch (const std::exception& e) {
      // The samples are still in memory: the caller writes them whatever happened here.
      r.message += "; no checkpoint: " + std::string(e.what());
    }
  }
  // The output always ends with the last state: at an interruption after its checkpoint (whose
  // snapshot list is what a restart carries over, so a restarted output still matches an
  // uninterrupted one), and at a divergence or failure for the diagnosis (the fields may hold the
  // non-finite values that stopped it).
  if (hooks.snapshot && r.status != RunStatus::Completed &&
      !reached(last_snapshot, solver.state().t)) {
    try {
      snapshot();
    } catch (const std::exception& e) {
      r.message += "; no snapshot of the last state: " + std::string(e.what());
    }
  }

  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  r.I_min = std::isfinite(I_lo) ? I_lo : nan;
  r.I_max = std::isfinite(I_lo) ? I_hi : nan;
  r.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  return r;
}

}  // namespace granbench::twod
