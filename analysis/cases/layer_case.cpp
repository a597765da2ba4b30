// The decelerating and high-speed paper cases (layer_case.hpp): specification from the case
// file, the runs (in parallel), the grid dependence, the growth of x-dependent perturbations,
// the HDF5 output and the summary.
#include "analysis/cases/layer_case.hpp"

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <mutex>
#include <numeric>
#include <sstream>
#include <thread>

#include "analysis/cases/layer_xdmf.hpp"
#include "analysis/cases/perturbation_energy.hpp"
#include "analysis/comparison/twod_settings.hpp"
#include "common/companion_path.hpp"
#include "common/hdf5_file.hpp"
#include "common/steady_state.hpp"
#include "twod/viscosity_mixing.hpp"

namespace granbench::cases {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

twod::ViscosityMixing parse_mixing(const CaseFile& f, const std::string& res) {
  if (!f.has("mixing", res)) return twod::ViscosityMixing::Arithmetic;
  const std::string m = f.text("mixing", res);
  if (const auto rule = twod::viscosity_mixing_from_name(m)) return *rule;
  throw CaseFileError(f.path() + ": key 'mixing' = '" + m +
                      "'; valid values {arithmetic,harmonic}");
}

CurveKind curve_of(const CaseFile& f, const std::string& key, const std::string& name) {
  try {
    return parse_curve_name(name);
  } catch (const std::exception&) {
    throw CaseFileError(f.path() + ": key '" + key + "' has unknown curve '" + name + "'");
  }
}

// Mean of the downslope-averaged I over the bulk of the layer (cells wholly below h0 - dz).
double bulk_mean_I(const LayerRunRecord& r, double h0) {
  if (r.I_profile.empty()) return nan;
  double sum = 0.0;
  int n = 0;
  for (int k = 0; k < bulk_cells(r.nz, r.Lz, h0); ++k)
    if (std::isfinite(r.I_profile.back()[k])) sum += r.I_profile.back()[k], ++n;
  return n > 0 ? sum / n : nan;
}

nlohmann::json finite_or_null(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

}  // namespace

LayerCaseSpec layer_case_spec(const CaseFile& f, const std::string& res) {
  LayerCaseSpec s;
  s.name = f.name();
  s.title = f.has("title") ? f.text("title") : s.name;
  s.resolution = res;
  s.curves = f.texts("curves", res);
  s.h0 = f.number_in("h0", res, 1e-5, 1.0);
  s.angle0_deg = f.number_in("angle0", res, 0.1, 89.0);
  s.angle_deg = f.number_in("angle", res, 0.0, 89.0);
  const double Lx = f.number_in("Lx_over_h0", res, 0.1, 1e4) * s.h0;
  const double Lz = f.number_in("Lz_over_h0", res, 1.05, 100.0) * s.h0;
  const std::vector<double> nx = f.numbers("nx", res), nz = f.numbers("nz", res);
  if (nx.empty() || nx.size() != nz.size())
    throw CaseFileError(f.path() + ": keys 'nx' and 'nz' must be lists of equal length");
  const double t_end = f.number_in("t_end", res, 1e-6, 1e4);
  const int samples = int(f.number_in("samples", res, 2, 1000));

  // The solver settings of the case file (the 2D settings of every command, twod_settings.hpp).
  TwodSettings settings;
  settings.frame_fraction = 0.0;  // layers at rest or far from steady: solved in the lab frame
  if (f.has("eta_max", res)) settings.eta_max = f.number_in("eta_max", res, 1e-6, 1e12);
  if (f.has("eta_min", res)) settings.eta_min = f.number_in("eta_min", res, 1e-9, 1e6);
  if (f.has("D_min", res)) settings.D_min = f.number_in("D_min", res, 1e-15, 1.0);
  if (f.has("dt_max", res)) settings.dt_max = f.number_in("dt_max", res, 1e-9, 1.0);
  if (f.has("cfl", res)) settings.cfl = f.number_in("cfl", res, 1e-3, 0.499);
  settings.mixing = parse_mixing(f, res);
  if (f.has("momentum_transport", res)) {
    const std::string m = f.text("momentum_transport", res);
    if (m != "consistent" && m != "velocity")
      throw CaseFileError(f.path() + ": key 'momentum_transport' = '" + m +
                          "'; valid values {consistent,velocity}");
    settings.consistent_momentum = m == "consistent";
  }
  ChuteCase chute;  // the run's flow: the curve is set per run below
  chute.angle_deg = s.angle_deg;
  chute.h0 = s.h0;
  chute.Lx = Lx;
  for (const auto& curve : s.curves) {
    for (std::size_t r = 0; r < nx.size(); ++r) {
      if (nx[r] < 4 || nz[r] < 4 || nx[r] != std::floor(nx[r]) || nz[r] != std::floor(nz[r]))
        throw CaseFileError(f.path() + ": 'nx' and 'nz' entries must be integers >= 4");
      LayerRunSpec run;
      chute.curve = curve_of(f, "curves", curve);
      run.params = twod_solver_params(chute, settings);
      run.initial_curve = f.has("initial_curve", res)
                              ? curve_of(f, "initial_curve", f.text("initial_curve", res))
                              : run.params.rheology.curve;
      run.initial_zeta = degrees_to_radians(s.angle0_deg);
      run.h0 = s.h0;
      run.nx = int(nx[r]), run.nz = int(nz[r]);
      run.Lx = Lx, run.Lz = Lz;
      run.t_end = t_end;
      run.samples = samples;
      if (f.has("noise", res)) run.noise = f.number_in("noise", res, 0.0, 0.5);
      run.label = curve + "_" + std::to_string(run.nx) + "x" + std::to_string(run.nz);
      // The initial state must exist: a steady Bagnold flow of the initial curve at angle0.
      try {
        steady_state(MuCurve(run.initial_curve, chute.material, s.h0), run.initial_zeta, s.h0);
      } catch (const std::exception& e) {
        throw CaseFileError(f.path() + ": key 'angle0': no steady flow of the initial curve (" +
                            e.what() + ")");
      }
      s.runs.push_back(run);
    }
  }
  return s;
}

LayerCaseResult run_layer_case(const LayerCaseSpec& spec, unsigned jobs,
                               const std::atomic<bool>* stop, const LayerCaseProgress& progress) {
  LayerCaseResult out;
  out.runs.resize(spec.runs.size());
  std::vector<double> t_now(spec.runs.size(), 0.0);
  std::vector<double> cost(spec.runs.size());
  for (std::size_t i = 0; i < spec.runs.size(); ++i)
    cost[i] = std::pow(double(spec.runs[i].nx) * spec.runs[i].nz, 1.5) * spec.runs[i].t_end;
  const double total_cost = std::accumulate(cost.begin(), cost.end(), 0.0);
  std::mutex mutex;
  std::size_t next = 0;
  auto show = [&] {  // one status line for all runs (called under the mutex)
    std::ostringstream line;
    double done = 0.0;
    for (std::size_t i = 0; i < spec.runs.size(); ++i) {
      line << " " << spec.runs[i].label << " " << std::fixed << std::setprecision(3) << t_now[i];
      done += cost[i] * t_now[i] / spec.runs[i].t_end;
    }
    line << " / " << spec.runs.front().t_end << " s";
    progress(line.str(), done / total_cost);
  };
  const unsigned workers = std::max(1u, std::min<unsigned>(jobs, spec.runs.size()));
  auto worker = [&] {
    for (;;) {
      std::size_t i;
      {
        std::lock_guard lock(mutex);
        if (next >= spec.runs.size()) return;
        i = next++;
      }
      LayerRunProgress lp;
      lp.stop = stop;
      if (progress)
        lp.report = [&, i](const LayerRunRecord&, double t) {
          std::lock_guard lock(mutex);
          t_now[i] = t;
          show();
        };
      LayerRunSpec run = spec.runs[i];  // the workers share the 2D solver's threads
      run.params.threads = std::max(1, run.params.threads / static_cast<int>(workers));
      out.runs[i] = run_layer(run, lp);
      std::lock_guard lock(mutex);
      t_now[i] = out.runs[i].t_reached;
      if (progress) show();
    }
  };
  std::vector<std::thread> pool;
  for (unsigned w = 0; w < workers; ++w) pool.emplace_back(worker);
  for (auto& th : pool) th.join();

  // Grid dependence: each curve's coarsest run against each finer one.
  nlohmann::json gd = nlohmann::json::object();
  for (const auto& curve : spec.curves) {
    std::vector<const LayerRunRecord*> mine;
    for (std::size_t i = 0; i < spec.runs.size(); ++i)
      if (spec.runs[i].label.rfind(curve + "_", 0) == 0) mine.push_back(&out.runs[i]);
    for (std::size_t r = 1; r < mine.size(); ++r) {
      const GridDependence d = grid_dependence(*mine[0], *mine[r], spec.h0);
      out.grid_dependence.emplace_back(curve, d);
      nlohmann::json series = nlohmann::json::array();
      for (double v : d.rms_log10_I) series.push_back(finite_or_null(v));
      gd[mine[0]->label + "_vs_" + mine[r]->label] = {
          {"t", d.t}, {"rms_log10_I", series}, {"both_flowing", d.both_flowing}};
    }
  }

  nlohmann::json runs = nlohmann::json::array();
  for (std::size_t i = 0; i < spec.runs.size(); ++i) {
    const LayerRunRecord& r = out.runs[i];
    const LayerRunSpec& s = spec.runs[i];
    double steady_I = nan;  // the run curve's own steady I at the run's slope, if one exists
    try {
      steady_I = steady_state(MuCurve(s.params.rheology.curve, s.params.rheology.material, s.h0),
                              s.params.zeta, s.h0)
                     .I_zeta;
    } catch (const std::exception&) {
    }
    // the growth of x-dependent perturbations (perturbation_energy.hpp)
    const std::vector<double> E = perturbation_energy(r, s.h0);
    nlohmann::json E_series = nlohmann::json::array();
    for (double v : E) E_series.push_back(finite_or_null(v));
    const EnergyGrowth growth = energy_growth(r.t, E);
    nlohmann::json energy_growth_json =
        growth.rate ? nlohmann::json{{"rate", *growth.rate},
                                     {"window", {growth.t_from, growth.t_to}},
                                     {"samples", growth.samples}}
                    : nlohmann::json{{"rate", nullptr}, {"reason", growth.reason}};
    double I_lo = INFINITY, I_hi = 0.0;
    for (const auto& field : r.I_field)
      for (double v : field)
        if (std::isfinite(v) && v > 0.0) I_lo = std::min(I_lo, v), I_hi = std::max(I_hi, v);
    runs.push_back(
        {{"label", r.label},
         {"curve", std::string(curve_name(s.params.rheology.curve))},
         {"nx", r.nx},
         {"nz", r.nz},
         {"status", r.status},
         {"message", r.message},
         {"t_reached", r.t_reached},
         {"steps", r.steps},
         {"wall_seconds", r.wall_seconds},
         {"mass_error", r.mass_error},
         {"initial_I", r.initial_I},
         {"steady_I", finite_or_null(steady_I)},
         {"final_bulk_I", finite_or_null(bulk_mean_I(r, s.h0))},
         {"final_max_speed",
          r.max_speed.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.max_speed.back())},
         {"final_illposed_fraction", r.illposed_fraction.empty()
                                         ? nlohmann::json(nullptr)
                                         : nlohmann::json(r.illposed_fraction.back())},
         {"I_range", std::isfinite(I_lo) ? nlohmann::json{I_lo, I_hi} : nlohmann::json(nullptr)},
         {"perturbation_energy", E_series},
         {"energy_growth", energy_growth_json}});
  }
  out.summary = {{"case", spec.name}, {"title", spec.title},       {"resolution", spec.resolution},
                 {"h0", spec.h0},     {"angle0", spec.angle0_deg}, {"angle", spec.angle_deg},
                 {"runs", runs},      {"grid_dependence", gd}};
  return out;
}

