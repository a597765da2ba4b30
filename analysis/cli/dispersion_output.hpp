// The HDF5 files of `granbench dispersion`: the depth-averaged relation (7.11) over k_hat with
// the requested points, and for --theory twod the three theories over k_hat (the 2D surface
// branch, (7.11) with chi = 1 and chi = 5/4) with each requested point's surface eigenmode; and
// the JSON of the 2D modes.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "analysis/linear2d/linear_stability_2d.hpp"
#include "analysis/theory/dispersion.hpp"
#include "common/hdf5_file.hpp"
#include "common/steady_state.hpp"

namespace granbench::cli {

// The JSON of one 2D linear mode, and of the light-layer modes beside their stress-free
// counterparts (with the differences).
nlohmann::json mode_json(const Linear2DMode& m);
nlohmann::json light_layer_json(const Linear2DResult& r);

void write_dispersion_data(const std::string& path, const SteadyState& s, double chi,
                           const std::vector<DispersionMode>& modes, const std::string& curve);

// The three theories over k_hat in [1e-2, 10] into the group "curve": the 2D surface branch (and
// the largest other 2D growth rate), (7.11) with chi = 1 and with chi = 5/4.
void write_theory_curves(H5Writer& out, const SteadyState& s, const linear2d::LinearBaseState& base,
                         int N);

void write_theories(const std::string& path, const SteadyState& s,
                    const std::vector<Linear2DResult>& results, const Linear2DOptions& opt,
                    const std::string& curve);

}  // namespace granbench::cli
