// The glyphs text needs, rasterised once per (glyph, pixel height) and packed into one
// single-channel picture that text_layer.hpp blends from. Free of GL.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "render/font.hpp"

namespace tumble::render {

// A glyph's place in the atlas and how it sits on the pen position.
struct AtlasGlyph {
  int x = 0, y = 0;           // the bitmap's top-left texel in the atlas (texels, row 0 on top)
  int width = 0, height = 0;  // of the bitmap (px = texels: drawn one texel per pixel)
  int left = 0;               // from the pen position to the bitmap's left column (px, rightwards)
  int top = 0;                // from the baseline to the bitmap's top row (px, upwards)
};

class GlyphAtlas {
 public:
  // Starts at `size` × `size` texels and doubles when full, up to `max_size`.
  GlyphAtlas(int size, int max_size);

  // The glyph at `pixel_height`, rasterised by `font` and packed on first use. Nothing when it
  // no longer fits in a max_size atlas (thousands of large glyphs).
  std::optional<AtlasGlyph> find_or_add(Font& font, std::uint32_t glyph, int pixel_height);

  int size() const { return size_; }
  // size × size coverage values, row 0 first.
  const std::vector<std::uint8_t>& texels() const { return texels_; }

 private:
  // The top-left texel for a bitmap of width × height, growing the atlas if needed.
  std::optional<std::pair<int, int>> pack(int width, int height);
  void grow();

  int size_;
  int max_size_;
  std::vector<std::uint8_t> texels_;
  // Shelf packing: glyphs side by side along a shelf, shelves one under the other.
  int shelf_y_ = 0;                                             // top row of the shelf being filled
  int shelf_height_ = 0;                                        // its tallest bitmap so far
  int shelf_x_ = 0;                                             // the next free column on it
  std::map<std::pair<std::uint32_t, int>, AtlasGlyph> glyphs_;  // by (glyph, pixel height)
};

}  // namespace tumble::render
