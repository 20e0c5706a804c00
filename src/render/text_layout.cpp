#include "render/text_layout.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <utility>

#include "render/utf8.hpp"

namespace tumble::render {
namespace {

// A position in 1/64 px (FreeType's 26.6 fixed point) to the nearest whole pixel.
int round_26_6(std::int64_t value) {
  return static_cast<int>((value + 32) >> 6);  // arithmetic shift: floor, also below zero
}

int ceil_26_6(std::int64_t value) {
  return static_cast<int>((value + 63) >> 6);
}

// A line's glyphs with pen positions relative to the line's start (1/64 px), and its width.
struct Line {
  std::vector<std::pair<std::uint32_t, std::int64_t>> glyphs;  // glyph index, pen (1/64 px)
  int width = 0;                                               // px
};

std::vector<Line> break_and_advance(Font& font, std::u32string_view text, int pixel_height) {
  std::vector<Line> lines(1);
  std::int64_t pen = 0;
  std::uint32_t previous = 0;
  for (const char32_t c : text) {
    if (c == U'\n') {
      lines.back().width = ceil_26_6(pen);
      lines.emplace_back();
      pen = 0;
      previous = 0;
      continue;
    }
    const std::uint32_t glyph = font.glyph_index(c);
    pen += font.kerning(previous, glyph, pixel_height);
    lines.back().glyphs.emplace_back(glyph, pen);
    pen += font.advance(glyph, pixel_height);  // a missing glyph keeps its width as a gap
    previous = glyph;
  }
  lines.back().width = ceil_26_6(pen);
  return lines;
}

// Where along each axis the anchor sits: 0 = left or top, 1 = centre, 2 = right or bottom.
std::pair<int, int> anchor_thirds(Anchor anchor) {
  const int index = static_cast<int>(anchor);
  return {index % 3, index / 3};
}

// The start of a box `size` long on a frame `frame` long at `third` (0, 1, 2), moved by `offset`.
int place(int third, int frame, int size, double offset) {
  const double start = 0.5 * third * (frame - size) + offset;
  return static_cast<int>(std::floor(start + 0.5));
}

}  // namespace

double scale_to_frame(double length_at_reference, int frame_height) {
  return length_at_reference * frame_height / kTextReferenceHeight;
}

int text_pixel_height(double height_at_reference, int frame_height) {
  const double scaled = scale_to_frame(height_at_reference, frame_height);
  return std::max(1, static_cast<int>(std::lround(scaled)));
}

Result<TextLayout> lay_out(Font& font, const Text& text, int frame_width, int frame_height) {
  assert(std::isfinite(text.height) && text.height > 0.0 && text.offset.allFinite());
  const Result<std::u32string> characters = decode_utf8(text.text);
  if (!characters) return Error{characters.error()};
  TextLayout out;
  out.pixel_height = text_pixel_height(text.height, frame_height);
  const LineMetrics metrics = font.line_metrics(out.pixel_height);
  const std::vector<Line> lines = break_and_advance(font, *characters, out.pixel_height);
  int text_width = 0;
  for (const Line& line : lines) text_width = std::max(text_width, line.width);
  const int text_height = metrics.ascender + metrics.descender +
                          static_cast<int>(lines.size() - 1) * metrics.line_height;
  const int padding = static_cast<int>(std::lround(kTextPadding * out.pixel_height));
  out.box.width = text_width + 2 * padding;
  out.box.height = text_height + 2 * padding;
  const auto [column, row] = anchor_thirds(text.anchor);
  out.box.x =
      place(column, frame_width, out.box.width, scale_to_frame(text.offset.x(), frame_height));
  out.box.y =
      place(row, frame_height, out.box.height, scale_to_frame(text.offset.y(), frame_height));
  for (std::size_t i = 0; i < lines.size(); ++i) {
    // Each line aligned in the box the way the box is anchored: left, centred or right.
    const int line_x = out.box.x + padding + column * (text_width - lines[i].width) / 2;
    const int baseline =
        out.box.y + padding + metrics.ascender + static_cast<int>(i) * metrics.line_height;
    for (const auto& [glyph, pen] : lines[i].glyphs) {
      if (glyph == 0) continue;
      out.glyphs.push_back(PlacedGlyph{glyph, line_x + round_26_6(pen), baseline});
    }
  }
  return out;
}

PixelBox place_apart(PixelBox box, const std::vector<PixelBox>& taken, int frame_width,
                     int frame_height, int gap) {
  box.x = std::clamp(box.x, 0, std::max(frame_width - box.width, 0));
  box.y = std::clamp(box.y, 0, std::max(frame_height - box.height, 0));
  // The first taken box the box at row y meets (with the gap), or null.
  const auto meets = [&](int y) -> const PixelBox* {
    for (const PixelBox& other : taken) {
      if (box.x < other.x + other.width + gap && other.x < box.x + box.width + gap &&
          y < other.y + other.height + gap && other.y < y + box.height + gap) {
        return &other;
      }
    }
    return nullptr;
  };
  int down = box.y;
  while (const PixelBox* other = meets(down)) down = other->y + other->height + gap;
  if (down + box.height <= frame_height) return {box.x, down, box.width, box.height};
  int up = box.y;
  while (const PixelBox* other = meets(up)) up = other->y - gap - box.height;
  return {box.x, up >= 0 ? up : down, box.width, box.height};
}

}  // namespace tumble::render
