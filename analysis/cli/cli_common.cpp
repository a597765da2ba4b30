// Shared command-line pieces: validators, flow/material options, JSON printing, plotting.
#include "analysis/cli/cli_common.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <limits>
#include <sstream>

#include "analysis/cli/shipped_files.hpp"
#include "twod/parallel.hpp"

namespace granbench::cli {

namespace {
std::string fmt(double v) {
  std::ostringstream s;
  s.precision(12);  // whole bounds such as 1048576 in full
  s << v;
  return s.str();
}
}  // namespace

namespace {
// v in the interval from lo to hi, each end included or not, and a whole number if `whole`; the
// message names the interval as the help does ([lo, hi], (lo, hi) or [lo, hi)), or `shown`.
CLI::Validator interval(double lo, double hi, bool lo_included, bool hi_included,
                        const std::string& name, bool whole = false, std::string shown = "") {
  const std::string range = !shown.empty() ? shown
                                           : (lo_included ? "[" : "(") + fmt(lo) + ", " + fmt(hi) +
                                                 (hi_included ? "]" : ")");
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        double v = 0.0;
        try {
          std::size_t used = 0;
          v = std::stod(text, &used);
          if (used != text.size()) throw std::invalid_argument(text);
        } catch (const std::exception&) {
          return "'" + text + "' is not a number; valid range " + range;
        }
        if (whole && v != std::floor(v))
          return "'" + text + "' is not a whole number; valid range " + range;
        const bool above = lo_included ? v >= lo : v > lo;
        const bool below = hi_included ? v <= hi : v < hi;
        if (!(above && below)) return "value " + text + " out of range; valid range " + range;
        return {};
      },
      "in " + range, name);
}
}  // namespace

CLI::Validator positive() {
  return open_range(0.0, std::numeric_limits<double>::infinity());
}

CLI::Validator open_range(double lo, double hi) {
  return interval(lo, hi, false, false, "open_range");
}

CLI::Validator non_negative() {
  return half_open_range(0.0, std::numeric_limits<double>::infinity());
}

CLI::Validator closed_range(double lo, double hi) {
  return interval(lo, hi, true, true, "closed_range");
}

CLI::Validator count_range(long lo, long hi, const std::string& shown) {
  return interval(double(lo), double(hi), true, true, "count_range", true, shown);
}

CLI::Validator half_open_range(double lo, double hi) {
  return interval(lo, hi, true, false, "half_open_range");
}

CLI::Validator one_of(const std::vector<std::string>& values) {
  std::string list;
  for (const auto& v : values) list += (list.empty() ? "" : ",") + v;
  return CLI::Validator(
      [values, list](std::string& text) -> std::string {
        for (const auto& v : values)
          if (v == text) return {};
        return "'" + text + "' is not allowed; valid values {" + list + "}";
      },
      "{" + list + "}", "one_of");
}

CurveKind FlowOptions::curve_kind() const {
  return parse_curve_name(curve);
}

MuCurve FlowOptions::make_curve() const {
  // Some material values leave no curve of this kind to build (the regularised and low-I curves
  // need a neutral point of the upper branch): bad input, not an internal error.
  try {
    return MuCurve(curve_kind(), material, h0);
  } catch (const std::runtime_error& e) {
    throw UsageError(
        "--curve: the " + curve + " curve cannot be built from these material values (" + e.what() +
        "); valid: --mu-s, --mu-d, --I0, --alpha for which it exists, or another --curve");
  }
}

SteadyState FlowOptions::steady() const {
  try {
    return steady_state(make_curve(), degrees_to_radians(angle_deg), h0);
  } catch (const CurveRangeError& e) {
    throw UsageError(std::string("--angle: ") + e.what());
  }
}

