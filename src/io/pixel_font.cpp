#include "io/pixel_font.hpp"

#include <algorithm>
#include <cstddef>

namespace tumble::io {
namespace {

struct Glyph {
  char c;
  // One byte per row, top first; bit 4 is the leftmost of the 5 columns.
  std::array<std::uint8_t, kPixelFontHeight> rows;
};

constexpr Glyph kGlyphs[] = {
    {'0', {0x0E, 0x11, 0x13, 0x15, 0x19, 0x11, 0x0E}},
    {'1', {0x04, 0x0C, 0x04, 0x04, 0x04, 0x04, 0x0E}},
    {'2', {0x0E, 0x11, 0x01, 0x02, 0x04, 0x08, 0x1F}},
    {'3', {0x1F, 0x02, 0x04, 0x02, 0x01, 0x11, 0x0E}},
    {'4', {0x02, 0x06, 0x0A, 0x12, 0x1F, 0x02, 0x02}},
    {'5', {0x1F, 0x10, 0x1E, 0x01, 0x01, 0x11, 0x0E}},
    {'6', {0x06, 0x08, 0x10, 0x1E, 0x11, 0x11, 0x0E}},
    {'7', {0x1F, 0x01, 0x02, 0x04, 0x08, 0x08, 0x08}},
    {'8', {0x0E, 0x11, 0x11, 0x0E, 0x11, 0x11, 0x0E}},
    {'9', {0x0E, 0x11, 0x11, 0x0F, 0x01, 0x02, 0x0C}},
    {'.', {0x00, 0x00, 0x00, 0x00, 0x00, 0x0C, 0x0C}},
    {'-', {0x00, 0x00, 0x00, 0x1F, 0x00, 0x00, 0x00}},
    {'+', {0x00, 0x04, 0x04, 0x1F, 0x04, 0x04, 0x00}},
    {'=', {0x00, 0x00, 0x1F, 0x00, 0x1F, 0x00, 0x00}},
    {':', {0x00, 0x0C, 0x0C, 0x00, 0x0C, 0x0C, 0x00}},
    {'t', {0x08, 0x08, 0x1C, 0x08, 0x08, 0x09, 0x06}},
    {'s', {0x00, 0x00, 0x0E, 0x10, 0x0E, 0x01, 0x1E}},
    {'e', {0x00, 0x00, 0x0E, 0x11, 0x1F, 0x10, 0x0E}},
    {' ', {0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00}},
};

const Glyph& glyph_of(char c) {
  for (const Glyph& glyph : kGlyphs) {
    if (glyph.c == c) return glyph;
  }
  return kGlyphs[std::size(kGlyphs) - 1];  // the space
}

void fill_square(Image& image, int x, int y, int side, const std::array<std::uint8_t, 3>& rgb) {
  for (int row = std::max(y, 0); row < std::min(y + side, image.height); ++row) {
    for (int column = std::max(x, 0); column < std::min(x + side, image.width); ++column) {
      std::uint8_t* pixel = image.row(row) + 3 * static_cast<std::size_t>(column);
      pixel[0] = rgb[0];
      pixel[1] = rgb[1];
      pixel[2] = rgb[2];
    }
  }
}

}  // namespace

bool pixel_font_has(char c) {
  return c == ' ' || &glyph_of(c) != &kGlyphs[std::size(kGlyphs) - 1];
}

int pixel_text_width(std::string_view text, int scale) {
  if (text.empty()) return 0;
  return scale * (kPixelFontAdvance * static_cast<int>(text.size() - 1) + kPixelFontWidth);
}

void draw_pixel_text(Image& image, int x, int y, int scale, std::string_view text,
                     const std::array<std::uint8_t, 3>& rgb) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    const Glyph& glyph = glyph_of(text[i]);
    const int left = x + scale * kPixelFontAdvance * static_cast<int>(i);
    for (int row = 0; row < kPixelFontHeight; ++row) {
      for (int column = 0; column < kPixelFontWidth; ++column) {
        if (glyph.rows[static_cast<std::size_t>(row)] & (0x10 >> column)) {
          fill_square(image, left + scale * column, y + scale * row, scale, rgb);
        }
      }
    }
  }
}

}  // namespace tumble::io
