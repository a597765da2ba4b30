// Test support: run the granbench command of this build tree and capture its exit code, stdout
// and stderr. Shared by the end-to-end CLI tests (header only; include by relative path).
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>

namespace granbench::testing {

struct CommandResult {
  int code = -1;
  std::string out, err;
};

// Runs the shell command `cmd` with its stderr in a file in the temporary directory named after
// `tag`, this process and the call, removed after reading. (Named after `tag` alone, the file was
// shared by the tests of one suite, which ctest -j runs as concurrent processes: one test once
// read the other's stderr.)
inline CommandResult run_shell(const std::string& cmd, const std::string& tag) {
  static int calls = 0;  // tests call this from their main thread only
  const auto errfile = std::filesystem::temp_directory_path() /
                       ("granbench_" + tag + "_" + std::to_string(getpid()) + "_" +
                        std::to_string(++calls) + "_err.txt");
  CommandResult r;
  FILE* p = popen((cmd + " 2>" + errfile.string()).c_str(), "r");
  std::array<char, 4096> buf{};
  while (p && fgets(buf.data(), buf.size(), p)) r.out += buf.data();
  const int status = p ? pclose(p) : -1;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  FILE* e = fopen(errfile.c_str(), "r");
  while (e && fgets(buf.data(), buf.size(), e)) r.err += buf.data();
  if (e) fclose(e);
  std::error_code ignored;
  std::filesystem::remove(errfile, ignored);
  return r;
}

// `args` is appended to the path of the granbench binary of this build tree, which follows
// `launcher` (e.g. "mpirun -np 2 ", empty: none).
inline CommandResult run_granbench(const std::string& args, const std::string& tag = "cli",
                                   const std::string& launcher = "") {
  return run_shell(launcher + std::string(GRANBENCH_BINARY_DIR) + "/granbench " + args, tag);
}

}  // namespace granbench::testing
