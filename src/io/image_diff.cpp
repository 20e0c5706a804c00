#include "io/image_diff.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdlib>

namespace tumble::io {
namespace {

// The largest of a pixel's three channel differences (0-255).
int pixel_difference(const std::uint8_t* a, const std::uint8_t* b) {
  return std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}

}  // namespace

DiffResult compare_images(const Image& a, const Image& b, const DiffOptions& options) {
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

Image diff_image(const Image& a, const Image& b, int threshold) {
  assert(a.width == b.width && a.height == b.height);
  assert(a.rgb.size() == b.rgb.size());
  Image out(a.width, a.height);
  for (std::size_t i = 0; i < a.rgb.size(); i += 3) {
    const int difference = pixel_difference(&a.rgb[i], &b.rgb[i]);
    if (difference > threshold) {
      out.rgb[i] = static_cast<std::uint8_t>(128 + difference / 2);  // 1 -> 128, 255 -> 255
      continue;
    }
    // Rec. 601 luma in 8-bit fixed point (77 + 150 + 29 = 256), then 30% of it.
    const int luma = (77 * a.rgb[i] + 150 * a.rgb[i + 1] + 29 * a.rgb[i + 2]) >> 8;
    const auto grey = static_cast<std::uint8_t>(luma * 3 / 10);
    out.rgb[i] = out.rgb[i + 1] = out.rgb[i + 2] = grey;
  }
  return out;
}

}  // namespace tumble::io
