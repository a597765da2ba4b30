// Steady uniform (Bagnold) flow and the depth-averaged coefficients; see steady_state.hpp.
#include "common/steady_state.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "common/ill_posedness.hpp"

namespace granbench {

double degrees_to_radians(double deg) {
  return deg * std::numbers::pi / 180.0;
}

SteadyState steady_state(const MuCurve& curve, double zeta, double h0) {
  const Material& m = curve.material();
  SteadyState s;
  s.material = m;
  s.zeta = zeta;
  s.h0 = h0;
  const double tan_zeta = std::tan(zeta);
  try {
    s.I_zeta = curve.inverse(tan_zeta);  // mu(I_zeta) = tan(zeta), §5.2
  } catch (const CurveRangeError&) {
    std::ostringstream msg;
    const double deg = 180.0 / std::numbers::pi;
    msg << "no steady uniform flow at angle " << zeta * deg << " deg for the "
        << curve_name(curve.kind()) << " curve; valid range (" << std::atan(curve.mu_min()) * deg
        << ", " << std::atan(curve.mu_max()) * deg << ") deg";
    throw CurveRangeError(msg.str());
  }
  const double c = std::cos(zeta);
  const double root = std::sqrt(m.phi * m.g * c);
  s.u_surface = 2.0 * s.I_zeta / (3.0 * m.d) * root * std::pow(h0, 1.5);  // (5.5) at z = h0
  s.u_mean = 2.0 * s.I_zeta / (5.0 * m.d) * root * std::pow(h0, 1.5);     // §7, u_bar_0
  s.Fr = s.u_mean / std::sqrt(m.g * h0 * c);                              // (7.1)
  s.Gamma = s.I_zeta * curve.dmu_dI(s.I_zeta);                            // (7.9a), DESIGN §4
  s.gamma = m.I0 / s.I_zeta;                                              // (7.9b) = I0/I_zeta
  s.nu = 5.0 * m.d * std::sqrt(m.g) * std::sin(zeta) /
         (9.0 * s.I_zeta * std::sqrt(m.phi * c));  // (7.5), DESIGN §4
  s.R = s.u_mean * std::sqrt(h0) / s.nu;           // (7.6)
  s.C = ill_posedness_C(curve.mu(s.I_zeta), s.I_zeta * curve.dmu_dI(s.I_zeta));  // (3.9)
  s.well_posed = s.C <= 0.0;
  return s;
}

double SteadyState::pressure(double z) const {
  const double depth = std::max(h0 - z, 0.0);
  return material.bulk_density() * material.g * depth * std::cos(zeta);  // (5.4)
}

double SteadyState::velocity(double z) const {
  return velocity_at_depth(z, h0);
}

double SteadyState::velocity_at_depth(double z, double h) const {
  const double zc = std::clamp(z, 0.0, h);
  const double pref =
      2.0 * I_zeta / (3.0 * material.d) * std::sqrt(material.phi * material.g * std::cos(zeta));
  return pref * (std::pow(h, 1.5) - std::pow(h - zc, 1.5));  // (5.5)
}

double SteadyState::mean_velocity_at_depth(double h) const {
  return 2.0 * I_zeta / (5.0 * material.d) * std::sqrt(material.phi * material.g * std::cos(zeta)) *
         std::pow(h, 1.5);
}

double depth_averaged_inertial_number(const Material& m, double zeta, double h, double u_bar) {
  return 5.0 * m.d * u_bar / (2.0 * std::pow(h, 1.5) * std::sqrt(m.phi * m.g * std::cos(zeta)));
}

}  // namespace granbench
