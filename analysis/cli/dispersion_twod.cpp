// `granbench dispersion --theory twod` (dispersion_twod.hpp). Steps: (1) the 2D linear stability
// at each Lx, at N and at 3N/2 for the convergence check; (2) the short-wave ill-posedness probe;
// (3) the surface mode's cutoff, at both resolutions; (4) output: JSON, table, and with
// --out/--plot the three theories over k_hat (the 2D surface branch, (7.11) with chi = 1 and with
// chi = 5/4) plus each surface eigenmode's profiles.
#include "analysis/cli/dispersion_twod.hpp"

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <numbers>

#include "analysis/cli/dispersion_output.hpp"
#include "analysis/linear2d/eigenmode.hpp"
#include "analysis/linear2d/ill_posedness.hpp"
#include "analysis/linear2d/linear_stability_2d.hpp"
#include "analysis/theory/dispersion.hpp"
#include "common/hdf5_file.hpp"

namespace granbench::cli {

void run_twod_dispersion(const SteadyState& s, const MuCurve& curve, const std::vector<double>& Lx,
                         const TwoDDispersionOptions& t, const OutputOptions& output) {
  if (t.N < 8 || t.N > 160)
    throw UsageError("--chebyshev: Chebyshev intervals for --theory twod must be in [8, 160]");
  Linear2DOptions opt;
  opt.N = t.N;
  opt.N_check = t.N + t.N / 2;
  opt.light_layer = t.light_layer;
  std::vector<Linear2DResult> results;
  for (double L : Lx) results.push_back(linear_stability_2d(s, curve, L, opt));  // (1)
  const auto probe = linear2d::probe_ill_posedness(s, curve);                    // (2)
  const auto& base = results.front().base;
  const double F_c = linear2d::critical_froude_2d(base.mu, base.Gamma);
  // (3) the surface mode's cutoff, at N and at N_check for its convergence
  const auto cutoff = linear2d::surface_mode_cutoff_k_hat(base, opt.N, opt.map, opt.path);
  const auto cutoff_check =
      linear2d::surface_mode_cutoff_k_hat(base, opt.N_check, opt.map, opt.path);
  const double cutoff_Lx = cutoff ? 2.0 * std::numbers::pi * s.h0 / *cutoff : NAN;  // (7.13b)
  const double cutoff_difference =
      cutoff && cutoff_check ? std::abs(*cutoff - *cutoff_check) / *cutoff_check : NAN;

  if (!output.out.empty() || !output.plot.empty()) {  // (4)
    const std::string h5 = !output.out.empty() ? output.out : output.plot + ".data.h5";
    write_theories(h5, s, results, opt, t.curve_name);
    if (!output.plot.empty()) {
      run_plot_script("linear_theory.py", h5, output.plot);
      if (output.out.empty()) std::filesystem::remove(h5);
    }
  }
  if (probe.ill_posed_base_state) std::cerr << "granbench: warning: " << probe.message << "\n";

  if (output.json) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& r : results) {
      nlohmann::json m = mode_json(r.surface);
      m["Lx"] = r.Lx;
      m["k_hat"] = r.k_hat;
      m["convergence"] = {
          {"N", r.N},
          {"N_check", r.N_check},
          {"growth_rate_check", r.surface.lambda_hat_check.real() * s.u_mean / s.h0},
          {"phase_speed_check", -r.surface.lambda_hat_check.imag() / r.k_hat * s.u_mean},
          {"relative_difference", number_or_null(r.surface.relative_difference)}};
      nlohmann::json branches = nlohmann::json::array();
      for (const auto& u : r.unstable) branches.push_back(mode_json(u));
      m["unstable_branches"] = branches;
      if (r.light_layer) m["light_layer"] = light_layer_json(r);
      list.push_back(m);
    }
    nlohmann::json layer = nullptr;
    if (t.light_layer) {
      const auto l = linear2d::scale(*t.light_layer, s);
      layer = {{"rho_light", t.light_layer->rho_l},
               {"eta_light", t.light_layer->eta_l},
               {"Lz", t.light_layer->Lz_over_h0 * s.h0},
               {"density_ratio", l.r},
               {"viscosity_scaled", l.eps},
               {"overburden_scaled", l.overburden()}};
    }
    print_json({{"theory", "twod"},
                {"light_layer", layer},
                {"F", s.Fr},
                {"F_critical", F_c},
                {"Gamma", base.Gamma},
                {"u_mean", s.u_mean},
                {"modes", list},
                {"cutoff_k_hat", cutoff ? nlohmann::json(*cutoff) : nlohmann::json(nullptr)},
                {"cutoff_Lx", number_or_null(cutoff_Lx)},
                {"cutoff_relative_difference", number_or_null(cutoff_difference)},
                {"ill_posedness",
                 {{"C", probe.C},
                  {"k_hat_probe", probe.k_hat},
                  {"N1", probe.N1},
                  {"N2", probe.N2},
                  {"growth_rate_N1", probe.growth_rate_N1},
                  {"growth_rate_N2", probe.growth_rate_N2},
                  {"ill_posed_base_state", probe.ill_posed_base_state},
                  {"message", probe.message}}}});
    return;
  }
  std::cout << std::setprecision(5) << "Exact 2D linear stability (Chebyshev N = " << opt.N
            << ", check N = " << opt.N_check << "), " << t.curve_name << " curve, angle "
            << t.angle_deg << " deg, h0 = " << s.h0 << " m\n  F = " << s.Fr
            << " (2D long-wave critical " << F_c << "), Gamma = " << base.Gamma << "\n\n"
            << "  " << std::setw(10) << "Lx [m]" << std::setw(10) << "k_hat" << std::setw(15)
            << "growth [1/s]" << std::setw(15) << "speed [m/s]" << std::setw(12) << "rel. diff"
            << "   other unstable branches (growth, speed)\n";
  for (const auto& r : results) {
    std::cout << "  " << std::setw(10) << r.Lx << std::setw(10) << r.k_hat << std::setw(15)
              << r.surface.growth_rate << std::setw(15) << r.surface.phase_speed << std::setw(12)
              << std::setprecision(2) << r.surface.relative_difference << std::setprecision(5)
              << "  ";
    for (const auto& u : r.unstable)
      if (!u.surface) std::cout << " (" << u.growth_rate << ", " << u.phase_speed << ")";
    std::cout << "\n";
    if (!r.light_layer) continue;
    const auto& l = *r.light_layer;
    std::cout << "  " << std::setw(10) << "  light" << std::setw(10) << "" << std::setw(15)
              << l.surface.growth_rate << std::setw(15) << l.surface.phase_speed << std::setw(12)
              << std::setprecision(2) << l.surface.relative_difference << std::setprecision(5)
              << "  ";
    for (const auto& c : l.continued)
      if (!c.surface) std::cout << " (" << c.growth_rate << ", " << c.phase_speed << ")";
    std::cout << "\n";
  }
  if (t.light_layer) {
    const auto l = linear2d::scale(*t.light_layer, s);
    std::cout << "\n  light: grains under a fluid of density " << t.light_layer->rho_l
              << " kg/m^3, viscosity " << t.light_layer->eta_l
              << " Pa s up to Lz = " << t.light_layer->Lz_over_h0 * s.h0
              << " m (p = 0, du/dz = 0 there): "
              << "rho_l/rho_g = " << l.r << ", overburden " << l.overburden()
              << " h0; other branches continued from the stress-free ones\n";
  }
  if (cutoff)
    std::cout << std::setprecision(6) << "\n  2D cutoff: k_hat = " << *cutoff
              << ", Lx = " << cutoff_Lx << " m (the surface mode decays on shorter waves; "
              << std::setprecision(2) << cutoff_difference << " relative to N = " << opt.N_check
              << ")\n"
              << std::setprecision(5);
  else
    std::cout << "\n  no 2D cutoff: the surface mode decays at every wavelength (F below "
                 "critical) or grows up to k_hat = 30\n";
  std::cout << "\n  " << probe.message << "\n";
}

}  // namespace granbench::cli
