// The default antialiasing: a luminance-edge filter on the read-back picture, run on the CPU
// after one sample per pixel was drawn. Multisampling multiplies llvmpipe's rasterising and
// shading work per pixel; this costs one pass over the image. Free of GL. Internal to src/render/.
#pragma once

#include <cstdint>
#include <vector>

#include "io/image.hpp"
#include "render/pixel_box.hpp"

namespace tumble::render {

// Copies the picture `rgba` (width × height × 4 bytes, top row first) to `out` as RGB (resized
// to width × height), blending each pixel on a hard luminance edge with its neighbour across the
// edge by how much of the pixel the straightened edge would cover: the idea of FXAA (Lottes
// 2009). Pixels away from edges are copied unchanged, and so are those inside `unfiltered`
// (text, antialiased by its glyphs' coverage: text_layer.hpp). The same input gives the same
// bytes. `with_alpha`: `out.alpha` is rgba's alpha, blended on edges with the colour's share (so
// that an edge of a transparent frame is partly transparent, as its coverage: the colour there
// is a picture over the background colour, straight_alpha.hpp); else the alpha is ignored and
// `out.alpha` left empty.
void filter_edges(const std::uint8_t* rgba, int width, int height, io::Image& out,
                  const std::vector<PixelBox>& unfiltered = {}, bool with_alpha = false);

}  // namespace tumble::render
