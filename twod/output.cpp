// HDF5 snapshots and their XDMF index. Fields are averaged to cell centres (u from its two
// x-faces, w from its two z-faces) and stored [nz][nx], with x and z node coordinates, so that
// the XDMF "2DRectMesh" (VXVY geometry) with cell-centred attributes describes them exactly.
// The XDMF file is a temporal collection of one grid per snapshot, each pointing into the HDF5
// file as "file.h5:/snapshots/NNNN/<field>". A run on a moving grid (grid.hpp) is written in the
// lab frame: its columns rolled into place and u + U, with each snapshot's own node coordinates
// (/snapshots/NNNN/xz_nodes, x offset by its x_offset attribute, under half a cell).
#include "twod/output.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "twod/diagnostics.hpp"
#include "twod/frame.hpp"
#include "twod/viscosity_mixing.hpp"

namespace granbench::twod {

void write_parameters(H5Writer& out, const std::string& group, const Grid& g,
                      const SolverParams& p) {
  out.create_group(group);
  const Rheology& r = p.rheology;
  const Material& m = r.material;
  // The flow's inputs and the grid also on the root, where every granbench file keeps them.
  if (group != "/") {
    write_flow_inputs(out, std::string(curve_name(r.curve)), m, p.zeta * 180.0 / std::numbers::pi,
                      NAN);
    out.attribute("/", "nx", g.nx);
    out.attribute("/", "nz", g.nz);
  }
  auto a = [&](const char* key, double v) { out.attribute(group, key, v); };
  a("nx", g.nx);
  a("nz", g.nz);
  a("Lx", g.Lx);
  a("Lz", g.Lz);
  a("frame_speed", g.frame_speed);  // the grid's speed; the outputs are in the lab frame
  a("angle_deg", p.zeta * 180.0 / std::numbers::pi);
  out.attribute(group, "curve", std::string(curve_name(r.curve)));
  for (const MaterialConstant& c : material_constants) a(c.key, m.*c.value);
  a("eta_max", r.eta_max);
  a("eta_min", r.eta_min);
  a("D_min", r.D_min);
  a("rho_light", r.rho_light);
  a("eta_light", r.eta_light);
  a("ambient_pressure_gradient", r.ambient_pressure_gradient ? 1.0 : 0.0);
  a("effective_pressure", r.effective_pressure ? 1.0 : 0.0);
  out.attribute(group, "viscosity_mixing", std::string(viscosity_mixing_name(r.mixing)));
  a("cfl", p.cfl);
  a("dt_max", p.dt_max);
  a("solver_tolerance", p.solver_tolerance);
  a("viscous_tolerance", p.viscous_tolerance);
  a("viscosity_passes", p.viscosity_passes);
  a("advection_ab2", p.advection_ab2 ? 1.0 : 0.0);
  a("consistent_momentum", p.consistent_momentum ? 1.0 : 0.0);
  a("viscosity_tangent", p.viscosity_tangent ? 1.0 : 0.0);
  a("hydrostatic_viscosity_pressure", p.hydrostatic_viscosity_pressure ? 1.0 : 0.0);
  a("surface_row_pressure", p.surface_row_pressure ? 1.0 : 0.0);
  a("surface_row_shear", p.surface_row_shear ? 1.0 : 0.0);
  a("predictor_pressure_acceleration", p.predictor_pressure_acceleration ? 1.0 : 0.0);
  a("predictor_acceleration_limit", p.predictor_acceleration_limit);
  a("stress_bdf2", p.stress_bdf2 ? 1.0 : 0.0);
  a("advection_transverse_terms", p.advection_transverse_terms ? 1.0 : 0.0);
  a("interface_midstep_velocity", p.interface_midstep_velocity ? 1.0 : 0.0);
  a("surface_row_shear_spacing", r.surface_row_shear_spacing ? 1.0 : 0.0);
  out.attribute(
      group, "interface_pressure",
      std::string(r.interface_pressure == InterfacePressure::Extrapolated ? "extrapolated"
                                                                          : "cell-average"));
}

namespace {
// The node coordinates as one (nz+1, nx+1, 2) array of (x, z), x fastest, x shifted by
// x_offset: the 2DSMesh/XY geometry that all three ParaView XDMF readers open (the legacy reader
// shows 2DRectMesh blank and its Glyph filter crashes on it; shared/reports/paraview.md).
std::vector<double> node_coordinates(const Grid& g, double x_offset) {
  std::vector<double> xz;
  xz.reserve(2 * std::size_t(g.nx + 1) * std::size_t(g.nz + 1));
  for (int k = 0; k <= g.nz; ++k)
    for (int i = 0; i <= g.nx; ++i) xz.insert(xz.end(), {i * g.dx + x_offset, k * g.dz});
  return xz;
}
}  // namespace

SnapshotWriter::SnapshotWriter(H5Writer& out, std::string h5_file_name, std::string xdmf_path,
                               const Grid& g)
    : out_(out), h5_name_(std::move(h5_file_name)), xdmf_path_(std::move(xdmf_path)), g_(g) {
  check_xdmf_file_name(h5_name_);
  std::vector<double> xn(g.nx + 1), zn(g.nz + 1);
  for (int i = 0; i <= g.nx; ++i) xn[i] = i * g.dx;
  for (int k = 0; k <= g.nz; ++k) zn[k] = k * g.dz;
  out_.write("/snapshots/x_nodes", xn);
  out_.write("/snapshots/z_nodes", zn);
  out_.write("/snapshots/xz_nodes", node_coordinates(g, 0.0), {g.nz + 1u, g.nx + 1u, 2});
}

void SnapshotWriter::write(const Solver& solver) {
  const Grid& g = g_;
  const Fields& s = solver.state();
  const Properties& props = solver.properties();
  char name[64];
  std::snprintf(name, sizeof name, "/snapshots/%04zu", times_.size());
  const std::string grp = name;
  std::vector<double> uc(g.cells()), wc(g.cells());
  for (int k = 0; k < g.nz; ++k)
    for (int i = 0; i < g.nx; ++i) {
      uc[g.at(i, k)] = 0.5 * (s.u[g.at(i, k)] + s.u[g.at(i + 1, k)]);
      wc[g.at(i, k)] = 0.5 * (s.w[g.at(i, k)] + s.w[g.at(i, k + 1)]);
    }
  const std::vector<std::size_t> dims = {std::size_t(g.nz), std::size_t(g.nx)};
  std::vector<double> I = props.I_c;
  for (double& v : I)
    if (!std::isfinite(v)) v = std::nan("");  // p <= 0: I undefined
  // In the lab frame (frame.hpp): the grid's columns rolled to where they are in the lab, their
  // centres offset by less than half a cell (this snapshot's own node coordinates), u + U.
  const ColumnShift shift = lab_column_shift(g, s.t);
  auto lab = [&](const std::vector<double>& v, double add = 0.0) {
    if (g.frame_speed == 0.0) return v;
    std::vector<double> out(v.size());
    for (int k = 0; k < g.nz; ++k)
      for (int i = 0; i < g.nx; ++i) out[g.at(i + shift.shift, k)] = v[g.at(i, k)] + add;
    return out;
  };
  uc = lab(uc, g.frame_speed);
  wc = lab(wc);
  out_.write(grp + "/u", uc, dims);
  out_.write(grp + "/w", wc, dims);
  out_.write(grp + "/p", lab(s.p), dims);
  out_.write(grp + "/f", lab(s.f), dims);
  out_.write(grp + "/I", lab(I), dims);
  out_.write(grp + "/eta", lab(props.eta_c), dims);
  out_.write(grp + "/C", lab(ill_posedness_field(props.I_c, solver.viscosity_model().curve())),
             dims);
  if (g.frame_speed != 0.0) {
    out_.write(grp + "/xz_nodes", node_coordinates(g, shift.remainder), {g.nz + 1u, g.nx + 1u, 2});
    out_.attribute(grp, "x_offset", shift.remainder);
  }
  // (u, w, 0) per cell, so that Glyph and Stream Tracer work without a Calculator.
  std::vector<double> velocity;
  velocity.reserve(3 * uc.size());
  for (std::size_t c = 0; c < uc.size(); ++c) velocity.insert(velocity.end(), {uc[c], wc[c], 0.0});
  out_.write(grp + "/velocity", velocity, {dims[0], dims[1], 3});
  out_.attribute(grp, "t", s.t);
  times_.push_back(s.t);
}

void SnapshotWriter::finish() const {
  const std::string partial = xdmf_path_ + ".partial";
  {
    std::ofstream x(partial);
    // Times in full: a rounded time would not name the sample it belongs to.
    x << std::setprecision(std::numeric_limits<double>::max_digits10);
    const int nx = g_.nx, nz = g_.nz;
    const std::string h5 = xml_escaped(h5_name_);
    const auto item = [&](const std::string& dims, const std::string& path) {
      return "<DataItem Dimensions=\"" + dims + "\" NumberType=\"Float\" Precision=\"8\" " +
             "Format=\"HDF\">" + h5 + ":" + path + "</DataItem>";
    };
    const std::string nodes = std::to_string(nz + 1) + " " + std::to_string(nx + 1);
    const std::string cells = std::to_string(nz) + " " + std::to_string(nx);
    x << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n <Domain>\n"
      << "  <Grid Name=\"twod\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    for (std::size_t n = 0; n < times_.size(); ++n) {
      char grp[32];
      std::snprintf(grp, sizeof grp, "/snapshots/%04zu", n);
      x << "   <Grid Name=\"t" << n << "\" GridType=\"Uniform\">\n"
        << "    <Time Value=\"" << times_[n] << "\"/>\n"
        << "    <Topology TopologyType=\"2DSMesh\" Dimensions=\"" << nodes << "\"/>\n"
        << "    <Geometry GeometryType=\"XY\">\n     "
        << item(nodes + " 2", g_.frame_speed != 0.0 ? std::string(grp) + "/xz_nodes"
                                                    : std::string("/snapshots/xz_nodes"))
        << "\n    </Geometry>\n";
      for (const char* f : {"u", "w", "p", "f", "I", "eta", "C"})
        x << "    <Attribute Name=\"" << f << "\" AttributeType=\"Scalar\" Center=\"Cell\">\n     "
          << item(cells, std::string(grp) + "/" + f) << "\n    </Attribute>\n";
      x << "    <Attribute Name=\"velocity\" AttributeType=\"Vector\" Center=\"Cell\">\n     "
        << item(cells + " 3", std::string(grp) + "/velocity") << "\n    </Attribute>\n";
      x << "   </Grid>\n";
    }
    x << "  </Grid>\n </Domain>\n</Xdmf>\n";
  }
  std::filesystem::rename(partial, xdmf_path_);
}

std::string xml_escaped(const std::string& text) {
  std::string e;
  for (char c : text) switch (c) {
      case '&':
        e += "&amp;";
        break;
      case '<':
        e += "&lt;";
        break;
      case '>':
        e += "&gt;";
        break;
      case '"':
        e += "&quot;";
        break;
      case '\'':
        e += "&apos;";
        break;
      default:
        e += c;
    }
  return e;
}

void check_xdmf_file_name(const std::string& name) {
  // The Xdmf3 readers return an empty data set, silently, for a file name with white space, and
  // "name:path" is how XDMF addresses a dataset, so a ':' would split the name.
  const auto bad = name.find_first_of(" \t\n\r\v\f:");
  if (bad != std::string::npos)
    throw std::invalid_argument(
        "--out: '" + name + "' has " +
        (name[bad] == ':' ? std::string("a ':'") : std::string("white space")) +
        ", which ParaView's XDMF readers cannot open; valid: a file name "
        "without spaces or ':'");
}

}  // namespace granbench::twod
