// The rollwave cases of `granbench case` (§7, figures 9-12): `granbench run --model twod` with
// the case file's [run] options in this process, the figures, and the paper's measures of the
// run: (7.12) over the linear period and the developed wave over the probe window.
#include <iostream>

#include "analysis/cli/case_kinds.hpp"
#include "analysis/cli/commands.hpp"
#include "analysis/cli/output_checks.hpp"
#include "analysis/cli/run_model.hpp"
#include "analysis/cli/run_twod.hpp"
#include "analysis/spectral/growth_estimator_712.hpp"
#include "analysis/spectral/saturated_wave.hpp"
#include "common/failure_policy.hpp"

namespace granbench::cli {

namespace {

// The options of `granbench run` (both models' own included, as on its command line) from the
// case's [run] table.
void parse_run_table(const cases::CaseFile& file, const std::string& resolution, RunOptions& run,
                     TwodOptions& twod) {
  CLI::App app("the [run] table of a case file");
  DepthAvgOptions depthavg;
  add_run_options(app, run);
  add_depthavg_options(app, depthavg);
  add_twod_options(app, twod);
  std::vector<std::string> args;
  // Case files spell every key with underscores (t_end, dt_snapshot), the [run] table too; the
  // option of a key is its name with '-' for '_' (t_end: --t-end).
  for (const auto& [key, values] : file.table("run", resolution)) {
    std::string option = key;
    std::replace(option.begin(), option.end(), '_', '-');
    for (const auto& v : values) args.push_back("--" + option + "=" + v);
  }
  std::reverse(args.begin(), args.end());  // CLI11 takes a vector of arguments last first
  try {
    app.parse(args);
  } catch (const CLI::ParseError& e) {
    throw cases::CaseFileError(file.path() + ": table [run]: " + e.what());
  }
}

// (7.12) averaged over [t0, t1], the paper's measure of the growth in figure 12; null with the
// reason when the window holds no growth above h0.
nlohmann::json growth_712_json(const SurfaceSeries& s, double t0, double t1) {
  nlohmann::json j = {{"window", {t0, t1}}};
  try {
    const Estimate712 e = growth_estimate_712(s, t0, t1);
    j["growth_rate"] = e.growth_rate;
    j["fit_growth_rate"] = e.fit.slope;
  } catch (const std::invalid_argument& e) {
    j["growth_rate"] = nullptr;
    j["reason"] = e.what();
  }
  return j;
}

// The wave over [t0, t1] (the paper's 8.5-9.1 s), measured as compare --saturated measures both
// models (saturated_wave.hpp): amplitude, steepest slope, front width, speed and flux.
nlohmann::json developed_wave_json(const SurfaceSeries& s, double t0, double t1) {
  try {
    return to_json(measure_saturated_wave(s, t0, t1));
  } catch (const std::invalid_argument& e) {
    return {{"t_from", t0}, {"t_to", t1}, {"reason", e.what()}};
  }
}

}  // namespace

// The rollwave cases (§7): `granbench run --model twod` with the file's [run] options.
nlohmann::json run_rollwave_kind(const cases::CaseFile& file, const CaseOptions& o,
                                 int& exit_code) {
  const std::string h5 = path_in(o, file.name() + ".h5");
  // The figure's keys, checked before the run.
  const double probe_x = file.number("probe_x", o.resolution);
  const std::vector<double> window = file.numbers("probe_window", o.resolution);
  const double field_time = file.number("field_time", o.resolution);
  if (window.size() != 2 || !(window[0] < window[1]))
    throw cases::CaseFileError(file.path() + ": key 'probe_window' must be [t0, t1], t0 < t1");
  const std::vector<double> growth_window = file.has("growth_window", o.resolution)
                                                ? file.numbers("growth_window", o.resolution)
                                                : std::vector<double>{};
  if (!growth_window.empty() &&
      (growth_window.size() != 2 || !(growth_window[0] < growth_window[1])))
    throw cases::CaseFileError(file.path() + ": key 'growth_window' must be [t0, t1], t0 < t1");
  RunOptions run;
  TwodOptions twod;
  parse_run_table(file, o.resolution, run, twod);
  run.model = "twod";
  run.output.json = true;
  run.output.out = h5;
  run.output.quiet = o.output.quiet;
  TwodRunReport report;
  const InterruptGuard guard(InterruptGuard::Signals::IntAndTerm);
  try {
    check_run_options(run);
    report = run_twod_model(run, twod, guard.flag());
  } catch (const UsageError& e) {
    throw UsageError("case file " + file.path() + ", table [run]: " + e.what());
  }
  try {
    throw_unless_completed(report, guard);
  } catch (const CommandFailed& e) {
    exit_code = e.exit_code;  // after the figures of what was computed
  }
  if (exit_code != 0) std::cerr << "granbench: " << report.message << "\n";
  nlohmann::json j = {{"case", file.name()},
                      {"resolution", o.resolution},
                      {"run", report.json},
                      {"developed_wave", developed_wave_json(report.series, window[0], window[1])}};
  if (!growth_window.empty())
    j["growth_712"] = growth_712_json(report.series, growth_window[0], growth_window[1]);
  const std::string png_prefix = path_in(o, file.name());
  plot_run("case_rollwave.py", h5, png_prefix,
           std::to_string(probe_x) + " " + std::to_string(window[0]) + " " +
               std::to_string(window[1]) + " " + std::to_string(field_time),
           exit_code == 0);
  j["outputs"] = {h5, png_prefix + "_fields.png", png_prefix + "_streamlines.png",
                  png_prefix + "_surface.png"};
  return j;
}

}  // namespace granbench::cli
