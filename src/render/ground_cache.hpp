// The ground drawn once and kept: its colour and depth in a framebuffer of their own, copied
// into each frame before the boxes are drawn, and drawn again only when something its pixels
// depend on changes (the camera, the far plane, its extent). The ground does not move, so a
// frame whose camera stays put shades none of it but where shadows may fall. Internal to
// src/render/; needs a current GL context from create() to destruction.
#pragma once

#include <array>
#include <string>

#include "render/framebuffer.hpp"

namespace tumble::render {

// Everything of a frame the kept ground's pixels depend on beyond the render's settings, as
// the ground pass's uniforms get it: equal keys draw equal pixels.
struct GroundKey {
  std::array<float, 16> view_projection{};  // world to clip, column-major
  std::array<float, 3> center{};            // of the ground's square, world frame (m)
  float half_extent = 0.0f;                 // of the square (m)

  bool operator==(const GroundKey&) const = default;
};

class GroundCache {
 public:
  GroundCache() = default;  // nothing kept: for a renderer without ground
  // Kept in a framebuffer like the frame's: width × height, `samples` per pixel (1 = no
  // multisampling).
  static Result<GroundCache> create(int width, int height, int samples);

  // Whether the kept picture is the one drawn for `key`.
  bool holds(const GroundKey& key) const { return drawn_ && key == key_; }
  // Binds the cache's framebuffer for the caller to clear and draw the ground of `key` into.
  void begin_drawing(const GroundKey& key);
  // Copies the kept colour and depth into the framebuffer `target` and leaves that bound.
  void copy_to(GLuint target) const { buffer_.copy_to(target, kColorAndDepth); }

 private:
  static constexpr GLbitfield kColorAndDepth = GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT;
  Framebuffer buffer_;
  bool drawn_ = false;  // whether key_ says what buffer_ holds
  GroundKey key_;
};

}  // namespace tumble::render
