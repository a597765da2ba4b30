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
#include "analysis/cli/case_kinds.hpp"
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

void run_case_file(const CaseOptions& o) {
  // (the default is the source tree's cases/, compiled in: gone if the tree was moved)
  if (std::error_code ec; !std::filesystem::is_directory(o.cases_dir, ec))
    throw UsageError("--cases-dir: '" + o.cases_dir +
                     "' is not a directory; valid values: a directory of case files "
                     "(<name>.toml), such as the repository's cases/");
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
  const cases::CaseFile file = cases::read_case_file(path);
  const std::string kind = file.text("kind");
  if (kind == "decelerating" || kind == "high-speed")
    j = run_layer_kind(file, o, exit_code);
  else if (kind == "rollwave")
    j = run_rollwave_kind(file, o, exit_code);
  else if (kind == "wellposed")
    j = run_wellposed_kind(file, o);
  else if (kind == "figure13")
    j = run_figure13_kind(file, o, exit_code);
  else
    throw cases::CaseFileError(
        path + ": key 'kind' = '" + kind +
        "'; valid values {decelerating,high-speed,rollwave,wellposed,figure13}");
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

// A case file that cannot be read, is not TOML or lacks a key is bad input (exit 2), whether
// listed, named or run.
void run_case(const CaseOptions& o) {
  try {
    run_case_file(o);
  } catch (const cases::CaseFileError& e) {
    throw UsageError(std::string("case file ") + e.what());
  }
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
      ->check(count_range(1, 256))
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
