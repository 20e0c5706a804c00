// A framebuffer of the renderer's own: colour (RGBA8) and depth (24 bits), multisampled or not.
// Frames are drawn into one and copied into the off-screen context's buffer at the end, so
// that every pass draws into the same kind of buffer, whatever the antialiasing: the kept
// ground (ground_cache.hpp) copied into a frame then meets the frame's own depths exactly.
// Internal to src/render/; needs a current GL context from create() to destruction.
#pragma once

#include <string>

#include "common/result.hpp"
#include "render/gl.hpp"
#include "render/gl_name.hpp"

namespace tumble::render {

class Framebuffer {
 public:
  Framebuffer() = default;  // no GL objects: for a renderer whose set-up failed
  // width × height pixels, `samples` per pixel (1 = no multisampling).
  static Result<Framebuffer> create(int width, int height, int samples);
  ~Framebuffer();
  Framebuffer(Framebuffer&& other) noexcept = default;
  Framebuffer& operator=(Framebuffer&& other) noexcept = default;
  Framebuffer(const Framebuffer&) = delete;
  Framebuffer& operator=(const Framebuffer&) = delete;

  GLuint id() const { return framebuffer_.get(); }
  // Copies `buffers` (GL_COLOR_BUFFER_BIT, GL_DEPTH_BUFFER_BIT) into the framebuffer `target`
  // of the same size, resolving samples when `target` has one per pixel, and leaves `target`
  // bound.
  void copy_to(GLuint target, GLbitfield buffers) const;

 private:
  GlName framebuffer_, color_, depth_;
  int width_ = 0, height_ = 0;
};

}  // namespace tumble::render
