// A layer case's HDF5 file gets an XDMF index (analysis/cases/layer_xdmf.hpp): one temporal
// collection per run, I at every sample, each referenced dataset present. With pvpython installed
// (Debian's paraview), the file is opened with all three ParaView XDMF readers, which must show
// every run's cells, the field I and every sample time (skipped without pvpython).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "tests/support/run_granbench.hpp"
#include "tests/support/scratch_dir.hpp"

namespace fs = std::filesystem;
using granbench::testing::ScratchDir;

TEST(LayerCaseXdmf, EveryRunAndSampleIsIndexedAndParaViewOpensIt) {
  const ScratchDir scratch("gb_layer_xdmf");
  const fs::path& dir = scratch.path();
  const auto r = granbench::testing::run_granbench(
      "case decelerating --resolution smoke --quiet --out-dir " + dir.string(), "layer_xdmf");
  ASSERT_EQ(r.code, 0) << r.err;
  const fs::path xdmf = dir / "decelerating.xdmf";
  ASSERT_TRUE(fs::exists(xdmf));
  std::stringstream text;
  text << std::ifstream(xdmf).rdbuf();
  const std::string s = text.str();

  // Cells per run from the topology, times from the first run, every dataset path distinct.
  long cells = 0;
  std::set<std::string> runs;
  const std::regex run_re("<Grid Name=\"([^\"]+)\" GridType=\"Collection\"");
  for (std::sregex_iterator it(s.begin(), s.end(), run_re), end; it != end; ++it)
    runs.insert((*it)[1]);
  ASSERT_GE(runs.size(), 2u) << "two grids of the decelerating case";
  const std::regex topo_re("Dimensions=\"(\\d+) (\\d+)\"/>");
  std::size_t topologies = 0, times = 0;
  for (std::sregex_iterator it(s.begin(), s.end(), topo_re), end; it != end; ++it) ++topologies;
  for (std::size_t p = s.find("<Time "); p != std::string::npos; p = s.find("<Time ", p + 1))
    ++times;
  EXPECT_EQ(topologies, times) << "one mesh per sample";
  const std::size_t times_per_run = times / runs.size();
  EXPECT_EQ(times_per_run * runs.size(), times) << "every run has the same samples";
  for (const std::string& run : runs) {
    const std::regex one(
        "<Grid Name=\"" + run +
        "\" GridType=\"Collection\" CollectionType=\"Temporal\">\\s*<Grid Name=\"t0\""
        " GridType=\"Uniform\">\\s*<Time Value=\"[^\"]+\"/>\\s*<Topology "
        "TopologyType=\"2DSMesh\" Dimensions=\"(\\d+) (\\d+)\"/>");
    std::smatch m;
    ASSERT_TRUE(std::regex_search(s, m, one)) << run;
    cells += (std::stol(m[1]) - 1) * (std::stol(m[2]) - 1);
    EXPECT_NE(s.find("decelerating.h5:/runs/" + run + "/samples/0000/I"), std::string::npos);
  }

  if (std::system("command -v pvpython >/dev/null 2>&1") != 0) {
    GTEST_SKIP() << "no pvpython: the ParaView readers are not tried";
  }
  const std::string xvfb =
      std::system("command -v xvfb-run >/dev/null 2>&1") == 0 ? "xvfb-run -a " : "";
  const std::string script = GRANBENCH_SOURCE_DIR "/tests/analysis/cases/open_layer_xdmf.py";
  const int status =
      std::system((xvfb + "pvpython " + script + " " + xdmf.string() + " " + std::to_string(cells) +
                   " " + std::to_string(times_per_run) + " >" + (dir / "pv.txt").string() + " 2>&1")
                      .c_str());
  std::stringstream pv;
  pv << std::ifstream(dir / "pv.txt").rdbuf();
  EXPECT_EQ(status, 0) << pv.str();
}
