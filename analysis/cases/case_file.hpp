// A paper case as a TOML file in cases/ (docs/design.md: cases/ holds only data). A case file has a
// `kind` naming the runner (decelerating, high-speed, rollwave, wellposed), a `title`, the
// paper's `figures`, keys shared by every resolution at the top level, and keys that depend on
// the resolution under [smoke] (a reduced version that runs in CI in seconds) and [paper] (the
// full case). A key under the chosen resolution's table overrides the top-level one.
//
//   kind = "decelerating"
//   angle = 10.0
//   [smoke]
//   t_end = 0.02
#pragma once

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace granbench::cases {

// A missing, malformed or out-of-range key: the message names the file and the key.
struct CaseFileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class CaseFile {
 public:
  CaseFile(std::string path, std::map<std::string, std::vector<std::string>> values);

  const std::string& path() const { return path_; }
  std::string name() const;  // the file name without directory and .toml
  // Typed lookups of `key` for a resolution ("smoke" or "paper"): "<resolution>.key" first, then
  // the top-level "key". Throws CaseFileError when absent or not of the type.
  std::string text(const std::string& key, const std::string& resolution = "") const;
  double number(const std::string& key, const std::string& resolution = "") const;
  int integer(const std::string& key, const std::string& resolution = "") const;
  std::vector<std::string> texts(const std::string& key, const std::string& resolution = "") const;
  std::vector<double> numbers(const std::string& key, const std::string& resolution = "") const;
  bool has(const std::string& key, const std::string& resolution = "") const;
  // The keys of table `name` ([name], then [<resolution>.name] overriding), e.g. the options a
  // case passes on to a granbench subcommand: key -> values (strings unquoted).
  std::map<std::string, std::vector<std::string>> table(const std::string& name,
                                                        const std::string& resolution) const;
  // A number within [lo, hi], else CaseFileError naming the key and the range.
  double number_in(const std::string& key, const std::string& resolution, double lo,
                   double hi) const;

 private:
  const std::vector<std::string>& raw(const std::string& key, const std::string& resolution) const;
  std::string path_;
  std::map<std::string, std::vector<std::string>> values_;  // "key" or "table.key"
};

// Parses a case file; throws CaseFileError if unreadable or not TOML.
CaseFile read_case_file(const std::string& path);
// The case files (*.toml) in a directory, sorted by name.
std::vector<CaseFile> list_case_files(const std::string& directory);

}  // namespace granbench::cases
