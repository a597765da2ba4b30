// Parallel, resumable dispersion sweeps; see sweep.hpp.
#include "sweep.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <mutex>
#include <thread>

#include "hdf5_file.hpp"

namespace granbench {

std::vector<double> parse_range(const std::string& text) {
  const auto a = text.find(':'), b = text.rfind(':');
  if (a == std::string::npos || a == b) throw std::invalid_argument("expected A:B:N");
  std::size_t used = 0;
  const double lo = std::stod(text.substr(0, a));
  const double hi = std::stod(text.substr(a + 1, b - a - 1));
  const std::string ns = text.substr(b + 1);
  const long n = std::stol(ns, &used);
  if (used != ns.size() || n < 1 || !(lo > 0.0) || !(hi >= lo))
    throw std::invalid_argument("expected 0 < A <= B and N >= 1");
  std::vector<double> v;
  for (long i = 0; i < n; ++i) v.push_back(n == 1 ? lo : lo + (hi - lo) * i / (n - 1));
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

SweepPoint run_point(const SweepSpec& spec, const Task& task, const RunControl& ctl) {
  ChuteCase c = spec.chute;
  c.Lx = task.Lx;
  SweepPoint p;
  p.model = task.model;
  p.Lx = task.Lx;
  p.theory = exact_theories(c);
  p.k_hat = p.theory.k_hat;
  const ModelRun r = task.model == "twod" ? run_twod(c, spec.twod_settings, ctl)
                                          : run_depthavg(c, spec.depthavg_settings, ctl);
  const Measurement m = measure(r.series);
  p.growth_rate = m.spectral.growth_rate;
  p.phase_speed = m.spectral.phase_speed;
  p.growth_rate_712 = m.growth_712.value_or(NAN);
  if (task.model == "twod") {
    p.growth_rate_exact = p.theory.exact_2d.growth_rate;
    p.phase_speed_exact = p.theory.exact_2d.phase_speed;
  } else {
    const bool bagnold = spec.depthavg_settings.chi != 1.0;
    const TheoryValue& t = bagnold ? p.theory.exact_bagnold : p.theory.exact;
    p.growth_rate_exact = t.growth_rate;
    p.phase_speed_exact = t.phase_speed;
  }
  p.wall_seconds = r.wall_seconds;
  p.completed = r.outcome == RunOutcome::Completed;
  p.message = r.message;
  return p;
}

}  // namespace

std::vector<SweepPoint> run_sweep(const SweepSpec& spec, const SweepProgress& progress) {
  std::vector<SweepPoint> points;
  if (!spec.out.empty() && std::filesystem::exists(spec.out)) points = read_sweep(spec.out);
  std::vector<Task> tasks;
  std::size_t index = 0;
  for (const char* model : {"depthavg", "twod"}) {
    if ((std::string(model) == "twod") ? !spec.twod : !spec.depthavg) continue;
    for (double Lx : spec.Lx) {
      const Task t{model, Lx};
      const bool mine = static_cast<int>(index++ % spec.ranks) == spec.rank;
      const bool done = std::any_of(points.begin(), points.end(), [&](const SweepPoint& p) {
        return p.completed && same_point(p, t);
      });
      if (mine && !done) tasks.push_back(t);
    }
  }
  // Unfinished (interrupted) points from an earlier run are recomputed.
  std::erase_if(points, [](const SweepPoint& p) { return !p.completed; });
  const std::size_t total = tasks.size();
  std::mutex mutex;
  std::size_t next = 0, done = 0;
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
      points.push_back(p);
      ++done;
      if (!spec.out.empty()) write_sweep(spec.out, spec, points);  // keep every finished point
      if (progress.point_done) progress.point_done(p, done, total);
    }
  };
  std::vector<std::thread> pool;
  const unsigned n = std::max(1u, std::min<unsigned>(spec.jobs, static_cast<unsigned>(total)));
  for (unsigned i = 0; i < n; ++i) pool.emplace_back(worker);
  for (auto& th : pool) th.join();
  std::sort(points.begin(), points.end(), [](const SweepPoint& a, const SweepPoint& b) {
    return a.model != b.model ? a.model < b.model : a.Lx < b.Lx;
  });
  return points;
}

