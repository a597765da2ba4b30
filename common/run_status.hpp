// How a run of either model ended; one type for both models, the comparison, sweeps and cases.
//   Completed    reached its end time
//   Interrupted  stopped on request (SIGINT, SIGTERM) at a sample; what was computed is kept
//   Diverged     the solver's own divergence check fired (time, place and quantity in a message)
//   Failed       any other exception left the time loop (a linear solve, memory, a hook); the
//                samples up to then are kept and the message says when and why
#pragma once

namespace granbench {

enum class RunStatus { Completed, Interrupted, Diverged, Failed };

// "completed", "interrupted", "diverged", "failed" (the spelling of every output).
constexpr const char* run_status_name(RunStatus s) {
  switch (s) {
    case RunStatus::Completed:
      return "completed";
    case RunStatus::Interrupted:
      return "interrupted";
    case RunStatus::Diverged:
      return "diverged";
    case RunStatus::Failed:
      return "failed";
  }
  return "failed";
}

}  // namespace granbench
