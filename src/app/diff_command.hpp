// `tumble diff`: compare two PNGs within a tolerance, for golden-image checks.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>

#include "app/exit_codes.hpp"

namespace tumble::app {

struct DiffCommandOptions {
  std::string first_path;
  std::string second_path;
  int threshold = 0;            // a pixel differs when a channel differs by more than this (0-255)
  std::int64_t max_pixels = 0;  // the images match when at most this many pixels differ
  std::string out;              // where to write the diff image; empty for none
};

// Prints one line of figures to `out` and messages to `err`. Returns kExitOk when the images
// match, kExitMismatch when they do not, kExitBadInput when they cannot be compared.
int run_diff(const DiffCommandOptions& options, std::FILE* out, std::FILE* err);

}  // namespace tumble::app
