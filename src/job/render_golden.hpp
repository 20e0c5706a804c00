// `tumble render --golden DIR`: a render checked against a stored golden render in one step, the
// way `tumble diff DIR <the new render's folder>` checks it, with the same options, outputs
// (--report, --junit, --json) and exit codes (0 match, 1 mismatch, 2 error).
#pragma once

#include <cstdio>

#include "common/exit_codes.hpp"
#include "common/result.hpp"
#include "diff/diff_command.hpp"  // DiffCommandOptions
#include "job/render_job.hpp"

namespace tumble::job {

// Checked before rendering, so that a mistake costs no render: the golden (`golden.first_path`)
// is a folder of frames, a render's folder or a video; the comparison options are sound; and the
// golden lies outside the folder the render replaces. The error names the path.
Result<void> check_golden(const diff::DiffCommandOptions& golden, const RenderJob& job);

// After a successful render: compares the golden (A, the expected) with what the job wrote into
// its folder (B): its frames, or its video when it wrote no frames. A render of a frame range is
// compared over that range only. Returns what run_diff returns.
Result<ExitCode> compare_with_golden(diff::DiffCommandOptions golden, const RenderJob& job,
                                     std::FILE* out);

}  // namespace tumble::job
