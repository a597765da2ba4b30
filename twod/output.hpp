// Output of the 2D solver (output.cpp): cell-centred HDF5 snapshots of u, w, p, f, I, eta and
// C(I) and the vector velocity (u, w, 0), with an XDMF index that ParaView opens as a time series
// with any of its three XDMF readers (a 2DSMesh with XY node geometry: x along the slope, VTK's
// y the bed-normal z), and the run parameters (the regularisation constants included,
// docs/design.md §8) as attributes. I and C are NaN where p <= 0 (no inertial number without
// pressure).
#pragma once

#include <string>
#include <vector>

#include "common/hdf5_file.hpp"
#include "twod/grid.hpp"
#include "twod/solver.hpp"

namespace granbench::twod {

// Every solver parameter as an attribute of `group` (SI units, angle in degrees).
void write_parameters(H5Writer& out, const std::string& group, const Grid& g,
                      const SolverParams& params);

// The text with & < > " ' as XML entities (for the file name inside the XDMF).
std::string xml_escaped(const std::string& text);
// std::invalid_argument naming --out for an HDF5 file name with white space or ':'.
void check_xdmf_file_name(const std::string& name);

class SnapshotWriter {
 public:
  // h5_file_name: the HDF5 file name as the XDMF file should reference it (relative path);
  // std::invalid_argument when ParaView could not open it (check_xdmf_file_name).
  SnapshotWriter(H5Writer& out, std::string h5_file_name, std::string xdmf_path, const Grid& g);
  // Write /snapshots/NNNN/{u,w,p,f,I,eta,C} (cell centres, [nz][nx]), velocity ([nz][nx][3])
  // and, once, the node coordinates.
  void write(const Solver& solver);
  // Write the XDMF index (atomically: .partial, then rename).
  void finish() const;
  // Take over the first times.size() snapshots of an earlier output of the same run (a restart
  // into the same file, snapshot_carry_over.cpp): copied as they are, numbered as before, and
  // indexed in the XDMF. Throws std::runtime_error when `earlier` does not hold them.
  void carry_over(const std::string& earlier, const std::vector<double>& times);
  std::size_t count() const { return times_.size(); }

 private:
  H5Writer& out_;
  std::string h5_name_, xdmf_path_;
  Grid g_;
  std::vector<double> times_;
};

}  // namespace granbench::twod
