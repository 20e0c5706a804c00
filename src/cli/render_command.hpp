// `tumble render`: a scene to PNG frames and an MP4, off-screen.
#pragma once

#include <cstdio>
#include <optional>

#include "diff/diff_command.hpp"  // DiffCommandOptions
#include "job/render_job.hpp"     // RenderOptions

namespace tumble::cli {

// Runs the command; progress and messages go to `err`. With `golden` (--golden DIR and the diff
// options), the finished render is then compared with DIR (app/render_golden.hpp), whose figures
// go to `out`. Returns the process exit code.
int run_render(const job::RenderOptions& options,
               const std::optional<diff::DiffCommandOptions>& golden, std::FILE* out,
               std::FILE* err);

}  // namespace tumble::cli
