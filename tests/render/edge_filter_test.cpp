#include "render/edge_filter.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <vector>

namespace tumble::render {
namespace {

constexpr int kWidth = 64;
constexpr int kHeight = 48;

// An RGBA picture with each pixel's grey level (0 to 255) from `grey(x, y)`.
std::vector<std::uint8_t> grey_picture(const std::function<int(int, int)>& grey) {
  std::vector<std::uint8_t> rgba(4 * kWidth * kHeight);
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      std::uint8_t* pixel = &rgba[4 * (y * kWidth + x)];
      pixel[0] = pixel[1] = pixel[2] = static_cast<std::uint8_t>(grey(x, y));
      pixel[3] = 255;
    }
  }
  return rgba;
}

io::Image filtered(const std::vector<std::uint8_t>& rgba) {
  io::Image out;
  filter_edges(rgba.data(), kWidth, kHeight, out);
  return out;
}

// A straight edge: bright on one side of the line through `point` along `direction`, dark on
// the other, in pixel coordinates (x right, y down).
struct Line {
  double point_x, point_y;
  double direction_x, direction_y;

  bool bright(double x, double y) const {
    return direction_x * (y - point_y) - direction_y * (x - point_x) > 0.0;
  }
  // Grey level 0 or 255 of pixel (x, y) drawn with one sample at its centre.
  int aliased(int x, int y) const { return bright(x + 0.5, y + 0.5) ? 255 : 0; }
  // The grey level of pixel (x, y) perfectly antialiased: 255 × its bright share, from 32 × 32
  // samples.
  double exact(int x, int y) const {
    int inside = 0;
    for (int i = 0; i < 32; ++i) {
      for (int j = 0; j < 32; ++j) inside += bright(x + (i + 0.5) / 32.0, y + (j + 0.5) / 32.0);
    }
    return 255.0 * inside / 1024.0;
  }
  double distance(int x, int y) const {  // from the pixel's centre to the line (pixels)
    const double cross = direction_x * (y + 0.5 - point_y) - direction_y * (x + 0.5 - point_x);
    return std::abs(cross) / std::hypot(direction_x, direction_y);
  }
};

// Filters the aliased drawing of `line` and checks that it comes out close to the exact share
// of each pixel on the bright side: over the pixels within two of the line, the summed error
// falls to less than half of the aliased picture's. Pixels further away are unchanged.
void expect_smoothed(const Line& line) {
  const io::Image out = filtered(grey_picture([&](int x, int y) { return line.aliased(x, y); }));
  double aliased_error = 0.0, filtered_error = 0.0;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      if (line.distance(x, y) > 2.0) {
        ASSERT_EQ(out.row(y)[3 * x], line.aliased(x, y))
            << "away from the line, at " << x << "," << y;
        continue;
      }
      aliased_error += std::abs(line.aliased(x, y) - line.exact(x, y));
      filtered_error += std::abs(out.row(y)[3 * x] - line.exact(x, y));
    }
  }
  EXPECT_LT(filtered_error, 0.5 * aliased_error)
      << "summed error: aliased " << aliased_error << ", filtered " << filtered_error;
}

TEST(EdgeFilter, FlatPictureIsCopiedUnchanged) {
  const auto rgba = grey_picture([](int, int) { return 140; });
  const io::Image out = filtered(rgba);
  ASSERT_EQ(out.width, kWidth);
  ASSERT_EQ(out.height, kHeight);
  for (const std::uint8_t value : out.rgb) ASSERT_EQ(value, 140);
}

// Soft shading (steps of 3 of 255 between neighbours) is below the filter's contrast floor.
TEST(EdgeFilter, GentleGradientIsCopiedUnchanged) {
  const auto rgba = grey_picture([](int x, int y) { return 10 + 3 * x + y / 2; });
  const io::Image out = filtered(rgba);
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x)
      ASSERT_EQ(out.row(y)[3 * x], 10 + 3 * x + y / 2) << x << "," << y;
  }
}

