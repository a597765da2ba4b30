// The JSON of a seeded-mode measurement (surface_measurement.hpp), written the same way by
// `granbench run` (both models) and `granbench compare`:
//   modes:  [{growth_rate [1/s], phase_speed [m/s], amplitude [m at the window start]}, ...],
//           every wave fitted at the seeded wavenumber, largest amplitude first; [] when none.
// A measurement without a clean window gives nulls, never a number (its reason is reported
// beside them by the caller).
#pragma once

#include <nlohmann/json.hpp>

#include "surface_measurement.hpp"

namespace granbench::cli {

nlohmann::json modes_json(const SurfaceMeasurement& m);
// [t_first, t_last] of the fit, or null.
nlohmann::json window_json(const SurfaceMeasurement& m);

}  // namespace granbench::cli
