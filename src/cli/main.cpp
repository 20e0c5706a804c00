// The command line: each command registers its own options (src/cli/X_command.hpp); main parses,
// runs the command parsed and prints its error, once.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <new>
#include <string>

#include "cli/bench_command.hpp"
#include "cli/check_command.hpp"
#include "cli/command.hpp"
#include "cli/diff_command.hpp"
#include "cli/join_command.hpp"
#include "cli/plan_command.hpp"
#include "cli/render_command.hpp"
#include "cli/simulate_command.hpp"
#include "sys/process.hpp"

int main(int argc, char** argv) {
  using namespace tumble::cli;
  tumble::sys::set_up_process();
  CLI::App app{"tumble: rigid-body scenes to frames and video, headless"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("tumble ") + TUMBLE_VERSION,
                       "Print tumble's version and exit");
  Commands commands;
  add_simulate_command(app, commands);
  add_render_command(app, commands);
  add_plan_command(app, commands);
  add_join_command(app, commands);
  add_diff_command(app, commands);
  add_bench_command(app, commands);
  add_check_command(app, commands);

  if (argc < 2) {
    std::fputs(app.help().c_str(), stderr);
    return tumble::kExitBadInput;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    const int code = app.exit(error);
    return code == 0 ? tumble::kExitOk : tumble::kExitBadInput;
  }
  try {
    const CommandResult code = run_parsed(commands);
    if (code) return *code;
    std::fprintf(stderr, "tumble: %s\n", code.error().c_str());
  } catch (const std::bad_alloc&) {
    std::fputs("tumble: out of memory\n", stderr);
  } catch (const std::exception& error) {  // a last resort: commands return their errors
    std::fprintf(stderr, "tumble: %s\n", error.what());
  }
  return tumble::kExitBadInput;
}
