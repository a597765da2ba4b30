// Test support: a directory of its own for one test's files (header only; include by relative
// path). Shared by the tests that write outputs, checkpoints or configuration files.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>

namespace granbench::testing {

// A directory under the system's temporary directory, named after `name` and this process:
// ctest -j runs the tests of one executable as concurrent processes, which must not share files.
// It starts empty (a crashed earlier process of the same id may have left one) and is removed
// with everything in it when it goes out of scope, so an ASSERT that returns early leaves nothing
// behind either. The owner's permissions are restored first: a test may make it read-only.
class ScratchDir {
 public:
  explicit ScratchDir(const std::string& name)
      : path_(std::filesystem::temp_directory_path() / (name + "_" + std::to_string(getpid()))) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ignored;
    std::filesystem::permissions(path_, std::filesystem::perms::owner_all,
                                 std::filesystem::perm_options::add, ignored);
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::string str() const { return path_.string(); }
  // The path of `file` in the directory, as a string for a command line.
  std::string operator/(const std::string& file) const { return (path_ / file).string(); }

 private:
  std::filesystem::path path_;
};

}  // namespace granbench::testing
