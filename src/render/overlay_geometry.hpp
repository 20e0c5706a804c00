// A frame's lines and arrows as triangles in clip space, free of GL (drawn by overlay_layer.hpp):
// widths fixed in pixels on the picture, so that an arrow near the camera and one far away read
// alike, and depths those of the 3D segment, so that the scene can hide them.
#pragma once

#include <optional>
#include <vector>

#include "render/frame.hpp"
#include "render/geometry.hpp"

namespace tumble::render {

// Per vertex: clip-space x, y, z, w, then the sRGB-encoded colour premultiplied by its opacity.
inline constexpr int kOverlayFloatsPerVertex = 8;

// Widths on the picture (px at 720 rows, scaled with the frame's height): thick enough to read
// at 320 × 180, thin enough not to hide a cube at 720p.
inline constexpr double kArrowShaftWidth = 5.0;
inline constexpr double kArrowHeadLength = 22.0;
inline constexpr double kArrowHeadWidth = 16.0;
inline constexpr double kLineWidth = 3.0;

// Where a world point lands on a width × height picture: px from the left column and from the
// top row (pixel centres at +0.5); nothing when it is behind the camera's near plane.
std::optional<Eigen::Vector2d> project_to_pixel(const Mat4& view_projection, const Vec3& point,
                                                int width, int height);

// The triangles of `lines` then `arrows` (kOverlayFloatsPerVertex floats a vertex), cut at the
// near plane. An arrow shorter than a pixel on the picture draws nothing; one shorter than twice
// its head gets a smaller head.
std::vector<float> overlay_triangles(const std::vector<Polyline>& lines,
                                     const std::vector<Arrow>& arrows, const Mat4& view_projection,
                                     int width, int height);

}  // namespace tumble::render
