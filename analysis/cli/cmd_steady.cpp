// granbench steady: the steady uniform Bagnold flow for a slope and depth (§5.2, §7): I_zeta,
// surface and mean speeds (5.5), Froude number (7.1) and the depth-averaged coefficients
// R (7.6), Gamma (7.9a), nu (7.5), generalised to the chosen curve (docs/design.md §4).
#include <iomanip>
#include <iostream>
#include <memory>

#include "analysis/cli/cli_common.hpp"
#include "analysis/cli/commands.hpp"
#include "analysis/cli/help_footer.hpp"
#include "analysis/cli/output_checks.hpp"
#include "analysis/theory/dispersion.hpp"
#include "common/hdf5_file.hpp"
#include "common/steady_state.hpp"

namespace granbench::cli {

namespace {

struct SteadyOptions {
  FlowOptions flow;
  OutputOptions output;
};

void run_steady(const SteadyOptions& o) {
  const SteadyState s = o.flow.steady();
  if (!o.output.out.empty()) {
    constexpr int kN = 201;
    std::vector<double> z(kN), u(kN), p(kN);
    for (int i = 0; i < kN; ++i) {
      z[i] = s.h0 * i / (kN - 1);
      u[i] = s.velocity(z[i]);
      p[i] = s.pressure(z[i]);
    }
    H5Writer out(o.output.out);
    out.write("profile/z", z);
    out.write("profile/u", u);
    out.write("profile/p", p);
    for (auto [k, v] : {std::pair{"I_zeta", s.I_zeta},
                        {"u_surface", s.u_surface},
                        {"u_mean", s.u_mean},
                        {"Fr", s.Fr},
                        {"R", s.R},
                        {"Gamma", s.Gamma},
                        {"nu", s.nu}})
      out.attribute("/", k, v);
    write_flow_inputs(out, o.flow.curve, o.flow.material, o.flow.angle_deg, s.h0);
    out.close();
  }
  const double Fc = critical_froude(1.0);
  if (o.output.json) {
    nlohmann::json j{{"curve", o.flow.curve},
                     {"angle", o.flow.angle_deg},
                     {"h0", s.h0},
                     {"I_zeta", s.I_zeta},
                     {"u_surface", s.u_surface},
                     {"u_mean", s.u_mean},
                     {"Fr", s.Fr},
                     {"R", s.R},
                     {"Gamma", s.Gamma},
                     {"gamma", s.gamma},
                     {"nu", s.nu},
                     {"C", s.C},
                     {"well_posed", s.well_posed},
                     {"long_wave_unstable", s.Fr > Fc}};
    print_json(j);
    return;
  }
  std::cout << std::setprecision(6) << "Steady uniform flow, " << o.flow.curve << " curve, angle "
            << o.flow.angle_deg << " deg, h0 = " << s.h0 << " m\n"
            << "  I_zeta     " << s.I_zeta << "   (mu(I_zeta) = tan zeta)\n"
            << "  u_surface  " << s.u_surface << " m/s   (5.5)\n"
            << "  u_mean     " << s.u_mean << " m/s\n"
            << "  Fr         " << s.Fr << "   (7.1); long waves " << (s.Fr > Fc ? "grow" : "decay")
            << " in the depth-averaged model (Fr_c = 2/3)\n"
            << "  R          " << s.R << "   (7.6)\n"
            << "  Gamma      " << s.Gamma << "   (7.9a)\n"
            << "  nu         " << s.nu << " m^1/2 s^-1   (7.5)\n"
            << "  C(I_zeta)  " << s.C << "   -> " << (s.well_posed ? "well posed" : "ILL POSED")
            << "\n";
}

}  // namespace

void add_steady_command(CLI::App& app) {
  auto opts = std::make_shared<SteadyOptions>();
  CLI::App* sub =
      app.add_subcommand("steady", "the steady uniform Bagnold flow on a slope (§5.2, §7)");
  sub->footer(help_footer({"granbench steady --angle 28.5 --h0 0.004 --json",
                           "granbench steady --curve jop --angle 25 --out steady.h5"},
                          {0, 2}));
  add_flow_options(*sub, opts->flow);
  add_output_options(*sub, opts->output, /*with_plot=*/false);
  sub->callback([opts] {
    require_writable_outputs(opts->output);  // before any work, with the OS's reason
    run_steady(*opts);
  });
}

}  // namespace granbench::cli
