// `tumble diff A B [options]`: its options; the comparison itself is diff::run_diff
// (diff/diff_command.hpp).
#pragma once

#include "cli/command.hpp"

namespace tumble::cli {

void add_diff_command(CLI::App& app, Commands& commands);

}  // namespace tumble::cli
