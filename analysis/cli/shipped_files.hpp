// Where granbench finds the files it ships beside the program: the case files (`granbench case`)
// and the plotting scripts (`--plot`). An installed granbench (`cmake --install build --prefix
// P`) finds them under P/share/granbench, beside the P/bin it runs from, so that it keeps working
// after its source and build trees are gone; one run from its build tree finds them in the source
// tree it was built from.
#pragma once

#include <string>

namespace granbench::cli {

// The directory of the case files (the default of `case --cases-dir`).
std::string shipped_cases_dir();
// The directory of the plotting scripts.
std::string shipped_plot_dir();

}  // namespace granbench::cli
