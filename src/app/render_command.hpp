// `tumble render`: a scene to PNG frames and an MP4, off-screen.
#pragma once

#include <cstdio>

#include "app/render_job.hpp"  // RenderOptions

namespace tumble::app {

// Runs the command; progress and messages go to `err`. Returns the process exit code.
int run_render(const RenderOptions& options, std::FILE* err);

}  // namespace tumble::app
