// compare.h5: both SurfaceSeries, the measurements, the exact theories and the resolved
// configuration of a comparison, as the plot script and later analyses read them.
#pragma once

#include <string>

#include "analysis/comparison/compare.hpp"
#include "common/hdf5_file.hpp"

namespace granbench {

// The resolved configuration of a comparison as root attributes (case, material, both models'
// settings, the base state), shared by compare.h5 and the saturated-wave comparison's file.
void write_compare_configuration(H5Writer& out, const ChuteCase& k, const SteadyState& base,
                                 const TwodSettings& twod, const DepthAvgSettings& depthavg);

void write_comparison(const std::string& path, const Comparison& c, const TwodSettings& twod,
                      const DepthAvgSettings& depthavg);

}  // namespace granbench
