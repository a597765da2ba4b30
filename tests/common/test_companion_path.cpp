// The XDMF index and checkpoint beside an HDF5 output (common/companion_path.hpp).
#include <gtest/gtest.h>

#include "common/companion_path.hpp"

using granbench::companion_path;

TEST(CompanionPath, AnHdf5ExtensionIsReplaced) {
  EXPECT_EQ(companion_path("run.h5", ".xdmf"), "run.xdmf");
  EXPECT_EQ(companion_path("out/run.h5", ".checkpoint.h5"), "out/run.checkpoint.h5");
  EXPECT_EQ(companion_path("a.b.hdf5", ".xdmf"), "a.b.xdmf");
  EXPECT_EQ(companion_path("RUN.H5", ".xdmf"), "RUN.xdmf");
}

TEST(CompanionPath, AnyOtherNameKeepsItsDotsAndGetsTheSuffixAppended) {
  // two runs named r0.25 and r0.45 once shared r0.xdmf and r0.checkpoint.h5
  EXPECT_EQ(companion_path("r0.25", ".xdmf"), "r0.25.xdmf");
  EXPECT_EQ(companion_path("r0.45", ".checkpoint.h5"), "r0.45.checkpoint.h5");
  EXPECT_EQ(companion_path("dir.v2/run", ".xdmf"), "dir.v2/run.xdmf");
}
