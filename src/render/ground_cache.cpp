#include "render/ground_cache.hpp"

namespace tumble::render {

Result<GroundCache> GroundCache::create(int width, int height, int samples) {
  Result<Framebuffer> buffer = Framebuffer::create(width, height, samples);
  if (!buffer) return Error{buffer.error()};
  GroundCache out;
  out.buffer_ = std::move(buffer).value();
  return out;
}

void GroundCache::begin_drawing(const GroundKey& key) {
  glBindFramebuffer(GL_FRAMEBUFFER, buffer_.id());
  key_ = key;
  drawn_ = true;
}

}  // namespace tumble::render
