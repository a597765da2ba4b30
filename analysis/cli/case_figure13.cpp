// `granbench case figure13`: figure 13 with the 2D model. The 2D sweep over the case's domain
// lengths runs twice (analysis/comparison/sweep.hpp), in the two ways a growth rate can be taken
// from a 2D run:
//   sine       the paper's protocol: the sine start (7.2) at the paper's a0 = 0.2 mm, and the
//              estimator (7.12) averaged over the fixed window of the linear period (0.5-3 s in
//              figure 12);
//   eigenmode  the least-stable mode of the exact 2D linear theory at a small amplitude, and the
//              matrix-pencil fit of the seeded mode (analysis/spectral/measurement.hpp).
// Both beside (7.11), its chi = 5/4 form and the exact 2D theory at every length. Each sweep
// keeps its points in <name>_sine.h5 and <name>_eigenmode.h5 as they finish (an interrupted
// case resumes them when run again); the theories' curves go to <name>_theory.h5 and the figure
// to <name>.png.
#include <chrono>
#include <cmath>
#include <iostream>

#include "analysis/cli/case_kinds.hpp"
#include "analysis/cli/dispersion_output.hpp"
#include "analysis/cli/output_checks.hpp"
#include "analysis/comparison/model_runs.hpp"
#include "analysis/comparison/sweep.hpp"
#include "analysis/linear2d/base_state.hpp"
#include "common/failure_policy.hpp"
#include "common/hdf5_file.hpp"

