// The table of dataset units and names; see dataset_units.hpp.
#include "common/dataset_units.hpp"

#include <map>
#include <utility>

namespace granbench {

namespace {

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// Exact paths first: the same short name means different things in different places.
const std::map<std::string, DatasetDoc>& by_path() {
  static const std::map<std::string, DatasetDoc> t = {
      {"/settings", {"mixed", "settings of the sweep, one per name in the attribute 'names'"}},
      {"/profile/z", {"m", "height above the base"}},
      {"/profile/u", {"m/s", "steady downslope velocity u(z)"}},
      {"/profile/p", {"Pa", "steady pressure p(z)"}},
      {"/figure2/mu", {"1", "friction coefficient mu"}},
      {"/snapshots/x_nodes", {"m", "cell-node coordinates along the slope"}},
      {"/snapshots/z_nodes", {"m", "cell-node coordinates normal to the slope"}},
      {"/snapshots/xz_nodes", {"m", "(x, z) of every cell node, [nz+1][nx+1][2], x fastest"}},
      {"/state/u", {"m/s", "downslope velocity on the cell faces"}},
      {"/state/w", {"m/s", "slope-normal velocity on the cell faces"}},
      {"/state/p", {"Pa", "pressure at the cell centres"}},
      {"/state/f", {"1", "granular volume fraction of each cell"}},
      {"/state/t", {"s", "time of the checkpoint"}},
      {"/state/steps", {"1", "time steps taken"}},
      {"/state/dt_last", {"s", "last time step"}},
      {"/state/initial_volume", {"m^2", "granular volume per unit width at t = 0"}},
      {"/state/nx", {"1", "cells along the slope"}},
      {"/state/nz", {"1", "cells normal to the slope"}},
      {"/state/Lx", {"m", "domain length"}},
      {"/state/Lz", {"m", "domain height"}},
      {"/warm_start/viscous_dt", {"s", "time step of the stored viscous increment"}},
      {"/warm_start/previous_dt", {"s", "previous time step"}},
      {"/warm_start/viscous_increment", {"m/s", "last viscous velocity increment (solver start)"}},
      {"/warm_start/pressure_increment",
       {"Pa s", "last pressure increment times dt (solver start)"}},
      {"/warm_start/advection_u", {"m/s^2", "last downslope advection term (solver start)"}},
      {"/warm_start/advection_w", {"m/s^2", "last slope-normal advection term (solver start)"}},
      {"/warm_start/increment_u",
       {"m/s", "last downslope non-advective velocity increment (BDF2 memory)"}},
      {"/warm_start/increment_w",
       {"m/s", "last slope-normal non-advective velocity increment (BDF2 memory)"}},
      {"/warm_start/previous_u", {"m/s", "previous level's downslope velocity (mid-step option)"}},
      {"/warm_start/previous_w",
       {"m/s", "previous level's slope-normal velocity (mid-step option)"}},
  };
  return t;
}

// Then the last component of the path.
const std::map<std::string, DatasetDoc>& by_name() {
  static const std::map<std::string, DatasetDoc> t = {
      {"x", {"m", "position along the slope (cell centres)"}},
      {"z", {"m", "height above the base"}},
      {"t", {"s", "time"}},
      {"h", {"m", "flow depth h(x, t)"}},
      {"u_mean", {"m/s", "depth-averaged downslope velocity"}},
      {"u", {"m/s", "downslope velocity at the cell centres"}},
      {"w", {"m/s", "slope-normal velocity at the cell centres"}},
      {"velocity", {"m/s", "velocity (u, w, 0) at the cell centres, [nz][nx][3]"}},
      {"p", {"Pa", "pressure at the cell centres"}},
      {"f", {"1", "granular volume fraction of each cell (1 grains, 0 light fluid)"}},
      {"I", {"1", "inertial number; NaN where p <= 0"}},
      {"eta", {"Pa s", "viscosity at the cell centres"}},
      {"C", {"1", "well-posedness coefficient C(I), ill posed where negative; NaN where p <= 0"}},
      {"mu", {"1", "friction coefficient mu(I)"}},
      {"mu_jop", {"1", "friction coefficient of the Jop curve"}},
      {"C_jop", {"1", "well-posedness coefficient C(I) of the Jop curve"}},
      {"I_plus_low", {"1", "upper inertial number of the ill-posed band, low-I branch"}},
      {"I_minus_low", {"1", "lower inertial number of the ill-posed band, low-I branch"}},
      {"I_plus_high", {"1", "upper inertial number of the ill-posed band, high-I branch"}},
      {"I_minus_high", {"1", "lower inertial number of the ill-posed band, high-I branch"}},
      {"interval_lo", {"1", "lower inertial number of each well-posed interval"}},
      {"interval_hi", {"1", "upper inertial number of each well-posed interval"}},
      {"neutral_points", {"1", "inertial numbers where C(I) = 0"}},
      {"u_profile", {"m/s", "downslope velocity profile u(z, t)"}},
      {"I_profile", {"1", "inertial-number profile I(z, t); NaN where p <= 0"}},
      {"I_field", {"1", "inertial number I(x, z, t); NaN where p <= 0"}},
      {"xz_nodes", {"m", "(x, z) of every cell node, [nz+1][nx+1][2], x fastest"}},
      {"max_speed", {"m/s", "largest speed in the domain"}},
      {"illposed_fraction", {"1", "fraction of granular cells where the flow is ill posed"}},
      {"rms_log10_I", {"1", "root-mean-square of log10 I over the layer"}},
      {"both_flowing", {"1", "1 where both runs still flow (some bulk row's mean |u| > 1e-3 m/s)"}},
      {"Lx", {"m", "domain length (one wavelength)"}},
      {"k_hat", {"1", "dimensionless wavenumber 2 pi h0 / Lx"}},
      {"lambda_hat_re", {"1", "dimensionless growth rate Re(lambda) h0 / u_mean"}},
      {"lambda_hat_im", {"1", "dimensionless frequency Im(lambda) h0 / u_mean"}},
      {"u_re", {"1", "real part of the eigenfunction u (arbitrary scale)"}},
      {"u_im", {"1", "imaginary part of the eigenfunction u (arbitrary scale)"}},
      {"w_re", {"1", "real part of the eigenfunction w (arbitrary scale)"}},
      {"w_im", {"1", "imaginary part of the eigenfunction w (arbitrary scale)"}},
      {"p_re", {"1", "real part of the eigenfunction p (arbitrary scale)"}},
      {"p_im", {"1", "imaginary part of the eigenfunction p (arbitrary scale)"}},
      {"modes",
       {"mixed",
        "fitted waves, rows of (growth rate [1/s], phase speed [m/s], "
        "amplitude at the window start [m])"}},
      {"window_start", {"s", "start of the fit window"}},
      {"window_end", {"s", "end of the fit window"}},
      {"fit_r2", {"1", "R^2 of the fit of ln|h_k| over the window"}},
      {"steps", {"1", "time steps of the run"}},
      {"mass_error", {"1", "relative change of the granular mass"}},
      {"wall_seconds", {"s", "wall-clock time of the run"}},
      {"completed", {"1", "1 where the point completed, 0 where not"}},
      {"growth_rate_712", {"1/s", "growth rate by the estimator (7.12) over the fit window"}},
      {"growth_rate_half_cells",
       {"1/s", "2D growth rate on half the cells across the layer (sweep --extrapolate)"}},
      {"dz_ratio", {"1", "cell height of the half grid over the point's (sweep --extrapolate)"}},
      {"growth_rate_extrapolated",
       {"1/s", "2D growth rate extrapolated to cells of no height, order 1.4 (NaN: not asked)"}},
      {"growth_rate_extrapolated_low",
       {"1/s", "lower bound of the extrapolation (orders 1.3 and 1.7)"}},
      {"growth_rate_extrapolated_high",
       {"1/s", "upper bound of the extrapolation (orders 1.3 and 1.7)"}},
      {"cells_x", {"1", "cells of the point's run along x"}},
      {"cells_z", {"1", "cells of the point's 2D run across the layer (NaN: depth-averaged)"}},
      {"growth_reason", {"text", "why the point has no growth rate (empty where it has one)"}},
      {"message", {"text", "why the point's run did not complete, or what it lacks (empty: none)"}},
  };
  return t;
}

}  // namespace

std::optional<DatasetDoc> dataset_doc(const std::string& path) {
  const std::string full = path.empty() || path[0] == '/' ? path : "/" + path;
  if (const auto it = by_path().find(full); it != by_path().end()) return it->second;
  const std::string name = full.substr(full.rfind('/') + 1);
  if (const auto it = by_name().find(name); it != by_name().end()) return it->second;
  // Measured and theoretical rates and speeds of every model: *_growth_rate, *_phase_speed.
  if (ends_with(name, "growth_rate") || ends_with(name, "growth_rate_exact"))
    return DatasetDoc{"1/s", "growth rate (" + name + ")"};
  if (ends_with(name, "phase_speed") || ends_with(name, "phase_speed_exact"))
    return DatasetDoc{"m/s", "phase speed (" + name + ")"};
  return std::nullopt;
}

}  // namespace granbench
