// Version, commit, command line and time of a granbench process; see provenance.hpp.
#include "common/provenance.hpp"

#include <ctime>
#include <fstream>
#include <iterator>

#include "granbench_build_info.hpp"  // generated at build time (common/CMakeLists.txt)

namespace granbench {

namespace {
// A word as a POSIX shell reads it back: bare when it holds only safe characters, otherwise in
// single quotes (a quote inside written as '\'').
std::string shell_quoted(const std::string& word) {
  const bool safe = !word.empty() && word.find_first_not_of(
                                         "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                         "0123456789-_./:=+,%@") == std::string::npos;
  if (safe) return word;
  std::string q = "'";
  for (char c : word) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}
}  // namespace

std::string granbench_version() {
  return GRANBENCH_VERSION;
}

std::string granbench_git_commit() {
  return GRANBENCH_GIT_COMMIT;
}

std::string granbench_code_target() {
  return GRANBENCH_CODE_TARGET;  // defined for this file by common/CMakeLists.txt
}

std::string process_command_line() {
  std::ifstream in("/proc/self/cmdline", std::ios::binary);
  const std::string raw((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::string line, word;
  for (char c : raw) {
    if (c != '\0') {
      word += c;
      continue;
    }
    if (!line.empty()) line += ' ';
    line += shell_quoted(word);
    word.clear();
  }
  return line;
}

std::string utc_timestamp_now() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

}  // namespace granbench
