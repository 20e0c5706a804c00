#include "render/overlay_layer.hpp"

#include "render/overlay_geometry.hpp"

namespace tumble::render {

Result<std::unique_ptr<OverlayLayer>> OverlayLayer::create(int width, int height,
                                                           const std::string& shader_directory) {
  std::unique_ptr<OverlayLayer> out(new OverlayLayer());
  out->width_ = width;
  out->height_ = height;
  Result<ShaderProgram> program =
      ShaderProgram::build(shader_directory, {"overlay.vert"}, {"overlay.frag"});
  if (!program) return Error{program.error()};
  out->program_ = std::move(program).value();
  out->opacity_ = out->program_.uniform("u_opacity");
  glGenVertexArrays(1, &out->vao_);
  glGenBuffers(1, &out->vbo_);
  glBindVertexArray(out->vao_);
  glBindBuffer(GL_ARRAY_BUFFER, out->vbo_);
  const GLsizei stride = kOverlayFloatsPerVertex * sizeof(float);
  glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, stride, nullptr);
  glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, stride,
                        reinterpret_cast<const void*>(4 * sizeof(float)));
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(1);
  glBindVertexArray(0);
  if (glGetError() != GL_NO_ERROR) return Error{"OpenGL error while setting up the overlays"};
  return out;
}

OverlayLayer::~OverlayLayer() {
  glDeleteVertexArrays(1, &vao_);
  glDeleteBuffers(1, &vbo_);
}

void OverlayLayer::draw(const std::vector<Polyline>& lines, const std::vector<Arrow>& arrows,
                        const Mat4& view_projection) {
  const std::vector<float> vertices =
      overlay_triangles(lines, arrows, view_projection, width_, height_);
  if (vertices.empty()) return;
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  const auto bytes = static_cast<GLsizeiptr>(vertices.size() * sizeof(float));
  if (vertices.size() > vbo_floats_) {
    glBufferData(GL_ARRAY_BUFFER, bytes, vertices.data(), GL_DYNAMIC_DRAW);
    vbo_floats_ = vertices.size();
  } else {
    glBufferSubData(GL_ARRAY_BUFFER, 0, bytes, vertices.data());
  }
  glUseProgram(program_.id());
  glDisable(GL_CULL_FACE);  // bands face either way, as their offsets fall
  glDepthMask(GL_FALSE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);  // premultiplied "over" (Porter & Duff 1984)
  glBindVertexArray(vao_);
  const GLsizei count = static_cast<GLsizei>(vertices.size() / kOverlayFloatsPerVertex);
  glDepthFunc(GL_GREATER);  // hidden by the scene
  glUniform1f(opacity_, kHiddenOpacity);
  glDrawArrays(GL_TRIANGLES, 0, count);
  glDepthFunc(GL_LEQUAL);  // in view
  glUniform1f(opacity_, 1.0f);
  glDrawArrays(GL_TRIANGLES, 0, count);
  glBindVertexArray(0);
  glDepthFunc(GL_LESS);
  glDisable(GL_BLEND);
  glDepthMask(GL_TRUE);
  glEnable(GL_CULL_FACE);
}

}  // namespace tumble::render
