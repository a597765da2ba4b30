// The text summary of `granbench case` (case_report.hpp).
#include "analysis/cli/case_report.hpp"

#include <algorithm>
#include <cstdio>
#include <iostream>

namespace granbench::cli {

void print_summary(const std::string& kind, const nlohmann::json& j) {
  std::cout << "case " << j.value("case", std::string()) << " (" << kind << ")\n";
  if (j.contains("runs")) {
    std::cout << "  run                 status      t [s]   steps   initial I   final bulk I   "
                 "steady I   "
                 "ill-posed   wall [s]\n";
    for (const auto& r : j["runs"]) {
      auto num = [](const nlohmann::json& v) {
        char b[32];
        if (v.is_null()) return std::string("-");
        std::snprintf(b, sizeof b, "%.4g", v.get<double>());
        return std::string(b);
      };
      char line[256];
      std::snprintf(line, sizeof line, "  %-18s  %-10s  %5.3f  %6ld  %10s  %13s  %9s  %9s  %8.1f\n",
                    r["label"].get<std::string>().c_str(), r["status"].get<std::string>().c_str(),
                    r["t_reached"].get<double>(), r["steps"].get<long>(),
                    num(r["initial_I"]).c_str(), num(r["final_bulk_I"]).c_str(),
                    num(r["steady_I"]).c_str(), num(r["final_illposed_fraction"]).c_str(),
                    r["wall_seconds"].get<double>());
      std::cout << line;
      if (!r["message"].get<std::string>().empty())
        std::cout << "      " << r["message"].get<std::string>() << "\n";
    }
    for (const auto& [pair, d] : j["grid_dependence"].items()) {
      const auto& v = d["rms_log10_I"];
      std::cout << "  grid dependence " << pair << ": rms log10(I) difference";
      for (std::size_t n = 0; n < v.size(); n += std::max<std::size_t>(1, v.size() / 5))
        std::cout << "  t=" << d["t"][n].get<double>() << ": "
                  << (v[n].is_null() ? std::string("-") : std::to_string(v[n].get<double>()));
      std::cout << "  (end: "
                << (v.back().is_null() ? std::string("-") : std::to_string(v.back().get<double>()))
                << ")\n";
      // The comparison that means something: while both grids still flow (grid_dependence.hpp).
      double largest = -1.0, at = 0.0;
      if (d.contains("both_flowing"))
        for (std::size_t n = 0; n < v.size(); ++n)
          if (d["both_flowing"][n].get<bool>() && v[n].is_number() && v[n].get<double>() > largest)
            largest = v[n].get<double>(), at = d["t"][n].get<double>();
      if (largest >= 0.0)
        std::cout << "    largest while both grids flow: " << largest << " at t = " << at << " s\n";
    }
  }
  if (j.contains("run") && j["run"].is_object()) {
    const auto& r = j["run"];
    std::cout << "  status " << r.value("status", std::string("?")) << ", t reached "
              << r.value("t_reached", 0.0) << " s, wall " << r.value("wall_seconds", 0.0) << " s\n";
    for (const char* key : {"growth_rate", "phase_speed", "wave_speed", "wave_mode", "mass_error"})
      if (r.contains(key) && !r[key].is_null())
        std::cout << "  " << key << " " << r[key].dump() << "\n";
  }
  if (j.contains("points")) {  // figure13: growth rates [1/s] per length, beside the theories
    std::cout << "   Lx [m]   k_hat   (7.11)  chi=5/4   2D exact   sine (7.12)  vs 2D   "
                 "eigenmode  vs 2D\n";
    auto num = [](const nlohmann::json& v, const char* format, double scale = 1.0) {
      char b[32];
      if (v.is_null()) return std::string("-");
      std::snprintf(b, sizeof b, format, scale * v.get<double>());
      return std::string(b);
    };
    for (const auto& p : j["points"]) {
      char line[256];
      std::snprintf(line, sizeof line, "  %7.3f  %6.3f  %7.3f  %7.3f  %9.3f  %11s  %6s  %9s  %6s\n",
                    p["Lx"].get<double>(), p["k_hat"].get<double>(), p["exact_711"].get<double>(),
                    p["exact_bagnold"].get<double>(), p["exact_2d"].get<double>(),
                    num(p["sine_712"], "%.3f").c_str(),
                    num(p["sine_712_vs_2d"], "%+.0f%%", 100.0).c_str(),
                    num(p["eigenmode_spectral"], "%.3f").c_str(),
                    num(p["eigenmode_vs_2d"], "%+.0f%%", 100.0).c_str());
      std::cout << line;
    }
  }
  if (j.contains("outputs"))
    for (const auto& f : j["outputs"]) std::cout << "  wrote " << f.get<std::string>() << "\n";
}

}  // namespace granbench::cli
