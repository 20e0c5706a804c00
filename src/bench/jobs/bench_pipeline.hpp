// `tumble bench pipeline`: the same scene rendered several ways in one run, to show what the
// pipelined frame path buys over the obvious ways of making a video.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>

#include "common/exit_codes.hpp"
#include "common/result.hpp"

namespace tumble::bench {

struct BenchPipelineOptions {
  std::string scene_path;  // "" = a built-in lit, shadowed spinning cube over a gridded ground
  int width = 1280;
  int height = 720;
  std::int64_t frames = 300;
  int msaa = 0;  // samples per pixel; 0 = as the scene says, as `tumble render` draws it
  std::string out = "output/bench";  // pipeline.md goes here; frames are written and removed
  // > 0: instead of the paths, the whole render against this many chunks (app/bench_chunks.hpp)
  std::int64_t chunks = 0;
};

// Prints a table of frames/s per path and their ratios (or, with `chunks`, of the chunks' costs
// against the whole render's) and writes it to OUT/pipeline.md, with progress on `err`. Returns
// kExitOk, or kExitInterrupted + N after saying it was stopped by signal N.
Result<ExitCode> run_bench_pipeline(const BenchPipelineOptions& options, std::FILE* out,
                                    std::FILE* err);

}  // namespace tumble::bench
