// Every HDF5 file granbench writes records how it was made and what it holds (qa.md: no output
// recorded the version, the command line, the date or units; three lacked their inputs): the root
// attributes granbench_version, git_commit, command_line and created (ISO 8601 UTC), the inputs
// (curve, material, angle and depth where the command has them), and `units` and `long_name` on
// every dataset. Each command's output is opened and checked; `--version` prints the version and
// the commit.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <string>

#include "common/hdf5_file.hpp"
#include "common/provenance.hpp"
#include "tests/support/run_granbench.hpp"
#include "tests/support/scratch_dir.hpp"

namespace {

using granbench::testing::run_granbench;
namespace fs = std::filesystem;
using granbench::testing::ScratchDir;
using namespace granbench;

struct Case {
  const char* name;
  const char* args;  // --out FILE is appended, or --out-dir DIR where `file` names the output
  bool has_slope;
  const char* file = nullptr;
};

const Case kCases[] = {
    {"wellposed", "wellposed --curve regularised", false},
    {"steady", "steady --angle 28.5 --h0 0.004", true},
    {"dispersion", "dispersion --Lx 0.08", true},
    {"dispersion_twod", "dispersion --theory twod --Lx 0.08", true},
    {"run_depthavg", "run --model depthavg --nx 40 --t-end 0.05", true},
    {"run_twod", "run --model twod --nx 40 --nz 16 --t-end 0.02", true},
    {"sweep", "sweep --model depthavg --nx 64 --jobs 1 --Lx 0.08:0.08:1", true},
    {"compare", "compare --nx 40 --nz 16 --nx-depthavg 40 --t-end 0.05", true},
    {"compare_saturated",
     "compare --saturated --nx 24 --nz 12 --nx-depthavg 40 --t-end 0.1 --window 0.05", true},
    {"case_layer", "case decelerating --resolution smoke", true, "decelerating.h5"},
};

class Provenance : public ::testing::TestWithParam<Case> {};

TEST_P(Provenance, EveryFileRecordsVersionCommandTimeInputsAndUnits) {
  const Case& c = GetParam();
  const ScratchDir scratch("gb_prov");
  const fs::path& dir = scratch.path();
  const std::string out = (dir / (c.file ? c.file : std::string(c.name) + ".h5")).string();
  const std::string where = c.file ? " --out-dir " + dir.string() : " --quiet --out " + out;
  const auto r = run_granbench(std::string(c.args) + " --json" + where, "prov");
  ASSERT_EQ(r.code, 0) << c.args << "\n" << r.err;
  ASSERT_TRUE(fs::exists(out));

  const auto text = [&](const char* key) { return h5_read_string_attribute(out, "/", key); };
  EXPECT_EQ(text("granbench_version"), granbench_version());
  EXPECT_FALSE(text("git_commit").empty());
  EXPECT_EQ(text("code_target"), granbench_code_target());
  const std::string line = text("command_line");
  EXPECT_NE(line.find("granbench"), std::string::npos) << line;
  EXPECT_NE(line.find(std::string(c.args).substr(0, std::string(c.args).find(' '))),
            std::string::npos)
      << line;
  EXPECT_NE(line.find(c.file ? "--out-dir " + dir.string() : "--out " + out), std::string::npos)
      << line;
  EXPECT_TRUE(std::regex_match(text("created"), std::regex(R"(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ)")))
      << text("created");

  EXPECT_FALSE(text("curve").empty());
  for (const char* key :
       {"mu_s", "mu_d", "I0", "d", "phi", "rho_star", "g", "mu_inf", "alpha", "h0"})
    EXPECT_TRUE(h5_has_attribute(out, "/", key)) << c.name << ": no root attribute " << key;
  if (c.has_slope) {
    EXPECT_TRUE(h5_has_attribute(out, "/", "angle_deg")) << c.name;
  }

  const auto sets = h5_dataset_paths(out);
  EXPECT_FALSE(sets.empty());
  for (const std::string& set : sets) {
    EXPECT_TRUE(h5_has_attribute(out, set, "units")) << c.name << ": " << set << " has no units";
    EXPECT_TRUE(h5_has_attribute(out, set, "long_name"))
        << c.name << ": " << set << " has no long_name";
  }
}

INSTANTIATE_TEST_SUITE_P(EachCommand, Provenance, ::testing::ValuesIn(kCases),
                         [](const auto& info) { return std::string(info.param.name); });

// The 2D step's Courant number, new to compare (thirty-seventh session), reaches its 2D run and
// is recorded with the inputs; above the VOF's 1/2, where the volume fractions sub-step.
TEST(Provenance, CompareRecordsTheCourantNumberItWasGiven) {
  const ScratchDir scratch("gb_prov_cfl");
  const fs::path& dir = scratch.path();
  const std::string out = (dir / "compare.h5").string();
  const std::string args = "compare --nx 16 --nz 8 --nx-depthavg 16 --t-end 1e-3 --cfl 0.8";
  const auto r = run_granbench(args + " --quiet --out " + out, "prov_cfl");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(h5_read_double_attribute(out, "/", "twod_cfl"), 0.8);
}

TEST(Version, PrintsTheVersionAndTheCommit) {
  const auto r = run_granbench("--version", "version");
  EXPECT_EQ(r.code, 0) << r.err;
  // the first line; then where it finds the files it ships (tests/analysis/cli/test_install.cpp)
  const std::string first = r.out.substr(0, r.out.find('\n') + 1);
  EXPECT_EQ(first, "granbench " + granbench_version() + " (commit " + granbench_git_commit() +
                       ", " + granbench_code_target() + " code)\n");
  EXPECT_EQ(r.out.find("cases: "), first.size()) << r.out;
}

}  // namespace
