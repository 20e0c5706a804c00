// A transparent frame's colour made straight (unassociated), as PNG and WebM mean it.
//
// Every layer of a transparent frame blends with "over" onto a framebuffer cleared to the
// background colour at alpha 0 (GL's blending for the overlays and the quads seen from behind,
// TextLayer on the CPU). "Over" is linear, so each pixel keeps
//     colour = premultiplied colour + background × (1 − alpha)
// from the clear on: the picture as it would show over the background colour (which is what the
// edge filter, multisampling and text blending see, as in an opaque frame). The straight colour
// is then (colour − background × (1 − alpha)) / alpha.
#pragma once

#include "io/image.hpp"
#include "render/frame.hpp"

namespace tumble::render {

// Makes `image`'s colour straight where its alpha is partial (1-254), given the `background` it
// was cleared to (sRGB-encoded, 0-1): opaque pixels are already straight, and a fully transparent
// one keeps what it holds (the background colour, or an edge the edge filter smoothed). Rounded
// to the nearest level and clamped to 0-255; an 8-bit colour of alpha a comes back within
// 0.5 + 0.5 / a levels of the exact value. Nothing happens without an alpha plane.
void make_alpha_straight(io::Image& image, const Color& background);

}  // namespace tumble::render
