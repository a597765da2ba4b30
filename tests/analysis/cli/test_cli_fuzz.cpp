// Fuzzing the command line: each subcommand, from a cheap valid start, with one to three of its
// options given random values (valid, at the edges, and not numbers at all). Whatever the values,
// granbench must end with exit 0 (ran), 2 (refused, one line) or 3 (the run failed, reported) —
// never a signal, never exit 1 (an internal error). The seed is fixed, so a failure repeats; each
// case is listed with its command line. Each command runs under `timeout` so a hang is a failure
// (exit 124) rather than a stuck suite.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "tests/support/run_granbench.hpp"
#include "tests/support/scratch_dir.hpp"

namespace {

using granbench::testing::run_granbench;

struct Command {
  std::string base;                  // a cheap valid invocation
  std::vector<std::string> options;  // options to fuzz
};

const std::vector<Command> kCommands = {
    {"wellposed --json", {"--curve", "--mu-s", "--mu-d", "--I0", "--alpha", "--mu-inf", "--h0"}},
    {"steady --json",
     {"--curve", "--angle", "--h0", "--mu-s", "--mu-d", "--I0", "--d", "--phi", "--mu-inf",
      "--alpha", "--kk-mu0", "--hm-c"}},
    {"dispersion --json", {"--curve", "--angle", "--h0", "--Lx", "--theory", "--mu-d"}},
    {"run --model depthavg --nx 40 --t-end 0.05 --json --quiet",
     {"--angle", "--h0", "--Lx", "--nx", "--a0", "--mode", "--t-end", "--dt-out", "--chi",
      "--limiter", "--frame-speed", "--curve"}},
    {"run --model twod --nx 24 --nz 12 --t-end 0.01 --json --quiet",
     {"--angle", "--h0", "--Lx", "--nx", "--nz", "--a0", "--t-end", "--dt-out", "--curve"}},
    {"sweep --model depthavg --nx 32 --jobs 1 --Lx 0.08:0.08:1 --json --quiet",
     {"--angle", "--h0", "--Lx", "--nx", "--seed-tolerance", "--t-end", "--chi", "--frame-speed",
      "--model", "--curve"}},
    {"compare --nx 24 --nz 12 --nx-depthavg 40 --t-end 0.02 --json --quiet",
     {"--angle", "--h0", "--Lx", "--nx", "--nz", "--nx-depthavg", "--t-end", "--a0", "--curve"}},
    {"compare --saturated --nx 24 --nz 12 --nx-depthavg 40 --t-end 0.1 --window 0.05 --json "
     "--quiet",
     {"--window", "--a0", "--init", "--Lx", "--h0", "--dt-out"}},
    {"case --list", {"--resolution", "--jobs"}},
};

const std::vector<std::string> kValues = {
    "0",    "-1",      "nan",    "inf",         "-inf",        "1e400",        "abc",      "''",
    "0x1E", "1e-300",  "0.5",    "3",           "28.5",        "29.1",         "0.004",    "0.08",
    "1",    "2",       "jop",    "regularised", "low-i",       "kamrin-koval", "holyoake", "twod",
    "both", "bagnold", "linear", "mc",          "0.01:0.02:2", "1e9",          "65537",    "-0",
    "1e-9", "90",      "5"};

TEST(CliFuzz, EveryEndIsExitZeroTwoOrThree) {
  // GRANBENCH_FUZZ_SEED and GRANBENCH_FUZZ_CASES explore further; the defaults are what CI runs.
  const char* seed = std::getenv("GRANBENCH_FUZZ_SEED");
  const char* cases = std::getenv("GRANBENCH_FUZZ_CASES");
  std::mt19937 rng(seed ? std::stoul(seed) : 20261201u);
  const int kCases = cases ? std::stoi(cases) : 200;
  const granbench::testing::ScratchDir scratch("gb_fuzz");
  const std::string dir = scratch.str();
  for (int n = 0; n < kCases; ++n) {
    const Command& c = kCommands[rng() % kCommands.size()];
    std::string args = c.base;
    const int changes = 1 + static_cast<int>(rng() % 3);
    for (int k = 0; k < changes; ++k)
      args += " " + c.options[rng() % c.options.size()] + " " + kValues[rng() % kValues.size()];
    const auto r = run_granbench(args, "fuzz", "cd " + dir + " && timeout -s KILL 60 ");
    const bool allowed = r.code == 0 || r.code == 2 || r.code == 3;
    EXPECT_TRUE(allowed) << "case " << n << ": granbench " << args << "\nexit "
                         << (r.code < 0 ? std::string("by a signal") : std::to_string(r.code))
                         << (r.code == 137 ? " (killed after 60 s)" : "") << "\n"
                         << r.err;
    if (r.code == 2) {
      EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << args << "\n" << r.err;
    }
  }
}

}  // namespace
