// granbench case: the paper's cases (§5-§7) as runnable case files in cases/ with their figures.
//
//   granbench case --list
//   granbench case decelerating                    (§5.2, figures 3-5)
//   granbench case high-speed --resolution smoke   (§6.2, figure 8; the CI version)
//   granbench case rollwave-8cm --out-dir runs/    (§7, figures 9-12)
//
// Each case file names its kind. Every case runs in this process, under the Ctrl-C/SIGTERM
// handling of `granbench run` (a stop keeps what was computed and exits with code 130): the
// uniform-layer cases (decelerating, high-speed) through analysis/cases/layer_case.hpp, the
// rollwave cases as `run --model twod` with the options in the file's [run] table (so the case is
// exactly what a user would type; run_twod.hpp), the wellposed case as `wellposed` for each of its
// curves. Every case writes <out-dir>/<name>*.h5 and draws its figures as <out-dir>/<name>_*.png
// with the scripts in analysis/plots.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "analysis/cases/case_file.hpp"
#include "analysis/cases/layer_case.hpp"
#include "analysis/cli/case_report.hpp"
#include "analysis/cli/cli_common.hpp"
#include "analysis/cli/commands.hpp"
#include "analysis/cli/help_footer.hpp"
#include "analysis/cli/output_checks.hpp"
#include "analysis/cli/run_model.hpp"
#include "analysis/cli/run_twod.hpp"
#include "common/failure_policy.hpp"

namespace granbench::cli {

namespace {

struct CaseOptions {
  std::string name;
  bool list = false;
  std::string resolution = "paper";
  std::string out_dir = ".";
  std::string cases_dir = GRANBENCH_CASES_DIR;
  unsigned jobs = 2;
  OutputOptions output;
};

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
  for (const auto& [key, values] : file.table("run", resolution))
    for (const auto& v : values) args.push_back("--" + key + "=" + v);
  std::reverse(args.begin(), args.end());  // CLI11 takes a vector of arguments last first
  try {
    app.parse(args);
  } catch (const CLI::ParseError& e) {
    throw cases::CaseFileError(file.path() + ": table [run]: " + e.what());
  }
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

void run_case(const CaseOptions& o) {
  if (o.list) {
    for (const auto& f : cases::list_case_files(o.cases_dir))
      std::cout << f.name() << "  [" << f.text("kind") << "]  "
                << (f.has("title") ? f.text("title") : std::string()) << "\n";
    return;
  }
  if (o.name.empty()) throw UsageError("NAME: a case name is required; see granbench case --list");
  const std::string path = (std::filesystem::path(o.cases_dir) / (o.name + ".toml")).string();
  if (!std::filesystem::exists(path)) {
    std::string names;
    for (const auto& f : cases::list_case_files(o.cases_dir))
      names += (names.empty() ? "" : ",") + f.name();
    throw UsageError("NAME: unknown case '" + o.name + "'; valid values {" + names + "}");
  }
  std::error_code ec;
  std::filesystem::create_directories(o.out_dir, ec);
  if (ec) throw UsageError("--out-dir: cannot create '" + o.out_dir + "': " + ec.message());

  int exit_code = 0;
  nlohmann::json j;
  std::string kind;
  try {
    const cases::CaseFile file = cases::read_case_file(path);
    kind = file.text("kind");
    if (kind == "decelerating" || kind == "high-speed")
      j = run_layer_kind(file, o, exit_code);
    else if (kind == "rollwave")
      j = run_rollwave_kind(file, o, exit_code);
    else if (kind == "wellposed")
      j = run_wellposed_kind(file, o);
    else
      throw cases::CaseFileError(path + ": key 'kind' = '" + kind +
                                 "'; valid values {decelerating,high-speed,rollwave,wellposed}");
  } catch (const cases::CaseFileError& e) {
    throw UsageError(std::string("case file ") + e.what());
  }
  j["kind"] = kind;
  if (o.output.json)
    print_json(j);
  else
    print_summary(kind, j);
  if (exit_code == kExitSigint || exit_code == kExitSigterm)
    throw CommandFailed("interrupted; the samples computed so far were kept", exit_code);
  if (exit_code != 0)
    throw CommandFailed("the case's run failed (exit code " + std::to_string(exit_code) + ")",
                        exit_code);
}

}  // namespace

void add_case_command(CLI::App& app) {
  auto o = std::make_shared<CaseOptions>();
  CLI::App* sub = app.add_subcommand(
      "case", "run one of the paper's cases (cases/*.toml) and draw its figures");
  sub->add_option("name", o->name, "case name (see --list)");
  sub->add_flag("--list", o->list, "list the cases");
  sub->add_option("--resolution", o->resolution,
                  "resolution {smoke,paper}: the CI version or the full case")
      ->check(one_of({"smoke", "paper"}))
      ->capture_default_str();
  sub->add_option("--out-dir", o->out_dir, "directory for the HDF5 files and figures")
      ->capture_default_str();
  sub->add_option("--cases-dir", o->cases_dir, "directory of the case files")
      ->capture_default_str();
  sub->add_option("--jobs", o->jobs, "runs of a case computed at once, in [1, 256]")
      ->check(CLI::Range(1u, 256u))
      ->capture_default_str();
  sub->add_flag("--json", o->output.json, "print the results as JSON");
  sub->add_flag("--quiet", o->output.quiet, "no progress on stderr");
  add_threads_option(*sub);
  sub->footer(
      help_footer({"granbench case --list", "granbench case decelerating --resolution smoke",
                   "granbench case rollwave-12cm --out-dir results"},
                  {0, 2, 3, 130, 143}));
  sub->callback([o] { run_case(*o); });
}

}  // namespace granbench::cli
