// The sweep's options and the SweepSpec they make; see sweep_plan.hpp.
#include "analysis/cli/sweep_plan.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "analysis/cli/extrapolation_report.hpp"
#include "analysis/cli/physics_warnings.hpp"
#include "analysis/cli/run_twod.hpp"
#include "analysis/comparison/twod_extrapolation.hpp"
#include "analysis/linear2d/eigenmode.hpp"

namespace granbench::cli {

namespace {

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
  // (a linear run's seed stays far below the linear bound: auto is central)
  lp.reconstruction = limiter_for_seed(o.depthavg.limiter, false);
  lp.co_moving = o.depthavg.frame_speed == "linear";
  return lp;
}

// An option that the chosen model would silently ignore is refused: the user meant something by
// it, and a stored sweep would otherwise look as if it had been run with it.
void refuse_options_that_do_not_apply(const SweepOptions& o, const CLI::App& app) {
  struct Rule {
    const char* option;
    std::vector<std::string> models;  // the models it changes
  };
  const Rule rules[] = {{"--nx", {"depthavg"}},
                        {"--seed-tolerance", {"depthavg"}},
                        {"--limiter", {"depthavg"}},
                        {"--chi", {"depthavg", "both"}},
                        {"--frame-speed", {"depthavg", "both"}},
                        {"--resolution", {"twod", "both"}},
                        {"--viscosity-passes", {"twod", "both"}},
                        {"--twod-frame", {"twod", "both"}},
                        {"--cfl", {"twod", "both"}},
                        {"--extrapolate", {"twod", "both"}}};
  for (const Rule& r : rules) {
    const CLI::Option* opt = app.get_option_no_throw(r.option);
    if (opt == nullptr || opt->count() == 0) continue;
    if (std::find(r.models.begin(), r.models.end(), o.model) != r.models.end()) continue;
    std::string list;
    for (const auto& m : r.models) list += (list.empty() ? "" : " or ") + ("--model " + m);
    throw UsageError(std::string(r.option) + ": does not apply to --model " + o.model +
                     "; valid only with " + list);
  }
}

}  // namespace

void add_sweep_options(CLI::App& sub, SweepOptions& o) {
  add_flow_options(sub, o.flow);
  sub.add_option("--model", o.model, "model {depthavg,twod,both}")
      ->check(one_of({"depthavg", "twod", "both"}))
      ->capture_default_str();
  sub.add_option("--Lx", o.Lx, "domain lengths A:B:N [m] (N evenly spaced from A to B)")
      ->capture_default_str();
  sub.add_option("--jobs", o.jobs, "parallel threads per process, in [1, 256]")
      ->check(count_range(1, 256))
      ->capture_default_str();
  sub.add_option("--nx", o.nx, "cells per domain (--model depthavg), in [16, 65536]")
      ->check(count_range(16, 65536))
      ->capture_default_str();
  sub.add_option("--seed-tolerance", o.tolerance,
                 "CVODE tolerance relative to the seeded perturbation (amplitude 1e-4 h0) "
                 "(--model depthavg), in (0, 1)")
      ->check(open_range(0.0, 1.0))
      ->capture_default_str();
  sub.add_option("--t-end", o.t_end,
                 "run length per point [s], > 0; default: max(4 periods, 0.5/|growth|), <= 5 s")
      ->check(positive());
  sub.add_option(
         "--resolution", o.resolution,
         "2D grid of --model twod|both at Lx = 8 cm {coarse: 80x32, default: 160x64, fine: "
         "320x128}; at another Lx, at least these cells along x and at most their dx, and " +
             twod_refinement_help())
      ->check(one_of({"coarse", "default", "fine"}))
      ->capture_default_str();
  sub.add_option("--twod-frame", o.twod_frame,
                 "2D grid (--model twod|both)'s speed as a fraction of the steady surface speed, "
                 "in [0, 1]; 0.5 about "
                 "halves the steps, 0 is the lab frame; output is in the lab frame either way")
      ->check(closed_range(0.0, 1.0))
      ->capture_default_str();
  add_twod_cfl_option(sub, o.cfl);
  sub.add_option("--viscosity-passes", o.viscosity_passes,
                 "2D predictor-projection passes per step (--model twod|both), in [1, 4]")
      ->check(count_range(1, 4))
      ->capture_default_str();
  sub.add_flag("--extrapolate", o.extrapolate,
               "run each 2D point (--model twod|both) again on half the cells across the layer and "
               "report its growth rate extrapolated to cells of no height (the measured order "
               "1.4, bounds from orders 1.3 and 1.7; 1.4-1.5 times the cost on one thread)");
  add_depthavg_options(sub, o.depthavg);
  add_output_options(sub, o.output);
}

const std::map<std::string, std::string>& sweep_options_without_effect_on_results() {
  static const std::map<std::string, std::string> neutral = {
      {"--help", "prints the help"},
      {"--model", "chooses the points; each is stored with its model"},
      {"--Lx", "chooses the points; each is stored with its Lx"},
      {"--jobs", "threads only; every point is computed alone"},
      {"--out", "where the points go"},
      {"--plot", "the figure of the points"},
      {"--json", "how the result is printed"},
      {"--quiet", "progress only"},
      {"--config", "read into the other options"}};
  return neutral;
}

