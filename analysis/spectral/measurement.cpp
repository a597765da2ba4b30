// The measurement every command reports; see measurement.hpp.
#include "analysis/spectral/measurement.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "analysis/spectral/growth_estimator_712.hpp"

namespace granbench {

namespace {

double half_range(std::span<const double> h) {
  const auto [lo, hi] = std::minmax_element(h.begin(), h.end());
  return 0.5 * (*hi - *lo);
}

nlohmann::json number_or_null(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

}  // namespace

bool whole_run_fitted(const Measurement& m) {
  return m.whole_run.last > m.whole_run.first;
}

Measurement measure(const SurfaceSeries& s, const MeasureOptions& opt) {
  Measurement m;
  m.spectral = measure_surface_series(s, opt);
  if (s.nt() < 3) return m;
  std::vector<double> log_amplitude;
  for (const auto& a : mode_amplitudes(s, opt.mode)) log_amplitude.push_back(std::log(std::abs(a)));
  m.whole_run = fit_line(s.t, log_amplitude, s.nt() / 10, s.nt() - 1);
  if (m.spectral.found()) {
    try {
      m.growth_712 = growth_estimate_712(s, m.spectral.t_first, m.spectral.t_last).growth_rate;
    } catch (const std::invalid_argument&) {
      // (7.12) needs max h > h0 throughout the window; a decaying mode can violate that.
    }
  }
  const std::size_t last = s.nt() - 1;
  m.final_amplitude = half_range(s.h_at(last));
  // Saturated: the amplitude changed by less than 5 % over the last fifth of the run, and the
  // wave is well out of the linear regime (amplitude above 5 % of h0, i.e. 0.2 mm for §7).
  const std::size_t from = last - std::min(last, std::max<std::size_t>(2, s.nt() / 5));
  const double a_from = half_range(s.h_at(from));
  m.saturated = m.final_amplitude > 0.05 * s.h0 &&
                std::fabs(m.final_amplitude - a_from) < 0.05 * m.final_amplitude;
  // The speed (the dominant Fourier mode's phase speed) over the same fifth, widened to 8 samples
  // (7 pairs) for a short run.
  const std::size_t wave_from = last - std::min(last, std::max<std::size_t>(7, s.nt() / 5));
  if (last - wave_from >= 7) {
    try {
      m.wave = wave_speed(s, s.t[wave_from], s.t[last]);
    } catch (const std::invalid_argument&) {
      // a flat surface has no wave to follow
    }
  }
  return m;
}

nlohmann::json to_json(const Measurement& m) {
  const SurfaceMeasurement& sp = m.spectral;
  nlohmann::json modes = nlohmann::json::array();
  for (const WaveMode& w : sp.modes)
    modes.push_back({{"growth_rate", number_or_null(w.growth_rate)},
                     {"phase_speed", number_or_null(w.phase_speed)},
                     {"amplitude", number_or_null(w.amplitude)}});
  return {
      {"growth_rate", number_or_null(sp.growth_rate)},
      {"phase_speed", number_or_null(sp.phase_speed)},
      {"modes", modes},
      {"window", sp.found() ? nlohmann::json{sp.t_first, sp.t_last} : nlohmann::json(nullptr)},
      {"reason", sp.found() ? nlohmann::json(nullptr) : nlohmann::json(sp.reason)},
      {"note", sp.note},
      {"fit_residual", number_or_null(sp.relative_residual)},
      {"fit_r2", number_or_null(sp.log_amplitude_r2)},
      {"growth_rate_712", m.growth_712 ? number_or_null(*m.growth_712) : nullptr},
      {"growth_rate_whole_run", whole_run_fitted(m) ? number_or_null(m.whole_run.slope) : nullptr},
      {"whole_run_r2", whole_run_fitted(m) ? number_or_null(m.whole_run.r2) : nullptr},
      {"wave_speed", m.wave ? number_or_null(m.wave->speed) : nullptr},
      {"wave_speed_spread", m.wave ? number_or_null(m.wave->spread) : nullptr},
      {"wave_mode", m.wave ? nlohmann::json(m.wave->mode) : nullptr},
      {"saturated", m.saturated},
      {"final_amplitude", m.final_amplitude}};
}

}  // namespace granbench
