// Run loop of the depth-averaged solver: sampling, progress, interruption, divergence detection.
#include "depthavg/solver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <iomanip>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "common/real_fft.hpp"

namespace granbench::depthavg {

namespace {

double mass_of(const std::vector<double>& U, double dx) {
  double m = 0.0;
  for (std::size_t j = 0; 2 * j < U.size(); ++j) m += U[2 * j];
  return m * dx;
}

const char* quantity_name(std::size_t component) {
  return component % 2 == 0 ? "h" : "h*u";
}

// First sign of divergence in U: a non-finite value, a non-positive depth, or a depth beyond
// 100 h0. Empty when the state looks sane.
std::string check_state(const Rhs& rhs, std::span<const double> U, double t) {
  const double h0 = rhs.base().h0;
  for (std::size_t i = 0; i < U.size(); ++i) {
    const bool is_h = i % 2 == 0;
    const bool bad = !std::isfinite(U[i]) || (is_h && (U[i] <= 0.0 || U[i] > 100.0 * h0));
    if (bad) {
      std::ostringstream s;
      s << "diverged at t = " << t << " s, x = " << rhs.x(i / 2) << " m: " << quantity_name(i)
        << " = " << U[i];
      return s.str();
    }
  }
  return {};
}

// Periodic translation of v by `distance` (in units of the period) to the right, exact for the
// grid's Fourier interpolant: coefficient m gains exp(-2 pi i m distance).
void translate(RealFFT& fft, std::vector<double>& v, double distance) {
  auto V = fft.forward(v);
  const double n = static_cast<double>(v.size());
  for (std::size_t m = 0; m < V.size(); ++m)
    V[m] *= std::polar(1.0 / n, -2.0 * std::numbers::pi * static_cast<double>(m) * distance);
  v = fft.inverse(V);
}

// The time the base flow's fastest wave, u + sqrt(g h cos(zeta)) in the lab frame, takes to
// cross a cell. A working integration takes about one step per crossing at the default
// tolerances, a few at the tightest ones; the stall limit below is a thousand per crossing.
double cell_crossing_time(const Rhs& rhs) {
  const SteadyState& b = rhs.base();
  return rhs.dx() / (std::fabs(b.u_mean) + std::sqrt(b.material.g * std::cos(b.zeta) * b.h0));
}
constexpr double kStallStepsPerCrossing = 1000.0;
constexpr long kStallStepsAtLeast = 10000;

}  // namespace

Solver::Solver(const SteadyState& base, const MuCurve& curve, const SpaceParams& space,
               const IntegratorParams& integrator)
    : rhs_(base, curve, space), integrator_(integrator) {}

RunResult Solver::run(const std::vector<double>& U0, const OutputParams& out,
                      const RunCallbacks& cb) const {
  if (U0.size() != rhs_.size()) throw std::invalid_argument("Solver::run: wrong state size");
  if (!(out.dt_out > 0.0) || !(out.t_end > 0.0))
    throw std::invalid_argument("Solver::run: t_end and dt_out must be positive");
  const auto start = std::chrono::steady_clock::now();
  const std::size_t nx = rhs_.nx();
  const double u0 = rhs_.base().u_mean, h0 = rhs_.base().h0;

  // Absolute tolerances per component: atol [m] for h, atol * u0 [m^2/s] for q; h kept positive.
  std::vector<double> scale(2 * nx), positive(2 * nx);
  for (std::size_t j = 0; j < nx; ++j) {
    scale[2 * j] = 1.0;
    scale[2 * j + 1] = u0;
    positive[2 * j] = 1.0;
  }
  CvodeIntegrator integ(rhs_, U0, integrator_, scale, positive);

  RunResult res;
  res.series = SurfaceSeries::uniform_grid(rhs_.space().Lx, nx, h0);
  std::vector<double> h(nx), u(nx);
  RealFFT fft(nx);
  const double c_frame = rhs_.space().frame_speed;
  // Samples are stored in the lab frame: a co-moving solution is translated back by c t.
  auto sample = [&](double t, std::span<const double> U) {
    for (std::size_t j = 0; j < nx; ++j) {
      h[j] = U[2 * j];
      u[j] = rhs_.velocity(U[2 * j], U[2 * j + 1]);
    }
    if (c_frame != 0.0) {
      const double distance = c_frame * t / rhs_.space().Lx;
      translate(fft, h, distance);
      translate(fft, u, distance);
    }
    res.series.append(t, h, u);
  };
  sample(0.0, U0);
  res.mass_initial = mass_of(U0, rhs_.dx());

  const auto n_samples = static_cast<std::size_t>(std::ceil(out.t_end / out.dt_out - 1e-9));
  const double crossing = cell_crossing_time(rhs_);
  try {
    for (std::size_t n = 1; n <= n_samples; ++n) {
      const double t_out = std::min(static_cast<double>(n) * out.dt_out, out.t_end);
      AdvanceLimits limits;
      limits.stop = cb.stop;
      limits.stall_steps = std::max(
          kStallStepsAtLeast,
          static_cast<long>(std::ceil(kStallStepsPerCrossing * (t_out - integ.time()) / crossing)));
      const AdvanceResult adv = integ.advance_to(t_out, limits);
      if (adv.interrupted) {
        res.status = RunStatus::Interrupted;
        res.message = "interrupted at t = " + std::to_string(adv.t) +
                      " s (the last sample at t = " + std::to_string(res.series.t.back()) + " s)";
        break;
      }
      if (!adv.ok) {
        std::ostringstream s;
        s << "diverged at t = " << adv.t << " s: ";
        if (adv.stalled)
          s << "the integration stalled (" << adv.steps
            << " CVODE steps since the sample at t = " << res.series.t.back() << " s, the last of "
            << std::setprecision(3) << adv.last_step << " s, " << adv.last_step / crossing
            << " of the " << crossing
            << " s a wave takes to cross a cell: a front or a dry bed the grid no longer "
               "resolves)"
            << std::setprecision(6);
        else
          s << "CVODE could not continue (" << adv.message << ")";
        s << "; " << (adv.nonfinite ? "non-finite " : "largest local error in ")
          << quantity_name(adv.worst) << " at x = " << rhs_.x(adv.worst / 2) << " m";
        res.status = RunStatus::Diverged;
        res.message = s.str();
        break;
      }
      const std::string bad = check_state(rhs_, integ.state(), adv.t);
      if (!bad.empty()) {
        res.status = RunStatus::Diverged;
        res.message = bad;
        break;
      }
      sample(adv.t, integ.state());
      if (cb.progress) cb.progress(adv.t, out.t_end);
      if (cb.stop && cb.stop->load() && n < n_samples) {
        res.status = RunStatus::Interrupted;
        res.message = "interrupted at t = " + std::to_string(adv.t) + " s";
        break;
      }
    }
  } catch (const std::exception& e) {
    // Whatever fails inside the loop, the samples so far are the caller's to keep.
    res.status = RunStatus::Failed;
    res.message = "failed at t = " + std::to_string(integ.time()) +
                  " s (after the sample at t = " + std::to_string(res.series.t.back()) +
                  " s): " + e.what();
  }

  const auto U = integ.state();
  res.final_state.assign(U.begin(), U.end());
  res.t_reached = integ.time();
  res.mass_final = mass_of(res.final_state, rhs_.dx());
  double q = 0.0;
  for (std::size_t j = 0; j < nx; ++j) q += U[2 * j + 1];
  res.flux_final = q / static_cast<double>(nx);
  res.stats = integ.stats();
  res.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return res;
}

}  // namespace granbench::depthavg
