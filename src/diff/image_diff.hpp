// Comparing two images of the same size: figures for a pass/fail decision, and a picture of where
// they differ.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

#include "io/image.hpp"
#include "io/quantisation.hpp"

namespace tumble::diff {

struct DiffOptions {
  int threshold = 0;  // a pixel differs when any channel differs by more than this (0-255)
  std::int64_t max_pixels = 0;  // the images match when at most this many pixels differ
};

struct DiffResult {
  std::int64_t differing_pixels = 0;  // pixels with some channel difference above the threshold
  int max_channel_difference = 0;  // over all pixels and channels, whatever the threshold (0-255)
  double rms = 0.0;                // root mean square channel difference, all channels (0-255)
  bool match = true;               // differing_pixels <= max_pixels
};

// Precondition: a and b have the same width and height.
DiffResult compare_images(const io::Image& a, const io::Image& b, const DiffOptions& options);

// A picture of the differences, the size of a and b (precondition: equal sizes). Pixels within the
// threshold show a as grey at 30% brightness (R = G = B <= 76); differing pixels are pure red
// (G = B = 0), from 128 for a difference of 1 to 255 for 255, so even the smallest stands out.
io::Image diff_image(const io::Image& a, const io::Image& b, int threshold);

// How one frame pair is judged, each in its own unit:
// - max: a pixel differs when one of its channels differs by more than T levels (0-255);
// - rms: the frame differs when the RMS channel difference exceeds T levels (0-255), as
//   matplotlib's compare_images;
// - perceptual: a pixel differs when its YIQ colour distance exceeds T (0-1), as pixelmatch;
// - ssim: the frame differs when its mean SSIM is below T (0-1);
// - psnr: the frame differs when its PSNR over the RGB channels is below T (dB).
// max and perceptual count pixels; the frame then differs when too many do.
enum class DiffMetric { max, rms, perceptual, ssim, psnr };

// "max", "rms", "perceptual", "ssim", "psnr": the names on the command line and in reports.
const char* diff_metric_name(DiffMetric metric);
std::optional<DiffMetric> diff_metric_named(std::string_view name);
// Whether the metric decides per pixel (then --max-pixels, --max-percent and anti-aliasing apply).
bool counts_pixels(DiffMetric metric);
// The threshold when none is given: exact for max (0), one level for rms, pixelmatch's 0.1 for
// perceptual, 0.99 for ssim and 40 dB for psnr (x264 at tumble's crf 18 gives about 45 dB).
double default_threshold(DiffMetric metric);

struct FrameCriteria {
  DiffMetric metric = DiffMetric::max;
  double threshold = 0.0;            // in the metric's unit (see DiffMetric)
  bool ignore_antialiasing = false;  // max, perceptual: pixels on anti-aliased edges not counted
  std::int64_t max_pixels = 0;       // max, perceptual: the frame matches with at most this many
  double max_percent = -1.0;         // when >= 0, instead at most this share of pixels (%)
};

// Every figure of one frame pair. differing_pixels and antialiased_pixels are of the chosen
// metric's pixel test (0 for the frame-wide metrics); ssim is computed for the ssim metric only.
struct FrameFigures {
  std::int64_t pixels = 0;
  std::int64_t differing_pixels = 0;    // failing the pixel test and counted
  std::int64_t antialiased_pixels = 0;  // failing it but ignored as anti-aliased edges
  // perceptual against a video with an allowance: failing it but ignored as within the video's
  // quantisation (io/quantisation.hpp); unset otherwise
  std::optional<std::int64_t> quantised_pixels;
  int max_channel_difference = 0;  // levels (0-255)
  double rms = 0.0;                // RMS channel difference over R, G and B (levels)
  double psnr = 0.0;               // 10 log10(255² / MSE) (dB); +inf for identical images
  std::optional<double> ssim;      // mean SSIM (0-1), for the ssim metric
  bool match = true;
};

// Precondition: a and b have the same width and height. For perceptual, an active `allowance`
// (one of a and b is an H.264 video's frame, the other the picture it was encoded from) also
// forgives failing pixels in macroblocks whose difference is within the video's quantisation.
FrameFigures compare_frame(const io::Image& a, const io::Image& b, const FrameCriteria& criteria,
                           const io::QuantisationAllowance& allowance = {});

// How far past the criteria a frame is, to rank frames worst first: differing pixels for the
// pixel metrics, the RMS, 1 - SSIM or -PSNR for the others.
double badness(const FrameFigures& figures, DiffMetric metric);

// A picture of what compare_frame counted: a in dim grey, counted pixels red (brighter for
// larger channel differences, as diff_image), ignored anti-aliased pixels yellow, pixels ignored
// as within a video's quantisation blue. For the frame-wide metrics every pixel with a channel
// difference is red.
io::Image difference_picture(const io::Image& a, const io::Image& b, const FrameCriteria& criteria,
                             const io::QuantisationAllowance& allowance = {});

}  // namespace tumble::diff
