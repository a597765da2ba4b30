// One failure policy for every granbench command (README "Exit codes"): what a stop signal does,
// which exit code each outcome gets, and the check that an output path can be written before
// any work is done. The solvers only see the stop flag; the commands map outcomes to codes here.
#pragma once

#include <atomic>
#include <csignal>
#include <string>

namespace granbench {

// Exit codes of the run commands. 130 and 143 are the shell's 128 + SIGINT / SIGTERM, so a
// script sees the same code as for a process killed by that signal, but the data is kept.
enum ExitCode : int {
  kExitOk = 0,
  kExitInternal = 1,   // a defect: an internal error escaped (please report it)
  kExitUsage = 2,      // bad input or an unwritable path, found before any work
  kExitRunFailed = 3,  // the run diverged or failed; data up to the last good sample kept
  kExitSigint = 128 + SIGINT,
  kExitSigterm = 128 + SIGTERM,
};

// SIGINT (and with Signals::IntAndTerm also SIGTERM) raises the flag instead of killing the
// process while a guard lives, so that a run stops at its next sample and keeps what it
// computed. The signal caught is kept for the exit code (128 + signal).
class InterruptGuard {
 public:
  enum class Signals { Int, IntAndTerm };
  explicit InterruptGuard(Signals signals = Signals::Int);
  ~InterruptGuard();
  const std::atomic<bool>* flag() const;
  int signal() const;     // the last signal caught; 0 if none
  int exit_code() const;  // 128 + signal(); kExitSigint if none was caught (stopped otherwise)
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

 private:
  bool term_;
};

// Why `path` cannot be written as an output file (the OS's reason: "No such file or directory",
// "Permission denied", "Is a directory"), or an empty string when it can. Probes by creating
// and removing a file beside it, so that it checks what the writer will do (a new file and a
// rename into the directory).
std::string unwritable_reason(const std::string& path);

}  // namespace granbench
