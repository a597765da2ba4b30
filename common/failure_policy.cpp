// The failure policy of failure_policy.hpp: the signal guard, the exit-code table, the path probe.
#include "common/failure_policy.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace granbench {

namespace {

// A signal handler can reach only static storage: these two are the process's whole signal
// state (the flag for the solvers' loops, the number for the exit code).
std::atomic<bool>& interrupt_flag() {
  static std::atomic<bool> flag{false};
  return flag;
}
volatile std::sig_atomic_t& caught_signal() {
  static volatile std::sig_atomic_t sig = 0;
  return sig;
}
extern "C" void on_stop_signal(int sig) {
  caught_signal() = sig;
  interrupt_flag().store(true);
}
using Handler = void (*)(int);
Handler& previous_handler(int sig) {
  static Handler on_int = SIG_DFL, on_term = SIG_DFL;
  return sig == SIGTERM ? on_term : on_int;
}

}  // namespace

InterruptGuard::InterruptGuard(Signals signals) : term_(signals == Signals::IntAndTerm) {
  interrupt_flag().store(false);
  caught_signal() = 0;
  previous_handler(SIGINT) = std::signal(SIGINT, on_stop_signal);
  if (term_) previous_handler(SIGTERM) = std::signal(SIGTERM, on_stop_signal);
}

InterruptGuard::~InterruptGuard() {
  if (term_) std::signal(SIGTERM, previous_handler(SIGTERM));
  std::signal(SIGINT, previous_handler(SIGINT));
}

const std::atomic<bool>* InterruptGuard::flag() const {
  return &interrupt_flag();
}

int InterruptGuard::signal() const {
  return caught_signal();
}

int InterruptGuard::exit_code() const {
  const int sig = caught_signal();
  return sig != 0 ? 128 + sig : kExitSigint;
}

std::string unwritable_reason(const std::string& path) {
  namespace fs = std::filesystem;
  if (path.empty()) return "empty file name";
  const fs::path p(path);
  std::error_code ec;
  if (fs::is_directory(p, ec)) return std::strerror(EISDIR);
  const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
  // Built by append: GCC 12 warns (-Wrestrict, a false positive) on "." + string + ...
  std::string name = ".";
  name.append(p.filename().string()).append(".probe-").append(std::to_string(getpid()));
  const fs::path probe = dir / name;
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0600);
  if (fd < 0) return std::strerror(errno);
  ::close(fd);
  ::unlink(probe.c_str());
  return {};
}

}  // namespace granbench
