// An 8-bit RGB image in memory, top row first, with an optional straight (not premultiplied)
// alpha plane: what the renderer produces and the PNG and video writers consume.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace tumble::io {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  // width * height * 3 bytes, rows top to bottom, no padding
  // Empty for an opaque image; else width * height bytes, 0 transparent to 255 opaque, in the
  // order of `rgb`'s pixels.
  std::vector<std::uint8_t> alpha;

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgb(static_cast<std::size_t>(w) * h * 3, 0) {}

  std::size_t row_bytes() const { return static_cast<std::size_t>(width) * 3; }
  std::uint8_t* row(int y) { return rgb.data() + static_cast<std::size_t>(y) * row_bytes(); }
  const std::uint8_t* row(int y) const {
    return rgb.data() + static_cast<std::size_t>(y) * row_bytes();
  }
};

}  // namespace tumble::io
