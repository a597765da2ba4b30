// Benchmark of the 2D solver on the §7 rollwave case (not a test): Lx = 0.08 m, zeta = 28.5 deg,
// h0 = 4 mm, a0 = 0.2 mm, Lz = 2 h0, regularised curve, at 256 x 64 and 512 x 128 cells.
// Prints, per grid, the steps, wall and CPU seconds, cell updates per second (cells x steps /
// wall), the mean linear-solver iterations, the mass error, and the wall time a 10 s run would
// take at the measured rate.
//
//   bench_twod_rollwave                 256x64 to t = 1 s, 512x128 to t = 0.05 s
//   bench_twod_rollwave T1 T2           the two end times [s]
#include <chrono>
#include <cmath>
#include <ctime>
#include <iostream>
#include <nlohmann/json.hpp>

#include "diagnostics.hpp"
#include "initial_state.hpp"
#include "solver.hpp"
#include "steady_state.hpp"

using namespace granbench;
using namespace granbench::twod;

namespace {
nlohmann::json run(int nx, int nz, double t_end) {
  SolverParams params;
  params.zeta = degrees_to_radians(28.5);
  const double h0 = 4e-3, Lx = 0.08, a0 = 2e-4;
  const MuCurve curve(CurveKind::Regularised, params.rheology.material, h0);
  const SteadyState steady = steady_state(curve, params.zeta, h0);
  const Grid g(nx, nz, Lx, 2.0 * h0);
  Solver solver(g, params, make_initial_state(g, perturbed_bagnold(steady, a0, Lx), params));
  const auto w0 = std::chrono::steady_clock::now();
  const std::clock_t c0 = std::clock();
  solver.advance_to(t_end);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
  const double cpu = double(std::clock() - c0) / CLOCKS_PER_SEC;
  const RunStatistics st = solver.statistics();
  const double updates = double(st.steps) * double(g.cells());
  return {{"nx", nx},
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
  nlohmann::json out = {{"case", "rollwave Lx=0.08 zeta=28.5 h0=4mm a0=0.2mm Lz=2h0 regularised"},
                        {"runs", nlohmann::json::array()}};
  for (auto [nx, nz, t] : {std::tuple{256, 64, t1}, std::tuple{512, 128, t2}}) {
    if (t <= 0.0) continue;
    out["runs"].push_back(run(nx, nz, t));
    std::cerr << out["runs"].back().dump() << "\n";
  }
  std::cout << out.dump(2) << "\n";
}
