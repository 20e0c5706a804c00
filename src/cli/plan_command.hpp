// `tumble plan SCENE --chunks N | --chunk-frames K [--json]`: the frame ranges of a render cut
// into chunks for a render farm (GNU Parallel, a Slurm job array), one per line, as
// `tumble render --chunk I/N` renders them.
#pragma once

#include <cstdint>
#include <cstdio>
#include <optional>

#include "cli/command.hpp"
#include "job/render_job.hpp"  // RenderOptions

namespace tumble::cli {

struct PlanOptions {
  job::RenderOptions render;  // the scene and the overrides that change its frame count (--fps)
  std::optional<std::int64_t> chunks;        // --chunks N
  std::optional<std::int64_t> chunk_frames;  // --chunk-frames K: ceil(count / K) chunks
  bool json = false;
};

// The plan goes to `out`.
CommandResult run_plan(const PlanOptions& options, std::FILE* out);

// `tumble plan SCENE --chunks N | --chunk-frames K [--fps F] [--quality Q] [--json]`.
void add_plan_command(CLI::App& app, Commands& commands);

}  // namespace tumble::cli
