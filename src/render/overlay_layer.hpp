// A frame's lines and arrows (overlay_geometry.hpp) drawn with overlay.vert/overlay.frag into the
// frame's framebuffer, after the scene and before the text.
//
// Depth-tested, and how: a vector of a body starts at its centre, inside the body, and an arrow
// drawn on top of everything would seem to float in front of the body whichever way it points,
// while one hidden by the depth test would vanish inside the body, or entirely when short. So
// both: where the scene is nearer, the line is drawn faint (kHiddenOpacity), elsewhere at its
// full opacity. The two passes test the same depths with GL_GREATER and GL_LEQUAL, so each pixel
// is drawn by exactly one, and nothing writes depth: lines never hide each other or the text.
// The edge filter (edge_filter.hpp) then smooths their edges with the scene's.
//
// Internal to src/render/; needs a current GL context from create() to destruction.
#pragma once

#include <memory>
#include <string>

#include "common/result.hpp"
#include "render/frame.hpp"
#include "render/geometry.hpp"
#include "render/shader_program.hpp"

namespace tumble::render {

// Of a line where the scene hides it: enough to follow it through a body, little enough that
// what is in front reads as in front.
inline constexpr float kHiddenOpacity = 0.3f;

class OverlayLayer {
 public:
  // For frames of width × height px, with the shaders of `shader_directory`.
  static Result<std::unique_ptr<OverlayLayer>> create(int width, int height,
                                                      const std::string& shader_directory);
  ~OverlayLayer();
  OverlayLayer(const OverlayLayer&) = delete;
  OverlayLayer& operator=(const OverlayLayer&) = delete;

  // Blends the lines, then the arrows, over the bound framebuffer, seen through
  // `view_projection` (world to clip space), against the depths the scene left there.
  void draw(const std::vector<Polyline>& lines, const std::vector<Arrow>& arrows,
            const Mat4& view_projection);

 private:
  OverlayLayer() = default;
  int width_ = 0, height_ = 0;  // of the frame (px)
  ShaderProgram program_;
  GLint opacity_ = -1;  // u_opacity's location
  GLuint vao_ = 0, vbo_ = 0;
  std::size_t vbo_floats_ = 0;  // the buffer's size, grown as needed and reused frame to frame
};

}  // namespace tumble::render
