// What `granbench run --model depthavg` prints (depthavg_report.hpp).
#include "analysis/cli/depthavg_report.hpp"

#include <iomanip>
#include <iostream>
#include <sstream>

#include "analysis/cli/cli_common.hpp"
#include "common/hdf5_file.hpp"

namespace granbench::cli {

namespace {
// Why --limiter auto chose the slopes it did (empty for a named limiter); the bound is the
// measurement's, which the rule judges by (DepthAvgSettings::limited_where_it_saturates).
std::string auto_limiter_note(const nlohmann::json& j) {
  if (j.at("limiter_option") != "auto") return "";
  std::ostringstream bound;
  bound << MeasureOptions{}.linear_bound * 100.0 << " % of h0";
  return j.at("limiter") == "central"
             ? " (--limiter auto: the seed stays below " + bound.str() + " to the end)"
             : " (--limiter auto: the seed grows past " + bound.str() + " before the end)";
}
}  // namespace

void print_depthavg_run(const RunOptions& o, const nlohmann::json& j, const Measurement& m) {
  if (o.output.json) {
    print_json(j);
  } else {
    auto show = [](const nlohmann::json& v) {
      std::ostringstream s;
      if (v.is_null())
        s << "-";
      else
        s << std::setprecision(6) << v.get<double>();
      return s.str();
    };
    std::cout << "depthavg run (" << j.at("status").get<std::string>()
              << "), chi = " << j.at("chi").get<double>() << ", " << o.flow.curve
              << " curve, angle " << o.flow.angle_deg << " deg, h0 = " << o.flow.h0
              << " m, Lx = " << o.Lx << " m, nx = " << o.nx << "\n"
              << "  t reached        " << j.at("t_reached").get<double>() << " s in "
              << j.at("wall_seconds").get<double>() << " s wall\n"
              << "  CVODE            " << j.at("steps").get<long>() << " steps, "
              << j.at("rhs_evals").get<long>() << " RHS evaluations, "
              << j.at("linear_solves").get<long>() << " linear solves\n"
              << "  slopes           " << j.at("limiter").get<std::string>() << auto_limiter_note(j)
              << "\n"
              << "  mass error       " << j.at("mass_error").get<double>() << " (relative)\n"
              << "  flux at end      " << j.at("flux").get<double>() << " m^2/s\n"
              << "  growth rate      " << show(j.at("growth_rate"))
              << " 1/s   (7.11): " << j.at("growth_rate_exact").get<double>()
              << "   (7.12): " << show(j.at("growth_rate_712")) << "\n"
              << "  phase speed      " << show(j.at("phase_speed"))
              << " m/s   (7.11): " << j.at("phase_speed_exact").get<double>() << "\n"
              << "  wave speed       " << show(j.at("wave_speed")) << " m/s "
              << wave_speed_note(m.wave) << "\n";
    if (!m.spectral.found())
      std::cout << "  growth rate not measured: " << m.spectral.reason << "\n";
    if (m.spectral.found()) {
      std::cout << "  growth window    " << m.spectral.t_first << " .. " << m.spectral.t_last
                << " s, " << m.spectral.modes.size() << " wave(s) fitted, relative residual "
                << m.spectral.relative_residual << "\n";
      for (std::size_t i = 0; i < m.spectral.modes.size(); ++i)
        if (i != m.spectral.seeded)
          std::cout << "  other wave       growth " << m.spectral.modes[i].growth_rate
                    << " 1/s, speed " << m.spectral.modes[i].phase_speed << " m/s, amplitude "
                    << m.spectral.modes[i].amplitude * 1e3
                    << " mm (seeded: " << m.spectral.modes[m.spectral.seeded].amplitude * 1e3
                    << " mm)\n";
    }
  }
}

void write_depthavg_run(const RunOptions& o, const DepthAvgOptions& mo,
                        const depthavg::SpaceParams& space, const SteadyState& base,
                        const depthavg::RunResult& r, const nlohmann::json& j) {
  H5Writer h5(o.output.out);
  write_surface_series(h5, "surface", r.series);
  const std::vector<std::pair<std::string, double>> numbers = {
      {"angle_deg", o.flow.angle_deg},
      {"h0", o.flow.h0},
      {"Lx", o.Lx},
      {"nx", static_cast<double>(o.nx)},
      {"a0", o.a0},
      {"mode", static_cast<double>(o.mode)},
      {"noise", o.noise},
      {"seed", static_cast<double>(o.seed)},
      {"t_end", o.t_end},
      {"dt_out", j.at("dt_out").get<double>()},
      {"rtol", o.rtol},
      {"atol", o.atol},
      {"chi", space.chi},
      {"frame_speed", space.frame_speed},
      {"h_dry_fraction", space.h_dry_fraction},
      {"F", base.Fr},
      {"R", base.R},
      {"Gamma", base.Gamma},
      {"nu", base.nu},
      {"u_mean", base.u_mean},
      {"t_reached", r.t_reached},
      {"mass_error", r.mass_error()}};
  for (const auto& [k, v] : numbers) h5.attribute("/", k, v);
  for (const MaterialConstant& c : material_constants)
    h5.attribute("/", c.key, base.material.*c.value);
  for (const auto& [k, v] : std::vector<std::pair<std::string, std::string>>{
           {"model", "depthavg"},
           {"curve", o.flow.curve},
           {"init", o.init},
           {"limiter", j.at("limiter").get<std::string>()},  // the one used
           {"limiter_option", mo.limiter},
           {"status", j.at("status").get<std::string>()},
           {"message", r.message},
           {"results_json", j.dump()}})
    h5.attribute("/", k, v);
  h5.close();
}

}  // namespace granbench::cli
