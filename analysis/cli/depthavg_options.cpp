// The depth-averaged model's own options of `granbench run --model depthavg` and their parsing
// (run_model.hpp). Parsing and validation only; the run is in run_depthavg.cpp.
#include <cmath>
#include <string>

#include "analysis/cli/run_model.hpp"

namespace granbench::cli {

void add_depthavg_options(CLI::App& app, DepthAvgOptions& o) {
  const std::string g = "Depth-averaged model";
  app.add_option("--chi", o.chi,
                 "momentum shape factor chi in (7.4): 1 (the paper's), bagnold (5/4), or a "
                 "number in [1, 2]")
      ->group(g)
      ->capture_default_str();
  app.add_option("--limiter", o.limiter,
                 "slope reconstruction {auto,central,minmod,mc,vanalbada}: central is unlimited "
                 "(linear runs), vanalbada a smooth limiter; auto is central while the seed, "
                 "grown at the (7.11) rate, stays below 5 % of h0 to the run's end, vanalbada "
                 "where it grows past it (as compare and sweep do)")
      ->check(one_of({"auto", "central", "minmod", "mc", "vanalbada"}))
      ->group(g)
      ->capture_default_str();
  app.add_option("--frame-speed", o.frame_speed,
                 "solve in the frame moving at this speed [m/s], or 'linear' for the seeded "
                 "mode's (7.11) phase speed, or 0 for the lab frame; output is in the lab frame")
      ->group(g)
      ->capture_default_str();
}

depthavg::Reconstruction limiter_for_seed(const std::string& limiter, bool seed_saturates) {
  if (limiter != "auto") return depthavg::parse_reconstruction(limiter);
  return seed_saturates ? depthavg::Reconstruction::VanAlbada : depthavg::Reconstruction::Central;
}

namespace {
// The whole text as a number, NaN otherwise.
double number_or_nan(const std::string& text) {
  try {
    std::size_t used = 0;
    const double v = std::stod(text, &used);
    return used == text.size() ? v : NAN;
  } catch (const std::exception&) {
    return NAN;
  }
}
}  // namespace

double parse_chi(const std::string& text) {
  if (text == "bagnold") return 1.25;
  const double v = number_or_nan(text);
  if (!(v >= 1.0 && v <= 2.0))
    throw UsageError("--chi: '" + text +
                     "' is not allowed; valid values: bagnold or a number in [1, 2]");
  return v;
}

double parse_frame_speed(const std::string& text, double linear_speed) {
  if (text == "linear") return linear_speed;
  const double v = number_or_nan(text);
  if (!(std::fabs(v) <= 100.0))
    throw UsageError("--frame-speed: '" + text +
                     "' is not allowed; valid values: linear or a "
                     "number in [-100, 100] m/s");
  return v;
}

}  // namespace granbench::cli
