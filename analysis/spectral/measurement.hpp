// The one measurement of a SurfaceSeries that every command reports (`run` of either model,
// `compare`, `sweep`): the seeded mode and the other waves at its wavenumber (matrix pencil,
// surface_measurement.hpp), the paper's estimator (7.12) over the same window, ln|h_k| fitted over
// the whole run, and the developed wave (amplitude, and speed: the phase speed of the dominant
// Fourier mode, wave_speed.hpp).
// `to_json` is the one spelling of these results in every command's JSON output.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>

#include "analysis/spectral/spectral_growth.hpp"
#include "analysis/spectral/surface_measurement.hpp"
#include "analysis/spectral/wave_speed.hpp"
#include "common/surface_series.hpp"

namespace granbench {

struct Measurement {
  SurfaceMeasurement spectral;  // the seeded mode (growth_rate, phase_speed), modes, window, reason
  // ln|h_k| fitted over the whole run after the first tenth: robust where the automatic window is
  // not (a beating of two waves at the seeded wavenumber), and the only rate of a saturated run.
  LinearFit whole_run;
  std::optional<double> growth_712;  // (7.12) averaged over the spectral fit's window, if any
  // The wave over the last fifth of the run: its speed (the dominant Fourier mode's phase speed
  // over the last fifth, widened to at least 8 samples; wave_speed.hpp) and whether it has
  // saturated (amplitude steady within 5 % and above 5 % of h0, out of the linear regime), in
  // which case it is the developed rollwave's speed.
  std::optional<WaveSpeed> wave;
  bool saturated = false;
  double final_amplitude = 0.0;  // (max h - min h)/2 at the last sample [m]
};

// Whether the series was long enough for the whole-run fit.
bool whole_run_fitted(const Measurement& m);

// opt.seeded_phase_speed: the phase speed of the model's own theory, which identifies the seeded
// component among the fitted waves.
Measurement measure(const SurfaceSeries& s, const MeasureOptions& opt = {});

// growth_rate, phase_speed (the seeded mode, null where not measured), modes, window [t0, t1],
// reason (null when measured), note, fit_residual, fit_r2, growth_rate_712,
// growth_rate_whole_run, whole_run_r2, wave_speed, wave_speed_spread, wave_mode (the Fourier mode
// followed for wave_speed), saturated, final_amplitude.
nlohmann::json to_json(const Measurement& m);

}  // namespace granbench
