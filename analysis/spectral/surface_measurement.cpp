// Seeded-mode measurement of a SurfaceSeries by a windowed matrix pencil fit; see
// surface_measurement.hpp for the rules.
#include "analysis/spectral/surface_measurement.hpp"

#include <algorithm>
#include <numbers>
#include <optional>
#include <sstream>

#include "analysis/spectral/spectral_growth.hpp"

namespace granbench {

namespace {

std::string format(double v) {
  std::ostringstream s;
  s.precision(3);
  s << v;
  return s.str();
}

// Number of leading samples on the grid t_0 + n dt (rule 1).
std::size_t uniform_prefix(const std::vector<double>& t, double dt) {
  std::size_t n = 1;
  while (n < t.size() && std::fabs(t[n] - t[0] - static_cast<double>(n) * dt) <= 1e-6 * dt) ++n;
  return n;
}

// Index of the component the measurement reports as the seeded mode.
std::size_t seeded_index(const std::vector<WaveMode>& modes, double expected_speed) {
  if (!std::isfinite(expected_speed)) return 0;  // sorted: the largest at the window start
  std::size_t best = 0;
  for (std::size_t j = 1; j < modes.size(); ++j)
    if (std::fabs(modes[j].phase_speed - expected_speed) <
        std::fabs(modes[best].phase_speed - expected_speed))
      best = j;
  return best;
}

struct Window {
  std::size_t first, last;
  std::vector<WaveMode> modes;
  std::size_t seeded;  // index in modes
  PencilFit fit;
};

}  // namespace

SurfaceMeasurement measure_surface_series(const SurfaceSeries& s, const MeasureOptions& opt) {
  SurfaceMeasurement m;
  m.mode = opt.mode;
  m.k = 2.0 * std::numbers::pi * opt.mode / s.Lx;
  const std::size_t n_min =
      std::max(opt.min_samples, pencil_min_samples(std::max(1, opt.pencil.max_components)));
  if (s.nt() < n_min) {
    m.reason = "too short: " + std::to_string(s.nt()) + " samples (need " + std::to_string(n_min) +
               " in the window)";
    return m;
  }
  const auto hk = mode_amplitudes(s, opt.mode);
  // Height amplitude of h_k: a cos(k x) has |h_k| = a nx/2 (a nx at the Nyquist mode).
  const double nx = static_cast<double>(s.nx());
  const double to_height = 2 * static_cast<std::size_t>(opt.mode) == s.nx() ? 1.0 / nx : 2.0 / nx;

  // Rule 1: uniform samples.
  const double dt = s.t[1] - s.t[0];
  if (!(dt > 0.0)) {
    m.reason = "sample times do not increase";
    return m;
  }
  const std::size_t n_uniform = uniform_prefix(s.t, dt);
  if (n_uniform + 1 == s.nt())
    m.note = "the last sample (t = " + format(s.t.back()) +
             " s) is off the sampling grid and was left out";
  else if (n_uniform < s.nt())
    m.note = "samples from t = " + format(s.t[n_uniform]) +
             " s on are off the uniform grid of the first ones and were left out";

  // Rule 2: transient.
  const double t_skip = std::isfinite(opt.transient)
                            ? opt.transient
                            : opt.transient_fraction * (s.t[n_uniform - 1] - s.t[0]);
  std::size_t i0 = 0;
  while (i0 < n_uniform && s.t[i0] < s.t[0] + t_skip - 1e-9 * dt) ++i0;

  // Rule 3: linear regime.
  const double bound = opt.linear_bound * s.h0;
  const bool bounded = bound > 0.0 && std::isfinite(bound);
  std::size_t end = n_uniform;  // one past the last usable sample
  for (std::size_t n = i0; bounded && n < n_uniform; ++n)
    if (to_height * std::abs(hk[n]) > bound) {
      end = n;
      break;
    }
  if (bounded && end == i0 && i0 < n_uniform) {
    m.reason = "the mode's amplitude " + format(to_height * std::abs(hk[i0]) * 1e3) +
               " mm already exceeds the linear bound (" + format(100 * opt.linear_bound) +
               " % of h0) at t = " + format(s.t[i0]) + " s, after the transient";
    return m;
  }
  if (end < i0 + n_min) {
    m.reason = "too short: " + std::to_string(end > i0 ? end - i0 : 0) +
               " samples after the transient (t >= " + format(s.t[0] + t_skip) + " s)" +
               (end < n_uniform ? " before the linear bound is reached" : "") + "; need " +
               std::to_string(n_min);
    return m;
  }

  const std::size_t usable = end - i0;
  const std::size_t end_stride = std::max<std::size_t>(1, usable / 100);
  const std::size_t start_stride = std::max<std::size_t>(1, usable / 20);
  PencilOptions pencil = opt.pencil;
  pencil.target_residual = opt.max_residual;
  auto fit = [&](std::size_t i, std::size_t j) {
    return fit_exponentials(std::span(hk).subspan(i, j - i + 1), dt, pencil);
  };
  auto to_modes = [&](const PencilFit& f) {
    std::vector<WaveMode> modes;
    for (const auto& c : f.components)
      modes.push_back({c.lambda.real(), -c.lambda.imag() / m.k, to_height * std::abs(c.amplitude)});
    return modes;
  };

  // Rule 5: the window spans min_efolds e-folds or min_periods periods of the seeded component.
  auto long_enough = [&](const Window& w) {
    const double T = s.t[w.last] - s.t[w.first];
    const WaveMode& seeded = w.modes[w.seeded];
    return std::fabs(seeded.growth_rate) * T >= opt.min_efolds ||
           std::fabs(m.k * seeded.phase_speed) * T >= 2 * std::numbers::pi * opt.min_periods;
  };

  // Rule 7: the seeded component moves at the expected speed and is not the fit's noise.
  auto holds_seeded_wave = [&](const Window& w) {
    const double expected = opt.seeded_phase_speed;
    if (!std::isfinite(expected)) return true;
    const WaveMode& seeded = w.modes[w.seeded];
    return std::fabs(seeded.phase_speed - expected) <=
               opt.max_speed_mismatch * std::fabs(expected) &&
           seeded.amplitude >= opt.min_seeded_share * w.modes[0].amplitude;
  };

  double best_residual = INFINITY;
  std::size_t best_i = i0, best_j = i0 + n_min - 1;
  std::string short_window, other_waves;
  std::optional<Window> chosen;  // the longest clean window so far (rule 4)
  std::string stall;             // why the search stopped at a stall (rule 6), if it did
  for (std::size_t i = i0; i + n_min <= end; i += start_stride) {
    // A window from here cannot be longer than the one chosen: stop.
    if (chosen && end - 1 - i <= chosen->last - chosen->first) break;
    // Rule 4: from this start, the ends advance until a clean window is long enough (rule 5), and
    // on while the fit stays clean; the first end after that with a larger residual stops them.
    std::optional<Window> w;
    for (std::size_t j = i + n_min - 1;; j = std::min(j + end_stride, end - 1)) {
      PencilFit f = fit(i, j);
      if (f.relative_residual < best_residual) {
        best_residual = f.relative_residual;
        best_i = i;
        best_j = j;
      }
      if (f.relative_residual <= opt.max_residual) {
        Window c{i, j, to_modes(f), 0, std::move(f)};
        c.seeded = seeded_index(c.modes, opt.seeded_phase_speed);
        if (!holds_seeded_wave(c)) {
          if (w) break;  // the extension lost the seeded wave: the window so far stands
          if (other_waves.empty())
            other_waves = "; clean windows such as [" + format(s.t[i]) + ", " + format(s.t[j]) +
                          "] s hold no wave within " + format(100 * opt.max_speed_mismatch) +
                          " % of the seeded speed " + format(opt.seeded_phase_speed) +
                          " m/s with " + format(100 * opt.min_seeded_share) +
                          " % of the largest amplitude (nearest " +
                          format(c.modes[c.seeded].phase_speed) + " m/s at " +
                          format(c.modes[c.seeded].amplitude / c.modes[0].amplitude) +
                          " of it; the largest " + format(c.modes[0].phase_speed) + " m/s at " +
                          format(c.modes[0].growth_rate) + " 1/s)";
        } else if (long_enough(c))
          w = std::move(c);
        else if (!w && short_window.empty())
          short_window = "; clean windows such as [" + format(s.t[i]) + ", " + format(s.t[j]) +
                         "] s span fewer than " + format(opt.min_efolds) + " e-folds and " +
                         format(opt.min_periods) + " periods of the seeded wave";
      } else if (w) {
        break;
      }
      if (j == end - 1) break;  // the stride always ends on the last usable sample
    }
    if (!w) continue;
    const double sigma = w->modes[w->seeded].growth_rate;
    // Rule 6: a stall ends the search; what was found before it stands.
    if (i > i0) {
      const double efolds = std::log(std::abs(hk[i]) / std::abs(hk[i0]));
      const double rate_before = efolds / (s.t[i] - s.t[i0]);
      if (efolds >= 0.5 && sigma < 0.5 * rate_before) {
        stall = "stall: |h_k| grew " + format(efolds) + " e-folds (" + format(rate_before) +
                " 1/s) over [" + format(s.t[i0]) + ", " + format(s.t[i]) +
                "] s without a clean fit, and the first clean window after it, [" + format(s.t[i]) +
                ", " + format(s.t[w->last]) + "] s, grows at only " + format(sigma) + " 1/s";
        break;
      }
    }
    if (!chosen || w->last - w->first > chosen->last - chosen->first) chosen = std::move(w);
  }
  if (chosen) {
    m.modes = chosen->modes;
    m.seeded = chosen->seeded;
    m.growth_rate = m.modes[m.seeded].growth_rate;
    m.phase_speed = m.modes[m.seeded].phase_speed;
    m.first = chosen->first;
    m.last = chosen->last;
    m.t_first = s.t[chosen->first];
    m.t_last = s.t[chosen->last];
    m.relative_residual = chosen->fit.relative_residual;
    m.singular_values = chosen->fit.singular_values;
    std::vector<double> log_amplitude(hk.size());
    for (std::size_t n = chosen->first; n <= chosen->last; ++n)
      log_amplitude[n] = std::log(std::abs(hk[n]));
    m.log_amplitude_r2 = fit_line(s.t, log_amplitude, chosen->first, chosen->last).r2;
    return m;
  }
  if (!stall.empty()) {
    m.reason = stall;
    return m;
  }
  if (!other_waves.empty() && best_residual <= opt.max_residual) {
    m.reason = "the seeded wave is not resolved: after t = " + format(s.t[i0]) + " s" +
               other_waves.substr(1);
    return m;
  }
  m.reason = "no clean window: after t = " + format(s.t[i0]) +
             " s, no window of >= " + std::to_string(n_min) +
             " samples is fitted by <= " + std::to_string(opt.pencil.max_components) +
             " resolved exponentials to a relative residual of " + format(opt.max_residual) +
             " (best: " + format(best_residual) + " over [" + format(s.t[best_i]) + ", " +
             format(s.t[best_j]) + "] s)" + short_window + other_waves;
  return m;
}

}  // namespace granbench
