// Speed of a developed (nonlinear) travelling wave in a SurfaceSeries: the phase speed of its
// dominant Fourier component, the one wave speed of the project (`run`'s and `sweep`'s
// wave_speed, measurement.hpp, and `compare --saturated`'s and the rollwave case's, in
// saturated_wave.hpp, are this function).
//
// With H_m(t_n) the m-th Fourier coefficient of h(x, t_n) on the periodic grid, the followed mode
// m is the one of largest mean |H_m| over the window (1 <= m < nx/2; the Nyquist mode has no
// phase). Each pair of successive samples turns its phase by
//
//   dphi_n = arg(H_m(t_{n+1}) conj(H_m(t_n))),   c_n = -dphi_n / (k_m (t_{n+1} - t_n)),
//
// c_n being the pair's speed and k_m = 2 pi m / Lx; and the speed is the whole window's turn over
// its duration, c = -sum_n dphi_n / (k_m (t_last - t_first)): the time-weighted mean of the c_n.
// For a rigid translation h(x - c t) of a resolved profile every coefficient turns by exactly -k_m
// c dt, so the speed is exact (round-off), with no model of the shape and no sub-cell
// interpolation.
//
// Limit: dphi_n is taken in (-pi, pi], so each sample step must move the followed mode by less
// than half its wavelength, |c| dt < Lx / (2 m); a faster wave aliases to a wrong speed.
//
// Why not the cross-correlation of successive snapshots (the method used before): the peak of
// C(s) = sum_j h'_n(x_j) h'_{n+1}(x_{j+s}) weighs every component of the surface. The saturated 2D
// 12 cm rollwave (the paper's §7, 10 s, 240 cells, a sample every 6.9 ms) carries short components
// (modes 3-6) that change shape and move slowly between samples; they pulled the broad
// correlation peak to ~7 of the ~15 cells the wave moves per sample, and the reported speed was
// 0.55 m/s where the fundamental and the crest travel at 1.07-1.09 m/s.
#pragma once

#include <cstddef>
#include <vector>

#include "common/surface_series.hpp"

namespace granbench {

struct WaveSpeed {
  double speed = 0.0;   // the window's phase turn over its duration [m/s]
  double spread = 0.0;  // standard deviation of per_pair [m/s]
  int mode = 0;         // the Fourier mode followed (1: the fundamental, wavelength Lx)
  std::size_t pairs = 0;
  double t_from = 0.0, t_to = 0.0;  // the first and last samples used [s]
  std::vector<double> per_pair;     // speed of each pair of successive samples, in time order
};

// Uses the samples with t in [t_from, t_to]. Throws std::invalid_argument for fewer than 3 cells,
// fewer than two samples in the window, or a flat surface (no phase to follow).
WaveSpeed wave_speed(const SurfaceSeries& s, double t_from, double t_to);

}  // namespace granbench
