// Both models past saturation, measured alike; see saturated_comparison.hpp.
#include "analysis/comparison/saturated_comparison.hpp"

#include <stdexcept>

#include "analysis/comparison/compare_output.hpp"
#include "common/hdf5_file.hpp"

namespace granbench {

SaturatedWave measure_run_end(const ModelRun& r, double window) {
  if (r.series.nt() == 0)
    throw std::invalid_argument(r.model + ": no sample to measure (" + r.message + ")");
  return measure_saturated_wave(r.series, r.series.t.back() - window);
}

SaturatedComparison compare_saturated(const ChuteCase& c, const DepthAvgSettings& depthavg,
                                      const TwodSettings& twod, double window,
                                      const RunControl& ctl) {
  SaturatedComparison s;
  s.chute = c;
  s.base = c.steady();
  s.window = window;
  std::tie(s.depthavg, s.twod) = run_both(c, depthavg, twod, ctl);
  s.depthavg_wave = measure_run_end(s.depthavg, window);
  s.twod_wave = measure_run_end(s.twod, window);
  return s;
}

namespace {

// A dataset with its own units and name (dataset_units.hpp would give "h" the meaning h(x, t)).
void write_documented(H5Writer& out, const std::string& name, const std::vector<double>& v,
                      const std::string& units, const std::string& long_name) {
  out.write(name, v);
  out.attribute(name, "units", units);
  out.attribute(name, "long_name", long_name);
}

void write_model(H5Writer& out, const std::string& g, const ModelRun& r, const SaturatedWave& w) {
  write_surface_series(out, g, r.series);
  out.attribute(g, "outcome", std::string(run_status_name(r.outcome)));
  if (!r.message.empty()) out.attribute(g, "message", r.message);
  for (auto [name, v] : {std::pair{"window_t_from", w.t_from},
                         {"window_t_to", w.t_to},
                         {"samples", double(w.samples)},
                         {"amplitude", w.amplitude},
                         {"amplitude_spread", w.amplitude_spread},
                         {"max_slope", w.max_slope},
                         {"front_width", w.front_width},
                         {"wave_speed", w.wave_speed},
                         {"speed_mode", double(w.speed_mode)},
                         {"mean_flux", w.mean_flux},
                         {"mean_depth", w.mean_depth},
                         {"steps", double(r.steps)},
                         {"wall_seconds", r.wall_seconds},
                         {"mass_error", r.mass_error}})
    out.attribute(g, name, v);
  if (!w.reason.empty()) out.attribute(g, "reason", w.reason);
  out.create_group(g + "/wave_frame");
  write_documented(out, g + "/wave_frame/xi", w.xi, "m",
                   "distance from the steepest point of the front, x - x_front");
  write_documented(out, g + "/wave_frame/h", w.h_frame, "m",
                   "flow depth in the wave's frame at the last sample, h(xi)");
  out.attribute(g + "/wave_frame", "t", w.t_to);
  write_documented(out, g + "/amplitude", w.amplitude_history, "m",
                   "wave amplitude max h - min h at each sample time t");
}

}  // namespace

void write_saturated_comparison(const std::string& path, const SaturatedComparison& s,
                                const TwodSettings& twod, const DepthAvgSettings& depthavg) {
  H5Writer out(path);
  write_model(out, "depthavg", s.depthavg, s.depthavg_wave);
  write_model(out, "twod", s.twod, s.twod_wave);
  out.attribute("/", "window", s.window);
  write_compare_configuration(out, s.chute, s.base, twod, depthavg);
  out.close();
}

}  // namespace granbench
