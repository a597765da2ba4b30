// `compare --extrapolate` (twod_extrapolation.hpp), end to end: the 2D model runs again on half the
// cells across the layer (160 x 32 beside the default 160 x 64 at 8 cm), the JSON and the HDF5
// file carry the same extrapolated growth rate, inside its bounds and nearer the exact 2D theory
// than the default grid's (1.0754 against 1.0891 over this shorter run; the half grid 1.056); on
// two threads (the half grid beside the first 2D run) and on one (after it) alike.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "common/hdf5_file.hpp"
#include "tests/support/run_granbench.hpp"
#include "tests/support/scratch_dir.hpp"

namespace {

using granbench::testing::run_granbench;
namespace fs = std::filesystem;
using granbench::testing::ScratchDir;

TEST(CompareExtrapolate, TheHalfGridTakesTheDeficitOutOfTheGrowthRate) {
  const ScratchDir scratch("gb_cmp_extrap");
  const fs::path& dir = scratch.path();
  const std::string out = (dir / "c.h5").string();
  const auto r = run_granbench(
      "compare --Lx 0.08 --t-end 0.8 --extrapolate --json --quiet "
      "--threads 2 --out " +
          out + " --plot " + (dir / "c.png").string(),
      "cmp_extrap");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const double exact = j["exact_2d"]["growth_rate"], measured = j["twod"]["growth_rate"];
  const auto& e = j["twod"]["extrapolated"];
  ASSERT_TRUE(e["growth_rate"].is_number()) << e.dump();
  const double extrapolated = e["growth_rate"];
  EXPECT_EQ(e["half_cells_grid"], nlohmann::json({160, 32}));
  EXPECT_LT(double(e["growth_rate_half_cells"]), measured);
  EXPECT_GE(extrapolated, double(e["growth_rate_bounds"][0]));
  EXPECT_LE(extrapolated, double(e["growth_rate_bounds"][1]));
  EXPECT_LT(std::fabs(extrapolated - exact), 0.5 * std::fabs(measured - exact));
  EXPECT_EQ(granbench::h5_read_double_attribute(out, "twod", "extrapolated_growth_rate"),
            extrapolated);
  // On two threads the half grid runs beside the first 2D run, on one after it: the same numbers.
  const std::string out1 = (dir / "c1.h5").string();
  const auto r1 = run_granbench(
      "compare --Lx 0.08 --t-end 0.8 --extrapolate --json --quiet --threads 1 --out " + out1 +
          " --plot " + (dir / "c1.png").string(),
      "cmp_extrap1");
  ASSERT_EQ(r1.code, 0) << r1.err;
  const auto j1 = nlohmann::json::parse(r1.out);
  EXPECT_EQ(double(j1["twod"]["extrapolated"]["growth_rate"]), extrapolated);
  EXPECT_EQ(double(j1["twod"]["growth_rate"]), measured);
}

}  // namespace
