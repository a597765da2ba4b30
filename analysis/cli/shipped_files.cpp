// The shipped files' directories; see shipped_files.hpp.
#include "analysis/cli/shipped_files.hpp"

#include <filesystem>
#include <system_error>

namespace granbench::cli {

namespace {
// <prefix>/<relative> where the program runs from <prefix>/bin and that path exists (`is_there`
// checks it); otherwise `build_tree_path` (the build tree's program).
template <class IsThere>
std::string installed_or(const std::filesystem::path& relative, const char* build_tree_path,
                         IsThere&& is_there) {
  std::error_code ec;
  const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const auto installed = program.parent_path().parent_path() / relative;
    if (is_there(installed, ec)) return installed.string();
  }
  return build_tree_path;
}

// <prefix>/share/granbench/<kind>, or `source_tree_dir`.
std::string shipped_dir(const char* kind, const char* source_tree_dir) {
  return installed_or(std::filesystem::path("share") / "granbench" / kind, source_tree_dir,
                      [](const auto& p, auto& ec) { return std::filesystem::is_directory(p, ec); });
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
  return installed_or(
      std::filesystem::path("lib") / "granbench" / "libgranbench_mpi.so", GRANBENCH_MPI_MODULE,
      [](const auto& p, auto& ec) { return std::filesystem::is_regular_file(p, ec); });
}
#endif

}  // namespace granbench::cli
