// Figure data for the well-posedness analysis; see wellposedness_figures.hpp.
#include "analysis/theory/wellposedness_figures.hpp"

#include <cmath>

namespace granbench {

WellPosednessFigures well_posedness_figures(const MuCurve& curve) {
  WellPosednessFigures f;
  const MuCurve jop(CurveKind::Jop, curve.material());
  constexpr int kN = 800;
  for (int i = 0; i < kN; ++i) {
    const double I = std::pow(10.0, -8.0 + 10.0 * i / (kN - 1));  // 1e-8 .. 1e2
    f.I.push_back(I);
    f.mu.push_back(curve.mu(I));
    f.C.push_back(ill_posedness_C(curve, I));
    f.mu_jop.push_back(jop.mu(I));
    f.C_jop.push_back(ill_posedness_C(jop, I));
  }
  f.analysis = analyse_well_posedness(curve);
  const double sqrt2 = std::sqrt(2.0);
  for (int i = 1; i <= kN; ++i) f.mu_grid.push_back(sqrt2 * i / kN);
  // Figure 2 anchors the neutral curves at the Jop curve's neutral points: the paper takes Jop as
  // correct in its well-posed range and asks which curves may continue it (§4).
  const WellPosedness jop_points = analyse_well_posedness(jop);
  auto fill = [&](std::optional<double> anchor, std::vector<double>& plus,
                  std::vector<double>& minus) {
    if (!anchor) return;
    const double mu_a = jop.mu(*anchor);
    const auto cp = neutral_curve_through(*anchor, mu_a, +1);
    const auto cm = neutral_curve_through(*anchor, mu_a, -1);
    for (double m : f.mu_grid) {
      plus.push_back(cp.I_of_mu(m));
      minus.push_back(cm.I_of_mu(m));
    }
  };
  fill(jop_points.I1N, f.I_plus_low, f.I_minus_low);
  fill(jop_points.I2N, f.I_plus_high, f.I_minus_high);
  if (jop_points.I2N) f.I_max = I_max_from(*jop_points.I2N, jop.mu(*jop_points.I2N));
  return f;
}

void write_well_posedness_figures(H5Writer& out, const WellPosednessFigures& f) {
  out.write("figure1/I", f.I);
  out.write("figure1/mu", f.mu);
  out.write("figure1/C", f.C);
  out.write("figure1/mu_jop", f.mu_jop);
  out.write("figure1/C_jop", f.C_jop);
  out.write("figure2/mu", f.mu_grid);
  if (!f.I_plus_low.empty()) {
    out.write("figure2/I_plus_low", f.I_plus_low);
    out.write("figure2/I_minus_low", f.I_minus_low);
  }
  if (!f.I_plus_high.empty()) {
    out.write("figure2/I_plus_high", f.I_plus_high);
    out.write("figure2/I_minus_high", f.I_minus_high);
  }
  std::vector<double> lo, hi;
  for (auto [a, b] : f.analysis.intervals) {
    lo.push_back(a);
    hi.push_back(b);
  }
  out.write("wellposed/interval_lo", lo);
  out.write("wellposed/interval_hi", hi);
  out.write("wellposed/neutral_points", f.analysis.neutral);
  out.attribute("/", "I1N", f.analysis.I1N.value_or(NAN));
  out.attribute("/", "I2N", f.analysis.I2N.value_or(NAN));
  out.attribute("/", "I_max", f.I_max);
  out.attribute("/", "I_max_wellposed", f.analysis.I_max_wellposed);
}

}  // namespace granbench
