// An installed granbench (`cmake --install`) runs without its source and build trees: it finds
// its case files and plotting scripts under <prefix>/share/granbench (shipped_files.hpp), and its
// MPI module, when built, under <prefix>/lib/granbench; the build tree's command still finds them
// in the source and build trees.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "tests/support/run_granbench.hpp"
#include "tests/support/scratch_dir.hpp"

namespace {

using granbench::testing::run_shell;
namespace fs = std::filesystem;
using granbench::testing::ScratchDir;

TEST(Install, TheInstalledCommandFindsItsCasesAndPlotsUnderItsPrefix) {
  const ScratchDir scratch("granbench_install");
  const fs::path& prefix = scratch.path();
  const auto installed = run_shell(std::string(GRANBENCH_CMAKE_COMMAND) + " --install " +
                                       GRANBENCH_BINARY_DIR + " --prefix " + prefix.string(),
                                   "install");
  ASSERT_EQ(installed.code, 0) << installed.out << installed.err;
  const std::string program = (prefix / "bin" / "granbench").string();
  const fs::path share = prefix / "share" / "granbench";
  ASSERT_TRUE(fs::exists(program));
  EXPECT_TRUE(fs::exists(share / "cases" / "rollwave-8cm.toml"));
  EXPECT_TRUE(fs::exists(share / "plots" / "dispersion.py"));
#ifdef GRANBENCH_MPI_MODULE_NAME
  EXPECT_TRUE(fs::exists(prefix / "lib" / "granbench" / GRANBENCH_MPI_MODULE_NAME));
#endif

  const auto version = run_shell(program + " --version", "install_version");
  ASSERT_EQ(version.code, 0) << version.err;
  EXPECT_NE(version.out.find("cases: " + (share / "cases").string()), std::string::npos)
      << version.out;
  EXPECT_NE(version.out.find("plots: " + (share / "plots").string()), std::string::npos)
      << version.out;

  const auto list = run_shell(program + " case --list", "install_list");
  ASSERT_EQ(list.code, 0) << list.err;
  EXPECT_NE(list.out.find("rollwave-8cm"), std::string::npos) << list.out;

  // a figure drawn by the installed script, from a directory of its own
  const fs::path work = prefix / "work";
  fs::create_directories(work);
  const auto plot = run_shell("cd " + work.string() + " && " + program +
                                  " dispersion --Lx 0.08 --out d.h5 --plot d.png --quiet",
                              "install_plot");
  ASSERT_EQ(plot.code, 0) << plot.out << plot.err;
  EXPECT_TRUE(fs::exists(work / "d.png"));
}

TEST(Install, TheBuildTreesCommandFindsThemInTheSourceTree) {
  const auto version = granbench::testing::run_granbench("--version", "install_build_version");
  ASSERT_EQ(version.code, 0) << version.err;
  const fs::path source = GRANBENCH_SOURCE_DIR;
  EXPECT_NE(version.out.find("cases: " + (source / "cases").string()), std::string::npos)
      << version.out;
  EXPECT_NE(version.out.find("plots: " + (source / "analysis" / "plots").string()),
            std::string::npos)
      << version.out;
}

// What the command loads at every start (docs/performance.md, forty-fifth session): no MPI library
// (its calls are in the module that only a process started by mpirun loads) and, with
// GRANBENCH_STATIC_LIBS, none of the libraries linked from their archives.
TEST(Install, TheCommandLoadsNoMpiAndNoArchivedLibraryAtItsStart) {
  const auto libraries =
      run_shell(std::string("ldd ") + GRANBENCH_BINARY_DIR + "/granbench", "install_ldd");
  ASSERT_EQ(libraries.code, 0) << libraries.err;
  EXPECT_EQ(libraries.out.find("libmpi"), std::string::npos) << libraries.out;
#ifdef GRANBENCH_STATIC_LIBS_ON
  for (const char* archived : {"libsundials", "libfftw3", "libgsl", "libsz", "libz.", "libstdc++"})
    EXPECT_EQ(libraries.out.find(archived), std::string::npos) << archived << "\n" << libraries.out;
#endif
}

}  // namespace
