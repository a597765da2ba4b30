// The 2D model's own options of `granbench run --model twod` and the solver parameters they
// set (run_twod.hpp). Parsing, validation and mapping only; the run is in run_twod.cpp.
#include <cmath>
#include <string>

#include "analysis/cli/run_twod.hpp"
#include "common/steady_state.hpp"
#include "twod/initial_state.hpp"
#include "twod/run.hpp"

namespace granbench::cli {

void add_twod_options(CLI::App& app, TwodOptions& o) {
  app.add_option("--nz", o.nz, "twod: cells along z, in [4, 4096]")
      ->check(CLI::Range(4, 4096))
      ->capture_default_str();
  app.add_option("--Lz", o.Lz,
                 "twod: domain height [m], > h0 + a0; default about 2 h0 with h0 mid-cell")
      ->check(positive());
  app.add_option("--eta-max", o.eta_max, "twod: cap on the granular viscosity [Pa s], > 0")
      ->check(positive())
      ->capture_default_str();
  app.add_option("--eta-min", o.eta_min, "twod: floor on the granular viscosity [Pa s], > 0")
      ->check(positive())
      ->capture_default_str();
  app.add_option("--D-min", o.D_min, "twod: floor on |D| [1/s], > 0")
      ->check(positive())
      ->capture_default_str();
  app.add_option("--rho-light", o.rho_light, "twod: light-fluid density [kg/m^3], > 0")
      ->check(positive())
      ->capture_default_str();
  app.add_option("--eta-light", o.eta_light, "twod: light-fluid viscosity [Pa s], > 0")
      ->check(positive())
      ->capture_default_str();
  app.add_option("--mixing", o.mixing, "twod: viscosity in interface cells {arithmetic,harmonic}")
      ->check(one_of({"arithmetic", "harmonic"}))
      ->capture_default_str();
  app.add_option("--cfl", o.cfl, "twod: Courant number per direction, in (0, 0.5)")
      ->check(open_range(0.0, 0.5))
      ->capture_default_str();
  app.add_option(
         "--viscosity-passes", o.viscosity_passes,
         "twod: predictor-projection passes per step, eta from the previous pass, in [1, 4] "
         "(1: one solve, second order in time through the stress tangent; more passes "
         "cost n times as much, docs/twod-validation.md)")
      ->check(CLI::Range(1, 4))
      ->capture_default_str();
  app.add_option("--dt-max", o.dt_max, "twod: largest time step [s], > 0")
      ->check(positive())
      ->capture_default_str();
  app.add_option("--tolerance", o.tolerance,
                 "twod: relative residual of the linear solves, in (0, 1e-3)")
      ->check(open_range(0.0, 1e-3))
      ->capture_default_str();
  app.add_option("--dt-snapshot", o.dt_snapshot,
                 "twod: interval of the 2D field snapshots [s], >= t_end/1000; default t_end/10")
      ->check(positive());
  app.add_option("--checkpoint", o.checkpoint,
                 "twod: checkpoint file, written every --checkpoint-every and on SIGINT/SIGTERM, "
                 "removed when the run completes; default <out>.checkpoint.h5 "
                 "(twod.checkpoint.h5 without --out)");
  app.add_option("--checkpoint-every", o.checkpoint_every,
                 "twod: simulated time between checkpoints [s], >= 0 (0: only on SIGINT/SIGTERM); "
                 "the output file is brought up to date at each one, so a killed run restarts "
                 "from the last with --restart into the same --out")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--restart", o.restart,
                 "twod: continue from this checkpoint file (same physics and grid; into the same "
                 "--out, the earlier snapshots are kept)")
      ->check(CLI::ExistingFile);
}

twod::SolverParams twod_solver_params(const RunOptions& o, const TwodOptions& mo, double& Lz) {
  using namespace granbench::twod;
  if (o.noise != 0.0) throw UsageError("--noise: not available for --model twod; valid value 0");
  const MuCurve curve = o.flow.make_curve();
  const double zeta = degrees_to_radians(o.flow.angle_deg);
  const SteadyState base = o.flow.steady();  // no steady flow: an error on --angle
  Lz = mo.Lz > 0.0 ? mo.Lz : twod::mid_cell_domain_height(o.flow.h0, mo.nz);
  if (!(Lz > o.flow.h0 + o.a0))
    throw UsageError("--Lz: " + std::to_string(Lz) + " out of range; valid range (h0 + a0, inf)");
  if (!(mo.eta_min < mo.eta_max))
    throw UsageError("--eta-min: must be below --eta-max (" + std::to_string(mo.eta_max) + ")");
  SolverParams params;
  params.zeta = zeta;
  params.rheology.material = o.flow.material;
  params.rheology.curve = curve.kind();
  params.rheology.h0_for_curve = o.flow.h0;
  params.rheology.eta_max = mo.eta_max;
  params.rheology.eta_min = mo.eta_min;
  params.rheology.D_min = mo.D_min;
  params.rheology.rho_light = mo.rho_light;
  params.rheology.eta_light = mo.eta_light;
  params.rheology.mixing =
      mo.mixing == "harmonic" ? ViscosityMixing::Harmonic : ViscosityMixing::Arithmetic;
  params.cfl = mo.cfl;
  params.viscosity_passes = mo.viscosity_passes;
  params.dt_max = mo.dt_max;
  params.solver_tolerance = mo.tolerance;
  params.velocity_limit = divergence_speed_limit(base.u_surface);
  return params;
}

}  // namespace granbench::cli
