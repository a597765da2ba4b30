// Up-front checks of output paths and record counts (output_checks.hpp).
#include "analysis/cli/output_checks.hpp"

#include <cmath>
#include <iostream>
#include <sstream>

#include "analysis/cli/cli_common.hpp"
#include "common/failure_policy.hpp"

namespace granbench::cli {

void require_writable(const std::string& path, const std::string& option) {
  const std::string why = unwritable_reason(path);
  if (!why.empty()) throw UsageError(option + ": cannot write '" + path + "': " + why);
}

void require_writable_outputs(const OutputOptions& o) {
  if (!o.out.empty()) require_writable(o.out, "--out");
  if (!o.plot.empty()) require_writable(o.plot, "--plot");
}

std::optional<OutputLock> claim_output(const std::string& path, const std::string& option) {
  if (path.empty()) return std::nullopt;
  try {
    return std::optional<OutputLock>(std::in_place, path);
  } catch (const OutputLock::LockHeld& e) {
    throw UsageError(option + ": " + e.what() + " writing " + path +
                     "; wait for it to finish or choose another " + option);
  } catch (const std::runtime_error& e) {
    throw UsageError(option + ": " + e.what());
  }
}

void require_record_count(const std::string& option, double t_end, double dt, long cap,
                          const std::string& records) {
  const double n = std::ceil(t_end / dt - 1e-9);
  if (n <= double(cap)) return;
  std::ostringstream s;
  s << option << ": " << dt << " s gives " << n << " " << records << " up to --t-end " << t_end
    << " s, more than the cap of " << cap << "; valid range [" << t_end / double(cap) << ", inf)";
  throw UsageError(s.str());
}

void plot_run(const std::string& script, const std::string& h5, const std::string& png,
              const std::string& extra_args, bool run_completed) {
  try {
    run_plot_script(script, h5, png, extra_args);
  } catch (const std::runtime_error& e) {
    if (run_completed) throw;
    std::cerr << "granbench: no figure: " << e.what() << "\n";
  }
}

}  // namespace granbench::cli
