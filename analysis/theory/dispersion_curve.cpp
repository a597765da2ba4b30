// Sampling and writing the exact dispersion curve; see dispersion_curve.hpp.
#include "analysis/theory/dispersion_curve.hpp"

#include <cmath>
#include <vector>

namespace granbench {

void write_dispersion_curve(H5Writer& out, const std::string& group, const SteadyState& s,
                            double chi, double k_hat_lo, double k_hat_hi, int samples) {
  std::vector<double> k_hat, Lx, lam_re, lam_im, growth, speed;
  for (int i = 0; i < samples; ++i) {
    const double k = k_hat_lo * std::pow(k_hat_hi / k_hat_lo, i / (samples - 1.0));
    const DispersionMode m = dispersion_mode(s, chi, Lx_from_k_hat(s, k));  // (7.11), (7.13)
    k_hat.push_back(k);
    Lx.push_back(m.Lx);
    lam_re.push_back(m.lambda_hat.real());
    lam_im.push_back(m.lambda_hat.imag());
    growth.push_back(m.growth_rate);
    speed.push_back(m.phase_speed);
  }
  out.write(group + "/k_hat", k_hat);
  out.write(group + "/Lx", Lx);
  out.write(group + "/lambda_hat_re", lam_re);
  out.write(group + "/lambda_hat_im", lam_im);
  out.write(group + "/growth_rate", growth);
  out.write(group + "/phase_speed", speed);
}

}  // namespace granbench