namespace {
// Column names of the per-point table in the HDF5 file, in this order.
const char* const kColumns[] = {"Lx", "k_hat", "growth_rate", "phase_speed", "growth_rate_712",
                                "growth_rate_exact", "phase_speed_exact", "exact_growth_rate",
                                "exact_phase_speed", "exact_bagnold_growth_rate",
                                "exact_bagnold_phase_speed", "exact_2d_growth_rate",
                                "exact_2d_phase_speed", "wall_seconds", "completed"};
std::vector<double> row(const SweepPoint& p) {
  return {p.Lx, p.k_hat, p.growth_rate, p.phase_speed, p.growth_rate_712, p.growth_rate_exact,
          p.phase_speed_exact, p.theory.exact.growth_rate, p.theory.exact.phase_speed,
          p.theory.exact_bagnold.growth_rate, p.theory.exact_bagnold.phase_speed,
          p.theory.exact_2d.growth_rate, p.theory.exact_2d.phase_speed, p.wall_seconds,
          p.completed ? 1.0 : 0.0};
}
}  // namespace

void write_sweep(const std::string& path, const SweepSpec& spec,
                 const std::vector<SweepPoint>& points) {
  H5Writer out(path);
  for (const char* model : {"depthavg", "twod"}) {
    std::vector<std::vector<double>> cols(std::size(kColumns));
    for (const auto& p : points)
      if (p.model == model) {
        const auto r = row(p);
        for (std::size_t c = 0; c < r.size(); ++c) cols[c].push_back(r[c]);
      }
    if (cols[0].empty()) continue;
    for (std::size_t c = 0; c < cols.size(); ++c)
      out.write(std::string(model) + "/" + kColumns[c], cols[c]);
  }
  const ChuteCase& k = spec.chute;
  out.attribute("/", "curve", std::string(curve_name(k.curve)));
  out.attribute("/", "angle_deg", k.angle_deg);
  out.attribute("/", "h0", k.h0);
  out.attribute("/", "a0", k.a0);
  out.attribute("/", "t_end", k.t_end);
  out.attribute("/", "u_mean", k.steady().u_mean);
  out.attribute("/", "depthavg_nx", static_cast<double>(spec.depthavg_settings.nx));
  out.attribute("/", "depthavg_chi", spec.depthavg_settings.chi);
  out.attribute("/", "twod_nx", spec.twod_settings.nx);
  out.attribute("/", "twod_nz", spec.twod_settings.nz);
  out.close();
}

std::vector<SweepPoint> read_sweep(const std::string& path) {
  std::vector<SweepPoint> points;
  for (const char* model : {"depthavg", "twod"}) {
    const std::string g = std::string(model) + "/";
    if (!h5_has(path, g + "Lx")) continue;
    std::vector<std::vector<double>> cols;
    for (const char* c : kColumns) cols.push_back(h5_read_doubles(path, g + c));
    for (std::size_t i = 0; i < cols[0].size(); ++i) {
      SweepPoint p;
      p.model = model;
      std::size_t c = 0;
      for (double* field : {&p.Lx, &p.k_hat, &p.growth_rate, &p.phase_speed, &p.growth_rate_712,
                            &p.growth_rate_exact, &p.phase_speed_exact,
                            &p.theory.exact.growth_rate, &p.theory.exact.phase_speed,
                            &p.theory.exact_bagnold.growth_rate,
                            &p.theory.exact_bagnold.phase_speed, &p.theory.exact_2d.growth_rate,
                            &p.theory.exact_2d.phase_speed, &p.wall_seconds})
        *field = cols[c++][i];
      p.completed = cols[c][i] != 0.0;
      p.theory.k_hat = p.k_hat;
      points.push_back(p);
    }
  }
  return points;
}

}  // namespace granbench
