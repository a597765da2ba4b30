// Reproducibility from the output: `compare --json` gives, for each model, the `granbench run`
// command line that reproduces its run (analysis/comparison/run_command.hpp). Run alone, that
// command must report the same growth rate and phase speed to 1e-9 (relative): the same steps,
// the same series, the same measurement. A small 2D grid and a short run keep it to seconds; the
// Lx = 4 cm wave grows fast enough for both models to give a measured growth rate.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/run_granbench.hpp"
#include "tests/support/scratch_dir.hpp"

namespace {

using granbench::testing::run_granbench;

void expect_same_to_1e9(const nlohmann::json& a, const nlohmann::json& b, const char* key,
                        const std::string& model) {
  ASSERT_TRUE(a[key].is_number()) << model << " " << key << " not measured by compare: " << a;
  ASSERT_TRUE(b[key].is_number()) << model << " " << key << " not measured by run: " << b;
  const double x = a[key].get<double>(), y = b[key].get<double>();
  EXPECT_LE(std::fabs(x - y), 1e-9 * std::fabs(x))
      << model << " " << key << ": " << x << " vs " << y;
}

// `granbench compare ARGS --json --quiet` with its files in a directory of its own (removed after
// the run); the JSON, or an empty object (and a failure) if it did not exit 0.
nlohmann::json compare_json(const std::string& args, const std::string& tag) {
  const auto c = [&] {
    const granbench::testing::ScratchDir dir("gb_" + tag);
    return run_granbench("compare " + args + " --json --quiet --out " + (dir / "c.h5") +
                             " --plot " + (dir / "c.png"),
                         tag);
  }();
  EXPECT_EQ(c.code, 0) << c.err;
  return c.code == 0 ? nlohmann::json::parse(c.out) : nlohmann::json::object();
}

// A model's recorded run command, run alone, gives its growth rate and phase speed to 1e-9, on
// the same cells.
void expect_run_command_reproduces(const nlohmann::json& m, const std::string& model,
                                   const std::string& tag) {
  ASSERT_TRUE(m["run_command"].is_string()) << model;
  const std::string cmd = m["run_command"].get<std::string>();
  ASSERT_EQ(cmd.rfind("granbench run ", 0), 0u) << cmd;
  const auto r =
      run_granbench(cmd.substr(std::string("granbench ").size()) + " --json --quiet", tag);
  ASSERT_EQ(r.code, 0) << cmd << "\n" << r.err;
  const auto jr = nlohmann::json::parse(r.out);
  expect_same_to_1e9(m, jr, "growth_rate", model);
  expect_same_to_1e9(m, jr, "phase_speed", model);
  // and says which grid it took: compare's
  EXPECT_EQ(jr["cells"], m["cells"]) << model;
}

// compare's warning that the depth-averaged model limits its slopes; empty if there is none.
std::string limiter_warning(const nlohmann::json& jc) {
  for (const auto& w : jc["warnings"])
    if (w.get<std::string>().find("limits its slopes") != std::string::npos) return w;
  return "";
}

}  // namespace

TEST(RunCommand, EachModelsRunCommandReproducesItsGrowthRateAndPhaseSpeed) {
  const auto jc = compare_json("--Lx 0.04 --nx 32 --nz 16 --nx-depthavg 64 --t-end 1.2 --angle 29",
                               "run_command");
  ASSERT_FALSE(jc.empty());
  // the grids the runs took, as given
  EXPECT_EQ(jc["depthavg"]["cells"], nlohmann::json({64}));
  EXPECT_EQ(jc["twod"]["cells"], nlohmann::json({32, 16}));
  for (const std::string model : {"depthavg", "twod"})
    expect_run_command_reproduces(jc[model], model, "run_command_" + model);
}

// On a steep slope the seeded wave saturates within the run, so compare limits the
// depth-averaged slopes (DepthAvgSettings::limited_where_it_saturates): it says so, the command
// completes (with central slopes that run stalls at 1.05 s), and the run command it records names
// the limiter and reproduces the measurement.
TEST(RunCommand, ASaturatingDepthAveragedRunNamesItsLimiterAndIsReproduced) {
  const auto jc = compare_json("--angle 40 --Lx 0.08 --nx 32 --nz 16 --nx-depthavg 128 --t-end 1.5",
                               "run_command_steep");
  ASSERT_FALSE(jc.empty());
  const auto& m = jc["depthavg"];
  EXPECT_EQ(m["limiter"], "vanalbada");
  EXPECT_TRUE(m["completed"].get<bool>());
  EXPECT_FALSE(limiter_warning(jc).empty()) << jc["warnings"];
  ASSERT_NE(m["run_command"].get<std::string>().find("--limiter vanalbada"), std::string::npos)
      << m["run_command"];
  expect_run_command_reproduces(m, "depthavg", "run_command_steep_depthavg");
}

// A seed at or above the linear bound is said to start there (not to pass the bound at a negative
// time), and its depth-averaged run is limited too.
TEST(RunCommand, ASeedAboveTheLinearBoundIsSaidToStartThere) {
  const auto jc = compare_json("--Lx 0.08 --nx 32 --nz 16 --nx-depthavg 64 --t-end 0.1 --a0 4e-4",
                               "run_command_large_seed");
  ASSERT_FALSE(jc.empty());
  EXPECT_EQ(jc["depthavg"]["limiter"], "vanalbada");
  const std::string note = limiter_warning(jc);
  EXPECT_NE(note.find("starts at 0.1 h0"), std::string::npos) << note;
  EXPECT_EQ(note.find("t = -"), std::string::npos) << note;
}
