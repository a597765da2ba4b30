// flock(2) on "<path>.lock"; see output_lock.hpp.
#include "common/output_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>

namespace granbench {

OutputLock::OutputLock(const std::string& output_path) : lock_path_(output_path + ".lock") {
  // A holder that is finishing removes the file after unlocking it; a lock taken on that removed
  // file would protect nothing, so the file is opened again until the one locked is the one at
  // the path.
  for (;;) {
    fd_ = ::open(lock_path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0)
      throw std::runtime_error("cannot create the lock file " + lock_path_ + ": " +
                               std::strerror(errno));
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      const int err = errno;
      std::string holder;
      std::ifstream(lock_path_) >> holder;
      ::close(fd_);
      fd_ = -1;
      if (err == EWOULDBLOCK)
        throw LockHeld(lock_path_ + " is held by another granbench process" +
                       (holder.empty() ? "" : " (pid " + holder + ")"));
      throw std::runtime_error("cannot lock " + lock_path_ + ": " + std::strerror(err));
    }
    struct stat at_path {
    }, locked{};
    if (::stat(lock_path_.c_str(), &at_path) == 0 && ::fstat(fd_, &locked) == 0 &&
        at_path.st_ino == locked.st_ino && at_path.st_dev == locked.st_dev)
      break;
    ::close(fd_);
  }
  // The holder's pid, for the message the next process prints.
  const std::string pid = std::to_string(::getpid()) + "\n";
  const bool recorded = ::ftruncate(fd_, 0) == 0 &&
                        ::write(fd_, pid.data(), pid.size()) == static_cast<ssize_t>(pid.size());
  (void)recorded;  // only informative: the lock holds either way
}

OutputLock::~OutputLock() {
  if (fd_ < 0) return;
  ::unlink(lock_path_.c_str());  // while still holding it: see the constructor
  ::close(fd_);
}

}  // namespace granbench
