// Test support: the table of one verification study (its grids or steps, errors, observed orders,
// and the bounds the test asserts in words). The test prints it and writes it as Markdown to
// <build>/verification/<name>.md; scripts/verification_tables.sh runs the `convergence` tests and
// assembles those files into docs/verification.md, so the committed record is the tests' own
// output, not numbers copied by hand. Header only; include by relative path.
#pragma once

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace granbench::testing {

class VerificationTable {
 public:
  // `name` is the file stem (and the order key in docs/verification.md), `title` a heading,
  // `what` one sentence on what is compared with what.
  VerificationTable(std::string name, std::string title, std::string what,
                    std::vector<std::string> columns)
      : name_(std::move(name)),
        title_(std::move(title)),
        what_(std::move(what)),
        columns_(std::move(columns)) {}

  void row(std::vector<std::string> cells) { rows_.push_back(std::move(cells)); }
  // A bound the test asserts, in words ("observed order > 1.8").
  void bound(std::string text) { bounds_.push_back(std::move(text)); }

  // Prints the table and writes it; call after the assertions so a failed bound is visible in
  // the file as well as in the test log.
  void write() const {
    const std::string md = markdown();
    std::fputs(md.c_str(), stdout);
    const std::filesystem::path dir = std::filesystem::path(GRANBENCH_BINARY_DIR) / "verification";
    std::filesystem::create_directories(dir);
    std::ofstream(dir / (name_ + ".md")) << md;
  }

  std::string markdown() const {
    std::string s = "### " + title_ + "\n\n" + what_ + "\n\n|";
    for (const auto& c : columns_) s += " " + c + " |";
    s += "\n|";
    for (std::size_t i = 0; i < columns_.size(); ++i) s += "---|";
    s += "\n";
    for (const auto& r : rows_) {
      s += "|";
      for (const auto& c : r) s += " " + c + " |";
      s += "\n";
    }
    if (!bounds_.empty()) {
      s += "\nAsserted:\n";
      for (const auto& b : bounds_) s += "- " + b + "\n";
    }
    return s + "\n";
  }

 private:
  std::string name_, title_, what_;
  std::vector<std::string> columns_;
  std::vector<std::vector<std::string>> rows_;
  std::vector<std::string> bounds_;
};

// Number formats for the cells: scientific with 3 significant digits, fixed with `digits`.
inline std::string sci(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3e", v);
  return b;
}
inline std::string fixed(double v, int digits = 2) {
  char b[32];
  std::snprintf(b, sizeof b, "%.*f", digits, v);
  return b;
}
inline std::string dash() {
  return "–";
}

}  // namespace granbench::testing
