// Reading the paper's case files (case_file.hpp) with CLI11's TOML reader, the one the --config
// option uses, so case files and config files follow the same syntax.
#include "analysis/cases/case_file.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace granbench::cases {

namespace {

std::string unquote(std::string s) {
  if (s.size() >= 2 && (s.front() == '"' || s.front() == '\'') && s.back() == s.front())
    s = s.substr(1, s.size() - 2);
  return s;
}

double parse_number(const std::string& text, const std::string& where) {
  std::size_t used = 0;
  double v = 0.0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size())
    throw CaseFileError(where + ": '" + text + "' is not a number");
  return v;
}

}  // namespace

CaseFile::CaseFile(std::string path, std::map<std::string, std::vector<std::string>> values)
    : path_(std::move(path)), values_(std::move(values)) {}

std::string CaseFile::name() const {
  return std::filesystem::path(path_).stem().string();
}

bool CaseFile::has(const std::string& key, const std::string& resolution) const {
  return (!resolution.empty() && values_.count(resolution + "." + key)) || values_.count(key);
}

const std::vector<std::string>& CaseFile::raw(const std::string& key,
                                              const std::string& resolution) const {
  if (!resolution.empty()) {
    const auto it = values_.find(resolution + "." + key);
    if (it != values_.end()) return it->second;
  }
  const auto it = values_.find(key);
  if (it == values_.end())
    throw CaseFileError(
        path_ + ": key '" + key + "' missing" +
        (resolution.empty() ? "" : " (at the top level or under [" + resolution + "])"));
  return it->second;
}

std::string CaseFile::text(const std::string& key, const std::string& resolution) const {
  const auto& v = raw(key, resolution);
  if (v.size() != 1) throw CaseFileError(path_ + ": key '" + key + "' must be one value");
  return unquote(v.front());
}

std::vector<std::string> CaseFile::texts(const std::string& key,
                                         const std::string& resolution) const {
  std::vector<std::string> out;
  for (const auto& s : raw(key, resolution)) out.push_back(unquote(s));
  return out;
}

double CaseFile::number(const std::string& key, const std::string& resolution) const {
  return parse_number(text(key, resolution), path_ + ": key '" + key + "'");
}

double CaseFile::number_in(const std::string& key, const std::string& resolution, double lo,
                           double hi) const {
  const double v = number(key, resolution);
  if (!(v >= lo && v <= hi)) {
    std::ostringstream msg;
    msg << path_ << ": key '" << key << "' = " << v << " out of range; valid range [" << lo << ", "
        << hi << "]";
    throw CaseFileError(msg.str());
  }
  return v;
}

int CaseFile::integer(const std::string& key, const std::string& resolution) const {
  const double v = number(key, resolution);
  if (v != double(int(v))) throw CaseFileError(path_ + ": key '" + key + "' must be an integer");
  return int(v);
}

std::vector<double> CaseFile::numbers(const std::string& key, const std::string& resolution) const {
  std::vector<double> out;
  for (const auto& s : texts(key, resolution))
    out.push_back(parse_number(s, path_ + ": key '" + key + "'"));
  return out;
}

std::map<std::string, std::vector<std::string>> CaseFile::table(
    const std::string& name, const std::string& resolution) const {
  std::map<std::string, std::vector<std::string>> out;
  for (const std::string& prefix : {name + ".", resolution + "." + name + "."}) {
    for (const auto& [key, values] : values_) {
      if (key.rfind(prefix, 0) != 0 || key.find('.', prefix.size()) != std::string::npos) continue;
      std::vector<std::string> plain;
      for (const auto& v : values) plain.push_back(unquote(v));
      out[key.substr(prefix.size())] = plain;
    }
  }
  return out;
}

CaseFile read_case_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw CaseFileError("cannot read case file '" + path + "'");
  std::vector<CLI::ConfigItem> items;
  try {
    items = CLI::ConfigTOML().from_config(in);
  } catch (const CLI::ParseError& e) {
    throw CaseFileError(path + ": not valid TOML: " + e.what());
  }
  std::map<std::string, std::vector<std::string>> values;
  for (const auto& item : items) {
    if (item.name.empty() || item.name == "++" || item.name == "--") continue;
    std::string key;
    for (const auto& p : item.parents) key += p + ".";
    values[key + item.name] = item.inputs;
  }
  return CaseFile(path, std::move(values));
}

std::vector<CaseFile> list_case_files(const std::string& directory) {
  std::vector<std::string> paths;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(directory, ec))
    if (entry.path().extension() == ".toml") paths.push_back(entry.path().string());
  if (ec)
    throw CaseFileError("cannot list the case directory '" + directory + "': " + ec.message());
  std::sort(paths.begin(), paths.end());
  std::vector<CaseFile> out;
  for (const auto& p : paths) out.push_back(read_case_file(p));
  return out;
}

}  // namespace granbench::cases
