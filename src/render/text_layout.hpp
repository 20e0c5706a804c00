// Where each glyph of a Text goes on the frame: pen advances with kerning, lines on baselines,
// the text's box placed at its anchor. Free of GL; the glyphs are drawn by text_layer.hpp.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "common/result.hpp"
#include "render/font.hpp"
#include "render/frame.hpp"
#include "render/pixel_box.hpp"

namespace tumble::render {

// The padding between a text's lines and the edge of its box (and of its background), as a
// fraction of the em size: the background is not tight against the letters.
inline constexpr double kTextPadding = 0.25;
// The frame height Text's sizes are given for (px).
inline constexpr int kTextReferenceHeight = 720;

struct PlacedGlyph {
  std::uint32_t glyph = 0;  // the font's glyph index, never 0
  int x = 0;                // pen position on the baseline: px from the frame's left column
  int y = 0;                // the baseline: px down from the frame's top row
};

struct TextLayout {
  int pixel_height = 0;  // the em size the glyphs are rasterised at (px)
  PixelBox box;          // the lines' extent with kTextPadding on each side, at the anchor
  // Glyphs the font lacks are left out (a gap, never the missing-glyph box): the caller warns
  // about them from Font::missing_characters.
  std::vector<PlacedGlyph> glyphs;
};

// A length given at kTextReferenceHeight for a frame `frame_height` rows tall (px).
double scale_to_frame(double length_at_reference, int frame_height);
// The em size glyphs are drawn at: Text::height scaled to the frame, in whole pixels (>= 1), so
// that glyphs are cached and drawn per whole pixel size.
int text_pixel_height(double height_at_reference, int frame_height);

// Lays out `text` on a frame of `frame_width` × `frame_height` px. Invalid UTF-8 is an error
// naming the byte (decode_utf8).
Result<TextLayout> lay_out(Font& font, const Text& text, int frame_width, int frame_height);

// Where a label's box goes: `box` moved inside the frame (frame_width × frame_height px), then
// the nearest place straight down, or else straight up, where it is clear of every box of
// `taken` by `gap` px; if neither fits in the frame, the place below. The same size.
PixelBox place_apart(PixelBox box, const std::vector<PixelBox>& taken, int frame_width,
                     int frame_height, int gap);

// The anchor a scene names (common/anchor.hpp).
using common::anchor_from_name;

}  // namespace tumble::render
