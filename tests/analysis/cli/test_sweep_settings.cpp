// Every option of `granbench sweep` that changes a result is stored with the points, so that a
// resume can refuse a file computed with another value (qa.md: --viscosity-passes was not, and
// old growth rates came back labelled with the new setting). The options are enumerated from the
// registered subcommand, not from a list kept here: for each model and each option, a value other
// than the default must either change the stored settings (sweep.hpp: stored_settings) or be
// refused as not applying to that model; only the options listed in
// sweep_options_without_effect_on_results() are exempt.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "analysis/cli/sweep_plan.hpp"
#include "tests/support/scratch_dir.hpp"

namespace {

using namespace granbench;
using namespace granbench::cli;

enum class Outcome { Stored, Refused, Ignored, Invalid };

struct Trial {
  Outcome outcome;
  std::string detail;
};

using Settings = std::vector<std::pair<std::string, double>>;

// The stored settings of `sweep --model MODEL [option value]`.
Trial try_value(const std::string& model, const std::string& option, const std::string& value,
                const Settings& baseline) {
  CLI::App app;
  SweepOptions o;
  add_sweep_options(app, o);
  std::vector<std::string> args = {"--model", model};
  if (!option.empty()) args.push_back(option);
  if (!value.empty()) args.push_back(value);  // (a flag is given alone)
  std::reverse(args.begin(), args.end());     // CLI11 parses a reversed vector
  try {
    app.parse(args);
  } catch (const CLI::ParseError& e) {
    return {Outcome::Invalid, e.what()};
  }
  SweepPlan plan;
  try {
    plan = plan_sweep(o, app);
  } catch (const UsageError& e) {
    const std::string what = e.what();
    // Refused as not applying to the model (not for a value out of range).
    if (what.rfind(option + ": does not apply to --model", 0) == 0) return {Outcome::Refused, what};
    return {Outcome::Invalid, what};
  }
  const Settings stored = stored_settings(plan.spec);
  if (option.empty() || stored != baseline) return {Outcome::Stored, ""};
  return {Outcome::Ignored, ""};
}

// Values to try instead of the default: the other allowed values of a choice, else numbers near
// the default and a few plain ones (the first valid one is enough); for a flag, the flag alone.
std::vector<std::string> candidates(const CLI::Option& opt) {
  if (opt.get_expected_min() == 0) return {""};  // a flag: given, it differs from the default
  std::vector<std::string> v;
  const std::string def = opt.get_default_str();
  const std::string type = opt.get_type_name();
  const auto brace = type.find('{');
  if (brace != std::string::npos) {
    std::istringstream list(type.substr(brace + 1, type.find('}') - brace - 1));
    for (std::string item; std::getline(list, item, ',');)
      if (item != def) v.push_back(item);
  }
  try {
    const double d = std::stod(def);
    for (double x : {d * 1.25, d * 0.8, d + 1.0, d - 1.0, d * 2.0}) {
      std::ostringstream s;
      s << x;
      if (s.str() != def) v.push_back(s.str());
    }
  } catch (const std::exception&) {
  }
  for (const char* x : {"0", "0.5", "1.5", "2", "3", "bagnold"}) v.push_back(x);
  return v;
}

TEST(SweepSettings, EveryOptionThatChangesAResultIsStoredOrRefused) {
  CLI::App app;
  SweepOptions defaults;
  add_sweep_options(app, defaults);
  const auto& neutral = sweep_options_without_effect_on_results();
  for (const std::string model : {"depthavg", "twod", "both"}) {
    const Trial base = try_value(model, "", "", {});
    ASSERT_EQ(base.outcome, Outcome::Stored) << model << ": " << base.detail;
    CLI::App reference;
    SweepOptions o;
    add_sweep_options(reference, o);
    std::vector<std::string> args = {"--model", model};
    std::reverse(args.begin(), args.end());
    reference.parse(args);
    const Settings baseline = stored_settings(plan_sweep(o, reference).spec);
    int checked = 0;
    for (const CLI::Option* opt : app.get_options()) {
      const std::string name = opt->get_name();
      if (neutral.count(name)) continue;
      ++checked;
      bool valid = false, refused = false, stored = false;
      std::string last;
      for (const std::string& value : candidates(*opt)) {
        const Trial t = try_value(model, name, value, baseline);
        if (t.outcome == Outcome::Invalid) {
          last = t.detail;
          continue;
        }
        valid = true;
        refused = refused || t.outcome == Outcome::Refused;
        stored = stored || t.outcome == Outcome::Stored;
        if (stored || refused) break;
      }
      EXPECT_TRUE(valid) << "--model " << model << " " << name
                         << ": no other valid value found to try (" << last << ")";
      EXPECT_TRUE(!valid || stored || refused)
          << "--model " << model << " " << name
          << " changes no stored setting and is not refused: a resume would mix its results";
    }
    EXPECT_GT(checked, 15) << model;
  }
}

// The exemptions name registered options only (a renamed option must not stay exempt by mistake).
TEST(SweepSettings, EveryExemptOptionExists) {
  CLI::App app;
  SweepOptions o;
  add_sweep_options(app, o);
  for (const auto& [name, why] : sweep_options_without_effect_on_results())
    EXPECT_NE(app.get_option_no_throw(name), nullptr) << name << " (" << why << ")";
}

// A stored sweep with another --viscosity-passes is refused on resume, naming the setting.
TEST(SweepSettings, AResumeWithOtherViscosityPassesIsRefused) {
  SweepSpec spec;
  spec.Lx = {0.08};
  spec.depthavg = false;
  spec.twod = true;
  const granbench::testing::ScratchDir scratch("gb_sweep_vp");
  spec.out = scratch / "sweep.h5";
  write_sweep(spec.out, spec, {});
  EXPECT_NO_THROW(check_stored_settings(spec.out, spec));
  spec.twod_settings.viscosity_passes = 2;
  try {
    check_stored_settings(spec.out, spec);
    ADD_FAILURE() << "accepted a sweep stored with another --viscosity-passes";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("twod_viscosity_passes"), std::string::npos) << e.what();
  }
}

