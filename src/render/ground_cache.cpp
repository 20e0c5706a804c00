#include "render/ground_cache.hpp"

namespace tumble::render {

GroundCache GroundCache::create(int width, int height, int samples, std::string& error) {
  GroundCache out;
  out.buffer_ = Framebuffer::create(width, height, samples, error);
  return out;
}

void GroundCache::begin_drawing(const GroundKey& key) {
  glBindFramebuffer(GL_FRAMEBUFFER, buffer_.id());
  key_ = key;
  drawn_ = true;
}

}  // namespace tumble::render
