// H5Writer: HDF5 output written to "<path>.partial" and renamed into place on close().
#include "common/hdf5_file.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numeric>
#include <stdexcept>

#include "common/dataset_units.hpp"
#include "common/provenance.hpp"

namespace granbench {

namespace {

void check(herr_t status, const std::string& what) {
  if (status < 0) throw std::runtime_error("HDF5: failed to " + what);
}

std::vector<hsize_t> shape(std::size_t n, const std::vector<std::size_t>& dims) {
  if (dims.empty()) return {static_cast<hsize_t>(n)};
  std::size_t total =
      std::accumulate(dims.begin(), dims.end(), std::size_t{1}, std::multiplies<>());
  if (total != n) throw std::invalid_argument("HDF5: dataset dims do not match the data size");
  return {dims.begin(), dims.end()};
}

template <class T>
void write_dataset(hid_t file, const std::string& name, std::span<const T> data,
                   const std::vector<std::size_t>& dims, hid_t type) {
  const auto hdims = shape(data.size(), dims);
  hid_t space = H5Screate_simple(static_cast<int>(hdims.size()), hdims.data(), nullptr);
  hid_t lcpl = H5Pcreate(H5P_LINK_CREATE);
  H5Pset_create_intermediate_group(lcpl, 1);
  hid_t set = H5Dcreate2(file, name.c_str(), type, space, lcpl, H5P_DEFAULT, H5P_DEFAULT);
  H5Pclose(lcpl);
  if (set < 0) {
    H5Sclose(space);
    throw std::runtime_error("HDF5: cannot create dataset " + name);
  }
  herr_t st = data.empty() ? 0 : H5Dwrite(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data());
  H5Dclose(set);
  H5Sclose(space);
  check(st, "write " + name);
}

// H5Ovisit callback: collects the paths of the datasets.
herr_t collect_dataset(hid_t, const char* name, const H5O_info_t* info, void* paths) {
  if (info->type == H5O_TYPE_DATASET)
    static_cast<std::vector<std::string>*>(paths)->push_back(std::string("/") + name);
  return 0;
}

std::vector<std::string> dataset_paths(hid_t file) {
  std::vector<std::string> paths;
  check(H5Ovisit2(file, H5_INDEX_NAME, H5_ITER_NATIVE, collect_dataset, &paths, H5O_INFO_BASIC),
        "list the datasets");
  return paths;
}

bool has_attribute(hid_t file, const std::string& object, const std::string& key) {
  return H5Aexists_by_name(file, object.c_str(), key.c_str(), H5P_DEFAULT) > 0;
}

}  // namespace

H5Writer::H5Writer(std::string path) : path_(std::move(path)), partial_(path_ + ".partial") {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors are reported by exceptions instead
  file_ = H5Fcreate(partial_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (file_ < 0) throw std::runtime_error("cannot create HDF5 file " + partial_);
}

H5Writer::~H5Writer() {
  if (!closed_) {
    if (file_ >= 0) H5Fclose(file_);
    std::remove(partial_.c_str());
  }
}

void H5Writer::create_group(const std::string& group) {
  if (H5Lexists(file_, group.c_str(), H5P_DEFAULT) > 0) return;
  hid_t lcpl = H5Pcreate(H5P_LINK_CREATE);
  H5Pset_create_intermediate_group(lcpl, 1);
  hid_t g = H5Gcreate2(file_, group.c_str(), lcpl, H5P_DEFAULT, H5P_DEFAULT);
  H5Pclose(lcpl);
  if (g < 0) throw std::runtime_error("HDF5: cannot create group " + group);
  H5Gclose(g);
}

void H5Writer::write(const std::string& name, std::span<const double> data,
                     const std::vector<std::size_t>& dims) {
  write_dataset(file_, name, data, dims, H5T_NATIVE_DOUBLE);
}

void H5Writer::write(const std::string& name, std::span<const std::int64_t> data,
                     const std::vector<std::size_t>& dims) {
  write_dataset(file_, name, data, dims, H5T_NATIVE_INT64);
}

void H5Writer::write(const std::string& name, std::span<const std::string> text) {
  std::size_t width = 1;  // HDF5 has no strings of length 0
  for (const std::string& t : text) width = std::max(width, t.size());
  std::vector<char> packed(text.size() * width, '\0');
  for (std::size_t i = 0; i < text.size(); ++i)
    std::copy(text[i].begin(), text[i].end(), packed.begin() + static_cast<long>(i * width));
  hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, width);
  H5Tset_strpad(type, H5T_STR_NULLPAD);
  const hsize_t n = text.size();
  hid_t space = H5Screate_simple(1, &n, nullptr);
  hid_t lcpl = H5Pcreate(H5P_LINK_CREATE);
  H5Pset_create_intermediate_group(lcpl, 1);
  hid_t set = H5Dcreate2(file_, name.c_str(), type, space, lcpl, H5P_DEFAULT, H5P_DEFAULT);
  H5Pclose(lcpl);
  herr_t st = set < 0 ? -1
              : n     ? H5Dwrite(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, packed.data())
                      : 0;
  if (set >= 0) H5Dclose(set);
  H5Sclose(space);
  H5Tclose(type);
  check(st, "write " + name);
}

void H5Writer::attribute(const std::string& object, const std::string& key, double value) {
  hid_t space = H5Screate(H5S_SCALAR);
  if (H5Aexists_by_name(file_, object.c_str(), key.c_str(), H5P_DEFAULT) > 0)
    H5Adelete_by_name(file_, object.c_str(), key.c_str(), H5P_DEFAULT);
  hid_t attr = H5Acreate_by_name(file_, object.c_str(), key.c_str(), H5T_NATIVE_DOUBLE, space,
                                 H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  herr_t st = attr < 0 ? -1 : H5Awrite(attr, H5T_NATIVE_DOUBLE, &value);
  if (attr >= 0) H5Aclose(attr);
  H5Sclose(space);
  check(st, "write attribute " + key + " on " + object);
}

void H5Writer::attribute(const std::string& object, const std::string& key,
                         const std::string& value) {
  hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, value.empty() ? 1 : value.size());
  hid_t space = H5Screate(H5S_SCALAR);
  if (H5Aexists_by_name(file_, object.c_str(), key.c_str(), H5P_DEFAULT) > 0)
    H5Adelete_by_name(file_, object.c_str(), key.c_str(), H5P_DEFAULT);
  hid_t attr = H5Acreate_by_name(file_, object.c_str(), key.c_str(), type, space, H5P_DEFAULT,
                                 H5P_DEFAULT, H5P_DEFAULT);
  const char* text = value.empty() ? "" : value.c_str();
  herr_t st = attr < 0 ? -1 : H5Awrite(attr, type, text);
  if (attr >= 0) H5Aclose(attr);
  H5Sclose(space);
  H5Tclose(type);
  check(st, "write attribute " + key + " on " + object);
}

void H5Writer::close() {
  if (closed_) return;
  attribute("/", "granbench_version", granbench_version());
  attribute("/", "git_commit", granbench_git_commit());
  attribute("/", "code_target", granbench_code_target());
  attribute("/", "command_line", process_command_line());
  attribute("/", "created", utc_timestamp_now());
  for (const std::string& set : dataset_paths(file_)) {
    const auto doc = dataset_doc(set);
    if (!doc) continue;  // unknown to the table: tests/common/test_provenance.cpp finds it
    if (!has_attribute(file_, set, "units")) attribute(set, "units", doc->units);
    if (!has_attribute(file_, set, "long_name")) attribute(set, "long_name", doc->long_name);
  }
  check(H5Fclose(file_), "close " + partial_);
  file_ = -1;
  std::filesystem::rename(partial_, path_);
  closed_ = true;
}

void write_surface_series(H5Writer& out, const std::string& group, const SurfaceSeries& s) {
  out.create_group(group);
  out.write(group + "/x", s.x);
  out.write(group + "/t", s.t);
  out.write(group + "/h", s.h, {s.nt(), s.nx()});
  if (!s.u_mean.empty()) out.write(group + "/u_mean", s.u_mean, {s.nt(), s.nx()});
  out.attribute(group, "Lx", s.Lx);
  out.attribute(group, "h0", s.h0);
}

void write_flow_inputs(H5Writer& out, const std::string& curve, const Material& m, double angle_deg,
                       double h0) {
  out.attribute("/", "curve", curve);
  if (!std::isnan(angle_deg)) out.attribute("/", "angle_deg", angle_deg);
  if (!std::isnan(h0)) out.attribute("/", "h0", h0);
  for (const MaterialConstant& c : material_constants) out.attribute("/", c.key, m.*c.value);
}

namespace {
// A dataset of a file opened for reading; both closed when it goes out of scope.
class ReadSet {
 public:
  ReadSet(const std::string& path, const std::string& name) {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    file_ = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (file_ < 0) throw std::runtime_error("cannot open HDF5 file " + path);
    set_ = H5Dopen2(file_, name.c_str(), H5P_DEFAULT);
    if (set_ < 0) {
      H5Fclose(file_);
      throw std::runtime_error("no dataset " + name + " in " + path);
    }
  }
  ~ReadSet() {
    H5Dclose(set_);
    H5Fclose(file_);
  }
  ReadSet(const ReadSet&) = delete;
  ReadSet& operator=(const ReadSet&) = delete;
  hid_t id() const { return set_; }

