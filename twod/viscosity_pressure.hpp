// The pressure at which the viscosity of the new time level is evaluated (viscosity_pressure.cpp).
#pragma once

#include <vector>

#include "twod/grid.hpp"
#include "twod/parameters.hpp"

namespace granbench::twod {

// The light fluid's hydrostatic pressure rho_light g cos(zeta) (Lz - z), which the pore fluid
// carries: subtracted from the mixture pressure for mu(I) when Rheology::effective_pressure is
// set (0 otherwise).
double ambient_pressure(const Grid& g, const SolverParams& params, double z);

// p less the ambient pressure at each cell centre: the pressure of the grains' contacts, for
// the viscosity at the present pressure (the solver's start, its further Picard passes and the
// step without the hydrostatic part, SolverParams::hydrostatic_viscosity_pressure = false).
void effective_pressure(const Grid& g, const SolverParams& params, const std::vector<double>& p,
                        std::vector<double>& p_eff);

// p^n plus the change of the hydrostatic pressure between the column heights h^n and h^{n+1}
// (the surface before and after this step's VOF advection), less the ambient pressure.
// Writes p_eta (resized to the cells).
void viscosity_pressure(const Grid& g, const SolverParams& params, const std::vector<double>& p,
                        const std::vector<double>& h_before, const std::vector<double>& h_after,
                        std::vector<double>& p_eta);

// The dynamic part d = p - p_hs(h) of the pressure at the last two time levels, kept to
// extrapolate it to the new level (SolverParams::extrapolate_dynamic_viscosity_pressure).
struct DynamicPressureHistory {
  std::vector<double> older, old;  // d^{n-2}, d^{n-1}
  double t_older = 0.0, t_old = 0.0;
  int levels = 0;  // how many of the two are set
};

// As above, plus the dynamic part extrapolated to t + dt along its slope over two steps,
//   p_eta = p_hs(h^{n+1}) + d^n + dt (d^n - d^{n-2}) / (t^n - t^{n-2}) - p_ambient,
// which is second order and, unlike the slope over one step, does not amplify a pressure that
// alternates from step to step. Shifts the history to level n.
void viscosity_pressure(const Grid& g, const SolverParams& params, const std::vector<double>& p,
                        const std::vector<double>& h_before, const std::vector<double>& h_after,
                        double t, double dt, DynamicPressureHistory& history,
                        std::vector<double>& p_eta);

}  // namespace granbench::twod
