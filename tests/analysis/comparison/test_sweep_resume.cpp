// Sweeps keep every finished point in the output file and a re-run skips them, also the points
// that the ranks of a killed multi-process run left in their part files; a stored sweep with
// other settings is refused; points survive packing for the trip between processes.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "analysis/comparison/sweep.hpp"
#include "tests/support/scratch_dir.hpp"

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
  const granbench::testing::ScratchDir scratch("gb_sweep_resume");
  const std::string path = scratch / "sweep.h5";
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
  // The resumed points reproduce with the command they ran with (made again from the spec).
  EXPECT_TRUE(second[0].resumed);
  ASSERT_FALSE(first[0].run_command.empty());
  EXPECT_EQ(second[0].run_command, first[0].run_command);
  EXPECT_EQ(second[2].run_command, first[1].run_command);
}

namespace {
// Cheap clean linear depth-averaged points (the --model depthavg sweep's measurement).
SweepSpec linear_spec(const std::string& out) {
  SweepSpec spec;
  depthavg::LinearRunParams lp;
  lp.nx = 64;
  spec.depthavg_linear = lp;
  spec.Lx = {0.04, 0.06, 0.08};
  spec.out = out;
  spec.jobs = 1;
  return spec;
}
}  // namespace

TEST(Sweep, ResumesFromThePartFilesOfAKilledMultiProcessRun) {
  const granbench::testing::ScratchDir scratch("gb_sweep_parts");
  const std::string path = scratch / "sweep.h5";
  // Rank 1 of 2 finished its share (point 1, Lx = 0.06) and the run was killed before the end.
  SweepSpec rank1 = linear_spec(path);
  rank1.rank = 1;
  rank1.ranks = 2;
  const auto kept = run_share(rank1, {});
  ASSERT_EQ(kept.size(), 1u);
  ASSERT_TRUE(std::filesystem::exists(sweep_part_path(path, 1)));
  ASSERT_FALSE(std::filesystem::exists(path));
  // One process resumes: it runs the other two points only, and leaves one complete file.
  std::size_t ran = 0;
  SweepProgress progress;
  progress.point_done = [&](const SweepPoint&, std::size_t, std::size_t) { ++ran; };
  const auto all = run_sweep(linear_spec(path), progress);
  EXPECT_EQ(ran, 2u);
  ASSERT_EQ(all.size(), 3u);
  EXPECT_TRUE(all[1].resumed);
  EXPECT_DOUBLE_EQ(all[1].growth_rate, kept[0].growth_rate);
  for (const auto& p : all) {
    EXPECT_TRUE(p.completed);
    EXPECT_NEAR(p.growth_rate, p.growth_rate_exact, 0.05 * p.growth_rate_exact);  // nx = 64
  }
  EXPECT_FALSE(std::filesystem::exists(sweep_part_path(path, 1)));
  EXPECT_EQ(read_sweep(path).size(), 3u);
  // Another grid: the stored sweep is refused rather than mixed in.
  SweepSpec other = linear_spec(path);
  other.depthavg_linear->nx = 96;
  EXPECT_THROW(read_finished(other), std::invalid_argument);
}

namespace {
// Two points, the second without a growth rate and with the measurement's reason.
std::vector<SweepPoint> two_points() {
  SweepPoint a, b;
  a.model = "depthavg";
  a.Lx = 0.05;
  a.k_hat = 0.5;
  a.growth_rate = 1.25;
  a.completed = true;
  b.model = "twod";
  b.Lx = 0.07;
  b.growth_rate = NAN;
  b.growth_reason = "too short: 15 samples after the transient (t >= 0.005 s); need 16";
  b.message = "twod run diverged at t = 0.0954 s: u = 160 m/s at x = 0.0412 m, z = 0.0045 m";
  b.theory.exact_2d.phase_speed = 1.14;
  b.steps = 123;
  return {a, b};
}

void expect_two_points(const std::vector<SweepPoint>& back) {
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[0].model, "depthavg");
  EXPECT_EQ(back[0].growth_rate, 1.25);
  EXPECT_EQ(back[0].growth_reason, "");
  EXPECT_TRUE(back[0].completed);
  EXPECT_EQ(back[1].model, "twod");
  EXPECT_EQ(back[1].Lx, 0.07);
  EXPECT_TRUE(std::isnan(back[1].growth_rate));
  EXPECT_EQ(back[1].growth_reason, two_points()[1].growth_reason);
  EXPECT_EQ(back[1].message, two_points()[1].message);
  EXPECT_EQ(back[0].message, "");
  EXPECT_EQ(back[1].theory.exact_2d.phase_speed, 1.14);
  EXPECT_EQ(back[1].steps, 123);
  EXPECT_FALSE(back[1].completed);
}
}  // namespace

// Between processes (MPI ranks) and through the sweep file, a point keeps its numbers, the
// reason it has no growth rate and why its run did not complete.
TEST(Sweep, PointsAndTheirReasonsSurvivePacking) {
  expect_two_points(unpack_points(pack_points(two_points())));
  // a reason followed by a third point: the lengths keep the points apart
  auto three = two_points();
  three.push_back(three[0]);
  const auto back = unpack_points(pack_points(three));
  ASSERT_EQ(back.size(), 3u);
  EXPECT_EQ(back[2].growth_rate, 1.25);
}

TEST(Sweep, PointsAndTheirReasonsSurviveTheFile) {
  const granbench::testing::ScratchDir scratch("gb_sweep_reasons");
  const std::string path = scratch / "sweep.h5";
  write_sweep(path, linear_spec(path), two_points());
  expect_two_points(read_sweep(path));
}
