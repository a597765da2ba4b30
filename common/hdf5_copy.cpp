// Copying objects between HDF5 files and reading a numeric attribute (hdf5_file.hpp): what a
// restarted run needs to carry the snapshots of its first part into its own output.
#include <hdf5.h>

#include <stdexcept>

#include "common/hdf5_file.hpp"

namespace granbench {

void H5Writer::copy_from(const std::string& source, const std::string& object) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t src = H5Fopen(source.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (src < 0) throw std::runtime_error("cannot open HDF5 file " + source);
  const hid_t lcpl = H5Pcreate(H5P_LINK_CREATE);
  H5Pset_create_intermediate_group(lcpl, 1);
  const herr_t st = H5Ocopy(src, object.c_str(), file_, object.c_str(), H5P_DEFAULT, lcpl);
  H5Pclose(lcpl);
  H5Fclose(src);
  if (st < 0) throw std::runtime_error("HDF5: cannot copy " + object + " from " + source);
}

double h5_read_attribute(const std::string& path, const std::string& object,
                         const std::string& key) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0) throw std::runtime_error("cannot open HDF5 file " + path);
  double v = 0.0;
  const hid_t attr = H5Aopen_by_name(file, object.c_str(), key.c_str(), H5P_DEFAULT, H5P_DEFAULT);
  const herr_t st = attr < 0 ? -1 : H5Aread(attr, H5T_NATIVE_DOUBLE, &v);
  if (attr >= 0) H5Aclose(attr);
  H5Fclose(file);
  if (st < 0) throw std::runtime_error("no attribute " + key + " on " + object + " in " + path);
  return v;
}

}  // namespace granbench
