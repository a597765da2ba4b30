// --config FILE.toml for every subcommand (DESIGN.md: any option can come from the file and the
// command line overrides it). CLI11 2.1 reads config files only at the top level, so the file is
// expanded here into ordinary options before parsing: each top-level key `name = value` (or under
// a [<subcommand>] section) becomes --name=value after the subcommand, unless the command line
// already gives --name.
#pragma once

#include <string>
#include <vector>

namespace granbench::cli {

// args excludes the program name. Throws UsageError naming --config for an unreadable file.
std::vector<std::string> expand_config_files(const std::vector<std::string>& args);

}  // namespace granbench::cli
