// Data of the paper's well-posedness figures for any curve, next to the Jop curve (2.12):
//   figure 1/7  mu(I) and C(I) (3.9) over I, with the neutral points and well-posed intervals;
//   figure 2    the neutral curves I_pm^N(mu) (4.3) through the lower (a) and upper (b) neutral
//               points, and I_max (§4).
#pragma once

#include <vector>

#include "common/hdf5_file.hpp"
#include "common/mu_curves.hpp"
#include "common/neutral_points.hpp"

namespace granbench {

struct WellPosednessFigures {
  std::vector<double> I;              // log-spaced grid
  std::vector<double> mu, C;          // chosen curve
  std::vector<double> mu_jop, C_jop;  // Jop curve, same material
  // Neutral curves through the lower (I1N) and upper (I2N) neutral points of the Jop curve:
  // mu grid in (0, sqrt(2)] and I_+^N(mu), I_-^N(mu).
  std::vector<double> mu_grid;
  std::vector<double> I_plus_low, I_minus_low, I_plus_high, I_minus_high;
  WellPosedness analysis;
  double I_max = 0.0;  // §4 bound from Jop's upper neutral point
};

WellPosednessFigures well_posedness_figures(const MuCurve& curve);
void write_well_posedness_figures(H5Writer& out, const WellPosednessFigures& f);

}  // namespace granbench
