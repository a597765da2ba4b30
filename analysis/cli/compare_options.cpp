// The options of `granbench compare`; see compare_options.hpp.
#include "analysis/cli/compare_options.hpp"

#include "analysis/cli/run_twod.hpp"

namespace granbench::cli {

void add_compare_options(CLI::App& sub, CompareOptions& o) {
  sub.add_option("--Lx", o.Lx, "domain length = wavelength [m], > 0")
      ->check(positive())
      ->capture_default_str();
  sub.add_option("--a0", o.a0, "initial amplitude of h [m], in (0, h0)")
      ->check(positive())
      ->capture_default_str();
  sub.add_flag("--paper", o.paper, "the paper's start: sine (7.2) with a0 = 0.2 mm");
  sub.add_option("--init", o.init, "initial perturbation {eigenmode,sine}")
      ->check(one_of({"eigenmode", "sine"}))
      ->capture_default_str();
  sub.add_option("--t-end", o.t_end, "simulated time [s], > 0")
      ->check(positive())
      ->capture_default_str();
  sub.add_option("--dt-out", o.dt_out, "sampling interval [s], > 0 (default: automatic)")
      ->check(positive());
  sub.add_option("--resolution", o.resolution,
                 "grids at Lx = 8 cm {coarse: 80x32 / 128, default: 160x64 / 256, fine: 320x128 / "
                 "512}; at another Lx, at least these 2D cells along x and at most their dx, and " +
                     twod_refinement_help())
      ->check(one_of({"coarse", "default", "fine"}))
      ->capture_default_str();
  // The ranges of `run` (cmd_run.cpp, twod_options.cpp); the product is capped in run_compare.
  sub.add_option("--nx", o.nx, "2D cells along x (overrides --resolution), in [8, 65536]")
      ->check(count_range(8, 65536));
  sub.add_option("--nz", o.nz,
                 "2D cells across Lz ~ 2 h0 (overrides --resolution and its refinement for short "
                 "waves), in [4, 4096]")
      ->check(count_range(4, 4096));
  sub.add_option("--nx-depthavg", o.nx_depthavg,
                 "depth-averaged cells (overrides --resolution), in [8, 1048576]")
      ->check(count_range(8, 1 << 20));
  sub.add_option("--frame-speed", o.frame_speed,
                 "depth-averaged model's frame {linear,0}: moving at the (7.11) phase speed, or "
                 "the lab frame; output is in the lab frame")
      ->check(one_of({"linear", "0"}))
      ->capture_default_str();
  sub.add_option("--twod-frame", o.twod_frame,
                 "2D grid's speed as a fraction of the steady surface speed, in [0, 1]; 0.5 about "
                 "halves the steps, 0 is the lab frame; output is in the lab frame either way")
      ->check(closed_range(0.0, 1.0))
      ->capture_default_str();
  add_twod_cfl_option(sub, o.cfl);
  sub.add_flag("--extrapolate", o.extrapolate,
               "run the 2D model again on half the cells across the layer and report its growth "
               "rate extrapolated to cells of no height (the measured order 1.4, bounds from "
               "orders 1.3 and 1.7)");
  sub.add_option("--viscosity-passes", o.viscosity_passes,
                 "2D predictor-projection passes per step, eta from the previous pass, in [1, 4] "
                 "(1 is second order in time already; more passes cost n times as much)")
      ->check(count_range(1, 4))
      ->capture_default_str();
}

}  // namespace granbench::cli
