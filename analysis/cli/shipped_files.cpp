// The shipped files' directories; see shipped_files.hpp.
#include "analysis/cli/shipped_files.hpp"

#include <filesystem>
#include <system_error>

namespace granbench::cli {

namespace {
// <prefix>/share/granbench/<kind> where the program runs from <prefix>/bin and that directory
// exists; otherwise `source_tree_dir` (the build tree's program).
std::string shipped_dir(const char* kind, const char* source_tree_dir) {
  std::error_code ec;
  const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const auto installed = program.parent_path().parent_path() / "share" / "granbench" / kind;
    if (std::filesystem::is_directory(installed, ec)) return installed.string();
  }
  return source_tree_dir;
}
}  // namespace

std::string shipped_cases_dir() {
  return shipped_dir("cases", GRANBENCH_CASES_DIR);
}

std::string shipped_plot_dir() {
  return shipped_dir("plots", GRANBENCH_PLOT_DIR);
}

#ifdef GRANBENCH_MPI_MODULE
std::string shipped_mpi_module() {
  std::error_code ec;
  const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const auto installed =
        program.parent_path().parent_path() / "lib" / "granbench" / "libgranbench_mpi.so";
    if (std::filesystem::is_regular_file(installed, ec)) return installed.string();
  }
  return GRANBENCH_MPI_MODULE;
}
#endif

}  // namespace granbench::cli
