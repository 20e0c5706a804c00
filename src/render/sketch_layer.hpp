// Panels and strokes (frame.hpp) drawn over the picture read back, on the CPU, as text is
// (text_layer.hpp says why): a plot is a few thousand pixels of flat colour and thin lines.
// Each stroke is antialiased by its exact coverage of a pixel's centre line of width + 1 px
// (the distance from the pixel's centre to the polyline, so joints never blend twice), and
// blended "over" in sRGB-encoded values as the text is. On a transparent frame the alpha is
// composited too (a + (1 − a) × the alpha below), as every layer is (straight_alpha.hpp).
#pragma once

#include <vector>

#include "io/image.hpp"
#include "render/frame.hpp"
#include "render/pixel_box.hpp"

namespace tumble::render {

// The pixels the panels cover on a frame of `image`'s size, clipped to it.
std::vector<PixelBox> panel_boxes(const std::vector<Panel>& panels, int width, int height);

// Draws `panels`, then `strokes`, over `image`.
void draw_sketch(const std::vector<Panel>& panels, const std::vector<Stroke>& strokes,
                 io::Image& image);

}  // namespace tumble::render
