// Parallel, resumable dispersion sweeps; see sweep.hpp.
#include "analysis/comparison/sweep.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <mutex>
#include <thread>

#include "analysis/comparison/twod_extrapolation.hpp"
#include "analysis/spectral/growth_estimator_712.hpp"
#include "analysis/theory/dispersion.hpp"

namespace granbench {

std::vector<double> parse_range(const std::string& text) {
  const auto a = text.find(':'), b = text.rfind(':');
  if (a == std::string::npos || a == b) throw std::invalid_argument("expected A:B:N");
  // A number filling its whole field, or std::invalid_argument.
  const auto number = [](const std::string& s) {
    std::size_t used = 0;
    double v = 0.0;
    try {
      v = std::stod(s, &used);
    } catch (const std::logic_error&) {
      used = 0;
    }
    if (used == 0 || used != s.size()) throw std::invalid_argument("'" + s + "' is not a number");
    return v;
  };
  const double lo = number(text.substr(0, a)), hi = number(text.substr(a + 1, b - a - 1));
  const double n = number(text.substr(b + 1));
  if (!(lo > 0.0) || !(hi >= lo) || !std::isfinite(hi) || !(n >= 1 && n <= 10000) ||
      n != std::floor(n))
    throw std::invalid_argument("expected 0 < A <= B and integer 1 <= N <= 10000");
  std::vector<double> v;
  for (int i = 0; i < n; ++i) v.push_back(n == 1 ? lo : lo + (hi - lo) * i / (n - 1));
  return v;
}

namespace {

struct Task {
  std::string model;
  double Lx;
};

bool same_point(const SweepPoint& p, const Task& t) {
  return p.model == t.model && std::fabs(p.Lx - t.Lx) <= 1e-12 * t.Lx;
}

// A depth-averaged point from the clean linear run, against (7.11) with the run's chi.
void measure_linear(const SweepSpec& spec, const ChuteCase& c, SweepPoint& p) {
  const auto r = depthavg::linear_run(c.steady(), c.make_curve(), spec.depthavg_settings.chi, c.Lx,
                                      *spec.depthavg_linear);
  p.growth_rate = r.measured.growth_rate;
  p.phase_speed = r.measured.phase_speed;
  p.growth_rate_712 = NAN;
  p.growth_rate_exact = r.exact.growth_rate;
  p.phase_speed_exact = r.exact.phase_speed;
  p.window_start = r.measured.t_first;
  p.window_end = r.measured.t_last;
  p.fit_r2 = r.measured.log_amplitude_r2;
  p.steps = static_cast<double>(r.stats.steps);
  p.mass_error = r.mass_error;
  p.wall_seconds = r.wall_seconds;
  p.cells_x = static_cast<double>(spec.depthavg_linear->nx);
  p.completed = r.ok;
  p.message = r.message;
  if (!r.measured.found()) p.growth_reason = r.measured.reason;
}

// The `granbench run` command of a seeded point; empty for a depth-averaged linear run (no
// `run` equivalent).
std::string seeded_run_command(const SweepSpec& spec, const SweepPoint& p) {
  ChuteCase c = spec.chute;
  c.Lx = p.Lx;
  if (p.model == "twod")
    return twod_command_of(c, point_twod_settings(spec, p.Lx, p.growth_rate_exact));
  return spec.depthavg_linear ? std::string()
                              : depthavg_command_of(c, point_depthavg_settings(spec, p.Lx));
}

// A point from a seeded run of either model, measured like compare's (compare.hpp).
void measure_seeded(const SweepSpec& spec, const ChuteCase& c, SweepPoint& p,
                    const RunControl& ctl) {
  const TwodSettings twod = point_twod_settings(spec, c.Lx, p.theory.exact_2d.growth_rate);
  // the depth-averaged run's own theory: (7.11) with its chi
  const TheoryValue& depthavg_theory =
      spec.depthavg_settings.chi != 1.0 ? p.theory.exact_bagnold : p.theory.exact;
  const ModelRun r = p.model == "twod" ? run_twod(c, twod, ctl)
                                       : run_depthavg(c, point_depthavg_settings(spec, c.Lx), ctl);
  MeasureOptions opt;
  opt.seeded_phase_speed =
      p.model == "twod" ? p.theory.exact_2d.phase_speed : depthavg_theory.phase_speed;
  const Measurement m = measure(r.series, opt);
  p.growth_rate = m.spectral.growth_rate;
  if (!m.spectral.found()) p.growth_reason = m.spectral.reason;
  p.phase_speed = m.spectral.phase_speed;
  p.growth_rate_712 = m.growth_712.value_or(NAN);
  if (spec.window_712) try {
      p.growth_rate_712 =
          growth_estimate_712(r.series, spec.window_712->first, spec.window_712->second)
              .growth_rate;
    } catch (const std::invalid_argument&) {
      p.growth_rate_712 = NAN;  // the window holds no growth above h0 (or too few samples)
    }
  if (p.model == "twod") {
    p.growth_rate_exact = p.theory.exact_2d.growth_rate;
    p.phase_speed_exact = p.theory.exact_2d.phase_speed;
  } else {
    p.growth_rate_exact = depthavg_theory.growth_rate;
    p.phase_speed_exact = depthavg_theory.phase_speed;
  }
  p.window_start = m.spectral.t_first;
  p.window_end = m.spectral.t_last;
  p.fit_r2 = m.spectral.log_amplitude_r2;
  p.steps = static_cast<double>(r.steps);
  p.mass_error = r.mass_error;
  p.wall_seconds = r.wall_seconds;
  p.cells_x = r.nx;
  if (p.model == "twod") p.cells_z = r.nz;
  p.completed = r.outcome == RunOutcome::Completed;
  p.message = r.message;
  p.run_command = r.run_command;
  if (!m.spectral.found())
    p.message += (p.message.empty() ? "" : "; ") + ("no growth rate: " + m.spectral.reason);
}

// The seeded 2D point again on half the cells across the layer, and its growth rate extrapolated
// from the two (twod_extrapolation.hpp). A second run that is interrupted leaves the point
// unfinished (a resume runs it again); one that diverges, or completes without a growth rate,
// leaves the extrapolation NaN and says why (a resume would only repeat it).
void extrapolate_in_dz(const SweepSpec& spec, const ChuteCase& c, SweepPoint& p,
                       const RunControl& ctl) {
  const TwodExtrapolation e =
      extrapolate_twod_growth(c, point_twod_settings(spec, c.Lx, p.theory.exact_2d.growth_rate),
                              p.growth_rate, p.theory.exact_2d.phase_speed, ctl);
  p.wall_seconds += e.wall_seconds;
  if (!e.found()) {
    p.message += (p.message.empty() ? "" : "; ") + ("not extrapolated: " + e.reason);
    p.completed = p.completed && e.outcome != RunOutcome::Interrupted;
    return;
  }
  p.growth_rate_half_cells = e.growth_rate_half_cells;
  p.dz_ratio = e.dz_ratio;
  p.growth_rate_extrapolated = e.growth.value;
  p.growth_rate_extrapolated_low = e.growth.low;
  p.growth_rate_extrapolated_high = e.growth.high;
}

SweepPoint run_point(const SweepSpec& spec, const Task& task, const RunControl& ctl) {
  ChuteCase c = spec.chute;
  c.Lx = task.Lx;
  SweepPoint p;
  p.model = task.model;
  p.Lx = task.Lx;
  // (not a number until measured: a run that throws before its measurement has none)
  p.growth_rate = p.phase_speed = NAN;
  try {
    const bool linear = task.model == "depthavg" && spec.depthavg_linear.has_value();
    p.theory = exact_theories(c, !linear);
    p.k_hat = p.theory.k_hat;
    if (linear)
      measure_linear(spec, c, p);
    else
      measure_seeded(spec, c, p, ctl);
    if (p.model == "twod" && spec.twod_extrapolate && p.completed)
      extrapolate_in_dz(spec, c, p, ctl);
  } catch (const std::exception& e) {
    p.completed = false;
    p.message = e.what();
    if (std::isnan(p.growth_rate)) p.growth_reason = "the run did not complete: " + p.message;
  }
  return p;
}

// The process's store: the output file for one process, its part file for one of several.
std::string store_path(const SweepSpec& spec) {
  if (spec.out.empty()) return "";
  return spec.ranks > 1 ? sweep_part_path(spec.out, spec.rank) : spec.out;
}

// Part files of earlier multi-process runs beside `out`, whatever their number of ranks.
std::vector<std::string> part_files(const std::string& out) {
  std::vector<std::string> found;
  const std::filesystem::path p(out);
  const std::filesystem::path dir = p.has_parent_path() ? p.parent_path() : ".";
  const std::string prefix = p.filename().string() + ".rank";
  if (!std::filesystem::is_directory(dir)) return found;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (name.starts_with(prefix) && name.ends_with(".h5")) found.push_back(e.path().string());
  }
  return found;
}

void sort_points(std::vector<SweepPoint>& points) {
  std::sort(points.begin(), points.end(), [](const SweepPoint& a, const SweepPoint& b) {
    return a.model != b.model ? a.model < b.model : a.Lx < b.Lx;
  });
}

}  // namespace

