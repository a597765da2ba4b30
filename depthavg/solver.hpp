// The depth-averaged solver: integrates (7.3)-(7.4) (rhs.hpp) with CVODE (cvode_integrator.hpp)
// from an initial state to t_end, sampling h(x, t) and u(x, t) into a SurfaceSeries every dt_out.
// It reports progress, stops early and keeps what it computed when the stop flag is raised
// (Ctrl-C), and stops cleanly when the solution diverges, saying when, where and in which
// quantity. With SpaceParams::frame_speed c the equations are solved in the frame moving at c
// (rhs.hpp) and each sample is translated back to the lab frame by c t (Fourier shift).
#pragma once

#include <atomic>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "common/run_status.hpp"
#include "common/surface_series.hpp"
#include "depthavg/cvode_integrator.hpp"
#include "depthavg/params.hpp"
#include "depthavg/rhs.hpp"

namespace granbench::depthavg {

using granbench::RunStatus;  // common/run_status.hpp

struct RunResult {
  SurfaceSeries series;
  CvodeStats stats;
  RunStatus status = RunStatus::Completed;
  std::string message;  // what went wrong (time, place, quantity), empty if completed
  double wall_seconds = 0.0;
  double t_reached = 0.0;
  double mass_initial = 0.0;  // integral of h over the domain [m^2]
  double mass_final = 0.0;
  double flux_final = 0.0;          // domain mean of q = h u at the last sample [m^2/s]
  std::vector<double> final_state;  // U at t_reached, in the computational (possibly co-moving)
                                    // frame; the series is always in the lab frame
  double mass_error() const { return std::fabs(mass_final - mass_initial) / mass_initial; }
};

struct RunCallbacks {
  std::function<void(double t, double t_end)> progress;  // after each sample, may be empty
  const std::atomic<bool>* stop = nullptr;  // checked after each sample and each chunk of steps
};

class Solver {
 public:
  Solver(const SteadyState& base, const MuCurve& curve, const SpaceParams& space,
         const IntegratorParams& integrator);
  const Rhs& rhs() const { return rhs_; }
  RunResult run(const std::vector<double>& U0, const OutputParams& out,
                const RunCallbacks& callbacks = {}) const;

 private:
  Rhs rhs_;
  IntegratorParams integrator_;
};

}  // namespace granbench::depthavg
