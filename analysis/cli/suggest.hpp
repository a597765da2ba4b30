// "Did you mean ...?" for a mistyped name: the closest of the valid names by edit distance, if
// it is close enough to be a likely typo (at most a third of the longer name's letters differ),
// or a valid name the typed one starts (`granbench stead` -> steady).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace granbench::cli {

std::optional<std::string> closest_name(const std::string& typed,
                                        const std::vector<std::string>& valid);

}  // namespace granbench::cli
