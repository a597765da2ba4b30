// The 2D growth rate from two grids; see twod_extrapolation.hpp.
#include "analysis/comparison/twod_extrapolation.hpp"

#include "analysis/spectral/measurement.hpp"

namespace granbench {

TwodSettings half_cells_across(const TwodSettings& fine) {
  TwodSettings half = fine;
  half.nz = fine.nz / 2;
  return half;
}

double half_grid_cells_per_depth(const TwodSettings& fine, double h0) {
  const TwodSettings half = half_cells_across(fine);
  return h0 / (half.domain_height(h0) / half.nz);
}

TwodExtrapolation run_half_grid(const ChuteCase& c, const TwodSettings& fine,
                                double seeded_phase_speed, const RunControl& ctl) {
  const TwodSettings half = half_cells_across(fine);
  TwodExtrapolation e;
  e.nx = half.nx;
  e.nz = half.nz;
  if (const double n = half_grid_cells_per_depth(fine, c.h0);
      n < kGrowthDeficitFewestCellsPerDepth) {
    e.reason = "half the cells across the layer, " + std::to_string(n) +
               " per h0, lie below the deficit law's range";
    return e;
  }
  const ModelRun r = run_twod(c, half, ctl);
  e.outcome = r.outcome;
  e.wall_seconds = r.wall_seconds;
  e.steps = r.steps;
  if (r.outcome != RunOutcome::Completed) {
    e.reason = "the run on half the cells across the layer stopped: " +
               (r.message.empty() ? std::string(run_status_name(r.outcome)) : r.message);
    return e;
  }
  MeasureOptions opt;
  opt.seeded_phase_speed = seeded_phase_speed;
  const Measurement m = measure(r.series, opt);
  if (!m.spectral.found()) {
    e.reason = "no growth rate on half the cells across the layer: " + m.spectral.reason;
    return e;
  }
  e.growth_rate_half_cells = m.spectral.growth_rate;
  e.dz_ratio = (half.domain_height(c.h0) / half.nz) / (fine.domain_height(c.h0) / fine.nz);
  return e;
}

void extrapolate_from(TwodExtrapolation& e, double fine_growth) {
  if (!e.found()) return;
  if (std::isnan(fine_growth)) {
    e.reason = "no growth rate on the first grid";
    return;
  }
  e.growth = extrapolate_growth_in_dz(fine_growth, e.growth_rate_half_cells, e.dz_ratio);
}

TwodExtrapolation extrapolate_twod_growth(const ChuteCase& c, const TwodSettings& fine,
                                          double fine_growth, double seeded_phase_speed,
                                          const RunControl& ctl) {
  if (std::isnan(fine_growth)) {  // (no run for an extrapolation that cannot be made)
    TwodExtrapolation e;
    e.reason = "no growth rate on the first grid";
    return e;
  }
  TwodExtrapolation e = run_half_grid(c, fine, seeded_phase_speed, ctl);
  extrapolate_from(e, fine_growth);
  return e;
}

}  // namespace granbench
