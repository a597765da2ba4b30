// The 2D run's XDMF index opens in every ParaView reader (shared/reports/paraview.md): a 2DSMesh
// with XY node geometry (not 2DRectMesh/VXVY, which the legacy reader shows blank), a `velocity`
// vector attribute, times at full precision, the HDF5 name XML-escaped, and names ParaView
// cannot open (white space) refused before the run. With pvpython installed, the file is also
// opened with each of ParaView's three XDMF readers (skipped otherwise).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "common/hdf5_file.hpp"
#include "tests/support/run_granbench.hpp"
#include "tests/support/scratch_dir.hpp"

namespace {

using granbench::testing::run_granbench;
namespace fs = std::filesystem;
using granbench::testing::ScratchDir;

const std::string kRun =
    "run --model twod --nx 40 --nz 16 --t-end 0.02 --dt-snapshot 0.01 --quiet --out ";

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

class XdmfOutput : public ::testing::Test {
 protected:
  const ScratchDir scratch_{"gb_xdmf"};
  const fs::path& dir_ = scratch_.path();
};

TEST_F(XdmfOutput, StructuredMeshVelocityVectorAndExactTimes) {
  const std::string h5 = (dir_ / "run.h5").string();
  const auto r = run_granbench(kRun + h5, "xdmf");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string x = read(dir_ / "run.xdmf");
  EXPECT_EQ(x.find("2DRectMesh"), std::string::npos);
  EXPECT_EQ(x.find("VXVY"), std::string::npos);
  EXPECT_NE(x.find("<Topology TopologyType=\"2DSMesh\" Dimensions=\"17 41\"/>"), std::string::npos)
      << x;
  EXPECT_NE(x.find("<Geometry GeometryType=\"XY\">"), std::string::npos);
  EXPECT_NE(x.find("Dimensions=\"17 41 2\""), std::string::npos);
  EXPECT_NE(x.find("<Attribute Name=\"velocity\" AttributeType=\"Vector\" Center=\"Cell\">"),
            std::string::npos);
  EXPECT_NE(x.find("Dimensions=\"16 40 3\""), std::string::npos);

  // Every <Time> reads back as the exact time stored with its snapshot.
  const std::regex time(R"re(<Time Value="([^"]+)"/>)re");
  int n = 0;
  for (auto it = std::sregex_iterator(x.begin(), x.end(), time); it != std::sregex_iterator();
       ++it, ++n) {
    char grp[32];
    std::snprintf(grp, sizeof grp, "/snapshots/%04d", n);
    EXPECT_EQ(std::strtod((*it)[1].str().c_str(), nullptr),
              granbench::h5_read_double_attribute(h5, grp, "t"))
        << (*it)[1];
  }
  EXPECT_GE(n, 2);

  // velocity = (u, w, 0) cell by cell; the node coordinates (x, z) with x fastest.
  std::vector<std::size_t> dims;
  const auto v = granbench::h5_read_doubles(h5, "/snapshots/0001/velocity", &dims);
  const auto u = granbench::h5_read_doubles(h5, "/snapshots/0001/u");
  const auto w = granbench::h5_read_doubles(h5, "/snapshots/0001/w");
  ASSERT_EQ(dims, (std::vector<std::size_t>{16, 40, 3}));
  for (std::size_t c = 0; c < u.size(); ++c) {
    EXPECT_EQ(v[3 * c], u[c]);
    EXPECT_EQ(v[3 * c + 1], w[c]);
    EXPECT_EQ(v[3 * c + 2], 0.0);
  }
  const auto xz = granbench::h5_read_doubles(h5, "/snapshots/xz_nodes", &dims);
  const auto xn = granbench::h5_read_doubles(h5, "/snapshots/x_nodes");
  const auto zn = granbench::h5_read_doubles(h5, "/snapshots/z_nodes");
  ASSERT_EQ(dims, (std::vector<std::size_t>{17, 41, 2}));
  EXPECT_EQ(xz[2 * 1], xn[1]);
  EXPECT_EQ(xz[2 * 41 + 1], zn[1]);
  // The run's grid moves (twod/frame.hpp): each snapshot is in the lab frame with its own node
  // coordinates, offset from the lab's nodes by its x_offset, under half a cell.
  EXPECT_NE(x.find("run.h5:/snapshots/0001/xz_nodes"), std::string::npos) << x;
  const auto moved = granbench::h5_read_doubles(h5, "/snapshots/0001/xz_nodes", &dims);
  ASSERT_EQ(dims, (std::vector<std::size_t>{17, 41, 2}));
  const double offset = granbench::h5_read_double_attribute(h5, "/snapshots/0001", "x_offset");
  EXPECT_LE(std::abs(offset), 0.5 * xn[1] * (1.0 + 1e-12));
  EXPECT_NEAR(moved[2 * 1], xn[1] + offset, 1e-15);
  EXPECT_EQ(moved[2 * 41 + 1], zn[1]);
}

TEST_F(XdmfOutput, FileNamesAreEscapedOrRefused) {
  const std::string amp = (dir_ / "a&b.h5").string();
  const auto ok = run_granbench(kRun + "'" + amp + "'", "xdmf");
  ASSERT_EQ(ok.code, 0) << ok.err;
  const std::string x = read(dir_ / "a&b.xdmf");
  EXPECT_NE(x.find(">a&amp;b.h5:/snapshots/"), std::string::npos) << x;
  EXPECT_EQ(x.find(">a&b.h5"), std::string::npos);

  const std::string spaced = (dir_ / "my run.h5").string();
  const auto bad = run_granbench(kRun + "'" + spaced + "'", "xdmf");
  EXPECT_NE(bad.code, 0);
  EXPECT_NE(bad.err.find("--out"), std::string::npos) << bad.err;
  EXPECT_NE(bad.err.find("white space"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(spaced));
}

// Each of ParaView's readers sees the whole grid, every array and every time, and a threshold
// f > 0.5 keeps the granular layer (about half the cells: Lz ~ 2 h0).
TEST_F(XdmfOutput, EveryParaViewReaderOpensIt) {
  if (std::system("command -v pvpython >/dev/null 2>&1") != 0) GTEST_SKIP() << "no pvpython";
  const std::string h5 = (dir_ / "run.h5").string();
  ASSERT_EQ(run_granbench(kRun + h5, "xdmf").code, 0);
  const std::string script = GRANBENCH_SOURCE_DIR "/tests/analysis/cli/open_xdmf.py";
  const std::string xvfb =
      std::system("command -v xvfb-run >/dev/null 2>&1") == 0 ? "xvfb-run -a " : "";
  const int status = std::system((xvfb + "pvpython " + script + " " + (dir_ / "run.xdmf").string() +
                                  " 40 16 > " + (dir_ / "pv.txt").string() + " 2>&1")
                                     .c_str());
  EXPECT_EQ(status, 0) << read(dir_ / "pv.txt");
}

}  // namespace
