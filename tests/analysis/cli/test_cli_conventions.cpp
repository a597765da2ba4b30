// Conventions of the command line (qa.md, "Misleading" and "Conventions"): an unknown command is
// named with a suggestion; --help shows examples and the exit codes; mu_s >= mu_d is refused;
// --mu-inf has a validator and its errors name it; options that do not apply to the sweep's
// model are refused, not ignored; a case directory that is not there is refused.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "tests/support/run_granbench.hpp"

namespace {

using granbench::testing::run_granbench;

granbench::testing::CommandResult run(const std::string& args) {
  return run_granbench(args, "conventions");
}

// Exit 2 with one line that starts "granbench: error: " + `start` and holds `parts`.
void expect_refused(const std::string& args, const std::string& start,
                    const std::vector<std::string>& parts = {}) {
  const auto r = run(args);
  EXPECT_EQ(r.code, 2) << args << "\n" << r.err;
  EXPECT_EQ(r.err.rfind("granbench: error: " + start, 0), 0u) << args << "\n" << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
  for (const auto& p : parts) EXPECT_NE(r.err.find(p), std::string::npos) << p << " in " << r.err;
}

TEST(CliConventions, AnUnknownCommandIsNamedWithASuggestion) {
  expect_refused("stead --angle 30", "unknown command 'stead'", {"(did you mean 'steady'?)"});
  expect_refused("sweeep", "unknown command 'sweeep'", {"(did you mean 'sweep'?)"});
  expect_refused("frobnicate", "unknown command 'frobnicate'", {"steady"});
}

TEST(CliConventions, HelpShowsExamplesAndExitCodes) {
  for (const std::string cmd : {"", "steady ", "wellposed ", "dispersion ", "sweep "}) {
    const auto r = run(cmd + "--help");
    EXPECT_EQ(r.code, 0) << cmd;
    EXPECT_NE(r.out.find("Examples:\n  granbench "), std::string::npos) << cmd << r.out;
    EXPECT_NE(r.out.find("Exit codes:"), std::string::npos) << cmd << r.out;
    EXPECT_NE(r.out.find("  2    bad input"), std::string::npos) << cmd << r.out;
  }
  const auto top = run("--help");
  for (const char* code : {"  3 ", "  130 ", "  143 "})
    EXPECT_NE(top.out.find(code), std::string::npos) << code;
}

TEST(CliConventions, FrictionCoefficientsAreChecked) {
  expect_refused("steady --mu-s 0.6 --mu-d 0.5", "--mu-s", {"--mu-d", "mu_s < mu_d"});
  expect_refused("steady --mu-s 0.5 --mu-d 0.5", "--mu-s");
  expect_refused("steady --mu-inf -5", "--mu-inf", {"valid range"});
  expect_refused("steady --mu-inf nan", "--mu-inf", {"valid range"});
}

// Counts and fractions bounded on both sides say so in the words of every other option (they
// said CLI11's "Value 3 not in range 4 to 4096"), with whole bounds in full; --mode names nx/2.
TEST(CliConventions, BoundedOptionsNameTheirIntervals) {
  expect_refused("run --model twod --nz 3", "--nz: value 3 out of range",
                 {"valid range [4, 4096]"});
  expect_refused("run --nx 7", "--nx: value 7 out of range", {"valid range [8, 1048576]"});
  expect_refused("compare --nx 70000", "--nx: value 70000 out of range", {"[8, 65536]"});
  expect_refused("run --noise 0.5", "--noise: value 0.5 out of range", {"valid range [0, 0.5)"});
  expect_refused("sweep --jobs 0", "--jobs: value 0 out of range", {"valid range [1, 256]"});
  expect_refused("run --model twod --twod-frame 1.5", "--twod-frame:", {"valid range [0, 1]"});
  // the 2D Courant number: the same interval in run, compare and sweep
  expect_refused("run --model twod --cfl 1", "--cfl: value 1 out of range", {"(0, 1)"});
  expect_refused("compare --cfl 0", "--cfl: value 0 out of range", {"(0, 1)"});
  expect_refused("sweep --model twod --Lx 0.08:0.08:1 --cfl 1.5", "--cfl:", {"(0, 1)"});
  expect_refused("sweep --model depthavg --Lx 0.08:0.08:1 --cfl 0.8", "--cfl: does not apply",
                 {"--model twod or --model both"});
  expect_refused("run --model twod --nz abc", "--nz: 'abc' is not a number", {"[4, 4096]"});
  expect_refused("run --mode 0", "--mode: value 0 out of range", {"valid range [1, nx/2]"});
  expect_refused("run --mode 200", "--mode: value 200 out of range", {"[1, nx/2] (nx = 256)"});
  expect_refused("run --mode 2.5", "--mode: '2.5' is not a whole number", {"[1, nx/2]"});
  expect_refused("run --model twod --nz 40.5", "--nz: '40.5' is not a whole number", {"[4, 4096]"});
  // (CLI11's own check printed the largest double in full)
  expect_refused("run --a0 -1", "--a0: value -1 out of range", {"valid range [0, inf)"});
  expect_refused("run --model twod --checkpoint-every -1", "--checkpoint-every:", {"[0, inf)"});
}

TEST(CliConventions, SweepOptionsThatDoNotApplyToTheModelAreRefused) {
  const std::string sweep = "sweep --Lx 0.08:0.08:1 --jobs 1 ";
  expect_refused(sweep + "--model twod --nx 64", "--nx: does not apply to --model twod");
  expect_refused(sweep + "--model twod --seed-tolerance 1e-5", "--seed-tolerance: does not apply");
  expect_refused(sweep + "--model both --limiter minmod", "--limiter: does not apply");
  expect_refused(sweep + "--model depthavg --viscosity-passes 2",
                 "--viscosity-passes: does not apply to --model depthavg", {"--model twod"});
  expect_refused(sweep + "--model depthavg --resolution coarse", "--resolution: does not apply");
}

}  // namespace