TwodSettings point_twod_settings(const SweepSpec& spec, double Lx, double exact_growth) {
  TwodSettings twod = spec.twod_settings.refined_across(Lx, spec.chute.steady(), exact_growth,
                                                        spec.chute.a0, spec.chute.t_end);
  twod.nx = twod.cells_along(Lx);
  twod.threads = std::max(1, twod.threads / static_cast<int>(std::max(1u, spec.jobs)));
  return twod;
}

DepthAvgSettings point_depthavg_settings(const SweepSpec& spec, double Lx) {
  ChuteCase c = spec.chute;
  c.Lx = Lx;
  const double growth = dispersion_mode(c.steady(), spec.depthavg_settings.chi, Lx).growth_rate;
  return spec.depthavg_settings.limited_where_it_saturates(c, growth);
}

std::string sweep_part_path(const std::string& out, int rank) {
  return out + ".rank" + std::to_string(rank) + ".h5";
}

std::vector<SweepPoint> read_finished(const SweepSpec& spec) {
  std::vector<SweepPoint> finished;
  if (spec.out.empty()) return finished;
  std::vector<std::string> files = part_files(spec.out);
  if (std::filesystem::exists(spec.out)) files.insert(files.begin(), spec.out);
  for (const auto& f : files) {
    check_stored_settings(f, spec);
    for (SweepPoint& p : read_sweep(f)) {
      const bool known = std::any_of(finished.begin(), finished.end(), [&](const SweepPoint& q) {
        return same_point(q, {p.model, p.Lx});
      });
      if (!p.completed || known) continue;  // unfinished (interrupted) points are recomputed
      p.resumed = true;
      finished.push_back(p);
    }
  }
  return finished;
}

