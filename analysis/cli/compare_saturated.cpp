// granbench compare --saturated; see compare_saturated.hpp.
#include "analysis/cli/compare_saturated.hpp"

#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <mutex>
#include <numbers>
#include <stdexcept>

#include "analysis/cli/commands.hpp"
#include "analysis/cli/compare_report.hpp"
#include "analysis/cli/output_checks.hpp"
#include "analysis/cli/physics_warnings.hpp"
#include "analysis/comparison/compare.hpp"
#include "analysis/comparison/saturated_comparison.hpp"
#include "common/failure_policy.hpp"

namespace granbench::cli {

namespace {

// The quantities of the table and of the ratio, by their key in to_json(SaturatedWave), so that
// the table, the JSON and the ratio spell them once.
struct Quantity {
  const char* key;
  const char* label;
  double scale;  // table unit per SI unit
};
constexpr Quantity kQuantities[] = {
    {"amplitude", "amplitude max-min h [mm]", 1e3},    {"max_slope", "steepest |dh/dx| [1]", 1.0},
    {"front_width", "front width 10-90 % [mm]", 1e3},  {"wave_speed", "wave speed [m/s]", 1.0},
    {"mean_flux", "mean flux h u [cm^2/s]", 1e4},      {"mean_depth", "mean depth [mm]", 1e3},
    {"amplitude_spread", "amplitude spread [mm]", 1e3}};

nlohmann::json model_json(const ModelRun& r, const SaturatedWave& w) {
  nlohmann::json j = to_json(w);
  j.update({{"completed", r.outcome == RunOutcome::Completed},
            {"outcome", run_status_name(r.outcome)},
            {"steps", r.steps},
            {"wall_seconds", r.wall_seconds},
            {"mass_error", r.mass_error},
            {"run_command", r.run_command}});
  if (!r.message.empty()) j["message"] = r.message;
  return j;
}

double number(const nlohmann::json& v) {
  return v.is_number() ? v.get<double>() : NAN;
}

// depthavg / twod of each quantity (null where either is not measured).
nlohmann::json ratios(const nlohmann::json& depthavg, const nlohmann::json& twod) {
  nlohmann::json r = nlohmann::json::object();
  for (const Quantity& q : kQuantities)
    r[q.key] = number_or_null(number(depthavg[q.key]) / number(twod[q.key]));
  return r;
}

// The linear theories of the case, whose phase speeds the table shows beside the measured wave
// speeds. A case with no 2D linear surface mode (e.g. --h0 90 at 8 cm) has no wave to saturate
// and would run for hours on a meaningless grid; it is refused before any run, as compare
// refuses it.
Theories linear_theories(const ChuteCase& chute) {
  try {
    return exact_theories(chute);
  } catch (const std::runtime_error& e) {
    const double k_hat = 2.0 * std::numbers::pi * chute.h0 / chute.Lx;
    throw UsageError("--Lx: no 2D linear surface mode to saturate at k_hat = 2 pi h0/Lx = " +
                     std::to_string(k_hat) + " (" + e.what() + "); choose another --Lx or --h0");
  }
}

nlohmann::json theory_json(const Theories& t) {
  return {{"k_hat", t.k_hat},
          {"exact_growth_rate", t.exact.growth_rate},
          {"exact_phase_speed", t.exact.phase_speed},
          {"exact_2d_growth_rate", number_or_null(t.exact_2d.growth_rate)},
          {"exact_2d_phase_speed", number_or_null(t.exact_2d.phase_speed)}};
}

void print_saturated_table(const SaturatedComparison& s, const Theories& theory,
                           const nlohmann::json& depthavg, const nlohmann::json& twod,
                           const nlohmann::json& ratio) {
  const ChuteCase& c = s.chute;
  std::cout << std::fixed << std::setprecision(3) << "granbench compare --saturated: Lx = " << c.Lx
            << " m, angle " << c.angle_deg << " deg, h0 = " << c.h0 * 1e3 << " mm, "
            << curve_name(c.curve) << " curve, " << (c.seed == Seed::Sine ? "sine" : "eigenmode")
            << " start a0 = " << c.a0 * 1e3 << " mm, t_end = " << c.t_end << " s\n"
            << "  measured over the last " << s.window << " s of each run: depthavg t = ["
            << s.depthavg_wave.t_from << ", " << s.depthavg_wave.t_to << "] s, twod t = ["
            << s.twod_wave.t_from << ", " << s.twod_wave.t_to << "] s\n\n"
            << std::left << std::setw(30) << "" << std::right << std::setw(12) << "depthavg"
            << std::setw(12) << "twod" << std::setw(16) << "depthavg/twod"
            << "\n";
  auto cell = [](const nlohmann::json& v, double scale, int width) {
    if (v.is_number())
      std::cout << std::setw(width) << v.get<double>() * scale;
    else
      std::cout << std::setw(width) << "n/a";
  };
  for (const Quantity& q : kQuantities) {
    std::cout << "  " << std::left << std::setw(28) << q.label << std::right;
    cell(depthavg[q.key], q.scale, 12);
    cell(twod[q.key], q.scale, 12);
    cell(ratio[q.key], 1.0, 16);
    std::cout << "\n";
  }
  std::cout << "  linear phase speed [m/s]    " << std::setw(12) << theory.exact.phase_speed
            << std::setw(12) << theory.exact_2d.phase_speed << "   ((7.11) chi = 1; exact 2D)\n";
  for (const auto& [name, j] : {std::pair{"depthavg", &depthavg}, {"twod", &twod}})
    if (!(*j)["reason"].is_null())
      std::cout << "  " << name << ": " << (*j)["reason"].get<std::string>() << "\n";
  std::cout << std::setprecision(1) << "\n  runs: depthavg " << s.depthavg.wall_seconds
            << " s wall (" << s.depthavg.steps << " steps), twod " << s.twod.wall_seconds
            << " s wall (" << s.twod.steps << " steps)\n";
}

}  // namespace

void add_saturated_options(CLI::App& compare, SaturatedOptions& s) {
  compare.add_flag("--saturated", s.enabled,
                   "run both models past saturation and compare the saturated waves (amplitude, "
                   "front steepness and width, speed, flux); defaults: sine start a0 = 0.2 mm, "
                   "--t-end 10, MC limiter in the depth-averaged model");
  compare
      .add_option("--window", s.window,
                  "with --saturated: the measured end of each run [s], in (0, t_end)")
      ->check(positive())
      ->capture_default_str();
  s.t_end = compare.get_option("--t-end");
  s.a0 = compare.get_option("--a0");
  s.init = compare.get_option("--init");
  s.paper = compare.get_option("--paper");
}

void run_compare_saturated(ChuteCase chute, DepthAvgSettings depthavg, const TwodSettings& twod,
                           const OutputOptions& output, const SaturatedOptions& s,
                           const std::vector<std::string>& warnings) {
  const bool paper = s.paper->count() > 0;
  if (s.t_end->count() == 0) chute.t_end = kSaturatedTEnd;
  if (s.a0->count() == 0 && !paper) chute.a0 = kSaturatedA0;
  if (s.init->count() == 0) chute.seed = Seed::Sine;
  if (chute.a0 >= chute.h0) throw UsageError("--a0: must be below h0; valid range (0, h0)");
  if (s.window >= chute.t_end)
    throw UsageError("--window: must be below t_end = " + std::to_string(chute.t_end) +
                     " s; valid range (0, t_end)");
  depthavg.reconstruction = depthavg::Reconstruction::MC;
  const Theories theory = linear_theories(chute);

  const std::string h5 = output.out.empty() ? "compare_saturated.h5" : output.out;
  const std::string png = output.plot.empty() ? "compare_saturated.png" : output.plot;
  require_writable(h5, "--out");
  const auto claim = claim_output(h5, "--out");
  require_writable(png, "--plot");
  if (chute.dt_out > 0.0)
    require_record_count("--dt-out", chute.t_end, chute.dt_out, kMaxSamples, "samples");
  const InterruptGuard guard(InterruptGuard::Signals::IntAndTerm);
  RunControl ctl;
  ctl.stop = guard.flag();
  std::mutex io;
  if (progress_enabled(output))
    ctl.progress = [&, start = std::chrono::steady_clock::now()](const std::string& model, double t,
                                                                 double t_end) {
      const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - start;
      std::lock_guard lock(io);
      std::cerr << "\r  saturated " << model << ": t = " << std::fixed << std::setprecision(2) << t
                << " s, " << eta_text(wall.count(), 0.0, t, t_end) << "    " << std::flush;
    };
  print_warnings(warnings);

  const SaturatedComparison result = compare_saturated(chute, depthavg, twod, s.window, ctl);
  if (ctl.progress) std::cerr << "\n";
  write_saturated_comparison(h5, result, twod, depthavg);
  const bool completed = result.depthavg.outcome == RunOutcome::Completed &&
                         result.twod.outcome == RunOutcome::Completed;
  plot_run("compare_saturated.py", h5, png, "", completed);

  const nlohmann::json d = model_json(result.depthavg, result.depthavg_wave);
  const nlohmann::json t = model_json(result.twod, result.twod_wave);
  const nlohmann::json ratio = ratios(d, t);
  if (output.json) {
    print_json({{"mode", "saturated"},
                {"Lx", chute.Lx},
                {"angle", chute.angle_deg},
                {"h0", chute.h0},
                {"a0", chute.a0},
                {"init", chute.seed == Seed::Sine ? "sine" : "eigenmode"},
                {"t_end", chute.t_end},
                {"window", s.window},
                {"depthavg", d},
                {"twod", t},
                {"ratio", ratio},
                {"theory", theory_json(theory)},
                {"warnings", warnings},
                {"out", h5},
                {"plot", png}});
  } else {
    print_saturated_table(result, theory, d, t, ratio);
    std::cout << "  wrote " << h5 << " and " << png << "\n";
  }
  throw_unless_both_completed(result.depthavg, result.twod, guard, h5);
}

}  // namespace granbench::cli
