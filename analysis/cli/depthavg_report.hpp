// What `granbench run --model depthavg` measures and prints (depthavg_report.cpp).
#pragma once

#include <nlohmann/json.hpp>
#include <optional>

#include "growth_estimator_712.hpp"
#include "run_model.hpp"
#include "surface_measurement.hpp"
#include "surface_series.hpp"
#include "wave_speed.hpp"

namespace granbench::cli {

struct DepthAvgMeasured {
  SurfaceMeasurement growth;  // the seeded mode; a reason instead when there is no clean window
  std::optional<Estimate712> e712;
  std::optional<WaveSpeed> wave;
};

// The seeded mode is the component nearest the (7.11) phase speed; a saturated wave (e.g. (7.2)
// at Lx = 8 cm, which saturates within 0.3 s) has no clean linear window and gives a reason.
DepthAvgMeasured measure_depthavg(const SurfaceSeries& s, int mode, double expected_speed);

// The table (or, with --json, the JSON `j`) of a depth-averaged run on stdout.
void print_depthavg_run(const RunOptions& o, const nlohmann::json& j, const DepthAvgMeasured& m);

}  // namespace granbench::cli
