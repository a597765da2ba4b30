// The names of the files written beside an HDF5 output: its XDMF index and its checkpoint.
#pragma once

#include <string>

namespace granbench {

// `out` with its HDF5 extension (.h5, .hdf5, .hdf, .he5) replaced by `suffix`, or with `suffix`
// appended when it has none: "run.h5" -> "run.xdmf", but "r0.25" -> "r0.25.xdmf", not "r0.xdmf",
// which two runs named r0.25 and r0.45 would have shared (and so their checkpoint files).
std::string companion_path(const std::string& out, const std::string& suffix);

}  // namespace granbench
