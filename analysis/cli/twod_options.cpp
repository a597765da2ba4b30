// The 2D model's own options of `granbench run --model twod` and the solver parameters they
// set (run_twod.hpp). Parsing, validation and mapping only; the run is in run_twod.cpp.
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "analysis/cli/run_twod.hpp"
#include "twod/initial_state.hpp"

namespace granbench::cli {

namespace {

std::vector<std::string> mixing_names() {
  std::vector<std::string> names;
  for (const auto& [name, rule] : twod::viscosity_mixing_names) names.emplace_back(name);
  return names;
}

}  // namespace

std::string twod_refinement_help() {
  std::ostringstream t;
  t << "for a wave under " << TwodSettings::longest_wave_to_refine << " h0 up to "
    << TwodSettings::max_refinement << "x the cells across the layer, near the 2D cutoff up to "
    << TwodSettings::max_law_refinement << "x (the deficit law's grid for "
    << 100 * grid_preset("default").twod_aimed_growth_deficit << " % of the growth; "
    << 100 * grid_preset("coarse").twod_aimed_growth_deficit
    << " % on coarse), there with a light layer of " << TwodSettings::near_cutoff_light_layer
    << " h0 if the seed grown to the run's end stays within " << TwodSettings::small_wave_over_h0
    << " h0";
  return t.str();
}

void add_twod_cfl_option(CLI::App& app, double& cfl) {
  // The VOF's split step needs 1/2 per direction and takes sub-steps above it (vof_advection.hpp);
  // the rest of the step ran every case tried up to 0.9 (0.99 on the 8-cm wave). On that wave at
  // 32 cells per h0 the growth converges at order 1.9 from cfl 0.8 to 0.2, and 0.8 costs 0.6 % of
  // it against 0.4 for 0.54 times the steps (docs/twod-validation.md §2, "Steps above half a
  // cell"); the decay of short surface waves moves more, so the default stays 0.4.
  app.add_option("--cfl", cfl,
                 "2D Courant number per direction, in (0, 1); above 0.5 the volume fractions take "
                 "sub-steps; 0.8 takes about half the steps of the default and costs the 8-cm "
                 "wave 0.6 % of its growth rate (docs/twod-validation.md §2)")
      ->check(open_range(0.0, 1.0))
      ->capture_default_str();
}

void add_twod_options(CLI::App& app, TwodOptions& o) {
  app.add_option("--nz", o.settings.nz,
                 "twod: cells along z, in [4, 4096]; default 64, and (the wave: Lx / mode) " +
                     twod_refinement_help() + ", as compare and sweep")
      ->check(count_range(4, 4096))
      ->capture_default_str();
  app.add_option("--Lz", o.Lz,
                 "twod: domain height [m], > h0 + a0; default about 2 h0 (1.25 h0 near the 2D "
                 "cutoff, see --nz) with h0 mid-cell")
      ->check(positive());
  app.add_option("--eta-max", o.settings.eta_max, "twod: cap on the granular viscosity [Pa s], > 0")
      ->check(positive())
      ->capture_default_str();
  app.add_option("--eta-min", o.settings.eta_min,
                 "twod: floor on the granular viscosity [Pa s], > 0")
      ->check(positive())
      ->capture_default_str();
  app.add_option("--D-min", o.settings.D_min, "twod: floor on |D| [1/s], > 0")
      ->check(positive())
      ->capture_default_str();
  app.add_option("--rho-light", o.settings.rho_light, "twod: light-fluid density [kg/m^3], > 0")
      ->check(positive())
      ->capture_default_str();
  app.add_option("--eta-light", o.settings.eta_light, "twod: light-fluid viscosity [Pa s], > 0")
      ->check(positive())
      ->capture_default_str();
  app.add_option("--mixing", o.mixing, "twod: viscosity in interface cells {arithmetic,harmonic}")
      ->check(one_of(mixing_names()))
      ->capture_default_str();
  app.add_option("--momentum-transport", o.momentum_transport,
                 "twod: what carries momentum across faces {velocity,consistent}; consistent: the "
                 "mass fluxes of the VOF step, so that grains thrown off a steep front keep their "
                 "own momentum (long nonlinear runs; docs/twod-validation.md)")
      ->check(one_of({"velocity", "consistent"}))
      ->capture_default_str();
  add_twod_cfl_option(app, o.settings.cfl);
  app.add_option("--twod-frame", o.settings.frame_fraction,
                 "twod: speed of the computational grid as a fraction of the steady surface "
                 "speed, in [0, 1]; 0.5 about halves the steps, 0 is the lab frame; output is in "
                 "the lab frame either way")
      ->check(closed_range(0.0, 1.0))
      ->capture_default_str();
  app.add_option(
         "--viscosity-passes", o.settings.viscosity_passes,
         "twod: predictor-projection passes per step, eta from the previous pass, in [1, 4] "
         "(1: one solve, second order in time through the stress tangent; more passes "
         "cost n times as much, docs/twod-validation.md)")
      ->check(count_range(1, 4))
      ->capture_default_str();
  app.add_option("--dt-max", o.settings.dt_max, "twod: largest time step [s], > 0")
      ->check(positive())
      ->capture_default_str();
  app.add_option("--tolerance", o.settings.tolerance,
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
      ->check(non_negative())
      ->capture_default_str();
  app.add_option("--restart", o.restart,
                 "twod: continue from this checkpoint file (same physics and grid; into the same "
                 "--out, the earlier snapshots are kept)")
      ->check(CLI::ExistingFile);
}

void add_twod_extrapolate_option(CLI::App& app, TwodOptions& o) {
  app.add_flag("--extrapolate", o.extrapolate,
               "twod: after the run, run the same wave again on half the cells across the layer "
               "and report its growth rate extrapolated to cells of no height (the measured "
               "order 1.4, bounds from 1.3 and 1.7; docs/twod-validation.md §3); needs --mode 1 "
               "and at least 15 cells per h0 on the half grid");
}

ChuteCase chute_case(const RunOptions& o) {
  ChuteCase c = o.flow.chute(o.Lx);
  c.a0 = o.a0;
  c.seed = o.init == "eigenmode" ? Seed::Eigenmode : Seed::Sine;
  c.t_end = o.t_end;
  c.dt_out = o.dt_out;
  return c;
}

twod::SolverParams twod_run_params(const RunOptions& o, const TwodOptions& mo, double& Lz) {
  if (o.noise != 0.0) throw UsageError("--noise: not available for --model twod; valid value 0");
  o.flow.steady();  // no steady flow: an error on --angle
  const TwodSettings settings = twod_run_settings(o, mo);
  // (a given --Lz as given: Lz_over_h0 times h0 could differ from it in the last bit)
  Lz = mo.Lz > 0.0 ? mo.Lz : settings.domain_height(o.flow.h0);
  if (!(Lz > o.flow.h0 + o.a0))
    throw UsageError("--Lz: " + std::to_string(Lz) + " out of range; valid range (h0 + a0, inf)");
  if (!(mo.settings.eta_min < mo.settings.eta_max))
    throw UsageError("--eta-min: must be below --eta-max (" + std::to_string(mo.settings.eta_max) +
                     ")");
  return twod_solver_params(chute_case(o), settings);
}

TwodSettings twod_run_settings(const RunOptions& o, const TwodOptions& mo) {
  TwodSettings settings = mo.settings;
  settings.nx = int(o.nx);
  settings.Lz_over_h0 = mo.Lz > 0.0 ? mo.Lz / o.flow.h0 : 0.0;
  settings.mixing = *twod::viscosity_mixing_from_name(mo.mixing);  // checked by the option
  settings.consistent_momentum = mo.momentum_transport == "consistent";
  // The options were made before --threads was parsed; the thread count is this thread's now.
  settings.threads = twod::thread_count();
  return settings;
}

}  // namespace granbench::cli
