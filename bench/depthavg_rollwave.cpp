// Benchmark (not a test) of the depth-averaged solver.
//
// 1. The rollwave case of §7: Lx = 0.08 m, zeta = 28.5 deg, h0 = 4 mm, a0 = 0.2 mm (7.2),
//    regularised curve (6.3)-(6.4), nx = 512, t_end = 10 s, the settings of `granbench run`
//    (central reconstruction, rtol 1e-6, atol 1e-10, BDF order <= 2 (5 in the lab frame),
//    Newton systems by the exact periodic block-band solve, the frame moving at the linear phase
//    speed): wall time, CVODE steps, right-hand-side evaluations, Jacobians and linear solves.
//    Target < 1 s on one core. Also at rtol
//    1e-4 (atol 1e-8), and in the lab frame (`--frame-speed 0`). docs/performance.md has the time
//    error of each.
// 2. A linear-regime sweep of 24 domain lengths (0.03 .. 0.4 m, eigenmode seeding, the settings
//    of `granbench sweep`) on 2 threads, lab and co-moving frames: wall time. Target < 10 s.
//
// Prints one JSON object. Usage: bench_depthavg_rollwave [--skip-lab] [--skip-sweep]
// (--skip-lab skips the slow lab-frame rollwave, --skip-sweep the two sweeps)
#include <atomic>
#include <chrono>
#include <cstring>
#include <ctime>
#include <iostream>
#include <nlohmann/json.hpp>
#include <thread>

#include "analysis/comparison/depthavg_linear_run.hpp"
#include "analysis/spectral/wave_speed.hpp"
#include "analysis/theory/dispersion.hpp"
#include "common/mu_curves.hpp"
#include "common/steady_state.hpp"
#include "depthavg/initial_state.hpp"
#include "depthavg/solver.hpp"

using namespace granbench;

namespace {

nlohmann::json rollwave(const SteadyState& base, const MuCurve& curve, double frame_speed,
                        double rtol, double atol, int max_order) {
  depthavg::SpaceParams space;
  space.Lx = 0.08;
  space.nx = 512;
  space.frame_speed = frame_speed;
  depthavg::IntegratorParams integ;
  integ.rtol = rtol;
  integ.atol = atol;
  integ.max_order = max_order;  // as `granbench run`: 2 co-moving, 5 in the lab frame
  depthavg::InitialParams init;
  init.a0 = 2e-4;
  depthavg::OutputParams output;
  output.t_end = 10.0;
  output.dt_out = 0.01;
  const depthavg::Solver solver(base, curve, space, integ);
  const std::clock_t cpu0 = std::clock();
  const auto r = solver.run(depthavg::initial_state(solver.rhs(), init), output);
  const double cpu = static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC;
  const auto ws = wave_speed(r.series, 0.5 * output.t_end, output.t_end);
  return {{"frame_speed", frame_speed},
          {"nx", space.nx},
          {"t_end", output.t_end},
          {"rtol", integ.rtol},
          {"max_order", integ.max_order},
          {"atol", integ.atol},
          {"wall_seconds", r.wall_seconds},
          {"cpu_seconds", cpu},  // the machine may be shared: CPU time is the fairer figure
          {"steps", r.stats.steps},
          {"rhs_evals", r.stats.rhs_evals},
          {"rhs_evals_jtimes", r.stats.rhs_evals_jtimes},
          {"rhs_evals_jacobian", r.stats.rhs_evals_jacobian},
          {"rhs_evals_total", r.stats.total_rhs_evals()},
          {"linear_iterations", r.stats.linear_iterations},
          {"jacobian_evals", r.stats.jacobian_evals},
          {"linear_solves", r.stats.linear_solves},
          {"nonlinear_iterations", r.stats.nonlinear_iterations},
          {"error_test_failures", r.stats.error_test_failures},
          {"nonlinear_convergence_failures", r.stats.nonlinear_convergence_failures},
          {"last_order", r.stats.last_order},
          {"microseconds_per_step", 1e6 * r.wall_seconds / r.stats.steps},
          {"mass_error", r.mass_error()},
          {"wave_speed", ws.speed},
          {"completed", r.status == depthavg::RunStatus::Completed},
          {"target_seconds", 1.0}};
}

nlohmann::json sweep(const SteadyState& base, const MuCurve& curve, bool co_moving) {
  const int n = 24;
  std::vector<double> Lx(n);
  for (int i = 0; i < n; ++i) Lx[i] = 0.03 + (0.4 - 0.03) * i / (n - 1);
  std::vector<depthavg::LinearRunResult> res(n);
  std::atomic<int> next{0};
  depthavg::LinearRunParams lp;  // as `granbench sweep`: nx = 192, tolerance 1e-6
  lp.nx = 192;
  lp.co_moving = co_moving;
  const auto start = std::chrono::steady_clock::now();
  const std::clock_t cpu0 = std::clock();
  auto worker = [&] {
    for (int i; (i = next++) < n;) res[i] = depthavg::linear_run(base, curve, 1.0, Lx[i], lp);
  };
  std::thread a(worker), b(worker);
  a.join();
  b.join();
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double cpu = static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC;
  double worst_g = 0.0, worst_c = 0.0;
  long steps = 0;
  for (const auto& p : res) {
    if (p.exact.growth_rate > 0.0) worst_g = std::max(worst_g, p.growth_relative_error());
    worst_c = std::max(worst_c, p.speed_relative_error());
    steps += p.stats.steps;
  }
  return {{"points", n},
          {"threads", 2},
          {"co_moving", co_moving},
          {"nx", lp.nx},
          {"wall_seconds", wall},
          {"cpu_seconds_both_threads", cpu},
          {"target_seconds", 10.0},
          {"total_steps", steps},
          {"worst_growth_relative_error_unstable", worst_g},
          {"worst_phase_speed_relative_error", worst_c}};
}

}  // namespace

int main(int argc, char** argv) {
  bool skip_lab = false, skip_sweep = false;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--skip-lab") == 0)
      skip_lab = true;
    else if (std::strcmp(argv[i], "--skip-sweep") == 0)
      skip_sweep = true;
    else {
      std::cerr << "usage: bench_depthavg_rollwave [--skip-lab] [--skip-sweep]\n";
      return 2;
    }
  }
  const Material material;
  const double h0 = 4e-3;
  const MuCurve curve(CurveKind::Regularised, material, h0);
  const SteadyState base = steady_state(curve, degrees_to_radians(28.5), h0);
  const double c_linear = dispersion_mode(base, 1.0, 0.08).phase_speed;
  nlohmann::json out;
  out["rollwave_comoving"] = rollwave(base, curve, c_linear, 1e-6, 1e-10, 2);
  out["rollwave_comoving_rtol_1e-4"] = rollwave(base, curve, c_linear, 1e-4, 1e-8, 2);
  if (!skip_lab) out["rollwave_lab"] = rollwave(base, curve, 0.0, 1e-6, 1e-10, 5);
  if (!skip_sweep) {
    out["sweep_lab"] = sweep(base, curve, false);
    out["sweep_comoving"] = sweep(base, curve, true);
  }
  std::cout << out.dump(2) << "\n";
}
