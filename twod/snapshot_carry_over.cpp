// SnapshotWriter::carry_over (output.hpp): a run restarted into its own output keeps the
// snapshots written before the restart. They are copied object by object (every field and
// attribute the writer put there), and their times are checked against the checkpoint's list,
// so that a file from another run is refused rather than spliced in.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "twod/output.hpp"

namespace granbench::twod {

void SnapshotWriter::carry_over(const std::string& earlier, const std::vector<double>& times) {
  for (const double t : times) {
    char name[64];
    std::snprintf(name, sizeof name, "/snapshots/%04zu", times_.size());
    const double stored = h5_read_attribute(earlier, name, "t");
    if (std::abs(stored - t) > 1e-12 * std::max(1.0, std::abs(t)))
      throw std::runtime_error(earlier + ": snapshot " + name +
                               " is at t = " + std::to_string(stored) + " s, the checkpoint's at " +
                               std::to_string(t) + " s (not the same run)");
    out_.copy_from(earlier, name);
    times_.push_back(t);
  }
}

}  // namespace granbench::twod
