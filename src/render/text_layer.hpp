// Text over the frame: each Text laid out (text_layout.hpp), its glyphs rasterised once into a
// glyph cache (glyph_atlas.hpp) and blended over the picture read back, on the CPU.
//
// Where text sits in the frame's order, and why: last, over everything, after the read-back (and
// the edge filter, which leaves the pixels text lies on alone: glyph stems are hard luminance
// edges to it, which it would blend with their neighbours into thicker, blurred strokes).
// FreeType's coverage already antialiases the glyphs. Why on the CPU: glyph rectangles are
// whole pixels, one coverage byte per pixel, so blending them is a few operations a pixel over
// the glyphs' own pixels; drawn by llvmpipe as textured, blended triangles the same three
// captions cost 13% of a light 720p frame (render_bench's BM_TextCostPerFrame720p), its
// rasteriser shading whole 4 × 4 blocks around every small glyph. Multisampled frames get the
// same text after the resolve: each glyph pixel would have had the same value in every sample.
#pragma once

#include <memory>
#include <string_view>
#include <vector>

#include "common/result.hpp"
#include "io/image.hpp"
#include "render/font.hpp"
#include "render/frame.hpp"
#include "render/glyph_atlas.hpp"
#include "render/pixel_box.hpp"
#include "render/text_layout.hpp"

namespace tumble::render {

class TextLayer {
 public:
  // For frames of width × height px, in `font_family` (font.hpp); an error names the family.
  static Result<std::unique_ptr<TextLayer>> create(int width, int height,
                                                   std::string_view font_family);

  // Lays out `texts` for the next draw() and returns the rectangles it will draw on, within the
  // frame, for the edge filter to leave: a text's background box, or each of its glyphs' grown
  // by a pixel (the filter's reach across an edge). Fully transparent glyphs and boxes draw
  // nothing and return nothing. Precondition: each text is valid UTF-8 (decode_utf8).
  std::vector<PixelBox> lay_out(const std::vector<Text>& texts);

  // Blends what lay_out() placed over `image` (width × height), each text over the ones before,
  // in sRGB-encoded values as a video compositor does: premultiplied "over" (Porter & Duff
  // 1984). An alpha plane, when `image` has one, gets "over" too (the text's alpha × coverage
  // over the alpha below); the colour is then the picture as it shows over the colour the
  // transparent parts hold (the Renderer makes it straight afterwards, straight_alpha.hpp).
  void draw(io::Image& image) const;

  const Font& font() const { return *font_; }

 private:
  TextLayer() = default;

  // A rectangle of whole pixels to blend: a glyph's coverage from the atlas, or solid.
  struct Piece {
    PixelBox box;                   // within the frame
    int texel_x = -1, texel_y = 0;  // the atlas texel at the box's top-left; -1: solid
    Eigen::Vector4f color;          // sRGB-encoded, premultiplied by its opacity (0-1)
  };
  void add(const PixelBox& box, int texel_x, int texel_y, const Eigen::Vector4f& color);

  int width_ = 0, height_ = 0;  // of the frame (px)
  std::unique_ptr<Font> font_;
  GlyphAtlas atlas_{256, 256};
  std::vector<Piece> pieces_;  // of the last lay_out(), in drawing order
};

}  // namespace tumble::render
