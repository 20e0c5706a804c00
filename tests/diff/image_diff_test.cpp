// Image comparison on images that differ by known amounts.
#include "diff/image_diff.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <set>
#include <utility>
#include <vector>

namespace tumble::diff {
namespace {

constexpr int kWidth = 7;
constexpr int kHeight = 5;

// Each channel a different value, and no value near 0 or 255, so changes of either sign fit.
io::Image base_image() {
  io::Image image(kWidth, kHeight);
  for (std::size_t i = 0; i < image.rgb.size(); ++i) {
    image.rgb[i] = static_cast<std::uint8_t>(20 + (i * 37) % 200);
  }
  return image;
}

std::uint8_t* pixel(io::Image& image, int x, int y) {
  return image.row(y) + 3 * x;
}

TEST(CompareImages, IdenticalImagesHaveNoDifference) {
  const io::Image a = base_image();
  const DiffResult result = compare_images(a, a, {});
  EXPECT_EQ(result.differing_pixels, 0);
  EXPECT_EQ(result.max_channel_difference, 0);
  EXPECT_EQ(result.rms, 0.0);
  EXPECT_TRUE(result.match);
}

TEST(CompareImages, OneChannelOfOnePixelChangedByTen) {
  const io::Image a = base_image();
  io::Image b = a;
  pixel(b, 3, 2)[1] += 10;
  const DiffResult result = compare_images(a, b, {});
  EXPECT_EQ(result.differing_pixels, 1);
  EXPECT_EQ(result.max_channel_difference, 10);
  EXPECT_EQ(result.rms, std::sqrt(100.0 / (kWidth * kHeight * 3)));
  EXPECT_FALSE(result.match);
  // The comparison is symmetric: a decrease counts like an increase.
  const DiffResult reversed = compare_images(b, a, {});
  EXPECT_EQ(reversed.differing_pixels, 1);
  EXPECT_EQ(reversed.max_channel_difference, 10);
  EXPECT_EQ(reversed.rms, result.rms);
}

TEST(CompareImages, APixelDiffersByItsLargestChannelAndRmsCountsEveryChannel) {
  const io::Image a = base_image();
  io::Image b = a;
  std::uint8_t* changed = pixel(b, 0, 4);
  changed[0] += 3;
  changed[1] -= 7;
  changed[2] += 5;
  EXPECT_EQ(compare_images(a, b, {6, 0}).differing_pixels, 1);  // 7 > 6
  EXPECT_EQ(compare_images(a, b, {7, 0}).differing_pixels, 0);
  const DiffResult result = compare_images(a, b, {});
  EXPECT_EQ(result.max_channel_difference, 7);
  EXPECT_EQ(result.rms, std::sqrt((9.0 + 49.0 + 25.0) / (kWidth * kHeight * 3)));
}

TEST(CompareImages, APixelDiffersOnlyWhenAboveTheThreshold) {
  const io::Image a = base_image();
  io::Image b = a;
  pixel(b, 6, 0)[2] -= 10;
  const DiffResult below = compare_images(a, b, {9, 0});
  EXPECT_EQ(below.differing_pixels, 1);
  EXPECT_FALSE(below.match);
  const DiffResult at = compare_images(a, b, {10, 0});
  EXPECT_EQ(at.differing_pixels, 0);
  EXPECT_TRUE(at.match);
  const DiffResult above = compare_images(a, b, {11, 0});
  EXPECT_EQ(above.differing_pixels, 0);
  EXPECT_TRUE(above.match);
  // The threshold decides the count, not the figures.
  EXPECT_EQ(at.max_channel_difference, 10);
  EXPECT_EQ(at.rms, below.rms);
  EXPECT_GT(at.rms, 0.0);
}

TEST(CompareImages, TheImagesMatchWhenAtMostMaxPixelsDiffer) {
  const io::Image a = base_image();
  io::Image b = a;
  pixel(b, 0, 0)[0] += 1;
  pixel(b, 4, 1)[1] += 2;
  pixel(b, 6, 4)[2] += 3;
  EXPECT_EQ(compare_images(a, b, {0, 2}).differing_pixels, 3);
  EXPECT_FALSE(compare_images(a, b, {0, 2}).match);
  EXPECT_TRUE(compare_images(a, b, {0, 3}).match);
  EXPECT_TRUE(compare_images(a, b, {0, 4}).match);
  // Raising the threshold past the smallest difference removes it from the count.
  EXPECT_EQ(compare_images(a, b, {1, 2}).differing_pixels, 2);
  EXPECT_TRUE(compare_images(a, b, {1, 2}).match);
}

TEST(CompareImages, BlackAgainstWhiteIsTheLargestPossibleDifference) {
  const io::Image black(3, 2);
  io::Image white(3, 2);
  white.rgb.assign(white.rgb.size(), 255);
  const DiffResult result = compare_images(black, white, {254, 5});
  EXPECT_EQ(result.differing_pixels, 6);
  EXPECT_EQ(result.max_channel_difference, 255);
  EXPECT_EQ(result.rms, 255.0);
  EXPECT_FALSE(result.match);
}

TEST(DiffImage, HighlightsExactlyThePixelsAboveTheThreshold) {
  const io::Image a = base_image();
  io::Image b = a;
  pixel(b, 1, 1)[0] += 1;   // below the threshold of 2: not highlighted
  pixel(b, 2, 3)[1] += 3;   // highlighted
  pixel(b, 5, 0)[2] -= 20;  // highlighted
  pixel(b, 6, 4)[0] += 2;   // at the threshold: not highlighted
  const std::set<std::pair<int, int>> expected = {{2, 3}, {5, 0}};
  const io::Image diff = diff_image(a, b, 2);
  ASSERT_EQ(diff.width, kWidth);
  ASSERT_EQ(diff.height, kHeight);
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const std::uint8_t* out = diff.row(y) + 3 * x;
      const bool highlighted = out[0] != out[1] || out[1] != out[2];
      EXPECT_EQ(highlighted, expected.count({x, y}) == 1) << x << "," << y;
    }
  }
}

TEST(DiffImage, RedGrowsWithTheDifferenceAndTheRestIsDimmedGrey) {
  io::Image a(4, 1);
  a.rgb = {255, 255, 255, 0, 0, 0, 100, 100, 100, 0, 0, 0};
  io::Image b = a;
  b.rgb[3] = 1;     // pixel 1 differs by 1
  b.rgb[11] = 255;  // pixel 3 differs by 255
  const io::Image diff = diff_image(a, b, 0);
  EXPECT_EQ(diff.rgb, (std::vector<std::uint8_t>{76, 76, 76,    // white at 30%
                                                 128, 0, 0,     // smallest difference
                                                 30, 30, 30,    // grey 100 at 30%
                                                 255, 0, 0}));  // largest difference
}

}  // namespace
}  // namespace tumble::diff
