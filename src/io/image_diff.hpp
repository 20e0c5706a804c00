// Comparing two images of the same size: figures for a pass/fail decision, and a picture of where
// they differ.
#pragma once

#include <cstdint>

#include "io/image.hpp"

namespace tumble::io {

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
DiffResult compare_images(const Image& a, const Image& b, const DiffOptions& options);

// A picture of the differences, the size of a and b (precondition: equal sizes). Pixels within the
// threshold show a as grey at 30% brightness (R = G = B <= 76); differing pixels are pure red
// (G = B = 0), from 128 for a difference of 1 to 255 for 255, so even the smallest stands out.
Image diff_image(const Image& a, const Image& b, int threshold);

}  // namespace tumble::io
