// `tumble bench pipeline --chunks N`: what cutting a render into N chunks costs. The whole
// render and each chunk run in a process of their own, one after another (forked from the
// benchmark before it creates any OpenGL context, so each pays its own context, shaders and
// Mesa's start-up, as a farm's processes do), and their CPU is read from the kernel (wait4).
#pragma once

#include <cstdint>
#include <cstdio>
#include <filesystem>

#include "job/render_job.hpp"

namespace tumble::bench {

// Renders `job` whole and as `chunks` chunks (app/chunk_plan.hpp) into folders below `scratch`,
// with progress on `err`, and returns the table (Markdown); an error names what failed.
Result<std::string> bench_chunks(const job::RenderJob& job, std::int64_t chunks,
                                 const std::filesystem::path& scratch, std::FILE* err);

}  // namespace tumble::bench