namespace granbench::cli {

namespace {

// The sweep both protocols share: the flow, the lengths and the 2D grid preset of the file.
SweepSpec shared_spec(const cases::CaseFile& f, const std::string& res, unsigned jobs) {
  SweepSpec s;
  try {
    s.chute.curve = parse_curve_name(f.text("curve", res));
  } catch (const std::exception& e) {
    throw cases::CaseFileError(f.path() + ": key 'curve': " + e.what());
  }
  s.chute.angle_deg = f.number_in("angle", res, 0.1, 89.0);
  s.chute.h0 = f.number_in("h0", res, 1e-5, 1.0);
  s.Lx = f.numbers("Lx", res);
  if (s.Lx.empty())
    throw cases::CaseFileError(f.path() + ": key 'Lx' must list at least one length");
  for (double L : s.Lx)
    if (!(L > 0.0 && L < 100.0))
      throw cases::CaseFileError(f.path() + ": key 'Lx': every length in (0, 100) m");
  try {
    const GridPreset g = grid_preset(f.text("grid", res));
    s.twod_settings.nx = g.twod_nx;
    s.twod_settings.nz = g.twod_nz;
    s.twod_settings.aimed_growth_deficit = g.twod_aimed_growth_deficit;
  } catch (const std::invalid_argument&) {
    throw cases::CaseFileError(f.path() + ": key 'grid' = '" + f.text("grid", res) +
                               "'; valid values {coarse,default,fine}");
  }
  s.depthavg = false;
  s.twod = true;
  s.jobs = jobs;
  return s;
}

// The sweep of one protocol ("sine" or "eigenmode"): its start, amplitude and run length.
SweepSpec protocol_spec(const SweepSpec& shared, const cases::CaseFile& f, const std::string& res,
                        const std::string& protocol, const std::string& out) {
  SweepSpec s = shared;
  s.chute.seed = protocol == "sine" ? Seed::Sine : Seed::Eigenmode;
  s.chute.a0 = f.number_in(protocol + "_a0", res, 1e-9, 0.5 * s.chute.h0);
  s.chute.t_end = f.number_in(protocol + "_t_end", res, 1e-3, 100.0);
  if (protocol == "sine") {
    const std::vector<double> w = f.numbers("sine_window", res);
    if (w.size() != 2 || !(0.0 <= w[0] && w[0] < w[1] && w[1] <= s.chute.t_end))
      throw cases::CaseFileError(
          f.path() + ": key 'sine_window' must be [t0, t1], 0 <= t0 < t1 <= sine_t_end");
    s.window_712 = {w[0], w[1]};
  }
  s.out = out;
  return s;
}

double relative(double measured, double exact) {
  return (measured - exact) / std::fabs(exact);
}

// One length: the three theories and each protocol's growth rate with its deviation from the
// exact 2D theory (null where there is no measurement).
nlohmann::json point_json(const SweepPoint& sine, const SweepPoint& eigen) {
  const double exact_2d = sine.theory.exact_2d.growth_rate;
  return {{"Lx", sine.Lx},
          {"k_hat", sine.k_hat},
          {"exact_711", sine.theory.exact.growth_rate},
          {"exact_bagnold", sine.theory.exact_bagnold.growth_rate},
          {"exact_2d", exact_2d},
          {"sine_712", number_or_null(sine.growth_rate_712)},
          {"sine_712_vs_2d", number_or_null(relative(sine.growth_rate_712, exact_2d))},
          {"sine_spectral", number_or_null(sine.growth_rate)},
          {"eigenmode_spectral", number_or_null(eigen.growth_rate)},
          {"eigenmode_vs_2d", number_or_null(relative(eigen.growth_rate, exact_2d))},
          {"completed", sine.completed && eigen.completed},
          {"sine_message",
           sine.message},  // what stopped the run or its fit (not stored: empty when resumed)
          {"eigenmode_message", eigen.message}};
}

}  // namespace

nlohmann::json run_figure13_kind(const cases::CaseFile& file, const CaseOptions& o,
                                 int& exit_code) {
  const std::string& res = o.resolution;
  const SweepSpec shared = shared_spec(file, res, o.jobs);
  const std::string stem = path_in(o, file.name());
  const SweepSpec sine = protocol_spec(shared, file, res, "sine", stem + "_sine.h5");
  const SweepSpec eigen = protocol_spec(shared, file, res, "eigenmode", stem + "_eigenmode.h5");
  const std::string theory_h5 = stem + "_theory.h5", png = stem + ".png";
  for (const std::string& path : {sine.out, eigen.out, theory_h5, png})
    require_writable(path, "--out-dir");
  const auto claim_sine = claim_output(sine.out, "--out-dir");
  const auto claim_eigen = claim_output(eigen.out, "--out-dir");

  // The theories' curves first (seconds): the figure's lines.
  const SteadyState base = shared.chute.steady();
  {
    H5Writer out(theory_h5);
    write_theory_curves(out, base, linear2d::mu_i_base_state(base, shared.chute.make_curve()), 32);
    write_flow_inputs(out, std::string(curve_name(shared.chute.curve)), base.material,
                      shared.chute.angle_deg, shared.chute.h0);
    out.attribute("/", "u_mean", base.u_mean);
    out.close();
  }

  const InterruptGuard guard(InterruptGuard::Signals::IntAndTerm);
  const std::size_t total = 2 * shared.Lx.size();
  std::size_t offset = 0;
  SweepProgress progress;
  progress.stop = guard.flag();
  if (progress_enabled(o.output))
    progress.point_done = [&, wall0 = std::chrono::steady_clock::now()](
                              const SweepPoint& p, std::size_t done, std::size_t) {
      const double wall =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
      std::cerr << "  [" << offset + done << "/" << total << "] "
                << (offset == 0 ? "sine" : "eigenmode") << " Lx = " << p.Lx << " m: growth "
                << p.growth_rate << " 1/s, "
                << eta_text(wall, 0.0, double(offset + done), double(total)) << "\n";
    };
  const std::vector<SweepPoint> sine_points = run_sweep(sine, progress);
  offset = shared.Lx.size();
  const std::vector<SweepPoint> eigen_points =
      guard.flag()->load() ? std::vector<SweepPoint>{} : run_sweep(eigen, progress);
  if (guard.flag()->load()) exit_code = guard.exit_code();

  std::size_t resumed = 0;  // points read back from the sweep files of an earlier run
  for (const auto* list : {&sine_points, &eigen_points})
    for (const SweepPoint& p : *list) resumed += p.resumed ? 1 : 0;
  nlohmann::json points = nlohmann::json::array();
  double worst_sine = 0.0, worst_eigen = 0.0;  // over the lengths the 2D theory calls unstable
  for (std::size_t i = 0; i < sine_points.size() && i < eigen_points.size(); ++i) {
    points.push_back(point_json(sine_points[i], eigen_points[i]));
    if (exit_code == 0 && !(sine_points[i].completed && eigen_points[i].completed))
      exit_code = kExitRunFailed;
    const double exact = sine_points[i].theory.exact_2d.growth_rate;
    if (exact > 0.0) {
      worst_sine = std::max(worst_sine, std::fabs(relative(sine_points[i].growth_rate_712, exact)));
      worst_eigen = std::max(worst_eigen, std::fabs(relative(eigen_points[i].growth_rate, exact)));
    }
  }
  plot_run("case_figure13.py", theory_h5, png, "'" + sine.out + "' '" + eigen.out + "'",
           exit_code == 0);
  return {{"case", file.name()},
          {"resolution", res},
          {"grid", file.text("grid", res)},
          {"points", points},
          {"points_resumed", resumed},
          {"max_abs_deviation_unstable",
           {{"sine_712", number_or_null(worst_sine)},
            {"eigenmode_spectral", number_or_null(worst_eigen)}}},
          {"outputs", {sine.out, eigen.out, theory_h5, png}}};
}

}  // namespace granbench::cli
