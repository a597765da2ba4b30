// The names of the interface-cell viscosity rules (twod/parameters.hpp, ViscosityMixing), as the
// command line, case files and HDF5 attributes spell them. One list, so that a rule added to the
// enum is named the same everywhere.
#pragma once

#include <array>
#include <optional>
#include <string_view>
#include <utility>

#include "twod/parameters.hpp"

namespace granbench::twod {

inline constexpr std::array<std::pair<const char*, ViscosityMixing>, 2> viscosity_mixing_names{{
    {"arithmetic", ViscosityMixing::Arithmetic},
    {"harmonic", ViscosityMixing::Harmonic},
}};

inline const char* viscosity_mixing_name(ViscosityMixing m) {
  for (const auto& [name, value] : viscosity_mixing_names)
    if (value == m) return name;
  return "unknown";
}

// The rule of that name; nothing for an unknown name (the caller names the option or key).
inline std::optional<ViscosityMixing> viscosity_mixing_from_name(std::string_view name) {
  for (const auto& [n, value] : viscosity_mixing_names)
    if (name == n) return value;
  return std::nullopt;
}

}  // namespace granbench::twod
