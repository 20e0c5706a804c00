#include "diff/diff_outputs.hpp"

#include <cstdio>

#include "io/atomic_file.hpp"
#include "io/json_text.hpp"

namespace tumble::diff {
namespace {

std::string figures_json(const diff::FrameFigures& figures) {
  return "{\"pixels\": " + std::to_string(figures.pixels) +
         ", \"differing_pixels\": " + std::to_string(figures.differing_pixels) +
         ", \"antialiased_pixels\": " + std::to_string(figures.antialiased_pixels) +
         ", \"quantised_pixels\": " +
         (figures.quantised_pixels ? std::to_string(*figures.quantised_pixels) : "null") +
         ", \"max_channel_difference\": " + std::to_string(figures.max_channel_difference) +
         ", \"rms\": " + io::json_number(figures.rms) +
         ", \"psnr_db\": " + io::json_number(figures.psnr) +
         ", \"ssim\": " + (figures.ssim ? io::json_number(*figures.ssim) : "null") + "}";
}

std::string frame_json(const FrameOutcome& frame) {
  return "    {\"index\": " + std::to_string(frame.index) +
         ", \"name\": " + io::json_string(frame.name) +
         ", \"match\": " + (frame.match ? "true" : "false") +
         ", \"problem\": " + (frame.problem.empty() ? "null" : io::json_string(frame.problem)) +
         ", \"figures\": " + (frame.figures ? figures_json(*frame.figures) : "null") + "}";
}

}  // namespace

Result<void> write_diff_json(const std::string& path, const DiffSubject& subject,
                             const SequenceDiff& diff) {
  const diff::FrameCriteria& criteria = subject.criteria;
  std::string text =
      "{\n  \"first\": " + io::json_string(subject.first_path) +
      ",\n  \"second\": " + io::json_string(subject.second_path) +
      ",\n  \"metric\": " + io::json_string(diff::diff_metric_name(criteria.metric)) +
      ",\n  \"threshold\": " + io::json_number(criteria.threshold) +
      ",\n  \"ignore_antialiasing\": " + (criteria.ignore_antialiasing ? "true" : "false") +
      ",\n  \"max_pixels\": " + std::to_string(criteria.max_pixels) + ",\n  \"max_percent\": " +
      (criteria.max_percent < 0 ? "null" : io::json_number(criteria.max_percent)) +
      ",\n  \"first_frames\": " + std::to_string(diff.first_count) +
      ",\n  \"second_frames\": " + std::to_string(diff.second_count) + ",\n  \"adaptation\": " +
      (diff.adaptation.empty() ? "null" : io::json_string(diff.adaptation)) +
      ",\n  \"match\": " + (diff.match() ? "true" : "false") + ",\n  \"frames\": [";
  for (std::size_t n = 0; n < diff.frames.size(); ++n) {
    text += (n ? ",\n" : "\n") + frame_json(diff.frames[n]);
  }
  text += "\n  ]\n}\n";
  return write_text_atomically(path, text);
}

Result<void> write_text_atomically(const std::string& path, const std::string& text) {
  Result<io::AtomicFile> file = io::AtomicFile::open(path);
  if (!file) return Error{file.error()};
  std::fwrite(text.data(), 1, text.size(), file->stream());  // commit() reports a failed write
  return file->commit();
}

}  // namespace tumble::diff
