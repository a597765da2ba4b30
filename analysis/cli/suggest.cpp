// The closest valid name to a mistyped one; see suggest.hpp.
#include "analysis/cli/suggest.hpp"

#include <algorithm>

namespace granbench::cli {

namespace {
// Levenshtein distance (insertions, deletions and substitutions of one character).
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}
}  // namespace

std::optional<std::string> closest_name(const std::string& typed,
                                        const std::vector<std::string>& valid) {
  std::optional<std::string> best;
  std::size_t best_distance = 0;
  for (const auto& v : valid) {
    if (!typed.empty() && v.rfind(typed, 0) == 0) return v;
    const std::size_t d = edit_distance(typed, v);
    if (3 * d <= std::max(typed.size(), v.size()) && (!best || d < best_distance)) {
      best = v;
      best_distance = d;
    }
  }
  return best;
}

}  // namespace granbench::cli
