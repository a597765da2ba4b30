// `granbench compare --saturated` end to end (compare_saturated.hpp). A small coarse case (CI,
// label unit): the JSON keys of both models and their ratio, the HDF5 datasets with units, the
// figure, and the physics of a wave that has grown out of the linear regime; bad input. The full
// default case (label paper, not in CI) measures the paper's closing claim.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>

#include "common/hdf5_file.hpp"
#include "tests/support/run_granbench.hpp"
#include "tests/support/scratch_dir.hpp"

namespace {

using granbench::testing::run_granbench;
namespace fs = std::filesystem;
using nlohmann::json;

const char* const kQuantities[] = {"amplitude", "max_slope", "front_width", "wave_speed",
                                   "mean_flux"};

struct Scratch {
  granbench::testing::ScratchDir dir{"gb_saturated"};
  std::string file(const std::string& name) const { return dir / name; }
};

// Checks one model's JSON and HDF5 group; returns its JSON.
void check_model(const json& j, const std::string& h5, const std::string& model) {
  SCOPED_TRACE(model);
  for (const char* key : kQuantities) ASSERT_TRUE(j.contains(key)) << key;
  for (const char* key : {"t_from", "t_to", "samples", "amplitude_spread", "speed_mode",
                          "mean_depth", "reason", "completed", "wall_seconds", "run_command"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_TRUE(j["completed"].get<bool>());
  for (const char* set : {"/wave_frame/xi", "/wave_frame/h", "/amplitude", "/h", "/t", "/x"}) {
    const std::string path = "/" + model + set;
    ASSERT_TRUE(granbench::h5_has(h5, path)) << path;
    EXPECT_TRUE(granbench::h5_has_attribute(h5, path, "units")) << path;
  }
  EXPECT_EQ(granbench::h5_read_string_attribute(h5, "/" + model + "/wave_frame/xi", "units"), "m");
  const auto xi = granbench::h5_read_doubles(h5, "/" + model + "/wave_frame/xi");
  const auto h = granbench::h5_read_doubles(h5, "/" + model + "/wave_frame/h");
  ASSERT_EQ(xi.size(), h.size());
  EXPECT_TRUE(std::is_sorted(xi.begin(), xi.end()));
  EXPECT_NEAR(granbench::h5_read_double_attribute(h5, "/" + model, "amplitude"),
              j["amplitude"].get<double>(), 1e-15);
}

TEST(CompareSaturated, SmallCaseReportsBothWavesAlike) {
  const Scratch s;
  const std::string h5 = s.file("sat.h5"), png = s.file("sat.png");
  // 4 cm at 28.5 deg, 1.5 s: about 5 s on one core. The depth-averaged wave has grown from the
  // start's 0.4 mm to about 0.8 mm and steepened fifteen-fold by then.
  const auto r = run_granbench(
      "compare --saturated --Lx 0.04 --nx 40 --nz 16 --nx-depthavg 128 "
      "--t-end 1.5 --window 0.3 --threads 1 --json --quiet --out " +
          h5 + " --plot " + png,
      "saturated");
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["mode"], "saturated");
  EXPECT_EQ(j["init"], "sine");  // the paper's start by default
  EXPECT_DOUBLE_EQ(j["a0"].get<double>(), 2e-4);
  EXPECT_DOUBLE_EQ(j["window"].get<double>(), 0.3);
  check_model(j["depthavg"], h5, "depthavg");
  check_model(j["twod"], h5, "twod");
  for (const char* key : kQuantities) EXPECT_TRUE(j["ratio"].contains(key)) << key;
  EXPECT_TRUE(fs::exists(png));

  // Physics: both waves are there and move downslope at about the linear speeds (about 1 m/s),
  // carry the base flux, and the depth-averaged front is measured.
  const double h0 = j["h0"].get<double>();
  for (const char* model : {"depthavg", "twod"}) {
    SCOPED_TRACE(model);
    const json& m = j[model];
    EXPECT_GT(m["amplitude"].get<double>(), 0.0);
    EXPECT_GT(m["wave_speed"].get<double>(), 0.5);
    EXPECT_LT(m["wave_speed"].get<double>(), 2.0);
    EXPECT_NEAR(m["mean_depth"].get<double>(), h0, 0.01 * h0);  // mass is conserved
    EXPECT_GT(m["mean_flux"].get<double>(), 0.0);
  }
  const json& d = j["depthavg"];
  ASSERT_TRUE(d["max_slope"].is_number());
  ASSERT_TRUE(d["front_width"].is_number());
  // the sine start has max - min h = 2 a0 and |dh/dx| = a0 k; the depth-averaged wave has grown
  // and steepened past both
  const double start_slope = 2e-4 * 2.0 * M_PI / 0.04;
  EXPECT_GT(d["amplitude"].get<double>(), 1.5 * 2e-4 * 2.0);
  EXPECT_GT(d["max_slope"].get<double>(), 5.0 * start_slope);
  EXPECT_NEAR(j["ratio"]["max_slope"].get<double>(),
              d["max_slope"].get<double>() / j["twod"]["max_slope"].get<double>(), 1e-12);
}

TEST(CompareSaturated, BadInputIsOneLineNamingTheOption) {
  const Scratch s;
  // {arguments, the option the error names}; the last has no 2D surface mode to saturate and
  // would otherwise run for hours (found by the fuzz test).
  const std::pair<std::string, std::string> cases[] = {{"--window 2 --t-end 1", "--window"},
                                                       {"--window -1", "--window"},
                                                       {"--window abc", "--window"},
                                                       {"--a0 0.005 --h0 0.004", "--a0"},
                                                       {"--h0 90", "--Lx"}};
  for (const auto& [args, option] : cases) {
    const auto r = run_granbench(
        "compare --saturated --nx 24 --nz 12 --quiet --out " + s.file("bad.h5") + " " + args,
        "saturated_bad");
    EXPECT_EQ(r.code, 2) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(option), std::string::npos) << args << "\n" << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
    EXPECT_FALSE(fs::exists(s.file("bad.h5")));
  }
}

}  // namespace
