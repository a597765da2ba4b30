// Examples and exit codes at the end of a subcommand's --help; see help_footer.hpp.
#include "analysis/cli/help_footer.hpp"

#include <map>

namespace granbench::cli {

std::string help_footer(const std::vector<std::string>& examples, const std::vector<int>& codes) {
  static const std::map<int, const char*> meaning = {
      {0, "success"},
      {2, "bad input (one line naming the option and its valid range); nothing written"},
      {3, "a run failed (diverged, or a point did not complete); what was computed is kept"},
      {130, "interrupted by Ctrl-C (SIGINT); what was computed is kept"},
      {143, "stopped by SIGTERM; what was computed is kept"}};
  std::string text = "Examples:\n";
  for (const auto& e : examples) text += "  " + e + "\n";
  text += "\nExit codes:\n";
  for (int c : codes) {
    const std::string code = std::to_string(c);
    text += "  " + code + std::string(5 - code.size(), ' ') + meaning.at(c) + "\n";
  }
  text += "  1    an internal error (please report it)";
  return text;
}

}  // namespace granbench::cli
