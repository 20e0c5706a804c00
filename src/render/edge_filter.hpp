// The default antialiasing: a luminance-edge filter on the read-back picture, run on the CPU
// after one sample per pixel was drawn. Multisampling multiplies llvmpipe's rasterising and
// shading work per pixel; this costs one pass over the image. Free of GL. Internal to src/render/.
#pragma once

#include <cstdint>
#include <vector>

#include "io/image.hpp"
#include "render/pixel_box.hpp"

namespace tumble::render {

// Copies the picture `rgba` (width × height × 4 bytes, top row first; alpha ignored) to `out`
// as RGB (resized to width × height), blending each pixel on a hard luminance edge with its
// neighbour across the edge by how much of the pixel the straightened edge would cover: the
// idea of FXAA (Lottes 2009). Pixels away from edges are copied unchanged, and so are those
// inside `unfiltered` (text, antialiased by its glyphs' coverage: text_layer.hpp). The same
// input gives the same bytes.
void filter_edges(const std::uint8_t* rgba, int width, int height, io::Image& out,
                  const std::vector<PixelBox>& unfiltered = {});

}  // namespace tumble::render
