// The saturated wave's amplitude, front, speed and flux; see saturated_wave.hpp.
#include "analysis/spectral/saturated_wave.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "analysis/spectral/wave_speed.hpp"

namespace granbench {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::size_t wrap(long j, std::size_t n) {
  const long m = static_cast<long>(n);
  return static_cast<std::size_t>(((j % m) + m) % m);
}

// The vertex of the parabola through (-1, ym), (0, y0), (1, yp): its offset from 0 (in [-1/2,
// 1/2] when y0 is the discrete extreme) and its value. Exact for a quadratic, so the refined
// extreme of a smooth profile is off by O(dx^3) where the discrete one is off by O(dx^2).
struct Vertex {
  double offset, value;
};
Vertex parabola_vertex(double ym, double y0, double yp) {
  const double curvature = ym - 2.0 * y0 + yp;
  if (curvature == 0.0) return {0.0, y0};
  const double offset = std::clamp(0.5 * (ym - yp) / curvature, -0.5, 0.5);
  return {offset, y0 - 0.25 * (ym - yp) * offset};
}

// The largest value of sign * v on the periodic grid (sign = -1: the smallest, negated): its
// cell and the refined vertex near it.
struct Extreme {
  std::size_t index;
  Vertex vertex;
};
Extreme periodic_extreme(std::span<const double> v, double sign) {
  const std::size_t n = v.size();
  std::size_t best = 0;
  for (std::size_t j = 1; j < n; ++j)
    if (sign * v[j] > sign * v[best]) best = j;
  return {best, parabola_vertex(sign * v[wrap(long(best) - 1, n)], sign * v[best],
                                sign * v[wrap(long(best) + 1, n)])};
}

// Where h crosses `level`, walking from cell i + start in steps of dir (+1 or -1) until h is at
// or below the level (below = true) or at or above it; linear interpolation between the last two
// cells. Positions are relative to cell i [cells]; NaN if the level is never reached.
double crossing(std::span<const double> h, std::size_t i, long start, long dir, double level,
                bool below) {
  const std::size_t n = h.size();
  for (long m = 0; m <= static_cast<long>(n); ++m) {
    const long off = start + dir * m;
    const double v = h[wrap(long(i) + off, n)];
    if (below ? v > level : v < level) continue;
    if (m == 0) return static_cast<double>(off);
    const double prev = h[wrap(long(i) + off - dir, n)];
    return static_cast<double>(off - dir) + static_cast<double>(dir) * (level - prev) / (v - prev);
  }
  return kNaN;
}

// Front width: the distance over which h rises from 10 % to 90 % of the wave's amplitude (max h -
// min h of the whole profile) across the steepest front, between cells a = i and b = i + 1. Why
// these levels: the 0 % and 100 % points of a smooth front are where it meets the flat layer
// ahead of it and the crest behind it, and both move a long way with a small change of those
// (a tanh front never reaches them); the 10-90 % points sit on the front itself, so the width is
// a property of the front (2 atanh(0.8) w = 2.197 w for h ~ tanh(x/w)), and of a discontinuity
// resolved on a grid it is under one cell. The levels are those of the whole wave rather than of
// the nearest local extremes, because short ripples riding on the layer ahead of and behind a 2D
// front (docs/paper-cases.md) make local extremes that would stop the walk a cell or two from the
// front.
double front_width(std::span<const double> h, std::size_t i, double slope_sign, double lo,
                   double hi, double dx) {
  const double low = lo + 0.1 * (hi - lo), high = lo + 0.9 * (hi - lo);
  // slope < 0: cell a is the high one and the low side is +x; slope > 0: the other way round.
  // The walk towards the low side starts at the high cell, the walk towards the high side at the
  // low cell, so each passes through the front.
  const double x_low =
      slope_sign < 0.0 ? crossing(h, i, 0, +1, low, true) : crossing(h, i, 1, -1, low, true);
  const double x_high =
      slope_sign < 0.0 ? crossing(h, i, 1, -1, high, false) : crossing(h, i, 0, +1, high, false);
  return std::fabs(x_low - x_high) * dx;
}

struct MeanSpread {
  double mean = kNaN, spread = kNaN;
};
MeanSpread mean_spread(const std::vector<double>& v) {
  std::vector<double> ok;
  for (double x : v)
    if (std::isfinite(x)) ok.push_back(x);
  if (ok.empty()) return {};
  MeanSpread r{0.0, 0.0};
  for (double x : ok) r.mean += x / static_cast<double>(ok.size());
  for (double x : ok) r.spread += (x - r.mean) * (x - r.mean) / static_cast<double>(ok.size());
  r.spread = std::sqrt(r.spread);
  return r;
}

nlohmann::json finite_or_null(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

}  // namespace

ProfileShape measure_profile(std::span<const double> h, double Lx) {
  const std::size_t n = h.size();
  if (n < 4) throw std::invalid_argument("measure_profile: need at least 4 cells");
  const double dx = Lx / static_cast<double>(n);
  ProfileShape p;
  const double hi = periodic_extreme(h, +1.0).vertex.value;
  const double lo = -periodic_extreme(h, -1.0).vertex.value;
  p.amplitude = hi - lo;
  // face j + 1/2 carries (h_{j+1} - h_j)/dx
  std::vector<double> slope(n), magnitude(n);
  for (std::size_t j = 0; j < n; ++j) {
    slope[j] = (h[wrap(long(j) + 1, n)] - h[j]) / dx;
    magnitude[j] = std::fabs(slope[j]);
  }
  const Extreme steep = periodic_extreme(magnitude, +1.0);
  const std::size_t i = steep.index;
  p.max_slope = steep.vertex.value;
  p.front_sign = slope[i] < 0.0 ? -1.0 : 1.0;
  // face i + 1/2 is at x = (i + 1) dx
  p.front_position = std::fmod((double(i) + 1.0 + steep.vertex.offset) * dx + Lx, Lx);
  p.front_width = p.amplitude > 0.0 ? front_width(h, i, p.front_sign, lo, hi, dx) : kNaN;
  return p;
}

SaturatedWave measure_saturated_wave(const SurfaceSeries& s, double t_from, double t_to) {
  if (s.nx() < 4) throw std::invalid_argument("measure_saturated_wave: need at least 4 cells");
  std::size_t n0 = s.nt(), n1 = 0;
  for (std::size_t n = 0; n < s.nt(); ++n)
    if (s.t[n] >= t_from && s.t[n] <= t_to) {
      n0 = std::min(n0, n);
      n1 = n;
    }
  if (n0 == s.nt())
    throw std::invalid_argument("measure_saturated_wave: no sample in the window [" +
                                std::to_string(t_from) + ", " + std::to_string(t_to) + "] s");
  SaturatedWave w;
  w.t_from = s.t[n0];
  w.t_to = s.t[n1];
  w.samples = n1 - n0 + 1;
  std::vector<double> amplitude, slope, width;
  for (std::size_t n = 0; n < s.nt(); ++n) {
    const ProfileShape p = measure_profile(s.h_at(n), s.Lx);
    w.amplitude_history.push_back(p.amplitude);
    if (n < n0 || n > n1) continue;
    amplitude.push_back(p.amplitude);
    slope.push_back(p.max_slope);
    width.push_back(p.front_width);
  }
  const MeanSpread a = mean_spread(amplitude);
  w.amplitude = a.mean;
  w.amplitude_spread = a.spread;
  w.max_slope = mean_spread(slope).mean;
  w.front_width = mean_spread(width).mean;
  if (!std::isfinite(w.front_width)) w.reason += "no front (flat profile); ";

  if (!(w.amplitude > 0.0)) {
    w.wave_speed = kNaN;  // a flat surface has no phase to follow
  } else if (w.samples >= 2) {
    try {
      const WaveSpeed c = wave_speed(s, w.t_from, w.t_to);  // the samples n0 .. n1
      w.wave_speed = c.speed;
      w.speed_mode = c.mode;
    } catch (const std::invalid_argument&) {
      w.wave_speed = kNaN;  // flat to round-off
      w.reason += "no wave to follow for the speed (flat to round-off); ";
    }
  } else {
    w.wave_speed = kNaN;
    w.reason += "wave speed needs two samples in the window; ";
  }

  double depth = 0.0, flux = 0.0;
  const bool has_u = s.u_mean.size() == s.h.size();
  for (std::size_t n = n0; n <= n1; ++n) {
    const auto h = s.h_at(n);
    for (std::size_t j = 0; j < s.nx(); ++j) {
      depth += h[j];
      if (has_u) flux += h[j] * s.u_at(n)[j];
    }
  }
  const double count = static_cast<double>(w.samples * s.nx());
  w.mean_depth = depth / count;
  w.mean_flux = has_u ? flux / count : kNaN;
  if (!has_u) w.reason += "no depth-averaged velocity in the series (no flux); ";
  if (!w.reason.empty()) w.reason.erase(w.reason.size() - 2);

  // The last sample in the wave's frame.
  const auto h = s.h_at(n1);
  const double x_front = measure_profile(h, s.Lx).front_position;
  std::vector<std::pair<double, double>> frame;
  for (std::size_t j = 0; j < s.nx(); ++j) {
    double xi = std::fmod(s.x[j] - x_front, s.Lx);
    if (xi < -0.5 * s.Lx) xi += s.Lx;
    if (xi >= 0.5 * s.Lx) xi -= s.Lx;
    frame.emplace_back(xi, h[j]);
  }
  std::sort(frame.begin(), frame.end());
  for (const auto& [xi, hj] : frame) {
    w.xi.push_back(xi);
    w.h_frame.push_back(hj);
  }
  return w;
}

nlohmann::json to_json(const SaturatedWave& w) {
  return {{"t_from", w.t_from},
          {"t_to", w.t_to},
          {"samples", w.samples},
          {"amplitude", finite_or_null(w.amplitude)},
          {"amplitude_spread", finite_or_null(w.amplitude_spread)},
          {"max_slope", finite_or_null(w.max_slope)},
          {"front_width", finite_or_null(w.front_width)},
          {"wave_speed", finite_or_null(w.wave_speed)},
          {"speed_mode", w.speed_mode},
          {"mean_flux", finite_or_null(w.mean_flux)},
          {"mean_depth", finite_or_null(w.mean_depth)},
          {"reason", w.reason.empty() ? nlohmann::json(nullptr) : nlohmann::json(w.reason)}};
}

}  // namespace granbench