 private:
  hid_t file_ = -1, set_ = -1;
};
}  // namespace

std::vector<double> h5_read_doubles(const std::string& path, const std::string& name,
                                    std::vector<std::size_t>* dims) {
  const ReadSet read(path, name);
  const hid_t set = read.id();
  hid_t space = H5Dget_space(set);
  const int rank = H5Sget_simple_extent_ndims(space);
  std::vector<hsize_t> hd(static_cast<std::size_t>(std::max(rank, 0)));
  H5Sget_simple_extent_dims(space, hd.data(), nullptr);
  std::size_t n = 1;
  for (auto v : hd) n *= v;
  std::vector<double> data(n);
  herr_t st = n ? H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()) : 0;
  H5Sclose(space);
  check(st, "read " + name);
  if (dims) dims->assign(hd.begin(), hd.end());
  return data;
}

std::vector<std::string> h5_read_strings(const std::string& path, const std::string& name) {
  const ReadSet read(path, name);
  const hid_t set = read.id();
  hid_t stored = H5Dget_type(set);
  const bool fixed_text = H5Tget_class(stored) == H5T_STRING && H5Tis_variable_str(stored) == 0;
  const std::size_t width = fixed_text ? H5Tget_size(stored) : 0;
  H5Tclose(stored);
  hid_t space = H5Dget_space(set);
  const hssize_t n = H5Sget_simple_extent_npoints(space);
  std::vector<char> packed(static_cast<std::size_t>(std::max<hssize_t>(n, 0)) * width);
  herr_t st = -1;
  if (fixed_text) {
    hid_t type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, width);
    H5Tset_strpad(type, H5T_STR_NULLPAD);
    st = n > 0 ? H5Dread(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, packed.data()) : 0;
    H5Tclose(type);
  }
  H5Sclose(space);
  if (!fixed_text) throw std::runtime_error(name + " in " + path + " is not fixed-length text");
  check(st, "read " + name);
  std::vector<std::string> text;
  for (std::size_t i = 0; i * width < packed.size(); ++i) {
    const char* begin = packed.data() + i * width;
    text.emplace_back(begin, std::find(begin, begin + width, '\0'));
  }
  return text;
}

