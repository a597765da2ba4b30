// granbench sweep: growth rate and phase speed of the linear waves over a range of domain lengths,
// measured by the model beside the exact relation (7.11) — the paper's figure 13.
//
//   granbench sweep --model depthavg --Lx 0.03:0.4:12 --jobs 2 --json
//   granbench sweep --model depthavg --Lx 0.02:0.6:24 --chi bagnold --plot fig13.png
//
// Each point is a clean linear measurement (depthavg/linear_run.hpp): the normal mode (7.10)
// seeded at amplitude 1e-4 h0, unlimited central reconstruction, tight tolerances, the growth rate
// and phase speed fitted spectrally over an automatically found window. Points run in parallel
// on --jobs threads.
#include <algorithm>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <mutex>
#include <thread>

#include "cli_common.hpp"
#include "commands.hpp"
#include "dispersion_curve.hpp"
#include "hdf5_file.hpp"
#include "depthavg/linear_run.hpp"
#include "run_model.hpp"
#include "sweep_models.hpp"

namespace granbench::cli {

namespace {

struct SweepOptions {
  FlowOptions flow;
  OutputOptions output;
  DepthAvgOptions depthavg;
  std::string model = "depthavg";
  std::string Lx = "0.03:0.4:12";
  unsigned jobs = std::max(1u, std::thread::hardware_concurrency());
  std::size_t nx = 192;
  double tolerance = 1e-6;
  double t_end = 0.0;
  std::string resolution = "coarse";  // 2D grid of --model twod|both
};

std::vector<double> parse_range(const std::string& text) {
  const std::string err = "--Lx: expected A:B:N with 0 < A <= B and integer N >= 1, got '" + text + "'";
  const auto c1 = text.find(':'), c2 = text.rfind(':');
  if (c1 == std::string::npos || c1 == c2) throw UsageError(err);
  double a = 0.0, b = 0.0;
  long n = 0;
  try {
    std::size_t u1 = 0, u2 = 0, u3 = 0;
    const std::string sa = text.substr(0, c1), sb = text.substr(c1 + 1, c2 - c1 - 1),
                      sn = text.substr(c2 + 1);
    a = std::stod(sa, &u1);
    b = std::stod(sb, &u2);
    n = std::stol(sn, &u3);
    if (u1 != sa.size() || u2 != sb.size() || u3 != sn.size()) throw UsageError(err);
  } catch (const std::logic_error&) {
    throw UsageError(err);
  }
  if (!(a > 0.0 && b >= a && n >= 1 && n <= 10000 && std::isfinite(b))) throw UsageError(err);
  std::vector<double> v(static_cast<std::size_t>(n));
  for (long i = 0; i < n; ++i) v[i] = n == 1 ? a : a + (b - a) * static_cast<double>(i) / (n - 1);
  return v;
}

void write_sweep(const std::string& path, const SteadyState& s, double chi,
                 const std::vector<depthavg::LinearRunResult>& pts) {
  H5Writer out(path);
  std::vector<double> Lx, k_hat, g, ge, c, ce;
  for (const auto& p : pts) {
    Lx.push_back(p.Lx);
    k_hat.push_back(p.exact.k_hat);
    g.push_back(p.measured.growth_rate);
    ge.push_back(p.exact.growth_rate);
    c.push_back(p.measured.phase_speed);
    ce.push_back(p.exact.phase_speed);
  }
  out.write("points/Lx", Lx);
  out.write("points/k_hat", k_hat);
  out.write("points/growth_rate", g);
  out.write("points/growth_rate_exact", ge);
  out.write("points/phase_speed", c);
  out.write("points/phase_speed_exact", ce);
  // The exact curve (7.11) over a log range of k_hat around the points, for the figure.
  const double k_lo = *std::min_element(k_hat.begin(), k_hat.end()) / 3.0;
  const double k_hi = *std::max_element(k_hat.begin(), k_hat.end()) * 3.0;
  write_dispersion_curve(out, "curve", s, chi, k_lo, k_hi, 300);
  out.attribute("/", "chi", chi);
  out.attribute("/", "h0", s.h0);
  out.attribute("/", "u_mean", s.u_mean);
  out.attribute("/", "angle_deg", s.zeta * 180.0 / M_PI);
  out.attribute("/", "F", s.Fr);
  out.attribute("/", "R", s.R);
  out.attribute("/", "Gamma", s.Gamma);
  out.attribute("/", "model", "depthavg");
  out.close();
}

// --model twod|both: the resumable two-model engine (sweep_models.hpp).
void run_two_model_sweep(const SweepOptions& o) {
  ModelSweepOptions m;
  m.depthavg = o.model == "both";
  m.twod = true;
  m.Lx = parse_range(o.Lx);
  m.jobs = o.jobs;
  if (o.t_end > 0.0) m.t_end = o.t_end;
  m.nx = o.resolution == "fine" ? 320 : o.resolution == "default" ? 160 : 80;
  m.nz = m.nx / 5;
  m.chi = parse_chi(o.depthavg.chi);
  run_model_sweep(o.flow, o.output, m);
}

void run_sweep(const SweepOptions& o) {
  if (o.model != "depthavg") return run_two_model_sweep(o);
  const double chi = parse_chi(o.depthavg.chi);
  const auto Lxs = parse_range(o.Lx);
  const MuCurve curve = o.flow.make_curve();
  const SteadyState base = o.flow.steady();
  depthavg::LinearRunParams lp;
  lp.nx = o.nx;
  lp.tolerance = o.tolerance;
  lp.t_end = o.t_end;
  lp.reconstruction = depthavg::parse_reconstruction(o.depthavg.limiter);
  if (o.depthavg.frame_speed == "linear")
    lp.co_moving = true;
  else if (o.depthavg.frame_speed != "0")
    throw UsageError("--frame-speed: '" + o.depthavg.frame_speed +
                     "' is not allowed for sweep; valid values {0, linear}");

  const std::size_t n = Lxs.size();
  std::vector<depthavg::LinearRunResult> res(n);
  std::vector<bool> done(n, false);
  std::atomic<std::size_t> next{0}, finished{0};
  std::mutex mtx;
  std::string failure;
  const InterruptGuard guard;
  const bool progress = progress_enabled(o.output);
  const auto start = std::chrono::steady_clock::now();
  auto worker = [&] {
    for (std::size_t i; !guard.flag()->load() && (i = next++) < n;) {
      try {
        res[i] = depthavg::linear_run(base, curve, chi, Lxs[i], lp);
        done[i] = true;  // distinct elements per thread; read after join
      } catch (const std::exception& e) {
        std::lock_guard<std::mutex> lock(mtx);
        failure = "Lx = " + std::to_string(Lxs[i]) + ": " + e.what();
      }
      const std::size_t f = ++finished;
      if (progress) {
        std::lock_guard<std::mutex> lock(mtx);
        std::cerr << "\r  " << f << " / " << n << " points" << std::flush;
      }
    }
  };
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < std::min<std::size_t>(o.jobs, n); ++t) pool.emplace_back(worker);
  for (auto& t : pool) t.join();
  if (progress) std::cerr << "\n";
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!failure.empty()) throw CommandFailed("sweep failed at " + failure, 3);

