#include "render/text_layer.hpp"

#include <algorithm>
#include <cassert>
#include <optional>

namespace tumble::render {
namespace {

constexpr int kFloatsPerCorner = 8;   // x, y (px), atlas u, v (texels), premultiplied r, g, b, a
constexpr int kFirstAtlasSize = 512;  // texels per side: a few hundred glyphs of 720p captions

bool contains(const PixelBox& outer, const PixelBox& inner) {
  return inner.x >= outer.x && inner.y >= outer.y &&
         inner.x + inner.width <= outer.x + outer.width &&
         inner.y + inner.height <= outer.y + outer.height;
}

// `box` cut to the frame; nothing when none of it is inside.
std::optional<PixelBox> clipped(const PixelBox& box, int width, int height) {
  const int x0 = std::max(box.x, 0), y0 = std::max(box.y, 0);
  const int x1 = std::min(box.x + box.width, width), y1 = std::min(box.y + box.height, height);
  if (x1 <= x0 || y1 <= y0) return std::nullopt;
  return PixelBox{x0, y0, x1 - x0, y1 - y0};
}

// Appends a rectangle of whole pixels as two triangles; `texel` its top-left atlas texel, or
// negative for a solid one.
void add_rectangle(std::vector<float>& out, const PixelBox& box, float texel_x, float texel_y,
                   const Eigen::Vector4f& premultiplied) {
  const bool solid = texel_x < 0.0f;
  const float x0 = static_cast<float>(box.x), y0 = static_cast<float>(box.y);
  const float x1 = x0 + static_cast<float>(box.width), y1 = y0 + static_cast<float>(box.height);
  const float u0 = texel_x, v0 = texel_y;
  const float u1 = solid ? u0 : u0 + static_cast<float>(box.width);
  const float v1 = solid ? v0 : v0 + static_cast<float>(box.height);
  const float corners[6][4] = {{x0, y0, u0, v0}, {x1, y0, u1, v0}, {x0, y1, u0, v1},
                               {x1, y0, u1, v0}, {x1, y1, u1, v1}, {x0, y1, u0, v1}};
  for (const auto& corner : corners) {
    out.insert(out.end(), corner, corner + 4);
    out.insert(out.end(), premultiplied.data(), premultiplied.data() + 4);
  }
}

Eigen::Vector4f premultiply(const Rgba& color, double opacity) {
  const double alpha = std::clamp(color.w() * opacity, 0.0, 1.0);
  const Eigen::Vector3d rgb = color.head<3>().cwiseMax(0.0).cwiseMin(1.0) * alpha;
  return Eigen::Vector4f(static_cast<float>(rgb.x()), static_cast<float>(rgb.y()),
                         static_cast<float>(rgb.z()), static_cast<float>(alpha));
}

}  // namespace

Result<std::unique_ptr<TextLayer>> TextLayer::create(int width, int height,
                                                     std::string_view font_family,
                                                     const std::string& shader_directory) {
  std::unique_ptr<TextLayer> out(new TextLayer());
  out->width_ = width;
  out->height_ = height;
  Result<std::unique_ptr<Font>> font = Font::open(font_family);
  if (!font) return Error{font.error()};
  out->font_ = std::move(font).value();
  std::string error;
  out->program_ = ShaderProgram::build(shader_directory, {"text.vert"}, {"text.frag"}, error);
  if (!out->program_.valid()) return Error{error};
  GLint max_size = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
  out->atlas_ = GlyphAtlas(std::min(kFirstAtlasSize, max_size), max_size);
  glGenTextures(1, &out->texture_);
  glGenVertexArrays(1, &out->vao_);
  glGenBuffers(1, &out->vbo_);
  glBindVertexArray(out->vao_);
  glBindBuffer(GL_ARRAY_BUFFER, out->vbo_);
  const GLsizei stride = kFloatsPerCorner * sizeof(float);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, stride, nullptr);
  glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, stride,
                        reinterpret_cast<const void*>(2 * sizeof(float)));
  glVertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, stride,
                        reinterpret_cast<const void*>(4 * sizeof(float)));
  for (GLuint i = 0; i < 3; ++i) glEnableVertexAttribArray(i);
  glBindVertexArray(0);
  if (glGetError() != GL_NO_ERROR) return Error{"OpenGL error while setting up the text layer"};
  return out;
}

