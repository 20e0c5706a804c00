// What every command of src/cli/ is to main: a subcommand that registered its own options, and
// what runs it once the command line is parsed. Each X_command.cpp exposes
// `void add_X_command(CLI::App& app, Commands& commands)`, which adds the subcommand to `app`,
// binds its options to values the run closure owns, and appends the pair to `commands`.
#pragma once

#include <functional>
#include <vector>

#include "common/exit_codes.hpp"
#include "common/result.hpp"

namespace CLI {
class App;
}

namespace tumble::cli {

// The exit code of a command that ran (kExitOk, kExitMismatch, kExitInterrupted + N, or
// kExitBadInput after it said why itself), or an error main prints once, as
// "tumble: <message>", exiting with kExitBadInput.
using CommandResult = Result<ExitCode>;

struct Command {
  const CLI::App* app;  // run when this subcommand was parsed
  std::function<CommandResult()> run;
};
using Commands = std::vector<Command>;

// Runs the command that was parsed, then checks that what it printed reached standard output
// (`tumble check s.toml > /dev/full` must not succeed, nor `diff` report a mismatch nobody saw).
CommandResult run_parsed(const Commands& commands);

}  // namespace tumble::cli
