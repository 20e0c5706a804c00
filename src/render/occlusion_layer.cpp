#include "render/occlusion_layer.hpp"

#include <algorithm>
#include <cmath>

#include "render/geometry.hpp"

namespace tumble::render {
namespace {

// Per body, at occlusion.vert's locations 1 to 7: the square (3), the centre (3), the rotation's
// columns (9), the half size (3), the kind and the reach (2).
constexpr int kInstanceFloats = 20;

std::optional<PixelRect> merged(const std::optional<PixelRect>& a,
                                const std::optional<PixelRect>& b) {
  if (!a) return b;
  if (!b) return a;
  const int x0 = std::min((*a)[0], (*b)[0]), y0 = std::min((*a)[1], (*b)[1]);
  const int x1 = std::max((*a)[0] + (*a)[2], (*b)[0] + (*b)[2]);
  const int y1 = std::max((*a)[1] + (*a)[3], (*b)[1] + (*b)[3]);
  return PixelRect{x0, y0, x1 - x0, y1 - y0};
}

}  // namespace

Result<OcclusionLayer> OcclusionLayer::create(int width, int height,
                                              const std::string& shader_directory) {
  OcclusionLayer out;
  out.width_ = width;
  out.height_ = height;
  out.buffer_width_ = (width + kOcclusionDownsampling - 1) / kOcclusionDownsampling;
  out.buffer_height_ = (height + kOcclusionDownsampling - 1) / kOcclusionDownsampling;
  Result<ShaderProgram> program = ShaderProgram::build(
      shader_directory, {"occlusion.vert"}, {"version.glsl", "form_factor.glsl", "occlusion.frag"});
  if (!program) return Error{program.error()};
  out.program_ = std::move(program).value();
  Result<ShaderProgram> apply_program =
      ShaderProgram::build(shader_directory, {"occlusion_apply.vert"}, {"occlusion_apply.frag"});
  if (!apply_program) return Error{apply_program.error()};
  out.apply_program_ = std::move(apply_program).value();

  glGenTextures(1, out.texture_.out());
  glBindTexture(GL_TEXTURE_2D, out.texture_.get());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, out.buffer_width_, out.buffer_height_, 0, GL_RGBA,
               GL_UNSIGNED_BYTE, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glGenFramebuffers(1, out.framebuffer_.out());
  glBindFramebuffer(GL_FRAMEBUFFER, out.framebuffer_.get());
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, out.texture_.get(),
                         0);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    return Error{"ambient-occlusion framebuffer is incomplete"};
  }

  glGenVertexArrays(1, out.vertex_array_.out());
  glBindVertexArray(out.vertex_array_.get());
  const float corners[] = {-1, -1, 1, -1, -1, 1, 1, 1};
  glGenBuffers(1, out.corner_buffer_.out());
  glBindBuffer(GL_ARRAY_BUFFER, out.corner_buffer_.get());
  glBufferData(GL_ARRAY_BUFFER, sizeof(corners), corners, GL_STATIC_DRAW);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), nullptr);
  glEnableVertexAttribArray(0);
  glGenBuffers(1, out.instance_buffer_.out());
  glBindBuffer(GL_ARRAY_BUFFER, out.instance_buffer_.get());
  const auto attribute = [](GLuint location, GLint components, int offset) {
    glVertexAttribPointer(location, components, GL_FLOAT, GL_FALSE, kInstanceFloats * sizeof(float),
                          reinterpret_cast<const void*>(offset * sizeof(float)));
    glVertexAttribDivisor(location, 1);
    glEnableVertexAttribArray(location);
  };
  attribute(1, 3, 0);
  attribute(2, 3, 3);
  for (GLuint column = 0; column < 3; ++column) attribute(3 + column, 3, 6 + 3 * column);
  attribute(6, 3, 15);
  attribute(7, 2, 18);
  glGenVertexArrays(1, out.apply_vertex_array_.out());
  glBindVertexArray(out.apply_vertex_array_.get());
  glBindBuffer(GL_ARRAY_BUFFER, out.corner_buffer_.get());
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), nullptr);
  glEnableVertexAttribArray(0);
  glBindVertexArray(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return out;
}

OcclusionLayer::~OcclusionLayer() {
  if (!texture_.get()) return;
  glDeleteFramebuffers(1, framebuffer_.out());
  glDeleteTextures(1, texture_.out());
  glDeleteVertexArrays(1, vertex_array_.out());
  glDeleteVertexArrays(1, apply_vertex_array_.out());
  const GLuint buffers[] = {corner_buffer_.get(), instance_buffer_.get()};
  glDeleteBuffers(2, buffers);
}

