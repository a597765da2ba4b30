// What `granbench sweep` reports; see sweep_report.hpp.
#include "analysis/cli/sweep_report.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "analysis/cli/cli_common.hpp"

namespace granbench::cli {

namespace {

nlohmann::json theory_json(const TheoryValue& t) {
  return {{"growth_rate", t.growth_rate}, {"phase_speed", t.phase_speed}};
}

double relative_error(double measured, double exact) {
  return std::fabs(measured - exact) / std::fabs(exact);
}

// The extrapolation of a 2D point (SweepSpec::twod_extrapolate); null where none was asked, a null
// growth rate and the reason where it could not be made.
nlohmann::json extrapolated_json(const SweepPoint& p) {
  if (std::isnan(p.growth_rate_extrapolated)) {
    const auto why = p.message.find("not extrapolated: ");
    if (why == std::string::npos) return nullptr;
    return {{"growth_rate", nullptr}, {"reason", p.message.substr(why + 18)}};
  }
  return {{"growth_rate", p.growth_rate_extrapolated},
          {"growth_rate_bounds", {p.growth_rate_extrapolated_low, p.growth_rate_extrapolated_high}},
          {"growth_relative_error",
           number_or_null(relative_error(p.growth_rate_extrapolated, p.growth_rate_exact))},
          {"growth_rate_half_cells", p.growth_rate_half_cells},
          {"dz_ratio", p.dz_ratio}};
}

// The run's cells: [nx] for the depth-averaged model, [nx, nz] for the 2D one, null where the
// point has none (not run).
nlohmann::json cells_json(const SweepPoint& p) {
  if (std::isnan(p.cells_x)) return nullptr;
  const auto nx = std::lround(p.cells_x);
  return std::isnan(p.cells_z) ? nlohmann::json{nx} : nlohmann::json{nx, std::lround(p.cells_z)};
}

// The same as text for the table: "256", "160x256", or "-".
std::string cells_text(const SweepPoint& p) {
  if (std::isnan(p.cells_x)) return "-";
  std::string t = std::to_string(std::lround(p.cells_x));
  if (!std::isnan(p.cells_z)) t += "x" + std::to_string(std::lround(p.cells_z));
  return t;
}

bool any_extrapolated(const std::vector<SweepPoint>& points) {
  return std::any_of(points.begin(), points.end(),
                     [](const SweepPoint& p) { return !std::isnan(p.growth_rate_extrapolated); });
}

// Why a point has no growth rate: empty (JSON null) where it has one; the measurement's reason
// (kept in the sweep file and sent between processes); the run's failure where it stopped before
// a measurement; otherwise (a point read from a file written before the reasons were stored) a
// note that the reason was not kept.
std::string growth_reason(const SweepPoint& p) {
  if (!std::isnan(p.growth_rate)) return "";
  if (!p.growth_reason.empty()) return p.growth_reason;
  if (!p.message.empty()) return "the run did not complete: " + p.message;
  return std::string(
             "the reason is not kept in a sweep file written before granbench stored it "
             "(") +
         (p.run_command.empty() ? "a sweep of this length alone, without --out, gives it"
                                : "its run_command runs it again") +
         ")";
}

nlohmann::json growth_reason_json(const SweepPoint& p) {
  const std::string why = growth_reason(p);
  return why.empty() ? nlohmann::json(nullptr) : nlohmann::json(why);
}

}  // namespace

nlohmann::json point_json(const SweepPoint& p) {
  return {
      {"model", p.model},
      {"Lx", p.Lx},
      {"k_hat", p.k_hat},
      {"growth_rate", number_or_null(p.growth_rate)},
      {"growth_reason", growth_reason_json(p)},
      {"growth_rate_exact", p.growth_rate_exact},
      {"phase_speed", number_or_null(p.phase_speed)},
      {"phase_speed_exact", p.phase_speed_exact},
      {"growth_relative_error", number_or_null(relative_error(p.growth_rate, p.growth_rate_exact))},
      {"phase_speed_relative_error",
       number_or_null(relative_error(p.phase_speed, p.phase_speed_exact))},
      {"growth_rate_712", number_or_null(p.growth_rate_712)},
      {"extrapolated", extrapolated_json(p)},
      {"exact_711", theory_json(p.theory.exact)},
      {"exact_bagnold", theory_json(p.theory.exact_bagnold)},
      {"exact_2d", theory_json(p.theory.exact_2d)},
      {"window", {number_or_null(p.window_start), number_or_null(p.window_end)}},
      {"fit_r2", number_or_null(p.fit_r2)},
      {"steps", p.steps},
      {"cells", cells_json(p)},
      {"mass_error", number_or_null(p.mass_error)},
      {"wall_seconds", p.wall_seconds},
      {"completed", p.completed},
      {"resumed", p.resumed},
      {"run_command",
       p.run_command.empty() ? nlohmann::json(nullptr) : nlohmann::json(p.run_command)},
      {"status", p.completed         ? "completed"
                 : p.message.empty() ? "unfinished"
                                     : p.message}};
}

void print_table(const std::vector<SweepPoint>& points, const std::string& title) {
  std::cout << title << "\n"
            << std::setw(10) << "model" << std::setw(9) << "Lx [m]" << std::setw(9) << "k_hat"
            << std::setw(12) << "growth" << std::setw(12) << "theory" << std::setw(10) << "rel.err"
            << std::setw(11) << "speed" << std::setw(11) << "theory" << std::setw(10) << "rel.err"
            << std::setw(10) << "cells";
  const bool extrapolated = any_extrapolated(points);
  if (extrapolated)
    std::cout << std::setw(12) << "extrap." << std::setw(10) << "rel.err" << std::setw(22)
              << "bounds";
  std::cout << "\n";
  for (const auto& p : points) {
    std::cout << std::setw(10) << p.model << std::setprecision(4) << std::setw(9) << p.Lx
              << std::setw(9) << p.k_hat << std::setprecision(5) << std::setw(12) << p.growth_rate
              << std::setw(12) << p.growth_rate_exact << std::setprecision(2) << std::setw(10)
              << relative_error(p.growth_rate, p.growth_rate_exact) << std::setprecision(5)
              << std::setw(11) << p.phase_speed << std::setw(11) << p.phase_speed_exact
              << std::setprecision(2) << std::setw(10)
              << relative_error(p.phase_speed, p.phase_speed_exact) << std::setw(10)
              << cells_text(p);
    if (extrapolated && !std::isnan(p.growth_rate_extrapolated)) {
      std::ostringstream bounds;
      bounds << std::setprecision(5) << "[" << p.growth_rate_extrapolated_low << ", "
             << p.growth_rate_extrapolated_high << "]";
      std::cout << std::setprecision(5) << std::setw(12) << p.growth_rate_extrapolated
                << std::setprecision(2) << std::setw(10)
                << relative_error(p.growth_rate_extrapolated, p.growth_rate_exact) << std::setw(22)
                << bounds.str();
    } else if (extrapolated) {
      std::cout << std::setw(12) << "-" << std::setw(10) << "-" << std::setw(22) << "-";
    }
    std::cout << (p.completed ? "" : "  (unfinished)") << (p.resumed ? "  (kept)" : "") << "\n";
  }
  if (extrapolated)
    std::cout << "extrap.: the 2D growth rate extrapolated from this grid and half its cells "
                 "across the layer (order 1.4 in the cell height; bounds: orders 1.7 and 1.3)\n";
  for (const auto& p : points)
    if (const std::string why = growth_reason(p); !why.empty())
      std::cout << std::setprecision(4) << p.model << " at Lx = " << p.Lx
                << " m: growth not measured: " << why << "\n";
}

nlohmann::json sweep_json(const std::vector<SweepPoint>& points, const nlohmann::json& settings,
                          unsigned jobs, int ranks, double wall_seconds) {
  const auto resumed = static_cast<std::size_t>(
      std::count_if(points.begin(), points.end(), [](const SweepPoint& p) { return p.resumed; }));
  double worst = 0.0;  // over the unstable points, against each model's own theory
  double worst_extrapolated = 0.0;
  nlohmann::json list = nlohmann::json::array();
  for (const auto& p : points) {
    if (p.growth_rate_exact > 0.0 && p.completed) {
      worst = std::max(worst, relative_error(p.growth_rate, p.growth_rate_exact));
      if (!std::isnan(p.growth_rate_extrapolated))
        worst_extrapolated = std::max(
            worst_extrapolated, relative_error(p.growth_rate_extrapolated, p.growth_rate_exact));
    }
    list.push_back(point_json(p));
  }
  nlohmann::json j = settings;
  j.update(
      {{"jobs", jobs},
       {"ranks", ranks},
       {"wall_seconds", wall_seconds},
       {"points_run", points.size() - resumed},
       {"points_resumed", resumed},
       {"max_growth_relative_error_unstable", worst},
       {"max_extrapolated_growth_relative_error_unstable",
        any_extrapolated(points) ? nlohmann::json(worst_extrapolated) : nlohmann::json(nullptr)},
       {"points", list}});
  return j;
}

}  // namespace granbench::cli
