// A small RAII wrapper over FFTW's real-to-complex and complex-to-real transforms of one length,
// for the spectral analyses of a SurfaceSeries (surface_measurement, wave_speed). FFTW's planner is
// not thread-safe, so plan creation and destruction are serialised by one mutex (the sweep
// analyses runs in parallel threads); executing a plan is thread-safe.
//
//   forward:  H_m = sum_j h_j exp(-2 pi i j m / n),  m = 0 .. n/2
//   inverse:  h_j = sum_m H_m exp(+2 pi i j m / n)   (unnormalised, as FFTW)
#pragma once

#include <complex>
#include <cstddef>
#include <span>
#include <vector>

namespace granbench {

class RealFFT {
 public:
  explicit RealFFT(std::size_t n);
  ~RealFFT();
  RealFFT(const RealFFT&) = delete;
  RealFFT& operator=(const RealFFT&) = delete;

  std::size_t size() const { return n_; }
  // n/2 + 1 coefficients of the real signal x (size n).
  std::vector<std::complex<double>> forward(std::span<const double> x);
  // Real signal (size n) from n/2 + 1 coefficients; unnormalised.
  std::vector<double> inverse(std::span<const std::complex<double>> X);

 private:
  std::size_t n_;
  double* real_ = nullptr;
  void* spec_ = nullptr;  // fftw_complex*
  void* fwd_ = nullptr;   // fftw_plan
  void* inv_ = nullptr;
};

}  // namespace granbench
