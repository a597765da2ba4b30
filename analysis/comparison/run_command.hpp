// The `granbench run` command line that reproduces one model's run of a comparison or of a sweep
// point: every option the run depends on (material constants only where they differ from table 1),
// numbers in their shortest exact decimal form, so that the rerun takes the same steps and reports
// the same growth rate and phase speed (tests/analysis/cli/test_run_command.cpp checks it to 1e-9).
// The thread count is left out: results do not depend on it.
#pragma once

#include <string>

#include "analysis/comparison/chute_case.hpp"
#include "analysis/comparison/model_runs.hpp"

namespace granbench {

// dt_out: the sampling interval the run used (ModelRun::dt_out).
std::string depthavg_run_command(const ChuteCase& c, const DepthAvgSettings& s, double dt_out);
std::string twod_run_command(const ChuteCase& c, const TwodSettings& s, double dt_out);

}  // namespace granbench
