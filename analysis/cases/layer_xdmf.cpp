// The XDMF index of a layer case; see layer_xdmf.hpp.
#include "analysis/cases/layer_xdmf.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>

#include "twod/output.hpp"

namespace granbench::cases {

std::string layer_sample_name(std::size_t n) {
  char name[24];
  std::snprintf(name, sizeof name, "%04zu", n);
  return name;
}

std::vector<double> layer_run_nodes(const LayerRunRecord& r) {
  std::vector<double> xz;
  xz.reserve(std::size_t(r.nz + 1) * (r.nx + 1) * 2);
  for (int k = 0; k <= r.nz; ++k)
    for (int i = 0; i <= r.nx; ++i) {
      xz.push_back(r.Lx * i / r.nx);
      xz.push_back(r.Lz * k / r.nz);
    }
  return xz;
}

void write_layer_case_xdmf(const std::string& xdmf_path, const std::string& h5_name,
                           const LayerCaseResult& result) {
  const std::string partial = xdmf_path + ".partial";
  {
    std::ofstream x(partial);
    x << std::setprecision(std::numeric_limits<double>::max_digits10);  // times in full
    const std::string h5 = twod::xml_escaped(h5_name);
    x << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n <Domain>\n";
    for (const LayerRunRecord& r : result.runs) {
      const std::string g = "/runs/" + twod::xml_escaped(r.label);
      const std::string nodes = std::to_string(r.nz + 1) + " " + std::to_string(r.nx + 1);
      const std::string cells = std::to_string(r.nz) + " " + std::to_string(r.nx);
      x << "  <Grid Name=\"" << twod::xml_escaped(r.label)
        << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
      for (std::size_t n = 0; n < r.t.size(); ++n) {
        x << "   <Grid Name=\"t" << n << "\" GridType=\"Uniform\">\n"
          << "    <Time Value=\"" << r.t[n] << "\"/>\n"
          << "    <Topology TopologyType=\"2DSMesh\" Dimensions=\"" << nodes << "\"/>\n"
          << "    <Geometry GeometryType=\"XY\">\n"
          << "     <DataItem Dimensions=\"" << nodes << " 2\" NumberType=\"Float\" Precision=\"8\""
          << " Format=\"HDF\">" << h5 << ":" << g << "/xz_nodes</DataItem>\n"
          << "    </Geometry>\n"
          << "    <Attribute Name=\"I\" AttributeType=\"Scalar\" Center=\"Cell\">\n"
          << "     <DataItem Dimensions=\"" << cells << "\" NumberType=\"Float\" Precision=\"8\""
          << " Format=\"HDF\">" << h5 << ":" << g << "/samples/" << layer_sample_name(n)
          << "/I</DataItem>\n"
          << "    </Attribute>\n"
          << "   </Grid>\n";
      }
      x << "  </Grid>\n";
    }
    x << " </Domain>\n</Xdmf>\n";
  }
  std::filesystem::rename(partial, xdmf_path);
}

}  // namespace granbench::cases
