// Benchmark of the projection's linear solve alone (not a test): the multigrid-preconditioned
// conjugate gradients of twod/projection.cpp on the pressure operator of a real state of the §7
// rollwave case (Lx = 0.08 m, zeta = 28.5 deg, h0 = 4 mm, a0 = 0.2 mm, Lz = 2 h0), after the
// solver has run to t_state, so that the operator holds the wavy surface's density jump as the
// VOF left it (the faces' densities from the fill fractions, 1500 against the default light fluid).
//
// Per grid it solves A x = b from x = 0 to the projection's tolerance, for b a fixed
// pseudo-random field (white: every scale of the error is excited, the smooth ones that the
// coarse levels must remove among them; b = A x for a random x would put nearly all of it at the
// scales the smoother removes, and took 7 iterations at 256 x 64 where this takes 10), and prints
// as JSON: the multigrid's levels and coarsest grid, the iterations, the mean reduction of the
// residual per iteration (tol^(1/iterations)), and the wall time per solve and per iteration (best
// of `repeats`). A running solve starts from the previous step's increment and takes fewer
// iterations (9.3 per step at 256 x 64 over the 10-s rollwave); this measures the preconditioner's
// convergence factor, the figure that a change to the multigrid's smoother, transfers or coarse
// operators moves (docs/performance.md, "The pressure multigrid's coarse operators").
//
//   bench_pressure_multigrid                  256x64, 160x64, 160x16, 512x128; state at 0.05 s
//   bench_pressure_multigrid NXxNZ[,...] T R  the grids, the state's time, repeats per solve
// One thread (the solve's arithmetic is the same for any count; parallel.hpp).
#include "twod/pressure_multigrid.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/steady_state.hpp"
#include "twod/initial_state.hpp"
#include "twod/pcg.hpp"
#include "twod/projection.hpp"
#include "twod/solver.hpp"

using namespace granbench;
using namespace granbench::twod;

namespace {

std::vector<std::pair<int, int>> parse_grids(const std::string& text) {
  std::vector<std::pair<int, int>> grids;
  std::stringstream list(text);
  for (std::string item; std::getline(list, item, ',');) {
    const auto x = item.find('x');
    if (x == std::string::npos) throw std::invalid_argument("grid '" + item + "' is not NXxNZ");
    grids.emplace_back(std::stoi(item.substr(0, x)), std::stoi(item.substr(x + 1)));
  }
  return grids;
}

nlohmann::json measure(int nx, int nz, double t_state, int repeats) {
  const double h0 = 0.004, Lx = 0.08, a0 = 2e-4;
  SolverParams params;
  params.zeta = degrees_to_radians(28.5);
  params.threads = 1;
  const MuCurve curve(CurveKind::Regularised, params.rheology.material, h0);
  const SteadyState steady = steady_state(curve, params.zeta, h0);
  Grid g(nx, nz, Lx, 2.0 * h0);
  g.frame_speed = 0.5 * steady.u_surface;  // as granbench's runs (twod/frame.hpp)
  Solver solver(g, params, make_initial_state(g, perturbed_bagnold(steady, a0, Lx), params));
  solver.advance_to(t_state);

  PressureMultigrid multigrid;
  PoissonLevel& op = multigrid.fine_operator(nx, nz, g.dx / g.dz);
  fill_pressure_operator(g, solver.properties(), op);
  multigrid.rebuild();
  const auto [coarsest_nx, coarsest_nz] = coarsest_level(nx, nz, g.dx / g.dz);

  std::mt19937 random(12345);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::VectorXd b(nx * nz), x;
  for (auto& v : b) v = uniform(random);

  const double tol = params.solver_tolerance;
  PcgWorkspace work;
  int iterations = 0;
  double best = 1e30;
  for (int r = 0; r < repeats; ++r) {
    x.setZero(nx * nz);
    const auto t0 = std::chrono::steady_clock::now();
    iterations =
        pcg([&](const Eigen::VectorXd& v, Eigen::VectorXd& y) { op.apply(v, y); },
            [&](const Eigen::VectorXd& rr, Eigen::VectorXd& z) { multigrid.precondition(rr, z); },
            b, x, tol, 500, work);
    best = std::min(best,
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return {{"nx", nx},
          {"nz", nz},
          {"state_time_s", t_state},
          {"levels", multigrid.levels()},
          {"coarsest", {coarsest_nx, coarsest_nz}},
          {"tolerance", tol},
          {"iterations", iterations},
          {"reduction_per_iteration", iterations > 0 ? std::pow(tol, 1.0 / iterations) : 0.0},
          {"ms_per_solve", 1e3 * best},
          {"ms_per_iteration", iterations > 0 ? 1e3 * best / iterations : 0.0}};
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const auto grids = parse_grids(argc > 1 ? argv[1] : "256x64,160x64,160x16,512x128");
    const double t_state = argc > 2 ? std::stod(argv[2]) : 0.05;
    const int repeats = argc > 3 ? std::stoi(argv[3]) : 20;
    nlohmann::json out = {{"benchmark", "pressure_multigrid"}, {"grids", nlohmann::json::array()}};
    for (const auto& [nx, nz] : grids) {
      out["grids"].push_back(measure(nx, nz, t_state, repeats));
      std::cerr << "bench_pressure_multigrid: " << nx << " x " << nz << " done\n";
    }
    std::cout << out.dump(2) << "\n";
  } catch (const std::exception& e) {
    std::cerr << "bench_pressure_multigrid: " << e.what() << "\n";
    return 1;
  }
}