std::vector<SweepPoint> run_share(const SweepSpec& spec, const std::vector<SweepPoint>& finished,
                                  const SweepProgress& progress) {
  std::vector<Task> tasks;
  std::size_t index = 0;
  for (const char* model : {"depthavg", "twod"}) {
    if ((std::string(model) == "twod") ? !spec.twod : !spec.depthavg) continue;
    for (double Lx : spec.Lx) {
      const Task t{model, Lx};
      const bool mine = static_cast<int>(index++ % spec.ranks) == spec.rank;
      const bool done = std::any_of(finished.begin(), finished.end(),
                                    [&](const SweepPoint& p) { return same_point(p, t); });
      if (mine && !done) tasks.push_back(t);
    }
  }
  const std::string store = store_path(spec);
  std::vector<SweepPoint> kept = finished, ran;
  std::mutex mutex;
  std::size_t next = 0;
  RunControl ctl;
  ctl.stop = progress.stop;
  auto worker = [&] {
    for (;;) {
      Task t;
      {
        std::lock_guard lock(mutex);
        if (next >= tasks.size() || (progress.stop && progress.stop->load())) return;
        t = tasks[next++];
      }
      SweepPoint p = run_point(spec, t, ctl);
      std::lock_guard lock(mutex);
      ran.push_back(p);
      kept.push_back(p);
      try {
        if (!store.empty()) write_sweep(store, spec, kept);  // keep every finished point
      } catch (const std::exception& e) {
        ran.back().completed = false;
        ran.back().message = "could not keep it in " + store + ": " + e.what();
      }
      if (progress.point_done) progress.point_done(ran.back(), ran.size(), tasks.size());
    }
  };
  std::vector<std::thread> pool;
  const auto n = std::max<std::size_t>(1, std::min<std::size_t>(spec.jobs, tasks.size()));
  for (std::size_t i = 0; i < n; ++i) pool.emplace_back(worker);
  for (auto& th : pool) th.join();
  return ran;
}

std::vector<SweepPoint> finish_sweep(const SweepSpec& spec, std::vector<SweepPoint> points) {
  // Points read back from a file or from another process carry no command line (the store keeps
  // numbers only); it is a function of the spec and the length, so it is made again here.
  for (SweepPoint& p : points)
    if (p.run_command.empty()) p.run_command = seeded_run_command(spec, p);
  sort_points(points);
  if (spec.out.empty()) return points;
  write_sweep(spec.out, spec, points);
  for (const auto& f : part_files(spec.out)) std::filesystem::remove(f);
  return points;
}

std::vector<SweepPoint> run_sweep(const SweepSpec& spec, const SweepProgress& progress) {
  std::vector<SweepPoint> points = read_finished(spec);
  const auto ran = run_share(spec, points, progress);
  points.insert(points.end(), ran.begin(), ran.end());
  return finish_sweep(spec, std::move(points));
}

}  // namespace granbench
