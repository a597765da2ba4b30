// The exact depth-averaged dispersion curve (7.11) with shape factor chi, sampled on a log grid
// of k_hat and written to HDF5 for the figures of `dispersion` and `sweep`: group/k_hat, Lx,
// lambda_hat_re, lambda_hat_im, growth_rate [1/s], phase_speed [m/s].
#pragma once

#include <string>

#include "analysis/theory/dispersion.hpp"
#include "common/hdf5_file.hpp"

namespace granbench {

void write_dispersion_curve(H5Writer& out, const std::string& group, const SteadyState& s,
                            double chi, double k_hat_lo, double k_hat_hi, int samples);

}  // namespace granbench