TextLayer::~TextLayer() {
  glDeleteTextures(1, &texture_);
  glDeleteVertexArrays(1, &vao_);
  glDeleteBuffers(1, &vbo_);
}

std::vector<float> TextLayer::vertices(const std::vector<Text>& texts,
                                       std::vector<PixelBox>& drawn_on) {
  std::vector<float> out;
  for (const Text& text : texts) {
    const Result<TextLayout> layout = lay_out(*font_, text, width_, height_);
    assert(layout.ok() && "text must be checked with decode_utf8 before it is drawn");
    if (!layout) continue;
    std::vector<PixelBox> kept;
    const Eigen::Vector4f background =
        premultiply(text.background.value_or(Rgba::Zero()), text.opacity);
    const bool boxed = background.w() > 0.0f;
    if (boxed) {
      add_rectangle(out, layout->box, -1.0f, -1.0f, background);
      kept.push_back(layout->box);
    }
    const Eigen::Vector4f color = premultiply(text.color, text.opacity);
    for (const PlacedGlyph& placed : layout->glyphs) {
      if (color.w() == 0.0f) break;
      const auto glyph = atlas_.find_or_add(*font_, placed.glyph, layout->pixel_height);
      assert(glyph && "a frame's glyphs fit in an atlas of GL_MAX_TEXTURE_SIZE");
      if (!glyph || glyph->width == 0) continue;  // a space has no bitmap
      const PixelBox box{placed.x + glyph->left, placed.y - glyph->top, glyph->width,
                         glyph->height};
      add_rectangle(out, box, static_cast<float>(glyph->x), static_cast<float>(glyph->y), color);
      // Inside the background box already kept, unless it reaches past it (a deep descender).
      const PixelBox grown{box.x - 1, box.y - 1, box.width + 2, box.height + 2};
      if (!boxed || !contains(layout->box, grown)) kept.push_back(grown);
    }
    for (const PixelBox& box : kept) {
      if (const auto inside = clipped(box, width_, height_)) drawn_on.push_back(*inside);
    }
  }
  return out;
}

void TextLayer::upload_atlas() {
  const auto [first, last] = atlas_.changed_rows();
  if (!atlas_.resized() && first == last) return;
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);  // rows of single bytes, any width
  const int size = atlas_.size();
  if (atlas_.resized()) {
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, size, size, 0, GL_RED, GL_UNSIGNED_BYTE,
                 atlas_.texels().data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  } else {
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, first, size, last - first, GL_RED, GL_UNSIGNED_BYTE,
                    atlas_.texels().data() + static_cast<std::size_t>(first) * size);
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);  // GL's default, as the rest of the renderer has it
  atlas_.mark_uploaded();
}

std::vector<PixelBox> TextLayer::draw(const std::vector<Text>& texts) {
  std::vector<PixelBox> drawn_on;
  const std::vector<float> corners = vertices(texts, drawn_on);
  if (drawn_on.empty()) return drawn_on;  // nothing visible inside the frame
  GLint kept_texture = 0;  // the renderer's (the shadow map) on unit 0, given back at the end
  glActiveTexture(GL_TEXTURE0);
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &kept_texture);
  glBindTexture(GL_TEXTURE_2D, texture_);
  upload_atlas();
  glDisable(GL_DEPTH_TEST);  // over everything
  glDisable(GL_CULL_FACE);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(corners.size() * sizeof(float)),
               corners.data(), GL_STREAM_DRAW);
  glUseProgram(program_.id());
  glUniform2f(program_.uniform("u_frame_size"), static_cast<float>(width_),
              static_cast<float>(height_));
  glUniform1i(program_.uniform("u_atlas"), 0);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);  // premultiplied "over" (Porter & Duff 1984)
  glBindVertexArray(vao_);
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(corners.size() / kFloatsPerCorner));
  glBindVertexArray(0);
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_CULL_FACE);
  glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(kept_texture));
  return drawn_on;
}

}  // namespace tumble::render
