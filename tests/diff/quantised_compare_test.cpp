// The H.264 quantisation allowance in a comparison: which failing pixels compare_frame forgives
// because their macroblock's difference is within the video's quantisation.
#include "diff/image_diff.hpp"

#include <gtest/gtest.h>

#include "io/quantisation.hpp"

namespace tumble::diff {
namespace {

// Two macroblocks side by side, mid grey.
io::Image two_blocks() {
  io::Image image(2 * io::kMacroblockSize, io::kMacroblockSize);
  image.rgb.assign(image.rgb.size(), 120);
  return image;
}

// BT.709, limited range (swscale's SWS_CS_ITU709 is 1).
io::QuantisationAllowance bt709(int qp) {
  return io::h264_allowance(qp, 0, 1, false);
}

// compare_frame: perceptual forgives a failing pixel in a macroblock within the allowance (and
// says how many), max does not.
TEST(Quantisation, PerceptualForgivesPixelsWithinTheAllowanceAndMaxDoesNot) {
  io::Image base = two_blocks();
  io::Image changed = base;
  changed.row(3)[3 * 5] = 200;  // one pixel of the left block: 80 levels more red
  // RMS over 256 pixels: Y' 80 · 0.2126 · 219/255 / 16 = 0.91, Cr 80 · 0.7874 / 1.5748 ·
  // 224/255 / 16 = 2.20: within half the step of QP 20 (6.5 / 2), not of QP 14 (3.25 / 2).
  FrameCriteria perceptual{DiffMetric::perceptual, 0.1, true, 0, -1.0};
  const FrameFigures within = compare_frame(base, changed, perceptual, bt709(20));
  EXPECT_EQ(within.differing_pixels, 0);
  EXPECT_EQ(within.quantised_pixels, 1);
  EXPECT_TRUE(within.match);
  const FrameFigures beyond = compare_frame(base, changed, perceptual, bt709(14));
  EXPECT_EQ(beyond.differing_pixels, 1);
  EXPECT_EQ(beyond.quantised_pixels, 0);
  const FrameFigures none = compare_frame(base, changed, perceptual);
  EXPECT_EQ(none.differing_pixels, 1);
  EXPECT_FALSE(none.quantised_pixels.has_value());
  FrameCriteria exact{DiffMetric::max, 0.0, false, 0, -1.0};
  const FrameFigures max = compare_frame(base, changed, exact, bt709(20));
  EXPECT_EQ(max.differing_pixels, 1);
  EXPECT_FALSE(max.quantised_pixels.has_value());
}

}  // namespace
}  // namespace tumble::diff
