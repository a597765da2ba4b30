// `granbench dispersion --theory twod` end to end: the documented JSON (growth rate and phase
// speed of the surface mode, convergence check, unstable branches, the cutoff, ill-posedness
// probe), agreement with the library, the warning for an ill-posed base state, and bad input (exit
// 2, one line naming the option, no output file); the --light-layer options and output.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>

#include "analysis/linear2d/linear_stability_2d.hpp"
#include "tests/support/run_granbench.hpp"
#include "tests/support/scratch_dir.hpp"

namespace {
granbench::testing::CommandResult run(const std::string& args) {
  return granbench::testing::run_granbench(args, "linear2d");
}
}  // namespace

TEST(Linear2DCli, TwoDTheoryJsonCarriesTheConvergenceCheck) {
  const auto r = run("dispersion --theory twod --angle 28.5 --h0 0.004 --Lx 0.08 --Lx 0.02 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["theory"], "twod");
  ASSERT_EQ(j["modes"].size(), 2u);
  const auto& m = j["modes"][0];
  // Same numbers as the library call.
  using namespace granbench;
  const MuCurve c(CurveKind::Regularised, Material{}, 4e-3);
  const auto lib = linear_stability_2d(steady_state(c, degrees_to_radians(28.5), 4e-3), c, 0.08);
  EXPECT_NEAR(m["growth_rate"].get<double>(), lib.surface.growth_rate, 1e-10);
  EXPECT_NEAR(m["phase_speed"].get<double>(), lib.surface.phase_speed, 1e-10);
  EXPECT_TRUE(m["surface_mode"].get<bool>());
  EXPECT_EQ(m["convergence"]["N"], 32);
  EXPECT_EQ(m["convergence"]["N_check"], 48);
  EXPECT_LT(m["convergence"]["relative_difference"].get<double>(), 1e-8);
  EXPECT_NEAR(m["convergence"]["growth_rate_check"].get<double>(), 1.089143, 1e-5);
  EXPECT_EQ(m["unstable_branches"].size(), 1u);
  // At 2 cm the slow branch is listed too, first (largest growth).
  const auto& b = j["modes"][1]["unstable_branches"];
  ASSERT_EQ(b.size(), 2u);
  EXPECT_FALSE(b[0]["surface_mode"].get<bool>());
  EXPECT_NEAR(b[0]["phase_speed"].get<double>(), 0.3195, 1e-3);
  EXPECT_NEAR(j["F_critical"].get<double>(), 0.6076, 5e-4);
  EXPECT_FALSE(j["ill_posedness"]["ill_posed_base_state"].get<bool>());
  // The cutoff: the library's, as a length by (7.13b), converged between N = 32 and 48.
  const auto kc = linear2d::surface_mode_cutoff_k_hat(lib.base, 32);
  ASSERT_TRUE(kc.has_value());
  EXPECT_NEAR(j["cutoff_k_hat"].get<double>(), *kc, 1e-12);
  EXPECT_NEAR(j["cutoff_Lx"].get<double>(), 2.0 * std::numbers::pi * 4e-3 / *kc, 1e-15);
  EXPECT_LT(j["cutoff_relative_difference"].get<double>(), 1e-4);
}

TEST(Linear2DCli, IllPosedBaseStateIsReported) {
  const auto r =
      run("dispersion --theory twod --curve jop --angle 28.5 --h0 0.004 --Lx 0.08 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["ill_posedness"]["ill_posed_base_state"].get<bool>());
  EXPECT_GT(j["ill_posedness"]["C"].get<double>(), 0.0);
  EXPECT_NE(r.err.find("ill posed"), std::string::npos) << r.err;
}

TEST(Linear2DCli, BadResolutionIsRejectedWithoutOutput) {
  const granbench::testing::ScratchDir dir("gb_linear2d_bad");
  const std::string out = dir / "out.h5";
  const auto r = run("dispersion --theory twod --Lx 0.08 --chebyshev 4 --out " + out);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--chebyshev"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("[8, 160]"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(Linear2DCli, LightLayerJsonCarriesTheFluidModes) {
  const auto r =
      run("dispersion --theory twod --Lx 0.02 --light-layer --rho-light 1.5 --eta-light 1e-3 --Lz "
          "0.008 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_DOUBLE_EQ(j["light_layer"]["rho_light"].get<double>(), 1.5);
  EXPECT_DOUBLE_EQ(j["light_layer"]["Lz"].get<double>(), 0.008);
  EXPECT_NEAR(j["light_layer"]["density_ratio"].get<double>(), 1e-3, 1e-15);
  const auto& m = j["modes"][0];
  const auto& l = m["light_layer"];
  EXPECT_TRUE(l["surface_mode"].get<bool>());
  EXPECT_LT(l["relative_difference"].get<double>(), 1e-6);
  EXPECT_NEAR(l["growth_rate_difference"].get<double>(),
              l["growth_rate"].get<double>() - m["growth_rate"].get<double>(), 1e-12);
  EXPECT_NEAR(l["growth_rate"].get<double>(), 0.6364, 1e-3);  // the stress-free 0.820
  // The slow branch continued: first of the two stress-free unstable branches.
  ASSERT_EQ(l["continued_branches"].size(), 2u);
  EXPECT_NEAR(l["continued_branches"][0]["phase_speed"].get<double>(), 0.3200, 1e-3);
  EXPECT_GE(l["unstable_branches"].size(), 2u);
}

TEST(Linear2DCli, LightLayerOptionsAreChecked) {
  auto fails_naming = [](const std::string& args, const std::string& option) {
    const auto r = run(args);
    EXPECT_EQ(r.code, 2) << args;
    EXPECT_NE(r.err.find(option), std::string::npos) << r.err;
  };
  fails_naming("dispersion --theory twod --Lx 0.08 --light-layer --rho-light 0", "--rho-light");
  fails_naming("dispersion --theory twod --Lx 0.08 --light-layer --eta-light -1", "--eta-light");
  fails_naming("dispersion --theory twod --Lx 0.08 --light-layer --Lz 0.004", "--Lz");
  fails_naming("dispersion --theory twod --Lx 0.08 --rho-light 1", "--light-layer");
  fails_naming("dispersion --theory depthavg --Lx 0.08 --light-layer", "--light-layer");
}
