// `tumble render`: a scene to PNG frames and an MP4, off-screen.
#pragma once

#include <cstdio>
#include <optional>

#include "cli/command.hpp"
#include "diff/diff_command.hpp"  // DiffCommandOptions
#include "job/render_job.hpp"     // RenderOptions

namespace tumble::cli {

// Runs the command; progress and messages go to `err`. With `golden` (--golden DIR and the diff
// options), the finished render is then compared with DIR (job/render_golden.hpp), whose figures
// go to `out`.
CommandResult run_render(const job::RenderOptions& options,
                         const std::optional<diff::DiffCommandOptions>& golden, std::FILE* out,
                         std::FILE* err);

// `tumble render SCENE [options]`: the overrides of the scene's settings, the frames, the
// outputs, --golden and tumble diff's options.
void add_render_command(CLI::App& app, Commands& commands);

}  // namespace tumble::cli
