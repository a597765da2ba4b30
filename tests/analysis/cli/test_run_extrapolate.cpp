// `run --model twod --extrapolate`, end to end: after the run (160 x 64 at 8 cm, the defaults),
// the same wave runs on half the cells across the layer. That second run is the one `run --nz 32`
// makes (the surface mid-cell again, the same sampling): its growth rate is the same number, bit
// for bit. The
// extrapolation is the deficit law's Richardson step on the pair, inside its bounds, nearer the
// exact 2D theory than the run's own growth, and stored in the output file's results as printed.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "analysis/comparison/growth_deficit_law.hpp"
#include "common/hdf5_file.hpp"
#include "tests/support/run_granbench.hpp"
#include "tests/support/scratch_dir.hpp"

namespace {

using granbench::testing::run_granbench;
namespace fs = std::filesystem;
using granbench::testing::ScratchDir;

TEST(RunExtrapolate, TheHalfGridIsTheRunOnHalfTheCellsAndTakesTheDeficitOut) {
  const ScratchDir scratch("gb_run_extrap");
  const fs::path& dir = scratch.path();
  const std::string wave =
      "run --model twod --Lx 0.08 --init eigenmode --a0 1e-6 --t-end 0.8 "
      "--threads 2 --json --quiet";
  const std::string out = (dir / "r.h5").string();
  const auto r = run_granbench(wave + " --extrapolate --out " + out, "run_extrap");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const double exact = j["growth_rate_theory"], measured = j["growth_rate"];
  const auto& e = j["extrapolated"];
  ASSERT_TRUE(e["growth_rate"].is_number()) << e.dump();
  EXPECT_EQ(e["half_cells_grid"], nlohmann::json({160, 32}));

  // (the run's steps land on its snapshot times; the half grid writes none, so its twin writes
  // one, at the end)
  const auto half = run_granbench(
      wave + " --nz 32 --dt-snapshot 0.8 --out " + (dir / "h.h5").string(), "run_half");
  ASSERT_EQ(half.code, 0) << half.err;
  EXPECT_EQ(double(e["growth_rate_half_cells"]),
            double(nlohmann::json::parse(half.out)["growth_rate"]));

  const double extrapolated = e["growth_rate"];
  EXPECT_EQ(extrapolated, granbench::extrapolate_growth_in_dz(
                              measured, double(e["growth_rate_half_cells"]), double(e["dz_ratio"]))
                              .value);
  EXPECT_GE(extrapolated, double(e["growth_rate_bounds"][0]));
  EXPECT_LE(extrapolated, double(e["growth_rate_bounds"][1]));
  EXPECT_LT(std::fabs(extrapolated - exact), 0.5 * std::fabs(measured - exact));
  const auto stored =
      nlohmann::json::parse(granbench::h5_read_string_attribute(out, "/", "results_json"));
  EXPECT_EQ(stored["extrapolated"], e);

  // Without the option the key is there and null, and the run is the same.
  const auto plain = run_granbench(wave + " --out " + (dir / "p.h5").string(), "run_plain");
  ASSERT_EQ(plain.code, 0) << plain.err;
  const auto p = nlohmann::json::parse(plain.out);
  EXPECT_TRUE(p["extrapolated"].is_null());
  EXPECT_EQ(double(p["growth_rate"]), measured);
}

}  // namespace
