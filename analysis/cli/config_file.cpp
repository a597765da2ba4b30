// Expansion of --config TOML files into command-line options; see config_file.hpp.
#include "config_file.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <fstream>

#include "cli_common.hpp"

namespace granbench::cli {

namespace {

bool given(const std::vector<std::string>& args, const std::string& name) {
  return std::any_of(args.begin(), args.end(), [&](const std::string& a) {
    return a == "--" + name || a.rfind("--" + name + "=", 0) == 0;
  });
}

}  // namespace

std::vector<std::string> expand_config_files(const std::vector<std::string>& args) {
  std::vector<std::string> rest;
  std::vector<std::string> files;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--config") {
      if (i + 1 >= args.size()) throw UsageError("--config: needs a TOML file name");
      files.push_back(args[++i]);
    } else if (args[i].rfind("--config=", 0) == 0) {
      files.push_back(args[i].substr(9));
    } else {
      rest.push_back(args[i]);
    }
  }
  if (files.empty()) return rest;
  // The subcommand is the first argument that is not an option.
  const auto sub = std::find_if(rest.begin(), rest.end(),
                                [](const std::string& a) { return a.rfind("-", 0) != 0; });
  const std::string subcommand = sub == rest.end() ? "" : *sub;
  std::vector<std::string> expanded;
  for (const auto& file : files) {
    std::ifstream in(file);
    if (!in) throw UsageError("--config: cannot read '" + file + "'; valid: a readable TOML file");
    std::vector<CLI::ConfigItem> items;
    try {
      items = CLI::ConfigTOML().from_config(in);
    } catch (const CLI::ParseError& e) {
      throw UsageError("--config: '" + file + "' is not valid TOML: " + e.what());
    }
    for (const auto& item : items) {
      const bool top = item.parents.empty();
      const bool ours = item.parents.size() == 1 && item.parents[0] == subcommand;
      if ((!top && !ours) || item.name.empty() || item.name == "++" || item.name == "--") continue;
      if (given(rest, item.name)) continue;  // the command line overrides the file
      for (const auto& value : item.inputs) expanded.push_back("--" + item.name + "=" + value);
    }
  }
  const auto at = sub == rest.end() ? rest.end() : sub + 1;
  const auto offset = at - rest.begin();
  rest.insert(rest.begin() + offset, expanded.begin(), expanded.end());
  return rest;
}

}  // namespace granbench::cli
