#include "render/text_layout.hpp"
#include "support/default_font.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

namespace tumble::render {
namespace {

using testing::default_font;

Text live_value(Anchor anchor) {
  Text text;
  text.text = "\xCF\x89 = 1.23 rad/s   t = 2.0 s";  // ω
  text.anchor = anchor;
  text.offset = Eigen::Vector2d(16.0, 12.0);  // px at 720 rows
  text.height = 32.0;
  return text;
}

const Anchor kAnchors[] = {Anchor::kTopLeft,    Anchor::kTop,    Anchor::kTopRight,
                           Anchor::kLeft,       Anchor::kCentre, Anchor::kRight,
                           Anchor::kBottomLeft, Anchor::kBottom, Anchor::kBottomRight};

// The box sits at its anchor, moved by the offset scaled to the frame: flush with the left
// (top) edge, centred, or flush with the right (bottom) edge, within a pixel of rounding.
TEST(TextLayout, AnchorsPlaceTheBoxWhereExpected) {
  const auto font = default_font();
  ASSERT_TRUE(font);
  for (const auto& [width, height] : {std::pair{320, 180}, std::pair{1280, 720}}) {
    const double scale = height / 720.0;
    for (int i = 0; i < 9; ++i) {
      const Result<TextLayout> layout = lay_out(*font, live_value(kAnchors[i]), width, height);
      ASSERT_TRUE(layout) << layout.error();
      const PixelBox& box = layout->box;
      const int column = i % 3, row = i / 3;
      const double expected_x = (column == 0   ? 0.0
                                 : column == 1 ? 0.5 * (width - box.width)
                                               : width - box.width) +
                                16.0 * scale;
      const double expected_y = (row == 0   ? 0.0
                                 : row == 1 ? 0.5 * (height - box.height)
                                            : height - box.height) +
                                12.0 * scale;
      EXPECT_NEAR(box.x, expected_x, 1.0) << width << "x" << height << " anchor " << i;
      EXPECT_NEAR(box.y, expected_y, 1.0) << width << "x" << height << " anchor " << i;
    }
  }
}

// Every glyph's ink lies inside the box, and the box is the line's height plus the padding.
TEST(TextLayout, TheBoxHoldsEveryGlyphAndThePadding) {
  const auto font = default_font();
  ASSERT_TRUE(font);
  const Result<TextLayout> layout = lay_out(*font, live_value(Anchor::kCentre), 1280, 720);
  ASSERT_TRUE(layout) << layout.error();
  ASSERT_EQ(layout->pixel_height, 32);
  const LineMetrics metrics = font->line_metrics(32);
  const int padding = 8;  // kTextPadding of 32 px
  EXPECT_EQ(layout->box.height, metrics.ascender + metrics.descender + 2 * padding);
  // 26 characters, spaces too: the font has them all.
  EXPECT_EQ(layout->glyphs.size(), 26u);
  int right_most = 0;
  for (const PlacedGlyph& placed : layout->glyphs) {
    const GlyphBitmap bitmap = font->rasterize(placed.glyph, 32);
    if (bitmap.width == 0) continue;
    EXPECT_GE(placed.x + bitmap.left, layout->box.x + padding - 1);
    EXPECT_GE(placed.y - bitmap.top, layout->box.y + padding);
    EXPECT_LE(placed.y - bitmap.top + bitmap.height, layout->box.y + layout->box.height - padding);
    right_most = std::max(right_most, placed.x + bitmap.left + bitmap.width);
  }
  EXPECT_LE(right_most, layout->box.x + layout->box.width - padding + 1);
  EXPECT_GE(right_most, layout->box.x + layout->box.width - padding - 3);  // 's' ends near it
}

// The same text at 180 and at 720 rows: a quarter of the size, within a pixel of rounding.
TEST(TextLayout, SizeScalesWithTheFrameHeight) {
  const auto font = default_font();
  ASSERT_TRUE(font);
  const Result<TextLayout> small = lay_out(*font, live_value(Anchor::kTopLeft), 320, 180);
  const Result<TextLayout> large = lay_out(*font, live_value(Anchor::kTopLeft), 1280, 720);
  ASSERT_TRUE(small && large);
  EXPECT_EQ(small->pixel_height, 8);
  EXPECT_EQ(large->pixel_height, 32);
  EXPECT_NEAR(small->box.width, large->box.width / 4.0, 1.0);
  EXPECT_NEAR(small->box.height, large->box.height / 4.0, 1.0);
  EXPECT_GT(large->box.width, 300);  // 26 characters of 32 px: about 370 px
  EXPECT_LT(large->box.width, 450);
  EXPECT_EQ(text_pixel_height(32.0, 1080), 48);
  EXPECT_EQ(text_pixel_height(1.0, 180), 1);  // never below one pixel
}

TEST(TextLayout, LinesStackOnBaselinesAndAlignToTheAnchorsSide) {
  const auto font = default_font();
  ASSERT_TRUE(font);
  Text text = live_value(Anchor::kTopLeft);
  text.text = "\xCE\x94t = 0.5 s\nx\xC2\xB2";  // "Δt = 0.5 s" over "x²"
  const LineMetrics metrics = font->line_metrics(32);
  for (const Anchor anchor : {Anchor::kTopLeft, Anchor::kTopRight}) {
    text.anchor = anchor;
    const Result<TextLayout> layout = lay_out(*font, text, 1280, 720);
    ASSERT_TRUE(layout) << layout.error();
    ASSERT_EQ(layout->glyphs.size(), 12u);
    const PlacedGlyph& first_line = layout->glyphs[0];    // Δ
    const PlacedGlyph& second_line = layout->glyphs[10];  // x
    EXPECT_EQ(second_line.y - first_line.y, metrics.line_height);
    EXPECT_EQ(layout->box.height,
              metrics.ascender + metrics.descender + metrics.line_height + 2 * 8);
    if (anchor == Anchor::kTopLeft) {
      EXPECT_EQ(second_line.x, first_line.x);
    } else {
      // "x²" is far shorter than "Δt = 0.5 s": its start moves right by the difference.
      EXPECT_GT(second_line.x, first_line.x + 80);
    }
  }
}

TEST(TextLayout, KerningMovesTheNextGlyph) {
  const auto font = default_font();
  ASSERT_TRUE(font);
  Text text = live_value(Anchor::kTopLeft);
  text.height = 64.0;
  text.text = "AV";
  const Result<TextLayout> layout = lay_out(*font, text, 1280, 720);
  ASSERT_TRUE(layout) << layout.error();
  ASSERT_EQ(layout->glyphs.size(), 2u);
  const std::uint32_t a = font->glyph_index(U'A');
  const double unkerned = font->advance(a, 64) / 64.0;
  const double kerned =
      (font->advance(a, 64) + font->kerning(a, font->glyph_index(U'V'), 64)) / 64.0;
  EXPECT_NEAR(layout->glyphs[1].x - layout->glyphs[0].x, kerned, 0.5);
  EXPECT_NEAR(unkerned - kerned, 4.1, 0.1);  // DejaVu's A–V pair: -131 units per 2048 at 64 px
}

TEST(TextLayout, AMissingGlyphIsLeftOutAndKeepsAGap) {
  const auto font = default_font();
  ASSERT_TRUE(font);
  Text text = live_value(Anchor::kTopLeft);
  text.text =
      "a\xE4\xB8\xAD"
      "b";  // a中b
  const Result<TextLayout> layout = lay_out(*font, text, 1280, 720);
  ASSERT_TRUE(layout) << layout.error();
  ASSERT_EQ(layout->glyphs.size(), 2u);
  EXPECT_NE(layout->glyphs[0].glyph, 0u);
  EXPECT_NE(layout->glyphs[1].glyph, 0u);
  EXPECT_GT(layout->glyphs[1].x - layout->glyphs[0].x, 25);  // a's advance and the gap
}

TEST(TextLayout, InvalidUtf8IsAnErrorNamingTheByte) {
  const auto font = default_font();
  ASSERT_TRUE(font);
  Text text = live_value(Anchor::kTopLeft);
  text.text = "t = \xFF";
  const Result<TextLayout> layout = lay_out(*font, text, 1280, 720);
  ASSERT_FALSE(layout);
  EXPECT_NE(layout.error().find("invalid UTF-8 at byte 4"), std::string::npos) << layout.error();
}

bool disjoint(const PixelBox& a, const PixelBox& b) {
  return a.x + a.width <= b.x || b.x + b.width <= a.x || a.y + a.height <= b.y ||
         b.y + b.height <= a.y;
}

// Labels asked at the same place (two aligned vectors' tips) go one below the other, the gap
// apart; one past the frame's edge comes inside; one that cannot go down goes up.
TEST(TextLayout, PlaceApartMovesALabelClearOfTheOthersAndIntoTheFrame) {
  const PixelBox asked{100, 50, 40, 20};
  const PixelBox first = place_apart(asked, {}, 320, 180, 2);
  EXPECT_EQ(first, asked);
  const PixelBox second = place_apart(asked, {first}, 320, 180, 2);
  EXPECT_TRUE(disjoint(first, second));
  EXPECT_EQ(second, (PixelBox{100, 72, 40, 20}));  // 50 + 20 + the gap of 2
  const PixelBox third = place_apart(asked, {first, second}, 320, 180, 2);
  EXPECT_EQ(third, (PixelBox{100, 94, 40, 20}));
  EXPECT_EQ(place_apart({300, -5, 40, 20}, {}, 320, 180, 2), (PixelBox{280, 0, 40, 20}));
  const PixelBox low{100, 155, 40, 20};
  const PixelBox above = place_apart(low, {low}, 320, 180, 2);
  EXPECT_EQ(above, (PixelBox{100, 133, 40, 20}));
}

TEST(TextLayout, AnchorNamesAreTheScenesWords) {
  EXPECT_EQ(anchor_from_name("top-left"), Anchor::kTopLeft);
  EXPECT_EQ(anchor_from_name("top"), Anchor::kTop);
  EXPECT_EQ(anchor_from_name("top-right"), Anchor::kTopRight);
  EXPECT_EQ(anchor_from_name("left"), Anchor::kLeft);
  EXPECT_EQ(anchor_from_name("centre"), Anchor::kCentre);
  EXPECT_EQ(anchor_from_name("center"), Anchor::kCentre);
  EXPECT_EQ(anchor_from_name("right"), Anchor::kRight);
  EXPECT_EQ(anchor_from_name("bottom-left"), Anchor::kBottomLeft);
  EXPECT_EQ(anchor_from_name("bottom"), Anchor::kBottom);
  EXPECT_EQ(anchor_from_name("bottom-right"), Anchor::kBottomRight);
  EXPECT_EQ(anchor_from_name("Top-Left"), std::nullopt);
  EXPECT_EQ(anchor_from_name("middle"), std::nullopt);
}

}  // namespace
}  // namespace tumble::render
