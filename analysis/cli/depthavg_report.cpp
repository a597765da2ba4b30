// What `granbench run --model depthavg` measures and prints (depthavg_report.hpp).
#include "depthavg_report.hpp"

#include <iomanip>
#include <iostream>
#include <sstream>

#include "cli_common.hpp"

namespace granbench::cli {

DepthAvgMeasured measure_depthavg(const SurfaceSeries& s, int mode, double expected_speed) {
  DepthAvgMeasured m;
  MeasureOptions opt;
  opt.mode = mode;
  opt.seeded_phase_speed = expected_speed;
  m.growth = measure_surface_series(s, opt);
  if (m.growth.found()) {
    try {
      m.e712 = growth_estimate_712(s, m.growth.t_first, m.growth.t_last);
    } catch (const std::invalid_argument&) {
      // (7.12) needs max h > h0 throughout the window.
    }
  }
  if (s.nt() < 8) return m;
  try {
    m.wave = wave_speed(s, 0.5 * s.t.back(), s.t.back());
  } catch (const std::invalid_argument&) {
  }
  return m;
}

void print_depthavg_run(const RunOptions& o, const nlohmann::json& j, const DepthAvgMeasured& m) {
  if (o.output.json) {
    print_json(j);
  } else {
    auto show = [](const nlohmann::json& v) {
      std::ostringstream s;
      if (v.is_null()) s << "-";
      else s << std::setprecision(6) << v.get<double>();
      return s.str();
    };
    std::cout << "depthavg run (" << j["status"].get<std::string>() << "), chi = " << j["chi"].get<double>() << ", " << o.flow.curve
              << " curve, angle " << o.flow.angle_deg << " deg, h0 = " << o.flow.h0
              << " m, Lx = " << o.Lx << " m, nx = " << o.nx << "\n"
              << "  t reached        " << j["t_reached"].get<double>() << " s in " << j["wall_seconds"].get<double>() << " s wall\n"
              << "  CVODE            " << j["steps"].get<long>() << " steps, " << j["rhs_evals"].get<long>()
              << " RHS evaluations, " << j["linear_iterations"].get<long>() << " linear iterations\n"
              << "  mass error       " << j["mass_error"].get<double>() << " (relative)\n"
              << "  flux at end      " << j["flux"].get<double>() << " m^2/s\n"
              << "  growth rate      " << show(j["growth_rate"]) << " 1/s   (7.11): "
              << j["growth_rate_exact"].get<double>() << "   (7.12): " << show(j["growth_rate_712"]) << "\n"
              << "  phase speed      " << show(j["phase_speed"]) << " m/s   (7.11): "
              << j["phase_speed_exact"].get<double>() << "\n"
              << "  wave speed       " << show(j["wave_speed"]) << " m/s (cross-correlation, "
              << "second half of the run)\n";
    if (!m.growth.found()) std::cout << "  growth rate not measured: " << m.growth.reason << "\n";
    if (m.growth.found()) {
      std::cout << "  growth window    " << m.growth.t_first << " .. " << m.growth.t_last << " s, "
                << m.growth.modes.size() << " wave(s) fitted, relative residual "
                << m.growth.relative_residual << "\n";
      for (std::size_t i = 0; i < m.growth.modes.size(); ++i)
        if (i != m.growth.seeded)
          std::cout << "  other wave       growth " << m.growth.modes[i].growth_rate
                    << " 1/s, speed " << m.growth.modes[i].phase_speed << " m/s, amplitude "
                    << m.growth.modes[i].amplitude * 1e3
                    << " mm (seeded: " << m.growth.modes[m.growth.seeded].amplitude * 1e3
                    << " mm)\n";
    }
  }
}

}  // namespace granbench::cli
