#include "render/framebuffer.hpp"

#include <utility>

namespace tumble::render {

Result<Framebuffer> Framebuffer::create(int width, int height, int samples) {
  Framebuffer out;
  out.width_ = width;
  out.height_ = height;
  glGenFramebuffers(1, &out.framebuffer_);
  glBindFramebuffer(GL_FRAMEBUFFER, out.framebuffer_);
  const auto attach = [&](GLuint& renderbuffer, GLenum format, GLenum attachment) {
    glGenRenderbuffers(1, &renderbuffer);
    glBindRenderbuffer(GL_RENDERBUFFER, renderbuffer);
    if (samples > 1) {
      glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, width, height);
    } else {
      glRenderbufferStorage(GL_RENDERBUFFER, format, width, height);
    }
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, attachment, GL_RENDERBUFFER, renderbuffer);
  };
  attach(out.color_, GL_RGBA8, GL_COLOR_ATTACHMENT0);
  attach(out.depth_, GL_DEPTH_COMPONENT24, GL_DEPTH_ATTACHMENT);
  const bool complete = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (!complete) {
    return Error{samples > 1
                     ? "multisampled framebuffer (" + std::to_string(samples) + "x) is incomplete"
                     : "framebuffer is incomplete"};
  }
  return out;
}

Framebuffer::~Framebuffer() {
  if (framebuffer_ == 0) return;
  glDeleteFramebuffers(1, &framebuffer_);
  const GLuint renderbuffers[] = {color_, depth_};
  glDeleteRenderbuffers(2, renderbuffers);
}

Framebuffer::Framebuffer(Framebuffer&& other) noexcept
    : framebuffer_(std::exchange(other.framebuffer_, 0)),
      color_(std::exchange(other.color_, 0)),
      depth_(std::exchange(other.depth_, 0)),
      width_(other.width_),
      height_(other.height_) {}

Framebuffer& Framebuffer::operator=(Framebuffer&& other) noexcept {
  std::swap(framebuffer_, other.framebuffer_);
  std::swap(color_, other.color_);
  std::swap(depth_, other.depth_);
  std::swap(width_, other.width_);
  std::swap(height_, other.height_);
  return *this;
}

void Framebuffer::copy_to(GLuint target, GLbitfield buffers) const {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, target);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, buffers, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, target);
}

}  // namespace tumble::render
