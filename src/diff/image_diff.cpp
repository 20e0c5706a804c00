#include "diff/image_diff.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <vector>

#include "diff/perceptual_diff.hpp"
#include "diff/ssim.hpp"
#include "io/quantisation.hpp"

namespace tumble::diff {
namespace {

// The largest of a pixel's three channel differences (0-255).
int pixel_difference(const std::uint8_t* a, const std::uint8_t* b) {
  return std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}

// Rec. 601 luma in 8-bit fixed point (77 + 150 + 29 = 256), then 30% of it.
std::uint8_t dim_grey(const std::uint8_t* pixel) {
  const int luma = (77 * pixel[0] + 150 * pixel[1] + 29 * pixel[2]) >> 8;
  return static_cast<std::uint8_t>(luma * 3 / 10);
}

enum class PixelVerdict { same, differs, antialiased, quantised };

// What the pixel test of a counting metric needs besides the two images.
struct PixelTest {
  const FrameCriteria& criteria;
  double max_yiq_distance_squared;
  // perceptual against a video with an allowance: macroblocks_within's answer, else empty
  std::vector<std::uint8_t> quantised_blocks;

  PixelTest(const io::Image& a, const io::Image& b, const FrameCriteria& frame_criteria,
            const io::QuantisationAllowance& allowance)
      : criteria(frame_criteria),
        max_yiq_distance_squared(kMaxYiqDistanceSquared * criteria.threshold * criteria.threshold) {
    // max stays a test of channel levels as they are: only perceptual forgives the codec.
    if (criteria.metric == DiffMetric::perceptual && allowance.active()) {
      quantised_blocks = io::macroblocks_within(a, b, allowance);
    }
  }
};

// Whether a pixel passes the pixel test of a counting metric, and if not whether it is forgiven
// as an anti-aliased edge in either image (pixelmatch's rule) or as within the video's
// quantisation. Pixels at `offset` (bytes).
PixelVerdict judge_pixel(const io::Image& a, const io::Image& b, std::size_t offset,
                         const PixelTest& test) {
  const std::uint8_t* pa = &a.rgb[offset];
  const std::uint8_t* pb = &b.rgb[offset];
  if (pa[0] == pb[0] && pa[1] == pb[1] && pa[2] == pb[2]) return PixelVerdict::same;
  const FrameCriteria& criteria = test.criteria;
  const bool fails = criteria.metric == DiffMetric::perceptual
                         ? yiq_distance_squared(pa, pb) > test.max_yiq_distance_squared
                         : pixel_difference(pa, pb) > criteria.threshold;
  if (!fails) return PixelVerdict::same;
  const int x = static_cast<int>(offset / 3 % static_cast<std::size_t>(a.width));
  const int y = static_cast<int>(offset / 3 / static_cast<std::size_t>(a.width));
  if (criteria.ignore_antialiasing && (is_antialiased(a, x, y, b) || is_antialiased(b, x, y, a))) {
    return PixelVerdict::antialiased;
  }
  if (test.quantised_blocks.empty()) return PixelVerdict::differs;
  const int columns = (a.width + io::kMacroblockSize - 1) / io::kMacroblockSize;
  const std::size_t block =
      static_cast<std::size_t>(y / io::kMacroblockSize) * columns + x / io::kMacroblockSize;
  return test.quantised_blocks[block] ? PixelVerdict::quantised : PixelVerdict::differs;
}

bool few_enough(std::int64_t differing, std::int64_t pixels, const FrameCriteria& criteria) {
  if (criteria.max_percent < 0.0) return differing <= criteria.max_pixels;
  return 100.0 * static_cast<double>(differing) <=
         criteria.max_percent * static_cast<double>(pixels);
}

bool frame_matches(const FrameFigures& figures, const FrameCriteria& criteria) {
  switch (criteria.metric) {
    case DiffMetric::max:
    case DiffMetric::perceptual:
      return few_enough(figures.differing_pixels, figures.pixels, criteria);
    case DiffMetric::rms:
      return figures.rms <= criteria.threshold;
    case DiffMetric::ssim:
      return *figures.ssim >= criteria.threshold;
    case DiffMetric::psnr:
      return figures.psnr >= criteria.threshold;
  }
  return false;
}

}  // namespace

const char* diff_metric_name(DiffMetric metric) {
  switch (metric) {
    case DiffMetric::max:
      return "max";
    case DiffMetric::rms:
      return "rms";
    case DiffMetric::perceptual:
      return "perceptual";
    case DiffMetric::ssim:
      return "ssim";
    case DiffMetric::psnr:
      return "psnr";
  }
  return "?";
}

std::optional<DiffMetric> diff_metric_named(std::string_view name) {
  for (DiffMetric metric : {DiffMetric::max, DiffMetric::rms, DiffMetric::perceptual,
                            DiffMetric::ssim, DiffMetric::psnr}) {
    if (name == diff_metric_name(metric)) return metric;
  }
  return std::nullopt;
}

bool counts_pixels(DiffMetric metric) {
  return metric == DiffMetric::max || metric == DiffMetric::perceptual;
}

double default_threshold(DiffMetric metric) {
  switch (metric) {
    case DiffMetric::max:
      return 0.0;
    case DiffMetric::rms:
      return 1.0;
    case DiffMetric::perceptual:
      return 0.1;
    case DiffMetric::ssim:
      return 0.99;
    case DiffMetric::psnr:
      return 40.0;
  }
  return 0.0;
}

FrameFigures compare_frame(const io::Image& a, const io::Image& b, const FrameCriteria& criteria,
                           const io::QuantisationAllowance& allowance) {
  assert(a.width == b.width && a.height == b.height);
  assert(a.rgb.size() == b.rgb.size());
  FrameFigures figures;
  figures.pixels = std::int64_t{a.width} * a.height;
  const bool per_pixel = counts_pixels(criteria.metric);
  const PixelTest test(a, b, criteria, allowance);
  if (!test.quantised_blocks.empty()) figures.quantised_pixels = 0;
  std::int64_t sum_of_squares = 0;  // at most 3 · 255² per pixel: no overflow below ~4e13 pixels
  for (std::size_t i = 0; i < a.rgb.size(); i += 3) {
    const int d0 = a.rgb[i] - b.rgb[i], d1 = a.rgb[i + 1] - b.rgb[i + 1];
    const int d2 = a.rgb[i + 2] - b.rgb[i + 2];
    if ((d0 | d1 | d2) == 0) continue;  // most pixels of similar frames: nothing to add
    sum_of_squares += d0 * d0 + d1 * d1 + d2 * d2;
    figures.max_channel_difference =
        std::max({figures.max_channel_difference, std::abs(d0), std::abs(d1), std::abs(d2)});
    if (!per_pixel) continue;
    const PixelVerdict verdict = judge_pixel(a, b, i, test);
    figures.differing_pixels += verdict == PixelVerdict::differs;
    figures.antialiased_pixels += verdict == PixelVerdict::antialiased;
    if (verdict == PixelVerdict::quantised) ++*figures.quantised_pixels;
  }
  const double mean_square =
      a.rgb.empty() ? 0.0 : static_cast<double>(sum_of_squares) / static_cast<double>(a.rgb.size());
  figures.rms = std::sqrt(mean_square);
  figures.psnr = mean_square == 0.0 ? std::numeric_limits<double>::infinity()
                                    : 10.0 * std::log10(255.0 * 255.0 / mean_square);
  if (criteria.metric == DiffMetric::ssim) figures.ssim = mean_ssim(a, b);
  figures.match = frame_matches(figures, criteria);
  return figures;
}

double badness(const FrameFigures& figures, DiffMetric metric) {
  switch (metric) {
    case DiffMetric::max:
    case DiffMetric::perceptual:
      return static_cast<double>(figures.differing_pixels);
    case DiffMetric::rms:
      return figures.rms;
    case DiffMetric::ssim:
      return 1.0 - figures.ssim.value_or(1.0);
    case DiffMetric::psnr:
      return -figures.psnr;
  }
  return 0.0;
}

io::Image difference_picture(const io::Image& a, const io::Image& b, const FrameCriteria& criteria,
                             const io::QuantisationAllowance& allowance) {
  assert(a.width == b.width && a.height == b.height);
  io::Image out = diff_image(a, b, 0);  // red wherever a channel differs, dim grey elsewhere
  if (!counts_pixels(criteria.metric)) return out;
  const PixelTest test(a, b, criteria, allowance);
  for (std::size_t i = 0; i < a.rgb.size(); i += 3) {
    switch (judge_pixel(a, b, i, test)) {
      case PixelVerdict::differs:
        break;
      case PixelVerdict::antialiased:
        out.rgb[i] = out.rgb[i + 1] = 255;  // yellow, as pixelmatch marks them
        break;
      case PixelVerdict::quantised:
        out.rgb[i] = 0;  // blue: within the video's quantisation
        out.rgb[i + 1] = 128;
        out.rgb[i + 2] = 255;
        break;
      case PixelVerdict::same:  // equal, or within the threshold: grey like the rest
        out.rgb[i] = out.rgb[i + 1] = out.rgb[i + 2] = dim_grey(&a.rgb[i]);
        break;
    }
  }
  return out;
}

DiffResult compare_images(const io::Image& a, const io::Image& b, const DiffOptions& options) {
  assert(a.width == b.width && a.height == b.height);
  assert(a.rgb.size() == b.rgb.size());
  DiffResult result;
  std::int64_t sum_of_squares = 0;  // at most 255² per channel: no overflow below ~4e13 pixels
  for (std::size_t i = 0; i < a.rgb.size(); i += 3) {
    const int difference = pixel_difference(&a.rgb[i], &b.rgb[i]);
    if (difference > options.threshold) ++result.differing_pixels;
    result.max_channel_difference = std::max(result.max_channel_difference, difference);
    for (std::size_t c = i; c < i + 3; ++c) {
      const int d = a.rgb[c] - b.rgb[c];
      sum_of_squares += d * d;
    }
  }
  if (!a.rgb.empty()) {
    result.rms = std::sqrt(static_cast<double>(sum_of_squares) / static_cast<double>(a.rgb.size()));
  }
  result.match = result.differing_pixels <= options.max_pixels;
  return result;
}

io::Image diff_image(const io::Image& a, const io::Image& b, int threshold) {
  assert(a.width == b.width && a.height == b.height);
  assert(a.rgb.size() == b.rgb.size());
  io::Image out(a.width, a.height);
  for (std::size_t i = 0; i < a.rgb.size(); i += 3) {
    const int difference = pixel_difference(&a.rgb[i], &b.rgb[i]);
    if (difference > threshold) {
      out.rgb[i] = static_cast<std::uint8_t>(128 + difference / 2);  // 1 -> 128, 255 -> 255
      continue;
    }
    out.rgb[i] = out.rgb[i + 1] = out.rgb[i + 2] = dim_grey(&a.rgb[i]);
  }
  return out;
}

}  // namespace tumble::diff
