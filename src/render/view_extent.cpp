#include "render/view_extent.hpp"

#include <algorithm>

#include "render/geometry.hpp"

namespace tumble::render {

ViewExtent view_extent(const FrameView& view) {
  const Camera& camera = view.camera;
  ViewExtent extent;
  // The part of the world worth lighting and showing: a sphere around the look-at point that
  // holds every box, at least 1 m across.
  for (const Box& box : view.boxes) {
    extent.radius =
        std::max(extent.radius, (box.position - camera.look_at).norm() + 0.5 * box.size.norm());
  }
  // Quads reach further (a wall behind the boxes): the far plane keeps them.
  for (const Quad& quad : view.quads) {
    for (const Vec3& corner : corners(quad)) {
      extent.quad_reach = std::max(extent.quad_reach, (corner - camera.look_at).norm());
    }
  }
  extent.camera_distance = (camera.position - camera.look_at).norm();
  extent.near = std::max(0.01, 0.05 * std::max(extent.camera_distance - extent.radius, 0.1));
  extent.far = std::max(extent.camera_distance + 4.0 * extent.radius + 100.0,
                        extent.camera_distance + 1.01 * extent.quad_reach);
  extent.ground_half_extent = std::max(30.0, 8.0 * (extent.camera_distance + extent.radius));
  return extent;
}

}  // namespace tumble::render
