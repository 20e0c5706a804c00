// Ambient occlusion on the ground: how much of the fill light the bodies near the ground hide
// from each point of it, in a buffer a quarter of the frame's size each way that the ground's
// shading reads
// (shaders/ground.frag). Each body near the ground draws a square on the ground around itself
// whose pixels compute the body's occlusion in closed form (shaders/occlusion.frag); blending
// multiplies them, so the buffer holds the product of (1 − occlusion) over the bodies. Internal to
// src/render/; needs a current GL context from create() to destruction.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "common/result.hpp"
#include "render/frame.hpp"
#include "render/gl_name.hpp"
#include "render/occluders.hpp"
#include "render/screen_bounds.hpp"
#include "render/shader_program.hpp"

namespace tumble::render {

using Mat4 = Eigen::Matrix4d;

// The occlusion buffer has one texel per 4 × 4 pixels, read with bilinear filtering: occlusion
// varies over a body's width, and its closed form is the costliest shading of a frame.
inline constexpr int kOcclusionDownsampling = 4;

class OcclusionLayer {
 public:
  OcclusionLayer() = default;  // no GL objects: for a renderer without occlusion
  static Result<OcclusionLayer> create(int width, int height, const std::string& shader_directory);
  ~OcclusionLayer();
  OcclusionLayer(OcclusionLayer&&) noexcept = default;
  OcclusionLayer& operator=(OcclusionLayer&&) noexcept = default;

  // Where draw() darkens the ground, and where its buffer is fresh (that and the rectangle
  // asked for besides): the buffer elsewhere is stale.
  struct Regions {
    std::optional<PixelRect> occluded, fresh;
  };
  // Draws the occlusion of `boxes` on the ground at `ground_height` with this strength (0 to 1),
  // fresh over `also` too (where the shadowed ground pass will read it).
  Regions draw(const std::vector<Box>& boxes, double ground_height, double strength,
               const Mat4& view_projection, const std::optional<PixelRect>& also);
  // Multiplies the lit ground drawn in the bound framebuffer, inside `region`, by what the
  // occlusion leaves of its light, `fill_share` being the fill's share of it
  // (shaders/occlusion_apply.frag): before the bodies are drawn over it.
  void apply(const PixelRect& region, double fill_share);
  GLuint texture() const { return texture_.get(); }
  int buffer_width() const { return buffer_width_; }
  int buffer_height() const { return buffer_height_; }

 private:
  int width_ = 0, height_ = 0;                // of the frame (pixels)
  int buffer_width_ = 0, buffer_height_ = 0;  // of the occlusion buffer (texels)
  ShaderProgram program_, apply_program_;
  GlName framebuffer_, texture_, vertex_array_, apply_vertex_array_, corner_buffer_,
      instance_buffer_;
  std::vector<float> instances_;
};

}  // namespace tumble::render
