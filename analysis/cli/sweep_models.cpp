// The two-model dispersion sweep; see sweep_models.hpp.
#include "sweep_models.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <mutex>

#include "commands.hpp"
#include "run_model.hpp"
#include "sweep.hpp"

namespace granbench::cli {

void run_model_sweep(const FlowOptions& flow, const OutputOptions& output,
                     const ModelSweepOptions& o) {
  SweepSpec spec;
  spec.chute.material = flow.material;
  spec.chute.curve = flow.curve_kind();
  spec.chute.angle_deg = flow.angle_deg;
  spec.chute.h0 = flow.h0;
  spec.chute.t_end = o.t_end;
  (void)flow.steady();  // a slope with no steady flow is an error on --angle
  spec.Lx = o.Lx;
  spec.depthavg = o.depthavg;
  spec.twod = o.twod;
  spec.depthavg_settings.nx = o.nx_depthavg;
  spec.depthavg_settings.chi = o.chi;
  spec.twod_settings.nx = o.nx;
  spec.twod_settings.nz = o.nz;
  spec.jobs = o.jobs;
  // Points are kept in the HDF5 file as they finish: that file is what a re-run resumes from.
  spec.out = !output.out.empty() ? output.out : (!output.plot.empty() ? output.plot + ".data.h5" : "");

  const InterruptGuard guard;
  std::mutex io;
  const bool show = progress_enabled(output);
  SweepProgress progress;
  progress.stop = guard.flag();
  progress.point_done = [&](const SweepPoint& p, std::size_t done, std::size_t total) {
    if (!show) return;
    std::lock_guard lock(io);
    std::cerr << "  [" << done << "/" << total << "] " << p.model << " Lx = " << p.Lx
              << " m: growth " << p.growth_rate << " 1/s (" << p.wall_seconds << " s)\n";
  };
  const auto start = std::chrono::steady_clock::now();
  const auto points = run_sweep(spec, progress);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  if (!output.plot.empty() && !points.empty()) run_plot_script("sweep_models.py", spec.out, output.plot);
  if (output.out.empty() && !output.plot.empty()) std::filesystem::remove(spec.out);

  if (output.json) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& p : points)
      list.push_back({{"model", p.model},
                      {"Lx", p.Lx},
                      {"k_hat", p.k_hat},
                      {"growth_rate", number_or_null(p.growth_rate)},
                      {"growth_rate_exact", p.growth_rate_exact},
                      {"phase_speed", number_or_null(p.phase_speed)},
                      {"phase_speed_exact", p.phase_speed_exact},
                      {"growth_rate_712", number_or_null(p.growth_rate_712)},
                      {"exact_711", {{"growth_rate", p.theory.exact.growth_rate},
                                     {"phase_speed", p.theory.exact.phase_speed}}},
                      {"exact_bagnold", {{"growth_rate", p.theory.exact_bagnold.growth_rate},
                                         {"phase_speed", p.theory.exact_bagnold.phase_speed}}},
                      {"exact_2d", {{"growth_rate", p.theory.exact_2d.growth_rate},
                                    {"phase_speed", p.theory.exact_2d.phase_speed}}},
                      {"wall_seconds", p.wall_seconds},
                      {"completed", p.completed}});
    print_json({{"wall_seconds", wall}, {"jobs", o.jobs}, {"points", list}});
  } else {
    std::cout << "sweep over " << o.Lx.size() << " domain lengths (" << std::fixed
              << std::setprecision(1) << wall << " s wall, " << o.jobs << " jobs)\n"
              << std::setw(10) << "model" << std::setw(9) << "Lx [m]" << std::setw(11) << "growth"
              << std::setw(11) << "theory" << std::setw(11) << "speed" << std::setw(11)
              << "theory" << "\n";
    for (const auto& p : points)
      std::cout << std::setw(10) << p.model << std::setprecision(4) << std::setw(9) << p.Lx
                << std::setprecision(3) << std::setw(11) << p.growth_rate << std::setw(11)
                << p.growth_rate_exact << std::setw(11) << p.phase_speed << std::setw(11)
                << p.phase_speed_exact << (p.completed ? "" : "  (unfinished)") << "\n";
  }
  const std::size_t expected = o.Lx.size() * ((o.depthavg ? 1 : 0) + (o.twod ? 1 : 0));
  const auto finished = static_cast<std::size_t>(
      std::count_if(points.begin(), points.end(), [](const SweepPoint& p) { return p.completed; }));
  if (finished < expected)
    throw CommandFailed("interrupted with " + std::to_string(finished) + " of " +
                            std::to_string(expected) + " points kept in " + spec.out +
                            "; run the same command again to resume",
                        130);
}

}  // namespace granbench::cli
