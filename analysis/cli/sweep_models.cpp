// The sweep's processes, its table, JSON, HDF5 file and figure; see sweep_models.hpp.
#include "analysis/cli/sweep_models.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <mutex>
#include <optional>

#include "analysis/cli/commands.hpp"
#include "analysis/cli/mpi_session.hpp"
#include "analysis/cli/output_checks.hpp"
#include "analysis/cli/physics_warnings.hpp"
#include "analysis/cli/run_model.hpp"
#include "analysis/cli/sweep_report.hpp"
#include "common/output_lock.hpp"

namespace granbench::cli {

namespace {

struct SharedSweep {
  std::vector<SweepPoint> points;  // all of them, on rank 0
  bool root = true;
  int ranks = 1;
  bool interrupted = false;
  int interrupt_exit_code = 130;  // 128 + the signal (SIGINT 130, SIGTERM 143)
  std::string refused, failure;   // the stored sweep does not match; writing --out failed
};

// Steps 1-3 of sweep_models.hpp. Every rank takes the same path through the collective calls;
// errors come back as values, to be raised after MPI_Finalize.
SharedSweep run_shared(SweepSpec spec, const OutputOptions& output,
                       const std::vector<std::string>& warnings) {
  MpiSession mpi;
  SharedSweep s;
  s.root = mpi.root();
  s.ranks = spec.ranks = mpi.size();
  spec.rank = mpi.rank();
  std::vector<double> kept{1.0};  // a leading 1: the stored points are usable
  // Rank 0 holds --out for the whole sweep: a second sweep on the same file is refused instead
  // of each rewriting the file without the other's points.
  std::optional<OutputLock> lock;
  if (s.root) try {
      if (!spec.out.empty()) lock.emplace(spec.out);
      const auto finished = pack_points(read_finished(spec));
      kept.insert(kept.end(), finished.begin(), finished.end());
    } catch (const std::invalid_argument& e) {
      kept = {0.0};
      s.refused = e.what();
    } catch (const OutputLock::LockHeld& e) {
      kept = {0.0};
      s.refused = std::string(e.what()) + ": another sweep is writing " + spec.out +
                  "; wait for it to finish or choose another --out";
    } catch (const std::runtime_error& e) {
      // No lock file where --out goes (a missing directory, no permission), or a stored file that
      // cannot be read: refused before any point runs, and on every rank alike.
      kept = {0.0};
      s.refused = e.what();
    }
  kept = mpi.broadcast(kept);
  if (kept[0] == 0.0) return s;
  if (s.root) print_warnings(warnings);  // (every check has passed)
  auto finished = unpack_points(std::span(kept).subspan(1));
  for (SweepPoint& p : finished) p.resumed = true;

  // SIGTERM (batch systems, `timeout`, containers) stops a sweep like Ctrl-C: the finished points
  // are kept (failure_policy.hpp).
  const InterruptGuard guard(InterruptGuard::Signals::IntAndTerm);
  std::mutex io;
  const bool show = s.root && progress_enabled(output);
  SweepProgress progress;
  progress.stop = guard.flag();
  // The ETA assumes the points left cost what the finished ones did on average.
  progress.point_done = [&, wall0 = std::chrono::steady_clock::now()](
                            const SweepPoint& p, std::size_t done, std::size_t total) {
    if (!show) return;
    std::lock_guard lock(io);
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    std::cerr << "  [" << done << "/" << total << "] " << p.model << " Lx = " << p.Lx
              << " m: growth " << p.growth_rate << " 1/s";
    if (!std::isnan(p.growth_rate_extrapolated))
      std::cerr << ", extrapolated " << p.growth_rate_extrapolated << " 1/s";
    std::cerr << " (" << p.wall_seconds << " s), "
              << eta_text(wall, 0.0, double(done), double(total)) << "\n";
  };
  auto ran = run_share(spec, finished, progress);
  if (s.ranks > 1) ran = unpack_points(mpi.gather(pack_points(ran)));
  s.interrupted = guard.flag()->load();
  s.interrupt_exit_code = guard.exit_code();
  if (s.root) try {
      s.points = finished;
      s.points.insert(s.points.end(), ran.begin(), ran.end());
      s.points = finish_sweep(spec, std::move(s.points));
    } catch (const std::exception& e) {
      s.failure = e.what();
    }
  const bool written = mpi.broadcast({s.failure.empty() ? 1.0 : 0.0})[0] == 1.0;
  if (written && s.ranks > 1 && !spec.out.empty())
    std::filesystem::remove(sweep_part_path(spec.out, spec.rank));
  return s;
}

}  // namespace

void run_sweep_command(SweepSpec spec, const OutputOptions& output, const nlohmann::json& settings,
                       const std::string& title, const std::vector<std::string>& warnings) {
  // Points are kept in the HDF5 file as they finish: that file is what a re-run resumes from.
  const bool keep_data = !output.out.empty();
  spec.out = keep_data ? output.out : (!output.plot.empty() ? output.plot + ".data.h5" : "");
  if (!spec.out.empty()) require_writable(spec.out, keep_data ? "--out" : "--plot");  // before work
  const auto start = std::chrono::steady_clock::now();
  const SharedSweep s = run_shared(spec, output, warnings);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!s.refused.empty()) throw UsageError("--out: " + s.refused);
  if (!s.root) return;
  if (!s.failure.empty()) throw CommandFailed("sweep: " + s.failure, 1);

  const auto& points = s.points;
  if (!output.plot.empty() && !points.empty()) {
    const bool depthavg_only = !spec.twod;
    run_plot_script(depthavg_only ? "sweep.py" : "sweep_models.py", spec.out, output.plot);
  }
  if (!keep_data && !output.plot.empty()) std::filesystem::remove(spec.out);

  const auto count = [&](auto pred) {
    return static_cast<std::size_t>(std::count_if(points.begin(), points.end(), pred));
  };
  const std::size_t finished = count([](const SweepPoint& p) { return p.completed; });
  const std::size_t resumed = count([](const SweepPoint& p) { return p.resumed; });
  if (output.json) {
    print_json(sweep_json(points, settings, spec.jobs, s.ranks, wall));
  } else {
    std::ostringstream head;
    head << title << " (" << std::fixed << std::setprecision(1) << wall << " s wall, " << spec.jobs
         << " jobs x " << s.ranks << " processes; " << resumed
         << " points kept from an earlier run)";
    print_table(points, head.str());
  }
  const std::size_t expected = spec.Lx.size() * ((spec.depthavg ? 1 : 0) + (spec.twod ? 1 : 0));
  // Without --out the points lived in a scratch file for the figure, removed above: nothing is
  // kept for a resume, and the message must not say otherwise.
  const std::string kept =
      keep_data ? " kept in " + spec.out + "; run the same command again to resume"
                : "; nothing is kept (give --out FILE to keep the points for a resume)";
  if (finished < expected && s.interrupted)
    throw CommandFailed("interrupted with " + std::to_string(finished) + " of " +
                            std::to_string(expected) + " points" + kept,
                        s.interrupt_exit_code);
  if (finished < expected) {
    const auto bad = std::find_if(points.begin(), points.end(),
                                  [](const SweepPoint& p) { return !p.completed; });
    std::ostringstream m;
    m << "sweep: " << expected - finished << " of " << expected << " points did not complete";
    if (bad != points.end())
      m << " (first: " << bad->model << " Lx = " << bad->Lx << ": "
        << (bad->message.empty() ? "unfinished" : bad->message) << ")";
    throw CommandFailed(m.str(), 3);
  }
}

}  // namespace granbench::cli
