// `tumble diff`: compare two PNGs, two folders of frames (or renders' output folders), two videos,
// or a video and a folder, frame by frame within a tolerance, for golden-image checks.
#pragma once

#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <utility>

#include "common/exit_codes.hpp"
#include "common/result.hpp"
#include "diff/diff_run.hpp"

namespace tumble::diff {

struct DiffCommandOptions {
  std::string first_path;                   // A, the expected frames
  std::string second_path;                  // B, the actual frames
  std::string metric = "max";               // max, rms, perceptual, ssim or psnr (diff::DiffMetric)
  std::string threshold;                    // in the metric's unit; empty for its default
  std::optional<bool> ignore_antialiasing;  // unset: on for perceptual only
  std::optional<std::int64_t> max_pixels;   // a frame matches when at most this many differ (0)
  std::optional<double> max_percent;        // or at most this share of its pixels (%)
  std::optional<std::pair<long long, long long>> frames;  // compare frames A to B-1 only
  std::string out;     // two PNGs: where to write the diff image; empty for none
  std::string report;  // folder for the HTML report; empty for none
  std::string junit;   // JUnit XML file; empty for none
  std::string json;    // JSON file with every figure; empty for none
};

// The options checked (metric, threshold in its unit, pixel limits, frame range) as the criteria
// of a comparison: the error names the option. run_diff starts with it; `render --golden` calls
// it before rendering, so a bad option costs no render.
Result<SequenceOptions> diff_settings(const DiffCommandOptions& options);

// Prints figures to `out` (one line for two PNGs; for sequences a line per failing frame and a
// summary). Returns kExitOk when everything matches and kExitMismatch when not; fails when the
// inputs cannot be compared or an output cannot be written.
Result<ExitCode> run_diff(const DiffCommandOptions& options, std::FILE* out);

}  // namespace tumble::diff
