#include "common/companion_path.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <filesystem>

namespace granbench {

std::string companion_path(const std::string& out, const std::string& suffix) {
  std::filesystem::path p(out);
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  constexpr std::array<const char*, 4> hdf5_extensions{".h5", ".hdf5", ".hdf", ".he5"};
  const bool is_hdf5 =
      std::find(hdf5_extensions.begin(), hdf5_extensions.end(), ext) != hdf5_extensions.end();
  return is_hdf5 ? p.replace_extension(suffix).string() : out + suffix;
}

}  // namespace granbench
