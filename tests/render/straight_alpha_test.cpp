// A transparent frame's alpha means what it shows: laid over any colour, it gives the picture
// the renderer draws on that colour. Text with its box, arrows, trails and the cube, over green
// and over white, each against an opaque frame drawn on that colour; and the straightening itself.
#include "render/straight_alpha.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "render/renderer.hpp"
#include "support/render_golden.hpp"

namespace tumble::render {
namespace {

using testing::draw;

// `image` (straight alpha) laid over `below` (sRGB-encoded, 0-1), in sRGB-encoded values as a
// compositor does: c × a + below × (1 − a); channel `c` of pixel (x, y), in 0-255 units.
double over(const io::Image& image, int x, int y, int c, const Color& below) {
  const std::size_t i = static_cast<std::size_t>(y) * image.width + x;
  const double alpha = image.alpha[i] / 255.0;
  return image.rgb[3 * i + c] * alpha + 255.0 * below[c] * (1.0 - alpha);
}

int channel(const io::Image& image, int x, int y, int c) {
  return image.rgb[3 * (static_cast<std::size_t>(y) * image.width + x) + c];
}

constexpr int kWidth = 320, kHeight = 180;

RenderSettings settings_on(const Color& background, int msaa) {
  RenderSettings settings;
  settings.width = kWidth;
  settings.height = kHeight;
  settings.msaa = msaa;
  settings.background = background;
  settings.ground.enabled = false;
  settings.font = std::string(kDefaultFontFamily);
  settings.overlays = true;
  return settings;
}

// A blue cube; a red caption on an opaque blue box at the top left; a red caption with no box at
// the bottom right; a half-transparent box with white text at the top right; a green arrow with a
// red label and a fading trail beside the cube.
FrameView caption_view() {
  FrameView view;
  view.camera.position = Vec3(2.6, 2.0, 3.6);
  view.boxes.push_back(Box{.orientation = Quat(Eigen::AngleAxisd(0.4, Vec3::UnitY())),
                           .color = Color(0.1, 0.2, 0.9)});
  view.texts.push_back(Text{.text = "Red on blue",
                            .anchor = Anchor::kTopLeft,
                            .offset = Eigen::Vector2d(24.0, 24.0),
                            .height = 96.0,
                            .color = Rgba(1.0, 0.0, 0.0, 1.0),
                            .background = Rgba(0.0, 0.0, 1.0, 1.0)});
  view.texts.push_back(Text{.text = "Red",
                            .anchor = Anchor::kBottomRight,
                            .offset = Eigen::Vector2d(-24.0, -24.0),
                            .height = 120.0,
                            .color = Rgba(1.0, 0.0, 0.0, 1.0)});
  view.texts.push_back(Text{.text = "half",
                            .anchor = Anchor::kTopRight,
                            .offset = Eigen::Vector2d(-24.0, 24.0),
                            .height = 64.0,
                            .color = Rgba(1.0, 1.0, 1.0, 1.0),
                            .background = Rgba(0.0, 0.0, 0.0, 0.5)});
  view.arrows.push_back(Arrow{
      .from = Vec3(1.3, -0.5, 0.5), .to = Vec3(1.3, 0.7, 0.5), .color = Rgba(0.1, 0.8, 0.2, 1.0)});
  view.labels.push_back(Label{.text = "v",
                              .position = Vec3(1.3, 0.7, 0.5),
                              .height = 48.0,
                              .color = Rgba(1.0, 0.0, 0.0, 1.0)});
  view.lines.push_back(
      Polyline{.points = {Vec3(-1.2, -0.5, 0.8), Vec3(-1.5, 0.2, 0.8), Vec3(-1.3, 0.9, 0.8)},
               .opacity = {0.2, 0.6, 1.0},
               .color = Rgba(1.0, 1.0, 0.0, 1.0)});
  return view;
}

TEST(StraightAlpha, UndoesOverOnTheBackground) {
  io::Image image(3, 1);
  image.alpha = {0, 128, 255};
  // Red at alpha 128/255 over the clear colour (0.2, 0.4, 0.6): 255 × a + 51 × (1 − a), ...
  const double a = 128.0 / 255.0;
  image.rgb = {51,
               102,
               153,
               static_cast<std::uint8_t>(std::lround(255.0 * a + 51.0 * (1.0 - a))),
               static_cast<std::uint8_t>(std::lround(102.0 * (1.0 - a))),
               static_cast<std::uint8_t>(std::lround(153.0 * (1.0 - a))),
               7,
               8,
               9};
  make_alpha_straight(image, Color(0.2, 0.4, 0.6));
  // Transparent and opaque pixels are kept; the partial one is red within 0.5 + 0.5 / a levels.
  EXPECT_EQ(std::vector<std::uint8_t>(image.rgb.begin(), image.rgb.begin() + 3),
            (std::vector<std::uint8_t>{51, 102, 153}));
  EXPECT_EQ(std::vector<std::uint8_t>(image.rgb.begin() + 6, image.rgb.end()),
            (std::vector<std::uint8_t>{7, 8, 9}));
  const double bound = 0.5 + 0.5 / a;
  EXPECT_NEAR(image.rgb[3], 255, bound);
  EXPECT_NEAR(image.rgb[4], 0, bound);
  EXPECT_NEAR(image.rgb[5], 0, bound);
}

// Every pixel of the transparent frame laid over green and over white is the opaque frame drawn
// on green or white within 2 levels: with 4 samples everywhere (an edge's alpha is its coverage);
// with the edge filter but for 1% of the pixels, on outlines (below). The red text is red and the
// box blue, within 2 levels, both over green and over white.
TEST(StraightAlpha, TransparentFrameOverAColourIsTheFrameDrawnOnIt) {
  const FrameView view = caption_view();
  for (const int msaa : {4, kEdgeFilter}) {
    RenderSettings transparent = settings_on(Color(0.78, 0.84, 0.9), msaa);
    transparent.transparent = true;
    const io::Image clear = draw(transparent, view);
    ASSERT_EQ(clear.alpha.size(), static_cast<std::size_t>(kWidth) * kHeight);
    for (const Color& below : {Color(0.0, 1.0, 0.0), Color(1.0, 1.0, 1.0)}) {
      const io::Image opaque = draw(settings_on(below, msaa), view);
      int worst = 0, differing = 0, red = 0, blue = 0;
      for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
          int pixel_worst = 0;
          for (int c = 0; c < 3; ++c) {
            const int laid = static_cast<int>(std::lround(over(clear, x, y, c, below)));
            pixel_worst = std::max(pixel_worst, std::abs(laid - channel(opaque, x, y, c)));
          }
          worst = std::max(worst, pixel_worst);
          differing += pixel_worst > 2;
          const auto is = [&](int r, int g, int b) {
            return std::abs(over(clear, x, y, 0, below) - r) <= 2 &&
                   std::abs(over(clear, x, y, 1, below) - g) <= 2 &&
                   std::abs(over(clear, x, y, 2, below) - b) <= 2;
          };
          red += is(255, 0, 0);
          blue += is(0, 0, 255);
        }
      }
      const std::string name =
          "msaa " + std::to_string(msaa) + " over " + (below.x() > 0.5 ? "white" : "green");
      // The glyphs' cores and the box, a few thousand pixels each at this size.
      EXPECT_GT(red, 400) << name;
      EXPECT_GT(blue, 3000) << name;
      if (msaa == 4) {
        EXPECT_LE(worst, 2) << name;
      } else {
        // Outlines (the cube's, the arrow's, the trail's): the filter finds an edge by its
        // contrast with what is around it, the background colour here and green or white there,
        // so it smooths somewhat other pixels; about 240 of the 57600 differ.
        EXPECT_LE(differing, kWidth * kHeight / 100) << name << ", largest " << worst;
      }
    }
  }
}

}  // namespace
}  // namespace tumble::render
