// `tumble simulate`: run a scene's physics and print the states as CSV.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>

#include "cli/command.hpp"

namespace tumble::cli {

struct SimulateOptions {
  std::string scene_path;
  std::string out = "-";   // a file path, or "-" for standard output
  std::int64_t every = 1;  // write a row every N steps (plus t = 0 and the last step)
};

// Runs the command; warnings and the note of a stop by a signal go to `err`.
CommandResult run_simulate(const SimulateOptions& options, std::FILE* err);

// `tumble simulate SCENE [--out CSV] [--every N]`.
void add_simulate_command(CLI::App& app, Commands& commands);

}  // namespace tumble::cli
