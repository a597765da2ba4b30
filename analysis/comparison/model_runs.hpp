// Running either model on a ChuteCase and returning the same record: the SurfaceSeries h(x, t)
// and the run statistics that `granbench run --json` reports for both models (steps,
// wall_seconds, mass_error, flux, and for the 2D model the range of I and the ill-posed fraction).
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <tuple>
#include <utility>

#include "analysis/comparison/chute_case.hpp"
#include "analysis/comparison/twod_settings.hpp"
#include "common/run_status.hpp"
#include "common/surface_series.hpp"
#include "depthavg/params.hpp"
#include "twod/grid.hpp"
#include "twod/parameters.hpp"

namespace granbench {

using RunOutcome = RunStatus;  // common/run_status.hpp

struct ModelRun {
  std::string model;  // "depthavg" or "twod"
  SurfaceSeries series;
  RunOutcome outcome = RunOutcome::Completed;
  std::string message;  // what stopped it early (time, place, quantity)
  long steps = 0;
  double wall_seconds = 0.0;
  double mass_error = 0.0;          // relative
  double flux = 0.0;                // mean downslope flux per unit width at the end [m^2/s]
  double I_min = 0.0, I_max = 0.0;  // 2D only: over granular cells at the end
  double illposed_fraction = 0.0;   // 2D only
  double seeded_growth_rate = 0.0;  // the theory's growth rate of the seeded mode, if seeded
  double dt_out = 0.0;              // sampling interval of the series [s]
  std::string run_command;  // `granbench run ...` that reproduces this run (run_command.hpp)
  int nx = 0, nz = 0;       // the grid's cells (nz: 2D only), which compare and sweep choose
};

struct DepthAvgSettings {
  std::size_t nx = 256;
  double chi = 1.0;  // shape factor of the momentum flux
  // Central (unlimited) slopes measure the linear regime cleanly; a limiter keeps the fronts of a
  // nonlinear wave free of the oscillations that stall the integration (MC for the paper's
  // rollwave, van Albada where a small seed grows into one: limited_where_it_saturates).
  depthavg::Reconstruction reconstruction = depthavg::Reconstruction::Central;
  double rtol = 1e-7;
  // Solve in the frame moving at the seeded mode's (7.11) phase speed (depthavg/rhs.hpp); the
  // series comes back in the lab frame. ~20 times fewer steps than the lab frame.
  bool co_moving = true;

  // These settings with van Albada's limiter in place of central slopes when c's seed, grown at
  // growth_rate (the (7.11) rate of c), passes the measurement's linear bound (5 % of h0) before
  // c.t_end: the wave then steepens into fronts, and on steep slopes (40 deg at 8 cm) central
  // slopes oscillate there until CVODE stalls. Van Albada's limiter is smooth, so CVODE keeps
  // long steps, and it moves the linear-regime growth by about 0.1 % (docs/comparison.md).
  DepthAvgSettings limited_where_it_saturates(const ChuteCase& c, double growth_rate) const;
};

// The named grids of compare and sweep ({coarse, default, fine}): 2D grids with 16, 32 and 64
// cells per h0 (Lz ~ 2 h0, the surface mid-cell) and 128, 256, 512 depth-averaged cells.
// docs/twod-validation.md shows the 2D growth rate converging from below with the cells per h0 and
// first turning positive, as the 2D theory says, at 32. Throws std::invalid_argument for another
// name.
struct GridPreset {
  int twod_nx, twod_nz;
  std::size_t depthavg_nx;
  double twod_aimed_growth_deficit;  // TwodSettings::aimed_growth_deficit
};
GridPreset grid_preset(const std::string& name);

ModelRun run_depthavg(const ChuteCase& c, const DepthAvgSettings& s, const RunControl& ctl = {});
// The `granbench run` command lines that reproduce run_depthavg(c, s) and run_twod(c, s)
// (run_command.hpp), with the sampling interval those runs choose; without running anything, so
// that a point read back from a sweep file gets the same command as when it ran.
std::string depthavg_command_of(const ChuteCase& c, const DepthAvgSettings& s);
std::string twod_command_of(const ChuteCase& c, const TwodSettings& s);
ModelRun run_twod(const ChuteCase& c, const TwodSettings& s, const RunControl& ctl = {});

// Both models on the same case at once, each on its own std::thread; returns {depthavg, twod},
// the same records as run_depthavg and run_twod one after the other (neither run reads the
// other's state, and the 2D results do not depend on its thread count). While the
// depth-averaged run occupies a core, the 2D solver uses twod.threads - 1 threads (at
// least 1), then twod.threads: oversubscribed threads wait on each other.
// `after_depthavg`, if given, runs on the depth-averaged run's thread once that run has ended
// (compare --extrapolate: the 2D half grid, on one thread), and the 2D run takes the core back
// only after it; it must not throw.
std::pair<ModelRun, ModelRun> run_both(const ChuteCase& c, const DepthAvgSettings& depthavg,
                                       const TwodSettings& twod, const RunControl& ctl = {},
                                       const std::function<void()>& after_depthavg = {});

}  // namespace granbench
