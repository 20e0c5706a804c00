// Short labels ("t = 1.25 s") drawn into an Image on the CPU from a built-in 5×7 pixel font of
// the digits and a few signs: for pictures composed after the frames (the contact sheet), where
// no OpenGL context or font file is at hand. The same text gives the same pixels anywhere.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

#include "io/image.hpp"

namespace tumble::io {

inline constexpr int kPixelFontWidth = 5;    // of a glyph, in font pixels
inline constexpr int kPixelFontHeight = 7;   // of a glyph, in font pixels
inline constexpr int kPixelFontAdvance = 6;  // from one glyph to the next, in font pixels

// The characters the font has: the digits and ".-+=ts :e" (others are drawn as a space).
bool pixel_font_has(char c);

// Width in image pixels of `text` at `scale` image pixels per font pixel.
int pixel_text_width(std::string_view text, int scale);

// Draws `text` with its top-left corner at (x, y) (pixels, y down), each font pixel a
// `scale` × `scale` square of `rgb`; what falls outside the image is left out.
void draw_pixel_text(Image& image, int x, int y, int scale, std::string_view text,
                     const std::array<std::uint8_t, 3>& rgb);

}  // namespace tumble::io
