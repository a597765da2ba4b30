// Names of the depth-averaged model's choices as used on the command line and in output files.
#include "depthavg/params.hpp"

#include <stdexcept>
#include <string>

namespace granbench::depthavg {

std::string_view reconstruction_name(Reconstruction r) {
  switch (r) {
    case Reconstruction::Central:
      return "central";
    case Reconstruction::Minmod:
      return "minmod";
    case Reconstruction::MC:
      return "mc";
    case Reconstruction::VanAlbada:
      return "vanalbada";
  }
  return "?";
}

Reconstruction parse_reconstruction(std::string_view name) {
  if (name == "central") return Reconstruction::Central;
  if (name == "minmod") return Reconstruction::Minmod;
  if (name == "mc") return Reconstruction::MC;
  if (name == "vanalbada") return Reconstruction::VanAlbada;
  throw std::invalid_argument("unknown reconstruction '" + std::string(name) +
                              "' (valid: central, minmod, mc, vanalbada)");
}

}  // namespace granbench::depthavg
