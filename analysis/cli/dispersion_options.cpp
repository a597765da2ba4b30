// The options of `granbench dispersion`; see dispersion_options.hpp.
#include "analysis/cli/dispersion_options.hpp"

namespace granbench::cli {

std::optional<linear2d::LightLayer> light_layer(const DispersionOptions& o, Theory theory) {
  if (!o.light_layer) return std::nullopt;
  if (theory != Theory::TwoD) throw UsageError("--light-layer: only with --theory twod");
  const double Lz = o.Lz > 0.0 ? o.Lz : 2.0 * o.flow.h0;
  if (!(Lz > o.flow.h0))
    throw UsageError("--Lz: " + std::to_string(Lz) + " out of range; valid range (h0, inf)");
  return linear2d::LightLayer{o.rho_light, o.eta_light, Lz / o.flow.h0};
}

Theory parse_theory(const std::string& t) {
  if (t == "depthavg") return Theory::DepthAvg;
  if (t == "depthavg-bagnold") return Theory::DepthAvgBagnold;
  return Theory::TwoD;
}

void add_dispersion_options(CLI::App& app, DispersionOptions& o) {
  add_flow_options(app, o.flow);
  add_output_options(app, o.output);
  app.add_option("--Lx", o.Lx, "domain length(s) = wavelength(s) [m], > 0")
      ->required()
      ->check(positive());
  app.add_option("--theory", o.theory, "linear theory {depthavg,depthavg-bagnold,twod}")
      ->check(one_of({"depthavg", "depthavg-bagnold", "twod"}))
      ->capture_default_str();
  app.add_option("--chebyshev", o.resolution,
                 "Chebyshev intervals for --theory twod, in [8, 160] (check at 3N/2)")
      ->capture_default_str();
  const std::string light = "Light layer (--theory twod --light-layer)";
  auto* flag = app.add_flag("--light-layer", o.light_layer,
                            "--theory twod: also the grains under the 2D solver's light fluid "
                            "(density --rho-light, viscosity --eta-light, top at --Lz: p = 0, "
                            "du/dz = 0)")
                   ->group(light);
  app.add_option("--rho-light", o.rho_light, "light-fluid density [kg/m^3], > 0")
      ->check(positive())
      ->needs(flag)
      ->group(light)
      ->capture_default_str();
  app.add_option("--eta-light", o.eta_light, "light-fluid viscosity [Pa s], > 0")
      ->check(positive())
      ->needs(flag)
      ->group(light)
      ->capture_default_str();
  app.add_option("--Lz", o.Lz, "domain height [m], > h0; default 2 h0")
      ->check(positive())
      ->needs(flag)
      ->group(light);
}

}  // namespace granbench::cli
