// granbench wellposed: where a mu(I) curve keeps the incompressible equations well posed
// (Barker & Gray 2017, §3-§4, figures 1, 2 and 7): neutral points (roots of C(I), (3.9)), the
// well-posed intervals of I, A_- of the regularised curve (6.4) and its largest well-posed I.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>

#include "analysis/cli/cli_common.hpp"
#include "analysis/cli/commands.hpp"
#include "analysis/cli/help_footer.hpp"
#include "analysis/cli/output_checks.hpp"
#include "analysis/theory/wellposedness_figures.hpp"

namespace granbench::cli {

namespace {

struct WellposedOptions {
  FlowOptions flow;
  OutputOptions output;
};

nlohmann::json opt_json(const std::optional<double>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

// Writes --out and --plot (when given) and returns the JSON result.
nlohmann::json wellposed(const WellposedOptions& o, const MuCurve& curve,
                         const WellPosednessFigures& fig) {
  const WellPosedness& w = fig.analysis;
  if (!o.output.out.empty() || !o.output.plot.empty()) {
    const std::string h5 = !o.output.out.empty() ? o.output.out : o.output.plot + ".data.h5";
    {
      H5Writer out(h5);
      write_well_posedness_figures(out, fig);
      // No slope here: the curve and the material (and h0, which the Holyoake curve uses).
      write_flow_inputs(out, std::string(curve_name(curve.kind())), o.flow.material, NAN,
                        o.flow.h0);
      out.close();
    }
    if (!o.output.plot.empty()) {
      run_plot_script("wellposed.py", h5, o.output.plot);
      if (o.output.out.empty()) std::filesystem::remove(h5);
    }
  }
  nlohmann::json intervals = nlohmann::json::array();
  for (auto [lo, hi] : w.intervals) intervals.push_back({lo, hi});
  nlohmann::json j;
  j["curve"] = curve_name(curve.kind());
  j["I1N"] = opt_json(w.I1N);
  j["I2N"] = opt_json(w.I2N);
  j["neutral_points"] = w.neutral;
  j["well_posed_intervals"] = intervals;
  j["A_minus"] =
      curve.junction_I() > 0.0 ? nlohmann::json(curve.A_minus()) : nlohmann::json(nullptr);
  j["I_max_wellposed"] = w.I_max_wellposed;
  j["I_max_bound"] = fig.I_max > 0.0 ? nlohmann::json(fig.I_max) : nlohmann::json(nullptr);
  return j;
}

void run_wellposed(const WellposedOptions& o) {
  const MuCurve curve = o.flow.make_curve();
  const WellPosednessFigures fig = well_posedness_figures(curve);
  const WellPosedness& w = fig.analysis;
  const nlohmann::json j = wellposed(o, curve, fig);
  const bool has_low_branch = curve.junction_I() > 0.0;
  if (o.output.json) {
    print_json(j);
    return;
  }
  auto show = [](const std::optional<double>& v) {
    std::ostringstream s;
    if (v)
      s << std::setprecision(7) << *v;
    else
      s << "none";
    return s.str();
  };
  std::cout << "Well-posedness of the " << curve_name(curve.kind()) << " curve (C(I) of (3.9))\n"
            << "  lower neutral point I1N      " << show(w.I1N)
            << (has_low_branch ? "   (junction of the low-I branch)" : "") << "\n"
            << "  upper neutral point I2N      " << show(w.I2N) << "\n";
  if (has_low_branch)
    std::cout << "  A_- of (5.3)/(6.4)           " << std::setprecision(7) << curve.A_minus()
              << "\n";
  std::cout << "  well-posed intervals of I   ";
  for (auto [lo, hi] : w.intervals) std::cout << " [" << lo << ", " << hi << "]";
  if (w.intervals.empty()) std::cout << " none";
  std::cout << "\n  largest well-posed I         " << w.I_max_wellposed << "\n";
  if (fig.I_max > 0.0) std::cout << "  I_max of §4 (from Jop's I2N) " << fig.I_max << "\n";
  if (!o.output.out.empty()) std::cout << "  data written to " << o.output.out << "\n";
  if (!o.output.plot.empty()) std::cout << "  figure written to " << o.output.plot << "\n";
}

}  // namespace

nlohmann::json wellposed_result(const std::string& curve, const std::string& h5,
                                const std::string& png) {
  WellposedOptions o;
  o.flow.curve = curve;
  o.output.out = h5;
  o.output.plot = png;
  const MuCurve mu = o.flow.make_curve();
  return wellposed(o, mu, well_posedness_figures(mu));
}

void add_wellposed_command(CLI::App& app) {
  auto opts = std::make_shared<WellposedOptions>();
  CLI::App* sub = app.add_subcommand(
      "wellposed", "neutral points and well-posed ranges of I for a mu(I) curve (§3-§4)");
  sub->footer(help_footer({"granbench wellposed --curve jop --json",
                           "granbench wellposed --curve regularised --out wp.h5 --plot wp.png"},
                          {0, 2}));
  add_flow_options(*sub, opts->flow, /*add_slope=*/false);
  add_output_options(*sub, opts->output);
  sub->callback([opts] {
    require_writable_outputs(opts->output);  // before any work, with the OS's reason
    run_wellposed(*opts);
  });
}

}  // namespace granbench::cli