  std::vector<depthavg::LinearRunResult> pts;
  for (std::size_t i = 0; i < n; ++i)
    if (done[i]) pts.push_back(res[i]);
  double worst = 0.0;
  nlohmann::json list = nlohmann::json::array();
  for (const auto& p : pts) {
    if (p.exact.growth_rate > 0.0) worst = std::max(worst, p.growth_relative_error());
    list.push_back({{"Lx", p.Lx},
                    {"k_hat", p.exact.k_hat},
                    {"growth_rate", number_or_null(p.measured.growth_rate)},
                    {"growth_rate_exact", p.exact.growth_rate},
                    {"phase_speed", number_or_null(p.measured.phase_speed)},
                    {"phase_speed_exact", p.exact.phase_speed},
                    {"growth_relative_error", number_or_null(p.growth_relative_error())},
                    {"phase_speed_relative_error", number_or_null(p.speed_relative_error())},
                    {"window", {p.measured.amplitude_fit.t_first, p.measured.amplitude_fit.t_last}},
                    {"fit_r2", p.measured.amplitude_fit.r2},
                    {"steps", p.stats.steps},
                    {"mass_error", p.mass_error},
                    {"wall_seconds", p.wall_seconds},
                    {"status", p.ok ? "completed" : p.message}});
  }
  if (!pts.empty() && (!o.output.out.empty() || !o.output.plot.empty())) {
    const std::string h5 = !o.output.out.empty() ? o.output.out : o.output.plot + ".data.h5";
    write_sweep(h5, base, chi, pts);
    if (!o.output.plot.empty()) {
      run_plot_script("sweep.py", h5, o.output.plot);
      if (o.output.out.empty()) std::filesystem::remove(h5);
    }
  }
  if (o.output.json) {
    print_json({{"model", o.model},
                {"chi", chi},
                {"nx", o.nx},
                {"tolerance", o.tolerance},
                {"frame_speed", o.depthavg.frame_speed},
                {"jobs", o.jobs},
                {"wall_seconds", wall},
                {"max_growth_relative_error_unstable", worst},
                {"points", list}});
  } else {
    std::cout << "depthavg sweep, chi = " << chi << ", " << o.flow.curve << " curve, angle "
              << o.flow.angle_deg << " deg, h0 = " << o.flow.h0 << " m, nx = " << o.nx << " ("
              << wall << " s wall on " << o.jobs << " threads)\n"
              << std::setw(9) << "Lx [m]" << std::setw(9) << "k_hat" << std::setw(13)
              << "growth" << std::setw(13) << "(7.11)" << std::setw(10) << "rel.err"
              << std::setw(12) << "speed" << std::setw(12) << "(7.11)" << std::setw(10)
              << "rel.err" << "\n";
    for (const auto& p : pts)
      std::cout << std::setprecision(5) << std::setw(9) << p.Lx << std::setw(9) << p.exact.k_hat
                << std::setw(13) << p.measured.growth_rate << std::setw(13)
                << p.exact.growth_rate << std::setw(10) << std::setprecision(2)
                << p.growth_relative_error() << std::setprecision(5) << std::setw(12)
                << p.measured.phase_speed << std::setw(12) << p.exact.phase_speed
                << std::setw(10) << std::setprecision(2) << p.speed_relative_error() << "\n";
  }
  if (pts.size() < n)
    throw CommandFailed("interrupted after " + std::to_string(pts.size()) + " of " +
                            std::to_string(n) + " points; those were kept",
                        130);
}

}  // namespace

