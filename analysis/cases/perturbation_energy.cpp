// The perturbation measure E(t) of a uniform-layer run and its exponential growth rate
// (perturbation_energy.hpp).
#include "analysis/cases/perturbation_energy.hpp"

#include <cmath>
#include <limits>
#include <sstream>

namespace granbench::cases {

std::vector<double> perturbation_energy(const LayerRunRecord& run, double h0) {
  std::vector<double> E;
  const std::size_t nx = run.nx;
  for (const auto& field : run.I_field) {
    double sum = 0.0;
    std::size_t cells = 0;
    for (int k = 0; k < run.nz && run.z[k] <= 0.8 * h0; ++k) {
      const double* row = &field[std::size_t(k) * nx];
      double mean = 0.0;
      bool grains = true;  // every cell of the row holds grains (I finite and positive)
      for (std::size_t i = 0; i < nx && grains; ++i) {
        grains = std::isfinite(row[i]) && row[i] > 0.0;
        mean += row[i];
      }
      if (!grains) continue;
      mean /= double(nx);
      for (std::size_t i = 0; i < nx; ++i) sum += std::pow((row[i] - mean) / mean, 2);
      cells += nx;
    }
    E.push_back(cells ? sum / double(cells) : std::numeric_limits<double>::quiet_NaN());
  }
  return E;
}

EnergyGrowth energy_growth(const std::vector<double>& t, const std::vector<double>& E, double from,
                           double to) {
  EnergyGrowth g;
  std::size_t first = 0;
  while (first < E.size() && !(E[first] >= from)) ++first;
  if (first == E.size()) {
    std::ostringstream why;
    why << "E never reaches " << from << ": no growth out of the noise";
    g.reason = why.str();
    return g;
  }
  std::size_t last = first;  // one past the window
  while (last < E.size() && E[last] >= from && E[last] <= to) ++last;
  const std::size_t n = last - first;
  if (n < 4) {
    std::ostringstream why;
    why << "only " << n << " samples between E = " << from << " and " << to;
    g.reason = why.str();
    return g;
  }
  double st = 0.0, sy = 0.0, stt = 0.0, sty = 0.0;
  for (std::size_t j = first; j < last; ++j) {
    const double y = std::log(E[j]);
    st += t[j];
    sy += y;
    stt += t[j] * t[j];
    sty += t[j] * y;
  }
  g.rate = (n * sty - st * sy) / (n * stt - st * st);
  g.t_from = t[first];
  g.t_to = t[last - 1];
  g.samples = int(n);
  return g;
}

}  // namespace granbench::cases
