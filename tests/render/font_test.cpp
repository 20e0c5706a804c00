// The default font through fontconfig and FreeType: the physics symbols have real glyphs, a
// character the font lacks is reported, a family not installed is an error naming it.
#include "render/font.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "render/utf8.hpp"
#include "support/default_font.hpp"

namespace tumble::render {
namespace {

using testing::default_font;

// The symbols issue 13 names: ω τ θ Δ ² · → ≈ °.
const std::u32string kPhysicsSymbols = {0x3C9, 0x3C4,  0x3B8,  0x394, 0xB2,
                                        0xB7,  0x2192, 0x2248, 0xB0};

TEST(Font, FindsDejaVuSansThroughFontconfig) {
  const Result<FontFile> file = find_font("DejaVu Sans");
  ASSERT_TRUE(file) << file.error();
  const std::string name = file->path.substr(file->path.find_last_of('/') + 1);
  EXPECT_EQ(name, "DejaVuSans.ttf") << file->path;  // the regular face, not Bold or Condensed
  EXPECT_EQ(file->face_index, 0);
  EXPECT_TRUE(find_font("dejavu sans")) << "family names are matched ignoring case";
}

TEST(Font, AFamilyFontconfigDoesNotHaveIsAnErrorNamingIt) {
  const Result<FontFile> file = find_font("No Such Family Xq");
  ASSERT_FALSE(file);
  EXPECT_NE(file.error().find("font family \"No Such Family Xq\" is not installed"),
            std::string::npos)
      << file.error();
  const Result<std::unique_ptr<Font>> font = Font::open("No Such Family Xq");
  ASSERT_FALSE(font);
  EXPECT_NE(font.error().find("No Such Family Xq"), std::string::npos) << font.error();
}

TEST(Font, AFileFreeTypeCannotReadIsAnErrorNamingIt) {
  const Result<std::unique_ptr<Font>> font = Font::load({"/nonexistent/font.ttf", 0});
  ASSERT_FALSE(font);
  EXPECT_EQ(font.error().rfind("/nonexistent/font.ttf: FreeType cannot read the font", 0), 0u)
      << font.error();
}

// Each symbol has a glyph of its own, and what FreeType draws for it is not the missing-glyph
// box (.notdef, glyph 0): the text would otherwise show boxes where a reader expects ω.
TEST(Font, PhysicsSymbolsHaveGlyphsThatAreNotTheMissingGlyphBox) {
  const auto font = default_font();
  ASSERT_TRUE(font);
  EXPECT_TRUE(font->missing_characters(kPhysicsSymbols).empty());
  const GlyphBitmap box = font->rasterize(0, 32);
  ASSERT_GT(box.width, 0) << "DejaVu Sans draws its .notdef as a box";
  for (const char32_t c : kPhysicsSymbols) {
    const std::uint32_t glyph = font->glyph_index(c);
    ASSERT_NE(glyph, 0u) << describe_character(c);
    const GlyphBitmap drawn = font->rasterize(glyph, 32);
    const int inked = static_cast<int>(std::count_if(drawn.coverage.begin(), drawn.coverage.end(),
                                                     [](auto v) { return v > 128; }));
    EXPECT_GT(inked, 3) << describe_character(c) << " draws (nearly) nothing";
    const bool same_as_box = drawn.width == box.width && drawn.height == box.height &&
                             drawn.left == box.left && drawn.top == box.top &&
                             drawn.coverage == box.coverage;
    EXPECT_FALSE(same_as_box) << describe_character(c) << " is drawn as the missing-glyph box";
  }
}

TEST(Font, MissingCharactersAreListedOnceEachInOrder) {
  const auto font = default_font();
  ASSERT_TRUE(font);
  // 中 (a CJK ideograph) and 🚀 (an emoji; DejaVu Sans has 😀 but not this) are not in DejaVu
  // Sans; ω is, and '\n' needs none.
  const Result<std::u32string> text =
      decode_utf8("a\xE4\xB8\xAD \xCF\x89\n\xF0\x9F\x9A\x80\xE4\xB8\xAD");
  ASSERT_TRUE(text) << text.error();
  const std::vector<char32_t> missing = font->missing_characters(*text);
  ASSERT_EQ(missing, (std::vector<char32_t>{0x4E2D, 0x1F680}));
  EXPECT_EQ(describe_character(missing[1]), "U+1F680 '\xF0\x9F\x9A\x80'");
}

TEST(Font, RasterisingIsTheSameEveryTime) {
  const auto font = default_font();
  ASSERT_TRUE(font);
  const std::uint32_t omega = font->glyph_index(0x3C9);
  const GlyphBitmap first = font->rasterize(omega, 24);
  font->rasterize(font->glyph_index(U'A'), 40);  // another glyph and size in between
  const GlyphBitmap again = font->rasterize(omega, 24);
  EXPECT_EQ(first.coverage, again.coverage);
  EXPECT_EQ(first.width, again.width);
  EXPECT_EQ(first.left, again.left);
  EXPECT_EQ(first.top, again.top);
  // Anti-aliased: edges are partly covered, not only 0 and 255.
  EXPECT_TRUE(std::any_of(first.coverage.begin(), first.coverage.end(),
                          [](auto v) { return v > 20 && v < 235; }));
}

TEST(Font, MetricsAndAdvancesScaleWithThePixelHeight) {
  const auto font = default_font();
  ASSERT_TRUE(font);
  const LineMetrics small = font->line_metrics(10);
  const LineMetrics large = font->line_metrics(100);
  // DejaVu Sans: ascender 1901, descender -483, height 2384 in 2048 units per em.
  EXPECT_EQ(large.ascender, 93);   // ceil(1901 * 100 / 2048)
  EXPECT_EQ(large.descender, 24);  // ceil(483 * 100 / 2048)
  EXPECT_EQ(large.line_height, 117);
  EXPECT_EQ(small.ascender, 10);
  EXPECT_EQ(small.descender, 3);
  const std::uint32_t m = font->glyph_index(U'M');
  // M advances 1767 units: 86.28 px at 100 px, 8.63 px at 10 px (1/64 px, within a rounding).
  EXPECT_NEAR(font->advance(m, 100), 1767.0 * 100 / 2048 * 64, 1.0);
  EXPECT_NEAR(font->advance(m, 10), 1767.0 * 10 / 2048 * 64, 1.0);
}

TEST(Font, KerningPullsAVTogether) {
  const auto font = default_font();
  ASSERT_TRUE(font);
  const std::int32_t av = font->kerning(font->glyph_index(U'A'), font->glyph_index(U'V'), 64);
  // -131 of 2048 font units per em at 64 px, in 1/64 px: -4.1 px
  EXPECT_NEAR(av, -131.0 * 64 / 2048 * 64, 1.0) << "DejaVu Sans kerns A and V";
  EXPECT_EQ(font->kerning(font->glyph_index(U'A'), 0, 64), 0);
}

}  // namespace
}  // namespace tumble::render
