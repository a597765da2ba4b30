// The strict TOML subset reader; see toml_reader.hpp.
#include "common/toml_reader.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>
#include <sstream>

namespace granbench {

namespace {

class Parser {
 public:
  Parser(const std::string& text, const std::string& name) : s_(text), name_(name) {}

  TomlDocument parse() {
    TomlDocument doc;
    std::vector<std::string> table;
    while (!at_end()) {
      skip_blank();
      if (at_end()) break;
      if (peek() == '\n') {
        next();
        continue;
      }
      if (peek() == '#') {
        skip_comment();
        continue;
      }
      if (peek() == '[') {
        const int line = line_;
        next();
        if (peek() == '[') fail("arrays of tables ([[...]]) are not supported");
        skip_blank();
        table = read_key_path("table name");
        skip_blank();
        if (peek() != ']') fail("expected ']' to close the table header");
        next();
        end_of_line();
        if (!declared_.insert(join(table)).second)
          fail("table [" + join(table) + "] declared twice");
        doc.tables.push_back({table, line});
        continue;
      }
      TomlEntry e;
      e.line = line_;
      std::vector<std::string> path = read_key_path("key");
      e.key = path.back();
      path.pop_back();
      e.table = table;
      e.table.insert(e.table.end(), path.begin(), path.end());
      key_ = e.key;
      skip_blank();
      if (peek() != '=') fail("expected '=' after the key");
      next();
      skip_blank();
      if (peek() == '[') {
        e.is_array = true;
        read_array(e.values);
      } else {
        e.values.push_back(read_scalar());
      }
      end_of_line();
      const std::string full = join(e.table) + (e.table.empty() ? "" : ".") + e.key;
      if (!keys_.insert(full).second) fail("key '" + full + "' given twice");
      doc.entries.push_back(e);
      key_.clear();
    }
    return doc;
  }

 private:
  const std::string& s_;
  const std::string& name_;
  std::size_t i_ = 0;
  int line_ = 1;
  std::string key_;  // the key being read, for messages
  std::set<std::string> keys_, declared_;

  bool at_end() const { return i_ >= s_.size(); }
  char peek() const { return at_end() ? '\0' : s_[i_]; }
  char next() {
    const char c = s_[i_++];
    if (c == '\n') ++line_;
    return c;
  }

  [[noreturn]] void fail(const std::string& what) const {
    std::ostringstream m;
    m << name_ << ":" << line_ << ": " << what;
    if (!key_.empty()) m << " (key '" << key_ << "')";
    throw TomlError(m.str());
  }

  static std::string join(const std::vector<std::string>& path) {
    std::string j;
    for (const auto& p : path) j += (j.empty() ? "" : ".") + p;
    return j;
  }

  void skip_blank() {
    while (peek() == ' ' || peek() == '\t') next();
  }
  void skip_comment() {
    while (!at_end() && peek() != '\n') {
      const unsigned char c = static_cast<unsigned char>(next());
      if (c < 0x20 && c != '\t') fail("control character in a comment");
    }
  }
  // After a value or a header: blanks, an optional comment, then the end of the line.
  void end_of_line() {
    skip_blank();
    if (peek() == '#') skip_comment();
    if (peek() == '\r') next();
    if (!at_end() && peek() != '\n') fail("unexpected text after the value");
  }

  std::vector<std::string> read_key_path(const char* what) {
    std::vector<std::string> path;
    for (;;) {
      skip_blank();
      if (peek() == '"') {
        path.push_back(read_basic_string());
      } else if (peek() == '\'') {
        path.push_back(read_literal_string());
      } else {
        std::string k;
        while (std::isalnum(static_cast<unsigned char>(peek())) || peek() == '_' || peek() == '-')
          k += next();
        if (k.empty()) {
          const unsigned char c = static_cast<unsigned char>(peek());
          fail(std::string("expected a ") + what +
               (std::isprint(c) ? std::string(", found '") + static_cast<char>(c) + "'"
                                : std::string(", found a byte that is not text")));
        }
        path.push_back(k);
      }
      skip_blank();
      if (peek() != '.') return path;
      next();
    }
  }

  std::string read_basic_string() {
    next();  // "
    if (s_.compare(i_, 2, "\"\"") == 0) fail("multi-line strings are not supported");
    std::string v;
    for (;;) {
      if (at_end() || peek() == '\n') fail("unterminated string");
      const char c = next();
      if (c == '"') return v;
      if (static_cast<unsigned char>(c) < 0x20 && c != '\t') fail("control character in a string");
      if (c != '\\') {
        v += c;
        continue;
      }
      const char e = at_end() ? '\0' : next();
      switch (e) {
        case '"':
          v += '"';
          break;
        case '\\':
          v += '\\';
          break;
        case 'n':
          v += '\n';
          break;
        case 't':
          v += '\t';
          break;
        case 'r':
          v += '\r';
          break;
        case 'b':
          v += '\b';
          break;
        case 'f':
          v += '\f';
          break;
        default:
          fail(std::string("unknown escape '\\") + e + "' in a string");
      }
    }
  }

