// granbench: the command-line front end.
//
//   granbench wellposed  --curve regularised            where a mu(I) curve is well posed (§3-§4)
//   granbench steady     --angle 28.5 --h0 0.004        the steady uniform Bagnold state (§5, §7)
//   granbench dispersion --angle 28.5 --h0 0.004 --Lx 0.08   exact linear theory (7.11)
//
// Exit codes (also in --help): 0 success, 2 bad input (one line naming the option and its valid
// range), 3 a run that failed (diverged), 130/143 interrupted by SIGINT/SIGTERM with what was
// computed kept, 1 an internal error.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <iostream>

#include "analysis/cli/cli_common.hpp"
#include "analysis/cli/commands.hpp"
#include "analysis/cli/config_file.hpp"
#include "analysis/cli/heap_pages.hpp"
#include "analysis/cli/shipped_files.hpp"
#include "analysis/cli/suggest.hpp"
#include "common/provenance.hpp"

namespace {

using namespace granbench::cli;

const char* const kFooter = R"(Examples:
  granbench steady --angle 28.5 --h0 0.004 --json
  granbench dispersion --Lx 0.08 --out dispersion.h5
  granbench run --model twod --nx 160 --nz 64 --t-end 4 --out run.h5
  granbench sweep --model depthavg --Lx 0.03:0.4:12 --out sweep.h5
  granbench steady --config flow.toml --print-config

Every subcommand takes --config FILE.toml (its keys are the long options without '--', at the
top or under a [<subcommand>] section; the command line overrides them) and --print-config.
`granbench <command> --help` lists the options of one command.

Exit codes:
  0    success
  2    bad input: one line on stderr names the option and its valid range; nothing is written
  3    a run failed (diverged, or a point of a sweep did not complete); what was computed is kept
  130  interrupted by Ctrl-C (SIGINT); what was computed is kept
  143  stopped by SIGTERM; what was computed is kept
  1    an internal error (please report it))";

// A subcommand name that is not one: "unknown command 'X'" with the closest valid one.
void check_command_name(const std::vector<std::string>& args, const CLI::App& app) {
  auto first = args.begin();
  while (first != args.end() && first->rfind("-", 0) == 0)
    first += *first == "--config" && first + 1 != args.end() ? 2 : 1;  // skip its file name
  if (first == args.end()) return;
  std::vector<std::string> names;
  for (const CLI::App* s : app.get_subcommands([](const CLI::App*) { return true; }))
    names.push_back(s->get_name());
  if (std::find(names.begin(), names.end(), *first) != names.end()) return;
  std::string list;
  for (const auto& n : names) list += (list.empty() ? "" : ",") + n;
  const auto guess = closest_name(*first, names);
  throw UsageError("unknown command '" + *first + "'" +
                   (guess ? " (did you mean '" + *guess + "'?)" : std::string()) +
                   "; valid commands {" + list + "} (granbench --help)");
}

// An option that came from a --config file is named with its file and line in errors.
std::string with_origin(const std::string& message, const ExpandedArgs& expanded) {
  const std::string option = message.substr(0, message.find(':'));
  const auto at = expanded.origins.find(option);
  return at == expanded.origins.end() ? message : message + " (from --config " + at->second + ")";
}

}  // namespace

int main(int argc, char** argv) {
  granbench::cli::use_huge_pages_for_the_heap();
  CLI::App app{"granbench: depth-averaged and 2D mu(I) chute flows against exact theory"};
  app.require_subcommand(1);
  app.footer(kFooter);
  app.set_version_flag("--version", "granbench " + granbench::granbench_version() + " (commit " +
                                        granbench::granbench_git_commit() + ", " +
                                        granbench::granbench_code_target() +
                                        " code)\ncases: " + granbench::cli::shipped_cases_dir() +
                                        "\nplots: " + granbench::cli::shipped_plot_dir());
  add_wellposed_command(app);
  add_steady_command(app);
  add_dispersion_command(app);
  add_run_command(app);
  add_sweep_command(app);
  add_compare_command(app);
  add_case_command(app);
  ExpandedArgs expanded;
  try {
    std::vector<std::string> args(argv + 1, argv + argc);
    check_command_name(args, app);
    // Options from --config files become ordinary options first (config_file.hpp).
    expanded = expand_config_files(args, app);
    if (expanded.print_config)  // parse and show, but run nothing
      for (CLI::App* s : app.get_subcommands([](CLI::App*) { return true; })) s->callback([] {});
    args = expanded.args;
    std::reverse(args.begin(), args.end());  // CLI11 parses a reversed vector
    app.parse(args);
    if (expanded.print_config) std::cout << effective_options_toml(*app.get_subcommands().front());
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "granbench: error: " << with_origin(e.what(), expanded) << "\n";
    return 2;
  } catch (const UsageError& e) {
    std::cerr << "granbench: error: " << with_origin(e.what(), expanded) << "\n";
    return 2;
  } catch (const granbench::cli::CommandFailed& e) {
    std::cerr << "granbench: " << e.what() << "\n";
    return e.exit_code;
  } catch (const std::exception& e) {
    std::cerr << "granbench: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
