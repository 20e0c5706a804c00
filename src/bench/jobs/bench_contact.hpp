// `tumble bench contact`: the pile of issue 12 (bench/pile.hpp) run by tumble and by Bullet 3.24
// in one run, their figures side by side with the ratios of their step times. tumble must not
// link Bullet, so Bullet's column comes from the contact_bench executable beside tumble's, run
// as a child process (`contact_bench --engine bullet --stream`); tumble's column runs in this
// process, before it, so that the two never share the cores.
#pragma once

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>

#include "bench/pile.hpp"
#include "common/exit_codes.hpp"
#include "common/result.hpp"

namespace tumble::bench {

struct BenchContactOptions {
  int bodies = 1000;  // boxes (or balls) in the pile
  PileShapes shapes = PileShapes::boxes;
  double seconds = 20.0;   // simulated time (s), rounded to whole steps of 1/60 s
  std::uint64_t seed = 1;  // of the boxes' sizes, orientations and velocities
  // "" for no files; else an existing folder for contact_bench.json and contact_bench.csv.
  std::string out;
  bool quiet = false;  // no progress on standard error
};

// Where tumble looks for contact_bench: beside its own executable (/proc/self/exe).
std::filesystem::path contact_bench_path();

// Prints the table on `out`, progress on `err`. Returns kExitOk with both columns (and the files,
// if asked for), and kExitBadInput, having said so on `err` before the run, when contact_bench
// is missing (tumble's column is still printed; no files are written). Fails when the folder of
// --out is missing or unwritable (before running), when contact_bench fails (tumble's column is
// still printed; no files are written), or when a file cannot be written.
Result<ExitCode> run_bench_contact(const BenchContactOptions& options, std::FILE* out,
                                   std::FILE* err);

}  // namespace tumble::bench
