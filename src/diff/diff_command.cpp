#include "diff/diff_command.hpp"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>

#include "diff/diff_inputs.hpp"
#include "diff/diff_outputs.hpp"
#include "diff/diff_run.hpp"
#include "diff/diff_text.hpp"
#include "diff/image_diff.hpp"
#include "io/image.hpp"
#include "io/png_io.hpp"

namespace tumble::diff {
namespace {

std::string size_text(const io::Image& image) {
  return std::to_string(image.width) + "x" + std::to_string(image.height);
}

// The threshold in the metric's unit, checked against its range; the error says why it is
// refused.
Result<double> parse_threshold(diff::DiffMetric metric, const std::string& text) {
  if (text.empty()) return diff::default_threshold(metric);
  if (metric == diff::DiffMetric::max) {
    long long whole = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), whole);
    if (error != std::errc() || end != text.data() + text.size() || whole < 0 || whole > 255) {
      return Error{"--threshold: expected a whole number from 0 to 255, got " + text};
    }
    return static_cast<double>(whole);
  }
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  const double top = metric == diff::DiffMetric::rms    ? 255.0
                     : metric == diff::DiffMetric::psnr ? 1000.0
                                                        : 1.0;
  if (end == text.c_str() || *end != '\0' || !std::isfinite(value) || value < 0 || value > top) {
    return Error{"--threshold: expected a number from 0 to " +
                 std::to_string(static_cast<int>(top)) + " for --metric " +
                 diff::diff_metric_name(metric) + ", got " + text};
  }
  return value;
}

// The options as criteria for one frame; the error says why they do not fit together.
Result<diff::FrameCriteria> criteria_from(const DiffCommandOptions& options) {
  const std::optional<diff::DiffMetric> metric = diff::diff_metric_named(options.metric);
  if (!metric) {
    return Error{"--metric: expected max, rms, perceptual, ssim or psnr, got " + options.metric};
  }
  diff::FrameCriteria criteria;
  criteria.metric = *metric;
  const Result<double> threshold = parse_threshold(*metric, options.threshold);
  if (!threshold) return Error{threshold.error()};
  criteria.threshold = *threshold;
  const bool per_pixel = diff::counts_pixels(*metric);
  if (!per_pixel && (options.max_pixels || options.max_percent || options.ignore_antialiasing)) {
    return Error{std::string("--max-pixels, --max-percent and --ignore-antialiasing judge pixels: "
                             "they apply to --metric max and perceptual, not ") +
                 diff::diff_metric_name(*metric)};
  }
  criteria.ignore_antialiasing =
      options.ignore_antialiasing.value_or(*metric == diff::DiffMetric::perceptual);
  criteria.max_pixels = options.max_pixels.value_or(0);
  criteria.max_percent = options.max_percent.value_or(-1.0);
  return criteria;
}

// Writes the --json, --junit and --report outputs asked for, stopping at the first that fails.
Result<void> write_outputs(const DiffCommandOptions& options, const DiffSubject& subject,
                           const SequenceDiff& diff) {
  Result<void> written = Result<void>::success();
  if (!options.json.empty()) written = write_diff_json(options.json, subject, diff);
  if (written && !options.junit.empty()) written = write_diff_junit(options.junit, subject, diff);
  if (written && !options.report.empty()) {
    written = write_diff_report(options.report, subject, diff);
  }
  return written;
}

Result<ExitCode> diff_images(const DiffCommandOptions& options, const SequenceOptions& settings,
                             std::FILE* out) {
  Result<io::Image> first = io::read_png(options.first_path);
  if (!first) return Error{first.error()};
  Result<io::Image> second = io::read_png(options.second_path);
  if (!second) return Error{second.error()};
  if (first->width != second->width || first->height != second->height) {
    return Error{"cannot compare images of different sizes: " + options.first_path + " is " +
                 size_text(*first) + ", " + options.second_path + " is " + size_text(*second)};
  }
  const io::Image picture = options.out.empty()
                                ? io::Image()
                                : diff::difference_picture(*first, *second, settings.criteria);
  const Result<SequenceDiff> compared =
      compare_pair(std::move(*first), std::move(*second), options.second_path, settings);
  if (!compared) return Error{compared.error()};
  const SequenceDiff& diff = *compared;
  std::fprintf(out, "%s\n", outcome_text(diff.frames.front(), settings.criteria).c_str());
  std::fflush(out);
  if (!options.out.empty()) {
    if (const Result<void> written = io::write_png(options.out, picture); !written) {
      return Error{written.error()};
    }
  }
  const Result<void> written =
      write_outputs(options, {options.first_path, options.second_path, settings.criteria}, diff);
  if (!written) return Error{written.error()};
  return diff.match() ? kExitOk : kExitMismatch;
}

Result<ExitCode> diff_sequences(const DiffCommandOptions& options, const SequenceOptions& settings,
                                std::FILE* out) {
  Result<DiffInput> first = resolve_diff_input(options.first_path);
  if (!first) return Error{first.error()};
  Result<DiffInput> second = resolve_diff_input(options.second_path);
  if (!second) return Error{second.error()};
  const Result<SequenceDiff> compared = compare_sequences(*first, *second, settings);
  if (!compared) return Error{compared.error()};
  const SequenceDiff& diff = *compared;
  if (diff.frames.empty()) {
    return Error{"--frames " + std::to_string(settings.first_frame) + ":" +
                 std::to_string(settings.end_frame) + ": no such frames (A has " +
                 std::to_string(diff.first_count) + ", B has " + std::to_string(diff.second_count) +
                 ")"};
  }
  for (const FrameOutcome& frame : diff.frames) {
    if (!frame.match) {
      std::fprintf(out, "%s: %s\n", frame.name.c_str(),
                   outcome_text(frame, settings.criteria).c_str());
    }
  }
  std::fprintf(out, "%s (%s)\n", verdict_text(diff).c_str(),
               criteria_text(settings.criteria).c_str());
  if (!diff.adaptation.empty()) std::fprintf(out, "note: %s\n", diff.adaptation.c_str());
  std::fflush(out);
  const Result<void> written =
      write_outputs(options, {options.first_path, options.second_path, settings.criteria}, diff);
  if (!written) return Error{written.error()};
  return diff.match() ? kExitOk : kExitMismatch;
}

}  // namespace

Result<SequenceOptions> diff_settings(const DiffCommandOptions& options) {
  SequenceOptions settings;
  const Result<diff::FrameCriteria> criteria = criteria_from(options);
  if (!criteria) return Error{criteria.error()};
  settings.criteria = *criteria;
  settings.keep_images = !options.report.empty();
  if (options.frames) {
    const auto [first_frame, end_frame] = *options.frames;
    if (first_frame < 0 || end_frame <= first_frame) {
      return Error{"--frames: expected A:B with 0 <= A < B, got " + std::to_string(first_frame) +
                   ":" + std::to_string(end_frame)};
    }
    settings.first_frame = first_frame;
    settings.end_frame = end_frame;
  }
  return settings;
}

Result<ExitCode> run_diff(const DiffCommandOptions& options, std::FILE* out) {
  const Result<SequenceOptions> settings = diff_settings(options);
  if (!settings) return Error{settings.error()};
  const bool images = names_png(options.first_path) || names_png(options.second_path);
  if (images && options.frames) {
    return Error{"--frames selects frames of folders and videos, not of two PNGs"};
  }
  if (!images && !options.out.empty()) {
    return Error{
        "--out writes the difference of two PNGs; for folders and videos use --report FOLDER"};
  }
  return images ? diff_images(options, *settings, out) : diff_sequences(options, *settings, out);
}

}  // namespace tumble::diff
