// Dispersion sweeps over domain length (figure 13): for each Lx and each chosen model, one
// seeded run measured with the same analysis (compare.hpp), beside the exact theories at that
// k_hat. The depth-averaged-only sweep may instead measure each point with the clean linear run
// (analysis/comparison/depthavg_linear_run.hpp: normal mode (7.10), tight tolerances) against
// (7.11).
//
// Points run in parallel on local cores, and may be shared among processes (MPI ranks): point i
// of the list (depthavg points first, then twod) runs on the process with i % ranks == rank.
//
// Resuming. Each finished point is written at once to the process's store (rewritten whole and
// renamed into place, so it is never half-written): the output file itself for one process, the
// part file "<out>.rank<r>.h5" for rank r of several. A sweep reads the completed points of the
// output file and of any part files beside it (an interrupted multi-process run), skips them, and
// at its end writes every point to the output file once and removes the part files. A stored
// sweep whose settings differ from the new one is refused rather than mixed in.
#pragma once

#include <cmath>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "analysis/comparison/compare.hpp"
#include "analysis/comparison/depthavg_linear_run.hpp"

namespace granbench {

struct SweepPoint {
  std::string model;  // "depthavg" or "twod"
  double Lx = 0.0;
  double k_hat = 0.0;
  double growth_rate = 0.0, phase_speed = 0.0;  // measured (spectral)
  double growth_rate_712 = 0.0;                 // (7.12) over the same window (NaN if none)
  double growth_rate_exact = 0.0, phase_speed_exact = 0.0;  // the model's own theory
  Theories theory;                                          // all three theories at this k_hat
  double window_start = 0.0, window_end = 0.0;              // of the spectral fit [s]
  double fit_r2 = 0.0;                                      // of ln|h_k| over the window
  double steps = 0.0;                                       // time steps of the run
  double mass_error = 0.0;                                  // relative
  double wall_seconds = 0.0;                                // of the point's runs
  // The cells of the point's run along x and, for the 2D model, across the layer (NaN: none),
  // which the grid rules choose per length (TwodSettings::cells_along, cells_across)
  double cells_x = NAN, cells_z = NAN;
  // With SweepSpec::twod_extrapolate, a 2D point runs again on half the cells across the layer,
  // and its growth rate is extrapolated to cells of no height (growth_deficit_law.hpp); NaN
  // otherwise.
  double growth_rate_half_cells = NAN;  // measured on half the cells across the layer
  double dz_ratio = NAN;                // their height over the point's
  double growth_rate_extrapolated = NAN;
  double growth_rate_extrapolated_low = NAN, growth_rate_extrapolated_high = NAN;  // its bounds
  bool completed = false;
  bool resumed = false;  // read back from an earlier run (not stored)
  std::string message;   // why a point did not complete, or what its measurement lacks
  // Why growth_rate is NaN (the measurement's reason: no clean window, ...); empty where it has
  // one, and for a point read from a file written before the reasons were stored
  std::string growth_reason;
  // `granbench run ...` that reproduces a seeded point's run (run_command.hpp), also for resumed
  // points (made again from the spec); empty for the depth-averaged linear runs (no `run`
  // equivalent)
  std::string run_command;
};

struct SweepSpec {
  ChuteCase chute;  // Lx is replaced by each point's
  std::vector<double> Lx;
  bool depthavg = true, twod = false;
  DepthAvgSettings depthavg_settings;
  // Set: depth-averaged points are clean linear runs with these parameters, judged against (7.11)
  // with depthavg_settings.chi (depthavg_settings.nx is then unused).
  std::optional<depthavg::LinearRunParams> depthavg_linear;
  TwodSettings twod_settings;
  // Each 2D point also runs on half the cells across the layer, and its growth rate is
  // extrapolated in the cell height with the deficit law's order (growth_deficit_law.hpp): near
  // the 2D cutoff a grid's deficit is a large part of a small growth rate.
  bool twod_extrapolate = false;
  // Set: growth_rate_712 is (7.12) averaged over this fixed window [t0, t1] (the paper's
  // protocol for figure 13: 0.5 s < t < 3 s), not over the spectral fit's window.
  std::optional<std::pair<double, double>> window_712;
  unsigned jobs = 2;
  std::string out;  // HDF5 file; empty: not written, nothing resumed
  // This process's share of the points (MPI ranks): point i runs here if i % ranks == rank.
  int rank = 0, ranks = 1;
};

// The 2D settings of the point of length Lx: the preset's cells along it (cells_along) and across
// the layer for its wavelength, its exact 2D growth rate and the sweep's seed and run length
// (refined_across, which near the cutoff also thins the light layer; NaN: by the wavelength
// alone, the fewest it can have), and the --jobs workers sharing the 2D solver's
// threads (oversubscribed threads wait on each other). The one place a point's grid is made.
TwodSettings point_twod_settings(const SweepSpec& spec, double Lx, double exact_growth);

// The depth-averaged settings of the seeded point of length Lx: the sweep's, with van Albada's
// limiter where the seed, grown at the rate of (7.11) with the sweep's chi, passes the linear
// bound before the run's end (DepthAvgSettings::limited_where_it_saturates).
DepthAvgSettings point_depthavg_settings(const SweepSpec& spec, double Lx);

// Ls from "A:B:N" (N points evenly spaced from A to B inclusive, 0 < A <= B, 1 <= N <= 10000);
// throws std::invalid_argument.
std::vector<double> parse_range(const std::string& text);

struct SweepProgress {
  std::function<void(const SweepPoint&, std::size_t done, std::size_t total)> point_done;
  const std::atomic<bool>* stop = nullptr;
};

// One process: read_finished, run_share, finish_sweep. All points of the spec (resumed ones
// included), sorted by model then Lx.
std::vector<SweepPoint> run_sweep(const SweepSpec& spec, const SweepProgress& progress = {});

// The steps, for a sweep shared among processes:
// the completed points kept in spec.out and its part files (marked resumed); throws
// std::invalid_argument when spec.out holds a sweep with other settings;
std::vector<SweepPoint> read_finished(const SweepSpec& spec);
// this process's share of the points not in `finished`, each kept at once in the process's store
// together with `finished`; returns the points it ran (an exception in one becomes an
// uncompleted point with its message);
std::vector<SweepPoint> run_share(const SweepSpec& spec, const std::vector<SweepPoint>& finished,
                                  const SweepProgress& progress = {});
// all points, sorted, written to spec.out once; the part files removed.
std::vector<SweepPoint> finish_sweep(const SweepSpec& spec, std::vector<SweepPoint> points);

// The store of rank r of several: "<out>.rank<r>.h5".
std::string sweep_part_path(const std::string& out, int rank);
// Points as one array of numbers (the stored columns and texts), to send between processes.
std::vector<double> pack_points(const std::vector<SweepPoint>& points);
std::vector<SweepPoint> unpack_points(std::span<const double> packed);

// The HDF5 file: per model a group of columns (Lx, k_hat, growth_rate, ..., and the text columns
// growth_reason and message); the run settings as the dataset "settings" (names in its attribute
// "names"), and root attributes for the figures; with depthavg points, the exact curve (7.11)
// with the run's chi in the group "curve".
void write_sweep(const std::string& path, const SweepSpec& spec,
                 const std::vector<SweepPoint>& points);
std::vector<SweepPoint> read_sweep(const std::string& path);
// The settings that decide a point's value, by name, stored with the points and compared on
// resume: every option of `granbench sweep` that changes a result lands in one of them
// (tests/analysis/cli/test_sweep_settings.cpp checks that by enumerating the options).
std::vector<std::pair<std::string, double>> stored_settings(const SweepSpec& spec);
// Throws std::invalid_argument naming the first setting in which the sweep stored at `path`
// differs from `spec` (sweep_store.cpp).
void check_stored_settings(const std::string& path, const SweepSpec& spec);

}  // namespace granbench
