// Where granbench finds the files it ships beside the program: the case files (`granbench case`),
// the plotting scripts (`--plot`) and the MPI module (mpi_session.hpp). An installed granbench
// (`cmake --install build --prefix P`) finds them under P/share/granbench, beside the P/bin it runs
// from, so that it keeps working after its source and build trees are gone; one run from its build
// tree finds them in the source tree it was built from.
#pragma once

#include <string>

namespace granbench::cli {

// The directory of the case files (the default of `case --cases-dir`).
std::string shipped_cases_dir();
// The directory of the plotting scripts.
std::string shipped_plot_dir();
#ifdef GRANBENCH_MPI_MODULE
// The MPI module: P/lib/granbench/libgranbench_mpi.so when installed, else the build tree's.
std::string shipped_mpi_module();
#endif

}  // namespace granbench::cli
