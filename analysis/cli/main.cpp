// granbench: the command-line front end.
//
//   granbench wellposed  --curve regularised            where a mu(I) curve is well posed (§3-§4)
//   granbench steady     --angle 28.5 --h0 0.004        the steady uniform Bagnold state (§5, §7)
//   granbench dispersion --angle 28.5 --h0 0.004 --Lx 0.08   exact linear theory (7.11)
//
// Exit codes: 0 success, 2 bad input (one line naming the option and its valid range),
// other non-zero codes for failures a command reports (e.g. a diverged solver).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <iostream>

#include "cli_common.hpp"
#include "commands.hpp"
#include "config_file.hpp"
#include "provenance.hpp"

int main(int argc, char** argv) {
  using namespace granbench::cli;
  CLI::App app{"granbench: depth-averaged and 2D mu(I) chute flows against exact theory"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "granbench " + granbench::granbench_version() + " (commit " +
                                        granbench::granbench_git_commit() + ")");
  add_wellposed_command(app);
  add_steady_command(app);
  add_dispersion_command(app);
  add_run_command(app);
  add_sweep_command(app);
  add_compare_command(app);
  add_case_command(app);
  try {
    // Options from --config files become ordinary options first (config_file.hpp).
    std::vector<std::string> args(argv + 1, argv + argc);
    args = expand_config_files(args);
    std::reverse(args.begin(), args.end());  // CLI11 parses a reversed vector
    app.parse(args);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "granbench: error: " << e.what() << "\n";
    return 2;
  } catch (const UsageError& e) {
    std::cerr << "granbench: error: " << e.what() << "\n";
    return 2;
  } catch (const CommandFailed& e) {
    std::cerr << "granbench: " << e.what() << "\n";
    return e.exit_code;
  } catch (const std::exception& e) {
    std::cerr << "granbench: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