SweepPlan plan_sweep(const SweepOptions& o, const CLI::App& app) {
  refuse_options_that_do_not_apply(o, app);
  SweepPlan plan;
  SweepSpec& spec = plan.spec;
  spec.chute = o.flow.chute(spec.chute.Lx);  // Lx is replaced by each point's
  (void)o.flow.steady();                     // a slope with no steady flow is an error on --angle
  if (o.depthavg.frame_speed != "linear" && o.depthavg.frame_speed != "0")
    throw UsageError("--frame-speed: '" + o.depthavg.frame_speed +
                     "' is not allowed for sweep; valid values {0, linear}");
  spec.Lx = domain_lengths(o.Lx);
  spec.depthavg = o.model != "twod";
  spec.twod = o.model != "depthavg";
  spec.depthavg_settings.chi = parse_chi(o.depthavg.chi);
  spec.depthavg_settings.co_moving = o.depthavg.frame_speed == "linear";
  spec.jobs = o.jobs;
  nlohmann::json& settings = plan.settings;
  settings = {{"model", o.model}, {"chi", spec.depthavg_settings.chi}};
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
    spec.twod_settings.aimed_growth_deficit = grid_preset(o.resolution).twod_aimed_growth_deficit;
    spec.twod_settings.viscosity_passes = o.viscosity_passes;
    spec.twod_settings.frame_fraction = o.twod_frame;
    spec.twod_settings.cfl = o.cfl;
    spec.twod_extrapolate = o.extrapolate;
    if (o.extrapolate) {  // every point's half grid within the deficit law's range
      for (const double Lx : spec.Lx) {
        // (on the grid of the wavelength alone: a point's growth only adds cells)
        const double n = half_grid_cells_per_depth(point_twod_settings(spec, Lx, NAN), o.flow.h0);
        if (n >= kGrowthDeficitFewestCellsPerDepth) continue;
        std::ostringstream m;
        m << "--extrapolate: not with --resolution " << o.resolution << ", whose half grid (" << n
          << " cells per h0 at Lx = " << Lx << " m) is below the deficit law's range; valid with "
          << "at least " << kGrowthDeficitFewestCellsPerDepth
          << " there: --resolution default or fine";
        throw UsageError(m.str());
      }
    }
    settings.update({{"frame_speed", o.depthavg.frame_speed},
                     {"resolution", o.resolution},
                     {"viscosity_passes", o.viscosity_passes},
                     {"twod_frame", o.twod_frame},
                     {"cfl", o.cfl},
                     {"extrapolate", o.extrapolate},
                     {"twod_nx", spec.twod_settings.nx},
                     {"twod_nz", spec.twod_settings.nz},
                     {"t_end", spec.chute.t_end}});
    const double shortest = *std::min_element(spec.Lx.begin(), spec.Lx.end());
    // (the grid of the wavelength alone: the warnings below it are the wavelength's)
    const TwodSettings at_shortest = point_twod_settings(spec, shortest, NAN);
    plan.warnings = twod_warnings(o.flow.steady(),
                                  at_shortest.domain_height(o.flow.h0) / at_shortest.nz, shortest);
    settings["warnings"] = plan.warnings;
    title << ", 2D grid " << spec.twod_settings.nx << "x" << spec.twod_settings.nz
          << " at 8 cm (at least " << spec.twod_settings.nx << " cells along x, dx at most "
          << 1e3 * TwodSettings::reference_length / spec.twod_settings.nx
          << " mm; more cells across the layer for waves under "
          << TwodSettings::longest_wave_to_refine << " h0 and near the 2D cutoff)";
    if (o.extrapolate) title << ", extrapolated from half the cells across the layer";
  }
  plan.title = title.str();
  return plan;
}

void add_growth_accuracy_warnings(const SweepOptions& o, SweepPlan& plan) {
  const SweepSpec& spec = plan.spec;
  if (!spec.twod) return;
  const SteadyState base = o.flow.steady();
  const MuCurve curve = o.flow.make_curve();
  for (const double Lx : spec.Lx) {
    double growth = 0.0;
    try {
      growth = linear2d::surface_eigenmode(base, curve, Lx).growth_rate();
    } catch (const std::exception&) {
      continue;  // no surface mode: the point reports that itself
    }
    const TwodSettings point = point_twod_settings(spec, Lx, growth);
    if (spec.twod_extrapolate)
      if (auto w = thin_layer_extrapolation_warning(point, o.flow.h0)) {
        std::ostringstream named;
        named << "Lx = " << Lx << " m: " << *w;
        plan.warnings.push_back(named.str());
      }
    const double dz = point.domain_height(o.flow.h0) / point.nz;
    if (auto w =
            twod_growth_accuracy_warning(base, dz, Lx, growth, point.domain_height(o.flow.h0))) {
      std::ostringstream named;
      named << "Lx = " << Lx << " m: " << *w;
      if (!spec.twod_extrapolate &&
          !under_thin_light_layer(point.domain_height(o.flow.h0), o.flow.h0) &&
          half_grid_cells_per_depth(point, o.flow.h0) >= kGrowthDeficitFewestCellsPerDepth)
        named << extrapolate_suggestion("the point");
      plan.warnings.push_back(named.str());
    }
  }
  plan.settings["warnings"] = plan.warnings;
}

}  // namespace granbench::cli