bool h5_has(const std::string& path, const std::string& name) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0) return false;
  const bool has = H5Lexists(file, name.c_str(), H5P_DEFAULT) > 0;
  H5Fclose(file);
  return has;
}

namespace {
// The file opened read-only for one look; closed when it goes out of scope.
struct ReadOnlyFile {
  hid_t id;
  explicit ReadOnlyFile(const std::string& path) {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    if (id < 0) throw std::runtime_error("cannot open HDF5 file " + path);
  }
  ~ReadOnlyFile() { H5Fclose(id); }
  ReadOnlyFile(const ReadOnlyFile&) = delete;
  ReadOnlyFile& operator=(const ReadOnlyFile&) = delete;
};

hid_t open_attribute(const ReadOnlyFile& f, const std::string& path, const std::string& object,
                     const std::string& key) {
  const hid_t attr = H5Aopen_by_name(f.id, object.c_str(), key.c_str(), H5P_DEFAULT, H5P_DEFAULT);
  if (attr < 0) throw std::runtime_error("no attribute " + key + " on " + object + " in " + path);
  return attr;
}
}  // namespace

std::string h5_read_string_attribute(const std::string& path, const std::string& object,
                                     const std::string& key) {
  const ReadOnlyFile f(path);
  const hid_t attr = open_attribute(f, path, object, key);
  const hid_t type = H5Aget_type(attr);
  std::string value;
  herr_t st = -1;
  if (H5Tget_class(type) == H5T_STRING && !H5Tis_variable_str(type)) {
    value.assign(H5Tget_size(type), '\0');
    st = H5Aread(attr, type, value.data());
    value.resize(value.find('\0') == std::string::npos ? value.size() : value.find('\0'));
  }
  H5Tclose(type);
  H5Aclose(attr);
  check(st, "read the string attribute " + key + " on " + object);
  return value;
}

double h5_read_double_attribute(const std::string& path, const std::string& object,
                                const std::string& key) {
  const ReadOnlyFile f(path);
  const hid_t attr = open_attribute(f, path, object, key);
  double v = 0.0;
  const herr_t st = H5Aread(attr, H5T_NATIVE_DOUBLE, &v);
  H5Aclose(attr);
  check(st, "read the attribute " + key + " on " + object);
  return v;
}

bool h5_has_attribute(const std::string& path, const std::string& object, const std::string& key) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0) return false;
  const bool has = (object == "/" || H5Lexists(file, object.c_str(), H5P_DEFAULT) > 0) &&
                   has_attribute(file, object, key);
  H5Fclose(file);
  return has;
}

std::vector<std::string> h5_dataset_paths(const std::string& path) {
  const ReadOnlyFile f(path);
  return dataset_paths(f.id);
}

SurfaceSeries read_surface_series(const std::string& path, const std::string& group) {
  SurfaceSeries s;
  s.x = h5_read_doubles(path, group + "/x");
  s.t = h5_read_doubles(path, group + "/t");
  s.h = h5_read_doubles(path, group + "/h");
  if (h5_has(path, group + "/u_mean")) s.u_mean = h5_read_doubles(path, group + "/u_mean");
  // Lx and h0 are attributes; recover them from the grid and the data when reading.
  const double dx = s.x.size() > 1 ? s.x[1] - s.x[0] : 0.0;
  s.Lx = dx * static_cast<double>(s.x.size());
  double sum = 0.0;
  for (std::size_t i = 0; i < s.x.size() && !s.h.empty(); ++i) sum += s.h[i];
  s.h0 = s.x.empty() ? 0.0 : sum / static_cast<double>(s.x.size());
  return s;
}

}  // namespace granbench
