// Periodic checkpoints of `granbench run --model twod` (twod/run_output.hpp): a run killed with
// a real SIGKILL restarts from its last checkpoint into the same --out and ends with the
// uninterrupted run's surface series (to 1e-12), snapshots (times, fields, XDMF index, one at
// t_end) and growth rate. The kill waits for the first checkpoint to appear (it is renamed into
// place complete), not for a time.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "common/hdf5_file.hpp"
#include "tests/support/run_granbench.hpp"
#include "tests/support/scratch_dir.hpp"

namespace {
using granbench::testing::run_granbench;
namespace fs = std::filesystem;
using granbench::testing::ScratchDir;

const std::string kRun =
    "run --model twod --nx 32 --nz 8 --Lx 0.04 --a0 1e-5 --t-end 4 --dt-snapshot 0.3 "
    "--checkpoint-every 0.5 --json --quiet ";

// The snapshot times of an output, in their order (the groups are numbered 0000, 0001, ...).
std::vector<double> snapshot_times(const std::string& h5) {
  std::vector<double> t;
  for (int n = 0;; ++n) {
    char name[32];
    std::snprintf(name, sizeof name, "/snapshots/%04d", n);
    if (!granbench::h5_has(h5, std::string(name) + "/f")) return t;
    t.push_back(granbench::h5_read_attribute(h5, name, "t"));
  }
}

std::size_t count(const std::string& file, const std::string& what) {
  std::ifstream in(file);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// Kills and reaps the forked run when the test leaves before it has (a failed ASSERT, the wait
// below timing out), so that no run outlives the test.
struct ChildGuard {
  pid_t pid = -1;
  bool reaped = false;
  ~ChildGuard() {
    if (pid > 0 && !reaped) {
      kill(pid, SIGKILL);
      waitpid(pid, nullptr, 0);
    }
  }
};

}  // namespace

TEST(TwodSigkill, ARunKilledAfterACheckpointRestartsIntoTheSameOutAsIfUninterrupted) {
  const ScratchDir scratch("gb_sigkill");
  const fs::path& dir = scratch.path();
  const std::string ref = (dir / "ref.h5").string(), out = (dir / "run.h5").string();
  const std::string checkpoint = (dir / "run.checkpoint.h5").string();

  const auto full = run_granbench(kRun + "--out " + ref, "sigkill_ref");
  ASSERT_EQ(full.code, 0) << full.err;
  EXPECT_FALSE(fs::exists(dir / "ref.checkpoint.h5"));  // removed once the run completed

  // The same run, killed by SIGKILL as soon as its first checkpoint exists.
  const std::string cmd = "exec " + std::string(GRANBENCH_BINARY_DIR) + "/granbench " + kRun +
                          "--out " + out + " >/dev/null 2>&1";
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  ChildGuard child{pid};
  int status = 0;
  bool exited = false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(5);
  while (!fs::exists(checkpoint)) {
    if (waitpid(pid, &status, WNOHANG) == pid) {
      exited = child.reaped = true;
      break;
    }
    ASSERT_LT(std::chrono::steady_clock::now(), deadline) << "no checkpoint after 5 minutes";
    usleep(2000);
  }
  ASSERT_FALSE(exited) << "the run ended before its first checkpoint (status " << status << ")";
  kill(pid, SIGKILL);
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  child.reaped = true;
  ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL)
      << "the run completed before the kill; make it longer";
  ASSERT_TRUE(fs::exists(out));  // brought up to date at the checkpoint, before it

  const auto rest =
      run_granbench(kRun + "--out " + out + " --restart " + checkpoint, "sigkill_rest");
  ASSERT_EQ(rest.code, 0) << rest.err;
  EXPECT_FALSE(fs::exists(checkpoint));

  const granbench::SurfaceSeries a = granbench::read_surface_series(ref, "/surface");
  const granbench::SurfaceSeries b = granbench::read_surface_series(out, "/surface");
  ASSERT_EQ(a.t.size(), b.t.size());
  for (std::size_t n = 0; n < a.t.size(); ++n) EXPECT_NEAR(a.t[n], b.t[n], 1e-12);
  ASSERT_EQ(a.h.size(), b.h.size());
  double dh = 0.0;
  for (std::size_t n = 0; n < a.h.size(); ++n) dh = std::max(dh, std::abs(a.h[n] - b.h[n]));
  EXPECT_LE(dh, 1e-12);

  const std::vector<double> ta = snapshot_times(ref), tb = snapshot_times(out);
  ASSERT_EQ(ta.size(), 15u);  // 0, 0.3, ..., 3.9 and t_end = 4
  EXPECT_NEAR(ta.back(), 4.0, 1e-12);
  ASSERT_EQ(ta.size(), tb.size());
  for (std::size_t n = 0; n < ta.size(); ++n) {
    EXPECT_NEAR(ta[n], tb[n], 1e-12);
    char name[48];
    std::snprintf(name, sizeof name, "/snapshots/%04zu/u", n);
    const auto ua = granbench::h5_read_doubles(ref, name),
               ub = granbench::h5_read_doubles(out, name);
    ASSERT_EQ(ua.size(), ub.size());
    for (std::size_t i = 0; i < ua.size(); ++i) ASSERT_NEAR(ua[i], ub[i], 1e-12) << name;
  }
  EXPECT_EQ(count((dir / "ref.xdmf").string(), "<Time Value="), ta.size());
  EXPECT_EQ(count((dir / "run.xdmf").string(), "<Time Value="), ta.size());

  const auto ja = nlohmann::json::parse(full.out), jb = nlohmann::json::parse(rest.out);
  ASSERT_FALSE(ja["growth_rate"].is_null()) << ja["reason"];
  EXPECT_NEAR(ja["growth_rate"].get<double>(), jb["growth_rate"].get<double>(), 1e-12);
}
