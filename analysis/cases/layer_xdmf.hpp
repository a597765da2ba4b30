// The XDMF index of a layer case's HDF5 file (decelerating §5.2, high-speed §6.2), so that
// ParaView opens its runs as it opens a 2D run's snapshots: one temporal collection per run
// (grid label), the inertial number I as a cell field at every sample time, on a 2DSMesh with XY
// node coordinates (the mesh type every ParaView XDMF reader displays, twod/output.hpp). I of
// each sample is its own dataset, /runs/<label>/samples/NNNN/I [nz][nx].
#pragma once

#include <string>

#include "analysis/cases/layer_case.hpp"

namespace granbench::cases {

// Node coordinates of run `r`, [nz + 1][nx + 1][2] (x, z), as the XDMF file references them at
// /runs/<label>/xz_nodes; write_layer_case writes them.
std::vector<double> layer_run_nodes(const LayerRunRecord& r);

// The group of sample n under /runs/<label>/samples/ ("0000", "0001", ...).
std::string layer_sample_name(std::size_t n);

// Writes `xdmf_path` (atomically) for the HDF5 file `h5_name` (as the XDMF file should reference
// it: a name relative to the XDMF file's folder).
void write_layer_case_xdmf(const std::string& xdmf_path, const std::string& h5_name,
                           const LayerCaseResult& result);

}  // namespace granbench::cases