// compare's grids and cases that no run can take are refused before any work (qa.md: compare
// --nx 1 and huge grids ended in late internal errors or bad_alloc; jop at 29.1 deg and a 1e9 m
// domain in exit 1), and so is a 2D output name that ParaView's XDMF readers cannot open.
TEST(CliConventions, ImpossibleGridsCasesAndFileNamesAreRefusedUpFront) {
  const std::string dir = ::testing::TempDir();
  const std::string quick =
      " --t-end 0.05 --quiet --out " + dir + "gb_conv_c.h5 --plot " + dir + "gb_conv_c.png";
  expect_refused("compare --nx 1" + quick, "--nx:", {"8"});
  expect_refused("compare --nx 60000 --nz 4000" + quick, "--nx:", {"nx * nz"});
  expect_refused("compare --curve jop --angle 29.1 --Lx 0.08" + quick, "--Lx:", {"2D linear"});
  expect_refused("compare --Lx 1e9 --h0 29.1" + quick, "--Lx:", {"2D linear"});
  expect_refused("run --model twod --t-end 0.01 --quiet --out 'a b.h5'", "--out:", {"white space"});
  // an extrapolation from a half grid below the deficit law's range (growth_deficit_law.hpp)
  expect_refused("compare --extrapolate --resolution coarse" + quick,
                 "--extrapolate:", {"7.5 per h0", "--nz 64 or more"});
  expect_refused("compare --extrapolate --nz 40" + quick, "--extrapolate:", {"9.5 per h0"});
  expect_refused("compare --extrapolate --saturated" + quick,
                 "--extrapolate: not with --saturated");
  expect_refused("sweep --model twod --resolution coarse --extrapolate --jobs 1",
                 "--extrapolate: not with --resolution coarse");
  expect_refused("sweep --model depthavg --extrapolate --jobs 1",
                 "--extrapolate: does not apply to --model depthavg");
  EXPECT_FALSE(std::filesystem::exists(dir + "gb_conv_c.h5"));
  const std::string run_quick = " --t-end 0.05 --quiet --out " + dir + "gb_conv_r.h5";
  expect_refused("run --model twod --extrapolate --nz 16" + run_quick,
                 "--extrapolate:", {"3.5 per h0", "--nz 64 or more"});
  expect_refused("run --model twod --extrapolate --mode 2" + run_quick,
                 "--extrapolate: needs --mode 1");
  expect_refused("run --model depthavg --extrapolate" + run_quick,
                 "--extrapolate: applies to --model twod only");
  EXPECT_FALSE(std::filesystem::exists(dir + "gb_conv_r.h5"));
  // a case directory that is not there (the default is compiled in: a moved source tree) is bad
  // input, not an internal error
  expect_refused("case --list --cases-dir " + dir + "gb_conv_no_cases",
                 "--cases-dir:", {"not a directory"});
  expect_refused(
      "case rollwave-8cm --out-dir " + dir + "gb_conv_case --cases-dir " + dir + "gb_conv_no_cases",
      "--cases-dir:");
  EXPECT_FALSE(std::filesystem::exists(dir + "gb_conv_case"));
}

// run: an option of the other model is refused, not silently ignored (qa.md: sweep --model twod
// ignored --nx and --tolerance; run did the same with every model option).
TEST(CliConventions, RunRefusesTheOptionsOfTheOtherModel) {
  expect_refused("run --model twod --t-end 0.01 --rtol 1e-5",
                 "--rtol: applies to --model depthavg");
  expect_refused("run --model twod --t-end 0.01 --chi 1.25", "--chi: applies to --model depthavg");
  expect_refused("run --model depthavg --t-end 0.01 --nz 16", "--nz: applies to --model twod");
  expect_refused("run --t-end 0.01 --eta-max 1", "--eta-max: applies to --model twod");
}
