// --config FILE.toml for every subcommand (docs/design.md: any option can come from the file and
// the command line overrides it). CLI11 2.1 reads config files only at the top level, so the file
// is read here (common/toml_reader.hpp, strict TOML) and expanded into ordinary options before
// parsing: `name = value` at the top applies to every subcommand that has --name; under a
// [<subcommand>] section it applies to that subcommand and overrides the top; a later file
// overrides an earlier one; the command line overrides them all. A key that is no option of its
// subcommand (of any subcommand, at the top), a section that is no subcommand and malformed TOML
// are refused with the file, the line and the key.
//
// --print-config writes the effective options of the subcommand as TOML (a [<subcommand>]
// table that --config reads back; defaults as comments) instead of running it.
#pragma once

#include <CLI/CLI.hpp>
#include <map>
#include <string>
#include <vector>

namespace granbench::cli {

struct ExpandedArgs {
  std::vector<std::string> args;  // the command line with the files' options added
  // "--name" of each option that came from a file -> "FILE line N", for error messages.
  std::map<std::string, std::string> origins;
  bool print_config = false;  // --print-config was given (and is removed from args)
};

// args excludes the program name; `app` has every subcommand registered. Throws UsageError
// naming --config for an unreadable file and for every error in one.
ExpandedArgs expand_config_files(const std::vector<std::string>& args, const CLI::App& app);

// The options of a parsed subcommand as TOML: the given values as keys, the defaults as comments.
std::string effective_options_toml(const CLI::App& sub);

}  // namespace granbench::cli