OcclusionLayer::Regions OcclusionLayer::draw(const std::vector<Box>& boxes, double ground_height,
                                             double strength, const Mat4& view_projection,
                                             const std::optional<PixelRect>& also) {
  instances_.clear();
  ScreenBounds bounds(view_projection);
  bool whole = false;
  for (const Box& box : boxes) {
    const Eigen::Matrix3d rotation = box.orientation.normalized().toRotationMatrix();
    const Vec3 half = 0.5 * box.size;
    // The box's extent along world y and across the ground, from its centre.
    const Vec3 reach_axes = rotation.cwiseAbs() * half;
    const double reach = kOcclusionReach * box.size.maxCoeff();
    if (box.position.y() - reach_axes.y() - ground_height > reach) continue;  // too high
    const double square = std::max(reach_axes.x(), reach_axes.z()) + reach;
    const bool sphere = box.solid == Solid::ball;
    const float values[kInstanceFloats] = {static_cast<float>(box.position.x()),
                                           static_cast<float>(box.position.z()),
                                           static_cast<float>(square),
                                           static_cast<float>(box.position.x()),
                                           static_cast<float>(box.position.y()),
                                           static_cast<float>(box.position.z()),
                                           static_cast<float>(rotation(0, 0)),
                                           static_cast<float>(rotation(1, 0)),
                                           static_cast<float>(rotation(2, 0)),
                                           static_cast<float>(rotation(0, 1)),
                                           static_cast<float>(rotation(1, 1)),
                                           static_cast<float>(rotation(2, 1)),
                                           static_cast<float>(rotation(0, 2)),
                                           static_cast<float>(rotation(1, 2)),
                                           static_cast<float>(rotation(2, 2)),
                                           static_cast<float>(half.x()),
                                           static_cast<float>(half.y()),
                                           static_cast<float>(half.z()),
                                           sphere ? 1.0f : 0.0f,
                                           static_cast<float>(reach)};
    instances_.insert(instances_.end(), std::begin(values), std::end(values));
    for (int corner = 0; corner < 4 && !whole; ++corner) {
      whole =
          !bounds.take_in(Vec3(box.position.x() + (corner & 1 ? square : -square), ground_height,
                               box.position.z() + (corner & 2 ? square : -square)));
    }
  }
  const std::optional<PixelRect> own =
      whole ? std::optional<PixelRect>(PixelRect{0, 0, width_, height_})
            : bounds.pixels(width_, height_, 1);
  const std::optional<PixelRect> region = merged(own, also);
  if (!region) return {};

  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
  glViewport(0, 0, buffer_width_, buffer_height_);
  glEnable(GL_SCISSOR_TEST);
  // The buffer's texels under the region, and one more around them for the bilinear reads.
  constexpr int k = kOcclusionDownsampling;
  const int x0 = std::max(0, (*region)[0] / k - 1), y0 = std::max(0, (*region)[1] / k - 1);
  const int x1 = std::min(buffer_width_, ((*region)[0] + (*region)[2] + k - 1) / k + 1);
  const int y1 = std::min(buffer_height_, ((*region)[1] + (*region)[3] + k - 1) / k + 1);
  glScissor(x0, y0, x1 - x0, y1 - y0);
  glClearColor(1.0f, 1.0f, 1.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  if (own) {
    glUseProgram(program_.id());
    const Eigen::Matrix4f vp = view_projection.cast<float>();
    glUniformMatrix4fv(program_.uniform("u_view_projection"), 1, GL_FALSE, vp.data());
    glUniform1f(program_.uniform("u_ground_height"), static_cast<float>(ground_height));
    glUniform1f(program_.uniform("u_strength"), static_cast<float>(strength));
    glBindVertexArray(vertex_array_.get());
    glBindBuffer(GL_ARRAY_BUFFER, instance_buffer_.get());
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(instances_.size() * sizeof(float)),
                 instances_.data(), GL_STREAM_DRAW);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ZERO, GL_SRC_COLOR);  // the buffer times (1 − occlusion)
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4,
                          static_cast<GLsizei>(instances_.size() / kInstanceFloats));
    glDisable(GL_BLEND);
    glEnable(GL_CULL_FACE);
    glEnable(GL_DEPTH_TEST);
    glBindVertexArray(0);
  }
  glDisable(GL_SCISSOR_TEST);
  return {.occluded = own, .fresh = region};
}

void OcclusionLayer::apply(const PixelRect& region, double fill_share) {
  glUseProgram(apply_program_.id());
  glActiveTexture(GL_TEXTURE2);
  glBindTexture(GL_TEXTURE_2D, texture_.get());
  glActiveTexture(GL_TEXTURE0);
  glUniform1i(apply_program_.uniform("u_occlusion"), 2);
  glUniform2f(apply_program_.uniform("u_occlusion_scale"),
              1.0f / static_cast<float>(kOcclusionDownsampling * buffer_width_),
              1.0f / static_cast<float>(kOcclusionDownsampling * buffer_height_));
  glUniform1f(apply_program_.uniform("u_fill_share"), static_cast<float>(fill_share));
  glEnable(GL_SCISSOR_TEST);
  glScissor(region[0], region[1], region[2], region[3]);
  glDisable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ZERO, GL_SRC_COLOR);  // the frame's colour times the factor
  glBindVertexArray(apply_vertex_array_.get());
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  glBindVertexArray(0);
  glDisable(GL_BLEND);
  glDepthMask(GL_TRUE);
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_SCISSOR_TEST);
}

}  // namespace tumble::render
