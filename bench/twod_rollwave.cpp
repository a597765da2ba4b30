// Benchmark of the 2D solver on the §7 rollwave case (not a test): Lx = 0.08 m, zeta = 28.5 deg,
// h0 = 4 mm, a0 = 0.2 mm, Lz = 2 h0, regularised curve, at 256 x 64 and 512 x 128 cells.
// Prints, per grid, the thread count, the steps, wall and CPU seconds, cell updates per second
// (cells x steps / wall, and per CPU second), the mean linear-solver iterations, the mass error,
// and the wall time a 10 s run would take at the measured rate. Before the runs, a STREAM-like
// triad a = b + s c over three 32 MiB arrays (far larger than the caches) measures the memory
// bandwidth with the same thread count, the reference for the cell-update rate: the solver's
// loops are memory bound, so bandwidth / (cell updates per second) is the bytes it moves per
// cell update. Before and after the runs, a ping-pong of one cache line between two threads
// measures the cores' round-trip latency: on this project's virtual machine it is 110 ns in some
// hours and 420-490 ns in others (the two virtual cores placed near or far apart), and the
// two-thread speed-up follows it, because every parallel loop hands data from core to core. The
// probe runs only when the process may use two CPUs or more (its affinity mask: under `taskset`
// to one CPU it would spin for minutes), and a thread count above the available CPUs is named
// on stderr (JSON `available_cpus`). With two CPUs or more, one thread runs once pinned to each
// (`pinned_to_cpu`): the host at times runs one virtual CPU well below the other, and each run
// with more threads reports its speed-up against the fastest and the slowest of them.
//
//   bench_twod_rollwave                 256x64 to t = 1 s, 512x128 to t = 0.05 s
//   bench_twod_rollwave T1 T2           the two end times [s] (0 skips a grid)
//   bench_twod_rollwave T1 T2 1,2       each grid once per thread count, back to back
//   bench_twod_rollwave T1 T2 1,2 F     the grid moving at F times the steady surface speed
//                                       (default 0.5, as granbench's runs; 0: the lab frame)
// Without the third argument the thread count is OpenMP's default (OMP_NUM_THREADS or all
// cores). The results are identical for every thread count (twod/parallel.hpp); only the times
// differ. Timing on a loaded machine is meaningless: check `uptime` first.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "bench/core_placement.hpp"
#include "common/steady_state.hpp"
#include "twod/diagnostics.hpp"
#include "twod/initial_state.hpp"
#include "twod/parallel.hpp"
#include "twod/solver.hpp"

using namespace granbench;
using namespace granbench::twod;
using granbench::bench::allowed_cpus;
using granbench::bench::available_cpus;
using granbench::bench::core_round_trip_ns;
using granbench::bench::pin_calling_thread;

