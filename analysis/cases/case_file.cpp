// Reading the paper's case files (case_file.hpp) with the strict TOML reader that --config uses
// (common/toml_reader.hpp), so case files and config files follow the same syntax, and text that
// is not TOML is an error naming the file and the line rather than keys read wrongly.
#include "analysis/cases/case_file.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/toml_reader.hpp"

namespace granbench::cases {

namespace {

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
  return v.front();
}

std::vector<std::string> CaseFile::texts(const std::string& key,
                                         const std::string& resolution) const {
  return raw(key, resolution);
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
      out[key.substr(prefix.size())] = values;
    }
  }
  return out;
}

CaseFile read_case_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw CaseFileError(path + ": cannot be read");
  std::ostringstream text;
  text << in.rdbuf();
  TomlDocument doc;
  try {
    doc = read_toml(text.str(), path);
  } catch (const TomlError& e) {
    throw CaseFileError(e.what());  // "FILE:LINE: what"
  }
  std::map<std::string, std::vector<std::string>> values;
  for (const TomlEntry& e : doc.entries) {
    std::string key;
    for (const auto& t : e.table) key += t + ".";
    values[key + e.key] = e.values;
  }
  return CaseFile(path, std::move(values));
}

std::vector<CaseFile> list_case_files(const std::string& directory) {
  std::vector<std::string> paths;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(directory, ec))
    if (entry.path().extension() == ".toml") paths.push_back(entry.path().string());
  if (ec)
    throw CaseFileError("in " + directory + ": the directory cannot be listed: " + ec.message());
  std::sort(paths.begin(), paths.end());
  std::vector<CaseFile> out;
  for (const auto& p : paths) out.push_back(read_case_file(p));
  return out;
}

}  // namespace granbench::cases
