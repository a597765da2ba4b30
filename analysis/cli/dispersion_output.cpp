// The HDF5 files of `granbench dispersion`; see dispersion_output.hpp.
#include "analysis/cli/dispersion_output.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "analysis/cli/cli_common.hpp"
#include "analysis/linear2d/eigenmode.hpp"
#include "analysis/theory/dispersion_curve.hpp"
#include "common/hdf5_file.hpp"

namespace granbench::cli {

namespace {

// The light-layer counterpart of the stress-free mode `free`, with the differences.
nlohmann::json light_mode_json(const Linear2DMode& m, const Linear2DMode& free) {
  nlohmann::json j = mode_json(m);
  j["growth_rate_difference"] = m.growth_rate - free.growth_rate;
  j["phase_speed_difference"] = m.phase_speed - free.phase_speed;
  return j;
}

}  // namespace

void write_dispersion_data(const std::string& path, const SteadyState& s, double chi,
                           const std::vector<DispersionMode>& modes, const std::string& curve) {
  // The curve over k_hat (log grid) and the chosen points, dimensional and non-dimensional.
  const DispersionParams p = DispersionParams::from(s, chi);
  std::vector<double> pk, pg, pc, pL;
  for (const auto& m : modes) {
    pk.push_back(m.k_hat);
    pg.push_back(m.growth_rate);
    pc.push_back(m.phase_speed);
    pL.push_back(m.Lx);
  }
  H5Writer out(path);
  write_dispersion_curve(out, "curve", s, chi, 1e-3, 10.0, 400);
  out.write("points/k_hat", pk);
  out.write("points/growth_rate", pg);
  out.write("points/phase_speed", pc);
  out.write("points/Lx", pL);
  out.attribute("/", "chi", chi);
  out.attribute("/", "F", p.F);
  out.attribute("/", "R", p.R);
  out.attribute("/", "Gamma", p.Gamma);
  out.attribute("/", "u_mean", s.u_mean);
  write_flow_inputs(out, curve, s.material, s.zeta * 180.0 / std::numbers::pi, s.h0);
  out.close();
}

void write_theory_curves(H5Writer& out, const SteadyState& s, const linear2d::LinearBaseState& base,
                         int N) {
  std::vector<double> k_hat;
  for (int i = 0; i < 60; ++i) k_hat.push_back(std::pow(10.0, -2.0 + 3.0 * i / 59.0));
  const int N_curve = std::min(N, 24);  // converged to ~1e-7 (tests/analysis/linear2d)
  const auto branch = linear2d::surface_branch(base, k_hat, N_curve);
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
}

void write_theories(const std::string& path, const SteadyState& s,
                    const std::vector<Linear2DResult>& results, const Linear2DOptions& opt,
                    const std::string& curve) {
  H5Writer out(path);
  write_theory_curves(out, s, results.front().base, opt.N);
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

nlohmann::json mode_json(const Linear2DMode& m) {
  return {{"growth_rate", m.growth_rate},
          {"phase_speed", m.phase_speed},
          {"lambda_hat_re", m.lambda_hat.real()},
          {"lambda_hat_im", m.lambda_hat.imag()},
          {"surface_mode", m.surface},
          {"relative_difference", number_or_null(m.relative_difference)}};
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

}  // namespace granbench::cli
