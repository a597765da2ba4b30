// The kinds of case of `granbench case`; see case_kinds.hpp.
#include "analysis/cli/case_kinds.hpp"

#include <chrono>
#include <filesystem>
#include <iostream>

#include "analysis/cases/layer_case.hpp"
#include "analysis/cli/commands.hpp"
#include "analysis/cli/output_checks.hpp"
#include "common/failure_policy.hpp"

namespace granbench::cli {

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
