// Dispersion sweeps over domain length (figure 13): for each Lx and each chosen model, one
// seeded run measured with the same analysis (compare.hpp), beside the exact theories at that
// k_hat. Points run in parallel on local cores; each finished point is written at once to the
// output file (rewritten whole and renamed into place, so it is never half-written), and a
// re-run with the same output file skips the points it already holds (resumable).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "compare.hpp"

namespace granbench {

struct SweepPoint {
  std::string model;             // "depthavg" or "twod"
  double Lx = 0.0;
  double k_hat = 0.0;
  double growth_rate = 0.0, phase_speed = 0.0;    // measured (spectral)
  double growth_rate_712 = 0.0;                   // (7.12) over the same window (NaN if none)
  double growth_rate_exact = 0.0, phase_speed_exact = 0.0;  // the model's own theory
  Theories theory;               // all three theories at this k_hat
  double wall_seconds = 0.0;
  bool completed = false;
  std::string message;
};

struct SweepSpec {
  ChuteCase chute;               // Lx is replaced by each point's
  std::vector<double> Lx;
  bool depthavg = true, twod = false;
  DepthAvgSettings depthavg_settings;
  TwodSettings twod_settings;
  unsigned jobs = 2;
  std::string out;               // HDF5 file; empty: not written, nothing resumed
  // This process's share of the points (MPI ranks): point i runs here if i % ranks == rank.
  int rank = 0, ranks = 1;
};

// Ls from "A:B:N" (N points evenly spaced from A to B inclusive); throws std::invalid_argument.
std::vector<double> parse_range(const std::string& text);

struct SweepProgress {
  std::function<void(const SweepPoint&, std::size_t done, std::size_t total)> point_done;
  const std::atomic<bool>* stop = nullptr;
};

// All points of the spec (resumed ones included), sorted by model then Lx.
std::vector<SweepPoint> run_sweep(const SweepSpec& spec, const SweepProgress& progress = {});

void write_sweep(const std::string& path, const SweepSpec& spec,
                 const std::vector<SweepPoint>& points);
std::vector<SweepPoint> read_sweep(const std::string& path);

}  // namespace granbench
