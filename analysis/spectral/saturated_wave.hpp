// The shape, speed and flux of a saturated periodic wave in a SurfaceSeries, the same numbers for
// either model, so that the paper's closing claim (§7, §8: depth-averaged rollwaves have fronts
// much steeper than observed, the 2D waves a rounder shape) can be measured on both.
//
// Over the samples of a window [t_from, t_to] (the saturated end of a run):
//   amplitude    max h - min h of each profile, the extremes refined below one cell by a parabola
//                through the discrete extreme and its two neighbours; mean over the window.
//   max_slope    the largest |dh/dx| of each profile: the face differences (h_{j+1} - h_j)/dx are
//                second-order estimates at the faces, and a parabola through the largest and its
//                two neighbours gives the peak between faces; mean over the window.
//   front_width  the x-distance over which h rises from 10 % to 90 % of the amplitude across the
//                steepest front, with the crossings interpolated linearly between cells; mean over
//                the window (see front_width in saturated_wave.cpp for why these levels).
//   wave_speed   the phase speed of the profile's dominant Fourier component, its phase turn
//                summed from sample to sample over the whole window (wave_speed.hpp, the same
//                speed `run` reports); speed_mode is the mode followed.
//   mean_flux    the depth-integrated volume flux q = h u_mean per unit width, averaged over x and
//                over the window's samples [m^2/s]; NaN when the series has no u_mean.
// and the wave shape in the wave's frame at the last sample of the window: xi = x - x_front,
// wrapped into [-Lx/2, Lx/2) and sorted, with the steepest point of the front at xi = 0.
#pragma once

#include <cstddef>
#include <limits>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <vector>

#include "common/surface_series.hpp"

namespace granbench {

// One profile h_j = h((j + 1/2) dx) on a periodic grid of length Lx.
struct ProfileShape {
  double amplitude = 0.0;       // max h - min h [m]
  double max_slope = 0.0;       // largest |dh/dx| [1]
  double front_position = 0.0;  // x of the steepest point, in [0, Lx) [m]
  double front_sign = 0.0;      // sign of dh/dx there: -1 for a front facing +x (rollwave)
  double front_width = 0.0;     // 10 % to 90 % rise distance across that front [m]; NaN if none
};
ProfileShape measure_profile(std::span<const double> h, double Lx);

struct SaturatedWave {
  double t_from = 0.0, t_to = 0.0;  // the samples used [s]
  std::size_t samples = 0;
  double amplitude = 0.0;           // [m]
  double amplitude_spread = 0.0;    // standard deviation over the window [m]
  double max_slope = 0.0;           // [1]
  double front_width = 0.0;         // [m]
  double wave_speed = 0.0;          // [m/s]; NaN with fewer than two samples or a flat surface
  int speed_mode = 0;               // the Fourier mode followed for the speed (1: fundamental)
  double mean_flux = 0.0;           // [m^2/s]; NaN without u_mean
  double mean_depth = 0.0;          // mean h over x and the window [m]
  std::vector<double> xi, h_frame;  // last sample in the wave frame [m]
  std::vector<double> amplitude_history;  // max h - min h at every sample of the series [m]
  std::string reason;                     // why a quantity is NaN; empty when all were measured
};

// Throws std::invalid_argument for a series of fewer than 4 cells or with no sample in the window.
SaturatedWave measure_saturated_wave(const SurfaceSeries& s, double t_from,
                                     double t_to = std::numeric_limits<double>::infinity());

// The one spelling of these results in JSON (null for NaN): t_from, t_to, samples, amplitude,
// amplitude_spread, max_slope, front_width, wave_speed, speed_mode, mean_flux, mean_depth, reason.
nlohmann::json to_json(const SaturatedWave& w);

}  // namespace granbench
