// `granbench run` command lines of a comparison's model runs; see run_command.hpp.
#include "analysis/comparison/run_command.hpp"

#include <charconv>
#include <utility>

#include "depthavg/params.hpp"

namespace granbench {

namespace {

// Shortest decimal that reads back as the same double.
std::string exact(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

// The options shared by both models: slope, depth, curve, material, domain, seed and run length.
std::string chute_options(const ChuteCase& c, double dt_out) {
  std::string s = " --curve " + std::string(curve_name(c.curve)) + " --angle " +
                  exact(c.angle_deg) + " --h0 " + exact(c.h0) + " --Lx " + exact(c.Lx) +
                  " --init " + (c.seed == Seed::Eigenmode ? "eigenmode" : "sine") + " --a0 " +
                  exact(c.a0) + " --t-end " + exact(c.t_end) + " --dt-out " + exact(dt_out);
  const Material table1;
  const std::pair<const char*, double Material::*> constants[] = {
      {"--mu-s", &Material::mu_s},   {"--mu-d", &Material::mu_d},
      {"--I0", &Material::I0},       {"--d", &Material::d},
      {"--phi", &Material::phi},     {"--rho-star", &Material::rho_star},
      {"--g", &Material::g},         {"--mu-inf", &Material::mu_inf},
      {"--alpha", &Material::alpha}, {"--kk-mu0", &Material::kk_mu0},
      {"--kk-cK", &Material::kk_cK}, {"--hm-c", &Material::hm_c}};
  for (const auto& [option, member] : constants)
    if (c.material.*member != table1.*member)
      s += std::string(" ") + option + " " + exact(c.material.*member);
  return s;
}

}  // namespace

std::string depthavg_run_command(const ChuteCase& c, const DepthAvgSettings& s, double dt_out) {
  // The tolerances as run_depthavg (model_runs.cpp) sets them: atol relative to h0.
  return "granbench run --model depthavg" + chute_options(c, dt_out) + " --nx " +
         std::to_string(s.nx) + " --chi " + exact(s.chi) + " --limiter " +
         (s.limiter ? "mc" : "central") + " --rtol " + exact(s.rtol) + " --atol " +
         exact(1e-4 * s.rtol * c.h0) + " --bdf-order " +
         std::to_string(depthavg::IntegratorParams{}.max_order) + " --frame-speed " +
         (s.co_moving ? "linear" : "0");
}

std::string twod_run_command(const ChuteCase& c, const TwodSettings& s, double dt_out) {
  // `run` seeds the eigenmode at the default chebyshev_N, the only value compare and sweep use.
  return "granbench run --model twod" + chute_options(c, dt_out) + " --nx " + std::to_string(s.nx) +
         " --nz " + std::to_string(s.nz) + " --Lz " + exact(s.domain_height(c.h0)) + " --eta-max " +
         exact(s.eta_max) + " --rho-light " + exact(s.rho_light) + " --eta-light " +
         exact(s.eta_light) + " --viscosity-passes " + std::to_string(s.viscosity_passes);
}

}  // namespace granbench
