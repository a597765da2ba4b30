// granbench dispersion: exact linear theory for perturbations of wavelength Lx of the steady
// flow. --theory depthavg is the paper's relation (7.11) (chi = 1), depthavg-bagnold the same
// with the Bagnold shape factor chi = 5/4 (docs/design.md §10), twod the full 2D linear stability.
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <numbers>
#include <optional>

#include "analysis/cli/cli_common.hpp"
#include "analysis/cli/commands.hpp"
#include "analysis/cli/dispersion_options.hpp"
#include "analysis/cli/dispersion_output.hpp"
#include "analysis/cli/dispersion_twod.hpp"
#include "analysis/cli/help_footer.hpp"
#include "analysis/cli/output_checks.hpp"
#include "analysis/theory/dispersion.hpp"
#include "analysis/theory/dispersion_curve.hpp"
#include "common/hdf5_file.hpp"
#include "common/steady_state.hpp"
#include "twod/parameters.hpp"

namespace granbench::cli {

namespace {

void run_dispersion(const DispersionOptions& o) {
  const SteadyState s = o.flow.steady();
  const Theory theory = parse_theory(o.theory);
  const auto layer = light_layer(o, theory);
  if (theory == Theory::TwoD)
    return run_twod_dispersion(s, o.flow.make_curve(), o.Lx,
                               {o.resolution, o.flow.curve, o.flow.angle_deg, layer}, o.output);
  const double chi = theory == Theory::DepthAvgBagnold ? 1.25 : 1.0;
  const DispersionParams p = DispersionParams::from(s, chi);

  std::vector<DispersionMode> modes;
  for (double Lx : o.Lx) modes.push_back(dispersion_mode(s, chi, Lx));
  const auto kc = cutoff_k_hat(p);
  const double cutoff_Lx = kc ? Lx_from_k_hat(s, *kc) : NAN;

  if (!o.output.out.empty() || !o.output.plot.empty()) {
    const std::string h5 = !o.output.out.empty() ? o.output.out : o.output.plot + ".data.h5";
    write_dispersion_data(h5, s, chi, modes, o.flow.curve);
    if (!o.output.plot.empty()) {
      run_plot_script("dispersion.py", h5, o.output.plot);
      if (o.output.out.empty()) std::filesystem::remove(h5);
    }
  }

  if (o.output.json) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& m : modes)
      list.push_back({{"Lx", m.Lx},
                      {"k_hat", m.k_hat},
                      {"lambda_hat_re", m.lambda_hat.real()},
                      {"lambda_hat_im", m.lambda_hat.imag()},
                      {"growth_rate", m.growth_rate},
                      {"phase_speed", m.phase_speed}});
    print_json({{"theory", o.theory},
                {"chi", chi},
                {"F", p.F},
                {"F_critical", critical_froude(chi)},
                {"R", p.R},
                {"Gamma", p.Gamma},
                {"u_mean", s.u_mean},
                {"modes", list},
                {"cutoff_k_hat", kc ? nlohmann::json(*kc) : nlohmann::json(nullptr)},
                {"cutoff_Lx", number_or_null(cutoff_Lx)}});
    return;
  }
  std::cout << std::setprecision(5) << "Temporal dispersion relation, theory " << o.theory
            << " (chi = " << chi << "), " << o.flow.curve << " curve, angle " << o.flow.angle_deg
            << " deg, h0 = " << s.h0 << " m\n  F = " << p.F << " (critical " << critical_froude(chi)
            << "), R = " << p.R << ", Gamma = " << p.Gamma << "\n\n"
            << "  " << std::setw(10) << "Lx [m]" << std::setw(10) << "k_hat" << std::setw(14)
            << "Re lam_hat" << std::setw(14) << "Im lam_hat" << std::setw(15) << "growth [1/s]"
            << std::setw(15) << "speed [m/s]"
            << "\n";
  for (const auto& m : modes)
    std::cout << "  " << std::setw(10) << m.Lx << std::setw(10) << m.k_hat << std::setw(14)
              << m.lambda_hat.real() << std::setw(14) << m.lambda_hat.imag() << std::setw(15)
              << m.growth_rate << std::setw(15) << m.phase_speed << "\n";
  if (kc)
    std::cout << "\n  cutoff: k_hat = " << *kc << ", Lx = " << cutoff_Lx
              << " m (shorter waves decay)\n";
  else
    std::cout << "\n  no cutoff: every wavelength decays (F below critical)\n";
}

}  // namespace

void add_dispersion_command(CLI::App& app) {
  auto opts = std::make_shared<DispersionOptions>();
  CLI::App* sub = app.add_subcommand(
      "dispersion", "exact linear growth rate and phase speed for domain lengths Lx (7.11)");
  sub->footer(help_footer({"granbench dispersion --Lx 0.04 --Lx 0.08 --json",
                           "granbench dispersion --theory twod --Lx 0.08 --out dispersion.h5"},
                          {0, 2}));
  add_dispersion_options(*sub, *opts);
  sub->callback([opts] {
    require_writable_outputs(opts->output);  // before any work, with the OS's reason
    run_dispersion(*opts);
  });
}

}  // namespace granbench::cli
