// granbench run: one simulation of the periodic chute flow from an initial perturbation, with the
// measured growth rate and speed of the perturbation.
//
//   granbench run --model depthavg --angle 28.5 --h0 0.004 --a0 2e-4 --Lx 0.08 --nx 512 --t-end 10
//   granbench run --model depthavg --init eigenmode --a0 4e-6 --Lx 0.08 --t-end 2 --json
//
// Model-independent options live in RunOptions (run_model.hpp); each model adds its own options
// and has its own run_<model>.cpp. The model is chosen once, here.
#include <cmath>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "analysis/cli/cli_common.hpp"
#include "analysis/cli/commands.hpp"
#include "analysis/cli/help_footer.hpp"
#include "analysis/cli/run_model.hpp"
#include "analysis/cli/run_twod.hpp"
#include "analysis/linear2d/eigenmode.hpp"
#include "common/failure_policy.hpp"

namespace granbench::cli {

std::vector<std::string> model_names() {
  return {"depthavg", "twod"};
}

Model parse_model(const std::string& name) {
  if (name == "depthavg") return Model::DepthAvg;
  if (name == "twod") return Model::TwoD;
  throw UsageError("--model: '" + name + "' is not available; valid values {depthavg,twod}");
}

void add_run_options(CLI::App& app, RunOptions& o) {
  add_flow_options(app, o.flow);
  app.add_option("--model", o.model, "model {depthavg,twod}")
      ->check(one_of(model_names()))
      ->capture_default_str();
  app.add_option("--Lx", o.Lx, "domain length Lx [m], > 0")
      ->check(positive())
      ->capture_default_str();
  app.add_option("--nx", o.nx,
                 "cells along x, in [8, 1048576]; --model twod: by default 160 per 8 cm as in "
                 "compare (at least 160, a multiple of 16)")
      ->check(count_range(8, 1 << 20))
      ->capture_default_str();
  app.add_option("--a0", o.a0, "perturbation amplitude a0 [m] of (7.2), in [0, h0)")
      ->check(non_negative())
      ->capture_default_str();
  app.add_option("--mode", o.mode, "wavelengths of the perturbation in the domain, in [1, nx/2]")
      ->check(count_range(1, 1 << 19, "[1, nx/2]"))  // (nx/2 checked with nx: check_run_options)
      ->capture_default_str();
  app.add_option("--init", o.init,
                 "initial state {sine,eigenmode}: (7.2) or the normal mode (7.10)")
      ->check(one_of({"sine", "eigenmode"}))
      ->capture_default_str();
  app.add_option("--noise", o.noise, "random height noise as a fraction of h0, in [0, 0.5)")
      ->check(half_open_range(0.0, 0.5))
      ->capture_default_str();
  app.add_option("--seed", o.seed, "seed of the noise")->capture_default_str();
  app.add_option("--t-end", o.t_end, "end time [s], > 0")->check(positive())->capture_default_str();
  app.add_option("--dt-out", o.dt_out,
                 "sampling interval of h(x,t) [s], >= t_end/100000 (at most 1e5 samples); "
                 "default: automatic (the fastest wave moves at most Lx/(8 mode) per sample, and "
                 "at most 0.01 s, unless that gives more than 1e5 samples)")
      ->check(positive());
  app.add_option("--rtol", o.rtol, "CVODE relative tolerance, in (0, 1)")
      ->check(open_range(0.0, 1.0))
      ->capture_default_str();
  app.add_option("--atol", o.atol, "CVODE absolute tolerance [m of h], > 0")
      ->check(positive())
      ->capture_default_str();
  app.add_option("--bdf-order", o.bdf_order,
                 "CVODE BDF order limit (depthavg), in [1, 5]; default: 2 in a co-moving frame, 5 "
                 "in the lab frame (depthavg/params.hpp)")
      ->check(count_range(1, 5));
  add_output_options(app, o.output, false);
  add_threads_option(app);
}

void check_run_options(const RunOptions& o) {
  if (!(o.a0 < o.flow.h0))
    throw UsageError("--a0: " + std::to_string(o.a0) + " out of range; valid range [0, h0)");
  if (o.mode < 1 || static_cast<std::size_t>(o.mode) > o.nx / 2)
    throw UsageError("--mode: value " + std::to_string(o.mode) +
                     " out of range; valid range [1, nx/2] (nx = " + std::to_string(o.nx) + ")");
}

namespace {

// The names of the options that `add` registers on `app`.
template <class Add>
std::vector<std::string> options_added(CLI::App& app, Add add) {
  std::set<std::string> before;
  for (const CLI::Option* opt : app.get_options()) before.insert(opt->get_name());
  add();
  std::vector<std::string> added;
  for (const CLI::Option* opt : app.get_options())
    if (!before.count(opt->get_name())) added.push_back(opt->get_name());
  return added;
}

// An option given (on the command line or in --config) that the chosen model does not read is
// refused, not ignored: a user who set it believes it changed the run.
void refuse_options_of_other_model(const CLI::App& app, const std::vector<std::string>& names,
                                   const std::string& owner) {
  for (const std::string& name : names)
    if (app.get_option(name)->count() > 0)
      throw UsageError(name + ": applies to --model " + owner + " only");
}

// Without --nx or --nz (on the command line or in a --config file) the 2D model takes the grid
// that compare and sweep give this wave: along x the preset's 160 cells per 8 cm, at least 160,
// a multiple of 16 (TwodSettings::cells_along; 256 stays the depth-averaged default); across
// the layer 64 cells, more for a wave under 7.5 h0 and more again near the 2D cutoff
// (refined_across, with the wave's exact 2D growth; there a wave that stays small also gets a
// light layer of h0/4, so that the domain is about 1.25 h0 high). The options' shown defaults
// become those values.
void set_twod_grid_defaults(CLI::App& sub, RunOptions& run, TwodOptions& twod) {
  if (sub.count("--nx") == 0) {
    run.nx = std::size_t(twod.settings.cells_along(run.Lx));
    sub.get_option("--nx")->default_str(std::to_string(run.nx));
  }
  if (sub.count("--nz") == 0) {
    const double wavelength = run.Lx / run.mode;
    TwodSettings settings = twod.settings;
    settings.Lz_over_h0 = twod.Lz > 0.0 ? twod.Lz / run.flow.h0 : 0.0;
    try {
      const SteadyState base = run.flow.steady();
      Linear2DOptions quick;  // (the growth as compare's theory has it, without its check)
      quick.N_check = 0;
      const double growth =
          linear2d::surface_eigenmode(base, run.flow.make_curve(), wavelength, quick).growth_rate();
      const TwodSettings refined =
          settings.refined_across(wavelength, base, growth, run.a0, run.t_end);
      twod.settings.nz = refined.nz;
      twod.settings.light_layer_over_h0 = refined.light_layer_over_h0;
    } catch (const std::exception&) {
      // no steady flow or no surface mode (the run refuses the first with the reason later)
      twod.settings.nz = settings.cells_across(wavelength, run.flow.h0);
    }
    sub.get_option("--nz")->default_str(std::to_string(twod.settings.nz));
  }
}

}  // namespace

void add_run_command(CLI::App& app) {
  auto run = std::make_shared<RunOptions>();
  auto depthavg = std::make_shared<DepthAvgOptions>();
  auto twod = std::make_shared<TwodOptions>();
  CLI::App* sub = app.add_subcommand(
      "run", "simulate the periodic chute flow from a perturbation; measure growth and speed");
  add_run_options(*sub, *run);
  // CVODE's options are the depth-averaged model's; the rest of add_run_options serve both.
  std::vector<std::string> depthavg_only{"--rtol", "--atol", "--bdf-order"};
  for (const auto& name : options_added(*sub, [&] { add_depthavg_options(*sub, *depthavg); }))
    depthavg_only.push_back(name);
  const std::vector<std::string> twod_only = options_added(*sub, [&] {
    add_twod_options(*sub, *twod);
    add_twod_extrapolate_option(*sub, *twod);
  });
  sub->footer(help_footer(
      {"granbench run --model depthavg --angle 28.5 --h0 0.004 --Lx 0.08 --nx 512 --t-end 10",
       "granbench run --model twod --init eigenmode --a0 2e-5 --t-end 2 --out run.h5 --json",
       "granbench run --model twod --restart run.checkpoint.h5 --t-end 10 --out run.h5"},
      {0, 2, 3, 130, 143}));
  // The 2D grid's defaults depend on the length and the mode, so they are set once the options
  // are parsed, and shown so: --print-config and the run read the same values (the callback
  // below is not called under --print-config).
  sub->parse_complete_callback([sub, run, twod] {
    if (parse_model(run->model) == Model::TwoD) set_twod_grid_defaults(*sub, *run, *twod);
  });
  sub->callback([sub, run, depthavg, twod, depthavg_only, twod_only] {
    check_run_options(*run);
    if (parse_model(run->model) == Model::TwoD)
      refuse_options_of_other_model(*sub, depthavg_only, "depthavg");
    else
      refuse_options_of_other_model(*sub, twod_only, "twod");
    switch (parse_model(run->model)) {
      case Model::DepthAvg:
        run_depthavg(*run, *depthavg);
        break;
      case Model::TwoD:
        run_twod(*run, *twod);
        break;
    }
  });
}

}  // namespace granbench::cli
