// A strict reader for the part of TOML 1.0 that granbench's --config files use: comments, tables
// ([name], [a.b]), keys (bare, quoted, dotted) and values that are strings (basic and literal,
// one line), integers (decimal, 0x/0o/0b, with _ separators), floats (with inf and nan),
// booleans and arrays of those (which may span lines). Everything else TOML allows (dates,
// inline tables, multi-line strings) and everything it does not is an error naming the file, the
// line and the key. Written here because Debian 12 packages no maintained C++ TOML parser, and
// CLI11's reader accepts text that is not TOML at all (qa.md K02, CX1-CX8).
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace granbench {

struct TomlEntry {
  std::vector<std::string> table;  // the enclosing tables, outermost first; empty at the top
  std::string key;
  // The value as command-line text: numbers in C notation ("30", "0.004", "inf"), booleans as
  // "true"/"false", strings unquoted; an array gives one text per element.
  std::vector<std::string> values;
  bool is_array = false;
  int line = 0;
};

struct TomlError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A table declared with a [header] (a table with no keys is still one the file names).
struct TomlTable {
  std::vector<std::string> path;
  int line = 0;
};

struct TomlDocument {
  std::vector<TomlEntry> entries;  // in file order
  std::vector<TomlTable> tables;   // in file order
};

// Throws TomlError "FILE:LINE: what" (`name` is the file name used in messages).
TomlDocument read_toml(const std::string& text, const std::string& name);

}  // namespace granbench