namespace {

// STREAM triad a_i = b_i + s c_i on `threads` std::threads, each on its own contiguous part
// (first touched by that thread). Best of 10 repetitions; bytes counted as STREAM does (3 x 8
// per entry: two reads, one write). Returns GB/s (1e9 bytes).
double triad_bandwidth(int threads) {
  const std::size_t n = std::size_t(4) << 20;  // 4 Mi doubles = 32 MiB per array
  std::vector<double> a(n), b(n), c(n);
  auto parallel = [&](auto&& body) {
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t)
      pool.emplace_back([&, t] { body(n * t / threads, n * (t + 1) / threads); });
    for (auto& th : pool) th.join();
  };
  parallel([&](std::size_t lo, std::size_t hi) {
    for (std::size_t i = lo; i < hi; ++i) {
      a[i] = 0.0;
      b[i] = 1.0 + 1e-9 * double(i);
      c[i] = 2.0;
    }
  });
  const double s = 3.0;
  double best = 1e30;
  for (int rep = 0; rep < 10; ++rep) {
    const auto t0 = std::chrono::steady_clock::now();
    parallel([&](std::size_t lo, std::size_t hi) {
      for (std::size_t i = lo; i < hi; ++i) a[i] = b[i] + s * c[i];
    });
    best = std::min(best,
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  volatile double sink = a[n / 2];  // keep the stores
  (void)sink;
  return 3.0 * 8.0 * double(n) / best / 1e9;
}

nlohmann::json run(int nx, int nz, double t_end, int threads, double frame_fraction) {
  SolverParams params;
  params.zeta = degrees_to_radians(28.5);
  params.threads = threads;
  const double h0 = 4e-3, Lx = 0.08, a0 = 2e-4;
  const MuCurve curve(CurveKind::Regularised, params.rheology.material, h0);
  const SteadyState steady = steady_state(curve, params.zeta, h0);
  Grid g(nx, nz, Lx, 2.0 * h0);
  g.frame_speed = frame_fraction * steady.u_surface;  // (twod/frame.hpp)
  Solver solver(g, params, make_initial_state(g, perturbed_bagnold(steady, a0, Lx), params));
  const auto w0 = std::chrono::steady_clock::now();
  const std::clock_t c0 = std::clock();
  solver.advance_to(t_end);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
  const double cpu = double(std::clock() - c0) / CLOCKS_PER_SEC;
  const RunStatistics st = solver.statistics();
  const double updates = double(st.steps) * double(g.cells());
  return {{"threads", threads},
          {"frame_speed", g.frame_speed},
          {"nx", nx},
          {"nz", nz},
          {"t_end", t_end},
          {"steps", st.steps},
          {"wall_seconds", wall},
          {"cpu_seconds", cpu},
          {"cell_updates_per_second", updates / wall},
          {"cell_updates_per_cpu_second", updates / cpu},
          {"mean_dt", t_end / double(st.steps)},
          {"viscous_iterations_per_step", double(st.viscous_iterations) / double(st.steps)},
          {"projection_iterations_per_step", double(st.projection_iterations) / double(st.steps)},
          {"mass_error", st.mass_error()},
          {"wall_seconds_per_simulated_second", wall / t_end},
          {"projected_wall_seconds_to_10s", 10.0 * wall / t_end}};
}
}  // namespace

int main(int argc, char** argv) {
  const double t1 = argc > 1 ? std::atof(argv[1]) : 1.0;
  const double t2 = argc > 2 ? std::atof(argv[2]) : 0.05;
  std::vector<int> thread_counts;
  if (argc > 3) {
    std::stringstream list(argv[3]);
    for (std::string item; std::getline(list, item, ',');) {
      const int n = std::atoi(item.c_str());
      if (n < 1) {
        std::cerr << "bench_twod_rollwave: thread counts must be integers >= 1\n";
        return 2;
      }
      thread_counts.push_back(n);
    }
  } else {
    thread_counts.push_back(thread_count());
  }
  const double frame_fraction = argc > 4 ? std::atof(argv[4]) : 0.5;
  if (!(frame_fraction >= 0.0 && frame_fraction <= 1.0)) {
    std::cerr << "bench_twod_rollwave: the frame fraction must be in [0, 1]\n";
    return 2;
  }
  nlohmann::json out = {{"case", "rollwave Lx=0.08 zeta=28.5 h0=4mm a0=0.2mm Lz=2h0 regularised"},
                        {"hardware_threads", std::thread::hardware_concurrency()},
                        {"triad_bandwidth_GB_per_s", nlohmann::json::object()},
                        {"runs", nlohmann::json::array()}};
  const int cpus = available_cpus();
  const std::vector<int> allowed_cpus_at_start = allowed_cpus();
  out["available_cpus"] = cpus;
  const bool two_cores = cpus >= 2;
  if (!two_cores)
    std::cerr << "bench_twod_rollwave: one CPU available (affinity mask): no core round trip\n";
  for (int threads : thread_counts)
    if (threads > cpus)
      std::cerr << "bench_twod_rollwave: warning: " << threads << " threads on " << cpus
                << " available CPUs: the threads take turns, so the times do not measure "
                   "scaling\n";
  if (two_cores) {
    out["core_round_trip_ns"]["before"] = core_round_trip_ns();
    std::cerr << "core-to-core round trip " << out["core_round_trip_ns"]["before"] << " ns\n";
  }
  for (int threads : thread_counts) {
    const double bw = triad_bandwidth(threads);
    out["triad_bandwidth_GB_per_s"][std::to_string(threads)] = bw;
    std::cerr << "threads " << threads << ": triad bandwidth " << bw << " GB/s\n";
  }
  for (auto [nx, nz, t] : {std::tuple{256, 64, t1}, std::tuple{512, 128, t2}}) {
    if (t <= 0.0) continue;
    nlohmann::json grid_runs = nlohmann::json::array();
    for (int threads : thread_counts) {
      // One thread once on each CPU, pinned: the host at times runs one of the two virtual CPUs
      // 1.3-1.7 times slower than the other, and a second thread is to be judged against the
      // best one thread can do (docs/performance.md).
      const std::vector<int> placements =
          threads == 1 && two_cores ? allowed_cpus_at_start : std::vector<int>{-1};
      for (int cpu : placements) {
        const bool pin = cpu >= 0 && pin_calling_thread({cpu});
        nlohmann::json r = run(nx, nz, t, threads, frame_fraction);
        if (pin) pin_calling_thread(allowed_cpus_at_start);
        r["pinned_to_cpu"] = pin ? nlohmann::json(cpu) : nlohmann::json(nullptr);
        const double bw = out["triad_bandwidth_GB_per_s"][std::to_string(threads)];
        r["triad_bandwidth_GB_per_s"] = bw;
        r["bytes_per_cell_update_at_triad_bandwidth"] =
            bw * 1e9 / r["cell_updates_per_second"].get<double>();
        grid_runs.push_back(r);
        std::cerr << "threads " << threads << ": " << r.dump() << "\n";
      }
    }
    // The speed-up of each run with more threads against the fastest and the slowest run on one.
    double fastest = 0.0, slowest = 0.0;
    for (const auto& r : grid_runs)
      if (r["threads"] == 1) {
        const double wall = r["wall_seconds"];
        fastest = fastest > 0.0 ? std::min(fastest, wall) : wall;
        slowest = std::max(slowest, wall);
      }
    for (auto& r : grid_runs) {
      if (fastest > 0.0 && r["threads"].get<int>() > 1) {
        r["speedup_against_fastest_one_thread"] = fastest / r["wall_seconds"].get<double>();
        r["speedup_against_slowest_one_thread"] = slowest / r["wall_seconds"].get<double>();
      }
      out["runs"].push_back(r);
    }
  }
  if (two_cores) out["core_round_trip_ns"]["after"] = core_round_trip_ns();
  std::cout << out.dump(2) << "\n";
}
