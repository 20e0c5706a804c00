// Text drawn by the renderer over the frame: golden images at 320×180 and 1280×720, the glyphs
// on the picture exactly FreeType's bitmaps (so never the missing-glyph box, and kept from the
// edge filter), and frames without text on today's path, byte for byte. Goldens live in
// tests/render/golden/ (TUMBLE_UPDATE_GOLDEN=1 rewrites them, see renderer_test.cpp).
#include "render/text_layer.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "diff/image_diff.hpp"
#include "io/png_io.hpp"
#include "render/renderer.hpp"
#include "render/utf8.hpp"
#include "support/render_golden.hpp"
#include "support/result_text.hpp"

namespace tumble::render {
namespace {

using testing::draw;
using testing::kGoldens;
using testing::kShaders;

// Same machine, same Mesa and FreeType: bit-identical (DrawingTextTwiceIsByteIdentical). The
// tolerance is the scene goldens' (renderer_test.cpp): 8 of 255 per channel, and 1% of the
// pixels beyond that, for another Mesa, LLVM or FreeType rounding an edge's coverage otherwise.
diff::DiffOptions golden_tolerance(const io::Image& image) {
  return {.threshold = 8,
          .max_pixels = static_cast<std::int64_t>(image.width) * image.height / 100};
}

// The default antialiasing (the edge filter), a plain background that compresses well, a cube in
// the plain look (common::Look::plain, as the goldens were drawn).
RenderSettings text_settings(int width, int height) {
  RenderSettings settings;
  settings.look = common::Look::plain();
  settings.width = width;
  settings.height = height;
  settings.ground.enabled = false;
  settings.shadows = false;
  settings.font = std::string(kDefaultFontFamily);
  return settings;
}

FrameView cube_view() {
  FrameView view;
  view.camera.position = Vec3(2.6, 2.0, 3.6);
  view.boxes.push_back(Box{.orientation = Quat(Eigen::AngleAxisd(0.4, Vec3::UnitY()))});
  return view;
}

// A live value with ω, τ, Δ and ² on a translucent box at the top left, a caption without box
// at the bottom right, and a half-faded label over the cube.
FrameView overlay_view() {
  FrameView view = cube_view();
  view.texts.push_back(Text{.text = "\xCF\x89 = 1.23 rad/s   \xCF\x84 = 0.40 N\xC2\xB7m\n"
                                    "\xCE\x94t = 0.5 s   x\xC2\xB2 = 4 m\xC2\xB2",
                            .anchor = Anchor::kTopLeft,
                            .offset = Eigen::Vector2d(24.0, 24.0),
                            .height = 40.0,
                            .color = Rgba(1.0, 1.0, 1.0, 1.0),
                            .background = Rgba(0.05, 0.05, 0.1, 0.6)});
  view.texts.push_back(
      Text{.text = "\xCE\xB8 = 30\xC2\xB0  E \xE2\x86\x92 E\xE2\x82\x80 \xE2\x89\x88 2 J",
           .anchor = Anchor::kBottomRight,
           .offset = Eigen::Vector2d(-24.0, -16.0),
           .height = 36.0,
           .color = Rgba(0.1, 0.1, 0.3, 1.0)});
  view.texts.push_back(Text{.text = "t = 2.0 s",
                            .anchor = Anchor::kCentre,
                            .height = 56.0,
                            .color = Rgba(1.0, 0.9, 0.2, 1.0),
                            .background = Rgba(0.0, 0.0, 0.0, 0.8),
                            .opacity = 0.6});
  return view;
}

void expect_matches_golden(const io::Image& image, const std::string& name) {
  testing::expect_matches_golden(image, name, golden_tolerance(image));
}

TEST(TextLayer, OverlaysMatchGoldenAt320x180) {
  expect_matches_golden(draw(text_settings(320, 180), overlay_view()), "text_overlay_320x180");
}

TEST(TextLayer, OverlaysMatchGoldenAt1280x720) {
  expect_matches_golden(draw(text_settings(1280, 720), overlay_view()), "text_overlay_1280x720");
}

// White text on black: each pixel's value is the glyph's coverage, so the picture shows exactly
// FreeType's bitmap of ω, τ, Δ and ² where the layout puts it, nothing elsewhere (the edge filter,
// the default, has not touched it), and that bitmap is not the missing-glyph box.
TEST(TextLayer, DrawnGlyphsAreTheFontsBitmapsAndNotTheMissingGlyphBox) {
  RenderSettings settings = text_settings(160, 120);
  settings.background = Color(0.0, 0.0, 0.0);
  Result<std::unique_ptr<Font>> font = Font::open(kDefaultFontFamily);
  ASSERT_TRUE(font) << font.error();
  for (const char32_t c : {char32_t{0x3C9}, char32_t{0x3C4}, char32_t{0x394}, char32_t{0xB2}}) {
    FrameView view;
    view.texts.push_back(Text{.text = encode_utf8(c), .height = 240.0});  // 40 px at 120 rows
    const io::Image image = draw(settings, view);
    ASSERT_EQ(image.width, 160);
    const Result<TextLayout> layout = lay_out(**font, view.texts[0], 160, 120);
    ASSERT_TRUE(layout && layout->glyphs.size() == 1u) << describe_character(c);
    const PlacedGlyph& placed = layout->glyphs[0];
    const GlyphBitmap bitmap = (*font)->rasterize(placed.glyph, layout->pixel_height);
    const int x0 = placed.x + bitmap.left, y0 = placed.y - bitmap.top;
    int wrong = 0;
    for (int y = 0; y < image.height; ++y) {
      for (int x = 0; x < image.width; ++x) {
        const bool inside = x >= x0 && x < x0 + bitmap.width && y >= y0 && y < y0 + bitmap.height;
        const int expected =
            inside ? bitmap.coverage[static_cast<std::size_t>(y - y0) * bitmap.width + (x - x0)]
                   : 0;
        const std::uint8_t* pixel = image.row(y) + 3 * x;
        wrong += std::abs(pixel[0] - expected) > 1 || pixel[1] != pixel[0] || pixel[2] != pixel[0];
      }
    }
    EXPECT_EQ(wrong, 0) << describe_character(c) << ": pixels that are not the glyph's bitmap";
    const GlyphBitmap box = (*font)->rasterize(0, layout->pixel_height);
    EXPECT_FALSE(bitmap.width == box.width && bitmap.height == box.height &&
                 bitmap.coverage == box.coverage)
        << describe_character(c) << " drawn as the missing-glyph box";
  }
}

// 中 is not in DejaVu Sans: nothing is drawn for it (the caller warns), not a box.
TEST(TextLayer, AMissingCharacterDrawsNothing) {
  const RenderSettings settings = text_settings(320, 180);
  FrameView with = cube_view();
  with.texts.push_back(Text{.text = "\xE4\xB8\xAD", .anchor = Anchor::kCentre, .height = 120.0});
  EXPECT_EQ(draw(settings, with).rgb, draw(settings, cube_view()).rgb);
}

TEST(TextLayer, FullyFadedTextLeavesThePictureAsItWas) {
  const RenderSettings settings = text_settings(320, 180);
  FrameView faded = overlay_view();
  for (Text& text : faded.texts) text.opacity = 0.0;
  EXPECT_EQ(draw(settings, faded).rgb, draw(settings, cube_view()).rgb);
}

// A frame without text, even after frames with text, has the bytes of a renderer that loaded no
// font: today's path.
TEST(TextLayer, FramesWithoutTextAreThoseOfARendererWithoutAFont) {
  for (const int msaa : {kEdgeFilter, 4}) {
    RenderSettings settings = text_settings(320, 180);
    settings.msaa = msaa;
    settings.ground.enabled = true;
    settings.shadows = true;
    RenderSettings without_font = settings;
    without_font.font.clear();
    std::string error;
    const auto renderer =
        ::tumble::testing::value_or_empty(Renderer::create(settings, kShaders), error);
    ASSERT_TRUE(renderer) << error;
    io::Image with_text, after;
    renderer->draw(overlay_view(), with_text);
    renderer->draw(cube_view(), after);
    EXPECT_EQ(after.rgb, draw(without_font, cube_view()).rgb) << "msaa " << msaa;
    EXPECT_NE(with_text.rgb, after.rgb) << "msaa " << msaa;
  }
}

TEST(TextLayer, DrawingTextTwiceIsByteIdentical) {
  const RenderSettings settings = text_settings(320, 180);
  std::string error;
  const auto renderer =
      ::tumble::testing::value_or_empty(Renderer::create(settings, kShaders), error);
  ASSERT_TRUE(renderer) << error;
  io::Image first, between, second;
  renderer->draw(overlay_view(), first);
  FrameView other = overlay_view();  // other glyphs and sizes: the atlas fills and grows
  for (Text& text : other.texts) {
    text.height *= 7.0;
    text.text += " abcdefghijklmnopqrstuvwxyz";
  }
  renderer->draw(other, between);
  renderer->draw(overlay_view(), second);
  EXPECT_EQ(first.rgb, second.rgb);
  EXPECT_NE(first.rgb, between.rgb);
  EXPECT_EQ(draw(settings, overlay_view()).rgb, first.rgb) << "a fresh renderer";
}

TEST(TextLayer, AFontFontconfigDoesNotHaveIsAnErrorAtCreate) {
  RenderSettings settings = text_settings(320, 180);
  settings.font = "No Such Family Xq";
  std::string error;
  EXPECT_FALSE(::tumble::testing::value_or_empty(Renderer::create(settings, kShaders), error));
  EXPECT_NE(error.find("font family \"No Such Family Xq\" is not installed"), std::string::npos)
      << error;
}

// Two labels of aligned vectors, asked at the same tip (their texts keep apart): their boxes
// (each text's background, holding its glyphs) are disjoint on the picture.
TEST(TextLayer, LabelsAtTheSamePointDoNotOverlap) {
  const Result<std::unique_ptr<TextLayer>> layer = TextLayer::create(640, 360, kDefaultFontFamily);
  ASSERT_TRUE(layer) << layer.error();
  const Text label{.text = "\xCF\x89",
                   .anchor = Anchor::kLeft,
                   .offset = Eigen::Vector2d(300.0, -20.0),
                   .height = 28.0,
                   .background = Rgba(0.0, 0.0, 0.0, 0.5),
                   .keep_apart = true};
  Text other = label;
  other.text = "L";
  const std::vector<PixelBox> boxes = (*layer)->lay_out({label, other});
  ASSERT_EQ(boxes.size(), 2u);
  const PixelBox& a = boxes[0];
  const PixelBox& b = boxes[1];
  EXPECT_TRUE(a.x + a.width <= b.x || b.x + b.width <= a.x || a.y + a.height <= b.y ||
              b.y + b.height <= a.y)
      << a.x << "," << a.y << " " << a.width << "x" << a.height << " against " << b.x << "," << b.y
      << " " << b.width << "x" << b.height;
  // Without keep_apart they would be drawn on top of each other.
  Text plain = label, plain_other = other;
  plain.keep_apart = plain_other.keep_apart = false;
  const std::vector<PixelBox> stacked = (*layer)->lay_out({plain, plain_other});
  ASSERT_EQ(stacked.size(), 2u);
  EXPECT_EQ(stacked[0].y, stacked[1].y);
}

}  // namespace
}  // namespace tumble::render
