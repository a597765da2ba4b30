// H5Writer: round trip of a SurfaceSeries, and no file under the real name unless closed.
#include <gtest/gtest.h>

#include <filesystem>

#include "common/hdf5_file.hpp"
#include "tests/support/scratch_dir.hpp"

using namespace granbench;

TEST(Hdf5File, SurfaceSeriesRoundTrip) {
  const granbench::testing::ScratchDir dir("gb_hdf5_series");
  const std::string path = dir / "series.h5";
  SurfaceSeries s = SurfaceSeries::uniform_grid(0.08, 4, 4e-3);
  s.append(0.0, std::vector<double>{1, 2, 3, 4});
  s.append(0.5, std::vector<double>{5, 6, 7, 8});
  {
    H5Writer out(path);
    write_surface_series(out, "depthavg", s);
    out.close();
  }
  const SurfaceSeries r = read_surface_series(path, "depthavg");
  EXPECT_EQ(r.h, s.h);
  EXPECT_EQ(r.t, s.t);
  EXPECT_NEAR(r.Lx, 0.08, 1e-15);
}

TEST(Hdf5File, UnclosedWriterLeavesNoFile) {
  const granbench::testing::ScratchDir dir("gb_hdf5_partial");
  const std::string path = dir / "partial.h5";
  {
    H5Writer out(path);
    out.write("a", std::vector<double>{1.0});
  }  // destroyed without close(), as when a run fails
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_FALSE(std::filesystem::exists(path + ".partial"));
}