// The 2D points' physics warnings (physics_warnings.hpp) come with the plan. A sweep that reaches
// a wave of 5 h0 runs it on more cells across the layer (TwodSettings::cells_across) and is not
// warned of it on the default preset; on the coarse preset it is (and of the coarse grid, and of
// the deficit expected there). A point whose exact 2D growth is small against its grid's expected
// deficit, even on the most cells the deficit law gives it, is named with its length. A
// depth-averaged sweep gets none.
// The plan's warnings, physics ones included, for these sweep arguments.
std::vector<std::string> plan_warnings(std::vector<std::string> args) {
  CLI::App app;
  SweepOptions o;
  add_sweep_options(app, o);
  std::reverse(args.begin(), args.end());  // CLI11 parses a reversed vector
  app.parse(args);
  SweepPlan plan = plan_sweep(o, app);
  add_growth_accuracy_warnings(o, plan);
  return plan.warnings;
}

TEST(SweepSettings, AShortTwodWaveIsWarnedOfOnlyBelowItsRefinedGrid) {
  auto warnings = [](const std::string& model, const std::string& Lx,
                     const std::string& resolution) {
    std::vector<std::string> args = {"--model", model, "--Lx", Lx};
    if (!resolution.empty()) args.insert(args.end(), {"--resolution", resolution});
    return plan_warnings(args);
  };
  EXPECT_TRUE(warnings("twod", "0.02:0.08:4", "").empty());
  EXPECT_TRUE(warnings("both", "0.04:0.08:3", "default").empty());
  const auto coarse = warnings("twod", "0.02:0.08:4", "coarse");
  ASSERT_EQ(coarse.size(), 3u);
  EXPECT_NE(coarse[1].find("short wave (5 h0)"), std::string::npos) << coarse[1];
  // and on its 23.5 cells per h0 the 2 cm wave's growth is expected 17 % under the theory
  EXPECT_EQ(coarse[2].find("Lx = 0.02 m: a small growth rate"), 0u) << coarse[2];
  // Near the cutoff (1.370 cm) the default preset's grid follows the deficit law up to six times
  // its rows, under a light layer of h0/4: 1.4 cm (384 rows, 306.5 cells per h0) is not named,
  // 1.39 cm is, at that cap.
  EXPECT_TRUE(warnings("twod", "0.014:0.02:2", "").empty());
  const auto near_cutoff = warnings("twod", "0.0139:0.02:2", "");
  ASSERT_EQ(near_cutoff.size(), 1u);
  EXPECT_EQ(near_cutoff[0].find("Lx = 0.0139 m: a small growth rate"), 0u) << near_cutoff[0];
  EXPECT_TRUE(warnings("depthavg", "0.02:0.08:4", "").empty());
  // Under the thin light layer it gives the deficits measured there (the law overestimates them
  // and its order did not hold), not the law's cells nor the extrapolation that rests on it.
  EXPECT_NE(near_cutoff[0].find("thin light layer"), std::string::npos) << near_cutoff[0];
  EXPECT_EQ(near_cutoff[0].find("--extrapolate"), std::string::npos) << near_cutoff[0];
  EXPECT_EQ(near_cutoff[0].find("--nz"), std::string::npos) << near_cutoff[0];
  // Under h0 of light fluid (points run for 100 s, whose seed grows past h0/20, keep it) the
  // extrapolation is still the cheaper way out that it names.
  const auto deep = plan_warnings({"--model", "twod", "--Lx", "0.014:0.02:2", "--t-end", "100"});
  ASSERT_FALSE(deep.empty());
  EXPECT_EQ(deep[0].find("Lx = 0.014 m: a small growth rate"), 0u) << deep[0];
  EXPECT_NE(deep[0].find("or give --extrapolate"), std::string::npos) << deep[0];
}

// --extrapolate on a point under the thin light layer of the near-cutoff grids is warned of: the
// deficit law's order did not hold there at 1.4 cm. Points under h0 of light fluid are not named.
TEST(SweepSettings, AnExtrapolationOnTheThinLightLayerIsWarnedOf) {
  const auto warnings = plan_warnings({"--model", "twod", "--Lx", "0.014:0.02:2", "--extrapolate"});
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].find("Lx = 0.014 m: --extrapolate on the thin light layer"), 0u)
      << warnings[0];
}

// --extrapolate needs a half grid within the deficit law's range: refused on the coarse preset.
TEST(SweepSettings, ExtrapolationIsRefusedOnTheCoarsePreset) {
  CLI::App app;
  SweepOptions o;
  add_sweep_options(app, o);
  std::vector<std::string> args = {"--model", "twod", "--resolution", "coarse", "--extrapolate"};
  std::reverse(args.begin(), args.end());
  app.parse(args);
  try {
    (void)plan_sweep(o, app);
    ADD_FAILURE() << "--extrapolate accepted on the coarse preset";
  } catch (const UsageError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("--extrapolate: ", 0), 0u) << e.what();
  }
}

}  // namespace
