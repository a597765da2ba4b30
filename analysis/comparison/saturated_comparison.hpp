// The saturated rollwave in both models: the same chute case run with both models past
// saturation, and each wave measured by the same code (analysis/spectral/saturated_wave.hpp) over
// the same window at the end of the run, to measure the paper's closing claim (§7-§8): the
// depth-averaged waves have fronts much steeper than those observed, the 2D waves a rounder shape.
#pragma once

#include <string>

#include "analysis/comparison/chute_case.hpp"
#include "analysis/comparison/model_runs.hpp"
#include "analysis/spectral/saturated_wave.hpp"

namespace granbench {

struct SaturatedComparison {
  ChuteCase chute;
  SteadyState base;
  double window = 0.0;  // the measured end of each run [s]
  ModelRun depthavg, twod;
  SaturatedWave depthavg_wave, twod_wave;
};

// Measures a run over [t_last - window, t_last] of its own series, so that a run that stopped
// early is measured over the end of what it computed. Throws std::invalid_argument for an empty
// series.
SaturatedWave measure_run_end(const ModelRun& r, double window);

// Both models on c at once (run_both), each measured over the last `window` seconds.
SaturatedComparison compare_saturated(const ChuteCase& c, const DepthAvgSettings& depthavg,
                                      const TwodSettings& twod, double window,
                                      const RunControl& ctl = {});

// The output file: per model (groups depthavg/ and twod/) the SurfaceSeries, the measurement as
// attributes, the wave shape in the wave's frame (wave_frame/xi, wave_frame/h) and the amplitude
// at every sample (amplitude); the configuration as root attributes (compare_output.hpp).
void write_saturated_comparison(const std::string& path, const SaturatedComparison& s,
                                const TwodSettings& twod, const DepthAvgSettings& depthavg);

}  // namespace granbench
