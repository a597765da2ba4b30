// Expansion of --config TOML files into command-line options; see config_file.hpp.
#include "analysis/cli/config_file.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "analysis/cli/cli_common.hpp"
#include "common/toml_reader.hpp"

namespace granbench::cli {

namespace {

bool given(const std::vector<std::string>& args, const std::string& name) {
  return std::any_of(args.begin(), args.end(), [&](const std::string& a) {
    return a == "--" + name || a.rfind("--" + name + "=", 0) == 0;
  });
}

// Keys a file may not set: they steer the reading of files and the help.
bool reserved(const std::string& key) {
  return key == "config" || key == "print-config" || key == "help" || key == "version";
}

bool has_option(const CLI::App& sub, const std::string& key) {
  return !reserved(key) && sub.get_option_no_throw("--" + key) != nullptr;
}

std::string subcommand_list(const CLI::App& app) {
  std::string list;
  for (const CLI::App* s : app.get_subcommands([](const CLI::App*) { return true; }))
    list += (list.empty() ? "" : ",") + s->get_name();
  return "{" + list + "}";
}

std::string read_file(const std::string& file) {
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec))
    throw UsageError("--config: '" + file + "' is a directory; valid: a readable TOML file");
  std::ifstream in(file, std::ios::binary);
  if (!in.is_open())
    throw UsageError("--config: cannot read '" + file + "'; valid: a readable TOML file");
  std::ostringstream text;
  text << in.rdbuf();  // an empty file (or /dev/null) is valid, empty TOML
  return text.str();
}

struct Setting {
  std::vector<std::string> values;
  std::string origin;
};

}  // namespace

ExpandedArgs expand_config_files(const std::vector<std::string>& args, const CLI::App& app) {
  ExpandedArgs result;
  std::vector<std::string>& rest = result.args;
  std::vector<std::string> files;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--config") {
      if (i + 1 >= args.size()) throw UsageError("--config: needs a TOML file name");
      files.push_back(args[++i]);
    } else if (args[i].rfind("--config=", 0) == 0) {
      files.push_back(args[i].substr(9));
    } else if (args[i] == "--print-config") {
      result.print_config = true;
    } else {
      rest.push_back(args[i]);
    }
  }
  if (files.empty()) return result;
  // The subcommand is the first argument that is not an option.
  const auto sub_at = std::find_if(rest.begin(), rest.end(),
                                   [](const std::string& a) { return a.rfind("-", 0) != 0; });
  const std::string name = sub_at == rest.end() ? "" : *sub_at;
  const CLI::App* sub = nullptr;
  for (const CLI::App* s : app.get_subcommands([](const CLI::App*) { return true; }))
    if (s->get_name() == name) sub = s;
  const auto subs = app.get_subcommands([](const CLI::App*) { return true; });

  std::map<std::string, Setting> settings;  // by option name, the last file's, section over top
  for (const auto& file : files) {
    TomlDocument doc;
    try {
      doc = read_toml(read_file(file), file);
    } catch (const TomlError& e) {
      throw UsageError(std::string("--config: ") + e.what());
    }
    const auto where = [&](int line) { return file + ":" + std::to_string(line); };
    for (const TomlTable& t : doc.tables) {
      const bool known = t.path.size() == 1 &&
                         std::any_of(subs.begin(), subs.end(),
                                     [&](const CLI::App* s) { return s->get_name() == t.path[0]; });
      if (!known) {
        std::string joined;
        for (const auto& p : t.path) joined += (joined.empty() ? "" : ".") + p;
        throw UsageError("--config: " + where(t.line) + ": unknown section [" + joined +
                         "]; valid sections " + subcommand_list(app));
      }
    }
    for (const bool section_pass : {false, true})
      for (const TomlEntry& e : doc.entries) {
        if (e.table.empty() == section_pass) continue;
        if (e.table.size() > 1)
          throw UsageError(
              "--config: " + where(e.line) + ": key '" + e.key +
              "' is nested too deep; valid: top-level keys or keys of a [<subcommand>] section");
        const CLI::App* owner = nullptr;
        if (!e.table.empty()) {
          for (const CLI::App* s : subs)
            if (s->get_name() == e.table[0]) owner = s;
          if (owner == nullptr)
            throw UsageError("--config: " + where(e.line) + ": unknown section [" + e.table[0] +
                             "]; valid sections " + subcommand_list(app));
          if (!has_option(*owner, e.key))
            throw UsageError("--config: " + where(e.line) + ": unknown key '" + e.key + "' in [" +
                             e.table[0] + "]; valid: the long options of granbench " + e.table[0] +
                             " without '--' (see granbench " + e.table[0] + " --help)");
          if (owner != sub) continue;  // another subcommand's section
        } else {
          const bool anywhere = std::any_of(
              subs.begin(), subs.end(), [&](const CLI::App* s) { return has_option(*s, e.key); });
          if (!anywhere)
            throw UsageError("--config: " + where(e.line) + ": unknown key '" + e.key +
                             "'; valid: the long options of a subcommand without '--'");
          if (sub == nullptr || !has_option(*sub, e.key)) continue;  // for other subcommands
        }
        settings[e.key] = {e.values, file + " line " + std::to_string(e.line)};
      }
  }
  std::vector<std::string> expanded;
  for (const auto& [key, s] : settings) {
    if (given(rest, key)) continue;  // the command line overrides the files
    for (const auto& value : s.values) expanded.push_back("--" + key + "=" + value);
    result.origins["--" + key] = s.origin;
  }
  const auto offset = sub_at == rest.end() ? rest.size() : (sub_at - rest.begin()) + 1;
  rest.insert(rest.begin() + static_cast<std::ptrdiff_t>(offset), expanded.begin(), expanded.end());
  return result;
}

namespace {

std::string toml_value(const std::string& text) {
  static const std::regex number(
      R"([+-]?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?|[+-]?(inf|nan))");
  if (std::regex_match(text, number) || text == "true" || text == "false") return text;
  std::string q = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') q += '\\';
    if (c == '\n') {
      q += "\\n";
      continue;
    }
    q += c;
  }
  return q + "\"";
}

}  // namespace

std::string effective_options_toml(const CLI::App& sub) {
  std::ostringstream out;
  out << "# granbench " << sub.get_name() << ": effective options (read back with --config).\n"
      << "# Options left at their defaults are shown commented out: given in a file they would\n"
      << "# count as given, and a command refuses options that do not apply to its choices.\n";
  out << "[" << sub.get_name() << "]\n";
  for (const CLI::Option* opt : sub.get_options()) {
    if (opt->get_lnames().empty()) continue;  // positional
    const std::string name = opt->get_lnames().front();
    if (reserved(name)) continue;
    const bool given = opt->count() > 0;
    std::vector<std::string> values;
    if (opt->get_type_size() == 0) {  // a flag
      const bool on = given && (opt->results().empty() || opt->as<bool>());
      values.push_back(on ? "true" : "false");
    } else if (given) {
      values = opt->results();
    } else if (!opt->get_default_str().empty()) {
      values.push_back(opt->get_default_str());
    }
    if (values.empty()) continue;  // no value and no default (e.g. --out not given)
    out << (given ? "" : "# ") << name << " = ";
    if (values.size() == 1 && opt->get_items_expected_max() <= 1) {
      out << toml_value(values[0]) << "\n";
      continue;
    }
    out << "[";
    for (std::size_t i = 0; i < values.size(); ++i) out << (i ? ", " : "") << toml_value(values[i]);
    out << "]\n";
  }
  return out.str();
}

}  // namespace granbench::cli
