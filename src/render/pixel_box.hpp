// A rectangle of whole pixels on a frame: where text lies, and what the edge filter leaves alone.
#pragma once

namespace tumble::render {

// x right from the left column, y down from the top row (px).
struct PixelBox {
  int x = 0;
  int y = 0;
  int width = 0;
  int height = 0;

  bool operator==(const PixelBox&) const = default;
};

}  // namespace tumble::render
