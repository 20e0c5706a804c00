#include "render/framebuffer.hpp"

#include <string>

namespace tumble::render {

Result<Framebuffer> Framebuffer::create(int width, int height, int samples) {
  Framebuffer out;
  out.width_ = width;
  out.height_ = height;
  glGenFramebuffers(1, out.framebuffer_.out());
  glBindFramebuffer(GL_FRAMEBUFFER, out.framebuffer_.get());
  const auto attach = [&](GlName& renderbuffer, GLenum format, GLenum attachment) {
    glGenRenderbuffers(1, renderbuffer.out());
    glBindRenderbuffer(GL_RENDERBUFFER, renderbuffer.get());
    if (samples > 1) {
      glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, width, height);
    } else {
      glRenderbufferStorage(GL_RENDERBUFFER, format, width, height);
    }
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, attachment, GL_RENDERBUFFER, renderbuffer.get());
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
  const GLuint framebuffer = framebuffer_.get();
  if (framebuffer == 0) return;
  glDeleteFramebuffers(1, &framebuffer);
  const GLuint renderbuffers[] = {color_.get(), depth_.get()};
  glDeleteRenderbuffers(2, renderbuffers);
}

void Framebuffer::copy_to(GLuint target, GLbitfield buffers) const {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_.get());
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, target);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, buffers, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, target);
}

}  // namespace tumble::render
