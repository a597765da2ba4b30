// The sweep's HDF5 file and the points' trip between processes; see sweep.hpp.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "analysis/comparison/sweep.hpp"
#include "analysis/theory/dispersion_curve.hpp"
#include "common/hdf5_file.hpp"

namespace granbench {

std::vector<std::pair<std::string, double>> stored_settings(const SweepSpec& s) {
  const Material& m = s.chute.material;
  const ChuteCase& c = s.chute;
  std::vector<std::pair<std::string, double>> v = {{"curve", static_cast<double>(c.curve)},
                                                   {"angle_deg", c.angle_deg},
                                                   {"h0", c.h0},
                                                   {"depthavg_chi", s.depthavg_settings.chi}};
  for (const MaterialConstant& k : material_constants) v.emplace_back(k.key, m.*k.value);
  if (s.depthavg_linear) {
    const depthavg::LinearRunParams& l = *s.depthavg_linear;
    v.insert(v.end(), {{"linear_nx", static_cast<double>(l.nx)},
                       {"linear_tolerance", l.tolerance},
                       {"linear_amplitude", l.amplitude},
                       {"linear_t_end", l.t_end},
                       {"linear_reconstruction", static_cast<double>(l.reconstruction)},
                       {"linear_co_moving", l.co_moving ? 1.0 : 0.0}});
  } else {
    v.insert(v.end(),
             {{"a0", c.a0},
              {"seed", static_cast<double>(c.seed)},
              {"t_end", c.t_end},
              {"dt_out", c.dt_out},
              {"depthavg_nx", static_cast<double>(s.depthavg_settings.nx)},
              {"depthavg_limiter", static_cast<double>(s.depthavg_settings.reconstruction)},
              {"depthavg_rtol", s.depthavg_settings.rtol},
              {"depthavg_co_moving", s.depthavg_settings.co_moving ? 1.0 : 0.0}});
    if (s.window_712)
      v.insert(v.end(), {{"window_712_start", s.window_712->first},
                         {"window_712_end", s.window_712->second}});
    for (const auto& [name, value] : named_values(s.twod_settings))
      v.emplace_back("twod_" + name, value);
    // (stored only when set: a sweep without it resumes the files written before it existed)
    if (s.twod_extrapolate) v.emplace_back("twod_extrapolate", 1.0);
    // Seeded depth-averaged points limit their slopes where their wave saturates
    // (point_depthavg_settings); a file written before that rule may hold such points with
    // central slopes, so it lacks this and is not resumed.
    if (s.depthavg) v.emplace_back("depthavg_limited_where_saturating", 1.0);
  }
  return v;
}

namespace {
// Column names of the per-point table in the HDF5 file, in this order.
const char* const kColumns[] = {"Lx",
                                "k_hat",
                                "growth_rate",
                                "phase_speed",
                                "growth_rate_712",
                                "growth_rate_exact",
                                "phase_speed_exact",
                                "exact_growth_rate",
                                "exact_phase_speed",
                                "exact_bagnold_growth_rate",
                                "exact_bagnold_phase_speed",
                                "exact_2d_growth_rate",
                                "exact_2d_phase_speed",
                                "window_start",
                                "window_end",
                                "fit_r2",
                                "steps",
                                "mass_error",
                                "wall_seconds",
                                "growth_rate_half_cells",
                                "dz_ratio",
                                "growth_rate_extrapolated",
                                "growth_rate_extrapolated_low",
                                "growth_rate_extrapolated_high",
                                "cells_x",
                                "cells_z",
                                "completed"};
constexpr std::size_t kWidth = std::size(kColumns);

// The stored numbers of a point, in column order (`completed` last, as 0 or 1).
std::vector<double*> fields(SweepPoint& p) {
  return {&p.Lx,
          &p.k_hat,
          &p.growth_rate,
          &p.phase_speed,
          &p.growth_rate_712,
          &p.growth_rate_exact,
          &p.phase_speed_exact,
          &p.theory.exact.growth_rate,
          &p.theory.exact.phase_speed,
          &p.theory.exact_bagnold.growth_rate,
          &p.theory.exact_bagnold.phase_speed,
          &p.theory.exact_2d.growth_rate,
          &p.theory.exact_2d.phase_speed,
          &p.window_start,
          &p.window_end,
          &p.fit_r2,
          &p.steps,
          &p.mass_error,
          &p.wall_seconds,
          &p.growth_rate_half_cells,
          &p.dz_ratio,
          &p.growth_rate_extrapolated,
          &p.growth_rate_extrapolated_low,
          &p.growth_rate_extrapolated_high,
          &p.cells_x,
          &p.cells_z};
}
std::vector<double> row(SweepPoint p) {
  std::vector<double> r;
  for (const double* f : fields(p)) r.push_back(*f);
  r.push_back(p.completed ? 1.0 : 0.0);
  return r;
}
// The stored text of a point, by column name: why it has no growth rate, why it did not complete.
const char* const kTextColumns[] = {"growth_reason", "message"};
std::vector<std::string*> texts(SweepPoint& p) {
  return {&p.growth_reason, &p.message};
}

SweepPoint from_row(const std::string& model, std::span<const double> r) {
  SweepPoint p;
  p.model = model;
  std::size_t c = 0;
  for (double* f : fields(p)) *f = r[c++];
  p.completed = r[c] != 0.0;
  p.theory.k_hat = p.k_hat;
  return p;
}
}  // namespace

// Throws std::invalid_argument naming the first setting in which the stored sweep differs. The
// settings are matched by name, so a file without one (written before it was stored) is refused
// by that name rather than resumed with whatever value it was computed with.
void check_stored_settings(const std::string& path, const SweepSpec& spec) {
  const auto want = stored_settings(spec);
  if (!h5_has(path, "settings"))
    throw std::invalid_argument(path +
                                " is not a sweep file (it has no stored settings); remove "
                                "it or choose another file");
  const std::vector<double> have = h5_read_doubles(path, "settings");
  std::vector<std::string> names;
  std::istringstream list(h5_read_string_attribute(path, "settings", "names"));
  for (std::string n; std::getline(list, n, ',');) names.push_back(n);
  std::string differs = names.size() != have.size() ? "the names of its settings" : "";
  for (std::size_t i = 0; differs.empty() && i < want.size(); ++i) {
    const auto at = std::find(names.begin(), names.end(), want[i].first);
    std::ostringstream s;
    if (at == names.end())
      s << want[i].first << " not stored there, " << want[i].second << " here";
    else if (const double v = have[static_cast<std::size_t>(at - names.begin())];
             v != want[i].second)
      s << want[i].first << " " << v << " there, " << want[i].second << " here";
    differs = s.str();
  }
  for (std::size_t i = 0; differs.empty() && i < names.size(); ++i)
    if (std::none_of(want.begin(), want.end(), [&](const auto& w) { return w.first == names[i]; }))
      differs = names[i] + " stored there, not a setting of this sweep";
  if (!differs.empty())
    throw std::invalid_argument(path + " holds a sweep with other settings (" + differs +
                                "); remove it or choose another file to resume from");
}

// Each point: the model (1 twod, 0 depthavg), its row, then each of its texts as its length and
// one character code per number (the texts are short, and the collectives move numbers only).
std::vector<double> pack_points(const std::vector<SweepPoint>& points) {
  std::vector<double> v;
  for (SweepPoint p : points) {
    v.push_back(p.model == "twod" ? 1.0 : 0.0);
    const auto r = row(p);
    v.insert(v.end(), r.begin(), r.end());
    for (const std::string* text : texts(p)) {
      v.push_back(static_cast<double>(text->size()));
      for (const char c : *text) v.push_back(static_cast<unsigned char>(c));
    }
  }
  return v;
}

std::vector<SweepPoint> unpack_points(std::span<const double> packed) {
  std::vector<SweepPoint> points;
  std::size_t i = 0;
  while (i + kWidth + 1 < packed.size()) {
    points.push_back(
        from_row(packed[i] == 1.0 ? "twod" : "depthavg", packed.subspan(i + 1, kWidth)));
    i += kWidth + 1;
    for (std::string* text : texts(points.back())) {
      const auto length = i < packed.size() ? static_cast<std::size_t>(packed[i++]) : 0;
      if (i + length > packed.size())
        throw std::invalid_argument("unpack_points: a text runs past the end of the numbers");
      for (const double c : packed.subspan(i, length))
        text->push_back(static_cast<char>(static_cast<unsigned char>(c)));
      i += length;
    }
  }
  return points;
}

void write_sweep(const std::string& path, const SweepSpec& spec,
                 const std::vector<SweepPoint>& points) {
  H5Writer out(path);
  std::vector<double> k_hat;
  for (const char* model : {"depthavg", "twod"}) {
    std::vector<std::vector<double>> cols(kWidth);
    std::vector<std::vector<std::string>> text_cols(std::size(kTextColumns));
    for (SweepPoint p : points)
      if (p.model == model) {
        const auto r = row(p);
        for (std::size_t c = 0; c < r.size(); ++c) cols[c].push_back(r[c]);
        const auto t = texts(p);
        for (std::size_t c = 0; c < t.size(); ++c) text_cols[c].push_back(*t[c]);
      }
    if (cols[0].empty()) continue;
    for (std::size_t c = 0; c < cols.size(); ++c)
      out.write(std::string(model) + "/" + kColumns[c], cols[c]);
    for (std::size_t c = 0; c < text_cols.size(); ++c)
      out.write(std::string(model) + "/" + kTextColumns[c],
                std::span<const std::string>(text_cols[c]));
    if (std::string(model) == "depthavg") k_hat = cols[1];
  }
  const ChuteCase& k = spec.chute;
  const SteadyState base = k.steady();
  // The exact curve (7.11) with the run's chi around the depth-averaged points, for the figure.
  if (!k_hat.empty())
    write_dispersion_curve(out, "curve", base, spec.depthavg_settings.chi,
                           *std::min_element(k_hat.begin(), k_hat.end()) / 3.0,
                           *std::max_element(k_hat.begin(), k_hat.end()) * 3.0, 300);
  std::vector<double> values;
  std::string names;
  for (const auto& [name, value] : stored_settings(spec)) {
    values.push_back(value);
    names += (names.empty() ? "" : ",") + name;
  }
  out.write("settings", values);
  out.attribute("settings", "names", names);
  write_flow_inputs(out, std::string(curve_name(k.curve)), k.material, k.angle_deg, k.h0);
  out.attribute("/", "u_mean", base.u_mean);
  out.attribute("/", "depthavg_chi", spec.depthavg_settings.chi);
  out.attribute("/", "depthavg_measurement", spec.depthavg_linear ? "linear_run" : "seeded_run");
  out.close();
}

std::vector<SweepPoint> read_sweep(const std::string& path) {
  std::vector<SweepPoint> points;
  for (const char* model : {"depthavg", "twod"}) {
    const std::string g = std::string(model) + "/";
    if (!h5_has(path, g + "Lx")) continue;
    std::vector<std::vector<double>> cols;
    const std::size_t n = h5_read_doubles(path, g + "Lx").size();
    // (a column added since the file was written reads as NaN: the extrapolation's, the cells)
    for (const char* c : kColumns)
      cols.push_back(h5_has(path, g + c) ? h5_read_doubles(path, g + c)
                                         : std::vector<double>(n, NAN));
    // (a file written before the texts were kept has none: the report says so)
    std::vector<std::vector<std::string>> text_cols;
    for (const char* c : kTextColumns)
      text_cols.push_back(h5_has(path, g + c) ? h5_read_strings(path, g + c)
                                              : std::vector<std::string>(n));
    for (std::size_t i = 0; i < cols[0].size(); ++i) {
      std::vector<double> r;
      for (const auto& col : cols) r.push_back(col.at(i));
      points.push_back(from_row(model, r));
      const auto t = texts(points.back());
      for (std::size_t c = 0; c < t.size(); ++c) *t[c] = text_cols[c].at(i);
    }
  }
  return points;
}

}  // namespace granbench
