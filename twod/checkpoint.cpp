// Checkpoint file layout (HDF5): /state/{u,w,p,f} as stored on the staggered grid, and the
// scalars /state/{t, steps, dt_last, initial_volume, nx, nz, Lx, Lz} as one-element datasets;
// /surface is the SurfaceSeries recorded so far; /warm_start holds the linear solvers' initial
// guesses and the second-order step's memory (A^n, the last step: Solver::warm_start);
// /run/snapshot_times the times of the snapshots written so far; /physics/<name> one scalar per
// physical input (checkpoint_physics). A restart continues bit-for-bit from here.
#include "twod/checkpoint.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

#include "common/hdf5_file.hpp"
#include "twod/diagnostics.hpp"

namespace granbench::twod {

std::vector<std::pair<std::string, double>> checkpoint_physics(const SolverParams& p) {
  const Rheology& r = p.rheology;
  const Material& m = r.material;
  // Keyed by the option names (without "--"), so that a mismatch names the option to change.
  std::vector<std::pair<std::string, double>> v = {{"angle", p.zeta * 180.0 / std::numbers::pi},
                                                   {"curve", double(static_cast<int>(r.curve))},
                                                   {"h0", r.h0_for_curve}};
  for (const MaterialConstant& c : material_constants) v.emplace_back(c.option + 2, m.*c.value);
  v.insert(v.end(), {{"eta-max", r.eta_max},
                     {"eta-min", r.eta_min},
                     {"D-min", r.D_min},
                     {"rho-light", r.rho_light},
                     {"eta-light", r.eta_light},
                     {"mixing", double(static_cast<int>(r.mixing))},
                     // no option: a solver default that changed (5 December); a checkpoint from
                     // before it continued with the other pressure in mu(I) would mix two models
                     {"effective-pressure", r.effective_pressure ? 1.0 : 0.0}});
  return v;
}

void resume_from(Solver& solver, const Checkpoint& c) {
  solver.resume(c.steps, c.dt_last, c.initial_volume);
  solver.set_warm_start(c.warm_start);
}

std::string restart_mismatch(const Checkpoint& c, const Grid& g, const SolverParams& params) {
  auto differs = [](double a, double b) { return std::abs(a - b) > 1e-12 * std::abs(b); };
  auto text = [](const std::string& name, double a, double b) {
    std::ostringstream s;
    s.precision(12);
    if (name == "curve")
      s << name << ": the checkpoint has " << curve_name(CurveKind(int(a))) << ", this run "
        << curve_name(CurveKind(int(b)));
    else
      s << name << ": the checkpoint has " << a << ", this run " << b;
    return s.str();
  };
  if (c.physics.empty())
    return "restart: the checkpoint does not record its physics (written by an older granbench)";
  for (const auto& [name, run_value] : checkpoint_physics(params)) {
    bool found = false;
    for (const auto& [stored, value] : c.physics)
      if (stored == name) {
        found = true;
        if (differs(value, run_value)) return text(name, value, run_value);
      }
    if (!found) return name + ": not recorded in the checkpoint (written by an older granbench)";
  }
  // After the physics: a depth that differs also changes the default Lz, and --h0 is the
  // better name for that.
  const std::pair<std::string, std::pair<double, double>> grid[] = {{"nx", {c.grid.nx, g.nx}},
                                                                    {"nz", {c.grid.nz, g.nz}},
                                                                    {"Lx", {c.grid.Lx, g.Lx}},
                                                                    {"Lz", {c.grid.Lz, g.Lz}}};
  for (const auto& [name, v] : grid)
    if (differs(v.first, v.second)) return text(name, v.first, v.second);
  if (differs(c.grid.frame_speed, g.frame_speed)) {  // the co-moving frame (frame.hpp)
    std::ostringstream s;
    s.precision(6);
    s << "twod-frame: the checkpoint has a grid moving at " << c.grid.frame_speed
      << " m/s, this run " << g.frame_speed << " m/s";
    return s.str();
  }
  return {};
}

void write_checkpoint(const std::string& path, const Solver& solver, const SurfaceSeries& series,
                      const std::vector<double>& snapshot_times) {
  const Grid& g = solver.grid();
  const Fields& s = solver.state();
  const RunStatistics st = solver.statistics();
  H5Writer out(path);
  out.write("/state/u", s.u);
  out.write("/state/w", s.w);
  out.write("/state/p", s.p);
  out.write("/state/f", s.f);
  auto scalar = [&](const char* name, double v) {
    out.write(std::string("/state/") + name, std::span<const double>(&v, 1));
  };
  scalar("t", s.t);
  scalar("steps", double(st.steps));
  scalar("dt_last", st.dt_last);
  scalar("initial_volume", st.initial_volume);
  scalar("nx", g.nx);
  scalar("nz", g.nz);
  scalar("Lx", g.Lx);
  scalar("Lz", g.Lz);
  scalar("frame_speed", g.frame_speed);
  if (series.nt() > 0) write_surface_series(out, "/surface", series);
  const WarmStart w = solver.warm_start();
  if (!w.viscous_increment.empty()) {
    out.write("/warm_start/viscous_increment", w.viscous_increment);
    out.write("/warm_start/viscous_dt", std::span<const double>(&w.viscous_dt, 1));
  }
  if (!w.pressure_increment.empty())
    out.write("/warm_start/pressure_increment", w.pressure_increment);
  if (!w.advection_u.empty()) {
    out.write("/warm_start/advection_u", w.advection_u);
    out.write("/warm_start/advection_w", w.advection_w);
  }
  if (!w.increment_u.empty()) {
    out.write("/warm_start/increment_u", w.increment_u);
    out.write("/warm_start/increment_w", w.increment_w);
  }
  if (!w.previous_u.empty()) {
    out.write("/warm_start/previous_u", w.previous_u);
    out.write("/warm_start/previous_w", w.previous_w);
  }
  if (const DynamicPressureHistory& d = w.dynamic_pressure; d.levels > 0) {
    out.write("/warm_start/dynamic_pressure_older", d.older);
    out.write("/warm_start/dynamic_pressure_old", d.old);
    const double record[3] = {d.t_older, d.t_old, double(d.levels)};
    out.write("/warm_start/dynamic_pressure_times_levels", std::span<const double>(record, 3));
  }
  out.write("/warm_start/previous_dt", std::span<const double>(&w.previous_dt, 1));
  if (!snapshot_times.empty()) out.write("/run/snapshot_times", snapshot_times);
  for (const auto& [name, v] : checkpoint_physics(solver.params()))
    out.write("/physics/" + name, std::span<const double>(&v, 1));
  out.close();
}

Checkpoint read_checkpoint(const std::string& path) {
  auto scalar = [&](const char* name) {
    return h5_read_doubles(path, std::string("/state/") + name).at(0);
  };
  Checkpoint c;
  c.grid = Grid(int(scalar("nx")), int(scalar("nz")), scalar("Lx"), scalar("Lz"));
  // (checkpoints from before the co-moving frame were written in the lab frame)
  if (h5_has(path, "/state/frame_speed")) c.grid.frame_speed = scalar("frame_speed");
  c.state = Fields(c.grid);
  c.state.u = h5_read_doubles(path, "/state/u");
  c.state.w = h5_read_doubles(path, "/state/w");
  c.state.p = h5_read_doubles(path, "/state/p");
  c.state.f = h5_read_doubles(path, "/state/f");
  c.state.t = scalar("t");
  c.steps = long(scalar("steps"));
  c.dt_last = scalar("dt_last");
  c.initial_volume = scalar("initial_volume");
  if (c.state.u.size() != c.grid.cells() || c.state.w.size() != c.grid.w_faces() ||
      c.state.p.size() != c.grid.cells() || c.state.f.size() != c.grid.cells())
    throw std::runtime_error("checkpoint " + path + ": field sizes do not match its grid");
  if (h5_has(path, "/surface/h")) c.series = read_surface_series(path, "/surface");
  if (h5_has(path, "/warm_start/viscous_increment")) {
    c.warm_start.viscous_increment = h5_read_doubles(path, "/warm_start/viscous_increment");
    c.warm_start.viscous_dt = h5_read_doubles(path, "/warm_start/viscous_dt").at(0);
  }
  if (h5_has(path, "/warm_start/pressure_increment"))
    c.warm_start.pressure_increment = h5_read_doubles(path, "/warm_start/pressure_increment");
  auto optional = [&](const char* name, std::vector<double>& v) {
    if (h5_has(path, std::string("/warm_start/") + name))
      v = h5_read_doubles(path, std::string("/warm_start/") + name);
  };
  optional("advection_u", c.warm_start.advection_u);
  optional("advection_w", c.warm_start.advection_w);
  optional("increment_u", c.warm_start.increment_u);
  optional("increment_w", c.warm_start.increment_w);
  optional("previous_u", c.warm_start.previous_u);
  optional("previous_w", c.warm_start.previous_w);
  DynamicPressureHistory& history = c.warm_start.dynamic_pressure;
  optional("dynamic_pressure_older", history.older);
  optional("dynamic_pressure_old", history.old);
  std::vector<double> record;
  optional("dynamic_pressure_times_levels", record);
  if (record.size() == 3) {
    history.t_older = record[0];
    history.t_old = record[1];
    history.levels = int(record[2]);
  }
  std::vector<double> dt;
  optional("previous_dt", dt);
  if (!dt.empty()) c.warm_start.previous_dt = dt.at(0);
  if (h5_has(path, "/run/snapshot_times"))
    c.snapshot_times = h5_read_doubles(path, "/run/snapshot_times");
  for (const auto& [name, v] : checkpoint_physics(SolverParams{}))
    if (h5_has(path, "/physics/" + name))
      c.physics.emplace_back(name, h5_read_doubles(path, "/physics/" + name).at(0));
  return c;
}

}  // namespace granbench::twod