void write_layer_case(const std::string& path, const LayerCaseSpec& spec,
                      const LayerCaseResult& r) {
  H5Writer out(path);
  out.attribute("/", "case", spec.name);
  out.attribute("/", "title", spec.title);
  out.attribute("/", "resolution", spec.resolution);
  out.attribute("/", "h0", spec.h0);
  out.attribute("/", "angle0", spec.angle0_deg);
  out.attribute("/", "angle", spec.angle_deg);
  // The inputs on the root as in every granbench file: the case's curves, its material (one for
  // all runs), slope and depth.
  if (!spec.runs.empty()) {
    std::string curves;
    for (const auto& c : spec.curves) curves += (curves.empty() ? "" : ",") + c;
    write_flow_inputs(out, curves, spec.runs.front().params.rheology.material, spec.angle_deg,
                      spec.h0);
  }
  out.attribute("/", "results_json", r.summary.dump());
  out.create_group("/runs");
  if (!r.grid_dependence.empty()) out.create_group("/grid_dependence");
  for (std::size_t i = 0; i < r.runs.size(); ++i) {
    const LayerRunRecord& run = r.runs[i];
    const LayerRunSpec& s = spec.runs[i];
    const std::string g = "/runs/" + run.label;
    out.create_group(g);
    const std::size_t nt = run.t.size(), nz = run.z.size();
    std::vector<double> u, I, field;
    for (std::size_t n = 0; n < nt; ++n) {
      u.insert(u.end(), run.u_profile[n].begin(), run.u_profile[n].end());
      I.insert(I.end(), run.I_profile[n].begin(), run.I_profile[n].end());
      field.insert(field.end(), run.I_field[n].begin(), run.I_field[n].end());
    }
    out.write(g + "/t", run.t);
    out.write(g + "/z", run.z);
    out.write(g + "/u_profile", u, {nt, nz});
    out.write(g + "/I_profile", I, {nt, nz});
    out.write(g + "/I_field", field, {nt, std::size_t(run.nz), std::size_t(run.nx)});
    // For the XDMF index: the node coordinates, and I at each sample as its own [nz][nx] dataset.
    // ParaView's Xdmf3 readers do not read a hyperslab of I_field (tried: no array), so the
    // samples are stored once more; I_field stays for the figures.
    out.write(g + "/xz_nodes", layer_run_nodes(run),
              {std::size_t(run.nz) + 1, std::size_t(run.nx) + 1, 2});
    out.create_group(g + "/samples");
    for (std::size_t n = 0; n < nt; ++n) {
      const std::string sample = g + "/samples/" + layer_sample_name(n);
      out.create_group(sample);
      out.write(sample + "/I", run.I_field[n], {std::size_t(run.nz), std::size_t(run.nx)});
    }
    out.write(g + "/max_speed", run.max_speed);
    out.write(g + "/illposed_fraction", run.illposed_fraction);
    out.attribute(g, "curve", std::string(curve_name(s.params.rheology.curve)));
    out.attribute(g, "status", run.status);
    out.attribute(g, "message", run.message);
    out.attribute(g, "nx", double(run.nx));
    out.attribute(g, "nz", double(run.nz));
    out.attribute(g, "Lx", run.Lx);
    out.attribute(g, "Lz", run.Lz);
    out.attribute(g, "initial_I", run.initial_I);
    out.attribute(g, "eta_max", s.params.rheology.eta_max);
    out.attribute(g, "eta_min", s.params.rheology.eta_min);
    out.attribute(g, "D_min", s.params.rheology.D_min);
    out.attribute(g, "mixing", std::string(twod::viscosity_mixing_name(s.params.rheology.mixing)));
  }
  for (std::size_t n = 0; n < r.grid_dependence.size(); ++n) {
    const auto& [curve, d] = r.grid_dependence[n];
    const std::string g = "/grid_dependence/" + curve + "_" + std::to_string(n);
    out.create_group(g);
    out.write(g + "/t", d.t);
    out.write(g + "/rms_log10_I", d.rms_log10_I);
    out.write(g + "/both_flowing",
              std::vector<std::int64_t>(d.both_flowing.begin(), d.both_flowing.end()));
    out.attribute(g, "curve", curve);
  }
  out.close();
  // The XDMF index beside it (NAME.xdmf), referencing the HDF5 file by its name.
  const std::filesystem::path h5(path);
  write_layer_case_xdmf(companion_path(h5, ".xdmf"), h5.filename().string(), r);
}

}  // namespace granbench::cases