void add_flow_options(CLI::App& app, FlowOptions& o, bool add_slope) {
  std::string names;
  for (const auto& n : all_curve_names()) names += (names.empty() ? "" : ",") + n;
  app.add_option("--curve", o.curve, "mu(I) curve {" + names + "}")
      ->check(one_of(all_curve_names()))
      ->capture_default_str();
  if (add_slope) {
    app.add_option("--angle", o.angle_deg, "slope angle zeta [deg], in (0, 90)")
        ->check(open_range(0.0, 90.0))
        ->capture_default_str();
  }
  app.add_option("--h0", o.h0, "flow depth h0 [m], > 0")->check(positive())->capture_default_str();
  Material& m = o.material;
  const std::string g = "Material (table 1)";
  app.add_option("--mu-s", m.mu_s, "static friction mu_s")
      ->check(positive())
      ->group(g)
      ->capture_default_str();
  app.add_option("--mu-d", m.mu_d, "dynamic friction mu_d")
      ->check(positive())
      ->group(g)
      ->capture_default_str();
  app.add_option("--I0", m.I0, "inertial-number scale I0")
      ->check(positive())
      ->group(g)
      ->capture_default_str();
  app.add_option("--d", m.d, "grain diameter d [m]")
      ->check(positive())
      ->group(g)
      ->capture_default_str();
  app.add_option("--phi", m.phi, "solids volume fraction phi, in (0, 1)")
      ->check(open_range(0.0, 1.0))
      ->group(g)
      ->capture_default_str();
  app.add_option("--rho-star", m.rho_star, "grain density [kg/m^3]")
      ->check(positive())
      ->group(g)
      ->capture_default_str();
  app.add_option("--g", m.g, "gravity [m/s^2]")->check(positive())->group(g)->capture_default_str();
  app.add_option("--mu-inf", m.mu_inf, "high-I coefficient mu_inf of (6.3), > 0")
      ->check(positive())
      ->group(g)
      ->capture_default_str();
  app.add_option("--alpha", m.alpha, "low-I regularisation alpha of (5.2)/(6.3), in (0, 2)")
      ->check(open_range(0.0, 2.0))
      ->group(g)
      ->capture_default_str();
  app.add_option("--kk-mu0", m.kk_mu0, "Kamrin-Koval mu_0 of (5.1)")
      ->check(positive())
      ->group(g)
      ->capture_default_str();
  app.add_option("--kk-cK", m.kk_cK, "Kamrin-Koval c_K of (5.1)")
      ->check(positive())
      ->group(g)
      ->capture_default_str();
  app.add_option("--hm-c", m.hm_c, "Holyoake-McElwaine c of (6.1)")
      ->check(positive())
      ->group(g)
      ->capture_default_str();
  // Every curve rises from mu_s to mu_d: with mu_s >= mu_d there is no curve, and the errors
  // would come later, blamed on --angle.
  app.parse_complete_callback([&m] {
    if (!(m.mu_s < m.mu_d)) {
      std::ostringstream msg;
      msg << "--mu-s: value " << m.mu_s << " is not below --mu-d " << m.mu_d
          << "; valid: mu_s < mu_d";
      throw UsageError(msg.str());
    }
  });
}

void add_output_options(CLI::App& app, OutputOptions& o, bool with_plot) {
  app.add_flag("--json", o.json, "print the result as one JSON object on stdout");
  app.add_option("--out", o.out, "write data to this HDF5 file");
  // A name without an extension gets ".png": matplotlib would add it anyway, and the report
  // must name the file that was written.
  if (with_plot)
    app.add_option("--plot", o.plot,
                   "draw the figure into this PNG file (\".png\" added if no extension)")
        ->transform(CLI::Validator(
            [](std::string& path) {
              if (!path.empty() && std::filesystem::path(path).extension().empty()) path += ".png";
              return std::string();
            },
            ""));
  app.add_flag("--quiet", o.quiet, "no progress on stderr");
  // Expanded into options before parsing (config_file.hpp); declared here for --help.
  app.add_option("--config")
      ->description("read options from a TOML file (the command line overrides it)");
}

void add_threads_option(CLI::App& app) {
  app.add_option_function<int>(
         "--threads", [](const int& n) { twod::set_thread_count(n); },
         "threads of the 2D solver, integer >= 1 (default: OMP_NUM_THREADS or all cores)")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            std::size_t used = 0;
            long n = 0;
            try {
              n = std::stol(text, &used);
            } catch (const std::exception&) {
              used = 0;
            }
            if (used == 0 || used != text.size() || n < 1 || n > 1024)
              return "'" + text + "' is not an integer in the valid range [1, 1024]";
            return {};
          },
          "in [1, 1024]", "thread_count"));
}

nlohmann::json number_or_null(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

void print_json(const nlohmann::json& j) {
  std::cout << j.dump(2) << std::endl;
}

void run_plot_script(const std::string& script, const std::string& h5, const std::string& png,
                     const std::string& extra_args) {
  const std::string python = "/usr/bin/python3";
  const std::string cmd = python + " '" + shipped_plot_dir() + "/" + script + "' '" + h5 + "' '" +
                          png + "' " + extra_args;
  if (std::system(cmd.c_str()) != 0)
    throw std::runtime_error("plotting failed (" + cmd +
                             "); needs python3-matplotlib, python3-h5py");
}

ChuteCase FlowOptions::chute(double Lx) const {
  ChuteCase c;
  c.material = material;
  c.curve = curve_kind();
  c.angle_deg = angle_deg;
  c.h0 = h0;
  c.Lx = Lx;
  return c;
}

bool progress_enabled(const OutputOptions& o) {
  return !o.quiet && isatty(STDERR_FILENO);
}

std::string eta_text(double wall_seconds, double t_start, double t, double t_end) {
  if (!(t > t_start) || !(wall_seconds > 0.0)) return "ETA -";
  const long left = std::lround(wall_seconds * (t_end - t) / (t - t_start));
  if (left < 60) return "ETA " + std::to_string(left) + " s";
  if (left < 3600)
    return "ETA " + std::to_string(left / 60) + " min " + std::to_string(left % 60) + " s";
  return "ETA " + std::to_string(left / 3600) + " h " + std::to_string(left % 3600 / 60) + " min";
}

std::string wave_speed_note(const std::optional<WaveSpeed>& w) {
  if (!w) return "(not measured: fewer than 8 samples, or a flat surface)";
  std::ostringstream s;
  s << "(phase speed of Fourier mode " << w->mode
    << " over the last fifth of the run, t = " << w->t_from << " .. " << w->t_to << " s)";
  return s.str();
}

}  // namespace granbench::cli
