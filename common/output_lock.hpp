// An exclusive claim on an output file for the life of a process: flock(2) on "<path>.lock",
// taken without waiting. Two granbench processes writing one sweep would otherwise overwrite
// each other's points (each rewrites the whole file from what it read at its start); the second
// is refused instead. The kernel drops the lock when the process ends however it ends, so a
// killed run leaves no stale claim, only an unlocked file that the next run takes over.
#pragma once

#include <stdexcept>
#include <string>

namespace granbench {

class OutputLock {
 public:
  // Throws LockHeld when another process holds it, std::runtime_error (with the OS reason) when
  // the lock file cannot be created.
  explicit OutputLock(const std::string& output_path);
  ~OutputLock();  // releases the lock and removes the lock file
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;

  const std::string& lock_path() const { return lock_path_; }

  struct LockHeld : std::runtime_error {
    using std::runtime_error::runtime_error;
  };

 private:
  std::string lock_path_;
  int fd_ = -1;
};

}  // namespace granbench
