// Pictures for the video tests: a pattern that moves from frame to frame, and a measure of how
// far two pictures are apart.
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>

#include "io/image.hpp"

namespace tumble::testing {

using io::Image;

// Smooth sines in every channel sliding 2 px per frame: compressible, so crf 18 keeps it close.
inline Image moving_pattern(int width, int height, int k) {
  Image image(width, height);
  const double two_pi = 2.0 * std::numbers::pi;
  for (int y = 0; y < height; ++y) {
    std::uint8_t* row = image.row(y);
    for (int x = 0; x < width; ++x) {
      const double u = (x + 2.0 * k) / width;
      const double v = static_cast<double>(y) / height;
      row[3 * x + 0] = static_cast<std::uint8_t>(std::lround(128 + 100 * std::sin(two_pi * u)));
      row[3 * x + 1] = static_cast<std::uint8_t>(std::lround(128 + 100 * std::cos(two_pi * v)));
      row[3 * x + 2] =
          static_cast<std::uint8_t>(std::lround(128 + 100 * std::sin(two_pi * (u - v))));
    }
  }
  return image;
}

// Root-mean-square difference over every channel of every pixel (code values 0..255).
inline double rms_difference(const Image& a, const Image& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.rgb.size(); ++i) {
    const double d = static_cast<double>(a.rgb[i]) - b.rgb[i];
    sum += d * d;
  }
  return std::sqrt(sum / static_cast<double>(a.rgb.size()));
}

}  // namespace tumble::testing
