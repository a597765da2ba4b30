// Measurements and exact theories of the comparison; see compare.hpp.
#include "compare.hpp"

#include <algorithm>
#include <cmath>

#include "dispersion.hpp"
#include "growth_estimator_712.hpp"
#include "linear_stability_2d.hpp"
#include "wave_speed.hpp"

namespace granbench {

namespace {

double half_range(std::span<const double> h) {
  const auto [lo, hi] = std::minmax_element(h.begin(), h.end());
  return 0.5 * (*hi - *lo);
}

}  // namespace

Measurement measure(const SurfaceSeries& s, const MeasureOptions& opt) {
  Measurement m;
  m.spectral = measure_surface_series(s, opt);
  if (s.nt() < 3) return m;
  std::vector<double> log_amplitude;
  for (const auto& a : mode_amplitudes(s, opt.mode)) log_amplitude.push_back(std::log(std::abs(a)));
  m.whole_run = fit_line(s.t, log_amplitude, s.nt() / 10, s.nt() - 1);
  if (m.spectral.found()) {
    try {
      m.growth_712 = growth_estimate_712(s, m.spectral.t_first, m.spectral.t_last).growth_rate;
    } catch (const std::invalid_argument&) {
      // (7.12) needs max h > h0 throughout the window; a decaying mode can violate that.
    }
  }
  const std::size_t last = s.nt() - 1;
  m.final_amplitude = half_range(s.h_at(last));
  // Saturated: the amplitude changed by less than 5 % over the last fifth of the run, and the
  // wave is well out of the linear regime (amplitude above 5 % of h0, i.e. 0.2 mm for §7).
  const std::size_t from = last - std::min(last, std::max<std::size_t>(2, s.nt() / 5));
  const double a_from = half_range(s.h_at(from));
  m.saturated = m.final_amplitude > 0.05 * s.h0 &&
                std::fabs(m.final_amplitude - a_from) < 0.05 * m.final_amplitude;
  if (m.saturated) {
    m.wave_speed = wave_speed(s, s.t[from], s.t[last]).speed;
    m.amplitude = m.final_amplitude;
  }
  return m;
}

Theories exact_theories(const ChuteCase& c, bool with_2d) {
  const MuCurve curve = c.make_curve();
  const SteadyState base = steady_state(curve, degrees_to_radians(c.angle_deg), c.h0);
  Theories t;
  const DispersionMode d1 = dispersion_mode(base, 1.0, c.Lx);     // (7.11)
  const DispersionMode d54 = dispersion_mode(base, 1.25, c.Lx);   // chi = 5/4
  t.k_hat = d1.k_hat;
  t.exact = {d1.growth_rate, d1.phase_speed};
  t.exact_bagnold = {d54.growth_rate, d54.phase_speed};
  t.exact_2d = {NAN, NAN};
  t.exact_2d_convergence = NAN;
  if (!with_2d) return t;
  const Linear2DResult lin = linear_stability_2d(base, curve, c.Lx);
  t.exact_2d = {lin.surface.growth_rate, lin.surface.phase_speed};
  t.exact_2d_convergence = lin.surface.relative_difference;
  return t;
}

}  // namespace granbench
