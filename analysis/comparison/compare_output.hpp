// compare.h5: both SurfaceSeries, the measurements, the exact theories and the resolved
// configuration of a comparison, as the plot script and later analyses read them.
#pragma once

#include <string>

#include "analysis/comparison/compare.hpp"

namespace granbench {

void write_comparison(const std::string& path, const Comparison& c, const TwodSettings& twod,
                      const DepthAvgSettings& depthavg);

}  // namespace granbench
