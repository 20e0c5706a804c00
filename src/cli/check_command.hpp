// `tumble check SCENE`: load and validate a scene without running it, and print the stability
// advisor's warnings about its step and integrator.
#pragma once

#include <cstdio>
#include <string>

#include "cli/command.hpp"

namespace tumble::cli {

struct CheckOptions {
  std::string scene_path;
};

// Warnings and a closing summary line go to `out`. Returns kExitOk for a valid scene (warnings or
// not) and the load error for one that does not load.
CommandResult run_check(const CheckOptions& options, std::FILE* out);

// `tumble check SCENE`.
void add_check_command(CLI::App& app, Commands& commands);

}  // namespace tumble::cli
