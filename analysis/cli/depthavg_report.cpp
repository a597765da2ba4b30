// What `granbench run --model depthavg` prints (depthavg_report.hpp).
#include "analysis/cli/depthavg_report.hpp"

#include <iomanip>
#include <iostream>
#include <sstream>

#include "analysis/cli/cli_common.hpp"

namespace granbench::cli {

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
    std::cout << "depthavg run (" << j["status"].get<std::string>()
              << "), chi = " << j["chi"].get<double>() << ", " << o.flow.curve << " curve, angle "
              << o.flow.angle_deg << " deg, h0 = " << o.flow.h0 << " m, Lx = " << o.Lx
              << " m, nx = " << o.nx << "\n"
              << "  t reached        " << j["t_reached"].get<double>() << " s in "
              << j["wall_seconds"].get<double>() << " s wall\n"
              << "  CVODE            " << j["steps"].get<long>() << " steps, "
              << j["rhs_evals"].get<long>() << " RHS evaluations, "
              << j["linear_iterations"].get<long>() << " linear iterations\n"
              << "  mass error       " << j["mass_error"].get<double>() << " (relative)\n"
              << "  flux at end      " << j["flux"].get<double>() << " m^2/s\n"
              << "  growth rate      " << show(j["growth_rate"])
              << " 1/s   (7.11): " << j["growth_rate_exact"].get<double>()
              << "   (7.12): " << show(j["growth_rate_712"]) << "\n"
              << "  phase speed      " << show(j["phase_speed"])
              << " m/s   (7.11): " << j["phase_speed_exact"].get<double>() << "\n"
              << "  wave speed       " << show(j["wave_speed"]) << " m/s (cross-correlation, "
              << "last fifth of the run)\n";
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

}  // namespace granbench::cli
