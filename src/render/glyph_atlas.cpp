#include "render/glyph_atlas.hpp"

#include <algorithm>
#include <cstring>

namespace tumble::render {

GlyphAtlas::GlyphAtlas(int size, int max_size)
    : size_(size),
      max_size_(std::max(size, max_size)),
      texels_(static_cast<std::size_t>(size) * size, 0) {}

std::optional<AtlasGlyph> GlyphAtlas::find_or_add(Font& font, std::uint32_t glyph,
                                                  int pixel_height) {
  const auto key = std::make_pair(glyph, pixel_height);
  if (const auto found = glyphs_.find(key); found != glyphs_.end()) return found->second;
  const GlyphBitmap bitmap = font.rasterize(glyph, pixel_height);
  const auto corner = pack(bitmap.width, bitmap.height);
  if (!corner) return std::nullopt;
  const AtlasGlyph placed{corner->first, corner->second, bitmap.width,
                          bitmap.height, bitmap.left,    bitmap.top};
  for (int row = 0; row < bitmap.height; ++row) {
    std::memcpy(&texels_[static_cast<std::size_t>(placed.y + row) * size_ + placed.x],
                &bitmap.coverage[static_cast<std::size_t>(row) * bitmap.width],
                static_cast<std::size_t>(bitmap.width));
  }
  glyphs_.emplace(key, placed);
  return placed;
}

std::optional<std::pair<int, int>> GlyphAtlas::pack(int width, int height) {
  if (width == 0 || height == 0) return std::make_pair(0, 0);  // a space: nothing to store
  while (true) {
    if (shelf_x_ + width > size_) {  // on to a new shelf under this one
      shelf_y_ += shelf_height_;
      shelf_x_ = 0;
      shelf_height_ = 0;
    }
    if (width <= size_ && shelf_y_ + height <= size_) break;
    if (size_ >= max_size_) return std::nullopt;
    grow();
  }
  const auto corner = std::make_pair(shelf_x_, shelf_y_);
  shelf_x_ += width;
  shelf_height_ = std::max(shelf_height_, height);
  return corner;
}

void GlyphAtlas::grow() {
  // Twice as wide and tall, the glyphs where they were: their places stay valid.
  const int old_size = size_;
  size_ = std::min(2 * size_, max_size_);
  std::vector<std::uint8_t> grown(static_cast<std::size_t>(size_) * size_, 0);
  for (int row = 0; row < old_size; ++row) {
    std::memcpy(&grown[static_cast<std::size_t>(row) * size_],
                &texels_[static_cast<std::size_t>(row) * old_size],
                static_cast<std::size_t>(old_size));
  }
  texels_ = std::move(grown);
}

}  // namespace tumble::render
