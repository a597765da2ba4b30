// Writes compare.h5; see compare_output.hpp.
#include "analysis/comparison/compare_output.hpp"

#include <cmath>
#include <vector>

#include "common/hdf5_file.hpp"

namespace granbench {

namespace {

void write_measurement(H5Writer& out, const std::string& g, const ModelRun& r,
                       const Measurement& m) {
  write_surface_series(out, g, r.series);
  const SurfaceMeasurement& w = m.spectral;
  out.attribute(g, "growth_rate", w.growth_rate);  // NaN when no clean window (see reason)
  out.attribute(g, "phase_speed", w.phase_speed);
  out.attribute(g, "fit_t_first", w.t_first);
  out.attribute(g, "fit_t_last", w.t_last);
  // ln|h_k| of the seeded component = fit_intercept + growth_rate t, in FFTW's unnormalised
  // units (|h_k| = amplitude nx / 2), for the plot.
  const double raw = w.found() ? w.modes[w.seeded].amplitude * double(r.series.nx()) / 2.0 : NAN;
  out.attribute(g, "fit_intercept", std::log(raw) - w.growth_rate * w.t_first);
  out.attribute(g, "fit_residual", w.relative_residual);
  out.attribute(g, "fit_reason", w.reason);
  // The fitted waves, largest first: rows of (growth rate [1/s], phase speed [m/s],
  // amplitude at the window start [m]).
  std::vector<double> rows;
  for (const WaveMode& v : w.modes)
    rows.insert(rows.end(), {v.growth_rate, v.phase_speed, v.amplitude});
  if (!rows.empty()) out.write(g + "/modes", rows, {w.modes.size(), 3});
  out.attribute(g, "growth_rate_712", m.growth_712.value_or(NAN));
  // the developed wave's speed and amplitude, when it has saturated
  out.attribute(g, "wave_speed", m.saturated && m.wave ? m.wave->speed : NAN);
  out.attribute(g, "amplitude", m.saturated ? m.final_amplitude : NAN);
  out.attribute(g, "steps", static_cast<double>(r.steps));
  out.attribute(g, "wall_seconds", r.wall_seconds);
  out.attribute(g, "mass_error", r.mass_error);
  out.attribute(g, "flux", r.flux);
  out.attribute(g, "seeded_growth_rate", r.seeded_growth_rate);
  out.attribute(g, "outcome", std::string(run_status_name(r.outcome)));
  if (!r.message.empty()) out.attribute(g, "message", r.message);
}

}  // namespace

void write_comparison(const std::string& path, const Comparison& c, const TwodSettings& twod,
                      const DepthAvgSettings& depthavg) {
  H5Writer out(path);
  write_measurement(out, "depthavg", c.depthavg, c.depthavg_measured);
  write_measurement(out, "twod", c.twod, c.twod_measured);
  out.attribute("twod", "I_min", c.twod.I_min);
  out.attribute("twod", "I_max", c.twod.I_max);
  out.attribute("twod", "illposed_fraction", c.twod.illposed_fraction);
  if (const auto& e = c.twod_extrapolation) {
    out.attribute("twod", "extrapolated_growth_rate", e->growth.value);  // NaN: see the reason
    out.attribute("twod", "extrapolated_growth_rate_low", e->growth.low);
    out.attribute("twod", "extrapolated_growth_rate_high", e->growth.high);
    out.attribute("twod", "growth_rate_half_cells", e->growth_rate_half_cells);
    out.attribute("twod", "half_cells_nz", static_cast<double>(e->nz));
    out.attribute("twod", "dz_ratio", e->dz_ratio);
    out.attribute("twod", "extrapolation_reason", e->reason);
  }
  out.create_group("theory");
  out.attribute("theory", "k_hat", c.theory.k_hat);
  out.attribute("theory", "exact_growth_rate", c.theory.exact.growth_rate);
  out.attribute("theory", "exact_phase_speed", c.theory.exact.phase_speed);
  out.attribute("theory", "exact_bagnold_growth_rate", c.theory.exact_bagnold.growth_rate);
  out.attribute("theory", "exact_bagnold_phase_speed", c.theory.exact_bagnold.phase_speed);
  out.attribute("theory", "exact_2d_growth_rate", c.theory.exact_2d.growth_rate);
  out.attribute("theory", "exact_2d_phase_speed", c.theory.exact_2d.phase_speed);
  out.attribute("theory", "exact_2d_convergence", c.theory.exact_2d_convergence);
  write_compare_configuration(out, c.chute, c.base, twod, depthavg);
  out.close();
}

void write_compare_configuration(H5Writer& out, const ChuteCase& k, const SteadyState& base,
                                 const TwodSettings& twod, const DepthAvgSettings& depthavg) {
  const Material& m = k.material;
  write_flow_inputs(out, std::string(curve_name(k.curve)), m, k.angle_deg, k.h0);
  for (auto [name, v] : {std::pair{"Lx", k.Lx},
                         {"a0", k.a0},
                         {"t_end", k.t_end},
                         {"twod_Lz", twod.domain_height(k.h0)},
                         {"depthavg_nx", double(depthavg.nx)},
                         {"depthavg_chi", depthavg.chi},
                         {"depthavg_rtol", depthavg.rtol},
                         {"depthavg_co_moving", depthavg.co_moving ? 1.0 : 0.0},
                         {"I_zeta", base.I_zeta},
                         {"u_mean", base.u_mean},
                         {"Fr", base.Fr}})
    out.attribute("/", name, v);
  for (const auto& [name, value] : named_values(twod)) out.attribute("/", "twod_" + name, value);
  out.attribute("/", "seed", std::string(k.seed == Seed::Eigenmode ? "eigenmode" : "sine"));
  out.attribute("/", "depthavg_limiter",
                std::string(depthavg::reconstruction_name(depthavg.reconstruction)));
}

}  // namespace granbench
