// Text over the frame: each Text laid out (text_layout.hpp), its glyphs taken from a GL atlas
// texture (glyph_atlas.hpp) and drawn with text.vert/text.frag into the frame's framebuffer,
// after the scene and before the read-back.
//
// Where text sits in the frame's order, and why: last of the passes, over everything, into
// the frame's own framebuffer before the read-back, so that it costs only its glyphs' and
// boxes' pixels (no layer to clear, read and composite, no second wait for the rasteriser).
// Then the edge filter (edge_filter.hpp), on the CPU over the picture read back, leaves the
// pixels text drew on alone: glyph stems are hard luminance edges to it, which it would blend
// with their neighbours (thicker, blurred strokes) and walk along at its slowest. FreeType's
// coverage already antialiases the glyphs. Multisampled frames take the same order (the text
// drawn into every sample) and are not filtered at all.
//
// Internal to src/render/; needs a current GL context from create() to destruction.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "common/result.hpp"
#include "render/font.hpp"
#include "render/frame.hpp"
#include "render/glyph_atlas.hpp"
#include "render/shader_program.hpp"
#include "render/text_layout.hpp"

namespace tumble::render {

class TextLayer {
 public:
  // For frames of width × height px: opens `font_family` (font.hpp) and builds the shaders from
  // `shader_directory`. An error names the family or the shader file.
  static Result<std::unique_ptr<TextLayer>> create(int width, int height,
                                                   std::string_view font_family,
                                                   const std::string& shader_directory);
  ~TextLayer();
  TextLayer(const TextLayer&) = delete;
  TextLayer& operator=(const TextLayer&) = delete;

  // Blends `texts` over the bound framebuffer (width × height), each over the ones before, in
  // sRGB-encoded values as a video compositor does. Returns the rectangles drawn on, within the
  // frame, for the edge filter to leave: a text's background box, or each of its glyphs' grown
  // by a pixel (the filter's reach across an edge). Fully transparent glyphs and boxes draw
  // nothing and return nothing. Precondition: each text is valid UTF-8 (decode_utf8).
  std::vector<PixelBox> draw(const std::vector<Text>& texts);

  const Font& font() const { return *font_; }

 private:
  TextLayer() = default;
  // Two triangles per glyph and per background, kFloatsPerCorner floats per corner (text.vert's
  // inputs); `drawn_on` gets what they cover, as draw() returns it.
  std::vector<float> vertices(const std::vector<Text>& texts, std::vector<PixelBox>& drawn_on);
  void upload_atlas();

  int width_ = 0, height_ = 0;  // of the frame (px)
  std::unique_ptr<Font> font_;
  GlyphAtlas atlas_{256, 256};
  ShaderProgram program_;
  GLuint texture_ = 0, vao_ = 0, vbo_ = 0;
};

}  // namespace tumble::render
