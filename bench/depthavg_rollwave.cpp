// Benchmark (not a test) of the depth-averaged solver, issue 3 item 7.
//
// 1. The rollwave case of §7: Lx = 0.08 m, zeta = 28.5 deg, h0 = 4 mm, a0 = 0.2 mm (7.2),
//    regularised curve (6.3)-(6.4), nx = 512, t_end = 10 s, the defaults of `granbench run`
//    (central reconstruction, rtol 1e-6, atol 1e-10, band-preconditioned SPGMR):
//    wall time, CVODE steps, right-hand-side evaluations, linear iterations. Target < 1 s.
// 2. A linear-regime sweep of 24 domain lengths (0.03 .. 0.4 m, eigenmode seeding, the settings
//    of `granbench sweep`), run on 2 threads: wall time. Target < 10 s on 2 cores.
//
// Prints one JSON object. Usage: bench_depthavg_rollwave [--skip-sweep]
#include <atomic>
#include <chrono>
#include <cstring>
#include <iostream>
#include <nlohmann/json.hpp>
#include <thread>

#include "depthavg/linear_run.hpp"
#include "depthavg/initial_state.hpp"
#include "mu_curves.hpp"
#include "depthavg/solver.hpp"
#include "steady_state.hpp"
#include "wave_speed.hpp"

using namespace granbench;

int main(int argc, char** argv) {
  const bool skip_sweep = argc > 1 && std::strcmp(argv[1], "--skip-sweep") == 0;
  const Material material;
  const double h0 = 4e-3;
  const MuCurve curve(CurveKind::Regularised, material, h0);
  const SteadyState base = steady_state(curve, degrees_to_radians(28.5), h0);
  nlohmann::json out;

  // 1. The rollwave run.
  depthavg::SpaceParams space;
  space.Lx = 0.08;
  space.nx = 512;
  const depthavg::IntegratorParams integ;  // defaults, as `granbench run`
  depthavg::InitialParams init;
  init.a0 = 2e-4;
  depthavg::OutputParams output;
  output.t_end = 10.0;
  output.dt_out = 0.01;
  const depthavg::Solver solver(base, curve, space, integ);
  const auto U0 = depthavg::initial_state(solver.rhs(), init);
  const auto r = solver.run(U0, output);
  const auto ws = wave_speed(r.series, 0.5 * output.t_end, output.t_end);
  out["rollwave"] = {{"nx", space.nx},
                     {"t_end", output.t_end},
                     {"rtol", integ.rtol},
                     {"atol", integ.atol},
                     {"wall_seconds", r.wall_seconds},
                     {"steps", r.stats.steps},
                     {"rhs_evals", r.stats.rhs_evals},
                     {"rhs_evals_jtimes", r.stats.rhs_evals_jtimes},
                     {"rhs_evals_preconditioner", r.stats.rhs_evals_preconditioner},
                     {"rhs_evals_total", r.stats.total_rhs_evals()},
                     {"linear_iterations", r.stats.linear_iterations},
                     {"preconditioner_evals", r.stats.preconditioner_evals},
                     {"mass_error", r.mass_error()},
                     {"wave_speed", ws.speed},
                     {"microseconds_per_step", 1e6 * r.wall_seconds / r.stats.steps},
                     {"completed", r.status == depthavg::RunStatus::Completed},
                     {"target_seconds", 1.0}};

  // 2. The sweep of 24 domain lengths on 2 threads.
  if (!skip_sweep) {
    const int n = 24;
    std::vector<double> Lx(n);
    for (int i = 0; i < n; ++i) Lx[i] = 0.03 + (0.4 - 0.03) * i / (n - 1);
    std::vector<depthavg::LinearRunResult> res(n);
    std::atomic<int> next{0};
    const auto start = std::chrono::steady_clock::now();
    depthavg::LinearRunParams lp;  // as `granbench sweep`: nx = 192, tolerance 1e-6
    lp.nx = 192;
    auto worker = [&] {
      for (int i; (i = next++) < n;) res[i] = depthavg::linear_run(base, curve, 1.0, Lx[i], lp);
    };
    std::thread a(worker), b(worker);
    a.join();
    b.join();
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    double worst = 0.0;
    long steps = 0;
    for (const auto& p : res) {
      if (p.exact.growth_rate > 0.0) worst = std::max(worst, p.growth_relative_error());
      steps += p.stats.steps;
    }
    out["sweep"] = {{"points", n},        {"threads", 2},
                    {"wall_seconds", wall}, {"target_seconds", 10.0},
                    {"nx", lp.nx},          {"total_steps", steps},
                    {"worst_growth_relative_error_unstable", worst}};
  }
  std::cout << out.dump(2) << "\n";
}
