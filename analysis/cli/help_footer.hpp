// The end of each subcommand's --help: examples, and the exit codes that command can give (the
// top level's --help lists them all, main.cpp).
#pragma once

#include <string>
#include <vector>

namespace granbench::cli {

// `codes`: the exit codes the command gives besides 1 (an internal error, always listed).
std::string help_footer(const std::vector<std::string>& examples, const std::vector<int>& codes);

}  // namespace granbench::cli
