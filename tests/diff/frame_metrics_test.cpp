// The metrics of compare_frame on images that differ by known amounts, each checked against a
// value computed here from the metric's textbook formula.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "diff/image_diff.hpp"
#include "diff/perceptual_diff.hpp"
#include "diff/ssim.hpp"

namespace tumble::diff {
namespace {

// A textured image with no value near 0 or 255, so shifts of ±30 fit.
io::Image textured(int width, int height) {
  io::Image image(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      std::uint8_t* p = image.row(y) + 3 * x;
      p[0] = static_cast<std::uint8_t>(40 + (x * 23 + y * 7) % 170);
      p[1] = static_cast<std::uint8_t>(40 + (x * 5 + y * 31) % 170);
      p[2] = static_cast<std::uint8_t>(40 + (x * x + 3 * y) % 170);
    }
  }
  return image;
}

io::Image flat(int width, int height, std::uint8_t level) {
  io::Image image(width, height);
  image.rgb.assign(image.rgb.size(), level);
  return image;
}

std::uint8_t* pixel(io::Image& image, int x, int y) {
  return image.row(y) + 3 * x;
}

FrameCriteria criteria(DiffMetric metric, std::optional<double> threshold = std::nullopt,
                       bool ignore_antialiasing = false) {
  FrameCriteria c;
  c.metric = metric;
  c.threshold = threshold.value_or(default_threshold(metric));
  c.ignore_antialiasing = ignore_antialiasing;
  return c;
}

// Wang et al. 2004 written out directly: for every window position a 2D Gaussian (σ = 1.5)
// normalised over the window, weighted means, variances and covariance, eq. 13, then the mean.
double reference_ssim(const io::Image& a, const io::Image& b) {
  int side = std::min({11, a.width, a.height});
  if (side % 2 == 0) --side;
  const int r = side / 2;
  double total_weight = 0;
  for (int j = -r; j <= r; ++j) {
    for (int i = -r; i <= r; ++i) total_weight += std::exp(-(i * i + j * j) / 4.5);
  }
  const auto luma = [](const io::Image& image, int x, int y) {
    const std::uint8_t* p = image.row(y) + 3 * x;
    return 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2];
  };
  const double c1 = 6.5025, c2 = 58.5225;  // (0.01·255)², (0.03·255)²
  double sum = 0;
  int windows = 0;
  for (int cy = r; cy < a.height - r; ++cy) {
    for (int cx = r; cx < a.width - r; ++cx) {
      double mx = 0, my = 0, xx = 0, yy = 0, xy = 0;
      for (int j = -r; j <= r; ++j) {
        for (int i = -r; i <= r; ++i) {
          const double w = std::exp(-(i * i + j * j) / 4.5) / total_weight;
          const double x = luma(a, cx + i, cy + j), y = luma(b, cx + i, cy + j);
          mx += w * x;
          my += w * y;
          xx += w * x * x;
          yy += w * y * y;
          xy += w * x * y;
        }
      }
      const double vx = xx - mx * mx, vy = yy - my * my, cov = xy - mx * my;
      sum += (2 * mx * my + c1) * (2 * cov + c2) / ((mx * mx + my * my + c1) * (vx + vy + c2));
      ++windows;
    }
  }
  return sum / windows;
}

TEST(FrameMetrics, OneChangedPixelIsCountedByMaxAndPerceptual) {
  const io::Image a = flat(9, 7, 100);
  io::Image b = a;
  std::uint8_t* changed = pixel(b, 4, 3);
  changed[0] = 140;  // +40 red
  const FrameFigures max = compare_frame(a, b, criteria(DiffMetric::max));
  EXPECT_EQ(max.differing_pixels, 1);
  EXPECT_EQ(max.max_channel_difference, 40);
  EXPECT_FALSE(max.match);
  // YIQ distance² of +40 red: the weights times the Y, I, Q steps, by hand.
  const double y = 40 * 0.29889531, i = 40 * 0.59597799, q = 40 * 0.21147017;
  const double distance = 0.5053 * y * y + 0.299 * i * i + 0.1957 * q * q;  // 256.0
  EXPECT_NEAR(yiq_distance_squared(pixel(b, 4, 3), a.row(3) + 12), distance, 1e-9);
  // A lone pixel in a flat image is no edge: ignoring anti-aliasing changes nothing.
  const double just_below = std::sqrt(distance / kMaxYiqDistanceSquared) - 1e-6;
  const FrameFigures perceptual =
      compare_frame(a, b, criteria(DiffMetric::perceptual, just_below, true));
  EXPECT_EQ(perceptual.differing_pixels, 1);
  EXPECT_EQ(perceptual.antialiased_pixels, 0);
  EXPECT_FALSE(perceptual.match);
  // At the default 0.1 (distance² 352) the change is too small to see.
  EXPECT_TRUE(compare_frame(a, b, criteria(DiffMetric::perceptual)).match);
  // RMS and PSNR over all 9·7·3 channels.
  const double mse = 1600.0 / (9 * 7 * 3);
  EXPECT_DOUBLE_EQ(compare_frame(a, b, criteria(DiffMetric::rms)).rms, std::sqrt(mse));
  EXPECT_FALSE(compare_frame(a, b, criteria(DiffMetric::rms, std::sqrt(mse) - 1e-9)).match);
  EXPECT_TRUE(compare_frame(a, b, criteria(DiffMetric::rms, std::sqrt(mse))).match);
  EXPECT_NEAR(compare_frame(a, b, criteria(DiffMetric::psnr)).psnr,
              10 * std::log10(255.0 * 255.0 / mse), 1e-12);
  EXPECT_NEAR(*compare_frame(a, b, criteria(DiffMetric::ssim)).ssim, reference_ssim(a, b), 1e-12);
}