void add_sweep_command(CLI::App& app) {
  auto o = std::make_shared<SweepOptions>();
  CLI::App* sub = app.add_subcommand(
      "sweep", "measured linear growth rate and phase speed over domain lengths vs (7.11)");
  add_flow_options(*sub, o->flow);
  sub->add_option("--model", o->model, "model {depthavg,twod,both}")
      ->check(one_of({"depthavg", "twod", "both"}))
      ->capture_default_str();
  sub->add_option("--Lx", o->Lx, "domain lengths A:B:N [m] (N evenly spaced from A to B)")
      ->capture_default_str();
  sub->add_option("--jobs", o->jobs, "parallel threads, in [1, 256]")
      ->check(CLI::Range(1u, 256u))
      ->capture_default_str();
  sub->add_option("--nx", o->nx, "cells per domain, in [16, 65536]")
      ->check(CLI::Range(std::size_t{16}, std::size_t{65536}))
      ->capture_default_str();
  sub->add_option("--tolerance", o->tolerance,
                  "CVODE tolerance relative to the seeded perturbation (amplitude 1e-4 h0), in (0, 1)")
      ->check(open_range(0.0, 1.0))
      ->capture_default_str();
  sub->add_option("--t-end", o->t_end,
                  "run length per point [s], > 0; default: max(4 periods, 0.5/|growth|), <= 5 s")
      ->check(positive());
  sub->add_option("--resolution", o->resolution,
                  "2D grid of --model twod|both {coarse: 80x16, default: 160x32, fine: 320x64}")
      ->check(one_of({"coarse", "default", "fine"}))
      ->capture_default_str();
  add_depthavg_options(*sub, o->depthavg);
  add_output_options(*sub, o->output);
  sub->callback([o] { run_sweep(*o); });
}

}  // namespace granbench::cli