// A picture's colours are kept: the filter drops alpha and copies red, green and blue as given.
TEST(EdgeFilter, ColoursAwayFromEdgesAreKept) {
  std::vector<std::uint8_t> rgba(4 * kWidth * kHeight);
  for (std::size_t i = 0; i < rgba.size(); i += 4) {
    rgba[i] = 200, rgba[i + 1] = 40, rgba[i + 2] = 90, rgba[i + 3] = 7;
  }
  const io::Image out = filtered(rgba);
  for (std::size_t i = 0; i < out.rgb.size(); i += 3) {
    ASSERT_EQ(out.rgb[i], 200);
    ASSERT_EQ(out.rgb[i + 1], 40);
    ASSERT_EQ(out.rgb[i + 2], 90);
  }
}

// An edge along the pixel grid is already what an antialiased picture shows: it stays sharp.
// Pixels not next to it are unchanged; those next to it move by at most 16 of 255.
TEST(EdgeFilter, EdgeAlongThePixelGridStaysSharp) {
  const auto rgba = grey_picture([](int x, int) { return x < 30 ? 30 : 230; });
  const io::Image out = filtered(rgba);
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const int before = x < 30 ? 30 : 230;
      const int after = out.row(y)[3 * x];
      if (x == 29 || x == 30) {
        EXPECT_LE(std::abs(after - before), 16) << x << "," << y;
      } else {
        ASSERT_EQ(after, before) << x << "," << y;
      }
    }
  }
}

// An aliased edge at a shallow slope (a staircase of 7-pixel steps) and the same turned steep
// (steps of 7 rows), bright below or right of it, and the other way round.
TEST(EdgeFilter, StaircaseComesCloseToTheExactCoverage) {
  expect_smoothed(Line{0.0, 20.3, 7.0, 1.0});
  expect_smoothed(Line{0.0, 20.3, -7.0, -1.0});
  expect_smoothed(Line{25.3, 0.0, 1.0, 7.0});
  expect_smoothed(Line{25.3, 0.0, -1.0, -7.0});
}

// Steeper and flatter: steps of 3 pixels, and of 20 (longer than the walk along an edge).
TEST(EdgeFilter, StaircasesOfOtherSlopesComeCloseToo) {
  expect_smoothed(Line{0.0, 10.6, 3.0, 1.0});
  expect_smoothed(Line{0.0, 22.1, 20.0, 1.0});
}

// Text's pixels (text_layer.hpp) come through unfiltered; the rest of the staircase is smoothed
// as without them.
TEST(EdgeFilter, PixelsInsideUnfilteredBoxesAreCopiedUnchanged) {
  const Line line{10.0, 5.0, 7.0, 2.0};
  const std::vector<std::uint8_t> rgba =
      grey_picture([&](int x, int y) { return line.aliased(x, y); });
  const io::Image plain = filtered(rgba);
  const std::vector<PixelBox> boxes = {{20, 4, 16, 12}, {40, 10, 3, 30}};
  io::Image kept;
  filter_edges(rgba.data(), kWidth, kHeight, kept, boxes);
  int smoothed_inside = 0;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const bool inside = std::any_of(boxes.begin(), boxes.end(), [&](const PixelBox& b) {
        return x >= b.x && x < b.x + b.width && y >= b.y && y < b.y + b.height;
      });
      const int value = kept.row(y)[3 * x];
      if (inside) {
        ASSERT_EQ(value, line.aliased(x, y)) << "inside a box, at " << x << "," << y;
        smoothed_inside += plain.row(y)[3 * x] != value;
      } else {
        ASSERT_EQ(value, plain.row(y)[3 * x]) << "outside the boxes, at " << x << "," << y;
      }
    }
  }
  EXPECT_GT(smoothed_inside, 5) << "the boxes hold part of the staircase the filter smooths";
}

TEST(EdgeFilter, SamePictureGivesTheSameBytes) {
  const auto rgba = grey_picture([](int x, int y) { return ((x * 7 + y * 13) % 5) * 60; });
  EXPECT_EQ(filtered(rgba).rgb, filtered(rgba).rgb);
}

}  // namespace
}  // namespace tumble::render
