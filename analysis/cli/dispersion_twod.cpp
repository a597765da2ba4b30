// `granbench dispersion --theory twod` (dispersion_twod.hpp). Steps: (1) the 2D linear stability
// at each Lx, at N and at 3N/2 for the convergence check; (2) the short-wave ill-posedness probe;
// (3) output: JSON, table, and with --out/--plot the three theories over k_hat (the 2D surface
// branch, (7.11) with chi = 1 and with chi = 5/4) plus each surface eigenmode's profiles.
#include "analysis/cli/dispersion_twod.hpp"

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>

#include "analysis/linear2d/eigenmode.hpp"
#include "analysis/linear2d/ill_posedness.hpp"
#include "analysis/linear2d/linear_stability_2d.hpp"
#include "analysis/theory/dispersion.hpp"
#include "common/hdf5_file.hpp"

namespace granbench::cli {

namespace {

nlohmann::json mode_json(const Linear2DMode& m) {
  return {{"growth_rate", m.growth_rate},
          {"phase_speed", m.phase_speed},
          {"lambda_hat_re", m.lambda_hat.real()},
          {"lambda_hat_im", m.lambda_hat.imag()},
          {"surface_mode", m.surface},
          {"relative_difference", number_or_null(m.relative_difference)}};
}

// The light-layer counterpart of the stress-free mode `free`, with the differences.
nlohmann::json light_mode_json(const Linear2DMode& m, const Linear2DMode& free) {
  nlohmann::json j = mode_json(m);
  j["growth_rate_difference"] = m.growth_rate - free.growth_rate;
  j["phase_speed_difference"] = m.phase_speed - free.phase_speed;
  return j;
}

nlohmann::json light_layer_json(const Linear2DResult& r) {
  const auto& l = *r.light_layer;
  nlohmann::json continued = nlohmann::json::array(), unstable = nlohmann::json::array();
  for (std::size_t i = 0; i < l.continued.size(); ++i)
    continued.push_back(light_mode_json(l.continued[i], r.unstable[i]));
  for (const auto& u : l.unstable) unstable.push_back(mode_json(u));
  nlohmann::json j = light_mode_json(l.surface, r.surface);
  j["continued_branches"] = continued;
  j["unstable_branches"] = unstable;
  return j;
}

void write_theories(const std::string& path, const SteadyState& s,
                    const std::vector<Linear2DResult>& results, const Linear2DOptions& opt,
                    const std::string& curve) {
  std::vector<double> k_hat;
  for (int i = 0; i < 60; ++i) k_hat.push_back(std::pow(10.0, -2.0 + 3.0 * i / 59.0));
  const int N_curve = std::min(opt.N, 24);  // converged to ~1e-7 (tests/analysis/linear2d)
  const auto branch = linear2d::surface_branch(results.front().base, k_hat, N_curve);
  const double rate = s.u_mean / s.h0;
  std::vector<double> Lx, g2, c2, go, co, g1, c1, g54, c54;
  for (const auto& p : branch) {
    Lx.push_back(Lx_from_k_hat(s, p.k_hat));
    g2.push_back(p.surface.real() * rate);
    c2.push_back(-p.surface.imag() / p.k_hat * s.u_mean);
    go.push_back(p.other_max_growth * rate);
    co.push_back(p.other_phase_speed * s.u_mean);
    const auto d1 = dispersion_mode(s, 1.0, Lx.back());
    const auto d54 = dispersion_mode(s, 1.25, Lx.back());
    g1.push_back(d1.growth_rate);
    c1.push_back(d1.phase_speed);
    g54.push_back(d54.growth_rate);
    c54.push_back(d54.phase_speed);
  }
  H5Writer out(path);
  out.write("curve/k_hat", k_hat);
  out.write("curve/Lx", Lx);
  out.write("curve/twod_growth_rate", g2);
  out.write("curve/twod_phase_speed", c2);
  out.write("curve/twod_other_growth_rate", go);
  out.write("curve/twod_other_phase_speed", co);
  out.write("curve/depthavg_growth_rate", g1);
  out.write("curve/depthavg_phase_speed", c1);
  out.write("curve/bagnold_growth_rate", g54);
  out.write("curve/bagnold_phase_speed", c54);
  std::vector<double> pL, pk, pg, pc;
  for (std::size_t i = 0; i < results.size(); ++i) {
    const auto& r = results[i];
    pL.push_back(r.Lx);
    pk.push_back(r.k_hat);
    pg.push_back(r.surface.growth_rate);
    pc.push_back(r.surface.phase_speed);
    const linear2d::Eigenmode mode(s, r.base, r.k_hat, linear2d::ChebyshevGrid(r.N), opt.map,
                                   r.surface_pair);
    std::vector<double> z(mode.z_nodes()), ur, ui, wr, wi, pr, pi;
    for (Eigen::Index j = 0; j < mode.u_nodes().size(); ++j) {
      ur.push_back(mode.u_nodes()(j).real());
      ui.push_back(mode.u_nodes()(j).imag());
      wr.push_back(mode.w_nodes()(j).real());
      wi.push_back(mode.w_nodes()(j).imag());
      pr.push_back(mode.p_nodes()(j).real());
      pi.push_back(mode.p_nodes()(j).imag());
    }
    const std::string g = "eigenmode_" + std::to_string(i) + "/";
    out.write(g + "z", z);
    out.write(g + "u_re", ur);
    out.write(g + "u_im", ui);
    out.write(g + "w_re", wr);
    out.write(g + "w_im", wi);
    out.write(g + "p_re", pr);
    out.write(g + "p_im", pi);
    out.attribute(g, "Lx", r.Lx);
  }
  out.write("points/Lx", pL);
  out.write("points/k_hat", pk);
  out.write("points/growth_rate", pg);
  out.write("points/phase_speed", pc);
  out.attribute("/", "F", s.Fr);
  out.attribute("/", "Gamma", results.front().base.Gamma);
  out.attribute("/", "u_mean", s.u_mean);
  write_flow_inputs(out, curve, s.material, s.zeta * 180.0 / std::numbers::pi, s.h0);
  out.attribute("/", "N", double(opt.N));
  out.close();
}

}  // namespace

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

  if (!output.out.empty() || !output.plot.empty()) {  // (3)
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
  std::cout << "\n  " << probe.message << "\n";
}

}  // namespace granbench::cli
