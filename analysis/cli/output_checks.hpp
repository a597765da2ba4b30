// The checks of the failure policy (failure_policy.hpp) that run before any work, as UsageError
// (exit 2): output and checkpoint paths that cannot be written (with the OS's reason), and
// sampling intervals that would fill memory or disk; and the figure of a run that stopped early.
#pragma once

#include <optional>
#include <string>

#include "analysis/cli/cli_common.hpp"
#include "common/output_lock.hpp"

namespace granbench::cli {

// Caps on the records of one run: a sample of h(x, t) costs 2 nx doubles in memory, a 2D
// snapshot seven fields of nx nz doubles on disk. 1e5 samples of a 256-cell run are 400 MB.
inline constexpr long kMaxSamples = 100000;
inline constexpr long kMaxSnapshots = 1000;

// UsageError "<option>: cannot write '<path>': <reason>" when `path` cannot be created.
void require_writable(const std::string& path, const std::string& option);

// require_writable for --out and --plot of a command that writes nothing else, when given.
void require_writable_outputs(const OutputOptions& o);

// The claim on `path` for this process's life (common/output_lock.hpp): UsageError naming
// `option` and the lock file when another granbench process is writing the same output. An empty
// path claims nothing.
std::optional<OutputLock> claim_output(const std::string& path, const std::string& option);

// UsageError naming `option` and its valid range when t_end / dt exceeds `cap` records.
void require_record_count(const std::string& option, double t_end, double dt, long cap,
                          const std::string& records);

// run_plot_script for a run's figure. When the run did not complete, a plotting failure (no
// python3-matplotlib) is reported on stderr instead of thrown, so that the run's own exit code
// (interrupted, diverged, failed) is the one the caller sees.
void plot_run(const std::string& script, const std::string& h5, const std::string& png,
              const std::string& extra_args, bool run_completed);

}  // namespace granbench::cli
