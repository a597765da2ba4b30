// The units and a readable name of every dataset granbench writes, looked up by its path in the
// file. H5Writer gives each dataset these as the attributes `units` and `long_name` when it
// closes the file (unless the writer set them itself), so the writers stay free of bookkeeping
// and a reader (h5dump, ParaView, h5py) sees them on every array. Units are SI, "1" for
// dimensionless numbers (the CF convention); a table of mixed columns names them in long_name.
#pragma once

#include <optional>
#include <string>

namespace granbench {

struct DatasetDoc {
  std::string units;
  std::string long_name;
};

// nullopt for a name this table does not know (tests/common/test_provenance.cpp opens the output
// of every command and fails on such a dataset).
std::optional<DatasetDoc> dataset_doc(const std::string& path);

}  // namespace granbench
