#include "render/glyph_atlas.hpp"
#include "support/default_font.hpp"

#include <gtest/gtest.h>

#include <memory>

namespace tumble::render {
namespace {

using testing::default_font;

// The atlas texels under a glyph's place.
std::vector<std::uint8_t> texels_of(const GlyphAtlas& atlas, const AtlasGlyph& glyph) {
  std::vector<std::uint8_t> out;
  for (int row = 0; row < glyph.height; ++row) {
    const auto* start =
        &atlas.texels()[static_cast<std::size_t>(glyph.y + row) * atlas.size() + glyph.x];
    out.insert(out.end(), start, start + glyph.width);
  }
  return out;
}

TEST(GlyphAtlas, HoldsEachGlyphsBitmapOncePerPixelHeight) {
  const auto font = default_font();
  ASSERT_TRUE(font);
  GlyphAtlas atlas(256, 256);
  const std::uint32_t omega = font->glyph_index(0x3C9);
  const auto first = atlas.find_or_add(*font, omega, 24);
  ASSERT_TRUE(first);
  EXPECT_EQ(texels_of(atlas, *first), font->rasterize(omega, 24).coverage);
  const auto again = atlas.find_or_add(*font, omega, 24);
  ASSERT_TRUE(again);
  EXPECT_EQ(again->x, first->x);
  EXPECT_EQ(again->y, first->y);
  const auto larger = atlas.find_or_add(*font, omega, 48);
  ASSERT_TRUE(larger);
  EXPECT_GT(larger->height, first->height);
  EXPECT_EQ(texels_of(atlas, *larger), font->rasterize(omega, 48).coverage);
  EXPECT_NE(std::make_pair(larger->x, larger->y), std::make_pair(first->x, first->y));
}

TEST(GlyphAtlas, GrowsWhenFullAndKeepsWhatItHeld) {
  const auto font = default_font();
  ASSERT_TRUE(font);
  GlyphAtlas atlas(32, 128);
  std::vector<std::pair<std::uint32_t, AtlasGlyph>> held;
  for (char32_t c = U'A'; c <= U'Z'; ++c) {
    const std::uint32_t glyph = font->glyph_index(c);
    const auto placed = atlas.find_or_add(*font, glyph, 20);
    ASSERT_TRUE(placed) << static_cast<char>(c);
    held.emplace_back(glyph, *placed);
  }
  EXPECT_EQ(atlas.size(), 128);  // 26 capitals of about 14 × 15 px need more than 64²
  for (const auto& [glyph, placed] : held) {
    EXPECT_EQ(texels_of(atlas, placed), font->rasterize(glyph, 20).coverage);
  }
  // No two glyphs share texels.
  for (std::size_t i = 0; i < held.size(); ++i) {
    for (std::size_t j = i + 1; j < held.size(); ++j) {
      const AtlasGlyph& a = held[i].second;
      const AtlasGlyph& b = held[j].second;
      const bool apart = a.x + a.width <= b.x || b.x + b.width <= a.x || a.y + a.height <= b.y ||
                         b.y + b.height <= a.y;
      EXPECT_TRUE(apart) << i << " and " << j;
    }
  }
}

TEST(GlyphAtlas, AGlyphThatCannotFitIsRefused) {
  const auto font = default_font();
  ASSERT_TRUE(font);
  GlyphAtlas atlas(16, 32);
  EXPECT_FALSE(atlas.find_or_add(*font, font->glyph_index(U'M'), 200));
  EXPECT_TRUE(atlas.find_or_add(*font, font->glyph_index(U'M'), 12));
}

}  // namespace
}  // namespace tumble::render
