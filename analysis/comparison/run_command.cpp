// `granbench run` command lines of a comparison's model runs; see run_command.hpp.
#include "analysis/comparison/run_command.hpp"

#include <charconv>
#include <utility>

#include "depthavg/params.hpp"
#include "twod/viscosity_mixing.hpp"

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
  for (const MaterialConstant& k : material_constants)
    if (c.material.*k.value != table1.*k.value)
      s += std::string(" ") + k.option + " " + exact(c.material.*k.value);
  return s;
}

// The 2D settings that compare and sweep leave at their defaults, named only when changed.
std::string twod_numerics_options(const TwodSettings& s) {
  const TwodSettings defaults;
  std::string text;
  for (const auto& [option, member] : {std::pair{"--eta-min", &TwodSettings::eta_min},
                                       {"--D-min", &TwodSettings::D_min},
                                       {"--cfl", &TwodSettings::cfl},
                                       {"--dt-max", &TwodSettings::dt_max},
                                       {"--tolerance", &TwodSettings::tolerance}})
    if (s.*member != defaults.*member) text += std::string(" ") + option + " " + exact(s.*member);
  if (s.mixing != defaults.mixing)
    text += std::string(" --mixing ") + twod::viscosity_mixing_name(s.mixing);
  if (s.consistent_momentum != defaults.consistent_momentum)
    text +=
        std::string(" --momentum-transport ") + (s.consistent_momentum ? "consistent" : "velocity");
  return text;
}

}  // namespace

std::string depthavg_run_command(const ChuteCase& c, const DepthAvgSettings& s, double dt_out) {
  // The tolerances as run_depthavg (model_runs.cpp) sets them: atol relative to h0.
  return "granbench run --model depthavg" + chute_options(c, dt_out) + " --nx " +
         std::to_string(s.nx) + " --chi " + exact(s.chi) + " --limiter " +
         std::string(depthavg::reconstruction_name(s.reconstruction)) + " --rtol " + exact(s.rtol) +
         " --atol " + exact(1e-4 * s.rtol * c.h0) + " --bdf-order " +
         std::to_string(depthavg::IntegratorParams{}.max_order) + " --frame-speed " +
         (s.co_moving ? "linear" : "0");
}

std::string twod_run_command(const ChuteCase& c, const TwodSettings& s, double dt_out) {
  // `run` seeds the eigenmode at the default chebyshev_N, the only value compare and sweep use.
  return "granbench run --model twod" + chute_options(c, dt_out) + " --nx " + std::to_string(s.nx) +
         " --nz " + std::to_string(s.nz) + " --Lz " + exact(s.domain_height(c.h0)) + " --eta-max " +
         exact(s.eta_max) + " --rho-light " + exact(s.rho_light) + " --eta-light " +
         exact(s.eta_light) + " --viscosity-passes " + std::to_string(s.viscosity_passes) +
         twod_numerics_options(s);
}

}  // namespace granbench
