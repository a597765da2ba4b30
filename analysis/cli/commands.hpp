// The granbench subcommands. Each add_*_command registers one subcommand with its options and a
// callback; callbacks signal bad input with cli::UsageError (exit 2) and other failures with
// cli::CommandFailed (its exit code). One file per subcommand: cmd_<name>.cpp.
#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

namespace granbench::cli {

struct CommandFailed : std::runtime_error {
  CommandFailed(const std::string& what, int code) : std::runtime_error(what), exit_code(code) {}
  int exit_code;
};

void add_wellposed_command(CLI::App& app);
void add_steady_command(CLI::App& app);
void add_dispersion_command(CLI::App& app);
void add_run_command(CLI::App& app);
void add_sweep_command(CLI::App& app);
void add_compare_command(CLI::App& app);
void add_case_command(CLI::App& app);

// `granbench wellposed --curve CURVE --out H5 --plot PNG --json` in this process: writes the data
// and the figure and returns the JSON that command prints (used by `case`).
nlohmann::json wellposed_result(const std::string& curve, const std::string& h5,
                                const std::string& png);

}  // namespace granbench::cli
