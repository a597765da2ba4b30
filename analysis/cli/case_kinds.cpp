// The kinds of case of `granbench case`; see case_kinds.hpp.
#include "analysis/cli/case_kinds.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>

#include "analysis/cases/layer_case.hpp"
#include "analysis/cli/commands.hpp"
#include "analysis/cli/output_checks.hpp"
#include "analysis/cli/run_model.hpp"
#include "analysis/cli/run_twod.hpp"
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

}  // namespace

std::string path_in(const CaseOptions& o, const std::string& file) {
  return (std::filesystem::path(o.out_dir) / file).string();
}

// The uniform-layer cases: decelerating (§5.2) and high-speed (§6.2).
nlohmann::json run_layer_kind(const cases::CaseFile& file, const CaseOptions& o, int& exit_code) {
  const cases::LayerCaseSpec spec = cases::layer_case_spec(file, o.resolution);
  const std::string h5 = path_in(o, spec.name + ".h5");
  require_writable(h5, "--out-dir");
  const InterruptGuard guard(InterruptGuard::Signals::IntAndTerm);
  cases::LayerCaseProgress progress;
  if (progress_enabled(o.output))
    progress = [wall0 = std::chrono::steady_clock::now()](const std::string& status, double done) {
      const double wall =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
      std::cerr << "\r " << status << ", " << eta_text(wall, 0.0, done, 1.0) << "    "
                << std::flush;
    };
  const cases::LayerCaseResult result = cases::run_layer_case(spec, o.jobs, guard.flag(), progress);
  if (progress) std::cerr << "\n";
  cases::write_layer_case(h5, spec, result);
  for (const auto& r : result.runs)
    if (r.status == "interrupted") exit_code = guard.exit_code();
  const std::string png_prefix = path_in(o, spec.name);
  // snapshot_time: the time of the I snapshots (the decelerating layer is at rest by the end).
  plot_run("case_layer.py", h5, png_prefix,
           file.has("snapshot_time", o.resolution)
               ? std::to_string(file.number("snapshot_time", o.resolution))
               : "",
           exit_code == 0);
  nlohmann::json j = result.summary;
  j["outputs"] = {h5, png_prefix + "_profiles.png", png_prefix + "_snapshots.png"};
  if (!result.grid_dependence.empty()) j["outputs"].push_back(png_prefix + "_grid_dependence.png");
  return j;
}

// The rollwave cases (§7): `granbench run --model twod` with the file's [run] options.
nlohmann::json run_rollwave_kind(const cases::CaseFile& file, const CaseOptions& o,
                                 int& exit_code) {
  const std::string h5 = path_in(o, file.name() + ".h5");
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
  nlohmann::json j = {{"case", file.name()}, {"resolution", o.resolution}, {"run", report.json}};
  const std::string png_prefix = path_in(o, file.name());
  const double probe_x = file.number("probe_x", o.resolution);
  const std::vector<double> window = file.numbers("probe_window", o.resolution);
  const double field_time = file.number("field_time", o.resolution);
  if (window.size() != 2)
    throw cases::CaseFileError(file.path() + ": key 'probe_window' must be [t0, t1]");
  plot_run("case_rollwave.py", h5, png_prefix,
           std::to_string(probe_x) + " " + std::to_string(window[0]) + " " +
               std::to_string(window[1]) + " " + std::to_string(field_time),
           exit_code == 0);
  j["outputs"] = {h5, png_prefix + "_fields.png", png_prefix + "_streamlines.png",
                  png_prefix + "_surface.png"};
  return j;
}

// The well-posedness figures (1, 2, 7): `granbench wellposed` for each of the file's curves.
nlohmann::json run_wellposed_kind(const cases::CaseFile& file, const CaseOptions& o) {
  nlohmann::json j = {{"case", file.name()}, {"curves", nlohmann::json::object()}};
  for (const auto& curve : file.texts("curves", o.resolution)) {
    const std::string stem = path_in(o, file.name() + "_" + curve);
    j["curves"][curve] = wellposed_result(curve, stem + ".h5", stem + ".png");
    j["outputs"].push_back(stem + ".h5");
    j["outputs"].push_back(stem + ".png");
  }
  return j;
}

}  // namespace granbench::cli
