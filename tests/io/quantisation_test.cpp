// The H.264 quantisation allowance: the quantiser step and chroma QP against H.264's tables, and
// which macroblocks a difference of known Y', Cb and Cr RMS falls within.
#include "io/quantisation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

namespace tumble::io {
namespace {

// Two macroblocks side by side, mid grey.
Image two_blocks() {
  Image image(2 * kMacroblockSize, kMacroblockSize);
  image.rgb.assign(image.rgb.size(), 120);
  return image;
}

// `image` with `delta` added to channel `channel` of every pixel of the left macroblock.
Image left_block_shifted(Image image, int channel, int delta) {
  for (int y = 0; y < kMacroblockSize; ++y) {
    for (int x = 0; x < kMacroblockSize; ++x) {
      std::uint8_t& level = image.row(y)[3 * x + channel];
      level = static_cast<std::uint8_t>(level + delta);
    }
  }
  return image;
}

// BT.709, limited range (swscale's SWS_CS_ITU709 is 1).
QuantisationAllowance bt709(int qp, int chroma_qp_offset = 0) {
  return h264_allowance(qp, chroma_qp_offset, 1, false);
}

TEST(Quantisation, StepFollowsTheTableAndDoublesEverySixQp) {
  EXPECT_DOUBLE_EQ(h264_quantiser_step(0), 0.625);
  EXPECT_DOUBLE_EQ(h264_quantiser_step(4), 1.0);
  EXPECT_DOUBLE_EQ(h264_quantiser_step(28), 16.0);
  EXPECT_DOUBLE_EQ(h264_quantiser_step(29), 18.0);
  EXPECT_DOUBLE_EQ(h264_quantiser_step(51), 224.0);
  for (int qp = 0; qp + 6 <= 51; ++qp) {
    EXPECT_DOUBLE_EQ(h264_quantiser_step(qp + 6), 2.0 * h264_quantiser_step(qp)) << qp;
  }
}

TEST(Quantisation, ChromaQpFollowsTable815) {
  EXPECT_EQ(h264_chroma_qp(29, 0), 29);
  EXPECT_EQ(h264_chroma_qp(30, 0), 29);
  EXPECT_EQ(h264_chroma_qp(34, 0), 32);
  EXPECT_EQ(h264_chroma_qp(51, 0), 39);
  EXPECT_EQ(h264_chroma_qp(40, -2), 35);  // qPI 38
  EXPECT_EQ(h264_chroma_qp(60, 0), 39);   // clipped to 51 first
}

// A grey step of 10 levels in R, G and B is 10 · 219/255 = 8.588 Y' levels and no chroma: within
// half the step of QP 29 (18 / 2), not of QP 28 (16 / 2 = 8 < 8.588). The right macroblock, equal
// in both, is within either.
TEST(Quantisation, AGreyStepIsWithinWhenItsLumaRmsIsAtMostHalfTheStep) {
  Image base = two_blocks();
  Image brighter =
      left_block_shifted(left_block_shifted(left_block_shifted(base, 0, 10), 1, 10), 2, 10);
  EXPECT_EQ(macroblocks_within(base, brighter, bt709(29)), (std::vector<std::uint8_t>{1, 1}));
  EXPECT_EQ(macroblocks_within(base, brighter, bt709(28)), (std::vector<std::uint8_t>{0, 1}));
}

// 20 levels more blue: Y' 20 · 0.0722 · 219/255 = 1.24, Cb (20 - 1.444) / (2 · 0.9278) · 224/255
// = 8.785, Cr 1.444 / (2 · 0.7874) · 224/255 = 0.805. Within at QP 29 (chroma QP 29: half step
// 9); a chroma_qp_index_offset of -2 makes it chroma QP 27 (half step 7): then not.
TEST(Quantisation, ABlueStepIsJudgedByTheChromaStep) {
  Image base = two_blocks();
  Image bluer = left_block_shifted(base, 2, 20);
  EXPECT_EQ(macroblocks_within(base, bluer, bt709(29)), (std::vector<std::uint8_t>{1, 1}));
  EXPECT_EQ(macroblocks_within(base, bluer, bt709(29, -2)), (std::vector<std::uint8_t>{0, 1}));
  EXPECT_EQ(macroblocks_within(bluer, base, bt709(29, -2)), (std::vector<std::uint8_t>{0, 1}));
}

}  // namespace
}  // namespace tumble::io