// A vertical black-to-white edge whose one grey (anti-aliased) column changes shade, as when an
// edge moves by a fraction of a pixel.
TEST(FrameMetrics, AShiftedEdgePassesPerceptualIgnoringAntiAliasingAndFailsMax) {
  io::Image a(12, 8);
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 12; ++x) {
      const std::uint8_t level = x < 5 ? 0 : x == 5 ? 128 : 255;
      std::fill_n(pixel(a, x, y), 3, level);
    }
  }
  io::Image b = a;
  for (int y = 0; y < 8; ++y) std::fill_n(pixel(b, 5, y), 3, 96);  // 32 levels darker
  EXPECT_TRUE(is_antialiased(a, 5, 3, b));
  EXPECT_TRUE(is_antialiased(a, 5, 0, b));   // at the border too
  EXPECT_FALSE(is_antialiased(a, 2, 3, b));  // inside the flat black
  const FrameFigures ignoring = compare_frame(a, b, criteria(DiffMetric::perceptual, {}, true));
  EXPECT_EQ(ignoring.differing_pixels, 0);
  EXPECT_EQ(ignoring.antialiased_pixels, 8);
  EXPECT_TRUE(ignoring.match);
  // 0.5053 · 32² = 517 > 352: seen when anti-aliasing counts, and by max at any threshold below 32.
  EXPECT_EQ(compare_frame(a, b, criteria(DiffMetric::perceptual)).differing_pixels, 8);
  const FrameFigures max = compare_frame(a, b, criteria(DiffMetric::max));
  EXPECT_EQ(max.differing_pixels, 8);
  EXPECT_FALSE(max.match);
}

TEST(FrameMetrics, AChangeInsideAFlatAreaIsNoAntiAliasing) {
  io::Image a = flat(12, 8, 0);
  for (int y = 0; y < 8; ++y) {
    for (int x = 6; x < 12; ++x) std::fill_n(pixel(a, x, y), 3, 255);
  }
  io::Image b = a;
  std::fill_n(pixel(b, 2, 4), 3, 128);  // a grey dot in the black: both neighbours darker-or-equal
  const FrameFigures figures = compare_frame(a, b, criteria(DiffMetric::perceptual, {}, true));
  EXPECT_EQ(figures.differing_pixels, 1);
  EXPECT_EQ(figures.antialiased_pixels, 0);
}

TEST(FrameMetrics, AColourShiftOfKnownSizeGivesTheTextbookPsnrAndSsim) {
  const io::Image a = textured(16, 14);
  io::Image b = a;
  for (std::uint8_t& level : b.rgb) level += 10;
  const FrameFigures psnr = compare_frame(a, b, criteria(DiffMetric::psnr));
  EXPECT_NEAR(psnr.psnr, 10 * std::log10(65025.0 / 100.0), 1e-12);  // 28.13 dB
  EXPECT_FALSE(psnr.match);                                         // below 40 dB
  EXPECT_TRUE(compare_frame(a, b, criteria(DiffMetric::psnr, 28.0)).match);
  EXPECT_DOUBLE_EQ(psnr.rms, 10.0);
  const FrameFigures ssim = compare_frame(a, b, criteria(DiffMetric::ssim));
  const double expected = reference_ssim(a, b);
  EXPECT_NEAR(*ssim.ssim, expected, 1e-12);
  EXPECT_LT(expected, 1.0);
  EXPECT_GT(expected, 0.9);  // luminance shifts only: structure and contrast are kept
  EXPECT_EQ(*compare_frame(a, a, criteria(DiffMetric::ssim)).ssim, 1.0);
}

