// Sweeps keep every finished point in the output file and a re-run skips them.
#include <gtest/gtest.h>

#include <filesystem>

#include "sweep.hpp"

using namespace granbench;

TEST(Sweep, ParsesRangesAndRejectsBadOnes) {
  const auto v = parse_range("0.02:0.08:4");
  ASSERT_EQ(v.size(), 4u);
  EXPECT_DOUBLE_EQ(v.front(), 0.02);
  EXPECT_DOUBLE_EQ(v.back(), 0.08);
  EXPECT_THROW(parse_range("0.02:0.08"), std::invalid_argument);
  EXPECT_THROW(parse_range("0.08:0.02:3"), std::invalid_argument);
  EXPECT_THROW(parse_range("-1:0.02:3"), std::invalid_argument);
}

TEST(Sweep, ResumesFromTheOutputFile) {
  const std::string path = std::filesystem::temp_directory_path() / "granbench_sweep_resume.h5";
  std::filesystem::remove(path);
  SweepSpec spec;
  spec.chute.t_end = 0.3;
  spec.depthavg_settings.nx = 64;
  spec.Lx = {0.04, 0.08};
  spec.out = path;
  spec.jobs = 2;
  const auto first = run_sweep(spec);
  ASSERT_EQ(first.size(), 2u);
  ASSERT_TRUE(std::filesystem::exists(path));
  // A third point: only it runs; the two stored ones come back unchanged from the file.
  spec.Lx = {0.04, 0.06, 0.08};
  std::size_t ran = 0;
  SweepProgress progress;
  progress.point_done = [&](const SweepPoint&, std::size_t, std::size_t) { ++ran; };
  const auto second = run_sweep(spec, progress);
  EXPECT_EQ(ran, 1u);
  ASSERT_EQ(second.size(), 3u);
  EXPECT_DOUBLE_EQ(second[0].growth_rate, first[0].growth_rate);
  EXPECT_DOUBLE_EQ(second[2].growth_rate, first[1].growth_rate);
  std::filesystem::remove(path);
}
