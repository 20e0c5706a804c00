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

bool read(const std::string& path, io::Image& image, std::FILE* err) {
  Result<io::Image> read = io::read_png(path);
  if (!read) {
    std::fprintf(err, "tumble: %s\n", read.error().c_str());
    return false;
  }
  image = std::move(read).value();
  return true;
}

// The threshold in the metric's unit, checked against its range: "" or why it is refused.
std::string parse_threshold(diff::DiffMetric metric, const std::string& text, double& out) {
  if (text.empty()) {
    out = diff::default_threshold(metric);
    return {};
  }
  if (metric == diff::DiffMetric::max) {
    long long whole = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), whole);
    if (error != std::errc() || end != text.data() + text.size() || whole < 0 || whole > 255) {
      return "--threshold: expected a whole number from 0 to 255, got " + text;
    }
    out = static_cast<double>(whole);
    return {};
  }
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  const double top = metric == diff::DiffMetric::rms    ? 255.0
                     : metric == diff::DiffMetric::psnr ? 1000.0
                                                        : 1.0;
  if (end == text.c_str() || *end != '\0' || !std::isfinite(value) || value < 0 || value > top) {
    return "--threshold: expected a number from 0 to " + std::to_string(static_cast<int>(top)) +
           " for --metric " + diff::diff_metric_name(metric) + ", got " + text;
  }
  out = value;
  return {};
}

// The options as criteria for one frame: "" or why they do not fit together.
std::string criteria_from(const DiffCommandOptions& options, diff::FrameCriteria& criteria) {
  const std::optional<diff::DiffMetric> metric = diff::diff_metric_named(options.metric);
  if (!metric)
    return "--metric: expected max, rms, perceptual, ssim or psnr, got " + options.metric;
  criteria.metric = *metric;
  if (std::string error = parse_threshold(*metric, options.threshold, criteria.threshold);
      !error.empty()) {
    return error;
  }
  const bool per_pixel = diff::counts_pixels(*metric);
  if (!per_pixel && (options.max_pixels || options.max_percent || options.ignore_antialiasing)) {
    return std::string(
               "--max-pixels, --max-percent and --ignore-antialiasing judge pixels: they "
               "apply to --metric max and perceptual, not ") +
           diff::diff_metric_name(*metric);
  }
  criteria.ignore_antialiasing =
      options.ignore_antialiasing.value_or(*metric == diff::DiffMetric::perceptual);
  criteria.max_pixels = options.max_pixels.value_or(0);
  criteria.max_percent = options.max_percent.value_or(-1.0);
  return {};
}

// Writes the --json, --junit and --report outputs asked for; false after printing an error.
bool write_outputs(const DiffCommandOptions& options, const DiffSubject& subject,
                   const SequenceDiff& diff, std::FILE* err) {
  Result<void> written = Result<void>::success();
  if (!options.json.empty()) written = write_diff_json(options.json, subject, diff);
  if (written && !options.junit.empty()) written = write_diff_junit(options.junit, subject, diff);
  if (written && !options.report.empty()) {
    written = write_diff_report(options.report, subject, diff);
  }
  if (!written) std::fprintf(err, "tumble: %s\n", written.error().c_str());
  return written.ok();
}

int diff_images(const DiffCommandOptions& options, const SequenceOptions& settings, std::FILE* out,
                std::FILE* err) {
  io::Image first;
  io::Image second;
  if (!read(options.first_path, first, err) || !read(options.second_path, second, err)) {
    return kExitBadInput;
  }
  if (first.width != second.width || first.height != second.height) {
    std::fprintf(err, "tumble: cannot compare images of different sizes: %s is %s, %s is %s\n",
                 options.first_path.c_str(), size_text(first).c_str(), options.second_path.c_str(),
                 size_text(second).c_str());
    return kExitBadInput;
  }
  const io::Image picture = options.out.empty()
                                ? io::Image()
                                : diff::difference_picture(first, second, settings.criteria);
  const SequenceDiff diff = compare_pair(first, second, options.second_path, settings);
  std::fprintf(out, "%s\n", outcome_text(diff.frames.front(), settings.criteria).c_str());
  std::fflush(out);
  if (!options.out.empty()) {
    if (const Result<void> written = io::write_png(options.out, picture); !written) {
      std::fprintf(err, "tumble: %s\n", written.error().c_str());
      return kExitBadInput;
    }
  }
  if (!write_outputs(options, {options.first_path, options.second_path, settings.criteria}, diff,
                     err)) {
    return kExitBadInput;
  }
  return diff.match() ? kExitOk : kExitMismatch;
}

int diff_sequences(const DiffCommandOptions& options, const SequenceOptions& settings,
                   std::FILE* out, std::FILE* err) {
  DiffInput first, second;
  for (auto [path, input] :
       {std::pair{&options.first_path, &first}, {&options.second_path, &second}}) {
    Result<DiffInput> resolved = resolve_diff_input(*path);
    if (!resolved) {
      std::fprintf(err, "tumble: %s\n", resolved.error().c_str());
      return kExitBadInput;
    }
    *input = std::move(resolved).value();
  }
  const SequenceDiff diff = compare_sequences(first, second, settings);
  if (!diff.error.empty()) {
    std::fprintf(err, "tumble: %s\n", diff.error.c_str());
    return kExitBadInput;
  }
  if (diff.frames.empty()) {
    std::fprintf(
        err, "tumble: --frames %lld:%lld: no such frames (A has %lld, B has %lld)\n",
        static_cast<long long>(settings.first_frame), static_cast<long long>(settings.end_frame),
        static_cast<long long>(diff.first_count), static_cast<long long>(diff.second_count));
    return kExitBadInput;
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
  if (!write_outputs(options, {options.first_path, options.second_path, settings.criteria}, diff,
                     err)) {
    return kExitBadInput;
  }
  return diff.match() ? kExitOk : kExitMismatch;
}

}  // namespace

Result<SequenceOptions> diff_settings(const DiffCommandOptions& options) {
  SequenceOptions settings;
  if (std::string error = criteria_from(options, settings.criteria); !error.empty()) {
    return Error{error};
  }
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

int run_diff(const DiffCommandOptions& options, std::FILE* out, std::FILE* err) {
  const Result<SequenceOptions> settings = diff_settings(options);
  if (!settings) {
    std::fprintf(err, "tumble: %s\n", settings.error().c_str());
    return kExitBadInput;
  }
  const bool images = names_png(options.first_path) || names_png(options.second_path);
  if (images && options.frames) {
    std::fprintf(err, "tumble: --frames selects frames of folders and videos, not of two PNGs\n");
    return kExitBadInput;
  }
  if (!images && !options.out.empty()) {
    std::fprintf(err,
                 "tumble: --out writes the difference of two PNGs; for folders and videos "
                 "use --report FOLDER\n");
    return kExitBadInput;
  }
  return images ? diff_images(options, *settings, out, err)
                : diff_sequences(options, *settings, out, err);
}

}  // namespace tumble::diff
