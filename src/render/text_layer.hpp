// Text over the frame: each Text laid out (text_layout.hpp), its glyphs taken from a GL atlas
// texture (glyph_atlas.hpp) and drawn with text.vert/text.frag into a transparent layer of its
// own, which is then composited over the picture read back from the scene's framebuffer.
//
// Why after the read-back, and not into the scene's framebuffer before it: the default
// antialiasing is the edge filter (edge_filter.hpp), run on the CPU over the picture read back.
// Glyph stems are hard luminance edges to it: drawn before it, text would be blended with its
// neighbours (thicker, blurred strokes, the scene smeared into the background box). FreeType's
// coverage already antialiases the glyphs, so they go over the filtered picture untouched, and
// only the layer's pixels under a text's box are read back and blended. Multisampled renders take
// the same path, so a text looks the same whatever the antialiasing.
//
// Internal to src/render/; needs a current GL context from create() to destruction.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "io/image.hpp"
#include "render/font.hpp"
#include "render/frame.hpp"
#include "render/framebuffer.hpp"
#include "render/glyph_atlas.hpp"
#include "render/result.hpp"
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

  // Blends `texts` over `picture` (width × height, as the renderer read it back), each over the
  // ones before it. Glyph colours are blended in sRGB-encoded values, as a video compositor
  // does. Preconditions: each text is valid UTF-8 (the caller checks with decode_utf8).
  void draw(const std::vector<Text>& texts, io::Image& picture);

  const Font& font() const { return *font_; }

 private:
  TextLayer() = default;
  // Every text laid out (invalid UTF-8, which the caller rules out, draws nothing).
  std::vector<TextLayout> lay_out_all(const std::vector<Text>& texts);
  // Two triangles per glyph and per background, kFloatsPerCorner floats per corner (text.vert's
  // inputs); `covered` gets each text's box grown to hold its glyphs' ink.
  std::vector<float> vertices(const std::vector<Text>& texts,
                              const std::vector<TextLayout>& layouts,
                              std::vector<PixelBox>& covered);
  void upload_atlas();
  void draw_layer(const std::vector<float>& vertices, const std::vector<PixelBox>& regions);
  void composite(const PixelBox& region, io::Image& picture);

  int width_ = 0, height_ = 0;  // of the frame (px)
  std::unique_ptr<Font> font_;
  GlyphAtlas atlas_{256, 256};
  ShaderProgram program_;
  Framebuffer layer_;  // premultiplied RGBA, cleared to transparent under each text's box
  GLuint texture_ = 0, vao_ = 0, vbo_ = 0;
  std::vector<std::uint8_t> readback_;  // a region of the layer, RGBA, top row first
};

// The disjoint rectangles that cover `boxes` clipped to a width × height frame: overlapping
// boxes merged into the box around them, so that each pixel is blended once.
std::vector<PixelBox> merged_regions(const std::vector<PixelBox>& boxes, int width, int height);

}  // namespace tumble::render
