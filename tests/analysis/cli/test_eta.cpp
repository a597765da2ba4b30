// The ETA of the progress lines (cli_common.hpp): the wall time left at the pace so far.
#include <gtest/gtest.h>

#include "analysis/cli/cli_common.hpp"

using granbench::cli::eta_text;

TEST(ProgressEta, WallTimeLeftAtThePaceSoFar) {
  EXPECT_EQ(eta_text(10.0, 0.0, 1.0, 4.0), "ETA 30 s");         // 10 s per simulated second
  EXPECT_EQ(eta_text(30.0, 2.0, 3.0, 10.0), "ETA 3 min 30 s");  // a restart from t = 2 s
  EXPECT_EQ(eta_text(100.0, 0.0, 0.1, 10.0), "ETA 2 h 45 min");
  EXPECT_EQ(eta_text(5.0, 1.0, 1.0, 2.0), "ETA -");  // no progress yet
}