TEST(FrameMetrics, SsimOnATinyImageUsesTheLargestOddWindowThatFits) {
  EXPECT_EQ(ssim_window_side(1280, 720), 11);
  EXPECT_EQ(ssim_window_side(8, 20), 7);
  EXPECT_EQ(ssim_window_side(1, 5), 1);
  double total = 0;
  for (int k = -5; k <= 5; ++k) total += ssim_window_weight(k, 11);
  EXPECT_NEAR(total, 1.0, 1e-15);
  EXPECT_NEAR(ssim_window_weight(0, 11) / ssim_window_weight(1, 11), std::exp(1 / 4.5), 1e-12);
  io::Image a = textured(8, 6);
  io::Image b = a;
  pixel(b, 3, 3)[1] += 25;
  EXPECT_NEAR(mean_ssim(a, b), reference_ssim(a, b), 1e-12);
}

TEST(FrameMetrics, IdenticalImagesHaveInfinitePsnrAndMatchEveryMetric) {
  const io::Image a = textured(20, 12);
  for (DiffMetric metric : {DiffMetric::max, DiffMetric::rms, DiffMetric::perceptual,
                            DiffMetric::ssim, DiffMetric::psnr}) {
    const FrameFigures figures = compare_frame(a, a, criteria(metric));
    EXPECT_TRUE(figures.match) << diff_metric_name(metric);
    EXPECT_EQ(figures.psnr, std::numeric_limits<double>::infinity());
  }
}

TEST(FrameMetrics, MaxPercentAllowsAShareOfThePixels) {
  const io::Image a = flat(10, 10, 50);
  io::Image b = a;
  pixel(b, 1, 1)[0] = 200;
  pixel(b, 8, 8)[2] = 200;
  FrameCriteria c = criteria(DiffMetric::max);
  c.max_percent = 2.0;  // 2 of 100 pixels
  EXPECT_TRUE(compare_frame(a, b, c).match);
  c.max_percent = 1.99;
  EXPECT_FALSE(compare_frame(a, b, c).match);
  c.max_percent = -1.0;
  c.max_pixels = 2;
  EXPECT_TRUE(compare_frame(a, b, c).match);
}

TEST(FrameMetrics, TheYiqScaleTopsOutAtPixelmatchsConstant) {
  double largest = 0;
  for (int from = 0; from < 8; ++from) {
    for (int to = 0; to < 8; ++to) {
      const std::uint8_t p[3] = {std::uint8_t(from & 1 ? 255 : 0), std::uint8_t(from & 2 ? 255 : 0),
                                 std::uint8_t(from & 4 ? 255 : 0)};
      const std::uint8_t q[3] = {std::uint8_t(to & 1 ? 255 : 0), std::uint8_t(to & 2 ? 255 : 0),
                                 std::uint8_t(to & 4 ? 255 : 0)};
      largest = std::max(largest, yiq_distance_squared(p, q));
    }
  }
  EXPECT_NEAR(largest, kMaxYiqDistanceSquared, 1.0);  // red against cyan: 35214.7
}

TEST(FrameMetrics, TheDifferencePictureMarksCountedRedAndAntiAliasedYellow) {
  io::Image a(12, 8);
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 12; ++x) std::fill_n(pixel(a, x, y), 3, x < 5 ? 0 : x == 5 ? 128 : 255);
  }
  io::Image b = a;
  std::fill_n(pixel(b, 5, 2), 3, 96);  // on the edge: anti-aliasing
  std::fill_n(pixel(b, 9, 4), 3, 0);   // a black dot in the white: counted
  const io::Image picture = difference_picture(a, b, criteria(DiffMetric::perceptual, {}, true));
  const std::uint8_t* edge = picture.row(2) + 3 * 5;
  EXPECT_EQ(edge[0], 255);
  EXPECT_EQ(edge[1], 255);
  EXPECT_EQ(edge[2], 0);
  const std::uint8_t* dot = picture.row(4) + 3 * 9;
  EXPECT_EQ(dot[0], 128 + 255 / 2);
  EXPECT_EQ(dot[1], 0);
  const std::uint8_t* same = picture.row(0);
  EXPECT_EQ(same[0], same[1]);
}

}  // namespace
}  // namespace tumble::diff
