// `tumble check SCENE`: load and validate a scene without running it, and print the stability
// advisor's warnings about its step and integrator.
#pragma once

#include <cstdio>
#include <string>

#include "common/exit_codes.hpp"

namespace tumble::cli {

struct CheckOptions {
  std::string scene_path;
};

// Warnings and a closing summary line go to `out`, a load error to `err`. Returns kExitOk for a
// valid scene (warnings or not) and kExitBadInput for one that does not load.
int run_check(const CheckOptions& options, std::FILE* out, std::FILE* err);

}  // namespace tumble::cli
