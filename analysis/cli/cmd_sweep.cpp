// granbench sweep: growth rate and phase speed of the linear waves over a range of domain lengths,
// measured by the model(s) beside the exact theory — the paper's figure 13.
//
//   granbench sweep --model depthavg --Lx 0.03:0.4:12 --jobs 2 --json
//   granbench sweep --model depthavg --Lx 0.02:0.6:24 --chi bagnold --plot fig13.png
//   granbench sweep --model both --Lx 0.01:0.08:8 --out sweep.h5 --plot fig13.png
//   mpirun -np 4 granbench sweep --model depthavg --Lx 0.02:0.4:32 --jobs 1 --out sweep.h5
//
// With --model depthavg each point is a clean linear measurement (depthavg/linear_run.hpp): the
// normal mode (7.10) seeded at amplitude 1e-4 h0, unlimited central reconstruction, tight
// tolerances, the growth rate and phase speed fitted spectrally over an automatically found
// window, against (7.11). With --model twod|both each point is a run seeded with the eigenmode of
// the model's own theory, measured like `compare`. All go through the resumable engine
// (analysis/comparison/sweep.hpp) on --jobs threads, shared among the ranks under mpirun
// (sweep_models.hpp): finished points are kept in --out and a re-run skips them.
#include <thread>

#include "cli_common.hpp"
#include "commands.hpp"
#include "run_model.hpp"
#include "sweep_models.hpp"

namespace granbench::cli {

namespace {

struct SweepOptions {
  FlowOptions flow;
  OutputOptions output;
  DepthAvgOptions depthavg;
  std::string model = "depthavg";
  std::string Lx = "0.03:0.4:12";
  unsigned jobs = std::max(1u, std::thread::hardware_concurrency());
  std::size_t nx = 192;
  double tolerance = 1e-6;
  double t_end = 0.0;
  std::string resolution = "default";  // 2D grid of --model twod|both (32 cells per h0)
  int viscosity_passes = 1;           // of --model twod|both
};

std::vector<double> domain_lengths(const std::string& text) {
  try {
    return parse_range(text);
  } catch (const std::invalid_argument&) {
    throw UsageError("--Lx: expected A:B:N with 0 < A <= B and integer N in [1, 10000], got '" +
                     text + "'");
  }
}

// --model depthavg: clean linear runs against (7.11).
depthavg::LinearRunParams linear_params(const SweepOptions& o) {
  depthavg::LinearRunParams lp;
  lp.nx = o.nx;
  lp.tolerance = o.tolerance;
  lp.t_end = o.t_end;
  lp.reconstruction = depthavg::parse_reconstruction(o.depthavg.limiter);
  lp.co_moving = o.depthavg.frame_speed == "linear";
  return lp;
}

void run_sweep(const SweepOptions& o) {
  SweepSpec spec;
  spec.chute.material = o.flow.material;
  spec.chute.curve = o.flow.curve_kind();
  spec.chute.angle_deg = o.flow.angle_deg;
  spec.chute.h0 = o.flow.h0;
  (void)o.flow.steady();  // a slope with no steady flow is an error on --angle
  if (o.depthavg.frame_speed != "linear" && o.depthavg.frame_speed != "0")
    throw UsageError("--frame-speed: '" + o.depthavg.frame_speed +
                     "' is not allowed for sweep; valid values {0, linear}");
  spec.Lx = domain_lengths(o.Lx);
  spec.depthavg = o.model != "twod";
  spec.twod = o.model != "depthavg";
  spec.depthavg_settings.chi = parse_chi(o.depthavg.chi);
  spec.depthavg_settings.co_moving = o.depthavg.frame_speed == "linear";
  spec.jobs = o.jobs;
  nlohmann::json settings = {{"model", o.model}, {"chi", spec.depthavg_settings.chi}};
  std::ostringstream title;
  title << o.model << " sweep over " << spec.Lx.size()
        << " domain lengths, chi = " << spec.depthavg_settings.chi << ", " << o.flow.curve
        << " curve, angle " << o.flow.angle_deg << " deg, h0 = " << o.flow.h0 << " m";
  if (o.model == "depthavg") {
    spec.depthavg_linear = linear_params(o);
    settings.update(
        {{"nx", o.nx}, {"tolerance", o.tolerance}, {"frame_speed", o.depthavg.frame_speed}});
    title << ", nx = " << o.nx;
  } else {
    spec.chute.t_end = o.t_end > 0.0 ? o.t_end : 2.0;
    spec.depthavg_settings.nx = 256;
    spec.twod_settings.nx = grid_preset(o.resolution).twod_nx;
    spec.twod_settings.nz = grid_preset(o.resolution).twod_nz;
    spec.twod_settings.viscosity_passes = o.viscosity_passes;
    // (recorded only when not the default, so sweeps stored before the option still resume)
    if (o.viscosity_passes != 1) settings["viscosity_passes"] = o.viscosity_passes;
    settings.update({{"frame_speed", o.depthavg.frame_speed},
                     {"resolution", o.resolution},
                     {"twod_nx", spec.twod_settings.nx},
                     {"twod_nz", spec.twod_settings.nz},
                     {"t_end", spec.chute.t_end}});
    title << ", 2D grid " << spec.twod_settings.nx << "x" << spec.twod_settings.nz;
  }
  run_sweep_command(std::move(spec), o.output, settings, title.str());
}

}  // namespace

void add_sweep_command(CLI::App& app) {
  auto o = std::make_shared<SweepOptions>();
  CLI::App* sub = app.add_subcommand(
      "sweep", "measured linear growth rate and phase speed over domain lengths vs (7.11)");
  add_flow_options(*sub, o->flow);
  sub->add_option("--model", o->model, "model {depthavg,twod,both}")
      ->check(one_of({"depthavg", "twod", "both"}))
      ->capture_default_str();
  sub->add_option("--Lx", o->Lx, "domain lengths A:B:N [m] (N evenly spaced from A to B)")
      ->capture_default_str();
  sub->add_option("--jobs", o->jobs, "parallel threads per process, in [1, 256]")
      ->check(CLI::Range(1u, 256u))
      ->capture_default_str();
  sub->add_option("--nx", o->nx, "cells per domain, in [16, 65536]")
      ->check(CLI::Range(std::size_t{16}, std::size_t{65536}))
      ->capture_default_str();
  sub->add_option(
         "--tolerance", o->tolerance,
         "CVODE tolerance relative to the seeded perturbation (amplitude 1e-4 h0), in (0, 1)")
      ->check(open_range(0.0, 1.0))
      ->capture_default_str();
  sub->add_option("--t-end", o->t_end,
                  "run length per point [s], > 0; default: max(4 periods, 0.5/|growth|), <= 5 s")
      ->check(positive());
  sub->add_option("--resolution", o->resolution,
                  "2D grid of --model twod|both {coarse: 80x32, default: 160x64, fine: 320x128}")
      ->check(one_of({"coarse", "default", "fine"}))
      ->capture_default_str();
  sub->add_option("--viscosity-passes", o->viscosity_passes,
                  "2D predictor-projection passes per step (--model twod|both), in [1, 4]")
      ->check(CLI::Range(1, 4))
      ->capture_default_str();
  add_depthavg_options(*sub, o->depthavg);
  add_output_options(*sub, o->output);
  add_threads_option(*sub);
  sub->callback([o] { run_sweep(*o); });
}

}  // namespace granbench::cli
