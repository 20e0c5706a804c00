// `tumble simulate`: run a scene's physics and print the states as CSV.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>

#include "common/exit_codes.hpp"

namespace tumble::cli {

struct SimulateOptions {
  std::string scene_path;
  std::string out = "-";   // a file path, or "-" for standard output
  std::int64_t every = 1;  // write a row every N steps (plus t = 0 and the last step)
};

// Runs the command; messages go to `err`. Returns the process exit code.
int run_simulate(const SimulateOptions& options, std::FILE* err);

}  // namespace tumble::cli
