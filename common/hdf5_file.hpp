// A thin RAII wrapper over the HDF5 C API: create a file, write double/int datasets of any rank,
// and scalar or string attributes. Files are written to "<name>.partial" and renamed on
// close(), so an interrupted or failed run never leaves a half-written file under the real name.
// close() also stamps the provenance on the root (provenance.hpp: granbench_version,
// git_commit, command_line, created) and gives every dataset its `units` and `long_name`
// (dataset_units.hpp) unless the writer set them, so every file granbench writes has them.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "common/material.hpp"
#include "common/surface_series.hpp"

namespace granbench {

class H5Writer {
 public:
  explicit H5Writer(std::string path);
  ~H5Writer();  // discards the partial file unless close() succeeded
  H5Writer(const H5Writer&) = delete;
  H5Writer& operator=(const H5Writer&) = delete;

  void create_group(const std::string& group);
  void write(const std::string& name, std::span<const double> data,
             const std::vector<std::size_t>& dims = {});
  void write(const std::string& name, std::span<const std::int64_t> data,
             const std::vector<std::size_t>& dims = {});
  // A one-dimensional dataset of text, each entry padded with NULs to the longest one's length
  // (fixed-length strings: what every HDF5 version and h5py read alike).
  void write(const std::string& name, std::span<const std::string> text);
  // Attributes on an object ("/" for the file root).
  void attribute(const std::string& object, const std::string& key, double value);
  void attribute(const std::string& object, const std::string& key, const std::string& value);
  // Flush, close and rename into place (after the provenance and units, see above).
  void close();
  // Copy `object` (a group with everything under it, or a dataset, with their attributes) from
  // the HDF5 file `source` to the same path here (hdf5_copy.cpp).
  void copy_from(const std::string& source, const std::string& object);
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::string partial_;
  std::int64_t file_ = -1;
  bool closed_ = false;
};

void write_surface_series(H5Writer& out, const std::string& group, const SurfaceSeries& s);
// The inputs of a flow as root attributes: curve, the material constants (material.hpp's names),
// and, where the output has them, angle_deg and h0 (NaN: not written).
void write_flow_inputs(H5Writer& out, const std::string& curve, const Material& m, double angle_deg,
                       double h0);

// Reading back (tests, resumable sweeps, plots-free analysis).
std::vector<double> h5_read_doubles(const std::string& path, const std::string& name,
                                    std::vector<std::size_t>* dims = nullptr);
bool h5_has(const std::string& path, const std::string& name);
// A dataset of fixed-length strings (H5Writer::write of text), each without its padding.
std::vector<std::string> h5_read_strings(const std::string& path, const std::string& name);
// Attributes of an object ("/" for the root); throw std::runtime_error when missing.
std::string h5_read_string_attribute(const std::string& path, const std::string& object,
                                     const std::string& key);
double h5_read_double_attribute(const std::string& path, const std::string& object,
                                const std::string& key);
bool h5_has_attribute(const std::string& path, const std::string& object, const std::string& key);
// Every dataset of the file by its full path ("/surface/h"), in the file's order.
std::vector<std::string> h5_dataset_paths(const std::string& path);
SurfaceSeries read_surface_series(const std::string& path, const std::string& group);
// A numeric attribute of an object; throws std::runtime_error when absent (hdf5_copy.cpp).
double h5_read_attribute(const std::string& path, const std::string& object,
                         const std::string& key);

}  // namespace granbench
