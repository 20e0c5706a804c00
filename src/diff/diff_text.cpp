#include "diff/diff_text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace tumble::diff {
namespace {

std::string number_text(const char* format, double value) {
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

std::string pixel_count_text(const diff::FrameFigures& figures,
                             const diff::FrameCriteria& criteria) {
  std::string text = std::to_string(figures.differing_pixels) + " of " +
                     std::to_string(figures.pixels) + " pixels differ (" +
                     percent_text(figures.differing_pixels, figures.pixels) + ")";
  if (criteria.ignore_antialiasing) {
    text += ", " + std::to_string(figures.antialiased_pixels) + " anti-aliased ignored";
  }
  if (figures.quantised_pixels) {
    text += ", " + std::to_string(*figures.quantised_pixels) + " within the video's quantisation";
  }
  return text;
}

std::string psnr_text(double psnr) {
  return std::isinf(psnr) ? "PSNR inf dB" : number_text("PSNR %.2f dB", psnr);
}

}  // namespace

std::string percent_text(std::int64_t part, std::int64_t whole) {
  const double percent = 100.0 * static_cast<double>(part) / static_cast<double>(whole);
  const int decimals =
      percent > 0.0 ? std::max(0, 2 - static_cast<int>(std::floor(std::log10(percent)))) : 0;
  char text[64];
  std::snprintf(text, sizeof text, "%.*f%%", decimals, percent);
  return text;
}

std::string figures_text(const diff::FrameFigures& figures, const diff::FrameCriteria& criteria) {
  const std::string largest =
      "largest channel difference " + std::to_string(figures.max_channel_difference);
  const std::string rms = number_text("RMS %.4g", figures.rms);
  switch (criteria.metric) {
    case diff::DiffMetric::max:
    case diff::DiffMetric::perceptual:
      return pixel_count_text(figures, criteria) + ", " + largest + ", " + rms;
    case diff::DiffMetric::rms:
      return rms + ", " + largest;
    case diff::DiffMetric::ssim:
      return number_text("SSIM %.5f", figures.ssim.value_or(0.0)) + ", " + rms;
    case diff::DiffMetric::psnr:
      return psnr_text(figures.psnr) + ", " + rms;
  }
  return {};
}

std::string outcome_text(const FrameOutcome& outcome, const diff::FrameCriteria& criteria) {
  std::string text = outcome.match ? "match" : "mismatch";
  if (!outcome.problem.empty()) text += ": " + outcome.problem;
  if (outcome.figures) text += ": " + figures_text(*outcome.figures, criteria);
  return text;
}

std::string markup_text(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        const bool control = static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n';
        out += control ? '?' : c;
    }
  }
  return out;
}

std::string verdict_text(const SequenceDiff& diff) {
  std::size_t failing = 0;
  for (const FrameOutcome& frame : diff.frames) failing += !frame.match;
  std::string text = std::string(diff.match() ? "match" : "mismatch") + ": " +
                     std::to_string(failing) + " of " + std::to_string(diff.frames.size()) +
                     " frames differ";
  if (diff.first_count != diff.second_count) {
    text += "; A has " + std::to_string(diff.first_count) + " frames, B has " +
            std::to_string(diff.second_count);
  }
  return text;
}

std::string criteria_text(const diff::FrameCriteria& criteria) {
  const std::string threshold = number_text("%g", criteria.threshold);
  switch (criteria.metric) {
    case diff::DiffMetric::max:
      return "max, threshold " + threshold + " (channel levels 0-255)";
    case diff::DiffMetric::rms:
      return "rms, threshold " + threshold + " (channel levels 0-255)";
    case diff::DiffMetric::perceptual:
      return "perceptual, threshold " + threshold + " (YIQ distance 0-1)";
    case diff::DiffMetric::ssim:
      return "ssim, threshold " + threshold + " (mean SSIM 0-1)";
    case diff::DiffMetric::psnr:
      return "psnr, threshold " + threshold + " dB";
  }
  return {};
}

}  // namespace tumble::diff
