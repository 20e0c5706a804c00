// `tumble bench accuracy`: speed against error of every integrator on the hard cases
// (bench/accuracy.hpp), written as a CSV, a Markdown report and a gnuplot chart. (`tumble bench
// pipeline`, the rendering path, is in bench_pipeline.hpp.)
#pragma once

#include <cstdio>
#include <string>

#include "cli/command.hpp"

namespace tumble::cli {

struct BenchAccuracyOptions {
  std::string out =
      "output/bench";  // folder for accuracy.csv, .md, .png (and the plot's .gp, .dat)
  bool quick = false;  // the reduced sweep of bench::quick_accuracy_settings()
};

// Progress lines go to `err`, the list of files written to `out`. Returns kExitOk, or an error
// when a file cannot be written or gnuplot is missing or fails (the CSV and the Markdown are
// written first, so they are there either way).
CommandResult run_bench_accuracy(const BenchAccuracyOptions& options, std::FILE* out,
                                 std::FILE* err);

// `tumble bench pipeline | accuracy | contact`, each with its options.
void add_bench_command(CLI::App& app, Commands& commands);

}  // namespace tumble::cli