  std::string read_literal_string() {
    next();  // '
    if (s_.compare(i_, 2, "''") == 0) fail("multi-line strings are not supported");
    std::string v;
    for (;;) {
      if (at_end() || peek() == '\n') fail("unterminated string");
      const char c = next();
      if (c == '\'') return v;
      v += c;
    }
  }

  void read_array(std::vector<std::string>& values) {
    next();  // [
    for (;;) {
      skip_array_space();
      if (peek() == ']') {
        next();
        return;
      }
      if (peek() == '[') fail("nested arrays are not supported");
      values.push_back(read_scalar());
      skip_array_space();
      if (peek() == ',') {
        next();
        continue;
      }
      if (peek() != ']') fail("expected ',' or ']' in the array");
    }
  }
  void skip_array_space() {
    for (;;) {
      skip_blank();
      if (peek() == '#') skip_comment();
      if (peek() == '\r' || peek() == '\n') {
        next();
        continue;
      }
      if (at_end()) fail("unterminated array");
      return;
    }
  }

  // A string, boolean or number, as command-line text.
  std::string read_scalar() {
    if (peek() == '"') return read_basic_string();
    if (peek() == '\'') return read_literal_string();
    if (peek() == '{') fail("inline tables are not supported");
    std::string word;
    while (!at_end() && std::string(" \t\r\n,]#").find(peek()) == std::string::npos) word += next();
    if (word.empty()) fail("expected a value");
    if (word == "true" || word == "false") return word;
    return number(word);
  }

  // TOML numbers: decimal integers and floats with '_' between digits, 0x/0o/0b integers,
  // inf and nan with an optional sign.
  std::string number(const std::string& word) {
    std::string body = word;
    std::string sign;
    if (!body.empty() && (body[0] == '+' || body[0] == '-')) {
      sign = body[0] == '-' ? "-" : "";
      body = body.substr(1);
    }
    if (body == "inf" || body == "nan") return sign + body;
    const auto bad = [&] {
      fail("'" + word + "' is not a TOML value (strings need quotes: \"" + word + "\")");
    };
    if (body.size() > 2 && body[0] == '0' &&
        std::string("xob").find(body[1]) != std::string::npos) {
      if (!sign.empty() || word[0] == '+') bad();
      const int base = body[1] == 'x' ? 16 : body[1] == 'o' ? 8 : 2;
      const std::string digits = strip_underscores(body.substr(2), bad);
      std::size_t used = 0;
      long long v = 0;
      try {
        v = std::stoll(digits, &used, base);
      } catch (const std::exception&) {
        bad();
      }
      if (used != digits.size()) bad();
      return std::to_string(v);
    }
    const std::string digits = strip_underscores(body, bad);
    // Digits, at most one '.', with digits on both sides, and an optional exponent.
    std::size_t k = 0;
    const auto run = [&] {
      const std::size_t start = k;
      while (k < digits.size() && std::isdigit(static_cast<unsigned char>(digits[k]))) ++k;
      return k - start;
    };
    const std::size_t int_digits = run();
    if (int_digits == 0 || (int_digits > 1 && digits[0] == '0')) bad();  // no leading zeros
    if (k < digits.size() && digits[k] == '.') {
      ++k;
      if (run() == 0) bad();
    }
    if (k < digits.size() && (digits[k] == 'e' || digits[k] == 'E')) {
      ++k;
      if (k < digits.size() && (digits[k] == '+' || digits[k] == '-')) ++k;
      if (run() == 0) bad();
    }
    if (k != digits.size()) bad();
    return sign + digits;
  }

  template <class Bad>
  static std::string strip_underscores(const std::string& text, const Bad& bad) {
    std::string out;
    for (std::size_t k = 0; k < text.size(); ++k) {
      if (text[k] != '_') {
        out += text[k];
        continue;
      }
      // '_' only between two digits
      if (k == 0 || k + 1 == text.size() ||
          !std::isxdigit(static_cast<unsigned char>(text[k - 1])) ||
          !std::isxdigit(static_cast<unsigned char>(text[k + 1])))
        bad();
    }
    return out;
  }
};

}  // namespace

TomlDocument read_toml(const std::string& text, const std::string& name) {
  return Parser(text, name).parse();
}

}  // namespace granbench
