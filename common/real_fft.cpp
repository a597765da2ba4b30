// FFTW wrapper; see real_fft.hpp.
#include "common/real_fft.hpp"

#include <fftw3.h>

#include <algorithm>
#include <mutex>
#include <stdexcept>

namespace granbench {

namespace {
std::mutex& planner_mutex() {
  static std::mutex m;  // FFTW's planner is process-wide state
  return m;
}
}  // namespace

RealFFT::RealFFT(std::size_t n) : n_(n) {
  if (n < 2) throw std::invalid_argument("RealFFT: length must be at least 2");
  std::lock_guard<std::mutex> lock(planner_mutex());
  real_ = fftw_alloc_real(n);
  auto* spec = fftw_alloc_complex(n / 2 + 1);
  spec_ = spec;
  const int len = static_cast<int>(n);
  fwd_ = fftw_plan_dft_r2c_1d(len, real_, spec, FFTW_ESTIMATE);
  if (!fwd_) throw std::runtime_error("RealFFT: FFTW planning failed");
  // The inverse plan waits for the first inverse(): the measurements only go forward, and a
  // process's first complex-to-real plan took 1.2-1.7 ms (docs/performance.md).
}

RealFFT::~RealFFT() {
  std::lock_guard<std::mutex> lock(planner_mutex());
  if (fwd_) fftw_destroy_plan(static_cast<fftw_plan>(fwd_));
  if (inv_) fftw_destroy_plan(static_cast<fftw_plan>(inv_));
  fftw_free(real_);
  fftw_free(spec_);
}

std::vector<std::complex<double>> RealFFT::forward(std::span<const double> x) {
  if (x.size() != n_) throw std::invalid_argument("RealFFT::forward: wrong length");
  std::copy(x.begin(), x.end(), real_);
  fftw_execute(static_cast<fftw_plan>(fwd_));
  const auto* s = static_cast<const fftw_complex*>(spec_);
  std::vector<std::complex<double>> out(n_ / 2 + 1);
  for (std::size_t m = 0; m < out.size(); ++m) out[m] = {s[m][0], s[m][1]};
  return out;
}

std::vector<double> RealFFT::inverse(std::span<const std::complex<double>> X) {
  if (X.size() != n_ / 2 + 1) throw std::invalid_argument("RealFFT::inverse: wrong length");
  auto* s = static_cast<fftw_complex*>(spec_);
  if (!inv_) {
    std::lock_guard<std::mutex> lock(planner_mutex());
    inv_ = fftw_plan_dft_c2r_1d(static_cast<int>(n_), s, real_, FFTW_ESTIMATE);
    if (!inv_) throw std::runtime_error("RealFFT: FFTW planning failed");
  }
  for (std::size_t m = 0; m < X.size(); ++m) {
    s[m][0] = X[m].real();
    s[m][1] = X[m].imag();
  }
  fftw_execute(static_cast<fftw_plan>(inv_));  // c2r overwrites its input; s is scratch
  return {real_, real_ + n_};
}

}  // namespace granbench
