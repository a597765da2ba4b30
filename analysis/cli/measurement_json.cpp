// JSON of a seeded-mode measurement; see measurement_json.hpp.
#include "measurement_json.hpp"

#include "cli_common.hpp"

namespace granbench::cli {

nlohmann::json modes_json(const SurfaceMeasurement& m) {
  nlohmann::json list = nlohmann::json::array();
  for (const WaveMode& w : m.modes)
    list.push_back({{"growth_rate", number_or_null(w.growth_rate)},
                    {"phase_speed", number_or_null(w.phase_speed)},
                    {"amplitude", number_or_null(w.amplitude)}});
  return list;
}

nlohmann::json window_json(const SurfaceMeasurement& m) {
  return m.found() ? nlohmann::json{m.t_first, m.t_last} : nlohmann::json(nullptr);
}

}  // namespace granbench::cli
